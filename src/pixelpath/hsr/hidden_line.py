"""Line drawings: the wireframe (every edge) and the hidden-line drawing (only what is seen).

``style="wireframe"`` is the notes' figure *without hidden-surface elimination*: every edge of
every polygon of the scene's objects (the polygons' own edges, not the diagonals of their fan
triangulation; an edge shared by two polygons of an object is drawn once), clipped to the view
frustum in homogeneous coordinates and drawn one pixel wide by Bresenham's algorithm
(:mod:`pixelpath.raster.lines`), in the object's material colour, unlit, over the background.
Where lines cross, the nearer one is drawn. Back-face elimination is itself a hidden-surface
method (SPEC §9 errata), so the wireframe ignores ``backface_cull``: it shows the edges of the
back faces too.

``style="hidden-line"`` is the figure *with hidden-surface elimination*: the same edges, each
pixel kept only where the edge is not behind the visible surface of the filled render made by
the chosen method (any of them, the ray tracer included: only its per-pixel depth and object id
are read). With ``backface_cull`` (the default) only the edges of polygons facing the eye are
candidates, so a culled face draws no outline of its own; the silhouette, shared by a front and
a back face, stays. The test at a line pixel is

    line depth <= surface depth + tolerance,

with the line's depth interpolated perspective-correctly along it, and a tolerance from the
surface's local depth slope (:func:`surface_limit`): Bresenham puts a line pixel's centre up to
a pixel off the line, so the line is compared with the farthest surface sample over its pixel
and the eight neighbours, plus half the depth range there (a crease's slope). Edges lying on
the visible surface therefore survive, and silhouettes too (a neighbour shows what is behind);
edges behind another surface, or behind the same object's front, disappear. The price is at
most one pixel of a hidden line showing where it passes behind an outline. Planes are
infinite: they have no edges to draw, but they hide edges behind them.

The result is a :class:`~pixelpath.contract.Frame`: colour of the line (or the background),
the line's depth (``inf`` where none) and its object (-1 where none).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.raster.tessellate import _IdentityCache, scene_geometry
from pixelpath.scene import Plane, Scene

__all__ = ["hidden_lines", "polygon_edges", "surface_limit", "surface_view", "wireframe"]

# Tolerance of the hidden-line test (:func:`surface_limit`): a share of the depth range over a
# pixel's neighbourhood (about one pixel of the surface's slope, as the range spans two), and
# a relative margin well above the rounding of the float32 depth buffer.
SLOPE = 0.5
RELATIVE = 1e-5


def polygon_edges(scene: Scene, geometry, polygons: np.ndarray | None = None):
    """Return every polygon edge of the scene's objects once per object, as world segments.

    Parameters
    ----------
    scene : Scene
        Its planes are skipped (an infinite plane has no edges).
    geometry : SceneGeometry
        The scene's tessellation (:func:`pixelpath.raster.tessellate.scene_geometry`).
    polygons : (P,) bool array_like, optional
        Polygons whose edges to take (default all); an edge is kept when one of the polygons
        sharing it is.

    Returns
    -------
    starts, ends : (E, 3) float64 ndarray
        The edges' ends. Vertices at the same position in an object (a box's corners repeated
        per face, for flat normals) are one vertex, so a shared edge appears once.
    owners : (E,) intp ndarray
        The object of each edge.

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> from pixelpath.raster.tessellate import scene_geometry
    >>> from pixelpath.hsr.hidden_line import polygon_edges
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0)), objects=[Box((0, 0, 0), (1, 1, 1))])
    >>> starts, ends, owners = polygon_edges(scene, scene_geometry(scene))
    >>> len(owners)  # a cube has 12 edges (its 6 quads, not their 12 triangles' 18)
    12
    """
    starts, ends, owners = [], [], []
    first_polygon = 0
    for index, (obj, mesh) in enumerate(zip(scene.objects, geometry.meshes, strict=True)):
        count = mesh.face_count
        chosen = None if polygons is None else np.asarray(polygons)[first_polygon:][:count]
        first_polygon += count
        if isinstance(obj, Plane):
            continue
        edges = _EDGES.get(mesh, _MeshEdges.of)
        pairs = edges.pairs if chosen is None else edges.pairs[edges.used_by(chosen)]
        starts.append(edges.points[pairs[:, 0]])
        ends.append(edges.points[pairs[:, 1]])
        owners.append(np.full(len(pairs), index, dtype=np.intp))
    if not owners:
        return np.empty((0, 3)), np.empty((0, 3)), np.empty(0, dtype=np.intp)
    return np.concatenate(starts), np.concatenate(ends), np.concatenate(owners)


@dataclasses.dataclass(frozen=True)
class _MeshEdges:
    """A mesh's distinct polygon edges, and which edge each corner of each polygon starts."""

    points: np.ndarray  # (K, 3) distinct vertex positions
    pairs: np.ndarray  # (E, 2) edges as point indices, lower first, sorted
    corner_edge: np.ndarray  # (C,) edge from each polygon corner to the next; -1 if degenerate
    corner_polygon: np.ndarray  # (C,) polygon of each corner

    @classmethod
    def of(cls, mesh) -> _MeshEdges:
        """Weld the vertices by position, list each polygon's edges, keep each edge once."""
        vertices = mesh.vertices
        order = np.lexsort(vertices.T[::-1])
        ordered = vertices[order]
        starts_group = np.ones(len(vertices), dtype=bool)
        starts_group[1:] = np.any(ordered[1:] != ordered[:-1], axis=1)
        welded = np.empty(len(vertices), dtype=np.intp)
        welded[order] = np.cumsum(starts_group) - 1
        offsets, indices = mesh.face_offsets, mesh.face_indices
        following = np.arange(1, len(indices) + 1)
        following[offsets[1:] - 1] = offsets[:-1]  # a face's last corner joins its first
        a, b = welded[indices], welded[indices[following]]
        low, high = np.minimum(a, b), np.maximum(a, b)
        proper = low != high  # a repeated corner makes no edge
        count = len(ordered)
        keys, edge = np.unique(low[proper] * count + high[proper], return_inverse=True)
        corner_edge = np.full(len(indices), -1, dtype=np.intp)
        corner_edge[proper] = edge.reshape(-1)
        pairs = np.stack([keys // count, keys % count], axis=1)
        corner_polygon = np.repeat(np.arange(mesh.face_count), np.diff(offsets))
        return cls(ordered[starts_group], pairs, corner_edge, corner_polygon)

    def used_by(self, polygons: np.ndarray) -> np.ndarray:
        """(E,) whether each edge belongs to one of the chosen polygons ((P,) bool)."""
        used = np.zeros(len(self.pairs), dtype=bool)
        edges = self.corner_edge[polygons[self.corner_polygon]]
        used[edges[edges >= 0]] = True
        return used


# Edges of the last meshes drawn (meshes are immutable; a scene's are reused frame to frame).
_EDGES = _IdentityCache(64)


def wireframe(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Draw every polygon edge of ``scene`` (no hidden-surface elimination).

    Parameters
    ----------
    scene : Scene
        What to draw; the edges take their object's material colour, unlit.
    view : View
        Camera and region.
    options : RenderOptions
        ``explain`` adds a report of the edges drawn; ``backface_cull`` does not apply.

    Returns
    -------
    Frame

    Examples
    --------
    >>> import pixelpath as pp
    >>> scene = pp.Scene(pp.Camera(eye=(3, 2, 4), target=(0, 0, 0), width=48, height=32),
    ...                  objects=[pp.Box((-1, -1, -1), (1, 1, 1))])
    >>> image = pp.render(scene, style="wireframe")
    >>> int((image.object_id == 0).sum()) > 0, image.stats["edges"]
    (True, 12)
    """
    from pixelpath.raster.lines import draw_lines

    geometry = scene_geometry(scene, view.camera)
    starts, ends, owners = polygon_edges(scene, geometry)
    lines = draw_lines(starts, ends, owners, view)
    stats = {"edges": len(owners), **lines.counts}
    report = _report("wireframe", stats, None) if options.explain else None
    return _frame(scene, geometry, lines, stats, report)


def hidden_lines(
    scene: Scene,
    view: View,
    options: RenderOptions,
    frame: Frame,
    frame_view: View | None = None,
) -> Frame:
    """Draw the parts of the polygon edges that are not behind the filled render's surface.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera and region of the drawing.
    options : RenderOptions
        With ``backface_cull`` only the edges of polygons facing the eye are drawn.
    frame : Frame
        The filled render of ``frame_view`` by any method; its ``depth`` and ``object_id``
        say what is seen.
    frame_view : View, optional
        The region ``frame`` covers: ``view``, or ``view`` grown by a pixel on each side
        inside the image (:func:`surface_view`), so that the depth slopes at the region's
        border are those of the whole image (default ``view``).

    Returns
    -------
    Frame
        The drawing; its stats are the filled render's and the lines'.

    Examples
    --------
    >>> import pixelpath as pp
    >>> scene = pp.Scene(pp.Camera(eye=(3, 2, 4), target=(0, 0, 0), width=48, height=32),
    ...                  objects=[pp.Box((-1, -1, -1), (1, 1, 1))])
    >>> lines = pp.render(scene, style="hidden-line")
    >>> every = pp.render(scene, style="wireframe")
    >>> bool(((lines.object_id == 0) <= (every.object_id == 0)).all())  # a subset of the edges
    True
    """
    from pixelpath.hsr.backface import front_facing
    from pixelpath.raster.lines import draw_lines

    frame_view = frame_view or view
    if frame.depth.shape != (frame_view.height, frame_view.width):
        raise ValueError(
            f"frame must cover frame_view ({frame_view.height}, {frame_view.width}), got "
            f"{frame.depth.shape}"
        )
    geometry = scene_geometry(scene, view.camera)
    polygons = None
    if options.backface_cull:
        polygons = front_facing(geometry.polygon_normals, geometry.polygon_points,
                                view.camera.viewpoint())
    starts, ends, owners = polygon_edges(scene, geometry, polygons)
    limit = surface_limit(frame.depth, frame.object_id)
    top, left = view.y0 - frame_view.y0, view.x0 - frame_view.x0
    limit = limit[top : top + view.height, left : left + view.width]
    lines = draw_lines(starts, ends, owners, view, limit)
    stats = {**frame.stats, "edges": len(owners), **lines.counts}
    report = _report("hidden-line", stats, frame.report) if options.explain else None
    return _frame(scene, geometry, lines, stats, report)


def surface_view(view: View) -> View:
    """Return ``view`` grown by one pixel on each side, within the camera's image.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.contract import View
    >>> from pixelpath.hsr.hidden_line import surface_view
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), width=64, height=48)
    >>> grown = surface_view(View(camera, 0, 10, 32, 20))
    >>> grown.x0, grown.y0, grown.width, grown.height
    (0, 9, 33, 22)
    """
    camera = view.camera
    x0, y0 = max(view.x0 - 1, 0), max(view.y0 - 1, 0)
    x1 = min(view.x0 + view.width + 1, camera.width)
    y1 = min(view.y0 + view.height + 1, camera.height)
    return View(camera, x0, y0, x1 - x0, y1 - y0)


def surface_limit(depth: np.ndarray, object_id: np.ndarray) -> np.ndarray:
    """Return the depth beyond which a line is hidden at each pixel of a filled render.

    A line pixel's centre lies up to a pixel off the line, so the surface is judged over the
    pixel and its eight neighbours: with ``hi`` and ``lo`` the largest and smallest depth
    there, the limit is ``hi + SLOPE · (hi − lo) + RELATIVE · hi``. A surface that is planar
    over the neighbourhood is never farther than ``hi`` under the line, and a crease (where
    two faces meet, or a face meets the floor) is no farther than its slope allows beyond
    that. Where a neighbour shows nothing (``inf``) the limit is ``inf``: a line on a
    silhouette stays. Neighbours beyond the array's border are not counted.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.hsr.hidden_line import surface_limit
    >>> depth = np.array([[1.0, 1.1, 1.2, 1.3], [1.0, 1.1, 1.2, np.inf]])
    >>> ids = np.array([[0, 0, 0, 0], [0, 0, 0, -1]])
    >>> np.round(surface_limit(depth, ids), 4).tolist()  # inf beside the empty pixel
    [[1.15, 1.3, inf, inf], [1.15, 1.3, inf, inf]]
    """
    depth = np.where(np.asarray(object_id) >= 0, np.asarray(depth, dtype=np.float64), np.inf)
    high = _around(depth, np.maximum)
    low = _around(depth, np.minimum)
    with np.errstate(invalid="ignore"):  # inf - inf where the whole neighbourhood is empty
        limit = high + SLOPE * (high - low) + RELATIVE * high
    return np.where(np.isinf(high), np.inf, limit)


def _around(values: np.ndarray, pick) -> np.ndarray:
    """``pick`` (np.maximum or np.minimum) over each pixel's 3 × 3 neighbourhood.

    Separable: along columns, then along rows; a pixel on the border has fewer neighbours.
    """
    out = values.copy()
    for axis in (0, 1):
        source = out.copy()
        lower = [slice(None)] * 2
        upper = [slice(None)] * 2
        lower[axis], upper[axis] = slice(None, -1), slice(1, None)
        lower, upper = tuple(lower), tuple(upper)
        pick(out[lower], source[upper], out=out[lower])
        pick(out[upper], source[lower], out=out[upper])
    return out


def _frame(scene: Scene, geometry, lines, stats: dict, report) -> Frame:
    """Make the frame: lines in their objects' colours over the background, depth, objects."""
    colors = np.vstack([geometry.materials[:, :3], np.asarray(scene.background)[None]])
    rgb = colors[lines.owner].astype(np.float32)  # owner -1 picks the background row
    return Frame(rgb, lines.depth.astype(np.float32), lines.owner, stats, report)


def _report(style: str, stats: dict, surface_report):
    """Report the line counts (after the filled render's own report, for hidden lines)."""
    from pixelpath.report import Report

    notes = (
        "every polygon edge, clipped to the frustum in homogeneous coordinates and drawn by "
        "Bresenham's algorithm, nearest line in front",
    )
    if surface_report is None:
        return Report(method=style, summary=stats, notes=notes)
    return Report(
        method=f"{surface_report.method}, {style}",
        summary={**surface_report.summary, **stats},
        tables=surface_report.tables,
        notes=(*surface_report.notes,
               "hidden-line: a line pixel is kept unless it lies behind the visible surface "
               "over its pixel and the eight neighbours (with their depth slope as tolerance)"),
    )
