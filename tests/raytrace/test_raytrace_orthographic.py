"""The ray tracer with an orthographic camera: parallel primary rays from the eye's plane."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp


@pytest.mark.parametrize("z", [0.0, -40.0])
def test_sphere_is_the_same_disc_at_any_distance_with_analytic_depths(z):
    # 10 pixels per unit: pixel (i, j) looks along -z through x = (i + 0.5) / 10 - 2,
    # y = 1 - (j + 0.5) / 10. A ray at distance rho < r from the axis of a sphere of radius r
    # hits it at depth (eye z - centre z) - sqrt(r^2 - rho^2), wherever the sphere is.
    radius = 0.6
    camera = pp.Camera(eye=(0.0, 0.0, 10.0), target=(0.0, 0.0, 0.0), width=40, height=20,
                       projection="orthographic", view_height=2.0)
    scene = pp.Scene(camera, objects=[pp.Sphere((0.0, 0.0, z), radius)],
                     lights=[pp.PointLight((0, 0, 20))])
    image = pp.render(scene, "raytrace")
    x = (np.arange(40) + 0.5) / 10 - 2.0
    y = 1.0 - (np.arange(20) + 0.5) / 10
    rho2 = x[None, :] ** 2 + y[:, None] ** 2
    inside = rho2 < radius**2
    np.testing.assert_array_equal(image.object_id == 0, inside)
    expected = 10.0 - z - np.sqrt(radius**2 - rho2[inside])
    np.testing.assert_allclose(image.depth[inside], expected, rtol=1e-6)


def test_orthographic_view_vector_is_the_same_everywhere():
    # V points towards the camera (+z) at every point, not towards the eye: with the light
    # along +z too, a sphere off the axis has its highlight where N = +z, over its centre. (A
    # V towards the eye at (0, 0, 2) would move it about 2.4 pixels towards the image centre.)
    camera = pp.Camera(eye=(0.0, 0.0, 2.0), target=(0.0, 0.0, 0.0), width=129, height=129,
                       projection="orthographic", view_height=1.6)
    material = pp.Material(color=(1, 1, 1), ka=0.0, kd=0.0, ks=1.0, shininess=200)
    scene = pp.Scene(camera, objects=[pp.Sphere((0.4, 0.0, 0.0), 0.3, material)],
                     lights=[pp.DirectionalLight(direction=(0, 0, -1))], ambient=0.0)
    red = np.asarray(pp.render(scene, "raytrace"))[:, :, 0]
    row, column = np.unravel_index(np.argmax(red), red.shape)
    centre = (0.4 + 0.8) / 1.6 * 129 - 0.5  # the column whose centre is at x = 0.4
    assert row == 64
    assert abs(column - centre) <= 0.5
