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
            "directory, so the first real command runs at full speed. Prints, per kernel "
            "module, the seconds taken and how many specializations were compiled or loaded "
            "from the cache (a second run compiles nothing)."
        ),
        examples=["pixelpath warmup"],
        run=run,
    )


def run(args: argparse.Namespace) -> int:
    """Compile every kernel; print per kernel module the time and what compiled, and the cache."""
    from pixelpath._precompiled import cache_root, markers
    from pixelpath._warm import run_warmups

    start = time.perf_counter()
    reports = run_warmups(markers())
    total = time.perf_counter() - start
    out = console()
    out.print(f"{'kernel module':34s} {'seconds':>8s} {'compiled':>9s} {'from cache':>11s}")
    for report in reports:
        out.print(
            f"{report.module:34s} {report.seconds:8.1f} {report.compiled:9d} {report.loaded:11d}"
        )
    compiled = sum(report.compiled for report in reports)
    loaded = sum(report.loaded for report in reports)
    out.print(f"{'total (with imports)':34s} {total:8.1f} {compiled:9d} {loaded:11d}")
    folder = cache_root()
    out.print(
        f"warmed up {len(reports)} kernel modules in {total:.1f} s: {compiled} specializations "
        f"compiled, {loaded} loaded from the cache; cache: {folder or 'none (not writable)'}"
    )
    return 0
