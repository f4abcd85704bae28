"""A model file's up axis: Z-up (and other) files turned to stand on +Y as they are read."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import pixelpath as pp
from pixelpath.io.models import UP_AXES, read_model, up_axis

DATA = Path(__file__).resolve().parents[1] / "data" / "models"

# Where each up axis sends a file's point (x, y, z), worked out by hand: the up axis becomes
# +Y, and a Z-up file's front (-Y, as CAD programs show it) faces +Z, towards the camera.
EXPECTED = {
    "+y": lambda x, y, z: (x, y, z),
    "+z": lambda x, y, z: (x, z, -y),
    "+x": lambda x, y, z: (-y, x, z),
    "-y": lambda x, y, z: (-x, -y, z),
    "-z": lambda x, y, z: (x, -z, y),
    "-x": lambda x, y, z: (y, -x, z),
}


@pytest.mark.parametrize("up", UP_AXES)
def test_each_up_axis_moves_every_point_as_worked_out_by_hand(block, up):
    plain = read_model(block).objects[0]
    turned = read_model(block, up=up).objects[0]
    expected = np.array([EXPECTED[up](*point) for point in plain.vertices.tolist()])
    assert turned.vertices.tolist() == expected.tolist()  # exact: only reordered and negated
    assert np.array_equal(turned.face_indices, plain.face_indices)


@pytest.mark.parametrize("up", UP_AXES)
def test_a_turned_part_keeps_its_faces_facing_out(block, up):
    # a rotation, never a mirror: a closed box's faces still face away from its centre
    mesh = read_model(block, up=up).objects[0]
    centre = mesh.vertices.mean(axis=0)
    corners = mesh.vertices[mesh.triangles].mean(axis=1)
    assert np.all(np.einsum("ij,ij->i", corners - centre, mesh.face_normals) > 0.0)


def test_a_z_up_part_stands_up_and_shows_its_front(block):
    scene = pp.load_scene(block, up="z")
    low, high = scene.bounds()
    assert (high - low).tolist() == [1.0, 4.0, 2.0]  # its 4 units of height now along +Y
    # the framing camera looks from the front (+Z) and above, at the part's -Y side
    view = scene.camera.eye - scene.camera.target
    assert view[2] > 0.0 and view[1] > 0.0 and abs(view[0]) < 1e-9
    image = pp.render(scene)
    drawn = np.argwhere(np.asarray(image.object_id) >= 0)
    height, width = drawn.max(axis=0) - drawn.min(axis=0)
    assert height > 2 * width  # a tall block, where the default framing saw a flat one


def test_the_file_camera_and_lights_turn_with_the_model(tmp_path):
    # Everything in the file turns together, so the picture is the same: the rotation is
    # exact, and only the order of a few sums in the projection differs
    gltf = json.loads((DATA / "BoxVertexColors.gltf").read_text())
    gltf["cameras"] = [{"type": "perspective",
                        "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100.0}}]
    gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "intensity": 1.0}, {"type": "point", "intensity": 30.0}]}}
    gltf.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
    gltf["nodes"] += [
        {"translation": [0.5, 1.0, 4.0], "camera": 0},
        {"rotation": [-0.3826834, 0.0, 0.0, 0.9238795],
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"translation": [2.0, 3.0, 2.0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    ]
    count = len(gltf["nodes"])
    gltf["scenes"][gltf.get("scene", 0)]["nodes"] += [count - 3, count - 2, count - 1]
    path = tmp_path / "lit.gltf"
    path.write_text(json.dumps(gltf))
    plain = read_model(path, size=(96, 72))
    turned = read_model(path, size=(96, 72), up="-x")
    assert turned.camera.eye.tolist() == list(EXPECTED["-x"](*plain.camera.eye.tolist()))
    assert turned.lights[1].position.tolist() == list(
        EXPECTED["-x"](*plain.lights[1].position.tolist()))
    first, second = pp.render(plain), pp.render(turned)
    assert (np.asarray(first.object_id) >= 0).mean() > 0.05  # the box is in the picture
    assert np.abs(np.asarray(first) - np.asarray(second)).max() < 1e-5


def test_bad_up_axes_are_refused_before_the_file_is_read(block, tmp_path):
    assert up_axis("Z") == "+z" and up_axis(" -x") == "-x"
    with pytest.raises(ValueError, match=r"up must be one of \+y, \+z"):
        read_model(block, up="w")
    with pytest.raises(TypeError, match="up must be a str"):
        read_model(block, up=2)
    with pytest.raises(ValueError, match="applies to model files"):
        scene = tmp_path / "s.toml"
        scene.write_text('[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n')
        pp.load_scene(scene, up="z")
    with pytest.raises(TypeError, match="up must be a str"):
        pp.load_scene(scene, up=None)
    assert pp.load_scene(scene, up="Y") == pp.load_scene(scene)
    assert pp.load_scene(block, up="y") == pp.load_scene(block)


def test_views_are_placed_round_the_turned_model_and_resume_only_so(block, tmp_path):
    out = tmp_path / "views"
    poses = pp.render_views(block, 2, out, size=(16, 16), up="z")
    document = json.loads((out / "transforms.json").read_text())
    assert document["pixelpath"]["up"] == "+z"
    assert np.array_equal(poses, pp.render_views(block, 2, out, size=(16, 16), up="+z",
                                                 resume=True))
    with pytest.raises(ValueError, match="resume cannot complete"):
        pp.render_views(block, 2, out, size=(16, 16), resume=True)
    with pytest.raises(ValueError, match="pass the file's path"):
        pp.render_views(pp.load_scene(block), 2, tmp_path / "other", up="z")


def run_cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pixelpath", *args], capture_output=True,
                          text=True, check=False)


def test_the_cli_turns_model_files_and_refuses_up_elsewhere(block, tmp_path):
    out = tmp_path / "block.png"
    done = run_cli("render", str(block), "-o", str(out), "--size", "48x48", "--up=-z", "-q")
    assert done.returncode == 0, done.stderr
    reference = tmp_path / "reference.png"
    pp.render(read_model(block, size=(48, 48), up="-z")).save(reference)
    assert np.array_equal(np.asarray(Image.open(out)), np.asarray(Image.open(reference)))
    bad = run_cli("render", str(block), "-o", str(out), "--up", "w")
    assert bad.returncode == 2 and "--up: up must be one of" in bad.stderr
    elsewhere = run_cli("render", "showcase", "-o", str(out), "--up", "z")
    assert elsewhere.returncode == 2 and "--up applies to model files" in elsewhere.stderr
