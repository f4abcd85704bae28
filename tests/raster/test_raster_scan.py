"""Scan conversion: the top-left fill rule, coverage of meshes, the notes' Gouraud values."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.raster import coverage, interpolate, scan_convert


def centres(width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre coordinates (x, y) of an image, each (H, W)."""
    return np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)


def grid_mesh(x0, y0, x1, y1, n, jitter, seed):
    """A rectangle [x0, x1] x [y0, y1] cut into n x n quads (two triangles each).

    Interior vertices move by up to ``jitter`` pixels; a few are then snapped onto pixel
    centres so that edges pass exactly through centres (the fill rule's hard case).
    """
    rng = np.random.default_rng(seed)
    xs, ys = np.meshgrid(np.linspace(x0, x1, n + 1), np.linspace(y0, y1, n + 1))
    points = np.stack([xs.ravel(), ys.ravel()], axis=1)
    interior = (xs > x0) & (xs < x1) & (ys > y0) & (ys < y1)
    inner = np.flatnonzero(interior.ravel())
    points[inner] += rng.uniform(-jitter, jitter, (len(inner), 2))
    snapped = inner[: len(inner) // 3]
    points[snapped] = np.floor(points[snapped]) + 0.5
    triangles = []
    for row in range(n):
        for col in range(n):
            v = row * (n + 1) + col
            triangles += [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]]
    return points, np.array(triangles)


def test_two_triangles_of_a_rectangle_share_their_diagonal():
    # Pixel (0, 1) has its centre (0.5, 1.5) left of the diagonal (0,0)-(3,2): lower triangle.
    ids = scan_convert([[0, 0], [3, 0], [3, 2], [0, 2]], [[0, 1, 2], [0, 2, 3]], 3, 2)
    assert ids.tolist() == [[1, 0, 0], [1, 1, 0]]


def test_top_left_rule_on_a_right_triangle():
    # Legs on the top and left edges are included, the hypotenuse x + y = 4 is excluded:
    # exactly the centres with x + y < 4.
    counts = coverage([[0, 0], [4, 0], [0, 4]], [[0, 1, 2]], 4, 4)
    x, y = centres(4, 4)
    assert counts.tolist() == (x + y < 4).astype(int).tolist()


def test_pixel_centre_on_a_vertical_edge_goes_to_the_right_triangle():
    # Two triangles meet along x = 2.5, which passes through the centres of column 2.
    points = [[0.5, 0], [2.5, 0], [2.5, 4], [4.5, 4], [4.5, 0]]
    ids = scan_convert(points, [[0, 1, 2], [1, 4, 3], [1, 3, 2]], 5, 4)
    assert np.all(ids[:, 2] != 0)
    counts = coverage(points, [[0, 1, 2], [1, 4, 3], [1, 3, 2]], 5, 4)
    assert counts.max() == 1


@pytest.mark.parametrize("seed", range(4))
def test_subdivided_quad_covers_every_pixel_exactly_once(seed):
    x0, y0, x1, y1 = 2.3, 1.5, 45.5, 37.8
    points, triangles = grid_mesh(x0, y0, x1, y1, n=7, jitter=2.0, seed=seed)
    counts = coverage(points, triangles, 48, 40)
    x, y = centres(48, 40)
    expected = (x >= x0) & (x < x1) & (y >= y0) & (y < y1)
    assert counts.max() == 1  # no pixel drawn twice
    assert np.array_equal(counts == 1, expected)  # no cracks, nothing outside


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), fan=st.integers(3, 12))
def test_triangle_fan_around_an_inner_point_covers_its_polygon_once(seed, fan):
    # A convex polygon (points on a circle) fanned around a random point inside it, and the
    # same polygon fanned from its first vertex: both cover exactly the same pixels once.
    rng = np.random.default_rng(seed)
    angles = (np.arange(fan) + rng.uniform(-0.4, 0.4, fan)) * 2 * np.pi / fan
    ring = np.stack([16 + 14 * np.cos(angles), 16 + 14 * np.sin(angles)], axis=1)
    inner = rng.dirichlet(np.ones(fan)) @ ring
    fanned = coverage(
        np.vstack([inner, ring]), [[0, 1 + k, 1 + (k + 1) % fan] for k in range(fan)], 32, 32
    )
    from_vertex = coverage(ring, [[0, k, k + 1] for k in range(1, fan - 1)], 32, 32)
    assert fanned.max() == 1
    assert np.array_equal(fanned, from_vertex)


def test_nearer_triangle_wins_whatever_the_order():
    near = [[0, 0, 2.0], [8, 0, 2.0], [0, 8, 2.0]]
    far = [[0, 0, 5.0], [8, 0, 5.0], [0, 8, 5.0]]
    ids = scan_convert(np.array(near + far), [[0, 1, 2], [3, 4, 5]], 8, 8)
    swapped = scan_convert(np.array(far + near), [[0, 1, 2], [3, 4, 5]], 8, 8)
    assert np.all(ids[ids >= 0] == 0)
    assert np.all(swapped[swapped >= 0] == 1)


def test_degenerate_triangles_draw_nothing():
    points = [[0, 0], [4, 4], [8, 8], [3, 1], [3, 1]]
    assert coverage(points, [[0, 1, 2], [3, 4, 0], [3, 3, 3]], 10, 10).sum() == 0


def test_triangles_far_outside_the_image_are_clamped():
    counts = coverage([[-1e6, -1e6], [1e6, -1e6], [0, 1e6]], [[0, 1, 2]], 16, 8)
    assert counts.tolist() == np.ones((8, 16), int).tolist()


class TestGouraudInterpolationOfTheNotes:
    """Notes, "Gouraud shading", example: I1 = 0.9 (top), I2 = 0.2 (left), I3 = 0.6 (right)."""

    points = np.array([[50.5, 10.5], [10.5, 90.5], [90.5, 90.5]])
    intensities = np.array([0.9, 0.2, 0.6])

    def image(self):
        return interpolate(self.points, [[0, 1, 2]], self.intensities, 100, 100)

    def test_midpoint_of_edge_v1_v2(self):
        # I = 0.9 + (0.2 - 0.9) * 0.5 = 0.55 at t = 0.5, the pixel centre (30.5, 50.5).
        assert self.image()[50, 30] == pytest.approx(0.55, abs=1e-12)

    def test_span_interpolation_between_the_edges(self):
        # On scan line y = 70.5 the edges give I_L and I_R by the edge formula; a pixel between
        # them gets I_L + (I_R - I_L)(x - x_L)/(x_R - x_L).
        y = 70.5
        t_left = (y - 10.5) / 80.0  # along V1 -> V2
        t_right = (y - 10.5) / 80.0  # along V1 -> V3
        x_left, i_left = 50.5 - 40 * t_left, 0.9 + (0.2 - 0.9) * t_left
        x_right, i_right = 50.5 + 40 * t_right, 0.9 + (0.6 - 0.9) * t_right
        image = self.image()
        for column in (21, 40, 50, 66):
            x = column + 0.5
            expected = i_left + (i_right - i_left) * (x - x_left) / (x_right - x_left)
            assert image[70, column] == pytest.approx(expected, abs=1e-12)

    def test_scan_line_example_gives_half_way_value(self):
        # A rectangle whose left side is lit 0.3 and right side 0.7 (the notes' I_L, I_R):
        # the pixel exactly in the middle of a span gets 0.5.
        points = [[0.5, 0.5], [8.5, 0.5], [8.5, 20.5], [0.5, 20.5]]
        image = interpolate(points, [[0, 1, 2], [0, 2, 3]], [0.3, 0.7, 0.7, 0.3], 10, 22)
        assert image[10, 4] == pytest.approx(0.5, abs=1e-12)
        assert np.isnan(image[0, 9]) and np.isnan(image[21, 0])


def test_perspective_correct_interpolation_matches_ray_casting():
    # A tilted 3-D triangle seen by a pinhole (focal f pixels, looking down -Z): interpolating
    # the depth and the world X of its vertices must give, at every pixel centre, the depth
    # and X where that pixel's ray meets the triangle's plane.
    f, cx, cy = 40.0, 32.0, 32.0
    world = np.array([[-1.0, -1.0, -2.0], [3.0, -1.5, -6.0], [-0.5, 2.0, -3.0]])
    depth = -world[:, 2]
    screen = np.stack([cx + f * world[:, 0] / depth, cy - f * world[:, 1] / depth, depth], 1)
    values = np.stack([depth, world[:, 0]], axis=1)
    image = interpolate(screen, [[0, 1, 2]], values, 64, 64)
    normal = np.cross(world[1] - world[0], world[2] - world[0])
    x, y = centres(64, 64)
    rays = np.stack([(x - cx) / f, -(y - cy) / f, -np.ones_like(x)], axis=-1)
    t = (normal @ world[0]) / (rays @ normal)  # ray r(t) = t d meets the plane; d_z = -1
    drawn = ~np.isnan(image[..., 0])
    assert drawn.sum() > 300
    assert np.allclose(image[..., 0][drawn], t[drawn], rtol=1e-9)
    assert np.allclose(image[..., 1][drawn], (t * rays[..., 0])[drawn], rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize(
    ("points", "triangles", "error"),
    [
        ([[0, 0, 0, 0]], [[0, 0, 0]], ValueError),
        ([[0, 0], [1, 0], [np.nan, 1]], [[0, 1, 2]], ValueError),
        ([[0, 0], [1, 0], [0, 1]], [[0, 1, 3]], ValueError),
        ([[0, 0], [1, 0], [0, 1]], [[0.0, 1.0, 2.0]], TypeError),
        ([[0, 0], [1, 0], [0, 1]], [[0, 1]], ValueError),
        ([[0, 0, 1], [1, 0, 1], [0, 1, -1]], [[0, 1, 2]], ValueError),
    ],
)
def test_bad_input_is_rejected_clearly(points, triangles, error):
    with pytest.raises(error):
        scan_convert(points, triangles, 4, 4)


@pytest.mark.parametrize(("width", "height"), [(0, 4), (4, -1), (1 << 17, 4)])
def test_bad_sizes_are_rejected(width, height):
    with pytest.raises(ValueError, match=r"width|height"):
        coverage([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], width, height)


def test_interpolate_checks_the_values_shape():
    with pytest.raises(ValueError, match="values"):
        interpolate([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], [1.0, 2.0], 4, 4)
