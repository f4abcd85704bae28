"""Line drawing: segments clipped to the view frustum, then drawn one pixel wide by Bresenham.

A world-space segment is transformed to clip coordinates and clipped against the six frustum
planes *before* the perspective divide (Liang-Barsky's parametric clipping, one interval of
the segment per half-space), so a segment crossing the near plane keeps exactly its part in
front of the camera. Its ends are then mapped to pixels and the line between their pixels is
drawn with Bresenham's integer algorithm: one pixel per step along the major axis, the minor
coordinate advancing when the accumulated error crosses half a pixel. The result is
8-connected, one pixel wide, with ``max(|Δx|, |Δy|) + 1`` pixels.

Each line pixel carries the line's depth there (the distance along the viewing axis),
interpolated perspective-correctly: 1/w is affine along the projected line. The nearest line
wins where lines cross, and an optional per-pixel depth limit removes the pixels of lines
behind a surface (the hidden-line drawing of :mod:`pixelpath.hsr.hidden_line`).

Examples
--------
>>> from pixelpath.raster.lines import bresenham
>>> bresenham((0, 0), (5, 2)).tolist()
[[0, 0], [1, 0], [2, 1], [3, 1], [4, 2], [5, 2]]
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from pixelpath.raster._arrays import kernel_array

if TYPE_CHECKING:
    from pixelpath.contract import View

__all__ = ["LineBuffers", "bresenham", "draw_lines"]


class LineBuffers(NamedTuple):
    """Lines drawn into a region: the nearest line's depth and owner at each pixel."""

    depth: np.ndarray  # (h, w) float64 view-axis depth, inf where no line is drawn
    owner: np.ndarray  # (h, w) int32 owner of the line drawn there, -1 where none
    counts: dict[str, int]  # segments outside the frustum, cut by it; line pixels drawn, hidden


def bresenham(start, end) -> np.ndarray:
    """Return the pixels of Bresenham's line between two pixels, both ends included.

    Parameters
    ----------
    start, end : (2,) int
        Pixel (column, row) of the two ends.

    Returns
    -------
    (N, 2) intp ndarray
        The pixels from ``start`` to ``end``, ``N = max(|Δx|, |Δy|) + 1``; consecutive pixels
        are 8-neighbours.

    Examples
    --------
    >>> from pixelpath.raster.lines import bresenham
    >>> bresenham((0, 0), (1, 3)).tolist()
    [[0, 0], [0, 1], [1, 2], [1, 3]]
    """
    from pixelpath.raster import _line_kernels

    ends = []
    for name, value in (("start", start), ("end", end)):
        array = np.asarray(value)
        if array.shape != (2,) or not np.issubdtype(array.dtype, np.integer):
            raise ValueError(f"{name} must be two integer pixel coordinates, got {value!r}")
        ends.extend(int(v) for v in array)
    return _line_kernels.bresenham_pixels(*ends)


def draw_lines(
    starts: np.ndarray,
    ends: np.ndarray,
    owners: np.ndarray,
    view: View,
    limit: np.ndarray | None = None,
) -> LineBuffers:
    """Clip world-space segments to the view frustum and draw them into the view's region.

    Parameters
    ----------
    starts, ends : (E, 3) array_like
        World positions of the segments' ends.
    owners : (E,) int array_like
        What each segment belongs to (written where it is drawn; an object index).
    view : View
        Camera and region; pixels are computed in the whole image's coordinates, so a region
        gets exactly the pixels of the whole image.
    limit : (h, w) array_like, optional
        Per-pixel depth beyond which a line pixel is hidden (default: nothing is hidden).

    Returns
    -------
    LineBuffers

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.contract import View
    >>> from pixelpath.raster.lines import draw_lines
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=11, height=11)
    >>> lines = draw_lines([[-5.0, 0.0, 0.0]], [[5.0, 0.0, 0.0]], [0], View.whole(camera))
    >>> (lines.owner == 0).sum(axis=1).tolist()  # clipped to the image: one full row
    [0, 0, 0, 0, 0, 11, 0, 0, 0, 0, 0]
    >>> float(lines.depth[5, 5])
    5.0
    """
    from pixelpath.raster import _line_kernels

    camera = view.camera
    starts = kernel_array(starts).reshape(-1, 3)
    ends = kernel_array(ends).reshape(-1, 3)
    owners = kernel_array(owners, np.intp).reshape(-1)
    if not (np.isfinite(starts).all() and np.isfinite(ends).all()):
        raise ValueError("starts and ends must be finite (no NaN or inf coordinates)")
    if not (len(starts) == len(ends) == len(owners)):
        raise ValueError(
            f"starts, ends and owners must have one row per segment, got {len(starts)}, "
            f"{len(ends)} and {len(owners)}"
        )
    shape = (view.height, view.width)
    if limit is None:
        limit = np.full(shape, np.inf)
    limit = kernel_array(limit)
    if limit.shape != shape:
        raise ValueError(f"limit must have the region's shape {shape}, got {limit.shape}")
    screen = np.empty((len(starts), _line_kernels.SEGMENT_FIELDS))
    kept = np.empty(len(starts), dtype=np.bool_)
    matrix = kernel_array(camera.projection_matrix() @ camera.view_matrix())
    cut = _line_kernels.clip_segments(starts, ends, matrix, camera.orthographic, screen, kept,
                                      camera.width, camera.height)
    depth = np.full(shape, np.inf)
    owner = np.full(shape, -1, dtype=np.int32)
    drawn, hidden = _line_kernels.draw_segments(
        screen, kept, owners, camera.width, camera.height, camera.orthographic, camera.near,
        camera.far, view.x0, view.y0, limit, depth, owner,
    )
    counts = {
        "edges outside the frustum": int(len(kept) - np.count_nonzero(kept)),
        "edges cut by the frustum": int(cut),
        "line pixels": int(drawn),
        "line pixels hidden": int(hidden),
    }
    return LineBuffers(depth, owner, counts)
