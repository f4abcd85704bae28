"""Polygon meshes: ragged faces, fan triangles, Newell face normals, area-weighted vertex normals.

Faces are polygons of three or more vertex indices, wound counter-clockwise seen from outside, so
the right-hand rule gives outward normals (SPEC, "Precise conventions"). They are stored in the
ragged (CSR) layout kernels like: ``face_indices[face_offsets[f]:face_offsets[f + 1]]`` are the
vertices of face ``f``.

- Face normals use Newell's method, which sums over the polygon's edges (i, j):
  ``N = Σ ((y_i − y_j)(z_i + z_j), (z_i − z_j)(x_i + x_j), (x_i − x_j)(y_i + y_j))``. The sum is
  twice the polygon's vector area, well defined for non-planar polygons too. A degenerate face
  (zero area) has the zero vector as its normal: it covers no pixels.
- Vertex normals, when not given, are the normalized sum of the un-normalized Newell vectors of
  the faces around the vertex, i.e. the area-weighted average of their unit normals. A vertex no
  face uses (or whose faces cancel) gets the zero vector.
- Rendering uses the fan triangulation ``(v0, v_k, v_k+1)`` of every polygon, which is exact
  when the polygon is convex (or every vertex is visible from v0). A polygon whose fan folds
  over (a fan triangle facing against the polygon's Newell normal: a concave polygon, such as
  an L or C shape from an OBJ file) is cut into ears instead, in the plane it projects to
  best; either way a polygon of k vertices gives k - 2 triangles, wound as it is, and
  ``triangle_face`` maps each triangle back to its polygon.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene.material import Material

_UNCHANGEABLE = (
    "cannot set {name!r}: a Mesh cannot be changed once made (renderers keep what they derive "
    "from it); make a new one, e.g. Mesh(mesh.vertices, mesh.faces, material, mesh.normals, "
    "mesh.colors, mesh.uv, mesh.name)"
)


class Mesh:
    """A polygon mesh with a material.

    Parameters
    ----------
    vertices : (V, 3) array_like
        Vertex positions; finite.
    faces : (F, k) int array_like or sequence of sequences of int
        Polygons of at least three vertex indices each, counter-clockwise seen from outside.
    material : Material, optional
        Surface material (default ``Material()``).
    normals : (V, 3) array_like, optional
        Per-vertex normals (normalized on input); computed area-weighted when omitted.
    colors : (V, 3) or (V, 4) array_like, optional
        Per-vertex colours, linear, in [0, 1] (uint8 is scaled by 1/255): they multiply the
        material's colour (and its texture) across each face. A fourth column is alpha (stored;
        it affects only what alpha the material asks for). Stored as (V, 4).
    uv : (V, 2) array_like, optional
        Per-vertex texture coordinates, u to the right and v **up**: (0, 0) is the bottom-left
        of the material's texture picture (OBJ's and trimesh's convention).
    name : str, optional
        A label for messages and ``pixelpath info``.

    Raises
    ------
    ValueError
        Empty meshes, non-finite vertices, faces with fewer than three vertices or with indices
        outside ``0..V-1`` (the message names the face).

    Notes
    -----
    A mesh cannot be changed once made, like every scene object: the renderers keep what they
    derive from it (its BVH, its triangles, its edges) for as long as it lives, and a changed
    mesh would be drawn as it was. Setting an attribute raises ``AttributeError``; make a new
    mesh instead, for example ``Mesh(mesh.vertices, mesh.faces, red, mesh.normals, mesh.colors,
    mesh.uv, mesh.name)`` for another material.

    Examples
    --------
    >>> from pixelpath.scene import Mesh
    >>> quad = Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    >>> quad.triangles.tolist()
    [[0, 1, 2], [0, 2, 3]]
    >>> quad.face_normals.tolist()
    [[0.0, 0.0, 1.0]]
    >>> painted = Mesh(quad.vertices, quad.faces, colors=[[1, 0, 0]] * 4, uv=[[0, 0]] * 4)
    >>> painted.colors[0].tolist()
    [1.0, 0.0, 0.0, 1.0]
    """

    def __init__(
        self,
        vertices: Any,
        faces: Any,
        material: Material | None = None,
        normals: Any = None,
        colors: Any = None,
        uv: Any = None,
        name: str | None = None,
        *,
        source: dict[str, Any] | None = None,
    ) -> None:
        self.vertices = v.frozen(v.float_array(vertices, "vertices", (None, 3)))
        if len(self.vertices) == 0:
            raise ValueError("vertices is empty: a mesh needs at least three vertices")
        offsets, indices = _ragged_faces(faces, len(self.vertices))
        self.face_offsets = v.frozen(offsets)
        self.face_indices = v.frozen(indices)
        self.material = v.instance(material or Material(), "material", Material)
        self.normals = None if normals is None else _given_normals(normals, len(self.vertices))
        self.colors = None if colors is None else _given_colors(colors, len(self.vertices))
        self.uv = None if uv is None else v.frozen(v.float_array(uv, "uv", (len(self.vertices), 2)))
        if name is not None and not isinstance(name, str):
            raise TypeError(f"name must be a str, got {type(name).__name__}")
        self.name = name
        # How this mesh was made (a file path or a generator and a transform), so that
        # Scene.to_dict can write it back compactly; None means "write the arrays inline".
        self.source = source
        self._sealed = True

    def __setattr__(self, name: str, value: Any) -> None:
        if self.__dict__.get("_sealed"):
            raise AttributeError(_UNCHANGEABLE.format(name=name))
        object.__setattr__(self, name, value)

    def __delattr__(self, name: str) -> None:
        raise AttributeError(_UNCHANGEABLE.format(name=name))

    def _label(self, *, name: str | None, source: dict[str, Any] | None) -> Mesh:
        """Set the loader's bookkeeping (``name``, ``source``), which no renderer reads.

        Both are required: a default would quietly erase the one a caller left out.
        """
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "source", source)
        return self

    __hash__ = None  # meshes compare by value

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Mesh):
            return NotImplemented
        return (
            np.array_equal(self.vertices, other.vertices)
            and np.array_equal(self.face_offsets, other.face_offsets)
            and np.array_equal(self.face_indices, other.face_indices)
            and _same_optional(self.normals, other.normals)
            and _same_optional(self.colors, other.colors)
            and _same_optional(self.uv, other.uv)
            and self.material == other.material
            and self.name == other.name
        )

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return (
            f"<Mesh{label}: {len(self.vertices)} vertices, {self.face_count} faces, "
            f"{len(self.triangles)} triangles>"
        )

    @property
    def face_count(self) -> int:
        """Number of polygon faces F."""
        return len(self.face_offsets) - 1

    @property
    def face_sizes(self) -> np.ndarray:
        """(F,) intp number of vertices of each face."""
        return np.diff(self.face_offsets)

    @property
    def faces(self) -> list[list[int]]:
        """The faces as a list of vertex-index lists (the constructor's ragged form)."""
        flat = self.face_indices.tolist()
        bounds = self.face_offsets.tolist()
        return [flat[start:stop] for start, stop in itertools.pairwise(bounds)]

    @functools.cached_property
    def triangles(self) -> np.ndarray:
        """(T, 3) intp triangles of every face, T = Σ (k_f − 2): fans, ears where concave."""
        sizes = self.face_sizes
        triangle_face = self.triangle_face
        # k-th triangle of face f is (v0, v_{k+1}, v_{k+2}): its rank inside the face is k.
        first_triangle = np.cumsum(sizes - 2) - (sizes - 2)
        rank = np.arange(len(triangle_face)) - np.repeat(first_triangle, sizes - 2)
        first = self.face_offsets[triangle_face]
        corners = np.stack([first, first + rank + 1, first + rank + 2], axis=1)
        triangles = np.ascontiguousarray(self.face_indices[corners], dtype=np.intp)
        for face in self._folded_faces(triangles):
            polygon = self.face_indices[self.face_offsets[face] : self.face_offsets[face + 1]]
            start = first_triangle[face]
            triangles[start : start + len(polygon) - 2] = polygon[
                _ears(self.vertices[polygon], self._newell[face])
            ]
        return v.frozen(triangles)

    def _folded_faces(self, triangles: np.ndarray) -> np.ndarray:
        """Return the faces of four or more vertices with a fan triangle facing backwards."""
        in_polygon = np.flatnonzero(self.face_sizes[self.triangle_face] > 3)
        if len(in_polygon) == 0:  # triangle meshes: nothing to look at
            return in_polygon
        a, b, c = (self.vertices[triangles[in_polygon, k]] for k in range(3))
        facing = np.einsum("ij,ij->i", np.cross(b - a, c - a),
                           self._newell[self.triangle_face[in_polygon]])
        return np.unique(self.triangle_face[in_polygon[facing < 0.0]])

    @functools.cached_property
    def triangle_face(self) -> np.ndarray:
        """(T,) intp index of the polygon each triangle of :attr:`triangles` comes from."""
        return v.frozen(np.repeat(np.arange(self.face_count, dtype=np.intp), self.face_sizes - 2))

    @functools.cached_property
    def _newell(self) -> np.ndarray:
        """(F, 3) un-normalized Newell vectors: twice each face's vector area.

        Coordinate by coordinate, each gathered into a contiguous row: the same products and
        sums as over the (N, 3) corners, at two thirds of the time (the bunny's 69,451 faces).
        Triangles, the commonest faces, take :func:`_triangle_newell`.
        """
        if len(self.face_indices) == 3 * self.face_count:  # every face a triangle
            return _triangle_newell(self.vertices, self.face_indices.reshape(-1, 3))
        x, y, z = np.ascontiguousarray(self.vertices.T)[:, self.face_indices]
        following = np.arange(1, len(self.face_indices) + 1)
        following[self.face_offsets[1:] - 1] = self.face_offsets[:-1]  # last corner wraps to first
        xn, yn, zn = x[following], y[following], z[following]
        starts = self.face_offsets[:-1]
        return np.stack([
            np.add.reduceat((y - yn) * (z + zn), starts),
            np.add.reduceat((z - zn) * (x + xn), starts),
            np.add.reduceat((x - xn) * (y + yn), starts),
        ], axis=1)

    @functools.cached_property
    def face_areas(self) -> np.ndarray:
        """(F,) area of each face (of its vector area for a non-planar polygon)."""
        return v.frozen(0.5 * np.linalg.norm(self._newell, axis=1))

    @functools.cached_property
    def face_normals(self) -> np.ndarray:
        """(F, 3) unit face normals by Newell's method; zero for degenerate faces."""
        return v.frozen(v.unit_or_zero(self._newell))

    @functools.cached_property
    def vertex_normals(self) -> np.ndarray:
        """(V, 3) unit vertex normals: the given ``normals``, else area-weighted face normals."""
        if self.normals is not None:
            return self.normals
        owner = np.repeat(self._newell, self.face_sizes, axis=0)
        count = len(self.vertices)
        return v.frozen(v.unit_or_zero(v.sum_rows_at(self.face_indices, owner, count)))

    def bounds(self) -> np.ndarray:
        """Return the (2, 3) axis-aligned bounding box ``[minimum, maximum]`` of the vertices.

        Computed once per mesh (every render asks for it); the array is read-only.

        Examples
        --------
        >>> from pixelpath.scene import Box
        >>> Box((0, 0, 0), (1, 2, 3)).to_mesh().bounds().tolist()
        [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]]
        """
        return self._bounds

    @functools.cached_property
    def _bounds(self) -> np.ndarray:
        return v.frozen(bounding_box(self.vertices))

    def transformed(self, matrix: Any) -> Mesh:
        """Return this mesh under an affine (4, 4) transform; normals use the inverse transpose.

        A transform that mirrors (negative determinant) reverses each face's winding, so faces
        stay counter-clockwise seen from outside.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath.scene import Mesh
        >>> tri = Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> mirrored = tri.transformed(np.diag([1.0, 1.0, -1.0, 1.0]))  # z -> -z
        >>> mirrored.face_normals.tolist(), mirrored.faces
        ([[0.0, 0.0, -1.0]], [[0, 2, 1]])
        """
        linear, shift = _affine_parts(matrix)
        vertices = moved(self.vertices, linear, shift)
        normals = None
        if self.normals is not None:
            normals = self.normals @ np.linalg.inv(linear)  # (L^-T n) for each row n
        faces: Any = (self.face_offsets, self.face_indices)
        if np.linalg.det(linear) < 0.0:
            faces = (self.face_offsets, _reverse_windings(self.face_offsets, self.face_indices))
        return Mesh(
            vertices,
            _RaggedFaces(*faces),
            self.material,
            normals,
            self.colors,
            self.uv,
            self.name,
        )

    @classmethod
    def load(cls, path: str | Path, material: Material | None = None) -> Mesh:
        """Read an OBJ, PLY or STL file through trimesh, keeping its polygon faces.

        Normals stored in the file are used when there is one per vertex; otherwise they are
        computed area-weighted. This reads the geometry alone, with ``material`` (the default
        material when None): a file's own materials, textures, texture coordinates and vertex
        colours, and glTF/GLB files, are read by :func:`pixelpath.load_scene` and
        :func:`pixelpath.io.models.read_model_objects`.

        Raises
        ------
        FileNotFoundError
            When ``path`` does not exist.
        ValueError
            For unsupported formats, unreadable or empty meshes and out-of-range indices; the
            message names the file.

        Examples
        --------
        >>> from pixelpath.scene import Mesh
        >>> Mesh.load("suzanne.obj").face_count  # doctest: +SKIP
        500
        """
        from pixelpath.io.meshes import read_mesh

        path = Path(path)
        vertices, faces, normals = read_mesh(path)
        try:
            return cls(vertices, faces, material, normals, name=path.stem, source={"path": path})
        except ValueError as exc:
            raise ValueError(f"{path}: {exc}") from None


class _RaggedFaces:
    """Faces already in (offsets, indices) form, passed between meshes without re-checking."""

    def __init__(self, offsets: np.ndarray, indices: np.ndarray) -> None:
        self.offsets = offsets
        self.indices = indices


def _ragged_faces(faces: Any, vertex_count: int) -> tuple[np.ndarray, np.ndarray]:
    """Return (offsets, indices) of ``faces`` after checking sizes and index range."""
    if isinstance(faces, _RaggedFaces):
        return faces.offsets.copy(), faces.indices.copy()
    offsets, indices, smallest = _faces_to_ragged(faces)
    if len(offsets) == 1:
        raise ValueError("faces is empty: a mesh needs at least one face")
    # the fewest corners of a face, and the indices' minimum and maximum, tell whether anything
    # is wrong, quicker than masks of every element; the masks then say where
    if smallest < 3:
        sizes = np.diff(offsets)
        face = int(np.argmax(sizes < 3))
        raise ValueError(f"face {face} has {sizes[face]} vertices; a face needs at least 3")
    if indices.min() < 0 or indices.max() >= vertex_count:
        corner = int(np.argmax((indices < 0) | (indices >= vertex_count)))
        face = int(np.searchsorted(offsets, corner, side="right") - 1)
        raise ValueError(
            f"face {face} refers to vertex {indices[corner]}, outside 0..{vertex_count - 1} "
            f"(the mesh has {vertex_count} vertices)"
        )
    return offsets, indices


def _faces_to_ragged(faces: Any) -> tuple[np.ndarray, np.ndarray, int]:
    """Return (offsets, indices, the fewest vertices of a face) of polygons (0 when none)."""
    if isinstance(faces, str) or not isinstance(faces, Sequence | np.ndarray):
        raise TypeError(f"faces must be a sequence of polygons, got {type(faces).__name__}")
    try:
        table = np.asarray(faces)
    except ValueError:  # ragged: polygons of several sizes
        table = None
    if table is not None and table.ndim == 2 and table.dtype.kind in "iu":  # integers
        count, size = table.shape
        offsets = np.arange(count + 1, dtype=np.intp) * size
        return offsets, np.ascontiguousarray(table, dtype=np.intp).reshape(-1), size
    polygons = [_index_list(face, number) for number, face in enumerate(faces)]
    sizes = [len(p) for p in polygons]
    offsets = np.concatenate([[0], np.cumsum(sizes, dtype=np.intp)]).astype(np.intp)
    indices = np.concatenate(polygons).astype(np.intp) if polygons else np.zeros(0, np.intp)
    return offsets, indices, min(sizes, default=0)


def _index_list(face: Any, number: int) -> np.ndarray:
    try:
        array = np.asarray(face)
    except ValueError:
        array = np.asarray([None])
    if array.ndim != 1 or not (np.issubdtype(array.dtype, np.integer) or array.size == 0):
        raise TypeError(f"face {number} must be a sequence of vertex indices (ints), got {face!r}")
    return array.astype(np.intp)


def _given_normals(normals: Any, vertex_count: int) -> np.ndarray:
    array = v.float_array(normals, "normals", (vertex_count, 3), copy=False)  # only read
    lengths = v.row_lengths(array)
    if not lengths.all():  # a zero vector has length 0 (and so may a tiny one): look closer
        zero = (array[:, 0] == 0.0) & (array[:, 1] == 0.0) & (array[:, 2] == 0.0)
        if np.any(zero):
            raise ValueError(f"normals[{int(np.argmax(zero))}] is the zero vector")
    return v.frozen(v.unit_rows(array, lengths))


def _given_colors(colors: Any, vertex_count: int) -> np.ndarray:
    """Return (V, 4) colours in [0, 1] (alpha 1 when not given); uint8 is scaled by 1/255."""
    raw = np.asarray(colors) if not isinstance(colors, str) else colors
    scale = 255.0 if getattr(raw, "dtype", None) == np.uint8 else 1.0
    array = v.float_array(raw, "colors", (vertex_count, None)) / scale
    if array.shape[1] not in (3, 4):
        raise ValueError(f"colors must have shape (V, 3) or (V, 4), got shape {array.shape}")
    if array.min(initial=0.0) < 0.0 or array.max(initial=0.0) > 1.0:
        raise ValueError(
            f"colors must lie in [0, 1] (or be uint8), got {array.min():g}..{array.max():g}"
        )
    if array.shape[1] == 3:
        array = np.concatenate([array, np.ones((vertex_count, 1))], axis=1)
    return v.frozen(array)


def bounding_box(points: np.ndarray) -> np.ndarray:
    """Return the (2, 3) minimum and maximum corners of (N, 3) ``points``.

    On the columns made contiguous: NumPy's ``points.min(axis=0)`` on an (N, 3) array is some
    ten times slower than three column minima, with the same values, and the minima of
    strided columns twice those of a copy laid out column by column.

    Examples
    --------
    >>> from pixelpath.scene.mesh import bounding_box
    >>> bounding_box(np.array([[0.0, 5.0, 1.0], [2.0, -1.0, 1.0]])).tolist()
    [[0.0, -1.0, 1.0], [2.0, 5.0, 1.0]]
    """
    columns = np.ascontiguousarray(points.T)
    return np.stack([columns.min(axis=1), columns.max(axis=1)])


def moved(points: np.ndarray, linear: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """Return (N, 3) ``points`` under the affine map ``x -> linear @ x + shift``, as (N, k).

    ``linear`` is (k, 3) and ``shift`` (k,): k = 3 for points moved in space, 4 for their
    homogeneous clip coordinates. ``points @ linear.T + shift``, bit for bit, the shift added
    column by column: adding a (k,) row to (N, k) runs NumPy's inner loop k elements long, at
    two to five times the time.

    Examples
    --------
    >>> from pixelpath.scene.mesh import moved
    >>> moved(np.array([[1.0, 2.0, 3.0]]), np.eye(3) * 2.0, np.array([0.0, 0.0, 1.0])).tolist()
    [[2.0, 4.0, 7.0]]
    """
    result = points @ linear.T
    for axis, offset in enumerate(shift.tolist()):
        result[:, axis] += offset
    return result


def _triangle_newell(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Return (F, 3) Newell vectors of triangles (a, b, c), as ``Mesh._newell`` sums them.

    The edges' terms (a, b), (b, c), (c, a) are added as ``np.add.reduceat`` adds a face's
    three: the first plus the sum of the other two, so the bits are those of the general
    path, at under half its time (no corner gathered twice, no sums over segments): 0.10 s
    against 0.23-0.29 s for 1.3 million triangles, at rest.
    """
    coordinates = np.ascontiguousarray(vertices.T)
    corners = [np.ascontiguousarray(triangles[:, k]) for k in range(3)]
    x, y, z = ([row[corner] for corner in corners] for row in coordinates)
    newell = np.empty((len(triangles), 3))
    for axis, (p, q) in enumerate(((y, z), (z, x), (x, y))):
        first = (p[0] - p[1]) * (q[0] + q[1])
        rest = (p[1] - p[2]) * (q[1] + q[2]) + (p[2] - p[0]) * (q[2] + q[0])
        newell[:, axis] = first + rest
    return newell


def _same_optional(a: np.ndarray | None, b: np.ndarray | None) -> bool:
    return (a is None) == (b is None) and (a is None or np.array_equal(a, b))


def _ears(points: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """Return (k - 2, 3) corner numbers cutting a polygon of k ``points`` into ears.

    The polygon is projected on the coordinate plane its ``normal`` (Newell's vector) is most
    nearly perpendicular to, keeping its winding counter-clockwise there. An ear is a convex
    corner whose triangle holds no other corner; cutting one leaves a polygon of one corner
    fewer. A polygon with no ear left (it crosses itself) keeps the fan of what remains.
    """
    axis = int(np.argmax(np.abs(normal)))
    u, w = (axis + 1) % 3, (axis + 2) % 3
    if normal[axis] < 0.0:
        u, w = w, u
    flat = points[:, [u, w]]
    ring = list(range(len(points)))
    ears = []
    while len(ring) > 3:
        ear = _an_ear(flat, ring)
        if ear is None:
            break
        ears.append((ring[ear - 1], ring[ear], ring[(ear + 1) % len(ring)]))
        del ring[ear]
    ears += [(ring[0], ring[k], ring[k + 1]) for k in range(1, len(ring) - 1)]
    return np.array(ears, dtype=np.intp)


def _an_ear(flat: np.ndarray, ring: list[int]) -> int | None:
    """Return the place in ``ring`` of a convex corner whose triangle holds no other corner."""
    for k in range(len(ring)):
        corner = (ring[k - 1], ring[k], ring[(k + 1) % len(ring)])
        a, b, c = flat[list(corner)]
        if _cross(a, b, c) <= 0.0:  # a reflex (or straight) corner is no ear
            continue
        others = flat[[j for j in ring if j not in corner]]
        inside = (_cross(a, b, others) >= 0.0) & (_cross(b, c, others) >= 0.0) & (
            _cross(c, a, others) >= 0.0
        )
        if not inside.any():
            return k
    return None


def _cross(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> Any:
    """Return the z of (b - a) × (c - a): positive when a, b, c turn counter-clockwise."""
    c = np.asarray(c)
    return (b[0] - a[0]) * (c[..., 1] - a[1]) - (b[1] - a[1]) * (c[..., 0] - a[0])


def _affine_parts(matrix: Any) -> tuple[np.ndarray, np.ndarray]:
    m = v.float_array(matrix, "matrix", (4, 4))
    if not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
        raise ValueError(f"matrix must be affine (last row 0, 0, 0, 1), got {m[3].tolist()}")
    if abs(np.linalg.det(m[:3, :3])) < 1e-300:
        raise ValueError("matrix is singular: it would flatten the mesh")
    return m[:3, :3], m[:3, 3]


def _reverse_windings(offsets: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Reverse each polygon's vertex order, keeping its first vertex first."""
    face = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    start, stop = offsets[face], offsets[face + 1]
    position = np.arange(len(indices))
    mirrored = np.where(position == start, start, start + stop - position)
    return indices[mirrored]
