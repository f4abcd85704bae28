"""Sutherland-Hodgman's stage generalized to one half-space over vertices with attributes.

The notes clip against one window boundary at a time: walk the edges (S, E) with S starting at
the last vertex, emit the intersection when the edge crosses the boundary and E when E is
inside. Nothing in that walk depends on the boundary being a line in the plane, so here a
boundary is any half-space ``d(v) = c · v[:m] + c_m >= 0`` given by its coefficients
``plane = (c_0, ..., c_{m-1}, c_m)``, and a vertex is a row of ``k >= m`` numbers: the first
``m`` are its coordinates, the rest are attributes carried along (interpolated linearly at
intersections). The frustum clipping of the raster pipeline uses it in homogeneous clip space
(x, y, z, w), where the near plane is ``z + w >= 0``.

Intersections are computed from the inside end of an edge towards its outside end
(``t = d_in / (d_in - d_out)``), so two polygons sharing an edge get the bit-identical point:
clipped meshes stay watertight.
"""

from __future__ import annotations

from pixelpath._jit import njit


@njit(inline="always")
def halfspace_distance(plane, vertex):
    """Signed value ``d = c · v[:m] + c_m`` of a vertex; inside when ``d >= 0``."""
    m = plane.shape[0] - 1
    d = plane[m]
    for axis in range(m):
        d += plane[axis] * vertex[axis]
    return d


@njit(inline="always")
def _emit_crossing(inner, d_in, outer, d_out, dst, row):
    t = d_in / (d_in - d_out)
    for axis in range(inner.shape[0]):
        dst[row, axis] = inner[axis] + t * (outer[axis] - inner[axis])


@njit
def clip_polygon_halfspace(src, n, plane, dst):
    """Clip the polygon ``src[:n]`` (rows of k numbers) against ``plane``; return the count.

    The result goes to ``dst``, which needs room for ``n + n // 2`` rows in general (at most
    one output per edge plus one per edge re-entering the half-space; ``n + 1`` for a convex
    polygon, which crosses the boundary at most twice).
    """
    if n == 0:
        return 0
    m = 0
    s = src[n - 1]  # S starts as the last vertex
    d_s = halfspace_distance(plane, s)
    for i in range(n):
        e = src[i]
        d_e = halfspace_distance(plane, e)
        if (d_s >= 0.0) != (d_e >= 0.0):  # the edge crosses: emit the intersection first
            if d_s >= 0.0:
                _emit_crossing(s, d_s, e, d_e, dst, m)
            else:
                _emit_crossing(e, d_e, s, d_s, dst, m)
            m += 1
        if d_e >= 0.0:
            dst[m, :] = e
            m += 1
        s = e
        d_s = d_e
    return m
