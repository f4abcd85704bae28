"""KHR_mesh_quantization: integer positions, normals and texture coordinates read as floats.

The quantized files are written here: the Duck's own float data (read from its GLB by the test,
not through trimesh) stored as integers the way gltfpack stores them, with the node transform
and the texture transform that scale them back. The expected values are the Duck's float data.
"""

from __future__ import annotations

import json
import struct

import numpy as np
import pytest
from test_models import DATA, QUAD, _data_uri, _glb_with_binary, quad_gltf, write

import pixelpath as pp
from pixelpath.io.models import read_model

QUANTIZED = {"extensionsUsed": ["KHR_mesh_quantization"],
             "extensionsRequired": ["KHR_mesh_quantization"]}


def _glb_json_and_binary(data: bytes) -> tuple[dict, bytes]:
    (json_length,) = struct.unpack("<I", data[12:16])
    (binary_length,) = struct.unpack("<I", data[20 + json_length:24 + json_length])
    start = 28 + json_length
    return json.loads(data[20:20 + json_length]), data[start:start + binary_length]


def _floats(gltf: dict, binary: bytes, index: int) -> np.ndarray:
    """A float32 accessor of the Duck's GLB, (count, components)."""
    accessor = gltf["accessors"][index]
    view = gltf["bufferViews"][accessor["bufferView"]]
    components = {"VEC2": 2, "VEC3": 3}[accessor["type"]]
    stride = view.get("byteStride", 4 * components)
    start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    rows = [np.frombuffer(binary, "<f4", components, start + i * stride)
            for i in range(accessor["count"])]
    return np.array(rows)


def _padded(values: np.ndarray) -> bytes:
    """Rows padded to 4-byte strides, as glTF asks of vertex attributes."""
    width = -(-values.shape[1] * values.itemsize // 4) * 4
    rows = np.zeros((len(values), width), np.uint8)
    rows[:, :values.shape[1] * values.itemsize] = values.view(np.uint8).reshape(len(values), -1)
    return rows.tobytes()


def quantized_duck(position: str) -> tuple[bytes, dict[str, np.ndarray]]:
    """The Duck with gltfpack's storage: positions as ``position`` ("u2": unsigned shorts of
    a 14-bit grid, "i2n": normalized signed shorts), normals as normalized signed bytes,
    texture coordinates as unsigned shorts of a 16-bit grid moved by KHR_texture_transform.

    Returns the GLB and the Duck's float attributes with the quantization steps.
    """
    gltf, binary = _glb_json_and_binary((DATA / "Duck.glb").read_bytes())
    attributes = gltf["meshes"][0]["primitives"][0]["attributes"]
    positions = _floats(gltf, binary, attributes["POSITION"])
    normals = _floats(gltf, binary, attributes["NORMAL"])
    uv = _floats(gltf, binary, attributes["TEXCOORD_0"])
    low, high = positions.min(axis=0), positions.max(axis=0)
    if position == "u2":
        step = float((high - low).max()) / (2**14 - 1)
        stored = np.round((positions - low) / step).astype("<u2")
        node = {"translation": low.tolist(), "scale": [step] * 3}
        accessor = {"componentType": 5123}
    else:
        center, half = (low + high) / 2, float((high - low).max()) / 2
        stored = np.round((positions - center) / half * 32767).astype("<i2")
        step = half / 32767
        node = {"translation": center.tolist(), "scale": [half] * 3}
        accessor = {"componentType": 5122, "normalized": True}
    uv_low = uv.min(axis=0)
    uv_step = (uv.max(axis=0) - uv_low) / 65535
    blocks = [_padded(stored), _padded(np.round(normals * 127).astype("<i1")),
              np.round((uv - uv_low) / uv_step).astype("<u2").tobytes()]
    image_view = gltf["bufferViews"][gltf["images"][0]["bufferView"]]
    image = binary[image_view["byteOffset"]:image_view["byteOffset"] + image_view["byteLength"]]
    indices = gltf["accessors"][gltf["meshes"][0]["primitives"][0]["indices"]]
    index_view = gltf["bufferViews"][indices["bufferView"]]
    start = index_view["byteOffset"] + indices.get("byteOffset", 0)
    blocks += [binary[start:start + 2 * indices["count"]], image]
    views, offset = [], 0
    for block, stride in zip(blocks, [8, 4, None, None, None], strict=True):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(block)}
                     | ({"byteStride": stride} if stride else {}))
        offset += len(block) + (-len(block) % 4)
    count = len(positions)
    gltf.update(
        QUANTIZED,
        bufferViews=views,
        accessors=[
            {"bufferView": 0, "count": count, "type": "VEC3", **accessor},
            {"bufferView": 1, "componentType": 5120, "normalized": True, "count": count,
             "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": count, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": indices["count"],
             "type": "SCALAR"},
        ],
        images=[{"bufferView": 4, "mimeType": "image/png"}],
    )
    gltf["nodes"][2].update(node)  # the node of the Duck's mesh, under the 0.01 scale
    gltf["meshes"][0]["primitives"][0].update(
        attributes={"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, indices=3)
    texture = gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]
    texture["extensions"] = {"KHR_texture_transform": {"offset": uv_low.tolist(),
                                                       "scale": uv_step.tolist()}}
    gltf["extensionsUsed"].append("KHR_texture_transform")
    blob = b"".join(block + bytes(-len(block) % 4) for block in blocks)
    expected = {"positions": positions, "normals": normals, "uv": uv, "step": np.array(step),
                "uv_step": uv_step}
    return _glb_with_binary(gltf, blob), expected


@pytest.mark.parametrize("position", ["u2", "i2n"])
def test_quantized_duck_loads_as_the_duck(tmp_path, position):
    """Positions within half a grid step (times the root's 0.01 scale) of the Duck's floats,
    normals within a byte's rounding, uv within half a step, in pixelpath's v-up uv.
    """
    data, duck = quantized_duck(position)
    path = tmp_path / "duck.glb"
    path.write_bytes(data)
    (mesh,) = read_model(path).objects
    scale = 0.01  # the Duck's root node
    half_step = 0.5 * float(duck["step"]) * scale
    float32 = 2e-7  # rounding of the float32 arithmetic at the Duck's size (below 1)
    np.testing.assert_allclose(mesh.vertices, duck["positions"] * scale, rtol=0,
                               atol=half_step + float32)
    assert np.abs(mesh.vertices - duck["positions"] * scale).max() > 0  # they were quantized
    cosines = np.sum(mesh.normals * duck["normals"], axis=1)
    assert cosines.min() > np.cos(np.radians(1.0))
    gltf_uv = np.column_stack([mesh.uv[:, 0], 1.0 - mesh.uv[:, 1]])
    np.testing.assert_allclose(gltf_uv, duck["uv"], rtol=0, atol=0.5 * duck["uv_step"].max()
                               + 1e-6)


def test_quantized_duck_renders_as_the_duck(tmp_path):
    data, _ = quantized_duck("u2")
    path = tmp_path / "duck.glb"
    path.write_bytes(data)
    size = (96, 72)
    quantized = pp.render(read_model(path, size=size, frame=True), method="zbuffer")
    original = pp.render(read_model(DATA / "Duck.glb", size=size, frame=True), method="zbuffer")
    assert np.mean((quantized.object_id >= 0) != (original.object_id >= 0)) < 0.005
    drawn = original.object_id >= 0
    assert drawn.mean() > 0.2
    difference = np.abs(quantized.rgb - original.rgb)[drawn]
    assert np.median(difference) < 0.01 and difference.mean() < 0.02


def _quad_with_positions(stored: np.ndarray, component: int, normalized: bool) -> dict:
    """The quad of ``quad_gltf`` with its corners ``stored`` as integers (rows padded to 4
    bytes), in a buffer of their own."""
    gltf = quad_gltf(**QUANTIZED)
    blob = _padded(stored)
    gltf["buffers"].append({"byteLength": len(blob), "uri": _data_uri(blob)})
    gltf["bufferViews"].append({"buffer": 1, "byteLength": len(blob),
                                "byteStride": len(blob) // len(stored)})
    gltf["accessors"][0] = {"bufferView": 3, "componentType": component, "count": len(stored),
                            "type": "VEC3"} | ({"normalized": True} if normalized else {})
    return gltf


@pytest.mark.parametrize(
    ("dtype", "component", "normalized", "node_scale"),
    [
        ("<u1", 5121, False, 1.0),  # integers as they are
        ("<i1", 5120, False, 1.0),
        ("<u2", 5123, False, 1.0),
        ("<i2", 5122, False, 1.0),
        ("<u1", 5121, True, 255.0),  # fractions c / 255, scaled back by the node
        ("<u2", 5123, True, 65535.0),
        ("<i1", 5120, True, 127.0),
        ("<i2", 5122, True, 32767.0),
    ],
)
def test_integer_positions_of_every_type(tmp_path, dtype, component, normalized, node_scale):
    """A normalized type's node scales the fractions back to the corners."""
    gltf = _quad_with_positions(QUAD.astype(dtype), component, normalized)
    gltf["nodes"][0]["scale"] = [node_scale] * 3
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.vertices, QUAD, rtol=1e-6, atol=0)


def test_signed_normalized_minimum_is_minus_one(tmp_path):
    """glTF's rule for signed normalized integers: max(c / 127, -1), so -128 and -127 are -1."""
    stored = np.array([[-128, 0, 0], [127, 0, 0], [127, 127, 0], [-127, 127, 0]], "<i1")
    (mesh,) = read_model(write(tmp_path, _quad_with_positions(stored, 5120, True))).objects
    np.testing.assert_allclose(mesh.vertices[:, 0], [-1, 1, 1, -1], rtol=1e-6)
