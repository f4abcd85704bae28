"""Alpha-tested materials (glTF alphaMode MASK) cut holes in every method and the ray tracer.

Expected pixels come from independent NumPy geometry (tests/alpha_scenes.py), never from the
renderer itself. The ray tracer's secondary rays through holes: tests/raytrace.
"""

from __future__ import annotations

import numpy as np
import pytest
from agreement import check_agreement

import pixelpath as pp
from alpha_scenes import (
    BLUE,
    HOLES,
    OPAQUE,
    SQUARE,
    SQUARE_UV,
    camera,
    expected_holes,
    facing_scene,
    holed_quad,
    texel_under,
    unlit,
    wall,
)
from camera_rays import view_rays
from pixelpath.scene import icosphere, torus
from pixelpath.scene.texture import surface_tables

RASTER = ["zbuffer", "scanline", "painter", "bsp", "warnock", "octree"]
EVERY_METHOD = [*RASTER, "raytrace"]
METHOD_SHADINGS = [(m, s) for m in RASTER for s in ("flat", "gouraud", "phong")] + [
    ("raytrace", "phong"), ("raytrace", "flat"),
]


# --- holes in every method ------------------------------------------------------------------


@pytest.mark.parametrize(("method", "shading"), METHOD_SHADINGS)
def test_transparent_texels_show_the_wall_behind(method, shading):
    image = pp.render(facing_scene([holed_quad(), wall()]), method, shading)
    kept, clear, colour = expected_holes(3.0)
    ids, rgb = image.object_id, np.asarray(image)
    np.testing.assert_array_equal(ids[clear], np.where(kept, 0, 1)[clear])
    np.testing.assert_array_equal(rgb[clear & kept], colour[clear & kept])
    np.testing.assert_array_equal(rgb[clear & ~kept], np.broadcast_to(BLUE, rgb.shape)[
        clear & ~kept])
    # the depth seen through a hole is the wall's (4 from the eye), the quad's 3
    np.testing.assert_allclose(image.depth[clear], np.where(kept, 3.0, 4.0)[clear], rtol=1e-6)
    assert (kept & clear).sum() > 50 and (~kept & clear).sum() > 200


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_a_hole_over_nothing_shows_the_background(method):
    scene = pp.Scene(camera(), [holed_quad()], [pp.PointLight((0, 0, 5))], ambient=1.0,
                     background=(0.2, 0.3, 0.4))
    image = pp.render(scene, method)
    kept, clear, _ = expected_holes(3.0)
    np.testing.assert_array_equal(image.object_id[clear], np.where(kept, 0, -1)[clear])
    np.testing.assert_array_equal(image.alpha[clear], kept[clear].astype(np.float32))
    assert np.isinf(image.depth[clear & ~kept]).all()
    np.testing.assert_allclose(np.asarray(image)[clear & ~kept], [[0.2, 0.3, 0.4]] * int(
        (clear & ~kept).sum()), atol=1e-6)


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_holes_in_front_of_holes(method):
    # Two holed quads, the far one turned by 90 degrees (its opaque texels where the near one
    # has holes): together they cover the square; the wall shows nowhere inside it.
    far = holed_quad(z=-0.5)
    far = pp.Mesh(far.vertices, far.faces, far.material, uv=[[1, 0], [1, 1], [0, 1], [0, 0]])
    image = pp.render(facing_scene([holed_quad(), far, wall()]), method)
    kept_near, clear, _ = expected_holes(3.0)
    rays = view_rays(camera())
    inside_far, clear_far, row, column = texel_under(3.5 * rays[..., 0], 3.5 * rays[..., 1])
    # the far quad's uv are turned: its texel (row, column) is the picture's (column, 1 - row)
    kept_far = inside_far & OPAQUE[column, 1 - row]
    expected = np.where(kept_near, 0, np.where(kept_far, 1, 2))
    check = clear & clear_far
    np.testing.assert_array_equal(image.object_id[check], expected[check])
    assert (expected[check] == 1).sum() > 50


def _bilinear_mask_scene() -> pp.Scene:
    """An oblique, bilinearly filtered mask with soft alpha over objects that cross it."""
    rng = np.random.default_rng(5)
    alpha = rng.uniform(0, 1, (6, 6, 1))
    leaf = np.concatenate([rng.uniform(0.3, 1, (6, 6, 3)), alpha], axis=2)
    quad = pp.Mesh(np.array(SQUARE, float) * 1.5, [[0, 1, 2, 3]],
                   pp.Material(color=(0.9, 0.8, 0.3), texture=leaf, texture_filter="bilinear",
                               alpha_cutoff=0.45, double_sided=True),
                   uv=SQUARE_UV)
    quad = quad.transformed(pp.scene.transform_matrix(rotate=(-35, 20, 0), translate=(0, 0.4, 0)))
    objects = [quad, torus(1.0, 0.3, 24, 12, material=pp.Material(color=(0.3, 0.5, 0.9))),
               icosphere(2, 0.6, (0.8, 0.2, -0.6), pp.Material(color=(0.9, 0.3, 0.3))),
               wall(z=-2.5, color=(0.5, 0.5, 0.5))]
    return pp.Scene(
        pp.Camera(eye=(0.5, 1.5, 4.5), target=(0, 0.2, 0), fov=45, width=96, height=72),
        objects, [pp.PointLight((3, 5, 4))],
    )


# Without the JIT the BSP case takes 15 s (its tree cuts the torus): the main pass only.
@pytest.mark.parametrize(
    "method",
    [pytest.param(m, marks=pytest.mark.slow) if m == "bsp" else m
     for m in [*RASTER[1:], "raytrace"]],
)
def test_every_method_cuts_the_zbuffers_holes_in_a_bilinear_mask(method):
    # Every method must cut the same holes as the z-buffer, pixel for pixel up to the
    # z-buffer's edges (the agreement rule of the hidden-surface tests); the ray tracer,
    # which samples the mask at its own hit points, on 98 % of the pixels.
    scene = _bilinear_mask_scene()
    reference = pp.render(scene, "zbuffer")
    assert 0.05 < np.mean(reference.object_id == 0) < 0.5  # holes and leaf both in view
    if method == "raytrace":
        traced = pp.render(scene, "raytrace")
        assert np.mean(traced.object_id == reference.object_id) > 0.98
    else:
        check_agreement(scene, method)


# --- what is cut --------------------------------------------------------------------------


def one_texel_quad(texel_alpha: float, colors=None, **material) -> pp.Mesh:
    texture = np.ones((1, 1, 4))
    texture[..., 3] = texel_alpha
    return pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(texture=texture, **material), uv=SQUARE_UV,
                   colors=colors)


@pytest.mark.parametrize(
    ("quad", "drawn"),
    [
        (one_texel_quad(0.4, alpha_cutoff=0.5), False),
        (one_texel_quad(0.4, alpha_cutoff=0.3), True),
        (one_texel_quad(0.0), True),  # opaque (no cutoff): alpha is ignored
        (one_texel_quad(0.0, alpha_cutoff=0.0), True),  # nothing is below 0
        (one_texel_quad(0.8, alpha=0.5, alpha_cutoff=0.5), False),  # 0.5 x 0.8 = 0.4
        (one_texel_quad(1.0, alpha=0.6, alpha_cutoff=0.5), True),
        (one_texel_quad(1.0, colors=[[1, 1, 1, 0.25]] * 4, alpha_cutoff=0.5), False),
        (one_texel_quad(1.0, colors=[[1, 1, 1, 0.75]] * 4, alpha_cutoff=0.5), True),
        (one_texel_quad(1.0, alpha_cutoff=1.5), False),  # above 1 cuts everything
    ],
    ids=["below", "above", "opaque", "cutoff-0", "material-alpha", "material-alpha-kept",
         "vertex-alpha", "vertex-alpha-kept", "cutoff-above-1"],
)
@pytest.mark.parametrize("method", ["zbuffer", "scanline", "warnock", "raytrace"])
def test_the_alpha_tested_is_material_x_vertex_x_texture(quad, drawn, method):
    image = pp.render(facing_scene([quad, wall()]), method)
    assert image.object_id[16, 16] == (0 if drawn else 1)


# BSP splits the 5120-triangle icosphere: a minute or more without Numba's JIT, so the fast
# passes leave it to the main one (which runs every test).
@pytest.mark.parametrize(
    "method", [pytest.param(m, marks=pytest.mark.slow) if m == "bsp" else m for m in EVERY_METHOD]
)
def test_untextured_objects_below_their_cutoff_vanish(method):
    # A sphere's alpha is its material's: below the cutoff it is cut away everywhere (the ray
    # tracer's analytic sphere as the rasterizer's icosphere), above it it is drawn.
    gone = pp.Sphere((0, 0, 0), 0.8, unlit(alpha=0.2, alpha_cutoff=0.5))
    kept = pp.Sphere((0, 0, 0), 0.8, unlit(alpha=0.6, alpha_cutoff=0.5))
    plane = pp.Plane((0, 0, -1), (0, 0, 1), unlit(alpha=0.1, alpha_cutoff=0.5))
    assert (pp.render(facing_scene([gone, wall()]), method).object_id[16, 16]) == 1
    assert (pp.render(facing_scene([kept, wall()]), method).object_id[16, 16]) == 0
    assert (pp.render(facing_scene([plane]), method).object_id == -1).all()


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_an_opaque_texture_under_a_cutoff_draws_the_same_bits(method):
    # A cutoff that the alpha never falls below is not even tested (surface_tables leaves it
    # out), and the picture is the one without it, bit for bit.
    picture = HOLES.copy()
    picture[..., 3] = 200  # alpha 0.78 everywhere
    plain = pp.Mesh(SQUARE, [[0, 1, 2, 3]], pp.Material(texture=picture), uv=SQUARE_UV)
    masked = pp.Mesh(SQUARE, [[0, 1, 2, 3]], pp.Material(texture=picture, alpha_cutoff=0.7),
                     uv=SQUARE_UV)
    assert surface_tables([masked]).alpha.tolist() == [[1.0, 0.0]]
    scenes = [facing_scene([quad, wall()], eye=(0.5, 0.8, 3)) for quad in (plain, masked)]
    first, second = (pp.render(scene, method) for scene in scenes)
    np.testing.assert_array_equal(np.asarray(first), np.asarray(second))
    np.testing.assert_array_equal(first.depth, second.depth)


def test_regions_and_ssaa_cut_the_same_holes():
    scene = facing_scene([holed_quad(), wall()])
    whole = pp.render(scene)
    part = pp.render(scene, region=(5, 7, 25, 25))
    np.testing.assert_array_equal(part.object_id, whole.object_id[7:25, 5:25])
    smooth = pp.render(scene, ssaa=2)
    kept, clear, _ = expected_holes(3.0)
    np.testing.assert_array_equal(smooth.object_id[clear], np.where(kept, 0, 1)[clear])


@pytest.mark.parametrize("method", ["scanline", "warnock"])
def test_explain_reports_say_how_holes_are_decided(method):
    _, report = pp.render(facing_scene([holed_quad(), wall()]), method, explain=True)
    assert any("alpha-tested" in note for note in report.notes)
    _, plain = pp.render(facing_scene([wall()]), method, explain=True)
    assert not any("alpha-tested" in note for note in plain.notes)
