"""pixelpath's PNG encoder: the pixels Pillow's encoder writes, at any zlib level."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image as PILImage

from pixelpath.io.images import encode_image, encode_png, read_image, write_image


def _decoded(data: bytes) -> np.ndarray:
    with PILImage.open(io.BytesIO(data)) as image:
        image.verify()  # the chunks' CRCs and the structure
    with PILImage.open(io.BytesIO(data)) as image:
        return np.asarray(image)


@pytest.mark.parametrize("level", range(10))
@pytest.mark.parametrize("channels", [3, 4])
def test_every_level_decodes_to_the_pixels(level, channels):
    pixels = np.random.default_rng(level).integers(0, 256, (17, 23, channels), dtype=np.uint8)
    pixels[5:9] = 40  # and some flat rows
    assert np.array_equal(_decoded(encode_png(pixels, level)), pixels)


def test_encode_image_with_a_level_writes_the_pixels_pillow_writes(tmp_path):
    rgb = np.random.default_rng(1).random((31, 45, 3), dtype=np.float32)
    alpha = np.random.default_rng(2).random((31, 45), dtype=np.float32)
    for gamma in (None, "srgb", 2.2):
        pillow = _decoded(encode_image(rgb, ".png", gamma=gamma, alpha=alpha))
        ours = _decoded(encode_image(rgb, ".png", gamma=gamma, alpha=alpha, png_level=1))
        assert np.array_equal(ours, pillow)
    write_image(tmp_path / "a.png", rgb, png_level=0)
    expected = _decoded(encode_image(rgb, ".png")).astype(np.float32) / 255.0
    assert np.array_equal(read_image(tmp_path / "a.png"), expected)
    assert len((tmp_path / "a.png").read_bytes()) > rgb.size  # level 0 stores the rows


def test_other_formats_ignore_the_level_but_check_it():
    rgb = np.zeros((4, 4, 3), np.float32)
    assert encode_image(rgb, ".bmp", png_level=3) == encode_image(rgb, ".bmp")
    with pytest.raises(ValueError, match="png_level must be an int from 0 to 9"):
        encode_image(rgb, ".bmp", png_level=11)


@pytest.mark.parametrize(
    "pixels",
    [np.zeros((2, 2, 3), np.float32), np.zeros((2, 2), np.uint8), np.zeros((2, 2, 2), np.uint8)],
)
def test_only_8_bit_rgb_or_rgba_is_encoded(pixels):
    with pytest.raises(ValueError, match="pixels must be"):
        encode_png(pixels)
