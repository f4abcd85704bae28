"""The texturing figure: affine against perspective-correct texture coordinates."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

import pixelpath as pp
from pixelpath.figures._canvas import save
from pixelpath.figures.texturing import (
    affine_rgb,
    checkerboard,
    perspective_figure,
    receding_floor,
)


@pytest.fixture(scope="module")
def halves():
    scene = receding_floor(120, 90)
    correct = pp.render(scene, shading="flat")
    affine = pp.Image(affine_rgb(scene), encoding=correct.encoding)
    return correct, affine


def test_the_figure_has_two_captioned_halves():
    figure = perspective_figure(width=120, height=90)
    assert figure.mode == "RGB"
    assert figure.height == 90 + 22 + 16  # the picture, the captions, the margins
    assert figure.width >= 2 * 120


def test_both_halves_cover_the_same_pixels(halves):
    correct, affine = halves
    drawn = correct.object_id >= 0
    assert drawn.sum() > 0.2 * drawn.size
    assert np.all(np.asarray(affine)[~drawn] == 1.0)  # the white background around both
    assert np.all(np.asarray(correct)[~drawn] == 1.0)


def _differing(correct, affine, rows):
    a, b = correct.to_uint8()[rows], affine.to_uint8()[rows]
    drawn = correct.object_id[rows] >= 0
    return np.any(a != b, axis=-1)[drawn].mean()


def test_the_halves_agree_near_and_differ_far(halves):
    correct, affine = halves
    rows = np.nonzero((correct.object_id >= 0).any(axis=1))[0]
    nearest, far = rows[-1], rows[: len(rows) // 3]
    # On the nearest row both interpolations run between the same two vertices at one depth:
    # only a few pixels next to a square's edge fall on the other side of it.
    assert _differing(correct, affine, [nearest]) < 0.15
    assert _differing(correct, affine, far) > 0.3


def test_the_halves_show_the_same_texels():
    """Only the interpolation differs: both halves hold the checkerboard's two colours."""
    scene = receding_floor(80, 60)
    texels = {tuple(c) for c in scene.objects[0].material.texture.linear(0)[..., :3].reshape(-1, 3)}
    rgb = affine_rgb(scene)
    drawn = pp.render(scene).object_id >= 0
    assert {tuple(c) for c in rgb[drawn]} <= texels


def test_the_figure_is_written_as_png(tmp_path):
    path = save(perspective_figure(width=64, height=48), tmp_path / "texturing.png")
    with Image.open(path) as picture:
        assert picture.format == "PNG" and picture.height == 48 + 38


def test_checkerboard_errors():
    assert checkerboard(2).shape == (2, 2, 3)
    with pytest.raises(ValueError, match="squares"):
        checkerboard(1)
