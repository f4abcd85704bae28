"""A bounding-volume hierarchy over triangles, and the nearest hits of many rays on a mesh.

The tree is built in compiled code with the binned surface-area heuristic and stored in flat
arrays (see :mod:`pixelpath.raytrace._bvh_kernels` for the layout and
:mod:`pixelpath.raytrace._traversal_kernels` for the traversals). The triangles are stored in
leaf order, so the ones a leaf holds are next to each other in memory.
:func:`intersect` is a headless replacement for trimesh's ray module: the nearest triangle of a
million rays in one call, traced on several threads, with the ray tracer's watertight test.

Examples
--------
>>> import numpy as np
>>> from pixelpath.scene import Box
>>> from pixelpath.raytrace import intersect
>>> cube = Box((-1, -1, -1), (1, 1, 1)).to_mesh()
>>> t, face = intersect(cube, [[0, 0, 5], [3, 3, 5]], (0, 0, -1))  # face 4 faces +z
>>> t.tolist(), face.tolist()
([4.0, inf], [4, -1])
"""

from __future__ import annotations

import dataclasses
import time
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath._threads import in_threads
from pixelpath.raster.tessellate import _IdentityCache
from pixelpath.raytrace.geometry import _broadcast, _nonzero
from pixelpath.scene import Mesh

__all__ = ["BVH", "intersect"]


@dataclasses.dataclass(frozen=True, eq=False)
class BVH:
    """A binned-SAH bounding-volume hierarchy over triangles, in flat arrays.

    Build one with :meth:`build`. Node k has the box ``bounds[k]`` (min x, y, z, max x, y, z)
    and ``links[k] = (first, count)``: a leaf (count > 0) holds the triangles at positions
    ``first .. first + count − 1`` of the leaf order, an inner node (count 0) has the children
    ``first`` and ``first + 1``.

    Attributes
    ----------
    bounds : (N, 6) float64
        Node boxes.
    links : (N, 2) intp
        Node links, as above.
    order : (T,) intp
        The triangle (index into the input) at each position of the leaf order.
    corners : (T, 9) float64
        The triangles' corners in leaf order.
    depth : int
        Levels of the tree (1 for a single leaf).
    build_seconds : float
        Wall-clock time the build took (the first build in a process also loads, or compiles,
        the build kernels).

    Examples
    --------
    >>> from pixelpath.scene import icosphere
    >>> from pixelpath.raytrace import BVH
    >>> ball = icosphere(2)
    >>> bvh = BVH.build(ball.vertices, ball.triangles)
    >>> bvh.triangle_count, bvh.statistics()["leaves"] > 1
    (320, True)
    """

    bounds: np.ndarray
    links: np.ndarray
    order: np.ndarray
    corners: np.ndarray
    depth: int
    build_seconds: float

    @classmethod
    def build(cls, vertices: Any, triangles: Any) -> BVH:
        """Build the hierarchy of the triangles ``vertices[triangles]``.

        Parameters
        ----------
        vertices : (V, 3) array_like
            Finite vertex positions.
        triangles : (T, 3) int array_like
            Vertex indices of each triangle, in 0..V-1.

        Returns
        -------
        BVH

        Raises
        ------
        ValueError
            Wrong shapes, non-finite vertices, indices out of range.

        Examples
        --------
        >>> from pixelpath.raytrace import BVH
        >>> bvh = BVH.build([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> bvh.bounds.tolist(), bvh.links.tolist()
        ([[0.0, 0.0, 0.0, 1.0, 1.0, 0.0]], [[0, 1]])
        """
        vertices = v.float_array(vertices, "vertices", (None, 3))
        triangles = _indices(triangles, len(vertices))
        return cls._from_corners(_corners(vertices, triangles))

    @classmethod
    def _from_corners(cls, corners: np.ndarray) -> BVH:
        """Build from checked (T, 9) float64 triangle corners."""
        from pixelpath.raytrace import _bvh_kernels

        start = time.perf_counter()
        count = len(corners)
        boxes = np.empty((count, 6))
        _bvh_kernels.triangle_boxes(corners, boxes)
        order = np.empty(count, dtype=np.intp)
        bounds = np.empty((max(2 * count, 1), 6))
        links = np.empty((max(2 * count, 1), 2), dtype=np.intp)
        used, depth = (0, 0) if count == 0 else _bvh_kernels.build_bvh(
            boxes, order, bounds, links
        )
        return cls(
            bounds=np.ascontiguousarray(bounds[:used]),
            links=np.ascontiguousarray(links[:used]),
            order=order,
            corners=np.take(corners, order, axis=0),
            depth=int(depth),
            build_seconds=time.perf_counter() - start,
        )

    @property
    def triangle_count(self) -> int:
        """Number of triangles T."""
        return len(self.order)

    def statistics(self) -> dict[str, Any]:
        """Return the tree's size and quality: nodes, leaves, depth, SAH cost, build time.

        The SAH cost is the expected cost of a random ray's traversal, in triangle tests:
        ``Σ_inner A(n)/A(root) · NODE_COST + Σ_leaves A(n)/A(root) · count(n)``.

        Examples
        --------
        >>> from pixelpath.raytrace import BVH
        >>> stats = BVH.build([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]).statistics()
        >>> stats["nodes"], stats["leaves"], stats["depth"], stats["SAH cost"]
        (1, 1, 1, 1.0)
        """
        from pixelpath.raytrace._bvh_kernels import NODE_COST

        counts = self.links[:, 1]
        leaves = counts > 0
        extent = self.bounds[:, 3:] - self.bounds[:, :3]
        x, y, z = extent[:, 0], extent[:, 1], extent[:, 2]
        areas = x * y + y * z + z * x
        root = areas[0] if len(areas) and areas[0] > 0 else 1.0
        cost = (np.sum(areas[~leaves]) * NODE_COST + np.sum(areas[leaves] * counts[leaves])) / root
        return {
            "triangles": self.triangle_count,
            "nodes": len(self.links),
            "leaves": int(np.count_nonzero(leaves)),
            "depth": self.depth,
            "triangles per leaf": float(counts[leaves].mean()) if leaves.any() else 0.0,
            "SAH cost": float(cost),
            "build seconds": self.build_seconds,
        }

    def intersect(self, origins: Any, directions: Any) -> tuple[np.ndarray, np.ndarray]:
        """Return (t, triangle) of the nearest hit of each ray; (inf, -1) where it misses.

        Parameters
        ----------
        origins, directions : (..., 3) array_like
            Rays ``origin + t·direction`` (directions of any non-zero length: t is in units
            of their length); the leading axes broadcast.

        Returns
        -------
        t : ndarray of float64
            Distance of the nearest hit with t > 0, shaped like the broadcast leading axes.
        triangle : ndarray of intp
            Index (into the triangles the tree was built from) of the triangle hit.

        Examples
        --------
        >>> from pixelpath.raytrace import BVH
        >>> bvh = BVH.build([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> bvh.intersect([0.25, 0.25, 2.0], [0, 0, -1])
        (array(2.), array(0))
        """
        return self._nearest(origins, directions, self.order)

    def _nearest(
        self, origins: Any, directions: Any, labels: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`intersect`, giving ``labels[i]`` (-1 on a miss) for the triangle i hit.

        i is the triangle's position in the leaf order.
        """
        from pixelpath.raytrace._hit_kernels import slab_nan_allowed
        from pixelpath.raytrace._traversal_kernels import BLOCK, LANES, intersect_many

        # No copies: the rays are only read (a million rays' copies and checks cost more than
        # a fifth of their tracing). The kernel checks their values as it reads them, on
        # every thread; the checks here only give the message when it finds a bad one.
        given = (v.numeric_array(origins, "origins", 3, copy=False),
                 v.numeric_array(directions, "directions", 3, copy=False))
        shape, o, d = _broadcast(dict(zip(("origins", "directions"), given, strict=True)),
                                 {"origins", "directions"})
        t = np.empty(len(o))
        label = np.empty(len(o), dtype=np.intp)
        if self.triangle_count == 0:
            _check_rays(*given)
            t.fill(np.inf)
            label.fill(-1)
        else:
            no_skip = np.zeros(0, dtype=np.bool_)
            levels = self.depth + 1
            unusable = []

            def trace(start: int, stop: int) -> None:
                # The packets start as zeros: a packet of fewer than LANES rays reads (and
                # ignores) the rows it does not fill, which must hold numbers.
                with slab_nan_allowed():
                    unusable.append(intersect_many(
                        self.bounds, self.links, self.corners, self.order, no_skip, False,
                        labels, o, d, start, stop, np.zeros((BLOCK, 9)),
                        np.empty(BLOCK, dtype=np.intp), np.empty(levels, dtype=np.intp),
                        np.empty(levels), np.empty((levels, LANES)), t, label,
                    ))

            in_threads(trace, len(o))
            if any(unusable):
                _check_rays(*given)
        return t.reshape(shape), label.reshape(shape)


def _check_rays(origins: np.ndarray, directions: np.ndarray) -> None:
    """Raise the error that NaN, infinite values or a zero-length direction deserve."""
    v.finite_array(origins, "origins", 3, copy=False)
    _nonzero(v.finite_array(directions, "directions", 3, copy=False), "directions")


def _corners(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Return the (T, 9) corners ``vertices[triangles]`` of the triangles, one row each.

    ``np.take`` gathers the rows in half the time of fancy indexing (a million triangles:
    15 ms, not 41).
    """
    return np.take(vertices, triangles, axis=0).reshape(-1, 9)


def _indices(triangles: Any, vertex_count: int) -> np.ndarray:
    """Return (T, 3) intp triangle indices after checking their type, shape and range."""
    array = np.asarray(triangles)
    if array.size and not np.issubdtype(array.dtype, np.integer):
        raise TypeError(f"faces must be integer vertex indices, got dtype {array.dtype}")
    array = array.astype(np.intp).reshape(array.shape)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"faces must have shape (F, 3) (triangles), got shape {array.shape}")
    bad = (array < 0) | (array >= vertex_count)
    if np.any(bad):
        face = int(np.argwhere(bad)[0, 0])
        raise ValueError(
            f"face {face} refers to vertex {array[face].tolist()}, outside 0..{vertex_count - 1}"
        )
    return array


def _mesh_bvh(mesh: Any) -> tuple[BVH, np.ndarray]:
    """Return the BVH of a mesh's triangles and the face of each triangle in its leaf order.

    A pixelpath ``Mesh`` (immutable) keeps both for later calls; other meshes (a
    ``trimesh.Trimesh``, anything with ``vertices`` (V, 3) and triangle ``faces`` (F, 3)) are
    built each time, since they may change between calls.
    """
    if isinstance(mesh, Mesh):
        return _MESH_TREES.get(mesh, _pixelpath_mesh_bvh)
    if not (hasattr(mesh, "vertices") and hasattr(mesh, "faces")):
        raise TypeError(
            f"mesh must be a pixelpath Mesh or have vertices (V, 3) and faces (F, 3), got "
            f"{type(mesh).__name__}"
        )
    bvh = BVH.build(mesh.vertices, mesh.faces)
    return bvh, bvh.order  # each face is one triangle


def _pixelpath_mesh_bvh(mesh: Any) -> tuple[BVH, np.ndarray]:
    bvh = BVH._from_corners(_corners(mesh.vertices, mesh.triangles))
    return bvh, mesh.triangle_face[bvh.order]


_MESH_TREES = _IdentityCache(16)  # the trees of the last few pixelpath meshes


def intersect(mesh: Any, origins: Any, directions: Any) -> tuple[np.ndarray, np.ndarray]:
    """Return (t, face) of the nearest hit of each ray on a mesh; (inf, -1) where it misses.

    Parameters
    ----------
    mesh : Mesh or mesh-like
        A pixelpath :class:`~pixelpath.Mesh` (polygon faces; its tree is kept for later
        calls), or any object with ``vertices`` (V, 3) and triangle ``faces`` (F, 3), such as
        a ``trimesh.Trimesh``.
    origins, directions : (..., 3) array_like
        Rays ``origin + t·direction``; directions of any non-zero length (t is in units of
        their length); the leading axes broadcast.

    Returns
    -------
    t : ndarray of float64
        Distance of the nearest hit with t > 0 (both sides of a face count), ``inf`` on a miss.
    face : ndarray of intp
        Index of the face hit (a polygon's index for a pixelpath Mesh), -1 on a miss.

    Raises
    ------
    ValueError
        NaN or infinite values, zero-length directions, shapes that do not broadcast, face
        indices out of range.
    TypeError
        A mesh of another kind, non-numeric rays.

    Notes
    -----
    A ray through an edge or a vertex hits one of the faces there, never none (watertight test,
    conservative box tests). Where two faces are hit at exactly the same t, the lower face
    index wins, so the answer is the one a loop over every face would give.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import icosphere
    >>> from pixelpath.raytrace import intersect
    >>> ball = icosphere(3)
    >>> t, face = intersect(ball, np.zeros((2, 3)), [[0, 0, 1], [0, 2, 0]])
    >>> np.round(t, 2).tolist(), bool(face.min() >= 0)
    ([1.0, 0.5], True)
    """
    bvh, leaf_face = _mesh_bvh(mesh)
    return bvh._nearest(origins, directions, leaf_face)
