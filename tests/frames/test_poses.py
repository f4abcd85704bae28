"""Camera layouts of a dataset of views: known spacings, invariants and seeded reproducibility."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import pixelpath as pp
from pixelpath.frames.poses import place_cameras, view_directions


def test_orbit_views_are_evenly_spaced_at_one_elevation():
    directions = view_directions(8, "orbit", elevation=30)
    assert np.allclose(directions[:, 1], 0.5)  # sin 30°
    azimuths = np.degrees(np.arctan2(directions[:, 0], directions[:, 2])) % 360
    assert np.allclose(azimuths, np.arange(8) * 45.0)


def test_the_sphere_layout_covers_the_upper_hemisphere_evenly():
    directions = view_directions(400, "sphere")
    assert np.allclose(np.linalg.norm(directions, axis=1), 1.0)
    assert (directions[:, 1] > 0).all()
    # equal areas: as many views in the band 0 < y < 0.5 as in 0.5 < y < 1 (Archimedes)
    assert abs(int((directions[:, 1] < 0.5).sum()) - 200) <= 1
    # and round the axis: each quadrant of azimuth holds a quarter
    quadrants = np.histogram(np.arctan2(directions[:, 0], directions[:, 2]), bins=4,
                             range=(-math.pi, math.pi))[0]
    assert (abs(quadrants - 100) <= 3).all()


def test_the_full_sphere_has_views_from_below():
    directions = view_directions(100, "sphere", hemisphere=False)
    assert abs(int((directions[:, 1] < 0).sum()) - 50) <= 1


def test_random_views_repeat_with_the_seed_and_change_with_it():
    first = view_directions(20, "random", seed=3)
    assert np.array_equal(first, view_directions(20, "random", seed=3))
    assert not np.allclose(first, view_directions(20, "random", seed=4))
    assert (first[:, 1] >= 0).all() and np.allclose(np.linalg.norm(first, axis=1), 1.0)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"n": 0}, "at least 1 view"),
        ({"n": 3, "layout": "spiral"}, "unknown layout 'spiral'"),
        ({"n": 3, "layout": "sphere", "elevation": 10}, "elevation applies to the orbit"),
        ({"n": 3, "elevation": 95}, "elevation must be degrees in -89..89"),
        ({"n": 3, "layout": "random", "seed": -1}, "seed must be a whole number"),
    ],
)
def test_bad_layouts_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        view_directions(**kwargs)


def test_n_must_be_an_int():
    with pytest.raises(TypeError, match="n must be an int"):
        view_directions(2.5)


def _scene(objects):
    return pp.Scene(pp.Camera(eye=(0, 0, 9), target=(0, 0, 0)), objects)


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(["orbit", "sphere", "random"]),
    st.integers(1, 12),
    st.integers(0, 1000),
    st.tuples(st.integers(16, 400), st.integers(16, 400)),
)
def test_every_corner_of_the_model_is_inside_every_view(layout, n, seed, size):
    box = pp.Box((-2.0, 0.0, -0.5), (1.0, 0.7, 3.0))
    scene = _scene([box])
    cameras = place_cameras(scene, view_directions(n, layout, seed=seed), size)
    for camera in (cameras.camera(index) for index in range(n)):
        corners = np.array(np.meshgrid(*box.bounds().T, indexing="ij")).reshape(3, -1).T
        view = camera.view_matrix() @ np.c_[corners, np.ones(8)].T
        depth = -view[2]
        tan_v = math.tan(math.radians(camera.fov) / 2)
        assert (depth > camera.near).all() and (depth < camera.far).all()
        assert (np.abs(view[1]) <= tan_v * depth * (1 + 1e-9)).all()
        assert (np.abs(view[0]) <= tan_v * camera.aspect * depth * (1 + 1e-9)).all()
        assert np.allclose(camera.target, box.bounds().mean(axis=0))


def test_all_views_stand_at_one_distance_unless_told():
    scene = _scene([pp.Box((-2, 0, -0.5), (1, 0.7, 3))])
    cameras = place_cameras(scene, view_directions(7, "sphere"), (64, 48))
    distances = np.linalg.norm(cameras.eyes - cameras.target, axis=1)
    assert np.allclose(distances, distances[0])
    told = place_cameras(scene, view_directions(3), (64, 48), distance=20.0)
    assert np.allclose(np.linalg.norm(told.eyes - told.target, axis=1), 20.0)


def test_views_from_straight_above_have_a_valid_up():
    scene = _scene([pp.Sphere((0, 0, 0), 1.0)])
    camera = place_cameras(scene, np.array([[0.0, 1.0, 0.0]]), (32, 32), distance=5).camera(0)
    right, up, back = camera.basis()
    assert np.allclose(back, (0, 1, 0)) and np.allclose(up, (0, 0, -1))
    assert np.allclose(right, (1, 0, 0))  # the model's front (+Z) at the bottom of the picture


def test_a_scene_without_anything_bounded_cannot_be_framed():
    with pytest.raises(ValueError, match="no bounded objects"):
        place_cameras(_scene([pp.Plane((0, 0, 0), (0, 1, 0))]), view_directions(2), (8, 8))


def test_poses_invert_each_camera_s_view_matrix_in_opengl_axes():
    scene = _scene([pp.Box((-2, 0, -0.5), (1, 0.7, 3))])
    cameras = place_cameras(scene, view_directions(40, "random", hemisphere=False), (20, 10))
    for index, pose in enumerate(cameras.poses()):
        camera = cameras.camera(index)
        assert np.allclose(pose @ camera.view_matrix(), np.eye(4))
        distance = np.linalg.norm(camera.eye - camera.target)
        assert np.allclose(pose @ [0, 0, -distance, 1], [*camera.target, 1])  # looks down -Z
        assert np.allclose(pose[:3, 1], camera.basis()[1])  # the camera's +Y is its up
