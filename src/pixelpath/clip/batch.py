"""Batch Sutherland-Hodgman: many polygons, compiled passes run on several threads.

The polygons travel as one flat ``(V, 2)`` coordinate buffer and an ``offsets`` array of
``P + 1`` indices (polygon ``i`` is ``coords[offsets[i]:offsets[i + 1]]``), the layout GIS tools
and GPU code use; :func:`clip_flat` works on it directly, :func:`clip_polygons` is the friendly
face that takes and returns a list of ``(Ni, 2)`` arrays. Each polygon is clipped exactly as
:func:`pixelpath.clip.sutherland_hodgman` clips it, so the results are identical.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np

from pixelpath.clip import _kernels, _validate
from pixelpath.clip.window import Rect, as_window

__all__ = ["clip_flat", "clip_polygons"]

# The fewest polygons worth a run of their own: a small batch is clipped on the calling thread.
# (in_threads' four runs a thread balance cheap (outside) and costly (crossing) polygons; each
# run costs a dispatch from Python, and 16 a thread took a tenth longer.)
_LEAST_POLYGONS = 256


def clip_flat(
    coords: np.ndarray, offsets: np.ndarray, window: object
) -> tuple[np.ndarray, np.ndarray]:
    """Clip every polygon of a flat coordinate buffer against a convex window.

    Parameters
    ----------
    coords : (V, 2) array_like
        The vertices of all polygons, one polygon after the other.
    offsets : (P + 1,) array_like of int
        Polygon ``i`` is ``coords[offsets[i]:offsets[i + 1]]``; ``offsets[0] == 0`` and
        ``offsets[-1] == V``.
    window : Rect or (K, 2) array_like
        A :class:`~pixelpath.clip.Rect` or a convex polygon.

    Returns
    -------
    coords : (W, 2) ndarray
        The clipped polygons' vertices.
    offsets : (P + 1,) ndarray of intp
        Where each clipped polygon starts; an empty result has ``offsets[i] == offsets[i + 1]``.

    Raises
    ------
    ValueError
        For a bad buffer, bad offsets, a polygon with fewer than 3 distinct vertices, a
        non-finite coordinate or one beyond ±1e150 (the message gives the polygon's index and
        the vertex), or a bad window.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.clip import Rect, clip_flat
    >>> coords = np.array([[1, 1], [9, 1], [9, 7], [1, 7], [20, 20], [21, 20], [20, 21.0]])
    >>> out, offsets = clip_flat(coords, [0, 4, 7], Rect(2, 2, 8, 6))
    >>> offsets.tolist()
    [0, 4, 4]
    """
    if not (type(coords) is np.ndarray and coords.dtype == np.float64 and coords.ndim == 2
            and coords.shape[1] == 2 and coords.flags.c_contiguous):
        coords = _validate.polygon_array(coords, "coords")
    offsets = _check_offsets(offsets, len(coords))
    table = window.table if type(window) is Rect else as_window(window).table
    return _clip_batch(coords, offsets, table)


def _clip_batch(
    coords: np.ndarray, offsets: np.ndarray, table: np.ndarray, slot_scale: int = 1
) -> tuple[np.ndarray, np.ndarray]:
    """Clip checked flat polygons against a boundary table in three passes; (coords, offsets).

    1. check each polygon and sort it by its bounding box: wholly outside a boundary (nothing
       left), wholly inside every boundary (unchanged), or to be clipped;
    2. clip the latter into staging slots of ``slot_scale * (n + K)`` rows given to those
       polygons only (so little memory is touched);
    3. pack every result at its final offset; a result too big for its slot, which takes a
       subject crossing the boundaries many times, is clipped again there.

    Each pass runs its kernel on runs of polygons from several threads (one, for a small
    batch: handing it to the threads would cost more than the work).
    """
    from pixelpath._threads import in_threads

    count = len(offsets) - 1
    status = np.zeros(count, dtype=np.intp)
    fate = np.empty(count, dtype=np.intp)
    in_threads(lambda start, stop: _kernels.sort_subjects(
        coords, offsets, table, start, stop, status, fate), count, least=_LEAST_POLYGONS)
    bad = np.flatnonzero(status)
    if bad.size:
        i = int(bad[0])
        polygon = coords[offsets[i] : offsets[i + 1]]
        raise _validate.subject_error(int(status[i]), f"polygon {i}", polygon)
    room = np.where(fate == _kernels.STRADDLES, np.diff(offsets) + len(table), 0)
    slot = np.zeros(count + 1, dtype=np.intp)
    np.cumsum(slot_scale * room, out=slot[1:])
    staging = np.empty((slot[-1], 2))
    sizes = np.empty(count, dtype=np.intp)
    in_threads(lambda start, stop: _kernels.clip_straddling(
        coords, offsets, table, fate, slot, start, stop, staging, sizes),
        count, least=_LEAST_POLYGONS)
    out_offsets = np.zeros(count + 1, dtype=np.intp)
    np.cumsum(sizes, out=out_offsets[1:])
    out = np.empty((out_offsets[-1], 2))
    in_threads(lambda start, stop: _kernels.pack_clipped(
        coords, offsets, table, fate, slot, staging, sizes, out_offsets, start, stop, out),
        count, least=_LEAST_POLYGONS)
    return out, out_offsets


def clip_polygons(polygons: Sequence[np.ndarray], window: object) -> list[np.ndarray]:
    """Clip many polygons against one convex window in a single compiled pass.

    Parameters
    ----------
    polygons : sequence of (Ni, 2) array_like
        The subject polygons.
    window : Rect or (K, 2) array_like
        A :class:`~pixelpath.clip.Rect` or a convex polygon.

    Returns
    -------
    list of (Mi, 2) ndarray
        ``sutherland_hodgman(polygons[i], window)`` for each ``i`` (views into one buffer);
        ``(0, 2)`` where nothing is left. Zero-width bridges are not warned about here: see
        :func:`~pixelpath.clip.zero_width_bridges`.

    Raises
    ------
    ValueError
        For a polygon of the wrong shape, with a non-finite coordinate, one beyond ±1e150 or
        fewer than 3 distinct vertices (the message gives its index), or a bad window.
    TypeError
        For non-numeric coordinates.

    Examples
    --------
    >>> from pixelpath.clip import Rect, clip_polygons
    >>> squares = [[(1, 1), (9, 1), (9, 7), (1, 7)], [(3, 3), (4, 3), (4, 4), (3, 4)]]
    >>> for clipped in clip_polygons(squares, Rect(2, 2, 8, 6)):
    ...     print(clipped.tolist())
    [[2.0, 6.0], [2.0, 2.0], [8.0, 2.0], [8.0, 6.0]]
    [[3.0, 3.0], [4.0, 3.0], [4.0, 4.0], [3.0, 4.0]]
    """
    if len(polygons) == 0:
        return []
    coords, offsets = _flatten(polygons)
    out, out_offsets = clip_flat(coords, offsets, window)
    return [out[a:b] for a, b in itertools.pairwise(out_offsets.tolist())]


def _flatten(polygons: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Concatenate the polygons into one buffer, naming the first bad one on failure."""
    try:
        arrays = [np.asarray(p) for p in polygons]
        if all(a.ndim == 2 and a.shape[1:] == (2,) for a in arrays):
            lengths = np.fromiter((len(a) for a in arrays), dtype=np.intp, count=len(arrays))
            coords = np.concatenate(arrays)
            if coords.dtype.kind in "iuf":
                offsets = np.zeros(len(arrays) + 1, dtype=np.intp)
                np.cumsum(lengths, out=offsets[1:])
                return np.ascontiguousarray(coords, dtype=np.float64), offsets
    except ValueError:  # ragged nested lists: find the culprit below
        pass
    for i, polygon in enumerate(polygons):
        _validate.polygon_array(polygon, f"polygons[{i}]")
    raise TypeError("polygons must be a sequence of (N, 2) arrays of real coordinates")


def _check_offsets(offsets: object, vertex_count: int) -> np.ndarray:
    raw = np.asarray(offsets)
    if raw.ndim != 1 or raw.size == 0:
        raise ValueError(f"offsets must have shape (P + 1,), got shape {raw.shape}")
    if raw.dtype.kind not in "iu":
        raise TypeError(f"offsets must be integers, got dtype {raw.dtype}")
    if raw[0] != 0 or raw[-1] != vertex_count or np.any(np.diff(raw) < 0):
        raise ValueError(
            f"offsets must rise from 0 to the vertex count {vertex_count}, "
            f"got {raw[:3].tolist()}...{raw[-1:].tolist()}"
        )
    return np.ascontiguousarray(raw, dtype=np.intp)
