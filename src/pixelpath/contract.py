"""The render contract: what :func:`pixelpath.render` hands a method and what it gets back.

A rendering method is a module with ``STEPS`` (how many progress steps it reports) and
``render_frame(scene, view, options) -> Frame`` (the :class:`Method` protocol);
:data:`METHOD_MODULES` names the module of each method. The methods (:mod:`pixelpath.hsr`,
:mod:`pixelpath.raytrace`) import these types from here, and :mod:`pixelpath.renderer`, which
validates a call and calls a method, imports them too: so no method imports the renderer, and
the renderer imports the methods only when one is asked for.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from pixelpath.scene import Camera, Scene

__all__ = [
    "METHOD_MODULES",
    "METHOD_NAMES",
    "STYLES",
    "Frame",
    "Method",
    "RenderOptions",
    "View",
]

METHOD_NAMES = ("zbuffer", "scanline", "painter", "bsp", "warnock", "octree", "raytrace")
STYLES = ("filled", "wireframe", "hidden-line")

# The module implementing each method.
METHOD_MODULES = {
    "zbuffer": "pixelpath.hsr.zbuffer",
    "scanline": "pixelpath.hsr.scanline",
    "painter": "pixelpath.hsr.painter",
    "bsp": "pixelpath.hsr.bsp",
    "warnock": "pixelpath.hsr.warnock",
    "octree": "pixelpath.hsr.octree",
    "raytrace": "pixelpath.raytrace.tracer",
}


@dataclasses.dataclass(frozen=True)
class View:
    """The camera and the rectangle of its image that a method renders.

    Pixel (i, j) of the region is pixel (x0 + i, y0 + j) of the camera's image, computed with
    exactly the same numbers, so tiles rendered separately stitch into the whole image.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.contract import View
    >>> view = View.whole(Camera(eye=(0, 0, 5), target=(0, 0, 0), width=64, height=48))
    >>> view.x0, view.y0, view.width, view.height
    (0, 0, 64, 48)
    """

    camera: Camera
    x0: int
    y0: int
    width: int
    height: int

    @classmethod
    def whole(cls, camera: Camera) -> View:
        """Return the view of the camera's whole image."""
        return cls(camera, 0, 0, camera.width, camera.height)


@dataclasses.dataclass(frozen=True)
class RenderOptions:
    """The choices :func:`render` passes to a method (already validated)."""

    shading: str = "phong"
    backface_cull: bool = True
    blinn: bool = False
    explain: bool = False
    max_depth: int = 5
    samples: int = 1
    fresnel: bool = False
    progress: Callable[[int], None] = dataclasses.field(default=lambda steps: None)


@dataclasses.dataclass(frozen=True)
class Frame:
    """The buffers of one rendered frame (or region of one).

    Attributes
    ----------
    rgb : (h, w, 3) float32
        Clamped intensities; the background where nothing was drawn.
    depth : (h, w) float32
        Distance along the viewing axis; ``inf`` where nothing was drawn.
    object_id : (h, w) int32
        Index of the scene object seen at each pixel; -1 for the background.
    stats : dict of str to int
        What the pipeline's stages took in and let through.
    report : Report or None
        What the method did, when asked to explain itself.
    normal : (h, w, 3) float32 or None
        Unit shading normal of the visible surface, 0 where nothing was drawn; None for the
        line styles, which draw no surfaces.
    """

    rgb: np.ndarray
    depth: np.ndarray
    object_id: np.ndarray
    stats: dict[str, int] = dataclasses.field(default_factory=dict)
    report: Any = None
    normal: np.ndarray | None = None


class Method(Protocol):
    """What the module of each of :data:`METHOD_MODULES` provides."""

    STEPS: int

    def render_frame(self, scene: Scene, view: View, options: RenderOptions) -> Frame:
        """Render ``view`` of ``scene``: the region's buffers, its stats and report."""
        ...
