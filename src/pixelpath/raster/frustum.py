"""Clipping triangles against the view frustum in homogeneous clip coordinates.

Inside the frustum ``−w ≤ x ≤ w``, ``−w ≤ y ≤ w`` and ``−w ≤ z ≤ w``: six half-spaces, each a
linear inequality in (x, y, z, w). Clipping *before* the perspective divide is what makes a
triangle crossing the near plane come out right: its part behind the eye (w < 0) would wrap
around through infinity after the divide. Each crossing triangle goes through the project's
Sutherland-Hodgman stage (:func:`pixelpath.clip._kernels.clip_stage`, with its homogeneous
``PLANE`` boundaries) once per plane; vertex attributes (world position, normal, colours) are
interpolated with the same parameter. The clipped convex
polygon is fanned back into triangles.

Only triangles that need it are clipped: one with all vertices outside one plane is dropped;
one inside the near and far planes and within a guard band around the sides is drawn as it is
(the scan converter clamps it to the image).
"""

from __future__ import annotations

import numpy as np

from pixelpath.raster._arrays import kernel_array

__all__ = ["clip_to_frustum"]


def clip_to_frustum(
    vertices: np.ndarray, triangles: np.ndarray, keep: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Clip triangles to the view frustum.

    Parameters
    ----------
    vertices : (V, k) array_like, k >= 4
        Vertex rows whose first four numbers are clip coordinates (x, y, z, w); the other
        columns are attributes, interpolated where an edge is cut.
    triangles : (T, 3) int array_like
        Vertex indices.
    keep : (T,) bool array_like, optional
        Triangles to consider (for example the front faces); default all.

    Returns
    -------
    vertices : (V + N, k) float64 ndarray
        The input vertices followed by the N vertices made by clipping.
    triangles : (M, 3) intp ndarray
        The triangles to draw: the kept ones that need no clipping, in their order, then the
        pieces of the clipped ones.
    source : (M,) intp ndarray
        For each output triangle, the index of the input triangle it comes from.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raster import clip_to_frustum
    >>> # One vertex behind the near plane (z < -w): the triangle becomes a quad, two triangles.
    >>> v = np.array([[0.0, 0.0, 0.5, 1.0], [0.5, 0.0, 0.5, 1.0], [0.0, 0.5, -3.0, 1.0]])
    >>> out, tris, source = clip_to_frustum(v, [[0, 1, 2]])
    >>> len(out), tris.tolist(), source.tolist()
    (7, [[3, 4, 5], [3, 5, 6]], [0, 0])
    >>> bool(np.all(out[3:, 2] >= -out[3:, 3]))
    True
    """
    vertices = kernel_array(vertices)
    if vertices.ndim != 2 or vertices.shape[1] < 4:
        raise ValueError(f"vertices must have shape (V, k) with k >= 4, got {vertices.shape}")
    triangles = _triangle_indices(triangles, len(vertices))
    if keep is None:
        keep = np.ones(len(triangles), dtype=np.bool_)
    keep = kernel_array(keep, np.bool_)
    if keep.shape != (len(triangles),):
        raise ValueError(f"keep must have shape ({len(triangles)},), got {keep.shape}")
    if not np.all(np.isfinite(vertices[:, :4])):
        raise ValueError("vertices must have finite clip coordinates (no NaN or inf)")
    clip = np.ascontiguousarray(vertices[:, :4])
    inside, crossing = classify(clip, triangles, keep)
    (new_vertices,), new_triangles, new_source = clip_crossing((vertices,), triangles, crossing)
    return (
        np.concatenate([vertices, new_vertices]),
        np.concatenate([triangles[inside], new_triangles]),
        np.concatenate([inside, new_source]),
    )


def classify(
    clip: np.ndarray, triangles: np.ndarray, keep: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Return the kept triangles wholly inside (guard band) and those to clip, as indices.

    ``clip`` is (V, 4) float64, ``triangles`` (T, 3) intp and ``keep`` (T,) bool, all
    contiguous; triangles outside one frustum plane are in neither list.
    """
    from pixelpath.raster import _setup_kernels

    status = np.empty(len(triangles), dtype=np.int8)
    _setup_kernels.classify_triangles(clip, triangles, keep, status)
    inside = np.flatnonzero(status == _setup_kernels.INSIDE)
    return inside, np.flatnonzero(status == _setup_kernels.CROSSING)


def clip_crossing(
    columns: tuple[np.ndarray, ...], triangles: np.ndarray, crossing: np.ndarray
) -> tuple[tuple[np.ndarray, ...], np.ndarray, np.ndarray]:
    """Clip the ``crossing`` triangles; per-vertex data comes in several column blocks.

    ``columns`` are (V, k_i) arrays of per-vertex values; the first block's first four columns
    are the clip coordinates. Only the vertices of crossing triangles are gathered, so a frame
    that needs no clipping copies nothing. Returns the new vertices' blocks (N, k_i), their
    triangles (indices continue after V) and each new triangle's source triangle.
    """
    from pixelpath.raster import _setup_kernels

    count = len(columns[0])
    if len(crossing) == 0:
        empty = tuple(np.empty((0, block.shape[1])) for block in columns)
        return empty, np.empty((0, 3), dtype=np.intp), np.empty(0, dtype=np.intp)
    corners, local = np.unique(triangles[crossing], return_inverse=True)
    rows = np.hstack([block[corners] for block in columns])
    local = np.ascontiguousarray(local.reshape(-1, 3), dtype=np.intp)
    new_rows, new_triangles, source = _setup_kernels.clip_triangles(
        rows, local, np.arange(len(crossing), dtype=np.intp)
    )
    splits = np.cumsum([block.shape[1] for block in columns])[:-1]
    blocks = tuple(np.ascontiguousarray(b) for b in np.hsplit(new_rows, splits))
    return blocks, new_triangles - len(rows) + count, crossing[source]


def _triangle_indices(triangles: np.ndarray, vertex_count: int) -> np.ndarray:
    """Return ``triangles`` as a contiguous (T, 3) intp array of valid indices, or raise."""
    array = np.asarray(triangles)
    if array.size == 0:
        return np.empty((0, 3), dtype=np.intp)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"triangles must have shape (T, 3), got {array.shape}")
    if not np.issubdtype(array.dtype, np.integer):
        raise TypeError(f"triangles must hold integer vertex indices, got dtype {array.dtype}")
    if array.min() < 0 or array.max() >= vertex_count:
        raise ValueError(
            f"triangles index vertices 0..{vertex_count - 1}, got indices "
            f"{array.min()}..{array.max()}"
        )
    return kernel_array(array, np.intp)
