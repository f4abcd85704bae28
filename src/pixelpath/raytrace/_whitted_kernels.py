"""Compiled Whitted ray tracing: one pixel's tree of rays, followed with an explicit stack.

The colour a ray brings back is the notes' sum, ``I = I_local + kr I_R + kt I_T``: the local
Phong light where it hits (each light's share scaled by what its shadow ray lets through), plus
the light of the reflected ray weighted by ``reflectivity`` and that of the refracted ray
weighted by ``transparency``. Unrolled, a pixel is a sum over the tree of rays of
``weight × I_local``, where a ray's weight is the product of the coefficients on its way from
the eye. So the tree is walked depth first with a stack of pending rays, each carrying its
weight, and every ray adds its share as it is traced: no recursion, no values passed back up.

* Primary rays start at the eye with a direction whose component along the viewing axis is 1,
  so t is the depth the rasterizer stores; they see what lies between the camera's near and far
  planes and, when back faces are culled, only the faces the rasterizer keeps (a mesh polygon
  or plane facing away from the eye, a sphere's far side).
  Their nearest hits are found for a whole row before it is shaded, the triangles four
  neighbouring rays at a time (``primary_hits``, ``closest_triangles4``).
* Secondary rays (shadow, reflected, refracted) see both sides of everything. They start at the
  hit point moved ``epsilon`` along the geometric normal, to the side they leave towards, so
  they never hit the surface they start on (no shadow acne, no black glass).
* Refraction follows Snell's law with the notes' T = ηd + (η cos θi − cos θt)N; a ray leaving an
  object (its direction along the outward normal) goes from ``ior`` back to 1. When T does not
  exist (total internal reflection) the transmitted share is reflected instead; with Schlick's
  Fresnel term F the transmitted share is split into F reflected and 1 − F transmitted.
* Shadow rays are any-hit queries: an opaque object blocks the light, a transparent one lets
  its ``transparency`` through (no bending of the light: no caustics).
* Alpha-tested materials (``Material.alpha_cutoff``) are holes where their alpha test cuts
  them, for every ray: eye, shadow, reflected and refracted rays go on through to what lies
  behind (``TraceScene.cutouts``). A scene with such triangles has its secondary rays and
  shadow rays searched with the test (one by one: the packet searches make none), and an eye
  ray whose packet found a cut-away hit is traced again alone, with it. Other scenes are
  searched exactly as without alpha tests. Spheres and planes have no texture coordinates:
  their alpha is their material's, and one it cuts away is left out of the scene
  (:mod:`pixelpath.raytrace.tracer`).
* A ray is traced only when its depth is at most ``max_depth`` and its weight at least
  ``MIN_WEIGHT``.

``render_rows`` can record every ray it traces into a log (``ray_tree`` runs it on one pixel
and reads it); the renderer passes an empty log.

This module holds the row loop and the log. The records it works on are
:mod:`pixelpath.raytrace._records`', the eye rays :mod:`pixelpath.raytrace._primary_kernels`'
and what happens at a hit :mod:`pixelpath.raytrace._surface_kernels`'.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import compile_for, inlined, njit
from pixelpath.lighting._kernels import light_direction, shade_point
from pixelpath.raytrace._hit_kernels import enters_box, reflect_direction, slab_nan_allowed
from pixelpath.raytrace._primary_kernels import _stored_geometry, primary_hits, primary_shadows
from pixelpath.raytrace._records import (
    COLOR,
    COUNT_MISSED,
    COUNT_NODES,
    COUNT_PRIMARY,
    COUNT_REFLECTED,
    COUNT_REFRACTED,
    COUNT_SHADOW,
    COUNT_TESTS,
    COUNT_TOTAL_REFLECTION,
    COUNTS,
    DEPTH,
    DIRECTION,
    EMISSION,
    ENTERING,
    ETA,
    FRESNEL,
    GEOMETRIC,
    GEOMETRY_ENTERING,
    GEOMETRY_OBJECT,
    IOR,
    KIND,
    KR,
    KT,
    LOCAL,
    MIN_WEIGHT,
    NORMAL,
    OBJECT,
    ORIGIN,
    PARENT,
    POINT,
    PRIMARY,
    PRIMITIVE,
    PRIMITIVE_INDEX,
    REFLECTED,
    REFLECTIVITY,
    REFRACTED,
    SAMPLE,
    TOTAL_REFLECTION,
    TRANSPARENCY,
    TRIANGLE,
    WEIGHT,
    T,
    new_work,
)
from pixelpath.raytrace._surface_kernels import (
    _coloured_material,
    _offset,
    _push,
    _unit,
    hit_geometry,
    nearest_analytic,
    shadow_start,
    textured_emission,
    transmission,
)
from pixelpath.raytrace._traversal_kernels import MISS, any_triangle, closest_triangle
from pixelpath.scene._texture_kernels import GLOW, colored


@njit(refcount=False, from_python=False)
def _log_ray(log, row, parent, kind, depth, weight, ox, oy, oz, dx, dy, dz, sample):
    log[row, PARENT] = parent
    log[row, KIND] = kind
    log[row, DEPTH] = depth
    log[row, WEIGHT] = weight
    log[row, ORIGIN], log[row, ORIGIN + 1], log[row, ORIGIN + 2] = ox, oy, oz
    log[row, DIRECTION], log[row, DIRECTION + 1], log[row, DIRECTION + 2] = dx, dy, dz
    log[row, SAMPLE] = sample


@njit(refcount=False, from_python=False)
def _log_miss(log, row, background):
    log[row, T] = math.inf
    log[row, OBJECT] = MISS
    log[row, PRIMITIVE] = MISS
    for c in range(3):
        log[row, LOCAL + c] = background[c]


@njit(refcount=False, from_python=False)
def _log_hit(log, row, t, obj, kind, index, source, px, py, pz, nx, ny, nz, gx, gy, gz,
             entering, material, shaded, kr, kt, total, fresnel, eta):
    log[row, T] = t
    log[row, OBJECT] = obj
    log[row, PRIMITIVE] = kind
    log[row, PRIMITIVE_INDEX] = source[index] if kind == TRIANGLE else index
    log[row, POINT], log[row, POINT + 1], log[row, POINT + 2] = px, py, pz
    log[row, NORMAL], log[row, NORMAL + 1], log[row, NORMAL + 2] = nx, ny, nz
    log[row, GEOMETRIC], log[row, GEOMETRIC + 1], log[row, GEOMETRIC + 2] = gx, gy, gz
    log[row, ENTERING] = 1.0 if entering else 0.0
    for c in range(3):
        log[row, LOCAL + c] = shaded[c]
        log[row, COLOR + c] = material[c]
    log[row, KR] = kr
    log[row, KT] = kt
    log[row, TOTAL_REFLECTION] = 1.0 if total else 0.0
    log[row, FRESNEL] = fresnel
    log[row, ETA] = eta


@njit(refcount=False, from_python=False)
def _clamp01(value):
    return min(max(value, 0.0), 1.0)


# Fields of a traced pixel in render_rows' row of pixels (``out``).
RED, GREEN, BLUE, PIXEL_DEPTH, PIXEL_OBJECT, PIXEL_NORMAL = 0, 1, 2, 3, 4, 5
PIXEL_FIELDS = 8


@njit(refcount=False)
def render_rows(rows, scene, settings, work, out, x0, y0, rgb, image_depth, object_id, normal,
                row_counts):
    """Trace the listed rows of the region whose top-left pixel is (x0, y0) of the image.

    Writes rgb (h, w, 3) float32, image_depth (h, w) float32 (inf where nothing was hit),
    object_id (h, w) int32 (-1 there), the unit normal (h, w, 3) float32 seen at the nearest
    hit (0 there) and each row's counters into row_counts (h, COUNTS). ``work`` is the calling
    thread's scratch space (:func:`pixelpath.raytrace._records.new_work`) and ``out`` (w,
    PIXEL_FIELDS) its row of traced pixels, where the last row's values stay in full
    precision. Serial: the caller runs disjoint lists of rows from several threads (the kernel
    releases the GIL), each with its own ``work`` and ``out``.

    A pixel's fields are r, g, b (the mean of the clamped colours of its samples), depth,
    object and normal (from the nearest sample that hit something). Each sample's eye ray and
    its tree are followed with the stack work.rays: a ray adds ``weight × I_local`` as it is
    traced. The eye rays' nearest hits are found first, for the whole row
    (:func:`primary_hits`); pixels outside ``scene.screen_bounds``, whose eye rays can hit
    nothing, take the background without a search.

    The loops over rows, pixels, samples and rays, and the local light of a hit, share this
    one function on purpose: a compiled call passes each array as several machine words, more
    work than a ray that misses needs. So the scene's and the scratch arrays are taken out of
    their tuples once per call; per secondary ray only the nearest-hit searches are called (a
    few arrays each, the triangles' only when the ray enters the root box), per packet of eye
    rays the packet's search, per shadow ray the any-hit search, and per hit the normal and
    Phong kernels. The rows' loop is here too: in a kernel of its own that called this one per
    row, LLVM optimized and generated this one's code a second time (about 3 s of LLVM's
    time in the ray tracer's compile, ``docs/performance.md``). Like the searches, the row
    kernel counts no references (``njit(refcount=False)``): counted, the scene's arrays had
    their counts updated atomically at each of those calls and inlined helpers, per ray, from
    every thread.
    """
    spheres = scene.spheres
    planes = scene.planes
    plane_back = scene.plane_back
    bounds = scene.bounds
    links = scene.links
    tris = scene.tris
    tri_source = scene.tri_source
    tri_back = scene.tri_back
    tri_normals = scene.tri_normals
    tri_flat = scene.tri_flat
    tri_object = scene.tri_object
    sphere_object = scene.sphere_object
    plane_object = scene.plane_object
    materials = scene.materials
    lights = scene.lights
    ambient = scene.ambient
    background = scene.background
    tri_pass = scene.tri_pass
    cutouts = scene.cutouts
    holes = cutouts.masked.shape[0] > 0  # alpha-tested triangles: search with the test
    rays = work.rays
    counts = work.counts
    stack = work.stack
    stack_t = work.stack_t
    shaded = work.shaded
    lit = work.lights
    log_lights = work.log_lights
    logged_rays = work.logged
    log = work.log
    has_triangles = links.shape[0] > 0
    has_analytic = spheres.shape[0] > 0 or planes.shape[0] > 0
    samples = settings.samples
    primary_found = work.primary
    primary_hit = work.primary_hit
    primary_shadow = work.primary_shadow
    primary_geometry = work.primary_geometry
    cull_none = False
    width = rgb.shape[1]
    scale = 1.0 / samples
    # A pixel none of whose eye rays was searched (outside scene.screen_bounds) shows the
    # background: the same sums and scaling as the per-sample loop below makes for rays that
    # miss.
    missed_red = missed_green = missed_blue = 0.0
    for _ in range(samples):
        missed_red += _clamp01(background[0])
        missed_green += _clamp01(background[1])
        missed_blue += _clamp01(background[2])
    missed_red, missed_green, missed_blue = (
        missed_red * scale, missed_green * scale, missed_blue * scale
    )
    for k in range(rows.shape[0]):
        row = rows[k]
        y = y0 + row
        for c in range(COUNTS):
            counts[c] = 0
        first, stop = primary_hits(y, x0, width, scene, settings, work)
        primary_shadows(first, stop, scene, settings, work)
        searched_first, searched_stop = first // samples, -(-stop // samples)  # pixels
        unsearched = (width - (searched_stop - searched_first)) * samples
        counts[COUNT_PRIMARY] += unsearched
        counts[COUNT_MISSED] += unsearched
        for i in range(searched_first):
            _store_pixel(out, i, missed_red, missed_green, missed_blue, math.inf, MISS, 0.0,
                         0.0, 0.0)
        for i in range(searched_stop, width):
            _store_pixel(out, i, missed_red, missed_green, missed_blue, math.inf, MISS, 0.0,
                         0.0, 0.0)
        for i in range(searched_first, searched_stop):
            red = green = blue = 0.0
            nearest = math.inf
            nearest_object = MISS
            nearest_normal = (0.0, 0.0, 0.0)
            for sample in range(samples):
                ray = i * samples + sample  # its eye ray's place in the row's primary pass
                if primary_hit[ray, 1] == MISS and log.shape[0] == 0:
                    # An eye ray that hits nothing brings the background: no tree to follow.
                    counts[COUNT_PRIMARY] += 1
                    counts[COUNT_MISSED] += 1
                    red += _clamp01(background[0])
                    green += _clamp01(background[1])
                    blue += _clamp01(background[2])
                    continue
                top = _push(rays, 0, primary_found[ray, 6], primary_found[ray, 7],
                            primary_found[ray, 8], primary_found[ray, 3],
                            primary_found[ray, 4], primary_found[ray, 5], 1.0, 0.0, float(PRIMARY),
                            -1.0)
                r = g = b = 0.0
                first_t = math.inf
                first_object = MISS
                first_normal = (0.0, 0.0, 0.0)
                while top > 0:
                    top -= 1
                    ox, oy, oz = rays[top, 0], rays[top, 1], rays[top, 2]
                    dx, dy, dz = rays[top, 3], rays[top, 4], rays[top, 5]
                    weight, depth, kind = rays[top, 6], rays[top, 7], rays[top, 8]
                    primary = depth == 0.0
                    if primary:  # found for the whole row beforehand
                        counts[COUNT_PRIMARY] += 1
                        t = primary_found[ray, 0]
                        w1, w2 = primary_found[ray, 1], primary_found[ray, 2]
                        hit_kind, index = primary_hit[ray, 0], primary_hit[ray, 1]
                    else:  # secondary rays see both sides of everything, from their origin on
                        counts[COUNT_REFLECTED if kind == REFLECTED else COUNT_REFRACTED] += 1
                        t, hit_kind, index = nearest_analytic(
                            spheres, planes, plane_back, ox, oy, oz, dx, dy, dz, 0.0, math.inf,
                            cull_none,
                        )
                        w1 = w2 = 0.0
                        if has_triangles and enters_box(bounds, 0, ox, oy, oz, dx, dy, dz, 0.0, t):
                            if holes:
                                t_tri, tri, b1, b2, nodes, tests = closest_triangle(
                                    bounds, links, tris, tri_source, tri_back, cull_none, ox, oy,
                                    oz, dx, dy, dz, 0.0, t, stack, stack_t, cutouts,
                                )
                            else:
                                t_tri, tri, b1, b2, nodes, tests = closest_triangle(
                                    bounds, links, tris, tri_source, tri_back, cull_none, ox, oy,
                                    oz, dx, dy, dz, 0.0, t, stack, stack_t,
                                )
                            counts[COUNT_NODES] += nodes
                            counts[COUNT_TESTS] += tests
                            if tri != MISS:
                                t, hit_kind, index, w1, w2 = t_tri, TRIANGLE, tri, b1, b2
                    logged = logged_rays[0]
                    logged_rays[0] += 1
                    if logged < log.shape[0]:
                        _log_ray(log, logged, rays[top, 9], kind, depth, weight, ox, oy, oz, dx, dy,
                                 dz, sample)
                    if index == MISS:
                        counts[COUNT_MISSED] += 1
                        r += weight * background[0]
                        g += weight * background[1]
                        b += weight * background[2]
                        if logged < log.shape[0]:
                            _log_miss(log, logged, background)
                        continue
                    if primary:
                        px, py, pz, gx, gy, gz, nx, ny, nz = _stored_geometry(primary_geometry, ray)
                        obj = int(primary_geometry[ray, GEOMETRY_OBJECT])
                        entering = primary_geometry[ray, GEOMETRY_ENTERING] != 0.0
                    else:
                        obj, px, py, pz, gx, gy, gz, nx, ny, nz, entering = hit_geometry(
                            spheres, sphere_object, planes, plane_object, tris, tri_normals,
                            tri_flat, tri_object, settings.flat, ox, oy, oz, dx, dy, dz, t,
                            hit_kind, index, w1, w2,
                        )
                    # Local light: a light behind the surface (N·L <= 0) contributes nothing and
                    # needs no shadow ray; each other light enters the model scaled by the light
                    # its shadow ray lets through (work.lights holds them).
                    lit_count = 0
                    for light in range(lights.shape[0]):
                        lx, ly, lz = light_direction(lights, light, px, py, pz)
                        through = -1.0  # not tested
                        blocker = MISS
                        if nx * lx + ny * ly + nz * lz > 0.0:
                            counts[COUNT_SHADOW] += 1
                            if primary:  # tested for the whole row beforehand
                                through = primary_shadow[ray, light, 0]
                                blocker = int(primary_shadow[ray, light, 1])
                            else:
                                through, blocker, sx, sy, sz, lx, ly, lz, t_light = shadow_start(
                                    spheres, sphere_object, planes, plane_object, materials, lights,
                                    light, px, py, pz, gx, gy, gz, lx, ly, lz, settings.epsilon,
                                    has_analytic,
                                )
                                if blocker == MISS and has_triangles:  # the any-hit query
                                    if holes:
                                        fraction, hit, nodes, tests = any_triangle(
                                            bounds, links, tris, tri_pass, sx, sy, sz, lx, ly, lz,
                                            0.0, t_light, stack, cutouts,
                                        )
                                    else:
                                        fraction, hit, nodes, tests = any_triangle(
                                            bounds, links, tris, tri_pass, sx, sy, sz, lx, ly, lz,
                                            0.0, t_light, stack,
                                        )
                                    counts[COUNT_NODES] += nodes
                                    counts[COUNT_TESTS] += tests
                                    if hit != MISS:
                                        through, blocker = 0.0, tri_object[hit]
                                    else:
                                        through *= fraction
                            if through > 0.0:
                                for field in range(4):
                                    lit[lit_count, field] = lights[light, field]
                                for field in range(4, 7):
                                    lit[lit_count, field] = lights[light, field] * through
                                lit_count += 1
                        if logged < log.shape[0]:
                            log_lights[logged, light, 0] = through
                            log_lights[logged, light, 1] = blocker
                    material = materials[obj]
                    if hit_kind == TRIANGLE and colored(scene.tables, obj):
                        material = _coloured_material(scene, work.material, obj, index, w1, w2, px,
                                                      py, pz, nx, ny, nz, dx, dy, dz)
                    shade_point(px, py, pz, nx, ny, nz, ox, oy, oz, 1.0, material, lit[:lit_count],
                                ambient, settings.blinn, shaded)
                    if (materials[obj, EMISSION] + materials[obj, EMISSION + 1]
                            + materials[obj, EMISSION + 2] > 0.0):
                        # light the surface gives off itself, scaled by its texture if any
                        emitted = (materials[obj, EMISSION], materials[obj, EMISSION + 1],
                                   materials[obj, EMISSION + 2])
                        if hit_kind == TRIANGLE and scene.tables.objects[obj, GLOW] >= 0:
                            emitted = textured_emission(scene, emitted, obj, index, w1, w2,
                                                        px, py, pz, nx, ny, nz, dx, dy, dz)
                        for channel in range(3):
                            shaded[channel] += emitted[channel]
                    r += weight * shaded[0]
                    g += weight * shaded[1]
                    b += weight * shaded[2]
                    if primary:
                        first_t, first_object = t, obj
                        # The normal the viewer sees: turned against the eye ray.
                        facing = -1.0 if nx * dx + ny * dy + nz * dz > 0.0 else 1.0
                        first_normal = (facing * nx, facing * ny, facing * nz)
                    ux, uy, uz = _unit(dx, dy, dz)
                    bounce = depth < settings.max_depth
                    kr, kt, total, fresnel, eta, tx, ty, tz = transmission(
                        ux, uy, uz, nx, ny, nz, entering, materials[obj, REFLECTIVITY],
                        materials[obj, TRANSPARENCY], materials[obj, IOR], bounce, settings.fresnel,
                    )
                    if total:
                        counts[COUNT_TOTAL_REFLECTION] += 1
                    if logged < log.shape[0]:
                        _log_hit(log, logged, t, obj, hit_kind, index, tri_source, px, py, pz, nx,
                                 ny, nz, gx, gy, gz, entering, material, shaded, kr, kt, total,
                                 fresnel, eta)
                    if not bounce:
                        continue
                    if kt > 0.0 and weight * kt >= MIN_WEIGHT:
                        sx, sy, sz = _offset(px, py, pz, gx, gy, gz, tx, ty, tz, settings.epsilon)
                        top = _push(rays, top, sx, sy, sz, tx, ty, tz, weight * kt, depth + 1.0,
                                    float(REFRACTED), float(logged))
                    if kr > 0.0 and weight * kr >= MIN_WEIGHT:
                        rx, ry, rz = reflect_direction(ux, uy, uz, nx, ny, nz)
                        sx, sy, sz = _offset(px, py, pz, gx, gy, gz, rx, ry, rz, settings.epsilon)
                        top = _push(rays, top, sx, sy, sz, rx, ry, rz, weight * kr, depth + 1.0,
                                    float(REFLECTED), float(logged))
                red += _clamp01(r)
                green += _clamp01(g)
                blue += _clamp01(b)
                if first_t < nearest:
                    nearest, nearest_object, nearest_normal = first_t, first_object, first_normal
            _store_pixel(out, i, red * scale, green * scale, blue * scale, nearest,
                         nearest_object, nearest_normal[0], nearest_normal[1],
                         nearest_normal[2])
        for i in range(width):
            rgb[row, i, 0] = out[i, RED]
            rgb[row, i, 1] = out[i, GREEN]
            rgb[row, i, 2] = out[i, BLUE]
            image_depth[row, i] = out[i, PIXEL_DEPTH]
            object_id[row, i] = int(out[i, PIXEL_OBJECT])
            for axis in range(3):
                normal[row, i, axis] = out[i, PIXEL_NORMAL + axis]
        for c in range(COUNTS):
            row_counts[row, c] = counts[c]


# Compiled once and inlined by LLVM into its three places in render_rows (see pixelpath._jit).
@inlined
def _store_pixel(out, i, red, green, blue, depth, obj, nx, ny, nz):
    """Write pixel i's fields into ``out``, the row of traced pixels."""
    out[i, RED] = red
    out[i, GREEN] = green
    out[i, BLUE] = blue
    out[i, PIXEL_DEPTH] = depth
    out[i, PIXEL_OBJECT] = obj
    out[i, PIXEL_NORMAL] = nx
    out[i, PIXEL_NORMAL + 1] = ny
    out[i, PIXEL_NORMAL + 2] = nz


def trace_pixel(x: int, y: int, scene, settings, work) -> np.ndarray:
    """Trace pixel (x, y) alone with :func:`render_rows`; return its fields in full precision.

    The (PIXEL_FIELDS,) row ``render_rows`` leaves in its ``out``, before the image's float32
    buffers (here one pixel each, thrown away) round it; ``work`` is a scratch space for rows
    one pixel wide, whose log records the pixel's rays when it has room.
    """
    out = np.empty((1, PIXEL_FIELDS))
    with slab_nan_allowed():
        render_rows(np.zeros(1, dtype=np.intp), scene, settings, work, out, x, y,
                    np.empty((1, 1, 3), dtype=np.float32), np.empty((1, 1), dtype=np.float32),
                    np.empty((1, 1), dtype=np.int32), np.empty((1, 1, 3), dtype=np.float32),
                    np.empty((1, COUNTS), dtype=np.int64))
    return out[0]


def warmup() -> None:
    """Compile the tracer on a one-pixel scene holding a sphere and a plane.

    The scene has no triangles (:func:`~pixelpath.raytrace.tracer.warmup_scene`), so no
    kernel of the BVH's group is compiled here. The row kernel finds its eye rays' search and
    their shadow search in the disk cache when the groups ``raytrace-eye`` and
    ``raytrace-shadows`` compiled them first (``pixelpath._warm.FEEDS``, ``FOLLOWS``).
    """
    from pixelpath.raytrace.tracer import warmup_scene

    scene, settings, bvh_depth = warmup_scene()
    trace_pixel(0, 0, scene, settings, new_work(scene, settings, bvh_depth, 0, 1))


def _compile_row_step(kernel, *leading) -> None:
    """Compile ``kernel`` alone for the types :func:`render_rows` passes it.

    ``kernel`` takes ``leading`` (integers), then the scene, its settings and the scratch
    space, here those of the tracer's one-pixel warm-up scene.
    """
    from pixelpath.raytrace.tracer import warmup_scene

    scene, settings, bvh_depth = warmup_scene()
    compile_for(kernel, *(np.intp(value) for value in leading), scene, settings,
                new_work(scene, settings, bvh_depth, 0, 1))


def warm_eye_rays() -> None:
    """Compile the search of a row's eye rays (``primary_hits``) alone."""
    _compile_row_step(primary_hits, 0, 0, 1)


def warm_shadow_rays() -> None:
    """Compile the shadow search of a row's eye-ray hits (``primary_shadows``) alone."""
    _compile_row_step(primary_shadows, 0, 0)
