"""Compiled BVH build: the triangles' boxes and a bounding-volume hierarchy over them.

``build_bvh`` keeps the hierarchy in flat arrays, built top-down with the binned surface-area
heuristic (Wald 2007): at each node the triangles' centroids are put into ``BINS`` bins along
each axis and the split with the least ``A_left N_left + A_right N_right`` is taken when it
beats a leaf. Node k is ``bounds[k] = (min xyz, max xyz)`` and ``links[k] = (first, count)``:
a leaf holds ``count > 0`` triangles from position ``first`` of the leaf order; an inner node
(count 0) has children ``first`` and ``first + 1``.

The searches of the tree are :mod:`pixelpath.raytrace._traversal_kernels`'. :func:`warmup`
compiles the build, the searches and the ray tests of :mod:`pixelpath.raytrace._hit_kernels`
(the kernel group ``raytrace-bvh``).
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
def _bin_of(centroids, p, axis, low, scale):
    b = int((centroids[p, axis] - low) * scale)
    return min(max(b, 0), BINS - 1)


@njit
def _best_split(boxes, centroids, order, start, stop, centre_box, bins, sweep, counts):
    """Return (axis, last bin of the left side, SAH sum) of the best binned split; axis -1 if none.

    The SAH sum is ``A_left N_left + A_right N_right`` (half areas).
    """
    best_axis = -1
    best_bin = 0
    best_cost = math.inf
    for axis in range(3):
        low = centre_box[0, axis]
        extent = centre_box[0, 3 + axis] - low
        if not extent > 0.0:
            continue
        scale = BINS / extent
        for b in range(BINS):
            _empty_box(bins, b)
            counts[b] = 0
        for p in range(start, stop):
            b = _bin_of(centroids, order[p], axis, low, scale)
            counts[b] += 1
            _grow(bins, b, boxes, order[p])
        # sweep[b] becomes the box of bins b+1.. (the right side of a split after bin b),
        # accumulated in sweep[BINS - 1]; the left side accumulates in bins[BINS].
        _empty_box(sweep, BINS - 1)
        for b in range(BINS - 1, 0, -1):
            _grow(sweep, BINS - 1, bins, b)
            for field in range(6):
                sweep[b - 1, field] = sweep[BINS - 1, field]
        _empty_box(bins, BINS)
        left_count = 0
        right_count = stop - start
        for b in range(BINS - 1):
            _grow(bins, BINS, bins, b)
            left_count += counts[b]
            right_count -= counts[b]
            if left_count == 0 or right_count == 0:
                continue
            cost = _area(bins, BINS) * left_count + _area(sweep, b) * right_count
            if cost < best_cost:
                best_axis, best_bin, best_cost = axis, b, cost
    return best_axis, best_bin, best_cost


@njit
def build_bvh(boxes, centroids, order, bounds, links):
    """Build the BVH of primitives with boxes (n, 6) and centroids (n, 3); return (nodes, depth).

    ``order`` (n,) receives the leaf order of the primitives; ``bounds`` (2n, 6) and ``links``
    (2n, 2) receive the nodes (the first ``nodes`` rows are used). Built depth first with an
    explicit stack of pending nodes.
    """
    n = order.shape[0]
    for p in range(n):
        order[p] = p
    pending = np.empty((n + 1, 4), dtype=np.intp)  # node, start, stop, depth
    bins = np.empty((BINS + 1, 6))
    sweep = np.empty((BINS, 6))
    counts = np.zeros(BINS, dtype=np.intp)
    centre_box = np.empty((1, 6))
    pending[0, 0], pending[0, 1], pending[0, 2], pending[0, 3] = 0, 0, n, 1
    top = 1
    used = 1
    depth = 0
    while top > 0:
        top -= 1
        node, start = pending[top, 0], pending[top, 1]
        stop, level = pending[top, 2], pending[top, 3]
        depth = max(depth, level)
        _empty_box(bounds, node)
        _empty_box(centre_box, 0)
        for p in range(start, stop):
            _grow(bounds, node, boxes, order[p])
            for axis in range(3):
                c = centroids[order[p], axis]
                centre_box[0, axis] = min(centre_box[0, axis], c)
                centre_box[0, 3 + axis] = max(centre_box[0, 3 + axis], c)
        count = stop - start
        middle = start
        if count > 2:
            axis, last, cost = _best_split(
                boxes, centroids, order, start, stop, centre_box, bins, sweep, counts
            )
            area = _area(bounds, node)
            leaf_cost = float(count)
            split_cost = NODE_COST + (cost / area if area > 0.0 else leaf_cost)
            if axis >= 0 and (split_cost < leaf_cost or count > MAX_LEAF):
                middle = _partition(centroids, order, start, stop, axis, centre_box, last)
            elif count > MAX_LEAF:
                middle = (start + stop) // 2  # coincident centroids: any halving will do
        if middle == start:
            links[node, 0] = start
            links[node, 1] = count
            continue
        links[node, 0] = used
        links[node, 1] = 0
        pending[top, 0], pending[top, 1], pending[top, 2], pending[top, 3] = (
            used + 1, middle, stop, level + 1
        )
        pending[top + 1, 0], pending[top + 1, 1], pending[top + 1, 2], pending[top + 1, 3] = (
            used, start, middle, level + 1
        )
        top += 2
        used += 2
    return used, depth


@njit
def _partition(centroids, order, start, stop, axis, centre_box, last):
    """Move the primitives of bins 0..last to the front of order[start:stop]; return the split."""
    low = centre_box[0, axis]
    scale = BINS / (centre_box[0, 3 + axis] - low)
    i = start
    j = stop - 1
    while i <= j:
        if _bin_of(centroids, order[i], axis, low, scale) <= last:
            i += 1
        else:
            order[i], order[j] = order[j], order[i]
            j -= 1
    return i


@njit
def triangle_boxes(tris, boxes, centroids):
    """Write the bounding box (T, 6) and the box centre (T, 3) of every triangle of tris (T, 9)."""
    for i in range(tris.shape[0]):
        for axis in range(3):
            a, b, c = tris[i, axis], tris[i, 3 + axis], tris[i, 6 + axis]
            low = min(a, min(b, c))
            high = max(a, max(b, c))
            boxes[i, axis] = low
            boxes[i, 3 + axis] = high
            centroids[i, axis] = 0.5 * (low + high)


def warmup() -> None:
    """Compile the BVH build, both traversals and the public batch kernels on one triangle."""
    tris = np.array([[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]])
    boxes = np.empty((1, 6))
    centroids = np.empty((1, 3))
    triangle_boxes(tris, boxes, centroids)
    order = np.empty(1, dtype=np.intp)
    bounds = np.empty((2, 6))
    links = np.empty((2, 2), dtype=np.intp)
    _, depth = build_bvh(boxes, centroids, order, bounds, links)
    source = np.zeros(1, dtype=np.intp)
    rays = np.array([[0.2, 0.2, 1.0]])
    down = np.array([[0.0, 0.0, -1.0]])
    levels = depth + 1
    intersect_many(bounds, links, tris, source, np.zeros(0, dtype=np.bool_), False, source, rays,
                   down, np.intp(0), np.intp(1), np.empty((LANES, 9)),
                   np.empty(LANES, dtype=np.intp), np.empty(levels, dtype=np.intp),
                   np.empty(levels), np.empty((levels, LANES)), np.empty(1),
                   np.empty(1, dtype=np.intp))
    stack = np.empty(depth + 1, dtype=np.intp)
    any_triangle(bounds, links, tris, np.zeros(1), 0.2, 0.2, 1.0, 0.0, 0.0, -1.0, 0.0, 2.0, stack)
    t = np.empty(1)
    ray_sphere_many(rays, down, np.zeros((1, 3)), np.ones(1), t)
    ray_plane_many(rays, down, np.zeros((1, 3)), -down, t)
    refract_many(down, -down, np.ones(1), np.empty((1, 3)))
    reflect_many(down, -down, np.empty((1, 3)))
