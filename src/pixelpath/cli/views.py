"""``pixelpath views``: a dataset of views of a model (images, depth, normals, masks, poses)."""

from __future__ import annotations

import argparse
import functools
import time
from typing import Any

from pixelpath.cli._common import CommandError, add_command, compile_kernels, console, progress
from pixelpath.cli._frames import (
    PNG_LEVELS,
    cluster_for,
    parse_png_level,
    render_options,
    since,
)
from pixelpath.cli.render import (
    add_shading_options,
    add_up_option,
    parse_aovs_option,
    parse_size,
    scene_path,
)
from pixelpath.frames.plan import FRAMES_PNG_LEVEL
from pixelpath.frames.poses import LAYOUTS
from pixelpath.frames.views import VIEW_AOVS


def register(subparsers: Any) -> None:
    """Add the ``views`` subcommand."""
    parser = add_command(
        subparsers,
        "views",
        summary="render a dataset of views of a model: images, depth, normals, masks, poses",
        description=(
            "Render N views of a model file (glTF/GLB, OBJ+MTL, PLY, STL) or scene file into "
            "DIR in the layout NeRF, nerfstudio and instant-ngp read: images/, the buffers "
            "asked for with --aov (depth/ as float32 .npy, normals/ and masks/ as PNG) and "
            "transforms.json (intrinsics, and each view's camera-to-world matrix in OpenGL "
            "axes), written last. Cameras look at the model's centre, all at one distance "
            "that frames it in every view, in the model's own coordinates. Views render on a "
            "local Dask cluster (one worker a core) when there are enough of them, or on "
            "--workers N / --scheduler ADDRESS; the files are the same bytes either way."
        ),
        examples=[
            "pixelpath views Duck.glb -o duck_views",
            "pixelpath views Duck.glb -o duck_views -n 100 --size 800x800 "
            "--aov depth,normal,mask --transparent",
            "pixelpath views model.obj -o data --layout sphere -n 200 --workers 2",
            "pixelpath views model.glb -o data --layout random --seed 7 --method raytrace",
            "pixelpath views model.glb -o data -n 1000 --scheduler tcp://host:8786 --resume",
        ],
        run=run,
    )
    parser.add_argument("model", help="a model file (.glb .gltf .obj .ply .stl) or scene file")
    parser.add_argument("-o", "--output", required=True, metavar="DIR", help="dataset folder")
    parser.add_argument("-n", "--views", type=int, default=100, help="number of views (100)")
    parser.add_argument("--size", default="800x800", help="WIDTHxHEIGHT (default 800x800)")
    parser.add_argument(
        "--layout",
        default="orbit",
        choices=LAYOUTS,
        help="orbit: evenly round at one elevation; sphere: a Fibonacci sphere; random: "
        "seeded, uniform (sphere and random: upper hemisphere unless --full-sphere)",
    )
    add_up_option(parser)
    parser.add_argument("--seed", type=int, default=0, help="seed of the random layout (0)")
    parser.add_argument(
        "--elevation", type=float, help="the orbit's degrees above the horizon (default 22)"
    )
    parser.add_argument(
        "--full-sphere", action="store_true", help="sphere/random: views from below too"
    )
    parser.add_argument(
        "--distance",
        type=float,
        help="cameras' distance from the model's centre, in its units (default: framed)",
    )
    parser.add_argument("--fov", type=float, help="vertical field of view, degrees (default 45)")
    parser.add_argument(
        "--aov",
        type=functools.partial(parse_aovs_option, allowed=VIEW_AOVS),
        default=(),
        metavar="LIST",
        help=f"also write, comma-separated: {', '.join(VIEW_AOVS)}",
    )
    add_shading_options(parser)
    parser.add_argument(
        "--transparent", action="store_true", help="RGBA images, the background transparent"
    )
    parser.add_argument(
        "--png-level",
        type=parse_png_level,
        default=FRAMES_PNG_LEVEL,
        metavar="0-9",
        help=f"zlib compression of the PNG files: {PNG_LEVELS} (default: 1)",
    )
    cluster = parser.add_argument_group("clusters (Dask) and reruns")
    cluster.add_argument(
        "--workers", type=int, metavar="N", help="a local Dask cluster of N worker processes"
    )
    cluster.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="the Dask scheduler to use (tcp://host:8786); its workers must see DIR",
    )
    cluster.add_argument(
        "--resume", action="store_true", help="keep the views already complete in DIR"
    )
    cluster.add_argument(
        "--overwrite", action="store_true", help="replace the dataset already in DIR"
    )
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar or summary")
    parser.set_defaults(style="filled")


def run(args: argparse.Namespace) -> int:
    """Plan the dataset, render its views (here or on a cluster), write transforms.json."""
    from pixelpath.frames.views import plan_views, run_views
    from pixelpath.scene import load_scene
    from pixelpath.scene.texture import needs_lookups

    if args.workers is not None and args.scheduler is not None:
        raise CommandError("give --workers (a local cluster) or --scheduler, not both")
    if args.workers is not None and args.workers < 1:
        raise CommandError(f"--workers must be at least 1, got {args.workers}")
    start = time.perf_counter()
    source = scene_path(args.model)
    # before planning, whose check renders a pixel: the model is read for this on a first run
    compile_kernels([args.method], [args.shading], quiet=args.quiet,
                    lookups=lambda: needs_lookups(load_scene(source).objects))
    plan = plan_views(
        source,
        args.views,
        args.output,
        args.aov,
        layout=args.layout,
        seed=args.seed,
        elevation=args.elevation,
        hemisphere=not args.full_sphere,
        distance=args.distance,
        size=parse_size(args.size),
        fov=args.fov,
        transparent=args.transparent,
        gamma=args.gamma,
        png_level=args.png_level,
        resume=args.resume,
        overwrite=args.overwrite,
        up="+y" if args.up is None else args.up,
        options=render_options(args),
    )
    count = len(plan.todo)
    with cluster_for(args, count, plan.job.options, start) as client:
        rendering = time.perf_counter()
        with progress(f"rendering {count} views", count, quiet=args.quiet) as advance:
            path = run_views(plan, client, advance)
        seconds = time.perf_counter() - rendering
    if not args.quiet:
        skipped = len(plan.job.cameras) - count
        rate = f" ({count / seconds:.1f} views/s)" if count > 1 and seconds > 0 else ""
        kept = f"; kept {skipped} complete on disk" if skipped else ""
        width, height = plan.job.cameras.size
        console().print(
            f"wrote {count} view{'s' * (count != 1)} and {path} ({width}x{height}, "
            f"{args.method}) in {since(start)}{rate}{kept}"
        )
    return 0
