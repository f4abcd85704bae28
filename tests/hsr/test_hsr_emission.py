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


# A 2 x 2 emission picture: left column red, right column green (0 and 1, which its 8-bit
# sRGB texels keep exactly), read by the nearest texel so each half of the square shows one.
GLOW_PICTURE = np.zeros((2, 2, 3))
GLOW_PICTURE[:, 0] = (1.0, 0.0, 0.0)
GLOW_PICTURE[:, 1] = (0.0, 1.0, 0.0)
UV = [[0, 0], [1, 0], [1, 1], [0, 1]]


def textured_glow(**material) -> pp.Mesh:
    material = {"ka": 0, "kd": 0, "ks": 0, "emission": GLOW, "emission_texture": GLOW_PICTURE,
                "texture_filter": "nearest", **material}
    return pp.Mesh(SQUARE, [[0, 1, 2, 3]], pp.Material(**material), uv=UV)


def _halves(image) -> tuple[np.ndarray, np.ndarray]:
    """The drawn pixels of the left and right thirds of the image (clear of the middle)."""
    drawn = image.object_id == 0
    columns = np.arange(drawn.shape[1])
    return (image.rgb[drawn & (columns < 6)[None]], image.rgb[drawn & (columns >= 10)[None]])


@pytest.mark.parametrize(("method", "shading"), [
    *((m, s) for m in METHODS for s in ("flat", "gouraud", "phong")),
    ("raytrace", "flat"), ("raytrace", "phong"),
])
def test_an_emission_texture_scales_the_emission_point_by_point(method, shading):
    """In the dark the square shows E × texel: (0.25, 0, 0) on its left, (0, 0.5, 0) right."""
    scene = pp.Scene(CAMERA, [textured_glow()], [], ambient=0.0)
    left, right = _halves(pp.render(scene, method, shading))
    assert len(left) > 20 and len(right) > 20
    np.testing.assert_array_equal(left, np.tile(np.float32([0.25, 0.0, 0.0]), (len(left), 1)))
    np.testing.assert_array_equal(right, np.tile(np.float32([0.0, 0.5, 0.0]), (len(right), 1)))


@pytest.mark.parametrize("method", [*METHODS, "raytrace"])
def test_a_textured_emission_adds_to_a_textured_lit_surface(method):
    """A colour texture lit from the front, then the same square also glowing through its
    emission texture: the difference is E × the emission texel, pixel by pixel."""
    lights = [pp.PointLight((0, 0, 3), intensity=0.3)]
    paint = {"ka": 0.1, "kd": 0.7, "ks": 0.3, "texture": np.full((2, 2, 3), 0.5)}
    plain = pp.render(pp.Scene(CAMERA, [textured_glow(**paint, emission=(0, 0, 0))], lights),
                      method)
    glowing = pp.render(pp.Scene(CAMERA, [textured_glow(**paint)], lights), method)
    drawn = plain.object_id == 0
    texel = np.where(np.arange(16)[None, :, None] < 8, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    added = (np.broadcast_to(texel, (16, 16, 3)) * GLOW)[drawn]
    expected = np.minimum(plain.rgb[drawn].astype(np.float64) + added, 1.0)
    np.testing.assert_allclose(glowing.rgb[drawn], expected, atol=1e-6)


def test_a_mirror_shows_a_textured_emission():
    """The mirror ball before a glowing wall behind the eye (its uv span the wall): the
    reflection shows E × the wall's texels."""
    mirror = pp.Sphere((0, 0, 0), 1.0, pp.Material(ka=0, kd=0, ks=0, reflectivity=1.0))
    wall = pp.Mesh([[-9, -9, 4], [9, -9, 4], [9, 9, 4], [-9, 9, 4]], [[0, 3, 2, 1]],
                   pp.Material(ka=0, kd=0, ks=0, emission=GLOW,
                               emission_texture=GLOW_PICTURE, texture_filter="nearest"),
                   uv=UV)
    image = pp.render(pp.Scene(CAMERA, [mirror, wall], [], ambient=0.0), "raytrace")
    # u runs along x on the wall: the ball's left half reflects the wall's left (red) half
    np.testing.assert_allclose(image.rgb[8, 7], [0.25, 0.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(image.rgb[8, 8], [0.0, 0.5, 0.0], atol=1e-6)


@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_an_emission_texture_is_left_out_without_uv_or_emission(method):
    """No texture coordinates: E alone, as a colour texture is left out there. No emission:
    nothing, whatever the picture."""
    no_uv = pp.Mesh(SQUARE, [[0, 1, 2, 3]], textured_glow().material)
    image = pp.render(pp.Scene(CAMERA, [no_uv], [], ambient=0.0), method)
    drawn = image.object_id == 0
    np.testing.assert_array_equal(image.rgb[drawn], np.tile(np.float32(GLOW), (drawn.sum(), 1)))
    dark = pp.render(pp.Scene(CAMERA, [textured_glow(emission=(0, 0, 0))], [], ambient=0.0),
                     method)
    assert not dark.rgb.any()


def test_the_ray_tree_names_the_emission_texture():
    from pixelpath.raytrace.explain import ray_tree

    scene = pp.Scene(CAMERA, [textured_glow()], [], ambient=0.0)
    assert "emission E = (0.25, 0.5, 0.75) × the emission texture there" in str(
        ray_tree(scene, (8, 8)))


def test_an_emission_texture_is_checked():
    assert pp.Material(emission_texture=GLOW_PICTURE).emission_texture.width == 2
    with pytest.raises((TypeError, ValueError), match="texture"):
        pp.Material(emission_texture=np.zeros((2, 2, 7)))
