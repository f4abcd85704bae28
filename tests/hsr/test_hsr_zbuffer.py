"""The z-buffer method on scenes whose pictures are known analytically."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp


def pixel_rays(camera):
    """World directions (H, W, 3) through the pixel centres, scaled so that the component
    along the viewing axis is 1 (a hit at r(t) = eye + t d is at view-axis distance t)."""
    u, v, w = camera.basis()
    focal = (camera.height / 2) / np.tan(np.radians(camera.fov) / 2)
    x = (np.arange(camera.width) + 0.5 - camera.width / 2) / focal
    y = (camera.height / 2 - np.arange(camera.height) - 0.5) / focal
    xs, ys = np.meshgrid(x, y)
    return -w + xs[..., None] * u + ys[..., None] * v


def ray_triangle(eye, rays, a, b, c):
    """Ray parameter t of the hit with triangle abc (inf on a miss), by Cramer's rule."""
    e1, e2 = b - a, c - a
    p = np.cross(rays, e2)
    det = p @ e1
    s = eye - a
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = np.sum(s * p, axis=-1) / det
        q = np.cross(s, e1)
        gamma = (rays @ q) / det
        t = (q @ e2) / det
    hit = (beta >= 0) & (gamma >= 0) & (beta + gamma <= 1) & (t > 0)
    return np.where(hit, t, np.inf)


def test_flat_shaded_square_equals_the_illumination_formula():
    # Square of side 2 at z = 0 facing the eye at (0, 0, 5); fov 90 on 40 px gives a focal
    # length of 20 px, so the square covers pixels 16..23 in both directions.
    material = pp.Material(color=(1.0, 0.5, 0.25), ka=0.2, kd=0.6, ks=0.5, shininess=4)
    square = pp.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2, 3]], material)
    light = pp.DirectionalLight(direction=(-1, 0, -1), intensity=0.8)
    camera = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=40, height=40)
    scene = pp.Scene(camera, objects=[square], lights=[light], ambient=0.3)
    # At the centroid: N = (0, 0, 1), L = (1, 0, 1)/sqrt 2, V = (0, 0, 1), R = (-1, 0, 1)/sqrt 2,
    # so N.L = R.V = 0.70711 and I = ka Ia C + kd IL C N.L + ks IL (R.V)^n.
    cos = np.sqrt(0.5)
    colour = np.array([1.0, 0.5, 0.25])
    expected = 0.2 * 0.3 * colour + 0.6 * 0.8 * colour * cos + 0.5 * 0.8 * cos**4
    image = pp.render(scene, shading="flat")
    drawn = image.object_id == 0
    assert drawn.sum() == 64 and drawn[16:24, 16:24].all()
    assert np.allclose(np.asarray(image)[drawn], expected.astype(np.float32), atol=1e-6)
    assert np.allclose(image.depth[drawn], 5.0)


def test_sphere_silhouette_radius():
    # A sphere of radius 1 seen from distance 4 subtends asin(1/4); its outline is a circle of
    # radius focal * tan(asin(1/4)) pixels around the image centre.
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), fov=60, width=201, height=201)
    light = pp.PointLight((3, 3, 3))
    scene = pp.Scene(camera, objects=[pp.Sphere((0, 0, 0), 1.0)], lights=[light])
    image = pp.render(scene, shading="phong")
    focal = 100.5 / np.tan(np.radians(30))
    radius = focal * np.tan(np.arcsin(0.25))
    drawn = image.object_id == 0
    assert np.sqrt(drawn.sum() / np.pi) == pytest.approx(radius, rel=0.01)
    columns = np.flatnonzero(drawn[100])
    assert columns[0] + 0.5 == pytest.approx(100.5 - radius, abs=1.0)
    assert columns[-1] + 0.5 == pytest.approx(100.5 + radius, abs=1.0)
    # The nearest point of the sphere is 3 units from the eye.
    assert image.depth[100, 100] == pytest.approx(3.0, abs=2e-3)


def test_two_planes_in_the_right_depth_order():
    # A floor (y = -1) and a back wall (z = -4): at each pixel the visible plane is the one
    # the pixel's ray meets first, and the depth is that hit's view-axis distance.
    camera = pp.Camera(eye=(0.3, 0.5, 3), target=(0, -0.2, 0), fov=50, width=48, height=36)
    floor = pp.Plane((0, -1, 0), (0, 1, 0), pp.Material(color=(1, 0, 0)))
    wall = pp.Plane((0, 0, -4), (0, 0, 1), pp.Material(color=(0, 0, 1)))
    light = pp.PointLight((0, 3, 2))
    rays = pixel_rays(camera)
    eye = camera.eye
    with np.errstate(divide="ignore"):
        t_floor = (-1 - eye[1]) / rays[..., 1]
        t_wall = (-4 - eye[2]) / rays[..., 2]
    t_floor = np.where(t_floor > 0, t_floor, np.inf)
    t_wall = np.where(t_wall > 0, t_wall, np.inf)
    expected = np.where(t_floor < t_wall, 0, 1)
    clear = np.abs(t_floor - t_wall) > 0.05  # away from the line where the planes meet
    for objects, ids in (([floor, wall], (0, 1)), ([wall, floor], (1, 0))):
        image = pp.render(pp.Scene(camera, objects=objects, lights=[light]), shading="flat")
        assert np.all(image.object_id >= 0)
        seen = np.where(image.object_id == ids[0], 0, 1)
        assert np.array_equal(seen[clear], expected[clear])
        nearest = np.minimum(t_floor, t_wall)
        assert np.allclose(image.depth, nearest, rtol=1e-5)


def test_triangle_crossing_the_near_plane_renders_its_visible_part():
    # One vertex is behind the eye. Clipping in homogeneous space keeps exactly the part in
    # front of the near plane: each pixel is drawn iff its ray hits the triangle, at that depth.
    a, b, c = np.array([-2.0, -1.5, -3.0]), np.array([2.5, -1.0, -4.0]), np.array([0.5, 1.0, 6.0])
    triangle = pp.Mesh([a, b, c], [[0, 1, 2]])
    camera = pp.Camera(eye=(0, 0, 0), target=(0, 0, -1), fov=70, width=64, height=48, near=0.5)
    scene = pp.Scene(camera, objects=[triangle], lights=[pp.PointLight((0, 2, 0))])
    image = pp.render(scene, shading="gouraud", backface_cull=False)
    t = ray_triangle(camera.eye, pixel_rays(camera), a, b, c)
    t = np.where(t >= camera.near, t, np.inf)  # what the near plane removes
    drawn = image.object_id == 0
    disagree = drawn != np.isfinite(t)
    # Only pixels whose centre is within a hair of an edge may go either way.
    assert disagree.sum() <= 2
    both = drawn & np.isfinite(t)
    assert both.sum() > 500
    assert np.allclose(image.depth[both], t[both], rtol=1e-5)


def test_specular_highlight_inside_one_triangle_needs_phong():
    # One big triangle, a light and the eye close above its middle: the mirror highlight
    # falls inside the triangle, far from every vertex. Phong shading evaluates the model
    # there and shows it; Gouraud only interpolates the dull vertex intensities.
    material = pp.Material(color=(0.5, 0.5, 0.5), ka=0.1, kd=0.4, ks=0.6, shininess=200)
    triangle = pp.Mesh([[-6, -4, 0], [6, -4, 0], [0, 6, 0]], [[0, 1, 2]], material)
    # An odd size puts pixel (32, 32)'s centre on the axis, exactly above the mirror point.
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), fov=90, width=65, height=65)
    scene = pp.Scene(camera, objects=[triangle], lights=[pp.PointLight((0, 0, 4))], ambient=0.2)
    phong = np.asarray(pp.render(scene, shading="phong"))[..., 0]
    gouraud = np.asarray(pp.render(scene, shading="gouraud"))[..., 0]
    # At the point straight below the eye: N.L = R.V = 1, I = 0.1*0.2*0.5 + 0.4*0.5 + 0.6.
    peak = 0.01 + 0.2 + 0.6
    assert phong.max() == pytest.approx(peak, abs=1e-6)
    assert np.unravel_index(np.argmax(phong), phong.shape) == (32, 32)
    assert gouraud.max() < 0.5 * peak


def test_render_is_deterministic_and_independent_of_object_order():
    objects = [pp.Sphere((0, 0, 0), 1.0), pp.Box((-0.5, -0.5, -2), (1.5, 0.5, 0.3))]
    camera = pp.Camera(eye=(2, 1.5, 4), target=(0, 0, 0), width=40, height=30)
    light = pp.PointLight((4, 4, 4))
    first = pp.render(pp.Scene(camera, objects=objects, lights=[light]))
    again = pp.render(pp.Scene(camera, objects=objects, lights=[light]))
    swapped = pp.render(pp.Scene(camera, objects=objects[::-1], lights=[light]))
    assert np.array_equal(np.asarray(first), np.asarray(again))
    assert np.array_equal(first.object_id, again.object_id)
    assert np.array_equal(first.depth, swapped.depth)
    both = (first.object_id >= 0) & (swapped.object_id >= 0)
    assert np.array_equal(first.object_id[both], 1 - swapped.object_id[both])
    assert np.allclose(np.asarray(first), np.asarray(swapped), atol=1e-6)


def test_degenerate_faces_render_without_error():
    # Zero-area faces (repeated and collinear corners) beside a good one: drawn, no crash.
    mesh = pp.Mesh(
        [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 0, 3], [0, 1, 3]]
    )
    camera = pp.Camera(eye=(0.3, 0.3, 3), target=(0.3, 0.3, 0), width=20, height=20)
    for cull in (True, False):
        image = pp.render(pp.Scene(camera, objects=[mesh]), shading="flat", backface_cull=cull)
        assert (image.object_id == 0).sum() > 10


def test_picture_does_not_depend_on_the_thread_count():
    import numba

    if numba.config.DISABLE_JIT or numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs compiled kernels and at least two Numba threads")
    objects = [pp.Sphere((0, 0, 0), 1.0), pp.Plane((0, -1, 0), (0, 1, 0))]
    camera = pp.Camera(eye=(0.5, 1, 4), target=(0, 0, 0), width=64, height=200)
    scene = pp.Scene(camera, objects=objects, lights=[pp.PointLight((3, 4, 5))])
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = pp.render(scene)
        numba.set_num_threads(2)
        two = pp.render(scene)
    finally:
        numba.set_num_threads(before)
    assert np.array_equal(np.asarray(one), np.asarray(two))
    assert np.array_equal(one.depth, two.depth)
    assert np.array_equal(one.object_id, two.object_id)


@pytest.mark.parametrize("region", [(0, 0, 48, 70), (5, 13, 37, 45), (0, 40, 48, 20)])
def test_band_buffers_draw_what_the_region_buffers_draw(region):
    # Without explain the z-buffer keeps one band of visibility per thread, not the region's:
    # the same picture, on regions whose rows start and stop inside bands, with an
    # alpha-tested square (its own path through the depth test) in front of a sphere.
    from pixelpath.contract import RenderOptions, View
    from pixelpath.hsr.zbuffer import render_frame

    texture = np.ones((4, 4, 4))
    texture[1:3, 1:3, 3] = 0.0  # a transparent hole
    square = pp.Mesh([[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], [[0, 1, 2, 3]],
                     pp.Material(texture=texture, alpha_cutoff=0.5),
                     uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    camera = pp.Camera(eye=(0.3, 0.4, 5), target=(0, 0, 0), width=48, height=70)
    scene = pp.Scene(camera, [square, pp.Sphere((0, 0, 0), 1.2)], [pp.PointLight((3, 4, 5))])
    view = View(camera, *region)
    kept = render_frame(scene, view, RenderOptions(explain=True))
    banded = render_frame(scene, view, RenderOptions())
    assert (banded.object_id == 1).sum() > 50 and (banded.object_id == 0).sum() > 50
    for name in ("rgb", "depth", "object_id", "normal"):
        assert np.array_equal(getattr(kept, name), getattr(banded, name)), name
