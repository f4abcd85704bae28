"""The colour tables and worked examples of the notes (RGB, YIQ, CMY and HSV chapters)."""

import numpy as np
import pytest

from pixelpath import color

# The notes' table of common RGB values, with the HSV each must have (hue cases of the notes).
COMMON = [
    # name, 8-bit RGB, (H, S, V)
    ("black", (0, 0, 0), (0, 0, 0)),
    ("white", (255, 255, 255), (0, 0, 1)),
    ("red", (255, 0, 0), (0, 1, 1)),
    ("green", (0, 255, 0), (120, 1, 1)),
    ("blue", (0, 0, 255), (240, 1, 1)),
    ("yellow", (255, 255, 0), (60, 1, 1)),
    ("cyan", (0, 255, 255), (180, 1, 1)),
    ("magenta", (255, 0, 255), (300, 1, 1)),
    ("gray x=51", (51, 51, 51), (0, 0, 0.2)),
]


@pytest.mark.parametrize(("name", "rgb", "hsv"), COMMON, ids=[c[0] for c in COMMON])
def test_common_rgb_values_in_hsv(name, rgb, hsv):
    np.testing.assert_allclose(color.rgb_to_hsv(np.array(rgb, np.uint8)), hsv, atol=1e-12)
    np.testing.assert_allclose(color.hsv_to_rgb(hsv), np.array(rgb) / 255, atol=1e-12)


# The notes' YIQ table (three decimals), section "COLOUR REPRESENTATION (EXAMPLES)".
YIQ_TABLE = [
    ("white", (1, 1, 1), (1.000, 0.000, 0.000)),
    ("black", (0, 0, 0), (0.000, 0.000, 0.000)),
    ("red", (1, 0, 0), (0.299, 0.596, 0.211)),
    ("green", (0, 1, 0), (0.587, -0.274, -0.523)),
    ("blue", (0, 0, 1), (0.114, -0.322, 0.312)),
    ("yellow", (1, 1, 0), (0.886, 0.322, -0.312)),
    ("cyan", (0, 1, 1), (0.701, -0.596, -0.211)),
    ("magenta", (1, 0, 1), (0.413, 0.274, 0.523)),
]


@pytest.mark.parametrize(("name", "rgb", "yiq"), YIQ_TABLE, ids=[r[0] for r in YIQ_TABLE])
def test_notes_yiq_table(name, rgb, yiq):
    result = color.rgb_to_yiq(np.array(rgb, float))
    np.testing.assert_allclose(result, yiq, atol=5e-4)
    np.testing.assert_allclose(color.yiq_to_rgb(result), rgb, atol=1e-12)


def test_yiq_inverse_is_exact_not_the_notes_rounded_matrix():
    # The notes print the inverse rounded to three decimals (SPEC errata): using it, red comes
    # back visibly off; the exact inverse gives red to float precision.
    notes_inverse = np.array([[1.0, 0.956, 0.621], [1.0, -0.272, -0.647], [1.0, -1.106, 1.703]])
    yiq_red = np.array([0.299, 0.596, 0.211])
    assert np.abs(notes_inverse @ yiq_red - [1, 0, 0]).max() > 5e-4
    np.testing.assert_allclose(color.yiq_to_rgb(yiq_red), [1, 0, 0], atol=1e-14)


# The notes' CMY table: C, M, Y -> colour.
CMY_TABLE = [
    ((0, 0, 0), (1, 1, 1)),  # white
    ((1, 1, 1), (0, 0, 0)),  # black
    ((1, 0, 0), (0, 1, 1)),  # cyan
    ((0, 1, 0), (1, 0, 1)),  # magenta
    ((0, 0, 1), (1, 1, 0)),  # yellow
    ((1, 1, 0), (0, 0, 1)),  # blue = C + M
    ((0, 1, 1), (1, 0, 0)),  # red = M + Y
    ((1, 0, 1), (0, 1, 0)),  # green = C + Y
]


@pytest.mark.parametrize(("cmy", "rgb"), CMY_TABLE)
def test_notes_cmy_table(cmy, rgb):
    np.testing.assert_array_equal(color.cmy_to_rgb(np.array(cmy, float)), rgb)
    np.testing.assert_array_equal(color.rgb_to_cmy(np.array(rgb, float)), cmy)


# The notes' HSV examples table: bright colours at S = V = 1 every 60 degrees.
@pytest.mark.parametrize(
    ("hue", "rgb"),
    [
        (0, (1, 0, 0)),
        (60, (1, 1, 0)),
        (120, (0, 1, 0)),
        (180, (0, 1, 1)),
        (240, (0, 0, 1)),
        (300, (1, 0, 1)),
        (360, (1, 0, 0)),
    ],
)
def test_notes_hsv_examples(hue, rgb):
    np.testing.assert_allclose(color.hsv_to_rgb([hue, 1.0, 1.0]), rgb, atol=1e-15)


@pytest.mark.parametrize("hue", [0, 45, 123, 200, 359])
def test_zero_saturation_is_grey_and_zero_value_is_black(hue):
    np.testing.assert_allclose(color.hsv_to_rgb([hue, 0.0, 0.4]), [0.4] * 3, atol=1e-15)
    np.testing.assert_allclose(color.hsv_to_rgb([hue, 0.7, 0.0]), [0.0] * 3, atol=1e-15)


# The sector table, one row per 60-degree sector, at H = 60k + 30 with V = 1, S = 0.5:
# C = 0.5, X = C (1 - |(H/60) mod 2 - 1|) = 0.25, m = 0.5.
@pytest.mark.parametrize(
    ("hue", "primes"),
    [
        (30, ("C", "X", 0)),
        (90, ("X", "C", 0)),
        (150, (0, "C", "X")),
        (210, (0, "X", "C")),
        (270, ("X", 0, "C")),
        (330, ("C", 0, "X")),
    ],
)
def test_hsv_sector_table_rows(hue, primes):
    c, x, m = 0.5, 0.25, 0.5
    expected = [{"C": c, "X": x, 0: 0.0}[p] + m for p in primes]
    np.testing.assert_allclose(color.hsv_to_rgb([hue, 0.5, 1.0]), expected, atol=1e-15)


def test_rgb_to_hsv_hue_cases_by_hand():
    # Cmax = R: H = 60 ((G - B)/delta mod 6); (0.8, 0.2, 0.4): delta 0.6, (-0.2/0.6) mod 6 = 5.667
    np.testing.assert_allclose(color.rgb_to_hsv([0.8, 0.2, 0.4]), [340, 0.75, 0.8], atol=1e-12)
    # Cmax = G: H = 60 ((B - R)/delta + 2); (0.2, 0.8, 0.5): delta 0.6 -> 60 (0.5 + 2) = 150
    np.testing.assert_allclose(color.rgb_to_hsv([0.2, 0.8, 0.5]), [150, 0.75, 0.8], atol=1e-12)
    # Cmax = B: H = 60 ((R - G)/delta + 4); (0.5, 0.2, 0.8): 60 (0.5 + 4) = 270
    np.testing.assert_allclose(color.rgb_to_hsv([0.5, 0.2, 0.8]), [270, 0.75, 0.8], atol=1e-12)


def test_hsl_by_hand():
    # (0.2, 0.4, 0.6): Cmax 0.6, Cmin 0.2, L = 0.4, S = 0.4 / (1 - |0.8 - 1|) = 0.5, H = 210
    np.testing.assert_allclose(color.rgb_to_hsl([0.2, 0.4, 0.6]), [210, 0.5, 0.4], atol=1e-12)
    np.testing.assert_allclose(color.hsl_to_rgb([210, 0.5, 0.4]), [0.2, 0.4, 0.6], atol=1e-12)


def test_cmyk_by_hand_and_pure_black():
    # (1, 0.5, 0): C, M, Y = 0, 0.5, 1; K = 0; C' = C etc.
    np.testing.assert_allclose(color.rgb_to_cmyk([1.0, 0.5, 0.0]), [0, 0.5, 1, 0])
    # (0.4, 0.2, 0.2): C, M, Y = 0.6, 0.8, 0.8; K = 0.6; C' = 0, M' = Y' = 0.2/0.4 = 0.5
    np.testing.assert_allclose(color.rgb_to_cmyk([0.4, 0.2, 0.2]), [0, 0.5, 0.5, 0.6], atol=1e-15)
    np.testing.assert_array_equal(color.rgb_to_cmyk([0, 0, 0]), [0, 0, 0, 1])
    np.testing.assert_array_equal(color.cmyk_to_rgb([0, 0, 0, 1]), [0, 0, 0])


def test_ycbcr_bt601_full_range_by_hand():
    # Y = 0.299 R + 0.587 G + 0.114 B, Cb = 0.5 + (B - Y)/1.772, Cr = 0.5 + (R - Y)/1.402
    red = color.rgb_to_ycbcr([1.0, 0.0, 0.0])
    np.testing.assert_allclose(red, [0.299, 0.5 - 0.299 / 1.772, 0.5 + 0.701 / 1.402], atol=1e-15)
    np.testing.assert_allclose(color.rgb_to_ycbcr([1.0, 1.0, 1.0]), [1, 0.5, 0.5], atol=1e-15)
