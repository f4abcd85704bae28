"""Compiled kernels of the illumination model (see :mod:`pixelpath.lighting.phong`).

``shade_point`` is the scalar kernel that renderers call once per shaded sample; it allocates
nothing and writes its answer into ``out``, so it can sit inside another kernel's per-pixel
loop. ``shade_planar`` computes the same over a batch of points held planar (x, y, z in rows),
light by light in loops that LLVM vectorizes; the rasterizer's per-pixel Phong shading uses it.
Both are built from the same pieces (``unit_to_eye``, ``light_direction``, ``light_cosines``,
``power``/``power_planar``), each compiled once and inlined into its callers by LLVM, so the
formula is written once and the two agree bit for bit. Packed layouts (built by
:mod:`pixelpath.lighting.packing`):

* ``material`` (8,) float64: ``[r, g, b, ka, kd, ks, shininess, 0]`` (``Material.packed()``);
* ``lights`` (L, 7) float64: ``[kind, x, y, z, r*I, g*I, b*I]`` with kind 0 = point light at
  (x, y, z), kind 1 = directional light travelling along the unit vector (x, y, z);
* ``ambient`` (3,) float64: the ambient intensity Ia per channel.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import inlined, njit

POINT_LIGHT = 0.0
DIRECTIONAL_LIGHT = 1.0


@inlined
def unit_to_eye(px, py, pz, ex, ey, ez, ew):
    """Return V, the unit vector from point p to the eye (zero when the eye is on p).

    The eye is homogeneous, (ex, ey, ez, ew): a point when ew = 1 (a perspective camera, or a
    ray's origin), the direction towards a viewer at infinity when ew = 0 (an orthographic
    camera, whose V is the same everywhere). ``ew · p`` with ew = 1 is exact, so a point eye
    gives the bits of ``e − p``.
    """
    vx = ex - ew * px
    vy = ey - ew * py
    vz = ez - ew * pz
    v_len = math.sqrt(vx * vx + vy * vy + vz * vz)
    # Conditional expressions on cheap values, not branches: the planar loops stay vectorizable.
    inv = 1.0 / v_len if v_len > 0.0 else 1.0
    return vx * inv, vy * inv, vz * inv


@inlined
def light_direction(lights, k, px, py, pz):
    """Return L, the unit vector from point p towards light k (zero for a point light on p)."""
    if lights[k, 0] == POINT_LIGHT:
        lx = lights[k, 1] - px
        ly = lights[k, 2] - py
        lz = lights[k, 3] - pz
        l_len = math.sqrt(lx * lx + ly * ly + lz * lz)
        inv = 1.0 / l_len if l_len > 0.0 else 0.0
        return lx * inv, ly * inv, lz * inv
    return -lights[k, 1], -lights[k, 2], -lights[k, 3]


@inlined
def light_cosines(nx, ny, nz, lx, ly, lz, vx, vy, vz, blinn):
    """Return (max(0, N.L), the model's cosine R.V or N.H), the cosine 0 where N.L <= 0.

    A zero L (a point light on the point) gives N.L = 0: no diffuse term and no highlight.
    """
    n_dot_l = nx * lx + ny * ly + nz * lz
    if blinn:
        hx = lx + vx
        hy = ly + vy
        hz = lz + vz
        h_len = math.sqrt(hx * hx + hy * hy + hz * hz)
        n_dot_h = nx * hx + ny * hy + nz * hz
        cosine = n_dot_h / h_len if h_len > 0.0 else 0.0
    else:
        # R = 2(N.L)N - L, the mirror direction of the light about the normal.
        rx = 2.0 * n_dot_l * nx - lx
        ry = 2.0 * n_dot_l * ny - ly
        rz = 2.0 * n_dot_l * nz - lz
        cosine = rx * vx + ry * vy + rz * vz
    lit = n_dot_l > 0.0  # light behind the surface: no diffuse, no highlight
    return (n_dot_l if lit else 0.0), (cosine if lit else 0.0)


@njit
def shade_point(px, py, pz, nx, ny, nz, ex, ey, ez, ew, material, lights, ambient, blinn, out):
    """Write the unclamped intensity (r, g, b) at surface point p with unit normal n into out.

    (ex, ey, ez, ew) is the eye, homogeneous (see :func:`unit_to_eye`).

    I_c = ka Ia_c C_c + sum over lights of [kd IL_c C_c max(0, N.L) + ks IL_c spec], where C is
    the object colour and spec = (R.V)^n (Phong) or (N.H)^n (Blinn-Phong). spec is 0 whenever
    N.L <= 0 or the model's cosine (R.V, or N.H) is <= 0, so 0^0 never arises. A point light
    sitting exactly on p has no direction and contributes nothing. :func:`shade_planar` is the
    same computation over many points at once.
    """
    kd = material[4]
    ks = material[5]
    for c in range(3):
        out[c] = material[3] * ambient[c] * material[c]
    vx, vy, vz = unit_to_eye(px, py, pz, ex, ey, ez, ew)
    for k in range(lights.shape[0]):
        lx, ly, lz = light_direction(lights, k, px, py, pz)
        diffuse, cosine = light_cosines(nx, ny, nz, lx, ly, lz, vx, vy, vz, blinn)
        for c in range(3):
            out[c] += kd * lights[k, 4 + c] * material[c] * diffuse
        if cosine > 0.0:
            spec = power(cosine, material[6])
            for c in range(3):
                out[c] += ks * lights[k, 4 + c] * spec


@njit(error_model="numpy")
def shade_planar(count, points, normals, albedo, eye, material, lights, ambient, blinn, out,
                 scratch):
    """Shade the first ``count`` points like :func:`shade_point`, in planar layout.

    ``eye`` (4,) is homogeneous (see :func:`unit_to_eye`). ``points`` and ``normals`` (3, N)
    hold x, y and z in rows, ``albedo`` (3, N) the object
    colour C of each point (the material's colour, or a textured surface's colour there; it
    takes the place of the material's r, g, b), ``out`` (3, N) receives r, g and b,
    ``scratch`` (5, N) is work space. With C equal to the material's colour the results are
    bit for bit those of :func:`shade_point`: the products are formed in the same order.
    Every loop runs over unit-stride rows from index 0 without calls or branches that depend
    on the point, so LLVM vectorizes it (several points per instruction); the divisions are
    guarded, so ``error_model="numpy"`` (no zero-division check, which would block
    vectorizing) changes no result.
    """
    x, y, z = points[0], points[1], points[2]
    nx, ny, nz = normals[0], normals[1], normals[2]
    vx, vy, vz = scratch[0], scratch[1], scratch[2]
    cosine, spec = scratch[3], scratch[4]
    red, green, blue = out[0], out[1], out[2]
    cr, cg, cb = albedo[0], albedo[1], albedo[2]
    kd = material[4]
    ks = material[5]
    ambient_r = material[3] * ambient[0]
    ambient_g = material[3] * ambient[1]
    ambient_b = material[3] * ambient[2]
    ex, ey, ez, ew = eye[0], eye[1], eye[2], eye[3]
    for i in range(count):
        red[i] = ambient_r * cr[i]
        green[i] = ambient_g * cg[i]
        blue[i] = ambient_b * cb[i]
        vx[i], vy[i], vz[i] = unit_to_eye(x[i], y[i], z[i], ex, ey, ez, ew)
    for k in range(lights.shape[0]):
        diffuse_r = kd * lights[k, 4]
        diffuse_g = kd * lights[k, 5]
        diffuse_b = kd * lights[k, 6]
        for i in range(count):
            lx, ly, lz = light_direction(lights, k, x[i], y[i], z[i])
            diffuse, cosine_i = light_cosines(
                nx[i], ny[i], nz[i], lx, ly, lz, vx[i], vy[i], vz[i], blinn
            )
            cosine[i] = cosine_i
            red[i] += diffuse_r * cr[i] * diffuse
            green[i] += diffuse_g * cg[i] * diffuse
            blue[i] += diffuse_b * cb[i] * diffuse
        power_planar(cosine, count, material[6], spec)
        specular_r = ks * lights[k, 4]
        specular_g = ks * lights[k, 5]
        specular_b = ks * lights[k, 6]
        for i in range(count):
            red[i] += specular_r * spec[i]
            green[i] += specular_g * spec[i]
            blue[i] += specular_b * spec[i]


@inlined
def power_planar(base, count, exponent, out):
    """Write :func:`power` of the first ``count`` bases into out, 0 where a base is <= 0.

    The squarings run in the same order as in :func:`power` (bit-identical results), one pass
    over the points per bit of the exponent. ``base`` is overwritten.
    """
    whole = int(exponent)
    if whole != exponent or whole > 4096:
        for i in range(count):
            positive = base[i] if base[i] > 0.0 else 1.0
            out[i] = positive**exponent if base[i] > 0.0 else 0.0
        return
    for i in range(count):
        out[i] = 1.0 if base[i] > 0.0 else 0.0
    while whole > 0:
        if whole & 1:
            for i in range(count):
                out[i] *= base[i]
        whole >>= 1
        if whole > 0:
            for i in range(count):
                base[i] *= base[i]


@inlined(from_python=True)
def power(base, exponent):
    """Return ``base ** exponent``, by repeated squaring when the exponent is a whole number.

    Shininess is almost always a whole number (the notes use 1 to 100s); squaring takes a few
    multiplications where ``pow`` takes a logarithm and an exponential, a large share of the
    per-pixel cost of Phong shading.
    """
    whole = int(exponent)
    if whole != exponent or whole > 4096:
        return base**exponent
    result = 1.0
    while whole > 0:
        if whole & 1:
            result *= base
        base *= base
        whole >>= 1
    return result


@njit
def shade_many(points, normals, eye, material, lights, ambient, blinn, start, stop, out):
    """Shade points start..stop-1 of (N, 3), unit normals (N, 3), seen from eye (3,) into out.

    Serial: :func:`pixelpath.lighting.shade` runs disjoint ranges from several threads (a
    ``parallel=True`` loop took twice as long to compile).
    """
    for i in range(start, stop):
        shade_point(
            points[i, 0],
            points[i, 1],
            points[i, 2],
            normals[i, 0],
            normals[i, 1],
            normals[i, 2],
            eye[0],
            eye[1],
            eye[2],
            1.0,
            material,
            lights,
            ambient,
            blinn,
            out[i],
        )


def warmup() -> None:
    """Compile ``shade_many`` (and with it ``shade_point``) for both models."""
    points = np.zeros((1, 3))
    normals = np.array([[0.0, 0.0, 1.0]])
    eye = np.array([0.0, 0.0, 1.0])
    material = np.array([1.0, 1.0, 1.0, 0.1, 0.7, 0.3, 32.0, 0.0])
    lights = np.array([[POINT_LIGHT, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]])
    ambient = np.full(3, 0.1)
    out = np.empty((1, 3))
    for blinn in (False, True):
        shade_many(points, normals, eye, material, lights, ambient, blinn, 0, 1, out)
