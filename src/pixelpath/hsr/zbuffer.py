"""The depth-buffer (z-buffer) method, an image-space method (SPEC §9 errata).

For every pixel keep the nearest surface seen so far: a new sample replaces the stored one when
it is nearer (the notes' "Z_new < Z_buffer → update"). Here the buffer holds 1/w, w being the
distance along the viewing axis, because 1/w is affine in screen space (exactly interpolated)
and larger means nearer; ``Image.depth`` reports w itself. Ties keep the earlier triangle, so
the picture does not depend on the order of threads.

The pipeline (:mod:`pixelpath.raster`):

1. tessellate the scene (spheres, planes) and cull back faces in object space
   (:mod:`pixelpath.hsr.backface`);
2. light the vertices (Gouraud) or the polygons (flat);
3. transform to clip space, drop triangles outside the frustum and clip those crossing the
   near or far plane (or far outside the sides) with Sutherland-Hodgman in homogeneous
   coordinates;
4. divide, map to the viewport and scan-convert with the depth test, storing only the nearest
   triangle per pixel;
5. shade each visible pixel once (deferred), from perspective-correct interpolation.
"""

from __future__ import annotations

import dataclasses
import itertools
import threading
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from pixelpath.scene import Camera, Scene

__all__ = ["STEPS", "Frame", "zbuffer"]

RENDER_SLICES = 8  # progress steps of the rasterize-and-shade pass
SLICED_PIXELS = 1 << 22  # frames this large report that pass slice by slice
STEPS = 3 + RENDER_SLICES  # progress steps per frame

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


@dataclasses.dataclass(frozen=True)
class Frame:
    """The buffers of one rendered frame.

    Attributes
    ----------
    rgb : (H, W, 3) float32
        Clamped intensities; the background where nothing was drawn.
    depth : (H, W) float32
        Distance along the viewing axis; ``inf`` where nothing was drawn.
    object_id : (H, W) int32
        Index of the scene object seen at each pixel; -1 for the background.
    stats : dict of str to int
        How many triangles each pipeline stage took in and let through (see ``STAT_NAMES``).
    """

    rgb: np.ndarray
    depth: np.ndarray
    object_id: np.ndarray
    stats: dict[str, int] = dataclasses.field(default_factory=dict)


def zbuffer(
    scene: Scene,
    camera: Camera | None = None,
    *,
    shading: str = "phong",
    backface_cull: bool = True,
    blinn: bool = False,
    progress: Callable[[int], None] | None = None,
) -> Frame:
    """Render ``scene`` with the z-buffer method.

    Parameters
    ----------
    scene : Scene
        What to draw.
    camera : Camera, optional
        Overrides ``scene.camera`` (for example with a larger size for supersampling).
    shading : {"flat", "gouraud", "phong"}
        Where the illumination model is evaluated (:mod:`pixelpath.raster.shading`).
    backface_cull : bool
        Drop faces turned away from the eye (object-space test). When off, both sides of every
        face are drawn and lit with normals turned towards the viewer.
    blinn : bool
        Blinn-Phong highlights instead of Phong's.
    progress : callable, optional
        Called with a number of steps done as work advances (``STEPS`` in all).

    Returns
    -------
    Frame

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.hsr.zbuffer import zbuffer
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = zbuffer(scene)
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    from pixelpath.hsr.backface import front_facing
    from pixelpath.lighting import pack_lights
    from pixelpath.raster._arrays import kernel_array
    from pixelpath.raster.shading import shading_mode
    from pixelpath.raster.tessellate import scene_geometry

    camera = camera or scene.camera
    mode = shading_mode(shading)
    advance = progress or (lambda n: None)
    lighting = _Lighting(
        pack_lights(scene.lights), kernel_array(scene.ambient), kernel_array(camera.eye), blinn
    )

    # 1. Geometry and object-space back-face culling.
    geometry = scene_geometry(scene, camera)
    front = front_facing(geometry.polygon_normals, geometry.polygon_points, lighting.eye)
    keep = front[geometry.triangle_polygon]
    if not backface_cull:
        keep = np.ones_like(keep)
    advance(1)

    # 2-3. Lighting at vertices (Gouraud) or polygons (flat), clip space, frustum clipping.
    drawable, counts = _clip_to_view(geometry, camera, keep, front, mode, lighting)
    advance(1)

    # 4. Viewport and triangle set-up.
    setup, rows, offsets, items = _set_up(drawable, camera)
    advance(1)

    # 5. Scan conversion with the depth test, then deferred shading, band by band.
    frame = _render(drawable, setup, rows, offsets, items, camera, scene, geometry, mode,
                    lighting, advance)
    return dataclasses.replace(frame, stats=dict(zip(STAT_NAMES, counts, strict=True)))


class _Lighting(NamedTuple):
    """What the illumination model needs besides the surface: packed lights, Ia, eye, model."""

    lights: np.ndarray
    ambient: np.ndarray
    eye: np.ndarray
    blinn: bool


class _Drawable(NamedTuple):
    """The triangles left after culling and clipping, with their per-vertex data."""

    clip: np.ndarray  # (V, 4) clip coordinates
    positions: np.ndarray  # (V, 3) world positions
    normals: np.ndarray  # (V, 3) unit normals
    colors: np.ndarray  # (V, 6) Gouraud intensities, front then back; (0, 6) otherwise
    triangles: np.ndarray  # (T, 3) vertex indices
    info: np.ndarray  # (T, 2) object index, flip flag (seen from behind)
    flat_colors: np.ndarray  # (T, 3) flat-shading intensity; (T, 3) zeros otherwise


def _clip_to_view(geometry, camera, keep, front, mode, lighting) -> tuple[_Drawable, tuple]:
    """Light what needs lighting before clipping, then clip to the frustum; count each stage."""
    from pixelpath.raster import _kernels
    from pixelpath.raster.frustum import classify, clip_crossing
    from pixelpath.raster.transform import world_to_clip

    clip = world_to_clip(geometry.vertices, camera)
    columns = (clip, geometry.vertices, geometry.normals)
    if mode == _kernels.GOURAUD:
        back_drawn = bool(np.any(keep & ~front[geometry.triangle_polygon]))
        columns += (_vertex_colors(geometry, lighting, two_sided=back_drawn),)
    inside, crossing = classify(clip, geometry.triangles, keep)
    new_columns, new_triangles, new_source = clip_crossing(columns, geometry.triangles, crossing)
    if len(new_triangles):
        columns = tuple(np.concatenate(pair) for pair in zip(columns, new_columns, strict=True))
    triangles = np.concatenate([geometry.triangles[inside], new_triangles])
    polygon = geometry.triangle_polygon[np.concatenate([inside, new_source])]
    info = np.empty((len(polygon), 2), dtype=np.intp)
    info[:, 0] = geometry.polygon_object[polygon]
    info[:, 1] = ~front[polygon]
    drawable = _Drawable(
        *columns[:3],
        colors=columns[3] if len(columns) > 3 else np.empty((0, 6)),
        triangles=triangles,
        info=info,
        flat_colors=_flat_colors(geometry, polygon, ~front, mode, lighting),
    )
    culled = len(keep) - int(np.count_nonzero(keep))
    outside = len(keep) - culled - len(inside) - len(crossing)
    counts = (len(keep), culled, outside, len(inside), len(crossing), len(new_triangles),
              len(triangles))
    return drawable, counts


def _set_up(drawable: _Drawable, camera: Camera):
    """Divide, map to the viewport, set the triangles up and list them per band of rows."""
    from pixelpath.raster import _kernels

    screen = np.empty((len(drawable.clip), 3))
    _kernels.clip_to_screen(drawable.clip, camera.width, camera.height, screen)
    setup = np.empty((len(drawable.triangles), _kernels.SETUP_FIELDS))
    rows = np.empty((len(drawable.triangles), 2), dtype=np.intp)
    _kernels.setup_triangles(screen, drawable.triangles, camera.height, setup, rows)
    n_bands = -(-camera.height // _kernels.BAND_ROWS)
    offsets, items = _kernels.bin_triangles(rows, n_bands, _kernels.BAND_ROWS)
    return setup, rows, offsets, items


def _render(drawable, setup, rows, offsets, items, camera, scene, geometry, mode, lighting,
            advance) -> Frame:
    """Rasterize and shade every band into new output buffers (large frames in slices)."""
    from pixelpath.raster import _kernels, _pool
    from pixelpath.raster._arrays import kernel_array

    height, width = camera.height, camera.width
    inv_depth, triangle_id = _scratch_buffers(height, width)
    rgb = _pool.empty((height, width, 3), np.float32)
    depth = _pool.empty((height, width), np.float32)
    object_id = _pool.empty((height, width), np.int32)
    background = kernel_array(scene.background)
    n_bands = len(offsets) - 1
    # Threads take contiguous runs of this list: even bands then odd ones spreads the work.
    interleaved = np.concatenate([np.arange(0, n_bands, 2), np.arange(1, n_bands, 2)])
    slices = RENDER_SLICES if height * width >= SLICED_PIXELS else 1  # so a progress bar moves
    bounds = np.linspace(0, n_bands, slices + 1).astype(int).tolist()
    for start, stop in itertools.pairwise(bounds):
        _kernels.render_bands(
            interleaved[start:stop], setup, rows, offsets, items, _kernels.BAND_ROWS, inv_depth,
            triangle_id, drawable.triangles, drawable.positions, drawable.normals,
            drawable.colors, drawable.info, drawable.flat_colors, geometry.materials,
            lighting.lights, lighting.ambient, lighting.eye, mode, bool(lighting.blinn),
            background, rgb, depth, object_id,
        )
        advance(RENDER_SLICES // slices)
    return Frame(rgb=rgb, depth=depth, object_id=object_id)


_SCRATCH = threading.local()


def _scratch_buffers(height: int, width: int) -> tuple[np.ndarray, np.ndarray]:
    """Return the calling thread's 1/w and triangle buffers of this size, kept between frames.

    The rasterizer clears them itself; reusing them spares allocating and page-faulting
    12 bytes per pixel each frame. One pair per thread keeps concurrent renders apart; frames
    over ``SLICED_PIXELS`` get fresh buffers, so a huge render leaves no memory held.
    """
    buffers = getattr(_SCRATCH, "buffers", None)
    if buffers is None or buffers[0].shape != (height, width):
        buffers = (np.empty((height, width)), np.empty((height, width), dtype=np.int32))
        _SCRATCH.buffers = buffers if height * width <= SLICED_PIXELS else None
    return buffers


def _vertex_colors(geometry, lighting: _Lighting, two_sided: bool) -> np.ndarray:
    """(V, 6) Gouraud intensities at the vertices, lit from the front, then from the back.

    The back half is only computed when a face seen from behind is drawn (culling off).
    """
    from pixelpath.raster.shading import shade_points

    colors = np.zeros((len(geometry.vertices), 6))
    for start, flipped in ((0, False), (3, True))[: 2 if two_sided else 1]:
        colors[:, start : start + 3] = shade_points(
            geometry.vertices, geometry.normals, np.full(len(geometry.vertices), flipped),
            geometry.vertex_object, geometry.materials, lighting.lights, lighting.ambient,
            lighting.eye, blinn=lighting.blinn,
        )
    return colors


def _flat_colors(geometry, polygon, back, mode, lighting: _Lighting) -> np.ndarray:
    """(T, 3) intensity of each drawn triangle's polygon at its centroid (flat shading only)."""
    from pixelpath.raster import _kernels
    from pixelpath.raster.shading import shade_points

    if mode != _kernels.FLAT or len(polygon) == 0:
        return np.zeros((len(polygon), 3))
    used, inverse = np.unique(polygon, return_inverse=True)
    colors = shade_points(
        geometry.polygon_centroids[used], geometry.polygon_normals[used], back[used],
        geometry.polygon_object[used], geometry.materials, lighting.lights, lighting.ambient,
        lighting.eye, blinn=lighting.blinn,
    )
    return colors[inverse]
