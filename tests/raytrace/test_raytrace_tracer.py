"""The ray tracer as a rendering method: shadows, mirrors, glass, sampling, epsilon, errors."""

from __future__ import annotations

import math

import numba
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import pixelpath as pp
from pixelpath.raytrace import ray_tree, tracer
from pixelpath.renderer import render_steps

DARK = pp.Material(color=(1, 1, 1), ka=0.0, kd=0.0, ks=0.0)  # no light of its own
MIRROR = pp.Material(color=(1, 1, 1), ka=0.0, kd=0.0, ks=0.0, reflectivity=1.0)
GLASS = pp.Material(color=(1, 1, 1), ka=0.0, kd=0.0, ks=0.0, transparency=1.0, ior=1.5)


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


# --- shadows --------------------------------------------------------------------------------


def test_a_spheres_shadow_falls_where_geometry_says():
    # Light 4 above the centre of a sphere of radius 0.5: the shadow on the floor is the disc
    # cut by the tangent cone, radius 5·tan(asin(0.5 / 4)).
    radius = 5 * math.tan(math.asin(0.5 / 4))
    scene = pp.Scene(
        pp.Camera(eye=(0, 3, 6), target=(0, 0, 0), fov=30, width=61, height=41),
        [pp.Plane((0, 0, 0), (0, 1, 0)), pp.Sphere((0, 1, 0), 0.5)],
        lights=[pp.PointLight((0, 5, 0))],
        ambient=0.1,
    )
    checked = 0
    for x in range(0, 61, 3):
        for y in range(0, 41, 2):
            node = ray_tree(scene, (x, y), max_depth=0).root
            if node.object != 0:
                continue
            distance = math.hypot(node.point[0], node.point[2])
            if abs(distance - radius) < 0.03:
                continue  # the rim of the shadow falls between two float roundings
            (light,) = node.lights
            assert light.tested
            assert light.let_through == (0.0 if distance < radius else 1.0), (x, y, distance)
            assert light.blocker == (1 if distance < radius else None)
            if distance < radius:  # in the shadow only the ambient term is left
                np.testing.assert_array_equal(node.local, node.ambient)
            checked += 1
    assert checked > 100


# --- mirrors ----------------------------------------------------------------------------------


def test_a_mirror_shows_what_it_faces():
    # A mirror at z = 3 facing the eye at z = 5 shows the sphere behind the eye exactly as an
    # eye at the mirror image z = 1 sees it with the mirror gone, flipped left to right.
    ball = pp.Sphere((0.3, 0.2, 7.5), 1.0, pp.Material(color=(0.9, 0.3, 0.1), ks=0.5))
    lights = [pp.PointLight((2, 3, 4))]
    size = {"fov": 30, "width": 40, "height": 30}
    mirrored = pp.Scene(
        pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), **size),
        [pp.Plane((0, 0, 3), (0, 0, 1), MIRROR), ball],
        lights=lights,
    )
    direct = pp.Scene(
        pp.Camera(eye=(0, 0, 1), target=(0, 0, 8), **size), [ball], lights=lights
    )
    seen = np.asarray(pp.render(mirrored, "raytrace", max_depth=1))
    expected = np.asarray(pp.render(direct, "raytrace"))[:, ::-1]
    assert (expected.max(axis=2) > 0.1).mean() > 0.1  # the sphere fills part of the view
    np.testing.assert_allclose(seen, expected, atol=1e-5)
    assert np.all(pp.render(mirrored, "raytrace", max_depth=0).object_id == 0)


def test_max_depth_zero_draws_the_mirror_black():
    scene = pp.Scene(
        pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6),
        [pp.Plane((0, 0, -2), (0, 0, 1), MIRROR)],
        lights=[pp.PointLight((0, 0, 5))],
        background=(0.5, 0.5, 0.5),
    )
    np.testing.assert_allclose(np.asarray(pp.render(scene, "raytrace", max_depth=0)), 0.0)
    np.testing.assert_allclose(np.asarray(pp.render(scene, "raytrace", max_depth=1)), 0.5)


# --- glass ------------------------------------------------------------------------------------


def test_a_glass_slab_shifts_a_ray_but_does_not_bend_it():
    thickness = 0.5
    slab = pp.Box((-5, -5, -thickness), (5, 5, 0), GLASS)
    scene = pp.Scene(
        pp.Camera(eye=(1.5, 1.0, 4), target=(0, 0, 0), width=21, height=21),
        [slab], lights=[pp.PointLight((0, 3, 3))],
    )
    root = ray_tree(scene, (10, 10), shading="flat").root
    inside = root.refracted
    out = inside.refracted
    assert root.entering and not inside.entering and out.t == math.inf
    d = _unit(root.direction)
    np.testing.assert_allclose(_unit(out.direction), d, atol=1e-12)  # not bent
    theta_i = math.acos(abs(d[2]))  # the slab's faces are normal to z
    theta_t = math.asin(math.sin(theta_i) / 1.5)
    shift = thickness * math.sin(theta_i - theta_t) / math.cos(theta_t)
    # Distance between the incident line and the emerging one.
    gap = out.origin - root.origin
    lateral = np.linalg.norm(gap - np.dot(gap, d) * d)
    assert lateral == pytest.approx(shift, rel=1e-6)


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
def test_no_black_glass_a_clear_sphere_shows_what_lies_straight_behind_it(scale):
    # Through its centre a clear sphere bends nothing: that pixel shows the floor behind it just
    # as it looks with the sphere gone (its shadow lets all the light through).
    def scene(with_glass):
        objects = [pp.Plane((0, 0, -3 * scale), (0, 0, 1))]
        if with_glass:
            objects.append(pp.Sphere((0, 0, 0), scale, GLASS))
        return pp.Scene(
            pp.Camera(eye=(0, 0, 5 * scale), target=(0, 0, 0), width=9, height=9,
                      near=0.1 * scale, far=100 * scale),
            objects, lights=[pp.PointLight((0, 0, 10 * scale))],
        )

    tree = ray_tree(scene(True), (4, 4))
    kinds = [(node.kind, node.object) for node in tree.root.walk() if node.weight > 0.5]
    assert kinds[:4] == [("primary", 1), ("refracted", 1), ("refracted", 0)]
    clear = ray_tree(scene(False), (4, 4))
    np.testing.assert_allclose(tree.color, clear.color, rtol=1e-6)
    assert tree.color.min() > 0.5


def test_total_internal_reflection_turns_the_transmitted_share_into_reflection():
    # A ray entering a cube of dense glass (ior 2.5) through one face meets the next face at
    # more than 90° − asin(1/2.5) = 66.4° from its normal: beyond the critical angle, 23.6°.
    dense = pp.Material(ka=0, kd=0, ks=0, transparency=1.0, ior=2.5)
    scene = pp.Scene(
        pp.Camera(eye=(3, 2.5, 4), target=(0, 0, 0), width=24, height=24),
        [pp.Box((-1, -1, -1), (1, 1, 1), dense)], lights=[pp.PointLight((0, 0, 5))],
    )
    _, report = pp.render(scene, "raytrace", "flat", max_depth=4, explain=True)
    assert report.summary["total internal reflections"] > 0
    found = False
    for x in range(6, 18, 3):
        for node in ray_tree(scene, (x, 12), max_depth=4, shading="flat").root.walk():
            if node.total_internal_reflection:
                assert node.kt == 0.0 and node.kr == 1.0 and node.refracted is None
                assert not node.entering
                found = True
    assert found


def test_schlick_fresnel_at_normal_incidence_is_r0():
    scene = pp.Scene(
        pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=9, height=9),
        [pp.Sphere((0, 0, 0), 1.0, GLASS)], lights=[pp.PointLight((0, 0, 5))],
    )
    root = ray_tree(scene, (4, 4), fresnel=True).root
    r0 = ((1 - 1.5) / (1 + 1.5)) ** 2  # 0.04
    assert root.fresnel == pytest.approx(r0, abs=1e-12)
    assert root.kr == pytest.approx(r0, abs=1e-12) and root.kt == pytest.approx(1 - r0)
    assert ray_tree(scene, (4, 4)).root.fresnel == 0.0


# --- no shadow acne ---------------------------------------------------------------------------


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
@pytest.mark.parametrize("offset", [0.0, 1e4])
def test_no_shadow_acne_a_convex_object_never_shadows_its_lit_side(scale, offset):
    center = np.array([offset, offset, -offset])
    eye = center + np.array([0, scale, 5 * scale])
    objects = [
        pp.Sphere(center, scale),
        pp.scene.icosphere(2, scale, center + np.array([2.5 * scale, 0, 0])),
        pp.Plane(center - (0, scale, 0), (0, 1, 0)),
    ]
    scene = pp.Scene(
        pp.Camera(eye=eye, target=center, width=24, height=16, near=0.1 * scale,
                  far=100 * scale),
        objects, lights=[pp.PointLight(center + np.array([0, 100 * scale, 0]))],
    )
    tested = 0
    for x in range(24):
        for y in range(0, 16, 2):
            # Flat shading: the normal tested is the geometric one, so a light on its side is
            # never behind the object's own faces.
            node = ray_tree(scene, (x, y), max_depth=0, shading="flat").root
            if node.object in (0, 1):  # the light is straight above: nothing else blocks it
                for light in node.lights:
                    assert not light.tested or light.let_through == 1.0, (x, y, node.point)
                    tested += light.tested
    assert tested > 20


# --- sampling, threads, tiles -----------------------------------------------------------------


def _busy_scene(width=48, height=32):
    return pp.Scene(
        pp.Camera(eye=(0, 1.5, 5), target=(0, 0.5, 0), width=width, height=height),
        [
            pp.Plane((0, 0, 0), (0, 1, 0)),
            pp.Sphere((-0.8, 0.6, 0), 0.6, MIRROR),
            pp.Sphere((0.8, 0.6, 0.3), 0.6, GLASS),
            pp.scene.icosphere(1, 0.4, (0.0, 0.4, -1.0)),
        ],
        lights=[pp.PointLight((2, 5, 4)), pp.DirectionalLight(direction=(-1, -1, -1))],
    )


def test_samples_are_identical_across_thread_counts():
    scene = _busy_scene()
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = pp.render(scene, "raytrace", samples=4)
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
        many = pp.render(scene, "raytrace", samples=4)
    finally:
        numba.set_num_threads(before)
    assert np.array_equal(np.asarray(one), np.asarray(many))
    assert np.array_equal(one.object_id, many.object_id)
    assert np.array_equal(one.depth, many.depth)


def test_a_threads_kept_work_space_carries_nothing_from_one_render_to_the_next():
    scene = _busy_scene()
    first = pp.render(scene, "raytrace", samples=4)
    # in between: the same sizes (the work space kept), then smaller ones (made again), which
    # the first scene's second render must not reuse
    pp.render(_busy_scene(width=48, height=20), "raytrace", samples=4)
    pp.render(scene, "raytrace", samples=1, max_depth=0)
    again = pp.render(scene, "raytrace", samples=4)
    assert np.array_equal(np.asarray(first), np.asarray(again))
    assert np.array_equal(first.depth, again.depth)
    assert np.array_equal(first.object_id, again.object_id)
    assert np.array_equal(first.normal, again.normal)


def test_a_threads_kept_work_space_has_the_sizes_of_the_render_at_hand():
    from pixelpath.contract import RenderOptions
    from pixelpath.raytrace._records import new_work
    from pixelpath.raytrace.tracer import _thread_work, pack

    scene = _busy_scene()
    for samples, max_depth, width in [(4, 5, 48), (1, 0, 48), (4, 5, 48), (4, 5, 20)]:
        options = RenderOptions(samples=samples, max_depth=max_depth)
        world, settings, bvh_depth, _ = pack(scene, scene.camera, options)
        work, out = _thread_work(world, settings, bvh_depth, width)
        fresh = new_work(world, settings, bvh_depth, 0, width)
        assert [a.shape for a in work] == [a.shape for a in fresh]
        assert out.shape[0] == width


def test_supersampling_is_seeded_and_smooths_edges():
    scene = _busy_scene()
    first = np.asarray(pp.render(scene, "raytrace", samples=4))
    again = np.asarray(pp.render(scene, "raytrace", samples=4))
    single = np.asarray(pp.render(scene, "raytrace"))
    assert np.array_equal(first, again)
    # Averaging samples leaves more distinct grey levels on edges than one sample does.
    assert len(np.unique(first)) > len(np.unique(single))


@pytest.mark.parametrize("samples", [1, 4])
def test_a_region_equals_the_same_pixels_of_the_whole_image(samples):
    # Primary rays are traced four at a time along a row: regions whose rows hold a number of
    # rays that is not a multiple of four start and end the packets elsewhere.
    scene = _busy_scene()
    whole = pp.render(scene, "raytrace", samples=samples)
    for region in [(0, 0, 20, 12), (20, 12, 48, 32), (7, 5, 31, 29), (3, 2, 10, 9), (5, 0, 6, 32)]:
        x0, y0, x1, y1 = region
        tile = pp.render(scene, "raytrace", samples=samples, region=region)
        assert np.array_equal(np.asarray(tile), np.asarray(whole)[y0:y1, x0:x1])
        assert np.array_equal(tile.object_id, whole.object_id[y0:y1, x0:x1])


def test_progress_reports_every_step_and_the_explanation():
    calls = []
    _, report = pp.render(
        _busy_scene(), "raytrace", explain=True, progress=calls.append
    )
    assert sum(calls) == render_steps("raytrace")
    assert report.method == "raytrace"
    assert report.summary["primary rays"] == 48 * 32
    assert report.summary["reflected rays"] > 0 and report.summary["refracted rays"] > 0


def test_the_ray_tree_adds_up_to_the_rendered_pixel():
    scene = _busy_scene()
    image = np.asarray(pp.render(scene, "raytrace", samples=2))
    for pixel in [(14, 18), (33, 19), (24, 5)]:
        tree = ray_tree(scene, pixel, samples=2)
        np.testing.assert_array_equal(tree.rgb, image[pixel[1], pixel[0]])
        for root in tree.roots:
            assert np.all(np.isfinite(root.color))


# --- bad input ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("options", "error", "message"),
    [
        ({"max_depth": -1}, ValueError, "max_depth"),
        ({"samples": 0}, ValueError, "samples"),
        ({"samples": 2.0}, TypeError, "samples"),
        ({"shading": "gouraud"}, ValueError, "shading"),
    ],
)
def test_bad_options_are_refused(options, error, message):
    with pytest.raises(error, match=message):
        pp.render(_busy_scene(8, 6), "raytrace", **options)


def test_raster_methods_refuse_ray_tracing_options():
    with pytest.raises(ValueError, match="raytrace"):
        pp.render(_busy_scene(8, 6), "zbuffer", samples=4)


def test_ray_tree_refuses_pixels_outside_the_image():
    with pytest.raises(ValueError, match="pixel"):
        ray_tree(_busy_scene(8, 6), (8, 0))
    with pytest.raises(TypeError, match="pixel"):
        ray_tree(_busy_scene(8, 6), (1.5, 0))


# --- eye rays outside the scene's screen bounds ----------------------------------------------

CUBE = np.array([[-1.0, -1.0, -1.0, 1.0, 1.0, 1.0]])


def _shifted(x=0.0, y=0.0, z=0.0):
    return CUBE + np.array([x, y, z, x, y, z])


def _head_on(**options):
    return pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=100, height=100, **options)


def test_screen_bounds_of_a_cube_seen_head_on():
    # Perspective, fov 90: the near face (depth 4, half-width 1) spans ndc ±1/4, pixels
    # 37.5-62.5; orthographic with a view 4 high: ndc ±1/2, pixels 25-75. Then 2 pixels more
    # on each side (SCREEN_MARGIN), after rounding outwards.
    assert tracer.screen_bounds(_head_on(fov=90), CUBE).tolist() == [35, 65, 35, 65]
    orthographic = _head_on(projection="orthographic", view_height=4.0)
    assert tracer.screen_bounds(orthographic, CUBE).tolist() == [23, 77, 23, 77]
    # Moved right by 2: from x = 1 at depth 6 (ndc 1/6, pixel 58.3) to x = 3 at depth 4
    # (ndc 3/4, pixel 87.5).
    moved = _shifted(x=2.0)
    assert tracer.screen_bounds(_head_on(fov=90), moved).tolist() == [56, 90, 35, 65]


def test_screen_bounds_when_nothing_or_everything_can_be_hit():
    camera = _head_on(fov=90)
    whole, nothing = [0, 100, 0, 100], [0, 0, 0, 0]
    assert tracer.screen_bounds(camera, None).tolist() == whole  # a plane
    assert tracer.screen_bounds(camera, np.empty((0, 6))).tolist() == nothing
    assert tracer.screen_bounds(camera, _shifted(z=10.0)).tolist() == nothing  # behind
    assert tracer.screen_bounds(camera, CUBE * 10).tolist() == whole  # the eye inside
    assert tracer.screen_bounds(camera, np.vstack([CUBE, [[-1, -1, 4, 1, 1, 7]]])).tolist() \
        == whole  # one box beside the eye's plane
    assert tracer.screen_bounds(camera, CUBE * [1, 1, 1, 1, 1, np.inf]).tolist() == whole
    # Far to the side: cut to the image, empty.
    assert tracer.screen_bounds(camera, _shifted(x=90.0)).tolist()[:2] == [100, 100]


def _same_render(scene, monkeypatch, **options):
    """Assert a render equals the same render with every eye ray searched."""
    culled = pp.render(scene, "raytrace", **options)
    with monkeypatch.context() as patch:
        patch.setattr(tracer, "screen_bounds", lambda camera, boxes: np.array(
            [0, camera.width, 0, camera.height], dtype=np.intp))
        searched = pp.render(scene, "raytrace", **options)
    for field in ("rgb", "depth", "object_id", "normal", "alpha"):
        assert np.array_equal(getattr(culled, field), getattr(searched, field)), field
    work = ("BVH nodes visited", "triangle tests")  # fewer where rays are not searched
    assert {k: v for k, v in culled.stats.items() if k not in work} == {
        k: v for k, v in searched.stats.items() if k not in work
    }


@settings(max_examples=30, deadline=None)
@given(
    eye=st.tuples(*[st.floats(-4, 4)] * 3),
    target=st.tuples(*[st.floats(-1, 1)] * 3),
    orthographic=st.booleans(),
    size=st.tuples(st.integers(1, 23), st.integers(1, 17)),
    samples=st.sampled_from([1, 2, 4]),
)
def test_eye_rays_left_out_would_have_missed_everything(
    eye, target, orthographic, size, samples
):
    # Meshes and spheres seen from anywhere (inside their boxes too), at sizes whose rows end
    # mid-packet: the pixels, depths, ids, normals and ray counts are those of a render that
    # searches every eye ray. (monkeypatch is function-scoped: hypothesis wants a context.)
    view = np.subtract(target, eye)
    assume(np.linalg.norm(np.cross(view, (0, 1, 0))) > 1e-3)  # a camera needs an up
    projection = {"projection": "orthographic", "view_height": 3.0} if orthographic else {}
    camera = pp.Camera(eye=eye, target=target, width=size[0], height=size[1], **projection)
    scene = pp.Scene(camera, [
        pp.scene.icosphere(2),
        pp.Sphere((1.5, 0.5, 0.0), 0.4),
        pp.scene.Box((-2.0, -1.0, -1.0), (-1.2, 0.0, 0.5)),
    ], lights=[pp.PointLight((2, 4, 3))])
    with pytest.MonkeyPatch.context() as monkeypatch:
        _same_render(scene, monkeypatch, samples=samples)


def test_a_region_and_supersampling_leave_out_the_same_eye_rays(monkeypatch):
    camera = pp.Camera(eye=(0, 0.5, 6), target=(0, 0, 0), width=61, height=37, fov=40)
    scene = pp.Scene(camera, [pp.scene.icosphere(3)], lights=[pp.PointLight((2, 4, 3))])
    _same_render(scene, monkeypatch)
    _same_render(scene, monkeypatch, samples=4, region=(9, 3, 50, 30))
    _same_render(scene, monkeypatch, ssaa=2)
