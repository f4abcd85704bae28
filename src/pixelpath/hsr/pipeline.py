"""The stages every raster hidden-surface method shares: one front end, one shading pass.

The methods differ only in how they decide *which surface each pixel shows*; everything before
and after that is here, once, so the same scene gives the same colours whichever method drew
it::

    scene ──prepare()──> screen triangles ──method──> visibility ──shade()──> Frame
                         (culled, clipped,            (1/w and triangle
                          set up for scanning)          per pixel)

:func:`prepare` (the front end) tessellates the scene, culls back faces in object space
(:mod:`pixelpath.hsr.backface`), lights the vertices (Gouraud) or polygons (flat), transforms to
clip space, clips against the view frustum in homogeneous coordinates, divides, maps to the
viewport and sets each triangle up for scan conversion (edge table, planes of 1/w and of the
screen weights). Each drawable triangle remembers the triangle of the scene geometry it came
from (``Prepared.source``), which is how object-space orders (painter's, BSP, octree) find
their triangles again after clipping.

A method fills a :class:`Visibility`: per pixel of the region, 1/w of the visible surface
(0 where none; w is the distance along the viewing axis, and 1/w is affine in screen space) and
the index of its triangle (-1 where none). :func:`shade` (the back end) then evaluates the
illumination once per visible pixel, in the chosen shading mode (:mod:`pixelpath.raster.shading`).
:func:`paint` is the drawing step of the methods that produce a back-to-front order (painter's
and BSP): each triangle over the ones before it, with no depth test.

Alpha-tested materials (``Material.alpha_cutoff``) are honoured where visibility is decided:
each method asks about the samples of the triangles :func:`cutouts` marks, and one whose
surface is cut away there hides nothing, so the visibility buffers already hold what shows
through the holes and the shading pass has nothing to add.
"""

from __future__ import annotations

import dataclasses
import itertools
import threading
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from pixelpath._memory import fresh
from pixelpath._threads import in_runs
from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.scene import Scene

__all__ = [
    "FRONT_STEPS",
    "STAT_NAMES",
    "Lighting",
    "Prepared",
    "Visibility",
    "cutouts",
    "paint",
    "prepare",
    "shade",
]

FRONT_STEPS = 3  # progress steps of prepare()
SHADE_SLICES = 8  # progress steps of shade() (and of the z-buffer's fused pass)
SLICED_PIXELS = 1 << 22  # regions this large report the shading pass slice by slice

# Frame.stats keys, in pipeline order.
STAT_NAMES = (
    "triangles",  # after tessellation
    "back faces culled",
    "outside the frustum",
    "inside the frustum",  # drawn as they are
    "clipped",  # crossing the near or far plane, or far outside the sides
    "pieces after clipping",
    "triangles scan-converted",
)


class Lighting(NamedTuple):
    """What the illumination model needs besides the surface: lights, Ia, viewpoint, model.

    ``eye`` is the camera's homogeneous viewpoint (4,) (see ``Camera.viewpoint``).
    """

    lights: np.ndarray
    ambient: np.ndarray
    eye: np.ndarray
    blinn: bool


class Visibility(NamedTuple):
    """What a method decided: the visible surface at each pixel of the region."""

    inv_depth: np.ndarray  # (h, w) float64 1/w of the visible surface, 0 where none
    triangle_id: np.ndarray  # (h, w) int32 drawable triangle seen there, -1 where none


@dataclasses.dataclass(frozen=True)
class Prepared:
    """The front end's output: the triangles to draw, in screen space, with their attributes.

    Attributes
    ----------
    geometry : SceneGeometry
        The tessellated scene the triangles come from.
    clip : (V, 4) float64
        Clip coordinates of the drawable vertices.
    positions, normals : (V, 3) float64
        World positions and unit normals of the drawable vertices.
    uv, vertex_colors : (V, 2), (V, 4) float64
        Texture coordinates and vertex colours of the drawable vertices (no rows when no
        object has them; see :class:`~pixelpath.raster.tessellate.SceneGeometry`).
    colors : (V, 6) or (V, 12) float64
        Gouraud light at the vertices from the front, then from the back (see
        :func:`_vertex_colors`); (0, 6) in other modes.
    screen : (V, 3) float64
        (x, y) in pixels (row 0 at the top, pixel centres at half-integers) and 1/w.
    triangles : (T, 3) intp
        Vertex indices of the drawable triangles.
    source : (T,) intp
        Triangle of ``geometry`` each drawable triangle comes from (itself, or a piece of it
        after frustum clipping).
    info : (T, 2) intp
        Object index and flip flag (1 when the face is seen from behind) of each triangle.
    flat_colors : (T, 3) or (T, 6) float64
        Flat-shading light of each triangle's polygon (zeros in the other modes).
    face_normals : (T, 3) float64
        Unit normal of each triangle's polygon, turned towards the viewer.
    setup : (T, SETUP_FIELDS) float64
        Scan-conversion records (:mod:`pixelpath.raster._setup_kernels`).
    rows : (T, 2) intp
        Image rows [first, stop) each triangle covers inside the region.
    lighting : Lighting
    mode : int
        Shading mode code (:func:`pixelpath.raster.shading.shading_mode`).
    stats : dict of str to int
        How many triangles each front-end stage took in and let through.
    """

    geometry: object
    clip: np.ndarray
    positions: np.ndarray
    normals: np.ndarray
    uv: np.ndarray
    vertex_colors: np.ndarray
    colors: np.ndarray
    screen: np.ndarray
    triangles: np.ndarray
    source: np.ndarray
    info: np.ndarray
    flat_colors: np.ndarray
    face_normals: np.ndarray
    setup: np.ndarray
    rows: np.ndarray
    lighting: Lighting
    mode: int
    stats: dict[str, int]


def prepare(
    scene: Scene, view: View, options: RenderOptions, geometry=None, blends=None
) -> Prepared:
    """Run the front end: cull, light, clip, divide, map to the viewport, set up.

    Parameters
    ----------
    scene : Scene
        Lights, ambient light and, unless ``geometry`` is given, the objects.
    view : View
        Camera and region.
    options : RenderOptions
        Shading mode, culling, Blinn-Phong; ``options.progress`` advances ``FRONT_STEPS``.
    geometry : SceneGeometry, optional
        Geometry to draw instead of the scene's own tessellation (the BSP method passes its
        fragments); its polygon arrays must be the scene's.
    blends : (rows, corners, weights), optional
        Vertices of ``geometry`` made by cutting its triangles (the BSP method's splits):
        ``rows`` (N,) their indices, ``corners`` (N, 3) the vertices of the triangle each was
        cut from and ``weights`` (N, 3) its barycentric weights there. Gouraud shading blends
        their colours from those corners, as clipping does for the vertices it makes, so the
        pieces of a triangle shade exactly like the whole.

    Returns
    -------
    Prepared

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.pipeline import prepare
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> prepared = prepare(scene, View.whole(scene.camera), RenderOptions())
    >>> len(prepared.triangles), prepared.stats["back faces culled"]
    (6, 6)
    """
    from pixelpath.hsr.backface import front_facing
    from pixelpath.lighting import pack_lights
    from pixelpath.raster._arrays import kernel_array
    from pixelpath.raster.shading import shading_mode
    from pixelpath.raster.tessellate import scene_geometry

    camera = view.camera
    mode = shading_mode(options.shading)
    advance = options.progress
    viewpoint = kernel_array(camera.viewpoint())  # the eye, or the view's direction (w = 0)
    lighting = Lighting(
        pack_lights(scene.lights), kernel_array(scene.ambient), viewpoint, options.blinn
    )
    geometry = geometry if geometry is not None else scene_geometry(scene, camera)
    front = front_facing(geometry.polygon_normals, geometry.polygon_points, viewpoint)
    # Double-sided materials keep their back faces (drawn lit from behind, as with no culling).
    keep = (front | geometry.double_sided[geometry.polygon_object])[geometry.triangle_polygon]
    if not options.backface_cull:
        keep = np.ones_like(keep)
    advance(1)
    clipped = _clip_to_view(geometry, camera, keep, front, mode, lighting, blends)
    advance(1)
    prepared = _set_up(clipped, view)
    advance(1)
    return prepared


def _clip_to_view(geometry, camera, keep, front, mode, lighting, blends) -> dict:
    """Light what needs lighting before clipping, then clip to the frustum; count each stage."""
    from pixelpath.raster import _kernels
    from pixelpath.raster.frustum import classify, clip_crossing
    from pixelpath.raster.transform import world_to_clip

    clip = world_to_clip(geometry.vertices, camera)
    # Frustum clipping interpolates every per-vertex column at the vertices it makes; the
    # optional ones (no rows when unused) are left out of it and stay empty.
    named = {"clip": clip, "positions": geometry.vertices, "normals": geometry.normals,
             "uv": geometry.uv, "vertex_colors": geometry.colors}
    if mode == _kernels.GOURAUD:
        back_drawn = bool(np.any(keep & ~front[geometry.triangle_polygon]))
        named["colors"] = _vertex_colors(geometry, lighting, back_drawn, blends)
    else:
        named["colors"] = np.empty((0, 6))
    required = ("clip", "positions", "normals")
    names = [name for name, column in named.items() if name in required or len(column)]
    columns = tuple(named[name] for name in names)
    inside, crossing = classify(clip, geometry.triangles, keep)
    new_columns, new_triangles, new_source = clip_crossing(columns, geometry.triangles, crossing)
    if len(new_triangles):
        columns = tuple(np.concatenate(pair) for pair in zip(columns, new_columns, strict=True))
    # np.take, not fancy indexing: the same rows, several times quicker on (n, 3) arrays.
    triangles = np.concatenate([np.take(geometry.triangles, inside, axis=0), new_triangles])
    source = np.concatenate([inside, new_source])
    polygon = geometry.triangle_polygon[source]
    back = ~front[polygon]
    info = np.empty((len(polygon), 2), dtype=np.intp)
    info[:, 0] = geometry.polygon_object[polygon]
    info[:, 1] = back
    face_normals = np.take(geometry.polygon_normals, polygon, axis=0)
    if back.any():  # culling leaves none: the multiplication's 0.2 ms for the bunny spared
        face_normals[back] *= -1.0  # turned to the viewer
    named.update(zip(names, columns, strict=True))
    culled = len(keep) - int(np.count_nonzero(keep))
    outside = len(keep) - culled - len(inside) - len(crossing)
    counts = (len(keep), culled, outside, len(inside), len(crossing), len(new_triangles),
              len(triangles))
    return {
        "geometry": geometry,
        **named,
        "triangles": triangles,
        "source": source,
        "info": info,
        "flat_colors": _flat_colors(geometry, polygon, ~front, mode, lighting),
        "face_normals": face_normals,
        "lighting": lighting,
        "mode": mode,
        "stats": dict(zip(STAT_NAMES, counts, strict=True)),
    }


def _set_up(clipped: dict, view: View) -> Prepared:
    """Divide, map to the viewport and set the triangles up for the region's rows."""
    from pixelpath.raster import _setup_kernels

    camera = view.camera
    screen = np.empty((len(clipped["clip"]), 3))
    _setup_kernels.clip_to_screen(clipped["clip"], camera.width, camera.height, camera.orthographic,
                                  screen)
    triangles = clipped["triangles"]
    setup = np.empty((len(triangles), _setup_kernels.SETUP_FIELDS))
    rows = np.empty((len(triangles), 2), dtype=np.intp)
    _setup_kernels.setup_triangles(screen, triangles, camera.orthographic, view.y0,
                                   view.y0 + view.height, setup, rows)
    return Prepared(screen=screen, setup=setup, rows=rows, **clipped)


def bands(view: View) -> tuple[int, np.ndarray]:
    """Return the number of bands of rows in the region and their interleaved order.

    Parallel kernels hand threads contiguous runs of the list: even bands, then odd ones,
    gives each thread rows from all over the image, so the work is even.
    """
    from pixelpath.raster import _scan_kernels

    count = -(-view.height // _scan_kernels.BAND_ROWS)
    return count, np.concatenate([np.arange(0, count, 2), np.arange(1, count, 2)])


def binned(prepared: Prepared, view: View, order: np.ndarray | None = None):
    """Bin triangles (or the positions of ``order``) by band: CSR offsets and items."""
    from pixelpath.raster import _scan_kernels

    count, _ = bands(view)
    rows = prepared.rows if order is None else prepared.rows[order]
    return _scan_kernels.bin_triangles(rows, count, _scan_kernels.BAND_ROWS, view.y0)


def paint(prepared: Prepared, view: View, order: np.ndarray) -> Visibility:
    """Draw the triangles listed in ``order`` over each other, first to last (no depth test).

    This is the drawing step of the painter's and BSP methods: given a back-to-front order,
    the pixel shows the last triangle drawn over it.
    """
    from pixelpath.raster import _scan_kernels

    visibility = visibility_buffers(view)
    order = np.ascontiguousarray(order, dtype=np.intp)
    offsets, items = binned(prepared, view, order)
    _, band_list = bands(view)
    alpha = cutouts(prepared)
    in_runs(
        lambda run: _scan_kernels.paint_bands(
            run, prepared.setup, prepared.rows, offsets, items, order, _scan_kernels.BAND_ROWS,
            view.x0, view.y0, *visibility, alpha,
        ),
        band_list,
    )
    return visibility


def cutouts(prepared: Prepared):
    """Return what the alpha test reads, as the raster kernels' ``Cutouts`` record.

    Its ``masked`` flags the drawable triangles whose object is alpha-tested (a material
    with an ``alpha_cutoff`` its alpha can fall below, see
    :func:`pixelpath.scene.texture.surface_tables`); every method tests the samples of those
    triangles, and only those, before letting them hide anything.

    Examples
    --------
    >>> import numpy as np
    >>> import pixelpath as pp
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.pipeline import cutouts, prepare
    >>> texture = np.ones((2, 2, 4))
    >>> texture[0, 0, 3] = 0.0  # one transparent texel
    >>> square = pp.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2, 3]],
    ...                  pp.Material(texture=texture, alpha_cutoff=0.5),
    ...                  uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 3), target=(0, 0, 0), width=16, height=16),
    ...                  [square, pp.Box((-2, -2, -1), (2, 2, -0.5))])
    >>> prepared = prepare(scene, View.whole(scene.camera), RenderOptions())
    >>> masked = cutouts(prepared).masked
    >>> bool(masked[prepared.info[:, 0] == 0].all()), bool(masked[prepared.info[:, 0] == 1].any())
    (True, False)
    """
    from pixelpath.raster import _scan_kernels
    from pixelpath.scene._texture_kernels import CUTOFF

    tables = prepared.geometry.surfaces
    if np.any(tables.alpha[:, CUTOFF] > 0.0):
        masked = np.ascontiguousarray(tables.alpha[prepared.info[:, 0], CUTOFF] > 0.0)
    else:  # the common case: nothing to gather per triangle
        masked = np.zeros(len(prepared.info), dtype=np.bool_)
    return _scan_kernels.Cutouts(masked, prepared.setup, prepared.triangles, prepared.info,
                                 prepared.uv, prepared.vertex_colors, tables)


_SCRATCH = threading.local()


def visibility_buffers(view: View) -> Visibility:
    """Return the calling thread's 1/w and triangle buffers of the region's size.

    The methods clear them themselves; reusing them spares allocating and page-faulting
    12 bytes per pixel each frame. One pair per thread keeps concurrent renders apart; regions
    over ``SLICED_PIXELS`` get fresh buffers, so a huge render leaves no memory held.
    """
    shape = (view.height, view.width)
    buffers = getattr(_SCRATCH, "buffers", None)
    if buffers is None or buffers.inv_depth.shape != shape:
        kept = view.height * view.width <= SLICED_PIXELS
        # Kept ones on huge pages (a process's first render faulted them in at 4 KiB a fault);
        # one-off ones as NumPy allocates, not new huge pages for every frame.
        allocate = fresh if kept else np.empty
        buffers = Visibility(allocate(shape, np.float64), allocate(shape, np.int32))
        _SCRATCH.buffers = buffers if kept else None
    return buffers


def band_buffers(width: int) -> Visibility:
    """Return the calling thread's 1/w and triangle buffers of one band of rows, ``width`` wide.

    For a method that shades each band as soon as it has decided it (the z-buffer): every
    band reuses them, so they stay in the processor's cache, and a frame does not write its
    12 bytes a pixel of visibility to memory, nor fault them in on a process's first render.
    """
    return _thread_scratch("band", width, _band_visibility)


def _band_visibility(width: int) -> Visibility:
    """Return new, unfilled visibility buffers for one band of rows ``width`` wide."""
    from pixelpath.raster._scan_kernels import BAND_ROWS

    return Visibility(np.empty((BAND_ROWS, width)), np.empty((BAND_ROWS, width), np.int32))


def shading_batch(width: int) -> Any:
    """Return the calling thread's work arrays of the shading pass, for rows ``width`` wide.

    Kept per thread and reused frame after frame, as :func:`band_buffers` are
    (:func:`pixelpath.raster._kernels.new_batch`).
    """
    from pixelpath.raster._kernels import new_batch

    return _thread_scratch("batch", width, new_batch)


def _thread_scratch(name: str, width: int, allocate: Callable[[int], Any]) -> Any:
    """Return the calling thread's scratch ``name`` for rows ``width`` wide, made by ``allocate``.

    Made again only when the width changes.
    """
    kept = getattr(_SCRATCH, name, None)
    if kept is None or kept[0] != width:
        kept = (width, allocate(width))
        setattr(_SCRATCH, name, kept)
    return kept[1]


def surfaces(prepared: Prepared, scene: Scene, view: View):
    """Return what the shading kernels read, as their ``Surfaces`` record."""
    from pixelpath.raster import _kernels
    from pixelpath.raster._arrays import kernel_array

    lighting = prepared.lighting
    camera = view.camera
    return _kernels.Surfaces(
        prepared.setup, prepared.triangles, prepared.positions, prepared.normals,
        prepared.colors, prepared.info, prepared.flat_colors, prepared.face_normals,
        prepared.uv, prepared.vertex_colors, prepared.geometry.surfaces,
        prepared.geometry.coloured, prepared.geometry.materials, prepared.geometry.emission,
        lighting.lights, lighting.ambient, lighting.eye, kernel_array(scene.background),
        prepared.mode, bool(lighting.blinn), camera.orthographic, float(camera.near),
        float(camera.far),
    )


def output_buffers(view: View):
    """Return new (recycled) colour, depth and object-id buffers for the region."""
    from pixelpath.raster import _kernels, _pool

    shape = (view.height, view.width)
    return _kernels.Buffers(
        _pool.empty((*shape, 3), np.float32),
        _pool.empty(shape, np.float32),
        _pool.empty(shape, np.int32),
        _pool.empty((*shape, 3), np.float32),
    )


def slices(view: View) -> list[tuple[int, int]]:
    """Split the band list into runs, one progress step each (several only for big regions)."""
    count, _ = bands(view)
    parts = SHADE_SLICES if view.height * view.width >= SLICED_PIXELS else 1
    return list(itertools.pairwise(np.linspace(0, count, parts + 1).astype(int).tolist()))


def shade(
    prepared: Prepared,
    scene: Scene,
    view: View,
    visibility: Visibility,
    options: RenderOptions,
    report=None,
) -> Frame:
    """Run the back end: shade every visible pixel once; ``SHADE_SLICES`` progress steps.

    Returns the frame with the front end's counts as its stats and ``report`` attached.
    """
    from pixelpath.raster import _kernels, _scan_kernels

    out = output_buffers(view)
    kernel_surfaces = surfaces(prepared, scene, view)
    colour_tables = kernel_surfaces.tables if _kernels.looks_up(kernel_surfaces) else None
    _, order = bands(view)
    runs = slices(view)
    def shade_run(run: np.ndarray) -> None:
        _kernels.shade_bands(
            run, _scan_kernels.BAND_ROWS, view.x0, view.y0, *visibility, kernel_surfaces,
            colour_tables, shading_batch(view.width), out,
        )

    for start, stop in runs:
        in_runs(shade_run, order[start:stop])
        options.progress(SHADE_SLICES // len(runs))
    if report is not None:
        report = with_texture_lookups(report, prepared, scene, view, visibility)
    return Frame(out.rgb, out.depth, out.object_id, prepared.stats, report, out.normal)


def with_texture_lookups(report, prepared: Prepared, scene: Scene, view: View,
                         visibility: Visibility):
    """Return a method's explain report with the texture lookups of its picture added.

    Nothing is added when no drawn object is textured. Otherwise, per textured pixel, the
    footprint of the shading pass chooses the mip level (:func:`pixelpath.scene.
    _texture_kernels.mip_level`) and the summary counts the textured pixels and the texels
    read: 1 per ``nearest`` lookup, 4 per ``bilinear`` one, 4 or 8 per ``trilinear`` one (one
    level or a blend of two). A table lists each texture's filter and wrap, another the pixels
    per mip level (a blended pixel counts at its finer level). ``report.arrays`` gains, per
    pixel of the region, ``"texture"`` (the table's row, -1 for none), ``"texture level"``
    (-1 for none) and ``"texture blend"`` (the next level's weight).

    Examples
    --------
    >>> import numpy as np
    >>> import pixelpath as pp
    >>> floor = pp.Mesh([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], [[3, 2, 1, 0]],
    ...                 pp.Material(texture=np.ones((64, 64, 3))),
    ...                 uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> scene = pp.Scene(pp.Camera(eye=(0, 1, 2), target=(0, 0, 0), width=32, height=24),
    ...                  [floor], [pp.PointLight((0, 3, 3))])
    >>> _, report = pp.render(scene, explain=True)
    >>> report.summary["textured pixels"] > 0, report.tables[-1].title
    (True, 'mip levels')
    """
    import dataclasses

    from pixelpath.raster import _kernels
    from pixelpath.report import Table
    from pixelpath.scene._texture_kernels import NEAREST, TEXTURE, TRILINEAR
    from pixelpath.scene.texture import FILTERS, WRAPS

    tables = prepared.geometry.surfaces
    if not np.any(tables.objects[:, TEXTURE] >= 0):
        return report
    shape = visibility.triangle_id.shape
    texture, level = np.empty(shape, np.int32), np.empty(shape, np.int32)
    blend = np.empty(shape)
    _kernels.texture_lookups(view.x0, view.y0, visibility.triangle_id,
                             surfaces(prepared, scene, view), texture, level, blend)
    textured = texture >= 0
    modes = tables.textures[:, 2]
    texels_each = np.where(modes == NEAREST, 1, 4)[texture[textured]]
    texels_each[(modes[texture[textured]] == TRILINEAR) & (blend[textured] > 0.0)] = 8
    names = _texture_names(prepared.geometry, tables)
    samplers, levels = [], []
    for k, (first, _, mode, wrap) in enumerate(tables.textures.tolist()):
        mine = texture[textured] == k
        samplers.append((names[k], _size(tables, first), FILTERS[mode], WRAPS[wrap],
                         int(mine.sum()), int(texels_each[mine].sum())))
        used = level[textured][mine]
        blended = blend[textured][mine] > 0.0
        for m in np.unique(used).tolist():
            levels.append((names[k], m, _size(tables, first + m), int(np.sum(used == m)),
                           int(np.sum(blended[used == m]))))
    return dataclasses.replace(
        report,
        summary={**report.summary, "textured pixels": int(textured.sum()),
                 "texels read": int(texels_each.sum())},
        tables=(*report.tables,
                Table("textures", ("texture", "size", "filter", "wrap", "pixels", "texels read"),
                      samplers),
                Table("mip levels", ("texture", "level", "size", "pixels", "blended with next"),
                      levels)),
        notes=(*report.notes,
               "textures: a pixel's footprint, how many base texels it spans (from the screen "
               "derivatives of u and v), chooses the mip level: log2(footprint) with trilinear "
               "filtering, blending the two levels around it; the base level otherwise"),
        arrays={**report.arrays, "texture": texture, "texture level": level,
                "texture blend": blend},
    )


def _texture_names(geometry, tables) -> list[str]:
    """Name each texture row of the surface tables after its picture, or its first object."""
    from pixelpath.scene._texture_kernels import TEXTURE

    names = [""] * len(tables.textures)
    for obj in range(len(tables.objects) - 1, -1, -1):  # backwards: the first object wins
        k = tables.objects[obj, TEXTURE]
        if k >= 0:
            mesh = geometry.meshes[obj]
            names[k] = mesh.material.texture.name or mesh.name or f"object {obj}"
    return names


def _size(tables, level: int) -> str:
    """Return "w×h" of a packed mip level."""
    return f"{tables.levels[level, 1]}×{tables.levels[level, 2]}"


def _vertex_colors(geometry, lighting: Lighting, two_sided: bool, blends) -> np.ndarray:
    """Gouraud light at the vertices, lit from the front, then from the back.

    (V, 6) intensities, or (V, 12) when some object has a coloured surface (see
    :func:`_light`). The back half is only computed when a face seen from behind is drawn
    (culling off, or a double-sided material). Cut vertices (``blends``, see :func:`prepare`)
    take the blend of their corners' colours.
    """
    half = _light_width(geometry)
    colors = np.zeros((len(geometry.vertices), 2 * half))
    for start, flipped in ((0, False), (half, True))[: 2 if two_sided else 1]:
        colors[:, start : start + half] = _light(
            geometry, geometry.vertices, geometry.normals, np.full(len(geometry.vertices), flipped),
            geometry.vertex_object, lighting,
        )
    if blends is not None:
        rows, corners, weights = blends
        colors[rows] = np.einsum("nk,nkc->nc", weights, colors[corners])
    return colors


def _flat_colors(geometry, polygon, back, mode, lighting: Lighting) -> np.ndarray:
    """(T, 3|6) light of each drawn triangle's polygon at its centroid (flat shading only)."""
    from pixelpath.raster import _kernels

    if mode != _kernels.FLAT or len(polygon) == 0:
        return np.zeros((len(polygon), 3))
    used, inverse = np.unique(polygon, return_inverse=True)
    light = _light(
        geometry, geometry.polygon_centroids[used], geometry.polygon_normals[used], back[used],
        geometry.polygon_object[used], lighting,
    )
    return light[inverse]


def _light_width(geometry) -> int:
    """Return the width of :func:`_light`'s rows: 6 with coloured surfaces in the scene, else 3."""
    return 6 if np.any(geometry.coloured) else 3


def _light(geometry, points, normals, flip, owner, lighting: Lighting) -> np.ndarray:
    """Return the illumination model at points with unit normals, for flat and Gouraud shading.

    Returns (N, 3) intensities when no object has a coloured surface. Otherwise (N, 6): for a
    point of a plain object, its intensity and three zeros; for a point of a coloured object
    (texture or vertex colours), the light its surface colour multiplies (ambient and diffuse,
    computed with the colour white and no highlight), then the highlight (computed with the
    colour black), so that the colour looked up at each pixel tints the first and not the
    second, as Phong shading does.
    """
    from pixelpath.raster.shading import shade_points

    def shaded(rows, materials):
        return shade_points(
            points[rows], normals[rows], flip[rows], owner[rows], materials, lighting.lights,
            lighting.ambient, lighting.eye, blinn=lighting.blinn,
        )

    if _light_width(geometry) == 3:
        return shaded(slice(None), geometry.materials)
    coloured = geometry.coloured[owner]
    light = np.zeros((len(points), 6))
    light[~coloured, :3] = shaded(~coloured, geometry.materials)
    tinted, highlight = geometry.materials.copy(), geometry.materials.copy()
    tinted[:, :3], tinted[:, 5] = 1.0, 0.0
    highlight[:, :3] = 0.0
    light[coloured, :3] = shaded(coloured, tinted)
    light[coloured, 3:] = shaded(coloured, highlight)
    return light
