"""Input checks shared across the package: scene records, light packing and render options.

Each message names the argument and shows what came in.
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

# Largest image side accepted: 16384 pixels is far past any display, and larger requests are
# almost always a typo that would otherwise try to allocate tens of gigabytes.
MAX_IMAGE_SIDE = 16384

# Up to this many elements (a 4 x 4 matrix) checks run on Python floats: each NumPy call costs
# a microsecond or two whatever the size, many times the work a few floats need.
_FEW = 16
_UNIT_SLACK = 4.0 * float(np.finfo(np.float64).eps)  # a row this close to length 1 is kept


def frozen(array: np.ndarray) -> np.ndarray:
    """Return ``array`` marked read-only, so records that hold it stay immutable."""
    array.flags.writeable = False
    return array


def _describe(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    return repr(value) if len(repr(value)) <= 80 else f"a {type(value).__name__}"


def real(value: Any, name: str, *, positive: bool = False, minimum: float | None = None) -> float:
    """Return ``value`` as a finite float, checking its sign or lower bound when asked."""
    if type(value) is not float and (  # a float needs no look at the number ABCs (0.4 µs)
        isinstance(value, bool) or not isinstance(value, numbers.Real)
    ):
        raise TypeError(f"{name} must be a real number, got {_describe(value)}")
    result = float(value)
    if not math.isfinite(result):
        raise ValueError(f"{name} must be finite, got {result}")
    if positive and result <= 0.0:
        raise ValueError(f"{name} must be positive, got {result}")
    if minimum is not None and result < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {result}")
    return result


def image_side(value: Any, name: str) -> int:
    """Return an image width or height: a positive int no larger than :data:`MAX_IMAGE_SIDE`."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an int, got {_describe(value)}")
    side = int(value)
    if not 1 <= side <= MAX_IMAGE_SIDE:
        raise ValueError(f"{name} must be between 1 and {MAX_IMAGE_SIDE} pixels, got {side}")
    return side


def float_array(
    value: Any, name: str, shape: tuple[int | None, ...], *, copy: bool = True
) -> np.ndarray:
    """Return a finite float64 copy of ``value`` with the given shape (``None`` = any length).

    With ``copy=False`` a float64 array comes back as it is, for callers that only read it.
    """
    try:
        array = np.array(value, dtype=np.float64) if copy else np.asarray(value, np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be an array of numbers, got {_describe(value)}") from None
    got = array.shape
    if got != shape and (  # an exact match needs no element-wise look (it is the usual case)
        len(got) != len(shape)
        or any(n is not None and n != m for n, m in zip(shape, got, strict=True))
    ):
        sizes = ["n" if n is None else str(n) for n in shape]
        expected = "(" + ", ".join(sizes) + ("," if len(sizes) == 1 else "") + ")"
        raise ValueError(f"{name} must have shape {expected}, got shape {array.shape}")
    if not all_finite(array):
        bad = np.argwhere(~np.isfinite(array))[0]
        raise ValueError(f"{name} must be finite, got {array[tuple(bad)]} at index {tuple(bad)}")
    return array


def all_finite(array: np.ndarray) -> bool:
    """Return whether every element of ``array`` is finite (``np.isfinite(array).all()``).

    A few elements (up to 16) are checked as Python floats, quicker than NumPy's reduction.

    Examples
    --------
    >>> from pixelpath._validate import all_finite
    >>> all_finite(np.array([1.0, 2.0, 3.0])), all_finite(np.array([1.0, np.nan]))
    (True, False)
    """
    if array.size <= _FEW:
        return all(map(math.isfinite, array.ravel().tolist()))
    return bool(np.isfinite(array).all())


def vector3(value: Any, name: str) -> np.ndarray:
    """Return a finite, read-only float64 (3,) vector."""
    return frozen(float_array(value, name, (3,)))


def unit_rows(vectors: np.ndarray, lengths: np.ndarray | None = None) -> np.ndarray:
    """Return the rows of ``vectors`` scaled to unit length.

    Rows already of unit length (to 4 ulp) are kept as they are, so normalizing twice gives the
    same bits and records survive ``to_dict``/``from_dict`` round trips exactly. ``vectors`` is
    a float64 (3,) vector or (..., 3) array; the caller that has their ``row_lengths`` already
    may pass them as ``lengths`` (used for (..., 3) arrays).

    Examples
    --------
    >>> from pixelpath._validate import unit_rows
    >>> unit_rows(np.array([[3.0, 0.0, 4.0], [0.0, 0.0, 0.0]])).tolist()
    [[0.6, 0.0, 0.8], [0.0, 0.0, 0.0]]
    """
    if vectors.ndim == 1:  # one vector: the same arithmetic in Python floats, 20 times quicker
        x, y, z = vectors.tolist()
        length = math.sqrt((x * x + y * y) + z * z)
        if abs(length - 1.0) <= _UNIT_SLACK or length == 0.0:
            return vectors.astype(np.float64)  # a float64 copy, as the division below makes
        return np.array([x / length, y / length, z / length])
    lengths = (row_lengths(vectors) if lengths is None else lengths)[..., 0]
    keep = (np.abs(lengths - 1.0) <= _UNIT_SLACK) | (lengths == 0.0)
    if keep.all():  # the usual case for normals read from a file: x / 1.0 is x, bit for bit
        return vectors.astype(np.float64)  # a float64 copy, as the division below makes
    divisor = np.where(keep, 1.0, lengths)
    # column by column: dividing (n, 3) by (n, 1) runs NumPy's inner loop three elements long
    unit = np.empty(vectors.shape)
    for axis in range(3):
        np.divide(vectors[..., axis], divisor, out=unit[..., axis])
    return unit


def unit_or_zero(vectors: np.ndarray) -> np.ndarray:
    """Return (N, 3) ``vectors`` scaled to unit length; a row of length 0 becomes 0.

    For normals summed from faces, where a zero sum (faces of no area) means no direction.

    Examples
    --------
    >>> from pixelpath._validate import unit_or_zero
    >>> unit_or_zero(np.array([[0.0, 3.0, 4.0], [0.0, 0.0, 0.0]])).tolist()
    [[0.0, 0.6, 0.8], [0.0, 0.0, 0.0]]
    """
    lengths = np.linalg.norm(vectors, axis=1, keepdims=True)
    return np.divide(vectors, lengths, out=np.zeros_like(vectors), where=lengths > 0.0)


def sum_rows_at(index: np.ndarray, rows: np.ndarray, count: int) -> np.ndarray:
    """Return (count, 3): row k the sum of the (N, 3) ``rows`` whose ``index`` is k.

    For normals gathered from faces onto vertices (or places, or groups of corners).

    Examples
    --------
    >>> from pixelpath._validate import sum_rows_at
    >>> sum_rows_at(np.array([1, 1, 0]), np.eye(3), 3).tolist()
    [[0.0, 0.0, 1.0], [1.0, 1.0, 0.0], [0.0, 0.0, 0.0]]
    """
    return np.stack([np.bincount(index, rows[:, axis], count) for axis in range(3)], axis=1)


def row_lengths(vectors: np.ndarray) -> np.ndarray:
    """Return the lengths of (..., 3) vectors, shaped (..., 1).

    The bits of ``np.linalg.norm(vectors, axis=-1, keepdims=True)`` (the same squares, summed
    x, y, then z), at a fifth of its time: NumPy reduces a length-3 axis slowly.

    Examples
    --------
    >>> from pixelpath._validate import row_lengths
    >>> row_lengths(np.array([[3.0, 4.0, 0.0], [0.0, 0.0, 2.0]])).tolist()
    [[5.0], [2.0]]
    """
    if vectors.ndim == 1:  # one vector: the same arithmetic in Python floats
        x, y, z = vectors.tolist()
        return np.array([math.sqrt((x * x + y * y) + z * z)])
    squares = vectors * vectors  # one pass over the array rather than three strided ones
    return np.sqrt((squares[..., 0] + squares[..., 1]) + squares[..., 2])[..., None]


def vector_length(vector: np.ndarray) -> float:
    """Return the length of a float64 vector: ``float(np.linalg.norm(vector))``, bit for bit.

    NumPy's own formula (the square root of the vector's dot product with itself) without its
    checks and dispatch, which cost three times the sum.

    Examples
    --------
    >>> from pixelpath._validate import vector_length
    >>> vector_length(np.array([3.0, 4.0, 0.0]))
    5.0
    """
    flat = vector.ravel(order="K")  # contiguous, as np.linalg.norm hands it to dot
    return math.sqrt(flat.dot(flat))


def cross3(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Return the cross product of 3-vectors, as ``np.cross`` computes it, bit for bit.

    ``a`` and ``b`` are float64 (3,) vectors or (..., 3) arrays that broadcast together.
    ``np.cross`` spends some 30 microseconds preparing its axes; two vectors take a
    microsecond here, in Python floats.

    Examples
    --------
    >>> from pixelpath._validate import cross3
    >>> cross3(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])).tolist()
    [0.0, 0.0, 1.0]
    >>> cross3(np.array([[1.0, 0.0, 0.0]]), np.array([0.0, 0.0, 1.0])).tolist()
    [[0.0, -1.0, 0.0]]
    """
    if a.ndim == 1 and b.ndim == 1:
        (a0, a1, a2), (b0, b1, b2) = a.tolist(), b.tolist()
        return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def unit_vector3(value: Any, name: str) -> np.ndarray:
    """Return ``value`` normalized to unit length; a zero vector is a ValueError."""
    vector = float_array(value, name, (3,))
    if not any(vector.tolist()):
        raise ValueError(f"{name} must not be the zero vector")
    return frozen(unit_rows(vector))


def colour(value: Any, name: str) -> np.ndarray:
    """Return an (r, g, b) colour; components must be finite and non-negative."""
    if type(value) is tuple and value == _WHITE_TUPLE:  # every light's default: made once
        return _WHITE
    rgb = float_array(value, name, (3,))
    if min(rgb.tolist()) < 0.0:
        raise ValueError(f"{name} components must be non-negative (>= 0), got {rgb.tolist()}")
    return frozen(rgb)


_WHITE_TUPLE = (1.0, 1.0, 1.0)
_WHITE = frozen(np.ones(3))


def rgb_or_scalar(value: Any, name: str) -> np.ndarray:
    """Return a non-negative intensity given as a scalar or (r, g, b), as a (3,) array."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        value = (value, value, value)
    return colour(value, name)


def instance(value: Any, name: str, kinds: type | tuple[type, ...]) -> Any:
    """Return ``value`` unchanged after checking its type."""
    if not isinstance(value, kinds):
        names = " or ".join(k.__name__ for k in (kinds if isinstance(kinds, tuple) else (kinds,)))
        raise TypeError(f"{name} must be a {names}, got {type(value).__name__}")
    return value


def finite_array(
    value: Any, name: str, last: int | None = None, *, copy: bool = True
) -> np.ndarray:
    """Return a finite float64 copy of ``value``, of any shape, or ``(..., last)`` when given.

    With ``copy=False`` a float64 array comes back as it is, for callers that only read it.
    """
    array = numeric_array(value, name, last, copy=copy)
    if not np.all(np.isfinite(array)):
        kind = "NaN" if np.any(np.isnan(array)) else "infinite values"
        raise ValueError(f"{name} must be finite, got {kind} in {_describe(value)}")
    return array


def numeric_array(
    value: Any, name: str, last: int | None = None, *, copy: bool = True
) -> np.ndarray:
    """:func:`finite_array` before its look at every element: NaN and infinities pass.

    For kernels that check their input as they read it (a million rays' separate check took
    a single thread 3.5 ms); they call :func:`finite_array` for its message when they find a
    bad value.

    Examples
    --------
    >>> from pixelpath._validate import numeric_array
    >>> numeric_array([[1, float("nan"), 3]], "rays", 3).tolist()
    [[1.0, nan, 3.0]]
    """
    if isinstance(value, np.ndarray) and value.dtype.kind in "iufb":
        array = value.astype(np.float64, copy=copy)
    else:
        try:
            if isinstance(value, str | bytes) or np.asarray(value).dtype.kind not in "iufb":
                raise TypeError
            array = np.array(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise TypeError(
                f"{name} must be a number or an array of numbers, got {_describe(value)}"
            ) from None
    if last is not None and (array.ndim == 0 or array.shape[-1] != last):
        raise ValueError(f"{name} must have shape (..., {last}), got shape {array.shape}")
    return array


def choice(value: Any, name: str, choices: tuple[str, ...]) -> None:
    """Check that ``value`` is one of the strings ``choices``."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(choices)}; got {value!r}")


def int_in(value: Any, name: str, low: int, high: int, meaning: str) -> int:
    """Return ``value`` as an int in ``low..high``; ``meaning`` says what it counts."""
    if not isinstance(value, int | np.integer) or isinstance(value, bool):
        raise TypeError(f"{name} must be an int ({meaning}), got {type(value).__name__}")
    if not low <= value <= high:
        raise ValueError(f"{name} must be in {low}..{high} ({meaning}), got {value}")
    return int(value)
