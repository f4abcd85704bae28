"""Mesh colors/uv and Material texture options: storage, validation, transforms, equality."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.scene import Material, Mesh, Texture

QUAD = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
FACES = [[0, 1, 2, 3]]
UV = [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_colors_are_stored_as_rgba():
    mesh = Mesh(QUAD, FACES, colors=[[1, 0, 0], [0, 1, 0], [0, 0, 1], [0.5, 0.5, 0.5]])
    assert mesh.colors.shape == (4, 4) and mesh.colors.dtype == np.float64
    assert mesh.colors[:, 3].tolist() == [1, 1, 1, 1]
    assert mesh.colors[3].tolist() == [0.5, 0.5, 0.5, 1.0]
    with_alpha = Mesh(QUAD, FACES, colors=[[1, 0, 0, 0.25]] * 4)
    assert with_alpha.colors[0].tolist() == [1, 0, 0, 0.25]
    eight = Mesh(QUAD, FACES, colors=np.array([[255, 0, 51, 102]] * 4, dtype=np.uint8))
    assert eight.colors[0] == pytest.approx([1.0, 0.0, 0.2, 0.4])
    assert not mesh.colors.flags.writeable and Mesh(QUAD, FACES).colors is None


def test_uv_is_stored():
    mesh = Mesh(QUAD, FACES, uv=UV)
    assert mesh.uv.tolist() == UV and mesh.uv.dtype == np.float64
    assert not mesh.uv.flags.writeable and Mesh(QUAD, FACES).uv is None
    # Texture coordinates outside [0, 1] are allowed (wrap modes handle them).
    assert Mesh(QUAD, FACES, uv=np.array(UV) * 3 - 1).uv.min() == -1


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"colors": [[1, 0, 0]] * 3}, "colors"),
        ({"colors": [[1, 0]] * 4}, "colors"),
        ({"colors": [[1, 0, 0, 1, 1]] * 4}, "colors"),
        ({"colors": [[1.5, 0, 0]] * 4}, "colors"),
        ({"colors": [[-0.1, 0, 0]] * 4}, "colors"),
        ({"colors": [[np.nan, 0, 0]] * 4}, "colors"),
        ({"colors": [1, 0, 0]}, "colors"),
        ({"uv": [[0, 0]] * 3}, "uv"),
        ({"uv": [[0, 0, 0]] * 4}, "uv"),
        ({"uv": [[np.nan, 0]] * 4}, "uv"),
        ({"uv": [[np.inf, 0]] * 4}, "uv"),
        ({"uv": [0, 0]}, "uv"),
    ],
)
def test_bad_colors_and_uv(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Mesh(QUAD, FACES, **kwargs)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"texture_filter": "cubic"}, ValueError, "texture_filter"),
        ({"texture_filter": None}, ValueError, "texture_filter"),
        ({"texture_filter": "Nearest"}, ValueError, "texture_filter"),
        ({"texture_wrap": "border"}, ValueError, "texture_wrap"),
        ({"texture_wrap": 0}, ValueError, "texture_wrap"),
        ({"double_sided": 1}, TypeError, "double_sided"),
        ({"double_sided": "yes"}, TypeError, "double_sided"),
        ({"double_sided": None}, TypeError, "double_sided"),
        ({"texture": np.zeros((2, 2))}, ValueError, "shape"),
    ],
)
def test_bad_material_texture_options(kwargs, error, match):
    with pytest.raises(error, match=match):
        Material(**kwargs)


def test_material_texture_options():
    material = Material()
    assert material.texture is None and material.texture_filter == "trilinear"
    assert material.texture_wrap == "repeat" and material.double_sided is False
    picture = np.full((2, 2, 3), 0.5)
    textured = Material(texture=picture, texture_filter="nearest", texture_wrap="mirror",
                        double_sided=np.bool_(True))
    assert isinstance(textured.texture, Texture) and textured.double_sided is True
    assert textured.texture == Texture(picture)
    # Equality includes the texture and its options.
    assert Material(texture=picture) == Material(texture=Texture(picture))
    assert Material(texture=picture) != Material(texture=picture * 0.5)
    assert Material(texture=picture) != Material()
    assert Material(texture=picture) != Material(texture=picture, texture_filter="nearest")
    assert Material(texture_wrap="clamp") != Material()
    assert Material(double_sided=True) != Material()


def test_transformed_keeps_colors_and_uv():
    colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]
    mesh = Mesh(QUAD, FACES, colors=colors, uv=UV, name="q")
    moved = mesh.transformed(pp.scene.transform_matrix(translate=(1, 2, 3), rotate=(10, 20, 30)))
    assert np.array_equal(moved.colors, mesh.colors) and np.array_equal(moved.uv, mesh.uv)
    mirrored = mesh.transformed(np.diag([-1.0, 1, 1, 1]))  # reverses windings
    assert np.array_equal(mirrored.colors, mesh.colors) and np.array_equal(mirrored.uv, mesh.uv)


def test_equality_includes_colors_and_uv():
    base = Mesh(QUAD, FACES, colors=[[1, 0, 0]] * 4, uv=UV)
    assert base == Mesh(QUAD, FACES, colors=[[1, 0, 0, 1]] * 4, uv=UV)
    assert base != Mesh(QUAD, FACES, colors=[[1, 0, 0]] * 4)
    assert base != Mesh(QUAD, FACES, uv=UV)
    assert base != Mesh(QUAD, FACES, colors=[[0, 1, 0]] * 4, uv=UV)
    assert base != Mesh(QUAD, FACES, colors=[[1, 0, 0]] * 4, uv=np.array(UV) * 2)
