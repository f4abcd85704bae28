"""Helpers shared by the subcommands: registration with examples, consoles, progress bars."""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Callable, Iterable, Iterator
from typing import Any

from rich.console import Console


class CommandError(Exception):
    """An error the user can fix; printed without a traceback and exits with status 2."""


def add_command(
    subparsers: Any,
    name: str,
    *,
    summary: str,
    description: str,
    examples: list[str],
    run: Callable[[argparse.Namespace], int | None],
) -> argparse.ArgumentParser:
    """Add a subcommand whose ``--help`` ends with its examples."""
    epilog = "examples:\n" + "\n".join(f"  {line}" for line in examples)
    parser = subparsers.add_parser(
        name,
        help=summary,
        description=description,
        epilog=epilog,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.set_defaults(run=run)
    return parser


def console() -> Console:
    """Return the console for results (standard output, no colour codes when piped)."""
    return Console(highlight=False, soft_wrap=True)


def error_console() -> Console:
    """Return the console for errors and progress (standard error)."""
    return Console(stderr=True, highlight=False, soft_wrap=True)


def compile_kernels(
    methods: Iterable[str],
    shadings: Iterable[str] | None = None,
    *,
    lookups: bool | Callable[[], bool] | None = None,
    quiet: bool = False,
) -> None:
    """Before a first run, compile the kernels that renders with ``methods`` need, on every core.

    ``shadings`` are the shading modes those renders use (default: every mode); ``lookups``
    says whether the scenes they render have textures, vertex colours or alpha tests
    (:func:`pixelpath.scene.texture.needs_lookups`), or is a function that says so, called
    only when some kernels are to compile; None when that is not known (the kernels for both
    kinds). Nothing happens when the kernels are in the disk cache already. While they
    compile, a line on standard error says so (only on a terminal, and not when ``quiet``).
    """
    from pixelpath._precompiled import markers
    from pixelpath._warm import cold_groups, compile_groups, estimate_seconds, groups_for

    folder = markers()
    if callable(lookups):
        if not cold_groups(groups_for(methods, shadings), folder):  # both kinds cached
            return
        lookups = lookups()
    cold = cold_groups(groups_for(methods, shadings, lookups=lookups), folder)
    if not cold:
        return
    err = error_console()
    if not quiet and err.is_terminal:
        err.print(
            f"compiling kernels for the first run, about {estimate_seconds(cold, folder):.0f} s; "
            "later runs are instant"
        )
    compile_groups(cold, folder)


@contextlib.contextmanager
def progress(
    description: str, total: int, *, quiet: bool = False
) -> Iterator[Callable[[int], None]]:
    """Show a progress bar on standard error while work runs; yield an ``advance(n)`` callable.

    The bar is drawn only on a terminal and never when ``quiet`` is set, so logs and CI output
    stay clean.
    """
    err = error_console()
    if quiet or not err.is_terminal:
        yield lambda n=1: None
        return
    from rich.progress import (
        BarColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    columns = (
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.percentage:>3.0f}%"),
        TimeElapsedColumn(),
        TimeRemainingColumn(),
    )
    with Progress(*columns, console=err, transient=True) as bar:
        task = bar.add_task(description, total=total)
        yield lambda n=1: bar.advance(task, n)
