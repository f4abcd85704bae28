"""Compiled kernels of the illumination model (see :mod:`pixelpath.lighting.phong`).

``shade_point`` is the scalar kernel that every renderer calls once per shaded sample; it
allocates nothing and writes its answer into ``out``, so it can sit inside another kernel's
per-pixel loop. Packed layouts (built by :mod:`pixelpath.lighting.packing`):

* ``material`` (8,) float64: ``[r, g, b, ka, kd, ks, shininess, 0]`` (``Material.packed()``);
* ``lights`` (L, 7) float64: ``[kind, x, y, z, r*I, g*I, b*I]`` with kind 0 = point light at
  (x, y, z), kind 1 = directional light travelling along the unit vector (x, y, z);
* ``ambient`` (3,) float64: the ambient intensity Ia per channel.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit, prange, register_warmup

POINT_LIGHT = 0.0
DIRECTIONAL_LIGHT = 1.0


@njit
def shade_point(px, py, pz, nx, ny, nz, ex, ey, ez, material, lights, ambient, blinn, out):
    """Write the unclamped intensity (r, g, b) at surface point p with unit normal n into out.

    I_c = ka Ia_c C_c + sum over lights of [kd IL_c C_c max(0, N.L) + ks IL_c spec], where C is
    the object colour and spec = (R.V)^n (Phong) or (N.H)^n (Blinn-Phong). spec is 0 whenever
    N.L <= 0 or the model's cosine (R.V, or N.H) is <= 0, so 0^0 never arises. A point light
    sitting exactly on p has no direction and contributes nothing.
    """
    ka = material[3]
    kd = material[4]
    ks = material[5]
    shininess = material[6]
    for c in range(3):
        out[c] = ka * ambient[c] * material[c]

    # V: unit vector from the point to the eye (zero when the eye is on the point).
    vx = ex - px
    vy = ey - py
    vz = ez - pz
    v_len = math.sqrt(vx * vx + vy * vy + vz * vz)
    if v_len > 0.0:
        inv = 1.0 / v_len
        vx *= inv
        vy *= inv
        vz *= inv

    for k in range(lights.shape[0]):
        # L: unit vector from the point towards the light.
        if lights[k, 0] == POINT_LIGHT:
            lx = lights[k, 1] - px
            ly = lights[k, 2] - py
            lz = lights[k, 3] - pz
            l_len = math.sqrt(lx * lx + ly * ly + lz * lz)
            if l_len == 0.0:
                continue
            inv = 1.0 / l_len
            lx *= inv
            ly *= inv
            lz *= inv
        else:
            lx = -lights[k, 1]
            ly = -lights[k, 2]
            lz = -lights[k, 3]

        n_dot_l = nx * lx + ny * ly + nz * lz
        if n_dot_l <= 0.0:  # light behind the surface: no diffuse, no highlight
            continue
        for c in range(3):
            out[c] += kd * lights[k, 4 + c] * material[c] * n_dot_l

        spec = _specular(nx, ny, nz, lx, ly, lz, vx, vy, vz, n_dot_l, shininess, blinn)
        if spec > 0.0:
            for c in range(3):
                out[c] += ks * lights[k, 4 + c] * spec


@njit
def _specular(nx, ny, nz, lx, ly, lz, vx, vy, vz, n_dot_l, shininess, blinn):
    """Return (R.V)^n or, for Blinn-Phong, (N.H)^n; 0 when that cosine is not positive."""
    if blinn:
        hx = lx + vx
        hy = ly + vy
        hz = lz + vz
        h_len = math.sqrt(hx * hx + hy * hy + hz * hz)
        if h_len == 0.0:
            return 0.0
        cosine = (nx * hx + ny * hy + nz * hz) / h_len
    else:
        # R = 2(N.L)N - L, the mirror direction of the light about the normal.
        rx = 2.0 * n_dot_l * nx - lx
        ry = 2.0 * n_dot_l * ny - ly
        rz = 2.0 * n_dot_l * nz - lz
        cosine = rx * vx + ry * vy + rz * vz
    if cosine <= 0.0:
        return 0.0
    return power(cosine, shininess)


@njit(inline="always")
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


@njit(parallel=True)
def shade_many(points, normals, eye, material, lights, ambient, blinn, out):
    """Shade N points (N, 3) with unit normals (N, 3) seen from eye (3,) into out (N, 3)."""
    for i in prange(points.shape[0]):
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
            material,
            lights,
            ambient,
            blinn,
            out[i],
        )


@register_warmup
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
        shade_many(points, normals, eye, material, lights, ambient, blinn, out)
