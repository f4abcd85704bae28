"""shade() and the shade_point kernel against hand-computed intensities."""

from __future__ import annotations

from types import SimpleNamespace

import numba
import numpy as np
import pytest

from pixelpath import scene
from pixelpath.lighting import pack_ambient, pack_lights, pack_material, shade
from pixelpath.lighting._kernels import shade_point


def point_light(position, intensity=1.0, color=(1.0, 1.0, 1.0)):
    return SimpleNamespace(position=position, intensity=intensity, color=color)


def directional_light(direction, intensity=1.0, color=(1.0, 1.0, 1.0)):
    return SimpleNamespace(direction=direction, intensity=intensity, color=color)


# Orange material: colour (1, 0.5, 0.25), ka 0.1, kd 0.5, ks 0.4, n 2.
ORANGE = [1.0, 0.5, 0.25, 0.1, 0.5, 0.4, 2.0, 0.0]
WHITE = [1.0, 1.0, 1.0, 0.1, 0.6, 0.3, 8.0, 0.0]
ORIGIN = [[0.0, 0.0, 0.0]]
UP = [[0.0, 0.0, 1.0]]


def test_coloured_point_light_phong():
    # P = 0, N = z. Light at (0, 3, 4): L = (0, 0.6, 0.8), N.L = 0.8.
    # R = 2(0.8)N - L = (0, -0.6, 0.8); eye at (0, 0, 2): V = (0, 0, 1), R.V = 0.8, ^2 = 0.64.
    # IL = 2 * (1, 1, 0.5) = (2, 2, 1); Ia = (0.3, 0.2, 0.1).
    # ambient  = 0.1 * Ia * C        = (0.03, 0.01, 0.0025)
    # diffuse  = 0.5 * IL * C * 0.8  = 0.4 * (2, 1, 0.25) = (0.8, 0.4, 0.1)
    # specular = 0.4 * IL * 0.64     = 0.256 * (2, 2, 1)  = (0.512, 0.512, 0.256)
    lamp = point_light((0.0, 3.0, 4.0), intensity=2.0, color=(1.0, 1.0, 0.5))
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 2.0), ORANGE, [lamp], ambient=(0.3, 0.2, 0.1))
    np.testing.assert_allclose(rgb, [[1.342, 0.922, 0.3585]], rtol=1e-12)


def test_coloured_point_light_blinn():
    # Same geometry. H = (L + V)/|L + V| = (0, 0.6, 1.8)/sqrt(3.6); N.H = 1.8/sqrt(3.6),
    # (N.H)^2 = 3.24/3.6 = 0.9; specular = 0.4 * IL * 0.9 = (0.72, 0.72, 0.36).
    lamp = point_light((0.0, 3.0, 4.0), intensity=2.0, color=(1.0, 1.0, 0.5))
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 2.0), ORANGE, [lamp], (0.3, 0.2, 0.1), model="blinn")
    np.testing.assert_allclose(rgb, [[1.55, 1.13, 0.4625]], rtol=1e-12)


def test_directional_light_and_light_behind_surface():
    # Sun travelling straight down: L = (0, 0, 1), N.L = 1, R = N; eye on the normal: R.V = 1.
    # I = 0.1 * 0.2 + 0.6 + 0.3 = 0.92 per channel; the lamp under the surface adds nothing.
    sun = directional_light((0.0, 0.0, -3.0))
    below = point_light((0.0, 0.0, -5.0), intensity=10.0)
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 7.0), WHITE, [sun, below], ambient=0.2)
    np.testing.assert_allclose(rgb, [[0.92, 0.92, 0.92]], rtol=1e-12)


def test_no_specular_when_reflection_points_away_even_for_zero_shininess():
    # L = (0, 0.6, 0.8), R = (0, -0.6, 0.8); eye at (0, 5, 0): V = (0, 1, 0), R.V = -0.6 <= 0,
    # so the highlight is 0 (not 0.4 * (-0.6)^0 = 0.4). Diffuse 0.5 * 0.8 * C, ambient 0.
    material = [1.0, 1.0, 1.0, 0.0, 0.5, 0.4, 0.0, 0.0]
    lamp = point_light((0.0, 3.0, 4.0))
    for model in ("phong", "blinn"):
        rgb = shade(ORIGIN, UP, (0.0, 5.0, 0.0), material, [lamp], ambient=0.0, model=model)
        if model == "phong":
            np.testing.assert_allclose(rgb, [[0.4, 0.4, 0.4]], rtol=1e-12)
        else:
            # H = (0, 1.6, 0.8)/|.|, N.H = 0.8/sqrt(3.2) > 0, so n = 0 gives (N.H)^0 = 1:
            # I = 0.4 + 0.4 * 1 = 0.8.
            np.testing.assert_allclose(rgb, [[0.8, 0.8, 0.8]], rtol=1e-12)


def test_no_lights_gives_ambient_times_colour():
    # ka Ia C = 0.1 * (0.5, 0.5, 0.5) * (1, 0.5, 0.25).
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 1.0), ORANGE, [], ambient=0.5)
    np.testing.assert_allclose(rgb, [[0.05, 0.025, 0.0125]], rtol=1e-12)


def test_normals_are_normalized_and_broadcast_over_leading_axes():
    # A (2, 2, 3) grid of points on z = 0 sharing one (unnormalized) normal; a sun straight down
    # and the eye far up give kd + ks (R.V -> 1 as the eye recedes) + ka Ia at every point.
    points = np.zeros((2, 2, 3))
    points[..., 0] = [[0.0, 1.0], [0.0, 1.0]]
    rgb = shade(points, [0.0, 0.0, 5.0], (0.5, 0.0, 1e9), WHITE, [directional_light((0, 0, -1))],
                ambient=0.0)
    assert rgb.shape == (2, 2, 3)
    np.testing.assert_allclose(rgb, 0.9, rtol=1e-9)


def test_shade_point_is_callable_from_another_kernel():
    @numba.njit
    def grid(points, normal, eye, material, lights, ambient, out):
        for i in range(points.shape[0]):
            shade_point(points[i, 0], points[i, 1], points[i, 2], normal[0], normal[1],
                        normal[2], eye[0], eye[1], eye[2], 1.0, material, lights, ambient,
                        False, out[i])

    points = np.array([[0.0, 0.0, 0.0], [1.0, -2.0, 0.0], [3.0, 1.0, 0.0]])
    lamp = point_light((0.0, 3.0, 4.0), intensity=2.0, color=(1.0, 1.0, 0.5))
    lights = pack_lights([lamp])
    out = np.empty((3, 3))
    grid(points, np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, 2.0]), pack_material(ORANGE),
         lights, pack_ambient((0.3, 0.2, 0.1)), out)
    np.testing.assert_allclose(out[0], [1.342, 0.922, 0.3585], rtol=1e-12)
    expected = shade(points, UP, (0.0, 0.0, 2.0), ORANGE, lights, (0.3, 0.2, 0.1))
    np.testing.assert_allclose(out, expected, rtol=1e-12)


def test_pack_lights_layout():
    lamp = point_light((1.0, 2.0, 3.0), intensity=0.5, color=(1.0, 0.8, 0.6))
    sun = directional_light((0.0, -4.0, 3.0), intensity=(1.0, 2.0, 3.0))
    packed = pack_lights([lamp, sun])
    assert packed.dtype == np.float64 and packed.shape == (2, 7)
    np.testing.assert_allclose(packed[0], [0, 1, 2, 3, 0.5, 0.4, 0.3])
    # Direction (0, -4, 3) has length 5; colour white times per-channel intensity.
    np.testing.assert_allclose(packed[1], [1, 0, -0.8, 0.6, 1, 2, 3])
    assert pack_lights([]).shape == (0, 7)
    np.testing.assert_array_equal(pack_lights(packed), packed)
    np.testing.assert_array_equal(pack_lights(lamp), packed[:1])


@pytest.mark.parametrize(
    ("lights", "error", "match"),
    [
        ([SimpleNamespace(intensity=1.0)], TypeError, "position"),
        ([directional_light((0, 0, 0))], ValueError, "zero vector"),
        ([point_light((0, np.nan, 0))], ValueError, "finite"),
        ([point_light((0, 0))], ValueError, r"shape \(3,\)"),
        ([point_light((0, 0, 1), intensity=-1.0)], ValueError, ">= 0"),
        ([point_light((0, 0, 1), intensity=(1.0, 2.0))], ValueError, "intensity"),
        ([point_light("abc")], TypeError, "position"),
        (np.zeros((2, 6)), ValueError, r"\(L, 7\)"),
        (np.full((1, 7), 2.0), ValueError, "kind"),
        (42, TypeError, "lights"),
    ],
)
def test_pack_lights_rejects_bad_input(lights, error, match):
    with pytest.raises(error, match=match):
        pack_lights(lights)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"model": "gouraud"}, ValueError, "model"),
        ({"normals": [[0.0, 0.0, 0.0]]}, ValueError, "normals"),
        ({"points": [[0.0, 0.0]]}, ValueError, "points"),
        ({"points": [[0.0, np.inf, 0.0]]}, ValueError, "points"),
        ({"points": "here"}, TypeError, "points"),
        ({"eye": (0.0, 1.0)}, ValueError, "eye"),
        ({"material": [1.0, 1.0, 1.0, -0.1, 0.5, 0.5, 2.0, 0.0]}, ValueError, "material"),
        ({"material": [1.0, 1.0]}, ValueError, "material"),
        ({"ambient": -0.5}, ValueError, "ambient"),
        ({"ambient": "dim"}, TypeError, "ambient"),
        ({"normals": np.zeros((2, 3)) + 1, "points": np.zeros((3, 3))}, ValueError, "broadcast"),
    ],
)
def test_shade_rejects_bad_input(kwargs, error, match):
    arguments = {
        "points": ORIGIN,
        "normals": UP,
        "eye": (0.0, 0.0, 1.0),
        "material": WHITE,
        "lights": [point_light((0.0, 0.0, 1.0))],
        "ambient": 0.1,
    } | kwargs
    with pytest.raises(error, match=match):
        shade(**arguments)


def test_material_object_with_packed_method():
    material = SimpleNamespace(packed=lambda: np.array(ORANGE))
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 1.0), material, [], ambient=0.5)
    np.testing.assert_allclose(rgb, [[0.05, 0.025, 0.0125]], rtol=1e-12)


def test_scene_lights_and_material_are_accepted():
    lamp = scene.PointLight(position=(0.0, 3.0, 4.0), intensity=2.0, color=(1.0, 1.0, 0.5))
    sun = scene.DirectionalLight(direction=(0.0, 0.0, -2.0), intensity=0.5)
    packed = pack_lights([lamp, sun])
    np.testing.assert_allclose(packed, [[0, 0, 3, 4, 2, 2, 1], [1, 0, 0, -1, 0.5, 0.5, 0.5]])
    material = scene.Material(color=(1.0, 0.5, 0.25), ka=0.1, kd=0.5, ks=0.4, shininess=2.0)
    # The lamp alone gives (1.342, 0.922, 0.3585) (test_coloured_point_light_phong). The sun:
    # L = z, N.L = 1, R = z, R.V = 1: kd IL C + ks IL = 0.5 x 0.5 x C + 0.4 x 0.5
    # = (0.25 + 0.2, 0.125 + 0.2, 0.0625 + 0.2) = (0.45, 0.325, 0.2625).
    rgb = shade(ORIGIN, UP, (0.0, 0.0, 2.0), material, [lamp, sun], ambient=(0.3, 0.2, 0.1))
    np.testing.assert_allclose(rgb, [[1.792, 1.247, 0.621]], rtol=1e-12)


def numpy_reference(points, normals, eye, material, lights, ambient, blinn):
    """The model written independently with NumPy broadcasting (no kernel)."""
    color, (ka, kd, ks, shininess) = np.array(material[:3]), material[3:7]
    n = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    v = eye - points
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    total = np.broadcast_to(ka * np.asarray(ambient) * color, points.shape).copy()
    for light in lights:
        il = np.asarray(light.color) * light.intensity
        if hasattr(light, "position"):
            to_light = light.position - points
            to_light /= np.linalg.norm(to_light, axis=1, keepdims=True)
        else:
            to_light = np.broadcast_to(-np.asarray(light.direction), points.shape)
            to_light = to_light / np.linalg.norm(to_light, axis=1, keepdims=True)
        n_dot_l = np.sum(n * to_light, axis=1)
        if blinn:
            h = to_light + v
            cosine = np.sum(n * h, axis=1) / np.linalg.norm(h, axis=1)
        else:
            cosine = np.sum((2 * n_dot_l[:, None] * n - to_light) * v, axis=1)
        lit = n_dot_l > 0
        spec = np.where(lit & (cosine > 0), np.clip(cosine, 0, None) ** shininess, 0.0)
        total += np.where(lit, n_dot_l, 0.0)[:, None] * kd * il * color + ks * spec[:, None] * il
    return total


@pytest.mark.parametrize("model", ["phong", "blinn"])
def test_agrees_with_numpy_reference_for_many_points_and_coloured_lights(model):
    rng = np.random.default_rng(7)
    points = rng.uniform(-2, 2, size=(200, 3))
    normals = rng.normal(size=(200, 3))
    eye = np.array([0.5, 1.0, 9.0])
    lights = [
        point_light(np.array([0.0, 6.0, 5.0]), 1.0, (1.0, 0.9, 0.8)),
        point_light(np.array([-4.0, 1.0, 3.0]), 0.6, (0.2, 0.3, 1.0)),
        directional_light((1.0, -1.0, -0.5), 0.8, (1.0, 1.0, 0.5)),
    ]
    expected = numpy_reference(points, normals, eye, ORANGE, lights, (0.3, 0.2, 0.1),
                               model == "blinn")
    rgb = shade(points, normals, eye, ORANGE, lights, (0.3, 0.2, 0.1), model=model)
    np.testing.assert_allclose(rgb, expected, rtol=1e-10, atol=1e-12)
    # The sample is not trivial: some points see no light (ambient 0.1 x Ia x C only).
    ambient_only = np.all(np.isclose(rgb, [0.03, 0.01, 0.0025]), axis=1)
    assert 0 < ambient_only.sum() < len(rgb)


def test_many_points_shaded_on_the_threads_equal_the_points_shaded_alone():
    # Enough points to be handed out in runs to the threads; each must get its own shade.
    rng = np.random.default_rng(4)
    points = rng.uniform(-2.0, 2.0, (6000, 3))
    normals = rng.normal(size=(6000, 3))
    lamp = point_light((1.0, 3.0, 4.0), intensity=2.0, color=(1.0, 0.8, 0.5))
    together = shade(points, normals, (0.0, 0.0, 6.0), ORANGE, [lamp], ambient=0.2)
    alone = np.concatenate([
        shade(points[k : k + 1000], normals[k : k + 1000], (0.0, 0.0, 6.0), ORANGE, [lamp],
              ambient=0.2)
        for k in range(0, 6000, 1000)
    ])
    np.testing.assert_array_equal(together, alone)
