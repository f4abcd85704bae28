"""A scene's geometry: built once per set of objects, only planes following the camera."""

from __future__ import annotations

import dataclasses

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import pixelpath as pp
from pixelpath.raster import tessellate
from pixelpath.raster.tessellate import scene_geometry, view_reach
from pixelpath.scene.animation import Animation, ObjectKey, Turntable

OBJECTS = (
    pp.Sphere((0, 1, 0), 1.0),
    pp.Plane((0, 0, 0), (0, 1, 0)),
    pp.Box((1.5, 0, -1), (2.5, 1, 0)),
    pp.Mesh([[0, 0, 2], [1, 0, 2], [0, 1, 2]], [[0, 1, 2]], colors=[[1, 0, 0]] * 3),
    pp.Plane((0, 3, 0), (0, -1, 0.2)),
)


def scene_from(eye, fov=45.0, size=(64, 48), objects=OBJECTS):
    camera = pp.Camera(eye=eye, target=(0, 0.5, 0), fov=fov, width=size[0], height=size[1])
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((4, 6, 5))])


def fields(geometry):
    """Every array of the geometry, and each mesh's vertices and polygons."""
    arrays = [
        getattr(geometry, f.name) for f in dataclasses.fields(geometry)
        if isinstance(getattr(geometry, f.name), np.ndarray)
    ]
    arrays += [a for m in geometry.meshes for a in (m.vertices, m.face_indices, m.vertex_normals)]
    return arrays


coordinate = st.floats(-20, 20, allow_nan=False).filter(lambda x: abs(x) > 0.5)


@settings(max_examples=25, deadline=None)
@given(first=st.tuples(coordinate, coordinate, coordinate),
       second=st.tuples(coordinate, coordinate, coordinate), fov=st.floats(20, 100))
def test_another_cameras_geometry_is_what_a_fresh_build_gives_bit_for_bit(first, second, fov):
    scene = scene_from(first)
    scene_geometry(scene)
    moved = dataclasses.replace(scene, camera=scene_from(second, fov).camera)
    assert moved.objects is scene.objects
    reused = scene_geometry(moved)
    fresh = tessellate._build_geometry(OBJECTS, moved.camera)
    assert [a.tobytes() for a in fields(reused)] == [a.tobytes() for a in fields(fresh)]
    assert [a.dtype for a in fields(reused)] == [a.dtype for a in fields(fresh)]


@settings(max_examples=25, deadline=None)
@given(eye=st.tuples(coordinate, coordinate, coordinate),
       normal=st.tuples(coordinate, coordinate, coordinate))
def test_a_planes_cells_have_its_normal_exactly_from_any_camera(eye, normal):
    plane = pp.Plane((0.3, -0.2, 0.1), normal)
    objects = (OBJECTS[0], plane)
    for fov in (30.0, 90.0):  # a first camera, then another (the rows of _with_planes)
        geometry = scene_geometry(scene_from(eye, fov, objects=objects))
        cells = geometry.polygon_normals[geometry.polygon_object == 1]
        assert len(cells) == tessellate.PLANE_GRID**2
        assert (cells == plane.normal).all()
        # Newell's normal of the grid the camera gave agrees to rounding, as it should.
        newell = geometry.meshes[1].face_normals
        assert np.allclose(newell, plane.normal, rtol=0, atol=1e-12)


def test_without_planes_every_camera_shares_one_geometry():
    objects = tuple(o for o in OBJECTS if not isinstance(o, pp.Plane))
    one = scene_geometry(scene_from((3, 2, 6), objects=objects))
    other = scene_geometry(scene_from((-5, 1, 2), fov=80, objects=objects))
    assert one is other


def test_a_plane_reaches_as_far_as_each_camera_sees():
    narrow, wide = scene_from((0, 2, 8), fov=20), scene_from((0, 2, 8), fov=100)
    wide = dataclasses.replace(wide, objects=narrow.objects)  # same objects, same eye
    for scene in (narrow, wide, narrow):
        floor = scene_geometry(scene).meshes[1]
        spread = floor.vertices.max(axis=0) - floor.vertices.min(axis=0)
        assert np.isclose(spread[0], 2 * view_reach(scene.camera))


def test_scenes_made_from_the_same_objects_share_their_geometry_and_triangles():
    from pixelpath.raytrace.tracer import scene_triangles

    objects = [o for o in OBJECTS if not isinstance(o, pp.Plane)]
    one, other = scene_from((3, 2, 6), objects=objects), scene_from((-4, 1, 5), objects=objects)
    assert one.objects is not other.objects  # each Scene makes a tuple of the list
    assert scene_geometry(one) is scene_geometry(other)
    assert scene_triangles(one) is scene_triangles(other)
    moved = [*objects[:2], pp.Box((1.5, 0, -1), (2.5, 1, 0.5)), *objects[3:]]
    assert scene_geometry(scene_from((3, 2, 6), objects=moved)) is not scene_geometry(one)


def test_turntable_frames_share_the_first_frames_geometry():
    turning = dataclasses.replace(
        scene_from((0, 2, 8), objects=OBJECTS[:1]), animation=Animation(8, turntable=Turntable())
    )
    first = scene_geometry(turning.at_frame(0))
    assert all(scene_geometry(turning.at_frame(k)) is first for k in range(1, 8))
    spinning = dataclasses.replace(
        turning, animation=Animation(8, objects=[ObjectKey(0, 7, translate=(0, 1, 0))])
    )
    assert scene_geometry(spinning.at_frame(7)) is not first
