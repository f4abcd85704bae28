"""Mesh.load: OBJ, PLY and STL through trimesh, polygon faces kept, clear errors."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from pixelpath.scene import Material, Mesh

CUBE_VERTICES = [
    [0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
]  # fmt: skip
CUBE_QUADS = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]]


def obj_text(vertices, faces) -> str:
    lines = [f"v {x} {y} {z}" for x, y, z in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in face) for face in faces]
    return "\n".join(lines) + "\n"


def test_suzanne_keeps_its_quads_and_normals(shared_mesh):
    mesh = Mesh.load(shared_mesh("suzanne.obj"))
    assert mesh.face_count == 500 and len(mesh.triangles) == 968
    assert np.bincount(mesh.face_sizes).tolist() == [0, 0, 0, 32, 468]
    assert mesh.name == "suzanne"
    # First face line: "f 1//1 3//3 45//45 47//47"; those v lines of the file:
    np.testing.assert_allclose(
        mesh.vertices[mesh.faces[0]],
        [[-2.056562, 1.415748, 4.869517], [-1.994062, 1.345436, 4.791392],
         [-1.931562, 1.493873, 4.775767], [-2.025312, 1.493873, 4.861705]],
    )  # fmt: skip
    # The file's normals are used: vn 1 is (0.744549, -0.641131, 0.186007).
    np.testing.assert_allclose(mesh.vertex_normals[0], [0.744549, -0.641131, 0.186007], atol=1e-5)
    # and they agree in direction with the area-weighted ones for the bulk of the vertices
    computed = Mesh(mesh.vertices, mesh.faces).vertex_normals
    assert np.median(np.einsum("ij,ij->i", computed, mesh.vertex_normals)) > 0.95


def test_obj_with_mixed_polygons_keeps_every_face(tmp_path):
    vertices = [[0, 0, 0], [1, 0, 0], [1.5, 1, 0], [0.5, 1.5, 0], [-0.5, 1, 0], [0, 0, -1]]
    faces = [[0, 1, 2, 3, 4], [0, 5, 1], [1, 5, 2, 3]]
    path = tmp_path / "mixed.obj"
    path.write_text(obj_text(vertices, faces))
    mesh = Mesh.load(path, material=Material(kd=0.5))
    assert mesh.faces == faces
    np.testing.assert_allclose(mesh.vertices, vertices)
    assert mesh.material.kd == 0.5 and mesh.normals is None


def test_obj_cube_of_quads_is_closed_and_outward(tmp_path):
    path = tmp_path / "cube.obj"
    path.write_text(obj_text(CUBE_VERTICES, CUBE_QUADS))
    mesh = Mesh.load(path)
    assert mesh.faces == CUBE_QUADS
    outward = np.einsum("ij,ij->i", mesh.face_normals,
                        np.array([mesh.vertices[f].mean(0) for f in mesh.faces]) - 0.5)
    np.testing.assert_allclose(outward, 0.5)
    np.testing.assert_allclose(np.linalg.norm(mesh.vertex_normals, axis=1), 1.0)


def test_ply_keeps_polygons_and_normals(tmp_path):
    header = [
        "ply", "format ascii 1.0", "element vertex 5",
        "property float x", "property float y", "property float z",
        "property float nx", "property float ny", "property float nz",
        "element face 2", "property list uchar int vertex_indices", "end_header",
    ]  # fmt: skip
    body = ["0 0 0 0 0 1", "1 0 0 0 0 1", "1 1 0 0 0 1", "0 1 0 0 0 1", "0 0 -1 0 0 1"]
    body += ["4 0 1 2 3", "3 0 4 1"]
    path = tmp_path / "quad.ply"
    path.write_text("\n".join(header + body) + "\n")
    mesh = Mesh.load(path)
    assert mesh.faces == [[0, 1, 2, 3], [0, 4, 1]]
    np.testing.assert_allclose(mesh.vertex_normals, [[0, 0, 1]] * 5)


@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_a_concave_obj_face_is_drawn_without_its_notch(tmp_path, method):
    import pixelpath as pp

    # one octagon face, a "C" open to the right: x in 0..3, y in 0..3, notch x > 1, 1 < y < 2
    c_shape = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 2), (3, 2), (3, 3), (0, 3)]
    path = tmp_path / "c.obj"
    path.write_text(obj_text([(x, y, 0) for x, y in c_shape], [list(range(8))]))
    camera = pp.Camera(eye=(1.5, 1.5, 10), target=(1.5, 1.5, 0), width=64, height=64,
                       projection="orthographic", view_height=4.0)
    scene = pp.Scene(camera, [Mesh.load(path)], [pp.PointLight((1.5, 1.5, 10))])
    ids = pp.render(scene, method).object_id

    def drawn(x, y):  # 16 pixels a unit, (1.5, 1.5) at the centre, row 0 at the top
        return ids[int(32 - (y - 1.5) * 16), int(32 + (x - 1.5) * 16)] >= 0

    assert drawn(0.5, 1.5) and drawn(2.5, 0.5) and drawn(2.5, 2.5)
    assert not drawn(1.4, 1.5) and not drawn(1.8, 1.6)  # the notch, which the fan covered

def test_binary_ply_and_stl_written_by_trimesh(tmp_path):
    source = trimesh.creation.box(extents=(2, 4, 6))
    for suffix in ("ply", "stl"):
        path = tmp_path / f"box.{suffix}"
        source.export(path)
        mesh = Mesh.load(path)
        assert len(mesh.vertices) == 8 and mesh.face_count == 12  # STL corners are merged
        np.testing.assert_allclose(mesh.bounds(), [[-1, -2, -3], [1, 2, 3]])
        centroids = mesh.vertices[mesh.triangles].mean(axis=1)
        assert np.all(np.einsum("ij,ij->i", mesh.face_normals, centroids) > 0)
        # area-weighted vertex normals of a box corner point out of the corner
        corner = np.argmax(mesh.vertices.sum(axis=1))
        assert np.all(mesh.vertex_normals[corner] > 0)


@pytest.mark.parametrize(
    ("name", "text", "message"),
    [
        ("empty.obj", "", "has no faces"),
        ("points.obj", "v 0 0 0\nv 1 0 0\n", "has no faces"),
        ("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "refers to a vertex that does not"),
        ("garbage.ply", "this is not a ply file\n", "could not read this .ply file"),
        ("mesh.xyz", "0 0 0\n", "unsupported mesh format '.xyz'"),
        # a model file: the error says which readers take it
        ("Duck.glb", "glTF", r"'\.glb'; expected one of .*pixelpath\.load_scene .*read_model_obj"),
        ("box.gltf", "{}", r"'\.gltf'; expected one of .*pixelpath\.load_scene"),
    ],
)
def test_load_errors_name_the_file(tmp_path, name, text, message):
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(ValueError, match=message) as error:
        Mesh.load(path)
    assert str(path) in str(error.value)


def test_missing_file_is_a_file_not_found_error(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"mesh file not found: .*nothing\.obj"):
        Mesh.load(tmp_path / "nothing.obj")


def test_degenerate_face_in_a_file_is_rejected_with_the_file_name(tmp_path):
    path = tmp_path / "short.ply"
    header = ["ply", "format ascii 1.0", "element vertex 3", "property float x",
              "property float y", "property float z", "element face 1",
              "property list uchar int vertex_indices", "end_header"]  # fmt: skip
    path.write_text("\n".join([*header, "0 0 0", "1 0 0", "0 1 0", "2 0 1"]) + "\n")
    with pytest.raises(ValueError, match=r"short\.ply: face 0 has 2 vertices"):
        Mesh.load(path)


def test_obj_with_several_objects_keeps_each_face_in_place(tmp_path):
    path = tmp_path / "two.obj"
    path.write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
        "o first\nusemtl a\nf 1 2 3 4\no second\nusemtl b\nf 1 5 2\n"
    )
    mesh = Mesh.load(path)
    polygons = sorted(mesh.vertices[face].tolist() for face in mesh.faces)
    assert polygons == [
        [[0, 0, 0], [0, 0, 1], [1, 0, 0]],
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
    ]


def test_coincident_vertices_are_merged_when_the_file_has_no_normals(tmp_path):
    # Two triangles folded along the x axis, each with its own copy of the shared edge.
    path = tmp_path / "seam.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 0\nv 0 0 1\nf 1 2 3\nf 4 5 6\n")
    mesh = Mesh.load(path)
    np.testing.assert_array_equal(mesh.vertices, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    assert mesh.faces == [[0, 1, 2], [1, 0, 3]]
    # (1,0,0), (0,0,0), (0,0,1) faces +y: (-1,0,0) x (-1,0,1) = (0,1,0). The shared edge's
    # normal is the average of +z and +y (equal areas).
    np.testing.assert_allclose(mesh.vertex_normals[0], [0, np.sqrt(0.5), np.sqrt(0.5)])


def test_vertices_with_file_normals_are_kept_apart(tmp_path):
    path = tmp_path / "crease.obj"
    path.write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 0\nv 0 0 1\n"
        "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 -1 0\nvn 0 -1 0\nvn 0 -1 0\n"
        "f 1//1 2//2 3//3\nf 4//4 5//5 6//6\n"
    )
    mesh = Mesh.load(path)
    assert len(mesh.vertices) == 6
    np.testing.assert_allclose(mesh.vertex_normals[[0, 4]], [[0, 0, 1], [0, -1, 0]])


@pytest.mark.parametrize(
    "name", ["suzanne.obj", "cow.obj", "spot.obj", "teapot.obj", "stanford-bunny.obj"]
)
def test_shared_meshes_keep_every_face_and_position(shared_mesh, name):
    path = shared_mesh(name)
    lines = path.read_text().splitlines()
    positions = np.array([line.split()[1:4] for line in lines if line.startswith("v ")], float)
    face_count = sum(line.startswith("f ") for line in lines)
    has_normals = any(line.startswith("vn ") for line in lines)
    mesh = Mesh.load(path)
    assert mesh.face_count == face_count
    # positions are merged only when the file brings no normals
    expected = len(positions) if has_normals else len(np.unique(positions, axis=0))
    assert len(mesh.vertices) == expected
    np.testing.assert_allclose(mesh.bounds(), [positions.min(0), positions.max(0)])
    used = np.unique(mesh.face_indices)  # the bunny has 1113 vertices no face uses
    np.testing.assert_allclose(np.linalg.norm(mesh.vertex_normals[used], axis=1), 1.0, atol=1e-12)
