"""Compiled BVH build: the triangles' boxes and a bounding-volume hierarchy over them.

``build_bvh`` keeps the hierarchy in flat arrays, built top-down with the binned surface-area
heuristic (Wald 2007): at each node the triangles' centroids are put into ``BINS`` bins along
each axis and the split with the least ``A_left N_left + A_right N_right`` is taken when it
beats a leaf. Node k is ``bounds[k] = (min xyz, max xyz)`` and ``links[k] = (first, count)``:
a leaf holds ``count > 0`` triangles from position ``first`` of the leaf order; an inner node
(count 0) has children ``first`` and ``first + 1``.

The searches of the tree are :mod:`pixelpath.raytrace._traversal_kernels`'. :func:`warmup`
compiles the build (the kernel group ``raytrace-bvh``), :func:`warm_queries` the searches of
batches of rays and the ray tests of :mod:`pixelpath.raytrace._hit_kernels`
(``raytrace-queries``).
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit
from pixelpath.raytrace._hit_kernels import (
    ray_plane_many,
    ray_sphere_many,
    reflect_many,
    refract_many,
)
from pixelpath.raytrace._traversal_kernels import LANES, any_triangle, intersect_many

BINS = 16  # SAH bins per axis
MAX_LEAF = 8  # a node holding more triangles than this is split even when a leaf costs less
NODE_COST = 1.0  # SAH: cost of visiting a node, relative to one triangle test

# The box helpers below stay inlined by Numba (see pixelpath._jit): as functions of their own,
# LLVM inlined them all, but a million-triangle build took 3 % longer, for no compile time saved.


@njit(inline="always")
def _area(box, k):
    """Half the surface area of box k of (n, 6) min/max rows (0 for an empty box)."""
    ex = box[k, 3] - box[k, 0]
    ey = box[k, 4] - box[k, 1]
    ez = box[k, 5] - box[k, 2]
    if ex < 0.0:
        return 0.0
    return ex * ey + ey * ez + ez * ex


@njit(inline="always")
def _empty_box(box, k):
    for axis in range(3):
        box[k, axis] = math.inf
        box[k, 3 + axis] = -math.inf


@njit(inline="always")
def _grow(box, k, other, j):
    """Grow box k to contain box j of ``other``."""
    for axis in range(3):
        box[k, axis] = min(box[k, axis], other[j, axis])
        box[k, 3 + axis] = max(box[k, 3 + axis], other[j, 3 + axis])


@njit(inline="always")
def _centre(low, high):
    """Return a primitive's centroid along an axis, the centre of its box's extent there.

    The one formula for it: the binning and the partition must put a primitive in the same
    bin, bit for bit.
    """
    return 0.5 * (low + high)


@njit(inline="always")
def _centroid(boxes, p, axis):
    """Return the centroid of box p of (n, 6) min/max rows along an axis."""
    return _centre(boxes[p, axis], boxes[p, 3 + axis])


@njit(inline="always")
def _bin_index(centre, low, scale):
    """Return the bin of a centroid coordinate in a node whose centroid box starts at low."""
    b = int((centre - low) * scale)
    return min(max(b, 0), BINS - 1)


@njit(inline="always")
def _bin_scale(centre_boxes, c, axis):
    """Return the bins per unit length along an axis of centroid box c (0: no extent)."""
    extent = centre_boxes[c, 3 + axis] - centre_boxes[c, axis]
    return BINS / extent if extent > 0.0 else 0.0


@njit(inline="always")
def _add_centroid(low, high, boxes, p):
    """Grow a centroid box, (low, high) 3-tuples, to contain the centroid of box p."""
    x, y, z = _centroid(boxes, p, 0), _centroid(boxes, p, 1), _centroid(boxes, p, 2)
    low = (min(low[0], x), min(low[1], y), min(low[2], z))
    high = (max(high[0], x), max(high[1], y), max(high[2], z))
    return low, high


@njit(inline="always")
def _set_box(box, k, low, high):
    for axis in range(3):
        box[k, axis] = low[axis]
        box[k, 3 + axis] = high[axis]


@njit(refcount=False, from_python=False)
def _node_boxes(boxes, start, stop, bounds, node, centre_boxes, c):
    """Write the box of boxes[start:stop] to bounds[node], of their centroids to centre_boxes[c]."""
    _empty_box(bounds, node)
    low = (math.inf, math.inf, math.inf)
    high = (-math.inf, -math.inf, -math.inf)
    for p in range(start, stop):
        _grow(bounds, node, boxes, p)
        low, high = _add_centroid(low, high, boxes, p)
    _set_box(centre_boxes, c, low, high)


@njit(refcount=False, from_python=False)
def _best_split(boxes, start, stop, centre_boxes, c, bins, counts, sweep, right_areas, filled):
    """Return (axis, last bin of the left side, SAH sum) of the best binned split; axis -1 if none.

    The primitives boxes[start:stop] (centroid box ``centre_boxes[c]``) are binned along the
    three axes in one pass; bin b of an axis is row ``axis * BINS + b`` of ``bins`` and
    ``counts``, which keep them for the caller. The SAH sum is ``A_left N_left + A_right
    N_right`` (half areas).
    """
    for b in range(3 * BINS):
        _empty_box(bins, b)
        counts[b] = 0
    lows = (centre_boxes[c, 0], centre_boxes[c, 1], centre_boxes[c, 2])
    # An axis without extent (scale 0) puts every primitive in its bin 0 and is not split.
    scales = (
        _bin_scale(centre_boxes, c, 0), _bin_scale(centre_boxes, c, 1),
        _bin_scale(centre_boxes, c, 2),
    )
    for p in range(start, stop):
        # The box in registers: after each store to the bins the compiler would load it again.
        box = (boxes[p, 0], boxes[p, 1], boxes[p, 2], boxes[p, 3], boxes[p, 4], boxes[p, 5])
        for axis in range(3):
            centre = _centre(box[axis], box[3 + axis])
            b = axis * BINS + _bin_index(centre, lows[axis], scales[axis])
            counts[b] += 1
            for field in range(3):
                bins[b, field] = min(bins[b, field], box[field])
                bins[b, 3 + field] = max(bins[b, 3 + field], box[3 + field])
    best_axis = -1
    best_bin = 0
    best_cost = math.inf
    for axis in range(3):
        if scales[axis] == 0.0:
            continue
        first = axis * BINS
        # The non-empty bins, in order, go to filled[:nonempty]: only the splits after them
        # are costed (a split after an empty bin costs what the one before it does, and ties
        # go to the first), and only their boxes are swept.
        nonempty = 0
        for b in range(BINS):
            filled[nonempty] = b
            nonempty += counts[first + b] > 0
        # right_areas[k]: the area of filled bins k+1.., the right side of a split after filled
        # bin k, swept in sweep[0]; the left side grows in sweep[1].
        _empty_box(sweep, 0)
        for k in range(nonempty - 1, 0, -1):
            _grow(sweep, 0, bins, first + filled[k])
            right_areas[k - 1] = _area(sweep, 0)
        _empty_box(sweep, 1)
        left_count = 0
        for k in range(nonempty - 1):
            _grow(sweep, 1, bins, first + filled[k])
            left_count += counts[first + filled[k]]
            cost = _area(sweep, 1) * left_count + right_areas[k] * (stop - start - left_count)
            if cost < best_cost:
                best_axis, best_bin, best_cost = axis, filled[k], cost
    return best_axis, best_bin, best_cost


@njit
def build_bvh(boxes, order, bounds, links):
    """Build the BVH of primitives with boxes (n, 6); return (nodes, depth).

    A primitive's centroid is the centre of its box. ``boxes`` is reordered in place into the
    leaf order, which ``order`` (n,) receives; ``bounds`` (2n, 6) and ``links`` (2n, 2)
    receive the nodes (the first ``nodes`` rows are used). Built depth first with an explicit
    stack of pending nodes. A node's box, and the box of its primitives' centroids, come from
    its parent's split (the bins on each side, the partition), so each node takes one pass
    over its primitives to bin them and one to partition them; only the root and the halves
    of a node with coincident centroids take a pass of their own to find theirs.
    """
    n = order.shape[0]
    for p in range(n):
        order[p] = p
    pending = np.empty((n + 1, 5), dtype=np.intp)  # node, start, stop, depth, boxes known
    centre_boxes = np.empty((n + 1, 6))  # the centroid box of each pending node
    bins = np.empty((3 * BINS, 6))
    counts = np.empty(3 * BINS, dtype=np.intp)
    sweep = np.empty((2, 6))
    right_areas = np.empty(BINS - 1)
    filled = np.empty(BINS, dtype=np.intp)
    pending[0, 0], pending[0, 1], pending[0, 2], pending[0, 3], pending[0, 4] = 0, 0, n, 1, 0
    top = 1
    used = 1
    depth = 0
    while top > 0:
        top -= 1
        node, start = pending[top, 0], pending[top, 1]
        stop, level = pending[top, 2], pending[top, 3]
        depth = max(depth, level)
        if not pending[top, 4]:
            _node_boxes(boxes, start, stop, bounds, node, centre_boxes, top)
        count = stop - start
        middle = start
        # The children are pushed as pending[top + 1] (the left, built first) and
        # pending[top]; their boxes go straight to bounds[used] and bounds[used + 1].
        known = True
        if count > 2:
            axis, last, cost = _best_split(
                boxes, start, stop, centre_boxes, top, bins, counts, sweep, right_areas, filled
            )
            area = _area(bounds, node)
            leaf_cost = float(count)
            split_cost = NODE_COST + (cost / area if area > 0.0 else leaf_cost)
            if axis >= 0 and (split_cost < leaf_cost or count > MAX_LEAF):
                _empty_box(bounds, used)
                _empty_box(bounds, used + 1)
                for b in range(BINS):
                    if counts[axis * BINS + b] > 0:
                        _grow(bounds, used + (b > last), bins, axis * BINS + b)
                middle = _partition(
                    boxes, order, start, stop, axis, last, centre_boxes, top + 1, top
                )
            elif count > MAX_LEAF:
                middle = (start + stop) // 2  # coincident centroids: any halving will do
                known = False
        if middle == start:
            links[node, 0] = start
            links[node, 1] = count
            continue
        links[node, 0] = used
        links[node, 1] = 0
        pending[top, 0], pending[top, 1], pending[top, 2] = used + 1, middle, stop
        pending[top + 1, 0], pending[top + 1, 1], pending[top + 1, 2] = used, start, middle
        for side in range(top, top + 2):
            pending[side, 3], pending[side, 4] = level + 1, known
        top += 2
        used += 2
    return used, depth


@njit(refcount=False, from_python=False)
def _partition(boxes, order, start, stop, axis, last, centre_boxes, left, right):
    """Move the primitives of bins 0..last to the front of [start, stop); return the split.

    ``order`` and ``boxes`` are reordered together. The centroid box of the node, read from
    ``centre_boxes[right]``, is replaced by those of the two sides: ``centre_boxes[left]``
    and ``centre_boxes[right]``.
    """
    low = centre_boxes[right, axis]
    scale = _bin_scale(centre_boxes, right, axis)
    # The sides' centroid boxes, kept in registers.
    left_low = right_low = (math.inf, math.inf, math.inf)
    left_high = right_high = (-math.inf, -math.inf, -math.inf)
    i = start
    j = stop - 1
    while i <= j:
        if _bin_index(_centroid(boxes, i, axis), low, scale) <= last:
            left_low, left_high = _add_centroid(left_low, left_high, boxes, i)
            i += 1
        else:
            right_low, right_high = _add_centroid(right_low, right_high, boxes, i)
            order[i], order[j] = order[j], order[i]
            for field in range(6):
                boxes[i, field], boxes[j, field] = boxes[j, field], boxes[i, field]
            j -= 1
    _set_box(centre_boxes, left, left_low, left_high)
    _set_box(centre_boxes, right, right_low, right_high)
    return i


@njit
def triangle_boxes(tris, boxes):
    """Write the bounding box (T, 6) of every triangle of tris (T, 9)."""
    for i in range(tris.shape[0]):
        for axis in range(3):
            a, b, c = tris[i, axis], tris[i, 3 + axis], tris[i, 6 + axis]
            boxes[i, axis] = min(a, min(b, c))
            boxes[i, 3 + axis] = max(a, max(b, c))


# The warm-ups' scene: one triangle, its corners as a (1, 9) row.
_ONE_TRIANGLE = np.array([[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]])


def warmup() -> None:
    """Compile the BVH build on one triangle (the kernel group ``raytrace-bvh``).

    The tracer calls only these of the module's kernels; the searches and ray tests that
    :mod:`pixelpath.raytrace.bvh` and :mod:`pixelpath.raytrace.geometry` call on batches of
    rays are :func:`warm_queries`' (``raytrace-queries``).
    """
    boxes = np.empty((1, 6))
    triangle_boxes(_ONE_TRIANGLE, boxes)
    build_bvh(boxes, np.empty(1, dtype=np.intp), np.empty((2, 6)), np.empty((2, 2), dtype=np.intp))


def warm_queries() -> None:
    """Compile the batch searches and ray tests on one triangle, a tree of one leaf.

    The tree is written out by hand (the root a leaf of the triangle), so that nothing of
    :func:`warmup`'s group compiles here.
    """
    tris = _ONE_TRIANGLE
    bounds = np.array([[0.0, 0.0, 0.0, 1.0, 1.0, 0.0]])  # its box: min xyz, max xyz
    links = np.array([[0, 1]], dtype=np.intp)
    levels = 2  # the tree's depth, 1, and one more, as the searches' stacks are sized
    source = np.zeros(1, dtype=np.intp)
    rays = np.array([[0.2, 0.2, 1.0]])
    down = np.array([[0.0, 0.0, -1.0]])
    intersect_many(bounds, links, tris, source, np.zeros(0, dtype=np.bool_), False, source, rays,
                   down, np.intp(0), np.intp(1), np.empty((LANES, 9)),
                   np.empty(LANES, dtype=np.intp), np.empty(levels, dtype=np.intp),
                   np.empty(levels), np.empty((levels, LANES)), np.empty(1),
                   np.empty(1, dtype=np.intp))
    stack = np.empty(levels, dtype=np.intp)
    any_triangle(bounds, links, tris, np.zeros(1), 0.2, 0.2, 1.0, 0.0, 0.0, -1.0, 0.0, 2.0, stack)
    t = np.empty(1)
    ray_sphere_many(rays, down, np.zeros((1, 3)), np.ones(1), t)
    ray_plane_many(rays, down, np.zeros((1, 3)), -down, t)
    refract_many(down, -down, np.ones(1), np.empty((1, 3)))
    reflect_many(down, -down, np.empty((1, 3)))
