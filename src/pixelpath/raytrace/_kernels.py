"""Compiled ray-geometry kernels: ray-primitive tests, the BVH build and its two traversals.

Rays are ``R(t) = o + t d`` with t in units of ``|d|``; a hit counts when ``t_min < t < t_max``.

* ``sphere_roots``: the notes' quadratic ``|o + t d − C|² = r²``, solved without cancellation:
  with ``f = o − C``, ``a = d·d`` and ``h = d·f`` (half the notes' b), the discriminant
  ``h² − a c`` is computed as ``a (r² − |f − (h/a) d|²)`` (the squared distance from the centre
  to the line; Ray Tracing Gems, ch. 7), and the roots as ``q/a`` and ``c/q`` with
  ``q = −(h + sign(h) √disc)``. An origin within a few units in the last place (of its own
  and the centre's coordinates) of the surface is *on* it (c = 0): its root t = 0 is no hit,
  so a ray leaving a surface never hits it again.
* ``plane_t``: ``t = n·(Q − o) / (n·d)`` (SPEC §9 errata: the notes print P0 twice); inf when
  the ray is parallel to the plane.
* ``triangle_t``: the watertight test of Woop, Benthin and Wald (JCGT 2013). The ray is sheared
  so that it runs along +z from the origin; each edge's 2D edge function is computed from its two
  end points in an order that makes a shared edge give exactly opposite values in the two
  triangles, so a ray through an edge or a vertex hits at least one of the triangles there,
  never none. Both sides of a triangle are hit (culling is the caller's business).
* ``build_bvh``: a bounding-volume hierarchy in flat arrays, built top-down with the binned
  surface-area heuristic (Wald 2007): at each node the triangles' centroids are put into
  ``BINS`` bins along each axis and the split with the least ``A_left N_left + A_right N_right``
  is taken when it beats a leaf. Node k is ``bounds[k] = (min xyz, max xyz)`` and
  ``links[k] = (first, count)``: a leaf holds ``count > 0`` triangles from position ``first``
  of the leaf order; an inner node (count 0) has children ``first`` and ``first + 1``.
* ``closest_triangle`` and ``any_triangle``: traversals with an explicit stack. Both test a
  node's two child boxes at the node and go straight on into one child the ray enters, pushing
  the other only when it is entered too (no stack round trip for the child visited next): the
  nearest-hit search the nearer child (the farther one kept with its entry distance, skipped
  when popped beyond the nearest hit found since), the any-hit search the second child; the
  box test grows its far distance by Ize's bound (2γ₃, "Robust BVH ray traversal",
  JCGT 2013) so rounding never prunes a box whose triangle the triangle test would hit. Ties in
  t go to the triangle listed first in the original order (``source``), so the nearest hit is the
  one a brute-force loop over all triangles finds.
* ``closest_triangles4`` and ``any_triangles4``: both searches for a packet of four rays, one
  walk of the tree for all four; the box tests of the four rays run side by side, compiled to
  vector instructions (``njit(simd=True)``), and each ray ends with what the one-ray search
  finds.
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
from pixelpath.scene._texture_kernels import cut_away

EPS = float(np.finfo(np.float64).eps)
# An origin whose |o − C|² − r² is within this fraction of |o − C|² + r² lies on the sphere.
SURFACE_TOLERANCE = 4.0 * EPS
# Slab distances are off by at most γ₃ = 3ε/(1 − 3ε) relatively (Ize 2013); 2γ₃ covers both ends.
BOX_SLACK = 2.0 * (3.0 * EPS / (1.0 - 3.0 * EPS))
BINS = 16  # SAH bins per axis
MAX_LEAF = 8  # a node holding more triangles than this is split even when a leaf costs less
NODE_COST = 1.0  # SAH: cost of visiting a node, relative to one triangle test
MISS = -1
LANES = 4  # rays of a packet: one 256-bit vector of float64
ROOT = np.intp(0)  # the root node: not the literal 0, which _enter_lanes was compiled for again


class Cutouts(NamedTuple):
    """The alpha-tested triangles of a BVH, and what their alpha test reads, in leaf order."""

    masked: np.ndarray  # (T,) bool: the triangle's surface may be cut away; no rows: none is
    objects: np.ndarray  # (T,) intp: its object (row of the tables)
    uv: np.ndarray  # (3T, 2) texture coordinates at the corners; (0, 2) when unused
    colors: np.ndarray  # (3T, 4) vertex colours at the corners; (0, 4) when unused
    tables: object  # SurfaceTables: textures, alpha and cutoff of each object


@njit(refcount=False)
def cut_away_hit(cutouts, i, w1, w2):
    """Whether triangle i's surface is cut away by its alpha test at barycentric (w1, w2).

    Ask only for triangles with ``cutouts.masked`` set.
    """
    first = 3 * i
    return cut_away(cutouts.tables, cutouts.objects[i], cutouts.uv, cutouts.colors, first,
                    first + 1, first + 2, 1.0 - w1 - w2, w1, w2)


@njit(inline="always")
def sphere_roots(ox, oy, oz, dx, dy, dz, cx, cy, cz, radius):
    """Return the roots t0 <= t1 of the ray-sphere quadratic, (inf, inf) when it misses."""
    fx = ox - cx
    fy = oy - cy
    fz = oz - cz
    a = dx * dx + dy * dy + dz * dz
    h = dx * fx + dy * fy + dz * fz
    ff = fx * fx + fy * fy + fz * fz
    rr = radius * radius
    c = ff - rr
    # o − C is rounded to the ulp of the larger coordinates: |f|² carries an error of about
    # 2|f|·ulp(size) on top of its own rounding.
    size = max(max(abs(ox), abs(oy), abs(oz)), max(abs(cx), abs(cy), abs(cz)))
    if abs(c) <= SURFACE_TOLERANCE * (ff + rr + 4.0 * math.sqrt(ff) * size):
        c = 0.0  # the origin is on the surface: one root is exactly 0
    s = h / a
    lx = fx - s * dx
    ly = fy - s * dy
    lz = fz - s * dz
    disc = a * (rr - (lx * lx + ly * ly + lz * lz))
    if disc < 0.0:
        return math.inf, math.inf
    root = math.sqrt(disc)
    q = -(h + root) if h >= 0.0 else root - h
    if q == 0.0:  # h = 0 and disc = 0: a tangent ray starting at its point of contact
        return 0.0, 0.0
    t0 = q / a
    t1 = c / q
    return (t0, t1) if t0 <= t1 else (t1, t0)


@njit(inline="always")
def sphere_t(t0, t1, t_min, t_max, cull):
    """Return the nearest root in (t_min, t_max), inf if none; with cull, the entering root only.

    t0 is where the line enters the sphere, t1 where it leaves: culling back faces keeps t0.
    """
    if t_min < t0 < t_max:
        return t0
    if not cull and t_min < t1 < t_max:
        return t1
    return math.inf


@njit(inline="always")
def plane_t(ox, oy, oz, dx, dy, dz, qx, qy, qz, nx, ny, nz):
    """Return t = n·(Q − o) / (n·d): inf when parallel, 0 for an origin on the plane."""
    denominator = nx * dx + ny * dy + nz * dz
    if denominator == 0.0:
        return math.inf
    numerator = nx * (qx - ox) + ny * (qy - oy) + nz * (qz - oz)
    size = (abs(qx) + abs(qy) + abs(qz) + abs(ox) + abs(oy) + abs(oz)) * (
        abs(nx) + abs(ny) + abs(nz)
    )
    if abs(numerator) <= SURFACE_TOLERANCE * size:
        return 0.0
    return numerator / denominator


def slab_nan_allowed():
    """Return a context in which the slab test's intended NaN (0·inf) raises no warning.

    Compiled code never warns; with ``NUMBA_DISABLE_JIT=1`` the kernels run on NumPy scalars,
    which do. The public functions call the traversals inside this context.
    """
    return np.errstate(invalid="ignore")


@njit(inline="always")
def reciprocal(value):
    """Return 1/value, ±inf for ±0 (the sign of zero kept), with no division by zero."""
    return 1.0 / value if value != 0.0 else math.copysign(math.inf, value)


@njit(inline="always")
def shear_setup(ox, oy, oz, dx, dy, dz):
    """Per-ray constants of the watertight test: axes (kx, ky, kz), origin on them, shear."""
    ax, ay, az = abs(dx), abs(dy), abs(dz)
    kz = 0 if ax >= ay and ax >= az else (1 if ay >= az else 2)
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    d = (dx, dy, dz)
    if d[kz] < 0.0:  # keep the winding: swap x and y when looking down -z
        kx, ky = ky, kx
    o = (ox, oy, oz)
    inv = 1.0 / d[kz]
    return kx, ky, kz, o[kx], o[ky], o[kz], d[kx] * inv, d[ky] * inv, inv


@njit(inline="always")
def triangle_t(tris, i, kx, ky, kz, okx, oky, okz, sx, sy, sz):
    """Return (t, w1, w2) of the ray with triangle i of tris (T, 9); t = inf on a miss.

    w1 and w2 are the barycentric weights of corners 1 and 2 (corner 0 has 1 − w1 − w2).
    """
    ax = tris[i, kx] - okx
    ay = tris[i, ky] - oky
    az = tris[i, kz] - okz
    bx = tris[i, 3 + kx] - okx
    by = tris[i, 3 + ky] - oky
    bz = tris[i, 3 + kz] - okz
    cx = tris[i, 6 + kx] - okx
    cy = tris[i, 6 + ky] - oky
    cz = tris[i, 6 + kz] - okz
    ax -= sx * az
    ay -= sy * az
    bx -= sx * bz
    by -= sy * bz
    cx -= sx * cz
    cy -= sy * cz
    # Edge functions: for the edge from P to Q, Q.x P.y − Q.y P.x (opposite P's partner corner).
    u = cx * by - cy * bx
    v = ax * cy - ay * cx
    w = bx * ay - by * ax
    if (u < 0.0 or v < 0.0 or w < 0.0) and (u > 0.0 or v > 0.0 or w > 0.0):
        return math.inf, 0.0, 0.0
    det = u + v + w
    if det == 0.0:
        return math.inf, 0.0, 0.0
    inv = 1.0 / det
    return sz * (u * az + v * bz + w * cz) * inv, v * inv, w * inv


@njit(inline="always")
def slab_columns(ix, iy, iz):
    """Return the columns of a box row holding each axis's near and far plane for this ray.

    A box row is (min x, min y, min z, max x, max y, max z): a ray going towards -x enters
    through max x. Choosing the columns once per ray keeps the box test free of branches.
    """
    nx = 0 if ix >= 0.0 else 3
    ny = 1 if iy >= 0.0 else 4
    nz = 2 if iz >= 0.0 else 5
    return nx, ny, nz, 3 - nx, 5 - ny, 7 - nz


@njit(inline="always")
def box_limit(t):
    """Return t grown by the box test's rounding bound: the farthest box entry worth visiting.

    A box entered up to here may still hold a hit at t (or end the segment there); the same
    growth widens the exit distance inside :func:`box_entry`.
    """
    return t + abs(t) * BOX_SLACK


@njit(inline="always")
def box_entry(bounds, k, ox, oy, oz, ix, iy, iz, columns, t_min, t_max):
    """Return where the ray enters box k within [t_min, t_max], inf when it misses it.

    ``ix, iy, iz`` are 1/d (±inf for a zero component) and ``columns`` the ray's
    :func:`slab_columns`. A ray lying in a slab's plane makes 0·inf = NaN there; each
    comparison with NaN is false and keeps the other value, so that plane constrains nothing.
    """
    nx, ny, nz, fx, fy, fz = columns
    near_x = (bounds[k, nx] - ox) * ix
    near_y = (bounds[k, ny] - oy) * iy
    near_z = (bounds[k, nz] - oz) * iz
    far_x = (bounds[k, fx] - ox) * ix
    far_y = (bounds[k, fy] - oy) * iy
    far_z = (bounds[k, fz] - oz) * iz
    lo = near_x if near_x > t_min else t_min
    lo = near_y if near_y > lo else lo
    lo = near_z if near_z > lo else lo
    hi = far_x if far_x < t_max else t_max
    hi = far_y if far_y < hi else hi
    hi = far_z if far_z < hi else hi
    return lo if lo <= box_limit(hi) else math.inf


@njit(inline="always")
def enters_box(bounds, k, ox, oy, oz, dx, dy, dz, t_min, t_max):
    """Return whether the ray enters box k within [t_min, t_max]: the traversals' own test.

    A ray that misses the root box (k = 0) finds nothing in the tree, so callers with many
    such rays test it first and spare the traversal's set-up.
    """
    ix, iy, iz = reciprocal(dx), reciprocal(dy), reciprocal(dz)
    columns = slab_columns(ix, iy, iz)
    return box_entry(bounds, k, ox, oy, oz, ix, iy, iz, columns, t_min, t_max) < math.inf


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


@njit(simd=True, refcount=False)
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


@njit(refcount=False)
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


@njit(refcount=False)
def _packet_shear(rays):
    """Return each ray's :func:`shear_setup` (the watertight triangle test's constants)."""
    return (
        shear_setup(rays[0, 0], rays[0, 1], rays[0, 2], rays[0, 3], rays[0, 4], rays[0, 5]),
        shear_setup(rays[1, 0], rays[1, 1], rays[1, 2], rays[1, 3], rays[1, 4], rays[1, 5]),
        shear_setup(rays[2, 0], rays[2, 1], rays[2, 2], rays[2, 3], rays[2, 4], rays[2, 5]),
        shear_setup(rays[3, 0], rays[3, 1], rays[3, 2], rays[3, 3], rays[3, 4], rays[3, 5]),
    )


@njit(inline="always")
def _lane_limits(best_t):
    """Return each lane's farthest box entry still worth visiting (its nearest hit, grown)."""
    return (
        box_limit(best_t[0]), box_limit(best_t[1]), box_limit(best_t[2]), box_limit(best_t[3])
    )


@njit(inline="always")
def _lane(values, r):
    return values[0] if r == 0 else values[1] if r == 1 else values[2] if r == 2 else values[3]


@njit(inline="always")
def _lanes_entering(entry, limit):
    return (
        (entry[0] <= limit[0]) + (entry[1] <= limit[1]) + (entry[2] <= limit[2])
        + (entry[3] <= limit[3])
    )


@njit(simd=True, refcount=False)
def closest_triangles4(bounds, links, tris, source, skip, cull, rays, lanes, t_min, hit, stack,
                       stack_t, lane_t):
    """Find what :func:`closest_triangle` finds for each of ``LANES`` rays, in one walk.

    The first ``lanes`` rows of ``rays`` (LANES, 9) are traced (fewer than ``LANES``: one by
    one, as at the end of a row); each holds a ray's origin and direction in columns 0-5 and
    its t_max in column 6; the kernel writes t (left at t_max on a miss) and the weights w1, w2 into
    columns 6-8 and the triangle (MISS on a miss) into ``hit``. Returns (nodes, tests) summed
    over the rays: a node counts once for each ray that enters it. The walk visits a node when
    any ray enters it before its nearest hit so far, testing both children's boxes for all
    four rays with the same arithmetic side by side (compiled to vector instructions); rays
    whose directions differ in sign on an axis enter boxes through different planes and are
    traced one by one instead. ``stack_t`` is :func:`closest_triangle`'s, ``lane_t``
    (depth + 1, LANES) float64.
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


@njit(inline="always")
def _lanes_in(entry):
    """Return the bit mask of the lanes whose entry is finite (bit r for lane r)."""
    return (
        (1 if entry[0] < math.inf else 0) | (2 if entry[1] < math.inf else 0)
        | (4 if entry[2] < math.inf else 0) | (8 if entry[3] < math.inf else 0)
    )


@njit(inline="always")
def _lane_count(mask):
    return (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + ((mask >> 3) & 1)


@njit(simd=True, refcount=False)
def any_triangles4(bounds, links, tris, pass_through, rays, lanes, t_min, hit, stack):
    """Run :func:`any_triangle` for each of ``LANES`` segments, in one walk of the tree.

    The first ``lanes`` rows of ``rays`` (LANES, 8) are traced (fewer than ``LANES``: one by
    one); each holds a segment's origin and direction in columns 0-5 and its t_max in
    column 6; the kernel writes the light let through into column 7 and the blocker
    (MISS when none) into ``hit``. Returns (nodes, tests) summed over the rays. The walk takes
    the children in any_triangle's fixed order, each ray only into the boxes it enters and
    only until it is blocked, so each ray visits the nodes, tests the triangles and multiplies
    the fractions let through that it would alone, in the same order: the same blocker and
    bit for bit the same light. The stack holds a node and the mask of the rays entering it
    (``node << LANES | mask``); rays whose directions differ in sign on an axis go one by one.
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


@njit
def intersect_many(bounds, links, tris, source, skip, cull, origins, directions, depth, start,
                   stop, t_out, index_out):
    """Write the nearest hit of rays start..stop-1 of (N, 3): t (inf on a miss), leaf index.

    Serial: the caller runs disjoint ranges of rays from several threads.
    """
    stack = np.empty(depth + 1, dtype=np.intp)
    stack_t = np.empty(depth + 1)
    for r in range(start, stop):
        t, i, _, _, _, _ = closest_triangle(
            bounds, links, tris, source, skip, cull, origins[r, 0], origins[r, 1],
            origins[r, 2], directions[r, 0], directions[r, 1], directions[r, 2], 0.0,
            math.inf, stack, stack_t,
        )
        t_out[r] = t
        index_out[r] = i


@njit
def ray_sphere_many(origins, directions, centers, radii, out):
    """Write t of each ray's nearest hit with t > 0 on its sphere into out (inf on a miss)."""
    for r in range(origins.shape[0]):
        t0, t1 = sphere_roots(
            origins[r, 0], origins[r, 1], origins[r, 2], directions[r, 0], directions[r, 1],
            directions[r, 2], centers[r, 0], centers[r, 1], centers[r, 2], radii[r],
        )
        out[r] = sphere_t(t0, t1, 0.0, math.inf, False)


@njit
def ray_plane_many(origins, directions, points, normals, out):
    """Write t of each ray's hit with t > 0 on its plane into out (inf if parallel or behind)."""
    for r in range(origins.shape[0]):
        t = plane_t(
            origins[r, 0], origins[r, 1], origins[r, 2], directions[r, 0], directions[r, 1],
            directions[r, 2], points[r, 0], points[r, 1], points[r, 2], normals[r, 0],
            normals[r, 1], normals[r, 2],
        )
        out[r] = t if 0.0 < t < math.inf else math.inf


@njit(inline="always")
def reflect_direction(dx, dy, dz, nx, ny, nz):
    """Return R = d − 2(d·N)N, the mirror image of direction d about the unit normal N."""
    dot = dx * nx + dy * ny + dz * nz
    return dx - 2.0 * dot * nx, dy - 2.0 * dot * ny, dz - 2.0 * dot * nz


@njit
def reflect_many(directions, normals, out):
    """Write the reflection of each direction (N, 3) about its unit normal into out (N, 3)."""
    for r in range(directions.shape[0]):
        out[r, 0], out[r, 1], out[r, 2] = reflect_direction(
            directions[r, 0], directions[r, 1], directions[r, 2], normals[r, 0], normals[r, 1],
            normals[r, 2],
        )


@njit(inline="always")
def refract_direction(dx, dy, dz, nx, ny, nz, eta):
    """Return the notes' T = ηd + (η cos θi − cos θt) N and whether it exists (False on TIR).

    d is the unit incident direction, N the unit normal on the incident side (d·N < 0) and
    η = n1/n2; cos θi = −d·N and cos θt = √(1 − η²(1 − cos² θi)) by Snell's law.
    """
    cos_i = -(dx * nx + dy * ny + dz * nz)
    sin2_t = eta * eta * (1.0 - cos_i * cos_i)
    if sin2_t > 1.0:
        return 0.0, 0.0, 0.0, False
    cos_t = math.sqrt(1.0 - sin2_t)
    k = eta * cos_i - cos_t
    return eta * dx + k * nx, eta * dy + k * ny, eta * dz + k * nz, True


@njit
def refract_many(directions, normals, eta, out):
    """Write the transmitted unit directions (N, 3) into out; NaN rows on total reflection."""
    for r in range(directions.shape[0]):
        tx, ty, tz, ok = refract_direction(
            directions[r, 0], directions[r, 1], directions[r, 2], normals[r, 0], normals[r, 1],
            normals[r, 2], eta[r],
        )
        out[r, 0] = tx if ok else math.nan
        out[r, 1] = ty if ok else math.nan
        out[r, 2] = tz if ok else math.nan


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
    t = np.empty(1)
    index = np.empty(1, dtype=np.intp)
    no_skip = np.zeros(0, dtype=np.bool_)
    intersect_many(bounds, links, tris, source, no_skip, False, rays, down, depth, np.intp(0),
                   np.intp(1), t, index)
    stack = np.empty(depth + 1, dtype=np.intp)
    any_triangle(bounds, links, tris, np.zeros(1), 0.2, 0.2, 1.0, 0.0, 0.0, -1.0, 0.0, 2.0, stack)
    ray_sphere_many(rays, down, np.zeros((1, 3)), np.ones(1), t)
    ray_plane_many(rays, down, np.zeros((1, 3)), -down, t)
    refract_many(down, -down, np.ones(1), np.empty((1, 3)))
    reflect_many(down, -down, np.empty((1, 3)))
