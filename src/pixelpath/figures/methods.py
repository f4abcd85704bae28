"""The figure of each hidden-surface method, drawn from its image and its explain report.

:data:`METHOD_FIGURES` maps a method's name to a function ``(image, report) -> PIL image``;
:func:`method_figure` looks it up. A method that has no figure yet gives ``None`` (the
playground then shows the image and the report only). Adding a method's figure is one
function and one entry here.

Examples
--------
>>> from pixelpath.figures.methods import METHOD_FIGURES
>>> sorted(METHOD_FIGURES)
['zbuffer']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from PIL import Image

from pixelpath.figures._canvas import paste_grid, paste_row

__all__ = ["METHOD_FIGURES", "depth_figure", "method_figure", "methods_side_by_side"]


def depth_figure(image: Any, report: Any = None) -> Image.Image:
    """Return the picture beside its depth buffer (near light, far dark, nothing black).

    This is what the z-buffer keeps besides the colours: the depth of the nearest surface
    seen so far at every pixel.

    Parameters
    ----------
    image : pixelpath.Image
        A rendered image with ``.depth``.
    report : Report, optional
        Not used; every method figure takes it.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.figures.methods import depth_figure
    >>> depth = np.array([[1.0, 2.0], [np.inf, 1.5]])
    >>> depth_figure(Image(np.zeros((2, 2, 3)), depth=depth)).height
    40
    """
    depth = np.asarray(image.depth, dtype=np.float64)
    drawn = np.isfinite(depth)
    grey = np.zeros(depth.shape, dtype=np.uint8)
    if drawn.any():
        near, far = depth[drawn].min(), depth[drawn].max()
        scale = (far - near) or 1.0
        grey[drawn] = np.rint(255 - 200 * (depth[drawn] - near) / scale).astype(np.uint8)
    pictures = [Image.fromarray(image.to_uint8()), Image.fromarray(grey).convert("RGB")]
    return paste_row(pictures, ["image", "depth buffer (near is light)"])


METHOD_FIGURES: dict[str, Callable[[Any, Any], Image.Image]] = {"zbuffer": depth_figure}


def method_figure(method: str, image: Any, report: Any) -> Image.Image | None:
    """Return the figure of ``method`` for one rendered image, or None when it has none.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.figures.methods import method_figure
    >>> method_figure("no such method", Image(np.zeros((2, 2, 3))), None) is None
    True
    """
    draw = METHOD_FIGURES.get(method)
    return None if draw is None else draw(image, report)


def methods_side_by_side(
    scene: Any, methods: Sequence[str] | None = None, *, columns: int = 4, **options: Any
) -> Image.Image:
    """Render ``scene`` with each method and place the pictures side by side, captioned.

    Every raster method gives the z-buffer's picture (up to silhouette pixels); the ray
    tracer adds shadows, reflection and refraction.

    Parameters
    ----------
    scene : Scene
        What to draw, at its camera's size.
    methods : sequence of str, optional
        Default: every method (:data:`pixelpath.renderer.METHOD_NAMES`).
    columns : int
        Pictures per row.
    **options
        Passed to :func:`pixelpath.render` for every method (``shading``, ``ssaa``...).

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.methods import methods_side_by_side
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=40, height=30),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> figure = methods_side_by_side(scene, ["zbuffer", "scanline"], columns=1)
    >>> figure.height  # two rows of: gap 8, caption 22, picture 30, gap 8
    136
    """
    from pixelpath.renderer import METHOD_NAMES, render

    methods = list(METHOD_NAMES if methods is None else methods)
    pictures = [
        Image.fromarray(render(scene, method=method, **options).to_uint8())
        for method in methods
    ]
    return paste_grid(pictures, methods, columns)
