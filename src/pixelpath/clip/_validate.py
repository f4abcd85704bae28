"""Input checks shared by the clipping functions: one home for the error messages."""

from __future__ import annotations

import numpy as np

from pixelpath.clip._kernels import LARGEST_COORDINATE, NON_FINITE, TOO_FEW_VERTICES, TOO_LARGE


def polygon_array(value: object, name: str) -> np.ndarray:
    """Return ``value`` as a finite, contiguous ``(N, 2)`` float64 array (a copy if needed).

    Raises
    ------
    TypeError
        If the values are not real numbers.
    ValueError
        If the shape is not ``(N, 2)`` or a coordinate is NaN or infinite.
    """
    raw = np.asarray(value)
    if raw.dtype.kind not in "iuf":
        raise TypeError(
            f"{name} must be an (N, 2) array of real coordinates, got dtype {raw.dtype}"
        )
    if raw.ndim != 2 or raw.shape[1] != 2:
        raise ValueError(f"{name} must have shape (N, 2), got shape {raw.shape}")
    points = np.ascontiguousarray(raw, dtype=np.float64)
    if not np.isfinite(points).all():
        raise _non_finite(points, name)
    return points


def _non_finite(points: np.ndarray, name: str) -> ValueError:
    i = int(np.flatnonzero(~np.isfinite(points).all(axis=1))[0])
    return ValueError(f"{name} has a NaN or infinite coordinate at vertex {i}: {points[i]}")


def bounded(points: np.ndarray, name: str) -> np.ndarray:
    """Return finite ``points`` if no coordinate exceeds what float kernels take, else raise.

    Sutherland-Hodgman computes in floating point (``LARGEST_COORDINATE`` in the kernels says
    why the limit keeps every intermediate finite); Weiler-Atherton computes exactly and needs
    no limit, which the message says.
    """
    error = _beyond_limit(points, name)
    if error is not None:
        raise error
    return points


def _beyond_limit(points: np.ndarray, name: str) -> ValueError | None:
    large = np.abs(points).max(axis=1, initial=0.0) > LARGEST_COORDINATE
    if not large.any():
        return None
    i = int(np.flatnonzero(large)[0])
    x, y = points[i]
    return ValueError(
        f"{name} vertex {i} at ({x:g}, {y:g}) is beyond ±{LARGEST_COORDINATE:g}, the largest "
        "coordinate Sutherland-Hodgman's floating-point arithmetic takes without overflow; "
        "weiler_atherton computes exactly and takes any finite coordinates"
    )


def subject_error(status: int, name: str, points: np.ndarray) -> ValueError:
    """Return the error for a kernel's status code about the polygon ``points``."""
    if status == NON_FINITE:
        return _non_finite(points, name)
    if status == TOO_LARGE:
        return _beyond_limit(points, name) or ValueError(f"{name} has a coordinate too large")
    if status == TOO_FEW_VERTICES:
        return ValueError(f"{name} needs at least 3 distinct vertices")
    return ValueError(f"{name} was rejected (status {status})")


def distinct_ring(points: np.ndarray, name: str) -> np.ndarray:
    """Drop vertices that repeat their predecessor (cyclically); require 3 distinct ones."""
    repeats = np.all(points == np.roll(points, 1, axis=0), axis=1)
    ring = points[~repeats] if not repeats.all() else points[:1]
    if len(np.unique(ring, axis=0)) < 3:
        raise ValueError(
            f"{name} needs at least 3 distinct vertices, got {len(ring)}: {ring.tolist()}"
        )
    return np.ascontiguousarray(ring)


def twice_signed_area(points: np.ndarray) -> float:
    """Shoelace sum: positive for counter-clockwise vertices."""
    x, y = points[:, 0], points[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
