"""Normals smoothed within a crease angle: sharp edges stay sharp, smooth surfaces smooth."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_models import DATA, FUZZ, _only_named_errors

import pixelpath as pp
import pixelpath.io.creases as creases
from pixelpath.io.creases import CREASE_ANGLE, crease_normals
from pixelpath.io.models import read_model

# A unit cube: 8 shared corners, two triangles a side, counter-clockwise seen from outside.
CUBE_VERTICES = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)
CUBE_TRIANGLES = np.array([
    [0, 1, 3], [0, 3, 2],  # x = 0
    [4, 6, 7], [4, 7, 5],  # x = 1
    [0, 4, 5], [0, 5, 1],  # y = 0
    [2, 3, 7], [2, 7, 6],  # y = 1
    [0, 2, 6], [0, 6, 4],  # z = 0
    [1, 5, 7], [1, 7, 3],  # z = 1
])
CUBE_NORMALS = np.repeat([[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]],
                         2, axis=0)


def _fold(degrees: float) -> tuple[np.ndarray, np.ndarray]:
    """Two triangles sharing the edge (0, 1) along x, the second turned ``degrees`` about it."""
    turn = math.radians(degrees)
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0.5, -1, 0],
                         [0.5, math.cos(turn), math.sin(turn)]])
    return vertices, np.array([[0, 1, 3], [0, 2, 1]])


def test_a_cube_gets_its_sides_normals_at_its_sides_corners():
    source, triangles, normals = crease_normals(CUBE_VERTICES, CUBE_TRIANGLES)
    assert len(source) == 24  # each corner of the cube split three ways
    np.testing.assert_array_equal(CUBE_VERTICES[source][triangles], CUBE_VERTICES[CUBE_TRIANGLES])
    np.testing.assert_array_equal(normals[triangles],
                                  np.repeat(CUBE_NORMALS[:, None], 3, axis=1))


@pytest.mark.parametrize(("degrees", "split"), [(40.0, False), (60.0, True)])
def test_faces_are_smoothed_within_the_angle_only(degrees, split):
    found = crease_normals(*_fold(degrees))
    assert (found is not None) == split
    if split:
        source, triangles, normals = found
        assert sorted(source.tolist()) == [0, 0, 1, 1, 2, 3]
        # the first face lies at the fold's angle past the second's plane (normal +z)
        np.testing.assert_allclose(normals[triangles[1]], [[0, 0, 1]] * 3, atol=1e-15)
        turn = math.radians(degrees)
        np.testing.assert_allclose(normals[triangles[0]],
                                   [[0, -math.sin(turn), math.cos(turn)]] * 3, atol=1e-15)


def test_a_cylinder_keeps_smooth_sides_and_flat_caps():
    sections, vertices = 16, [[0, 0, 0], [0, 0, 1]]
    for k in range(sections):
        angle = 2 * math.pi * k / sections
        vertices += [[math.cos(angle), math.sin(angle), 0], [math.cos(angle), math.sin(angle), 1]]
    triangles = []
    for k in range(sections):
        a, b = 2 + 2 * k, 2 + 2 * ((k + 1) % sections)  # bottom corners; tops are a+1, b+1
        triangles += [[0, b, a], [1, a + 1, b + 1], [a, b, b + 1], [a, b + 1, a + 1]]
    source, new, normals = crease_normals(np.array(vertices, float), np.array(triangles))
    at_corners = normals[new]  # (F, 3, 3): faces in fours, bottom cap, top cap, two sides
    np.testing.assert_array_equal(at_corners[0::4], [[[0, 0, -1]] * 3] * sections)
    np.testing.assert_array_equal(at_corners[1::4], [[[0, 0, 1]] * 3] * sections)
    sides = np.concatenate([at_corners[2::4], at_corners[3::4]])
    np.testing.assert_allclose(sides[..., 2], 0.0, atol=1e-15)  # level: the sides' own
    # smooth: one normal at each rim vertex for all the side faces around it, not one a face
    assert len(np.unique(sides.reshape(-1, 3), axis=0)) == 2 * sections
    assert len(source) == 2 + 2 * sections * 2  # each rim vertex: one for its cap, one side


def test_a_smooth_surface_is_left_to_area_weighted_normals():
    import trimesh

    sphere = trimesh.creation.icosphere(subdivisions=3)
    assert crease_normals(np.asarray(sphere.vertices, float), np.asarray(sphere.faces)) is None


def test_an_angle_of_0_draws_every_face_flat_unless_the_part_is_planar():
    source, triangles, normals = crease_normals(CUBE_VERTICES, CUBE_TRIANGLES, 0.0)
    np.testing.assert_array_equal(source, CUBE_TRIANGLES.ravel())  # a vertex per corner
    np.testing.assert_array_equal(normals[triangles],
                                  np.repeat(CUBE_NORMALS[:, None], 3, axis=1))
    side = CUBE_TRIANGLES[:2]  # the two triangles of the side x = 0
    assert crease_normals(CUBE_VERTICES, side, 0.0) is None


def test_a_face_of_no_area_makes_no_crease():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [2, 2, 0]], float)  # 0, 2, 3 in line
    assert crease_normals(vertices, np.array([[0, 1, 2], [0, 2, 3]])) is None


def test_copies_of_a_vertex_at_one_point_share_its_normal():
    """A texture seam: trimesh gives a vertex a copy for each (position, uv) pair. The
    sphere's faces on one side use copies of the vertices on the seam: no crease, but the
    copies get the whole sphere's normals, not each their side's."""
    import trimesh

    sphere = trimesh.creation.icosphere(subdivisions=2)
    vertices, triangles = np.asarray(sphere.vertices, float), np.array(sphere.faces)
    east = vertices[triangles].mean(axis=1)[:, 0] > 0.0
    seam = np.unique(triangles[east])
    copies = np.full(len(vertices), -1)
    copies[seam] = len(vertices) + np.arange(len(seam))
    triangles[east] = copies[triangles[east]]
    source, new, normals = crease_normals(np.vstack([vertices, vertices[seam]]), triangles)
    np.testing.assert_array_equal(new, triangles)  # no crease: nothing split
    np.testing.assert_array_equal(source, np.arange(len(vertices) + len(seam)))
    np.testing.assert_array_equal(normals[len(vertices):], normals[seam])
    welded = pp.Mesh(vertices, np.asarray(sphere.faces)).vertex_normals  # area-weighted
    np.testing.assert_allclose(normals[: len(vertices)], welded, atol=1e-12)


def test_large_meshes_are_worked_out_in_pieces_with_the_same_result(monkeypatch):
    whole = crease_normals(CUBE_VERTICES, CUBE_TRIANGLES)
    monkeypatch.setattr(creases, "_PAIRS_AT_ONCE", 7)
    pieces = crease_normals(CUBE_VERTICES, CUBE_TRIANGLES)
    for a, b in zip(whole, pieces, strict=True):
        np.testing.assert_array_equal(a, b)


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(4, 30))
def test_corner_normals_lie_within_the_angle_of_their_face(seed, count):
    """The average of unit normals within a cone stays in the cone; corners keep their places."""
    rng = np.random.default_rng(seed)
    vertices = rng.normal(size=(count, 3))
    triangles = np.array([rng.choice(count, 3, replace=False) for _ in range(2 * count)])
    found = crease_normals(vertices, triangles)
    if found is None:
        return
    source, new, normals = found
    np.testing.assert_array_equal(vertices[source][new], vertices[triangles])
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-12)
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    face = np.cross(b - a, c - a)
    area = np.linalg.norm(face, axis=1)
    real = area > 0.0  # a face of no area faces no way: its corners take any normal
    cosines = np.einsum("fkc,fc->fk", normals[new][real], face[real] / area[real, None])
    assert cosines.min() >= math.cos(math.radians(CREASE_ANGLE)) - 1e-9


def _ascii_stl(vertices: np.ndarray, triangles: np.ndarray) -> str:
    facets = "".join(
        "facet normal 0 0 0\nouter loop\n"
        + "".join(f"vertex {x} {y} {z}\n" for x, y, z in vertices[t])
        + "endloop\nendfacet\n"
        for t in triangles
    )
    return f"solid cube\n{facets}endsolid cube\n"


def _obj(vertices: np.ndarray, triangles: np.ndarray) -> str:
    return "".join(f"v {x} {y} {z}\n" for x, y, z in vertices) + "".join(
        f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles)


@pytest.mark.parametrize(("name", "writer"), [("cube.stl", _ascii_stl), ("cube.obj", _obj)])
def test_a_cube_file_without_normals_loads_with_sharp_edges(tmp_path, name, writer):
    (tmp_path / name).write_text(writer(CUBE_VERTICES, CUBE_TRIANGLES))
    (mesh,) = read_model(tmp_path / name).objects
    assert len(mesh.vertices) == 24
    np.testing.assert_allclose(mesh.normals[mesh.triangles],
                               np.repeat(CUBE_NORMALS[:, None], 3, axis=1), atol=1e-15)


def test_normals_in_the_file_are_kept(tmp_path):
    lines = _obj(CUBE_VERTICES, np.zeros((0, 3), int))
    lines += "vn 0 0 1\n" + "".join(f"f {a + 1}//1 {b + 1}//1 {c + 1}//1\n"
                                     for a, b, c in CUBE_TRIANGLES)
    (tmp_path / "given.obj").write_text(lines)
    (mesh,) = read_model(tmp_path / "given.obj").objects
    np.testing.assert_array_equal(mesh.normals, [[0, 0, 1]] * len(mesh.vertices))


CUBE_FILES = {"cube.stl": _ascii_stl(CUBE_VERTICES, CUBE_TRIANGLES).encode(),
              "cube.obj": _obj(CUBE_VERTICES, CUBE_TRIANGLES).encode(),
              "multibody.stl": (DATA / "multibody.stl").read_bytes()}


@FUZZ
@given(name=st.sampled_from(sorted(CUBE_FILES)), cut=st.floats(0.0, 1.0),
       edits=st.lists(st.tuples(st.floats(0.0, 1.0), st.sampled_from(b"0123456789-. e/\nf")),
                      max_size=6))
def test_fuzz_mesh_files_without_normals(tmp_path, name, cut, edits):
    """Truncated and edited files whose parts get crease normals: they load, or raise a
    ValueError or TypeError naming the file."""
    data = bytearray(CUBE_FILES[name])
    for where, byte in edits:
        data[min(int(where * len(data)), len(data) - 1)] = byte
    path = tmp_path / name
    path.write_bytes(bytes(data[: max(1, int(cut * len(data)))] if cut < 1.0 else data))
    _only_named_errors(path)
