"""The Whitted tracer's records: the packed scene, a render's settings, a thread's work space.

Also the numbers that name the fields the tracer's kernels and its Python side
(:mod:`pixelpath.raytrace.tracer`, :mod:`pixelpath.raytrace.explain`) share: a material row's,
a row's counters', a logged ray's, a pending ray's and a stored primary hit's. ``new_work``
allocates one thread's work space, which the thread keeps for all the rows it traces.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from pixelpath.raytrace._traversal_kernels import BLOCK, LANES, Cutouts
from pixelpath.scene._texture_kernels import SurfaceTables

# A ray whose weight falls below this is not traced: it could move no 8-bit pixel value unless
# the light it carries exceeded 16 (Hall and Greenberg's adaptive depth control).
MIN_WEIGHT = 1.0 / 4096.0

# Material rows of the tracer: Material.packed() (8 values), then these three, then the light
# the material emits (r, g, b).
REFLECTIVITY = 8
TRANSPARENCY = 9
IOR = 10
EMISSION = 11
MATERIAL_FIELDS = 14

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
COLOR = 33  # the surface colour C at the hit: the material's, times texture and vertex colours
LOG_FIELDS = 36

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
    # (4,) intp first and stop pixel columns, then rows, outside of which no eye ray can hit
    # anything: those rays are not searched (pixelpath.raytrace.tracer.screen_bounds)
    screen_bounds: np.ndarray


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
    packet: np.ndarray  # (BLOCK, 9) rays traced together: origin, direction, t, w1, w2
    packet_kind: np.ndarray  # (BLOCK,) intp the kind of primitive each one hits
    lane_hit: np.ndarray  # (BLOCK,) intp the triangle each one hits
    lane_t: np.ndarray  # (BVH depth + 1, LANES) the packet's stack of entry distances
    primary_geometry: np.ndarray  # (W × samples, GEOMETRY_FIELDS) what each hit is
    primary_shadow: np.ndarray  # (W × samples, L, 2) light let through, blocker per light
    shadows: np.ndarray  # (BLOCK, 9) shadow rays traced together: origin, direction, t_max,
    # light let through by the triangles, by the spheres and planes
    shadow_of: np.ndarray  # (BLOCK, 2) intp the primary ray and the light of each


def new_work(
    scene: TraceScene, settings: Settings, bvh_depth: int, log_size: int, row_width: int
) -> Work:
    """Return one thread's scratch space for rows of ``row_width`` pixels and ``log_size`` logs.

    Plain Python, not a kernel: a thread makes it once and keeps it while the sizes it
    depends on stay the same (``pixelpath.raytrace.tracer``), and compiled it cost about a
    second of the ray tracer's compile.

    Examples
    --------
    >>> from pixelpath.raytrace._records import new_work
    >>> from pixelpath.raytrace.tracer import warmup_scene
    >>> scene, settings, bvh_depth = warmup_scene()
    >>> new_work(scene, settings, bvh_depth, 0, 4).primary.shape[0] == 4 * settings.samples
    True
    """
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
        np.zeros((BLOCK, 9)),  # zeros: a short packet's unused rows are read, never used
        np.empty(BLOCK, dtype=np.intp),
        np.empty(BLOCK, dtype=np.intp),
        np.empty((bvh_depth + 1, LANES)),
        np.empty((primary_rays, GEOMETRY_FIELDS)),
        np.empty((primary_rays, lights, 2)),
        np.zeros((BLOCK, 9)),
        np.empty((BLOCK, 2), dtype=np.intp),
    )
