"""Ray-sphere, ray-plane, reflection and refraction on hand-derived cases and invariants."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pixelpath.raytrace import ray_plane, ray_sphere, reflect, refract

# --- ray-sphere: the roots of |P0 + t d - C|^2 = r^2 ----------------------------------------


@pytest.mark.parametrize(
    ("origin", "direction", "expected"),
    [
        ((0, 0, 5), (0, 0, -1), 4.0),  # from outside: the near root
        ((0, 0, 5), (0, 0, -2), 2.0),  # t in units of |d|
        ((0, 0, 0), (0, 0, 1), 1.0),  # from the centre: the far side
        ((0, 0, 0.5), (0, 0, -1), 1.5),  # from inside, off centre
        ((0, 1, -5), (0, 0, 1), 5.0),  # tangent: a double root still hits
        ((0, 0, 5), (0, 0, 1), math.inf),  # sphere behind the origin
        ((0, 1.5, 5), (0, 0, -1), math.inf),  # passes beside it
        ((0, 0, 1), (0, 0, 1), math.inf),  # on the surface, leaving: no hit at t = 0
        ((0, 0, 1), (0, 0, -1), 2.0),  # on the surface, going in: the far side
    ],
)
def test_ray_sphere_hand_cases(origin, direction, expected):
    assert ray_sphere(origin, direction, (0, 0, 0), 1.0) == pytest.approx(expected)


def test_ray_sphere_off_axis_hand_case():
    # P0 = (3, 4, 0), d = (-1, 0, 0), C = (0, 4, 0), r = 2: roots t = 1 and t = 5.
    assert ray_sphere((3, 4, 0), (-1, 0, 0), (0, 4, 0), 2.0) == pytest.approx(1.0)


def test_ray_sphere_on_surface_of_a_far_off_sphere_does_not_hit_itself():
    # A hit point computed by the tracer is only within rounding of the surface.
    center = np.array([1e4, -3e3, 2e4])
    direction = np.array([0.3, 0.8, -0.52])
    direction /= np.linalg.norm(direction)
    start = center + 7.0 * direction  # on the sphere of radius 7, leaving outwards
    assert ray_sphere(start, direction, center, 7.0) == math.inf


def test_ray_sphere_broadcasts_many_rays_against_many_spheres():
    origins = np.array([[0, 0, 5], [0, 0, 5], [0, 0, 0]])
    t = ray_sphere(origins, (0, 0, -1), [[0, 0, 0], [0, 0, 0], [0, 0, -3]], [1.0, 2.0, 1.0])
    np.testing.assert_allclose(t, [4.0, 3.0, 2.0])
    grid = ray_sphere(np.full((2, 4, 3), 5.0), (0, 0, -1), (0, 0, 0), 1.0)
    assert grid.shape == (2, 4)


@given(
    st.tuples(*[st.floats(-10, 10)] * 3),
    st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda d: np.linalg.norm(d) > 1e-3),
    st.floats(0.1, 5.0),
)
def test_ray_sphere_hit_lies_on_the_sphere(origin, direction, radius):
    t = ray_sphere(origin, direction, (0.5, -0.5, 1.0), radius)
    if t < math.inf:
        point = np.asarray(origin) + t * np.asarray(direction)
        assert np.linalg.norm(point - (0.5, -0.5, 1.0)) == pytest.approx(radius, rel=1e-6)
        assert t > 0


# --- ray-plane: t = n.(Q - P0) / (n.d) -----------------------------------------------------


@pytest.mark.parametrize(
    ("origin", "direction", "expected"),
    [
        ((0, 2, 0), (0, -1, 0), 2.0),
        ((0, 2, 0), (0, -4, 0), 0.5),
        ((1, 2, 3), (1, -1, 0), 2.0),  # oblique
        ((0, -2, 0), (0, -1, 0), math.inf),  # plane behind
        ((0, 2, 0), (1, 0, 0), math.inf),  # parallel
        ((0, 0, 0), (0, 1, 0), math.inf),  # origin on the plane
        ((0, -2, 0), (0, 1, 0), 2.0),  # from behind: a plane has two sides
    ],
)
def test_ray_plane_hand_cases(origin, direction, expected):
    assert ray_plane(origin, direction, (5, 0, -7), (0, 1, 0)) == pytest.approx(expected)


def test_ray_plane_is_not_the_notes_misprint():
    # The notes print t = n.(P0 - P0)/(n.d) = 0; the plane x + y = 2 seen from (0, 0, 0) along
    # (1, 1, 0) is met at t = 1.
    assert ray_plane((0, 0, 0), (1, 1, 0), (2, 0, 0), (1, 1, 0)) == pytest.approx(1.0)


# --- reflection and refraction -------------------------------------------------------------


def test_reflect_mirrors_the_travelling_direction():
    np.testing.assert_allclose(reflect((1, -1, 0), (0, 1, 0)), [1, 1, 0])
    np.testing.assert_allclose(reflect([[0, 0, -1], [3, 0, -4]], (0, 0, 1)), [[0, 0, 1], [3, 0, 4]])


@pytest.mark.parametrize("angle", [0.0, 10.0, 30.0, 45.0, 60.0, 89.0])
@pytest.mark.parametrize("eta", [1 / 1.5, 1 / 1.33, 1.0])
def test_refract_obeys_snells_law(angle, eta):
    theta = math.radians(angle)
    d = (math.sin(theta), -math.cos(theta), 0.0)
    t = refract(d, (0, 1, 0), eta)
    assert t is not None
    assert np.linalg.norm(t) == pytest.approx(1.0)
    assert t[0] == pytest.approx(eta * math.sin(theta), abs=1e-12)  # n1 sin(i) = n2 sin(t)
    assert t[1] < 0 and t[2] == 0  # goes on through, in the plane of incidence


def test_refract_total_internal_reflection_beyond_the_critical_angle():
    critical = math.degrees(math.asin(1 / 1.5))  # 41.81 degrees, glass to air
    for angle, reflected in [(critical - 0.1, False), (critical + 0.1, True), (80.0, True)]:
        theta = math.radians(angle)
        t = refract((math.sin(theta), -math.cos(theta), 0.0), (0, 1, 0), 1.5)
        assert (t is None) is reflected
    batch = refract([[0.8, -0.6, 0.0], [0.0, -1.0, 0.0]], (0, 1, 0), 1.5)
    assert np.isnan(batch[0]).all()
    np.testing.assert_allclose(batch[1], [0, -1, 0])


def test_two_parallel_interfaces_restore_the_direction():
    d = np.array([0.5, -0.8, 0.2])
    d /= np.linalg.norm(d)
    inside = refract(d, (0, 1, 0), 1 / 1.5)
    out = refract(inside, (0, 1, 0), 1.5)
    np.testing.assert_allclose(out, d, atol=1e-12)


# --- bad input ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: ray_sphere((0, 0, 0), (0, 0, 0), (0, 0, 0), 1), "direction"),
        (lambda: ray_sphere((0, 0, np.nan), (0, 0, 1), (0, 0, 0), 1), "origin"),
        (lambda: ray_sphere((0, 0, 0), (0, 0, 1), (0, 0, 0), -1), "radius"),
        (lambda: ray_sphere((0, 0), (0, 0, 1), (0, 0, 0), 1), "origin"),
        (lambda: ray_sphere(np.zeros((2, 3)), np.ones((3, 3)), (0, 0, 0), 1), "broadcast"),
        (lambda: ray_plane((0, 0, 0), (0, 0, 1), (0, 0, 0), (0, 0, 0)), "normal"),
        (lambda: ray_plane((0, 0, 0), (np.inf, 0, 1), (0, 0, 0), (0, 0, 1)), "direction"),
        (lambda: refract((0, -1, 0), (0, 1, 0), 0.0), "eta"),
        (lambda: refract((0, 1, 0), (0, 1, 0), 1.5), "incident side"),
        (lambda: refract((0, 0, 0), (0, 1, 0), 1.5), "d must not"),
    ],
)
def test_bad_input_raises_value_error_naming_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_non_numeric_input_raises_type_error():
    with pytest.raises(TypeError, match="origin"):
        ray_sphere("here", (0, 0, 1), (0, 0, 0), 1)
