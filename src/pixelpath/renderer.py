"""``pixelpath.render()``: draw a scene with one of the notes' hidden-surface methods.

Every raster method shares one pipeline (:mod:`pixelpath.hsr.pipeline`): the same front end
(tessellation, back-face culling, frustum clipping, viewport) and the same shading pass, so
they differ only in how they decide which surface each pixel shows. The ray tracer
(``method="raytrace"``) intersects the analytic objects exactly instead. The output is
deterministic: the same scene gives the same bytes whatever the number of threads.

A method is a module with ``STEPS`` (how many progress steps it reports) and
``render_frame(scene, view, options) -> Frame``: the contract of :mod:`pixelpath.contract`,
whose types this module re-exports (``pixelpath.renderer.View`` is ``pixelpath.contract.View``).
"""

from __future__ import annotations

import dataclasses
import importlib
from collections.abc import Callable
from typing import Any

import numpy as np

from pixelpath._validate import choice, int_in
from pixelpath.contract import METHOD_MODULES, METHOD_NAMES, STYLES, Frame, RenderOptions, View
from pixelpath.image import Image
from pixelpath.scene import Camera, Scene

__all__ = ["MAX_SAMPLES", "METHOD_NAMES", "STYLES", "Frame", "RenderOptions", "View", "render"]

# Samples (width × height × ssaa²) a frame may hold: 32 bytes of buffers per sample (colour,
# depth, object id, and the rasterizer's 1/w and triangle), about 2 GB at the limit.
MAX_SAMPLES = 1 << 26


def render(
    scene: Scene,
    method: str = "zbuffer",
    shading: str = "phong",
    *,
    backface_cull: bool = True,
    ssaa: int = 1,
    blinn: bool = False,
    style: str = "filled",
    explain: bool = False,
    max_depth: int = 5,
    samples: int = 1,
    fresnel: bool = False,
    region: tuple[int, int, int, int] | None = None,
    progress: Callable[[int], None] | None = None,
) -> Image | tuple[Image, Any]:
    """Render ``scene`` to an :class:`~pixelpath.Image` of the camera's size.

    Parameters
    ----------
    scene : Scene
        Camera, objects, lights, ambient light and background.
    method : {"zbuffer", "scanline", "painter", "bsp", "warnock", "octree", "raytrace"}
        How visibility is decided: one of the notes' hidden-surface methods (they agree up to
        pixels on silhouette edges), or ray tracing.
    shading : {"flat", "gouraud", "phong"}
        Flat (one intensity per face), Gouraud (intensities at the vertices, interpolated) or
        Phong (normals interpolated, the model evaluated per pixel).
    backface_cull : bool
        Drop faces turned away from the eye, N·(P − eye) ≥ 0 (see :mod:`pixelpath.hsr.backface`).
        When off both sides are drawn, lit with the normal turned towards the viewer.
    ssaa : int
        Supersampling: render ``ssaa × ssaa`` samples per pixel and average them (1 = none).
        Depth and object id come from the nearest sample of each pixel.
    blinn : bool
        Blinn-Phong highlights instead of Phong's.
    style : {"filled", "wireframe", "hidden-line"}
        Filled surfaces; every polygon edge as a one-pixel line (the notes' picture "without
        hidden-surface elimination"); or only the visible parts of the edges, as decided by
        ``method`` (the picture "with HSE").
    explain : bool
        Also return a :class:`~pixelpath.report.Report` of what the method did.
    max_depth : int
        Ray tracing only: reflection and refraction bounces followed (0 = local light only).
    samples : int
        Ray tracing only: stratified samples per pixel.
    fresnel : bool
        Ray tracing only: split a transparent surface's light between reflection and
        transmission by Schlick's approximation of the Fresnel equations.
    region : (x0, y0, x1, y1), optional
        Render only the pixels ``x0 <= x < x1``, ``y0 <= y < y1`` of the camera's image; they
        equal the same pixels of the whole image exactly (tiles stitch without seams).
    progress : callable, optional
        Called with a number of steps done (out of :func:`render_steps`) as work advances.

    Returns
    -------
    Image or (Image, Report)
        RGB in [0, 1] (float32), ``.depth``, ``.object_id``, ``.alpha``, ``.normal``, and
        ``.stats``: how many triangles were culled, clipped and drawn; with ``explain=True``
        also the report.

    Raises
    ------
    ValueError
        Unknown method, shading or style, ``ssaa`` < 1, a bad region, or a frame too large
        for memory.

    Examples
    --------
    >>> import numpy as np
    >>> import pixelpath as pp
    >>> scene = pp.Scene(
    ...     camera=pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=48, height=32),
    ...     objects=[pp.Sphere((0, 0, 0), 1.0)],
    ...     lights=[pp.PointLight((4, 4, 4))],
    ... )
    >>> img = pp.render(scene, shading="gouraud")
    >>> np.asarray(img).shape, int(img.object_id[16, 24]), float(img.depth[0, 0])
    ((32, 48, 3), 0, inf)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a pixelpath Scene, got {type(scene).__name__}")
    module = _method_module(method)
    choice(shading, "shading", ("flat", "gouraud", "phong"))
    choice(style, "style", STYLES)
    factor = int_in(ssaa, "ssaa", 1, 16, "samples per pixel side; 1 means no supersampling")
    options = RenderOptions(
        shading=shading,
        backface_cull=bool(backface_cull),
        blinn=bool(blinn),
        explain=bool(explain),
        max_depth=int_in(max_depth, "max_depth", 0, 64, "reflection/refraction bounces"),
        samples=int_in(samples, "samples", 1, 1024, "samples per pixel"),
        fresnel=bool(fresnel),
        progress=progress or (lambda steps: None),
    )
    if method != "raytrace" and (options.max_depth, options.samples, fresnel) != (5, 1, False):
        raise ValueError(
            f"max_depth, samples and fresnel apply to method='raytrace' only (got "
            f"method={method!r}); use ssaa= to supersample a raster method"
        )
    view = _view(scene.camera, region, factor)
    frame = _draw(module, scene, view, style, options)
    if factor > 1:
        image = _downsample(frame, factor, scene)
    else:
        image = Image._from_buffers(
            frame.rgb, frame.depth, frame.object_id, frame.stats, frame.normal,
            scene.background, scene.encoding,
        )
    if not explain:
        return image
    report = frame.report
    if report is not None and factor == 1:  # the figures draw the report over its image
        report = dataclasses.replace(report, image=image)
    return image, report


def _draw(module, scene: Scene, view: View, style: str, options: RenderOptions) -> Frame:
    """Run the method, then draw edges for the line styles."""
    if style == "filled":
        return module.render_frame(scene, view, options)
    from pixelpath.hsr import hidden_line

    if style == "wireframe":
        frame = hidden_line.wireframe(scene, view, options)
        options.progress(module.STEPS)  # the method's steps, none of which was needed
        return frame
    # The surface is rendered a pixel beyond the region, so that its depth slopes there (which
    # decide the lines' visibility) are the whole image's: tiles stitch without seams.
    surface = hidden_line.surface_view(view)
    frame = module.render_frame(scene, surface, options)
    return hidden_line.hidden_lines(scene, view, options, frame, surface)


def render_steps(method: str = "zbuffer") -> int:
    """Return how many progress steps :func:`render` reports for ``method``.

    Examples
    --------
    >>> from pixelpath.renderer import render_steps
    >>> render_steps("zbuffer")
    11
    """
    return _method_module(method).STEPS


def _method_module(method: str):
    if not isinstance(method, str) or method not in METHOD_NAMES:
        raise ValueError(f"method must be one of {', '.join(METHOD_NAMES)}; got {method!r}")
    return importlib.import_module(METHOD_MODULES[method])


def _view(camera: Camera, region: Any, factor: int) -> View:
    """Return the (supersampled) camera and region to render, after checking their size."""
    x0, y0, x1, y1 = _region(region, camera)
    samples = (x1 - x0) * (y1 - y0) * factor * factor
    if samples > MAX_SAMPLES:
        raise ValueError(
            f"{x1 - x0}x{y1 - y0} pixels with ssaa={factor} is {samples:,} samples, more "
            f"than the {MAX_SAMPLES:,} one frame may hold; lower the size or ssaa"
        )
    if factor > 1:
        try:
            camera = camera.with_size(camera.width * factor, camera.height * factor)
        except ValueError as exc:
            raise ValueError(f"ssaa={factor} makes the sample grid too large: {exc}") from None
    return View(camera, x0 * factor, y0 * factor, (x1 - x0) * factor, (y1 - y0) * factor)


def _region(region: Any, camera: Camera) -> tuple[int, int, int, int]:
    """Return a checked (x0, y0, x1, y1) inside the image; the whole image by default."""
    if region is None:
        return 0, 0, camera.width, camera.height
    try:
        values = [int(v) for v in region]
        exact = all(isinstance(v, int | np.integer) and not isinstance(v, bool) for v in region)
    except TypeError:
        raise TypeError(f"region must be four ints (x0, y0, x1, y1), got {region!r}") from None
    if len(values) != 4 or not exact:
        raise TypeError(f"region must be four ints (x0, y0, x1, y1), got {region!r}")
    x0, y0, x1, y1 = values
    if not (0 <= x0 < x1 <= camera.width and 0 <= y0 < y1 <= camera.height):
        raise ValueError(
            f"region must satisfy 0 <= x0 < x1 <= {camera.width} and 0 <= y0 < y1 <= "
            f"{camera.height} (the camera's image), got {tuple(values)}"
        )
    return x0, y0, x1, y1


def _downsample(frame: Frame, factor: int, scene: Scene) -> Image:
    """Average each factor × factor block of samples; keep the nearest sample's depth and id.

    Alpha is the share of a block's samples that drew a surface; the normal is the nearest
    sample's, like the depth and id.
    """
    height, width = frame.rgb.shape[0] // factor, frame.rgb.shape[1] // factor

    def per_pixel(buffer: np.ndarray) -> np.ndarray:
        """(height, width, factor², ...) the samples of each pixel on one axis."""
        blocks = buffer.reshape(height, factor, width, factor, *buffer.shape[2:])
        blocks = blocks.swapaxes(1, 2)
        return blocks.reshape(height, width, factor * factor, *buffer.shape[2:])

    blocks = frame.rgb.reshape(height, factor, width, factor, 3)
    rgb = blocks.mean(axis=(1, 3), dtype=np.float64)  # sums in float64, no float64 copy
    depth = per_pixel(frame.depth)
    ids = per_pixel(frame.object_id)
    pick = np.argmin(depth, axis=2)[..., None]
    normal = None
    if frame.normal is not None:
        normal = np.take_along_axis(per_pixel(frame.normal), pick[..., None], axis=2)[:, :, 0]
    return Image(
        rgb,
        np.take_along_axis(depth, pick, axis=2)[..., 0],
        np.take_along_axis(ids, pick, axis=2)[..., 0],
        frame.stats,
        alpha=np.mean(ids >= 0, axis=2),
        normal=normal,
        background=scene.background,
        encoding=scene.encoding,
    )
