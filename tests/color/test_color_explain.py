"""The teaching output: the notes' steps, and results that agree with the compiled kernels."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath import color
from pixelpath.color.explain import explain

MODELS = list(color.MODELS)


def test_rgb_to_hsv_steps_for_yellow():
    steps, result = explain([1.0, 1.0, 0.0], "rgb", "hsv")
    assert steps == [
        "Cmax = max(R, G, B) = 1",
        "Cmin = min(R, G, B) = 0",
        "Δ = Cmax − Cmin = 1 − 0 = 1",
        "Cmax = R, so H = 60 × ((G − B)/Δ mod 6) = 60 × ((1 − 0)/1 mod 6) = 60°",
        "V = Cmax = 1",
        "S = Δ/Cmax = 1/1 = 1",
    ]
    assert result == [60.0, 1.0, 1.0]


def test_hsv_to_rgb_names_the_sector_row():
    steps, result = explain([200, 0.5, 0.8], "hsv", "rgb")
    assert "H = 200° lies in 180-240°: (R', G', B') = (0, X, C) = (0, 0.2667, 0.4)" in steps
    np.testing.assert_allclose(result, [0.4, 2 / 3, 0.8])


def test_grey_hue_case_is_explained():
    steps, _ = explain([0.5, 0.5, 0.5], "rgb", "hsv")
    assert any("Δ = 0: a grey, so H = 0°" in s for s in steps)


def test_yiq_is_the_matrix_product():
    steps, _ = explain([1.0, 1.0, 0.0], "rgb", "yiq")
    assert steps[1] == "I = 0.596×R − 0.274×G − 0.322×B = 0.322"


def test_cmyk_of_black_avoids_division_by_zero():
    steps, result = explain([0.0, 0.0, 0.0], "rgb", "cmyk")
    assert result == [0.0, 0.0, 0.0, 1.0]
    assert "avoiding 0/0" in steps[-1]


@settings(max_examples=80, deadline=None)
@given(
    st.lists(st.floats(0, 1), min_size=3, max_size=3),
    st.sampled_from(MODELS),
    st.sampled_from(MODELS),
)
def test_explained_results_agree_with_the_kernels(rgb, src, dst):
    values = color.convert(rgb, "rgb", src).tolist()
    _, result = explain(values, src, dst)
    expected = color.convert(values, src, dst)
    if dst in ("hsv", "hsl"):  # hue of near-greys is ill-conditioned; compare on the circle
        d = abs(result[0] - expected[0]) % 360
        assert min(d, 360 - d) < 1e-6 or expected[1] < 1e-9
        np.testing.assert_allclose(result[1:], expected[1:], atol=1e-9)
    else:
        np.testing.assert_allclose(result, expected, atol=1e-9)


def test_unknown_model():
    with pytest.raises(ValueError, match="unknown colour model"):
        explain([0, 0, 0], "rgb", "lab")
