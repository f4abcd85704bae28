"""Input checks shared by the clipping functions: one home for the error messages."""

from __future__ import annotations

import numpy as np

from pixelpath.clip._kernels import NON_FINITE, TOO_FEW_VERTICES


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
    bad = ~np.isfinite(points).all(axis=1)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name} has a NaN or infinite coordinate at vertex {i}: {raw[i]}")
    return points


def subject_error(status: int, name: str) -> ValueError:
    """Return the error for a kernel's subject status code."""
    if status == NON_FINITE:
        return ValueError(f"{name} has a NaN or infinite coordinate")
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
