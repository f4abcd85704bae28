"""Per-pixel Phong shading of whole rows: every pixel gets the illumination of its own point."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.lighting import shade


@pytest.mark.parametrize("model", ["phong", "blinn"])
def test_wide_rows_of_two_materials_equal_the_illumination_formula(model):
    # Two squares in the plane z = 0, side by side, facing the eye: more than 256 drawn pixels
    # per row and a change of material inside each row (the rows are shaded in batches of one
    # object). Each pixel must show the illumination of the plane point seen through its
    # centre, with the plane's normal.
    width, height = 600, 12
    camera = pp.Camera(eye=(0.1, 0.0, 0.5), target=(0.1, 0.0, 0.0), fov=90, width=width,
                       height=height)
    shiny = pp.Material(color=(1.0, 0.2, 0.1), ka=0.1, kd=0.5, ks=0.6, shininess=20)
    matte = pp.Material(color=(0.1, 0.3, 1.0), ka=0.2, kd=0.8, ks=0.1, shininess=2.5)
    left = pp.Mesh([[-30, -1, 0], [0, -1, 0], [0, 1, 0], [-30, 1, 0]], [[0, 1, 2, 3]], shiny)
    right = pp.Mesh([[0, -1, 0], [30, -1, 0], [30, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]], matte)
    lights = [pp.PointLight((0.5, 0.3, 0.6)), pp.DirectionalLight(direction=(1, 0, -1))]
    scene = pp.Scene(camera, objects=[left, right], lights=lights, ambient=0.2)
    image = pp.render(scene, shading="phong", blinn=model == "blinn")

    focal = (height / 2) / np.tan(np.radians(45))
    xs, ys = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    # The ray through a pixel centre meets z = 0 at eye + 0.5 * (x, y, -focal) / focal.
    hits = np.stack([0.1 + 0.5 * (xs - width / 2) / focal, 0.5 * (height / 2 - ys) / focal,
                     np.zeros_like(xs)], axis=-1)
    owner = np.asarray(image.object_id)
    assert (owner == 0).sum() > 0 and (owner == 1).sum() > 0
    assert (owner >= 0).all()
    for index, material in enumerate((shiny, matte)):
        drawn = owner == index
        points = hits[drawn]
        normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
        expected = shade(points, normals, camera.eye, material, lights, 0.2, model=model)
        got = np.asarray(image)[drawn]
        np.testing.assert_allclose(got, np.clip(expected, 0, 1), atol=2e-5)
