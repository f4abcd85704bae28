"""phong_terms, reflect and phong_geometry: the notes' worked examples (corrected) and errors."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pixelpath.lighting import phong_geometry, phong_terms, reflect

NOTES_EXAMPLE = {
    "ka": 0.2,
    "kd": 0.6,
    "ks": 0.5,
    "shininess": 20,
    "ambient": 0.2,
    "light": 1.0,
    "n_dot_l": 0.707,
    "r_dot_v": 0.866,
}


def test_notes_phong_example_with_corrected_power():
    # Notes, "Basic illumination model" s.7 and "Phong shading" s.9 (the same numbers):
    # I_a = 0.2 x 0.2 = 0.04; I_d = 0.6 x 1 x 0.707 = 0.4242;
    # (0.866)^20 = exp(20 ln 0.866) = exp(20 x -0.143870) = exp(-2.87741) = 0.05628
    # (the notes print 0.0117, SPEC s.9), so I_s = 0.5 x 0.05628 = 0.02814 and
    # I = 0.04 + 0.4242 + 0.02814 = 0.49234 (not 0.47005).
    terms = phong_terms(**NOTES_EXAMPLE)
    assert terms.ambient == pytest.approx(0.04, abs=1e-12)
    assert terms.diffuse == pytest.approx(0.4242, abs=1e-12)
    assert terms.specular == pytest.approx(0.02814, abs=5e-6)
    assert terms.total == pytest.approx(0.49234, abs=5e-6)
    assert round(terms.total, 4) == 0.4923
    assert terms.clamped == terms.total  # already within [0, 1]
    assert isinstance(terms.total, float)


def test_notes_diffuse_example():
    # Notes, "Diffuse reflection" s.8: IL = 120 cd, kd = 0.7, theta = 60 deg:
    # I_d = 0.7 x 120 x cos 60 = 0.7 x 120 x 0.5 = 42 cd.
    terms = phong_terms(ka=0, kd=0.7, ks=0, shininess=1, ambient=0, light=120,
                        n_dot_l=math.cos(math.radians(60)), r_dot_v=0.0)
    assert terms.diffuse == pytest.approx(42.0, rel=1e-12)
    assert terms.total == pytest.approx(42.0, rel=1e-12)
    assert terms.clamped == 1.0  # 42 cd shown on a [0, 1] display saturates


def test_notes_diffuse_table():
    # Notes, "Diffuse reflection" s.7: I_d / (kd IL) = cos theta for 0, 30, 60, 90 deg and 0
    # beyond 90 deg: 1, sqrt(3)/2 = 0.8660, 0.5, 0, 0.
    angles = np.radians([0.0, 30.0, 60.0, 90.0, 120.0])
    terms = phong_terms(ka=0, kd=1, ks=0, shininess=1, ambient=0, light=1,
                        n_dot_l=np.cos(angles), r_dot_v=0.5)
    np.testing.assert_allclose(terms.diffuse, [1.0, math.sqrt(3) / 2, 0.5, 0.0, 0.0], atol=1e-15)


def test_notes_specular_example_with_corrected_power():
    # Notes, "Specular reflection" s.8: ks = 0.8, IL = 100 cd, n = 20, alpha = 30 deg:
    # cos^20 30 = (sqrt(3)/2)^20 = (3/4)^10 = 59049/1048576 = 0.056314 (the notes: 0.015),
    # I_s = 0.8 x 100 x 0.056314 = 4.5051 cd with the exact cosine (not 1.2 cd).
    terms = phong_terms(ka=0, kd=0, ks=0.8, shininess=20, ambient=0, light=100, n_dot_l=1.0,
                        r_dot_v=math.cos(math.radians(30)))
    assert terms.specular == pytest.approx(80 * 59049 / 1048576, rel=1e-12)
    # With the notes' rounded cosine 0.866: 0.866^20 = 0.05628 (see the Phong example),
    # 80 x 0.05628 = 4.5026, the 4.50 cd of SPEC s.9.
    rounded = phong_terms(ka=0, kd=0, ks=0.8, shininess=20, ambient=0, light=100, n_dot_l=1.0,
                          r_dot_v=0.866)
    assert round(rounded.specular, 2) == 4.50


def test_notes_specular_table():
    # Notes, "Specular reflection" s.7, I_s / (ks IL) = cos^20 alpha:
    #   0 deg: 1;  30 deg: (3/4)^10 = 0.0563 (notes: 0.015);  60 deg: 2^-20 = 9.54e-7;
    #   75 deg: cos^2 75 = (2 - sqrt 3)/4 = 0.066987, ^10 = exp(10 ln 0.066987)
    #           = exp(-27.0327) = 1.82e-12 (notes: 1.28e-13);  90 deg: 0.
    alpha = np.radians([0.0, 30.0, 60.0, 75.0, 90.0])
    terms = phong_terms(ka=0, kd=0, ks=1, shininess=20, ambient=0, light=1, n_dot_l=1.0,
                        r_dot_v=np.cos(alpha))
    expected = [1.0, 0.75**10, 2.0**-20, ((2 - math.sqrt(3)) / 4) ** 10, 0.0]
    np.testing.assert_allclose(terms.specular, expected, rtol=1e-9, atol=1e-15)
    assert terms.specular[3] == pytest.approx(1.82e-12, rel=5e-3)


def test_per_channel_light_broadcasts():
    # IL = (1, 0.8, 0.8): I_a = 0.04 each; I_d = 0.4242 x (1, 0.8, 0.8) = (0.4242, 0.33936,
    # 0.33936); I_s = 0.02814 x (1, 0.8, 0.8) = (0.02814, 0.022512, 0.022512).
    terms = phong_terms(**(NOTES_EXAMPLE | {"light": (1.0, 0.8, 0.8)}))
    assert terms.total.shape == (3,)
    np.testing.assert_allclose(terms.ambient, [0.04] * 3)
    np.testing.assert_allclose(terms.diffuse, [0.4242, 0.33936, 0.33936])
    np.testing.assert_allclose(terms.specular, [0.02814, 0.022512, 0.022512], atol=5e-6)


def test_coefficients_and_cosines_broadcast_to_a_grid():
    # kd per channel (3,) against three cosines (3, 1) gives (3, 3) terms: kd_c x cos_i.
    terms = phong_terms(ka=0, kd=[0.2, 0.4, 0.6], ks=0, shininess=1, ambient=0, light=1,
                        n_dot_l=[[1.0], [0.5], [0.0]], r_dot_v=0.5)
    np.testing.assert_allclose(terms.diffuse, [[0.2, 0.4, 0.6], [0.1, 0.2, 0.3], [0, 0, 0]])
    assert terms.ambient.shape == terms.total.shape == (3, 3)


def test_specular_is_zero_when_light_is_behind_or_viewer_is_outside():
    # N.L <= 0 or R.V <= 0 gives no highlight, also for n = 0 (0^0 and (-x)^0 never used).
    terms = phong_terms(ka=0, kd=0, ks=1, shininess=0, ambient=0, light=1,
                        n_dot_l=[-0.5, 0.0, 0.5, 0.5, 0.5], r_dot_v=[0.9, 0.9, 0.0, -0.3, 0.9])
    np.testing.assert_array_equal(terms.specular, [0.0, 0.0, 0.0, 0.0, 1.0])


def test_clamped_saturates_at_one():
    # ka Ia + kd IL + ks IL = 0.2 + 0.6 + 0.5 = 1.3 > 1, displayed as 1.
    terms = phong_terms(ka=0.2, kd=0.6, ks=0.5, shininess=5, ambient=1, light=1, n_dot_l=1.0,
                        r_dot_v=1.0)
    assert terms.total == pytest.approx(1.3)
    assert terms.clamped == 1.0


@pytest.mark.parametrize("name", ["ka", "kd", "ks", "shininess", "ambient", "light"])
def test_negative_values_are_rejected_by_name(name):
    with pytest.raises(ValueError, match=rf"^{name} must be >= 0"):
        phong_terms(**(NOTES_EXAMPLE | {name: -0.1}))


@pytest.mark.parametrize("name", list(NOTES_EXAMPLE))
def test_nan_is_rejected_by_name(name):
    with pytest.raises(ValueError, match=rf"^{name} must not be NaN"):
        phong_terms(**(NOTES_EXAMPLE | {name: [0.5, math.nan]}))


@pytest.mark.parametrize("name", list(NOTES_EXAMPLE))
@pytest.mark.parametrize("value", ["0.5", None, [0.5, "x"], True])
def test_non_numeric_is_a_type_error(name, value):
    with pytest.raises(TypeError, match=rf"^{name} must be a number"):
        phong_terms(**(NOTES_EXAMPLE | {name: value}))


@pytest.mark.parametrize("name", ["n_dot_l", "r_dot_v"])
def test_cosines_outside_minus_one_one_are_rejected(name):
    with pytest.raises(ValueError, match=rf"^{name} is a cosine"):
        phong_terms(**(NOTES_EXAMPLE | {name: 1.2}))


def test_infinite_and_unbroadcastable_arguments_are_rejected():
    with pytest.raises(ValueError, match="light must be finite"):
        phong_terms(**(NOTES_EXAMPLE | {"light": math.inf}))
    with pytest.raises(ValueError, match=r"do not broadcast.*ka\(2,\).*kd\(3,\)"):
        phong_terms(**(NOTES_EXAMPLE | {"ka": [0.1, 0.2], "kd": [0.1, 0.2, 0.3]}))


def test_reflect_hand_cases():
    # N = y: (1, 1, 0) -> 2(1)(0, 1, 0) - (1, 1, 0) = (-1, 1, 0); L = N -> N; L _|_ N -> -L.
    np.testing.assert_allclose(reflect([1.0, 1.0, 0.0], [0.0, 1.0, 0.0]), [-1.0, 1.0, 0.0])
    np.testing.assert_allclose(reflect([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]), [0.0, 0.0, 2.0])
    np.testing.assert_allclose(reflect([3.0, 0.0, 0.0], [0.0, 0.0, 1.0]), [-3.0, 0.0, 0.0])
    # N need not be unit: (0, 5, 0) means the same mirror as (0, 1, 0).
    np.testing.assert_allclose(reflect([1.0, 1.0, 0.0], [0.0, 5.0, 0.0]), [-1.0, 1.0, 0.0])


def test_reflect_broadcasts():
    lights = np.array([[1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [2.0, -1.0, 0.0]])
    r = reflect(lights, [0.0, 1.0, 0.0])
    # Mirroring about y flips x and z: (x, y, z) -> (-x, y, -z).
    np.testing.assert_allclose(r, lights * [-1.0, 1.0, -1.0])
    assert reflect(np.ones((4, 2, 3)), [0.0, 0.0, 1.0]).shape == (4, 2, 3)


@pytest.mark.parametrize(
    ("l", "n", "error", "match"),
    [
        ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], ValueError, "^l must not contain a zero-length"),
        ([1.0, 0.0, 0.0], [0.0, 0.0, 0.0], ValueError, "^n must not contain a zero-length"),
        ([1.0, 0.0], [0.0, 0.0, 1.0], ValueError, r"^l must have shape \(\.\.\., 3\)"),
        ([1.0, 0.0, math.nan], [0.0, 0.0, 1.0], ValueError, "^l must not be NaN"),
        ("up", [0.0, 0.0, 1.0], TypeError, "^l must be a number"),
        (np.ones((2, 3)), np.ones((3, 3)), ValueError, "do not broadcast"),
    ],
)
def test_reflect_rejects_bad_input(l, n, error, match):  # noqa: E741
    with pytest.raises(error, match=match):
        reflect(l, n)


def test_geometry_from_vectors():
    # N = z, L = (0, 1, 1)/sqrt 2, V = (0, -1, 1)/sqrt 2: N.L = 1/sqrt 2 = 0.70711,
    # R = 2 (1/sqrt 2) N - L = (0, -1, 1)/sqrt 2 = V, so R.V = 1 and alpha = 0;
    # H = (L + V)/|L + V| = (0, 0, 2/sqrt 2)/(2/sqrt 2) = N, N.H = 1.
    g = phong_geometry([0, 0, 1], [0, 1, 1], [0, -1, 1])
    s = 1 / math.sqrt(2)
    assert g.n_dot_l == pytest.approx(s)
    np.testing.assert_allclose(g.reflected, [0.0, -s, s])
    assert g.r_dot_v == pytest.approx(1.0)
    np.testing.assert_allclose(g.halfway, [0.0, 0.0, 1.0])
    assert g.theta == pytest.approx(45.0)
    assert g.alpha == pytest.approx(0.0, abs=1e-5)  # arccos is ill-conditioned at 1


def test_geometry_from_points():
    # P = (1, 1, 0), light (1, 4, 4): L = (0, 3, 4)/5; eye (1, 1, 2): V = (0, 0, 1).
    # N = z: N.L = 0.8; R = (0, -0.6, 0.8); R.V = 0.8.
    g = phong_geometry([0, 0, 2], surface=[1, 1, 0], light=[1, 4, 4], eye=[1, 1, 2])
    np.testing.assert_allclose(g.to_light, [0.0, 0.6, 0.8])
    np.testing.assert_allclose(g.to_eye, [0.0, 0.0, 1.0])
    assert g.n_dot_l == pytest.approx(0.8)
    np.testing.assert_allclose(g.reflected, [0.0, -0.6, 0.8])
    assert g.r_dot_v == pytest.approx(0.8)


def test_geometry_rejects_degenerate_and_mixed_input():
    with pytest.raises(ValueError, match="to_eye"):
        phong_geometry([0, 0, 1], surface=[1, 1, 1], light=[0, 0, 5], eye=[1, 1, 1])
    with pytest.raises(ValueError, match="either"):
        phong_geometry([0, 0, 1], [0, 1, 1], [0, 0, 1], surface=[0, 0, 0])
    with pytest.raises(ValueError, match="either"):
        phong_geometry([0, 0, 1], [0, 1, 1])
    with pytest.raises(ValueError, match=r"normal must have shape \(3,\)"):
        phong_geometry([[0, 0, 1]], [0, 1, 1], [0, 0, 1])
