"""glTF skins: a skinned mesh is posed by its joints at the file's rest pose.

The glTF files are the quad of ``quad_gltf`` with joints, weights and a skin written here, so
the expected corners are derived by hand: a joint's world matrix times its inverse bind
matrix, blended by the weights, and the skinned node's own transform ignored (the glTF rule).
"""

from __future__ import annotations

import base64
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from test_models import (
    FUZZ,
    JSON_VALUES,
    QUAD,
    _data_uri,
    edited_loads_or_names_itself,
    quad_gltf,
    refused,
    write,
)

from pixelpath.io.models import read_model

HALF = math.sqrt(0.5)
QUARTER_TURN_ABOUT_X = [HALF, 0.0, 0.0, HALF]  # glTF's (x, y, z, w)


def skinned_quad(joints: list[dict], weights: np.ndarray, joint_of: np.ndarray,
                 inverse_bind: np.ndarray | None = None, normals: bool = False) -> dict:
    """The quad (node 0, translated by (10, 0, 0), which the skin must override) skinned to
    ``joints`` (nodes 1, 2, ... under the scene's root), four corners each with its
    ``joint_of`` indices and ``weights`` (4 each)."""
    gltf = quad_gltf()
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1])
    primitive = gltf["meshes"][0]["primitives"][0]
    arrays = [("JOINTS_0", joint_of.astype("<u2"), 5123, "VEC4"),
              ("WEIGHTS_0", weights.astype("<f4"), 5126, "VEC4")]
    if normals:
        arrays.append(("NORMAL", np.tile(np.array([0, 0, 1], "<f4"), (4, 1)), 5126, "VEC3"))
    if inverse_bind is not None:  # column-major, as glTF stores matrices
        arrays.append(("ibm", inverse_bind.transpose(0, 2, 1).astype("<f4"), 5126, "MAT4"))
    for name, values, component, kind in arrays:
        gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(blob),
                                    "byteLength": values.nbytes})
        blob += values.tobytes()
        gltf["accessors"].append({"bufferView": len(gltf["bufferViews"]) - 1,
                                  "componentType": component, "count": len(values),
                                  "type": kind})
        if name != "ibm":
            primitive["attributes"][name] = len(gltf["accessors"]) - 1
    gltf["buffers"][0] = {"byteLength": len(blob), "uri": _data_uri(blob)}
    skin = {"joints": list(range(1, len(joints) + 1))}
    if inverse_bind is not None:
        skin["inverseBindMatrices"] = len(gltf["accessors"]) - 1
    gltf["skins"] = [skin]
    gltf["nodes"][0].update(skin=0, translation=[10.0, 0.0, 0.0])
    gltf["nodes"] += joints
    gltf["scenes"][0]["nodes"] = [0, *skin["joints"]]
    return gltf


ONE_JOINT = np.tile([0, 0, 0, 0], (4, 1))
FULLY = np.tile([1.0, 0.0, 0.0, 0.0], (4, 1))


def test_a_skinned_quad_is_placed_by_its_joint_not_its_node(tmp_path):
    """One joint, a quarter turn about x then (5, 0, 0): (x, y, 0) goes to (x + 5, 0, y); the
    node's (10, 0, 0) is ignored, and the normal +z turns to -y."""
    joint = {"translation": [5.0, 0.0, 0.0], "rotation": QUARTER_TURN_ABOUT_X}
    gltf = skinned_quad([joint], FULLY, ONE_JOINT, normals=True)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.vertices, [[5, 0, 0], [6, 0, 0], [6, 0, 1], [5, 0, 1]],
                               atol=1e-6)
    np.testing.assert_allclose(mesh.normals, np.tile([0, -1, 0], (4, 1)), atol=1e-6)


def test_weights_blend_the_joints(tmp_path):
    """Two joints at (0, 0, 0) and (0, 2, 0): corners weighted half and half move by
    (0, 1, 0), corners wholly on the second by (0, 2, 0)."""
    joints = [{}, {"translation": [0.0, 2.0, 0.0]}]
    weights = np.array([[0.5, 0.5, 0, 0], [0.5, 0.5, 0, 0], [0, 1, 0, 0], [1, 0, 0, 0]])
    joint_of = np.tile([0, 1, 0, 0], (4, 1))
    (mesh,) = read_model(write(tmp_path, skinned_quad(joints, weights, joint_of))).objects
    moves = np.array([[0, 1, 0], [0, 1, 0], [0, 2, 0], [0, 0, 0]])
    np.testing.assert_allclose(mesh.vertices, QUAD + moves, atol=1e-6)


def test_the_inverse_bind_matrix_undoes_the_joints_rest_place(tmp_path):
    """A joint at (0, 1, 0) whose inverse bind matrix moves by (0, -1, 0), as in Khronos'
    SimpleSkin: at rest the quad stays where its vertices say (the node's move ignored)."""
    inverse = np.eye(4)[None].copy()
    inverse[0, 1, 3] = -1.0
    gltf = skinned_quad([{"translation": [0.0, 1.0, 0.0]}], FULLY, ONE_JOINT, inverse)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.vertices, QUAD, atol=1e-6)


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda g: g["skins"][0].update(joints=[7]), "skin joint 7 is not a node of the scene"),
        (lambda g: g["nodes"][0].update(skin=3), "node 0: skin 3 is out of range"),
        (lambda g: g["skins"][0].update(joints=[]), "a skin has no joints"),
    ],
)
def test_bad_skins_are_refused(tmp_path, edit, message):
    gltf = skinned_quad([{}], FULLY, ONE_JOINT)
    edit(gltf)
    refused(tmp_path, gltf, message)


def test_a_joint_the_skin_lacks_is_refused(tmp_path):
    gltf = skinned_quad([{}], FULLY, np.tile([0, 3, 0, 0], (4, 1)))
    with pytest.raises(ValueError, match=r"model\.gltf.*JOINTS_0 names a joint its skin lacks"):
        read_model(write(tmp_path, gltf))


@FUZZ
@given(key_index=st.integers(0, 500), value=JSON_VALUES)
def test_fuzz_edited_skinned_gltf(tmp_path, key_index, value):
    """The skinned quad with one value of its JSON replaced: it loads, or the error names it."""
    joints = [{"translation": [5.0, 0.0, 0.0]}, {"rotation": QUARTER_TURN_ABOUT_X}]
    weights = np.tile([0.25, 0.75, 0.0, 0.0], (4, 1))
    gltf = skinned_quad(joints, weights, np.tile([0, 1, 0, 0], (4, 1)),
                        np.tile(np.eye(4), (2, 1, 1)), normals=True)
    edited_loads_or_names_itself(tmp_path, gltf, key_index, value)
