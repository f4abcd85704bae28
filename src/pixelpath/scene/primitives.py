"""Analytic primitives: sphere, infinite plane and axis-aligned box, each convertible to a mesh.

The ray tracer intersects spheres and planes exactly; the raster methods draw their meshes.
A ``Plane`` is infinite: ``to_mesh`` returns one large quad around a chosen centre, which the
raster stage clips to the view.
"""

from __future__ import annotations

import dataclasses
import functools
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record
from pixelpath.scene.material import Material
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.procedural import icosphere

# A plane's quad: the corners' steps along its tangents, counter-clockwise seen from its normal.
_QUAD_SIGNS = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=np.float64)
_QUAD_SIGNS.flags.writeable = False


def _material(value: Any) -> Material:
    return Material() if value is None else v.instance(value, "material", Material)


@dataclasses.dataclass(frozen=True, eq=False)
class Sphere(Record):
    """A sphere of ``radius`` > 0 around ``center``.

    Examples
    --------
    >>> from pixelpath.scene import Sphere
    >>> Sphere(center=(0, 1, 0), radius=2).bounds().tolist()
    [[-2.0, -1.0, -2.0], [2.0, 3.0, 2.0]]
    """

    center: Any
    radius: float
    material: Material = dataclasses.field(default_factory=Material)

    def __post_init__(self) -> None:
        self._set(
            center=v.vector3(self.center, "center"),
            radius=v.real(self.radius, "radius", positive=True),
            material=_material(self.material),
        )

    def bounds(self) -> np.ndarray:
        """Return the (2, 3) axis-aligned bounding box ``[minimum, maximum]``.

        Examples
        --------
        >>> from pixelpath.scene import Sphere
        >>> Sphere((1, 1, 1), 0.5).bounds().tolist()
        [[0.5, 0.5, 0.5], [1.5, 1.5, 1.5]]
        """
        return np.stack([self.center - self.radius, self.center + self.radius])

    def to_mesh(self, subdivisions: int = 3) -> Mesh:
        """Return an icosphere approximation with exact (radial) vertex normals.

        Examples
        --------
        >>> from pixelpath.scene import Sphere
        >>> Sphere((0, 0, 0), 1.0).to_mesh(subdivisions=2).face_count
        320
        """
        return icosphere(subdivisions, self.radius, self.center, self.material)


@dataclasses.dataclass(frozen=True, eq=False)
class Plane(Record):
    """The infinite plane through ``point`` with unit ``normal`` (normalized on input).

    Examples
    --------
    >>> from pixelpath.scene import Plane
    >>> Plane(point=(0, -1, 0), normal=(0, 3, 0)).normal.tolist()
    [0.0, 1.0, 0.0]
    """

    point: Any
    normal: Any
    material: Material = dataclasses.field(default_factory=Material)

    def __post_init__(self) -> None:
        self._set(
            point=v.vector3(self.point, "point"),
            normal=v.unit_vector3(self.normal, "normal"),
            material=_material(self.material),
        )

    def tangents(self) -> tuple[np.ndarray, np.ndarray]:
        """Return unit vectors (t1, t2) in the plane with ``t1 × t2 = normal``.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath.scene import Plane
        >>> t1, t2 = Plane((0, 0, 0), (0, 0, 1)).tangents()
        >>> np.cross(t1, t2).tolist()
        [0.0, 0.0, 1.0]
        """
        t1, t2 = _tangent_frame(self.normal.tobytes())
        return t1.copy(), t2.copy()

    def to_mesh(self, center: Any = (0.0, 0.0, 0.0), half_size: float = 100.0) -> Mesh:
        """Return a square quad of side ``2·half_size`` centred at ``center``'s projection.

        The quad is counter-clockwise seen from the side ``normal`` points to.

        Examples
        --------
        >>> from pixelpath.scene import Plane
        >>> quad = Plane((0, 0, 0), (0, 1, 0)).to_mesh(center=(5, 3, 0), half_size=1)
        >>> quad.bounds().tolist()
        [[4.0, 0.0, -1.0], [6.0, 0.0, 1.0]]
        """
        normals = np.tile(self.normal, (4, 1))
        return Mesh(self.corners(center, half_size), [[0, 1, 2, 3]], self.material,
                    normals=normals, name="plane")

    def corners(self, center: Any = (0.0, 0.0, 0.0), half_size: float = 100.0) -> np.ndarray:
        """Return the (4, 3) corners of :meth:`to_mesh`'s quad, counter-clockwise.

        Examples
        --------
        >>> from pixelpath.scene import Plane
        >>> Plane((0, 0, 0), (0, 1, 0)).corners(center=(5, 3, 0), half_size=1)[0].tolist()
        [4.0, 0.0, -1.0]
        """
        c = v.vector3(center, "center")
        half = v.real(half_size, "half_size", positive=True)
        middle = c - np.dot(c - self.point, self.normal) * self.normal
        t1, t2 = _tangent_frame(self.normal.tobytes())
        return middle + half * (_QUAD_SIGNS[:, :1] * t1 + _QUAD_SIGNS[:, 1:] * t2)


@functools.lru_cache(maxsize=64)
def _tangent_frame(normal: bytes) -> tuple[np.ndarray, np.ndarray]:
    """:meth:`Plane.tangents` of a unit normal given as its float64 bytes, read-only, kept.

    Keyed by the bytes, which tell -0.0 from 0.0 as the arithmetic does. A turntable fits its
    floor's grid to every frame's camera, and NumPy's two cross products took 60 µs of each fit.
    """
    n = np.frombuffer(normal, dtype=np.float64)
    helper = np.eye(3)[int(np.argmin(np.abs(n)))]  # the axis least aligned with n
    t1 = np.cross(helper, n)
    t1 /= np.linalg.norm(t1)
    return v.frozen(t1), v.frozen(np.cross(n, t1))


@dataclasses.dataclass(frozen=True, eq=False)
class Box(Record):
    """The axis-aligned box between corners ``minimum`` and ``maximum`` (strictly less per axis).

    Examples
    --------
    >>> from pixelpath.scene import Box
    >>> Box(minimum=(-1, -1, -1), maximum=(1, 1, 1)).to_mesh().face_count
    6
    """

    minimum: Any
    maximum: Any
    material: Material = dataclasses.field(default_factory=Material)

    def __post_init__(self) -> None:
        low = v.vector3(self.minimum, "minimum")
        high = v.vector3(self.maximum, "maximum")
        if np.any(low >= high):
            raise ValueError(
                f"minimum must be less than maximum on every axis, got minimum {low.tolist()} "
                f"and maximum {high.tolist()}"
            )
        self._set(minimum=low, maximum=high, material=_material(self.material))

    def bounds(self) -> np.ndarray:
        """Return the (2, 3) axis-aligned bounding box ``[minimum, maximum]``.

        Examples
        --------
        >>> from pixelpath.scene import Box
        >>> Box((0, 0, 0), (1, 2, 3)).bounds().tolist()
        [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]]
        """
        return np.stack([self.minimum, self.maximum])

    def to_mesh(self) -> Mesh:
        """Return the 6 outward quads (24 vertices, so each face has its own flat normal).

        Examples
        --------
        >>> from pixelpath.scene import Box
        >>> mesh = Box((0, 0, 0), (1, 1, 1)).to_mesh()
        >>> len(mesh.vertices), mesh.face_normals[0].tolist()
        (24, [1.0, 0.0, 0.0])
        """
        center = (self.minimum + self.maximum) / 2.0
        half = (self.maximum - self.minimum) / 2.0
        corners, normals = [], []
        square = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=np.float64)
        for axis in range(3):
            for sign in (1.0, -1.0):
                # (t1, t2, outward) is right-handed, so square's order is CCW seen from outside.
                t1, t2 = np.eye(3)[[(axis + 1) % 3, (axis + 2) % 3]]
                if sign < 0:
                    t1, t2 = t2, t1
                outward = sign * np.eye(3)[axis]
                face_center = center + outward * half
                corners.append(face_center + half * (square[:, :1] * t1 + square[:, 1:] * t2))
                normals.append(np.tile(outward, (4, 1)))
        faces = np.arange(24, dtype=np.intp).reshape(6, 4)
        return Mesh(np.vstack(corners), faces, self.material, np.vstack(normals), name="box")
