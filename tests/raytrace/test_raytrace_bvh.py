"""The BVH and ``intersect``: nearest hits equal a brute-force loop over every triangle."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.raytrace import BVH, intersect
from pixelpath.scene import icosphere, torus


def brute_force(vertices, triangles, origins, directions):
    """Nearest hit of each ray over all triangles by Möller-Trumbore in NumPy: (t, triangle).

    An independent reference: no tree, no shear; ties go to the lower triangle index.
    """
    corners = vertices[triangles]  # (T, 3, 3)
    e1 = corners[:, 1] - corners[:, 0]
    e2 = corners[:, 2] - corners[:, 0]
    best_t = np.full(len(origins), np.inf)
    best = np.full(len(origins), -1)
    for r, (o, d) in enumerate(zip(origins, directions, strict=True)):
        p = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, p)
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / det
            s = o - corners[:, 0]
            u = np.einsum("ij,ij->i", s, p) * inv
            q = np.cross(s, e1)
            v = (q @ d) * inv
            t = np.einsum("ij,ij->i", e2, q) * inv
            hit = (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        if hit.any():
            candidates = np.flatnonzero(hit)
            k = candidates[np.argmin(t[candidates])]
            best_t[r], best[r] = t[k], k
    return best_t, best


def random_rays(rng, count, spread=3.0):
    origins = rng.normal(size=(count, 3))
    origins *= spread / np.linalg.norm(origins, axis=1, keepdims=True)
    targets = rng.uniform(-0.8, 0.8, (count, 3))
    return origins, targets - origins


@pytest.mark.parametrize("seed", [0, 1])
def test_bvh_equals_brute_force_on_random_rays(seed):
    rng = np.random.default_rng(seed)
    ring = torus(0.7, 0.25, 24, 12).transformed(
        pp.scene.transform_matrix(rotate=rng.uniform(0, 360, 3))
    )
    vertices, triangles = ring.vertices, ring.triangles
    origins, directions = random_rays(rng, 400)
    t, triangle = BVH.build(vertices, triangles).intersect(origins, directions)
    expected_t, expected = brute_force(vertices, triangles, origins, directions)
    np.testing.assert_allclose(t, expected_t, rtol=1e-9)
    # Where two triangles are hit at (almost) the same t, both answers are right.
    different = triangle != expected
    assert np.all(np.isclose(t[different], expected_t[different], rtol=1e-9))
    assert different.mean() < 0.01
    assert 0.2 < np.isfinite(t).mean() < 1.0  # the rays both hit and miss


def test_coherent_rays_traced_four_at_a_time_equal_brute_force():
    # A camera's fan of rays, row by row: intersect traces runs of four neighbours as packets.
    ball = icosphere(2).transformed(pp.scene.transform_matrix(scale=(1.0, 0.6, 0.8)))
    xs = np.linspace(-0.9, 0.9, 23)
    gx, gy = np.meshgrid(xs, xs)
    directions = np.stack([gx.ravel(), gy.ravel(), -np.full(gx.size, 2.5)], axis=1)
    origins = np.broadcast_to([0.1, 0.05, 2.5], directions.shape)
    t, triangle = BVH.build(ball.vertices, ball.triangles).intersect(origins, directions)
    expected_t, expected = brute_force(ball.vertices, ball.triangles, origins, directions)
    np.testing.assert_allclose(t, expected_t, rtol=1e-9)
    assert np.all((triangle == expected) | np.isclose(t, expected_t, rtol=1e-9))
    assert 0.2 < np.isfinite(t).mean() < 1.0


def _grid(n=6):
    """An n × n grid of squares in z = 0, each cut into two triangles, and its vertex coords."""
    xs = np.arange(n + 1, dtype=float)
    gx, gy = np.meshgrid(xs, xs)
    vertices = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
    triangles = []
    for row in range(n):
        for col in range(n):
            v = row * (n + 1) + col
            triangles += [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]]
    return vertices, np.array(triangles)


def test_rays_through_shared_edges_and_vertices_always_hit():
    vertices, triangles = _grid()
    bvh = BVH.build(vertices, triangles)
    inner = vertices[(vertices[:, 0] > 0) & (vertices[:, 0] < 6) & (vertices[:, 1] > 0)
                     & (vertices[:, 1] < 6)]
    steps = np.array([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.5, 0.0], [0.5, 0.5, 0.0]])
    points = (inner[:, None, :] + steps).reshape(-1, 3)  # vertices, then edge midpoints
    rng = np.random.default_rng(3)
    for _ in range(5):
        tilt = rng.uniform(-0.7, 0.7, 3) * (1, 1, 0) + (0, 0, -1)  # oblique, downwards
        origins = points - 2.0 * tilt
        t, triangle = bvh.intersect(origins, tilt)
        assert np.all(triangle >= 0), "a ray through an edge or vertex fell between triangles"
        np.testing.assert_allclose(t, 2.0)
        np.testing.assert_allclose(origins + t[:, None] * tilt, points, atol=1e-12)


def test_intersect_reports_polygon_faces_and_misses():
    cube = pp.Box((-1, -1, -1), (1, 1, 1)).to_mesh()
    origins = [[0, 0, 5], [5, 0.3, 0.2], [0, -4, 0.5], [3, 3, 5]]
    directions = [[0, 0, -1], [-1, 0, 0], [0, 2, 0], [0, 0, -1]]
    t, face = intersect(cube, origins, directions)
    np.testing.assert_allclose(t, [4.0, 4.0, 1.5, math.inf])
    normals = cube.face_normals[face[:3]]
    np.testing.assert_allclose(normals, [[0, 0, 1], [1, 0, 0], [0, -1, 0]])
    assert face[3] == -1


def test_intersect_from_inside_hits_the_far_side():
    ball = icosphere(3)
    t, face = intersect(ball, np.zeros((3, 3)), np.eye(3))
    assert np.all(face >= 0)
    np.testing.assert_allclose(t, 1.0, atol=0.01)


def test_intersect_accepts_a_trimesh_like_object():
    class Soup:
        vertices = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, -1], [1, 0, -1], [0, 1, -1]])
        faces = np.array([[0, 1, 2], [3, 4, 5]])

    t, face = intersect(Soup(), [[0.2, 0.2, 3.0]], [[0, 0, -1]])
    assert t.tolist() == [pytest.approx(3.0)] and face.tolist() == [0]


@pytest.mark.slow  # the build loops in plain Python without the JIT
def test_bvh_of_a_large_mesh_is_shallow_and_cheap():
    ball = icosphere(5)  # 20,480 triangles
    stats = BVH.build(ball.vertices, ball.triangles).statistics()
    assert stats["triangles"] == 20480
    assert stats["depth"] <= 40
    assert stats["triangles per leaf"] <= 8
    # A ray through a well-built tree tests a few dozen triangles, not thousands.
    assert stats["SAH cost"] < 100


def coincident_and_scattered():
    """Forty copies of one triangle (coincident centroids: halved, not binned) among others."""
    rng = np.random.default_rng(2)
    vertices = rng.uniform(-1, 1, (60, 3))
    triangles = rng.integers(0, 60, (200, 3))
    triangles[50:90] = triangles[50]
    return vertices, triangles


@pytest.mark.parametrize(
    ("vertices", "triangles"),
    [
        (icosphere(3).vertices, icosphere(3).triangles),
        (torus(0.7, 0.25, 24, 12).vertices, torus(0.7, 0.25, 24, 12).triangles),
        coincident_and_scattered(),
    ],
    ids=["icosphere", "torus", "coincident"],
)
def test_bvh_nodes_bound_exactly_their_triangles(vertices, triangles):
    # The build takes a node's box from its parent's bins: it must be, bit for bit, the box of
    # the triangles below the node, and the leaves must hold every triangle once.
    bvh = BVH.build(vertices, triangles)
    assert np.array_equal(np.sort(bvh.order), np.arange(len(triangles)))
    corners = vertices[triangles][bvh.order]
    np.testing.assert_array_equal(bvh.corners, corners.reshape(-1, 9))
    low, high = corners.min(axis=1), corners.max(axis=1)
    expected = np.empty_like(bvh.bounds)
    covered = np.zeros(len(triangles), dtype=int)
    for k in range(len(bvh.links) - 1, -1, -1):  # children come after their parent
        first, count = bvh.links[k]
        if count:
            expected[k] = np.concatenate([low[first:first + count].min(0),
                                          high[first:first + count].max(0)])
            covered[first:first + count] += 1
        else:
            assert first > k
            pair = expected[first:first + 2]
            expected[k] = np.concatenate([pair[:, :3].min(0), pair[:, 3:].max(0)])
    np.testing.assert_array_equal(bvh.bounds, expected)
    assert np.all(covered == 1)


def test_coincident_centroids_still_build():
    tri = [[0, 1, 2]] * 40
    bvh = BVH.build([[0, 0, 0], [1, 0, 0], [0, 1, 0]], tri)
    t, triangle = bvh.intersect([0.2, 0.2, 1.0], [0, 0, -1])
    assert float(t) == 1.0 and int(triangle) == 0  # ties go to the first triangle


@pytest.mark.parametrize(
    ("mesh", "origins", "directions", "error", "message"),
    [
        (None, [[0, 0, 1]], [[0, 0, -1]], TypeError, "mesh"),
        ("cube", [[0, 0, 1]], [[0, 0, 0]], ValueError, "zero-length"),
        ("cube", [[0, np.nan, 1]], [[0, 0, -1]], ValueError, "origins"),
        ("cube", [[0, 0, 1]], [[0, 0, -1, 0]], ValueError, "directions"),
        ("bad faces", [[0, 0, 1]], [[0, 0, -1]], ValueError, "outside 0..2"),
    ],
)
def test_intersect_rejects_bad_input(mesh, origins, directions, error, message):
    class BadFaces:
        vertices = np.zeros((3, 3))
        faces = np.array([[0, 1, 3]])

    target = {"cube": pp.Box((-1, -1, -1), (1, 1, 1)).to_mesh(), "bad faces": BadFaces()}.get(mesh)
    with pytest.raises(error, match=message):
        intersect(target, origins, directions)


@pytest.mark.parametrize("ray", [0, 5, 4097, 9998])  # in the first, a middle and the last packet
@pytest.mark.parametrize(
    ("which", "value", "message"),
    [
        ("origins", np.nan, "origins must be finite, got NaN"),
        ("origins", -np.inf, "origins must be finite, got infinite values"),
        ("directions", np.inf, "directions must be finite, got infinite values"),
        ("directions", 0.0, "directions must not contain a zero-length vector"),
    ],
)
def test_one_bad_ray_among_many_is_reported(ray, which, value, message):
    # The kernel checks the rays as it reads them, from several threads; the message is the
    # one the checks before tracing gave.
    rng = np.random.default_rng(ray)
    rays = {"origins": rng.normal(size=(9999, 3)) * 3, "directions": rng.normal(size=(9999, 3))}
    rays[which][ray] = value
    given = {name: array.copy() for name, array in rays.items()}
    with pytest.raises(ValueError, match=message):
        intersect(pp.scene.icosphere(2), rays["origins"], rays["directions"])
    for name, array in rays.items():  # nothing the caller passed was changed
        assert np.array_equal(array, given[name], equal_nan=True)
