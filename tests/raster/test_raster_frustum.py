"""Transforms and frustum clipping in homogeneous coordinates."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.raster import clip_to_frustum, clip_to_screen, world_to_clip
from pixelpath.scene import Camera


def test_world_to_clip_w_is_the_view_axis_distance():
    cam = Camera(eye=(1, 2, 3), target=(1, 2, -7), fov=60, width=8, height=8)
    points = np.array([[1.0, 2.0, 0.0], [4.0, -1.0, -5.0], [1.0, 2.0, 2.9]])
    clip = world_to_clip(points, cam)
    assert clip[:, 3].tolist() == pytest.approx([3.0, 8.0, 0.1])


def test_clip_to_screen_hand_example():
    # x_ndc = 0.5 -> 3/4 of the width; y_ndc = 0.5 -> a quarter down from the top.
    screen = clip_to_screen([[1.0, 1.0, 0.0, 2.0]], 8, 4)
    assert screen.tolist() == [[6.0, 1.0, 0.5]]


def test_projected_point_lands_where_the_pinhole_formula_says():
    cam = Camera(eye=(0, 0, 0), target=(0, 0, -1), fov=90, width=200, height=100)
    clip = world_to_clip([[1.0, 0.5, -2.0]], cam)
    x, y, inv_w = clip_to_screen(clip, 200, 100)[0]
    focal = 50.0  # pixels: (height / 2) / tan(fov / 2)
    assert x == pytest.approx(100 + focal * 1.0 / 2.0)
    assert y == pytest.approx(50 - focal * 0.5 / 2.0)
    assert inv_w == pytest.approx(0.5)


def test_clip_to_screen_refuses_points_behind_the_eye():
    with pytest.raises(ValueError, match="w > 0"):
        clip_to_screen([[0.0, 0.0, 0.0, -1.0]], 4, 4)


def inside(vertices, tolerance=1e-12):
    x, y, z, w = vertices[:, :4].T
    slack = tolerance * np.maximum(1.0, np.abs(w))
    return np.all((np.abs(x) <= w + slack) & (np.abs(y) <= w + slack) & (np.abs(z) <= w + slack))


def test_triangle_inside_is_kept_unchanged():
    v = np.array([[0.0, 0.0, 0.0, 1.0], [0.5, 0.0, 0.0, 1.0], [0.0, 0.5, 0.0, 1.0]])
    out, triangles, source = clip_to_frustum(v, [[0, 1, 2]])
    assert np.array_equal(out, v)
    assert triangles.tolist() == [[0, 1, 2]] and source.tolist() == [0]


def test_triangle_outside_one_plane_is_dropped():
    v = np.array([[2.0, 0.0, 0.0, 1.0], [3.0, 0.0, 0.0, 1.0], [2.5, 0.5, 0.0, 1.0]])
    _, triangles, _ = clip_to_frustum(v, [[0, 1, 2]])
    assert len(triangles) == 0


def test_keep_mask_skips_triangles():
    v = np.array([[0.0, 0.0, 0.0, 1.0], [0.5, 0.0, 0.0, 1.0], [0.0, 0.5, 0.0, 1.0]])
    _, triangles, _ = clip_to_frustum(v, [[0, 1, 2]], keep=[False])
    assert len(triangles) == 0


def test_triangle_crossing_the_near_plane_is_cut_on_it():
    # Vertex 2 is behind the near plane (z < -w). The cut points lie on z = -w, and an
    # attribute that is linear in clip space (here 2x + 3y - z) is interpolated exactly.
    v = np.array([[0.0, 0.0, 0.5, 1.0], [0.5, 0.0, 0.5, 1.0], [0.0, 0.5, -3.0, 1.0]])
    v = np.hstack([v, (2 * v[:, 0] + 3 * v[:, 1] - v[:, 2])[:, None]])
    out, triangles, source = clip_to_frustum(v, [[0, 1, 2]])
    new = out[3:]
    assert len(triangles) == 2 and source.tolist() == [0, 0]
    assert inside(new)
    on_near = np.isclose(new[:, 2], -new[:, 3])
    assert on_near.sum() == 2
    assert np.allclose(new[:, 4], 2 * new[:, 0] + 3 * new[:, 1] - new[:, 2])


def test_shared_edge_is_cut_at_the_identical_point():
    # Two triangles sharing an edge that crosses the near plane, listed in opposite directions:
    # both must put the cut vertex at bit-identical coordinates (no crack in the mesh).
    a, b = [0.3, -0.2, 0.9, 1.0], [-0.1, 0.4, -7.0, 1.3]
    v = np.array([a, b, [0.6, 0.5, 0.2, 1.0], [-0.5, -0.4, 0.1, 1.1]])
    out, triangles, source = clip_to_frustum(v, [[0, 1, 2], [1, 0, 3]])
    first = {tuple(p) for p in out[triangles[source == 0].ravel()]}
    second = {tuple(p) for p in out[triangles[source == 1].ravel()]}
    shared = first & second
    assert len(shared) == 2  # a itself and the cut point on the near plane
    cut = next(p for p in shared if p != tuple(a))
    assert cut[2] == pytest.approx(-cut[3])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=12, max_size=12))
def test_clipped_pieces_stay_inside_the_frustum(coordinates):
    v = np.array(coordinates).reshape(3, 4)
    v[:, 3] = np.abs(v[:, 3]) + 0.1 * np.sign(v[:, 3] + 0.01)  # w of any sign, never 0
    out, triangles, _ = clip_to_frustum(v, [[0, 1, 2]])
    used = out[np.unique(triangles)] if len(triangles) else out[:0]
    # Triangles kept whole may stick out sideways (guard band) but never past near or far.
    assert np.all(used[:, 2] >= -used[:, 3] - 1e-9 * np.abs(used[:, 3]))
    assert np.all(used[:, 2] <= used[:, 3] + 1e-9 * np.abs(used[:, 3]))
    assert np.all(used[:, 3] > 0)


def test_bad_input():
    with pytest.raises(ValueError, match="shape"):
        clip_to_frustum(np.zeros((3, 3)), [[0, 1, 2]])
    with pytest.raises(ValueError, match="finite"):
        clip_to_frustum(np.full((3, 4), np.nan), [[0, 1, 2]])
    with pytest.raises(ValueError, match="index"):
        clip_to_frustum(np.ones((3, 4)), [[0, 1, 5]])
    with pytest.raises(ValueError, match="keep"):
        clip_to_frustum(np.ones((3, 4)), [[0, 1, 2]], keep=[True, False])


def test_growing_a_buffer_keeps_its_rows():
    from pixelpath.raster._setup_kernels import _grown, _grown_rows

    rows = np.arange(6.0).reshape(3, 2)
    bigger = _grown_rows(rows, 5)
    assert bigger.shape == (6, 2) and np.array_equal(bigger[:3], rows)
    items = np.arange(3)
    longer = _grown(items, 7)
    assert longer.shape == (7,) and np.array_equal(longer[:3], items)


def _classify_by_corners(clip, triangles, keep):
    """The frustum classification written out per triangle corner, in NumPy."""
    from pixelpath.raster._setup_kernels import GUARD_BAND

    x, y, z, w = (clip[triangles][..., k] for k in range(4))  # (T, 3) each
    planes = [z < -w, z > w, x < -w, x > w, y < -w, y > w]
    dropped = np.any([side.all(axis=1) for side in planes], axis=0)
    band = GUARD_BAND * w
    cut = ((z < -w) | (z > w) | (np.abs(x) > band) | (np.abs(y) > band)).any(axis=1)
    return np.where(~keep | dropped, 0, np.where(cut, 2, 1))


def _random_case(seed):
    """Vertices inside, beyond single planes, past the guard band, behind the eye and NaN,
    shared between triangles, and a keep mask."""
    rng = np.random.default_rng(seed)
    clip = rng.normal(size=(40, 4)) * rng.choice([0.3, 1.0, 12.0], size=(40, 1))
    clip[:, 3] = rng.choice([1.0, 0.5, -1.0], size=40) * rng.uniform(0.5, 2.0, size=40)
    clip[rng.random((40, 4)) < 0.02] = np.nan
    triangles = rng.integers(0, 40, size=(120, 3)).astype(np.intp)
    return clip, triangles, rng.random(120) < 0.8


def test_the_random_frustum_cases_hold_every_status():
    assert set(_classify_by_corners(*_random_case(0)).tolist()) == {0, 1, 2}


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_frustum_classification_matches_the_corner_by_corner_rule(seed):
    from pixelpath.raster import _setup_kernels

    clip, triangles, keep = _random_case(seed)
    status = np.empty(len(triangles), dtype=np.int8)
    _setup_kernels.classify_triangles(clip, triangles, keep, status)
    assert np.array_equal(status, _classify_by_corners(clip, triangles, keep))
