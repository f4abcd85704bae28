"""``pixelpath render``: render a scene file to an image."""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path
from typing import Any

from pixelpath.cli._common import (
    CommandError,
    add_command,
    compile_kernels,
    console,
    progress,
)
from pixelpath.cli._frames import add_frame_options, run_frames, wants_frames
from pixelpath.figures import DRAWN_METHODS
from pixelpath.io.aovs import AOVS, parse_aovs, write_aovs
from pixelpath.io.images import image_format
from pixelpath.io.models import MODEL_FORMATS
from pixelpath.raster.shading import SHADINGS
from pixelpath.renderer import METHOD_NAMES, STYLES


def register(subparsers: Any) -> None:
    """Add the ``render`` subcommand."""
    parser = add_command(
        subparsers,
        "render",
        summary="render a scene or model file to an image (any hidden-surface method, ray tracing)",
        description=(
            "Render a scene file with a hidden-surface method and a shading mode and write the "
            "image (PNG, JPEG, ... by extension; written atomically). SCENE may also name a "
            "model file (glTF/GLB, OBJ+MTL, PLY, STL: its camera and lights, or a camera "
            "framing it and a light rig) or a bundled demo scene. The camera's size comes from "
            "the file unless --size is given. "
            "--explain prints what the method did (per scan line, per subdivision level, ...). "
            "--figure and --animate draw it: the z-buffer and the scan-line method filling "
            "the image, Warnock's areas coloured by how each was decided, the painter's and "
            "the BSP tree's drawing order (with the tree), level by level or polygon by "
            "polygon (filled style, no --ssaa)."
        ),
        examples=[
            "pixelpath render scene.toml -o out.png",
            "pixelpath render Duck.glb -o duck.png --size 1024x768",
            "pixelpath render scene.toml -o out.png --method zbuffer --shading phong "
            "--size 1024x768",
            "pixelpath render showcase -o flat.png --shading flat --ssaa 2",
            "pixelpath render showcase -o lines.png --style hidden-line --method bsp --explain",
            "pixelpath render showcase -o out.png --size 160x120 --method warnock --explain "
            "--figure warnock.png --animate levels.gif",
            "pixelpath render scene.toml -o out.png --method painter --animate order.gif",
            "pixelpath render showcase -o traced.png --method raytrace --samples 4 --max-depth 5",
            'pixelpath render showcase --frames 0:120 -o "spin/f_{frame:03d}.png"',
            "pixelpath render scene.toml -o poster.png --size 8192x8192 --tiles 4x4 --workers 2",
            'pixelpath render scene.toml --frames all -o "out/f_{frame:04d}.png" '
            "--scheduler tcp://host:8786 --resume",
        ],
        run=run,
    )
    parser.add_argument(
        "scene",
        help="a .toml scene file, a model file (.glb .gltf .obj .ply .stl) or a bundled scene",
    )
    parser.add_argument("-o", "--output", required=True, help="image file to write (.png, ...)")
    add_shading_options(parser)
    parser.add_argument(
        "--style",
        default="filled",
        choices=STYLES,
        help="filled surfaces, every edge (wireframe) or only the visible edges (hidden-line)",
    )
    parser.add_argument("--size", help="image size WIDTHxHEIGHT (default: the scene camera's)")
    add_model_options(parser)
    parser.add_argument(
        "--transparent",
        action="store_true",
        help="write RGBA (PNG): the background transparent, edges (with --ssaa) partly",
    )
    parser.add_argument(
        "--aov",
        type=parse_aovs_option,
        default=(),
        metavar="LIST",
        help=f"also write these buffers beside the image, comma-separated ({', '.join(AOVS)}): "
        "depth as .npy, the others as PNG",
    )
    tracing = parser.add_argument_group("ray tracing (--method raytrace)")
    tracing.add_argument(
        "--samples", type=int, default=1, help="stratified, seeded samples per pixel (default 1)"
    )
    tracing.add_argument(
        "--max-depth",
        type=int,
        default=5,
        help="reflection/refraction bounces followed (default 5; 0 = local light only)",
    )
    tracing.add_argument(
        "--fresnel", action="store_true", help="split glass's light by Schlick's Fresnel term"
    )
    parser.add_argument(
        "--explain",
        action="store_true",
        help="print what the method did: pipeline counts, then the method's own steps",
    )
    figures = parser.add_argument_group(
        "figures (from what the method did; filled style, no --ssaa)"
    )
    figures.add_argument(
        "--figure",
        metavar="PNG",
        help=f"draw the method's figure ({', '.join(DRAWN_METHODS)})",
    )
    figures.add_argument(
        "--animate",
        metavar="GIF",
        help=f"write the method's animation, one frame per band, line group, level, polygon "
        f"or node ({', '.join(DRAWN_METHODS)})",
    )
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar or summary")
    add_frame_options(parser)


def add_shading_options(parser: argparse.ArgumentParser) -> None:
    """Add how pictures are drawn and encoded (``render`` and ``views`` share them)."""
    parser.add_argument(
        "--method", default="zbuffer", choices=METHOD_NAMES, help="hidden-surface method"
    )
    parser.add_argument("--shading", default="phong", choices=SHADINGS, help="shading mode")
    parser.add_argument("--ssaa", type=int, default=1, help="supersampling per side (1 = none)")
    parser.add_argument("--no-cull", action="store_true", help="draw back faces too (two-sided)")
    parser.add_argument("--blinn", action="store_true", help="Blinn-Phong highlights")
    parser.add_argument(
        "--gamma",
        type=parse_gamma,
        help="encode with this display gamma (e.g. 2.2), 'srgb' or 'linear' (default: the "
        "scene's encoding: sRGB for model files, linear for scene files)",
    )


def parse_size(text: str) -> tuple[int, int]:
    """Return (width, height) from ``WIDTHxHEIGHT``; raise CommandError on anything else.

    Examples
    --------
    >>> from pixelpath.cli.render import parse_size
    >>> parse_size("1024x768")
    (1024, 768)
    """
    parts = text.lower().split("x")
    if len(parts) != 2 or not all(part.strip().isdigit() for part in parts):
        raise CommandError(f"--size must look like 1024x768 (WIDTHxHEIGHT), got {text!r}")
    width, height = (int(part) for part in parts)
    return width, height


def parse_gamma(text: str) -> float | str:
    """Return ``--gamma``: a positive number, ``"srgb"`` or ``"linear"``.

    Examples
    --------
    >>> from pixelpath.cli.render import parse_gamma
    >>> parse_gamma("2.2"), parse_gamma("sRGB")
    (2.2, 'srgb')
    """
    if text.strip().lower() in ("srgb", "linear"):
        return text.strip().lower()
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not value > 0 or not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a positive number, srgb or linear: {text!r}")
    return value


def parse_aovs_option(text: str, allowed: tuple[str, ...] = AOVS) -> tuple[str, ...]:
    """Return the AOV names of ``--aov`` (argparse reports a bad one as a usage error)."""
    try:
        return parse_aovs(text, allowed)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def scene_path(name: str) -> Path:
    """Return the scene file ``name``, else the bundled scene of that name, else raise."""
    from pixelpath.scene import bundled_scenes

    path = Path(name)
    if path.exists():
        return path
    bundled = bundled_scenes()
    if name in bundled:
        return bundled[name]
    names = ", ".join(bundled) or "none"
    raise FileNotFoundError(f"scene file not found: {path} (bundled scenes: {names})")


def add_model_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--frame`` and ``--up``, which say how a model file is read and framed.

    ``render``, ``ray`` and ``info`` take both, so that one pixel of a picture can be traced,
    and its camera printed, from the scene the picture was rendered from.
    """
    parser.add_argument(
        "--frame",
        action="store_true",
        help="model files: frame the whole model from the front, even if the file has a camera",
    )
    add_up_option(parser)


def add_up_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--up``, a model file's up axis."""
    parser.add_argument(
        "--up",
        type=parse_up_option,
        metavar="AXIS",
        help="model files: the file's up axis, turned to point up before framing: y (the "
        "default, glTF's), z (most CAD and 3D-printing files), x, or --up=-z and so on",
    )


def parse_up_option(text: str) -> str:
    """Return ``--up`` as an axis of :data:`~pixelpath.io.models.UP_AXES` (a usage error if not)."""
    from pixelpath.io.models import up_axis

    try:
        return up_axis(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def load_scene_sized(
    name: str, size: str | None, frame: bool = False, up: str | None = None
) -> Any:
    """Load the scene file (or bundled scene) and apply ``--size`` (and ``--frame``, ``--up``)."""
    import dataclasses

    from pixelpath.scene import load_scene

    path = scene_path(name)
    model = path.suffix.lower() in MODEL_FORMATS
    for option, given in (("--frame", frame), ("--up", up is not None)):
        if given and not model:
            raise CommandError(f"{option} applies to model files (.glb .gltf .obj .ply .stl)")
    if model and (size is not None or frame or up is not None):
        from pixelpath.io.models import read_model

        sides = None if size is None else parse_size(size)
        if sides is not None and not all(1 <= side <= 16384 for side in sides):
            raise CommandError(f"--size {size}: each side must lie in 1..16384")
        # framed for this size, not cropped
        return read_model(path, size=sides, frame=frame, up="+y" if up is None else up)
    scene = load_scene(path)
    if size is not None:
        width, height = parse_size(size)
        try:
            camera = scene.camera.with_size(width, height)
        except ValueError as exc:
            raise CommandError(f"--size {size}: {exc}") from None
        scene = dataclasses.replace(scene, camera=camera)
    return scene


def render_to_file(
    scene: Any, output: Path, args: argparse.Namespace, label: str
) -> tuple[Any, Any, float]:
    """Render with the options in ``args``, showing progress; write ``output``.

    Returns the image, the method's report (``None`` unless ``args.explain``) and the seconds
    it took.
    """
    from pixelpath.renderer import render, render_steps
    from pixelpath.scene.texture import needs_lookups

    if not output.parent.is_dir():
        raise CommandError(f"output directory does not exist: {output.parent}")
    alpha = getattr(args, "transparent", False)
    try:  # before rendering: a long render should not end in "unknown extension"
        image_format(output.suffix, alpha=alpha)
    except ValueError as exc:
        raise CommandError(str(exc)) from None
    steps = render_steps(args.method)
    compile_kernels(
        [args.method, getattr(args, "style", "filled")], [args.shading],
        lookups=needs_lookups(scene.objects), quiet=args.quiet,
    )
    start = time.perf_counter()
    explain = getattr(args, "explain", False) or wants_figures(args)
    with progress(f"rendering {label}", steps, quiet=args.quiet) as advance:
        result = render(
            scene,
            method=args.method,
            shading=args.shading,
            backface_cull=not args.no_cull,
            ssaa=args.ssaa,
            blinn=args.blinn,
            style=getattr(args, "style", "filled"),
            explain=explain,
            progress=advance,
            max_depth=getattr(args, "max_depth", 5),
            samples=getattr(args, "samples", 1),
            fresnel=getattr(args, "fresnel", False),
        )
    image, report = result if explain else (result, None)
    png_level = getattr(args, "png_level", None)
    if png_level is None:
        image.save(output, gamma=args.gamma, alpha=alpha)
    else:  # the bytes Image.save writes, at another level of compression
        from pixelpath.frames.work import encode
        from pixelpath.io.images import write_bytes

        write_bytes(output, encode(image, output.suffix, args.gamma, alpha, png_level))
    for path in write_aovs(image, output, getattr(args, "aov", ()), png_level):
        if not args.quiet:
            console().print(f"wrote {path}")
    return image, report, time.perf_counter() - start


def run(args: argparse.Namespace) -> int:
    """Render the scene and write the image."""
    scene = load_scene_sized(args.scene, args.size, args.frame, args.up)
    check_figures(args)
    if args.turntable is not None:
        scene = with_turntable(scene, args.turntable)
        args.frames = args.frames or "all"
    if wants_frames(args):
        if args.transparent or args.aov:
            raise CommandError("--transparent and --aov write one image's files for now; "
                               "leave out the frame options")
        return run_frames(args, scene)
    output = Path(args.output)
    image, report, elapsed = render_to_file(scene, output, args, Path(args.scene).stem)
    if report is not None and args.explain:
        explain(scene, image, report, args)
    if report is not None:
        write_figures(report, args)
    if not args.quiet:
        camera = scene.camera
        console().print(
            f"wrote {output} ({camera.width}x{camera.height}, {args.method}, {args.shading} "
            f"shading) in {elapsed:.2f} s"
        )
        hint = empty_image_hint(image, args.no_cull)
        if hint is not None:
            console().print(hint)
    return 0


def empty_image_hint(image: Any, drew_back_faces: bool) -> str | None:
    """Say why a picture shows only background and what to try; None when it shows a surface.

    An open surface (a single-sided sheet, a cut-away part) seen from behind is culled away
    entirely, which looks like a failed render rather than a culled one.
    """
    if (image.object_id >= 0).any():
        return None
    hint = "nothing was drawn: no surface lies in the camera's view"
    if drew_back_faces:
        return hint
    return hint + ", or every surface in it faces away from the camera (--no-cull draws back faces)"


def with_turntable(scene: Any, frames: int) -> Any:
    """Return ``scene`` animated by one turn of the camera round it in ``frames`` frames.

    Examples
    --------
    >>> from pixelpath.cli.render import with_turntable
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), [Box((-1, -1, -1), (1, 1, 1))])
    >>> with_turntable(scene, 4).camera_at(1).eye.round(9).tolist()
    [5.0, 0.0, 0.0]
    """
    import dataclasses

    from pixelpath.scene import Animation, Turntable

    if scene.animation is not None:
        raise CommandError("--turntable: the scene has an [animation] of its own; use --frames")
    if frames < 1:
        raise CommandError(f"--turntable needs at least one frame, got {frames}")
    try:
        return dataclasses.replace(scene, animation=Animation(frames, turntable=Turntable()))
    except ValueError as exc:  # nothing bounded to orbit
        raise CommandError(f"--turntable: {exc}") from None


def wants_figures(args: argparse.Namespace) -> bool:
    """Whether the command asks for a figure or an animation of the method."""
    return bool(getattr(args, "figure", None) or getattr(args, "animate", None))


def check_figures(args: argparse.Namespace) -> None:
    """Refuse, before rendering, figures the method does not have or cannot draw."""
    if not wants_figures(args):
        return
    from pixelpath.figures.methods import METHOD_ANIMATIONS, METHOD_FIGURES

    for option, table, what in (("--figure", METHOD_FIGURES, "figure"),
                                ("--animate", METHOD_ANIMATIONS, "animation")):
        if not getattr(args, option[2:]):
            continue
        if args.method not in table:
            hint = ("; for a pixel's ray tree: pixelpath ray SCENE --pixel X,Y --figure "
                    "tree.png" if args.method == "raytrace" else "")
            raise CommandError(f"{option}: method {args.method!r} has no {what} (these do: "
                               f"{', '.join(table)}){hint}")
        if args.ssaa != 1:
            raise CommandError(f"{option} draws over the image at its own size: leave out "
                               "--ssaa")
        if args.style != "filled":
            raise CommandError(f"{option} draws the filled style: leave out --style")
        if wants_frames(args):
            raise CommandError(f"{option} draws one image; leave out the frame options")
    if args.animate and Path(args.animate).suffix.lower() != ".gif":
        raise CommandError(f"--animate writes a GIF: give a .gif path, got {args.animate!r}")


def write_figures(report: Any, args: argparse.Namespace) -> None:
    """Write the figure and the animation asked for."""
    from pixelpath.figures._canvas import save

    for path, write in ((args.figure, lambda p: save(report.figure(), p)),
                        (args.animate, report.animate)):
        if not path:
            continue
        try:
            written = write(path)
        except (ValueError, FileNotFoundError) as exc:  # a bad extension, no such folder
            raise CommandError(str(exc)) from None
        if not args.quiet:
            console().print(f"wrote {written}")


def explain(scene: Any, image: Any, report: Any, args: argparse.Namespace) -> None:
    """Print the method's report: its counts, then each of its tables."""
    from rich.table import Table

    summary = Table(title=f"{report.method}, {args.shading} shading", title_justify="left")
    summary.add_column("stage")
    summary.add_column("count", justify="right")
    summary.add_row("objects", str(len(scene.objects)))
    for name, value in report.summary.items():
        summary.add_row(name, _cell(value))
    drawn = int((image.object_id >= 0).sum())
    summary.add_row("pixels covered", f"{drawn:,} of {image.width * image.height:,}")
    if drawn:
        finite = image.depth[image.object_id >= 0]
        summary.add_row("depth range", f"{finite.min():.4g} .. {finite.max():.4g}")
    out = console()
    out.print(summary)
    for note in report.notes:
        out.print(f"[dim]{note}[/]")
    for steps in report.tables:
        table = Table(title=steps.title, title_justify="left")
        for column in steps.columns:
            table.add_column(column, justify="right")
        for row in steps.rows:
            table.add_row(*(_cell(value) for value in row))
        out.print(table)


def _cell(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, int) and not isinstance(value, bool):
        return f"{value:,}"
    return str(value)
