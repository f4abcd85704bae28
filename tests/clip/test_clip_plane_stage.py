"""The Sutherland-Hodgman stage against homogeneous PLANE boundaries (the raster's frustum clip).

A 2-D point (x, y) travels as the homogeneous row (x, y, 0, 1), so the half-plane
a x + b y + c >= 0 is the PLANE boundary (a, b, 0, c); further columns are attributes.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.clip._kernels import PLANE, clip_stage

NO_TRACE = np.empty((0, 2))


def clip(polygon, plane):
    """Clip 2-D ``polygon`` (rows x, y, attributes...) against a x + b y + c >= 0."""
    polygon = np.asarray(polygon, dtype=np.float64)
    n = len(polygon)
    rows = np.zeros((n, polygon.shape[1] + 2))
    rows[:, :2] = polygon[:, :2]
    rows[:, 3] = 1.0
    rows[:, 4:] = polygon[:, 2:]
    a, b, c = plane
    out = np.empty((n + n // 2 + 1, rows.shape[1]))
    m = clip_stage(rows, n, np.array([PLANE, a, b, 0.0, c]), out, NO_TRACE)
    return np.hstack([out[:m, :2], out[:m, 4:]])


def test_notes_walk_starting_from_the_last_vertex():
    # Square (1,1)-(9,1)-(9,7)-(1,7) against x >= 2, written as 1*x + 0*y - 2 >= 0.
    square = [[1, 1], [9, 1], [9, 7], [1, 7]]
    result = clip(square, [1, 0, -2])
    assert result.tolist() == [[2, 1], [9, 1], [9, 7], [2, 7]]


def test_attributes_ride_along():
    # Third column: a value linear in x and y (3x - y) is interpolated exactly at the cuts.
    triangle = np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 12.0], [0.0, 4.0, -4.0]])
    result = clip(triangle, [-1, 0, 2])  # x <= 2
    assert np.allclose(result[:, 2], 3 * result[:, 0] - result[:, 1])
    assert result[:, 0].max() == 2.0


def test_cut_points_do_not_depend_on_the_edge_direction():
    a, b = [0.3, -1.7], [2.9, 5.1]
    plane = [0.7, 0.2, -1.1]
    forward = clip([a, b, [10.0, -3.0]], plane)
    backward = clip([b, a, [-10.0, 3.0]], plane)
    shared = {tuple(p) for p in forward} & {tuple(p) for p in backward}
    assert any(p not in (tuple(a), tuple(b)) for p in shared)


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(3, 12),
    angle=st.floats(0, 2 * np.pi),
    offset=st.floats(-1.5, 1.5),
)
def test_area_matches_shapely_for_any_polygon(seed, n, angle, offset):
    # Star-shaped (often non-convex) polygons: the clipped area equals shapely's intersection
    # with the half-plane (bridges of Sutherland-Hodgman have no area), and the stage stays
    # within its n + n // 2 output bound.
    rng = np.random.default_rng(seed)
    angles = (np.arange(n) + rng.uniform(-0.4, 0.4, n)) * 2 * np.pi / n  # around the origin
    radii = rng.uniform(0.2, 1.0, n)
    polygon = np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=1)
    normal = np.array([np.cos(angle), np.sin(angle)])
    result = clip(polygon, [normal[0], normal[1], -offset])
    assert len(result) <= n + n // 2
    far = 10.0
    tangent = np.array([-normal[1], normal[0]])
    base = offset * normal
    half_plane = shapely.Polygon(
        [
            base + far * tangent,
            base - far * tangent,
            base - far * tangent + far * normal,
            base + far * tangent + far * normal,
        ]
    )
    subject = shapely.Polygon(polygon)
    assert subject.is_valid
    expected = subject.intersection(half_plane).area
    area = shapely.Polygon(result).area if len(result) >= 3 else 0.0
    assert area == pytest.approx(expected, abs=1e-9)


def test_everything_outside_or_empty_input():
    assert len(clip([[0, 0], [1, 0], [0, 1]], [1, 0, -5])) == 0
    out = np.empty((1, 4))
    row = np.array([PLANE, 1.0, 0.0, 0.0, 0.0])
    assert clip_stage(np.empty((0, 4)), 0, row, out, NO_TRACE) == 0


def test_a_crossing_exactly_at_a_vertex_is_not_emitted_twice():
    # x >= 0 with the vertex (0, 0) on the boundary. S starts at (1, 1): edge to (-1, 1) leaves,
    # emitting the cut (0, 1); edge to (0, 0) enters, and its cut is (0, 0) itself, emitted once;
    # edge to (1, 1) stays inside.
    assert clip([[-1, 1], [0, 0], [1, 1]], [1, 0, 0]).tolist() == [[0, 1], [0, 0], [1, 1]]
