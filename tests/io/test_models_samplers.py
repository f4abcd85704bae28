"""glTF samplers of base-colour textures become the Material's texture_filter and texture_wrap."""

from __future__ import annotations

import base64
import io
import json
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import pixelpath as pp
from pixelpath.io.models import read_model

DATA = Path(__file__).resolve().parents[1] / "data" / "models"

NEAREST, LINEAR = 9728, 9729
REPEAT, CLAMP, MIRROR = 10497, 33071, 33648

QUAD = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype="<f4")
FACES = np.array([0, 1, 2, 0, 2, 3], dtype="<u2")
# glTF's v runs down the image: the world's bottom-left corner shows glTF (u, v) = (0, 1)
UV = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], dtype="<f4")
# the 2 x 2 picture: top row red, green; bottom row blue, white
PICTURE = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], dtype=np.uint8)


def _data_uri(data: bytes, mime: str = "application/octet-stream") -> str:
    return f"data:{mime};base64,{base64.b64encode(data).decode()}"


def _png(array: np.ndarray) -> bytes:
    out = io.BytesIO()
    Image.fromarray(array).save(out, format="PNG")
    return out.getvalue()


def sampler_gltf(*samplers: dict | None, uv: np.ndarray = UV, names=None) -> dict:
    """Return a glTF of one textured quad per sampler (``None``: a texture without a sampler).

    Quad i lies at x = 2 i, in node ``"quad{i}"``, with material ``names[i]`` (``"m{i}"`` by
    default; a name of ``None`` leaves the material unnamed).
    """
    samplers = samplers or (None,)
    names = names if names is not None else [f"m{i}" for i in range(len(samplers))]
    blob = QUAD.tobytes() + np.asarray(uv, dtype="<f4").tobytes() + FACES.tobytes()
    n_v, n_uv = QUAD.nbytes, 4 * 8
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(samplers)))}],
        "nodes": [{"name": f"quad{i}", "mesh": i, "translation": [2 * i, 0, 0]}
                  for i in range(len(samplers))],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "indices": 2, "material": i}]}
                   for i in range(len(samplers))],
        "materials": [],
        "textures": [],
        "samplers": [],
        "images": [{"uri": _data_uri(_png(PICTURE), "image/png")}],
        "buffers": [{"byteLength": len(blob), "uri": _data_uri(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": n_v},
            {"buffer": 0, "byteOffset": n_v, "byteLength": n_uv},
            {"buffer": 0, "byteOffset": n_v + n_uv, "byteLength": FACES.nbytes},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    for i, (sampler, name) in enumerate(zip(samplers, names, strict=True)):
        texture = {"source": 0}
        if sampler is not None:
            texture["sampler"] = len(gltf["samplers"])
            gltf["samplers"].append(sampler)
        gltf["textures"].append(texture)
        material = {"doubleSided": True, "pbrMetallicRoughness": {
            "metallicFactor": 0.0, "baseColorTexture": {"index": i}}}
        if name is not None:
            material["name"] = name
        gltf["materials"].append(material)
    return gltf


def write(tmp_path: Path, gltf: dict, name: str = "model.gltf") -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(gltf))
    return path


def materials(path: Path) -> list[pp.Material]:
    return [mesh.material for mesh in read_model(path).objects]


# --- the mapping --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("sampler", "expected"),
    [
        (None, "trilinear"),  # no sampler at all
        ({}, "trilinear"),  # minFilter absent: the viewer's choice
        ({"magFilter": NEAREST}, "trilinear"),
        ({"minFilter": NEAREST}, "nearest"),
        ({"minFilter": NEAREST, "magFilter": NEAREST}, "nearest"),
        ({"minFilter": NEAREST, "magFilter": LINEAR}, "bilinear"),
        ({"minFilter": LINEAR}, "bilinear"),
        ({"minFilter": LINEAR, "magFilter": NEAREST}, "bilinear"),
        ({"minFilter": LINEAR, "magFilter": LINEAR}, "bilinear"),
        ({"minFilter": 9984}, "trilinear"),
        ({"minFilter": 9985, "magFilter": NEAREST}, "trilinear"),
        ({"minFilter": 9986}, "trilinear"),
        ({"minFilter": 9987, "magFilter": LINEAR}, "trilinear"),
    ],
)
def test_filter_follows_min_and_mag_filter(tmp_path, sampler, expected):
    (material,) = materials(write(tmp_path, sampler_gltf(sampler)))
    assert material.texture is not None
    assert material.texture_filter == expected
    assert material.texture_wrap == "repeat"


@pytest.mark.parametrize(
    ("wrap", "expected"), [(None, "repeat"), (REPEAT, "repeat"), (CLAMP, "clamp"),
                           (MIRROR, "mirror")],
)
def test_wrap_follows_wrap_s_and_t(tmp_path, wrap, expected):
    sampler = {} if wrap is None else {"wrapS": wrap, "wrapT": wrap}
    (material,) = materials(write(tmp_path, sampler_gltf(sampler)))
    assert material.texture_wrap == expected
    assert material.texture_filter == "trilinear"


def test_each_material_gets_its_own_sampler_in_a_glb(tmp_path):
    gltf = sampler_gltf(
        {"minFilter": NEAREST, "wrapS": CLAMP, "wrapT": CLAMP},
        {"minFilter": LINEAR, "wrapS": MIRROR, "wrapT": MIRROR},
        None,
    )
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    body = (len(text)).to_bytes(4, "little") + (0x4E4F534A).to_bytes(4, "little") + text
    path = tmp_path / "model.glb"
    path.write_bytes(b"glTF" + (2).to_bytes(4, "little") + (12 + len(body)).to_bytes(4, "little")
                     + body)
    found = {mesh.name: (mesh.material.texture_filter, mesh.material.texture_wrap)
             for mesh in read_model(path).objects}
    assert found == {"quad0": ("nearest", "clamp"), "quad1": ("bilinear", "mirror"),
                     "quad2": ("trilinear", "repeat")}


def test_wrap_t_that_differs_warns_once_per_material_and_wrap_s_wins(tmp_path):
    clamp_s = {"wrapS": CLAMP, "wrapT": MIRROR}
    gltf = sampler_gltf(clamp_s, {"wrapS": MIRROR}, {"wrapS": CLAMP, "wrapT": CLAMP})
    # a second primitive with the first material: still one warning for it
    gltf["meshes"][2]["primitives"].append({**gltf["meshes"][0]["primitives"][0]})
    path = write(tmp_path, gltf, "odd wraps.gltf")
    with pytest.warns(UserWarning) as record:
        objects = read_model(path).objects
    messages = [str(w.message) for w in record]
    assert len(messages) == 2, messages
    assert all(str(path) in message for message in messages)
    assert "'m0'" in messages[0] and "wrapT" in messages[0]
    assert "'m1'" in messages[1]  # wrapT absent is REPEAT, which differs from MIRROR
    wraps = sorted((mesh.material.name, mesh.material.texture_wrap) for mesh in objects)
    assert wraps == [("m0", "clamp"), ("m0", "clamp"), ("m1", "mirror"), ("m2", "clamp")]


def test_equal_wraps_do_not_warn(tmp_path):
    path = write(tmp_path, sampler_gltf({"wrapS": REPEAT}, {"wrapT": REPEAT}, {}))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        materials(path)


# --- matching by name ----------------------------------------------------------------------------


def test_one_unnamed_material_is_matched(tmp_path):
    gltf = sampler_gltf({"minFilter": NEAREST, "wrapS": CLAMP, "wrapT": CLAMP}, names=[None])
    (material,) = materials(write(tmp_path, gltf))
    assert (material.texture_filter, material.texture_wrap) == ("nearest", "clamp")


@pytest.mark.parametrize("names", [["same", "same"], [None, None]])
def test_ambiguous_names_keep_the_defaults(tmp_path, names):
    gltf = sampler_gltf({"minFilter": NEAREST, "wrapS": CLAMP, "wrapT": MIRROR},
                        {"minFilter": LINEAR, "wrapS": MIRROR}, names=names)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no wrapT warning either: no sampler is used
        found = materials(write(tmp_path, gltf))
    assert [(m.texture_filter, m.texture_wrap) for m in found] == [("trilinear", "repeat")] * 2


def test_other_formats_and_untextured_materials_keep_the_defaults(tmp_path):
    gltf = sampler_gltf({"minFilter": NEAREST, "wrapS": CLAMP, "wrapT": CLAMP})
    del gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]
    (material,) = materials(write(tmp_path, gltf))
    assert material.texture is None
    assert (material.texture_filter, material.texture_wrap) == ("trilinear", "repeat")
    (material,) = materials(DATA / "fuze.obj")  # an MTL texture has no sampler
    assert material.texture is not None
    assert (material.texture_filter, material.texture_wrap) == ("trilinear", "repeat")


@pytest.mark.parametrize("name", ["Duck.glb", "BoxTextured.glb"])
def test_real_files_samplers(name):
    # both have one sampler: LINEAR_MIPMAP_LINEAR (9986) / LINEAR, REPEAT in s and t
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        (material,) = materials(DATA / name)
    assert (material.texture_filter, material.texture_wrap) == ("trilinear", "repeat")


# --- bad samplers: a ValueError naming the file and the material --------------------------------


def _with_sampler_edit(edit):
    gltf = sampler_gltf({"minFilter": NEAREST, "wrapS": CLAMP})
    edit(gltf)
    return gltf


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (lambda g: g["samplers"][0].update(wrapS=12345), "wrapS 12345"),
        (lambda g: g["samplers"][0].update(wrapS="33071"), "wrapS '33071'"),
        (lambda g: g["samplers"][0].update(wrapT=True), "wrapT True"),
        (lambda g: g["samplers"][0].update(minFilter=9729.5), "minFilter 9729.5"),
        (lambda g: g["samplers"][0].update(magFilter=9984), "magFilter 9984"),  # no mipmaps
        (lambda g: g["textures"][0].update(sampler=3), "sampler 3 is out of range"),
        (lambda g: g["textures"][0].update(sampler=-1), "sampler -1 is out of range"),
        (lambda g: g["textures"][0].update(sampler="0"), "sampler must be an integer"),
        (lambda g: g.update(samplers={"0": {}}), "out of range"),
        (lambda g: g.update(samplers=[7]), "must be an object"),
    ],
)
def test_bad_samplers_are_refused_naming_file_and_material(tmp_path, edit, words):
    path = write(tmp_path, _with_sampler_edit(edit))
    with pytest.raises(ValueError, match=r"sampler|must be") as info:
        read_model(path)
    message = str(info.value)
    assert str(path) in message and "'m0'" in message and words in message, message


def test_bad_texture_reference_is_a_value_error(tmp_path):
    for index in (5, -1, "0", None):
        gltf = sampler_gltf({"minFilter": NEAREST})
        gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = index
        path = write(tmp_path, gltf)
        with pytest.raises(ValueError, match=re.escape(str(path))):
            read_model(path)


# --- rendering ----------------------------------------------------------------------------------


def _render(tmp_path: Path, wrap: int) -> np.ndarray:
    # uv from -1 to 2 across the quad: the picture three times in each direction
    sampler = {"minFilter": NEAREST, "magFilter": NEAREST, "wrapS": wrap, "wrapT": wrap}
    path = write(tmp_path, sampler_gltf(sampler, uv=UV * 3 - 1), f"wrap{wrap}.gltf")
    objects = read_model(path).objects
    camera = pp.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0), width=60, height=60,
                       projection="orthographic", view_height=1.0)
    scene = pp.Scene(camera, objects, [], ambient=1.0, encoding="srgb")
    return np.asarray(pp.render(scene, shading="flat"))


def test_clamp_renders_differently_from_repeat_outside_0_1(tmp_path):
    repeat, clamp = _render(tmp_path, REPEAT), _render(tmp_path, CLAMP)
    # the quad fills the 60 x 60 picture; uv in [0, 1] is the middle 20 x 20 square
    np.testing.assert_allclose(repeat[22:38, 22:38], clamp[22:38, 22:38])
    assert not np.allclose(repeat, clamp)
    # the bottom-left ninth: repeat shows the whole picture again (its top right quarter
    # green), clamp stretches the bottom-left texel (blue) over it
    bottom_left_top_right = (45, 15)
    green, blue = repeat[bottom_left_top_right], clamp[bottom_left_top_right]
    assert green[1] > 0.5 > max(green[0], green[2]), green
    assert blue[2] > 0.5 > max(blue[0], blue[1]), blue
    # the top-right ninth: clamp shows the top-right texel (green), repeat its bottom left (blue)
    assert clamp[15, 45][1] > 0.5 > clamp[15, 45][2]
    assert repeat[15, 45][2] > 0.5 > repeat[15, 45][1]
