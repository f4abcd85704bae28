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

``trace_row`` can record every ray it traces into a log (``ray_tree`` runs it on one pixel
and reads it); the renderer passes an empty log.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from pixelpath._jit import njit
from pixelpath.lighting._kernels import light_direction, shade_point
from pixelpath.raytrace._hit_kernels import (
    box_limit,
    enters_box,
    plane_t,
    reflect_direction,
    refract_direction,
    slab_nan_allowed,
    sphere_roots,
    sphere_t,
)
from pixelpath.raytrace._traversal_kernels import (
    LANES,
    MISS,
    Cutouts,
    any_triangle,
    any_triangles4,
    closest_triangle,
    closest_triangles4,
    cut_away_hit,
)
from pixelpath.scene._texture_kernels import SurfaceTables, colored, surface_color

# A ray whose weight falls below this is not traced: it could move no 8-bit pixel value unless
# the light it carries exceeded 16 (Hall and Greenberg's adaptive depth control).
MIN_WEIGHT = 1.0 / 4096.0

# Material rows of the tracer: Material.packed() (8 values), then these three.
REFLECTIVITY = 8
TRANSPARENCY = 9
IOR = 10
MATERIAL_FIELDS = 11

# Kinds of ray (log field KIND) and of primitive (log field PRIMITIVE).
PRIMARY, REFLECTED, REFRACTED = 0, 1, 2
SPHERE, PLANE, TRIANGLE = 0, 1, 2

# Counters of a row of pixels.
COUNT_PRIMARY, COUNT_SHADOW, COUNT_REFLECTED, COUNT_REFRACTED = 0, 1, 2, 3
COUNT_MISSED, COUNT_TOTAL_REFLECTION, COUNT_NODES, COUNT_TESTS = 4, 5, 6, 7
COUNTS = 8

# Fields of a logged ray.
PARENT, KIND, DEPTH, WEIGHT, ORIGIN, DIRECTION, T = 0, 1, 2, 3, 4, 7, 10
OBJECT, PRIMITIVE, PRIMITIVE_INDEX, POINT, NORMAL, GEOMETRIC = 11, 12, 13, 14, 17, 20
ENTERING, LOCAL, KR, KT, TOTAL_REFLECTION, FRESNEL, ETA, SAMPLE = 23, 24, 27, 28, 29, 30, 31, 32
LOG_FIELDS = 33

# Pending rays on the stack: origin, direction, weight, depth, kind, log index of the parent.
RAY_FIELDS = 10
# Stored primary hits: point, geometric normal, shading normal, then these two.
GEOMETRY_OBJECT, GEOMETRY_ENTERING = 9, 10
GEOMETRY_FIELDS = 11


class TraceScene(NamedTuple):
    """Everything the tracer intersects and shades, packed by :mod:`pixelpath.raytrace.tracer`."""

    spheres: np.ndarray  # (S, 4) centre and radius
    sphere_object: np.ndarray  # (S,) intp object index
    planes: np.ndarray  # (P, 6) point and unit normal
    plane_object: np.ndarray  # (P,) intp
    plane_back: np.ndarray  # (P,) bool: seen from behind by the eye (culled for primary rays)
    bounds: np.ndarray  # (N, 6) BVH node boxes
    links: np.ndarray  # (N, 2) intp BVH (first, count)
    tris: np.ndarray  # (T, 9) triangle corners, in leaf order
    tri_normals: np.ndarray  # (T, 9) unit vertex normals at the corners
    tri_flat: np.ndarray  # (T, 3) unit normal of the polygon each triangle comes from
    tri_object: np.ndarray  # (T,) intp
    tri_source: np.ndarray  # (T,) intp triangle index in the scene's order (ties, reports)
    tri_back: np.ndarray  # (T,) bool: faces away from the eye (culled for primary rays)
    tri_pass: np.ndarray  # (T,) float64 transparency of each triangle's object
    materials: np.ndarray  # (O, MATERIAL_FIELDS)
    lights: np.ndarray  # (L, 7) packed lights
    ambient: np.ndarray  # (3,)
    background: np.ndarray  # (3,)
    # (18,) eye; direction steps right (u tan_x) and up (v tan_y); forward (-w); origin steps
    # right and up (half the view's width and height along u and v). A perspective camera has
    # no origin steps (every ray starts at the eye), an orthographic one no direction steps.
    camera: np.ndarray
    tables: SurfaceTables  # textures and which objects have coloured surfaces
    tri_uv: np.ndarray  # (3T, 2) texture coordinates at the corners; (0, 2) when unused
    tri_colors: np.ndarray  # (3T, 4) vertex colours at the corners; (0, 4) when unused
    tri_texel_scale: np.ndarray  # (T,) uv units per world unit on each triangle
    pixel_cone: np.ndarray  # (2,) a pixel's footprint width at the eye, growth per distance
    cutouts: Cutouts  # the alpha-tested triangles (``masked`` has no rows when there are none)


class Settings(NamedTuple):
    """The scalar choices of a render."""

    max_depth: int
    samples: int
    blinn: bool
    flat: bool
    fresnel: bool
    cull: bool  # back faces culled for primary rays
    epsilon: float  # offset of secondary ray origins along the normal
    near: float
    far: float
    image_width: int  # of the whole (supersampled) image: pixel numbers seed the sampling
    image_height: int


class Work(NamedTuple):
    """Scratch space of one thread, and the optional log of rays."""

    stack: np.ndarray  # (BVH depth + 1,) intp
    stack_t: np.ndarray  # (BVH depth + 1,)
    rays: np.ndarray  # (max_depth + 2, RAY_FIELDS) pending rays
    lights: np.ndarray  # (L, 7) the lights a shadow ray reaches, scaled by what gets through
    shaded: np.ndarray  # (3,)
    material: np.ndarray  # (MATERIAL_FIELDS,) a hit's material with its surface colour
    counts: np.ndarray  # (COUNTS,) int64
    log: np.ndarray  # (M, LOG_FIELDS) logged rays; M = 0 logs nothing
    log_lights: np.ndarray  # (M, L, 2) per logged ray and light: light let through, blocker
    logged: np.ndarray  # (1,) intp rays logged (may exceed M: the rest were not written)
    primary: np.ndarray  # (W × samples, 9) t, w1, w2 of each primary ray's hit, its direction
    # and its origin
    primary_hit: np.ndarray  # (W × samples, 2) intp its kind and index (MISS when none)
    packet: np.ndarray  # (LANES, 9) rays traced together: origin, direction, t, w1, w2
    packet_kind: np.ndarray  # (LANES,) intp the kind of primitive each one hits
    lane_hit: np.ndarray  # (LANES,) intp the triangle each one hits
    lane_t: np.ndarray  # (BVH depth + 1, LANES) the packet's stack of entry distances
    primary_geometry: np.ndarray  # (W × samples, GEOMETRY_FIELDS) what each hit is
    primary_shadow: np.ndarray  # (W × samples, L, 2) light let through, blocker per light
    shadows: np.ndarray  # (LANES, 9) shadow rays traced together: origin, direction, t_max,
    # light let through by the triangles, by the spheres and planes
    shadow_of: np.ndarray  # (LANES, 2) intp the primary ray and the light of each


@njit
def new_work(scene, settings, bvh_depth, log_size, row_width):
    """Return one thread's scratch space for rows of ``row_width`` pixels and ``log_size`` logs."""
    lights = scene.lights.shape[0]
    primary_rays = row_width * settings.samples
    return Work(
        np.empty(bvh_depth + 1, dtype=np.intp),
        np.empty(bvh_depth + 1),
        np.empty((settings.max_depth + 2, RAY_FIELDS)),
        np.empty((lights, 7)),
        np.empty(3),
        np.empty(MATERIAL_FIELDS),
        np.zeros(COUNTS, dtype=np.int64),
        np.empty((log_size, LOG_FIELDS)),
        np.empty((log_size, lights, 2)),
        np.zeros(1, dtype=np.intp),
        np.empty((primary_rays, 9)),
        np.empty((primary_rays, 2), dtype=np.intp),
        np.zeros((LANES, 9)),  # zeros: a short packet's unused rows are read, never used
        np.empty(LANES, dtype=np.intp),
        np.empty(LANES, dtype=np.intp),
        np.empty((bvh_depth + 1, LANES)),
        np.empty((primary_rays, GEOMETRY_FIELDS)),
        np.empty((primary_rays, lights, 2)),
        np.zeros((LANES, 9)),
        np.empty((LANES, 2), dtype=np.intp),
    )


@njit(inline="always")
def _mul32(x, c):
    """Return x·c mod 2³² for x, c < 2³², in products below 2⁴⁹ (no int64 overflow)."""
    low = x * (c & 0xFFFF)
    high = ((x * (c >> 16)) & 0xFFFF) << 16
    return (low + high) & 0xFFFFFFFF


@njit(inline="always")
def _hash32(x):
    """Return a 32-bit integer hash of x (Wellons' lowbias32), in int64 arithmetic."""
    x &= 0xFFFFFFFF
    x ^= x >> 16
    x = _mul32(x, 0x7FEB352D)
    x ^= x >> 15
    x = _mul32(x, 0x846CA68B)
    x ^= x >> 16
    return x


@njit(inline="always")
def _uniform(pixel, sample, axis):
    """Return a number in [0, 1) fixed by (pixel, sample, axis): the same in every run."""
    h = _hash32(pixel ^ _hash32(2 * sample + axis + 0x9E3779B9))
    return (h >> 8) * (1.0 / 16777216.0)


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


@njit(inline="always")
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


@njit(refcount=False)
def primary_hits(y, x0, width, scene, settings, work):
    """Find the nearest hit of every primary ray of a row, the triangles a packet at a time.

    Ray j is sample ``j % samples`` of pixel ``x0 + j // samples``; primary rays see what lies
    between the near and far planes, culled like the rasterizer's. Each ray is first tested
    against the spheres and planes, then the triangles are searched up to the nearest of
    those: neighbouring rays of a row run through the same boxes of the tree, so
    ``closest_triangles4`` walks it once for ``LANES`` of them (the row's last few rays go one
    by one). A ray whose nearest triangle is alpha-tested and cut away there is traced again
    alone, with the alpha test (the packet search makes none). Writes ``work.primary`` (t, w1,
    w2) and ``work.primary_hit`` (kind, index; index MISS when nothing is hit) and adds the
    nodes and triangle tests to ``work.counts``. Arrays are taken out of their tuples once, as
    in :func:`trace_row`.
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
    full = count - count % LANES
    x = x0  # the pixel and sample of the next ray
    sample = 0
    for start in range(0, count, LANES):
        lanes = LANES if start < full else count - start
        for r in range(lanes):
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
                bounds, links, tris, tri_source, tri_back, cull, packet, lanes, near, lane_hit,
                stack, stack_t, lane_t,
            )
            counts[COUNT_NODES] += nodes
            counts[COUNT_TESTS] += tests
            for r in range(lanes):
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
        for r in range(lanes):
            for field in range(3):
                found[start + r, field] = packet[r, 6 + field]  # t, w1, w2
                found[start + r, 3 + field] = packet[r, 3 + field]  # the direction
                found[start + r, 6 + field] = packet[r, field]  # the origin
            found_hit[start + r, 0] = kinds[r]


@njit(refcount=False)
def primary_shadows(count, scene, settings, work):
    """Test the shadow rays of the first ``count`` primary hits of a row, a packet at a time.

    First each hit's object, point and normals (:func:`hit_geometry`) go into
    ``work.primary_geometry``, where :func:`trace_row` reads them back. Then, light by light,
    the shadow ray of each hit in front of which the light is (the one :func:`trace_row`
    would make) is tested against the spheres and planes, and the rays that none of them
    blocks are gathered four at a time and tested against the triangles together
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
    for ray in range(count):
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
        queued = np.intp(0)  # not the literal 0, for which any_triangles4 was compiled again
        for ray in range(count):
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
            if queued == LANES:
                _shadow_packet(queued, bounds, links, tris, tri_pass, tri_object, shadows,
                               shadow_of, hit, stack, counts, result)
                queued = np.intp(0)
        _shadow_packet(queued, bounds, links, tris, tri_pass, tri_object, shadows, shadow_of,
                       hit, stack, counts, result)


@njit(inline="always")
def _stored_geometry(geometry, ray):
    """Return a primary hit's point, geometric and shading normals from work.primary_geometry."""
    g = geometry
    return (g[ray, 0], g[ray, 1], g[ray, 2], g[ray, 3], g[ray, 4], g[ray, 5], g[ray, 6],
            g[ray, 7], g[ray, 8])


@njit(inline="always")
def _shadow_packet(lanes, bounds, links, tris, tri_pass, tri_object, shadows, shadow_of, hit,
                   stack, counts, result):
    """Test the ``lanes`` queued shadow rays against the triangles and write their results.

    Inlined into :func:`primary_shadows`: a call would pass a dozen arrays per packet.
    """
    nodes, tests = any_triangles4(bounds, links, tris, tri_pass, shadows, lanes, 0.0, hit, stack)
    counts[COUNT_NODES] += nodes
    counts[COUNT_TESTS] += tests
    for r in range(lanes):
        ray, light = shadow_of[r, 0], shadow_of[r, 1]
        if hit[r] != MISS:
            result[ray, light, 0], result[ray, light, 1] = 0.0, tri_object[hit[r]]
        else:
            result[ray, light, 0], result[ray, light, 1] = shadows[r, 8] * shadows[r, 7], MISS


@njit(inline="always")
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


@njit(inline="always")
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


@njit(refcount=False)
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


@njit(refcount=False)
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


@njit(inline="always")
def sphere_normal(cx, cy, cz, radius, px, py, pz):
    """Return the outward unit normal at point p of the sphere (centre c, radius)."""
    return _unit((px - cx) / radius, (py - cy) / radius, (pz - cz) / radius)


@njit(refcount=False)
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


@njit(refcount=False)
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

    The hit is at barycentric (w1, w2) of triangle ``index``. The texture is filtered for the
    pixel's footprint there: the cone's width at the hit's distance from the eye, stretched by
    1 / cos of the angle between ray and normal, in uv units through the triangle's texel
    scale.
    """
    for field in range(out.shape[0]):
        out[field] = scene.materials[obj, field]
    eye = scene.camera
    distance = math.sqrt((px - eye[0]) ** 2 + (py - eye[1]) ** 2 + (pz - eye[2]) ** 2)
    width = scene.pixel_cone[0] + scene.pixel_cone[1] * distance
    length = math.sqrt(dx * dx + dy * dy + dz * dz)
    cosine = abs(nx * dx + ny * dy + nz * dz) / length if length > 0.0 else 1.0
    span = scene.tri_texel_scale[index] * width / max(cosine, 1e-3)
    first = 3 * index  # the triangle's corners' rows of tri_uv and tri_colors
    r, g, b, _ = surface_color(
        scene.tables, scene.materials, obj, scene.tri_uv, scene.tri_colors, first, first + 1,
        first + 2, 1.0 - w1 - w2, w1, w2, span, 0.0, 0.0, span,
    )
    out[0], out[1], out[2] = r, g, b
    return out


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


@njit(refcount=False)
def _log_ray(log, row, parent, kind, depth, weight, ox, oy, oz, dx, dy, dz, sample):
    log[row, PARENT] = parent
    log[row, KIND] = kind
    log[row, DEPTH] = depth
    log[row, WEIGHT] = weight
    log[row, ORIGIN], log[row, ORIGIN + 1], log[row, ORIGIN + 2] = ox, oy, oz
    log[row, DIRECTION], log[row, DIRECTION + 1], log[row, DIRECTION + 2] = dx, dy, dz
    log[row, SAMPLE] = sample


@njit(refcount=False)
def _log_miss(log, row, background):
    log[row, T] = math.inf
    log[row, OBJECT] = MISS
    log[row, PRIMITIVE] = MISS
    for c in range(3):
        log[row, LOCAL + c] = background[c]


@njit(refcount=False)
def _log_hit(log, row, t, obj, kind, index, source, px, py, pz, nx, ny, nz, gx, gy, gz,
             entering, shaded, kr, kt, total, fresnel, eta):
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
    log[row, KR] = kr
    log[row, KT] = kt
    log[row, TOTAL_REFLECTION] = 1.0 if total else 0.0
    log[row, FRESNEL] = fresnel
    log[row, ETA] = eta


@njit(inline="always")
def _clamp01(value):
    return min(max(value, 0.0), 1.0)


# Fields of a traced pixel (trace_row's output).
RED, GREEN, BLUE, PIXEL_DEPTH, PIXEL_OBJECT, PIXEL_NORMAL = 0, 1, 2, 3, 4, 5
PIXEL_FIELDS = 8


@njit(refcount=False)
def trace_row(y, x0, width, scene, settings, work, out):
    """Trace pixels x0 .. x0 + width − 1 of row y of the whole image into out (width, 5).

    A pixel's fields are r, g, b (the mean of the clamped colours of its samples), depth and
    object (from the nearest sample that hit something). Each sample's eye ray and its tree
    are followed with the stack work.rays: a ray adds ``weight × I_local`` as it is traced.
    The eye rays' nearest hits are found first, for the whole row (:func:`primary_hits`).

    The loops over pixels, samples and rays, and the local light of a hit, share this one
    function on purpose: a compiled call passes each array as several machine words, more
    work than a ray that misses needs. So the scene's and the scratch arrays are taken out of
    their tuples once per row; per secondary ray only the nearest-hit searches are called (a
    few arrays each, the triangles' only when the ray enters the root box), per packet of eye
    rays the packet's search, per shadow ray the any-hit search, and per hit the normal and
    Phong kernels. Like the searches, the row kernels count no references
    (``njit(refcount=False)``): counted, the scene's arrays had their counts updated atomically
    at each of those calls and inlined helpers, per ray, from every thread.
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
    # Not the literal False: the searches would be compiled a second time for it.
    cull_none = np.bool_(False)
    primary_hits(y, x0, width, scene, settings, work)
    primary_shadows(width * samples, scene, settings, work)
    for i in range(width):
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
                    t, w1, w2 = primary_found[ray, 0], primary_found[ray, 1], primary_found[ray, 2]
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
                                bounds, links, tris, tri_source, tri_back, cull_none, ox, oy, oz,
                                dx, dy, dz, 0.0, t, stack, stack_t, cutouts,
                            )
                        else:
                            t_tri, tri, b1, b2, nodes, tests = closest_triangle(
                                bounds, links, tris, tri_source, tri_back, cull_none, ox, oy, oz,
                                dx, dy, dz, 0.0, t, stack, stack_t,
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
                        tri_flat, tri_object, settings.flat, ox, oy, oz, dx, dy, dz, t, hit_kind,
                        index, w1, w2,
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
                             ny, nz, gx, gy, gz, entering, shaded, kr, kt, total, fresnel, eta)
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
        scale = 1.0 / samples
        out[i, RED] = red * scale
        out[i, GREEN] = green * scale
        out[i, BLUE] = blue * scale
        out[i, PIXEL_DEPTH] = nearest
        out[i, PIXEL_OBJECT] = nearest_object
        for axis in range(3):
            out[i, PIXEL_NORMAL + axis] = nearest_normal[axis]


@njit
def render_rows(rows, scene, settings, bvh_depth, x0, y0, rgb, depth, object_id, normal,
                counts):
    """Trace the listed rows of the region whose top-left pixel is (x0, y0) of the image.

    Writes rgb (h, w, 3) float32, depth (h, w) float32 (inf where nothing was hit), object_id
    (h, w) int32 (-1 there), the unit normal (h, w, 3) float32 seen at the nearest hit (0
    there) and each row's counters into counts (h, COUNTS). Serial: the
    caller runs disjoint lists of rows from several threads (the kernel releases the GIL).
    """
    width = rgb.shape[1]
    out = np.empty((width, PIXEL_FIELDS))
    work = new_work(scene, settings, bvh_depth, np.intp(0), width)  # no log (not a literal 0)
    for k in range(rows.shape[0]):
        row = rows[k]
        for c in range(COUNTS):
            work.counts[c] = 0
        trace_row(y0 + row, x0, width, scene, settings, work, out)
        for i in range(width):
            rgb[row, i, 0] = out[i, RED]
            rgb[row, i, 1] = out[i, GREEN]
            rgb[row, i, 2] = out[i, BLUE]
            depth[row, i] = out[i, PIXEL_DEPTH]
            object_id[row, i] = int(out[i, PIXEL_OBJECT])
            for axis in range(3):
                normal[row, i, axis] = out[i, PIXEL_NORMAL + axis]
        for c in range(COUNTS):
            counts[row, c] = work.counts[c]


def warmup() -> None:
    """Compile the tracer on a one-pixel scene holding a sphere, a plane and a triangle."""
    from pixelpath.raytrace.tracer import warmup_scene

    scene, settings, bvh_depth = warmup_scene()
    rgb = np.empty((1, 1, 3), dtype=np.float32)
    depth = np.empty((1, 1), dtype=np.float32)
    ids = np.empty((1, 1), dtype=np.int32)
    counts = np.empty((1, COUNTS), dtype=np.int64)
    with slab_nan_allowed():
        render_rows(np.zeros(1, dtype=np.intp), scene, settings, bvh_depth, 0, 0, rgb, depth,
                    ids, np.empty((1, 1, 3), dtype=np.float32), counts)
        work = new_work(scene, settings, bvh_depth, 8, 1)
        trace_row(0, 0, 1, scene, settings, work, np.empty((1, PIXEL_FIELDS)))
