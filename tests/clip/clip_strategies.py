"""Hypothesis strategies and shapely helpers shared by the clipping tests."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import strategies as st


@st.composite
def star_polygons(draw, min_vertices=3, max_vertices=12, grid=False, concave=True):
    """A simple polygon, star-shaped around a random centre, counter-clockwise or not.

    With ``grid`` its vertices are small integers, which makes degenerate contacts (vertices on
    edges, collinear overlaps) common.
    """
    n = draw(st.integers(min_vertices, max_vertices))
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    # Jittered even spacing keeps every angular gap below pi, so the centre sees every vertex.
    angles = (np.arange(n) + rng.uniform(0, 0.45, n)) * (2 * np.pi / n)
    radii = rng.uniform(0.3, 1.0, n) if concave else np.ones(n)
    centre = rng.uniform(-0.5, 0.5, 2)
    scale = 6.0 if grid else 1.0
    directions = np.column_stack([np.cos(angles), np.sin(angles)])
    points = scale * (centre + radii[:, None] * directions)
    if grid:
        points = np.round(points)
    if draw(st.booleans()):
        points = points[::-1]
    return np.ascontiguousarray(points)


@st.composite
def convex_polygons(draw, max_vertices=10):
    """A convex polygon (the convex hull of random points), in a random orientation."""
    points = draw(star_polygons(3, max_vertices, concave=True))
    hull = np.asarray(shapely.Polygon(points).convex_hull.exterior.coords)[:-1]
    return hull[::-1].copy() if draw(st.booleans()) else hull.copy()


def is_valid_polygon(points: np.ndarray) -> bool:
    """Whether shapely sees a valid polygon with positive area (no duplicates, simple)."""
    if len(np.unique(points, axis=0)) != len(points) or len(points) < 3:
        return False
    polygon = shapely.Polygon(points)
    return polygon.is_valid and polygon.area > 1e-9


def polygonal_parts(geometry) -> list:
    """The polygons of a shapely result, ignoring points and lines of a collection."""
    parts = shapely.get_parts(geometry)
    return [p for p in parts if p.geom_type == "Polygon" and p.area > 0]


def signed_area(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
