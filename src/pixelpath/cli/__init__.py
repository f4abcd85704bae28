"""The ``pixelpath`` command line.

Each subcommand lives in its own module of this package with a ``register(subparsers)``
function; modules import their heavy dependencies inside the command body, so ``--help`` and
argument errors answer at once.
"""

from __future__ import annotations

import argparse
import atexit
import functools
import importlib
import logging
import os
import sys
import threading
import warnings
from collections.abc import Sequence
from typing import NoReturn

from rich.markup import escape

from pixelpath import __version__
from pixelpath.cli._common import CommandError, error_console

# Order shown by ``pixelpath --help``.
COMMANDS = (
    "demo", "render", "views", "ray", "info", "color", "clip", "phong", "exercise", "playground",
    "warmup",
)


def build_parser() -> argparse.ArgumentParser:
    """Return the argument parser with every subcommand registered."""
    parser = argparse.ArgumentParser(
        prog="pixelpath",
        description="The classic rendering pipeline of a graphics course, headless on the CPU.",
        epilog="Run 'pixelpath COMMAND --help' for a command's options and an example.",
    )
    parser.add_argument("--version", action="version", version=f"pixelpath {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMANDS:
        importlib.import_module(f"pixelpath.cli.{name}").register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the process exit status.

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments after the program name (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        0 on success, 1 when the command failed on valid arguments, 2 on bad input.

    Examples
    --------
    >>> from pixelpath.cli import main
    >>> main(["color", "255,255,0", "--to", "hsv"])  # doctest: +SKIP
    0
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 2
    shown = warnings.formatwarning
    # Warnings read like the errors ("pixelpath render: warning: ..."), without the source
    # line of pixelpath's that raised them, which a user of the command line has no use for.
    warnings.formatwarning = functools.partial(_warning_line, args.command)
    # trimesh logs a file it cannot read with a traceback (Python's last-resort handler prints
    # it) where pixelpath raises its own error naming the file: that error is shown alone.
    # A handler of the user's, on the root logger, still receives trimesh's records.
    quiet, trimesh_log = logging.NullHandler(), logging.getLogger("trimesh")
    trimesh_log.addHandler(quiet)
    try:
        return int(args.run(args) or 0)
    except (CommandError, ValueError, TypeError, FileNotFoundError) as exc:
        # escape: messages may hold brackets ("pixelpath[plot]") that are not rich markup.
        error_console().print(f"[bold red]pixelpath {args.command}: error:[/] {escape(str(exc))}")
        return 2
    except KeyboardInterrupt:
        return 130
    finally:
        warnings.formatwarning = shown
        trimesh_log.removeHandler(quiet)


def run() -> NoReturn:
    """Run the command line and end the process: the ``pixelpath`` command itself.

    :func:`main`, then an exit that skips Python's teardown of the interpreter. After a
    render that teardown, which frees the thousand modules, Numba's compiled kernels and LLVM
    that a render loads, took 0.2 s of a 0.9 s command (0.3 s after a first render that
    compiled its kernels), and frees nothing the system would not. The exit handlers still
    run and the output is flushed first; while threads other than pixelpath's idle pools
    still run, the process exits as usual, waiting for them. From Python, call :func:`main`,
    which returns.

    Examples
    --------
    >>> from pixelpath.cli import run
    >>> run()  # doctest: +SKIP
    """
    code = main()
    pools = sys.modules.get("pixelpath._threads")  # only there once something ran in threads
    if pools is not None:
        pools.stop_pools()
    main_thread = threading.main_thread()
    if any(not t.daemon for t in threading.enumerate() if t is not main_thread):
        sys.exit(code)
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe (pixelpath info | head): nothing to do
            pass
    os._exit(code)


def _warning_line(command: str, message: Warning | str, *_: object, **__: object) -> str:
    """Format a warning shown while ``command`` runs (``warnings.formatwarning``'s signature)."""
    return f"pixelpath {command}: warning: {message}\n"


if __name__ == "__main__":  # pragma: no cover
    run()
