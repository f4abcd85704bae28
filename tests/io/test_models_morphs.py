"""glTF morph targets: a mesh is drawn in the shape its default weights give it.

glTF's rest shape is ``base + sum(weight_i * target_i)``, the weights the node's ``weights``,
else its mesh's, else zeros; trimesh ignores targets and drew the base. The files are the quad
of ``quad_gltf`` with targets written here, so each expected corner is derived by hand.
Khronos' SimpleMorph (weights 0.5 and 0.5) drew its base triangle so; the first case here is
of its kind.
"""

from __future__ import annotations

import base64

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from test_models import (
    FUZZ,
    JSON_VALUES,
    QUAD,
    QUAD_TRIANGLES,
    _data_uri,
    corner_positions,
    edited_loads_or_names_itself,
    quad_gltf,
    refused,
    write,
)
from test_models_skins import FULLY, ONE_JOINT, skinned_quad

from pixelpath.io.models import read_model

# Two targets: the first lifts corner 2 by (0, 1, 0), the second moves corner 3 by (2, 0, 0)
# and lifts corner 2 by (0, 0, 4).
LIFT = np.array([[0, 0, 0], [0, 0, 0], [0, 1, 0], [0, 0, 0]], dtype="<f4")
SLIDE = np.array([[0, 0, 0], [0, 0, 0], [0, 0, 4], [2, 0, 0]], dtype="<f4")
NORMAL_TILT = np.array([[0, 1, 0]] * 4, dtype="<f4")


def _append(gltf: dict, values: np.ndarray, component: int, kind: str) -> int:
    """Append ``values`` to the quad's buffer as a new accessor; return its index."""
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1])
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(blob), "byteLength": values.nbytes})
    gltf["buffers"][0] = {"byteLength": len(blob) + values.nbytes,
                          "uri": _data_uri(blob + values.tobytes())}
    gltf["accessors"].append({"bufferView": len(gltf["bufferViews"]) - 1,
                              "componentType": component, "count": len(values), "type": kind})
    return len(gltf["accessors"]) - 1


def morphed_quad(gltf: dict, weights: list | None, normals: bool = False) -> dict:
    """``gltf`` (a quad) with the LIFT and SLIDE targets and the mesh's ``weights``."""
    primitive = gltf["meshes"][0]["primitives"][0]
    targets = [{"POSITION": _append(gltf, LIFT, 5126, "VEC3")},
               {"POSITION": _append(gltf, SLIDE, 5126, "VEC3")}]
    if normals:
        primitive["attributes"]["NORMAL"] = _append(gltf, np.tile(np.array([0, 0, 1], "<f4"),
                                                                  (4, 1)), 5126, "VEC3")
        targets[0]["NORMAL"] = _append(gltf, NORMAL_TILT, 5126, "VEC3")
    primitive["targets"] = targets
    if weights is not None:
        gltf["meshes"][0]["weights"] = weights
    return gltf


def test_the_default_weights_shape_the_mesh(tmp_path):
    (mesh,) = read_model(write(tmp_path, morphed_quad(quad_gltf(), [0.5, 0.25]))).objects
    expected = QUAD + 0.5 * LIFT + 0.25 * SLIDE  # corner 2 to (1, 1.5, 1), corner 3 to (0.5, 1, 0)
    np.testing.assert_allclose(corner_positions(mesh), expected[QUAD_TRIANGLES])
    assert corner_positions(mesh)[1].tolist() == [[0, 0, 0], [1.0, 1.5, 1.0], [0.5, 1, 0]]


def test_the_node_s_weights_override_the_mesh_s(tmp_path):
    gltf = morphed_quad(quad_gltf(), [0.5, 0.25])
    gltf["nodes"][0]["weights"] = [0.0, 1.0]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(corner_positions(mesh), (QUAD + SLIDE)[QUAD_TRIANGLES])


@pytest.mark.parametrize("weights", [None, [0, 0.0]])
def test_zero_or_absent_weights_leave_the_base_shape(tmp_path, weights):
    (mesh,) = read_model(write(tmp_path, morphed_quad(quad_gltf(), weights))).objects
    np.testing.assert_array_equal(mesh.vertices, QUAD)


def test_two_nodes_of_one_mesh_take_their_own_weights(tmp_path):
    gltf = morphed_quad(quad_gltf(), [1.0, 0.0])
    gltf["nodes"].append({"name": "slid", "mesh": 0, "weights": [0.0, 1.0],
                          "translation": [5.0, 0.0, 0.0]})
    gltf["scenes"][0]["nodes"] = [0, 1]
    meshes = {mesh.name: mesh for mesh in read_model(write(tmp_path, gltf)).objects}
    np.testing.assert_allclose(corner_positions(meshes["quad"]), (QUAD + LIFT)[QUAD_TRIANGLES])
    np.testing.assert_allclose(corner_positions(meshes["slid"]),
                               (QUAD + SLIDE + [5.0, 0.0, 0.0])[QUAD_TRIANGLES])


def test_targets_move_the_normals_too(tmp_path):
    """The normal (0, 0, 1) plus 1 x (0, 1, 0), normalized: (0, 1, 1) / sqrt(2)."""
    gltf = morphed_quad(quad_gltf(), [1.0, 0.0], normals=True)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.normals, np.tile([0, 0.5**0.5, 0.5**0.5], (4, 1)))


def test_a_sparse_target_moves_only_its_listed_vertices(tmp_path):
    """Exporters store targets sparse: no bufferView (zeros), corner 1 moved by (0, 0, 3)."""
    gltf = quad_gltf()
    indices = _append(gltf, np.array([1], "<u2"), 5123, "SCALAR")
    moves = _append(gltf, np.array([[0, 0, 3]], "<f4"), 5126, "VEC3")
    sparse = {"count": 1,
              "indices": {"bufferView": gltf["accessors"][indices]["bufferView"],
                          "componentType": 5123},
              "values": {"bufferView": gltf["accessors"][moves]["bufferView"]}}
    gltf["accessors"].append({"componentType": 5126, "count": 4, "type": "VEC3",
                              "sparse": sparse})
    gltf["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": len(gltf["accessors"]) - 1}]
    gltf["meshes"][0]["weights"] = [0.5]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    moved = np.array([[0, 0, 0], [0, 0, 1.5], [0, 0, 0], [0, 0, 0]])
    np.testing.assert_allclose(corner_positions(mesh), (QUAD + moved)[QUAD_TRIANGLES])


def test_a_skinned_mesh_is_morphed_before_it_is_posed(tmp_path):
    """A quarter turn about x then (5, 0, 0) takes (x, y, z) to (x + 5, -z, y): corner 2,
    morphed to (1, 2, 0) by LIFT, goes to (6, 0, 2)."""
    half = 0.5**0.5
    joint = {"translation": [5.0, 0.0, 0.0], "rotation": [half, 0.0, 0.0, half]}
    gltf = morphed_quad(skinned_quad([joint], FULLY, ONE_JOINT), [1.0, 0.0])
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    posed = np.array([[5, 0, 0], [6, 0, 0], [6, 0, 2], [5, 0, 1]])
    np.testing.assert_allclose(corner_positions(mesh), posed[QUAD_TRIANGLES], atol=1e-6)


def test_a_target_moving_texture_coordinates_is_named_in_a_warning(tmp_path):
    gltf = morphed_quad(quad_gltf(), [1.0, 0.0])
    gltf["meshes"][0]["primitives"][0]["targets"][0]["TEXCOORD_0"] = 1
    with pytest.warns(UserWarning, match=r"model\.gltf: morph targets move TEXCOORD_0, which "
                                         "pixelpath does not morph"):
        (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(corner_positions(mesh), (QUAD + LIFT)[QUAD_TRIANGLES])


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda g: g["meshes"][0].update(weights=[1.0]), "node 0: the morph weights must be"),
        (lambda g: g["nodes"][0].update(weights=[1.0, "x"]), "node 0: the morph weights must"),
        (lambda g: g["nodes"][0].update(weights=[1.0, float("nan")]), "the morph weights must"),
        (lambda g: g["meshes"][0]["primitives"][0]["targets"][0].update(POSITION=99),
         "attribute POSITION of a morph target names a missing accessor"),
        (lambda g: g["meshes"][0]["primitives"][0]["targets"].__setitem__(1, 3),
         "a morph target must be an object"),
        (lambda g: g["accessors"][3].update(count=3, type="VEC3"),
         "a morph target's POSITION does not match the primitive's vertices"),
    ],
)
def test_bad_morph_targets_are_refused(tmp_path, edit, message):
    gltf = morphed_quad(quad_gltf(), [1.0, 1.0])
    edit(gltf)
    refused(tmp_path, gltf, message)


@FUZZ
@given(key_index=st.integers(0, 500), value=JSON_VALUES)
def test_fuzz_edited_morphed_gltf(tmp_path, key_index, value):
    """The morphed quad with one value of its JSON replaced: it loads, or the error names it."""
    gltf = morphed_quad(quad_gltf(), [0.5, 0.25], normals=True)
    edited_loads_or_names_itself(tmp_path, gltf, key_index, value)
