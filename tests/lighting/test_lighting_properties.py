"""Hypothesis invariants of reflect, shade and phong_terms."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pixelpath.lighting import phong_terms, reflect, shade

coordinate = st.floats(-10.0, 10.0, allow_nan=False)
vector = st.tuples(coordinate, coordinate, coordinate).map(np.array)
unit_interval = st.floats(0.0, 1.0)
PROPERTY = settings(max_examples=60, deadline=None)


def unit(v):
    return v / np.linalg.norm(v)


@PROPERTY
@given(l=vector, n=vector)
def test_reflect_preserves_length_and_angle_and_is_an_involution(l, n):  # noqa: E741
    assume(np.linalg.norm(l) > 1e-3 and np.linalg.norm(n) > 1e-3)
    r = reflect(l, n)
    n_unit = unit(n)
    np.testing.assert_allclose(np.linalg.norm(r), np.linalg.norm(l), rtol=1e-9)
    np.testing.assert_allclose(r @ n_unit, l @ n_unit, atol=1e-9 * np.linalg.norm(l))
    np.testing.assert_allclose(reflect(r, n), l, atol=1e-9 * np.linalg.norm(l))


def lamp(position):
    return SimpleNamespace(position=position, intensity=1.0, color=(1.0, 1.0, 1.0))


@PROPERTY
@given(
    light=vector,
    eye=vector,
    normal=vector,
    ka=unit_interval,
    kd=unit_interval,
    ks=unit_interval,
    shininess=st.floats(1.0, 64.0),
    ambient=unit_interval,
)
def test_shade_equals_phong_terms_for_one_white_light_on_white(
    light, eye, normal, ka, kd, ks, shininess, ambient
):
    # The cosines come from plain NumPy here, not from the library.
    assume(min(np.linalg.norm(v) for v in (light, eye, normal)) > 1e-2)
    n, to_light, to_eye = unit(normal), unit(light), unit(eye)
    n_dot_l = n @ to_light
    r_dot_v = (2 * n_dot_l * n - to_light) @ to_eye
    assume(abs(n_dot_l) > 1e-6)  # the highlight jumps to 0 at N.L = 0
    material = [1.0, 1.0, 1.0, ka, kd, ks, shininess, 0.0]
    rgb = shade(np.zeros((1, 3)), n[None], eye, material, [lamp(light)], ambient)
    terms = phong_terms(ka=ka, kd=kd, ks=ks, shininess=shininess, ambient=ambient, light=1.0,
                        n_dot_l=n_dot_l, r_dot_v=r_dot_v)
    np.testing.assert_allclose(rgb[0], [terms.total] * 3, rtol=1e-9, atol=1e-12)


@PROPERTY
@given(light=vector, normal=vector, distance=st.floats(0.5, 20.0), shininess=st.floats(1, 64))
def test_blinn_and_phong_agree_when_the_halfway_vector_is_the_normal(
    light, normal, distance, shininess
):
    # Put the eye on the mirror direction R of L: then H = (L + R)/|L + R| = N and both
    # highlights are 1 ((R.V)^n = (N.H)^n = 1).
    assume(np.linalg.norm(light) > 1e-2 and np.linalg.norm(normal) > 1e-2)
    n, to_light = unit(normal), unit(light)
    assume(n @ to_light > 1e-3)
    eye = distance * (2 * (n @ to_light) * n - to_light)
    material = [1.0, 1.0, 1.0, 0.1, 0.5, 0.4, shininess, 0.0]
    args = (np.zeros((1, 3)), n[None], eye, material, [lamp(light)], 0.1)
    phong, blinn = shade(*args, model="phong"), shade(*args, model="blinn")
    np.testing.assert_allclose(phong, blinn, rtol=1e-9)
    np.testing.assert_allclose(phong, 0.1 * 0.1 + 0.5 * (n @ to_light) + 0.4, rtol=1e-9)


@PROPERTY
@given(
    theta=st.floats(1.0, 80.0),
    alpha=st.floats(1.0, 80.0),
    shininess=st.floats(1.0, 64.0),
)
def test_blinn_and_phong_differ_when_eye_is_off_the_mirror_direction(theta, alpha, shininess):
    # In the plane y = 0 with N = z: L at angle theta from N, V at angle alpha from R
    # (towards N). Then N.H = cos(alpha / 2) > cos(alpha) = R.V, so the highlights differ.
    t, a = np.radians(theta), np.radians(alpha)
    light = [-np.sin(t), 0.0, np.cos(t)]
    view_angle = t - a  # signed angle of V from N in the plane, R being at +t
    eye = [np.sin(view_angle), 0.0, np.cos(view_angle)]
    material = [1.0, 1.0, 1.0, 0.0, 0.0, 1.0, shininess, 0.0]
    args = (np.zeros((1, 3)), [[0.0, 0.0, 1.0]], eye, material, [lamp(light)], 0.0)
    phong, blinn = shade(*args, model="phong")[0, 0], shade(*args, model="blinn")[0, 0]
    np.testing.assert_allclose(phong, np.cos(a) ** shininess, rtol=1e-9)
    np.testing.assert_allclose(blinn, np.cos(a / 2) ** shininess, rtol=1e-9)
    assert blinn > phong


@PROPERTY
@given(
    base=st.fixed_dictionaries(
        {
            "ka": unit_interval,
            "kd": unit_interval,
            "ks": unit_interval,
            "shininess": st.floats(0.0, 100.0),
            "ambient": unit_interval,
            "light": st.floats(0.0, 10.0),
            "n_dot_l": st.floats(-1.0, 1.0),
            "r_dot_v": st.floats(-1.0, 1.0),
        }
    ),
    name=st.sampled_from(["ka", "kd", "ks", "ambient", "light", "shininess"]),
    step=st.floats(0.0, 5.0),
)
def test_total_is_monotone_in_each_coefficient(base, name, step):
    # Raising a coefficient or an intensity never darkens the point; raising the shininess
    # never brightens it (a cosine <= 1 to a higher power is smaller).
    before = phong_terms(**base).total
    after = phong_terms(**(base | {name: base[name] + step})).total
    if name == "shininess":
        assert after <= before + 1e-12
    else:
        assert after >= before - 1e-12
