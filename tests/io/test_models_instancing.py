"""glTF ``EXT_mesh_gpu_instancing``: a node's mesh is drawn once per instance.

Each instance is the node's world transform times the instance's translation, rotation and
scale; trimesh ignores the extension and drew the mesh once, at the node. The files are the
quad of ``quad_gltf`` with instance attributes written here, so the corners are derived by
hand.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from test_models import (
    FUZZ,
    JSON_VALUES,
    QUAD,
    edited_loads_or_names_itself,
    quad_gltf,
    refused,
    write,
)
from test_models_morphs import LIFT, _append, morphed_quad

from pixelpath.io.models import read_model

EXTENSION = "EXT_mesh_gpu_instancing"
SHIFTS = np.array([[0, 0, 0], [2, 0, 0], [0, 3, 0]], dtype="<f4")


def instanced_quad(gltf: dict, **attributes: tuple[np.ndarray, int, str]) -> dict:
    """``gltf`` whose node 0 draws its quad once per instance of ``attributes``
    (name: (values, componentType, type))."""
    ids = {name: _append(gltf, *spec) for name, spec in attributes.items()}
    node = gltf["nodes"][0]
    node.setdefault("extensions", {})[EXTENSION] = {"attributes": ids}
    gltf.setdefault("extensionsUsed", []).append(EXTENSION)
    return gltf


def _by_name(path) -> dict:
    return {mesh.name: mesh for mesh in read_model(path).objects}


def test_each_instance_is_drawn_where_its_translation_puts_it(tmp_path):
    gltf = instanced_quad(quad_gltf(), TRANSLATION=(SHIFTS, 5126, "VEC3"))
    meshes = _by_name(write(tmp_path, gltf))
    assert sorted(meshes) == ["quad[0]", "quad[1]", "quad[2]"]  # and no quad at the node
    for k, shift in enumerate(SHIFTS):
        np.testing.assert_allclose(meshes[f"quad[{k}]"].vertices, QUAD + shift)


def test_a_file_that_requires_the_extension_loads(tmp_path):
    gltf = instanced_quad(quad_gltf(), TRANSLATION=(SHIFTS, 5126, "VEC3"))
    gltf["extensionsRequired"] = [EXTENSION]
    assert len(read_model(write(tmp_path, gltf)).objects) == 3


def test_the_instance_transform_is_in_the_node_s_frame(tmp_path):
    """Node: move by (10, 0, 0), scale 2. Instance: a quarter turn about z, then (1, 0, 0):
    (x, y, 0) turns to (-y, x, 0), moves to (1 - y, x, 0), then (2 - 2y + 10, 2x, 0)."""
    half = 0.5**0.5
    gltf = instanced_quad(
        quad_gltf(),
        TRANSLATION=(np.array([[1, 0, 0]], "<f4"), 5126, "VEC3"),
        ROTATION=(np.array([[0, 0, half, half]], "<f4"), 5126, "VEC4"),
    )
    gltf["nodes"][0].update(translation=[10.0, 0.0, 0.0], scale=[2.0, 2.0, 2.0])
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    x, y = QUAD[:, 0], QUAD[:, 1]
    np.testing.assert_allclose(mesh.vertices, np.stack([12 - 2 * y, 2 * x, 0 * x], axis=1),
                               atol=1e-6)


def test_rotations_stored_as_normalized_shorts_are_decoded(tmp_path):
    """A half turn about y as normalized int16 (0, 32767, 0, 0): (x, y, 0) goes to (-x, y, 0)."""
    rotation = np.array([[0, 32767, 0, 0]], "<i2")
    gltf = instanced_quad(quad_gltf(), ROTATION=(rotation, 5122, "VEC4"))
    gltf["accessors"][-1]["normalized"] = True
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.vertices, QUAD * [-1, 1, 1], atol=1e-6)


def test_scales_and_the_node_s_children_are_kept(tmp_path):
    gltf = instanced_quad(quad_gltf(), SCALE=(np.array([[1, 1, 1], [3, 3, 3]], "<f4"), 5126,
                                              "VEC3"))
    gltf["nodes"][0]["children"] = [1]
    gltf["nodes"].append({"name": "child", "mesh": 0, "translation": [0.0, 0.0, 5.0]})
    meshes = _by_name(write(tmp_path, gltf))
    assert sorted(meshes) == ["child", "quad[0]", "quad[1]"]
    np.testing.assert_allclose(meshes["quad[1]"].vertices, QUAD * 3)
    np.testing.assert_allclose(meshes["child"].vertices, QUAD + np.array([0, 0, 5]))


def test_instances_of_a_morphed_mesh_are_morphed(tmp_path):
    gltf = instanced_quad(morphed_quad(quad_gltf(), [1.0, 0.0]),
                          TRANSLATION=(SHIFTS[:2], 5126, "VEC3"))
    meshes = _by_name(write(tmp_path, gltf))
    np.testing.assert_allclose(meshes["quad[1]"].vertices, QUAD + LIFT + SHIFTS[1])


@pytest.mark.parametrize("morphed", [False, True])
def test_an_unnamed_node_s_instances_take_its_mesh_s_name(tmp_path, morphed):
    gltf = morphed_quad(quad_gltf(), [1.0, 0.0]) if morphed else quad_gltf()
    gltf = instanced_quad(gltf, TRANSLATION=(SHIFTS[:1], 5126, "VEC3"))
    del gltf["nodes"][0]["name"]
    gltf["meshes"][0]["name"] = "tile"
    assert list(_by_name(write(tmp_path, gltf))) == ["tile[0]"]


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda g: g["nodes"][0]["extensions"].update({EXTENSION: []}),
         "node 0: EXT_mesh_gpu_instancing has no attributes object"),
        (lambda g: g["nodes"][0]["extensions"][EXTENSION]["attributes"].update(SCALE=0),
         "needs TRANSLATION, ROTATION or SCALE, each with one value an instance"),
        (lambda g: g["nodes"][0]["extensions"][EXTENSION]["attributes"].update(ROTATION=0),
         "EXT_mesh_gpu_instancing ROTATION must be a VEC4 accessor"),
        (lambda g: g["nodes"][0]["extensions"][EXTENSION]["attributes"].update(SCALE=99),
         "EXT_mesh_gpu_instancing SCALE names a missing accessor"),
    ],
)
def test_bad_instances_are_refused(tmp_path, edit, message):
    gltf = instanced_quad(quad_gltf(), TRANSLATION=(SHIFTS, 5126, "VEC3"))
    edit(gltf)
    refused(tmp_path, gltf, message)


@FUZZ
@given(key_index=st.integers(0, 500), value=JSON_VALUES)
def test_fuzz_edited_instanced_gltf(tmp_path, key_index, value):
    """The instanced quad with one value of its JSON replaced: it loads, or the error names it."""
    gltf = instanced_quad(quad_gltf(), TRANSLATION=(SHIFTS, 5126, "VEC3"),
                          SCALE=(np.ones((3, 3), "<f4"), 5126, "VEC3"))
    edited_loads_or_names_itself(tmp_path, gltf, key_index, value)
