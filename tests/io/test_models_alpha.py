"""glTF alphaMode: OPAQUE ignores alpha, MASK cuts holes at alphaCutoff, BLEND is drawn as MASK.

The glTF files are written here by hand (a quad with a 2 x 2 RGBA texture), so the expected
values do not come from trimesh.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_models import _png, quad_gltf, write

import pixelpath as pp
from pixelpath.io.models import read_model

# Rows top to bottom: opaque red, transparent; transparent, opaque green. The quad of
# quad_gltf spans [0, 1]^2 at z = 0 with the picture upright (v up), so its top-left quarter
# shows the top-left texel.
PICTURE = np.array(
    [[[255, 0, 0, 255], [255, 255, 255, 0]], [[255, 255, 255, 0], [0, 255, 0, 255]]], np.uint8
)
# Pixels of the 32 x 32 camera below at the centre of each quarter of the quad.
TOP_LEFT, TOP_RIGHT, BOTTOM_LEFT, BOTTOM_RIGHT = (12, 12), (12, 19), (19, 12), (19, 19)


def holed_gltf(mode: str | None, cutoff: float | None = None, factor=(1, 1, 1, 1)) -> dict:
    gltf = quad_gltf(image=_png(PICTURE))
    material = gltf["materials"][0]
    material["pbrMetallicRoughness"]["baseColorFactor"] = list(factor)
    if mode is not None:
        material["alphaMode"] = mode
    if cutoff is not None:
        material["alphaCutoff"] = cutoff
    return gltf


def seen(objects, method="zbuffer") -> np.ndarray:
    """The object ids of the model's parts in front of a wall (the last object), head on."""
    wall = pp.Mesh([[-2, -2, -1], [3, -2, -1], [3, 3, -1], [-2, 3, -1]], [[0, 1, 2, 3]])
    camera = pp.Camera(eye=(0.5, 0.5, 2), target=(0.5, 0.5, 0), fov=60, width=32, height=32)
    scene = pp.Scene(camera, [*objects, wall], [pp.PointLight((0.5, 0.5, 3))])
    return pp.render(scene, method).object_id


def test_opaque_ignores_the_texture_alpha(tmp_path):
    (mesh,) = read_model(write(tmp_path, holed_gltf(None))).objects
    assert mesh.material.alpha_cutoff is None
    assert mesh.material.texture.lowest_alpha == 1.0  # the alpha channel was dropped
    ids = seen([mesh])
    assert all(ids[p] == 0 for p in (TOP_LEFT, TOP_RIGHT, BOTTOM_LEFT, BOTTOM_RIGHT))


@pytest.mark.parametrize("method", ["zbuffer", "scanline", "painter", "bsp", "warnock", "octree",
                                    "raytrace"])
def test_mask_cuts_the_transparent_texels(tmp_path, method):
    (mesh,) = read_model(write(tmp_path, holed_gltf("MASK", 0.4))).objects
    assert mesh.material.alpha_cutoff == pytest.approx(0.4)
    assert mesh.material.alpha == 1.0 and mesh.material.transparency == 0.0
    ids = seen([mesh], method)
    assert (ids[TOP_LEFT], ids[TOP_RIGHT], ids[BOTTOM_LEFT], ids[BOTTOM_RIGHT]) == (0, 1, 1, 0)


def test_mask_cutoff_defaults_to_one_half(tmp_path):
    (mesh,) = read_model(write(tmp_path, holed_gltf("MASK"))).objects
    assert mesh.material.alpha_cutoff == 0.5


def test_mask_multiplies_the_base_colour_alpha(tmp_path):
    # baseColorFactor's alpha 0.3 x texel alpha 1 = 0.3 < 0.5: every texel is cut away
    (mesh,) = read_model(write(tmp_path, holed_gltf("MASK", 0.5, (1, 1, 1, 0.3)))).objects
    assert mesh.material.alpha == pytest.approx(0.3, abs=1 / 255)
    for method in ("zbuffer", "raytrace"):
        assert not (seen([mesh], method) == 0).any()
    (kept,) = read_model(write(tmp_path, holed_gltf("MASK", 0.5, (1, 1, 1, 0.6)), "b.gltf")).objects
    assert seen([kept])[TOP_LEFT] == 0 and seen([kept])[TOP_RIGHT] == 1


def test_blend_is_drawn_as_mask_at_one_half(tmp_path):
    (mesh,) = read_model(write(tmp_path, holed_gltf("BLEND", factor=(1, 1, 1, 0.75)))).objects
    material = mesh.material
    assert material.alpha_cutoff == 0.5 and material.alpha == 1.0
    assert material.transparency == pytest.approx(0.25, abs=1 / 255)  # the ray tracer's
    ids = seen([mesh])
    assert (ids[TOP_LEFT], ids[TOP_RIGHT], ids[BOTTOM_LEFT], ids[BOTTOM_RIGHT]) == (0, 1, 1, 0)


def test_a_binary_glb_with_mask_loads_and_renders(tmp_path):
    from test_models import glb_bytes

    path = tmp_path / "leaf.glb"
    path.write_bytes(glb_bytes(holed_gltf("MASK", 0.5)))
    scene = pp.load_scene(path)
    (mesh,) = scene.objects
    assert mesh.material.alpha_cutoff == 0.5
    ids = seen([mesh], "raytrace")
    assert (ids[TOP_LEFT], ids[TOP_RIGHT]) == (0, 1)


@pytest.mark.parametrize("cutoff", [-0.5])
def test_a_negative_cutoff_is_refused_naming_the_file(tmp_path, cutoff):
    path = write(tmp_path, holed_gltf("MASK", cutoff))
    with pytest.raises(ValueError, match=r"model\.gltf.*alphaCutoff"):
        read_model(path)
