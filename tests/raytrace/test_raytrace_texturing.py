"""Textures and vertex colours in the ray tracer (and the rasterizers' barycentrics).

Vertex colours are checked against barycentric coordinates computed here from each pixel's
ray and the triangle (world space, so the check is perspective-correct by construction);
reflections must show textured surfaces the right way round.
"""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from camera_rays import view_rays

QUADRANTS = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], np.uint8)


def barycentrics(eye, rays, a, b, c):
    """(H, W, 3) weights of a, b, c where each ray meets the triangle's plane."""
    normal = np.cross(b - a, c - a)
    t = ((a - eye) @ normal) / (rays @ normal)
    hit = eye + t[..., None] * rays
    area = normal @ normal
    wa = np.cross(c - b, hit - b) @ normal / area
    wb = np.cross(a - c, hit - c) @ normal / area
    return np.stack([wa, wb, 1 - wa - wb], axis=-1)


@pytest.mark.parametrize("method", ["raytrace", "zbuffer", "scanline", "painter"])
@pytest.mark.parametrize("shading", ["phong", "flat"])
def test_vertex_colours_at_the_hit_barycentrics(method, shading):
    corners = np.array([[-1.6, -1.0, 0.5], [1.4, -0.8, -3.0], [0.0, 1.4, -0.5]])
    colors = np.array([[1.0, 0.1, 0.0], [0.0, 0.9, 0.2], [0.1, 0.0, 1.0]])
    material = pp.Material(ka=1.0, kd=0.0, ks=0.0)  # ambient 1: the colour itself
    triangle = pp.Mesh(corners, [[0, 1, 2]], material, colors=colors)
    camera = pp.Camera(eye=(0.3, 0.2, 3.0), target=(0, 0, -1), fov=50, width=40, height=32)
    image = pp.render(pp.Scene(camera, objects=[triangle], ambient=1.0), method, shading)
    weights = barycentrics(np.asarray(camera.eye, float), view_rays(camera), *corners)
    inside = np.all(weights > 0.02, axis=-1)  # away from the edges
    assert inside.sum() > 100
    assert np.all(image.object_id[inside] == 0)
    expected = weights @ colors
    assert np.allclose(np.asarray(image)[inside], expected[inside], atol=2e-5)
    # An affine (screen-space) interpolation would be far off on this receding triangle:
    # the far corner's colour (green) covers much less of the picture than its screen share.
    assert np.abs(weights[inside] - 1 / 3).max() > 0.3


def test_reflections_show_textures_the_right_way_round():
    # The camera looks at a mirror; behind the camera a textured wall faces the mirror.
    mirror = pp.Mesh([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]], [[0, 1, 2, 3]],
                     pp.Material(color=(0, 0, 0), ka=0.0, kd=0.0, ks=0.0, reflectivity=1.0))
    wall_corners = np.array([[-3, -3, 4], [-3, 3, 4], [3, 3, 4], [3, -3, 4]], dtype=float)
    wall_uv = (wall_corners[:, :2] + 3) / 6  # u with world x, v with world y
    wall = pp.Mesh(wall_corners, [[0, 1, 2, 3]],
                   pp.Material(ka=1.0, kd=0.0, ks=0.0, texture=QUADRANTS,
                               texture_filter="nearest"),
                   uv=wall_uv)
    camera = pp.Camera(eye=(0, 0, 3), target=(0, 0, 0), fov=60, width=32, height=32)
    scene = pp.Scene(camera, objects=[mirror, wall], ambient=1.0)
    image = pp.render(scene, "raytrace", max_depth=2)
    rgb = np.asarray(image)
    assert np.all(image.object_id[10:22, 10:22] == 0)  # the mirror is what the camera sees
    # A reflected ray keeps x and y: world top-left (x < 0, y > 0) is the picture's red.
    assert rgb[10, 10].tolist() == [1, 0, 0]
    assert rgb[10, 21].tolist() == [0, 1, 0]
    assert rgb[21, 10].tolist() == [0, 0, 1]
    assert rgb[21, 21].tolist() == [1, 1, 1]


def test_explained_terms_use_the_textured_colour():
    """A ray tree's ambient and diffuse terms are those of the surface colour at the hit (the
    texture's), and with the specular terms they add up to the hit's local light."""
    from pathlib import Path

    from pixelpath.raytrace import ray_tree

    duck = pp.load_scene(Path(__file__).parents[1] / "data" / "models" / "Duck.glb")
    node = ray_tree(duck, (400, 300), max_depth=0).root
    assert node.object == 0
    parts = node.ambient + sum(light.diffuse + light.specular for light in node.lights)
    np.testing.assert_allclose(parts, node.local, atol=1e-9)
    assert node.local[2] < 0.5 * node.local[0]  # yellow, as the texture is: not grey


def test_the_tree_names_the_surface_colour_texture_and_vertex_colours_make():
    from pixelpath.raytrace import ray_tree

    def decoded(code):  # the sRGB curve (IEC 61966-2-1), worked here
        c = code / 255
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4

    corners = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    texture = np.full((2, 2, 3), (128, 64, 255), np.uint8)  # one colour: no filtering question
    material = pp.Material(color=(0.5, 1.0, 1.0), texture=texture, texture_filter="nearest")
    quad = pp.Mesh(corners, [[0, 1, 2, 3]], material, uv=[[0, 0], [1, 0], [1, 1], [0, 1]],
                   colors=[[1.0, 0.5, 1.0]] * 4)
    camera = pp.Camera(eye=(0, 0, 3), target=(0, 0, 0), width=8, height=8)
    tree = ray_tree(pp.Scene(camera, objects=[quad]), (4, 4), max_depth=0)
    expected = [0.5 * decoded(128), decoded(64) * 0.5, 1.0]  # material × texture × vertex
    np.testing.assert_allclose(tree.root.surface, expected, rtol=1e-9)
    shown = ", ".join(f"{c:.4g}" for c in expected)
    assert (f"surface colour C = ({shown}): the material's (0.5, 1, 1) × the texture at the "
            "hit's texture coordinates × the vertex colours there") in str(tree)
    plain = pp.Mesh(corners, [[0, 1, 2, 3]], pp.Material(color=(0.5, 1.0, 1.0)))
    tree = ray_tree(pp.Scene(camera, objects=[plain]), (4, 4), max_depth=0)
    assert tree.root.surface.tolist() == [0.5, 1.0, 1.0]
    assert "surface colour" not in str(tree)  # the material's colour, which the terms show
