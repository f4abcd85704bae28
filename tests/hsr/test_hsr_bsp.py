"""The BSP-tree method: the tree's size and splits on hand cases, traversal order, reuse."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from agreement import check_agreement, scene_of

import pixelpath as pp
from pixelpath.hsr.bsp import BSPTree, build_tree, render_frame
from pixelpath.raster.tessellate import scene_geometry
from pixelpath.renderer import RenderOptions, View

CAMERA = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=64, height=64)
# The flat triangle z = -1 (counter-clockwise seen from +z) and one on the plane z = 2 y - 1
# crossing it: FLAT's corners give z - 2 y + 1 = 2, 2, -2, CROSSING's give z + 1 = -1, -1, 1.
FLAT = [(-1, -1, -1), (1, -1, -1), (0, 1, -1)]
CROSSING = [(-1, -0.5, -2), (1, -0.5, -2), (0, 0.5, 0)]


def scene_with(*objects, camera=CAMERA) -> pp.Scene:
    return pp.Scene(camera, objects=list(objects), lights=[pp.PointLight((0, 0, 6))])


def triangle(points) -> pp.Mesh:
    return pp.Mesh(points, [[0, 1, 2]])


def crossing_pair() -> pp.Scene:
    return scene_with(triangle(FLAT), triangle(CROSSING))


def test_a_box_makes_a_chain_of_its_faces():
    # A convex solid has every other face behind each face's plane: whichever face splits
    # first, its two triangles stay at the node and the other ten go behind; six nodes in a
    # chain, nothing cut (12 triangles are too few to try axis-aligned planes).
    tree = build_tree(scene_with(pp.Box((0, 0, 0), (1, 1, 1))))
    assert (tree.node_count, tree.depth, tree.splits, tree.free_planes) == (6, 6, 0, 0)
    assert tree.fragment_count == 12
    assert tree.item_count.tolist() == [2] * 6


def test_crossing_triangles_make_three_nodes_and_one_split():
    # The candidates score alike (one split, no imbalance); the first, FLAT's plane z = -1,
    # wins. CROSSING is cut there: its corner (0, 0.5, 0) alone in front (one piece), the
    # other two behind (two pieces, coplanar: one node).
    tree = build_tree(crossing_pair())
    assert (tree.node_count, tree.depth, tree.splits, tree.free_planes) == (3, 2, 1, 0)
    assert tree.fragment_count == 4
    assert np.allclose(tree.node_planes[0], [0, 0, 1, 1])
    assert tree.fragment_object.tolist().count(1) == 3


def test_traversal_order_follows_the_eye():
    tree = build_tree(crossing_pair())
    tip = np.flatnonzero(tree.vertices[tree.fragments][:, :, 2].max(axis=1) > -1 + 1e-9)
    assert len(tip) == 1
    # Eye in front of z = -1: the two pieces behind it, then FLAT, then the tip.
    front = tree.order((0, 0, 5))
    assert tree.fragment_object[front].tolist() == [1, 1, 0, 1]
    assert front[-1] == tip[0]
    # Eye behind: the tip, FLAT, then the two pieces.
    back = tree.order((0, 0, -5))
    assert tree.fragment_object[back].tolist() == [1, 0, 1, 1]
    assert back[0] == tip[0]


def reference_order(tree: BSPTree, eye) -> list[int]:
    """The notes' recursive traversal: far subtree, the node's polygons, near subtree."""

    def visit(node):
        if node < 0:
            return []
        plane = tree.node_planes[node]
        in_front = plane[:3] @ eye + plane[3] > 0
        far, near = tree.children[node, 0 if in_front else 1], tree.children[node,
                                                                          1 if in_front else 0]
        first, count = tree.item_first[node], tree.item_count[node]
        own = tree.items[first : first + count][::-1].tolist()
        return visit(far) + own + visit(near)

    return visit(0)


# The interpenetrating scene's tree takes 10 s to build without the JIT: the main pass only.
@pytest.mark.parametrize(
    "kind", [pytest.param("interpenetrating", marks=pytest.mark.slow), "separate"]
)
def test_traversal_matches_the_recursive_definition(kind):
    tree = build_tree(scene_of(kind, seed=8))
    rng = np.random.default_rng(8)
    for eye in rng.uniform(-6, 6, (5, 3)):
        assert tree.order(eye).tolist() == reference_order(tree, eye)


def polygon_areas(vertices, triangles, polygon, count) -> np.ndarray:
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    return np.bincount(polygon, weights=area, minlength=count)


# Seed 1's tree takes 14 s to build without the JIT: the main pass only.
@pytest.mark.parametrize("seed", [pytest.param(1, marks=pytest.mark.slow), 2])
def test_splitting_keeps_area_and_every_fragment_on_its_side(seed):
    scene = scene_of("interpenetrating", seed)
    tree = build_tree(scene)
    assert tree.splits > 0
    geometry = scene_geometry(scene)
    polygons = len(geometry.polygon_object)
    start = np.searchsorted(geometry.polygon_object, np.arange(len(scene.objects)))
    fragment_polygon = start[tree.fragment_object] + tree.fragment_polygon
    whole = polygon_areas(geometry.vertices, geometry.triangles, geometry.triangle_polygon,
                          polygons)
    pieces = polygon_areas(tree.vertices, tree.fragments, fragment_polygon, polygons)
    assert np.allclose(pieces, whole, rtol=1e-9, atol=1e-12)
    # Every fragment lies in its node's plane and on one side of every plane above it.
    eps = 1e-9 * np.abs(tree.vertices).max()
    corners = tree.vertices[tree.fragments]  # (F, 3, 3)
    pending = [(0, [])]
    seen = 0
    while pending:
        node, sides = pending.pop()
        first, count = tree.item_first[node], tree.item_count[node]
        held = tree.items[first : first + count]
        seen += len(held)
        plane = tree.node_planes[node]
        assert np.all(np.abs(corners[held] @ plane[:3] + plane[3]) <= eps)
        for ancestor, side in sides:
            distances = (corners[held] @ tree.node_planes[ancestor, :3]
                         + tree.node_planes[ancestor, 3])
            assert np.all(side * distances >= -eps)
        for branch, side in ((0, -1), (1, 1)):
            child = tree.children[node, branch]
            if child >= 0:
                pending.append((child, [*sides, (node, side)]))
    assert seen == tree.fragment_count


def test_tree_is_built_once_and_reused_from_another_camera():
    scene = scene_of("interpenetrating", seed=3)
    tree = build_tree(scene)
    other = pp.Camera(eye=(-4.0, 1.0, -3.5), target=(0.0, 0.3, 0.0), fov=45,
                      width=scene.camera.width, height=scene.camera.height)
    moved = dataclasses.replace(scene, camera=other)
    assert build_tree(moved) is tree
    _, report = pp.render(moved, "bsp", explain=True)
    assert report.summary["tree"].startswith("reused")
    assert report.summary["nodes"] == tree.node_count
    check_agreement(moved, "bsp")


def test_a_turntables_frames_reuse_the_first_frames_tree():
    from pixelpath.scene.animation import Animation, Turntable

    turning = dataclasses.replace(
        scene_of("interpenetrating", seed=5), animation=Animation(6, turntable=Turntable())
    )
    tree = build_tree(turning.at_frame(0))
    for frame in range(1, 6):
        scene = turning.at_frame(frame)  # a new Scene, holding a new tuple of the same objects
        assert build_tree(scene) is tree
        _, report = pp.render(scene, "bsp", explain=True)
        assert report.summary["tree"].startswith("reused")


def test_a_tree_kept_by_the_caller_draws_the_scene():
    scene = crossing_pair()
    tree = build_tree(scene)
    view = View.whole(CAMERA)
    frame = render_frame(scene, view, RenderOptions(), tree=tree)
    reference = pp.render(scene, "zbuffer")
    assert np.array_equal(frame.object_id, reference.object_id)


def test_report_of_the_crossing_pair():
    _, report = pp.render(crossing_pair(), "bsp", explain=True)
    summary = report.summary
    assert summary["triangles in the tree"] == 2
    assert summary["triangles split"] == 1
    assert summary["fragments"] == 4
    assert summary["nodes"] == 3
    assert summary["depth"] == 2
    assert summary["nodes visited"] == 3
    assert summary["triangles painted"] == 4  # all face the eye and lie in view


def test_an_infinite_plane_splits_first():
    # The plane cuts nothing of itself and divides the box's faces by side; the box above
    # it is a chain of its six faces in front of the plane.
    floor = pp.Plane((0, 0, 0), (0, 1, 0))
    box = pp.Box((-0.5, 0.5, -0.5), (0.5, 1.5, 0.5))
    scene = scene_with(box, floor, camera=pp.Camera(eye=(0, 2, 5), target=(0, 0, 0), width=64,
                                                     height=48))
    tree = build_tree(scene)
    assert tree.node_object.tolist() == [1, -1, -1, -1, -1, -1, -1]
    assert tree.children[0, 0] == -1  # nothing behind the floor
    assert tree.splits == 0
    check_agreement(scene, "bsp")


def test_bad_arguments():
    scene = crossing_pair()
    view = View.whole(CAMERA)
    with pytest.raises(TypeError, match="scene"):
        build_tree("scene")
    with pytest.raises(TypeError, match="tree"):
        render_frame(scene, view, RenderOptions(), tree="tree")
    other = build_tree(scene_with(triangle(FLAT)))
    with pytest.raises(ValueError, match="other objects"):
        render_frame(scene, view, RenderOptions(), tree=other)
    with pytest.raises(ValueError, match="eye"):
        build_tree(scene).order((0, 0))


def test_the_build_ends_when_rounding_puts_a_polygon_off_its_own_plane():
    # The splitter's triangle stays at its node even where its given plane misses its
    # corners (here by far more than rounding): each node takes at least that polygon.
    from pixelpath.hsr._kernels import bsp as kernels

    rows = np.hstack([np.array([*FLAT, *CROSSING], dtype=float), np.zeros((6, 3))])
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    planes = np.array([[0.0, 0.0, 1.0, 1.0], [-0.2, -0.8, 0.56, 0.97]])  # the second is off
    stats = np.zeros(kernels.STATS, dtype=np.int64)
    built = kernels.build(rows, triangles, planes, np.zeros((0, 4)),
                          np.zeros((0, 0), dtype=np.int8), 1e-9, stats)
    fragments, items = built[4], built[10]
    assert len(items) == len(fragments) - stats[kernels.SPLITS]  # every live piece is held
    assert stats[kernels.NODES] <= 3
