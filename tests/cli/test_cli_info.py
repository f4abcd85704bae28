"""``pixelpath info``: the summary of a scene file, as tables and as JSON, and its errors."""

from __future__ import annotations

import json
import textwrap

import pytest

from pixelpath.cli import main

SCENE = textwrap.dedent(
    """\
    [camera]
    eye = [0, 0, 10]
    target = [0, 0, 0]
    width = 32
    height = 24

    [[lights]]
    type = "point"
    position = [1, 2, 3]

    [[lights]]
    type = "directional"
    direction = [0, -2, 0]

    [materials.gold]
    color = [1, 0.8, 0.2]

    [[objects]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 2
    material = "gold"

    [[objects]]
    type = "plane"
    point = [0, -2, 0]
    normal = [0, 1, 0]

    [[objects]]
    type = "mesh"
    name = "wedge"
    vertices = [[0, 0, 0], [4, 0, 0], [4, 3, 0], [0, 3, 0], [0, 0, 5]]
    faces = [[0, 1, 2, 3], [0, 4, 1]]
    material = { kd = 0.2 }
    """
)


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def test_json_summary_counts_and_bounds(scene_file, capsys):
    assert main(["info", str(scene_file), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert [obj["type"] for obj in summary["objects"]] == ["sphere", "plane", "mesh"]
    sphere, plane, wedge = summary["objects"]
    assert sphere["material"] == "gold" and sphere["faces"] is None
    assert sphere["bounds"] == [[-2, -2, -2], [2, 2, 2]]
    assert plane["bounds"] is None and plane["material"] == "default"
    assert (wedge["name"], wedge["faces"], wedge["triangles"]) == ("wedge", 2, 3)
    assert wedge["material"] == "inline"
    assert summary["totals"] == {
        "objects": 3, "faces": 2, "triangles": 3, "lights": 2,
        "bounds": [[-2, -2, -2], [4, 3, 5]],
    }  # fmt: skip
    assert summary["lights"][1] == {
        "type": "directional", "direction": [0, -1, 0], "intensity": 1.0, "color": [1, 1, 1]
    }  # fmt: skip
    assert summary["camera"]["width"] == 32 and summary["camera"]["fov"] == 45.0


def test_table_output_names_objects_lights_and_totals(scene_file, capsys):
    assert main(["info", str(scene_file)]) == 0
    out = capsys.readouterr().out
    for text in ("sphere", "plane", "wedge", "gold", "infinite", "directional", "32×24"):
        assert text in out
    assert "total: 3 objects, 2 faces, 3 triangles, 2 lights" in out


def test_totals_say_one_object_not_one_objects(tmp_path, capsys):
    path = tmp_path / "one.toml"
    path.write_text(
        '[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n\n'
        '[[objects]]\ntype = "box"\nminimum = [0, 0, 0]\nmaximum = [1, 1, 1]\n\n'
        '[[lights]]\ntype = "point"\nposition = [0, 3, 3]\n'
    )
    assert main(["info", str(path)]) == 0
    assert "total: 1 object, 6 faces, 12 triangles, 1 light;" in capsys.readouterr().out


def test_errors_exit_2_with_the_file_and_key(scene_file, capsys):
    scene_file.write_text(SCENE.replace("radius = 2", "radius = 0"))
    assert main(["info", str(scene_file)]) == 2
    err = capsys.readouterr().err
    assert "objects[0].radius" in err and "near line 21" in err and "must be positive" in err
    assert main(["info", str(scene_file.parent / "missing.toml")]) == 2
    assert "scene file not found" in capsys.readouterr().err


def test_empty_scene_has_no_bounds(tmp_path, capsys):
    path = tmp_path / "empty.toml"
    path.write_text(SCENE.split("[[lights]]")[0])
    assert main(["info", str(path), "--json"]) == 0
    totals = json.loads(capsys.readouterr().out)["totals"]
    assert totals == {"objects": 0, "faces": 0, "triangles": 0, "lights": 0, "bounds": None}


def test_a_model_file_is_summarized_as_render_reads_it(block, capsys):
    assert main(["info", str(block), "--up", "z", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    # the block spans x 2.5..3.5, y -6..-4, z 0..4; stood up, (x, y, z) goes to (x, z, -y)
    assert summary["totals"]["bounds"] == [[2.5, 0.0, 4.0], [3.5, 4.0, 6.0]]
    assert summary["camera"]["target"] == [3.0, 2.0, 5.0]
    assert main(["info", "showcase", "--frame"]) == 2
    assert "--frame applies to model files" in capsys.readouterr().err
