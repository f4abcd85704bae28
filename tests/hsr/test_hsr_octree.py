"""The octree method's own parts: front-to-back order, early termination, the report's counts."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.hsr import octree, pipeline
from pixelpath.hsr._kernels import octree as kernels
from pixelpath.renderer import RenderOptions, View
from pixelpath.scene import icosphere


def popcount(value: int) -> int:
    return bin(value).count("1")


@pytest.mark.parametrize("signs", list(itertools.product((-1, 1), repeat=3)))
def test_children_come_front_to_back_for_an_eye_in_every_octant(signs):
    center = np.array([0.5, -1.0, 2.0])
    eye = center + 3.0 * np.array(signs)
    order = octree.front_to_back(eye, center).tolist()
    eye_child = sum(1 << axis for axis in range(3) if signs[axis] > 0)
    assert sorted(order) == list(range(8))
    assert order[0] == eye_child and order[-1] == 7 - eye_child
    # Planes between each child and the eye's: 0, then three 1s, three 2s, one 3.
    assert [popcount(child ^ eye_child) for child in order] == [0, 1, 1, 1, 2, 2, 2, 3]


def test_children_order_by_hand():
    # Eye above, right and in front of the centre: the (+x, +y, +z) child first, then the
    # three sharing a face with it, x's neighbour first; the (-x, -y, -z) child last.
    assert octree.front_to_back((5, 5, 5), (0, 0, 0)).tolist() == [7, 6, 5, 3, 4, 2, 1, 0]
    assert octree.front_to_back((-5, 5, -5), (0, 0, 0)).tolist() == [2, 3, 0, 6, 1, 7, 4, 5]


def cells_met(lows, highs, eye, direction):
    """Indices of the boxes a ray meets, in the order it enters them (slab test)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (lows - eye) / direction
        t1 = (highs - eye) / direction
    near = np.nanmax(np.minimum(t0, t1), axis=1)
    far = np.nanmin(np.maximum(t0, t1), axis=1)
    hit = far >= np.maximum(near, 0.0)
    entry = np.maximum(near, 0.0)
    met = np.flatnonzero(hit)
    return met[np.argsort(entry[met], kind="stable")], entry


def test_random_rays_meet_the_children_in_the_order_given():
    rng = np.random.default_rng(1)
    for _ in range(200):
        center = rng.uniform(-1, 1, 3)
        half = rng.uniform(0.2, 2.0)
        eye = center + rng.uniform(-4, 4, 3)  # outside or inside the cell
        order = octree.front_to_back(eye, center)
        position = np.argsort(order)  # position[child] = its place in the order
        bits = (np.arange(8)[:, None] >> np.arange(3)) & 1
        lows = center - half + bits * half
        highs = lows + half
        for direction in rng.normal(size=(50, 3)):
            met, entry = cells_met(lows, highs, eye, direction)
            places = position[met]
            # Cells entered at distinct points must come in ray order.
            for a, b in itertools.pairwise(met):
                if entry[b] > entry[a] + 1e-12:
                    assert position[a] < position[b], (eye, center, direction, places)


def ring_of_spheres(eye=(0.3, 1.5, 6.0), size=(64, 48), radius=0.5):
    objects = [
        icosphere(2, radius, (np.cos(a) * 2.0, 0.4 * np.sin(3 * a), np.sin(a) * 2.0),
                  pp.Material(color=(0.8, 0.5, 0.3)))
        for a in np.linspace(0, 2 * np.pi, 9)[:-1]
    ]
    camera = pp.Camera(eye=eye, target=(0, 0, 0), fov=50, width=size[0], height=size[1])
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((3, 5, 4))])


def built_tree(scene, leaf_size=8):
    view = View.whole(scene.camera)
    prepared = pipeline.prepare(scene, view, RenderOptions(backface_cull=False))
    return octree.build_octree(prepared, view, leaf_size=leaf_size), prepared


def test_random_rays_meet_the_leaves_of_a_real_tree_in_traversal_order():
    scene = ring_of_spheres()
    tree = built_tree(scene)[0]
    assert tree.depth >= 3
    rng = np.random.default_rng(2)
    leaves = np.flatnonzero(tree.is_leaf)
    lows = tree.corners[leaves]
    highs = lows + tree.sides[leaves, None]
    for eye in [scene.camera.eye, np.array([0.1, 0.2, -0.3]), rng.uniform(-3, 3, 3)]:
        order = kernels.leaf_order(tree.tree, np.append(eye, 1.0))
        assert sorted(order.tolist()) == leaves.tolist()
        place = {leaf: k for k, leaf in enumerate(order.tolist())}
        for direction in rng.normal(size=(300, 3)):
            met, entry = cells_met(lows, highs, eye, direction)
            for a, b in itertools.pairwise(met):
                if entry[b] > entry[a] + 1e-12:
                    assert place[leaves[a]] < place[leaves[b]]


def test_every_triangle_lies_in_the_leaves_that_hold_it():
    tree, prepared = built_tree(ring_of_spheres(), leaf_size=4)
    corners = prepared.positions[prepared.triangles]
    holders = {}
    for leaf in np.flatnonzero(tree.is_leaf):
        for t in tree.triangles_of(leaf):
            holders.setdefault(int(t), []).append(leaf)
    # Every triangle covering a pixel row and column span of the image is stored, and every
    # point of it lies in a leaf that holds it.
    xs = prepared.screen[prepared.triangles, 0]
    covering = (prepared.rows[:, 0] < prepared.rows[:, 1]) & (xs.max(1) > 0) & (xs.min(1) < 64)
    assert covering.sum() > 1000
    assert sorted(holders) == np.flatnonzero(covering).tolist()
    rng = np.random.default_rng(3)
    for t, leaves in holders.items():
        weights = rng.dirichlet((1, 1, 1), size=5)
        points = weights @ corners[t]
        lows = tree.corners[leaves]
        inside = (points[:, None] >= lows - 1e-12) & (
            points[:, None] <= lows + tree.sides[leaves, None] + 1e-12
        )
        assert inside.all(axis=2).any(axis=1).all()


def near_wall_scene(size=(64, 48)):
    """A wall filling the view right in front of the camera, a ring of spheres behind it."""
    scene = ring_of_spheres(eye=(0.0, 0.0, 6.0), size=size, radius=0.9)
    wall = pp.Mesh([[-3, -3, 4.5], [3, -3, 4.5], [3, 3, 4.5], [-3, 3, 4.5]], [[0, 1, 2, 3]],
                   pp.Material(color=(0.2, 0.3, 0.9)))
    return pp.Scene(scene.camera, objects=[wall, *scene.objects], lights=scene.lights)


def test_a_near_wall_ends_the_traversal_early():
    scene = near_wall_scene()
    image, report = pp.render(scene, "octree", explain=True)
    reference, zreport = pp.render(scene, "zbuffer", explain=True)
    assert (image.object_id == 0).all() and np.array_equal(image.object_id, reference.object_id)
    assert np.array_equal(image.depth, reference.depth)
    summary = report.summary
    pixels = image.object_id.size
    # Every pixel is decided in the wall's cells, the cells behind are skipped unvisited ...
    assert summary["pixels decided early"] == pixels
    assert summary["skipped: their pixels all decided"] > 0
    # ... so the spheres' front faces (over a thousand triangles, covering over half of the
    # image behind the wall) are hardly drawn: only those sharing a leaf with the wall.
    spheres = summary["triangles scan-converted"] - 2
    assert spheres > 1000
    assert summary["triangles drawn (once per leaf)"] < 0.05 * spheres
    assert zreport.summary["depth tests (pixels covered by some triangle)"] > 1.3 * pixels
    assert summary["pixel samples depth-tested"] < 1.05 * pixels


def two_squares_scene():
    """A near square filling the view (octant +x +y +z of the root), a far one behind it.

    The root cube is [-0.9, 0.9]^3, so its centre (the splitting point) is the origin: the
    near square lies in child 7 and the far one in child 0.
    """
    def square(low, high, z, color):
        return pp.Mesh([[low, low, z], [high, low, z], [high, high, z], [low, high, z]],
                       [[0, 1, 2, 3]], pp.Material(color=color))

    camera = pp.Camera(eye=(0.5, 0.5, 1.5), target=(0.5, 0.5, 0.0), fov=60, width=32, height=32)
    objects = [square(0.1, 0.9, 0.9, (1, 0, 0)), square(-0.9, -0.1, -0.9, (0, 1, 0))]
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((0, 0, 5))])


def test_report_counts_on_a_hand_scene(monkeypatch):
    # Leaves of one triangle at most: the root splits once; the near square's child is too
    # small to split further (its two triangles would each go into four grandchildren).
    monkeypatch.setattr(octree, "LEAF_SIZE", 1)
    image, report = pp.render(two_squares_scene(), "octree", explain=True)
    summary = report.summary
    assert (image.object_id == 0).all()  # 32 x 32 = 1024 pixels, all the near square's
    expected = {
        "nodes built": 3,  # the root and its children 7 and 0
        "leaves": 2,
        "tree depth": 1,
        "triangles stored in leaves (once per leaf)": 4,
        "traversals (one per band of 32 rows)": 1,
        "nodes visited": 2,  # the root, then child 7 (in front)
        "culled by the view frustum": 0,
        "skipped: their pixels all decided": 1,  # child 0, behind the near square
        "triangles drawn (once per leaf)": 2,
        "pixel samples depth-tested": 1024,
        "pixels decided early": 1024,
        "pixels drawn": 1024,
    }
    assert {key: summary[key] for key in expected} == expected
    table = report.tables[0]
    assert [row[:6] for row in table.rows] == [(0, 1, 0, 1, 0, 0), (1, 2, 2, 1, 0, 1)]
    assert [row[6:] for row in table.rows] == [(0, 0), (2, 1024)]


def test_report_counts_when_the_root_is_a_leaf():
    # Default leaf size: both squares share the root, so the far one is drawn too (its
    # pixels are tested before the leaf's hits are decided).
    scene = two_squares_scene()
    _, report = pp.render(scene, "octree", explain=True)
    far_alone = pp.Scene(scene.camera, objects=[scene.objects[1]], lights=scene.lights)
    far_pixels = int((pp.render(far_alone).object_id == 0).sum())
    assert far_pixels > 0
    summary = report.summary
    assert (summary["nodes built"], summary["nodes visited"], summary["tree depth"]) == (1, 1, 0)
    assert summary["triangles drawn (once per leaf)"] == 4
    assert summary["pixel samples depth-tested"] == 1024 + far_pixels
    assert summary["pixels decided early"] == 1024


def test_cells_outside_the_frustum_are_culled():
    # Spheres all around the camera. Only triangles covering a pixel are stored, but the
    # boxes of those at the image's border reach into cells wholly outside the view.
    objects = [icosphere(3, 0.5, (3 * np.cos(a), 0.0, 3 * np.sin(a)))
               for a in np.linspace(0, 2 * np.pi, 13)[:-1]]
    camera = pp.Camera(eye=(0, 0.05, 0.05), target=(0, 0, -1), fov=40, width=48, height=32)
    scene = pp.Scene(camera, objects=objects, lights=[pp.PointLight((0, 3, 0))])
    image, report = pp.render(scene, "octree", explain=True)
    assert report.summary["culled by the view frustum"] > 0
    assert np.array_equal(image.object_id, pp.render(scene).object_id)


def test_an_empty_view_draws_nothing():
    scene = two_squares_scene()
    away = pp.Camera(eye=(0.5, 0.5, 1.5), target=(0.5, 0.5, 3.0), width=16, height=8)
    image, report = pp.render(pp.Scene(away, objects=scene.objects), "octree", explain=True)
    assert (image.object_id == -1).all() and np.isinf(image.depth).all()
    assert report.summary["pixels drawn"] == 0


def test_progress_reports_every_step():
    steps = []
    pp.render(two_squares_scene(), "octree", progress=steps.append)
    assert sum(steps) == octree.STEPS
