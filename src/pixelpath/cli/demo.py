"""``pixelpath demo``: render the showcase scenes shipped inside the package."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

from pixelpath.cli._common import CommandError, add_command, compile_kernels, console
from pixelpath.raster.shading import SHADINGS


def register(subparsers: Any) -> None:
    """Add the ``demo`` subcommand."""
    parser = add_command(
        subparsers,
        "demo",
        summary="render the built-in showcase scenes (no input needed)",
        description=(
            "Render every scene bundled with pixelpath (procedural spheres, boxes, tori and "
            "icospheres on a floor; see 'pixelpath info showcase') with the z-buffer and write "
            "one PNG per scene into DIR (created if needed). '--shading all' writes one image "
            "per shading mode, named SCENE-flat.png, SCENE-gouraud.png, SCENE-phong.png. "
            "--raytrace also ray-traces each scene (SCENE-raytrace.png: shadows, mirror, glass); "
            "its first run compiles the ray tracer, which takes a while once."
        ),
        examples=[
            "pixelpath demo -o demo",
            "pixelpath demo -o demo --shading all --ssaa 2",
            "pixelpath demo -o demo --raytrace",
        ],
        run=run,
    )
    parser.add_argument("-o", "--output", required=True, metavar="DIR", help="folder to write")
    parser.add_argument(
        "--shading", default="phong", choices=(*SHADINGS, "all"), help="shading mode(s)"
    )
    parser.add_argument("--size", help="image size WIDTHxHEIGHT (default: each scene's own)")
    parser.add_argument("--ssaa", type=int, default=2, help="supersampling per side (default 2)")
    parser.add_argument(
        "--raytrace", action="store_true", help="also ray-trace each scene (4 samples, depth 5)"
    )
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")


def run(args: argparse.Namespace) -> int:
    """Render each bundled scene in the chosen shading mode(s); list the files written."""
    from pixelpath.cli.render import load_scene_sized, render_to_file
    from pixelpath.scene import bundled_scenes

    scenes = bundled_scenes()
    if not scenes:
        raise CommandError("no bundled scenes found: is pixelpath installed with its data files?")
    folder = Path(args.output)
    if folder.exists() and not folder.is_dir():
        raise CommandError(f"output must be a folder, but {folder} is a file")
    folder.mkdir(parents=True, exist_ok=True)
    shadings = SHADINGS if args.shading == "all" else (args.shading,)
    options = argparse.Namespace(
        method="zbuffer", ssaa=args.ssaa, no_cull=False, blinn=False, gamma=None, quiet=args.quiet
    )
    start = time.perf_counter()
    compile_kernels([options.method], quiet=args.quiet)
    for name, path in scenes.items():
        scene = load_scene_sized(str(path), args.size)
        for shading in shadings:
            options.shading = shading
            output = folder / (f"{name}-{shading}.png" if len(shadings) > 1 else f"{name}.png")
            _, _, seconds = render_to_file(scene, output, options, f"{name} ({shading})")
            camera = scene.camera
            console().print(
                f"wrote {output} ({camera.width}x{camera.height}, {shading}) in {seconds:.2f} s"
            )
        if args.raytrace:
            traced = argparse.Namespace(
                **{**vars(options), "method": "raytrace", "shading": "phong", "ssaa": 1},
                samples=4, max_depth=5,
            )
            output = folder / f"{name}-raytrace.png"
            _, _, seconds = render_to_file(scene, output, traced, f"{name} (ray traced)")
            console().print(f"wrote {output} (ray traced, 4 samples) in {seconds:.2f} s")
    count = len(scenes) * (len(shadings) + bool(args.raytrace))
    console().print(f"{count} images in {time.perf_counter() - start:.1f} s")
    return 0
