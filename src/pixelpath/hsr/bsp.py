"""The BSP-tree method: a binary space partition built once in object space, drawn per eye.

A BSP tree divides space by planes. Each node holds a splitting plane, the polygons lying in
it, and two subtrees: what lies behind the plane and what lies in front of it. A polygon that
straddles a splitting plane is cut in two (or three) along it; the pieces keep their source
polygon, so culling and shading stay exactly those of the z-buffer. The tree depends only on
the scene's objects, not on the camera: :func:`build_tree` builds it once, and every render of
the same objects, from any eye, reuses it.

Drawing traverses the tree from the eye (the notes' rule): at a node whose plane has the eye
in front, draw the back subtree, then the node's polygons, then the front subtree (the other
way round when the eye is behind). That lists every polygon back to front; painting them in
that order with no depth test leaves the nearest one visible at every pixel.

Splitting planes are chosen to keep the tree small: at each node a few candidates are scored
on a sample of the node's polygons by how unbalanced the two sides are plus 24 times how many
polygons the plane cuts (a cut adds fragments to every frame; imbalance only lengthens the
build). Candidates are the planes of some of the polygons and, for runs
of many polygons, three axis-aligned planes through their middle (a convex mesh has every
other face behind each of its faces, so polygon planes alone would make a chain as deep as it
has faces). Infinite planes of the scene are the splitting planes of the top levels: they cut
nothing of themselves, and the grid the raster front end makes of them for each camera (see
:mod:`pixelpath.raster.tessellate`) is attached to their node at render time.

An object-space ordering with image-space drawing (SPEC §9 errata). Build: about
O(n log n) polygon classifications plus the pieces splitting makes; drawing: a visit of every
node and the painting of every polygon in view. Memory: the tree's fragments and vertices, kept
for the scene's objects (the last few sets of objects' trees are cached): every viewpoint, and
every frame of an animation whose objects do not move, draws the same tree.
"""

from __future__ import annotations

import dataclasses
import time
from typing import Any, NamedTuple

import numpy as np

from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Plane, Scene

__all__ = ["STEPS", "BSPTree", "build_tree", "render_frame"]

STEPS = pipeline.FRONT_STEPS + 2 + pipeline.SHADE_SLICES

# Distances below this fraction of the scene's size count as lying on a plane.
PLANE_TOLERANCE = 1e-9


@dataclasses.dataclass(frozen=True, eq=False)
class BSPTree:
    """A scene's BSP tree: fragments of its objects' triangles arranged by splitting planes.

    Build one with :func:`build_tree`. The arrays are the tree's flat storage (see
    :mod:`pixelpath.hsr._kernels.bsp`); do not modify them.

    Attributes
    ----------
    objects : tuple
        The scene objects the tree was built from.
    vertices, normals : (V, 3) float64
        Fragment vertices: those of the objects' triangles, then the ones made by cutting
        (their normals are interpolated, not renormalized, as clipping does).
    vertex_object : (V,) intp
        Object index of each vertex.
    cut_from : int
        Index of the first vertex made by cutting.
    source_vertex : (cut_from,) intp
        The scene geometry's vertex each of the first ``cut_from`` vertices is.
    blend_corners, blend_weights : (V - cut_from, 3)
        Each cut vertex as a blend of the corners of the triangle it was cut from.
    fragments : (F, 3) intp
        The triangles (whole or cut) the tree holds.
    fragment_object, fragment_polygon : (F,) intp
        The object of each fragment and the polygon of that object's mesh it belongs to.
    node_planes : (N, 4) float64
        Splitting plane of each node: unit normal n and offset d, n · x + d = 0.
    children : (N, 2) intp
        Back and front child of each node, -1 for none.
    item_first, item_count : (N,) intp; items : (I,) intp
        The fragments lying in each node's plane: ``items[first : first + count]``.
    node_object : (N,) intp
        For the nodes of infinite planes, the plane's object index; -1 for the others.
    triangles : int
        Triangles of the finite objects the tree was built from.
    depth : int
        Nodes on the longest path from the root.
    splits : int
        Triangles cut by a splitting plane.
    free_planes : int
        Nodes whose plane is an axis-aligned one rather than a polygon's.
    build_seconds : float
        Time the build took.

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> from pixelpath.hsr.bsp import build_tree
    >>> scene = Scene(Camera(eye=(3, 2, 4), target=(0, 0, 0)), objects=[Box((0, 0, 0), (1, 1, 1))])
    >>> tree = build_tree(scene)
    >>> tree.node_count, tree.fragment_count, tree.splits
    (6, 12, 0)
    """

    objects: tuple
    vertices: np.ndarray
    normals: np.ndarray
    vertex_object: np.ndarray
    cut_from: int
    source_vertex: np.ndarray
    blend_corners: np.ndarray
    blend_weights: np.ndarray
    fragments: np.ndarray
    fragment_object: np.ndarray
    fragment_polygon: np.ndarray
    node_planes: np.ndarray
    children: np.ndarray
    item_first: np.ndarray
    item_count: np.ndarray
    items: np.ndarray
    node_object: np.ndarray
    triangles: int
    depth: int
    splits: int
    free_planes: int
    build_seconds: float

    @property
    def node_count(self) -> int:
        """Number of nodes."""
        return len(self.node_planes)

    @property
    def fragment_count(self) -> int:
        """Number of fragments (triangles after cutting)."""
        return len(self.fragments)

    def order(self, eye: Any) -> np.ndarray:
        """Return the fragments back to front as seen from ``eye`` (infinite planes aside).

        ``eye`` is a point (x, y, z) or a homogeneous viewpoint (x, y, z, w) such as
        :meth:`Camera.viewpoint` (w = 0: an orthographic viewer at infinity).

        Examples
        --------
        >>> from pixelpath.scene import Camera, Mesh, Scene
        >>> from pixelpath.hsr.bsp import build_tree
        >>> near = [(-1, -1, 1), (1, -1, 1), (0, 1, 1)]
        >>> far = [(-1, -1, -1), (1, -1, -1), (0, 1, -1)]
        >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)),
        ...               objects=[Mesh(near, [[0, 1, 2]]), Mesh(far, [[0, 1, 2]])])
        >>> tree = build_tree(scene)
        >>> tree.fragment_object[tree.order((0, 0, 5))].tolist()  # the far one first
        [1, 0]
        >>> tree.fragment_object[tree.order((0, 0, -5))].tolist()
        [0, 1]
        >>> tree.fragment_object[tree.order((0, 0, -1, 0))].tolist()  # from -z, orthographic
        [0, 1]
        """
        from pixelpath.raster._arrays import kernel_array

        eye = kernel_array(eye)
        if eye.shape == (3,):
            eye = np.append(eye, 1.0)
        if eye.shape != (4,) or not np.all(np.isfinite(eye)):
            raise ValueError(
                f"eye must be a finite point (x, y, z) or (x, y, z, w), got {eye.tolist()!r}"
            )
        empty = np.zeros(self.node_count, dtype=np.intp)
        sequence, _ = self._traverse(eye, empty, empty, np.empty(0, dtype=np.intp))
        return sequence

    def _traverse(self, eye, extra_first, extra_count, extra_items):
        """(polygons back to front, nodes visited), with per-node extra polygons."""
        from pixelpath.hsr._kernels import bsp as kernels

        order = np.empty(len(self.items) + len(extra_items), dtype=np.intp)
        drawn, visited = kernels.traverse(
            self.node_planes, self.children, self.item_first, self.item_count, self.items,
            extra_first, extra_count, extra_items, eye, order,
        )
        return order[:drawn], int(visited)

    def __str__(self) -> str:
        return (
            f"BSP tree of {self.triangles:,} triangles: {self.node_count:,} nodes, depth "
            f"{self.depth}, {self.splits:,} split, {self.fragment_count:,} fragments, built in "
            f"{1000 * self.build_seconds:.0f} ms"
        )


def render_frame(
    scene: Scene, view: View, options: RenderOptions, tree: BSPTree | None = None
) -> Frame:
    """Render ``view`` of ``scene`` with the BSP-tree method.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera and region to render.
    options : RenderOptions
        Shading, culling, Blinn-Phong, progress, explain.
    tree : BSPTree, optional
        The scene's tree (from :func:`build_tree`); by default the cached one, built on the
        first render of these objects.

    Returns
    -------
    Frame
        With ``options.explain``, its report describes the tree and the traversal;
        ``report.arrays`` holds the painter's keys (``"order"``, ``"triangles"``,
        ``"object"``, ``"split"``: here a fragment cut by a splitting plane), the node of
        every drawable triangle (``"node"``), the tree's back and front children
        (``"children"``, -1 for none) and whether the eye is in front of each node's plane
        (``"eye in front"``).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.bsp import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    from pixelpath.hsr._kernels import bsp as kernels
    from pixelpath.raster.tessellate import scene_geometry

    if tree is None:
        tree, reused = _cached_tree(scene)
    elif not isinstance(tree, BSPTree):
        raise TypeError(f"tree must be a BSPTree (see build_tree), got {type(tree).__name__}")
    elif tree.objects is not scene.objects and tree.objects != scene.objects:
        raise ValueError("tree was built for other objects than this scene's")
    else:
        reused = True
    drawing = _drawing(tree, scene_geometry(scene, view.camera))
    prepared = pipeline.prepare(scene, view, options, drawing.geometry, drawing.blends)
    sequence, visited = tree._traverse(
        view.camera.viewpoint(), drawing.extra_first, drawing.extra_count, drawing.extra_items
    )
    order = np.empty(len(prepared.triangles), dtype=np.intp)
    drawn = kernels.draw_order(sequence, prepared.source, len(drawing.geometry.triangles), order)
    options.progress(1)
    visibility = pipeline.paint(prepared, view, order[:drawn])
    options.progress(1)
    report = None
    if options.explain:
        report = _report(tree, reused, prepared, drawing, visited, drawn, visibility)
        report.arrays.update(_order_arrays(tree, prepared, drawing, view, order[:drawn]))
    return pipeline.shade(prepared, scene, view, visibility, options, report)


class _Drawing(NamedTuple):
    """What one camera draws: the fragments plus the infinite planes' grid pieces."""

    geometry: Any  # SceneGeometry of the fragments, then the grid pieces
    blends: tuple[np.ndarray, np.ndarray, np.ndarray] | None
    extra_first: np.ndarray  # per node: its grid pieces, items[first : first + count]
    extra_count: np.ndarray
    extra_items: np.ndarray  # triangle indices in ``geometry``


def build_tree(scene: Scene) -> BSPTree:
    """Return the BSP tree of ``scene``'s objects, building it on first use.

    The tree depends on the objects only: later calls for a scene with the same objects (the
    same tuple, as ``dataclasses.replace(scene, camera=...)`` keeps it) return the same tree,
    and rendering with ``method="bsp"`` uses it from any camera.

    Parameters
    ----------
    scene : Scene

    Returns
    -------
    BSPTree

    Examples
    --------
    >>> import dataclasses
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> from pixelpath.hsr.bsp import build_tree
    >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), objects=[Box((0, 0, 0), (1, 1, 1))])
    >>> tree = build_tree(scene)
    >>> tree.triangles, tree.fragment_count >= tree.triangles  # a box's 6 faces, 2 triangles each
    (12, True)
    >>> moved = dataclasses.replace(scene, camera=Camera(eye=(5, 0, 0), target=(0, 0, 0)))
    >>> build_tree(moved) is tree
    True
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a pixelpath Scene, got {type(scene).__name__}")
    return _cached_tree(scene)[0]


def _cached_tree(scene: Scene) -> tuple[BSPTree, bool]:
    """Return the scene's tree and whether it was built before this call."""
    from pixelpath.raster.tessellate import _IdentityCache, member_ids

    global _TREES
    if _TREES is None:
        _TREES = _IdentityCache(8, member_ids)
    built = []

    def build(objects):
        built.append(True)
        return _build(scene)

    tree = _TREES.get(scene.objects, build)
    return tree, not built


_TREES = None  # the last few trees, keyed by the scene's objects (their identities, in order)


def _build(scene: Scene) -> BSPTree:
    """Tessellate the finite objects, set up the infinite planes, run the build kernel."""
    from pixelpath.hsr._kernels import bsp as kernels
    from pixelpath.raster.tessellate import scene_geometry

    start = time.perf_counter()
    geometry = scene_geometry(scene)
    plane_objects = np.array(
        [k for k, obj in enumerate(scene.objects) if isinstance(obj, Plane)], dtype=np.intp
    )
    triangle_object = geometry.polygon_object[geometry.triangle_polygon]
    finite = np.flatnonzero(~np.isin(triangle_object, plane_objects))
    used, local = np.unique(geometry.triangles[finite], return_inverse=True)
    triangles = np.ascontiguousarray(local.reshape(-1, 3), dtype=np.intp)
    vertices = geometry.vertices[used]
    planes, nonzero = _planes(vertices, triangles)
    finite, triangles = finite[nonzero], triangles[nonzero]
    infinite = np.array([_plane_row(scene.objects[k]) for k in plane_objects]).reshape(-1, 4)
    scale = max(float(np.abs(vertices).max(initial=0.0)), float(np.abs(infinite[:, 3]).max(
        initial=0.0)), 1.0)
    eps = PLANE_TOLERANCE * scale
    stats = np.zeros(kernels.STATS, dtype=np.int64)
    rows = np.ascontiguousarray(np.hstack([vertices, geometry.normals[used]]))
    (rows, count, blend_corners, blend_weights, fragments, source, node_planes, children, first,
     item_count, items, node_plane) = kernels.build(
        rows, triangles, planes, infinite, _relation(infinite, eps), eps, stats
    )
    # Keep only the fragments the nodes hold (a triangle that was cut is not drawn itself).
    fragments, source = fragments[items], source[items]
    items = np.arange(len(items), dtype=np.intp)
    polygon = geometry.triangle_polygon[finite[source]]
    fragment_object = geometry.polygon_object[polygon]
    polygon_start = np.searchsorted(geometry.polygon_object, np.arange(len(scene.objects)))
    vertex_object = geometry.vertex_object[used]
    cut_object = vertex_object[blend_corners[:, 0]]
    return BSPTree(
        objects=scene.objects,
        vertices=np.ascontiguousarray(rows[:count, :3]),
        normals=np.ascontiguousarray(rows[:count, 3:]),
        vertex_object=np.concatenate([vertex_object, cut_object]),
        cut_from=len(used),
        source_vertex=used,
        blend_corners=blend_corners,
        blend_weights=blend_weights,
        fragments=fragments,
        fragment_object=fragment_object,
        fragment_polygon=polygon - polygon_start[fragment_object],
        node_planes=node_planes,
        children=children,
        item_first=first,
        item_count=item_count,
        items=items,
        node_object=_node_objects(node_plane, plane_objects),
        triangles=len(triangles),
        depth=int(stats[kernels.DEPTH]),
        splits=int(stats[kernels.SPLITS]),
        free_planes=int(stats[kernels.FREE]),
        build_seconds=time.perf_counter() - start,
    )


def _node_objects(node_plane: np.ndarray, plane_objects: np.ndarray) -> np.ndarray:
    """Object index of each node's infinite plane (-1 for finite nodes)."""
    objects = np.full(len(node_plane), -1, dtype=np.intp)
    infinite = node_plane >= 0
    objects[infinite] = plane_objects[node_plane[infinite]]
    return objects


def _planes(vertices: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the planes (unit normal, offset) of the triangles of non-zero area, and which."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a)
    length = np.linalg.norm(normal, axis=1)
    nonzero = length > 0
    unit = normal[nonzero] / length[nonzero, None]
    planes = np.empty((len(unit), 4))
    planes[:, :3] = unit
    planes[:, 3] = -np.einsum("ij,ij->i", unit, a[nonzero])
    return planes, nonzero


def _plane_row(plane: Plane) -> np.ndarray:
    return np.array([*plane.normal, -float(plane.normal @ plane.point)])


def _relation(infinite: np.ndarray, eps: float) -> np.ndarray:
    """(P, P) int8: 0 where planes k and j cross, else the side of plane j that k lies on.

    Exactly parallel planes only (equal or opposite normals); coincident ones count as in
    front.
    """
    count = len(infinite)
    relation = np.zeros((count, count), dtype=np.int8)
    for k in range(count):
        for j in range(count):
            if j == k or np.any(np.cross(infinite[k, :3], infinite[j, :3]) != 0):
                continue
            # A point of plane k, and its side of plane j.
            point = -infinite[k, 3] * infinite[k, :3]
            relation[k, j] = -1 if infinite[j, :3] @ point + infinite[j, 3] < -eps else 1
    return relation


def _drawing(tree: BSPTree, geometry) -> _Drawing:
    """Return the fragments and this camera's infinite-plane pieces as one geometry.

    Cached per scene geometry (that is, per set of objects and, with planes, camera position).
    """
    global _DRAWINGS
    if _DRAWINGS is None:
        from pixelpath.raster.tessellate import _IdentityCache

        _DRAWINGS = _IdentityCache(8)
    cached = _DRAWINGS.get(geometry, lambda _: {})
    drawing = cached.get(id(tree))
    if drawing is None:
        drawing = _assemble(tree, geometry)
        cached.clear()
        cached[id(tree)] = drawing
    return drawing


_DRAWINGS = None  # per scene geometry: the drawing of the tree last drawn with it


def _assemble(tree: BSPTree, geometry) -> _Drawing:
    """Join the tree's fragments and the grid pieces of the infinite planes (routed per node)."""
    from pixelpath.hsr._kernels import bsp as kernels
    from pixelpath.raster.tessellate import SceneGeometry

    polygon_start = np.searchsorted(geometry.polygon_object, np.arange(len(geometry.meshes)))
    vertices, normals, vertex_object = [tree.vertices], [tree.normals], [tree.vertex_object]
    sources = [tree.source_vertex, np.full(len(tree.blend_corners), -1)]
    triangles = [tree.fragments]
    polygons = [polygon_start[tree.fragment_object] + tree.fragment_polygon]
    cut_rows = [tree.cut_from + np.arange(len(tree.blend_corners))]
    corners, weights = [tree.blend_corners], [tree.blend_weights]
    nodes = tree.node_count
    extra_first = np.zeros(nodes, dtype=np.intp)
    extra_count = np.zeros(nodes, dtype=np.intp)
    extra_items = np.empty(0, dtype=np.intp)
    plane_nodes = tree.node_object >= 0
    if plane_nodes.any():
        triangle_object = geometry.polygon_object[geometry.triangle_polygon]
        grid = np.flatnonzero(np.isin(triangle_object, tree.node_object[plane_nodes]))
        used, local = np.unique(geometry.triangles[grid], return_inverse=True)
        plane_index = np.searchsorted(np.unique(tree.node_object[plane_nodes]),
                                      triangle_object[grid])
        rows = np.ascontiguousarray(np.hstack([geometry.vertices[used], geometry.normals[used]]))
        infinite = _node_planes_index(tree)
        (rows, count, grid_corners, grid_weights, pieces, piece_node, piece_source) = (
            kernels.route_planes(
                tree.node_planes, tree.children, infinite, rows,
                np.ascontiguousarray(local.reshape(-1, 3), dtype=np.intp), plane_index,
                PLANE_TOLERANCE * max(1.0, float(np.abs(rows[:, :3]).max(initial=0.0))),
            )
        )
        offset = len(tree.vertices)
        grid_object = geometry.vertex_object[used]
        vertices.append(rows[:count, :3])
        normals.append(rows[:count, 3:])
        vertex_object += [grid_object, grid_object[grid_corners[:, 0]]]
        sources += [used, np.full(len(grid_corners), -1)]
        triangles.append(pieces + offset)
        polygons.append(geometry.triangle_polygon[grid[piece_source]])
        cut_rows.append(offset + len(used) + np.arange(len(grid_corners)))
        corners.append(grid_corners + offset)
        weights.append(grid_weights)
        by_node = np.argsort(piece_node, kind="stable")
        extra_count = np.bincount(piece_node, minlength=nodes).astype(np.intp)
        extra_first = (np.cumsum(extra_count) - extra_count).astype(np.intp)
        extra_items = (len(tree.fragments) + by_node).astype(np.intp)
    blends = None
    if sum(len(rows) for rows in cut_rows):
        blends = (np.concatenate(cut_rows), np.concatenate(corners), np.concatenate(weights))
    drawn = SceneGeometry(
        vertices=np.ascontiguousarray(np.concatenate(vertices)),
        normals=np.ascontiguousarray(np.concatenate(normals)),
        triangles=np.ascontiguousarray(np.concatenate(triangles), dtype=np.intp),
        triangle_polygon=np.concatenate(polygons).astype(np.intp),
        polygon_normals=geometry.polygon_normals,
        polygon_points=geometry.polygon_points,
        polygon_object=geometry.polygon_object,
        vertex_object=np.concatenate(vertex_object).astype(np.intp),
        materials=geometry.materials,
        meshes=geometry.meshes,
        surfaces=geometry.surfaces,
        uv=_carried(geometry.uv, sources, blends),
        colors=_carried(geometry.colors, sources, blends),
        double_sided=geometry.double_sided,
        emission=geometry.emission,
    )
    return _Drawing(drawn, blends, extra_first, extra_count, extra_items)


def _carried(values: np.ndarray, sources: list[np.ndarray], blends) -> np.ndarray:
    """Carry a per-vertex attribute of the scene geometry over to the fragments' vertices.

    Whole vertices take their source's value (``sources``, -1 for cut ones); cut vertices the
    blend of the corners they were cut between, as Gouraud colours do (see pipeline.prepare).
    """
    if len(values) == 0:
        return values
    carried = values[np.maximum(np.concatenate(sources), 0)]
    if blends is not None:
        rows, corners, weights = blends
        carried[rows] = np.einsum("nk,nkc->nc", weights, carried[corners])
    return np.ascontiguousarray(carried)


def _node_planes_index(tree: BSPTree) -> np.ndarray:
    """Per node: the index of its infinite plane among the tree's planes, -1 for finite nodes."""
    planes = np.unique(tree.node_object[tree.node_object >= 0])
    index = np.full(tree.node_count, -1, dtype=np.intp)
    infinite = tree.node_object >= 0
    index[infinite] = np.searchsorted(planes, tree.node_object[infinite])
    return index


def _order_arrays(tree: BSPTree, prepared: pipeline.Prepared, drawing: _Drawing, view: View,
                  order: np.ndarray) -> dict[str, np.ndarray]:
    """Return the drawing order and the tree's shape for the figures (see render_frame)."""
    from pixelpath.hsr.painter import order_arrays

    count = len(drawing.geometry.triangles)
    node_of = np.full(count, -1, dtype=np.intp)
    for lists in ((tree.item_first, tree.item_count, tree.items),
                  (drawing.extra_first, drawing.extra_count, drawing.extra_items)):
        owners, members = _members(*lists)
        node_of[members] = owners
    source = prepared.source
    fragment = source < len(tree.fragments)
    cut = np.zeros(len(source), dtype=bool)
    cut[fragment] = (tree.fragments[source[fragment]] >= tree.cut_from).any(axis=1)
    eye = view.camera.viewpoint()
    arrays = order_arrays(prepared, view, order, cut)
    arrays.update({
        "node": node_of[source],
        "children": tree.children.copy(),
        "eye in front": tree.node_planes[:, :3] @ eye[:3] + tree.node_planes[:, 3] * eye[3] >= 0,
    })
    return arrays


def _members(first: np.ndarray, count: np.ndarray, items: np.ndarray):
    """(owner, item) pairs of per-node lists ``items[first[n] : first[n] + count[n]]``."""
    owner = np.repeat(np.arange(len(count)), count)
    starts = np.repeat(first - (np.cumsum(count) - count), count)
    return owner, items[np.arange(len(owner)) + starts]


def _report(tree, reused, prepared, drawing, visited, drawn, visibility):
    """Report the build (nodes, depth, splits) and the traversal (nodes visited, drawn)."""
    from pixelpath.report import Report

    plane_pieces = len(drawing.extra_items)
    summary = {
        **{k: v for k, v in prepared.stats.items() if k != "triangles scan-converted"},
        "tree": "reused (built once for these objects)" if reused else "built for this render",
        "tree build time (ms)": round(1000 * tree.build_seconds, 1),
        "triangles in the tree": tree.triangles,
        "triangles split": tree.splits,
        "fragments": tree.fragment_count,
        "nodes": tree.node_count,
        "nodes on infinite planes": int(np.count_nonzero(tree.node_object >= 0)),
        "nodes with a free (axis-aligned) plane": tree.free_planes,
        "depth": tree.depth,
        "nodes visited": visited,
        "infinite-plane pieces this camera": plane_pieces,
        "triangles painted": drawn,
        "pixels drawn": int(np.count_nonzero(visibility.triangle_id >= 0)),
    }
    return Report(
        method="bsp",
        summary=summary,
        notes=(
            "object space: the tree is built once for the scene's objects, splitting polygons "
            "that straddle a splitting plane; image space: its polygons are painted back to "
            "front, in the order of a traversal from the eye, with no depth test",
            "at a node with the eye in front of its plane: back subtree, the node's polygons, "
            "front subtree (the reverse when the eye is behind)",
        ),
    )
