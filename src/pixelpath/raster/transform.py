"""Model → world → camera → clip space, then the perspective divide and the viewport.

Objects are given in world coordinates (a mesh's own transform is applied when it is loaded),
so the chain here is ``clip = P · V · world`` with V = :meth:`Camera.view_matrix` (the camera at
the origin looking down −Z) and P = :meth:`Camera.projection_matrix` (OpenGL-style: inside the
frustum −w ≤ x, y, z ≤ w, and ``w = −z_camera`` is the distance along the viewing axis).

After clipping (:mod:`pixelpath.raster.frustum`), the divide and the viewport give screen
coordinates with pixel (i, j) centred at (i + 0.5, j + 0.5) and row 0 at the top::

    x_screen = (x / w + 1) · W / 2        y_screen = (1 − y / w) · H / 2

The third screen coordinate is the depth key, 1/w: unlike depth, it is affine in screen
space, so the rasterizer interpolates it exactly and recovers perspective-correct attributes
from it. An orthographic camera's clip w is 1 everywhere; its key is ``(3 − z_ndc) / 2``,
affine in depth, also larger where nearer, and its attributes interpolate affinely.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from pixelpath.raster._arrays import kernel_array

if TYPE_CHECKING:
    from pixelpath.scene import Camera

__all__ = ["clip_to_screen", "depth_key_name", "world_to_clip"]


def world_to_clip(points: np.ndarray, camera: Camera) -> np.ndarray:
    """Map world points to homogeneous clip coordinates.

    Parameters
    ----------
    points : (N, 3) array_like
        World-space positions.
    camera : Camera
        Supplies the view and projection matrices.

    Returns
    -------
    (N, 4) float64 ndarray
        Clip coordinates (x, y, z, w); w is the depth along the viewing axis.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.raster import world_to_clip
    >>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=2, height=2)
    >>> float(world_to_clip([[0.0, 0.0, 0.0]], cam)[0, 3])  # the target is 5 units ahead
    5.0
    """
    from pixelpath.scene.mesh import moved

    points = _points(points, 3, "points")
    matrix = camera.projection_matrix() @ camera.view_matrix()
    return moved(points, matrix[:, :3], matrix[:, 3])


def clip_to_screen(
    clip: np.ndarray, width: int, height: int, orthographic: bool = False
) -> np.ndarray:
    """Perspective divide and viewport: clip coordinates to (x_screen, y_screen, depth key).

    Parameters
    ----------
    clip : (N, 4) array_like
        Clip coordinates with w > 0 (that is, already clipped against the near plane).
    width, height : int
        Image size in pixels.
    orthographic : bool
        Whether the clip coordinates come from an orthographic camera (w = 1): the key is
        then ``(3 − z_ndc) / 2``, 2 on the near plane and 1 on the far one.

    Returns
    -------
    (N, 3) float64 ndarray
        Pixel coordinates (row 0 at the top, pixel centres at half-integers) and the depth key
        (1/w for a perspective camera): larger is nearer.

    Examples
    --------
    >>> from pixelpath.raster import clip_to_screen
    >>> clip_to_screen([[0.0, 0.0, 0.0, 2.0], [-2.0, 2.0, 0.0, 2.0]], 4, 2).tolist()
    [[2.0, 1.0, 0.5], [0.0, 0.0, 0.5]]
    >>> clip_to_screen([[0.0, 0.0, -1.0, 1.0]], 4, 2, orthographic=True).tolist()  # near plane
    [[2.0, 1.0, 2.0]]
    """
    from pixelpath.raster import _setup_kernels

    clip = _points(clip, 4, "clip")
    if np.any(clip[:, 3] <= 0.0):
        raise ValueError("clip coordinates must have w > 0: clip against the near plane first")
    screen = np.empty((len(clip), 3))
    if not isinstance(orthographic, bool | np.bool_):
        raise TypeError(f"orthographic must be a bool, got {type(orthographic).__name__}")
    _setup_kernels.clip_to_screen(clip, int(width), int(height), bool(orthographic), screen)
    return screen


def depth_key_name(camera: Camera) -> str:
    """Name the depth key the raster methods compare, as their reports write it.

    1/w for a perspective camera; ``(3 − z_ndc)/2``, affine in depth, for an orthographic one.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.raster.transform import depth_key_name
    >>> depth_key_name(Camera(eye=(0, 0, 5), target=(0, 0, 0)))
    '1/w'
    """
    if camera.orthographic:
        return "(3 − z_ndc)/2"
    return "1/w"


def _points(values: np.ndarray, size: int, name: str) -> np.ndarray:
    """Return ``values`` as a finite contiguous float64 (N, size) array, or raise ValueError."""
    array = kernel_array(values)
    if array.ndim != 2 or array.shape[1] != size:
        raise ValueError(f"{name} must have shape (N, {size}), got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite (no NaN or inf coordinates)")
    return array
