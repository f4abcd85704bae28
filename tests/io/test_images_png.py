"""PNG compression levels: Pillow's encoder at the level asked, the same pixels at every one."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image as PILImage

from pixelpath.io.images import encode_image, read_image, write_image


def _decoded(data: bytes) -> np.ndarray:
    with PILImage.open(io.BytesIO(data)) as image:
        image.verify()  # the chunks' CRCs and the structure
    with PILImage.open(io.BytesIO(data)) as image:
        return np.asarray(image)


@pytest.mark.parametrize("level", range(10))
def test_every_level_writes_the_pixels_of_image_save(level):
    rgb = np.random.default_rng(1).random((31, 45, 3), dtype=np.float32)
    rgb[5:9] = 0.25  # and some flat rows
    alpha = np.random.default_rng(2).random((31, 45), dtype=np.float32)
    for gamma in (None, "srgb", 2.2):
        default = _decoded(encode_image(rgb, ".png", gamma=gamma, alpha=alpha))
        leveled = _decoded(encode_image(rgb, ".png", gamma=gamma, alpha=alpha, png_level=level))
        assert np.array_equal(leveled, default)


def test_the_level_is_pillows_compress_level(tmp_path):
    # A smooth picture: level 0 stores the rows, 1 compresses them, 9 squeezes hardest.
    y, x = np.mgrid[0:64, 0:96] / 96.0
    rgb = np.stack([x, y, (x + y) / 2], axis=-1)
    sizes = {level: len(encode_image(rgb, ".png", png_level=level)) for level in (0, 1, 9)}
    assert sizes[0] > rgb[..., 0].size * 3 > sizes[1] >= sizes[9]
    assert encode_image(rgb, ".png", png_level=6) == encode_image(rgb, ".png")  # Pillow's default
    write_image(tmp_path / "a.png", rgb, png_level=0)
    expected = _decoded(encode_image(rgb, ".png")).astype(np.float32) / 255.0
    assert np.array_equal(read_image(tmp_path / "a.png"), expected)


def test_other_formats_ignore_the_level_but_check_it():
    rgb = np.zeros((4, 4, 3), np.float32)
    assert encode_image(rgb, ".bmp", png_level=3) == encode_image(rgb, ".bmp")
    for bad in (11, -1, 1.0, True, "1"):
        with pytest.raises(ValueError, match="png_level must be an int from 0 to 9"):
            encode_image(rgb, ".png", png_level=bad)
