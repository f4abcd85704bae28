"""Material.alpha and alpha_cutoff: checks, scene files, and what the kernels are handed."""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from pixelpath.scene import Material, Mesh, Scene, Sphere, Texture, load_scene
from pixelpath.scene.texture import surface_tables

SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
SQUARE_UV = [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_defaults_are_opaque():
    material = Material()
    assert material.alpha == 1.0 and material.alpha_cutoff is None
    assert Material(alpha_cutoff=1).alpha_cutoff == 1.0
    assert isinstance(Material(alpha_cutoff=1).alpha_cutoff, float)
    assert Material(alpha_cutoff=0.5) != Material() and Material(alpha=0.5) != Material()


@pytest.mark.parametrize(
    ("options", "error", "match"),
    [
        ({"alpha": 1.5}, ValueError, "alpha must lie in"),
        ({"alpha": -0.1}, ValueError, "alpha must be at least"),
        ({"alpha_cutoff": -0.1}, ValueError, "alpha_cutoff must be at least 0"),
        ({"alpha_cutoff": math.nan}, ValueError, "alpha_cutoff must be finite"),
        ({"alpha_cutoff": "0.5"}, TypeError, "alpha_cutoff must be a real number"),
        ({"alpha_cutoff": True}, TypeError, "alpha_cutoff must be a real number"),
    ],
)
def test_bad_values(options, error, match):
    with pytest.raises(error, match=match):
        Material(**options)


def quad(material, colors=None, uv=SQUARE_UV):
    return Mesh(SQUARE, [[0, 1, 2, 3]], material, colors=colors, uv=uv)


def test_tables_keep_a_cutoff_only_where_the_alpha_can_fall_below_it():
    holes = np.ones((2, 2, 4))
    holes[0, 0, 3] = 0.2
    veiled = np.ones((2, 2, 4))
    veiled[..., 3] = 0.8
    objects = [
        quad(Material()),  # opaque
        quad(Material(texture=holes, alpha_cutoff=0.5)),  # a texel at 0.2: tested
        quad(Material(texture=veiled, alpha_cutoff=0.5)),  # 0.8 everywhere: never cut
        quad(Material(texture=veiled, alpha=0.5, alpha_cutoff=0.5)),  # 0.4: tested
        quad(Material(texture=holes, alpha_cutoff=0.5), uv=None),  # no uv: no texture
        quad(Material(alpha_cutoff=0.5), colors=[[1, 1, 1, 0.4]] * 4),  # vertex alpha
        Sphere((0, 0, 0), 1, Material(alpha=0.25, alpha_cutoff=0.5)),  # cut everywhere
        quad(Material(texture=holes, alpha_cutoff=0.0)),  # nothing is below 0
    ]
    alpha = surface_tables(objects).alpha
    np.testing.assert_allclose(alpha[:, 0], [1, 1, 1, 0.5, 1, 1, 0.25, 1])
    np.testing.assert_allclose(alpha[:, 1], [0, 0.5, 0, 0.5, 0, 0.5, 0.5, 0])


def test_lowest_alpha_of_a_texture():
    assert Texture(np.ones((3, 3, 3))).lowest_alpha == 1.0
    picture = np.full((3, 3, 4), 255, np.uint8)
    picture[1, 2, 3] = 0
    assert Texture(picture).lowest_alpha == 0.0


SCENE = textwrap.dedent(
    """\
    [camera]
    eye = [0, 0, 5]
    target = [0, 0, 0]

    [materials.leaf]
    color = [0.2, 0.7, 0.1]
    alpha = 0.8
    alpha_cutoff = 0.5

    [[objects]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 1
    material = "leaf"

    [[objects]]
    type = "sphere"
    center = [3, 0, 0]
    radius = 1
    material = { alpha_cutoff = 0.25 }
    """
)


def test_scene_files_read_and_write_the_alpha_test(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    scene = load_scene(path)
    leaf, inline = (obj.material for obj in scene.objects)
    assert (leaf.alpha, leaf.alpha_cutoff) == (0.8, 0.5)
    assert (inline.alpha, inline.alpha_cutoff) == (1.0, 0.25)
    data = scene.to_dict()
    written = {name: m for name, m in data["materials"].items()}
    assert written["leaf"]["alpha_cutoff"] == 0.5 and written["leaf"]["alpha"] == 0.8
    assert Scene.from_dict(data) == scene
    opaque = Scene(scene.camera, [Sphere((0, 0, 0), 1, Material(name="plain"))]).to_dict()
    assert "alpha_cutoff" not in opaque["materials"]["plain"]  # None is not written
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    from pixelpath.scene.schema import scene_json_schema

    jsonschema.validate(tomllib.loads(SCENE), scene_json_schema())
    jsonschema.validate(data, scene_json_schema())


def test_scene_files_name_a_bad_cutoff(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE.replace("alpha_cutoff = 0.5", "alpha_cutoff = -1"))
    with pytest.raises(ValueError, match=r"scene\.toml.*alpha_cutoff must be at least 0"):
        load_scene(path)
    path.write_text(SCENE.replace("alpha_cutoff = 0.5", 'alpha_cutoff = "half"'))
    with pytest.raises(ValueError, match=r"scene\.toml.*alpha_cutoff.*a number"):
        load_scene(path)
