"""Animation: interpolation on hand cases, the turntable, frame 0, errors of [animation]."""

from __future__ import annotations

import ast
import json
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pixelpath.scene import (
    Animation,
    Box,
    Camera,
    CameraKey,
    ObjectKey,
    Plane,
    Scene,
    Sphere,
    Turntable,
    bundled_scene,
    load_scene,
)
from pixelpath.scene.animation import ease

CAMERA = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=40)


def _scene(animation, objects=None):
    objects = [Sphere((1, 0, 0), 1.0)] if objects is None else objects
    return Scene(CAMERA, objects, animation=animation)


def test_ease_on_hand_values():
    assert [ease(t, "linear") for t in (0.0, 0.25, 1.0)] == [0.0, 0.25, 1.0]
    # 3t² − 2t³: 3/16 − 2/64 = 0.15625; 27/16 − 54/64 = 0.84375
    assert [ease(t, "smooth") for t in (0.0, 0.25, 0.5, 0.75, 1.0)] == [
        0.0, 0.15625, 0.5, 0.84375, 1.0
    ]


def test_linear_camera_key_from_the_camera_as_written():
    scene = _scene(Animation(6, camera=[CameraKey(4, eye=(0, 0, 9))]))
    eyes = [scene.at_frame(frame).camera.eye[2] for frame in range(6)]
    assert eyes == [5.0, 6.0, 7.0, 8.0, 9.0, 9.0]  # holds after the last key


def test_smooth_fov_eases_in_and_out():
    scene = _scene(Animation(5, camera=[CameraKey(4, fov=80)], interpolation="smooth"))
    fovs = [scene.camera_at(frame).fov for frame in range(5)]
    assert fovs == [40.0, 46.25, 60.0, 73.75, 80.0]


def test_each_segment_uses_its_start_keys_interpolation():
    keys = [
        CameraKey(2, target=(0, 2, 0), interpolation="smooth"),
        CameraKey(6, target=(0, 6, 0)),
    ]
    scene = _scene(Animation(7, camera=keys))  # default linear: frames 0..2 linear, then smooth
    heights = [scene.camera_at(frame).target[1] for frame in range(7)]
    assert heights == [0.0, 1.0, 2.0, 2.0 + 4 * 0.15625, 4.0, 2.0 + 4 * 0.84375, 6.0]


def test_keys_may_be_given_in_any_order():
    keys = [CameraKey(4, eye=(0, 0, 9)), CameraKey(2, eye=(0, 0, 1))]
    scene = _scene(Animation(5, camera=keys))
    assert [scene.camera_at(f).eye[2] for f in range(5)] == [5.0, 3.0, 1.0, 5.0, 9.0]


def test_object_keys_translate_rotate_and_scale_the_placed_object():
    keys = [ObjectKey(0, 2, rotate=(0, 90, 0)), ObjectKey(0, 4, translate=(0, 4, 0), scale=3)]
    scene = _scene(Animation(5, objects=keys))
    # frame 2: rotated 90° about +Y (+X turns to −Z); translate halfway (0, 2, 0); scale 2
    sphere = scene.at_frame(2).objects[0]
    assert np.allclose(sphere.center, [0, 2, -2], atol=1e-12) and sphere.radius == 2.0
    # frame 4: the rotation holds after its last key; translate (0, 4, 0), scale 3
    sphere = scene.at_frame(4).objects[0]
    assert np.allclose(sphere.center, [0, 4, -3], atol=1e-12) and sphere.radius == 3.0


def test_a_rotated_box_becomes_a_mesh_and_an_unkeyed_object_is_untouched():
    floor = Plane((0, 0, 0), (0, 1, 0))
    box = Box((0, 0, 0), (1, 1, 1))
    scene = _scene(Animation(3, objects=[ObjectKey(1, 2, rotate=(0, 0, 45))]), [floor, box])
    moved = scene.at_frame(2).objects
    assert moved[0] is floor
    assert type(moved[1]).__name__ == "Mesh"
    assert np.allclose(moved[1].bounds()[1][:2], [np.sqrt(0.5), np.sqrt(2)])  # corners turned


def test_turntable_orbits_the_centre_of_the_bounds():
    objects = [Sphere((0, 0, 0), 1.0), Box((-1, -1, -1), (1, 1, 1)), Plane((0, -1, 0), (0, 1, 0))]
    scene = _scene(Animation(4, turntable=Turntable()), objects)
    eyes = [scene.camera_at(frame).eye for frame in range(4)]
    expected = [[0, 0, 5], [5, 0, 0], [0, 0, -5], [-5, 0, 0]]  # counter-clockwise from above
    assert np.allclose(eyes, expected, atol=1e-12)
    assert np.allclose(scene.camera_at(3).target, 0.0, atol=1e-12)


def test_turntable_about_a_given_centre_turns_the_target_too():
    scene = _scene(Animation(2, turntable=Turntable(turns=0.5, center=(1, 0, 0))))
    camera = scene.camera_at(1)  # a quarter turn about x = 1, z = 0
    assert np.allclose(camera.eye, [6, 0, 1], atol=1e-12)
    assert np.allclose(camera.target, [1, 0, 1], atol=1e-12)


def test_frame_zero_is_the_scene_as_written_exactly():
    scene = _scene(
        Animation(
            9,
            camera=[CameraKey(8, eye=(1, 2, 3))],
            objects=[ObjectKey(0, 8, rotate=(10, 20, 30))],
            turntable=Turntable(turns=2),
            interpolation="smooth",
        )
    )
    first = scene.at_frame(0)
    assert first.camera == scene.camera and first.objects == scene.objects
    assert first.animation is None


def test_a_scene_without_animation_is_the_same_at_every_frame():
    scene = _scene(None)
    assert scene.at_frame(0) is scene and scene.at_frame(1234) is scene
    with pytest.raises(ValueError, match="frame must be >= 0"):
        scene.at_frame(-1)
    with pytest.raises(TypeError, match="frame must be an int"):
        scene.at_frame(1.5)


@pytest.mark.parametrize(
    ("make", "error", "match"),
    [
        (lambda: Animation(0), ValueError, "frames must be between 1 and"),
        (lambda: Animation(5, [CameraKey(0, fov=30)]), ValueError, "frame 0 is the scene"),
        (lambda: Animation(5, [CameraKey(5, fov=30)]), ValueError, r"outside the animation"),
        (
            lambda: Animation(5, [CameraKey(2, fov=30), CameraKey(2, eye=(1, 1, 1))]),
            ValueError,
            r"camera\[1\]: a second key at frame 2 \(the first is camera\[0\]\)",
        ),
        (lambda: CameraKey(1), ValueError, "at least one of eye, target, fov"),
        (lambda: CameraKey(1, fov=0), ValueError, "fov"),
        (lambda: ObjectKey(0, 1, scale=-1), ValueError, "scale factors must be positive"),
        (lambda: ObjectKey(0, 1, rotate=(1, 2)), ValueError, r"rotate must have shape \(3,\)"),
        (lambda: Animation(3, interpolation="cubic"), ValueError, "'linear', 'smooth'"),
        (lambda: Turntable(turns=0), ValueError, "turns must be non-zero"),
        (lambda: Animation(3, camera=[object()]), TypeError, r"camera\[0\] must be a CameraKey"),
    ],
)
def test_bad_animations_are_refused(make, error, match):
    with pytest.raises(error, match=match):
        make()


def test_keys_that_do_not_fit_the_scene_are_refused():
    with pytest.raises(ValueError, match=r"animation\.objects\[0\]: object 3 does not exist"):
        _scene(Animation(3, objects=[ObjectKey(3, 1, translate=(1, 0, 0))]))
    with pytest.raises(ValueError, match=r"objects\[0\]: scale must be uniform for a sphere"):
        _scene(Animation(3, objects=[ObjectKey(0, 1, scale=(1, 2, 1))]))
    with pytest.raises(ValueError, match=r"animation\.camera\[0\]: at frame 2: eye and target"):
        _scene(Animation(3, camera=[CameraKey(2, eye=(0, 0, 0))]))
    with pytest.raises(ValueError, match="no bounded objects to orbit; give the turntable a"):
        _scene(Animation(3, turntable=Turntable()), [Plane((0, 0, 0), (0, 1, 0))])


ANIMATED = textwrap.dedent(
    """\
    [camera]
    eye = [0, 1, 6]
    target = [0, 0, 0]

    [[objects]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 1

    [[objects]]
    type = "torus"
    name = "ring"

    [animation]
    frames = 10
    interpolation = "smooth"

    [animation.turntable]
    turns = 0.5

    [[animation.camera]]
    frame = 9
    fov = 30

    [[animation.objects]]
    object = "ring"
    frame = 9
    rotate = [0, 180, 0]
    interpolation = "linear"
    """
)


def _write(tmp_path, text):
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


def test_animation_table_loads_and_round_trips(tmp_path):
    scene = load_scene(_write(tmp_path, ANIMATED))
    animation = scene.animation
    assert animation.frames == 10 and animation.interpolation == "smooth"
    assert animation.turntable == Turntable(turns=0.5)
    assert animation.camera == (CameraKey(9, fov=30.0),)
    assert animation.objects == (ObjectKey(1, 9, rotate=(0, 180, 0), interpolation="linear"),)
    data = json.loads(json.dumps(scene.to_dict()))
    assert Scene.from_dict(data) == scene
    jsonschema = pytest.importorskip("jsonschema")
    from pixelpath.scene.schema import scene_json_schema

    jsonschema.validate(data, scene_json_schema())


@pytest.mark.parametrize(
    ("old", "new", "match"),
    [
        ("frame = 9\nfov", "frame = 0\nfov",
         r"animation\.camera\[0\]\.frame \(near line 22\): frame 0 is the scene as written"),
        ("frame = 9\nfov", "frame = 12\nfov",
         r"animation\.camera\[0\]\.frame \(near line 22\): frame 12 is outside the animation"),
        ("fov = 30", "fov = 300",
         r"animation\.camera\[0\]\.fov \(near line 23\): fov \(vertical"),
        ("fov = 30", "fvo = 30",
         r"animation\.camera\[0\]\.fvo \(near line 23\): unknown key; expected one of: eye, "),
        ('object = "ring"', 'object = "rings"',
         r"animation\.objects\[0\]\.object \(near line 26\): no object is named 'rings'; use "
         r"an index or one of the names: ring"),
        ('object = "ring"', "object = 2",
         r"animation\.objects\[0\]\.object \(near line 26\): no object 2: \[\[objects\]\] are"),
        ('object = "ring"\nframe = 9\nrotate = [0, 180, 0]',
         "object = 0\nframe = 9\nscale = [1, 2, 1]",
         r"animation\.objects\[0\]\.scale \(near line 28\): scale must be uniform for a sphere"),
        ('interpolation = "linear"', 'interpolation = "cubic"',
         r"animation\.objects\[0\]\.interpolation \(near line 29\): expected 'linear' or 'smooth'"),
        ("frames = 10", "frames = 0",
         r"animation\.frames \(near line 15\): frames must be between 1 and 1,000,000, got 0"),
        ("frames = 10", "frame = 10",
         r"animation\.frame \(near line 15\): unknown key; expected one of: camera, frames"),
        ("turns = 0.5", "turns = 0",
         r"animation\.turntable\.turns \(near line 19\): turns must be non-zero"),
    ],
)
def test_animation_errors_name_the_key_and_line(tmp_path, old, new, match):
    assert old in ANIMATED
    with pytest.raises(ValueError, match=match):
        load_scene(_write(tmp_path, ANIMATED.replace(old, new, 1)))


def test_a_duplicate_key_is_named(tmp_path):
    text = ANIMATED + "\n[[animation.camera]]\nframe = 9\neye = [1, 1, 1]\n"
    with pytest.raises(ValueError, match=r"animation\.camera\[1\] \(near line 31\): a second key"):
        load_scene(_write(tmp_path, text))


def test_the_showcase_turns_once_in_120_frames():
    scene = load_scene(bundled_scene("showcase"))
    assert scene.animation == Animation(120, turntable=Turntable(turns=1))
    low, high = scene.bounds()
    centre = (low + high) / 2
    eye0, eye60 = scene.camera_at(0).eye, scene.camera_at(60).eye
    assert np.allclose(eye0 + eye60 - 2 * centre, [0, 2 * (eye0[1] - centre[1]), 0])  # opposite


def test_the_scene_model_does_not_import_its_file_format():
    """Issue 10: loader and schema depend on the model, never the other way round."""
    folder = Path(__file__).resolve().parents[2] / "src" / "pixelpath" / "scene"
    format_modules = {"pixelpath.scene.loader", "pixelpath.scene.schema"}
    for path in folder.glob("*.py"):
        if path.stem in ("loader", "schema", "__init__"):
            continue
        imported = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module:
                imported.add(node.module)
                imported.update(f"{node.module}.{alias.name}" for alias in node.names)
            elif isinstance(node, ast.Import):
                imported.update(alias.name for alias in node.names)
        assert not imported & format_modules, f"{path.name} imports {imported & format_modules}"


def test_the_animation_example_of_the_format_document_loads(tmp_path):
    import re

    text = (Path(__file__).resolve().parents[2] / "docs" / "scene-format.md").read_text()
    example = next(
        block for block in re.findall(r"```toml\n(.*?)```", text, re.DOTALL)
        if block.startswith("[animation]")
    )
    head = '[camera]\neye = [0, 2, 8]\ntarget = [0, 0, 0]\n[[objects]]\ntype = "torus"\n'
    scene = load_scene(_write(tmp_path, head + 'name = "ring"\n' + example))
    assert scene.animation.frames == 120 and scene.animation.turntable.turns == 1
    assert scene.camera_at(60).fov == 50.0


def test_view_height_keys_zoom_an_orthographic_camera():
    from pixelpath.scene import Camera, Scene
    from pixelpath.scene.animation import Animation, CameraKey

    camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), projection="orthographic", view_height=2.0)
    animation = Animation(11, camera=[CameraKey(10, view_height=6.0)])
    scene = Scene(camera, animation=animation)
    assert [scene.camera_at(f).view_height for f in (0, 5, 10)] == [2.0, 4.0, 6.0]
    assert scene.camera_at(5).projection == "orthographic"


def test_view_height_keys_on_a_perspective_camera_are_refused():
    from pixelpath.scene import Camera, Scene
    from pixelpath.scene.animation import Animation, CameraKey

    animation = Animation(11, camera=[CameraKey(10, view_height=6.0)])
    with pytest.raises(ValueError, match=r"camera\[0\].*view_height keys zoom an orthographic"):
        Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), animation=animation)
    with pytest.raises(ValueError, match="view_height must be positive"):
        CameraKey(10, view_height=0)


def test_view_height_keys_load_from_toml(tmp_path):
    from pixelpath.scene import load_scene

    path = tmp_path / "zoom.toml"
    path.write_text(
        '[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\nprojection = "orthographic"\n'
        "view_height = 2.0\n\n[animation]\nframes = 5\n\n[[animation.camera]]\nframe = 4\n"
        "view_height = 10.0\n"
    )
    scene = load_scene(path)
    assert scene.camera_at(2).view_height == 6.0
    assert scene.at_frame(4).camera.view_height == 10.0
