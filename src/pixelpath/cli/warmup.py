"""``pixelpath warmup``: compile every kernel ahead of time."""

from __future__ import annotations

import argparse
import time

from pixelpath.cli._common import add_command, console


def register(subparsers) -> None:
    """Add the ``warmup`` subcommand."""
    add_command(
        subparsers,
        "warmup",
        summary="compile every Numba kernel now (cached on disk for later runs)",
        description=(
            "Compile all of pixelpath's kernels now and cache them in the per-user cache "
            "directory, so the first real command runs at full speed."
        ),
        examples=["pixelpath warmup"],
        run=run,
    )


def run(args: argparse.Namespace) -> int:
    """Compile and report how long it took and where the cache lives."""
    import pixelpath
    from pixelpath._jit import cache_dir

    start = time.perf_counter()
    count = pixelpath.warmup()
    elapsed = time.perf_counter() - start
    console().print(f"warmed up {count} kernel groups in {elapsed:.1f} s; cache: {cache_dir()}")
    return 0
