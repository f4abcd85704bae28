"""Back-face culling: the N·V convention (V from the eye into the scene) and its effect."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.hsr.backface import front_facing


def test_convention_v_from_the_eye_into_the_scene():
    # Eye on +z looking at faces in the plane z = 0: V = P - eye points to -z.
    normals = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    points = np.zeros((4, 3))
    # N.V = -5 (visible), +5 (back face), 0 (edge-on: culled), degenerate N = 0 (culled).
    assert front_facing(normals, points, (0, 0, 5)).tolist() == [True, False, False, False]


def test_cube_seen_from_a_corner_shows_three_faces():
    mesh = pp.Box((-1, -1, -1), (1, 1, 1)).to_mesh()
    points = mesh.vertices[mesh.face_indices[mesh.face_offsets[:-1]]]
    assert front_facing(mesh.face_normals, points, (4, 5, 6)).sum() == 3


def test_shapes_are_checked():
    with pytest.raises(ValueError, match="shape"):
        front_facing(np.zeros((2, 3)), np.zeros((3, 3)), (0, 0, 1))
    with pytest.raises(ValueError, match="eye"):
        front_facing(np.zeros((2, 3)), np.zeros((2, 3)), (0, 1))


def scene(objects, eye=(3, 2, 4), size=(40, 30)):
    camera = pp.Camera(eye=eye, target=(0, 0, 0), width=size[0], height=size[1])
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((5, 5, 5))])


def test_culling_does_not_change_a_closed_convex_mesh():
    box = scene([pp.Box((-1, -1, -1), (1, 1, 1))])
    culled = pp.render(box, shading="flat")
    both = pp.render(box, shading="flat", backface_cull=False)
    assert np.array_equal(np.asarray(culled), np.asarray(both))
    assert np.array_equal(culled.depth, both.depth)


def test_camera_inside_a_closed_mesh_sees_nothing_when_culling():
    # From inside a box every face turns away from the eye: culled, nothing drawn. With
    # culling off the inside walls fill the whole view, lit as two-sided faces.
    inside = scene([pp.Box((-5, -5, -5), (5, 5, 5))], eye=(0.5, 0.2, 1.0))
    culled = pp.render(inside, shading="flat")
    assert np.all(culled.object_id == -1) and np.all(np.isinf(culled.depth))
    walls = pp.render(inside, shading="flat", backface_cull=False)
    assert np.all(walls.object_id == 0)
    assert np.all(np.asarray(walls) > 0)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_back_of_a_quad_is_lit_like_its_front_when_two_sided(shading):
    # A quad in z = 0 facing +z, seen from -z with the light mirrored: the same picture as
    # seen from +z (mirrored left-right), because the back face's normal is turned around.
    quad = pp.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2, 3]])
    def view(z):
        camera = pp.Camera(eye=(0.3, 0.2, z), target=(0.3, 0.2, 0), width=24, height=24)
        light = pp.PointLight((0.5, 1.0, z / 2))
        return pp.Scene(camera, objects=[quad], lights=[light])

    front = pp.render(view(3.0), shading=shading)
    back_culled = pp.render(view(-3.0), shading=shading)
    back = pp.render(view(-3.0), shading=shading, backface_cull=False)
    assert np.all(back_culled.object_id == -1)
    assert np.array_equal(back.object_id >= 0, (front.object_id >= 0)[:, ::-1])
    drawn = front.object_id >= 0
    assert np.allclose(np.asarray(back)[:, ::-1][drawn], np.asarray(front)[drawn], atol=2e-3)
