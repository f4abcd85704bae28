"""shade_planar (many points at once, planar layout) against the scalar shade_point kernel."""

from __future__ import annotations

import numpy as np
import pytest

from pixelpath.lighting._kernels import DIRECTIONAL_LIGHT, POINT_LIGHT, shade_planar, shade_point

EYE = np.array([0.3, -0.2, 4.0])


def random_case(seed, count):
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(3, count))
    normals = rng.normal(size=(3, count))
    normals /= np.linalg.norm(normals, axis=0)
    points[:, 0] = EYE  # the eye on the point: V is zero
    direction = np.array([0.2, -0.6, -0.5])
    direction /= np.linalg.norm(direction)
    lights = np.array(
        [
            [POINT_LIGHT, 1.5, 2.0, 3.0, 1.0, 0.9, 0.8],
            [DIRECTIONAL_LIGHT, *direction, 0.5, 0.4, 0.3],
            [POINT_LIGHT, *points[:, 1], 0.7, 0.7, 0.7],  # a light on point 1: no contribution
        ]
    )
    return points, normals, lights


def scalar_reference(points, normals, material, lights, ambient, blinn):
    expected = np.empty((points.shape[1], 3))
    for i in range(points.shape[1]):
        shade_point(
            *points[:, i], *normals[:, i], *EYE, 1.0, material, lights, ambient, blinn,
            expected[i],
        )
    return expected


@pytest.mark.parametrize("blinn", [False, True])
@pytest.mark.parametrize("shininess", [0.0, 1.0, 7.0, 32.0, 2.5, 5000.0])
def test_planar_equals_scalar_bit_for_bit(blinn, shininess):
    count = 40
    points, normals, lights = random_case(int(shininess * 10) + blinn, count + 3)
    material = np.array([0.9, 0.5, 0.2, 0.1, 0.6, 0.4, shininess, 0.0])
    ambient = np.array([0.2, 0.3, 0.1])
    out = np.full((3, count + 3), -7.0)
    albedo = np.repeat(material[:3, None], count + 3, axis=1)
    shade_planar(count, points, normals, albedo, np.append(EYE, 1.0), material, lights, ambient,
                 blinn, out,
                 np.empty((5, count + 3)))
    expected = scalar_reference(points[:, :count], normals[:, :count], material, lights,
                                ambient, blinn)
    np.testing.assert_array_equal(out[:, :count].T, expected)
    np.testing.assert_array_equal(out[:, count:], -7.0)  # only the first count points


def test_planar_hand_computed_point():
    # P = 0, N = z, light at (0, 3, 4): N.L = 0.8; eye (0, 0, 2): R.V = 0.8, ^2 = 0.64.
    # ambient 0.1 * 0.5 * C = (0.05, 0.025, 0.0125), diffuse 0.5 * C * 0.8 = (0.4, 0.2, 0.1),
    # specular 0.4 * 0.64 = 0.256 on each channel.
    points = np.zeros((3, 1))
    normals = np.array([[0.0], [0.0], [1.0]])
    material = np.array([1.0, 0.5, 0.25, 0.1, 0.5, 0.4, 2.0, 0.0])
    lights = np.array([[POINT_LIGHT, 0.0, 3.0, 4.0, 1.0, 1.0, 1.0]])
    out = np.empty((3, 1))
    shade_planar(1, points, normals, material[:3, None].copy(), np.array([0.0, 0.0, 2.0, 1.0]),
                 material, lights, np.full(3, 0.5), False, out, np.empty((5, 1)))
    np.testing.assert_allclose(out[:, 0], [0.706, 0.481, 0.3685], rtol=1e-12)


def test_planar_albedo_tints_ambient_and_diffuse_not_the_highlight():
    # The same point as above with the object colour (0.5, 1, 0) given per point instead of
    # the material's: ambient 0.05 C, diffuse 0.4 C, specular 0.256 untouched.
    points = np.zeros((3, 1))
    normals = np.array([[0.0], [0.0], [1.0]])
    material = np.array([1.0, 0.5, 0.25, 0.1, 0.5, 0.4, 2.0, 0.0])
    lights = np.array([[POINT_LIGHT, 0.0, 3.0, 4.0, 1.0, 1.0, 1.0]])
    out = np.empty((3, 1))
    shade_planar(1, points, normals, np.array([[0.5], [1.0], [0.0]]),
                 np.array([0.0, 0.0, 2.0, 1.0]),
                 material, lights, np.full(3, 0.5), False, out, np.empty((5, 1)))
    np.testing.assert_allclose(out[:, 0], [0.45 * 0.5 + 0.256, 0.45 + 0.256, 0.256], rtol=1e-12)


def test_a_viewer_at_infinity_sees_every_point_along_one_direction():
    # Homogeneous eye (0, 0, 1, 0): V = (0, 0, 1) at every point (an orthographic camera), so
    # the highlight of a light straight above is the same at points far apart, where a point
    # eye at (0, 0, 2) would see it fade.
    points = np.array([[0.0, 30.0], [0.0, 0.0], [0.0, 0.0]])
    normals = np.array([[0.0, 0.0], [0.0, 0.0], [1.0, 1.0]])
    material = np.array([1.0, 1.0, 1.0, 0.0, 0.0, 1.0, 8.0, 0.0])
    lights = np.array([[DIRECTIONAL_LIGHT, 0.0, 0.0, -1.0, 1.0, 1.0, 1.0]])
    out = np.empty((3, 2))
    albedo = np.ones((3, 2))
    shade_planar(2, points, normals, albedo, np.array([0.0, 0.0, 1.0, 0.0]), material, lights,
                 np.zeros(3), False, out, np.empty((5, 2)))
    np.testing.assert_allclose(out, 1.0, rtol=1e-12)  # R = V = +z everywhere: (R.V)^8 = 1
    shade_planar(2, points, normals, albedo, np.array([0.0, 0.0, 2.0, 1.0]), material, lights,
                 np.zeros(3), False, out, np.empty((5, 2)))
    assert out[0, 0] == pytest.approx(1.0) and out[0, 1] < 1e-3
