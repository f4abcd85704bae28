"""Camera basis and matrices against hand-derived values; validation of every argument."""

from __future__ import annotations

import dataclasses
import math
import pickle

import numpy as np
import pytest

from pixelpath.scene import Camera


def ndc(camera: Camera, world_point) -> np.ndarray:
    clip = camera.projection_matrix() @ camera.view_matrix() @ np.append(world_point, 1.0)
    return clip[:3] / clip[3]


def test_basis_looking_down_minus_z_is_the_identity():
    u, v, w = Camera(eye=(0, 0, 5), target=(0, 0, 0)).basis()
    np.testing.assert_array_equal(np.stack([u, v, w]), np.eye(3))


def test_basis_looking_down_minus_x():
    # w = eye - target = +x; u = up x w = (0,1,0) x (1,0,0) = (0,0,-1); v = w x u = (0,1,0)
    u, v, w = Camera(eye=(5, 0, 0), target=(0, 0, 0)).basis()
    np.testing.assert_allclose(u, [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(v, [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(w, [1, 0, 0], atol=1e-15)


def test_basis_is_orthonormal_and_right_handed_for_a_tilted_up():
    u, v, w = Camera(eye=(1, 2, 3), target=(-2, 0.5, 1), up=(0.3, 1, 0.2)).basis()
    frame = np.stack([u, v, w])
    np.testing.assert_allclose(frame @ frame.T, np.eye(3), atol=1e-14)
    np.testing.assert_allclose(np.cross(u, v), w, atol=1e-14)


def test_the_kept_basis_is_read_only_and_follows_a_changed_camera():
    camera = Camera(eye=(5, 0, 0), target=(0, 0, 0))
    u = camera.basis()[0]
    with pytest.raises(ValueError, match="read-only"):
        u[0] = 1.0
    moved = dataclasses.replace(camera, eye=(0, 0, 5))
    np.testing.assert_array_equal(np.stack(moved.basis()), np.eye(3))
    assert camera.basis()[2].tolist() == [1.0, 0.0, 0.0]  # the first camera's, unchanged
    copy = pickle.loads(pickle.dumps(camera))
    np.testing.assert_array_equal(np.stack(copy.basis()), np.stack(camera.basis()))


def test_view_matrix_sends_eye_to_origin_and_target_down_minus_z():
    camera = Camera(eye=(1, 2, 3), target=(4, 6, 3))  # distance 5 along (0.6, 0.8, 0)
    view = camera.view_matrix()
    np.testing.assert_allclose(view @ [1, 2, 3, 1], [0, 0, 0, 1], atol=1e-14)
    np.testing.assert_allclose(view @ [4, 6, 3, 1], [0, 0, -5, 1], atol=1e-14)


def test_view_matrix_hand_values_for_a_camera_on_the_x_axis():
    view = Camera(eye=(5, 0, 0), target=(0, 0, 0)).view_matrix()
    expected = [[0, 0, -1, 0], [0, 1, 0, 0], [1, 0, 0, -5], [0, 0, 0, 1]]
    np.testing.assert_allclose(view, expected, atol=1e-15)


def test_projection_matrix_hand_values():
    # fov 90 -> f = 1/tan(45°) = 1; aspect 2; near 1, far 3:
    # [f/a, 0, 0, 0], [0, f, 0, 0], [0, 0, (3+1)/(1-3), 2*3*1/(1-3)], [0, 0, -1, 0]
    camera = Camera(eye=(0, 0, 0), target=(0, 0, -1), fov=90, width=200, height=100, near=1, far=3)
    expected = [[0.5, 0, 0, 0], [0, 1, 0, 0], [0, 0, -2, -3], [0, 0, -1, 0]]
    np.testing.assert_allclose(camera.projection_matrix(), expected, atol=1e-15)


def test_target_projects_to_the_centre_of_the_image():
    camera = Camera(eye=(3, -2, 7), target=(0.5, 1, -1), up=(0, 0, 1), near=0.5, far=50)
    np.testing.assert_allclose(ndc(camera, camera.target)[:2], [0, 0], atol=1e-12)


@pytest.mark.parametrize("fov", [30.0, 60.0, 90.0, 120.0])
@pytest.mark.parametrize(("width", "height"), [(640, 480), (100, 300)])
def test_frustum_corners_map_to_plus_minus_one(fov, width, height):
    near, far = 0.5, 20.0
    camera = Camera(eye=(0, 0, 0), target=(0, 0, -1), fov=fov, width=width, height=height,
                    near=near, far=far)
    for depth, z_ndc in ((near, -1.0), (far, 1.0)):
        half_height = depth * math.tan(math.radians(fov) / 2)
        half_width = half_height * width / height
        for sx in (-1, 1):
            for sy in (-1, 1):
                point = (sx * half_width, sy * half_height, -depth)
                np.testing.assert_allclose(ndc(camera, point), [sx, sy, z_ndc], atol=1e-12)


def test_clip_w_is_the_depth_along_the_viewing_axis():
    camera = Camera(eye=(0, 0, 10), target=(0, 0, 0), fov=60)
    for point, depth in (((0, 0, 0), 10.0), ((1, -2, 4), 6.0), ((3, 3, -5), 15.0)):
        clip = camera.projection_matrix() @ camera.view_matrix() @ np.append(point, 1.0)
        assert clip[3] == pytest.approx(depth)


def test_ndc_depth_increases_with_distance():
    camera = Camera(eye=(0, 0, 0), target=(0, 0, -1), near=0.1, far=100)
    depths = [ndc(camera, (0, 0, -d))[2] for d in (0.1, 1, 10, 50, 100)]
    assert depths[0] == pytest.approx(-1) and depths[-1] == pytest.approx(1)
    assert np.all(np.diff(depths) > 0)


def test_with_size_changes_only_the_size():
    camera = Camera(eye=(1, 2, 3), target=(0, 0, 0), fov=70, near=0.3, far=30)
    small = camera.with_size(64, 32)
    assert (small.width, small.height, small.fov, small.near) == (64, 32, 70, 0.3)
    np.testing.assert_array_equal(small.eye, camera.eye)
    assert small.aspect == 2.0


def test_vectors_are_read_only_float64():
    camera = Camera(eye=[0, 0, 5], target=[0, 0, 0])
    assert camera.eye.dtype == np.float64
    with pytest.raises(ValueError, match="read-only"):
        camera.eye[0] = 1.0


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"fov": 0}, ValueError, "fov"),
        ({"fov": 180}, ValueError, "fov"),
        ({"fov": float("nan")}, ValueError, "fov must be finite"),
        ({"width": 0}, ValueError, "width"),
        ({"height": 10**6}, ValueError, "height must be between 1 and 16384"),
        ({"width": 2.5}, TypeError, "width must be an int"),
        ({"width": True}, TypeError, "width"),
        ({"near": 0}, ValueError, "near must be positive"),
        ({"near": 5, "far": 5}, ValueError, "far must be greater than near"),
        ({"eye": (0, 0, 0)}, ValueError, "eye and target must differ"),
        ({"up": (0, 0, 2)}, ValueError, "parallel"),
        ({"eye": (0, float("nan"), 5)}, ValueError, "eye must be finite"),
        ({"eye": (0, 5)}, ValueError, r"eye must have shape \(3,\), got shape \(2,\)"),
        ({"target": "origin"}, TypeError, "target"),
    ],
)
def test_invalid_arguments_are_named(kwargs, error, message):
    arguments = {"eye": (0, 0, 5), "target": (0, 0, 0), **kwargs}
    with pytest.raises(error, match=message):
        Camera(**arguments)


# Orthographic cameras.


def ortho(**kwargs) -> Camera:
    arguments = {"eye": (0, 0, 5), "target": (0, 0, 0), "width": 8, "height": 4, "near": 1,
                 "far": 9, "projection": "orthographic", "view_height": 2.0, **kwargs}
    return Camera(**arguments)


def test_orthographic_view_box_maps_to_plus_minus_one():
    # view_height 2 and aspect 2: the box is x in [-2, 2], y in [-1, 1], depth in [1, 9].
    camera = ortho()
    np.testing.assert_allclose(ndc(camera, (2, 1, 5 - 1)), [1, 1, -1], atol=1e-15)
    np.testing.assert_allclose(ndc(camera, (-2, -1, 5 - 9)), [-1, -1, 1], atol=1e-15)
    np.testing.assert_allclose(ndc(camera, (1, -0.5, 0)), [0.5, -0.5, 0.0], atol=1e-15)


def test_orthographic_size_on_screen_does_not_depend_on_depth():
    camera = ortho()
    near_point, far_point = ndc(camera, (1.5, 0.5, 3.5)), ndc(camera, (1.5, 0.5, -3.5))
    np.testing.assert_allclose(near_point[:2], far_point[:2], atol=1e-15)
    assert (camera.projection_matrix() @ camera.view_matrix() @ [1.5, 0.5, -3.5, 1])[3] == 1


def test_viewpoint_is_the_eye_or_the_point_at_infinity_behind_the_camera():
    np.testing.assert_array_equal(Camera(eye=(1, 2, 3), target=(0, 0, 0)).viewpoint(),
                                  [1, 2, 3, 1])
    behind = ortho(eye=(0, 4, 0), target=(0, 0, 0), up=(0, 0, -1)).viewpoint()
    np.testing.assert_array_equal(behind, [0, 1, 0, 0])


def test_perspective_stays_the_default():
    camera = Camera(eye=(0, 0, 5), target=(0, 0, 0))
    assert (camera.projection, camera.view_height, camera.orthographic) == (
        "perspective", None, False)
    assert ortho().orthographic


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"view_height": None}, ValueError, "projection='orthographic' needs view_height"),
        ({"view_height": 0}, ValueError, "view_height must be positive"),
        ({"view_height": -2}, ValueError, "view_height must be positive"),
        ({"view_height": float("inf")}, ValueError, "view_height must be finite"),
        ({"view_height": "4"}, TypeError, "view_height must be a real number"),
        ({"projection": "isometric"}, ValueError, "projection must be one of"),
        ({"projection": 1}, TypeError, "projection must be a string"),
        ({"projection": "perspective", "view_height": 4.0}, ValueError,
         "view_height is for projection='orthographic' only"),
    ],
)
def test_invalid_orthographic_arguments_are_named(kwargs, error, message):
    with pytest.raises(error, match=message):
        ortho(**kwargs)


ORTHO_TOML = """
[camera]
eye = [4, 3, 5]
target = [0, 0, 0]
width = 64
height = 48
projection = "orthographic"
view_height = 4.0

[[objects]]
type = "sphere"
center = [0, 0, 0]
radius = 1
"""


def test_orthographic_camera_round_trips_through_toml_and_to_dict(tmp_path):
    import json

    from pixelpath.scene import Scene, load_scene

    path = tmp_path / "ortho.toml"
    path.write_text(ORTHO_TOML)
    scene = load_scene(path)
    assert (scene.camera.projection, scene.camera.view_height) == ("orthographic", 4.0)
    data = json.loads(json.dumps(scene.to_dict()))
    assert data["camera"]["projection"] == "orthographic"
    assert data["camera"]["view_height"] == 4.0
    assert Scene.from_dict(data).camera == scene.camera
    perspective = Scene.from_dict({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})
    assert "view_height" not in perspective.to_dict()["camera"]  # TOML has no null
    assert Scene.from_dict(perspective.to_dict()).camera == perspective.camera


def test_orthographic_toml_validates_against_the_published_schema(tmp_path):
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    from pixelpath.scene.schema import scene_json_schema

    jsonschema.validate(tomllib.loads(ORTHO_TOML), scene_json_schema())
    bad = tomllib.loads(ORTHO_TOML.replace('"orthographic"', '"isometric"'))
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, scene_json_schema())


def test_orthographic_toml_errors_name_the_file_and_key(tmp_path):
    from pixelpath.scene import load_scene

    path = tmp_path / "bad.toml"
    path.write_text(ORTHO_TOML.replace("view_height = 4.0\n", ""))
    with pytest.raises(ValueError, match=r"bad\.toml.*camera.*needs view_height"):
        load_scene(path)
    path.write_text(ORTHO_TOML.replace('"orthographic"', '"isometric"'))
    with pytest.raises(ValueError, match=r"bad\.toml.*camera\.projection"):
        load_scene(path)
