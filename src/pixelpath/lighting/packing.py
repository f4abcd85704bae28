"""Pack lights, materials and the ambient term into the flat float64 arrays the kernels read.

Layouts (the contract between :mod:`pixelpath.lighting` and the renderers):

* lights: ``(L, 7)`` rows ``[kind, x, y, z, r*I, g*I, b*I]``; kind 0 is a point light at
  (x, y, z), kind 1 a directional light whose unit direction of travel (from the light into the
  scene) is (x, y, z), so that the vector L towards it is ``-(x, y, z)``;
* material: ``(8,)`` ``[r, g, b, ka, kd, ks, shininess, 0]`` (``Material.packed()``);
* ambient: ``(3,)`` the ambient intensity Ia per channel.

Lights are read by duck typing (a ``position`` or a ``direction``, an ``intensity`` and a
``color``), so any object with those attributes works, not only the scene's classes.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from pixelpath import _validate as v

__all__ = ["pack_ambient", "pack_lights", "pack_material"]

LIGHT_FIELDS = 7


def _pack_one(light: Any, index: int) -> np.ndarray:
    """Return the packed row of one light object."""
    name = f"lights[{index}]"
    intensity = v.rgb_or_scalar(getattr(light, "intensity", 1.0), f"{name}.intensity")
    color = v.colour(getattr(light, "color", (1.0, 1.0, 1.0)), f"{name}.color")
    row = np.empty(LIGHT_FIELDS)
    if hasattr(light, "position"):
        row[0] = 0.0
        row[1:4] = v.vector3(light.position, f"{name}.position")
    elif hasattr(light, "direction"):
        row[0] = 1.0
        row[1:4] = v.unit_vector3(light.direction, f"{name}.direction")
    else:
        raise TypeError(
            f"{name} must be a light with a 'position' (point light) or a 'direction' "
            f"(directional light), got {type(light).__name__}"
        )
    row[4:7] = color * intensity
    return row


def _check_packed(lights: np.ndarray) -> np.ndarray:
    """Validate an already packed ``(L, 7)`` array and return a float64 contiguous copy."""
    if lights.ndim != 2 or lights.shape[1] != LIGHT_FIELDS:
        raise ValueError(f"packed lights must have shape (L, 7), got shape {lights.shape}")
    if not np.issubdtype(lights.dtype, np.number):
        raise TypeError(f"packed lights must be numeric, got dtype {lights.dtype}")
    packed = np.ascontiguousarray(lights, dtype=np.float64)
    if not np.all(np.isfinite(packed)):
        raise ValueError("packed lights must be finite")
    if not np.all(np.isin(packed[:, 0], (0.0, 1.0))):
        raise ValueError("packed lights: column 0 (kind) must be 0 (point) or 1 (directional)")
    return packed


def pack_lights(lights: Iterable[Any] | Any) -> np.ndarray:
    """Pack point and directional lights into the ``(L, 7)`` float64 array the kernels read.

    Parameters
    ----------
    lights : light, iterable of lights, or (L, 7) array_like
        Objects with ``position`` (point light) or ``direction`` (directional light, the way
        the light travels), ``intensity`` (scalar or (r, g, b), default 1) and ``color``
        ((r, g, b), default white); a single light is accepted too. An array that is already
        packed is validated and returned as a contiguous float64 copy.

    Returns
    -------
    (L, 7) ndarray of float64
        Rows ``[kind, x, y, z, r*I, g*I, b*I]``: kind 0 with the position, or kind 1 with the
        unit direction of travel.

    Raises
    ------
    TypeError
        If an entry is neither kind of light, or a field is not numeric.
    ValueError
        If a field has the wrong size, is not finite, is negative (intensity, colour) or a
        direction is the zero vector.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> from pixelpath.lighting import pack_lights
    >>> sun = SimpleNamespace(direction=(0, -2, 0), intensity=0.5, color=(1, 1, 0.8))
    >>> pack_lights([sun]).tolist()
    [[1.0, 0.0, -1.0, 0.0, 0.5, 0.5, 0.4]]
    """
    if isinstance(lights, np.ndarray):
        return _check_packed(lights)
    if hasattr(lights, "position") or hasattr(lights, "direction"):
        lights = [lights]
    try:
        items = list(lights)
    except TypeError as exc:
        raise TypeError(
            f"lights must be a light or an iterable of lights, got {type(lights).__name__}"
        ) from exc
    if items and all(isinstance(item, list | tuple) for item in items):
        return _check_packed(np.asarray(items, dtype=np.float64))
    rows = [_pack_one(light, index) for index, light in enumerate(items)]
    return np.array(rows, dtype=np.float64).reshape(len(rows), LIGHT_FIELDS)


def pack_material(material: Any) -> np.ndarray:
    """Return a material as the ``(8,)`` float64 array ``[r, g, b, ka, kd, ks, shininess, 0]``.

    Parameters
    ----------
    material : Material or (8,) array_like
        An object with a ``packed()`` method (the scene's ``Material``) or the packed values.

    Returns
    -------
    (8,) ndarray of float64

    Raises
    ------
    ValueError
        If the values are not finite, or a colour, coefficient or the shininess is negative.

    Examples
    --------
    >>> from pixelpath.lighting import pack_material
    >>> pack_material([1, 0, 0, 0.1, 0.7, 0.3, 32, 0]).tolist()
    [1.0, 0.0, 0.0, 0.1, 0.7, 0.3, 32.0, 0.0]
    """
    values = material.packed() if hasattr(material, "packed") else material
    packed = v.float_array(values, "material", (8,))
    if np.any(packed[:7] < 0):
        raise ValueError(
            f"material colour, ka, kd, ks and shininess must be >= 0, got {packed.tolist()}"
        )
    return packed


def pack_ambient(ambient: Any) -> np.ndarray:
    """Return the ambient intensity Ia as a ``(3,)`` float64 array (a scalar means grey).

    Parameters
    ----------
    ambient : float or (3,) array_like
        Ia, for all channels or per channel (r, g, b); must be finite and >= 0.

    Returns
    -------
    (3,) ndarray of float64

    Examples
    --------
    >>> from pixelpath.lighting import pack_ambient
    >>> pack_ambient(0.2).tolist()
    [0.2, 0.2, 0.2]
    """
    return v.rgb_or_scalar(ambient, "ambient").copy()
