"""The published format documents: the JSON Schema file and the example of docs/scene-format.md."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from pixelpath.scene import Mesh, Sphere, load_scene
from pixelpath.scene.schema import scene_json_schema

DOCS = Path(__file__).resolve().parents[2] / "docs"
REGENERATE = (
    'python -c "import json; from pixelpath.scene.schema import scene_json_schema; '
    'print(json.dumps(scene_json_schema(), indent=2))" > docs/scene.schema.json'
)


def test_published_schema_is_the_generated_one():
    published = json.loads((DOCS / "scene.schema.json").read_text())
    assert published == scene_json_schema(), f"regenerate it: {REGENERATE}"


def test_example_of_the_format_document_loads(tmp_path):
    text = (DOCS / "scene-format.md").read_text()
    example = re.search(r"```toml\n(.*?)```", text, re.DOTALL).group(1)
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "suzanne.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
    )
    path = tmp_path / "scene.toml"
    path.write_text(example)
    scene = load_scene(path)
    assert isinstance(scene.objects[0], Sphere) and scene.objects[0].material.name == "red"
    monkey = scene.objects[2]
    assert isinstance(monkey, Mesh) and monkey.name == "monkey" and monkey.faces == [[0, 1, 2, 3]]
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    jsonschema.validate(tomllib.loads(example), scene_json_schema())
