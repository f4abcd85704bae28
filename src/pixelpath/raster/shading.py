"""Flat, Gouraud and Phong shading (notes: "Gouraud shading", SPEC §5).

All three evaluate the same illumination model, the lighting stage's ``shade_point`` kernel:
``I = ka Ia C + Σ_lights [kd IL C max(0, N·L) + ks IL max(0, R·V)^n]``, clamped to [0, 1] only
when the pixel is written. They differ in *where* it is evaluated:

* ``"flat"``: once per polygon, at its centroid with its face normal; every pixel of the polygon
  gets that intensity.
* ``"gouraud"``: at the vertices with the vertex normals; intensities are interpolated along the
  edges, ``I(t) = I_A + (I_B − I_A) t``, then along each span,
  ``I(x) = I_L + (I_R − I_L)(x − x_L)/(x_R − x_L)``. On a triangle these two linear steps are
  its barycentric interpolation; the rasterizer uses the perspective-correct weights, which are
  exactly the notes' screen-space formulas for a face parallel to the image plane and the
  correct object-space interpolation otherwise.
* ``"phong"``: normals (and positions) are interpolated the same way and the model is evaluated
  at every pixel, after visibility is resolved (deferred), so each visible pixel is shaded once.

With back-face culling off, a face seen from behind is lit with its normals reversed (a
two-sided surface), in all three modes.
"""

from __future__ import annotations

import numpy as np

from pixelpath._threads import in_threads
from pixelpath.raster._arrays import kernel_array

__all__ = ["SHADINGS", "shade_points", "shading_mode"]

SHADINGS = ("flat", "gouraud", "phong")


def shading_mode(shading: str) -> int:
    """Return the kernel's code for a shading name, or raise ValueError for an unknown one.

    Examples
    --------
    >>> from pixelpath.raster.shading import shading_mode
    >>> shading_mode("phong")
    2
    """
    from pixelpath.raster import _kernels

    codes = {"flat": _kernels.FLAT, "gouraud": _kernels.GOURAUD, "phong": _kernels.PHONG}
    if not isinstance(shading, str) or shading not in codes:
        raise ValueError(f"shading must be one of {', '.join(SHADINGS)}; got {shading!r}")
    return codes[shading]


def shade_points(
    points: np.ndarray,
    normals: np.ndarray,
    flip: np.ndarray,
    owner: np.ndarray,
    materials: np.ndarray,
    lights: np.ndarray,
    ambient: np.ndarray,
    eye: np.ndarray,
    *,
    blinn: bool = False,
) -> np.ndarray:
    """Evaluate the illumination model at points, each with the material of its owner.

    Parameters
    ----------
    points, normals : (N, 3) float64
        Surface points and unit normals (world space).
    flip : (N,) bool
        Reverse the normal first (the point is seen from behind a two-sided surface).
    owner : (N,) intp
        Row of ``materials`` for each point.
    materials : (O, 8) float64
        Packed materials (``Material.packed()``).
    lights : (L, 7) float64
        Packed lights (:func:`pixelpath.lighting.pack_lights`).
    ambient : (3,) float64
        Ambient intensity per channel.
    eye : (3,) or (4,) float64
        The eye position, or the camera's homogeneous viewpoint (``Camera.viewpoint()``: the
        eye with w = 1, or the direction towards the viewer with w = 0 for an orthographic
        camera, whose view vector V is then the same at every point).
    blinn : bool
        Blinn-Phong highlights instead of Phong's.

    Returns
    -------
    (N, 3) float64 ndarray
        Unclamped intensities.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raster.shading import shade_points
    >>> material = np.array([[1.0, 1.0, 1.0, 0.1, 0.7, 0.3, 32.0, 0.0]])
    >>> light = np.array([[0.0, 0.0, 0.0, 5.0, 1.0, 1.0, 1.0]])  # point light above the point
    >>> out = shade_points(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]), np.zeros(1, bool),
    ...                    np.zeros(1, np.intp), material, light, np.full(3, 0.1),
    ...                    np.array([0.0, 0.0, 5.0]))
    >>> np.round(out, 4).tolist()  # ambient 0.01 + diffuse 0.7 + specular 0.3
    [[1.01, 1.01, 1.01]]
    """
    from pixelpath.raster import _kernels

    out = np.empty((len(points), 3))
    arrays = (
        kernel_array(points),
        kernel_array(normals),
        kernel_array(flip, np.bool_),
        kernel_array(owner, np.intp),
        kernel_array(materials),
        kernel_array(lights),
        kernel_array(ambient),
        kernel_array(eye if len(eye) == 4 else np.append(eye, 1.0)),
    )
    in_threads(
        lambda first, stop: _kernels.shade_points(first, stop, *arrays, bool(blinn), out),
        len(out),
    )
    return out
