"""Mesh topology and normals: fan triangles, Newell normals, area weighting, transforms, errors."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.scene import Material, Mesh

SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]


def regular_polygon(k: int, radius: float = 1.0) -> np.ndarray:
    angles = 2 * np.pi * np.arange(k) / k
    return np.stack([radius * np.cos(angles), radius * np.sin(angles), np.zeros(k)], axis=1)


def rotation(axis_angle) -> np.ndarray:
    """Rodrigues' rotation matrix for the rotation vector ``axis_angle``."""
    angle = float(np.linalg.norm(axis_angle))
    if angle == 0.0:
        return np.eye(3)
    kx, ky, kz = np.asarray(axis_angle) / angle
    k = np.array([[0, -kz, ky], [kz, 0, -kx], [-ky, kx, 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def test_fan_triangulation_of_mixed_polygons():
    vertices = np.vstack([SQUARE, regular_polygon(5) + np.array([3.0, 0, 0]), [[0, 0, 1]]])
    mesh = Mesh(vertices, [[0, 1, 2, 3], [4, 5, 6, 7, 8], [0, 1, 9]])
    assert mesh.face_count == 3
    assert mesh.face_offsets.tolist() == [0, 4, 9, 12]
    assert mesh.face_indices.tolist() == [0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 9]
    assert mesh.triangles.tolist() == [
        [0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7], [4, 7, 8], [0, 1, 9],
    ]  # fmt: skip
    assert mesh.triangle_face.tolist() == [0, 0, 1, 1, 1, 2]
    assert mesh.triangles.dtype == np.intp and mesh.triangle_face.dtype == np.intp
    assert mesh.faces == [[0, 1, 2, 3], [4, 5, 6, 7, 8], [0, 1, 9]]


# A "C": the square 0..3 with the notch 1..3 x 1..2 cut from its right side (area 7). The fan
# from its first corner would also cover the notch (the fan's triangles add up to 11).
C_SHAPE = [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2], [3, 2], [3, 3], [0, 3]]


def _covers_the_polygon(mesh: Mesh, outline, turn=None) -> None:
    """The triangles, turned back into the polygon's plane, tile the polygon exactly."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    turn = np.eye(3) if turn is None else turn
    flat = (mesh.vertices @ turn)[:, :2]  # turn is orthogonal: this undoes ``@ turn.T``
    pieces = [Polygon(flat[t]) for t in mesh.triangles]
    polygon = Polygon(outline)
    assert sum(p.area for p in pieces) == pytest.approx(polygon.area, rel=1e-9)
    assert unary_union(pieces).symmetric_difference(polygon).area < 1e-9 * polygon.area
    # every triangle wound as the polygon, none facing against its normal (a corner on the
    # line through its neighbours makes a triangle of no area)
    corners = mesh.vertices[mesh.triangles]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    assert np.all(normals @ mesh.face_normals[0] > -1e-12 * np.abs(normals).max())


def test_a_concave_polygon_is_cut_into_ears_not_fanned_over_its_notch():
    mesh = Mesh(np.hstack([C_SHAPE, np.zeros((8, 1))]), [list(range(8))])
    assert len(mesh.triangles) == 6 and mesh.triangle_face.tolist() == [0] * 6
    _covers_the_polygon(mesh, C_SHAPE)
    # a convex polygon keeps its fan, as before
    assert Mesh(regular_polygon(6), [list(range(6))]).triangles.tolist() == [
        [0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5],
    ]  # fmt: skip


@settings(max_examples=60, deadline=None)
@given(
    radii=st.lists(st.floats(0.2, 1.0), min_size=4, max_size=14),
    axis_angle=st.tuples(*[st.floats(-3, 3)] * 3),
)
def test_star_shaped_polygons_in_any_plane_are_tiled_exactly(radii, axis_angle):
    # corners at even angles round the origin, at random distances: simple, often concave
    angles = 2 * np.pi * np.arange(len(radii)) / len(radii)
    outline = np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=1)
    turn = rotation(axis_angle)
    points = np.hstack([outline, np.zeros((len(radii), 1))]) @ turn.T
    mesh = Mesh(points, [list(range(len(radii)))])
    assert len(mesh.triangles) == len(radii) - 2
    _covers_the_polygon(mesh, outline, turn)

def test_rectangular_face_array_equals_the_ragged_form():
    table = Mesh(SQUARE, np.array([[0, 1, 2], [0, 2, 3]]))
    ragged = Mesh(SQUARE, [(0, 1, 2), (0, 2, 3)])
    np.testing.assert_array_equal(table.triangles, ragged.triangles)
    np.testing.assert_array_equal(table.face_offsets, [0, 3, 6])


def test_newell_normal_and_area_of_a_tilted_rectangle():
    # A 2 x 1 rectangle in the plane y = z (normal (0, -1, 1)/√2), counter-clockwise about it.
    s = math.sqrt(0.5)
    rectangle = [[0, 0, 0], [2, 0, 0], [2, s, s], [0, s, s]]
    mesh = Mesh(rectangle, [[0, 1, 2, 3]])
    np.testing.assert_allclose(mesh.face_normals, [[0, -s, s]], atol=1e-15)
    np.testing.assert_allclose(mesh.face_areas, [2.0])


@settings(max_examples=40, deadline=None)
@given(
    k=st.integers(3, 12),
    radius=st.floats(0.1, 10),
    axis_angle=st.tuples(*[st.floats(-3, 3)] * 3),
    shift=st.tuples(*[st.floats(-100, 100)] * 3),
)
def test_newell_normal_of_rotated_regular_polygons(k, radius, axis_angle, shift):
    turn = rotation(axis_angle)
    polygon = regular_polygon(k, radius) @ turn.T + shift
    mesh = Mesh(polygon, [list(range(k))])
    np.testing.assert_allclose(mesh.face_normals[0], turn[:, 2], atol=1e-9)
    area = 0.5 * k * radius**2 * math.sin(2 * math.pi / k)
    np.testing.assert_allclose(mesh.face_areas[0], area, rtol=1e-9)
    assert len(mesh.triangles) == k - 2


@settings(max_examples=40, deadline=None)
@given(
    sizes=st.lists(st.integers(3, 12), min_size=1, max_size=30),
    scale=st.sampled_from([1e-3, 1.0, 1e4]),
    seed=st.integers(0, 2**32 - 1),
    triangles=st.booleans(),
)
def test_newell_vectors_are_the_sums_over_each_faces_corners_in_order(sizes, scale, seed,
                                                                       triangles):
    # The kernel's sum of Newell's terms, coordinate by coordinate, bit for bit equals the
    # plain form: the (N, 3) terms of every corner summed face by face (np.add.reduceat).
    # A mesh of triangles alone takes a path of its own, which must give the same bits.
    if triangles:
        sizes = [3] * len(sizes)
    rng = np.random.default_rng(seed)
    vertices = rng.normal(size=(40, 3)) * scale
    faces = [rng.choice(40, size=k, replace=False).tolist() for k in sizes]
    mesh = Mesh(vertices, faces)
    corners = mesh.vertices[mesh.face_indices]
    following = np.concatenate([np.roll(np.arange(a, b), -1) for a, b in
                                zip(mesh.face_offsets[:-1], mesh.face_offsets[1:], strict=True)])
    after = mesh.vertices[mesh.face_indices[following]]
    (x, y, z), (xn, yn, zn) = corners.T, after.T
    terms = np.stack([(y - yn) * (z + zn), (z - zn) * (x + xn), (x - xn) * (y + yn)], axis=1)
    plain = np.add.reduceat(terms, mesh.face_offsets[:-1], axis=0)
    assert np.array_equal(mesh._newell, plain)
    assert np.array_equal(np.signbit(mesh._newell), np.signbit(plain))


def test_vertex_normal_is_area_weighted():
    # Vertex 0 is shared by a triangle of area 2 facing +z and one of area 0.5 facing +y:
    # its normal is normalize(2·(0, 0, 1) + 0.5·(0, 1, 0)) = (0, 0.5, 2)/√4.25.
    vertices = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 1], [1, 0, 0]]
    mesh = Mesh(vertices, [[0, 1, 2], [0, 3, 4]])
    np.testing.assert_allclose(mesh.face_normals, [[0, 0, 1], [0, 1, 0]], atol=1e-15)
    np.testing.assert_allclose(mesh.vertex_normals[0], np.array([0, 0.5, 2]) / math.sqrt(4.25))
    np.testing.assert_allclose(mesh.vertex_normals[1], [0, 0, 1])
    np.testing.assert_allclose(mesh.vertex_normals[3], [0, 1, 0])


def test_given_normals_are_normalized_and_used():
    mesh = Mesh(SQUARE, [[0, 1, 2, 3]], normals=[[0, 0, 2]] * 3 + [[0, 3, 4]])
    np.testing.assert_allclose(mesh.vertex_normals, [[0, 0, 1]] * 3 + [[0, 0.6, 0.8]])


def test_given_arrays_stay_the_callers_and_the_mesh_keeps_its_own_read_only_copies():
    vertices, normals = np.array(SQUARE, dtype=float), np.array([[0.0, 0.0, 1.0]] * 4)
    mesh = Mesh(vertices, [[0, 1, 2, 3]], normals=normals)
    assert vertices.flags.writeable and normals.flags.writeable
    assert not np.shares_memory(mesh.normals, normals)
    assert not mesh.normals.flags.writeable and not mesh.vertices.flags.writeable
    normals[0] = (1.0, 0.0, 0.0)
    np.testing.assert_array_equal(mesh.normals[0], [0.0, 0.0, 1.0])


def test_degenerate_face_has_a_zero_normal_and_no_nan():
    mesh = Mesh([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 1, 3]])
    np.testing.assert_array_equal(mesh.face_normals[0], [0, 0, 0])
    assert mesh.face_areas[0] == 0.0
    np.testing.assert_allclose(mesh.vertex_normals[2], [0, 0, 0])
    np.testing.assert_allclose(mesh.vertex_normals[3], [0, 0, 1])


def test_bounds():
    mesh = Mesh([[1, -2, 3], [4, 5, -6], [0, 0, 0]], [[0, 1, 2]])
    np.testing.assert_array_equal(mesh.bounds(), [[0, -2, -6], [4, 5, 3]])


def test_transformed_moves_vertices_and_uses_the_inverse_transpose_for_normals():
    # A face in the plane x + y = 1 (normal (1, 1, 0)/√2); scaling x by 2 turns the plane
    # into x/2 + y = 1, whose normal is (0.5, 1, 0) normalized.
    vertices = [[1, 0, 0], [0, 1, 0], [0, 1, 1], [1, 0, 1]]
    mesh = Mesh(vertices, [[0, 1, 2, 3]], normals=[[1, 1, 0]] * 4)
    matrix = np.diag([2.0, 1.0, 1.0, 1.0])
    matrix[:3, 3] = [0, 0, 5]
    moved = mesh.transformed(matrix)
    np.testing.assert_allclose(moved.vertices, [[2, 0, 5], [0, 1, 5], [0, 1, 6], [2, 0, 6]])
    expected = np.array([0.5, 1, 0]) / math.hypot(0.5, 1)
    np.testing.assert_allclose(moved.face_normals, [expected], atol=1e-15)
    np.testing.assert_allclose(moved.vertex_normals, [expected] * 4, atol=1e-15)
    assert moved.material is mesh.material


def test_mirroring_keeps_faces_outward():
    cube = Mesh(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
        [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]],
    )
    mirrored = cube.transformed(np.diag([-1.0, 1.0, 1.0, 1.0]))
    for mesh in (cube, mirrored):
        centre = mesh.vertices.mean(axis=0)
        face_centres = np.array([mesh.vertices[f].mean(axis=0) for f in mesh.faces])
        outward = np.einsum("ij,ij->i", mesh.face_normals, face_centres - centre)
        np.testing.assert_allclose(outward, 0.5)


def test_input_arrays_are_copied_and_results_read_only():
    vertices = np.array(SQUARE, dtype=float)
    mesh = Mesh(vertices, [[0, 1, 2, 3]])
    vertices[0, 0] = 99.0
    assert mesh.vertices[0, 0] == 0.0
    for array in (mesh.vertices, mesh.triangles, mesh.face_normals, mesh.vertex_normals):
        assert not array.flags.writeable


def test_material_and_name():
    red = Material(color=(1, 0, 0))
    mesh = Mesh(SQUARE, [[0, 1, 2, 3]], material=red, name="quad")
    assert mesh.material is red and "quad" in repr(mesh)
    assert Mesh(SQUARE, [[0, 1, 2, 3]]).material == Material()


@pytest.mark.parametrize(
    ("vertices", "faces", "error", "message"),
    [
        (SQUARE, [[0, 1, 2], [0, 2, 4]], ValueError, "face 1 refers to vertex 4, outside 0..3"),
        (SQUARE, [[0, 1, 2], [-1, 2, 3]], ValueError, "face 1 refers to vertex -1"),
        (SQUARE, [[0, 1, 2], [0, 2]], ValueError, "face 1 has 2 vertices"),
        (SQUARE, [[0, 1, 2], []], ValueError, "face 1 has 0 vertices"),
        (SQUARE, [], ValueError, "faces is empty"),
        (np.zeros((0, 3)), [[0, 1, 2]], ValueError, "vertices is empty"),
        ([[0, 0, 0], [1, np.nan, 0], [0, 1, 0]], [[0, 1, 2]], ValueError, "must be finite"),
        ([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], ValueError, r"vertices must have shape \(n, 3\)"),
        (SQUARE, [[0, 1, 2.0]], TypeError, "face 0 must be a sequence of vertex indices"),
        (SQUARE, np.array([[0.0, 1.0, 2.0]]), TypeError, "face 0"),
        (SQUARE, "0 1 2", TypeError, "faces must be a sequence"),
    ],
)
def test_invalid_meshes_are_rejected_clearly(vertices, faces, error, message):
    with pytest.raises(error, match=message):
        Mesh(vertices, faces)


def test_invalid_normals_and_transforms():
    with pytest.raises(ValueError, match=r"normals must have shape \(4, 3\)"):
        Mesh(SQUARE, [[0, 1, 2, 3]], normals=[[0, 0, 1]] * 3)
    with pytest.raises(ValueError, match=r"normals\[2\] is the zero vector"):
        Mesh(SQUARE, [[0, 1, 2, 3]], normals=[[0, 0, 1]] * 2 + [[0, 0, 0]] * 2)
    mesh = Mesh(SQUARE, [[0, 1, 2, 3]])
    projective = np.eye(4)
    projective[3, 2] = -1
    with pytest.raises(ValueError, match="affine"):
        mesh.transformed(projective)
    with pytest.raises(ValueError, match="singular"):
        mesh.transformed(np.diag([1.0, 0.0, 1.0, 1.0]))
    with pytest.raises(TypeError, match="material must be a Material"):
        Mesh(SQUARE, [[0, 1, 2, 3]], material="red")


def test_a_mesh_cannot_be_changed_once_made():
    mesh = Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], name="tri")
    for name, value in (("material", Material(color=(1, 0, 0))), ("vertices", np.zeros((3, 3))),
                        ("name", "other"), ("extra", 1)):
        with pytest.raises(AttributeError, match="cannot be changed"):
            setattr(mesh, name, value)
    with pytest.raises(AttributeError, match="cannot be changed"):
        del mesh.material
    again = pickle.loads(pickle.dumps(mesh))
    assert again == mesh and again.name == "tri"
    with pytest.raises(AttributeError, match="cannot be changed"):
        again.material = Material()


def test_a_new_mesh_from_the_same_arrays_is_drawn_as_it_is_now():
    import pixelpath as pp

    grey = Mesh([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[0, 1, 2]])
    red = Mesh(grey.vertices, grey.faces, Material(color=(1, 0, 0), ks=0.0), grey.normals)
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=16, height=16)
    for method in ("zbuffer", "raytrace"):
        first = pp.render(pp.Scene(camera, [grey], [pp.PointLight((0, 0, 5))]), method)
        second = pp.render(pp.Scene(camera, [red], [pp.PointLight((0, 0, 5))]), method)
        center = np.asarray(second)[8, 8]
        assert center[0] > 0 and center[1] == 0 and np.asarray(first)[8, 8][1] > 0
