"""Packets of four rays: ``closest_triangles4`` finds, for each ray, exactly what the one-ray
search ``closest_triangle`` finds (itself checked against brute force in test_raytrace_bvh)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.raytrace import BVH
from pixelpath.raytrace import _traversal_kernels as kernels
from pixelpath.raytrace._hit_kernels import slab_nan_allowed
from pixelpath.scene import icosphere, torus


def _packet_hits(bvh, rays, t_min=0.0, cull=False, skip=None):
    """closest_triangles4 on (4, 7) rows of origin, direction, t_max: (t, triangle, w1, w2)."""
    skip = np.zeros(len(bvh.corners), dtype=np.bool_) if skip is None else skip
    packet = np.zeros((kernels.LANES, 9))
    packet[:, :7] = rays
    hit = np.empty(kernels.LANES, dtype=np.intp)
    stack = np.empty(bvh.depth + 1, dtype=np.intp)
    with slab_nan_allowed():
        nodes, tests = kernels.closest_triangles4(
            bvh.bounds, bvh.links, bvh.corners, bvh.order, skip, cull, packet, kernels.LANES, t_min,
            hit, stack,
            np.empty(bvh.depth + 1), np.empty((bvh.depth + 1, kernels.LANES)),
        )
    return [(packet[r, 6], hit[r], packet[r, 7], packet[r, 8]) for r in range(4)], nodes, tests


def _single_hits(bvh, rays, t_min=0.0, cull=False, skip=None):
    skip = np.zeros(len(bvh.corners), dtype=np.bool_) if skip is None else skip
    stack = np.empty(bvh.depth + 1, dtype=np.intp)
    found, nodes, tests = [], 0, 0
    with slab_nan_allowed():
        for ray in rays:
            t, i, w1, w2, n, m = kernels.closest_triangle(
                bvh.bounds, bvh.links, bvh.corners, bvh.order, skip, cull, *ray[:6], t_min,
                ray[6], stack, np.empty(bvh.depth + 1),
            )
            found.append((t, i, w1, w2))
            nodes += n
            tests += m
    return found, nodes, tests


def _fan(rng, origin, centre, spread):
    """Four rays from one origin towards points scattered around centre, with t_max = inf."""
    targets = centre + rng.normal(scale=spread, size=(4, 3))
    return np.column_stack([np.tile(origin, (4, 1)), targets - origin, np.full(4, math.inf)])


@pytest.mark.parametrize("spread", [0.01, 0.2, 2.0])
def test_a_packet_finds_what_each_ray_finds_alone(spread):
    rng = np.random.default_rng(int(spread * 100))
    ring = torus(0.7, 0.25, 24, 12).transformed(
        pp.scene.transform_matrix(rotate=rng.uniform(0, 360, 3))
    )
    bvh = BVH.build(ring.vertices, ring.triangles)
    kinds = set()
    for _ in range(150):
        origin = rng.normal(size=3)
        origin *= 3.0 / np.linalg.norm(origin)
        rays = _fan(rng, origin, rng.uniform(-0.8, 0.8, 3), spread)
        packet, _, _ = _packet_hits(bvh, rays)
        single, _, _ = _single_hits(bvh, rays)
        assert packet == single  # t, triangle and weights, bit for bit
        kinds.add(tuple(hit[1] >= 0 for hit in single))
    assert len(kinds) > 3  # packets that all hit, all miss, and partly hit


def test_a_packet_keeps_each_rays_own_limit_and_culls_back_faces():
    sphere = icosphere(3, 1.0)
    bvh = BVH.build(sphere.vertices, sphere.triangles)
    rays = np.array([[0.05 * k, 0.02, 5.0, 0.0, 0.0, -1.0, limit]
                     for k, limit in enumerate([10.0, 4.5, 3.9, 10.0])])
    packet, _, _ = _packet_hits(bvh, rays)
    assert packet == _single_hits(bvh, rays)[0]
    assert [hit[1] >= 0 for hit in packet] == [True, True, False, True]
    assert packet[2][0] == 3.9  # a miss leaves t at the ray's limit
    assert 4.0 < packet[0][0] < 4.01  # the near side of the (inscribed) unit sphere, 5 away
    # Culling the faces turned away from the rays: only the near side can be hit.
    corners = bvh.corners.reshape(-1, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    back = normals[:, 2] < 0  # facing away from rays that travel towards -z
    inside = rays.copy()
    inside[:, 2] = 0.0  # from the centre: only back faces ahead
    culled, _, _ = _packet_hits(bvh, inside, cull=True, skip=back)
    assert culled == _single_hits(bvh, inside, cull=True, skip=back)[0]
    assert all(hit[1] == kernels.MISS for hit in culled)


def test_packets_through_shared_edges_and_vertices_always_hit():
    n = 6
    xs = np.arange(n + 1, dtype=float)
    gx, gy = np.meshgrid(xs, xs)
    vertices = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
    triangles = [[v, v + 1, v + n + 2] for v in range(n * (n + 1)) if v % (n + 1) < n]
    triangles += [[v, v + n + 2, v + n + 1] for v in range(n * (n + 1)) if v % (n + 1) < n]
    bvh = BVH.build(vertices, np.array(triangles))
    eye = np.array([3.0, 3.0, 4.0])
    points = np.array([[x, y, 0.0] for x in np.arange(1.0, 5.5, 0.5)
                       for y in np.arange(1.0, 5.5, 0.5)])  # vertices and edge midpoints
    for start in range(0, len(points) - 3, 4):
        targets = points[start:start + 4]
        rays = np.column_stack([np.tile(eye, (4, 1)), targets - eye, np.full(4, math.inf)])
        packet, _, _ = _packet_hits(bvh, rays)
        assert packet == _single_hits(bvh, rays)[0]
        assert all(hit[1] >= 0 for hit in packet), "a ray fell between two triangles"
        np.testing.assert_allclose([hit[0] for hit in packet], 1.0)


def test_rays_whose_directions_differ_in_sign_are_traced_one_by_one():
    sphere = icosphere(2, 1.0)
    bvh = BVH.build(sphere.vertices, sphere.triangles)
    rays = np.array([[0.0, 0.0, 0.0, 1.0, 0.2, 0.1, math.inf],
                     [0.0, 0.0, 0.0, -1.0, 0.2, 0.1, math.inf],
                     [0.0, 0.0, 0.0, 0.3, -1.0, 0.1, math.inf],
                     [0.0, 0.0, 0.0, 0.3, 0.2, -1.0, math.inf]])
    packet, nodes, tests = _packet_hits(bvh, rays)
    single, single_nodes, single_tests = _single_hits(bvh, rays)
    assert packet == single
    assert (nodes, tests) == (single_nodes, single_tests)
    assert all(hit[1] >= 0 for hit in packet)  # from the centre every ray hits


def _any_hits(bvh, segments, pass_through, packet):
    """any_triangles4 (packet) or any_triangle per segment: [(light, blocker)], nodes, tests."""
    stack = np.empty(bvh.depth + 2, dtype=np.intp)
    with slab_nan_allowed():
        if packet:
            rays = np.zeros((kernels.LANES, 8))
            rays[:, :7] = segments
            hit = np.empty(kernels.LANES, dtype=np.intp)
            nodes, tests = kernels.any_triangles4(
                bvh.bounds, bvh.links, bvh.corners, pass_through, rays, kernels.LANES, 0.0, hit,
                stack,
            )
            return [(rays[r, 7], hit[r]) for r in range(4)], nodes, tests
        found, nodes, tests = [], 0, 0
        for segment in segments:
            light, blocker, n, m = kernels.any_triangle(
                bvh.bounds, bvh.links, bvh.corners, pass_through, *segment[:6], 0.0, segment[6],
                stack,
            )
            found.append((light, blocker))
            nodes += n
            tests += m
        return found, nodes, tests


@pytest.mark.parametrize("spread", [0.02, 0.3])
def test_a_packet_of_shadow_rays_finds_what_each_finds_alone(spread):
    # A shell of see-through and opaque triangles between points and a light: the same
    # blocker, the same light let through (its product taken in the same order), and the
    # same nodes and triangle tests for each ray as on its own.
    rng = np.random.default_rng(7)
    shell = icosphere(2, 1.0)
    bvh = BVH.build(shell.vertices, shell.triangles)
    pass_through = rng.choice([0.0, 0.5, 0.9], size=len(bvh.corners), p=[0.3, 0.4, 0.3])
    light = np.array([0.3, 3.0, 0.5])
    outcomes = set()
    for _ in range(200):
        points = rng.normal(scale=spread, size=(4, 3)) + rng.uniform(-0.6, 0.6, 3)
        segments = np.column_stack([points, light - points, np.ones(4)])
        packet, nodes, tests = _any_hits(bvh, segments, pass_through, packet=True)
        single, single_nodes, single_tests = _any_hits(bvh, segments, pass_through, packet=False)
        assert packet == single
        assert (nodes, tests) == (single_nodes, single_tests)
        outcomes.update("blocked" if blocker >= 0 else "dimmed" if light_let < 1 else "lit"
                        for light_let, blocker in single)
    assert {"blocked", "dimmed"} <= outcomes  # rays from inside leave through a triangle


def test_one_call_traces_many_packets_and_a_short_last_one():
    # 27 rays: six packets of four, then three rays one by one, all in one call (the tracer
    # hands BLOCK rays to a call); each finds what it finds alone. The buffers are rounded up
    # to whole packets, as the tracer's are.
    rng = np.random.default_rng(11)
    ring = torus(0.7, 0.25, 24, 12)
    bvh = BVH.build(ring.vertices, ring.triangles)
    count = 27
    rows = -(-count // kernels.LANES) * kernels.LANES
    origins = np.tile([0.2, 0.1, 3.0], (count, 1)) + rng.normal(scale=0.05, size=(count, 3))
    targets = rng.uniform(-0.9, 0.9, (count, 3))
    rays = np.column_stack([origins, targets - origins, np.full(count, math.inf)])
    packet = np.zeros((rows, 9))
    packet[:count, :7] = rays
    hit = np.empty(rows, dtype=np.intp)
    stack = np.empty(bvh.depth + 1, dtype=np.intp)
    skip = np.zeros(len(bvh.corners), dtype=np.bool_)
    with slab_nan_allowed():
        kernels.closest_triangles4(
            bvh.bounds, bvh.links, bvh.corners, bvh.order, skip, False, packet, count, 0.0, hit,
            stack, np.empty(bvh.depth + 1), np.empty((bvh.depth + 1, kernels.LANES)),
        )
    found = [(packet[r, 6], hit[r], packet[r, 7], packet[r, 8]) for r in range(count)]
    assert found == _single_hits(bvh, rays)[0]
    assert 0 < sum(h[1] >= 0 for h in found) < count  # hits and misses both

    pass_through = rng.choice([0.0, 0.5], size=len(bvh.corners))
    segments = np.column_stack([origins, targets - origins, np.ones(count)])
    shadows = np.zeros((rows, 8))
    shadows[:count, :7] = segments
    with slab_nan_allowed():
        nodes, tests = kernels.any_triangles4(
            bvh.bounds, bvh.links, bvh.corners, pass_through, shadows, count, 0.0, hit, stack,
        )
    single, single_nodes, single_tests = _any_hits(bvh, segments, pass_through, packet=False)
    assert [(shadows[r, 7], hit[r]) for r in range(count)] == single
    assert (nodes, tests) == (single_nodes, single_tests)
