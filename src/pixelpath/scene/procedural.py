"""Procedural meshes: the subdivided icosahedron (icosphere) and the torus, with exact normals.

Both are closed surfaces wound counter-clockwise seen from outside. Their vertex normals are the
analytic surface normals, not area-weighted averages, so smooth shading shows the true shape.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene.material import Material
from pixelpath.scene.mesh import Mesh

# Maximum subdivision level: level 7 already has 163842 vertices and 327680 triangles.
MAX_SUBDIVISIONS = 7
# Maximum torus segments each way: 1024 × 1024 is a million quads.
MAX_SEGMENTS = 1024
_GOLDEN = (1.0 + math.sqrt(5.0)) / 2.0
_ICOSAHEDRON_VERTICES = np.array(
    [
        [-1, _GOLDEN, 0], [1, _GOLDEN, 0], [-1, -_GOLDEN, 0], [1, -_GOLDEN, 0],
        [0, -1, _GOLDEN], [0, 1, _GOLDEN], [0, -1, -_GOLDEN], [0, 1, -_GOLDEN],
        [_GOLDEN, 0, -1], [_GOLDEN, 0, 1], [-_GOLDEN, 0, -1], [-_GOLDEN, 0, 1],
    ]
)  # fmt: skip
_ICOSAHEDRON_FACES = np.array(
    [
        [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
        [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
        [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
        [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
    ],
    dtype=np.intp,
)  # fmt: skip


def icosphere(
    subdivisions: int = 3,
    radius: float = 1.0,
    center: Any = (0.0, 0.0, 0.0),
    material: Material | None = None,
) -> Mesh:
    """Return a sphere mesh made by splitting an icosahedron's triangles ``subdivisions`` times.

    Each level splits every triangle into four at its edge midpoints, pushed out onto the
    sphere; level s has ``10·4^s + 2`` vertices and ``20·4^s`` triangles.

    Examples
    --------
    >>> from pixelpath.scene import icosphere
    >>> ball = icosphere(subdivisions=1)
    >>> len(ball.vertices), ball.face_count
    (42, 80)
    """
    level = _count(subdivisions, "subdivisions", 0, MAX_SUBDIVISIONS)
    radius = v.real(radius, "radius", positive=True)
    center = v.vector3(center, "center")
    directions = _ICOSAHEDRON_VERTICES / np.linalg.norm(_ICOSAHEDRON_VERTICES[0])
    faces = _ICOSAHEDRON_FACES
    for _ in range(level):
        directions, faces = _split_triangles(directions, faces)
    return Mesh(center + radius * directions, faces, material, normals=directions, name="icosphere")


def _split_triangles(points: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split each triangle into four at its edge midpoints, projected to the unit sphere."""
    edges = np.sort(faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    unique, edge_of = np.unique(edges, axis=0, return_inverse=True)
    midpoints = points[unique[:, 0]] + points[unique[:, 1]]
    midpoints /= np.linalg.norm(midpoints, axis=1, keepdims=True)
    a, b, c = faces.T
    ab, bc, ca = (len(points) + edge_of.reshape(-1, 3)).T
    children = np.stack([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]], axis=0)
    return np.vstack([points, midpoints]), children.transpose(0, 2, 1).reshape(-1, 3)


def torus(
    major_radius: float = 1.0,
    minor_radius: float = 0.25,
    major_segments: int = 32,
    minor_segments: int = 16,
    material: Material | None = None,
) -> Mesh:
    """Return a torus around the Y axis, centred at the origin, made of quads.

    The point at angles (φ around Y, θ around the tube) is
    ``((R + r cos θ) cos φ, r sin θ, (R + r cos θ) sin φ)``.

    Examples
    --------
    >>> from pixelpath.scene import torus
    >>> ring = torus(major_segments=8, minor_segments=4)
    >>> len(ring.vertices), ring.face_count, len(ring.triangles)
    (32, 32, 64)
    """
    big = v.real(major_radius, "major_radius", positive=True)
    small = v.real(minor_radius, "minor_radius", positive=True)
    if small >= big:
        raise ValueError(
            f"minor_radius must be less than major_radius, got {small} >= {big} "
            "(the tube would pass through the axis)"
        )
    around = _count(major_segments, "major_segments", 3, MAX_SEGMENTS)
    tube = _count(minor_segments, "minor_segments", 3, MAX_SEGMENTS)
    phi = 2.0 * np.pi * np.arange(around)[:, None] / around
    theta = 2.0 * np.pi * np.arange(tube)[None, :] / tube
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    normals = np.stack(
        np.broadcast_arrays(cos_t * np.cos(phi), sin_t, cos_t * np.sin(phi)), axis=-1
    ).reshape(-1, 3)
    axis_points = np.stack(np.broadcast_arrays(np.cos(phi), 0.0 * theta, np.sin(phi)), axis=-1)
    vertices = big * axis_points.reshape(-1, 3) + small * normals
    i, j = np.meshgrid(np.arange(around), np.arange(tube), indexing="ij")

    def index(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return (a % around) * tube + b % tube

    # Step along the tube (θ) first, then around the axis (φ): counter-clockwise from outside.
    quads = np.stack([index(i, j), index(i, j + 1), index(i + 1, j + 1), index(i + 1, j)], axis=-1)
    return Mesh(vertices, quads.reshape(-1, 4), material, normals=normals, name="torus")


def _count(value: Any, name: str, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise TypeError(f"{name} must be an int, got {value!r}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name} must be between {low} and {high}, got {value}")
    return int(value)
