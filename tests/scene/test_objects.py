"""Primitives, procedural meshes, materials, lights and the Scene container."""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest

from pixelpath.scene import (
    Box,
    Camera,
    DirectionalLight,
    Material,
    Mesh,
    Plane,
    PointLight,
    Scene,
    Sphere,
    icosphere,
    torus,
)


def enclosed_volume(mesh: Mesh) -> float:
    """Signed volume by the divergence theorem; positive when faces are wound outward."""
    a, b, c = (mesh.vertices[mesh.triangles[:, k]] for k in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def assert_closed_and_consistent(mesh: Mesh) -> None:
    """Every directed edge appears once and its reverse once: closed, consistently wound."""
    edges = Counter()
    for face in mesh.faces:
        edges.update(zip(face, face[1:] + face[:1], strict=True))
    assert all(count == 1 for count in edges.values())
    assert all((b, a) in edges for a, b in edges)


def test_box_mesh_is_six_outward_quads_with_flat_unit_normals():
    box = Box((-1, 0, 2), (3, 1, 4))
    mesh = box.to_mesh()
    assert (len(mesh.vertices), mesh.face_count, len(mesh.triangles)) == (24, 6, 12)
    centre = np.array([1, 0.5, 3])
    for face, normal in zip(mesh.faces, mesh.face_normals, strict=True):
        assert np.linalg.norm(normal) == pytest.approx(1)
        assert np.count_nonzero(normal) == 1  # axis-aligned
        assert np.dot(normal, mesh.vertices[face].mean(axis=0) - centre) > 0
        np.testing.assert_array_equal(mesh.vertex_normals[face], [normal] * 4)
    assert enclosed_volume(mesh) == pytest.approx(4 * 1 * 2)
    np.testing.assert_array_equal(mesh.bounds(), box.bounds())


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_icosphere_counts_radius_and_orientation(level):
    mesh = icosphere(level, radius=2.0, center=(1, 2, 3))
    assert len(mesh.vertices) == 10 * 4**level + 2
    assert mesh.face_count == len(mesh.triangles) == 20 * 4**level
    radial = mesh.vertices - [1, 2, 3]
    np.testing.assert_allclose(np.linalg.norm(radial, axis=1), 2.0)
    np.testing.assert_allclose(mesh.vertex_normals, radial / 2.0, atol=1e-15)
    centroids = mesh.vertices[mesh.triangles].mean(axis=1) - [1, 2, 3]
    assert np.all(np.einsum("ij,ij->i", mesh.face_normals, centroids) > 0)
    np.testing.assert_allclose(np.linalg.norm(mesh.face_normals, axis=1), 1.0)
    assert_closed_and_consistent(mesh)


def test_icosphere_volume_converges_to_the_sphere_from_below():
    sphere = 4 / 3 * math.pi
    volumes = [enclosed_volume(icosphere(level)) for level in range(5)]
    assert all(0 < vol < sphere for vol in volumes)
    assert np.all(np.diff(volumes) > 0)
    assert volumes[-1] == pytest.approx(sphere, rel=5e-3)


def test_torus_counts_orientation_and_volume():
    mesh = torus(major_radius=2.0, minor_radius=0.5, major_segments=48, minor_segments=24)
    assert (len(mesh.vertices), mesh.face_count, len(mesh.triangles)) == (1152, 1152, 2304)
    assert_closed_and_consistent(mesh)
    # The exact normals agree with the faces' Newell normals (outward winding).
    corner_normals = mesh.vertex_normals[mesh.face_indices].reshape(-1, 4, 3).mean(axis=1)
    assert np.all(np.einsum("ij,ij->i", corner_normals, mesh.face_normals) > 0.95)
    # Pappus: V = 2π²Rr² for the smooth torus; the polygon's is a little less.
    assert enclosed_volume(mesh) == pytest.approx(2 * math.pi**2 * 2.0 * 0.25, rel=2e-2)


def test_sphere_to_mesh_has_exact_normals_and_keeps_the_material():
    red = Material(color=(1, 0, 0))
    mesh = Sphere((0, 1, 0), 0.5, red).to_mesh(subdivisions=2)
    assert mesh.face_count == 320 and mesh.material is red
    np.testing.assert_allclose(mesh.vertex_normals, (mesh.vertices - [0, 1, 0]) / 0.5, atol=1e-14)


def test_plane_to_mesh_is_a_ccw_square_on_the_plane():
    plane = Plane(point=(0, 1, 0), normal=(1, 1, 1))
    quad = plane.to_mesh(center=(5, 5, 5), half_size=2)
    n = np.ones(3) / math.sqrt(3)
    np.testing.assert_allclose(quad.face_normals, [n], atol=1e-14)  # CCW seen from the normal
    np.testing.assert_allclose((quad.vertices - [0, 1, 0]) @ n, 0, atol=1e-13)
    # centred at the projection of (5, 5, 5) onto the plane: (5, 5, 5) - (14/√3)·n
    np.testing.assert_allclose(quad.vertices.mean(axis=0), np.array([5, 5, 5]) - 14 / 3, atol=1e-13)
    assert quad.face_areas[0] == pytest.approx(16)
    t1, t2 = plane.tangents()
    np.testing.assert_allclose(np.cross(t1, t2), n, atol=1e-15)


def test_plane_corners_are_its_quads_and_its_tangents_are_the_callers_to_change():
    plane = Plane(point=(0, 1, 0), normal=(1, 1, 1))
    quad = plane.to_mesh(center=(5, 5, 5), half_size=2)
    assert plane.corners(center=(5, 5, 5), half_size=2).tobytes() == quad.vertices.tobytes()
    t1, _ = plane.tangents()
    t1[:] = 0.0  # the plane keeps its own frame (kept per normal, for every plane)
    assert np.linalg.norm(plane.tangents()[0]) == pytest.approx(1.0)
    assert plane.corners(center=(5, 5, 5), half_size=2).tobytes() == quad.vertices.tobytes()


def test_material_packing_and_validation():
    packed = Material(color=(0.2, 0.4, 0.6), ka=0.1, kd=0.5, ks=0.25, shininess=20).packed()
    assert packed.dtype == np.float64
    assert packed.tolist() == [0.2, 0.4, 0.6, 0.1, 0.5, 0.25, 20.0, 0.0]
    assert Material() == Material(color=[1, 1, 1])
    assert Material() != Material(kd=0.6)
    with pytest.raises(ValueError, match="kd must be at least 0"):
        Material(kd=-0.1)
    with pytest.raises(ValueError, match=r"reflectivity must lie in \[0, 1\]"):
        Material(reflectivity=1.5)
    with pytest.raises(ValueError, match="color components must be non-negative"):
        Material(color=(1, -1, 0))
    with pytest.raises(ValueError, match="ior must be positive"):
        Material(ior=0)


def test_lights():
    light = DirectionalLight(direction=(0, -3, 4), intensity=0.5, color=(1, 0.5, 0))
    np.testing.assert_allclose(light.direction, [0, -0.6, 0.8])
    assert PointLight(position=(1, 2, 3)).intensity == 1.0
    with pytest.raises(ValueError, match="direction must not be the zero vector"):
        DirectionalLight(direction=(0, 0, 0))
    with pytest.raises(ValueError, match="position must be finite"):
        PointLight(position=(0, np.inf, 0))
    with pytest.raises(ValueError, match="intensity must be at least 0"):
        PointLight(position=(0, 0, 0), intensity=-1)


def test_primitive_validation():
    with pytest.raises(ValueError, match="radius must be positive"):
        Sphere((0, 0, 0), 0)
    with pytest.raises(ValueError, match="minimum must be less than maximum on every axis"):
        Box((0, 0, 0), (1, 0, 1))
    with pytest.raises(ValueError, match="normal must not be the zero vector"):
        Plane((0, 0, 0), (0, 0, 0))
    with pytest.raises(ValueError, match="subdivisions must be between 0 and 7"):
        icosphere(8)
    with pytest.raises(ValueError, match="minor_radius must be less than major_radius"):
        torus(1.0, 1.0)
    with pytest.raises(ValueError, match="major_segments must be between 3 and 1024, got 5000"):
        torus(major_segments=5000)
    with pytest.raises(TypeError, match="minor_segments must be an int"):
        torus(minor_segments=8.0)
    with pytest.raises(TypeError, match="material must be a Material"):
        Sphere((0, 0, 0), 1, material={"color": (1, 0, 0)})


def make_camera() -> Camera:
    return Camera(eye=(0, 0, 10), target=(0, 0, 0))


def test_scene_bounds_ignore_infinite_planes():
    scene = Scene(
        make_camera(),
        objects=[Sphere((0, 0, 0), 1), Box((2, 2, 2), (3, 4, 5)), Plane((0, -1, 0), (0, 1, 0))],
        lights=[PointLight((0, 5, 0)), DirectionalLight((0, -1, 0))],
        ambient=(0.1, 0.2, 0.3),
    )
    np.testing.assert_array_equal(scene.bounds(), [[-1, -1, -1], [3, 4, 5]])
    assert isinstance(scene.objects, tuple) and len(scene.lights) == 2
    np.testing.assert_array_equal(scene.ambient, [0.1, 0.2, 0.3])


def test_empty_scene_is_valid_but_has_no_bounds():
    scene = Scene(make_camera())
    assert scene.objects == () and scene.lights == ()
    np.testing.assert_array_equal(scene.background, [0, 0, 0])
    with pytest.raises(ValueError, match="no bounded objects"):
        scene.bounds()


def test_scene_validation_names_the_member():
    with pytest.raises(TypeError, match=r"objects\[1\] must be a Sphere or Plane or Box or Mesh"):
        Scene(make_camera(), objects=[Sphere((0, 0, 0), 1), "teapot"])
    with pytest.raises(TypeError, match=r"lights\[0\]"):
        Scene(make_camera(), lights=[Sphere((0, 0, 0), 1)])
    with pytest.raises(TypeError, match="camera must be a Camera"):
        Scene(camera=None)
    with pytest.raises(ValueError, match="ambient components must be non-negative"):
        Scene(make_camera(), ambient=-0.5)
