"""Compiled eye rays of the Whitted tracer: samples, rays, and a row's nearest hits and shadows.

A pixel's samples are stratified and jittered by a hash of (pixel, sample), so that a render is
the same in every run. ``primary_hits`` finds the nearest hit of every eye ray of a row (the
triangles four neighbouring rays at a time, ``closest_triangles4``) and ``primary_shadows``
traces those hits' shadow rays (``any_triangles4``), before the row loop of
:mod:`pixelpath.raytrace._whitted_kernels` shades them.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit
from pixelpath.lighting._kernels import light_direction
from pixelpath.raytrace._hit_kernels import box_limit, enters_box
from pixelpath.raytrace._records import (
    COUNT_NODES,
    COUNT_TESTS,
    GEOMETRY_ENTERING,
    GEOMETRY_OBJECT,
    TRIANGLE,
)
from pixelpath.raytrace._surface_kernels import hit_geometry, nearest_analytic, shadow_start
from pixelpath.raytrace._traversal_kernels import (
    BLOCK,
    LANES,
    MISS,
    any_triangle,
    any_triangles4,
    closest_triangle,
    closest_triangles4,
    cut_away_hit,
)


@njit(refcount=False, from_python=False)
def _mul32(x, c):
    """Return x·c mod 2³² for x, c < 2³², in products below 2⁴⁹ (no int64 overflow)."""
    low = x * (c & 0xFFFF)
    high = ((x * (c >> 16)) & 0xFFFF) << 16
    return (low + high) & 0xFFFFFFFF


@njit(refcount=False, from_python=False)
def _hash32(x):
    """Return a 32-bit integer hash of x (Wellons' lowbias32), in int64 arithmetic."""
    x &= 0xFFFFFFFF
    x ^= x >> 16
    x = _mul32(x, 0x7FEB352D)
    x ^= x >> 15
    x = _mul32(x, 0x846CA68B)
    x ^= x >> 16
    return x


@njit(refcount=False, from_python=False)
def _uniform(pixel, sample, axis):
    """Return a number in [0, 1) fixed by (pixel, sample, axis): the same in every run."""
    h = _hash32(pixel ^ _hash32(2 * sample + axis + 0x9E3779B9))
    return (h >> 8) * (1.0 / 16777216.0)


# Inlined by Numba: as a function of its own LLVM leaves it a call (see pixelpath._jit).
@njit(inline="always")
def sample_position(pixel, sample, samples):
    """Return where sample ``sample`` of ``samples`` lies in its pixel, (0.5, 0.5) for one.

    Stratified: the pixel is cut into columns × rows = samples cells (the most square
    factorization, wider than tall), one jittered sample per cell.
    """
    if samples == 1:
        return 0.5, 0.5
    rows = int(math.sqrt(samples))
    while samples % rows != 0:
        rows -= 1
    columns = samples // rows
    cx = sample % columns
    cy = sample // columns
    return (cx + _uniform(pixel, sample, 0)) / columns, (cy + _uniform(pixel, sample, 1)) / rows


@njit(refcount=False, from_python=False)
def primary_ray(camera, px, py, width, height):
    """Return the origin and direction of the ray through image point (px, py).

    (px, py) in pixels, row 0 at the top. The origin lies on the plane through the eye
    perpendicular to the view (the eye itself for a perspective camera) and the direction's
    component along the viewing axis is 1, so the t of a hit is its depth.
    """
    ndc_x = 2.0 * px / width - 1.0
    ndc_y = 1.0 - 2.0 * py / height
    return (
        camera[0] + ndc_x * camera[12] + ndc_y * camera[15],
        camera[1] + ndc_x * camera[13] + ndc_y * camera[16],
        camera[2] + ndc_x * camera[14] + ndc_y * camera[17],
        camera[9] + ndc_x * camera[3] + ndc_y * camera[6],
        camera[10] + ndc_x * camera[4] + ndc_y * camera[7],
        camera[11] + ndc_x * camera[5] + ndc_y * camera[8],
    )


@njit(refcount=False, from_python=False)
def primary_hits(y, x0, width, scene, settings, work):
    """Find the nearest hit of every primary ray of a row, the triangles a packet at a time.

    Ray j is sample ``j % samples`` of pixel ``x0 + j // samples``; primary rays see what lies
    between the near and far planes, culled like the rasterizer's. Each ray is first tested
    against the spheres and planes, then the triangles are searched up to the nearest of
    those: neighbouring rays of a row run through the same boxes of the tree, so
    ``closest_triangles4`` walks it once for ``LANES`` of them (the row's last few rays go one
    by one), ``BLOCK`` rays a call. A ray whose nearest triangle is alpha-tested and cut away
    there is traced again alone, with the alpha test (the packet search makes none). Writes
    ``work.primary`` (t, w1, w2) and ``work.primary_hit`` (kind, index; index MISS when
    nothing is hit) and adds the nodes and triangle tests to ``work.counts``. Arrays are
    taken out of their tuples once, as in ``render_rows``.

    Only the rays :func:`searched_rays` leaves in are made and searched; the others, whose
    pixels lie outside ``scene.screen_bounds``, are marked as misses. Returns the first and
    stop of the searched rays.
    """
    spheres, planes, plane_back = scene.spheres, scene.planes, scene.plane_back
    bounds, links, tris = scene.bounds, scene.links, scene.tris
    tri_source, tri_back, camera = scene.tri_source, scene.tri_back, scene.camera
    cutouts = scene.cutouts
    holes = cutouts.masked.shape[0] > 0
    packet, kinds, lane_hit = work.packet, work.packet_kind, work.lane_hit
    found, found_hit, counts = work.primary, work.primary_hit, work.counts
    stack, stack_t, lane_t = work.stack, work.stack_t, work.lane_t
    samples = settings.samples
    near, far, cull = settings.near, settings.far, settings.cull
    count = width * samples
    first, stop = searched_rays(y, x0, width, samples, scene.screen_bounds,
                                work.log.shape[0] > 0)
    for ray in range(first):
        found_hit[ray, 1] = MISS
    for ray in range(stop, count):
        found_hit[ray, 1] = MISS
    x = x0 + first // samples  # the pixel and sample of the next ray
    sample = first % samples
    for start in range(first, stop, BLOCK):
        batch = min(BLOCK, stop - start)
        for r in range(batch):
            sx, sy = sample_position(y * settings.image_width + x, sample, samples)
            ox, oy, oz, dx, dy, dz = primary_ray(
                camera, x + sx, y + sy, settings.image_width, settings.image_height
            )
            sample += 1
            if sample == samples:
                x, sample = x + 1, 0
            t, kinds[r], found_hit[start + r, 1] = nearest_analytic(
                spheres, planes, plane_back, ox, oy, oz, dx, dy, dz, near, far, cull,
            )
            packet[r, 0], packet[r, 1], packet[r, 2] = ox, oy, oz
            packet[r, 3], packet[r, 4], packet[r, 5], packet[r, 6] = dx, dy, dz, t
            packet[r, 7] = packet[r, 8] = 0.0
            found[start + r, 0] = t  # the ray's limit, kept for a search through a hole
        if links.shape[0] > 0:
            nodes, tests = closest_triangles4(
                bounds, links, tris, tri_source, tri_back, cull, packet, batch, near, lane_hit,
                stack, stack_t, lane_t,
            )
            counts[COUNT_NODES] += nodes
            counts[COUNT_TESTS] += tests
            for r in range(batch):
                hit = lane_hit[r]
                if holes and hit != MISS and cutouts.masked[hit] and cut_away_hit(
                    cutouts, hit, packet[r, 7], packet[r, 8]
                ):
                    t, hit, w1, w2, nodes, tests = closest_triangle(
                        bounds, links, tris, tri_source, tri_back, cull, packet[r, 0],
                        packet[r, 1], packet[r, 2], packet[r, 3], packet[r, 4], packet[r, 5],
                        near, found[start + r, 0], stack, stack_t, cutouts,
                    )
                    packet[r, 6], packet[r, 7], packet[r, 8], lane_hit[r] = t, w1, w2, hit
                    counts[COUNT_NODES] += nodes
                    counts[COUNT_TESTS] += tests
                if lane_hit[r] != MISS:
                    kinds[r], found_hit[start + r, 1] = TRIANGLE, lane_hit[r]
        for r in range(batch):
            for field in range(3):
                found[start + r, field] = packet[r, 6 + field]  # t, w1, w2
                found[start + r, 3 + field] = packet[r, 3 + field]  # the direction
                found[start + r, 6 + field] = packet[r, field]  # the origin
            found_hit[start + r, 0] = kinds[r]
    return first, stop


@njit(refcount=False, from_python=False)
def searched_rays(y, x0, width, samples, screen_bounds, logging):
    """Return the first and stop of the eye rays of row y that :func:`primary_hits` searches.

    Ray j is sample ``j % samples`` of pixel ``x0 + j // samples``. ``screen_bounds`` holds
    the first and stop pixel columns, then rows, outside of which no eye ray can hit
    anything (:func:`pixelpath.raytrace.tracer.screen_bounds`); the rays of other pixels
    need no search. The span is widened to whole packets of ``LANES`` rays counted from the
    row's first, so the searched rays travel in the same packets as in a search of the whole
    row, and find the same hits. A logged render (``logging``) searches every ray: the log
    records each eye ray's origin and direction.
    """
    count = width * samples
    if logging:
        return 0, count
    if y < screen_bounds[2] or y >= screen_bounds[3]:
        return 0, 0
    first = max(screen_bounds[0] - x0, 0) * samples
    stop = min(max(screen_bounds[1] - x0, 0) * samples, count)
    if first >= stop:
        return 0, 0
    return first - first % LANES, min(stop + (-stop) % LANES, count)


@njit(refcount=False, from_python=False)
def primary_shadows(first, stop, scene, settings, work):
    """Test the shadow rays of the primary hits ``first`` to ``stop`` of a row, packets at a time.

    First each hit's object, point and normals (:func:`hit_geometry`) go into
    ``work.primary_geometry``, where ``render_rows`` reads them back. Then, light by light,
    the shadow ray of each hit in front of which the light is (the one ``render_rows``
    would make) is tested against the spheres and planes, and the rays that none of them
    blocks are gathered, ``BLOCK`` at a time, and tested against the triangles four by four
    (``any_triangles4``): neighbouring pixels' rays towards one light run through the same
    boxes. Writes the light let through and the blocker (MISS when none) into
    ``work.primary_shadow`` and adds nodes and triangle tests to ``work.counts``. In a scene
    with alpha-tested triangles each ray is tested alone, with the alpha test.
    """
    spheres, planes, materials = scene.spheres, scene.planes, scene.materials
    sphere_object, plane_object = scene.sphere_object, scene.plane_object
    bounds, links, tris, tri_pass = scene.bounds, scene.links, scene.tris, scene.tri_pass
    tri_normals, tri_flat, tri_object = scene.tri_normals, scene.tri_flat, scene.tri_object
    lights, cutouts = scene.lights, scene.cutouts
    holes = cutouts.masked.shape[0] > 0
    found, found_hit, result = work.primary, work.primary_hit, work.primary_shadow
    geometry = work.primary_geometry
    shadows, shadow_of, hit = work.shadows, work.shadow_of, work.lane_hit
    stack, counts = work.stack, work.counts
    has_analytic = spheres.shape[0] > 0 or planes.shape[0] > 0
    has_triangles = links.shape[0] > 0
    for ray in range(first, stop):
        if found_hit[ray, 1] != MISS:
            obj, px, py, pz, gx, gy, gz, nx, ny, nz, entering = hit_geometry(
                spheres, sphere_object, planes, plane_object, tris, tri_normals, tri_flat,
                tri_object, settings.flat, found[ray, 6], found[ray, 7], found[ray, 8],
                found[ray, 3], found[ray, 4], found[ray, 5], found[ray, 0], found_hit[ray, 0],
                found_hit[ray, 1], found[ray, 1], found[ray, 2],
            )
            for field, value in enumerate((px, py, pz, gx, gy, gz, nx, ny, nz)):
                geometry[ray, field] = value
            geometry[ray, GEOMETRY_OBJECT] = obj
            geometry[ray, GEOMETRY_ENTERING] = entering
    for light in range(lights.shape[0]):
        queued = 0
        for ray in range(first, stop):
            if found_hit[ray, 1] == MISS:
                continue
            px, py, pz, gx, gy, gz, nx, ny, nz = _stored_geometry(geometry, ray)
            lx, ly, lz = light_direction(lights, light, px, py, pz)
            if not nx * lx + ny * ly + nz * lz > 0.0:
                continue
            through, blocker, sx, sy, sz, lx, ly, lz, t_light = shadow_start(
                spheres, sphere_object, planes, plane_object, materials, lights, light, px, py,
                pz, gx, gy, gz, lx, ly, lz, settings.epsilon, has_analytic,
            )
            # Blocked already, or the tree is out of its way (any_triangle's own root-box test,
            # with its limit): nothing for a packet to find.
            if blocker != MISS or not has_triangles or not enters_box(
                bounds, 0, sx, sy, sz, lx, ly, lz, 0.0, box_limit(t_light)
            ):
                result[ray, light, 0], result[ray, light, 1] = through, blocker
                continue
            if holes:  # alone, with the alpha test
                fraction, blocking, nodes, tests = any_triangle(
                    bounds, links, tris, tri_pass, sx, sy, sz, lx, ly, lz, 0.0, t_light, stack,
                    cutouts,
                )
                counts[COUNT_NODES] += nodes
                counts[COUNT_TESTS] += tests
                if blocking != MISS:
                    result[ray, light, 0], result[ray, light, 1] = 0.0, tri_object[blocking]
                else:
                    result[ray, light, 0], result[ray, light, 1] = through * fraction, MISS
                continue
            shadows[queued, 0], shadows[queued, 1], shadows[queued, 2] = sx, sy, sz
            shadows[queued, 3], shadows[queued, 4], shadows[queued, 5] = lx, ly, lz
            shadows[queued, 6], shadows[queued, 8] = t_light, through
            shadow_of[queued, 0], shadow_of[queued, 1] = ray, light
            queued += 1
            if queued == BLOCK:
                _shadow_packets(queued, bounds, links, tris, tri_pass, tri_object, shadows,
                                shadow_of, hit, stack, counts, result)
                queued = np.intp(0)
        _shadow_packets(queued, bounds, links, tris, tri_pass, tri_object, shadows, shadow_of,
                        hit, stack, counts, result)


@njit(refcount=False, from_python=False)
def _stored_geometry(geometry, ray):
    """Return a primary hit's point, geometric and shading normals from work.primary_geometry."""
    g = geometry
    return (g[ray, 0], g[ray, 1], g[ray, 2], g[ray, 3], g[ray, 4], g[ray, 5], g[ray, 6],
            g[ray, 7], g[ray, 8])


# Inlined by Numba: as a function of its own LLVM leaves it a call (see pixelpath._jit).
@njit(inline="always")
def _shadow_packets(queued, bounds, links, tris, tri_pass, tri_object, shadows, shadow_of,
                    hit, stack, counts, result):
    """Test the ``queued`` shadow rays against the triangles and write their results.

    Inlined into :func:`primary_shadows`: a call would pass a dozen arrays per block of rays.
    """
    nodes, tests = any_triangles4(bounds, links, tris, tri_pass, shadows, queued, 0.0, hit,
                                  stack)
    counts[COUNT_NODES] += nodes
    counts[COUNT_TESTS] += tests
    for r in range(queued):
        ray, light = shadow_of[r, 0], shadow_of[r, 1]
        if hit[r] != MISS:
            result[ray, light, 0], result[ray, light, 1] = 0.0, tri_object[hit[r]]
        else:
            result[ray, light, 0], result[ray, light, 1] = shadows[r, 8] * shadows[r, 7], MISS
