"""The ray tree figure: rays drawn where the cameras see them, each kind in its colour."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.figures._canvas import COLOURS, GAP, HEADER, MARGIN
from pixelpath.figures.ray_tree import overview_camera, ray_tree_figure
from pixelpath.raytrace import ray_tree

# The scene camera's 40 x 30 image is drawn 8 times larger: 320 x 240 panels.
PANEL_W, PANEL_H = 320, 240


def _scene(objects=None) -> pp.Scene:
    camera = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30)
    return pp.Scene(camera, objects or [pp.Sphere((0, 0, 0), 1.0)],
                    lights=[pp.PointLight((2, 3, 4))])


def _side() -> pp.Camera:
    # Looking along -x from (10, 0, 0), 90° vertically: a point (x, y, z) is at depth 10 - x,
    # to the right by -z, so at pixel (160 + 120 · (-z) / (10 - x), 120 - 120 · y / (10 - x)).
    return pp.Camera(eye=(10, 0, 0), target=(0, 0, 0), fov=90, width=PANEL_W, height=PANEL_H)


def _mask(figure, colour: str, panel: int) -> np.ndarray:
    array = np.asarray(figure)
    left = MARGIN + panel * (PANEL_W + GAP)
    part = array[HEADER : HEADER + PANEL_H, left : left + PANEL_W]
    return np.all(part == np.array(COLOURS[colour], dtype=part.dtype), axis=-1)


def test_primary_ray_runs_from_the_eye_to_its_hit_in_the_side_view():
    tree = ray_tree(_scene(), (20, 15))
    figure = ray_tree_figure(tree, overview=_side())
    primary = _mask(figure, "primary ray", 1)
    # The eye (0, 0, 5) is at pixel (100, 120); the hit, near (0, 0, 1), at (148, 120).
    assert primary[119:122, 95:106].any(), "the eye is not marked where it projects"
    # (up to the white rim of the dot marking the hit)
    assert primary[118:124, 104:142].any(axis=0).all(), "no eye ray from the eye to the hit"
    # Nothing else is drawn in its colour (the eye's label "eye" is written above the eye).
    ys, xs = np.nonzero(primary)
    assert xs.min() >= 95 and xs.max() <= 153 and ys.min() >= 100 and ys.max() <= 126


def test_primary_ray_is_a_point_at_the_pixel_in_the_cameras_view():
    tree = ray_tree(_scene(), (20, 15))
    figure = ray_tree_figure(tree, overview=_side())
    primary = _mask(figure, "primary ray", 0)
    # Pixel (20, 15)'s centre, 8 times larger: (164, 124); the ring around it has radius 7.
    ys, xs = np.nonzero(primary)
    assert len(xs)
    assert np.hypot(xs - 164, ys - 124).max() <= 9


def test_each_kind_of_ray_has_its_colour():
    mirror = pp.Material(color=(0.9, 0.9, 0.9), kd=0.2, reflectivity=0.6)
    glass = pp.Material(color=(0.9, 0.9, 0.9), kd=0.1, transparency=0.8, ior=1.5)
    # The eye ray hits the glass sphere, whose refracted ray goes on to the mirror behind it.
    scene = _scene([pp.Sphere((0, 0, 0), 1.0, glass), pp.Sphere((0, 0, -4), 1.5, mirror)])
    tree = ray_tree(scene, (20, 15))
    kinds = {node.kind for node in tree.root.walk()}
    assert {"primary", "reflected", "refracted"} <= kinds
    figure = ray_tree_figure(tree, overview=_side())
    for colour in ("primary ray", "reflected ray", "refracted ray", "shadow ray"):
        assert _mask(figure, colour, 1).any(), colour


def test_overview_camera_sees_the_eye_and_every_hit():
    tree = ray_tree(_scene(), (20, 15))
    camera = overview_camera(tree)
    from pixelpath.raster.transform import world_to_clip

    points = [tree.scene.camera.eye, *(n.point for n in tree.root.walk() if n.hit)]
    clip = world_to_clip(np.array(points), camera)
    ndc = clip[:, :3] / clip[:, 3:]
    assert np.all(np.abs(ndc[:, :2]) < 1)


def test_tree_figure_method_and_bad_input():
    tree = ray_tree(_scene(), (20, 15))
    assert tree.figure().mode == "RGB"
    assert tree._repr_png_().startswith(b"\x89PNG")
    with pytest.raises(TypeError, match="RayTree"):
        ray_tree_figure("not a tree")
    with pytest.raises(TypeError, match="Camera"):
        ray_tree_figure(tree, overview=(10, 0, 0))
