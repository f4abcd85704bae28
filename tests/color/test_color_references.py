"""Agreement with independent implementations: colorsys (stdlib) and scikit-image.

Their conventions, converted to ours: colorsys and skimage give hue in [0, 1) (ours is degrees);
colorsys.rgb_to_hls orders (H, L, S) (ours is H, S, L); skimage's YIQ matrix carries more digits
than the notes' (agreement to 2e-3); skimage's YCbCr is studio range, Y = 16 + 219 Y',
Cb = 128 + 224 (Cb' - 0.5).
"""

import colorsys

import numpy as np
import pytest

from pixelpath import color

skcolor = pytest.importorskip("skimage.color")

RGB = np.random.default_rng(7).random((500, 3))


def hue_distance(a, b):
    d = np.abs(a - b) % 360
    return np.minimum(d, 360 - d)


def test_hsv_matches_colorsys():
    expected = np.array([colorsys.rgb_to_hsv(*p) for p in RGB])
    ours = color.rgb_to_hsv(RGB)
    assert hue_distance(ours[:, 0], 360 * expected[:, 0]).max() < 1e-9
    np.testing.assert_allclose(ours[:, 1:], expected[:, 1:], atol=1e-12)


def test_hsv_to_rgb_matches_colorsys():
    hsv = np.column_stack([RGB[:, 0] * 360, RGB[:, 1], RGB[:, 2]])
    expected = np.array([colorsys.hsv_to_rgb(h / 360, s, v) for h, s, v in hsv])
    np.testing.assert_allclose(color.hsv_to_rgb(hsv), expected, atol=1e-12)


def test_hsl_matches_colorsys_hls():
    expected = np.array([colorsys.rgb_to_hls(*p) for p in RGB])  # (H, L, S)
    ours = color.rgb_to_hsl(RGB)
    assert hue_distance(ours[:, 0], 360 * expected[:, 0]).max() < 1e-9
    np.testing.assert_allclose(ours[:, 1], expected[:, 2], atol=1e-12)
    np.testing.assert_allclose(ours[:, 2], expected[:, 1], atol=1e-12)
    back = np.array([colorsys.hls_to_rgb(h / 360, light, s) for h, s, light in ours])
    np.testing.assert_allclose(color.hsl_to_rgb(ours), back, atol=1e-12)


def test_hsv_matches_scikit_image():
    expected = skcolor.rgb2hsv(RGB)
    ours = color.rgb_to_hsv(RGB)
    assert hue_distance(ours[:, 0], 360 * expected[:, 0]).max() < 1e-9
    np.testing.assert_allclose(ours[:, 1:], expected[:, 1:], atol=1e-12)
    np.testing.assert_allclose(color.hsv_to_rgb(ours), skcolor.hsv2rgb(expected), atol=1e-12)


def test_yiq_matches_scikit_image_to_its_precision():
    np.testing.assert_allclose(color.rgb_to_yiq(RGB), skcolor.rgb2yiq(RGB), atol=2e-3)


def test_ycbcr_matches_scikit_image_studio_range():
    studio = skcolor.rgb2ycbcr(RGB)
    expected = np.column_stack(
        [
            (studio[:, 0] - 16) / 219,
            (studio[:, 1] - 128) / 224 + 0.5,
            (studio[:, 2] - 128) / 224 + 0.5,
        ]
    )
    np.testing.assert_allclose(color.rgb_to_ycbcr(RGB), expected, atol=1e-6)


def test_uint8_scaling_matches_scikit_image():
    image = np.random.default_rng(8).integers(0, 256, (16, 16, 3), dtype=np.uint8)
    ours = color.rgb_to_hsv(image)
    expected = skcolor.rgb2hsv(image)
    np.testing.assert_allclose(ours[..., 1:], expected[..., 1:], atol=1e-6)
