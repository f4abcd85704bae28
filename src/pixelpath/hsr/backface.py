"""Back-face elimination, an object-space test (SPEC §9 errata: not an image-space one).

Convention used here: V points **from the eye into the scene**, ``V = P − eye`` for a point P
of the face, and N is the face's outward normal (faces are wound counter-clockwise seen from
outside). Then

* ``N · V < 0``: the face turns towards the eye — visible;
* ``N · V ≥ 0``: the face turns away (or is seen edge-on) — culled.

This is the notes' "N · V < 0 → visible" with their V. (With V from the surface to the eye,
the same test reads N · V > 0.) An orthographic camera has no eye point: its V is the viewing
direction d everywhere, so the test is N · d ≥ 0 → culled. Both are one formula with the
camera's homogeneous viewpoint E = (eye, 1) or (−d, 0): V = E_w · P − E. A face seen exactly
edge-on covers no pixel, so culling it changes nothing. Degenerate faces have N = 0 and are
culled too.

Examples
--------
>>> import numpy as np
>>> from pixelpath.hsr.backface import front_facing
>>> normals = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
>>> points = np.zeros((2, 3))
>>> front_facing(normals, points, eye=(0, 0, 5)).tolist()
[True, False]
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["front_facing"]


def front_facing(normals: np.ndarray, points: np.ndarray, eye: Any) -> np.ndarray:
    """Return which faces turn towards the eye: ``N · (P − eye) < 0``, or ``N · d < 0``.

    Parameters
    ----------
    normals : (F, 3) array_like
        Outward face normals (any length; zero for degenerate faces).
    points : (F, 3) array_like
        One point of each face (any point: the test is the same over a planar face).
    eye : (3,) or (4,) array_like
        The eye position, or a homogeneous viewpoint (:meth:`Camera.viewpoint`): ``(x, y, z,
        1)`` is the eye at (x, y, z), ``(x, y, z, 0)`` the orthographic viewer at infinity
        in direction (x, y, z) (opposite the viewing direction).

    Returns
    -------
    (F,) bool ndarray
        True for faces that are kept when back faces are culled.

    Examples
    --------
    >>> from pixelpath.hsr.backface import front_facing
    >>> front_facing([[1.0, 0.0, 0.0]], [[2.0, 0.0, 0.0]], eye=(5, 0, 0)).tolist()
    [True]
    >>> # Orthographic, looking down -z: a face tilted 89 degrees from the view still faces it.
    >>> front_facing([[0.9998, 0.0, 0.0175], [0.9998, 0.0, -0.0175]], [[9.0, 0, 0]] * 2,
    ...              eye=(0, 0, 1, 0)).tolist()
    [True, False]
    """
    from pixelpath.raster._arrays import kernel_array

    normals = kernel_array(normals)
    points = kernel_array(points)
    eye = kernel_array(eye)
    if normals.ndim != 2 or normals.shape[1] != 3 or points.shape != normals.shape:
        raise ValueError(
            f"normals and points must both have shape (F, 3), got {normals.shape} and "
            f"{points.shape}"
        )
    if eye.shape == (3,):
        eye = np.append(eye, 1.0)
    if eye.shape != (4,):
        raise ValueError(f"eye must have shape (3,) or (4,), got {eye.shape}")
    from pixelpath.raster import _setup_kernels

    out = np.empty(len(normals), dtype=np.bool_)
    _setup_kernels.front_facing_many(normals, points, eye, out)
    return out
