"""``pixelpath ray``: the tree of rays the ray tracer follows for one pixel."""

from __future__ import annotations

import argparse
from typing import Any

from pixelpath.cli._common import CommandError, add_command, console, error_console
from pixelpath.cli.render import add_model_options, load_scene_sized
from pixelpath.raster.shading import SHADINGS


def register(subparsers: Any) -> None:
    """Add the ``ray`` subcommand."""
    parser = add_command(
        subparsers,
        "ray",
        summary="trace one pixel and show its tree of rays (hits, shadows, reflection, refraction)",
        description=(
            "Trace the rays of one pixel of a scene file exactly as 'pixelpath render --method "
            "raytrace' does and print the pixel's colour, depth and object. --explain prints "
            "the whole tree: each ray with its origin and direction, each hit with t, point "
            "and normal (with the ray-sphere quadratic, its discriminant and roots where a "
            "sphere is hit), the local Phong terms and each light's shadow test, and the "
            "reflected and refracted rays with the weights that combine them. --figure draws "
            "the tree over the scene, seen by the scene's camera and from aside, each kind of "
            "ray in its colour (eye, shadow, reflected, refracted)."
        ),
        examples=[
            "pixelpath ray scene.toml --pixel 320,240 --explain",
            "pixelpath ray showcase --pixel 300,180 --max-depth 2 --explain",
            "pixelpath ray showcase --pixel 10,10 --size 64x40",
            "pixelpath ray showcase --pixel 272,256 --figure tree.png",
            "pixelpath ray part.stl --up z --size 320x240 --pixel 160,120 --explain",
        ],
        run=run,
    )
    parser.add_argument(
        "scene",
        help="a .toml scene file, a model file (.glb .gltf .obj .ply .stl) or a bundled scene",
    )
    parser.add_argument("--pixel", required=True, help="X,Y: column and row (row 0 at the top)")
    parser.add_argument("--size", help="image size WIDTHxHEIGHT (default: the scene camera's)")
    add_model_options(parser)
    parser.add_argument(
        "--shading", default="phong", choices=[s for s in SHADINGS if s != "gouraud"]
    )
    parser.add_argument("--samples", type=int, default=1, help="samples per pixel (default 1)")
    parser.add_argument(
        "--max-depth", type=int, default=5, help="reflection/refraction bounces (default 5)"
    )
    parser.add_argument("--fresnel", action="store_true", help="Schlick's Fresnel term for glass")
    parser.add_argument("--no-cull", action="store_true", help="eye rays see back faces too")
    parser.add_argument("--blinn", action="store_true", help="Blinn-Phong highlights")
    parser.add_argument("--explain", action="store_true", help="print the whole tree of rays")
    parser.add_argument(
        "--figure", metavar="PNG", help="draw the tree of rays over the scene (a PNG image)"
    )


def parse_pixel(text: str) -> tuple[int, int]:
    """Return (x, y) from ``X,Y``; raise CommandError on anything else.

    Examples
    --------
    >>> from pixelpath.cli.ray import parse_pixel
    >>> parse_pixel("320,240")
    (320, 240)
    """
    parts = text.split(",")
    if len(parts) != 2 or not all(part.strip().isdigit() for part in parts):
        raise CommandError(f"--pixel must look like 320,240 (column,row), got {text!r}")
    x, y = (int(part) for part in parts)
    return x, y


def run(args: argparse.Namespace) -> int:
    """Trace the pixel and print what it found."""
    from pixelpath.raytrace import ray_tree

    scene = load_scene_sized(args.scene, args.size, args.frame, args.up)
    tree = ray_tree(
        scene,
        parse_pixel(args.pixel),
        max_depth=args.max_depth,
        samples=args.samples,
        shading=args.shading,
        backface_cull=not args.no_cull,
        blinn=args.blinn,
        fresnel=args.fresnel,
    )
    out = console()
    if args.figure:
        _write_figure(tree, args.figure)
    if args.explain:
        out.print(str(tree), markup=False, highlight=False)
        return 0
    x, y = tree.pixel
    seen = f"object {tree.object}" if tree.object >= 0 else "the background"
    rgb = ", ".join(f"{c:.4g}" for c in tree.rgb)
    out.print(
        f"pixel ({x}, {y}): rgb ({rgb}), {seen} at depth {tree.depth:.6g}; {tree.rays} rays "
        "traced (--explain prints them)",
        markup=False,
        highlight=False,
    )
    return 0


def _write_figure(tree, path: str) -> None:
    from pixelpath.figures._canvas import save

    try:
        written = save(tree.figure(), path)
    except (ValueError, FileNotFoundError) as exc:  # a bad extension, no such folder
        raise CommandError(str(exc)) from None
    error_console().print(f"wrote {written}")
