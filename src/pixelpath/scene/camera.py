"""A look-at camera, perspective or orthographic, and its OpenGL-style matrices.

Conventions (SPEC, "Precise conventions"): right-handed world; the camera sits at ``eye`` and
looks at ``target``. Its basis is (u right, v up, w backward) with ``w = normalize(eye - target)``,
``u = normalize(up × w)``, ``v = w × u``, so camera space has +X right, +Y up and the camera looks
down -Z. The projection maps the view frustum to clip space; after the perspective divide x, y
and z lie in [-1, 1] inside the frustum, with z = -1 on the near plane and +1 on the far plane,
and ``w_clip = -z_camera`` is the depth along the viewing axis.

An orthographic camera (``projection="orthographic"``) sees a box ``view_height`` world units
tall and ``view_height × aspect`` wide instead of a frustum: its clip w is 1 everywhere, and
its rays are parallel. Its *viewpoint* (:meth:`Camera.viewpoint`) is then the point at infinity
behind it, a homogeneous (x, y, z, 0), which lets every test that asks "which side is the eye
on" (back-face culling, the BSP and octree orders, the painter's plane tests) be written once
for both projections.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any, Literal

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record

PROJECTIONS = ("perspective", "orthographic")


@dataclasses.dataclass(frozen=True, eq=False)
class Camera(Record):
    """Camera looking from ``eye`` at ``target``, perspective (pinhole) or orthographic.

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
    projection : {"perspective", "orthographic"}
        Perspective (``fov`` sets the view) or orthographic (parallel rays; ``view_height`` sets
        the view, ``fov`` is ignored).
    view_height : float, optional
        Orthographic only, and required there: the height of the view in world units (its
        width is ``view_height × aspect``). Giving it to a perspective camera is a ValueError
        rather than silently ignored.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), width=4, height=2)
    >>> [w.tolist() for w in cam.basis()]
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    >>> cam.aspect
    2.0
    >>> ortho = Camera(eye=(0, 0, 5), target=(0, 0, 0), projection="orthographic", view_height=4)
    >>> ortho.viewpoint().tolist()  # the point at infinity behind the camera
    [0.0, 0.0, 1.0, 0.0]
    """

    eye: Any
    target: Any
    up: Any = (0.0, 1.0, 0.0)
    fov: float = 45.0
    width: int = 640
    height: int = 480
    near: float = 0.1
    far: float = 1000.0
    projection: Literal["perspective", "orthographic"] = "perspective"
    view_height: float | None = None

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
            **_projection(self.projection, self.view_height),
        )
        self.basis()  # reject eye == target and an up parallel to the view now, not at render

    @property
    def orthographic(self) -> bool:
        """Whether the projection is orthographic.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> Camera(eye=(0, 0, 1), target=(0, 0, 0)).orthographic
        False
        """
        return self.projection == "orthographic"

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
        # Worked out once (the camera is frozen), when it is made: every render, light rig and
        # framing asks for it again. The vectors are read-only, as the camera's own are.
        frame = self.__dict__.get("_frame")
        if frame is None:
            frame = self.__dict__["_frame"] = tuple(map(v.frozen, self._frame_vectors()))
        return frame

    def _frame_vectors(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        backward = self.eye - self.target
        distance = v.vector_length(backward)
        if distance == 0.0:
            raise ValueError(f"eye and target must differ, both are {self.eye.tolist()}")
        w = backward / distance
        right = v.cross3(self.up, w)
        length = v.vector_length(right)
        if length <= 1e-12 * max(v.vector_length(self.up), 1e-300):
            raise ValueError(
                f"up {self.up.tolist()} must not be parallel to the viewing direction "
                f"{(-w).tolist()}"
            )
        u = right / length
        return u, v.cross3(w, u), w

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

    def viewpoint(self) -> np.ndarray:
        """Return where the camera sees from, homogeneous: ``(eye, 1)``, or ``(-d, 0)``.

        For an orthographic camera the viewer is the point at infinity opposite the viewing
        direction d. A point P lies on the viewer's side of a plane ``n · x + c = 0`` when
        ``n · E + c · E_w`` has the sign of ``n · P + c``; the vector from P towards the viewer
        is ``E − E_w · P``. Multiplying by ``E_w = 1`` is exact, so these formulas give the
        perspective tests' bits unchanged.

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> Camera(eye=(0, 0, 5), target=(0, 0, 0)).viewpoint().tolist()
        [0.0, 0.0, 5.0, 1.0]
        """
        if self.orthographic:
            return np.append(self.basis()[2], 0.0)
        return np.append(self.eye, 1.0)

    def projection_matrix(self) -> np.ndarray:
        """Return the (4, 4) OpenGL-style matrix from camera space to clip space.

        Perspective: clip w is the depth along the viewing axis. Orthographic: clip w is 1,
        and x, y, z are affine in the camera coordinates (the view box maps to [-1, 1]³).

        Examples
        --------
        >>> from pixelpath.scene import Camera
        >>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, near=1, far=3, width=2, height=2)
        >>> clip = cam.projection_matrix() @ [0, 0, -1, 1]  # a point on the near plane
        >>> (clip[:3] / clip[3]).tolist()
        [0.0, 0.0, -1.0]
        >>> ortho = Camera(eye=(0, 0, 5), target=(0, 0, 0), near=1, far=3, width=2, height=2,
        ...                projection="orthographic", view_height=4)
        >>> (ortho.projection_matrix() @ [2, -2, -3, 1]).tolist()  # a corner on the far plane
        [1.0, -1.0, 1.0, 1.0]
        """
        near, far = self.near, self.far
        matrix = np.zeros((4, 4))
        if self.orthographic:
            matrix[0, 0] = 2.0 / (self.view_height * self.aspect)
            matrix[1, 1] = 2.0 / self.view_height
            matrix[2, 2] = 2.0 / (near - far)
            matrix[2, 3] = (far + near) / (near - far)
            matrix[3, 3] = 1.0
            return matrix
        focal = 1.0 / math.tan(math.radians(self.fov) / 2.0)
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


def _projection(projection: Any, view_height: Any) -> dict[str, Any]:
    """Return the validated ``projection`` and ``view_height`` of a camera."""
    if not isinstance(projection, str):
        raise TypeError(f"projection must be a string, got {type(projection).__name__}")
    if projection not in PROJECTIONS:
        raise ValueError(f"projection must be one of {PROJECTIONS}, got {projection!r}")
    if projection == "perspective":
        if view_height is not None:
            raise ValueError(
                f"view_height is for projection='orthographic' only (a perspective camera's "
                f"view is set by fov), got view_height={view_height!r}"
            )
        return {"projection": projection, "view_height": None}
    if view_height is None:
        raise ValueError("projection='orthographic' needs view_height (world units), got None")
    return {
        "projection": projection,
        "view_height": v.real(view_height, "view_height", positive=True),
    }
