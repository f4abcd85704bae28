"""The octree method: cells of space visited front to back, stopping where pixels are decided.

Object space orders, image space decides (SPEC §9 errata). The drawable triangles are sorted
into an octree in world space: a cube around them, cut into eight equal children while a cell
holds more than ``LEAF_SIZE`` triangles (down to ``MAX_DEPTH`` levels). A triangle is stored
in every leaf its bounding box overlaps (not clipped to the cells), so a leaf may list a
triangle that only grazes it.

The tree is traversed front to back from the eye: at every node the children are taken by
how many of the node's three splitting planes lie between them and the child holding the eye
(none, one, two, three). A ray from the eye crosses each plane once at most, so every ray
meets the cells in this order. Each leaf's triangles are scan-converted (the shared top-left
fill rule) inside the leaf's screen footprint with a depth test on 1/w, ties going to the lower
triangle index as in the z-buffer (a sample of an alpha-tested material that its alpha test cuts
away is no hit: it replaces nothing). Then **early termination**:

* a pixel is *decided* once its nearest hit so far lies inside the leaf just drawn: every cell
  the pixel's ray meets later lies farther along it, so nothing can come in front any more;
* a cell whose footprint holds no undecided pixel is skipped with its whole subtree (a count
  of undecided pixels per 8 × 8 tile makes the test cheap);
* cells outside the view frustum are culled.

The result is what the z-buffer computes, pixel for pixel: only samples that cannot win are
left out. Pixels no triangle covers are never decided (nothing says a later cell will not
cover them), so early termination pays where the image is full, as behind a near wall.

The tree is built per frame over the front end's output (the triangles that survived back-face
culling and frustum clipping, in world space): planes are tessellated per camera and clipping
makes new pieces per view, so a tree kept with the scene could not hold them. Building costs
far less than drawing (see the report's build time). The image is cut into bands of 32 rows,
each traversing the tree on its own, in parallel; the report's counts are summed over bands.

Memory: the tree (about 150 bytes per node) and the stored triangle references, plus 5 bytes
per pixel of work buffers besides the visibility buffers. Time: building is O(R) per level for
R stored references; drawing touches each stored triangle's pixels inside its leaves until
they are decided.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from pixelpath._threads import in_runs
from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Scene

__all__ = ["LEAF_SIZE", "MAX_DEPTH", "OUTCOMES", "STEPS", "Octree", "build_octree",
           "front_to_back", "render_frame"]

STEPS = pipeline.FRONT_STEPS + 2 + pipeline.SHADE_SLICES
LEAF_SIZE = 32  # a cell holding more triangles is split
MAX_DEPTH = 12  # levels below the root at most
# What the traversal did with a node (``report.arrays["cell outcome"]``), codes 0..4 of
# pixelpath.hsr._kernels.octree's OUTCOME_* (a band reaching it more than once keeps the most).
OUTCOMES = (
    "not reached",
    "culled (outside the view)",
    "skipped (its pixels decided)",
    "entered",
    "drawn (a leaf)",
)
# A cell is not split when its children would hold more than this many times its triangles
# between them: its triangles are large for it, and splitting would only copy them.
MAX_GROWTH = 2
# Triangle boxes are padded by this fraction of the scene's size, so that a point on a
# triangle, rebuilt from a pixel's depth with rounding errors, lies in a cell holding it.
PAD = 1e-9


@dataclasses.dataclass(frozen=True)
class Octree:
    """An octree over one frame's drawable triangles.

    Attributes
    ----------
    tree : pixelpath.hsr._kernels.octree.Tree
        The node arrays: cells, links (level, leaf flag, triangle range, child per octant)
        and the leaves' triangle lists; the properties below read them.
    triangle_rects : (T, 4) float64
        Screen box (x min, x max, y min, y max) of every drawable triangle.
    build_seconds : float
        Time taken to build it.

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr import pipeline
    >>> from pixelpath.hsr.octree import build_octree
    >>> boxes = [Box((-2, -2, -2), (-1, -1, -1)), Box((1, 1, 1), (2, 2, 2))]
    >>> scene = Scene(Camera(eye=(4, 5, 6), target=(0, 0, 0), width=32, height=24), objects=boxes)
    >>> view = View.whole(scene.camera)
    >>> octree = build_octree(pipeline.prepare(scene, view, RenderOptions()), view, leaf_size=4)
    >>> octree.nodes, octree.leaves, octree.depth, octree.references  # a root, a leaf per box
    (3, 2, 1, 12)
    """

    tree: object
    triangle_rects: np.ndarray
    build_seconds: float

    @property
    def nodes(self) -> int:
        """Number of nodes."""
        return len(self.tree.cells)

    @property
    def corners(self) -> np.ndarray:
        """(N, 3) minimum corner of each node's cubic cell."""
        return self.tree.cells[:, :3]

    @property
    def sides(self) -> np.ndarray:
        """(N,) side of each node's cell."""
        return self.tree.cells[:, 3]

    @property
    def levels(self) -> np.ndarray:
        """(N,) level of each node (0 for the root)."""
        return self.tree.links[:, 0]

    @property
    def is_leaf(self) -> np.ndarray:
        """(N,) whether each node is a leaf."""
        return self.tree.links[:, 1].astype(bool)

    def triangles_of(self, node: int) -> np.ndarray:
        """Return the triangles stored in a leaf (ascending; empty for an inner node)."""
        start, stop = self.tree.links[node, 2:4]
        return self.tree.items[start:stop] if self.is_leaf[node] else self.tree.items[:0]

    @property
    def leaves(self) -> int:
        """Number of leaves."""
        return int(np.count_nonzero(self.is_leaf))

    @property
    def depth(self) -> int:
        """Level of the deepest node (0 when the root is a leaf)."""
        return int(self.levels.max(initial=0))

    @property
    def references(self) -> int:
        """Triangles stored in leaves, counting a triangle once per leaf holding it."""
        return len(self.tree.items)


def front_to_back(eye, center) -> np.ndarray:
    """Return the eight child octants of a cell centred at ``center``, front to back from ``eye``.

    Octant bits: 1 for the upper half in x, 2 in y, 4 in z. The eye's own child comes first,
    then the three across one splitting plane, the three across two, and the one across all
    three: the order in which any ray from the eye can meet them.

    Examples
    --------
    >>> from pixelpath.hsr.octree import front_to_back
    >>> front_to_back(eye=(5, 5, 5), center=(0, 0, 0)).tolist()
    [7, 6, 5, 3, 4, 2, 1, 0]
    """
    from pixelpath.hsr._kernels import octree as kernels
    from pixelpath.raster._arrays import kernel_array

    eye, center = kernel_array(eye), kernel_array(center)
    if eye.shape != (3,) or center.shape != (3,):
        raise ValueError(f"eye and center must have shape (3,), got {eye.shape}, {center.shape}")
    octant = sum(1 << axis for axis in range(3) if eye[axis] >= center[axis])
    return octant ^ kernels.FRONT_TO_BACK


def build_octree(
    prepared: pipeline.Prepared,
    view: View,
    leaf_size: int = LEAF_SIZE,
    max_depth: int = MAX_DEPTH,
) -> Octree:
    """Sort a frame's drawable triangles into an octree in world space.

    Only triangles that cover some pixel of the view's region are stored. The root is the
    cube around them; a triangle goes into every leaf its (slightly padded) box overlaps.

    Parameters
    ----------
    prepared : Prepared
        The front end's output for ``view``.
    view : View
        Camera and region.
    leaf_size : int
        A cell holding more triangles than this is split.
    max_depth : int
        Cells are not split below this level.

    Returns
    -------
    Octree
    """
    from pixelpath.hsr._kernels import octree as kernels

    start = time.perf_counter()
    bounds = np.empty((len(prepared.triangles), 6))
    rects = np.empty((len(prepared.triangles), 4))
    candidates = kernels.triangle_boxes(
        prepared.positions, prepared.screen, prepared.triangles, prepared.rows, view.x0,
        view.x0 + view.width, bounds, rects,
    )
    if len(candidates):
        low, high = bounds[candidates, :3].min(axis=0), bounds[candidates, 3:].max(axis=0)
    else:
        low, high = np.zeros(3), np.zeros(3)
    extent = float(np.max(high - low))
    pad = PAD * (extent + float(np.max(np.abs([low, high])))) + 1e-300
    side = extent + 4 * pad
    root = (low + high) / 2 - side / 2
    arrays = kernels.build_tree(
        bounds, candidates, root, side, pad, int(leaf_size), int(max_depth), MAX_GROWTH
    )
    return Octree(kernels.Tree(*arrays), rects, time.perf_counter() - start)


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Render ``view`` of ``scene`` with the octree method.

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
        With ``options.explain``, its report counts what the traversal did per level;
        ``report.arrays`` holds, per node of the tree, its cell's screen footprint
        (``"cell footprint"``: x min, x max, y min, y max in pixels of the region), its level
        (``"cell level"``), whether it is a leaf (``"cell is leaf"``) and the most any band
        did with it (``"cell outcome"``: an index into ``OUTCOMES``).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.octree import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions(explain=True))
    >>> int(frame.object_id[12, 16]), frame.report.summary["nodes visited"]
    (0, 1)
    """
    prepared = pipeline.prepare(scene, view, options)
    octree = build_octree(prepared, view, LEAF_SIZE, MAX_DEPTH)
    options.progress(1)
    visibility = pipeline.visibility_buffers(view)
    stats, visits = _traverse(octree, prepared, view, visibility, options.explain)
    options.progress(1)
    report = None
    if options.explain:
        report = _report(octree, prepared, view, visibility, stats)
        report.arrays.update(_cell_arrays(octree, view, *visits))
    return pipeline.shade(prepared, scene, view, visibility, options, report)


def _traverse(octree: Octree, prepared: pipeline.Prepared, view: View,
              visibility: pipeline.Visibility, record: bool = False):
    """Run the front-to-back traversal band by band.

    Returns the counts (bands, levels, k) and the cells' footprints with what each band did
    with each node (``record``; else an empty table).
    """
    from pixelpath.hsr._kernels import octree as kernels
    from pixelpath.raster._arrays import kernel_array

    camera = view.camera
    tree = octree.tree
    matrix = kernel_array(camera.projection_matrix() @ camera.view_matrix())
    rects = np.empty((octree.nodes, 4))
    outside = np.empty(octree.nodes, dtype=np.bool_)
    kernels.cell_footprints(tree, octree.triangle_rects, matrix, camera.width, camera.height,
                            rects, outside)
    count, order = pipeline.bands(view)
    stats = np.zeros((count, octree.depth + 1, kernels.STAT_COLUMNS), dtype=np.int64)
    shape = (view.height, view.width)
    scan = kernels.Scan(prepared.setup, prepared.rows, prepared.triangles, prepared.positions,
                        pipeline.cutouts(prepared))
    work = (np.empty(shape, dtype=np.uint8), np.empty(shape, dtype=np.int32))
    eye = camera.viewpoint()
    outcomes = np.zeros((count, octree.nodes if record else 0), dtype=np.int8)

    def run(bands: np.ndarray) -> None:
        kernels.traverse(tree, rects, outside, eye, scan, bands, view.x0, view.y0, *visibility,
                         *work, stats, outcomes)

    in_runs(run, order)  # bands are independent (the kernel releases the GIL)
    return stats, (rects, outcomes)


def _cell_arrays(octree: Octree, view: View, rects: np.ndarray,
                 outcomes: np.ndarray) -> dict[str, np.ndarray]:
    """Return the cells as the figures read them (see :func:`render_frame`)."""
    footprints = rects - np.array([view.x0, view.x0, view.y0, view.y0])
    return {
        "cell footprint": footprints,
        "cell level": octree.levels.copy(),
        "cell is leaf": octree.is_leaf.copy(),
        "cell outcome": outcomes.max(axis=0, initial=0),
    }


def _report(octree: Octree, prepared: pipeline.Prepared, view: View,
            visibility: pipeline.Visibility,
            stats: np.ndarray):
    """Report the tree's size and build time, and what the traversal did (total, per level)."""
    from pixelpath.hsr._kernels import octree as kernels
    from pixelpath.raster.transform import depth_key_name
    from pixelpath.report import Report, Table

    per_level = stats.sum(axis=0)
    total = per_level.sum(axis=0)
    levels = np.bincount(octree.levels, minlength=len(per_level))
    leaves = np.bincount(octree.levels[octree.is_leaf], minlength=len(per_level))
    rows = [
        (level, int(levels[level]), int(leaves[level]), *(int(per_level[level, column]) for column
         in (kernels.VISITED, kernels.CULLED, kernels.SKIPPED, kernels.DRAWN, kernels.DECIDED)))
        for level in range(len(per_level))
    ]
    drawn = int(np.count_nonzero(visibility.triangle_id >= 0))
    return Report(
        method="octree",
        summary={
            **prepared.stats,
            "octree build, per frame (ms)": round(1000 * octree.build_seconds, 3),
            "nodes built": octree.nodes,
            "leaves": octree.leaves,
            "tree depth": octree.depth,
            "triangles stored in leaves (once per leaf)": octree.references,
            "traversals (one per band of 32 rows)": len(stats),
            "nodes visited": int(total[kernels.VISITED]),
            "culled by the view frustum": int(total[kernels.CULLED]),
            "outside the band being traversed": int(total[kernels.OTHER_BAND]),
            "skipped: their pixels all decided": int(total[kernels.SKIPPED]),
            "triangles drawn (once per leaf)": int(total[kernels.DRAWN]),
            "pixel samples depth-tested": int(total[kernels.TESTED]),
            "pixels decided early": int(total[kernels.DECIDED]),
            "pixels drawn": drawn,
        },
        tables=(
            Table(
                "per level (counts summed over the bands)",
                ("level", "nodes", "leaves", "visited", "culled", "skipped", "triangles drawn",
                 "pixels decided"),
                rows,
            ),
        ),
        notes=(
            "object space orders, image space decides: cells are visited front to back from "
            "the eye, each leaf's triangles scan-converted with a depth test on "
            f"{depth_key_name(view.camera)}",
            "a pixel is decided once its nearest hit lies in a cell already drawn; a cell "
            "whose pixels are all decided is skipped with its subtree",
            "the tree is built per frame over the triangles left after culling and clipping",
        ),
    )
