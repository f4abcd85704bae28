"""``pixelpath.render()``: draw a scene with one of the notes' hidden-surface methods.

Raster methods tessellate spheres and planes, clip to the view frustum, scan-convert and shade
(flat, Gouraud or Phong); see :mod:`pixelpath.hsr` and :mod:`pixelpath.raster`. The output is
deterministic: the same scene gives the same bytes whatever the number of threads.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from pixelpath.image import Image
from pixelpath.scene import Scene

__all__ = ["MAX_SAMPLES", "METHOD_NAMES", "render"]

METHOD_NAMES = ("zbuffer", "scanline", "painter", "bsp", "warnock", "octree", "raytrace")

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
    progress: Callable[[int], None] | None = None,
) -> Image:
    """Render ``scene`` to an :class:`~pixelpath.Image` of the camera's size.

    Parameters
    ----------
    scene : Scene
        Camera, objects, lights, ambient light and background.
    method : str
        Hidden-surface method: ``"zbuffer"``. (``"scanline"``, ``"painter"``, ``"bsp"``,
        ``"warnock"``, ``"octree"`` and ``"raytrace"`` are named by the SPEC and not built yet:
        they raise ``NotImplementedError``.)
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
    progress : callable, optional
        Called with a number of steps done (out of :func:`render_steps`) as work advances.

    Returns
    -------
    Image
        RGB in [0, 1] (float32), ``.depth``, ``.object_id``, and ``.stats``: how many
        triangles were culled, clipped and scan-converted.

    Raises
    ------
    ValueError
        Unknown method or shading, ``ssaa`` < 1, or a frame too large for memory.
    NotImplementedError
        A method of the SPEC that this version does not implement yet.

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
    from pixelpath.hsr import METHODS

    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a pixelpath Scene, got {type(scene).__name__}")
    renderer = _method(method, METHODS)
    factor = _ssaa(ssaa)
    camera = scene.camera
    samples = camera.width * camera.height * factor * factor
    if samples > MAX_SAMPLES:
        raise ValueError(
            f"{camera.width}x{camera.height} with ssaa={factor} is {samples:,} samples, more "
            f"than the {MAX_SAMPLES:,} one frame may hold; lower the size or ssaa"
        )
    if factor > 1:
        camera = _scaled_camera(camera, factor)
    frame = renderer(
        scene,
        camera,
        shading=shading,
        backface_cull=bool(backface_cull),
        blinn=bool(blinn),
        progress=progress,
    )
    if factor == 1:
        return Image._from_buffers(frame.rgb, frame.depth, frame.object_id, frame.stats)
    return _downsample(frame, factor)


def render_steps(method: str = "zbuffer") -> int:
    """Return how many progress steps :func:`render` reports for ``method``.

    Examples
    --------
    >>> from pixelpath.renderer import render_steps
    >>> render_steps("zbuffer")
    11
    """
    from pixelpath.hsr import METHODS
    from pixelpath.hsr.zbuffer import STEPS

    _method(method, METHODS)
    return STEPS


def _method(method: str, registry: dict) -> Callable:
    if not isinstance(method, str) or method not in METHOD_NAMES:
        raise ValueError(f"method must be one of {', '.join(METHOD_NAMES)}; got {method!r}")
    renderer = registry.get(method)
    if renderer is None:
        raise NotImplementedError(
            f"method {method!r} is part of the specification but not implemented in this "
            f"version; use method='zbuffer'"
        )
    return renderer


def _ssaa(ssaa: int) -> int:
    if not isinstance(ssaa, int | np.integer) or isinstance(ssaa, bool):
        raise TypeError(f"ssaa must be an int (samples per pixel side), got {type(ssaa).__name__}")
    if not 1 <= ssaa <= 16:
        raise ValueError(f"ssaa must be in 1..16 (1 means no supersampling), got {ssaa}")
    return int(ssaa)


def _scaled_camera(camera, factor: int):
    try:
        return camera.with_size(camera.width * factor, camera.height * factor)
    except ValueError as exc:
        raise ValueError(f"ssaa={factor} makes the sample grid too large: {exc}") from None


def _downsample(frame, factor: int) -> Image:
    """Average each factor × factor block of samples; keep the nearest sample's depth and id."""
    height, width = frame.rgb.shape[0] // factor, frame.rgb.shape[1] // factor
    blocks = frame.rgb.reshape(height, factor, width, factor, 3)
    rgb = blocks.mean(axis=(1, 3), dtype=np.float64)  # sums in float64, no float64 copy
    depth = frame.depth.reshape(height, factor, width, factor).transpose(0, 2, 1, 3)
    depth = depth.reshape(height, width, factor * factor)
    nearest = np.argmin(depth, axis=2)
    ids = frame.object_id.reshape(height, factor, width, factor).transpose(0, 2, 1, 3)
    ids = ids.reshape(height, width, factor * factor)
    pick = nearest[..., None]
    return Image(
        rgb,
        np.take_along_axis(depth, pick, axis=2)[..., 0],
        np.take_along_axis(ids, pick, axis=2)[..., 0],
        frame.stats,
    )
