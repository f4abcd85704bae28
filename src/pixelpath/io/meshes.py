"""Mesh files (OBJ, PLY, STL) read through trimesh, keeping polygon faces where the file has them.

trimesh does the parsing. Its loaders triangulate polygons in two places, which are undone here:

- PLY: for ASCII files ``load_ply`` keeps the file's face lists in ``metadata["_ply_raw"]``;
  those are used. Binary PLY files come back whole when all faces have the same size; trimesh
  5.2 cannot read binary files with faces of mixed sizes (a clear error names the file).
- OBJ: ``load_obj`` (with ``maintain_order=True``) keeps whole faces when every face has the same
  size, but splits mixed files' quads into ``(a, b, c), (c, d, a)`` and larger polygons into fans
  ``(a, b, c), (a, c, d), ...``, in file order. The size of each face (the number of vertex
  references on each ``f`` line) tells which consecutive triangles came from one polygon, and
  the polygon is rebuilt only when its triangles match that split exactly; otherwise the
  triangles are kept as they are. Files that trimesh splits into pieces (several objects or
  materials) are joined piece by piece, each keeping whole faces only when they are all the
  same size.

STL: an ASCII file may hold several ``solid ... endsolid`` blocks (CAD programs write a part of
several bodies so), which trimesh reads as one part each: :func:`read_mesh` joins them, and
:func:`read_stl_solids` keeps them apart for model files, one object per solid.

Normals stored in the file (OBJ ``vn``, PLY ``nx ny nz``) are returned when there is one per
vertex. Files without them get their coincident vertices merged (keeping the order of first
appearance), so that area-weighted vertex normals are smooth across seams: STL stores each
triangle's corners separately, and some OBJ files (the Utah teapot) repeat vertices along patch
borders.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

MESH_FORMATS = (".obj", ".ply", ".stl")


def read_mesh(path: str | Path) -> tuple[np.ndarray, list[np.ndarray] | np.ndarray, Any]:
    """Read a mesh file; return ``(vertices, faces, normals)``.

    Parameters
    ----------
    path : str or Path
        An ``.obj``, ``.ply`` or ``.stl`` file.

    Returns
    -------
    vertices : (V, 3) float64
    faces : (F, k) int array or list of int arrays
        Polygons (0-based vertex indices) in file order.
    normals : (V, 3) float64 or None
        Per-vertex normals from the file, if it has one per vertex.

    Raises
    ------
    FileNotFoundError
        When ``path`` does not exist.
    ValueError
        For other formats, files trimesh cannot read, out-of-range indices and files without
        faces; the message starts with the path.

    Examples
    --------
    >>> from pixelpath.io.meshes import read_mesh
    >>> vertices, faces, normals = read_mesh("suzanne.obj")  # doctest: +SKIP
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"mesh file not found: {path}")
    suffix = path.suffix.lower()
    if suffix not in MESH_FORMATS:
        hint = ""
        if suffix in (".glb", ".gltf"):  # parts with materials: more than one mesh holds
            hint = ("; a glTF file is a model of parts, each with its transform and material: "
                    "read it with pixelpath.load_scene (a Scene) or "
                    "pixelpath.io.models.read_model_objects (its meshes)")
        raise ValueError(f"{path}: unsupported mesh format {suffix!r}; expected one of "
                         f"{', '.join(MESH_FORMATS)}{hint}")
    reader = {".obj": _read_obj, ".ply": _read_ply, ".stl": _read_stl}[suffix]
    vertices, faces, normals = _guarded(reader, path)
    if len(faces) == 0:
        raise ValueError(f"{path}: the file has no faces (an empty mesh or a point cloud)")
    vertices = np.asarray(vertices, dtype=np.float64)
    if normals is None or np.shape(normals) != vertices.shape:
        # Without normals in the file, corners at one position are one vertex, so that
        # area-weighted normals are smooth across seams (trimesh's default does the same).
        return *_merge_coincident(vertices, faces), None
    return vertices, faces, normals


def read_stl_solids(path: str | Path) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """Read each solid of an STL file; return ``(name, vertices, triangles)`` per solid.

    An ASCII STL file may hold several ``solid NAME ... endsolid`` blocks, as CAD programs
    write a part of several bodies; :func:`read_mesh` joins them into one mesh, and this
    keeps them apart, in file order, named as the file names them (a binary file, or an
    ASCII one with a single solid, gives one solid named after the file). Coincident
    corners are merged within each solid, as :func:`read_mesh` merges them; solids without
    triangles are left out.

    Raises
    ------
    ValueError
        For files trimesh cannot read; the message starts with the path.

    Examples
    --------
    >>> from pixelpath.io.meshes import read_stl_solids
    >>> [name for name, _, _ in read_stl_solids("multibody.stl")]  # doctest: +SKIP
    ['bodyB', 'bodyA']
    """
    path = Path(path)
    solids = _guarded(_stl_solids, path)
    if len(solids) == 1:
        solids = [(path.stem, *solids[0][1:])]
    return [
        (name, *_merge_coincident(np.asarray(vertices, dtype=np.float64), faces))
        for name, vertices, faces in solids
        if len(faces)
    ]


def _guarded(reader: Callable[[Path], Any], path: Path) -> Any:
    """Call ``reader(path)``, turning the errors of trimesh's parsers into a ValueError."""
    suffix = path.suffix.lower()
    try:
        return reader(path)
    except (IndexError, ValueError, TypeError, KeyError, AttributeError, EOFError) as exc:
        if isinstance(exc, IndexError) and suffix == ".obj":  # load_obj indexes v by f lines
            reason = "a face refers to a vertex that does not exist"
        else:
            reason = f"trimesh could not read this {suffix} file"
        raise ValueError(f"{path}: {reason} ({type(exc).__name__}: {exc})") from None


def _merge_coincident(vertices: np.ndarray, faces: Any) -> tuple[np.ndarray, Any]:
    """Join vertices with equal coordinates, keeping the order of first appearance."""
    _, first, inverse = np.unique(vertices, axis=0, return_index=True, return_inverse=True)
    if len(first) == len(vertices):
        return vertices, faces
    rank = np.empty(len(first), dtype=np.intp)
    rank[np.argsort(first)] = np.arange(len(first))
    remap = rank[inverse.reshape(-1)]
    if isinstance(faces, np.ndarray):
        return vertices[np.sort(first)], remap[faces]
    return vertices[np.sort(first)], [remap[np.asarray(face)] for face in faces]


def _read_obj(path: Path) -> tuple[np.ndarray, Any, Any]:
    from trimesh.exchange.obj import load_obj

    with path.open("rb") as file:
        loaded = load_obj(file, maintain_order=True, group_material=False, skip_materials=True)
    parts = list(loaded.get("geometry", {}).values())
    if not parts:
        return np.zeros((0, 3)), [], None
    if len(parts) > 1:  # several objects or materials: join the pieces
        return _concatenate(parts)
    part = parts[0]
    faces = np.asarray(part["faces"])
    if faces.shape[1] == 3:
        faces = _rebuild_polygons(faces, _obj_face_sizes(path))
    return part["vertices"], faces, part.get("vertex_normals")


def _obj_face_sizes(path: Path) -> np.ndarray:
    """Return the number of vertex references on each ``f`` line, in file order."""
    text = path.read_text(errors="replace").replace("\\\n", "")
    sizes = [len(line.split()) - 1 for line in text.splitlines() if line.startswith("f ")]
    return np.array(sizes, dtype=np.intp)


def _rebuild_polygons(triangles: np.ndarray, sizes: np.ndarray) -> Any:
    """Undo trimesh's quad split and fan triangulation; keep the triangles if they do not match."""
    if np.all(sizes == 3) or np.sum(np.maximum(sizes - 2, 0)) != len(triangles):
        return triangles
    polygons, start = [], 0
    for size in sizes.tolist():
        polygon = _polygon_from(triangles[start : start + size - 2], size)
        if polygon is None:
            return triangles
        polygons.append(polygon)
        start += size - 2
    return polygons


def _polygon_from(group: np.ndarray, size: int) -> np.ndarray | None:
    if size == 3:
        return group[0]
    if size == 4 and group[1][0] == group[0][2] and group[1][2] == group[0][0]:  # (a,b,c),(c,d,a)
        return np.array([*group[0], group[1][1]])
    if np.all(group[:, 0] == group[0, 0]) and np.all(group[1:, 1] == group[:-1, 2]):  # a fan
        return np.concatenate([group[0], group[1:, 2]])
    return None


def _read_ply(path: Path) -> tuple[np.ndarray, Any, Any]:
    from trimesh.exchange.ply import load_ply

    with path.open("rb") as file:
        loaded = load_ply(file, skip_materials=True)
    faces = loaded.get("faces")
    raw_faces = loaded.get("metadata", {}).get("_ply_raw", {}).get("face", {}).get("data")
    # ASCII files keep each face's list here; binary ones (same-size faces only) are already whole.
    if isinstance(raw_faces, dict):
        for key in ("vertex_indices", "vertex_index"):
            if key in raw_faces:
                faces = [np.asarray(face, dtype=np.intp).reshape(-1) for face in raw_faces[key]]
                break
    return loaded["vertices"], [] if faces is None else faces, loaded.get("vertex_normals")


def _read_stl(path: Path) -> tuple[np.ndarray, Any, Any]:
    solids = _stl_solids(path)
    if not solids:
        return np.zeros((0, 3)), [], None
    offsets = np.cumsum([0] + [len(vertices) for _, vertices, _ in solids])
    vertices = np.vstack([vertices for _, vertices, _ in solids])
    faces = np.vstack([
        faces + offset for (_, _, faces), offset in zip(solids, offsets[:-1], strict=True)
    ])
    return vertices, faces, None


def _stl_solids(path: Path) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """Return the file's solids as trimesh reads them: (name, vertices, triangles), in order."""
    from trimesh.exchange.stl import load_stl

    with path.open("rb") as file:
        loaded = load_stl(file)
    if "geometry" in loaded:  # an ASCII file: one part per solid, by name
        parts = loaded["geometry"].items()
        return [(name, part["vertices"], _triangles(part["faces"])) for name, part in parts]
    return [(path.stem, loaded["vertices"], _triangles(loaded["faces"]))]


def _triangles(faces: Any) -> np.ndarray:
    """(T, 3) vertex indices, also where a solid has no facets."""
    return np.asarray(faces, dtype=np.int64).reshape(-1, 3)


def _concatenate(parts: list[dict[str, Any]]) -> tuple[np.ndarray, list[np.ndarray], Any]:
    """Join the pieces trimesh splits a file into (by object or material), faces as given."""
    offsets = np.cumsum([0] + [len(part["vertices"]) for part in parts])
    faces = [
        face + offset
        for part, offset in zip(parts, offsets, strict=False)
        for face in np.asarray(part["faces"])
    ]
    vertices = np.vstack([part["vertices"] for part in parts])
    normals = [part.get("vertex_normals") for part in parts]
    normals = None if any(n is None for n in normals) else np.vstack(normals)
    return vertices, faces, normals
