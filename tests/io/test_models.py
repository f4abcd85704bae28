"""Model files (glTF, OBJ+MTL, PLY, STL) read into scenes: real files, hand-made glTF, bad input."""

from __future__ import annotations

import base64
import dataclasses
import importlib.util
import io
import json
import math
import shutil
import struct
import warnings
import zlib
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from PIL import Image

import pixelpath as pp
from pixelpath.io.models import framing_camera, read_model, read_model_objects
from pixelpath.scene import DirectionalLight, PointLight

DATA = Path(__file__).resolve().parents[1] / "data" / "models"

# --- a small glTF written by hand, so that the expected values do not come from trimesh ----------

QUAD = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype="<f4")
QUAD_FACES = np.array([0, 1, 2, 0, 2, 3], dtype="<u2")
QUAD_TRIANGLES = QUAD_FACES.reshape(-1, 3)
# glTF's v runs down the image: the world's bottom-left corner (0, 0, 0) shows the image's
# bottom-left texel at glTF (u, v) = (0, 1)
QUAD_UV_GLTF = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], dtype="<f4")
# the 2 x 2 picture: top row red, green; bottom row blue, white
PICTURE = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], dtype=np.uint8)


def _png(array: np.ndarray) -> bytes:
    out = io.BytesIO()
    Image.fromarray(array).save(out, format="PNG")
    return out.getvalue()


def _data_uri(data: bytes, mime: str = "application/octet-stream") -> str:
    return f"data:{mime};base64,{base64.b64encode(data).decode()}"


def quad_gltf(*, vertices=QUAD, indices=QUAD_FACES, image: bytes | None = None, **extra) -> dict:
    """Return the JSON of a glTF quad (one node 'quad'), textured when ``image`` is given."""
    blob = vertices.tobytes() + QUAD_UV_GLTF.tobytes() + indices.tobytes()
    n_v, n_uv = len(vertices) * 12, len(QUAD_UV_GLTF) * 8
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "quad", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "indices": 2, "material": 0}]}],
        "materials": [{"name": "m", "pbrMetallicRoughness": {"metallicFactor": 0.0}}],
        "buffers": [{"byteLength": len(blob), "uri": _data_uri(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": n_v},
            {"buffer": 0, "byteOffset": n_v, "byteLength": n_uv},
            {"buffer": 0, "byteOffset": n_v + n_uv, "byteLength": indices.nbytes},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }
    if image is not None:
        gltf["images"] = [{"uri": _data_uri(image, "image/png")}]
        gltf["textures"] = [{"source": 0}]
        gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    gltf.update(extra)
    return gltf


def corner_positions(mesh: pp.Mesh) -> np.ndarray:
    """Return the positions at each triangle's corners, (T, 3, 3).

    The same whether a part keeps its shared vertices or gets corners of their own (a glTF
    part without normals that is not planar is drawn flat): compare with
    ``expected[QUAD_TRIANGLES]``.
    """
    return mesh.vertices[mesh.triangles]


def write(tmp_path: Path, gltf: dict, name: str = "model.gltf") -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(gltf))
    return path


def glb_bytes(gltf: dict) -> bytes:
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


# --- each format ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "parts"),
    [
        ("Duck.glb", ["LOD3spShape"]),
        ("BoxTextured.glb", ["Mesh"]),
        ("BoxVertexColors.gltf", ["Cube"]),
        ("fuze.obj", ["fuze.obj"]),
    ],
)
def test_real_files_load_with_their_parts_and_trimesh_bounds(name, parts):
    scene = pp.load_scene(DATA / name)
    assert [obj.name for obj in scene.objects] == parts
    assert scene.encoding == "srgb"
    expected = trimesh.load(DATA / name, force="scene").bounds  # node transforms applied
    np.testing.assert_allclose(scene.bounds(), expected, atol=1e-9)


def test_parts_are_named_after_their_nodes(tmp_path):
    gltf = quad_gltf()
    primitive = gltf["meshes"][0]["primitives"][0]
    gltf["meshes"][0]["primitives"].append(dict(primitive))  # a mesh of two primitives
    gltf["nodes"].append({"mesh": 0, "translation": [2, 0, 0]})  # unnamed, mesh unnamed too
    gltf["scenes"][0]["nodes"].append(1)
    names = sorted(obj.name for obj in read_model(write(tmp_path, gltf)).objects)
    # each primitive of node "quad", then those of node 1, which has no name (trimesh calls
    # such parts "GLTF", "GLTF_1")
    assert names == ["node 1", "node 1_1", "quad", "quad_1"]
    gltf["meshes"][0]["name"] = "square"  # an unnamed node takes its mesh's name
    names = sorted(obj.name for obj in read_model(write(tmp_path, gltf)).objects)
    assert names == ["quad", "quad_1", "square", "square_1"]

def test_textured_files_keep_texture_and_uv():
    for name in ("Duck.glb", "BoxTextured.glb", "fuze.obj"):
        (mesh,) = read_model(DATA / name).objects
        assert mesh.material.texture is not None, name
        assert mesh.uv is not None and mesh.uv.shape == (len(mesh.vertices), 2), name


def test_node_transforms_are_applied(tmp_path):
    gltf = quad_gltf()
    gltf["nodes"] = [
        {"name": "parent", "translation": [10, 0, 0], "children": [1]},
        {"name": "child", "scale": [2, 2, 2], "mesh": 0},
    ]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    assert mesh.name == "child"
    np.testing.assert_allclose(mesh.bounds(), [[10, 0, 0], [12, 2, 0]])


def test_mirroring_node_keeps_faces_facing_out(tmp_path):
    gltf = quad_gltf()
    gltf["nodes"][0]["scale"] = [-1, 1, 1]  # mirrored in x, the quad still faces +Z
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.bounds(), [[-1, 0, 0], [0, 1, 0]])
    np.testing.assert_allclose(mesh.face_normals[:, 2], 1.0)


def test_uv_has_v_up_pinned_by_a_2x2_texture(tmp_path):
    (mesh,) = read_model(write(tmp_path, quad_gltf(image=_png(PICTURE)))).objects
    texture = np.asarray(Image.fromarray(PICTURE))
    # pixelpath's convention: (u, v) -> column u * W, row (1 - v) * H (v up)
    for corner, expected in [((0, 0, 0), (0, 0, 255)), ((1, 1, 0), (0, 255, 0)),
                             ((1, 0, 0), (255, 255, 255)), ((0, 1, 0), (255, 0, 0))]:
        index = int(np.flatnonzero(np.all(mesh.vertices == corner, axis=1))[0])
        u, v = np.clip(mesh.uv[index], 0.25, 0.75)  # the centre of the corner's texel
        texel = texture[int((1 - v) * 2), int(u * 2)]
        assert tuple(texel) == expected, corner


def test_uv_orientation_of_a_real_file():
    # trimesh flips glTF's v when loading (the 2 x 2 test above pins the convention): the
    # reader must not flip it a second time
    (mesh,) = read_model(DATA / "BoxTextured.glb").objects
    scene = trimesh.load(DATA / "BoxTextured.glb", force="scene")
    (geometry,) = scene.geometry.values()
    np.testing.assert_allclose(mesh.uv, geometry.visual.uv)  # trimesh's uv are already v up


def test_vertex_colours_are_kept():
    gltf = json.loads((DATA / "BoxVertexColors.gltf").read_text())
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",", 1)[1])
    view = gltf["bufferViews"][3]
    raw = np.frombuffer(blob[view["byteOffset"] : view["byteOffset"] + view["byteLength"]], "<f4")
    (mesh,) = read_model(DATA / "BoxVertexColors.gltf").objects
    np.testing.assert_allclose(mesh.colors, raw.reshape(-1, 4), atol=1e-6)  # linear, as stored


def test_ply_vertex_colours_are_decoded_from_srgb(tmp_path):
    box = trimesh.creation.box()
    box.visual.vertex_colors = [128, 0, 255, 255]
    path = tmp_path / "box.ply"
    box.export(path)
    scene = pp.load_scene(path)
    (mesh,) = scene.objects
    srgb = 128 / 255
    np.testing.assert_allclose(mesh.colors[0, :3], [((srgb + 0.055) / 1.055) ** 2.4, 0, 1],
                               atol=1e-6)
    assert mesh.material.color.tolist() == [1, 1, 1]  # the colours are the surface's own


def _face_coloured_square(tmp_path, colours) -> Path:
    """A unit square in z = 0 of two triangles sharing the diagonal, one colour per face."""
    faces = "\n".join(f"3 {a} {b} {c} {r} {g} {b_}" for (a, b, c), (r, g, b_)
                      in zip([(0, 1, 2), (0, 2, 3)], colours, strict=True))
    path = tmp_path / "square.ply"
    path.write_text(
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
        f"0 0 0\n1 0 0\n1 1 0\n0 1 0\n{faces}\n"
    )
    return path


def test_ply_face_colours_of_one_colour_colour_every_vertex(tmp_path):
    (mesh,) = read_model(_face_coloured_square(tmp_path, [(255, 0, 255)] * 2)).objects
    np.testing.assert_array_equal(mesh.colors, [[1, 0, 1, 1]] * 4)
    assert len(mesh.vertices) == 4 and mesh.material.color.tolist() == [1, 1, 1]


def test_ply_face_colours_give_each_face_its_corners(tmp_path):
    """A red and a blue triangle: six corners, three of each colour, on their faces' places,
    all with the square's normal (the shared corners' normals kept)."""
    (mesh,) = read_model(_face_coloured_square(tmp_path, [(255, 0, 0), (0, 0, 255)])).objects
    np.testing.assert_array_equal(mesh.colors, [[1, 0, 0, 1]] * 3 + [[0, 0, 1, 1]] * 3)
    np.testing.assert_array_equal(mesh.vertices[mesh.triangles],
                                  [[[0, 0, 0], [1, 0, 0], [1, 1, 0]],
                                   [[0, 0, 0], [1, 1, 0], [0, 1, 0]]])
    np.testing.assert_allclose(mesh.vertex_normals, [[0, 0, 1]] * 6)
    image = pp.render(pp.Scene(pp.Camera(eye=(0.5, 0.5, 2), target=(0.5, 0.5, 0), fov=40,
                                         width=32, height=32), [mesh],
                               [pp.DirectionalLight(direction=(0, 0, -1))]), "zbuffer")
    below, above = image.rgb[22, 12], image.rgb[9, 20]  # under and over the diagonal
    assert below[0] > 0.5 > below[2] and above[2] > 0.5 > above[0]


def test_stl_loads_with_the_default_camera_and_lights(tmp_path):
    path = tmp_path / "box.stl"
    trimesh.creation.box(extents=(1, 2, 3)).export(path)
    scene = pp.load_scene(path)
    assert len(scene.objects) == 1
    np.testing.assert_allclose(scene.bounds(), [[-0.5, -1, -1.5], [0.5, 1, 1.5]])
    assert len(scene.lights) == 3 and all(isinstance(x, DirectionalLight) for x in scene.lights)



def _ascii_stl(solids: dict[str, list[list[list[float]]]]) -> str:
    """An ASCII STL file with one ``solid NAME ... endsolid NAME`` block per entry."""
    lines = []
    for name, triangles in solids.items():
        lines.append(f"solid {name}")
        for triangle in triangles:
            lines += ["  facet normal 0 0 1", "    outer loop"]
            lines += [f"      vertex {x} {y} {z}" for x, y, z in triangle]
            lines += ["    endloop", "  endfacet"]
        lines.append(f"endsolid {name}")
    return "\n".join(lines) + "\n"


def test_stl_solids_become_named_objects_in_file_order(tmp_path):
    path = tmp_path / "part.stl"
    path.write_text(_ascii_stl({
        "left": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]],
        "right": [[[2, 0, 0], [3, 0, 0], [3, 1, 0]], [[2, 0, 0], [3, 1, 0], [2, 1, 0]]],
        "nothing": [],  # a solid without facets gives no object
    }))
    left, right = pp.load_scene(path).objects
    assert (left.name, right.name) == ("left", "right")
    triangle = left.vertices[left.triangles]
    np.testing.assert_array_equal(triangle, [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    # the square's two triangles share their diagonal's corners: four vertices, not six
    assert len(right.vertices) == 4 and right.face_count == 2
    np.testing.assert_allclose(right.bounds(), [[2, 0, 0], [3, 1, 0]])
    # Mesh.load reads the same file as one mesh of all the solids
    joined = pp.Mesh.load(path)
    assert len(joined.vertices) == 7 and joined.face_count == 3


def test_stl_of_a_cad_part_with_two_bodies():
    """trimesh's models/multibody.stl: two ASCII solids, as a CAD program exports them."""
    path = DATA / "multibody.stl"
    scene = pp.load_scene(path)
    reference = trimesh.load(path, process=False)  # a trimesh Scene: one geometry per solid
    assert [obj.name for obj in scene.objects] == ["bodyB", "bodyA"] == list(reference.geometry)
    for obj, body in zip(scene.objects, reference.geometry.values(), strict=True):
        # the same triangles (each as its nine corner coordinates), in any order
        ours = np.unique(obj.vertices[obj.triangles].reshape(len(obj.triangles), 9), axis=0)
        theirs = np.unique(body.vertices[body.faces].reshape(len(body.faces), 9), axis=0)
        assert len(ours) == obj.face_count == len(body.faces)
        np.testing.assert_array_equal(ours, theirs)
    image = pp.render(dataclasses.replace(scene, camera=scene.camera.with_size(96, 72)))
    assert set(np.unique(image.object_id).tolist()) == {-1, 0, 1}  # both bodies in sight
    assert pp.Mesh.load(path).face_count == sum(len(b.faces) for b in reference.geometry.values())

# --- materials ------------------------------------------------------------------------------


def test_mtl_ns_0_gives_no_highlight_and_keeps_the_texture():
    (mesh,) = read_model(DATA / "fuze.obj").objects  # Ks 1 1 1 but Ns 0
    assert mesh.material.ks == 0.0
    np.testing.assert_allclose(mesh.material.color, [1, 1, 1])
    assert mesh.material.name == "a-super-duper-material"


def test_gltf_roughness_1_gives_no_highlight():
    (duck,) = read_model(DATA / "Duck.glb").objects  # metallic 0, roughness 1 (the default)
    assert duck.material.ks == 0.0 and duck.material.kd == 1.0
    (box,) = read_model(DATA / "BoxVertexColors.gltf").objects  # roughness 0.99
    assert box.material.ks < 1e-3
    np.testing.assert_allclose(box.material.color, [0.8, 0.8, 0.8], atol=1 / 255)


def test_gltf_smooth_metal_and_flags(tmp_path):
    gltf = quad_gltf()
    gltf["materials"][0] = {
        "name": "metal",
        "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 0.5], "metallicFactor": 1.0,
                                 "roughnessFactor": 0.5},
        "doubleSided": True,
        "alphaMode": "BLEND",
    }
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    material = mesh.material
    assert material.ks == pytest.approx(0.25)  # (1 - 0.5)^2 for a metal
    assert material.shininess == pytest.approx(2 / 0.5**4 - 2)
    assert material.double_sided
    assert material.transparency == pytest.approx(0.5, abs=1 / 255)
    np.testing.assert_allclose(material.color, [1, 0.5, 0.25], atol=1 / 255)


def _with_metal_rough_picture(gltf: dict, picture: bytes) -> dict:
    """Give the quad's material a metallicRoughnessTexture of ``picture`` (PNG bytes)."""
    gltf.setdefault("images", []).append({"uri": _data_uri(picture, "image/png")})
    gltf.setdefault("textures", []).append({"source": len(gltf["images"]) - 1})
    pbr = gltf["materials"][0]["pbrMetallicRoughness"]
    pbr["metallicRoughnessTexture"] = {"index": len(gltf["textures"]) - 1}
    return gltf


# roughness (green) 0, 102, 204, 255: mean 140.25 = 0.55 x 255; metalness (blue) 0, 0, 51,
# 255: mean 76.5 = 0.3 x 255; red (occlusion, when packed) is not used
METAL_ROUGH = np.array([[[9, 0, 0], [9, 102, 0]], [[9, 204, 51], [9, 255, 255]]], np.uint8)


@pytest.mark.parametrize(
    ("factors", "metallic", "roughness"),
    [({}, 0.3, 0.55),  # absent factors are 1: the texture's means alone
     ({"metallicFactor": 0.5, "roughnessFactor": 0.8}, 0.15, 0.44)],
)
def test_a_metallic_roughness_texture_counts_by_its_means(tmp_path, factors, metallic,
                                                          roughness):
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["materials"][0]["pbrMetallicRoughness"] = factors | {"baseColorTexture": {"index": 0}}
    _with_metal_rough_picture(gltf, _png(METAL_ROUGH))
    material = read_model(write(tmp_path, gltf)).objects[0].material
    assert material.kd == pytest.approx(1 - 0.6 * metallic)
    assert material.ka == material.kd
    assert material.ks == pytest.approx((1 - roughness) ** 2 * (0.25 + 0.75 * metallic))
    assert material.shininess == pytest.approx(2 / roughness**4 - 2)
    assert material.texture is not None  # the base colour's, as before


def test_a_16_bit_grey_metallic_roughness_texture_is_read_as_fractions(tmp_path):
    grey = io.BytesIO()
    Image.fromarray(np.full((2, 2), 32768, dtype=np.uint16)).save(grey, format="PNG")
    gltf = quad_gltf()
    gltf["materials"][0]["pbrMetallicRoughness"] = {}  # factors 1: the texture's means alone
    scene = read_model(write(tmp_path, _with_metal_rough_picture(gltf, grey.getvalue())))
    assert scene.objects[0].material.kd == pytest.approx(1 - 0.6 * 32768 / 65535)


def test_a_textured_specular_glossiness_material_is_not_drawn_as_a_rough_metal(tmp_path):
    # trimesh turns KHR_materials_pbrSpecularGlossiness into metallic-roughness, the
    # texture's factors 1 and a metallic-roughness picture that holds the glossiness
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["materials"][0] = {"extensions": {"KHR_materials_pbrSpecularGlossiness": {
        "diffuseTexture": {"index": 0}, "specularFactor": [0.2] * 3, "glossinessFactor": 0.5}}}
    material = read_model(write(tmp_path, gltf)).objects[0].material
    assert material.shininess == pytest.approx(2 / 0.5**4 - 2, rel=0.05)  # roughness 1 - 0.5
    assert material.kd > 0.7  # a metal's would be 0.4


def test_a_corrupt_metallic_roughness_texture_is_refused(tmp_path):
    noise = np.random.default_rng(3).integers(0, 256, (64, 64, 3), dtype=np.uint8)
    gltf = _with_metal_rough_picture(quad_gltf(), _png(noise)[:200])
    refused(tmp_path, gltf, "metallic-roughness texture is not a readable image")


@pytest.mark.parametrize("named", [True, False])
@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_unlit_gltf_material_shows_its_colour_unshaded(tmp_path, named, method):
    """KHR_materials_unlit: every drawn pixel of the quad is its base colour exactly (the
    ambient term alone: 0.2 x 5 x C), whatever the lights; lit, the same quad is shaded.
    Unnamed, the one material is still found."""
    gltf = quad_gltf(extensionsUsed=["KHR_materials_unlit"])
    gltf["materials"][0] = {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1.0, 1.0]},
                            "extensions": {"KHR_materials_unlit": {}}}
    if named:
        gltf["materials"][0]["name"] = "flat"
    lit = json.loads(json.dumps(gltf))
    del lit["materials"][0]["extensions"]
    images = []
    for name, data in (("unlit.gltf", gltf), ("lit.gltf", lit)):
        scene = pp.load_scene(write(tmp_path, data, name))
        image = pp.render(dataclasses.replace(scene, camera=scene.camera.with_size(48, 36)),
                          method)
        images.append(np.asarray(image)[image.alpha == 1.0])
    unlit, shaded = images
    color = scene.objects[0].material.color  # trimesh keeps the factor in 8 bits: 128/255
    np.testing.assert_allclose(color, [0.5, 0.25, 1.0], atol=0.5 / 255)
    assert len(unlit) > 100
    np.testing.assert_allclose(unlit, np.broadcast_to(color, unlit.shape), atol=1e-6)
    assert np.abs(shaded - color).max() > 0.05


@pytest.mark.parametrize(("strength", "expected"), [(None, [1.0, 0.5, 0.0]),
                                                   (4.0, [4.0, 2.0, 0.0])])
def test_gltf_emission_is_the_factor_times_the_strength(tmp_path, strength, expected):
    gltf = quad_gltf()
    material = gltf["materials"][0]
    material["emissiveFactor"] = [1.0, 0.5, 0.0]
    if strength is not None:
        material["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength":
                                                                      strength}}
        gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    assert mesh.material.emission.tolist() == expected


@pytest.mark.parametrize(
    ("extensions", "transparency", "ior", "kd"),
    [
        ({"KHR_materials_transmission": {"transmissionFactor": 0.9},
          "KHR_materials_ior": {"ior": 1.33}}, 0.9, 1.33, 0.1),
        ({"KHR_materials_transmission": {"transmissionFactor": 0.25}}, 0.25, 1.5, 0.75),
        ({"KHR_materials_transmission": {}}, 0.0, 1.5, 1.0),  # glTF's default factor is 0
        ({"KHR_materials_ior": {"ior": 2.0}}, 0.0, 2.0, 1.0),
        ({"KHR_materials_ior": {"ior": 0}}, 0.0, 1.5, 1.0),  # below 1: glTF's default
        ({"KHR_materials_transmission": {"transmissionFactor": "x"}}, 0.0, 1.5, 1.0),
        ({"KHR_materials_transmission": {"transmissionFactor": 1.0},
          "KHR_materials_unlit": {}}, 0.0, 1.5, 0.0),  # unlit: the colour as it is
    ],
)
def test_gltf_transmission_and_ior_go_to_the_ray_tracer(tmp_path, extensions, transparency,
                                                       ior, kd):
    """A metallic factor of 0 gives kd = 1 before transmission takes its share."""
    gltf = quad_gltf()
    gltf["materials"][0]["extensions"] = extensions
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    material = mesh.material
    assert (material.transparency, material.ior, material.kd) == pytest.approx(
        (transparency, ior, kd))


def test_a_transmissive_gltf_square_lets_the_wall_behind_show(tmp_path):
    """Ray traced, a red wall seen through the square: redder through glass than through
    the same square opaque."""
    images = []
    for extensions in ({}, {"KHR_materials_transmission": {"transmissionFactor": 1.0}}):
        gltf = quad_gltf()
        gltf["materials"][0].update(extensions=extensions, doubleSided=True)
        scene = read_model(write(tmp_path, gltf))
        wall = pp.Mesh([[-5, -5, -1], [6, -5, -1], [6, 6, -1], [-5, 6, -1]], [[0, 1, 2, 3]],
                       pp.Material(color=(1, 0, 0), ka=1.0))
        camera = pp.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0), width=16, height=16,
                           fov=20)
        scene = dataclasses.replace(scene, camera=camera, objects=[*scene.objects, wall])
        images.append(pp.render(scene, "raytrace").rgb[8, 8])
    opaque, glass = images
    assert glass[0] - glass[1] > opaque[0] - opaque[1] + 0.2


def test_a_gltf_emission_texture_is_drawn(tmp_path):
    """The quad's picture as its emissiveTexture too, emissiveFactor (1, 0.5, 1): in the dark
    the quad shows the factor times the picture, its blue corner at the world's (0, 0, 0),
    red at (0, 1, 0), as the base colour's texture coordinates put them."""
    gltf = quad_gltf(image=_png(PICTURE), samplers=[{"magFilter": 9728, "minFilter": 9728}])
    gltf["textures"][0]["sampler"] = 0  # the nearest texel: each corner's colour exactly
    gltf["materials"][0].update(emissiveFactor=[1.0, 0.5, 1.0], emissiveTexture={"index": 0})
    scene = read_model(write(tmp_path, gltf))
    (mesh,) = scene.objects
    assert mesh.material.emission.tolist() == [1.0, 0.5, 1.0]
    np.testing.assert_array_equal(mesh.material.emission_texture.levels[0][..., :3], PICTURE)
    camera = pp.Camera(eye=(0.5, 0.5, 2), target=(0.5, 0.5, 0), width=40, height=40, fov=30,
                       near=0.1, far=10)
    dark = dataclasses.replace(scene, camera=camera, lights=[], ambient=0.0)
    image = pp.render(dark)
    np.testing.assert_allclose(image.rgb[30, 10], [0.0, 0.0, 1.0], atol=1e-6)  # bottom-left
    np.testing.assert_allclose(image.rgb[10, 10], [1.0, 0.0, 0.0], atol=1e-6)  # top-left
    np.testing.assert_allclose(image.rgb[10, 30], [0.0, 0.5, 0.0], atol=1e-6)  # top-right


@pytest.mark.parametrize(
    ("reference", "message"),
    [
        ({"index": 0, "texCoord": 1}, "reading texture coordinates TEXCOORD_1 where the base "
                                      "colour reads TEXCOORD_0"),
        ({"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}},
         "with a KHR_texture_transform other than the base colour's"),
    ],
)
def test_an_emission_texture_read_otherwise_is_named_as_not_drawn(tmp_path, reference, message):
    gltf = quad_gltf(image=_png(PICTURE), extensionsUsed=["KHR_texture_transform"])
    gltf["materials"][0].update(emissiveFactor=[1.0, 1.0, 1.0], emissiveTexture=reference)
    with pytest.warns(UserWarning, match=rf"model\.gltf: material 'm' emits light "
                                         rf"\(emissiveFactor .*\) through an emissiveTexture "
                                         rf"{message}, which is not drawn"):
        (mesh,) = read_model(write(tmp_path, gltf)).objects
    assert not mesh.material.emits  # the factor alone would light the quad evenly
    assert mesh.material.emission_texture is None


def test_mtl_emission_is_ke_decoded_from_srgb(tmp_path):
    (tmp_path / "glow.mtl").write_text("newmtl glow\nKd 0.5 0.5 0.5\nKe 1 0.25 0\n")
    (tmp_path / "glow.obj").write_text("mtllib glow.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                       "usemtl glow\nf 1 2 3\n")
    (mesh,) = read_model(tmp_path / "glow.obj").objects
    np.testing.assert_allclose(mesh.material.emission,
                               [1.0, ((0.25 + 0.055) / 1.055) ** 2.4, 0.0], rtol=1e-12)


def _glowing_obj(tmp_path, map_kd: str, map_ke: str) -> Path:
    """A textured OBJ square whose .mtl has Ke 1 1 1 and the given map lines."""
    Image.fromarray(PICTURE).save(tmp_path / "paint.png")
    Image.fromarray(PICTURE[::-1]).save(tmp_path / "my glow.png")
    (tmp_path / "glow.mtl").write_text(f"newmtl glow\nKd 1 1 1\nKe 1 1 1\n{map_kd}{map_ke}")
    (tmp_path / "glow.obj").write_text(
        "mtllib glow.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl glow\nf 1/1 2/2 3/3 4/4\n")
    return tmp_path / "glow.obj"


def test_an_mtl_map_ke_is_drawn(tmp_path):
    path = _glowing_obj(tmp_path, "map_Kd -s 2 2 1 paint.png\n", "map_Ke -s 2 2 1 my glow.png\n")
    (mesh,) = read_model(path).objects
    np.testing.assert_array_equal(mesh.material.emission_texture.levels[0][..., :3],
                                  PICTURE[::-1])
    assert mesh.material.emits and mesh.material.emission_texture.name == "my glow.png (map_Ke)"


@pytest.mark.parametrize(
    ("map_ke", "message"),
    [
        ("map_Ke my glow.png\n", "a map_Ke texture whose -s or -o differ from map_Kd's"),
        ("map_Ke -s 2 2 1 gone.png\n", "a map_Ke texture that was not found"),
    ],
)
def test_an_mtl_map_ke_that_cannot_be_drawn_is_named(tmp_path, map_ke, message):
    path = _glowing_obj(tmp_path, "map_Kd -s 2 2 1 paint.png\n", map_ke)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        (mesh,) = read_model(path).objects
    text = " | ".join(str(w.message) for w in caught)
    assert f"glow.obj: material 'glow' emits light (Ke [1.0, 1.0, 1.0]) through {message}" in text
    assert not mesh.material.emits and mesh.material.emission_texture is None


def test_an_mtl_map_ke_outside_the_folder_is_refused(tmp_path):
    (tmp_path / "inner").mkdir()
    path = _glowing_obj(tmp_path / "inner", "", "map_Ke ../secret.png\n")
    with pytest.raises(ValueError, match=r"glow\.obj.*outside the model's folder"):
        read_model(path)


def test_webp_textures_are_read(tmp_path):
    """EXT_texture_webp, required (no PNG fallback): the WebP picture is the texture."""
    out = io.BytesIO()
    Image.fromarray(PICTURE).save(out, format="WEBP", lossless=True)
    gltf = quad_gltf(image=out.getvalue(), extensionsUsed=["EXT_texture_webp"],
                     extensionsRequired=["EXT_texture_webp"])
    gltf["images"][0]["uri"] = _data_uri(out.getvalue(), "image/webp")
    gltf["textures"] = [{"extensions": {"EXT_texture_webp": {"source": 0}}}]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.material.texture.levels[0][..., :3], PICTURE)


def test_mtl_values_are_mapped(tmp_path):
    (tmp_path / "m.mtl").write_text("newmtl shiny\nKd 0.5 0.5 0.5\nKa 0.3 0.3 0.3\n"
                                    "Ks 0.8 0.8 0.8\nNs 50\nd 0.25\n")
    (tmp_path / "m.obj").write_text("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\n"
                                    "f 1 2 3\n")
    (mesh,) = read_model(tmp_path / "m.obj").objects
    material = mesh.material
    assert material.ka == pytest.approx(0.3)
    assert material.ks == pytest.approx(0.4)  # 0.8 * 50 / 100
    assert material.shininess == 50
    assert material.transparency == pytest.approx(0.75)
    np.testing.assert_allclose(material.color, ((0.5 + 0.055) / 1.055) ** 2.4)


def test_obj_with_spaces_and_missing_texture_warns(tmp_path):
    for name in ("fuze.obj", "fuze.obj.mtl"):
        shutil.copy(DATA / name, tmp_path / name)
    with pytest.warns(UserWarning, match=r"fuze uv.jpg"):
        (mesh,) = read_model(tmp_path / "fuze.obj").objects
    assert mesh.material.texture is None



_TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\n{uv}f {faces}\n"
_TRIANGLE_PLY = (
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\n{uv_header}element face 1\nproperty list uchar int vertex_indices\n"
    "end_header\n0 0 0{uv0}\n1 0 0{uv1}\n0 1 0{uv2}\n3 0 1 2\n"
)


@pytest.mark.parametrize("suffix", ["obj", "ply"])
def test_texture_coordinates_without_a_material_keep_the_plain_material(tmp_path, suffix):
    """uv and no texture (OBJ ``vt`` without ``.mtl``, PLY ``s t``): trimesh's 2 x 2 grey
    stand-in picture is not a texture; the model is drawn as the same file without uv."""
    if suffix == "obj":
        plain = _TRIANGLE_OBJ.format(uv="", faces="1 2 3")
        with_uv = _TRIANGLE_OBJ.format(uv="vt 0 0\nvt 1 0\nvt 0 1\n", faces="1/1 2/2 3/3")
    else:
        plain = _TRIANGLE_PLY.format(uv_header="", uv0="", uv1="", uv2="")
        with_uv = _TRIANGLE_PLY.format(uv_header="property float s\nproperty float t\n",
                                       uv0=" 0 0", uv1=" 1 0", uv2=" 0 1")
    (tmp_path / f"plain.{suffix}").write_text(plain)
    (tmp_path / f"uv.{suffix}").write_text(with_uv)
    (mesh,) = read_model(tmp_path / f"uv.{suffix}").objects
    assert mesh.uv is not None and mesh.material.texture is None
    np.testing.assert_allclose(mesh.material.color, [0.8, 0.8, 0.8])  # "no material"
    scenes = [pp.load_scene(tmp_path / f"{name}.{suffix}") for name in ("plain", "uv")]
    images = [pp.render(dataclasses.replace(scene, camera=scene.camera.with_size(64, 48)))
              for scene in scenes]
    assert np.asarray(images[0]).max() > 0.5  # lit light grey, not the stand-in's dark grey
    np.testing.assert_array_equal(np.asarray(images[0]), np.asarray(images[1]))


def _textured_square(tmp_path, map_line: str, uv: str = "0 0|1 0|1 1|0 1") -> Path:
    """An OBJ square whose .mtl names a 2 x 2 picture on ``map_line``; ``uv`` its corners'."""
    Image.fromarray(PICTURE).save(tmp_path / "my tex.png")
    (tmp_path / "m.mtl").write_text(f"newmtl t\nKd 1 1 1\n{map_line}\n")
    corners = "".join(f"vt {pair}\n" for pair in uv.split("|"))
    (tmp_path / "q.obj").write_text(
        f"mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n{corners}usemtl t\n"
        "f 1/1 2/2 3/3 4/4\n"
    )
    return tmp_path / "q.obj"


def test_mtl_map_options_are_read_past_and_the_unapplied_named(tmp_path):
    # trimesh hands "-s 2 2 1 -bm 0.5 my tex.png" to the resolver as the file's name
    path = _textured_square(tmp_path, "map_Kd -s 2 2 1 -bm 0.5 -blendu off my tex.png")
    with pytest.warns(UserWarning, match=r"q\.obj: material 't': the \.mtl texture options "
                                         r"'-bm 0\.5 -blendu off' are not applied"):
        (mesh,) = read_model(path).objects
    assert mesh.material.texture is not None
    np.testing.assert_array_equal(mesh.material.texture.levels[0][..., :3], PICTURE)
    with pytest.raises(ValueError, match=r"q\.obj: refers to .*outside the file's folder"):
        read_model(_textured_square(tmp_path, "map_Kd -s 2 ../my tex.png"))


def test_an_mtl_picture_trimesh_cannot_decode_is_refused_by_name(tmp_path):
    # trimesh drops such a picture silently: the square was drawn white, untextured
    path = _textured_square(tmp_path, "map_Kd my tex.png")
    (tmp_path / "my tex.png").write_bytes(bytes(range(256)) * 4)  # no picture's header
    with pytest.raises(ValueError, match=r"q\.obj: the texture 'my tex\.png' is not a picture "
                                         r"pixelpath can read \(not in a picture format"):
        read_model(path)


def test_an_mtl_picture_too_large_for_pillow_is_refused_with_its_size(tmp_path, monkeypatch):
    # Pillow refuses pictures of more than twice MAX_IMAGE_PIXELS (16384 x 16384 is past that
    # by default); a lower limit stands for such a size here: the 2 x 2 picture has 4 pixels
    path = _textured_square(tmp_path, "map_Kd my tex.png")
    monkeypatch.setattr(Image, "MAX_IMAGE_PIXELS", 1)
    with pytest.raises(ValueError, match=r"q\.obj: the texture 'my tex\.png' .*Image size "
                                         r"\(4 pixels\) exceeds limit.* at most 8192 texels"):
        read_model(path)


def test_a_gltf_picture_too_large_for_pillow_is_refused_with_its_size(tmp_path, monkeypatch):
    gltf = quad_gltf(image=_png(PICTURE))
    Image.fromarray(PICTURE).save(tmp_path / "big.png")
    gltf["images"][0]["uri"] = "big.png"
    monkeypatch.setattr(Image, "MAX_IMAGE_PIXELS", 1)
    refused(tmp_path, gltf, r"material 'm' has a base-colour texture that could not be read "
                            r"\(Image size \(4 pixels\) exceeds limit")


def test_a_material_library_of_any_name_is_not_taken_for_a_picture(tmp_path):
    path = _textured_square(tmp_path, "map_Kd my tex.png")
    (tmp_path / "m.mtl").rename(tmp_path / "materials.lib")
    path.write_text(path.read_text().replace("mtllib m.mtl", "mtllib materials.lib"))
    (mesh,) = read_model(path).objects
    np.testing.assert_array_equal(mesh.material.texture.levels[0][..., :3], PICTURE)
    # Blender's library for an object without materials: no newmtl line at all
    (tmp_path / "materials.lib").write_text("# Blender MTL File: 'None'\n# Material Count: 0\n")
    (mesh,) = read_model(path).objects
    assert mesh.material.texture is None


def test_an_unused_mtl_material_with_a_sound_picture_is_no_error(tmp_path):
    path = _textured_square(tmp_path, "map_Kd my tex.png")
    with (tmp_path / "m.mtl").open("a") as mtl:
        mtl.write("newmtl spare\nmap_Kd spare.png\n")
    Image.fromarray(PICTURE).save(tmp_path / "spare.png")
    (mesh,) = read_model(path).objects
    np.testing.assert_array_equal(mesh.material.texture.levels[0][..., :3], PICTURE)


@pytest.mark.parametrize(
    ("line", "uv", "wrap"),
    [
        ("-s 2 3 1 -o 0.25 0.5 0", [[0.25, 0.5], [2.25, 0.5], [2.25, 3.5], [0.25, 3.5]], "repeat"),
        ("-o 0.5", [[0.5, 0.0], [1.5, 0.0], [1.5, 1.0], [0.5, 1.0]], "repeat"),  # v, w: 0
        ("-s 4 -clamp on", [[0, 0], [4, 0], [4, 1], [0, 1]], "clamp"),  # v, w: 1
        ("-clamp off -s 1 1 1", [[0, 0], [1, 0], [1, 1], [0, 1]], "repeat"),
    ],
)
def test_mtl_map_scale_offset_and_clamp_are_applied(tmp_path, line, uv, wrap):
    """``-s`` scales uv, then ``-o`` moves them (u' = su u + ou, v' = sv v + ov); ``-clamp on``
    is the clamp wrap. Each expected uv is worked out by hand from the square's corners."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # every option here is applied: no warning
        (mesh,) = read_model(_textured_square(tmp_path, f"map_Kd {line} my tex.png")).objects
    np.testing.assert_array_equal(mesh.uv, uv)
    assert mesh.material.texture_wrap == wrap


def test_mtl_map_options_render_as_the_same_uv_written_out(tmp_path):
    """A square whose .mtl scales and moves its texture renders to the same bytes as the
    square whose ``vt`` lines hold the moved coordinates, and not as the square unmoved."""

    def picture(folder: Path, line: str, uv: str) -> np.ndarray:
        folder.mkdir()
        scene = pp.load_scene(_textured_square(folder, f"map_Kd {line}my tex.png", uv))
        return np.asarray(pp.render(dataclasses.replace(
            scene, camera=scene.camera.with_size(64, 48))))

    moved = picture(tmp_path / "options", "-s 0.5 0.5 -o 0.5 0 ", "0 0|1 0|1 1|0 1")
    written = picture(tmp_path / "written", "", "0.5 0|1 0|1 0.5|0.5 0.5")
    plain = picture(tmp_path / "plain", "", "0 0|1 0|1 1|0 1")
    np.testing.assert_array_equal(moved, written)
    assert not np.array_equal(moved, plain)


def test_ply_texture_file_is_the_colour_itself(tmp_path):
    Image.fromarray(PICTURE).save(tmp_path / "tex.png")
    header = ["ply", "format ascii 1.0", "comment TextureFile tex.png", "element vertex 3",
              "property float x", "property float y", "property float z", "property float s",
              "property float t", "element face 1", "property list uchar int vertex_indices",
              "end_header"]  # fmt: skip
    (tmp_path / "t.ply").write_text("\n".join([*header, "0 0 0 0 0", "1 0 0 1 0", "0 1 0 0 1",
                                               "3 0 1 2"]) + "\n")
    (mesh,) = read_model(tmp_path / "t.ply").objects
    assert mesh.material.texture is not None
    np.testing.assert_allclose(mesh.material.color, [1, 1, 1])  # not the grey of no material

# --- camera and lights --------------------------------------------------------------------------


def _project(camera, points):
    """Pixel coordinates of ``points`` seen by a perspective look-at camera (written here)."""
    eye, target = np.asarray(camera.eye), np.asarray(camera.target)
    back = (eye - target) / np.linalg.norm(eye - target)
    right = np.cross(camera.up, back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    rel = points - eye
    depth = -(rel @ back)
    scale = math.tan(math.radians(camera.fov) / 2)
    x = (rel @ right) / (depth * scale * camera.width / camera.height)
    y = (rel @ up) / (depth * scale)
    return (x + 1) / 2 * camera.width, (1 - y) / 2 * camera.height, depth


@pytest.mark.parametrize("name", ["BoxTextured.glb", "BoxVertexColors.gltf", "fuze.obj"])
def test_default_camera_frames_the_model(name):
    scene = read_model(DATA / name)
    camera = scene.camera
    assert (camera.width, camera.height) == (800, 600)
    bounds = scene.bounds()
    corners = np.array(np.meshgrid(*bounds.T, indexing="ij")).reshape(3, -1).T
    px, py, depth = _project(camera, corners)
    assert np.all((px >= 0) & (px <= camera.width) & (py >= 0) & (py <= camera.height))
    assert np.all((depth > camera.near) & (depth < camera.far))
    covered = max((px.max() - px.min()) / camera.width, (py.max() - py.min()) / camera.height)
    assert covered > 0.6
    # from the front (+Z) and a little above
    view = np.asarray(camera.eye) - np.asarray(camera.target)
    elevation = math.degrees(math.asin(view[1] / np.linalg.norm(view)))
    assert view[2] > 0 and 15 < elevation < 30


def test_framing_camera_honours_the_size():
    camera = framing_camera([[0, 0, 0], [10, 1, 1]], (200, 100))
    px, py, _ = _project(camera, np.array([[0, 0, 0], [10, 1, 1], [0, 1, 1], [10, 0, 0]]))
    assert px.min() >= 0 and px.max() <= 200 and py.min() >= 0 and py.max() <= 100


def test_file_camera_is_used():
    camera = read_model(DATA / "Duck.glb").camera
    assert camera.fov == pytest.approx(math.degrees(0.6605925559997559))
    # the camera node's translation under the root's 0.01 scale
    np.testing.assert_allclose(camera.eye, [4.00113, 4.63264, -4.31078], atol=1e-4)
    assert camera.height == 600 and camera.width == 900  # aspectRatio 1.5
    assert camera.near == pytest.approx(1.0)


def test_file_lights_are_used(tmp_path):
    gltf = quad_gltf()
    gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "intensity": 2.0, "color": [1, 0.5, 0.5]},
        {"type": "point", "intensity": 4.0},
    ]}}
    half = math.sqrt(0.5)
    gltf["nodes"] += [
        # rotated -90 degrees about X: the node's -Z points down, -Y
        {"rotation": [-half, 0, 0, half], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"translation": [0.5, 0.5, 2], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    ]
    gltf["scenes"][0]["nodes"] = [0, 1, 2]
    scene = read_model(write(tmp_path, gltf))
    directional, point = scene.lights
    assert isinstance(directional, DirectionalLight) and isinstance(point, PointLight)
    np.testing.assert_allclose(directional.direction, [0, -1, 0], atol=1e-6)
    np.testing.assert_allclose(point.position, [0.5, 0.5, 2])
    # lux 2 against candela 4 at 2 units from the model's centre (4 / 2^2 = 1): 2 is brightest
    assert directional.intensity == pytest.approx(1.0) and point.intensity == pytest.approx(0.5)


# --- scene files naming model files -------------------------------------------------------------


def test_scene_file_names_a_model_and_overrides_its_material(tmp_path):
    shutil.copy(DATA / "Duck.glb", tmp_path)
    (tmp_path / "s.toml").write_text(
        '[camera]\neye = [0, 1, 6]\ntarget = [0, 0.8, 0]\n[materials.red]\ncolor = [1, 0, 0]\n'
        '[[objects]]\ntype = "mesh"\npath = "Duck.glb"\nname = "duck"\n'
        '[[objects]]\ntype = "mesh"\npath = "Duck.glb"\nmaterial = "red"\n'
        'transform = { translate = [2, 0, 0] }\n'
    )
    scene = pp.load_scene(tmp_path / "s.toml")
    own, red = scene.objects
    assert own.name == "duck/LOD3spShape" and own.material.texture is not None
    assert red.material.texture is None and red.material.color.tolist() == [1, 0, 0]
    np.testing.assert_allclose(red.bounds(), own.bounds() + np.array([2, 0, 0]))
    again = pp.Scene.from_dict(scene.to_dict(base_dir=tmp_path), tmp_path)
    assert [obj.name for obj in again.objects] == [obj.name for obj in scene.objects]


@pytest.mark.parametrize("value", ["[1, 2]", "{ a = 1 }", "3"])
def test_scene_object_type_of_the_wrong_kind_names_file_key_and_line(tmp_path, value):
    path = tmp_path / "s.toml"
    path.write_text(f"[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[[objects]]\ntype = {value}\n")
    with pytest.raises(ValueError, match=r"s\.toml: objects\[0\]\.type \(near line 5\)"):
        pp.load_scene(path)


# --- bad input -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "uri", ["../../etc/passwd", "/etc/passwd", "file:///etc/passwd", "http://example.com/a.bin",
            "..%2F..%2Fetc%2Fpasswd", "sub/../../outside.bin"]
)
@pytest.mark.parametrize("kind", ["buffers", "images"])
def test_uris_outside_the_folder_are_refused_before_reading(tmp_path, monkeypatch, uri, kind):
    gltf = quad_gltf(image=_png(PICTURE))
    gltf[kind][0]["uri"] = uri
    path = write(tmp_path, gltf)

    def no_reading(*args, **kwargs):
        raise AssertionError("trimesh was asked to read the file")

    monkeypatch.setattr(trimesh, "load", no_reading)
    with pytest.raises(ValueError, match=r"model\.gltf") as error:
        read_model(path)
    assert uri in str(error.value)


@pytest.mark.parametrize(
    "extension", ["KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_texture_basisu"]
)
def test_required_extensions_trimesh_cannot_decode_are_named(tmp_path, extension):
    if extension.startswith("KHR_draco") and importlib.util.find_spec("DracoPy"):
        pytest.skip("DracoPy is installed: trimesh decodes Draco")
    path = write(tmp_path, quad_gltf(extensionsUsed=[extension], extensionsRequired=[extension]))
    with pytest.raises(ValueError, match=rf"model\.gltf.*{extension}"):
        read_model(path)


def _accessor_edit(tmp_path, index, **changes):
    gltf = quad_gltf()
    gltf["accessors"][index].update(changes)
    return write(tmp_path, gltf)


def test_absurd_counts_are_refused(tmp_path):
    with pytest.raises(ValueError, match=r"model\.gltf: accessor 0"):
        read_model(_accessor_edit(tmp_path, 0, count=10**12))


def _sparse(values_view: int, count: int = 1, indices_view: int = 2) -> dict:
    """A sparse block replacing the elements listed first in bufferView ``indices_view`` (the
    quad's triangle indices: 0, 1, 2, ...) with the first of bufferView ``values_view``."""
    return {"count": count, "indices": {"bufferView": indices_view, "componentType": 5123},
            "values": {"bufferView": values_view}}


def test_khronos_sparse_accessor_is_decoded():
    """Khronos' SimpleSparseAccessor: a 7 x 2 grid of vertices whose sparse block moves
    vertices 8, 10 and 12 of the top row up to y = 2, 3 and 4 (trimesh alone leaves it flat)."""
    (mesh,) = read_model(DATA / "SimpleSparseAccessor.gltf").objects
    expected = [[x, 0.0, 0.0] for x in range(7)] + [[x, 1.0, 0.0] for x in range(7)]
    expected[8], expected[10], expected[12] = [1, 2, 0], [3, 3, 0], [5, 4, 0]
    np.testing.assert_array_equal(mesh.vertices, expected)
    assert len(mesh.triangles) == 12


def _glb_with_binary(gltf: dict, blob: bytes) -> bytes:
    """A GLB of ``gltf`` whose buffer 0 is the binary chunk ``blob``."""
    gltf = {**gltf, "buffers": [{"byteLength": len(blob)}]}
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    blob += bytes(-len(blob) % 4)
    body = (struct.pack("<II", len(text), 0x4E4F534A) + text
            + struct.pack("<II", len(blob), 0x004E4942) + blob)
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def _glb_with_picture(tmp_path: Path, image: bytes, extra: int = 0) -> Path:
    """The quad with ``image`` as its texture, the picture in the GLB's binary chunk.

    The picture's bufferView claims ``extra`` bytes more than the picture has.
    """
    gltf = quad_gltf(image=image)
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1])
    blob += bytes(-len(blob) % 4)
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(blob),
                                "byteLength": len(image) + extra})
    gltf["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    path = tmp_path / "model.glb"
    path.write_bytes(_glb_with_binary(gltf, blob + image))
    return path


def test_a_picture_in_a_glb_binary_chunk_is_read(tmp_path):
    (mesh,) = read_model(_glb_with_picture(tmp_path, _png(PICTURE))).objects
    np.testing.assert_array_equal(mesh.material.texture.levels[0][..., :3], PICTURE)
    np.testing.assert_array_equal(corner_positions(mesh), QUAD[QUAD_TRIANGLES])


@pytest.mark.parametrize("pread", ["short", "absent", "system"])
def test_ranges_of_a_file_are_read_whole(tmp_path, monkeypatch, pread):
    """A short pread (the system's 2 GiB a call) and a system without pread (Windows) both
    read the range to its end, as a seek and a read do."""
    import os

    from pixelpath.io.models import _read_at

    path = tmp_path / "data.bin"
    path.write_bytes(bytes(range(256)) * 4)
    if pread == "short":
        monkeypatch.setattr(os, "pread", lambda fd, length, offset: b"\x00")
    elif pread == "absent":
        monkeypatch.delattr(os, "pread", raising=False)
    with path.open("rb") as file:
        assert _read_at(file, 300, 500) == path.read_bytes()[300:800]
        assert _read_at(file, 1000, 100) == path.read_bytes()[1000:]  # fewer at the end


def test_a_view_past_the_end_of_a_glb_binary_chunk_is_refused(tmp_path):
    # The chunk is padded to 4 bytes: a view 8 bytes too long runs past its end.
    path = _glb_with_picture(tmp_path, _png(PICTURE), extra=8)
    with pytest.raises(ValueError, match=r"model\.glb: bufferView 3 runs past the end"):
        read_model(path)


@pytest.mark.parametrize("container", ["gltf", "glb"])
def test_sparse_vertices_are_substituted(tmp_path, container):
    """Vertex 0 of the quad replaced by (0.5, 0.25, 2.0), from a values view of its own; in a
    GLB, the buffer is the binary chunk."""
    moved = np.array([[0.5, 0.25, 2.0]], dtype="<f4")
    gltf = quad_gltf()
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1]) + moved.tobytes()
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(blob) - 12, "byteLength": 12})
    gltf["buffers"][0] = {"byteLength": len(blob), "uri": _data_uri(blob)}
    gltf["accessors"][0]["sparse"] = _sparse(3)
    if container == "glb":
        path = tmp_path / "model.glb"
        path.write_bytes(_glb_with_binary(gltf, blob))
    else:
        path = write(tmp_path, gltf)
    (mesh,) = read_model(path).objects
    expected = QUAD.astype(np.float64)
    expected[0] = moved[0]
    np.testing.assert_array_equal(corner_positions(mesh), expected[QUAD_TRIANGLES])
    untouched = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])[QUAD_TRIANGLES]  # v up
    np.testing.assert_array_equal(mesh.uv[mesh.triangles], untouched)


def test_sparse_accessor_without_base_data_starts_from_zeros(tmp_path):
    """No bufferView: every element is zero but those the sparse block gives (here the
    first three corners, from the quad's own vertex data)."""
    gltf = quad_gltf()
    del gltf["accessors"][0]["bufferView"]
    gltf["accessors"][0]["sparse"] = _sparse(0, count=3)  # indices 0, 1, 2 -> QUAD[0:3]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.vertices, [*QUAD[:3], [0, 0, 0]])


def test_sparse_indices_are_substituted(tmp_path):
    """The triangles' index accessor made sparse: its first element (0) replaced by the
    first element of a view holding 3, so the first triangle becomes (3, 1, 2)."""
    gltf = quad_gltf(indices=np.array([0, 1, 2, 0, 2, 3, 3], dtype="<u2"))
    gltf["accessors"][2]["count"] = 6
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": gltf["bufferViews"][2]["byteOffset"]
                                + 12, "byteLength": 2})
    gltf["accessors"][2]["sparse"] = _sparse(3)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.triangles, [[3, 1, 2], [0, 2, 3]])


@pytest.mark.parametrize(
    ("sparse", "message"),
    [
        ({"count": 1, "indices": {"bufferView": 2, "componentType": 5126},
          "values": {"bufferView": 0}}, "sparse indices must be unsigned"),
        ({"count": 0, "indices": {"bufferView": 2, "componentType": 5123},
          "values": {"bufferView": 0}}, "count from 1 to the accessor's count"),
        ({"count": 5, "indices": {"bufferView": 2, "componentType": 5123},
          "values": {"bufferView": 0}}, "count from 1 to the accessor's count"),
        ({"count": 1, "indices": {"bufferView": 9, "componentType": 5123},
          "values": {"bufferView": 0}}, "names a missing bufferView"),
        ({"count": 1, "indices": {"bufferView": 2, "componentType": 5123, "byteOffset": 14},
          "values": {"bufferView": 0}}, "claims more elements than bufferView 2"),
        ({"count": 1, "indices": {"bufferView": 2, "componentType": 5123, "byteOffset": 12},
          "values": {"bufferView": 0}}, "substitutes element 4, past the accessor's 4"),
        ({"count": 1, "values": {"bufferView": 0}}, "needs indices, values"),
        ("dense", "needs indices, values"),
    ],
)
def test_bad_sparse_blocks_are_refused(tmp_path, sparse, message):
    """The sparse blocks take their indices from the quad's index view, which holds 0, 1, 2,
    0, 2, 3 and, here, a 4 after them (at byte 12): past the four vertices."""
    gltf = quad_gltf(indices=np.array([0, 1, 2, 0, 2, 3, 4], dtype="<u2"))
    gltf["accessors"][2]["count"] = 6
    gltf["accessors"][0]["sparse"] = sparse
    with pytest.raises(ValueError, match=rf"model\.gltf: accessor 0.*{message}"):
        read_model(write(tmp_path, gltf))


def _with_attribute(
    gltf: dict, name: str, values: np.ndarray, component: int, *, normalized: bool = True
) -> dict:
    """Add ``values`` (integers, normalized, unless floats) to the quad's buffer as its
    attribute ``name``."""
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1])
    view = {"buffer": 0, "byteOffset": len(blob), "byteLength": values.nbytes}
    blob += values.tobytes()
    gltf["buffers"][0] = {"byteLength": len(blob), "uri": _data_uri(blob)}
    gltf["bufferViews"].append(view)
    gltf["accessors"].append({"bufferView": len(gltf["bufferViews"]) - 1,
                              "componentType": component, "count": len(values),
                              "type": f"VEC{values.shape[1]}"}
                             | ({"normalized": True} if component != 5126 else {}))
    gltf["meshes"][0]["primitives"][0]["attributes"][name] = len(gltf["accessors"]) - 1
    return gltf


@pytest.mark.parametrize(("dtype", "component"), [("<u1", 5121), ("<u2", 5123)])
def test_normalized_texture_coordinates_are_fractions(tmp_path, dtype, component):
    """glTF allows TEXCOORD_0 as unsigned 8- or 16-bit integers standing for c / 255 or
    c / 65535 (trimesh alone read them as 0..255 or 0..65535)."""
    top = np.iinfo(dtype).max
    gltf = _with_attribute(quad_gltf(), "TEXCOORD_0", (QUAD_UV_GLTF * top).astype(dtype),
                           component)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.uv, [[0, 0], [1, 0], [1, 1], [0, 1]])  # v flipped up


@pytest.mark.parametrize(("dtype", "component"), [("<u1", 5121), ("<u2", 5123)])
def test_normalized_vertex_colours_are_fractions(tmp_path, dtype, component):
    """COLOR_0 as normalized unsigned bytes or shorts: c / 255 or c / 65535 (trimesh alone
    clipped 16-bit colours, reading 32768 as full intensity)."""
    top = np.iinfo(dtype).max
    colors = np.array([[top, 0, 0, top], [0, top // 2, 0, top], [0, 0, top, top],
                       [top, top, top, top]], dtype=dtype)
    gltf = _with_attribute(quad_gltf(), "COLOR_0", colors, component)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.colors, colors / top, atol=1e-7)


def test_sparse_morph_targets_are_left_alone(tmp_path):
    gltf = quad_gltf()
    gltf["accessors"].append({**gltf["accessors"][0], "sparse": {"count": "not read"}})
    gltf["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": 3}]  # not drawn
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.vertices, QUAD)


def test_zero_normals_in_a_file_become_the_faces_normals(tmp_path):
    """Corner 1's normal written as (0, 0, 0), as some exporters write them: it becomes the
    normal of the flat quad's faces, +Z; the others keep the file's (tilted) normals."""
    normals = np.array([[0, 0.6, 0.8], [0, 0, 0], [0, 0.6, 0.8], [0, 0.6, 0.8]], "<f4")
    gltf = _with_attribute(quad_gltf(), "NORMAL", normals, 5126)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.normals, [[0, 0.6, 0.8], [0, 0, 1], [0, 0.6, 0.8],
                                              [0, 0.6, 0.8]], atol=1e-7)


def test_zero_normal_of_a_corner_of_no_area_is_plus_z(tmp_path):
    """Corner 3 moved onto corner 0: the one face it belongs to, (0, 2, 3), has no area, so it
    has no faces' normal to take and gets +Z (it is never seen)."""
    vertices = QUAD.copy()
    vertices[3] = vertices[0]
    normals = np.array([[0, 0.6, 0.8], [0, 0.6, 0.8], [0, 0.6, 0.8], [0, 0, 0]], "<f4")
    gltf = _with_attribute(quad_gltf(vertices=vertices), "NORMAL", normals, 5126)
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_allclose(mesh.normals[3], [0, 0, 1])


@pytest.mark.parametrize("indexed", [True, False])
def test_triangle_fans_are_drawn(tmp_path, indexed):
    """The quad as a fan (mode 6) of corners 0, 1, 2, 3: triangles (0, 1, 2) and (0, 2, 3);
    without indices the corners are the vertices in order (trimesh alone drops fans)."""
    gltf = quad_gltf(indices=np.array([0, 1, 2, 3], "<u2"))
    primitive = gltf["meshes"][0]["primitives"][0]
    primitive["mode"] = 6
    gltf["accessors"][2]["count"] = 4
    if not indexed:
        del primitive["indices"]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.triangles, [[0, 1, 2], [0, 2, 3]])
    np.testing.assert_array_equal(mesh.uv, [[0, 0], [1, 0], [1, 1], [0, 1]])


def test_a_fan_of_two_corners_draws_nothing(tmp_path):
    gltf = quad_gltf(indices=np.array([0, 1], "<u2"))
    gltf["meshes"][0]["primitives"][0]["mode"] = 6
    gltf["accessors"][2]["count"] = 2
    with pytest.raises(ValueError, match=r"model\.gltf: the file has no triangle meshes"):
        read_model(write(tmp_path, gltf))


def test_a_file_of_nodes_alone_has_no_triangle_meshes(tmp_path):
    """A scene of empty nodes, as Blender exports empties (trimesh's ``empty_nodes.glb``):
    said so, not as trimesh's KeyError for the accessors such a file does not need."""
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [1]}],
            "nodes": [{"name": "child", "translation": [1, 0, 0]},
                      {"name": "parent", "children": [0]}]}
    path = tmp_path / "model.gltf"
    path.write_text(json.dumps(gltf))
    with pytest.raises(ValueError, match=r"model\.gltf: the file has no triangle meshes$"):
        read_model(path)


def test_indices_out_of_range_are_refused(tmp_path):
    indices = np.array([0, 1, 2, 0, 2, 99], dtype="<u2")
    with pytest.raises(ValueError, match=r"model\.gltf"):
        read_model(write(tmp_path, quad_gltf(indices=indices)))


def test_nan_positions_are_refused(tmp_path):
    vertices = QUAD.copy()
    vertices[2, 0] = np.nan
    with pytest.raises(ValueError, match=r"model\.gltf.*finite"):
        read_model(write(tmp_path, quad_gltf(vertices=vertices)))


def test_truncated_glb_is_refused(tmp_path):
    data = (DATA / "Duck.glb").read_bytes()
    for cut in (10, 100, len(data) // 2, len(data) - 1):
        path = tmp_path / "cut.glb"
        path.write_bytes(data[:cut])
        with pytest.raises(ValueError, match=r"cut\.glb"):
            read_model(path)


@pytest.mark.parametrize("version", ["1.0", "1.1", 1])
def test_gltf_1_json_is_refused_by_its_version(tmp_path, version):
    refused(tmp_path, quad_gltf(asset={"version": version}), r"version.*only glTF 2\.0")


def test_glb_of_version_1_is_refused(tmp_path):
    data = bytearray(glb_bytes(quad_gltf()))
    data[4:8] = struct.pack("<I", 1)
    path = tmp_path / "old.glb"
    path.write_bytes(bytes(data))
    with pytest.raises(ValueError, match=r"old\.glb: a GLB of version 1; only glTF 2\.0"):
        read_model(path)


def test_buffer_files_are_read_when_a_view_reads_them(tmp_path):
    gltf = quad_gltf()
    blob = base64.b64decode(gltf["buffers"][0]["uri"].partition(",")[2])
    (tmp_path / "quad.bin").write_bytes(blob)
    gltf["buffers"] = [{"byteLength": len(blob), "uri": "quad.bin"},
                       {"byteLength": 4, "uri": "unused.bin"}]  # no bufferView reads it
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.vertices, QUAD)
    (tmp_path / "quad.bin").unlink()
    refused(tmp_path, gltf, r"buffer 0's file 'quad\.bin' was not found")


def test_corrupt_jpeg_texture_is_refused_when_first_used(tmp_path):
    for name in ("fuze.obj", "fuze.obj.mtl"):
        shutil.copy(DATA / name, tmp_path / name)
    (tmp_path / "fuze uv.jpg").write_bytes((DATA / "fuze uv.jpg").read_bytes()[:2000])
    scene = pp.load_scene(tmp_path / "fuze.obj")  # pictures are decoded lazily, as trimesh does
    scene = dataclasses.replace(scene, camera=dataclasses.replace(scene.camera, width=32,
                                                                   height=24))
    with pytest.raises(ValueError, match=r"fuze\.obj texture: not a readable image"):
        pp.render(scene)


def test_missing_gltf_texture_warns_and_keeps_the_colour(tmp_path):
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["images"][0]["uri"] = "missing.png"
    with pytest.warns(UserWarning, match=r"missing.png"):
        (mesh,) = read_model(write(tmp_path, gltf)).objects
    assert mesh.material.texture is None


def _png_header_only(width: int, height: int) -> bytes:
    def chunk(kind: bytes, body: bytes) -> bytes:
        crc = struct.pack(">I", zlib.crc32(kind + body))
        return struct.pack(">I", len(body)) + kind + body + crc

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IEND", b"")


def test_huge_texture_is_refused_without_decoding(tmp_path):
    gltf = quad_gltf(image=_png_header_only(20000, 20000))
    with pytest.raises(ValueError, match=r"model\.gltf.*texture"):
        read_model(write(tmp_path, gltf))


def test_wrong_arguments(tmp_path):
    with pytest.raises(TypeError, match=r"path"):
        read_model(3)
    with pytest.raises(FileNotFoundError):
        read_model(tmp_path / "none.glb")
    (tmp_path / "a.fbx").write_text("x")
    with pytest.raises(ValueError, match=r"a\.fbx"):
        read_model(tmp_path / "a.fbx")
    with pytest.raises(TypeError, match=r"material"):
        read_model_objects(DATA / "Duck.glb", material="red")


def test_nothing_passed_is_modified(tmp_path):
    path = write(tmp_path, quad_gltf())
    before = path.read_bytes()
    read_model(str(path))
    assert path.read_bytes() == before


# --- fuzzing -------------------------------------------------------------------------------------

SMALL_GLB = glb_bytes(quad_gltf(image=_png(PICTURE)))
JSON_END = 20 + struct.unpack("<I", SMALL_GLB[12:16])[0]


def _edited_json(data: dict, key_index: int, value) -> dict:
    """Replace one value somewhere in the glTF JSON (chosen by ``key_index``)."""
    slots = []

    def walk(node):
        items = node.items() if isinstance(node, dict) else enumerate(node)
        for key, child in items:
            slots.append((node, key))
            if isinstance(child, dict | list):
                walk(child)

    walk(data)
    node, key = slots[key_index % len(slots)]
    node[key] = value
    return data


def _only_named_errors(path: Path) -> None:
    """Load ``path`` and decode its textures: it works, or raises ValueError/TypeError naming it.

    Warnings are allowed.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            for obj in read_model(path).objects:
                for texture in (obj.material.texture, obj.material.emission_texture):
                    if texture is not None:
                        assert texture.levels  # pictures decode at first use: errors come here
        except (ValueError, TypeError) as exc:
            assert path.name in str(exc), f"{type(exc).__name__} without the file's name: {exc}"


def edited_loads_or_names_itself(tmp_path: Path, gltf: dict, key_index: int, value) -> None:
    """``gltf`` with one JSON value replaced (:func:`_edited_json`): it loads, or the error
    names the file."""
    path = tmp_path / "fuzz.gltf"
    path.write_text(json.dumps(_edited_json(gltf, key_index, value)))
    _only_named_errors(path)


def refused(tmp_path: Path, gltf: dict, message: str) -> None:
    """Reading ``gltf`` raises a ValueError naming the file, then ``message`` (a pattern)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError, match=rf"model\.gltf.*{message}"):
            read_model(write(tmp_path, gltf))


FUZZ = settings(max_examples=50, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture])


@FUZZ
@given(cut=st.integers(0, len(SMALL_GLB)), flips=st.lists(st.integers(0, len(SMALL_GLB) * 8 - 1),
                                                          max_size=4))
def test_fuzz_truncated_and_bit_flipped_glb(tmp_path, cut, flips):
    data = bytearray(SMALL_GLB)
    for bit in flips:
        data[bit // 8] ^= 1 << (bit % 8)
    path = tmp_path / "fuzz.glb"
    path.write_bytes(bytes(data[: max(cut, 0)] if cut < len(data) else data))
    _only_named_errors(path)


JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**40), 2**40) | st.floats(allow_nan=True)
    | st.text(max_size=8),
    lambda children: st.lists(children, max_size=3) | st.dictionaries(st.text(max_size=5),
                                                                       children, max_size=3),
    max_leaves=6,
)


def _decoded_quad() -> dict:
    """The textured quad with accessors pixelpath decodes before trimesh reads them: positions
    from a sparse accessor (vertex 0 from its own data), 16-bit normalized colours, normals
    as normalized bytes (KHR_mesh_quantization's), the texture reading uv set 1, and the same
    corners drawn a second time as a triangle fan."""
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["accessors"][0]["sparse"] = _sparse(0)
    primitives = gltf["meshes"][0]["primitives"]
    primitives[0]["attributes"]["TEXCOORD_1"] = 1
    primitives.append({**primitives[0], "mode": 6})
    gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1
    gltf = _with_attribute(gltf, "NORMAL", np.tile(np.array([0, 0, 127], "<i1"), (4, 1)), 5120)
    return _with_attribute(gltf, "COLOR_0", np.full((4, 4), 40000, dtype="<u2"), 5123)


def _glowing_quad() -> dict:
    """The textured quad whose picture is its emissiveTexture too, through a transform."""
    gltf = quad_gltf(image=_png(PICTURE), extensionsUsed=["KHR_texture_transform"])
    gltf["materials"][0].update(emissiveFactor=[1.0, 0.5, 0.0], emissiveTexture={
        "index": 0, "texCoord": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}})
    return gltf


@FUZZ
@given(key_index=st.integers(0, 500), value=JSON_VALUES,
       base=st.sampled_from(["textured", "decoded", "glowing"]))
def test_fuzz_edited_gltf_json(tmp_path, key_index, value, base):
    gltf = {"textured": lambda: quad_gltf(image=_png(PICTURE)), "decoded": _decoded_quad,
            "glowing": _glowing_quad}[base]()
    edited_loads_or_names_itself(tmp_path, gltf, key_index, value)


TOML_VALUES = st.recursive(
    st.booleans() | st.integers(-5, 5) | st.floats(-10, 10) | st.sampled_from(
        ["mesh", "sphere", "box", "plane", "point", "red", "", "Duck.glb"]),
    lambda children: st.lists(children, max_size=3)
    | st.dictionaries(st.sampled_from(["type", "a", "radius"]), children, max_size=2),
    max_leaves=5,
)
OBJECT_KEYS = st.sampled_from(["type", "center", "radius", "path", "material", "name", "minimum",
                               "maximum", "point", "normal", "transform", "faces", "vertices"])


def _toml(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml(item) for item in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{key} = {_toml(item)}" for key, item in value.items()) + "}"
    return repr(value)


@FUZZ
@given(objects=st.lists(st.dictionaries(OBJECT_KEYS, TOML_VALUES, max_size=4), max_size=3),
       lights=st.lists(st.dictionaries(st.sampled_from(["type", "position", "direction"]),
                                       TOML_VALUES, max_size=3), max_size=2))
def test_fuzz_scene_files(tmp_path, objects, lights):
    text = "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n"
    for name, tables in (("objects", objects), ("lights", lights)):
        for table in tables:
            text += f"[[{name}]]\n" + "".join(f"{k} = {_toml(v)}\n" for k, v in table.items())
    path = tmp_path / "fuzz.toml"
    path.write_text(text)
    try:
        pp.load_scene(path)
    except (ValueError, TypeError, FileNotFoundError) as exc:
        assert "fuzz.toml" in str(exc), f"{type(exc).__name__} without the file's name: {exc}"


# --- rendering and the command line --------------------------------------------------------------


def test_render_a_loaded_model_draws_it():
    scene = read_model(DATA / "BoxVertexColors.gltf", size=(64, 48))
    image = pp.render(scene)
    drawn = np.asarray(image.object_id) >= 0
    assert 0.1 < drawn.mean() < 0.95
    pixels = np.asarray(image)[drawn]
    assert pixels.max() > 0.2  # lit by the default rig
    assert np.ptp(pixels.mean(axis=1)) > 0.05  # coloured faces, not one flat colour


def test_render_keeps_the_texture_orientation(tmp_path):
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["materials"][0]["doubleSided"] = True
    scene = read_model(write(tmp_path, gltf), size=(40, 40))
    camera = pp.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0), fov=20, width=40, height=40)
    scene = pp.Scene(camera, scene.objects, [], ambient=1.0, encoding="srgb")
    picture = np.asarray(pp.render(scene, shading="flat"))
    # the quad fills the middle of the view: sample each quarter's centre
    bottom_left, top_right = picture[27, 13], picture[13, 27]
    assert bottom_left[2] > 0.5 > bottom_left[0]  # blue
    assert top_right[1] > 0.5 > top_right[0]  # green


def _transformed_quad(tmp_path, **transform) -> Path:
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["materials"][0]["doubleSided"] = True
    texture = gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]
    texture["extensions"] = {"KHR_texture_transform": transform}
    gltf["extensionsUsed"] = gltf["extensionsRequired"] = ["KHR_texture_transform"]
    return write(tmp_path, gltf)


def test_khr_texture_transform_moves_the_texture_coordinates(tmp_path):
    # glTF's uv (v down) of the corners (0,0,0), (1,0,0), (1,1,0), (0,1,0): (0,1), (1,1),
    # (1,0), (0,0). Offset (0.5, 0) and scale (0.5, 1): u -> u/2 + 1/2, v kept; then v up
    path = _transformed_quad(tmp_path, offset=[0.5, 0], scale=[0.5, 1])
    (mesh,) = read_model(path).objects
    np.testing.assert_allclose(mesh.uv, [[0.5, 0], [1, 0], [1, 1], [0.5, 1]])
    # a quarter turn: (u, v) -> (cos u + sin v, -sin u + cos v) = (v, -u)
    (mesh,) = read_model(_transformed_quad(tmp_path, rotation=math.pi / 2)).objects
    np.testing.assert_allclose(mesh.uv, [[1, 1], [1, 2], [0, 2], [0, 1]], atol=1e-12)
    with pytest.raises(ValueError, match=r"model\.gltf: part 'quad': KHR_texture_transform sc"):
        read_model(_transformed_quad(tmp_path, scale=[1, "big"]))


def _two_uv_sets(container: str = "gltf") -> dict:
    """The textured quad whose set 0 is squeezed to a point and whose set 1 is the true uv."""
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 1  # the true uv
    return _with_attribute(gltf, "TEXCOORD_0", np.full((4, 2), 0.25, "<f4"), 5126)


@pytest.mark.parametrize("where", ["texCoord", "transform"])
def test_the_base_colour_reads_the_set_its_material_names(tmp_path, where):
    """``texCoord: 1`` (or KHR_texture_transform's own texCoord, which overrides it): the
    part's uv are set 1's, as the Khronos MultiUVTest model needs (trimesh reads set 0)."""
    gltf = _two_uv_sets()
    ref = gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]
    if where == "texCoord":
        ref["texCoord"] = 1
    else:
        ref.update(texCoord=0, extensions={"KHR_texture_transform": {"texCoord": 1}})
        gltf["extensionsUsed"] = ["KHR_texture_transform"]
    (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.uv, [[0, 0], [1, 0], [1, 1], [0, 1]])


def test_a_base_colour_set_in_a_glb_is_read_too(tmp_path):
    gltf = _two_uv_sets()
    gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",")[1])
    path = tmp_path / "model.glb"
    path.write_bytes(_glb_with_binary(gltf, blob))
    (mesh,) = read_model(path).objects
    np.testing.assert_array_equal(mesh.uv, [[0, 0], [1, 0], [1, 1], [0, 1]])


def test_a_set_the_mesh_lacks_is_warned_of_and_set_0_used(tmp_path):
    gltf = quad_gltf(image=_png(PICTURE))
    gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 2
    with pytest.warns(UserWarning, match=r"model\.gltf: mesh 0: material 'm'.*TEXCOORD_2.*set 0"):
        (mesh,) = read_model(write(tmp_path, gltf)).objects
    np.testing.assert_array_equal(mesh.uv, [[0, 0], [1, 0], [1, 1], [0, 1]])
    assert mesh.material.texture is not None

def test_khr_texture_transform_shows_in_the_picture(tmp_path):
    # the picture's right column (green above white) stretched over the whole quad
    scene = read_model(_transformed_quad(tmp_path, offset=[0.5, 0], scale=[0.5, 1]))
    camera = pp.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0), fov=20, width=40, height=40)
    scene = pp.Scene(camera, scene.objects, [], ambient=1.0, encoding="srgb")
    picture = np.asarray(pp.render(scene, shading="flat"))
    bottom_left, top_left = picture[27, 13], picture[13, 13]
    assert min(bottom_left) > 0.5  # white, where the untransformed texture shows blue
    assert top_left[1] > 0.5 > top_left[0]  # green, where it shows red

def test_cli_render_writes_a_png_of_a_model(tmp_path):
    from pixelpath.cli import main
    from pixelpath.io import read_image

    out = tmp_path / "duck.png"
    assert main(["render", str(DATA / "Duck.glb"), "-o", str(out), "--size", "48x32"]) == 0
    image = read_image(out)
    assert image.shape == (32, 48, 3)
    assert image.max() > 0


def test_cli_info_reads_a_model(capsys):
    from pixelpath.cli import main

    assert main(["info", str(DATA / "fuze.obj"), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert len(summary["objects"]) == 1


def test_orthographic_file_camera(tmp_path):
    gltf = quad_gltf()
    gltf["cameras"] = [{"type": "orthographic",
                        "orthographic": {"xmag": 2, "ymag": 1.5, "znear": 0.1, "zfar": 50}}]
    gltf["nodes"].append({"camera": 0, "translation": [0.5, 0.5, 5]})
    gltf["scenes"][0]["nodes"] = [0, 1]
    camera = read_model(write(tmp_path, gltf)).camera
    assert camera.projection == "orthographic" and camera.view_height == pytest.approx(3.0)
    # the view's width over its height is xmag / ymag, as for a perspective camera's aspect
    assert (camera.width, camera.height) == (800, 600)
    gltf["cameras"][0]["orthographic"]["xmag"] = 1.5
    assert read_model(write(tmp_path, gltf)).camera.width == 600
    np.testing.assert_allclose(camera.eye, [0.5, 0.5, 5])
    np.testing.assert_allclose(camera.target[:2], [0.5, 0.5])  # looking down -Z
    assert (camera.near, camera.far) == (pytest.approx(0.1), pytest.approx(50))


def test_glTF_materials_are_found_by_name_in_each_file_read():
    from pixelpath.io.models import _gltf_material_index, _gltf_materials_named

    first = {"materials": [{"name": "a"}, {"name": "b"}, {"name": "a"}, 7, {"name": [1]}, {}]}
    second = {"materials": [{"name": "b"}, {"name": "a"}]}
    assert _gltf_materials_named(first, "a") == (0, 2)
    assert _gltf_material_index(first, "a") is None  # ambiguous
    assert _gltf_material_index(first, "b") == 1
    assert _gltf_material_index(first, None) == 5  # the one material without a name
    assert _gltf_materials_named(first, [1]) == ()  # a JSON list names nothing
    assert _gltf_material_index(second, "a") == 1  # another file: its own names
    assert _gltf_material_index(first, "b") == 1 and _gltf_material_index(None, "b") is None
