"""Orthographic cameras in every hidden-surface method and in the ray tracer.

Hand-derived cases (an axis-aligned box covers exactly the pixels it should, whatever its
distance; the depth of a slanted face at each pixel; back faces at the edges of a wide view,
where the orthographic test N · d differs from the perspective one N · (P - eye)), then the
agreement scenes of ``agreement.py`` seen orthographically.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from agreement import KINDS, check_agreement, id_edges, scene_of

import pixelpath as pp

RASTER = ["zbuffer", "scanline", "painter", "bsp", "warnock", "octree"]
EVERY = [*RASTER, "raytrace"]


def ortho_camera(width=40, height=20, view_height=2.0, eye=(0.0, 0.0, 10.0), **kwargs):
    return pp.Camera(eye=eye, target=(eye[0], eye[1], 0.0), width=width, height=height,
                     projection="orthographic", view_height=view_height, **kwargs)


def render(scene, method, **options):
    if method == "raytrace":
        options.setdefault("max_depth", 0)
    return pp.render(scene, method, **options)


@pytest.mark.parametrize("method", EVERY)
@pytest.mark.parametrize("z", [2.0, -30.0])
def test_box_covers_the_predicted_rectangle_at_any_distance(method, z):
    # 10 pixels per world unit (a view 4 x 2 units on 40 x 20 pixels) centred at (0, 0).
    # x in [-1.23, 0.77] covers the pixel centres at x = -1.2 .. 0.7: columns 8 .. 27;
    # y in [-0.52, 0.38] covers y = -0.5 .. 0.3: rows 6 .. 14 (row 0 at the top, y = +0.95).
    box = pp.Box((-1.23, -0.52, z - 1.0), (0.77, 0.38, z + 1.0))
    scene = pp.Scene(ortho_camera(), objects=[box], lights=[pp.PointLight((5, 5, 20))])
    image = render(scene, method)
    expected = np.zeros((20, 40), dtype=bool)
    expected[6:15, 8:28] = True
    np.testing.assert_array_equal(image.object_id >= 0, expected)
    # Depth is the distance along the view from the eye (z = 10) to the front face.
    np.testing.assert_allclose(image.depth[expected], 10.0 - (z + 1.0), rtol=1e-6)
    assert np.all(np.isinf(image.depth[~expected]))


@pytest.mark.parametrize("method", EVERY)
def test_depth_of_a_slanted_face_is_known_at_every_pixel(method):
    # The plane z = -0.25 x, facing the camera (normal (0.25, 0, 1)): depth = 10 + 0.25 x.
    corners = [(-3.0, -2.0, 0.75), (3.0, -2.0, -0.75), (3.0, 2.0, -0.75), (-3.0, 2.0, 0.75)]
    quad = pp.Mesh(corners, [[0, 1, 2, 3]])
    scene = pp.Scene(ortho_camera(), objects=[quad], lights=[pp.PointLight((0, 0, 20))])
    image = render(scene, method)
    assert np.all(image.object_id == 0)
    x = (np.arange(40) + 0.5) / 10.0 - 2.0
    np.testing.assert_allclose(image.depth, np.broadcast_to(10.0 + 0.25 * x, (20, 40)),
                               rtol=1e-6)


def _tilted_triangle(center, tilt_degrees):
    """A triangle through ``center`` whose normal leans from +z towards +x by the tilt."""
    angle = np.radians(tilt_degrees)
    normal = np.array([np.sin(angle), 0.0, np.cos(angle)])
    along = np.array([np.cos(angle), 0.0, -np.sin(angle)])  # in the plane, in xz
    up = np.array([0.0, 1.0, 0.0])
    center = np.asarray(center, dtype=float)
    points = [center - 4 * along - 3 * up, center + 4 * along - 3 * up, center + 3 * up]
    assert np.cross(points[1] - points[0], points[2] - points[0]) @ normal > 0  # CCW from N
    return points


@pytest.mark.parametrize("method", EVERY)
def test_back_faces_at_the_edges_of_a_wide_view_follow_the_view_direction(method):
    # A view 80 x 40 units wide, looking down -z from (0, 0, 10). Right edge: a face turned
    # 75 degrees away from the view axis, towards +x: N . d < 0, so it faces the camera (a
    # perspective eye at the centre would see its back: N . (P - eye) > 0). Left edge: a face
    # turned 95 degrees: N . d > 0, a back face (the perspective test would keep it).
    camera = ortho_camera(width=160, height=80, view_height=40.0)
    front = pp.Mesh(_tilted_triangle((35.0, 0.0, 0.0), 75.0), [[0, 1, 2]])
    back = pp.Mesh(_tilted_triangle((-35.0, 0.0, 0.0), 95.0), [[0, 1, 2]])
    scene = pp.Scene(camera, objects=[front, back], lights=[pp.PointLight((0, 0, 20))])
    eye = camera.eye
    assert front.face_normals[0] @ (np.array([35.0, 0, 0]) - eye) > 0  # perspective: culled
    assert back.face_normals[0] @ (np.array([-35.0, 0, 0]) - eye) < 0  # perspective: kept
    culled = render(scene, method)
    drawn = set(np.unique(culled.object_id).tolist())
    assert drawn == {-1, 0}, f"{method} drew objects {drawn}"
    both = render(scene, method, backface_cull=False)
    assert set(np.unique(both.object_id).tolist()) == {-1, 0, 1}


def test_front_facing_takes_the_orthographic_viewpoint():
    from pixelpath.hsr.backface import front_facing

    camera = ortho_camera(width=160, height=80, view_height=40.0)
    normals = [[np.sin(np.radians(75)), 0, np.cos(np.radians(75))],
               [np.sin(np.radians(95)), 0, np.cos(np.radians(95))]]
    points = [[35.0, 0, 0], [-35.0, 0, 0]]
    assert front_facing(normals, points, camera.viewpoint()).tolist() == [True, False]
    assert front_facing(normals, points, camera.eye).tolist() == [False, True]


def _orthographic(scene: pp.Scene, view_height: float = 4.0) -> pp.Scene:
    camera = dataclasses.replace(scene.camera, projection="orthographic",
                                 view_height=view_height)
    return dataclasses.replace(scene, camera=camera)


# Without the JIT the BSP method cuts the floor's grid in plain Python (about 40 s), and the
# interpenetrating and separate scenes' in 12 s each: those cases run in the main pass only;
# the near scene's keeps the BSP method in the pass without the JIT.
@pytest.mark.parametrize(
    ("kind", "method"),
    [
        pytest.param(kind, method, marks=pytest.mark.slow)
        if method == "bsp" and kind != "near" else (kind, method)
        for kind in KINDS
        for method in RASTER[1:]
    ],
)
def test_methods_agree_with_the_zbuffer_orthographically(method, kind):
    check_agreement(_orthographic(scene_of(kind, seed=1)), method)


@pytest.mark.parametrize(
    "method", [pytest.param(m, marks=pytest.mark.slow) if m == "bsp" else m for m in RASTER[1:]]
)
def test_methods_agree_orthographically_with_back_faces_drawn(method):
    check_agreement(_orthographic(scene_of("near", seed=3)), method, backface_cull=False)


@pytest.mark.parametrize("kind", KINDS)
def test_raytrace_ids_and_depths_equal_the_zbuffers_orthographically(kind):
    scene = _orthographic(scene_of(kind, seed=5))
    reference = pp.render(scene, "zbuffer")
    image = pp.render(scene, "raytrace", max_depth=0)
    same = image.object_id == reference.object_id
    assert same.mean() >= 0.99
    assert not (~same & ~id_edges(reference.object_id)).any()
    spheres = [k for k, o in enumerate(scene.objects) if isinstance(o, pp.Sphere)]
    exact = same & ~np.isin(reference.object_id, spheres) & np.isfinite(reference.depth)
    np.testing.assert_allclose(image.depth[exact], reference.depth[exact], rtol=1e-4)



@pytest.mark.parametrize("style", ["wireframe", "hidden-line"])
def test_lines_have_the_same_pixels_at_any_distance_and_the_nearest_edges_depth(style):
    # Seen along its axis, the box's back edges project onto its front edges: the line pixels
    # (cells [i, i + 1) x [j, j + 1) under the ends, 10 pixels per unit) are the same at both
    # distances and carry the depth of the front face's edges.
    pixels = []
    for z in (2.0, -30.0):
        box = pp.Box((-1.23, -0.52, z - 1.0), (0.77, 0.38, z + 1.0))
        scene = pp.Scene(ortho_camera(), objects=[box], lights=[pp.PointLight((5, 5, 20))])
        image = pp.render(scene, style=style)
        drawn = np.isfinite(image.depth)
        np.testing.assert_allclose(image.depth[drawn], 10.0 - (z + 1.0), rtol=1e-6)
        pixels.append(drawn)
    np.testing.assert_array_equal(pixels[0], pixels[1])
    rows, columns = np.nonzero(pixels[0])
    assert (rows.min(), rows.max(), columns.min(), columns.max()) == (6, 15, 7, 27)


@pytest.mark.parametrize("method", ["zbuffer", "scanline", "octree"])
def test_reports_name_the_depth_key_of_the_projection(method):
    box = pp.Box((-1.0, -0.5, -1.0), (1.0, 0.5, 1.0))
    scene = pp.Scene(ortho_camera(), objects=[box], lights=[pp.PointLight((5, 5, 20))])
    _, report = pp.render(scene, method, explain=True)
    assert any("(3 − z_ndc)/2" in note for note in report.notes)
    perspective = dataclasses.replace(scene, camera=pp.Camera(eye=(0, 0, 10), target=(0, 0, 0)))
    _, report = pp.render(perspective, method, explain=True)
    assert any("1/w" in note for note in report.notes)
    assert not any("z_ndc" in note for note in report.notes)


@pytest.mark.parametrize("shading", ["phong", "gouraud"])
def test_an_orthographic_highlight_sits_where_the_ray_tracer_puts_it(shading):
    # V is the view's direction at every point: the highlight of a light straight ahead sits
    # over the sphere's centre, off the image's centre, as the ray tracer finds it (a point
    # eye at the camera's position would pull it towards the image's centre).
    camera = pp.Camera(eye=(3, 0, 3), target=(3, 0, 0), projection="orthographic",
                       view_height=4, width=160, height=120)
    shiny = pp.Material(ks=0.8, shininess=50)
    scene = pp.Scene(camera, [pp.Sphere((4, 0, 0), 1.5, shiny)], [pp.PointLight((4, 0, 20))])
    traced = np.asarray(pp.render(scene, "raytrace")).sum(axis=2)
    drawn = np.asarray(pp.render(scene, "zbuffer", shading)).sum(axis=2)
    traced_at = np.unravel_index(traced.argmax(), traced.shape)
    drawn_at = np.unravel_index(drawn.argmax(), drawn.shape)
    # The sphere's centre is 1 unit = 30 pixels right of the image's centre (column 80).
    assert traced_at[1] > 100
    assert abs(drawn_at[0] - traced_at[0]) <= 1 and abs(drawn_at[1] - traced_at[1]) <= 1


def test_a_wide_orthographic_view_of_a_plane_is_covered_to_its_edges():
    # A view 400 units wide at a near far plane: the plane's square must reach the view's
    # sides (fitted to the width of the view, not to a field of view).
    camera = pp.Camera(eye=(0, 5, 0.001), target=(0, 0, 0), projection="orthographic",
                       view_height=300, width=64, height=48, far=50)
    scene = pp.Scene(camera, [pp.Plane((0, 0, 0), (0, 1, 0))], [pp.PointLight((0, 10, 0))])
    for method in ("zbuffer", "raytrace"):
        assert np.all(pp.render(scene, method).object_id == 0), method
