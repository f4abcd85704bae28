"""Where the cameras of a dataset of views stand: orbit, Fibonacci sphere or seeded random.

:func:`view_directions` gives unit vectors from the model's centre towards each camera;
:func:`place_cameras` places a camera on each, all at one distance that frames the model in
every view, as :class:`ViewCameras` (arrays: thousands of views cost little to place and to
send to a cluster), whose ``poses()`` are the cameras' matrices in the NeRF convention.
Everything here is a pure function of its arguments: the same request gives the same poses,
to the bit, on every machine.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from typing import Any

import numpy as np

from pixelpath.scene import Camera, Mesh, Plane, Scene, Sphere

__all__ = ["LAYOUTS", "ViewCameras", "place_cameras", "view_directions"]

LAYOUTS = ("orbit", "sphere", "random")
ELEVATION = 22.0  # degrees, the orbit's default: the height of pixelpath's framing camera
_GOLDEN_ANGLE = math.pi * (3.0 - math.sqrt(5.0))


def view_directions(
    n: int,
    layout: str = "orbit",
    *,
    seed: int = 0,
    elevation: float | None = None,
    hemisphere: bool = True,
) -> np.ndarray:
    """Return ``n`` unit vectors from the model's centre towards the cameras, (n, 3).

    Parameters
    ----------
    n : int
        Number of views, at least 1.
    layout : {"orbit", "sphere", "random"}
        ``orbit``: evenly spaced round the vertical (+Y) axis at one ``elevation``, the first
        in front (+Z), going anticlockwise seen from above. ``sphere``: a Fibonacci sphere,
        evenly spread over the upper hemisphere (or the whole sphere). ``random``: uniformly
        distributed over the same, drawn with ``seed``.
    seed : int
        Seed of the ``random`` layout (NumPy's PCG64); the others ignore it.
    elevation : float, optional
        Degrees above the horizon, for ``orbit`` only (default 22, in -89..89).
    hemisphere : bool
        ``sphere`` and ``random``: only views from above the horizon (default), or from all
        round.

    Examples
    --------
    >>> from pixelpath.frames.poses import view_directions
    >>> (view_directions(4, elevation=0).round(6) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]]
    >>> bool((view_directions(50, "sphere")[:, 1] > 0).all())
    True
    """
    count = _count(n)
    if layout not in LAYOUTS:
        raise ValueError(f"unknown layout {layout!r}; choose from {', '.join(LAYOUTS)}")
    if elevation is not None and layout != "orbit":
        raise ValueError(f"elevation applies to the orbit layout, not to {layout!r}")
    if layout == "orbit":
        return _orbit(count, ELEVATION if elevation is None else elevation)
    if layout == "sphere":
        # heights at the middle of n equal bands: equal areas, so evenly spread points
        low = 0.0 if hemisphere else -1.0
        heights = 1.0 - (np.arange(count) + 0.5) / count * (1.0 - low)
        return _on_sphere(heights, np.arange(count) * _GOLDEN_ANGLE)
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
        raise ValueError(f"seed must be a whole number >= 0, got {seed!r}")
    generator = np.random.default_rng(int(seed))
    # Archimedes: the height of a uniform point on the sphere is uniform
    heights = generator.uniform(0.0 if hemisphere else -1.0, 1.0, count)
    return _on_sphere(heights, generator.uniform(0.0, 2.0 * math.pi, count))


@dataclasses.dataclass(frozen=True, eq=False)
class ViewCameras:
    """The cameras of a dataset of views, as arrays: one eye and up per view, the rest shared.

    Attributes
    ----------
    eyes, ups : (n, 3) ndarray
        Each camera's position and up vector.
    target : (3,) ndarray
        The point every camera looks at.
    fov : float
        Vertical field of view, degrees.
    size : (int, int)
        Width and height of the pictures.
    near, far : float
        Clipping distances shared by all views.
    """

    eyes: np.ndarray
    ups: np.ndarray
    target: np.ndarray
    fov: float
    size: tuple[int, int]
    near: float
    far: float

    def __len__(self) -> int:
        return len(self.eyes)

    def camera(self, index: int) -> Camera:
        """Return view ``index``'s :class:`~pixelpath.scene.Camera`."""
        width, height = self.size
        return Camera(
            eye=self.eyes[index], target=self.target, up=self.ups[index], fov=self.fov,
            width=width, height=height, near=self.near, far=self.far,
        )

    def poses(self) -> np.ndarray:
        """Return the (n, 4, 4) camera-to-world matrices, OpenGL axes (looking down −Z, +Y up).

        The columns are each camera's right, up and backward unit vectors and its position:
        the ``transform_matrix`` of NeRF's and nerfstudio's ``transforms.json``, the inverse
        of each camera's ``view_matrix()``.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath.frames.poses import ViewCameras
        >>> cameras = ViewCameras(np.array([[0.0, 0.0, 5.0]]), np.array([[0.0, 1.0, 0.0]]),
        ...                       np.zeros(3), 45.0, (8, 8), 1.0, 9.0)
        >>> cameras.poses()[0, :3].tolist()
        [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 5.0]]
        """
        back = self.eyes - self.target
        back /= np.linalg.norm(back, axis=1, keepdims=True)
        right = np.cross(self.ups, back)
        right /= np.linalg.norm(right, axis=1, keepdims=True)
        poses = np.zeros((len(self), 4, 4))
        poses[:, :3, 0], poses[:, :3, 1], poses[:, :3, 2] = right, np.cross(back, right), back
        poses[:, :3, 3], poses[:, 3, 3] = self.eyes, 1.0
        return poses


def place_cameras(
    scene: Scene,
    directions: np.ndarray,
    size: tuple[int, int],
    *,
    fov: float = 45.0,
    distance: float | None = None,
) -> ViewCameras:
    """Place a camera on each direction, looking at the centre of the scene's bounded objects.

    All cameras stand at one distance from the centre: ``distance``, or by default the
    smallest at which every view shows the whole bounding box within the middle 90 % of the
    picture (the largest of the views' framing distances). Near and far enclose the objects.

    Parameters
    ----------
    scene : Scene
        Its bounded objects (planes aside) are framed.
    directions : (n, 3) array
        Unit vectors from the centre towards the cameras (:func:`view_directions`).
    size : (int, int)
        Width and height of the pictures.
    fov : float
        Vertical field of view, degrees.
    distance : float, optional
        Distance from the centre, in scene units.

    Raises
    ------
    ValueError
        When the scene has nothing to frame (no bounded object, or non-finite bounds).

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.frames.poses import place_cameras, view_directions
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0)), [pp.Sphere((0, 1, 0), 1)])
    >>> cameras = place_cameras(scene, view_directions(3), (64, 64), distance=4)
    >>> len(cameras), cameras.target.tolist(), round(cameras.near, 3)
    (3, [0.0, 1.0, 0.0], 2.95)
    """
    from pixelpath.io.models import depth_range, framing_distance

    bounds = _framed_bounds(scene)
    ups = _ups(directions)
    with np.errstate(over="ignore", invalid="ignore"):  # a model too large overflows: below
        center = bounds.mean(axis=0)
        radius = _radius(scene, center)
        framed = float(np.max(framing_distance(bounds, directions, size, fov, up=ups)))
    if not (math.isfinite(radius) and math.isfinite(framed) and np.isfinite(center).all()):
        raise ValueError(
            f"the scene cannot be framed: its bounds {bounds.tolist()} overflow float64 "
            f"arithmetic"
        )
    if distance is None:
        distance = framed
    elif (
        isinstance(distance, bool)
        or not isinstance(distance, numbers.Real)
        or not (math.isfinite(distance) and distance > 0)
    ):
        raise ValueError(f"distance must be a positive number of scene units, got {distance!r}")
    near, far = depth_range(float(distance), radius)
    return ViewCameras(center + distance * directions, ups, center, float(fov), tuple(size),
                       near, far)


def _count(n: Any) -> int:
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"n must be an int, got {n!r}")
    if n < 1:
        raise ValueError(f"n must be at least 1 view, got {n}")
    return int(n)


def _orbit(count: int, elevation: Any) -> np.ndarray:
    if isinstance(elevation, bool) or not isinstance(elevation, numbers.Real) or not (
        -89.0 <= elevation <= 89.0
    ):
        raise ValueError(f"elevation must be degrees in -89..89, got {elevation!r}")
    heights = np.full(count, math.sin(math.radians(elevation)))
    return _on_sphere(heights, np.arange(count) * (2.0 * math.pi / count))


def _on_sphere(heights: np.ndarray, azimuths: np.ndarray) -> np.ndarray:
    """Return unit vectors at ``heights`` (y) and ``azimuths`` (radians, +Z towards +X)."""
    across = np.sqrt(np.maximum(1.0 - heights * heights, 0.0))
    return np.stack([across * np.sin(azimuths), heights, across * np.cos(azimuths)], axis=1)


def _ups(backs: np.ndarray) -> np.ndarray:
    """World +Y, or +Z for a camera looking almost straight down or up (where +Y is no up)."""
    ups = np.zeros_like(backs)
    vertical = np.abs(backs[:, 1]) > 0.9999
    ups[~vertical, 1] = 1.0
    ups[vertical, 2] = -np.sign(backs[vertical, 1])
    return ups


def _framed_bounds(scene: Scene) -> np.ndarray:
    bounds = scene.bounds()
    if not np.isfinite(bounds).all():
        raise ValueError(f"the scene cannot be framed: its bounds are not finite {bounds.tolist()}")
    return bounds


def _radius(scene: Scene, center: np.ndarray) -> float:
    """Distance from ``center`` to the farthest point of the bounded objects (at least 1e-9)."""
    farthest = 1e-9
    for obj in scene.objects:
        if isinstance(obj, Plane):
            continue  # infinite
        if isinstance(obj, Sphere):
            reach = float(np.linalg.norm(obj.center - center)) + obj.radius
            farthest = max(farthest, reach)
            continue
        if isinstance(obj, Mesh):
            points = obj.vertices
        else:
            points = np.array(np.meshgrid(*obj.bounds().T, indexing="ij")).reshape(3, -1).T
        farthest = max(farthest, float(np.max(np.linalg.norm(points - center, axis=1))))
    return farthest
