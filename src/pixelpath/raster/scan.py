"""Scan conversion of triangles: edge table, active edge list, top-left fill rule.

A triangle's *edge table* is its non-horizontal edges sorted by their upper end (the vertices
sorted by y). Scan lines run through pixel centres, y = j + 0.5 with row 0 at the top. On each
scan line the *active edge list* holds the two edges whose half-open range [y_top, y_bottom)
contains y; their intersections x_L ≤ x_R bound the span, and the pixels whose centres satisfy
``x_L ≤ x < x_R`` are drawn.

The half-open ranges are the **top-left fill rule**: a pixel centre lying exactly on an edge is
drawn by the triangle to the edge's right (or below a horizontal edge), never by both. Because
an edge's x is always computed from its upper to its lower end, two triangles sharing the edge
compute bit-identical spans; a mesh therefore covers each pixel exactly once: no cracks, no
pixel drawn twice.

Depth and attributes: the screen weights of the three vertices are affine in (x, y), and so is
1/w; the perspective-correct weights are ``b_i = (s_i / w_i) / Σ (s_k / w_k)``. For the
notes' Gouraud example (a face parallel to the image plane, all w equal) they reduce to the
linear interpolation along edges and spans of the notes.
"""

from __future__ import annotations

import numpy as np

from pixelpath._threads import in_runs, in_threads
from pixelpath.raster._arrays import kernel_array

__all__ = ["coverage", "interpolate", "scan_convert"]


def _setup(points: np.ndarray, triangles: np.ndarray, width: int, height: int):
    """Validate, then return (width, height, triangles, set-up records, covered rows)."""
    from pixelpath.raster import _setup_kernels
    from pixelpath.raster.frustum import _triangle_indices

    width, height = _size(width, "width"), _size(height, "height")
    points = np.asarray(points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise ValueError(f"points must have shape (N, 2) or (N, 3), got {points.shape}")
    if not np.all(np.isfinite(points)):
        raise ValueError("points must be finite (no NaN or inf)")
    screen = np.ones((len(points), 3))
    screen[:, :2] = points[:, :2]
    if points.shape[1] == 3:
        if np.any(points[:, 2] <= 0):
            raise ValueError("the third column of points is the depth w and must be > 0")
        screen[:, 2] = 1.0 / points[:, 2]
    triangles = _triangle_indices(triangles, len(points))
    setup = np.zeros((len(triangles), _setup_kernels.SETUP_FIELDS))
    rows = np.zeros((len(triangles), 2), dtype=np.intp)
    _setup_kernels.setup_triangles(screen, triangles, False, 0, height, setup, rows)
    return width, height, triangles, setup, rows


def _size(value: int, name: str) -> int:
    if not isinstance(value, int | np.integer) or isinstance(value, bool):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    if not 1 <= value <= 1 << 16:
        raise ValueError(f"{name} must be in 1..65536, got {value}")
    return int(value)


def scan_convert(
    points: np.ndarray, triangles: np.ndarray, width: int, height: int
) -> np.ndarray:
    """Scan-convert triangles with a depth test; return the triangle seen at each pixel.

    Parameters
    ----------
    points : (N, 2) or (N, 3) array_like
        Screen positions in pixels (row 0 at the top, pixel centres at half-integers), with an
        optional third column: the depth w > 0 (nearer wins; default all equal).
    triangles : (T, 3) int array_like
        Vertex indices.
    width, height : int
        Image size.

    Returns
    -------
    (height, width) int32 ndarray
        Index of the nearest triangle covering each pixel centre, -1 where none does (ties go
        to the lower index).

    Examples
    --------
    >>> from pixelpath.raster import scan_convert
    >>> scan_convert([[0, 0], [3, 0], [3, 2], [0, 2]], [[0, 1, 2], [0, 2, 3]], 3, 2).tolist()
    [[1, 0, 0], [1, 1, 0]]
    """
    width, height, triangles, setup, rows = _setup(points, triangles, width, height)
    return _nearest(setup, rows, triangles, width, height)


def _nearest(setup: np.ndarray, rows: np.ndarray, triangles: np.ndarray, width: int,
             height: int) -> np.ndarray:
    """Run the depth-tested scan conversion; return the triangle seen at each pixel."""
    from pixelpath.raster import _scan_kernels

    inv_depth = np.empty((height, width))
    triangle_id = np.empty((height, width), dtype=np.int32)
    n_bands = -(-height // _scan_kernels.BAND_ROWS)
    offsets, items = _scan_kernels.bin_triangles(rows, n_bands, _scan_kernels.BAND_ROWS, 0)
    cutouts = _scan_kernels.opaque_cutouts(setup, triangles)
    in_runs(
        lambda bands: _scan_kernels.rasterize_bands(
            bands, setup, rows, offsets, items, _scan_kernels.BAND_ROWS, 0, 0, inv_depth,
            triangle_id, cutouts,
        ),
        np.arange(n_bands),
    )
    return triangle_id


def coverage(points: np.ndarray, triangles: np.ndarray, width: int, height: int) -> np.ndarray:
    """Count how many triangles draw each pixel (no depth test): the fill rule made visible.

    Parameters
    ----------
    points : (N, 2) array_like
        Screen positions in pixels.
    triangles : (T, 3) int array_like
        Vertex indices.
    width, height : int
        Image size.

    Returns
    -------
    (height, width) int32 ndarray
        For a mesh without overlaps every covered pixel counts exactly 1.

    Examples
    --------
    >>> from pixelpath.raster import coverage
    >>> coverage([[0, 0], [3, 0], [3, 2], [0, 2]], [[0, 1, 2], [0, 2, 3]], 3, 2).tolist()
    [[1, 1, 1], [1, 1, 1]]
    """
    from pixelpath.raster import _scan_kernels

    width, height, _, setup, rows = _setup(points, triangles, width, height)
    counts = np.zeros((height, width), dtype=np.int32)
    _scan_kernels.count_coverage(setup, rows, 0, 0, counts)
    return counts


def interpolate(
    points: np.ndarray, triangles: np.ndarray, values: np.ndarray, width: int, height: int
) -> np.ndarray:
    """Interpolate per-vertex values over the visible triangles, perspective-correctly.

    This is Gouraud's interpolation when ``values`` are vertex intensities.

    Parameters
    ----------
    points : (N, 2) or (N, 3) array_like
        Screen positions, optionally with the depth w (see :func:`scan_convert`).
    triangles : (T, 3) int array_like
        Vertex indices.
    values : (N,) or (N, C) array_like
        A value (or C values) per vertex.
    width, height : int
        Image size.

    Returns
    -------
    (height, width) or (height, width, C) float64 ndarray
        NaN where no triangle is drawn.

    Examples
    --------
    >>> from pixelpath.raster import interpolate
    >>> # The notes' triangle: I1 = 0.9 at the top, I2 = 0.2 left, I3 = 0.6 right.
    >>> image = interpolate([[4, 0], [0, 8], [8, 8]], [[0, 1, 2]], [0.9, 0.2, 0.6], 8, 8)
    >>> round(float(image[4, 4]), 4)  # centre (4.5, 4.5)
    0.6438
    """
    from pixelpath.raster import _scan_kernels

    width, height, triangles, setup, rows = _setup(points, triangles, width, height)
    values = np.asarray(values, dtype=np.float64)
    single = values.ndim == 1
    table = values.reshape(len(values), -1) if values.ndim in (1, 2) else values
    if table.ndim != 2 or len(table) != len(np.asarray(points)):
        raise ValueError(
            f"values must have shape (N,) or (N, C) with N = {len(np.asarray(points))} points, "
            f"got {values.shape}"
        )
    triangle_id = _nearest(setup, rows, triangles, width, height)
    out = np.full((height, width, table.shape[1]), np.nan)
    table = kernel_array(table)
    in_threads(
        lambda first, stop: _scan_kernels.interpolate_values(
            first, stop, setup, triangles, table, triangle_id, out
        ),
        height,
    )
    return out[..., 0] if single else out
