"""Round trips and invariants of the colour models, over random colours and with hypothesis."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from pixelpath import color

MODELS = ["hsv", "hsl", "cmy", "cmyk", "yiq", "ycbcr"]
TO = {m: getattr(color, f"rgb_to_{m}") for m in MODELS}
FROM = {m: getattr(color, f"{m}_to_rgb") for m in MODELS}

unit_rgb = arrays(
    np.float64,
    st.tuples(st.integers(1, 20), st.just(3)),
    elements=st.floats(0.0, 1.0, allow_nan=False),
)


@pytest.mark.parametrize("model", MODELS)
def test_round_trip_float64(model):
    rgb = np.random.default_rng(1).random((2000, 3))
    np.testing.assert_allclose(FROM[model](TO[model](rgb)), rgb, atol=1e-12)


@pytest.mark.parametrize("model", MODELS)
def test_round_trip_float32(model):
    rgb = np.random.default_rng(2).random((2000, 3), dtype=np.float32)
    back = FROM[model](TO[model](rgb))
    assert back.dtype == np.float32
    np.testing.assert_allclose(back, rgb, atol=2e-6)


@pytest.mark.parametrize("model", MODELS)
def test_round_trip_uint8_is_exact_after_rounding(model):
    rgb = np.random.default_rng(3).integers(0, 256, (2000, 3), dtype=np.uint8)
    back = FROM[model](TO[model](rgb))
    np.testing.assert_array_equal(np.rint(back * 255).astype(np.uint8), rgb)


@pytest.mark.parametrize("model", MODELS)
def test_round_trip_uint16(model):
    rgb = np.random.default_rng(4).integers(0, 65536, (500, 3), dtype=np.uint16)
    back = FROM[model](TO[model](rgb))
    np.testing.assert_array_equal(np.rint(back * 65535).astype(np.uint16), rgb)


@settings(max_examples=60, deadline=None)
@given(unit_rgb)
def test_hsv_and_hsl_ranges(rgb):
    for hsx in (color.rgb_to_hsv(rgb), color.rgb_to_hsl(rgb)):
        assert np.all((hsx[:, 0] >= 0) & (hsx[:, 0] < 360))
        assert np.all((hsx[:, 1] >= 0) & (hsx[:, 1] <= 1 + 1e-12))
        assert np.all((hsx[:, 2] >= 0) & (hsx[:, 2] <= 1))


@settings(max_examples=60, deadline=None)
@given(unit_rgb)
def test_every_model_round_trips(rgb):
    for model in MODELS:
        np.testing.assert_allclose(FROM[model](TO[model](rgb)), rgb, atol=1e-9)


@settings(max_examples=40, deadline=None)
@given(unit_rgb, st.sampled_from(MODELS), st.sampled_from(MODELS))
@example(np.array([[5e-324, 0.0, 0.0]]), "hsl", "hsl")  # found by hypothesis
def test_convert_goes_through_rgb(rgb, src, dst):
    values = TO[src](rgb)
    converted = color.convert(values, src, dst)
    if dst == "rgb":
        np.testing.assert_allclose(converted, rgb, atol=1e-12)
        return
    # Compared as the colours they denote: a red of 5e-324 has HSL lightness 0 (half of it
    # rounds to 0) and saturation 1, which name no other colour than black; converting HSL to
    # HSL keeps those components as given, where the trip through RGB gives black's (0, 0, 0).
    expected = TO[dst](FROM[src](values))
    np.testing.assert_allclose(FROM[dst](converted), FROM[dst](expected), atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    st.floats(-1e4, 1e4, allow_nan=False),
    st.floats(0, 1),
    st.floats(0, 1),
    st.integers(-3, 3),
)
def test_hue_wraps_modulo_360(hue, sat, val, turns):
    base = color.hsv_to_rgb([hue, sat, val])
    np.testing.assert_allclose(color.hsv_to_rgb([hue + 360 * turns, sat, val]), base, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(st.floats(0, 1))
def test_greys_have_zero_hue_and_saturation(level):
    grey = np.full(3, level)
    for hsx in (color.rgb_to_hsv(grey), color.rgb_to_hsl(grey)):
        assert hsx[0] == 0 and hsx[1] == 0


@settings(max_examples=60, deadline=None)
@given(unit_rgb)
def test_cmyk_black_is_one_minus_max(rgb):
    np.testing.assert_allclose(color.rgb_to_cmyk(rgb)[:, 3], 1 - rgb.max(axis=1), atol=1e-15)


def test_hue_never_reaches_360():
    # (G - B)/delta = -1e-17 gives 6 - 1e-17 sextants, which rounds to 6: it must wrap to 0.
    hue = color.rgb_to_hsv([1.0, 0.0, 1e-17])[0]
    assert 0 <= hue < 360


def test_round_off_just_outside_the_unit_range_is_tolerated():
    rgb = np.array([1 + 1e-15, -1e-16, 0.5])
    hsv = color.rgb_to_hsv(rgb)
    assert 0 <= hsv[0] < 360
    np.testing.assert_allclose(color.hsv_to_rgb(hsv), rgb, atol=1e-12)


def test_values_far_outside_are_extrapolated_by_the_same_formulas():
    # Documented: no clipping; V = Cmax even above 1, CMY = 1 - RGB even when negative.
    np.testing.assert_allclose(color.rgb_to_hsv([2.0, 0.0, 0.0]), [0, 1, 2])
    np.testing.assert_allclose(color.rgb_to_cmy([2.0, -1.0, 0.5]), [-1, 2, 0.5])
