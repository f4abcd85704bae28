"""Object transforms: scale, then rotate about X, Y and Z, then translate; and moving objects.

``M = T · Rz · Ry · Rx · S`` acting on column vectors, angles in degrees, right-handed (a positive
angle turns counter-clockwise when looking down the axis towards the origin).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.primitives import Box, Plane, Sphere


def transform_matrix(
    translate: Any = (0.0, 0.0, 0.0), rotate: Any = (0.0, 0.0, 0.0), scale: Any = 1.0
) -> np.ndarray:
    """Return the (4, 4) affine matrix that scales, rotates (X, then Y, then Z) and translates.

    Parameters
    ----------
    translate : (3,) array_like
        Offset added last.
    rotate : (3,) array_like
        Angles in degrees about the X, Y and Z axes, applied in that order.
    scale : float or (3,) array_like
        Uniform or per-axis scale factors (non-zero), applied first.

    Examples
    --------
    >>> from pixelpath.scene import transform_matrix
    >>> m = transform_matrix(translate=(1, 0, 0), rotate=(0, 0, 90), scale=2)
    >>> (m @ [1, 0, 0, 1]).round(12).tolist()  # (2, 0, 0) turned onto +Y, then moved
    [1.0, 2.0, 0.0, 1.0]
    """
    offset = v.float_array(translate, "translate", (3,))
    angles = np.radians(v.float_array(rotate, "rotate", (3,)))
    uniform = np.ndim(scale) == 0
    factors = v.float_array(np.broadcast_to(scale, (3,)) if uniform else scale, "scale", (3,))
    if np.any(factors == 0.0):
        raise ValueError(f"scale factors must be non-zero, got {factors.tolist()}")
    matrix = np.eye(4)
    matrix[:3, :3] = _rotation(2, angles[2]) @ _rotation(1, angles[1]) @ _rotation(0, angles[0])
    matrix[:3, :3] *= factors  # scales the columns: R · diag(s)
    matrix[:3, 3] = offset
    return matrix


def _rotation(axis: int, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    rotation = np.eye(3)
    rotation[i, i], rotation[i, j], rotation[j, i], rotation[j, j] = c, -s, s, c
    return rotation


def transform_object(obj: Any, matrix: Any) -> Any:
    """Return a scene object moved by the (4, 4) affine ``matrix``; the input is left as it is.

    Spheres take translation, rotation and uniform scale (a ``ValueError`` otherwise); planes
    any transform (the point by the matrix, the normal by its inverse transpose); boxes stay
    boxes under translation and scale and become six-quad meshes when rotated; meshes are
    transformed vertex by vertex (:meth:`Mesh.transformed`).

    Examples
    --------
    >>> from pixelpath.scene import Sphere, transform_matrix
    >>> from pixelpath.scene.transform import transform_object
    >>> moved = transform_object(Sphere((1, 0, 0), 1.0), transform_matrix((0, 2, 0), scale=3))
    >>> moved.center.tolist(), moved.radius
    ([3.0, 2.0, 0.0], 3.0)
    """
    matrix = v.float_array(matrix, "matrix", (4, 4))
    linear, shift = matrix[:3, :3], matrix[:3, 3]
    if isinstance(obj, Sphere):
        gram = linear.T @ linear
        scale = float(np.sqrt(gram[0, 0]))
        if not np.allclose(gram, scale**2 * np.eye(3), rtol=1e-9, atol=1e-12 * scale**2):
            raise ValueError(
                "transform must scale a sphere uniformly (use an icosphere for an ellipsoid)"
            )
        return Sphere(linear @ obj.center + shift, scale * obj.radius, obj.material)
    if isinstance(obj, Plane):
        normal = np.linalg.inv(linear).T @ obj.normal
        return Plane(linear @ obj.point + shift, normal, obj.material)
    if isinstance(obj, Box):
        if np.count_nonzero(linear - np.diag(np.diag(linear))) == 0:  # no rotation: a box still
            a, b = (linear @ corner + shift for corner in (obj.minimum, obj.maximum))
            return Box(np.minimum(a, b), np.maximum(a, b), obj.material)
        return obj.to_mesh().transformed(matrix)
    if isinstance(obj, Mesh):
        return obj.transformed(matrix)
    raise TypeError(f"obj must be a Sphere, Plane, Box or Mesh, got {type(obj).__name__}")
