"""Line drawing: Bresenham's pixels, frustum clipping of segments, depth along the line."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from skimage.draw import line as skimage_line

from pixelpath.raster import world_to_clip
from pixelpath.raster.lines import bresenham, draw_lines
from pixelpath.renderer import View
from pixelpath.scene import Camera

coordinates = st.integers(-40, 40)


@settings(deadline=None)  # the first call loads the compiled kernel
@given(coordinates, coordinates, coordinates, coordinates)
def test_bresenham_draws_the_pixels_scikit_image_draws(x0, y0, x1, y1):
    rows, columns = skimage_line(y0, x0, y1, x1)
    assert bresenham((x0, y0), (x1, y1)).tolist() == np.stack([columns, rows], 1).tolist()


@settings(deadline=None)  # the first call loads the compiled kernel
@given(coordinates, coordinates, coordinates, coordinates)
def test_bresenham_lines_are_8_connected_one_pixel_per_major_step(x0, y0, x1, y1):
    pixels = bresenham((x0, y0), (x1, y1))
    assert pixels[0].tolist() == [x0, y0] and pixels[-1].tolist() == [x1, y1]
    assert len(pixels) == max(abs(x1 - x0), abs(y1 - y0)) + 1
    steps = np.abs(np.diff(pixels, axis=0))
    assert (steps.max(axis=1) == 1).all()  # 8-neighbours, never the same pixel twice
    major = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
    assert (steps[:, major] == 1).all()  # one pixel per column (row): no doubled pixels


def test_bresenham_by_hand():
    # Slope 2/5: the row steps after the error passes half a pixel.
    assert bresenham((0, 0), (5, 2)).tolist() == [[0, 0], [1, 0], [2, 1], [3, 1], [4, 2], [5, 2]]
    assert bresenham((2, 3), (2, 3)).tolist() == [[2, 3]]
    assert bresenham((3, 0), (0, 3)).tolist() == [[3, 0], [2, 1], [1, 2], [0, 3]]


def test_bresenham_rejects_bad_ends():
    with pytest.raises(ValueError, match="start"):
        bresenham((0.5, 1), (2, 2))
    with pytest.raises(ValueError, match="end"):
        bresenham((0, 1), (2, 2, 3))


def camera(**kwargs) -> Camera:
    options = {"eye": (0, 0, 5), "target": (0, 0, 0), "fov": 90, "width": 101, "height": 81}
    return Camera(**(options | kwargs))


def test_a_segment_gives_the_same_pixels_either_way_round():
    view = View.whole(camera())
    rng = np.random.default_rng(4)
    for a, b in rng.uniform(-4, 4, (50, 2, 3)):
        forward = draw_lines([a], [b], [0], view)
        backward = draw_lines([b], [a], [0], view)
        assert np.array_equal(forward.owner, backward.owner)
        assert np.allclose(forward.depth, backward.depth, rtol=1e-12)  # clipped from either end


def test_depth_along_the_line_is_perspective_correct():
    # A receding segment: at each pixel column, the depth is the view-axis distance of the
    # point of the segment that projects onto the column's centre.
    cam = camera()
    a, b = np.array([-4.0, -1.0, 2.0]), np.array([3.0, 1.5, -20.0])
    lines = draw_lines([a], [b], [0], View.whole(cam))
    (xa, _, _, wa), (xb, _, _, wb) = world_to_clip(np.stack([a, b]), cam)
    rows, columns = np.nonzero(lines.owner == 0)
    assert len(columns) == len(set(columns.tolist())) > 40  # x-major: one pixel per column
    target = 2 * (columns + 0.5) / cam.width - 1  # x / w at the column's centre
    s = (target * wa - xa) / ((xb - xa) - target * (wb - wa))
    inside = (s >= 0) & (s <= 1)
    assert inside.mean() > 0.95  # the end columns may lie just beyond the segment's ends
    expected = wa + s * (wb - wa)
    assert np.allclose(lines.depth[rows, columns][inside], expected[inside], rtol=1e-9)


def test_a_segment_crossing_the_near_plane_keeps_its_part_in_front():
    cam = camera(eye=(0, 0, 0), target=(0, 0, -1), near=0.5, fov=60)
    view = View.whole(cam)
    behind, front = np.array([-1.0, 0.3, 2.0]), np.array([1.2, -0.2, -4.0])
    # Analytically: the near plane is z = -0.5 (w = -z = 0.5).
    s = (-0.5 - behind[2]) / (front[2] - behind[2])
    on_near = behind + s * (front - behind)
    clipped = draw_lines([behind], [front], [0], view)
    expected = draw_lines([on_near], [front], [0], view)
    assert clipped.counts["edges cut by the frustum"] == 1
    assert np.array_equal(clipped.owner, expected.owner)
    assert np.allclose(clipped.depth, expected.depth, rtol=1e-12)
    drawn = clipped.owner == 0
    assert drawn.sum() > 20 and clipped.depth[drawn].min() >= 0.5 - 1e-12


def test_segments_outside_the_frustum_draw_nothing():
    cam = camera()
    behind_the_eye = ([0.0, 0.0, 6.0], [1.0, 1.0, 7.0])
    far_to_the_side = ([40.0, 0.0, 0.0], [40.0, 3.0, -1.0])
    starts, ends = zip(behind_the_eye, far_to_the_side, strict=True)
    lines = draw_lines(list(starts), list(ends), [0, 1], View.whole(cam))
    assert (lines.owner == -1).all() and np.isinf(lines.depth).all()
    assert lines.counts["edges outside the frustum"] == 2


def test_the_nearer_line_wins_and_the_limit_hides_lines_behind_it():
    cam = camera()
    view = View.whole(cam)
    near_line = ([-3.0, 0.0, 1.0], [3.0, 0.0, 1.0])  # depth 4
    far_line = ([0.0, -3.0, -1.0], [0.0, 3.0, -1.0])  # depth 6, crossing it
    starts, ends = zip(far_line, near_line, strict=True)
    lines = draw_lines(list(starts), list(ends), [1, 0], view)
    crossing = lines.owner[40, 50]
    assert crossing == 0 and lines.depth[40, 50] == pytest.approx(4.0)
    limit = np.full((cam.height, cam.width), 5.0)  # a surface at depth 5 hides the far line
    hidden = draw_lines(list(starts), list(ends), [1, 0], view, limit)
    assert set(np.unique(hidden.owner).tolist()) == {-1, 0}
    assert hidden.counts["line pixels hidden"] == (lines.owner == 1).sum() + 1


def test_a_region_gets_the_pixels_of_the_whole_image():
    cam = camera()
    rng = np.random.default_rng(5)
    starts, ends = rng.uniform(-5, 5, (2, 30, 3))
    owners = np.arange(30)
    whole = draw_lines(starts, ends, owners, View.whole(cam))
    for (x0, x1), (y0, y1) in itertools.product(
        itertools.pairwise((0, 33, 101)), itertools.pairwise((0, 50, 81))
    ):
        part = draw_lines(starts, ends, owners, View(cam, x0, y0, x1 - x0, y1 - y0))
        assert np.array_equal(part.owner, whole.owner[y0:y1, x0:x1])
        assert np.array_equal(part.depth, whole.depth[y0:y1, x0:x1])


def test_draw_lines_checks_its_input():
    view = View.whole(camera())
    with pytest.raises(ValueError, match="one row per segment"):
        draw_lines([[0.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]], [0, 1], view)
    with pytest.raises(ValueError, match="limit"):
        draw_lines([[0.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]], [0], view, np.zeros((2, 2)))
