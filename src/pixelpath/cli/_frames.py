"""``pixelpath render --frames/--tiles/--workers/--scheduler/--resume``: several frames or tiles.

Everything is checked (frames, output pattern, tiles, options, the scheduler's address) before
any frame is rendered; then one progress bar runs over all frames (tiles count as parts).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import time
from collections.abc import Iterator
from typing import Any

from pixelpath.cli._common import (
    CommandError,
    compile_kernels,
    console,
    error_console,
    progress,
)
from pixelpath.frames.plan import available_cores

DASK_MISSING = "needs dask: pip install 'pixelpath[dask]'"

# Without --workers or --scheduler, a local cluster (one worker process per core, started in
# about 3 s) is used from this many tasks per core on; fewer render in this process.
TASKS_PER_CORE_FOR_A_CLUSTER = 4


def add_frame_options(parser: argparse.ArgumentParser) -> None:
    """Add the options for several frames, tiles and Dask clusters to ``render``."""
    group = parser.add_argument_group("many frames, tiles and clusters (Dask)")
    group.add_argument(
        "--frames",
        metavar="SPEC",
        help="frames of the scene's [animation] to render: 0:120 (120 excluded), 0:120:2, "
        "5, 1,4,9 or all; -o must then contain {frame}, e.g. out/f_{frame:04d}.png",
    )
    group.add_argument(
        "--turntable",
        type=int,
        metavar="N",
        help="orbit the camera once round the scene in N frames (for a scene without an "
        "[animation], such as a model file); renders them all unless --frames says otherwise",
    )
    group.add_argument(
        "--tiles",
        metavar="CxR",
        help="split each frame into COLUMNSxROWS tiles rendered in parallel and stitched "
        "(identical to the untiled image)",
    )
    group.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="start a local Dask cluster of N worker processes (default: one per core when "
        f"there are {TASKS_PER_CORE_FOR_A_CLUSTER}+ frames or tiles per core, else this process)",
    )
    group.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="send the work to the Dask scheduler at this address (tcp://host:8786)",
    )
    group.add_argument(
        "--png-level",
        type=parse_png_level,
        metavar="0-9",
        help=f"zlib compression of PNG files: {PNG_LEVELS} (default: 1 for --frames, 6 for a "
        "single image)",
    )
    group.add_argument(
        "--resume",
        action="store_true",
        help="skip frames whose file is already complete (each is read back to make sure)",
    )


# What --png-level's values do, for the commands that take it.
PNG_LEVELS = (
    "0 none, 1 fastest (at 640x400 7.7 ms a picture, files half as large again as at 6), "
    "6 (21 ms), 9 smallest and slowest"
)


def parse_png_level(text: str) -> int:
    """Return ``--png-level``: an int from 0 to 9.

    Examples
    --------
    >>> from pixelpath.cli._frames import parse_png_level
    >>> parse_png_level("1")
    1
    """
    if not text.strip().isdigit() or not 0 <= int(text) <= 9:
        raise argparse.ArgumentTypeError(f"must be a whole number from 0 to 9, got {text!r}")
    return int(text)


def wants_frames(args: argparse.Namespace) -> bool:
    """Return True when any of the frame options was given."""
    given = (args.frames, args.tiles, args.workers, args.scheduler, args.turntable)
    return args.resume or any(value is not None for value in given)


def run_frames(args: argparse.Namespace, scene: Any) -> int:
    """Render the requested frames (or tiles) and write them; return the exit status.

    On a first run the kernels compile first, on every core, into the kernel cache that this
    process and a local cluster's workers read (not for a cluster elsewhere, ``--scheduler``).
    """
    from pixelpath.frames import parse_frames, parse_tiles, plan_frames, run_plan
    from pixelpath.frames.plan import FRAMES_PNG_LEVEL
    from pixelpath.scene.texture import needs_lookups

    if args.explain:
        raise CommandError("--explain describes one image; leave out the frame options")
    if args.workers is not None and args.scheduler is not None:
        raise CommandError("give --workers (a local cluster) or --scheduler, not both")
    if args.workers is not None and args.workers < 1:
        raise CommandError(f"--workers must be at least 1, got {args.workers}")
    frames = [0] if args.frames is None else parse_frames(args.frames)
    tiles = (1, 1) if args.tiles is None else parse_tiles(args.tiles)
    if args.scheduler is None:  # before planning, whose check renders a pixel
        compile_kernels([args.method, args.style], [args.shading], quiet=args.quiet,
                        lookups=needs_lookups(scene.objects))
    plan = plan_frames(
        scene,
        frames,
        args.output,
        tiles=tiles,
        resume=args.resume,
        gamma=args.gamma,
        png_level=FRAMES_PNG_LEVEL if args.png_level is None else args.png_level,
        options=render_options(args),
    )
    start = time.perf_counter()
    with cluster_for(args, plan.jobs, plan.options, start) as client:
        rendering = time.perf_counter()
        label = f"rendering {len(plan.todo)} frame{'s' * (len(plan.todo) != 1)}"
        with progress(label, plan.jobs, quiet=args.quiet) as advance:
            run_plan(plan, client, advance)
        seconds = time.perf_counter() - rendering
    _summary(args, plan, seconds, since(start))
    return 0


@contextlib.contextmanager
def cluster_for(
    args: argparse.Namespace, jobs: int, options: dict[str, Any], start: float
) -> Iterator[Any]:
    """Yield the Dask client for ``jobs`` tasks, its workers warmed for ``options``, or None.

    None means "render in this process" (see :func:`_client`); a cluster started here is
    closed on leaving, and the time since ``start`` it took to get ready is reported.
    """
    client = _client(args, jobs) if jobs else None
    try:
        if client is not None:
            from pixelpath.frames.cluster import warm_workers

            warm_workers(client, options)
            _say(args, f"{_cluster_name(client)} ready, kernels warmed, in {since(start)}")
        yield client
    finally:
        if client is not None:
            client.close()


def since(start: float) -> str:
    """Return the seconds since ``start`` (a ``perf_counter`` reading), as ``'1.5 s'``."""
    return f"{time.perf_counter() - start:.1f} s"


def render_options(args: argparse.Namespace) -> dict[str, Any]:
    """Return the keywords of ``render`` that the command line set."""
    options = {
        "method": args.method,
        "shading": args.shading,
        "backface_cull": not args.no_cull,
        "ssaa": args.ssaa,
        "blinn": args.blinn,
        "style": args.style,
    }
    for name in ("max_depth", "samples", "fresnel"):  # the ray tracer's, when the command has them
        if getattr(args, name, None) is not None:
            options[name] = getattr(args, name)
    return options


def _client(args: argparse.Namespace, jobs: int) -> Any:
    """Return the Dask client to run on, or None to render in this process."""
    has_dask = importlib.util.find_spec("distributed") is not None
    if args.scheduler is not None or args.workers is not None:
        if not has_dask:
            option = "--scheduler" if args.scheduler is not None else "--workers"
            raise CommandError(f"{option} {DASK_MISSING}")
        from pixelpath.frames.cluster import connect, local_client

        if args.scheduler is not None:
            try:
                return connect(args.scheduler)
            except ConnectionError as exc:
                raise CommandError(str(exc)) from None
        return local_client(args.workers)
    cores = available_cores()
    if cores < 2 or jobs < TASKS_PER_CORE_FOR_A_CLUSTER * cores:
        return None  # Numba's threads already use every core; a cluster would not pay
    if not has_dask:
        _say(args, f"rendering in this process (parallel frames {DASK_MISSING})")
        return None
    from pixelpath.frames.cluster import local_client

    return local_client(cores)


def _cluster_name(client: Any) -> str:
    workers = len(client.scheduler_info()["workers"])
    return f"Dask cluster of {workers} worker{'s' * (workers != 1)} ({client.scheduler.address})"


def _say(args: argparse.Namespace, text: str) -> None:
    if not args.quiet:
        error_console().print(text)


def _summary(args: argparse.Namespace, plan: Any, seconds: float, total: str) -> None:
    if args.quiet:
        return
    count = len(plan.todo)
    rate = f" ({count / seconds:.1f} frames/s)" if count > 1 and seconds > 0 else ""
    skipped = f"; skipped {len(plan.skipped)} complete on disk" if plan.skipped else ""
    first = plan.paths[plan.frames[0]]
    where = first if len(plan.frames) == 1 else f"{first.parent}/"
    camera = plan.scene.camera
    console().print(
        f"wrote {count} frame{'s' * (count != 1)} to {where} ({camera.width}x{camera.height}, "
        f"{args.method}, {args.shading} shading) in {total}{rate}{skipped}"
    )
