"""Vertex normals that keep a mesh's sharp edges sharp: smoothing within a crease angle.

A file without normals leaves the renderer to make them. Area-weighted vertex normals (the
average of the faces around a vertex) suit a smooth surface sampled by triangles, such as a
scanned bunny, but round off a box: at a cube's corner they point along the diagonal, and
Phong shading smears each face's light across its edges. Modelling tools therefore smooth
only across edges whose faces meet at less than a crease angle (Blender's "auto smooth"):
each corner of a face takes the area-weighted average of the faces around its vertex whose
normals lie within the angle of its own face's, and a vertex whose corners end up with
different normals is split into one vertex per normal. Vertices at the same point (the copies
trimesh makes along a texture seam, one per texture coordinate) are one place for this, so
that a smooth textured surface shows no seam in its shading.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath import _validate as v

__all__ = ["CREASE_ANGLE", "crease_normals"]

# degrees: between the common angles of CAD edges (45-degree chamfers are smoothed, a hexagonal
# prism's 60-degree edges and right angles stay sharp); a decimated scan keeps few creases
CREASE_ANGLE = 50.0

# Corner pairs worked out at once, to bound the memory of a large mesh (about 60 MB).
_PAIRS_AT_ONCE = 1 << 21


def crease_normals(
    vertices: np.ndarray, triangles: np.ndarray, angle: float = CREASE_ANGLE
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Return normals smoothed within ``angle`` degrees, splitting vertices along sharp edges.

    Parameters
    ----------
    vertices : (V, 3) float64 ndarray
    triangles : (F, 3) int ndarray
        Indices into ``vertices``.
    angle : float
        Faces whose normals differ by more than this many degrees share no smoothing; 0
        draws every face flat (each corner of a part that is not planar its own vertex).

    Returns
    -------
    (source, triangles, normals) or None
        ``source`` (V',) the vertex of ``vertices`` each new vertex copies (its texture
        coordinates and colour too), ``triangles`` (F, 3) into the new vertices, ``normals``
        (V', 3) unit vectors; None when no two faces at a vertex are more than ``angle``
        apart and no two vertices lie at one point, so that the area-weighted vertex normals
        are these normals already.

    Examples
    --------
    Two faces folded at a right angle along the edge (0, 1): the edge's vertices split in two.

    >>> import numpy as np
    >>> from pixelpath.io.creases import crease_normals
    >>> vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    >>> source, triangles, normals = crease_normals(vertices, np.array([[0, 1, 2], [0, 3, 1]]))
    >>> sorted(source.tolist())
    [0, 0, 1, 1, 2, 3]
    >>> normals[triangles[0]].tolist()  # the first face's corners: its own normal, +z
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    >>> normals[triangles[1]].tolist()  # the second face's: +y
    [[0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
    """
    corners = triangles.ravel()
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    weighted = np.cross(b - a, c - a)  # twice each face's area, along its normal
    face = np.arange(len(corners)) // 3
    at_corners = np.take(weighted, face, axis=0)
    facing = np.take(v.unit_or_zero(weighted), face, axis=0)
    # Normals are made per place: copies of a vertex at one point (a texture seam's, which
    # trimesh splits) share them, or the seam would show in the shading. Flat faces need none.
    place = np.arange(len(vertices)) if angle == 0.0 else _places(vertices)
    at = place[corners]
    smooth = v.unit_or_zero(v.sum_rows_at(at, at_corners, place.max(initial=-1) + 1))
    within = np.einsum("ij,ij->i", facing, np.take(smooth, at, axis=0))
    if angle == 0.0:
        return _flat(corners, facing, within)
    smooth[~smooth.any(axis=1)] = (0.0, 0.0, 1.0)  # a place of faces of no area, never seen
    # Faces all within half the angle of their place's smooth normal are within the angle of
    # each other: only the other places ("doubtful") need their faces compared in pairs.
    # A face of no area faces no way: it makes no crease (and weighs nothing).
    doubtful = np.zeros(len(smooth), dtype=bool)
    doubtful[at[(within < math.cos(math.radians(angle) / 2.0)) & facing.any(axis=1)]] = True
    look = np.flatnonzero(doubtful[at])
    groups = _Groups(at[look], at_corners[look], facing[look]) if len(look) else None
    normals = groups and groups.normals_within(math.cos(math.radians(angle)))
    if normals is None:  # no crease: the smooth normals, unless every vertex has a place
        seams = place.max(initial=-1) + 1 < len(vertices)
        return (np.arange(len(vertices)), triangles, smooth[place]) if seams else None
    # a vertex at a smooth place keeps its index; the corners at the other places make a
    # vertex for each of their vertices and normals
    sure = ~doubtful[place]
    new = (np.cumsum(sure) - 1)[corners]
    split = normals[groups.group]
    order, first = _runs(corners[look], _direction_keys(split))
    new[look[order]] = np.count_nonzero(sure) + np.cumsum(first) - 1
    ends = order[first]
    return (np.concatenate([np.flatnonzero(sure), corners[look][ends]]), new.reshape(-1, 3),
            np.concatenate([smooth[place[sure]], split[ends]]))


def _flat(
    corners: np.ndarray, facing: np.ndarray, within: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Return every corner as a vertex of its own with its face's normal; None for a flat part.

    ``within`` holds the cosine between each corner's face normal and its vertex's smooth
    normal: 1 at every corner (faces of no area aside) is a part whose vertices' faces all face
    one way, whose area-weighted normals are its faces' normals already.
    """
    real = facing.any(axis=1)
    if np.all((within >= 1.0 - 1e-12) | ~real):
        return None
    normals = facing.copy()
    normals[~real] = (0.0, 0.0, 1.0)  # faces of no area, never seen
    return corners.copy(), np.arange(len(corners)).reshape(-1, 3), normals


class _Groups:
    """The corners of each vertex grouped by the way their faces face.

    Faces around a vertex often face the same way (a CAD part's flat side is a fan of many
    triangles): their corners form one group, so that pairs are made of groups, not of
    corners, which keeps the pairs few at a vertex of hundreds of faces. Two faces are in
    one group when their unit normals agree to about 1e-6 (:func:`_direction_keys`).
    """

    def __init__(self, corners: np.ndarray, weighted: np.ndarray, unit: np.ndarray) -> None:
        order, first = _runs(corners, _direction_keys(unit))
        self.group = np.empty(len(corners), dtype=np.intp)  # each corner's group
        self.group[order] = np.cumsum(first) - 1
        self.vertex = corners[order[first]]  # each group's vertex, groups ordered by vertex
        self.unit = unit[order[first]]  # the way its faces face
        count = len(self.vertex)
        self.weighted = v.sum_rows_at(self.group, weighted, count)

    def normals_within(self, cos_limit: float) -> np.ndarray | None:
        """Return each group's normal: the sum of its place's groups' within the limit.

        None when every group takes in every other group of its place (no crease).
        """
        sums = self._sums_within(cos_limit)
        if sums is None:
            return None
        normals = v.unit_or_zero(sums)
        flat = ~normals.any(axis=1)  # faces of no area all round: their own normal, or +z
        normals[flat] = self.unit[flat]
        normals[~normals.any(axis=1)] = (0.0, 0.0, 1.0)
        return normals

    def _sums_within(self, cos_limit: float) -> np.ndarray | None:
        count = len(self.vertex)
        starts = np.flatnonzero(np.r_[True, self.vertex[1:] != self.vertex[:-1]])
        sizes = np.diff(np.r_[starts, count])
        group_size, group_start = np.repeat(sizes, sizes), np.repeat(starts, sizes)
        sums = np.zeros((count, 3))
        creased = False
        pointless = ~self.unit.any(axis=1)  # a group of faces of no area goes with any
        bounds = np.searchsorted(np.cumsum(group_size),
                                 np.arange(0, group_size.sum(), _PAIRS_AT_ONCE))
        for lo, hi in zip(bounds, [*bounds[1:], count], strict=True):
            k = group_size[lo:hi]
            mine = np.repeat(np.arange(lo, hi), k)  # each group beside each of its vertex's
            step = np.arange(len(mine)) - np.repeat(np.cumsum(k) - k, k)
            theirs = np.repeat(group_start[lo:hi], k) + step
            cosines = np.einsum("ij,ij->i", np.take(self.unit, mine, axis=0),
                                np.take(self.unit, theirs, axis=0))
            keep = (cosines >= cos_limit) | (mine == theirs) | pointless[mine] | pointless[theirs]
            creased = creased or not keep.all()
            sums += v.sum_rows_at(mine[keep], np.take(self.weighted, theirs[keep], axis=0),
                                  count)
        return sums if creased else None


def _places(vertices: np.ndarray) -> np.ndarray:
    """Return, for each vertex, the index of its point among the distinct points."""
    order = np.lexsort(vertices.T[::-1])
    ordered = vertices[order]
    first = np.r_[True, (ordered[1:] != ordered[:-1]).any(axis=1)]
    place = np.empty(len(vertices), dtype=np.intp)
    place[order] = np.cumsum(first) - 1
    return place


def _direction_keys(unit: np.ndarray) -> np.ndarray:
    """Return one int64 per unit vector: its components to 20 bits each (steps of 2e-6)."""
    steps = np.rint((unit + 1.0) * ((1 << 19) - 0.5)).astype(np.int64)  # 0 .. 2^20 - 1
    return (steps[:, 0] << 40) | (steps[:, 1] << 20) | steps[:, 2]


def _runs(vertex: np.ndarray, key: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the order that sorts by ``vertex``, then ``key``, and where each run starts."""
    order = np.lexsort((key, vertex))
    vertex, key = vertex[order], key[order]
    return order, np.r_[True, (vertex[1:] != vertex[:-1]) | (key[1:] != key[:-1])]
