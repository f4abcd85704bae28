"""glTF parts without normals are drawn flat, as the glTF specification asks (section 3.7.2.1).

The tetrahedron below shares its four vertices between four faces that each face another way:
smooth (area-weighted) vertex normals would round it off. Its faces' outward normals are
derived by hand: -z, -y and -x for the three faces on the coordinate planes, and
(1, 1, 1) / sqrt(3) for the slanted one.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from test_models import _data_uri, quad_gltf, write

import pixelpath as pp
from pixelpath.io.models import read_model

CORNERS = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype="<f4")
FACES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype="<u2")
FACE_NORMALS = np.array([[0, 0, -1], [0, -1, 0], [-1, 0, 0], [3**-0.5] * 3])
COLORS = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype="<f4")


def tetrahedron(*, normals: np.ndarray | None = None) -> dict:
    """Return a glTF tetrahedron (node 'tetra') with vertex colours, and ``normals`` if given."""
    arrays = [CORNERS, COLORS, FACES.ravel()] + ([] if normals is None else [normals])
    blob = b"".join(array.tobytes() for array in arrays)
    views, accessors, offset = [], [], 0
    kinds = [("VEC3", 5126), ("VEC3", 5126), ("SCALAR", 5123), ("VEC3", 5126)]
    for array, (kind, component) in zip(arrays, kinds, strict=False):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": array.nbytes})
        accessors.append({"bufferView": len(views) - 1, "componentType": component,
                          "count": len(array), "type": kind})
        offset += array.nbytes
    accessors[0] |= {"min": [0, 0, 0], "max": [1, 1, 1]}
    attributes = {"POSITION": 0, "COLOR_0": 1} | ({} if normals is None else {"NORMAL": 3})
    return {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "tetra", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": 2}]}],
        "buffers": [{"byteLength": len(blob), "uri": _data_uri(blob)}],
        "bufferViews": views,
        "accessors": accessors,
    }


def test_a_part_without_normals_gets_each_face_s_normal_at_its_corners(tmp_path):
    (mesh,) = read_model(write(tmp_path, tetrahedron())).objects
    assert len(mesh.vertices) == 12  # a vertex of its own at each face's corner
    np.testing.assert_array_equal(mesh.vertices[mesh.triangles], CORNERS[FACES])
    np.testing.assert_allclose(mesh.normals[mesh.triangles],
                               np.repeat(FACE_NORMALS[:, None], 3, axis=1), atol=1e-15)
    # the colours follow their corners (linear, as glTF's COLOR_0 is)
    np.testing.assert_array_equal(mesh.colors[mesh.triangles][..., :3], COLORS[FACES])


def test_a_part_with_normals_keeps_its_shared_vertices(tmp_path):
    smooth = CORNERS - 0.25  # away from the centre of the corners
    smooth /= np.linalg.norm(smooth, axis=1, keepdims=True)
    (mesh,) = read_model(write(tmp_path, tetrahedron(normals=smooth))).objects
    assert len(mesh.vertices) == 4
    np.testing.assert_allclose(mesh.normals, smooth, atol=1e-7)


def test_a_flat_part_without_normals_keeps_its_shared_vertices(tmp_path):
    (mesh,) = read_model(write(tmp_path, quad_gltf())).objects
    assert len(mesh.vertices) == 4 and mesh.normals is None
    np.testing.assert_allclose(mesh.vertex_normals, [[0, 0, 1]] * 4)


@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_a_part_without_normals_is_shaded_flat(tmp_path, method):
    """Seen along (1, 1, -3), three faces face the eye (the -x, -y and slanted ones): the
    picture shows their three normals and no other."""
    scene = read_model(write(tmp_path, tetrahedron()))
    centre = np.array([0.25, 0.25, 0.25])
    camera = pp.Camera(eye=centre + 1.5 * np.array([-1, -1, 3]), target=centre, width=64,
                       height=48)
    image = pp.render(dataclasses.replace(scene, camera=camera), method=method,
                      shading="phong")
    found = np.unique(np.round(image.normal[image.alpha > 0.0], 6), axis=0)
    np.testing.assert_allclose(found, [FACE_NORMALS[2], FACE_NORMALS[1], FACE_NORMALS[3]],
                               atol=1e-6)
