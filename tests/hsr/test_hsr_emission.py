"""Emission: light a surface gives off itself, I + E, in every method, shading and the tracer."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp

METHODS = ("zbuffer", "scanline", "painter", "bsp", "warnock", "octree")
GLOW = (0.25, 0.5, 0.75)
CAMERA = pp.Camera(eye=(0, 0, 3), target=(0, 0, 0), width=16, height=16)
SQUARE = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]


def glowing_square(**material) -> pp.Mesh:
    return pp.Mesh(SQUARE, [[0, 1, 2, 3]], pp.Material(**material))


@pytest.mark.parametrize(("method", "shading"), [
    *((m, s) for m in METHODS for s in ("flat", "gouraud", "phong")),
    ("raytrace", "flat"), ("raytrace", "phong"),  # the tracer has no Gouraud shading
])
def test_in_the_dark_a_surface_shows_its_emission(method, shading):
    """No light, no ambient: the Phong terms are all zero, so the square is E exactly."""
    scene = pp.Scene(CAMERA, [glowing_square(emission=GLOW)], [], ambient=0.0)
    image = pp.render(scene, method, shading)
    drawn = image.object_id == 0
    assert drawn.sum() > 50
    np.testing.assert_array_equal(image.rgb[drawn], np.tile(np.float32(GLOW), (drawn.sum(), 1)))


@pytest.mark.parametrize("method", [*METHODS, "raytrace"])
def test_emission_adds_to_the_lit_colour(method):
    lights = [pp.PointLight((0, 0, 3), intensity=0.3)]
    plain = pp.render(pp.Scene(CAMERA, [glowing_square()], lights), method)
    glowing = pp.render(pp.Scene(CAMERA, [glowing_square(emission=GLOW)], lights), method)
    drawn = plain.object_id == 0
    expected = np.minimum(plain.rgb[drawn].astype(np.float64) + GLOW, 1.0)
    np.testing.assert_allclose(glowing.rgb[drawn], expected, atol=1e-6)


def test_a_mirror_shows_an_emitting_surface():
    """A mirror ball in the dark, before a glowing wall behind the eye: its reflection is the
    wall's emission (the mirror itself adds nothing), and emission lights nothing else."""
    mirror = pp.Sphere((0, 0, 0), 1.0, pp.Material(ka=0, kd=0, ks=0, reflectivity=1.0))
    wall = pp.Mesh([[-9, -9, 4], [9, -9, 4], [9, 9, 4], [-9, 9, 4]], [[0, 3, 2, 1]],
                   pp.Material(ka=0, kd=0, ks=0, emission=GLOW))
    image = pp.render(pp.Scene(CAMERA, [mirror, wall], [], ambient=0.0), "raytrace")
    np.testing.assert_allclose(image.rgb[8, 8], GLOW, atol=1e-6)


def test_no_emission_changes_nothing():
    """The default emission is zero, and a scene of such materials renders as before: the same
    bits as a scene whose materials say so explicitly (no term added at all)."""
    lights = [pp.PointLight((1, 2, 3))]
    default = pp.Scene(CAMERA, [glowing_square(color=(0.5, 0.2, 0.1))], lights)
    explicit = pp.Scene(CAMERA, [glowing_square(color=(0.5, 0.2, 0.1), emission=(0, 0, 0))],
                        lights)
    for method in (*METHODS, "raytrace"):
        assert np.array_equal(pp.render(default, method).rgb, pp.render(explicit, method).rgb)


def test_emission_is_checked():
    with pytest.raises(ValueError, match="emission components must be non-negative"):
        pp.Material(emission=(-1, 0, 0))
    with pytest.raises(ValueError, match="emission"):
        pp.Material(emission=(1, 0))
