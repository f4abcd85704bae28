"""The figure of each hidden-surface method, drawn from its image and its explain report.

:data:`METHOD_FIGURES` maps a method's name to a function ``(image, report) -> PIL image``;
:func:`method_figure` looks it up. A method that has no figure yet gives ``None`` (the
playground then shows the image and the report only). :data:`METHOD_ANIMATIONS` maps a
method to its frames ``(image, report) -> [PIL image]``. ``Report.figure()``,
``Report.frames()`` and ``Report.animate(path)`` go through :func:`report_figure` and
:func:`report_frames`. Adding a method's figure is one function and one entry here; the
drawings are in :mod:`pixelpath.figures.hidden_surfaces`.

Examples
--------
>>> from pixelpath.figures.methods import METHOD_FIGURES
>>> sorted(METHOD_FIGURES)
['bsp', 'octree', 'painter', 'scanline', 'warnock', 'zbuffer']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from PIL import Image

from pixelpath.figures import hidden_surfaces
from pixelpath.figures._canvas import paste_grid, paste_row

__all__ = [
    "METHOD_ANIMATIONS",
    "METHOD_FIGURES",
    "depth_figure",
    "has_figure",
    "method_figure",
    "methods_side_by_side",
    "report_figure",
    "report_frames",
]


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
    grey = hidden_surfaces.depth_grey(image.depth)
    pictures = [Image.fromarray(image.to_uint8()), Image.fromarray(grey).convert("RGB")]
    return paste_row(pictures, ["image", "depth buffer (near is light)"])


METHOD_FIGURES: dict[str, Callable[[Any, Any], Image.Image]] = {
    "zbuffer": depth_figure,
    "scanline": hidden_surfaces.scanline_figure,
    "painter": hidden_surfaces.order_figure,
    "bsp": hidden_surfaces.bsp_figure,
    "warnock": hidden_surfaces.warnock_figure,
    "octree": hidden_surfaces.octree_figure,
}
# The animation of each method: a function (image, report) -> frames.
METHOD_ANIMATIONS: dict[str, Callable[[Any, Any], list[Image.Image]]] = {
    "zbuffer": hidden_surfaces.zbuffer_frames,
    "scanline": hidden_surfaces.scanline_frames,
    "painter": hidden_surfaces.order_frames,
    "bsp": hidden_surfaces.bsp_frames,
    "warnock": hidden_surfaces.warnock_frames,
    "octree": hidden_surfaces.octree_frames,
}


def method_figure(method: str, image: Any, report: Any) -> Image.Image | None:
    """Return the figure of ``method`` for one rendered image, or None when it has none.

    None also when ``report`` is not the method's own (the line styles report their edges):
    only the z-buffer's figure, the depth buffer, is drawn from the image alone.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.figures.methods import method_figure
    >>> method_figure("no such method", Image(np.zeros((2, 2, 3))), None) is None
    True
    """
    draw = METHOD_FIGURES.get(method)
    if draw is None:
        return None
    if draw is not depth_figure and getattr(report, "method", None) != method:
        return None  # a line style's report (wireframe, hidden-line) lacks the method's data
    return draw(image, report)


def has_figure(report: Any) -> bool:
    """Whether the report's method has a figure and the report carries its image.

    Examples
    --------
    >>> from pixelpath.report import Report
    >>> from pixelpath.figures.methods import has_figure
    >>> has_figure(Report("warnock", {}))  # no image attached
    False
    """
    return report.method in METHOD_FIGURES and report.image is not None


def report_figure(report: Any) -> Image.Image:
    """Return the figure of a report's method over the report's image (``Report.figure``).

    Raises
    ------
    ValueError
        Naming the method, when it has no figure or the report has no image.
    """
    _check_drawable(report, METHOD_FIGURES, "figure")
    return METHOD_FIGURES[report.method](report.image, report)


def report_frames(report: Any) -> tuple[list[Image.Image], list[int]]:
    """Return the frames of a report's method's animation and their durations (ms).

    Raises
    ------
    ValueError
        Naming the method, when it has no animation or the report has no image.
    """
    _check_drawable(report, METHOD_ANIMATIONS, "animation")
    frames = METHOD_ANIMATIONS[report.method](report.image, report)
    durations = [hidden_surfaces.STEP_MS] * (len(frames) - 1) + [hidden_surfaces.LAST_MS]
    return frames, durations


def _check_drawable(report: Any, table: dict[str, Any], what: str) -> None:
    if report.method not in table:
        has = ", ".join(table)
        hint = (" (for a pixel's ray tree: pixelpath ray SCENE --pixel X,Y --figure tree.png)"
                if report.method == "raytrace" else "")
        raise ValueError(f"method {report.method!r} has no {what}; these do: {has}{hint}")


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
