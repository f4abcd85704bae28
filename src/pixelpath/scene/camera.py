"""A look-at pinhole camera with a vertical field of view, and its OpenGL-style matrices.

Conventions (SPEC, "Precise conventions"): right-handed world; the camera sits at ``eye`` and
looks at ``target``. Its basis is (u right, v up, w backward) with ``w = normalize(eye - target)``,
``u = normalize(up × w)``, ``v = w × u``, so camera space has +X right, +Y up and the camera looks
down -Z. The projection maps the view frustum to clip space; after the perspective divide x, y
and z lie in [-1, 1] inside the frustum, with z = -1 on the near plane and +1 on the far plane,
and ``w_clip = -z_camera`` is the depth along the viewing axis.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record


@dataclasses.dataclass(frozen=True, eq=False)
class Camera(Record):
    """Pinhole camera looking from ``eye`` at ``target``.

    Parameters
    ----------
    eye, target : (3,) array_like
        Camera position and the point it looks at (distinct).
    up : (3,) array_like
        Approximate up direction; must not be parallel to the viewing direction.
    fov : float
        Vertical field of view in degrees, in (0, 180).
    width, height : int
        Image size in pixels, each in 1..16384.
    near, far : float
        Clipping distances along the viewing axis, ``0 < near < far``.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), width=4, height=2)
    >>> [w.tolist() for w in cam.basis()]
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    >>> cam.aspect
    2.0
    """

    eye: Any
    target: Any
    up: Any = (0.0, 1.0, 0.0)
    fov: float = 45.0
    width: int = 640
    height: int = 480
    near: float = 0.1
    far: float = 1000.0

    def __post_init__(self) -> None:
        fov = v.real(self.fov, "fov")
        if not 0.0 < fov < 180.0:
            raise ValueError(f"fov (vertical, in degrees) must lie in (0, 180), got {fov}")
        near = v.real(self.near, "near", positive=True)
        far = v.real(self.far, "far", positive=True)
        if far <= near:
            raise ValueError(f"far must be greater than near, got near={near}, far={far}")
        self._set(
            eye=v.vector3(self.eye, "eye"),
            target=v.vector3(self.target, "target"),
            up=v.vector3(self.up, "up"),
            fov=fov,
            width=v.image_side(self.width, "width"),
            height=v.image_side(self.height, "height"),
            near=near,
            far=far,
        )
        self.basis()  # reject eye == target and an up parallel to the view now, not at render

    @property
    def aspect(self) -> float:
        """Width over height of the image.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> Camera(eye=(0, 0, 1), target=(0, 0, 0), width=640, height=480).aspect
        1.3333333333333333
        """
        return self.width / self.height

    def basis(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Return the unit vectors (u right, v up, w backward) of the camera frame.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> u, v, w = Camera(eye=(0, 0, -5), target=(0, 0, 0)).basis()
        >>> u.tolist(), w.tolist()
        ([-1.0, 0.0, 0.0], [0.0, 0.0, -1.0])
        """
        backward = self.eye - self.target
        distance = float(np.linalg.norm(backward))
        if distance == 0.0:
            raise ValueError(f"eye and target must differ, both are {self.eye.tolist()}")
        w = backward / distance
        right = np.cross(self.up, w)
        length = float(np.linalg.norm(right))
        if length <= 1e-12 * max(float(np.linalg.norm(self.up)), 1e-300):
            raise ValueError(
                f"up {self.up.tolist()} must not be parallel to the viewing direction "
                f"{(-w).tolist()}"
            )
        u = right / length
        return u, np.cross(w, u), w

    def view_matrix(self) -> np.ndarray:
        """Return the (4, 4) world-to-camera matrix (camera at the origin, looking down -Z).

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> m = Camera(eye=(0, 0, 5), target=(0, 0, 0)).view_matrix()
        >>> (m @ [0, 0, 0, 1]).tolist()
        [0.0, 0.0, -5.0, 1.0]
        """
        u, v_, w = self.basis()
        matrix = np.eye(4)
        matrix[0, :3], matrix[1, :3], matrix[2, :3] = u, v_, w
        matrix[:3, 3] = -matrix[:3, :3] @ self.eye
        return matrix

    def projection_matrix(self) -> np.ndarray:
        """Return the (4, 4) OpenGL-style perspective matrix from camera space to clip space.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, near=1, far=3, width=2, height=2)
        >>> clip = cam.projection_matrix() @ [0, 0, -1, 1]  # a point on the near plane
        >>> (clip[:3] / clip[3]).tolist()
        [0.0, 0.0, -1.0]
        """
        focal = 1.0 / math.tan(math.radians(self.fov) / 2.0)
        near, far = self.near, self.far
        matrix = np.zeros((4, 4))
        matrix[0, 0] = focal / self.aspect
        matrix[1, 1] = focal
        matrix[2, 2] = (far + near) / (near - far)
        matrix[2, 3] = 2.0 * far * near / (near - far)
        matrix[3, 2] = -1.0
        return matrix

    def with_size(self, width: int, height: int) -> Camera:
        """Return the same camera with another image size.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> Camera(eye=(0, 0, 5), target=(0, 0, 0)).with_size(32, 24).width
        32
        """
        return dataclasses.replace(self, width=width, height=height)
