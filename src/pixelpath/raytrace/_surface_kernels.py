"""Compiled Whitted tracing at a hit: what was hit, its normals, its shadow rays, what goes on.

``hit_geometry`` turns a ray's nearest hit into its object, point and normals
(``sphere_normal``, ``triangle_normals``); ``nearest_analytic`` finds the nearest sphere or
plane; ``shadow_start`` traces a shadow ray through the spheres and planes
(``analytic_let_through``; the triangles are the caller's to search); ``transmission`` shares
what goes on between the reflected and the refracted ray (Snell's law, total internal
reflection, Schlick's Fresnel term); ``_coloured_material`` gives a hit's material its surface
colour there, and ``textured_emission`` the light its emission texture gives off. Their callers
are the eye rays' kernels (:mod:`pixelpath.raytrace._primary_kernels`) and the row loop
(:mod:`pixelpath.raytrace._whitted_kernels`).
"""

from __future__ import annotations

import math

from pixelpath._jit import inlined, njit
from pixelpath.raytrace._hit_kernels import plane_t, refract_direction, sphere_roots, sphere_t
from pixelpath.raytrace._records import PLANE, SPHERE, TRANSPARENCY
from pixelpath.raytrace._traversal_kernels import MISS
from pixelpath.scene._texture_kernels import GLOW, sample_at, surface_color

# These helpers are inlined into their callers (see pixelpath._jit): by LLVM (forceinline) the
# larger ones called from several places, by Numba the others, whose conversion saved no
# compile time. As functions of their own that LLVM was free to leave calls, the showcase's
# ray-traced frame took 7-14 % longer.


@inlined
def hit_geometry(spheres, sphere_object, planes, plane_object, tris, tri_normals, tri_flat,
                 tri_object, flat, ox, oy, oz, dx, dy, dz, t, kind, index, w1, w2):
    """Return what a ray's hit is: (object, point, geometric normal, shading normal, entering).

    Both normals are turned towards the ray when it meets the surface from behind (or from
    inside); ``entering`` tells which.
    """
    px, py, pz = ox + t * dx, oy + t * dy, oz + t * dz
    if kind == SPHERE:
        obj = sphere_object[index]
        gx, gy, gz = sphere_normal(spheres[index, 0], spheres[index, 1], spheres[index, 2],
                                   spheres[index, 3], px, py, pz)
        nx, ny, nz = gx, gy, gz
    elif kind == PLANE:
        obj = plane_object[index]
        gx, gy, gz = planes[index, 3], planes[index, 4], planes[index, 5]
        nx, ny, nz = gx, gy, gz
    else:
        obj = tri_object[index]
        gx, gy, gz, nx, ny, nz = triangle_normals(tris, tri_normals, tri_flat, flat, index, w1, w2)
    entering = gx * dx + gy * dy + gz * dz < 0.0
    if not entering:
        gx, gy, gz, nx, ny, nz = -gx, -gy, -gz, -nx, -ny, -nz
    return obj, px, py, pz, gx, gy, gz, nx, ny, nz, entering


@inlined
def shadow_start(spheres, sphere_object, planes, plane_object, materials, lights, light, px, py,
                 pz, gx, gy, gz, lx, ly, lz, epsilon, has_analytic):
    """Return the shadow ray of a hit towards a light, with what the spheres and planes do to it.

    (light let through by them, their blocker or MISS, origin, direction, t_max); the
    triangles are the caller's business.
    """
    sx, sy, sz, lx, ly, lz, t_light = shadow_ray(
        lights, light, px, py, pz, gx, gy, gz, lx, ly, lz, epsilon
    )
    through, blocker = 1.0, MISS
    if has_analytic:
        through, blocker = analytic_let_through(
            spheres, sphere_object, planes, plane_object, materials, sx, sy, sz, lx, ly, lz,
            t_light,
        )
    return through, blocker, sx, sy, sz, lx, ly, lz, t_light


@njit(inline="always")
def nearest_analytic(spheres, planes, plane_back, ox, oy, oz, dx, dy, dz, t_min, t_max, cull):
    """Return (t, kind, index) of the nearest sphere or plane hit; (t_max, SPHERE, MISS) if none."""
    t, kind, index = t_max, SPHERE, MISS
    if spheres.shape[0] > 0:  # no call (and no passing of arrays) for what the scene lacks
        t, index = nearest_sphere(spheres, ox, oy, oz, dx, dy, dz, t_min, t, cull)
    if planes.shape[0] > 0:
        t_plane, plane = nearest_plane(planes, plane_back, ox, oy, oz, dx, dy, dz, t_min, t, cull)
        if plane != MISS:
            t, kind, index = t_plane, PLANE, plane
    return t, kind, index


@njit(refcount=False, from_python=False)
def nearest_sphere(spheres, ox, oy, oz, dx, dy, dz, t_min, t_max, cull):
    """Return (t, index) of the nearest sphere hit in (t_min, t_max); (t_max, MISS) if none.

    With ``cull``, a sphere is hit only where the ray enters it.
    """
    best_t = t_max
    index = MISS
    for s in range(spheres.shape[0]):
        t0, t1 = sphere_roots(
            ox, oy, oz, dx, dy, dz, spheres[s, 0], spheres[s, 1], spheres[s, 2], spheres[s, 3]
        )
        t = sphere_t(t0, t1, t_min, best_t, cull)
        if t < best_t:
            best_t, index = t, s
    return best_t, index


@njit(refcount=False, from_python=False)
def nearest_plane(planes, plane_back, ox, oy, oz, dx, dy, dz, t_min, t_max, cull):
    """Return (t, index) of the nearest plane hit in (t_min, t_max); (t_max, MISS) if none.

    With ``cull``, planes with ``plane_back`` set are ignored.
    """
    best_t = t_max
    index = MISS
    for p in range(planes.shape[0]):
        if cull and plane_back[p]:
            continue
        t = plane_t(
            ox, oy, oz, dx, dy, dz, planes[p, 0], planes[p, 1], planes[p, 2], planes[p, 3],
            planes[p, 4], planes[p, 5],
        )
        if t_min < t < best_t:
            best_t, index = t, p
    return best_t, index


@njit(inline="always")
def _unit(x, y, z):
    length = math.sqrt(x * x + y * y + z * z)
    inv = 1.0 / length if length > 0.0 else 0.0
    return x * inv, y * inv, z * inv


@inlined
def sphere_normal(cx, cy, cz, radius, px, py, pz):
    """Return the outward unit normal at point p of the sphere (centre c, radius)."""
    return _unit((px - cx) / radius, (py - cy) / radius, (pz - cz) / radius)


@njit(refcount=False, from_python=False)
def triangle_normals(tris, tri_normals, tri_flat, flat, index, w1, w2):
    """Return (geometric normal, shading normal) of triangle ``index`` at barycentric (w1, w2).

    The shading normal interpolates the vertex normals (the polygon's normal with ``flat``);
    it falls back to the geometric normal where the interpolated one vanishes.
    """
    t = tris
    e1x, e1y, e1z = t[index, 3] - t[index, 0], t[index, 4] - t[index, 1], t[index, 5] - t[index, 2]
    e2x, e2y, e2z = t[index, 6] - t[index, 0], t[index, 7] - t[index, 1], t[index, 8] - t[index, 2]
    gx, gy, gz = _unit(e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x)
    if flat:
        sx, sy, sz = tri_flat[index, 0], tri_flat[index, 1], tri_flat[index, 2]
    else:
        w0 = 1.0 - w1 - w2
        n = tri_normals
        sx, sy, sz = _unit(
            w0 * n[index, 0] + w1 * n[index, 3] + w2 * n[index, 6],
            w0 * n[index, 1] + w1 * n[index, 4] + w2 * n[index, 7],
            w0 * n[index, 2] + w1 * n[index, 5] + w2 * n[index, 8],
        )
    if sx == 0.0 and sy == 0.0 and sz == 0.0:
        sx, sy, sz = gx, gy, gz
    return gx, gy, gz, sx, sy, sz


@njit(inline="always")
def _offset(px, py, pz, gx, gy, gz, dx, dy, dz, epsilon):
    """Return p moved epsilon along the geometric normal g, to the side direction d leaves to."""
    side = epsilon if gx * dx + gy * dy + gz * dz >= 0.0 else -epsilon
    return px + side * gx, py + side * gy, pz + side * gz


@njit(refcount=False, from_python=False)
def analytic_let_through(spheres, sphere_object, planes, plane_object, materials, ox, oy, oz,
                         dx, dy, dz, t_max):
    """Return (light let through, blocking object or MISS) by the spheres and planes.

    Each surface the shadow ray crosses in (0, t_max) lets its object's transparency through;
    an opaque one blocks the light (the search ends there).
    """
    through = 1.0
    for s in range(spheres.shape[0]):
        t0, t1 = sphere_roots(
            ox, oy, oz, dx, dy, dz, spheres[s, 0], spheres[s, 1], spheres[s, 2], spheres[s, 3],
        )
        obj = sphere_object[s]
        for t in (t0, t1):
            if 0.0 < t < t_max:
                through *= materials[obj, TRANSPARENCY]
                if through == 0.0:
                    return 0.0, obj
    for p in range(planes.shape[0]):
        t = plane_t(
            ox, oy, oz, dx, dy, dz, planes[p, 0], planes[p, 1], planes[p, 2], planes[p, 3],
            planes[p, 4], planes[p, 5],
        )
        if 0.0 < t < t_max:
            obj = plane_object[p]
            through *= materials[obj, TRANSPARENCY]
            if through == 0.0:
                return 0.0, obj
    return through, MISS


@njit(inline="always")
def shadow_ray(lights, k, px, py, pz, gx, gy, gz, lx, ly, lz, epsilon):
    """Return (origin, direction, t_max) of the shadow ray from p towards light k.

    (g: geometric normal on the side the light is, l: unit direction to the light.) It
    starts ``epsilon`` off the surface; for a point light it is the segment up to the light,
    t in (0, 1), for a directional light the whole half-line.
    """
    sx, sy, sz = _offset(px, py, pz, gx, gy, gz, lx, ly, lz, epsilon)
    if lights[k, 0] == 0.0:
        return sx, sy, sz, lights[k, 1] - sx, lights[k, 2] - sy, lights[k, 3] - sz, 1.0
    return sx, sy, sz, lx, ly, lz, math.inf


@njit(inline="always")
def _schlick(cos_i, cos_t, eta, ior):
    """Return Schlick's reflectance for the interface, using the cosine on the thinner side."""
    r0 = (1.0 - ior) / (1.0 + ior)
    r0 *= r0
    cosine = cos_t if eta > 1.0 else cos_i
    m = 1.0 - cosine
    return r0 + (1.0 - r0) * m * m * m * m * m


@njit(inline="always")
def _coloured_material(scene, out, obj, index, w1, w2, px, py, pz, nx, ny, nz, dx, dy, dz):
    """Write object ``obj``'s material with the surface colour at the hit into ``out``.

    The hit is at barycentric (w1, w2) of triangle ``index``; the texture is filtered for
    the pixel's footprint there (:func:`_hit_span`).
    """
    for field in range(out.shape[0]):
        out[field] = scene.materials[obj, field]
    span = _hit_span(scene, index, px, py, pz, nx, ny, nz, dx, dy, dz)
    first = 3 * index  # the triangle's corners' rows of tri_uv and tri_colors
    r, g, b, _ = surface_color(
        scene.tables, scene.materials, obj, scene.tri_uv, scene.tri_colors, first, first + 1,
        first + 2, 1.0 - w1 - w2, w1, w2, span, 0.0, 0.0, span,
    )
    out[0], out[1], out[2] = r, g, b
    return out


@njit(inline="always")
def textured_emission(scene, emission, obj, index, w1, w2, px, py, pz, nx, ny, nz, dx, dy,
                      dz):
    """Light object ``obj`` gives off at the hit: ``emission`` (r, g, b) × its emission texture.

    The texture is read at the hit's texture coordinates, filtered for the pixel's footprint
    there (:func:`_hit_span`), as the surface colour's is.
    """
    span = _hit_span(scene, index, px, py, pz, nx, ny, nz, dx, dy, dz)
    first = 3 * index  # the triangle's corners' rows of tri_uv
    r, g, b, _ = sample_at(scene.tables, scene.tables.objects[obj, GLOW], scene.tri_uv, first,
                           first + 1, first + 2, 1.0 - w1 - w2, w1, w2, span, 0.0, 0.0, span)
    return emission[0] * r, emission[1] * g, emission[2] * b


@njit(inline="always")
def _hit_span(scene, index, px, py, pz, nx, ny, nz, dx, dy, dz):
    """How far the texture coordinates move across the pixel at a hit on triangle ``index``.

    The cone's width at the hit's distance from the eye, stretched by 1 / cos of the angle
    between ray and normal, in uv units through the triangle's texel scale.
    """
    eye = scene.camera
    distance = math.sqrt((px - eye[0]) ** 2 + (py - eye[1]) ** 2 + (pz - eye[2]) ** 2)
    width = scene.pixel_cone[0] + scene.pixel_cone[1] * distance
    length = math.sqrt(dx * dx + dy * dy + dz * dz)
    cosine = abs(nx * dx + ny * dy + nz * dz) / length if length > 0.0 else 1.0
    return scene.tri_texel_scale[index] * width / max(cosine, 1e-3)


@njit(inline="always")
def _push(rays, top, ox, oy, oz, dx, dy, dz, weight, depth, kind, parent):
    rays[top, 0], rays[top, 1], rays[top, 2] = ox, oy, oz
    rays[top, 3], rays[top, 4], rays[top, 5] = dx, dy, dz
    rays[top, 6], rays[top, 7], rays[top, 8], rays[top, 9] = weight, depth, kind, parent
    return top + 1


@njit(inline="always")
def transmission(ux, uy, uz, nx, ny, nz, entering, kr, kt, ior, bounce, fresnel):
    """Return (kr, kt, total reflection, Fresnel term, eta, refracted direction) at a hit.

    u is the unit ray direction, n the shading normal on its side; ``bounce`` says whether
    secondary rays are traced at all. Total internal reflection hands the transmitted share to
    the reflection; with ``fresnel``, Schlick's term moves part of it there.
    """
    total = False
    term = 0.0
    eta = 1.0
    tx = ty = tz = 0.0
    if bounce and kt > 0.0:
        eta = 1.0 / ior if entering else ior
        tx, ty, tz, exists = refract_direction(ux, uy, uz, nx, ny, nz, eta)
        if not exists:
            total = True
            kr, kt = kr + kt, 0.0
        elif fresnel:
            cos_i = -(ux * nx + uy * ny + uz * nz)
            cos_t = -(tx * nx + ty * ny + tz * nz)
            term = _schlick(cos_i, cos_t, eta, ior)
            kr, kt = kr + kt * term, kt * (1.0 - term)
    return kr, kt, total, term, eta, tx, ty, tz
