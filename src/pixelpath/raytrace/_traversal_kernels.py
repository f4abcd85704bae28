"""Compiled BVH searches: the nearest hit and any hit, for one ray and for a packet of four.

Rays are ``R(t) = o + t d`` with t in units of ``|d|``; a hit counts when ``t_min < t < t_max``.
The tree is :mod:`pixelpath.raytrace._bvh_kernels`'s; the ray tests are
:mod:`pixelpath.raytrace._hit_kernels`'.

* ``closest_triangle`` and ``any_triangle``: traversals with an explicit stack. Both test a
  node's two child boxes at the node and go straight on into one child the ray enters, pushing
  the other only when it is entered too (no stack round trip for the child visited next): the
  nearest-hit search the nearer child (the farther one kept with its entry distance, skipped
  when popped beyond the nearest hit found since), the any-hit search the second child; the
  box test grows its far distance by Ize's bound (2γ₃, "Robust BVH ray traversal",
  JCGT 2013) so rounding never prunes a box whose triangle the triangle test would hit. Ties in
  t go to the triangle listed first in the original order (``source``), so the nearest hit is the
  one a brute-force loop over all triangles finds.
* ``closest_triangles4`` and ``any_triangles4``: both searches for packets of four rays, one
  walk of the tree for all four; the box tests of the four rays run side by side, compiled to
  vector instructions (``njit(simd=True)``), and each ray ends with what the one-ray search
  finds. One call traces a block of packets (``BLOCK`` rays from the tracer).
* Alpha-tested triangles (``Cutouts``: a material with an ``alpha_cutoff``): the one-ray
  searches given a ``cutouts`` record ask :func:`cut_away_hit` about a hit on one of them
  before it counts, and a hit whose surface is cut away there is no hit (the ray goes on
  through the hole). Without the record (the default) they are compiled as they were, with
  no test at all, and so are the packet searches, which never test: the tracer traces a
  packet's ray again alone, with the record, when its nearest hit is cut away
  (:mod:`pixelpath.raytrace._whitted_kernels`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from pixelpath._jit import njit
from pixelpath.raytrace._hit_kernels import (
    box_entry,
    box_limit,
    reciprocal,
    shear_setup,
    slab_columns,
    triangle_t,
)
from pixelpath.scene._texture_kernels import cut_away

MISS = -1
LANES = 4  # rays of a packet: one 256-bit vector of float64
BLOCK = 16 * LANES  # rays handed to one call of the packet searches
ROOT = 0  # the root node


class Cutouts(NamedTuple):
    """The alpha-tested triangles of a BVH, and what their alpha test reads, in leaf order."""

    masked: np.ndarray  # (T,) bool: the triangle's surface may be cut away; no rows: none is
    objects: np.ndarray  # (T,) intp: its object (row of the tables)
    uv: np.ndarray  # (3T, 2) texture coordinates at the corners; (0, 2) when unused
    colors: np.ndarray  # (3T, 4) vertex colours at the corners; (0, 4) when unused
    tables: object  # SurfaceTables: textures, alpha and cutoff of each object


@njit(refcount=False, from_python=False)
def cut_away_hit(cutouts, i, w1, w2):
    """Whether triangle i's surface is cut away by its alpha test at barycentric (w1, w2).

    Ask only for triangles with ``cutouts.masked`` set.
    """
    first = 3 * i
    return cut_away(cutouts.tables, cutouts.objects[i], cutouts.uv, cutouts.colors, first,
                    first + 1, first + 2, 1.0 - w1 - w2, w1, w2)


@njit(refcount=False)
def closest_triangle(bounds, links, tris, source, skip, cull, ox, oy, oz, dx, dy, dz, t_min,
                     t_max, stack, stack_t, cutouts=None):
    """Return the nearest triangle hit in (t_min, t_max): (t, i, w1, w2, nodes, tests).

    i is the triangle's position in the leaf order (MISS and t = t_max when nothing is hit);
    with ``cull``, triangles with ``skip[i]`` set are ignored; given ``cutouts``, hits the
    alpha test cuts away do not count (left out, the test is not even compiled in); nodes
    and tests count the boxes and triangles visited. ``stack`` (intp) and ``stack_t``
    (float64) need room for the tree's depth.
    """
    best_t = t_max
    best = MISS
    best_w1 = 0.0
    best_w2 = 0.0
    nodes = 0
    tests = 0
    if links.shape[0] == 0:
        return best_t, best, best_w1, best_w2, nodes, tests
    ix, iy, iz = reciprocal(dx), reciprocal(dy), reciprocal(dz)
    columns = slab_columns(ix, iy, iz)
    kx, ky, kz, okx, oky, okz, sx, sy, sz = shear_setup(ox, oy, oz, dx, dy, dz)
    k = 0
    k_t = box_entry(bounds, 0, ox, oy, oz, ix, iy, iz, columns, t_min, t_max)
    if k_t == math.inf:
        return best_t, best, best_w1, best_w2, nodes, tests
    top = 0
    while True:
        # Visit node k (entered at k_t) unless it lies beyond the nearest hit found so far,
        # then go on with its nearer child hit, or else the node last pushed.
        limit = box_limit(best_t)
        descend = False
        if k_t <= limit:
            nodes += 1
            first = links[k, 0]
            count = links[k, 1]
            if count > 0:
                for i in range(first, first + count):
                    if cull and skip[i]:
                        continue
                    tests += 1
                    t, w1, w2 = triangle_t(tris, i, kx, ky, kz, okx, oky, okz, sx, sy, sz)
                    if t_min < t and (
                        t < best_t or (t == best_t and best != MISS and source[i] < source[best])
                    ):
                        if cutouts is not None:  # a branch Numba prunes when there is none
                            if cutouts.masked[i] and cut_away_hit(cutouts, i, w1, w2):
                                continue
                        best_t, best, best_w1, best_w2 = t, i, w1, w2
            else:
                near_t = box_entry(bounds, first, ox, oy, oz, ix, iy, iz, columns, t_min, limit)
                far_t = box_entry(bounds, first + 1, ox, oy, oz, ix, iy, iz, columns, t_min,
                                  limit)
                near, far = first, first + 1
                if far_t < near_t:
                    near, far, near_t, far_t = far, near, far_t, near_t
                if near_t < math.inf:
                    if far_t < math.inf:
                        stack[top] = far
                        stack_t[top] = far_t
                        top += 1
                    k, k_t = near, near_t
                    descend = True
        if not descend:
            if top == 0:
                break
            top -= 1
            k = stack[top]
            k_t = stack_t[top]
    return best_t, best, best_w1, best_w2, nodes, tests


@njit(refcount=False)
def any_triangle(bounds, links, tris, pass_through, ox, oy, oz, dx, dy, dz, t_min, t_max,
                 stack, cutouts=None):
    """Return (light let through, blocker, nodes, tests) for the segment (t_min, t_max).

    Each triangle hit in the segment multiplies the light let through by its
    ``pass_through`` fraction; the first opaque one (fraction 0) ends the search at once and is
    returned as the blocker (MISS when none); given ``cutouts``, a hit the alpha test cuts
    away lets all the light through. This is the any-hit query of shadow rays: no ordering,
    no nearest hit.
    """
    let_through = 1.0
    nodes = 0
    tests = 0
    if links.shape[0] == 0:
        return let_through, MISS, nodes, tests
    ix, iy, iz = reciprocal(dx), reciprocal(dy), reciprocal(dz)
    columns = slab_columns(ix, iy, iz)
    kx, ky, kz, okx, oky, okz, sx, sy, sz = shear_setup(ox, oy, oz, dx, dy, dz)
    limit = box_limit(t_max)
    if box_entry(bounds, 0, ox, oy, oz, ix, iy, iz, columns, t_min, limit) == math.inf:
        return let_through, MISS, nodes, tests
    k = 0
    top = 0
    while True:
        # Node k's box is entered: test its triangles, or test both children's boxes here and
        # go on with the second child entered (the first kept for later). The fixed order
        # keeps the blocker found and the product of the fractions let through independent
        # of the ray's direction.
        nodes += 1
        first = links[k, 0]
        count = links[k, 1]
        if count == 0:
            enters_first = box_entry(bounds, first, ox, oy, oz, ix, iy, iz, columns, t_min,
                                     limit) < math.inf
            enters_second = box_entry(bounds, first + 1, ox, oy, oz, ix, iy, iz, columns, t_min,
                                      limit) < math.inf
            if enters_second:
                if enters_first:
                    stack[top] = first
                    top += 1
                k = first + 1
                continue
            if enters_first:
                k = first
                continue
        else:
            for i in range(first, first + count):
                tests += 1
                t, w1, w2 = triangle_t(tris, i, kx, ky, kz, okx, oky, okz, sx, sy, sz)
                if t_min < t < t_max:
                    if cutouts is not None:  # a branch Numba prunes when there is none
                        if cutouts.masked[i] and cut_away_hit(cutouts, i, w1, w2):
                            continue
                    if pass_through[i] == 0.0:
                        return 0.0, i, nodes, tests
                    let_through *= pass_through[i]
        if top == 0:
            break
        top -= 1
        k = stack[top]
    return let_through, MISS, nodes, tests


@njit(simd=True, refcount=False, from_python=False)
def _enter_lanes(bounds, k, ox, oy, oz, ix, iy, iz, columns, t_min, limit):
    """Return box k's entry distance for each lane (``box_entry``, four times side by side).

    Not inlined at Numba's level (LLVM inlines it): typing four copies of the box test at each
    call site made the packet searches take seconds longer to compile.
    """
    return (
        box_entry(bounds, k, ox[0], oy[0], oz[0], ix[0], iy[0], iz[0], columns, t_min, limit[0]),
        box_entry(bounds, k, ox[1], oy[1], oz[1], ix[1], iy[1], iz[1], columns, t_min, limit[1]),
        box_entry(bounds, k, ox[2], oy[2], oz[2], ix[2], iy[2], iz[2], columns, t_min, limit[2]),
        box_entry(bounds, k, ox[3], oy[3], oz[3], ix[3], iy[3], iz[3], columns, t_min, limit[3]),
    )


@njit(refcount=False, from_python=False)
def _packet(rays):
    """Return a packet's (coherent, slab columns, ox, oy, oz, 1/dx, 1/dy, 1/dz), each a 4-tuple.

    ``coherent``: every ray's direction has the signs of the first's, so all enter a box
    through the same planes (:func:`slab_columns`).
    """
    ix = (reciprocal(rays[0, 3]), reciprocal(rays[1, 3]), reciprocal(rays[2, 3]),
          reciprocal(rays[3, 3]))
    iy = (reciprocal(rays[0, 4]), reciprocal(rays[1, 4]), reciprocal(rays[2, 4]),
          reciprocal(rays[3, 4]))
    iz = (reciprocal(rays[0, 5]), reciprocal(rays[1, 5]), reciprocal(rays[2, 5]),
          reciprocal(rays[3, 5]))
    columns = slab_columns(ix[0], iy[0], iz[0])
    coherent = True
    for r in range(1, LANES):
        coherent &= slab_columns(_lane(ix, r), _lane(iy, r), _lane(iz, r)) == columns
    ox = (rays[0, 0], rays[1, 0], rays[2, 0], rays[3, 0])
    oy = (rays[0, 1], rays[1, 1], rays[2, 1], rays[3, 1])
    oz = (rays[0, 2], rays[1, 2], rays[2, 2], rays[3, 2])
    return coherent, columns, ox, oy, oz, ix, iy, iz


# Inlined by Numba: as a function of its own LLVM leaves it a call, which returns its 36
# numbers through memory (the shadowed bunny took 2 % longer).
@njit(inline="always")
def _packet_shear(rays):
    """Return each ray's :func:`shear_setup` (the watertight triangle test's constants)."""
    return (
        shear_setup(rays[0, 0], rays[0, 1], rays[0, 2], rays[0, 3], rays[0, 4], rays[0, 5]),
        shear_setup(rays[1, 0], rays[1, 1], rays[1, 2], rays[1, 3], rays[1, 4], rays[1, 5]),
        shear_setup(rays[2, 0], rays[2, 1], rays[2, 2], rays[2, 3], rays[2, 4], rays[2, 5]),
        shear_setup(rays[3, 0], rays[3, 1], rays[3, 2], rays[3, 3], rays[3, 4], rays[3, 5]),
    )


@njit(refcount=False, from_python=False)
def _lane_limits(best_t):
    """Return each lane's farthest box entry still worth visiting (its nearest hit, grown)."""
    return (
        box_limit(best_t[0]), box_limit(best_t[1]), box_limit(best_t[2]), box_limit(best_t[3])
    )


@njit(refcount=False, from_python=False)
def _lane(values, r):
    return values[0] if r == 0 else values[1] if r == 1 else values[2] if r == 2 else values[3]


@njit(refcount=False, from_python=False)
def _lanes_entering(entry, limit):
    return (
        (entry[0] <= limit[0]) + (entry[1] <= limit[1]) + (entry[2] <= limit[2])
        + (entry[3] <= limit[3])
    )


@njit(simd=True, refcount=False)
def closest_triangles4(bounds, links, tris, source, skip, cull, rays, count, t_min, hit, stack,
                       stack_t, lane_t):
    """Find what :func:`closest_triangle` finds for each of the first ``count`` rays of ``rays``.

    ``rays`` (n, 9), n at least ``count`` rounded up to a multiple of ``LANES``: each row holds
    a ray's origin and direction in columns 0-5 and its t_max in column 6; the kernel writes t
    (left at t_max on a miss) and the weights w1, w2 into columns 6-8 and the triangle (MISS on
    a miss) into ``hit`` (n,). Rays 0-3, 4-7, ... are traced as packets (:func:`_closest_packet`),
    a last packet of fewer than ``LANES`` rays one by one. Returns (nodes, tests) summed over
    the rays. One call for many packets: a call passes the tree's arrays and the scratch, some
    eighty machine words, which cost as much as a packet's whole walk where it misses the tree.
    """
    nodes = 0
    tests = 0
    for first in range(0, count, LANES):
        n, m = _closest_packet(
            bounds, links, tris, source, skip, cull, rays[first:first + LANES],
            min(LANES, count - first), t_min, hit[first:first + LANES], stack, stack_t, lane_t,
        )
        nodes += n
        tests += m
    return nodes, tests


# Inlined by Numba into closest_triangles4, its one caller: a call per packet is what that
# function saves.
@njit(inline="always")
def _closest_packet(bounds, links, tris, source, skip, cull, rays, lanes, t_min, hit, stack,
                    stack_t, lane_t):
    """Find what :func:`closest_triangle` finds for each of ``LANES`` rays, in one walk.

    The first ``lanes`` rows of ``rays`` (LANES, 9) are traced (fewer than ``LANES``: one by
    one, as at the end of a row), as :func:`closest_triangles4` says; a node counts once for
    each ray that enters it. The walk visits a node when any ray enters it before its nearest
    hit so far, testing both children's boxes for all four rays with the same arithmetic side
    by side (compiled to vector instructions); rays whose directions differ in sign on an axis
    enter boxes through different planes and are traced one by one instead. ``stack_t`` is
    :func:`closest_triangle`'s, ``lane_t`` (depth + 1, LANES) float64.
    """
    nodes = 0
    tests = 0
    coherent, columns, ox, oy, oz, ix, iy, iz = _packet(rays)
    if lanes < LANES or not coherent or links.shape[0] == 0:
        for r in range(lanes):
            t, i, w1, w2, n, m = closest_triangle(
                bounds, links, tris, source, skip, cull, rays[r, 0], rays[r, 1], rays[r, 2],
                rays[r, 3], rays[r, 4], rays[r, 5], t_min, rays[r, 6], stack, stack_t,
            )
            rays[r, 6], rays[r, 7], rays[r, 8], hit[r] = t, w1, w2, i
            nodes += n
            tests += m
        return nodes, tests
    for r in range(LANES):
        hit[r] = MISS
    best_t = rays[:, 6]
    entry = _enter_lanes(bounds, ROOT, ox, oy, oz, ix, iy, iz, columns, t_min,
                         (best_t[0], best_t[1], best_t[2], best_t[3]))
    limit = _lane_limits(best_t)
    if _lanes_entering(entry, limit) == 0:
        return nodes, tests
    shear = _packet_shear(rays)
    k = 0
    top = 0
    while True:
        # Node k is entered by the rays whose entry is within their limit: test its
        # triangles for them, or go on into the child that a ray enters first, keeping the
        # other for later with each ray's entry distance.
        entering = _lanes_entering(entry, limit)
        if entering > 0:
            nodes += entering
            first = links[k, 0]
            count = links[k, 1]
            if count > 0:
                for r in range(LANES):
                    if _lane(entry, r) > _lane(limit, r):
                        continue
                    kx, ky, kz, okx, oky, okz, sx, sy, sz = shear[r]
                    for i in range(first, first + count):
                        if cull and skip[i]:
                            continue
                        tests += 1
                        t, w1, w2 = triangle_t(tris, i, kx, ky, kz, okx, oky, okz, sx, sy, sz)
                        best = hit[r]
                        if t_min < t and (t < best_t[r] or (
                            t == best_t[r] and best != MISS and source[i] < source[best]
                        )):
                            rays[r, 6], rays[r, 7], rays[r, 8], hit[r] = t, w1, w2, i
                limit = _lane_limits(best_t)
            else:
                near = _enter_lanes(bounds, first, ox, oy, oz, ix, iy, iz, columns, t_min, limit)
                far = _enter_lanes(bounds, first + 1, ox, oy, oz, ix, iy, iz, columns, t_min,
                                   limit)
                near_first = min(min(near[0], near[1]), min(near[2], near[3]))
                far_first = min(min(far[0], far[1]), min(far[2], far[3]))
                near_child, far_child = first, first + 1
                if far_first < near_first:
                    near, far, near_first, far_first = far, near, far_first, near_first
                    near_child, far_child = far_child, near_child
                if near_first < math.inf:
                    if far_first < math.inf:
                        stack[top] = far_child
                        for r in range(LANES):
                            lane_t[top, r] = _lane(far, r)
                        top += 1
                    k, entry = near_child, near
                    continue
        if top == 0:
            break
        top -= 1
        k = stack[top]
        entry = (lane_t[top, 0], lane_t[top, 1], lane_t[top, 2], lane_t[top, 3])
    return nodes, tests


@njit(refcount=False, from_python=False)
def _lanes_in(entry):
    """Return the bit mask of the lanes whose entry is finite (bit r for lane r)."""
    return (
        (1 if entry[0] < math.inf else 0) | (2 if entry[1] < math.inf else 0)
        | (4 if entry[2] < math.inf else 0) | (8 if entry[3] < math.inf else 0)
    )


@njit(refcount=False, from_python=False)
def _lane_count(mask):
    return (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + ((mask >> 3) & 1)


@njit(simd=True, refcount=False)
def any_triangles4(bounds, links, tris, pass_through, rays, count, t_min, hit, stack):
    """Run :func:`any_triangle` for each of the first ``count`` segments of ``rays``.

    ``rays`` (n, 8 or more), n at least ``count`` rounded up to a multiple of ``LANES``: each
    row holds a segment's origin and direction in columns 0-5 and its t_max in column 6; the
    kernel writes the light let through into column 7 and the blocker (MISS when none) into
    ``hit`` (n,). Segments 0-3, 4-7, ... are traced as packets (:func:`_any_packet`), a last
    packet of fewer than ``LANES`` one by one, many packets a call (as
    :func:`closest_triangles4`). Returns (nodes, tests) summed over the segments.
    """
    nodes = 0
    tests = 0
    for first in range(0, count, LANES):
        n, m = _any_packet(bounds, links, tris, pass_through, rays[first:first + LANES],
                           min(LANES, count - first), t_min, hit[first:first + LANES], stack)
        nodes += n
        tests += m
    return nodes, tests


# Inlined by Numba into any_triangles4, its one caller (see _closest_packet).
@njit(inline="always")
def _any_packet(bounds, links, tris, pass_through, rays, lanes, t_min, hit, stack):
    """Run :func:`any_triangle` for each of ``LANES`` segments, in one walk of the tree.

    The first ``lanes`` rows of ``rays`` are traced (fewer than ``LANES``: one by one), as
    :func:`any_triangles4` says. The walk takes the children in any_triangle's fixed order,
    each ray only into the boxes it enters and only until it is blocked, so each ray visits
    the nodes, tests the triangles and multiplies the fractions let through that it would
    alone, in the same order: the same blocker and bit for bit the same light. The stack
    holds a node and the mask of the rays entering it (``node << LANES | mask``); rays whose
    directions differ in sign on an axis go one by one.
    """
    nodes = 0
    tests = 0
    coherent, columns, ox, oy, oz, ix, iy, iz = _packet(rays)
    if lanes < LANES or not coherent or links.shape[0] == 0:
        for r in range(lanes):
            rays[r, 7], hit[r], n, m = any_triangle(
                bounds, links, tris, pass_through, rays[r, 0], rays[r, 1], rays[r, 2],
                rays[r, 3], rays[r, 4], rays[r, 5], t_min, rays[r, 6], stack,
            )
            nodes += n
            tests += m
        return nodes, tests
    for r in range(LANES):
        rays[r, 7] = 1.0
        hit[r] = MISS
    t_max = (rays[0, 6], rays[1, 6], rays[2, 6], rays[3, 6])
    limit = _lane_limits(t_max)
    active = _lanes_in(_enter_lanes(bounds, ROOT, ox, oy, oz, ix, iy, iz, columns, t_min, limit))
    if active == 0:
        return nodes, tests
    shear = _packet_shear(rays)
    blocked = 0
    k = 0
    top = 0
    while True:
        # Node k's box is entered by the rays of ``active``: test its triangles for them, or
        # go on into the second child with the rays entering it (the first kept for later).
        nodes += _lane_count(active)
        first = links[k, 0]
        count = links[k, 1]
        if count == 0:
            in_first = active & _lanes_in(
                _enter_lanes(bounds, first, ox, oy, oz, ix, iy, iz, columns, t_min, limit)
            )
            in_second = active & _lanes_in(
                _enter_lanes(bounds, first + 1, ox, oy, oz, ix, iy, iz, columns, t_min, limit)
            )
            if in_second:
                if in_first:
                    stack[top] = first << LANES | in_first
                    top += 1
                k, active = first + 1, in_second
                continue
            if in_first:
                k, active = first, in_first
                continue
        else:
            for r in range(LANES):
                if not (active >> r) & 1:
                    continue
                kx, ky, kz, okx, oky, okz, sx, sy, sz = shear[r]
                for i in range(first, first + count):
                    tests += 1
                    t, _, _ = triangle_t(tris, i, kx, ky, kz, okx, oky, okz, sx, sy, sz)
                    if t_min < t < _lane(t_max, r):
                        if pass_through[i] == 0.0:
                            rays[r, 7], hit[r] = 0.0, i
                            blocked |= 1 << r
                            break
                        rays[r, 7] *= pass_through[i]
        active = 0
        while active == 0 and top > 0:  # the next node kept, for the rays not yet blocked
            top -= 1
            k = stack[top] >> LANES
            active = stack[top] & ~blocked & (2**LANES - 1)
        if active == 0:
            break
    return nodes, tests


@njit(refcount=False)
def intersect_many(bounds, links, tris, source, skip, cull, labels, origins, directions, start,
                   stop, packet, hit, stack, stack_t, lane_t, t_out, label_out):
    """Write the nearest hit of rays start..stop-1 of (N, 3): its t and its triangle's label.

    t is inf on a miss; the label of the triangle at leaf position i is ``labels[i]`` (MISS on
    a miss).

    Runs of ``LANES`` consecutive rays are traced as a packet (:func:`closest_triangles4`,
    ``BLOCK`` rays a call): neighbouring pixels' rays, or any rays given in a coherent order,
    walk the tree once together, and rays that do not fit a packet are traced one by one.
    ``skip`` and ``cull`` are the packet search's, passed in, and so is its scratch
    (``packet`` (BLOCK, 9), ``hit`` (BLOCK,), the stacks). Serial: the
    caller runs disjoint ranges of rays from several threads, each with its own scratch.

    Returns whether any of the rays is unusable (a NaN or an infinity, or a zero direction),
    checked as they are read: such a ray is traced as another, harmless one, and the caller
    raises an error instead of answering.
    """
    unusable = False
    for first in range(start, stop, BLOCK):
        count = min(BLOCK, stop - first)
        for r in range(count):
            for axis in range(3):
                packet[r, axis] = origins[first + r, axis]
                packet[r, 3 + axis] = directions[first + r, axis]
            packet[r, 6] = math.inf
            if not _usable_ray(packet, r):  # traced as a harmless ray: the search divides
                unusable = True             # by the direction, and the answer goes unread
                for column in range(6):
                    packet[r, column] = 0.0
                packet[r, 5] = 1.0
        closest_triangles4(bounds, links, tris, source, skip, cull, packet, count, 0.0, hit,
                           stack, stack_t, lane_t)
        for r in range(count):
            t_out[first + r] = packet[r, 6]
            label_out[first + r] = MISS if hit[r] == MISS else labels[hit[r]]
    return unusable


@njit(refcount=False, from_python=False)
def _usable_ray(packet, r):
    """Whether row r of a packet holds a finite origin and a finite, non-zero direction.

    ``x * 0.0`` is 0 for a finite x and NaN otherwise: one sum of six such products says
    whether all six numbers are finite, without a branch per number.
    """
    finite = (packet[r, 0] * 0.0 + packet[r, 1] * 0.0 + packet[r, 2] * 0.0 + packet[r, 3] * 0.0
              + packet[r, 4] * 0.0 + packet[r, 5] * 0.0) == 0.0
    return finite and (packet[r, 3] != 0.0 or packet[r, 4] != 0.0 or packet[r, 5] != 0.0)
