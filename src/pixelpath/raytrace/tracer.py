"""Ray tracing as a rendering method: ``pixelpath.render(scene, method="raytrace")``.

The notes' recursive ray tracer (section 8): a primary ray through each pixel centre (or
``samples`` stratified, seeded points of the pixel), the nearest hit over the analytic spheres
and infinite planes and the triangles of boxes and meshes (under a BVH), the Phong model with a
shadow ray per light, reflected and refracted rays to ``max_depth``. How one pixel's tree of rays
is followed is described in :mod:`pixelpath.raytrace._whitted_kernels`.

**Same pixels as the rasterizer.** Primary rays come from the same :class:`~pixelpath.Camera`
through the same pixel centres (``x + 0.5``, ``y + 0.5``, row 0 at the top) with a direction whose
component along the viewing axis is 1, so a hit's t is the depth the z-buffer stores. Like the
rasterizer, they see only what lies between the camera's near and far planes and, with
``backface_cull`` on, only front faces: the polygons :func:`pixelpath.hsr.backface.front_facing`
keeps (the very test the rasterizer runs), a plane only from its normal's side, a sphere only
where the ray enters it. So ``Image.object_id`` and ``Image.depth`` agree with the z-buffer's
except on silhouettes (the rasterizer draws a sphere as 5120 triangles, the ray tracer exactly).
Shadow, reflected and refracted rays see both sides of everything; a face seen from behind is lit
with its normal turned towards the ray (a two-sided surface, as the rasterizer does without
culling).

**Shading.** ``"phong"`` evaluates the model at each hit with the interpolated vertex normal of
a mesh; ``"flat"`` with the normal of the polygon hit (spheres and planes have one exact normal
either way). Gouraud shading interpolates vertex intensities, which a ray tracer has no use for:
``shading="gouraud"`` is refused.

**Alpha-tested materials** (``Material.alpha_cutoff``) are holes where their alpha test cuts
them, for every ray (eye, shadow, reflected, refracted): the searches skip such a hit and go on
through (:mod:`pixelpath.raytrace._whitted_kernels`). The test is the rasterizer's, at the hit's
barycentric coordinates, so both cut the same holes; scenes without it are traced as before.

**Epsilon.** Secondary rays start ``epsilon = EPSILON_SCALE × extent`` off the surface along its
geometric normal, extent being the largest coordinate (in absolute value) of the eye, the
target distance and the bounded objects: far above the rounding error of a hit point
(a few units in the last place of those coordinates), far below anything visible.
"""

from __future__ import annotations

import dataclasses
import threading
from typing import Any

import numpy as np

from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.raster.tessellate import _IdentityCache, member_ids
from pixelpath.raytrace.bvh import BVH
from pixelpath.scene import Box, Camera, Mesh, Plane, Scene, Sphere

__all__ = ["EPSILON_SCALE", "STEPS", "render_frame"]

EPSILON_SCALE = 1e-9
TRACE_SLICES = 16  # progress steps while tracing (each a share of the rows, run on several threads)
STEPS = 1 + TRACE_SLICES  # packing the scene (and building the BVH), then tracing
RUNS_PER_STEP = 4  # runs of rows handed to the threads per progress step
ROWS_PER_BLOCK = 16  # neighbouring rows traced one after the other (8-32 measured alike)


@dataclasses.dataclass(frozen=True)
class SceneTriangles:
    """The triangles of a scene's boxes and meshes under one BVH, in the tree's leaf order."""

    bvh: BVH
    normals: np.ndarray  # (T, 9) unit vertex normals at the three corners
    flat: np.ndarray  # (T, 3) unit normal of the polygon each triangle comes from
    objects: np.ndarray  # (T,) intp object index
    polygon: np.ndarray  # (T,) intp polygon (over all meshes) each triangle comes from
    polygon_normals: np.ndarray  # (P, 3)
    polygon_points: np.ndarray  # (P, 3) first corner of each polygon
    tables: Any  # SurfaceTables of the scene's objects (textures, vertex colours)
    uv: np.ndarray  # (3T, 2) texture coordinates at each triangle's corners; (0, 2) if unused
    colors: np.ndarray  # (3T, 4) vertex colours at the corners; (0, 4) if unused
    texel_scale: np.ndarray  # (T,) sqrt(uv area / world area): uv units per world unit


_TRIANGLES = _IdentityCache(8, member_ids)  # per scene objects (kept when the camera changes)


def scene_triangles(scene: Scene) -> SceneTriangles:
    """Return the BVH and leaf-ordered triangle data of a scene's boxes and meshes (cached).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, Scene, Sphere
    >>> from pixelpath.raytrace.tracer import scene_triangles
    >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)),
    ...               [Sphere((0, 0, 0), 1.0), Box((2, 0, 0), (3, 1, 1))])
    >>> triangles = scene_triangles(scene)
    >>> triangles.bvh.triangle_count, sorted(set(triangles.objects.tolist()))
    (12, [1])
    """
    return _TRIANGLES.get(scene.objects, _build_triangles)


def _build_triangles(objects: tuple[Any, ...]) -> SceneTriangles:
    from pixelpath.scene._texture_kernels import GLOW, HAS_COLORS, TEXTURE
    from pixelpath.scene.texture import surface_tables

    tables = surface_tables(objects)
    meshes = [(k, o if isinstance(o, Mesh) else o.to_mesh()) for k, o in enumerate(objects)
              if isinstance(o, Mesh | Box)]
    textured = (tables.objects[:, TEXTURE] >= 0) | (tables.objects[:, GLOW] >= 0)
    painted = tables.objects[:, HAS_COLORS] != 0
    corners, normals, flat, owner, polygon = [], [], [], [], []
    uv, colors = [], []
    polygon_normals, polygon_points = [], []
    polygons = 0
    for k, mesh in meshes:
        tri = mesh.triangles
        corners.append(mesh.vertices[tri].reshape(-1, 9))
        normals.append(mesh.vertex_normals[tri].reshape(-1, 9))
        flat.append(mesh.face_normals[mesh.triangle_face])
        owner.append(np.full(len(tri), k, dtype=np.intp))
        polygon.append(mesh.triangle_face + polygons)
        polygon_normals.append(mesh.face_normals)
        polygon_points.append(mesh.vertices[mesh.face_indices[mesh.face_offsets[:-1]]])
        polygons += mesh.face_count
        uv.append(mesh.uv[tri].reshape(-1, 6) if textured[k] else np.zeros((len(tri), 6)))
        colors.append(mesh.colors[tri].reshape(-1, 12) if painted[k] else np.ones((len(tri), 12)))

    def stacked(parts, width, dtype=np.float64):
        shape = (0, width) if width else (0,)
        return np.ascontiguousarray(np.concatenate(parts), dtype=dtype) if parts else np.empty(
            shape, dtype=dtype
        )

    bvh = BVH._from_corners(stacked(corners, 9))
    order = bvh.order

    def corner_rows(parts, width, used):
        """Leaf-ordered per-corner rows (3T, width), or none when no object uses them."""
        if not used.any():
            return np.empty((0, width))
        return np.ascontiguousarray(stacked(parts, 3 * width)[order].reshape(-1, width))

    corner_uv = corner_rows(uv, 2, textured)
    return SceneTriangles(
        bvh=bvh,
        normals=np.ascontiguousarray(stacked(normals, 9)[order]),
        flat=np.ascontiguousarray(stacked(flat, 3)[order]),
        objects=np.ascontiguousarray(stacked(owner, 0, np.intp)[order]),
        polygon=np.ascontiguousarray(stacked(polygon, 0, np.intp)[order]),
        polygon_normals=stacked(polygon_normals, 3),
        polygon_points=stacked(polygon_points, 3),
        tables=tables,
        uv=corner_uv,
        colors=corner_rows(colors, 4, painted),
        texel_scale=_texel_scale(bvh.corners, corner_uv),
    )


def _texel_scale(corners: np.ndarray, uv: np.ndarray) -> np.ndarray:
    """(T,) how many uv units one world unit spans on each triangle (0 without uv).

    The square root of the triangle's area in texture space over its area in space: with a
    pixel's footprint on the surface it gives the footprint in texels, which sets the mip
    level (the "ray cone" estimate of texture filtering in ray tracers).
    """
    if len(uv) == 0:
        return np.zeros(len(corners))
    p = corners.reshape(-1, 3, 3)
    world = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    t = uv.reshape(-1, 3, 2)
    e1, e2 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
    texture = np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    return np.sqrt(np.divide(texture, world, out=np.zeros(len(p)), where=world > 0.0))


def scene_materials(scene: Scene) -> np.ndarray:
    """Return (O, 14) rows: ``Material.packed()``, reflectivity, transparency, ior, emission.

    The first 8 values are the rasterizer's layout, so the lighting kernel reads a row as it is.

    Examples
    --------
    >>> from pixelpath.scene import Camera, Material, Scene, Sphere
    >>> from pixelpath.raytrace.tracer import scene_materials
    >>> glass = Material(transparency=0.9, ior=1.5)
    >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), [Sphere((0, 0, 0), 1, glass)])
    >>> scene_materials(scene)[0, 8:11].tolist()
    [0.0, 0.9, 1.5]
    """
    from pixelpath.raytrace._records import MATERIAL_FIELDS

    rows = [
        [*o.material.packed(), o.material.reflectivity, o.material.transparency, o.material.ior,
         *o.material.emission]
        for o in scene.objects
    ]
    return np.array(rows, dtype=np.float64).reshape(len(rows), MATERIAL_FIELDS)


def scene_extent(scene: Scene) -> float:
    """Return the length ``epsilon`` is a fraction of: the scene's largest coordinate.

    The largest absolute coordinate of the eye, of the bounded objects and of the planes'
    points, and at least the eye's distance to its target.

    Examples
    --------
    >>> from pixelpath.scene import Camera, Scene, Sphere
    >>> from pixelpath.raytrace.tracer import scene_extent
    >>> scene_extent(Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), [Sphere((0, 9, 0), 1)]))
    10.0
    """
    camera = scene.camera
    values = [np.abs(camera.eye).max(), float(np.linalg.norm(camera.eye - camera.target))]
    for obj in scene.objects:
        box = obj.bounds() if not isinstance(obj, Plane) else obj.point[None]
        values.append(float(np.abs(box).max()))
    return float(max(values))


def pack(scene: Scene, camera: Camera, options: RenderOptions):
    """Return what the kernels read: (TraceScene, Settings, BVH depth, SceneTriangles)."""
    from pixelpath.hsr.backface import front_facing
    from pixelpath.lighting import pack_lights
    from pixelpath.raster._arrays import kernel_array
    from pixelpath.raytrace import _records as rec
    from pixelpath.raytrace._traversal_kernels import Cutouts

    if options.shading not in ("phong", "flat"):
        raise ValueError(
            "method='raytrace' evaluates the model at every hit: shading must be 'phong' "
            f"(interpolated normals) or 'flat' (polygon normals), got {options.shading!r}"
        )
    triangles = scene_triangles(scene)
    cut = _alpha_tested(triangles.tables)
    # A sphere's or plane's alpha is its material's (no texture coordinates): an alpha-tested
    # one is cut away everywhere, and left out.
    spheres = [(k, o) for k, o in enumerate(scene.objects) if isinstance(o, Sphere) and not cut[k]]
    planes = [(k, o) for k, o in enumerate(scene.objects) if isinstance(o, Plane) and not cut[k]]
    plane_normals = np.array([p.normal for _, p in planes]).reshape(-1, 3)
    plane_points = np.array([p.point for _, p in planes]).reshape(-1, 3)
    viewpoint = camera.viewpoint()
    polygon_back = ~front_facing(triangles.polygon_normals, triangles.polygon_points, viewpoint)
    # Double-sided materials are never culled (as in the rasterizer's pipeline.prepare).
    double_sided = np.array([o.material.double_sided for o in scene.objects], dtype=bool)
    tri_back = polygon_back[triangles.polygon] & ~double_sided[triangles.objects]
    plane_back = ~front_facing(plane_normals, plane_points, viewpoint)
    plane_back &= ~double_sided[np.array([k for k, _ in planes], dtype=np.intp)]
    materials = scene_materials(scene)
    world = rec.TraceScene(
        spheres=np.array([[*s.center, s.radius] for _, s in spheres]).reshape(-1, 4),
        sphere_object=np.array([k for k, _ in spheres], dtype=np.intp),
        planes=np.ascontiguousarray(np.hstack([plane_points, plane_normals])),
        plane_object=np.array([k for k, _ in planes], dtype=np.intp),
        plane_back=plane_back,
        bounds=triangles.bvh.bounds,
        links=triangles.bvh.links,
        tris=triangles.bvh.corners,
        tri_normals=triangles.normals,
        tri_flat=triangles.flat,
        tri_object=triangles.objects,
        tri_source=triangles.bvh.order,
        tri_back=np.ascontiguousarray(tri_back),
        tri_pass=np.ascontiguousarray(materials[triangles.objects, rec.TRANSPARENCY]),
        materials=materials,
        lights=pack_lights(scene.lights),
        ambient=kernel_array(scene.ambient),
        background=kernel_array(scene.background),
        camera=_primary_rays(camera),
        tables=triangles.tables,
        tri_uv=triangles.uv,
        tri_colors=triangles.colors,
        tri_texel_scale=triangles.texel_scale,
        pixel_cone=_pixel_cone(camera),
        cutouts=Cutouts(_masked(cut, triangles.objects), triangles.objects, triangles.uv,
                        triangles.colors, triangles.tables),
        screen_bounds=screen_bounds(camera, _bounded_boxes(triangles, spheres, planes)),
    )
    settings = rec.Settings(
        max_depth=options.max_depth,
        samples=options.samples,
        blinn=bool(options.blinn),
        flat=options.shading == "flat",
        fresnel=bool(options.fresnel),
        cull=bool(options.backface_cull),
        epsilon=EPSILON_SCALE * scene_extent(scene),
        near=float(camera.near),
        far=float(camera.far),
        image_width=camera.width,
        image_height=camera.height,
    )
    return world, settings, max(triangles.bvh.depth, 1), triangles


def _bounded_boxes(triangles: SceneTriangles, spheres: list, planes: list) -> np.ndarray | None:
    """(B, 6) boxes (min x, y, z, max x, y, z) of everything an eye ray can hit; None if unbounded.

    The triangles' tree's root box and each sphere's box; a plane has no bounds.
    """
    if planes:
        return None
    boxes = [triangles.bvh.bounds[:1]] if triangles.bvh.links.shape[0] > 0 else []
    boxes += [np.concatenate([s.center - s.radius, s.center + s.radius])[None] for _, s in spheres]
    return np.concatenate(boxes) if boxes else np.empty((0, 6))


# Pixels added on each side of the projected boxes: far more than the rounding of any ray's
# search, so that no ray that would hit something is left out.
SCREEN_MARGIN = 2
# The eight corners of a box, as picks of its min (0) or max (1) on each axis.
_BOX_CORNERS = np.array([[(k >> axis) & 1 for axis in range(3)] for k in range(8)], dtype=bool)
_BOX_CORNERS.flags.writeable = False


def screen_bounds(camera: Camera, boxes: np.ndarray | None) -> np.ndarray:
    """Return the pixels whose eye rays can hit something inside ``boxes``.

    An eye ray meets a box only if its pixel lies in the box's picture, which is inside the
    rectangle around the pictures of its eight corners, projected as the rasterizer projects
    them (:func:`~pixelpath.raster.transform.world_to_clip`), when all of them lie in front
    of the eye. Returns (4,) intp: the first and stop pixel columns, then rows, of the union
    of those rectangles, widened by ``SCREEN_MARGIN`` pixels and cut to the image. The whole
    image when ``boxes`` is None (something unbounded, as a plane), when a perspective
    camera's eye lies beside a box, neither wholly in front of it nor behind, or when a box
    or its picture is not finite; nothing (all zeros) when every box lies behind a
    perspective camera's eye. The tracer does not search the eye rays of the other pixels:
    they miss everything.

    Parameters
    ----------
    camera : Camera
        The view (perspective or orthographic) and its size in pixels.
    boxes : (B, 6) array or None
        Boxes as (min x, y, z, max x, y, z).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.raytrace.tracer import screen_bounds
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=100, height=100)
    >>> screen_bounds(camera, np.array([[-1.0, -1, -1, 1, 1, 1]])).tolist()
    [35, 65, 35, 65]
    >>> screen_bounds(camera, None).tolist()
    [0, 100, 0, 100]
    """
    from pixelpath.raster.transform import world_to_clip

    whole = np.array([0, camera.width, 0, camera.height], dtype=np.intp)
    if boxes is None or not np.isfinite(boxes).all():
        return whole
    corners = np.where(_BOX_CORNERS[None], boxes[:, None, 3:], boxes[:, None, :3])
    clip = world_to_clip(corners.reshape(-1, 3), camera).reshape(-1, 8, 4)
    if not camera.orthographic:  # w is the depth along the view (1 when orthographic)
        # Eye rays go forward from the eye: a box wholly behind its plane is out of reach.
        clip = clip[(clip[..., 3] > 0.0).any(axis=1)]
        if not (clip[..., 3] > 0.0).all():
            return whole
    if clip.shape[0] == 0:
        return np.zeros(4, dtype=np.intp)
    columns = (clip[..., 0] / clip[..., 3] + 1.0) * camera.width / 2.0
    rows = (1.0 - clip[..., 1] / clip[..., 3]) * camera.height / 2.0
    if not (np.isfinite(columns).all() and np.isfinite(rows).all()):
        return whole
    return np.array([
        np.clip(np.floor(columns.min()) - SCREEN_MARGIN, 0, camera.width),
        np.clip(np.ceil(columns.max()) + SCREEN_MARGIN, 0, camera.width),
        np.clip(np.floor(rows.min()) - SCREEN_MARGIN, 0, camera.height),
        np.clip(np.ceil(rows.max()) + SCREEN_MARGIN, 0, camera.height),
    ], dtype=np.intp)


def _alpha_tested(tables) -> np.ndarray:
    """(O,) bool: the objects whose surface the alpha test may cut (a cutoff above 0)."""
    from pixelpath.scene._texture_kernels import CUTOFF

    return tables.alpha[:, CUTOFF] > 0.0


def _masked(cut: np.ndarray, objects: np.ndarray) -> np.ndarray:
    """(T,) bool: the triangles of alpha-tested objects (``cut``), in the leaf order.

    No rows when no triangle is alpha-tested: the kernels then search without the test.
    """
    masked = cut[objects] if cut.any() else cut[:0]
    return np.ascontiguousarray(masked if masked.any() else masked[:0])


def _primary_rays(camera: Camera) -> np.ndarray:
    """Return the kernels' (18,) camera: eye, direction steps, forward, origin steps.

    A pixel at normalized device coordinates (x, y) gets the ray from eye + x·(origin step
    right) + y·(origin step up) along forward + x·(direction step right) + y·(direction step
    up). A perspective camera's rays all start at the eye and fan out by the field of view; an
    orthographic camera's are parallel and start on the plane through the eye perpendicular to
    the view, spread over the view's width and height.
    """
    u, v, w = camera.basis()
    zero = np.zeros(3)
    if camera.orthographic:
        half_height = camera.view_height / 2.0
        steps = (zero, zero, -w, u * half_height * camera.aspect, v * half_height)
    else:
        tan_y = np.tan(np.radians(camera.fov) / 2.0)
        steps = (u * tan_y * camera.aspect, v * tan_y, -w, zero, zero)
    return np.concatenate([np.asarray(camera.eye, dtype=np.float64), *steps])


def _pixel_cone(camera: Camera) -> np.ndarray:
    """(2,) a pixel's footprint across its ray: width at the eye, growth per unit of distance.

    A perspective pixel spans the angle ``2 tan(fov / 2) / height``, so its footprint grows
    with distance; an orthographic one is ``view_height / height`` wide everywhere. Textures
    are filtered for this footprint (secondary rays take the hit's distance from the eye).
    """
    if camera.orthographic:
        return np.array([camera.view_height / camera.height, 0.0])
    return np.array([0.0, 2.0 * np.tan(np.radians(camera.fov) / 2.0) / camera.height])


def spread(count: int) -> np.ndarray:
    """Return 0..count-1 in bit-reversed order: every run of it samples the whole range.

    The tracer hands its blocks of rows to the threads in this order, so the blocks finished
    by any progress step come from all over the image and each step is a fair share of the work.

    Examples
    --------
    >>> from pixelpath.raytrace.tracer import spread
    >>> spread(8).tolist()
    [0, 4, 2, 6, 1, 5, 3, 7]
    """
    bits = max(int(count - 1).bit_length(), 1)
    keys = np.zeros(count, dtype=np.int64)
    index = np.arange(count, dtype=np.int64)
    for bit in range(bits):
        keys |= ((index >> bit) & 1) << (bits - 1 - bit)
    return np.argsort(keys, kind="stable").astype(np.intp)


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Ray-trace ``view`` of ``scene``.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera (already scaled for ssaa) and the region of its image to render.
    options : RenderOptions
        Shading ("phong" or "flat"), culling of back faces for primary rays, Blinn-Phong,
        Fresnel, ``max_depth``, ``samples``, progress (``STEPS`` steps), explain.

    Returns
    -------
    Frame
        Colours, depth along the viewing axis, object ids, the ray counts as ``stats`` and,
        with ``explain``, a :class:`~pixelpath.report.Report`.

    Examples
    --------
    >>> from pixelpath.scene import Camera, Plane, PointLight, Scene, Sphere
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.raytrace.tracer import render_frame
    >>> scene = Scene(Camera(eye=(0, 1, 5), target=(0, 0, 0), width=32, height=24),
    ...               [Sphere((0, 0, 0), 1), Plane((0, -1, 0), (0, 1, 0))],
    ...               lights=[PointLight((0, 5, 0))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> int(frame.object_id[12, 16]), frame.stats["primary rays"], frame.stats["shadow rays"] > 0
    (0, 768, True)
    """
    from pixelpath._threads import in_runs
    from pixelpath.raster import _pool
    from pixelpath.raytrace import _whitted_kernels as wk
    from pixelpath.raytrace._hit_kernels import slab_nan_allowed
    from pixelpath.raytrace._records import COUNTS

    world, settings, bvh_depth, triangles = pack(scene, view.camera, options)
    options.progress(1)
    shape = (view.height, view.width)
    rgb = _pool.empty((*shape, 3), np.float32)
    depth = _pool.empty(shape, np.float32)
    object_id = _pool.empty(shape, np.int32)
    normal = _pool.empty((*shape, 3), np.float32)
    counts = np.zeros((view.height, COUNTS), dtype=np.int64)
    # Blocks of neighbouring rows go to the threads as they free up: the next row's rays meet
    # the boxes and triangles this row's brought into the cache (rows taken from all over the
    # image one by one took 15-20 % longer on the bunny). The blocks themselves are taken from
    # all over the image (spread), so each run of them, and each progress step, holds busy and
    # empty rows alike. No wait between progress steps: each is reported when its share of the
    # runs has finished.
    blocks = np.array_split(np.arange(view.height, dtype=np.intp),
                            -(-view.height // ROWS_PER_BLOCK))
    rows = np.concatenate([blocks[k] for k in spread(len(blocks))])

    def trace(run: np.ndarray) -> None:
        work, out = _thread_work(world, settings, bvh_depth, view.width)
        with slab_nan_allowed():
            wk.render_rows(run, world, settings, work, out, view.x0, view.y0, rgb, depth,
                           object_id, normal, counts)

    runs = min(len(rows), TRACE_SLICES * RUNS_PER_STEP)
    finished = 0

    def report() -> None:
        nonlocal finished
        finished += 1
        steps = finished * TRACE_SLICES // runs - (finished - 1) * TRACE_SLICES // runs
        if steps:
            options.progress(steps)

    in_runs(trace, rows, runs=runs, done=report)
    stats = _stats(world, counts.sum(axis=0))
    report = _report(stats, triangles, settings) if options.explain else None
    return Frame(rgb, depth, object_id, stats, report, normal)


def _stats(world, totals: np.ndarray) -> dict[str, int]:
    from pixelpath.raytrace import _records as rec

    return {
        "spheres": len(world.spheres),
        "planes": len(world.planes),
        "triangles": len(world.tris),
        "BVH nodes": len(world.links),
        "primary rays": int(totals[rec.COUNT_PRIMARY]),
        "shadow rays": int(totals[rec.COUNT_SHADOW]),
        "reflected rays": int(totals[rec.COUNT_REFLECTED]),
        "refracted rays": int(totals[rec.COUNT_REFRACTED]),
        "rays that hit nothing": int(totals[rec.COUNT_MISSED]),
        "total internal reflections": int(totals[rec.COUNT_TOTAL_REFLECTION]),
        "BVH nodes visited": int(totals[rec.COUNT_NODES]),
        "triangle tests": int(totals[rec.COUNT_TESTS]),
    }


def _report(stats: dict[str, int], triangles: SceneTriangles, settings) -> Any:
    from pixelpath.report import Report, Table

    tree = triangles.bvh.statistics()
    traced = stats["primary rays"] + stats["shadow rays"] + stats["reflected rays"]
    traced += stats["refracted rays"]
    summary = {
        **stats,
        "rays traced": traced,
        "BVH nodes visited per ray": stats["BVH nodes visited"] / max(traced, 1),
        "triangle tests per ray": stats["triangle tests"] / max(traced, 1),
        "epsilon (offset of secondary rays)": settings.epsilon,
    }
    bvh = Table(
        "bounding-volume hierarchy (binned SAH)",
        ("triangles", "nodes", "leaves", "depth", "triangles per leaf", "SAH cost", "build ms"),
        [(tree["triangles"], tree["nodes"], tree["leaves"], tree["depth"],
          tree["triangles per leaf"], tree["SAH cost"], 1000.0 * tree["build seconds"])],
    )
    return Report(
        method="raytrace",
        summary=summary,
        tables=(bvh,),
        notes=(
            "object space: each ray is tested against the spheres and planes and, through the "
            "BVH, the triangles; the nearest hit is shaded with a shadow ray per light",
            f"max_depth {settings.max_depth}, {settings.samples} sample(s) per pixel; rays "
            "weighing less than 1/4096 are not traced",
        ),
    )


_SCRATCH = threading.local()  # each thread's work space, kept from run to run and render to render


def _thread_work(world, settings, bvh_depth: int, width: int) -> tuple:
    """Return the calling thread's (work, out) for ``render_rows`` on rows ``width`` wide.

    Made once per thread (:func:`pixelpath.raytrace._records.new_work` and a row of traced
    pixels), as :func:`pixelpath.hsr.pipeline.band_buffers` keeps a thread's band buffers, and
    made again only when a render needs other sizes: the scene's lights, the samples per pixel,
    the ray depth, the tree's depth or the row's width.
    """
    from pixelpath.raytrace import _whitted_kernels as wk
    from pixelpath.raytrace._records import new_work

    sizes = (world.lights.shape[0], settings.samples, settings.max_depth, bvh_depth, width)
    if getattr(_SCRATCH, "sizes", None) != sizes:
        _SCRATCH.work = new_work(world, settings, bvh_depth, 0, width)
        _SCRATCH.out = np.empty((width, wk.PIXEL_FIELDS))
        _SCRATCH.sizes = sizes
    return _SCRATCH.work, _SCRATCH.out


def warmup_scene():
    """Return a one-pixel scene of a glass sphere, a plane and two lights, packed for the kernels.

    It has no triangles, so the packing builds no tree: the arrays have the types a scene of
    meshes gives them, and no kernel of the BVH's group is compiled to make them.
    """
    from pixelpath.scene import DirectionalLight, Material, PointLight

    glass = Material(reflectivity=0.1, transparency=0.8, ior=1.5)
    objects = [Sphere((0, 0, 0), 1, glass), Plane((0, -1, 0), (0, 1, 0))]
    scene = Scene(
        Camera(eye=(0, 1, 5), target=(0, 0, 0), width=1, height=1),
        objects,
        lights=[PointLight((0, 5, 0)), DirectionalLight((0, -1, 0))],
    )
    world, settings, depth, _ = pack(scene, scene.camera, RenderOptions())
    return world, settings, depth
