"""The notes' ray geometry (section 8), vectorized: ray-sphere, ray-plane, reflection, refraction.

A ray is ``R(t) = P0 + t·d``; ``d`` may have any non-zero length and t is measured in units of
``|d|``. Every function broadcasts over leading axes like a NumPy ufunc (one ray against many
spheres, many rays against one plane, ...) and returns a float (or None) when given single
values. The hit tests are the very kernels the ray tracer runs
(:mod:`pixelpath.raytrace._hit_kernels`).

* Sphere: solve ``|P0 + t d − C|² = r²``, the quadratic ``a t² + b t + c = 0`` with
  ``a = d·d``, ``b = 2 d·(P0 − C)``, ``c = |P0 − C|² − r²``; the nearest root with t > 0 is the
  hit. A tangent ray hits (double root). A ray starting on the sphere (within a few units in
  the last place) does not hit it at t = 0: leaving it, it misses; going in, it hits the far
  side.
* Plane through Q with normal n: ``t = n·(Q − P0) / (n·d)`` (SPEC §9: the notes print P0 twice);
  no hit when the ray is parallel (n·d = 0) or the plane is behind (t <= 0).
* Reflection of a travelling direction: ``R = d − 2(d·N)N``. (``pixelpath.lighting.reflect``
  mirrors the vector *towards* the light, ``2(N·L)N − L``; for the same vector the two are
  opposite.)
* Refraction by Snell's law ``n1 sin θi = n2 sin θt``: with η = n1/n2, ``cos θi = −d·N`` and
  ``cos θt = √(1 − η²(1 − cos² θi))``, ``T = η d + (η cos θi − cos θt) N``. When
  ``η² (1 − cos² θi) > 1`` there is no T: total internal reflection.

Examples
--------
>>> from pixelpath.raytrace import ray_plane, ray_sphere
>>> ray_sphere(origin=(0, 0, 5), direction=(0, 0, -1), center=(0, 0, 0), radius=1)
4.0
>>> ray_plane(origin=(0, 2, 0), direction=(0, -4, 0), point=(0, 0, 0), normal=(0, 1, 0))
0.5
"""

from __future__ import annotations

from typing import Any

import numpy as np

from pixelpath import _validate as v

__all__ = ["ray_plane", "ray_sphere", "reflect", "refract"]


def _nonzero(array: np.ndarray, name: str) -> np.ndarray:
    # Column by column, stopping at the first with no zero: NumPy reduces a short last axis
    # slowly, and rays rarely have a zero component at all.
    zero = array[..., 0] == 0.0
    for axis in range(1, array.shape[-1]):
        if not zero.any():
            return array
        zero &= array[..., axis] == 0.0
    if zero.any():
        raise ValueError(f"{name} must not contain a zero-length vector")
    return array


def _broadcast(arrays: dict[str, np.ndarray], vector: set[str]) -> list[np.ndarray]:
    """Broadcast the leading axes of ``arrays``; return them flat: (N, 3) vectors, (N,) scalars."""
    leading = {k: (a.shape[:-1] if k in vector else a.shape) for k, a in arrays.items()}
    try:
        shape = np.broadcast_shapes(*leading.values())
    except ValueError:
        shapes = ", ".join(f"{k} {s}" for k, s in leading.items())
        raise ValueError(f"the leading axes of the arguments do not broadcast: {shapes}") from None
    flat = []
    for key, array in arrays.items():
        full = (*shape, 3) if key in vector else shape
        rows = np.ascontiguousarray(np.broadcast_to(array, full))
        flat.append(rows.reshape((-1, *full[len(shape):])))
    return [shape, *flat]


def _result(values: np.ndarray, shape: tuple[int, ...]) -> np.ndarray | float:
    values = values.reshape((*shape, *values.shape[1:]))
    return float(values) if values.ndim == 0 else values


def ray_sphere(origin: Any, direction: Any, center: Any, radius: Any) -> np.ndarray | float:
    """Return t of the nearest hit with t > 0 of the ray ``origin + t·direction``, inf on a miss.

    Parameters
    ----------
    origin, direction : (..., 3) array_like
        Ray origins P0 and directions d (any non-zero length; t is in units of ``|d|``).
    center : (..., 3) array_like
        Sphere centres C.
    radius : float or (...) array_like
        Radii r > 0.

    Returns
    -------
    float or ndarray
        t per ray (the broadcast shape of the leading axes); ``inf`` where the ray misses or
        the sphere is behind it.

    Raises
    ------
    ValueError
        Non-finite values, a zero-length direction, a radius <= 0, shapes that do not
        broadcast.
    TypeError
        Non-numeric input.

    Examples
    --------
    >>> from pixelpath.raytrace import ray_sphere
    >>> ray_sphere((0, 0, 0), (0, 0, 1), (0, 0, 0), 2.0)    # from inside: the far side
    2.0
    >>> ray_sphere((0, 1, -5), (0, 0, 1), (0, 0, 0), 1.0)   # tangent: a double root
    5.0
    >>> ray_sphere((0, 0, 5), (0, 0, 1), (0, 0, 0), 1.0)    # behind the origin
    inf
    """
    from pixelpath.raytrace import _hit_kernels

    o = v.finite_array(origin, "origin", 3)
    d = _nonzero(v.finite_array(direction, "direction", 3), "direction")
    c = v.finite_array(center, "center", 3)
    r = v.finite_array(radius, "radius")
    if np.any(r <= 0.0):
        raise ValueError(f"radius must be positive, got {radius!r}")
    arrays = {"origin": o, "direction": d, "center": c, "radius": r}
    shape, o, d, c, r = _broadcast(arrays, {"origin", "direction", "center"})
    out = np.empty(len(o))
    _hit_kernels.ray_sphere_many(o, d, c, r, out)
    return _result(out, shape)


def ray_plane(origin: Any, direction: Any, point: Any, normal: Any) -> np.ndarray | float:
    """Return ``t = n·(Q − P0)/(n·d)`` where the ray meets the plane; inf if parallel or behind.

    Parameters
    ----------
    origin, direction : (..., 3) array_like
        Ray origins P0 and directions d (any non-zero length).
    point, normal : (..., 3) array_like
        A point Q of each plane and its normal n (any non-zero length).

    Returns
    -------
    float or ndarray
        t > 0 per ray, ``inf`` where the ray is parallel to the plane, the plane lies behind
        it, or the ray starts on the plane.

    Raises
    ------
    ValueError
        Non-finite values, a zero-length direction or normal, shapes that do not broadcast.
    TypeError
        Non-numeric input.

    Examples
    --------
    >>> from pixelpath.raytrace import ray_plane
    >>> ray_plane((0, 5, 0), (1, 0, 0), (0, 0, 0), (0, 1, 0))   # parallel
    inf
    >>> ray_plane([[0, 5, 0], [0, -5, 0]], (0, -1, 0), (0, 0, 0), (0, 1, 0)).tolist()
    [5.0, inf]
    """
    from pixelpath.raytrace import _hit_kernels

    o = v.finite_array(origin, "origin", 3)
    d = _nonzero(v.finite_array(direction, "direction", 3), "direction")
    q = v.finite_array(point, "point", 3)
    n = _nonzero(v.finite_array(normal, "normal", 3), "normal")
    arrays = {"origin": o, "direction": d, "point": q, "normal": n}
    shape, o, d, q, n = _broadcast(arrays, set(arrays))
    out = np.empty(len(o))
    _hit_kernels.ray_plane_many(o, d, q, n, out)
    return _result(out, shape)


def _unit(array: np.ndarray) -> np.ndarray:
    return array / np.linalg.norm(array, axis=-1, keepdims=True)


def reflect(d: Any, n: Any) -> np.ndarray:
    """Return the mirror direction ``R = d − 2(d·N)N`` of a ray travelling along d.

    Parameters
    ----------
    d : (..., 3) array_like
        Incident directions (any length; R has the same length).
    n : (..., 3) array_like
        Surface normals (normalized first; either side of the surface).

    Returns
    -------
    (..., 3) ndarray

    Examples
    --------
    >>> from pixelpath.raytrace import reflect
    >>> reflect((1, -1, 0), (0, 2, 0)).tolist()
    [1.0, 1.0, 0.0]
    """
    from pixelpath.raytrace import _hit_kernels

    d = v.finite_array(d, "d", 3)
    n = _unit(_nonzero(v.finite_array(n, "n", 3), "n"))
    shape, d, n = _broadcast({"d": d, "n": n}, {"d", "n"})
    out = np.empty((len(d), 3))
    _hit_kernels.reflect_many(d, n, out)
    return out.reshape((*shape, 3))


def refract(d: Any, n: Any, eta: Any) -> np.ndarray | None:
    """Return the transmitted direction T by Snell's law, or None on total internal reflection.

    Parameters
    ----------
    d : (..., 3) array_like
        Incident directions (normalized first).
    n : (..., 3) array_like
        Normals on the incident side, ``d·n <= 0`` (normalized first).
    eta : float or (...) array_like
        η = n1/n2 > 0, the index of the medium the ray leaves over that of the one it enters.

    Returns
    -------
    (3,) ndarray or None, or (..., 3) ndarray
        The unit transmitted direction ``T = η d + (η cos θi − cos θt) N``. For a single ray,
        None when the light is totally reflected; for a batch, those rows are NaN.

    Raises
    ------
    ValueError
        Non-finite values, zero-length vectors, ``eta <= 0``, a normal on the far side
        (``d·n > 0``), shapes that do not broadcast.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raytrace import refract
    >>> t = refract((np.sin(np.radians(30)), -np.cos(np.radians(30)), 0), (0, 1, 0), 1 / 1.5)
    >>> round(float(np.degrees(np.arcsin(t[0]))), 4)    # sin θt = sin 30° / 1.5
    19.4712
    >>> refract((0.8, -0.6, 0.0), (0, 1, 0), 1.5) is None  # glass to air beyond 41.8°
    True
    """
    from pixelpath.raytrace import _hit_kernels

    d = _unit(_nonzero(v.finite_array(d, "d", 3), "d"))
    n = _unit(_nonzero(v.finite_array(n, "n", 3), "n"))
    eta_array = v.finite_array(eta, "eta")
    if np.any(eta_array <= 0.0):
        raise ValueError(f"eta must be positive (n1/n2), got {eta!r}")
    shape, d, n, eta_flat = _broadcast({"d": d, "n": n, "eta": eta_array}, {"d", "n"})
    facing = np.einsum("ij,ij->i", d, n)
    if np.any(facing > 0.0):
        raise ValueError(
            "n must be the normal on the incident side (d·n <= 0); flip it for a ray leaving "
            f"the surface, got d·n = {facing[np.argmax(facing > 0.0)]:.6g}"
        )
    out = np.empty((len(d), 3))
    _hit_kernels.refract_many(d, n, eta_flat, out)
    if not shape:
        return None if np.isnan(out[0, 0]) else out[0]
    return out.reshape((*shape, 3))
