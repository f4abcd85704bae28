"""Compiled ray tests (a ray against a sphere, a plane, a triangle, a box), reflection, refraction.

Rays are ``R(t) = o + t d`` with t in units of ``|d|``; a hit counts when ``t_min < t < t_max``.

The tests are inlined into the kernels that search a scene
(:mod:`pixelpath.raytrace._traversal_kernels`, :mod:`pixelpath.raytrace._whitted_kernels`);
the ``*_many`` kernels run them over arrays of rays for :mod:`pixelpath.raytrace.geometry`.

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
* ``box_entry``: the slab test of a ray against an axis-aligned box, its far distance grown by
  Ize's bound (2γ₃, "Robust BVH ray traversal", JCGT 2013) so that rounding never prunes a
  box whose triangle :func:`triangle_t` would hit.
* ``reflect_direction`` and ``refract_direction``: the notes' mirror and Snell directions.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import inlined, njit

EPS = float(np.finfo(np.float64).eps)
# An origin whose |o − C|² − r² is within this fraction of |o − C|² + r² lies on the sphere.
SURFACE_TOLERANCE = 4.0 * EPS
# Slab distances are off by at most γ₃ = 3ε/(1 − 3ε) relatively (Ize 2013); 2γ₃ covers both ends.
BOX_SLACK = 2.0 * (3.0 * EPS / (1.0 - 3.0 * EPS))


# Inlined by LLVM into its three callers (see pixelpath._jit), which left it a call otherwise.
@inlined
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


@njit(refcount=False, from_python=False)
def sphere_t(t0, t1, t_min, t_max, cull):
    """Return the nearest root in (t_min, t_max), inf if none; with cull, the entering root only.

    t0 is where the line enters the sphere, t1 where it leaves: culling back faces keeps t0.
    """
    if t_min < t0 < t_max:
        return t0
    if not cull and t_min < t1 < t_max:
        return t1
    return math.inf


@njit(refcount=False, from_python=False)
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


@njit(refcount=False, from_python=False)
def reciprocal(value):
    """Return 1/value, ±inf for ±0 (the sign of zero kept), with no division by zero."""
    return 1.0 / value if value != 0.0 else math.copysign(math.inf, value)


@njit(refcount=False, from_python=False)
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


# Inlined by LLVM into its six callers (see pixelpath._jit): left a call, the traversal loops
# took 10-14 % longer to cast the same rays.
@inlined
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


@njit(refcount=False, from_python=False)
def slab_columns(ix, iy, iz):
    """Return the columns of a box row holding each axis's near and far plane for this ray.

    A box row is (min x, min y, min z, max x, max y, max z): a ray going towards -x enters
    through max x. Choosing the columns once per ray keeps the box test free of branches.
    """
    nx = 0 if ix >= 0.0 else 3
    ny = 1 if iy >= 0.0 else 4
    nz = 2 if iz >= 0.0 else 5
    return nx, ny, nz, 3 - nx, 5 - ny, 7 - nz


@njit(refcount=False, from_python=False)
def box_limit(t):
    """Return t grown by the box test's rounding bound: the farthest box entry worth visiting.

    A box entered up to here may still hold a hit at t (or end the segment there); the same
    growth widens the exit distance inside :func:`box_entry`.
    """
    return t + abs(t) * BOX_SLACK


@njit(refcount=False, from_python=False)
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


@njit(refcount=False, from_python=False)
def enters_box(bounds, k, ox, oy, oz, dx, dy, dz, t_min, t_max):
    """Return whether the ray enters box k within [t_min, t_max]: the traversals' own test.

    A ray that misses the root box (k = 0) finds nothing in the tree, so callers with many
    such rays test it first and spare the traversal's set-up.
    """
    ix, iy, iz = reciprocal(dx), reciprocal(dy), reciprocal(dz)
    columns = slab_columns(ix, iy, iz)
    return box_entry(bounds, k, ox, oy, oz, ix, iy, iz, columns, t_min, t_max) < math.inf


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


@njit(refcount=False, from_python=False)
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


@njit(refcount=False, from_python=False)
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
