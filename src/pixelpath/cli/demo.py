"""``pixelpath demo``: render the showcase scenes shipped inside the package."""

from __future__ import annotations

import argparse
import dataclasses
import time
from pathlib import Path
from typing import Any

from pixelpath.cli._common import CommandError, add_command, compile_kernels, console
from pixelpath.raster.shading import SHADINGS

METHODS_PICTURE_SIZE = (240, 150)  # each method's picture in methods.png


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
            "Then the showcase ray-traced (showcase-raytrace.png: shadows, a mirror, glass) "
            "and drawn by every hidden-surface method side by side (methods.png); --quick "
            "leaves these two out (their first run compiles every method's kernels once)."
        ),
        examples=[
            "pixelpath demo -o demo",
            "pixelpath demo -o demo --quick",
            "pixelpath demo -o demo --shading all --ssaa 2",
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
        "--quick", action="store_true",
        help="only the bundled scenes with the z-buffer (no ray tracing, no methods figure)",
    )
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")


def run(args: argparse.Namespace) -> int:
    """Render each bundled scene, then the ray-traced and the methods pictures; list the files."""
    from pixelpath.cli.render import load_scene_sized, render_to_file
    from pixelpath.scene import bundled_scenes
    from pixelpath.scene.texture import needs_lookups

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
    loaded = {name: load_scene_sized(str(path), args.size) for name, path in scenes.items()}
    compile_kernels([options.method], shadings, quiet=args.quiet, lookups=any(
        needs_lookups(scene.objects) for scene in loaded.values()))
    count = 0
    for name, scene in loaded.items():
        for shading in shadings:
            options.shading = shading
            output = folder / (f"{name}-{shading}.png" if len(shadings) > 1 else f"{name}.png")
            _, _, seconds = render_to_file(scene, output, options, f"{name} ({shading})")
            camera = scene.camera
            console().print(
                f"wrote {output} ({camera.width}x{camera.height}, {shading}) in {seconds:.2f} s"
            )
            count += 1
    if not args.quick:
        count += _showcase_extras(loaded["showcase"], folder, options)
    console().print(f"{count} images in {time.perf_counter() - start:.1f} s")
    return 0


def _showcase_extras(scene: Any, folder: Path, options: argparse.Namespace) -> int:
    """Ray-trace the showcase and draw it with every method side by side; return 2."""
    from pixelpath.cli.render import render_to_file
    from pixelpath.figures._canvas import save
    from pixelpath.figures.methods import methods_side_by_side
    from pixelpath.renderer import METHOD_NAMES
    from pixelpath.scene.texture import needs_lookups

    compile_kernels(METHOD_NAMES, ["phong"], quiet=options.quiet,  # both pictures: Phong
                    lookups=needs_lookups(scene.objects))
    traced = argparse.Namespace(
        **{**vars(options), "method": "raytrace", "shading": "phong", "ssaa": 1},
        samples=4, max_depth=5,
    )
    output = folder / "showcase-raytrace.png"
    _, _, seconds = render_to_file(scene, output, traced, "showcase (ray traced)")
    console().print(f"wrote {output} (ray traced, 4 samples, depth 5) in {seconds:.2f} s")
    began = time.perf_counter()
    small = dataclasses.replace(scene, camera=scene.camera.with_size(*METHODS_PICTURE_SIZE))
    output = save(methods_side_by_side(small, METHOD_NAMES), folder / "methods.png")
    console().print(
        f"wrote {output} (the showcase by each of {len(METHOD_NAMES)} methods) in "
        f"{time.perf_counter() - began:.2f} s"
    )
    return 2
