"""What a multi-frame render will do, decided and checked before any work starts.

:func:`plan_frames` turns the user's request (frames, output pattern, tiles, render options,
resume) into a :class:`FramePlan`: the frames still to render, where each is written, and the
tiles each is split into. Every mistake is a ``ValueError`` or ``TypeError`` raised here, so a
run never fails half-way on something that could have been seen at the start.
"""

from __future__ import annotations

import dataclasses
import itertools
import numbers
import os
import re
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

from pixelpath.scene import Scene

Region = tuple[int, int, int, int]

# PNG compression of many frames: Pillow at zlib's level 1 encodes a 640×400 showcase frame in
# 7.7 ms (91 kB) where Image.save's level 6 takes 21 ms (61 kB), twice as long as rendering
# it. A higher level (``png_level=6``, ``--png-level 6``) makes files a third smaller.
FRAMES_PNG_LEVEL = 1

# The render() options a frame may use; region, explain and progress belong to the run.
RENDER_OPTIONS = (
    "method",
    "shading",
    "backface_cull",
    "ssaa",
    "blinn",
    "style",
    "max_depth",
    "samples",
    "fresnel",
)


@dataclasses.dataclass(frozen=True)
class FramePlan:
    """A checked multi-frame render.

    Attributes
    ----------
    scene : Scene
        The (animated) scene; workers get it once and draw each frame with ``at_frame``.
    frames : tuple of int
        Every requested frame, in the order given.
    todo : tuple of int
        The frames to render: ``frames`` less those already complete on disk (``resume``).
    paths : dict of int to Path, or None
        The file of each frame, or None when images are returned instead.
    regions : tuple of (x0, y0, x1, y1)
        The tiles of a frame, row by row; one region, the whole image, when not tiled.
    options : dict
        Keyword arguments for :func:`pixelpath.render`.
    gamma : float, "srgb", "linear" or None
        Display encoding of the files (None: the scene's ``encoding``).
    png_level : int or None
        zlib compression level of PNG files, 0 to 9 (None: 6, as ``Image.save``).
    """

    scene: Scene
    frames: tuple[int, ...]
    todo: tuple[int, ...]
    paths: dict[int, Path] | None
    regions: tuple[Region, ...]
    options: dict[str, Any]
    gamma: float | str | None = None
    png_level: int | None = None

    @property
    def jobs(self) -> int:
        """Number of tasks: frames to render times tiles per frame."""
        return len(self.todo) * len(self.regions)

    @property
    def skipped(self) -> tuple[int, ...]:
        """Frames already complete on disk."""
        done = set(self.todo)
        return tuple(frame for frame in self.frames if frame not in done)


def plan_frames(
    scene: Scene,
    frames: Iterable[int] | None,
    out: str | os.PathLike | None = None,
    *,
    tiles: tuple[int, int] = (1, 1),
    resume: bool = False,
    gamma: float | None = None,
    png_level: int | None = FRAMES_PNG_LEVEL,
    options: dict[str, Any] | None = None,
) -> FramePlan:
    """Check a multi-frame request and return its :class:`FramePlan`.

    Parameters are those of :func:`pixelpath.render_frames`; ``options`` holds its render
    keywords. Render options are checked by rendering one pixel of the first frame here.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.frames import plan_frames
    >>> from pixelpath.scene import Turntable, Animation
    >>> scene = pp.Scene(
    ...     pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30),
    ...     [pp.Sphere((0, 0, 0), 1.0)],
    ...     animation=Animation(24, turntable=Turntable()),
    ... )
    >>> plan = plan_frames(scene, range(0, 24, 8), "spin_{frame:02d}.png", tiles=(2, 1))
    >>> plan.todo, plan.paths[16].name, plan.regions
    ((0, 8, 16), 'spin_16.png', ((0, 0, 20, 30), (20, 0, 40, 30)))
    """
    from pixelpath.io.images import png_level_of

    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a pixelpath Scene, got {type(scene).__name__}")
    chosen = frame_numbers(frames, scene)
    options = render_options(options or {})
    gamma = checked_gamma(gamma)
    png_level = None if png_level is None else png_level_of(png_level)
    paths = None if out is None else output_paths(out, chosen)
    if resume and paths is None:
        raise ValueError("resume=True needs out= (frames complete on disk are skipped)")
    camera = scene.camera
    regions = tile_regions(camera.width, camera.height, tiles)
    _check_render(scene, chosen[0], options)
    check_tile_size(regions, options.get("ssaa", 1))
    todo = chosen
    if resume:
        todo = tuple(
            frame
            for frame in chosen
            if not frame_is_complete(paths[frame], camera.width, camera.height)
        )
    return FramePlan(scene, chosen, todo, paths, regions, options, gamma, png_level)


def parse_frames(text: str) -> list[int] | None:
    """Read the ``--frames`` syntax: ``all``, ``N``, ``START:STOP[:STEP]``, comma-separated.

    ``START:STOP`` is a Python range (STOP excluded); ``all`` gives None, which
    :func:`frame_numbers` reads as every frame of the animation.

    Examples
    --------
    >>> from pixelpath.frames import parse_frames
    >>> parse_frames("0:5"), parse_frames("3,10:16:2"), parse_frames("all")
    ([0, 1, 2, 3, 4], [3, 10, 12, 14], None)
    """
    text = text.strip()
    if text == "all":
        return None
    result: list[int] = []
    for part in text.split(","):
        match = re.fullmatch(r"\s*(\d+)\s*(?::\s*(\d+)\s*(?::\s*(\d+)\s*)?)?", part)
        if match is None:
            raise ValueError(
                f"--frames must look like 0:120, 0:120:2, 5 or 1,4,9 (or 'all'), got {text!r}"
            )
        start, stop, step = match.groups()
        if stop is None:
            result.append(int(start))
            continue
        if step is not None and int(step) == 0:
            raise ValueError(f"--frames: the step must be at least 1, got {part.strip()!r}")
        span = range(int(start), int(stop), int(step or 1))
        if not span:
            raise ValueError(f"--frames: {part.strip()!r} holds no frame (STOP is excluded)")
        result.extend(span)
    return result


def frame_numbers(frames: Iterable[int] | None, scene: Scene) -> tuple[int, ...]:
    """Return ``frames`` as a tuple of distinct ints inside the scene's animation.

    ``None`` means every frame of the animation (frame 0 alone for a scene without one). Each
    frame's camera is built here, so a camera the animation makes invalid is found now.
    """
    animation = scene.animation
    if frames is None:
        return tuple(range(animation.frames if animation is not None else 1))
    if isinstance(frames, numbers.Integral | str | bytes) or not isinstance(frames, Iterable):
        raise TypeError(
            f"frames must be a sequence of frame numbers such as range(120) (or [5] for one "
            f"frame), got {frames!r}"
        )
    result = []
    seen: set[int] = set()
    for frame in frames:
        if isinstance(frame, bool) or not isinstance(frame, numbers.Integral):
            raise TypeError(f"frames must hold ints, got {frame!r}")
        frame = int(frame)
        if frame in seen:
            raise ValueError(f"frame {frame} is listed twice (each frame is rendered once)")
        seen.add(frame)
        result.append(frame)
    if not result:
        raise ValueError("frames is empty: nothing to render")
    for frame in result:
        try:
            scene.camera_at(frame)
        except ValueError as exc:
            raise ValueError(f"frames: {exc}") from None
    return tuple(result)


def output_paths(out: str | os.PathLike, frames: tuple[int, ...]) -> dict[int, Path]:
    """Return the file of each frame: ``out`` formatted with ``frame=`` (``{frame:04d}``).

    Examples
    --------
    >>> from pixelpath.frames.plan import output_paths
    >>> output_paths("out/f_{frame:03d}.png", (7,))[7].as_posix()
    'out/f_007.png'
    """
    from pixelpath.io.images import image_format

    pattern = os.fspath(out)
    if not isinstance(pattern, str):
        raise TypeError(f"out must be a str or path, got {type(out).__name__}")
    try:
        paths = {frame: Path(pattern.format(frame=frame)) for frame in frames}
    except (KeyError, IndexError, ValueError, AttributeError) as exc:
        raise ValueError(
            f"out {pattern!r} is not a valid pattern: only {{frame}} may be used, with an "
            f"optional format such as {{frame:04d}} ({type(exc).__name__}: {exc})"
        ) from None
    if len(set(paths.values())) < len(frames):
        raise ValueError(
            f"out {pattern!r} gives the same file for several frames: put {{frame}} in it, "
            f"e.g. out/frame_{{frame:04d}}.png"
        )
    for path in paths.values():
        image_format(path.suffix)
        if path.exists() and not path.is_file():
            raise ValueError(f"out: {path} exists and is not a file")
    return paths


def parse_tiles(text: str) -> tuple[int, int]:
    """Read ``--tiles COLUMNSxROWS`` (``4x4``).

    Examples
    --------
    >>> from pixelpath.frames import parse_tiles
    >>> parse_tiles("4x2")
    (4, 2)
    """
    match = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", text)
    if match is None:
        raise ValueError(f"--tiles must look like 4x4 (COLUMNSxROWS), got {text!r}")
    return int(match[1]), int(match[2])


def tile_regions(width: int, height: int, tiles: Any) -> tuple[Region, ...]:
    """Split a ``width × height`` image into ``(columns, rows)`` tiles of near-equal size.

    Raises
    ------
    ValueError
        When a tile would be less than one pixel wide or high.

    Examples
    --------
    >>> from pixelpath.frames import tile_regions
    >>> tile_regions(5, 2, (2, 1))
    ((0, 0, 2, 2), (2, 0, 5, 2))
    """
    try:
        columns, rows = tiles
    except (TypeError, ValueError):
        raise TypeError(f"tiles must be (columns, rows), got {tiles!r}") from None
    for name, count, side, axis in (
        ("columns", columns, width, "wide"),
        ("rows", rows, height, "high"),
    ):
        if isinstance(count, bool) or not isinstance(count, numbers.Integral):
            raise TypeError(f"tiles {name} must be an int, got {count!r}")
        if not 1 <= count <= side:
            raise ValueError(
                f"tiles: {count} {name} do not divide a {width}x{height} image into tiles at "
                f"least one pixel {axis} (use 1..{side} {name})"
            )
    xs = np.linspace(0, width, int(columns) + 1).round().astype(int).tolist()
    ys = np.linspace(0, height, int(rows) + 1).round().astype(int).tolist()
    return tuple(
        (x0, y0, x1, y1) for y0, y1 in itertools.pairwise(ys) for x0, x1 in itertools.pairwise(xs)
    )


def frame_is_complete(path: Path, width: int, height: int) -> bool:
    """Return True when ``path`` is a whole, readable image of ``width × height`` pixels.

    The file is decoded in full (a truncated or corrupt file fails), not just looked up by name.
    """
    from PIL import Image as PILImage

    if not path.is_file():
        return False
    try:
        with PILImage.open(path) as image:
            image.verify()  # checksums and structure
        with PILImage.open(path) as image:
            image.load()  # every pixel decodes
            return image.size == (width, height)
    except (OSError, SyntaxError, ValueError):  # what Pillow raises for broken files
        return False


def available_cores() -> int:
    """Return the number of cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def render_options(options: dict[str, Any]) -> dict[str, Any]:
    """Return the render keywords after checking their names (values are checked by render)."""
    unknown = sorted(set(options) - set(RENDER_OPTIONS))
    if unknown:
        raise TypeError(
            f"unknown render option(s) {', '.join(unknown)}; frames take "
            f"{', '.join(RENDER_OPTIONS)}"
        )
    return dict(options)


def checked_gamma(gamma: Any) -> float | str | None:
    """Return ``gamma`` (None, ``"srgb"``, ``"linear"`` or a positive float) or raise."""
    if gamma is None or gamma in ("srgb", "linear"):
        return gamma
    if isinstance(gamma, bool) or not isinstance(gamma, numbers.Real) or not gamma > 0:
        raise ValueError(f"gamma must be a positive number, 'srgb' or 'linear', got {gamma!r}")
    return float(gamma)


def check_tile_size(
    regions: tuple[Region, ...], ssaa: int, what: str = "tile", advice: str = ""
) -> None:
    """Refuse frames (or tiles) too large for one render, pointing at ``tiles`` (or ``advice``)."""
    from pixelpath.renderer import MAX_SAMPLES

    x0, y0, x1, y1 = max(regions, key=lambda r: (r[2] - r[0]) * (r[3] - r[1]))
    samples = (x1 - x0) * (y1 - y0) * ssaa * ssaa
    if samples > MAX_SAMPLES:
        raise ValueError(
            f"a {x1 - x0}x{y1 - y0} {what} with ssaa={ssaa} is {samples:,} samples, more than "
            f"the {MAX_SAMPLES:,} one render may hold; "
            f"{advice or 'split the frame into more tiles'}"
        )


def _check_render(scene: Scene, frame: int, options: dict[str, Any]) -> None:
    """Render one pixel of ``frame`` with ``options``: every option is checked by render."""
    from pixelpath.renderer import render

    render(scene.at_frame(frame), region=(0, 0, 1, 1), **options)
