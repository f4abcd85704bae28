"""The painter's algorithm (depth sort): order polygons in object space, paint back to front.

Newell, Newell and Sancha's depth sort, as the notes teach it: sort the polygons by their
farthest depth; the farthest, P, may be painted when no polygon Q whose depth range overlaps
P's could be hidden by it. The notes' tests decide that for each such Q, cheapest first:

1. Q is entirely nearer than P (depth extents do not overlap);
2. their screen x extents do not overlap;
3. their screen y extents do not overlap;
4. P lies entirely on the far side of Q's plane, seen from the eye;
5. Q lies entirely on the eye's side of P's plane;
6. their projections do not overlap.

When every test fails, Q may have to be painted first: if the reversed tests 4 and 5 show
that Q cannot hide P, Q moves in front of P in the list and is marked. A marked polygon that
must move again means the polygons overlap cyclically; a pair that neither order satisfies
interpenetrates. Either way a polygon is split by the other's plane and its pieces go back into
the sorted list. The polygons are then painted in that order with no depth test; the last one
painted over a pixel is the one seen.

This is an object-space ordering with image-space drawing (SPEC §9 errata). The polygons are
the shared front end's triangles after back-face culling and frustum clipping; plane tests use
their planes in world space (a tolerance scaled to the scene counts a shared vertex as lying
on its neighbour's plane). Cost: the sort, plus for each polygon a comparison with each polygon
whose depth range overlaps its own (the sorted list stops the scan at the first that is
entirely nearer), plus the painting, which touches every covered pixel once per polygon
covering it. Memory: a record per polygon and the frame's buffers.
"""

from __future__ import annotations

import dataclasses
import warnings
from typing import NamedTuple

import numpy as np

from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Camera, Scene

__all__ = ["STEPS", "TESTS", "Comparison", "SplitLimitWarning", "compare", "render_frame"]

STEPS = pipeline.FRONT_STEPS + 2 + pipeline.SHADE_SLICES

# The notes' tests, in the order they are tried: what each one checks.
TESTS = (
    "depth extents do not overlap (Q entirely nearer)",
    "screen x extents do not overlap",
    "screen y extents do not overlap",
    "P entirely on the far side of Q's plane",
    "Q entirely on the eye's side of P's plane",
    "projections do not overlap",
)

# Distances below this fraction of the scene's size count as lying on a plane.
PLANE_TOLERANCE = 1e-9
# Splitting stops (pairs keep their sorted order, with a SplitLimitWarning) past MAX_GROWTH
# polygons per input polygon plus SPLIT_FLOOR. Meshes stay far below it; a small soup of
# crossing triangles needs the floor (trimesh's soup.stl, 100 triangles, up to 9,900 polygons
# seen from around it), and input that would split almost without end stops within seconds
# (300 large random triangles crossing each other reach the limit in 2.3 s on 2 cores).
MAX_GROWTH = 8
SPLIT_FLOOR = 16384


class SplitLimitWarning(UserWarning):
    """The depth sort stopped splitting at its polygon limit: some overlaps may show wrongly."""


class Comparison(NamedTuple):
    """How the depth sort decides whether P (the farther) may be painted before Q."""

    test: int  # the test (1..6) that settled it, or 0 when all failed
    outcome: str  # "P first", "Q first" (Q is moved before P) or "split"


class DepthSort(NamedTuple):
    """The front end's output extended by the pieces of split triangles, and the order."""

    prepared: pipeline.Prepared
    order: np.ndarray  # drawable triangles, back to front
    counts: np.ndarray  # the kernel's counts (see pixelpath.hsr._kernels.painter)
    sorted_count: int  # triangles that went through the sort
    pieces_from: int  # drawable triangles from this index on are pieces made by splitting


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Render ``view`` of ``scene`` with the painter's algorithm.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera and region to render.
    options : RenderOptions
        Shading, culling, Blinn-Phong, progress, explain.

    Returns
    -------
    Frame
        With ``options.explain``, its report counts the comparisons and the tests that settled
        them; ``report.arrays`` holds the triangles painted, back to front (``"order"``), and
        per drawable triangle its screen corners (``"triangles"``, (T, 3, 2) pixels of the
        region), its object (``"object"``) and whether it is a piece made by splitting
        (``"split"``).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.painter import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    prepared = pipeline.prepare(scene, view, options)
    result = depth_sort(prepared, view)
    options.progress(1)
    visibility = pipeline.paint(result.prepared, view, result.order)
    options.progress(1)
    report = _report(result, view, visibility) if options.explain else None
    return pipeline.shade(result.prepared, scene, view, visibility, options, report)


def depth_sort(prepared: pipeline.Prepared, view: View) -> DepthSort:
    """Order the drawable triangles back to front, splitting where the tests demand it.

    Triangles seen exactly edge-on (the eye in their plane) or of zero area on the screen
    cover no area and go first, unsorted. Every other triangle is sorted, whatever the
    region, so tiles of an image get the same order (and the same splits) as the whole.
    """
    from pixelpath.hsr._kernels import painter as kernels

    camera = view.camera
    planes, eps = _triangle_planes(prepared, camera)
    sortable = _sortable(prepared, planes, eps)
    candidates = np.flatnonzero(sortable)
    attrs, count = _vertex_rows(prepared, len(candidates))
    screen = np.zeros((len(attrs), 3))
    screen[:count] = prepared.screen
    counts = np.zeros(kernels.COUNTS, dtype=np.int64)
    limit = MAX_GROWTH * len(candidates) + SPLIT_FLOOR
    order, attrs, screen, count, corners, root = kernels.depth_sort(
        attrs, screen, count, np.ascontiguousarray(prepared.triangles[candidates]),
        np.ascontiguousarray(planes[candidates]), camera.width, camera.height,
        camera.orthographic, eps, limit, counts,
    )
    sorted_count = len(candidates)
    pieces = corners[sorted_count:]
    drawable = len(prepared.triangles)
    origin = candidates[root]  # the drawable triangle each polygon is or was cut from
    number = np.concatenate([origin[:sorted_count], drawable + np.arange(len(pieces))])
    order = np.concatenate([np.flatnonzero(~sortable), number[order]])
    extended = _with_pieces(prepared, view, attrs[:count], screen[:count], pieces,
                            origin[sorted_count:])
    if counts[kernels.LIMITED]:
        warnings.warn(
            f"the painter's algorithm stopped splitting at {limit:,} polygons (the limit for "
            f"{len(candidates):,} triangles): {counts[kernels.LIMITED]:,} overlapping pairs "
            "are drawn in depth order and may show wrongly; method='zbuffer' draws them "
            "exactly", SplitLimitWarning, stacklevel=2,
        )
    return DepthSort(extended, order, counts, sorted_count, drawable)


def _triangle_planes(prepared: pipeline.Prepared, camera: Camera) -> tuple[np.ndarray, float]:
    """Return each drawable triangle's plane and the on-plane tolerance.

    The (T, 5) planes are those of the scene triangles (unit normal, offset, the sign of the
    eye's side; the offset is NaN when the eye lies in the plane). Pieces clipped from one
    scene triangle share its plane exactly, so they classify alike.
    """
    from pixelpath.hsr._kernels import painter as kernels

    geometry = prepared.geometry
    planes = np.empty((len(prepared.source), kernels.PLANE_COLUMNS))
    kernels.triangle_planes(geometry.vertices, geometry.triangles, prepared.source,
                            camera.viewpoint(), planes)
    reach = np.abs(prepared.positions - camera.eye).max(initial=1.0)
    eps = PLANE_TOLERANCE * float(reach)
    eye_side = planes[:, 4]
    planes[:, 3] = np.where(np.abs(eye_side) > eps, planes[:, 3], np.nan)
    planes[:, 4] = np.where(eye_side < 0, -1.0, 1.0)
    return planes, eps


def _sortable(prepared: pipeline.Prepared, planes: np.ndarray, eps: float) -> np.ndarray:
    """Triangles with area on the screen and the eye off their plane (a NaN offset)."""
    xy = prepared.screen[prepared.triangles, :2]
    area2 = (xy[:, 1, 0] - xy[:, 0, 0]) * (xy[:, 2, 1] - xy[:, 0, 1]) - (
        xy[:, 2, 0] - xy[:, 0, 0]
    ) * (xy[:, 1, 1] - xy[:, 0, 1])
    return np.isfinite(area2) & (area2 != 0) & np.isfinite(planes[:, 3])


# The per-vertex arrays of a prepared frame, in the order of a vertex row: clip coordinates
# first (the sort reads them there), then the world position and the attributes.
_VERTEX_ARRAYS = ("clip", "positions", "normals", "colors", "uv", "vertex_colors")


def _cut_arrays(prepared: pipeline.Prepared) -> list[str]:
    """Return the per-vertex arrays the frame has rows of (optional ones may have none)."""
    return [name for name in _VERTEX_ARRAYS
            if len(getattr(prepared, name)) == len(prepared.clip)]


def _vertex_rows(prepared: pipeline.Prepared, sorted_count: int) -> tuple[np.ndarray, int]:
    """Return the vertex rows the sort cuts, and how many are in use.

    A row holds a vertex's clip coordinates, world position and attributes; room for split
    vertices follows the rows in use.
    """
    columns = [getattr(prepared, name) for name in _cut_arrays(prepared)]
    count = len(prepared.clip)
    width = sum(block.shape[1] for block in columns)
    attrs = np.empty((count + 64 + sorted_count // 8, width))
    start = 0
    for block in columns:
        attrs[:count, start : start + block.shape[1]] = block
        start += block.shape[1]
    return attrs, count


def _with_pieces(prepared, view, attrs, screen, pieces, origin) -> pipeline.Prepared:
    """Return the prepared frame with the split vertices and the pieces (set up) appended."""
    from pixelpath.raster import _setup_kernels

    if len(pieces) == 0:
        return prepared
    old = len(prepared.clip)
    new = attrs[old:]
    triangles = np.concatenate([prepared.triangles, pieces])
    setup = np.empty((len(pieces), _setup_kernels.SETUP_FIELDS))
    rows = np.empty((len(pieces), 2), dtype=np.intp)
    _setup_kernels.setup_triangles(screen, np.ascontiguousarray(pieces), view.camera.orthographic,
                                   view.y0, view.y0 + view.height, setup, rows)
    extended = {}
    start = 0
    for name in _cut_arrays(prepared):
        block = getattr(prepared, name)
        width = block.shape[1]
        extended[name] = np.concatenate([block, new[:, start : start + width]])
        start += width
    return dataclasses.replace(
        prepared,
        **extended,
        screen=screen,
        triangles=triangles,
        source=np.concatenate([prepared.source, prepared.source[origin]]),
        info=np.concatenate([prepared.info, prepared.info[origin]]),
        flat_colors=np.concatenate([prepared.flat_colors, prepared.flat_colors[origin]]),
        face_normals=np.concatenate([prepared.face_normals, prepared.face_normals[origin]]),
        setup=np.concatenate([prepared.setup, setup]),
        rows=np.concatenate([prepared.rows, rows]),
    )


def compare(p, q, camera: Camera) -> Comparison:
    """Decide one pair of triangles the way the depth sort does.

    Parameters
    ----------
    p, q : (3, 3) array_like
        World coordinates of the corners of P (the one sorted as farther, tested for being
        painted first) and of Q.
    camera : Camera
        The eye and the projection.

    Returns
    -------
    Comparison
        The first of the notes' tests (1..6) that lets P be painted before Q, or test 0 with
        the outcome "Q first" (Q cannot hide P: it moves before P) or "split" (neither order
        is proved: one is cut by the other's plane).

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.hsr.painter import compare
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), width=64, height=64)
    >>> far = [(-1, -1, -4), (1, -1, -4), (0, 1, -4)]
    >>> near = [(-1, -1, 0), (1, -1, 0), (0, 1, 0)]
    >>> compare(far, near, camera)
    Comparison(test=1, outcome='P first')
    >>> compare(near, far, camera)
    Comparison(test=0, outcome='Q first')
    """
    from pixelpath.hsr._kernels import painter as kernels
    from pixelpath.raster import _setup_kernels
    from pixelpath.raster._arrays import kernel_array
    from pixelpath.raster.transform import world_to_clip

    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a pixelpath Camera, got {type(camera).__name__}")
    points = np.concatenate([_corners(p, "p"), _corners(q, "q")])
    clip = world_to_clip(points, camera)
    if not np.all(clip[:, 3] > 0):
        raise ValueError("p and q must lie in front of the eye (positive view depth)")
    screen = np.empty((6, 3))
    _setup_kernels.clip_to_screen(kernel_array(clip), camera.width, camera.height,
                                  camera.orthographic, screen)
    attrs = np.hstack([clip, points])
    corners = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    records = np.empty((2, kernels.RECORD))
    for k in range(2):
        kernels._describe(corners[k], attrs, screen, camera.orthographic, records[k])
        a, b, c = points[3 * k : 3 * k + 3]
        normal = np.cross(b - a, c - a)
        if not np.linalg.norm(normal) > 0:
            raise ValueError(f"{'pq'[k]} must be a triangle of non-zero area")
        normal /= np.linalg.norm(normal)
        offset = -normal @ a
        records[k, kernels.NORMAL : kernels.OFFSET] = normal
        records[k, kernels.OFFSET] = offset
        viewpoint = camera.viewpoint()
        side = normal @ viewpoint[:3] + offset * viewpoint[3]
        records[k, kernels.EYE_SIGN] = 1.0 if side >= 0 else -1.0
    eps = PLANE_TOLERANCE * float(np.abs(points - camera.eye).max())
    test = int(kernels.compare(0, 1, records, corners, attrs, screen, eps))
    if test <= len(TESTS):
        return Comparison(test, "P first")
    return Comparison(0, "Q first" if test == kernels.MOVE else "split")


def _corners(values, name: str) -> np.ndarray:
    from pixelpath.raster._arrays import kernel_array

    try:
        array = kernel_array(values)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be three 3-D points, got {values!r}") from None
    if array.shape != (3, 3):
        raise ValueError(f"{name} must have shape (3, 3) (three corners), got {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite")
    return array


def _report(result: DepthSort, view: View, visibility: pipeline.Visibility):
    """Report comparisons, the tests that settled them, moves and splits; the order drawn."""
    from pixelpath.hsr._kernels import painter as kernels
    from pixelpath.report import Report, Table

    counts = result.counts.tolist()
    prepared = result.prepared
    rows = [(k, TESTS[k - 1], counts[k]) for k in range(1, len(TESTS) + 1)]
    rows.append(("-", "all failed, Q moved before P (reordered)", counts[kernels.MOVES]))
    rows.append(("-", "all failed, a polygon split by the other's plane", counts[kernels.SPLITS]))
    summary = {
        **{k: v for k, v in prepared.stats.items() if k != "triangles scan-converted"},
        "triangles sorted": result.sorted_count,
        "comparisons": counts[kernels.COMPARISONS],
        "moves (Q painted before P)": counts[kernels.MOVES],
        "cycles found": counts[kernels.CYCLES],
        "splits": counts[kernels.SPLITS],
        "pieces made by splitting": counts[kernels.PIECES],
        "triangles painted": len(result.order),
        "pixels drawn": int(np.count_nonzero(visibility.triangle_id >= 0)),
    }
    uncut = counts[kernels.UNRESOLVED] - counts[kernels.LIMITED]
    if uncut:
        summary["pairs left in sorted order (no plane cuts them)"] = uncut
    if counts[kernels.LIMITED]:
        summary["pairs left in sorted order (polygon limit reached)"] = counts[kernels.LIMITED]
    return Report(
        method="painter",
        summary=summary,
        tables=(Table("tests (pairs settled by each)", ("test", "P cannot hide Q when",
                                                          "pairs"), rows),),
        notes=(
            "object space: the triangles are ordered by the depth sort of Newell, Newell and "
            "Sancha; image space: they are painted back to front with no depth test",
            "test 1 also ends each scan: the list is sorted by farthest depth, so the first Q "
            "entirely nearer than P settles every polygon after it",
        ),
        arrays=order_arrays(prepared, view, result.order,
                            np.arange(len(prepared.triangles)) >= result.pieces_from),
    )


def order_arrays(prepared: pipeline.Prepared, view: View, order: np.ndarray,
                 split: np.ndarray) -> dict[str, np.ndarray]:
    """Return the drawing order as the figures read it (see :func:`render_frame`)."""
    corners = prepared.screen[prepared.triangles, :2] - np.array([view.x0, view.y0])
    return {"order": np.asarray(order, dtype=np.intp), "triangles": corners,
            "object": prepared.info[:, 0].copy(), "split": split}
