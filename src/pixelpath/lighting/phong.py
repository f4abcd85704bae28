"""The basic (Phong) illumination model of the notes, and its Blinn-Phong variant.

The intensity at a surface point P is (notes, "Basic illumination model", section 6)::

    I = ka Ia + kd IL max(0, N.L) + ks IL max(0, R.V)^n,      R = 2(N.L)N - L

with N the unit normal at P, L the unit vector from P to the light, V the unit vector from P to
the viewer, R the mirror direction of L about N, and n the shininess. With several lights the
diffuse and specular terms are summed over them; with colours every term is evaluated per channel
(r, g, b). Blinn-Phong replaces R.V by N.H with H = (L + V)/``|L + V|`` (the halfway vector).

Conventions of this module:

* the specular term is 0 whenever N.L <= 0 (light behind the surface) or its cosine is <= 0, so
  0^0 never arises, even for n = 0;
* totals are returned unclamped; ``PhongTerms.clamped`` is the total clipped to [0, 1] as the
  notes do for display;
* object colour multiplies the ambient and diffuse terms; the highlight takes the light's colour.

Errata (SPEC section 9): (0.866)^20 = 0.0563, not 0.0117, so the notes' example gives
I = 0.04 + 0.4242 + 0.0281 = 0.4923 (not 0.47005) and the specular example 0.8 x 100 x 0.0563
= 4.50 cd (not 1.2 cd).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from pixelpath.lighting.packing import pack_ambient, pack_lights, pack_material

__all__ = ["PhongGeometry", "PhongTerms", "phong_geometry", "phong_terms", "reflect", "shade"]

# A cosine typed by hand (0.707 for 45 degrees) may overshoot 1 by rounding; this much is allowed.
_COSINE_SLACK = 1e-9

MODELS = ("phong", "blinn")
_LEAST_POINTS = 2048  # the fewest points worth a thread's run: fewer are shaded in the caller


def _numeric(value: Any, name: str) -> np.ndarray:
    """Return ``value`` as a float64 array, raising TypeError when it is not numbers."""
    array = np.asarray(value)
    if array.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a number or an array of numbers, got {value!r}")
    array = array.astype(np.float64)
    if np.isnan(array).any():
        raise ValueError(f"{name} must not be NaN, got {value!r}")
    if not np.isfinite(array).all():
        raise ValueError(f"{name} must be finite, got {value!r}")
    return array


def _non_negative(value: Any, name: str) -> np.ndarray:
    array = _numeric(value, name)
    if (array < 0).any():
        raise ValueError(f"{name} must be >= 0, got {value!r}")
    return array


def _cosine(value: Any, name: str) -> np.ndarray:
    array = _numeric(value, name)
    if (np.abs(array) > 1 + _COSINE_SLACK).any():
        raise ValueError(f"{name} is a cosine and must lie in [-1, 1], got {value!r}")
    return np.clip(array, -1.0, 1.0)


def _vectors(value: Any, name: str) -> np.ndarray:
    """Return ``value`` as a finite float64 array of 3-vectors (..., 3), or raise."""
    array = _numeric(value, name)
    if array.ndim == 0 or array.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., 3), got shape {array.shape}")
    return array


def _unit(vectors: np.ndarray, name: str) -> np.ndarray:
    """Return ``vectors`` scaled to unit length; a zero vector is a ValueError."""
    length = np.linalg.norm(vectors, axis=-1, keepdims=True)
    if (length == 0).any():
        raise ValueError(f"{name} must not contain a zero-length vector")
    return vectors / length


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("...i,...i->...", a, b)


def _scalar_or_array(array: np.ndarray) -> np.ndarray | float:
    return float(array) if array.ndim == 0 else array


@dataclass(frozen=True)
class PhongTerms:
    """The three terms of the Phong model at one or many points, with their sum.

    Attributes
    ----------
    ambient, diffuse, specular : float or ndarray
        ``ka Ia``, ``kd IL max(0, N.L)`` and ``ks IL max(0, R.V)^n`` (0 when N.L <= 0).
    total : float or ndarray
        ``ambient + diffuse + specular``, unclamped.
    clamped : float or ndarray
        ``total`` clipped to [0, 1], the displayed intensity.
    """

    ambient: np.ndarray | float
    diffuse: np.ndarray | float
    specular: np.ndarray | float
    total: np.ndarray | float
    clamped: np.ndarray | float


def phong_terms(
    *,
    ka: Any,
    kd: Any,
    ks: Any,
    shininess: Any,
    ambient: Any,
    light: Any,
    n_dot_l: Any,
    r_dot_v: Any,
) -> PhongTerms:
    """Evaluate the Phong model term by term, in the exam form of the notes.

    Every argument broadcasts against the others like a NumPy ufunc argument, so per-channel
    (r, g, b) intensities or coefficients give per-channel terms, and arrays of cosines give
    the terms at many points at once.

    Parameters
    ----------
    ka, kd, ks : float or array_like
        Ambient, diffuse and specular reflection coefficients, >= 0.
    shininess : float or array_like
        The specular exponent n, >= 0.
    ambient : float or array_like
        The ambient light intensity Ia, >= 0.
    light : float or array_like
        The light source intensity IL, >= 0.
    n_dot_l : float or array_like
        cos(theta) = N.L, in [-1, 1].
    r_dot_v : float or array_like
        cos(alpha) = R.V, in [-1, 1] (pass N.H for Blinn-Phong).

    Returns
    -------
    PhongTerms
        ``.ambient``, ``.diffuse``, ``.specular``, ``.total`` (unclamped) and ``.clamped``;
        floats when every argument is a scalar, else arrays of the broadcast shape.

    Raises
    ------
    TypeError
        If an argument is not numeric.
    ValueError
        If an argument is NaN or infinite, a coefficient, intensity or the shininess is
        negative, a cosine lies outside [-1, 1], or the shapes do not broadcast.

    Examples
    --------
    The notes' worked example, with the corrected (0.866)^20 = 0.0563:

    >>> from pixelpath.lighting import phong_terms
    >>> t = phong_terms(ka=0.2, kd=0.6, ks=0.5, shininess=20, ambient=0.2, light=1.0,
    ...                 n_dot_l=0.707, r_dot_v=0.866)
    >>> round(t.ambient, 4), round(t.diffuse, 4), round(t.specular, 4), round(t.total, 4)
    (0.04, 0.4242, 0.0281, 0.4923)
    """
    named = {
        "ka": _non_negative(ka, "ka"),
        "kd": _non_negative(kd, "kd"),
        "ks": _non_negative(ks, "ks"),
        "shininess": _non_negative(shininess, "shininess"),
        "ambient": _non_negative(ambient, "ambient"),
        "light": _non_negative(light, "light"),
        "n_dot_l": _cosine(n_dot_l, "n_dot_l"),
        "r_dot_v": _cosine(r_dot_v, "r_dot_v"),
    }
    try:
        arrays = np.broadcast_arrays(*named.values())
    except ValueError as exc:
        shapes = ", ".join(f"{key}{value.shape}" for key, value in named.items())
        raise ValueError(f"phong_terms arguments do not broadcast together: {shapes}") from exc
    ka_, kd_, ks_, n, ia, il, n_dot_l_, r_dot_v_ = arrays

    lit = (n_dot_l_ > 0) & (r_dot_v_ > 0)
    # Raise only positive cosines to the power n, so 0^0 (and 0^n with n = 0) never happens.
    highlight = np.where(lit, np.where(lit, r_dot_v_, 1.0) ** n, 0.0)
    ambient_term = ka_ * ia
    diffuse_term = kd_ * il * np.maximum(n_dot_l_, 0.0)
    specular_term = ks_ * il * highlight
    total = ambient_term + diffuse_term + specular_term
    return PhongTerms(
        ambient=_scalar_or_array(ambient_term),
        diffuse=_scalar_or_array(diffuse_term),
        specular=_scalar_or_array(specular_term),
        total=_scalar_or_array(total),
        clamped=_scalar_or_array(np.clip(total, 0.0, 1.0)),
    )


def reflect(l: Any, n: Any) -> np.ndarray:  # noqa: E741  (the notes' name for the light vector)
    """Reflect the light vector L about the normal N: ``R = 2(N.L)N - L``.

    ``n`` is normalized first (only its direction matters); ``l`` is not, so ``|R| = |L|``
    and ``R.N = L.N``. Both broadcast over leading axes.

    Parameters
    ----------
    l : (..., 3) array_like
        The vector from the surface point towards the light.
    n : (..., 3) array_like
        The surface normal (any non-zero length).

    Returns
    -------
    (..., 3) ndarray of float64
        The mirror direction R.

    Raises
    ------
    TypeError
        If an argument is not numeric.
    ValueError
        If a shape is not (..., 3), the shapes do not broadcast, a value is not finite, or a
        vector has zero length.

    Examples
    --------
    >>> from pixelpath.lighting import reflect
    >>> reflect([1.0, 1.0, 0.0], [0.0, 1.0, 0.0]).tolist()
    [-1.0, 1.0, 0.0]
    """
    light = _vectors(l, "l")
    normal = _unit(_vectors(n, "n"), "n")
    _unit(light, "l")
    try:
        light, normal = np.broadcast_arrays(light, normal)
    except ValueError as exc:
        raise ValueError(
            f"l and n do not broadcast together: shapes {light.shape} and {normal.shape}"
        ) from exc
    return 2.0 * _dot(normal, light)[..., None] * normal - light


@dataclass(frozen=True)
class PhongGeometry:
    """The vectors and cosines of the Phong model at one point, each step kept for display.

    Attributes
    ----------
    normal, to_light, to_eye : ndarray (3,)
        The unit vectors N, L and V.
    n_dot_l : float
        cos(theta) = N.L.
    reflected : ndarray (3,)
        R = 2(N.L)N - L.
    r_dot_v : float
        cos(alpha) = R.V.
    halfway : ndarray (3,)
        H = (L + V)/``|L + V|`` (Blinn-Phong); the zero vector when L = -V.
    n_dot_h : float
        N.H.
    """

    normal: np.ndarray
    to_light: np.ndarray
    to_eye: np.ndarray
    n_dot_l: float
    reflected: np.ndarray
    r_dot_v: float
    halfway: np.ndarray
    n_dot_h: float

    @property
    def theta(self) -> float:
        """The angle between N and L, in degrees."""
        return float(np.degrees(np.arccos(np.clip(self.n_dot_l, -1.0, 1.0))))

    @property
    def alpha(self) -> float:
        """The angle between R and V, in degrees."""
        return float(np.degrees(np.arccos(np.clip(self.r_dot_v, -1.0, 1.0))))


def phong_geometry(
    normal: Any,
    to_light: Any = None,
    to_eye: Any = None,
    *,
    surface: Any = None,
    light: Any = None,
    eye: Any = None,
) -> PhongGeometry:
    """Derive N.L, R, R.V and the halfway vector from vectors or from points.

    Give either the directions ``to_light`` and ``to_eye``, or the points ``surface``,
    ``light`` and ``eye`` (then L = light - surface and V = eye - surface). All vectors are
    normalized, as the notes' formulas assume unit vectors.

    Parameters
    ----------
    normal : (3,) array_like
        The surface normal N.
    to_light, to_eye : (3,) array_like, optional
        The vectors from the surface point towards the light and towards the eye.
    surface, light, eye : (3,) array_like, optional
        The surface point, the light position and the eye position.

    Returns
    -------
    PhongGeometry

    Raises
    ------
    ValueError
        If both or neither forms are given, a vector is not (3,), not finite or of zero
        length (the light or the eye on the surface point).

    Examples
    --------
    >>> from pixelpath.lighting import phong_geometry
    >>> g = phong_geometry([0, 0, 1], [0, 1, 1], [0, -1, 1])
    >>> round(g.n_dot_l, 4), g.reflected.round(4).tolist(), round(g.r_dot_v, 4)
    (0.7071, [0.0, -0.7071, 0.7071], 1.0)
    """
    points = (surface, light, eye)
    if to_light is not None and to_eye is not None and all(p is None for p in points):
        to_light_vector = _single_vector(to_light, "to_light")
        to_eye_vector = _single_vector(to_eye, "to_eye")
    elif to_light is None and to_eye is None and all(p is not None for p in points):
        origin = _single_vector(surface, "surface")
        to_light_vector = _single_vector(light, "light") - origin
        to_eye_vector = _single_vector(eye, "eye") - origin
    else:
        raise ValueError(
            "give either to_light and to_eye (vectors) or surface, light and eye (points)"
        )
    n = _unit(_single_vector(normal, "normal"), "normal")
    l_unit = _unit(to_light_vector, "to_light (L)")
    v = _unit(to_eye_vector, "to_eye (V)")
    n_dot_l = float(n @ l_unit)
    r = 2.0 * n_dot_l * n - l_unit
    halfway = l_unit + v
    h_length = np.linalg.norm(halfway)
    h = halfway / h_length if h_length > 0 else np.zeros(3)
    return PhongGeometry(
        normal=n,
        to_light=l_unit,
        to_eye=v,
        n_dot_l=n_dot_l,
        reflected=r,
        r_dot_v=float(r @ v),
        halfway=h,
        n_dot_h=float(n @ h),
    )


def _single_vector(value: Any, name: str) -> np.ndarray:
    array = _vectors(value, name)
    if array.shape != (3,):
        raise ValueError(f"{name} must have shape (3,), got shape {array.shape}")
    return array


def shade(
    points: Any,
    normals: Any,
    eye: Any,
    material: Any,
    lights: Any,
    ambient: Any = 0.1,
    model: Literal["phong", "blinn"] = "phong",
) -> np.ndarray:
    """Evaluate the illumination model at many points with several coloured lights.

    ``I_c = ka Ia_c C_c + sum over lights [kd IL_c C_c max(0, N.L) + ks IL_c spec]`` per
    channel c, with C the material colour, ``spec = (R.V)^n`` (Phong) or ``(N.H)^n``
    (Blinn-Phong), and spec = 0 whenever N.L <= 0 or that cosine is <= 0. No shadows.
    Runs a compiled loop in parallel over the points (the kernel the renderers call per pixel).

    Parameters
    ----------
    points : (..., 3) array_like
        Surface points.
    normals : (..., 3) array_like
        Surface normals, broadcast against ``points``; normalized here.
    eye : (3,) array_like
        The viewer position.
    material : Material or (8,) array_like
        The scene's ``Material`` or its ``packed()`` values.
    lights : iterable of lights or (L, 7) array_like
        Point and directional lights (see :func:`pack_lights`).
    ambient : float or (3,) array_like, default 0.1
        The ambient intensity Ia, grey or per channel.
    model : {"phong", "blinn"}, default "phong"
        Use R.V (Phong) or N.H (Blinn-Phong) for the highlight.

    Returns
    -------
    (..., 3) ndarray of float64
        Unclamped (r, g, b) intensities, one row per point.

    Raises
    ------
    TypeError
        If an argument is not numeric or a light is of no known kind.
    ValueError
        If a shape is wrong, a value not finite, a normal of zero length, a coefficient
        negative, or ``model`` unknown.

    Examples
    --------
    One white light straight above a white point seen from above: ka Ia + kd + ks.

    >>> from types import SimpleNamespace
    >>> from pixelpath.lighting import shade
    >>> lamp = SimpleNamespace(position=(0, 0, 5), intensity=1.0, color=(1, 1, 1))
    >>> material = [1, 1, 1, 0.2, 0.6, 0.3, 10, 0]  # white, ka, kd, ks, n
    >>> shade([[0, 0, 0]], [[0, 0, 1]], (0, 0, 3), material, [lamp], ambient=0.5).round(6).tolist()
    [[1.0, 1.0, 1.0]]
    """
    if model not in MODELS:
        raise ValueError(f"model must be one of {MODELS}, got {model!r}")
    point_array = _vectors(points, "points")
    normal_array = _unit(_vectors(normals, "normals"), "normals")
    try:
        point_array, normal_array = np.broadcast_arrays(point_array, normal_array)
    except ValueError as exc:
        raise ValueError(
            f"points and normals do not broadcast together: shapes {point_array.shape} and "
            f"{normal_array.shape}"
        ) from exc
    eye_array = _single_vector(eye, "eye")
    packed_material = pack_material(material)
    packed_lights = pack_lights(lights)
    packed_ambient = pack_ambient(ambient)

    from pixelpath._threads import in_threads
    from pixelpath.lighting._kernels import shade_many

    shape = point_array.shape
    flat_points = np.ascontiguousarray(point_array.reshape(-1, 3))
    flat_normals = np.ascontiguousarray(normal_array.reshape(-1, 3))
    out = np.empty_like(flat_points)

    def shade_run(start: int, stop: int) -> None:
        shade_many(flat_points, flat_normals, eye_array, packed_material, packed_lights,
                   packed_ambient, model == "blinn", start, stop, out)

    in_threads(shade_run, len(flat_points), least=_LEAST_POINTS)
    return out.reshape(shape)
