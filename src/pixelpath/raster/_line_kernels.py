"""Compiled kernels of line drawing: frustum clipping of segments and Bresenham's algorithm.

* ``clip_segments``: each segment's part inside the view frustum, clipped in homogeneous
  coordinates (before the perspective divide, so a segment crossing the near plane keeps only
  its part in front of it); Liang-Barsky's parametric form: for each of the six half-spaces
  c · p >= 0 the segment p(s) = a + s (b - a) keeps an interval of s.
* ``bresenham_pixels`` and ``draw_segments``: Bresenham's integer algorithm, in every octant,
  from the pixel of one end to the pixel of the other: one pixel per step along the major axis,
  8-connected, the minor coordinate stepping when the error term says the line is nearer the
  next row (column). Segments are always walked from the end earlier in scan order, so a
  segment gives the same pixels whichever way round its ends are given.

Depth along a line works as in the triangle rasterizer: the ends carry the depth key (1/w for
a perspective camera, affine in depth for an orthographic one), which is affine along the
projected line, and :func:`pixelpath.raster._setup_kernels.key_depth` turns it into a depth.
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._setup_kernels import FRUSTUM_PLANES, ORTHO_KEY_AT_NDC_0, key_depth

# Columns of a screen segment: both ends' (x, y, depth key) in pixels.
SEGMENT_FIELDS = 6
# Where each end's (x, y, key) starts in a segment's row.
START_END, STOP_END = 0, 3


@njit
def clip_segments(starts, ends, matrix, orthographic, screen, kept, width, height):
    """Clip world segments (E, 3) to the frustum, ``matrix`` mapping world to clip space.

    Writes each kept segment's ends as (x, y, depth key) in pixels into ``screen``
    (E, SEGMENT_FIELDS) and whether anything was left into ``kept`` (E,); returns how many
    segments were cut.
    """
    cut = 0
    a = np.empty(4)
    b = np.empty(4)
    for e in range(starts.shape[0]):
        for row in range(4):
            a[row] = _transform(matrix, row, starts[e])
            b[row] = _transform(matrix, row, ends[e])
        first, last = 0.0, 1.0
        for p in range(6):
            plane = FRUSTUM_PLANES[p]
            da = _plane_side(plane, a)
            db = _plane_side(plane, b)
            if da < 0.0 and db < 0.0:
                first, last = 1.0, 0.0
                break
            if da < 0.0:
                first = max(first, da / (da - db))
            elif db < 0.0:
                last = min(last, da / (da - db))
        kept[e] = first <= last
        if not kept[e]:
            continue
        if first > 0.0 or last < 1.0:
            cut += 1
        _to_screen(a, b, first, orthographic, screen, e, START_END, width, height)
        _to_screen(a, b, last, orthographic, screen, e, STOP_END, width, height)
    return cut


@njit(from_python=False)
def _transform(matrix, row, point):
    """Return row ``row`` of ``matrix`` (4, 4) applied to the point (x, y, z, 1)."""
    return (matrix[row, 0] * point[0] + matrix[row, 1] * point[1] + matrix[row, 2] * point[2]
            + matrix[row, 3])


@njit(from_python=False)
def _plane_side(plane, point):
    """Return c · (x, y, z, w) for a boundary row [PLANE, c0, c1, c2, c3] of FRUSTUM_PLANES."""
    return (plane[1] * point[0] + plane[2] * point[1] + plane[3] * point[2]
            + plane[4] * point[3])


@njit(from_python=False)
def _to_screen(a, b, s, orthographic, screen, e, column, width, height):
    """Write (x, y, depth key) in pixels of the point a + s (b - a) (clip coordinates).

    The key is the triangle rasterizer's (``screen_point``): 1/w, or for an orthographic
    camera ``ORTHO_KEY_AT_NDC_0 - z_ndc / 2``.
    """
    x = a[0] + s * (b[0] - a[0])
    y = a[1] + s * (b[1] - a[1])
    w = a[3] + s * (b[3] - a[3])
    inv_w = 1.0 / w
    screen[e, column] = (x * inv_w + 1.0) * 0.5 * width
    screen[e, column + 1] = (1.0 - y * inv_w) * 0.5 * height
    if orthographic:
        z = a[2] + s * (b[2] - a[2])
        screen[e, column + 2] = ORTHO_KEY_AT_NDC_0 - 0.5 * z * inv_w
    else:
        screen[e, column + 2] = inv_w


@njit(from_python=False)
def _end_pixels(segment, width, height):
    """Pixel indices of both ends, walked from the end earlier in scan order (row, then column).

    A pixel (i, j) covers [i, i + 1) × [j, j + 1); an end on the image's right or bottom border
    (x = width, y = height, where clipping puts it) belongs to the last column (row).
    """
    ia = min(max(math.floor(segment[0]), 0), width - 1)
    ja = min(max(math.floor(segment[1]), 0), height - 1)
    ib = min(max(math.floor(segment[3]), 0), width - 1)
    jb = min(max(math.floor(segment[4]), 0), height - 1)
    flipped = jb < ja or (jb == ja and ib < ia)
    if flipped:
        return ib, jb, ia, ja, flipped
    return ia, ja, ib, jb, flipped


@njit(from_python=False)
def _step(i, j, error, dx, dy, sx, sy):
    """One step of Bresenham's algorithm (all octants): dx = |Δi|, dy = -|Δj|."""
    twice = 2 * error
    if twice >= dy:
        error += dy
        i += sx
    if twice <= dx:
        error += dx
        j += sy
    return i, j, error


@njit
def bresenham_pixels(ia, ja, ib, jb):
    """Return the pixels (N, 2) of Bresenham's line from (ia, ja) to (ib, jb), ends included."""
    dx, dy = abs(ib - ia), -abs(jb - ja)
    sx = 1 if ia < ib else -1
    sy = 1 if ja < jb else -1
    count = max(dx, -dy) + 1
    pixels = np.empty((count, 2), dtype=np.intp)
    i, j, error = ia, ja, dx + dy
    for k in range(count):
        pixels[k, 0] = i
        pixels[k, 1] = j
        i, j, error = _step(i, j, error, dx, dy, sx, sy)
    return pixels


@njit
def draw_segments(screen, kept, owner, width, height, orthographic, near, far, x0, y0, limit,
                  depth, ids):
    """Draw the kept segments one pixel wide into the region's depth (h, w) and ids (h, w).

    ``screen`` (E, SEGMENT_FIELDS) holds the segments in image pixels (``width`` × ``height``),
    the region's top-left pixel is (x0, y0). At each pixel the line's depth is interpolated
    correctly for the projection (its depth key is affine along the projected line, evaluated
    at the pixel centre's position along the major axis; ``orthographic``, ``near`` and
    ``far`` turn it into a depth). A line pixel is kept where its depth is at most
    ``limit`` (h, w) there, and then only when nearer than the line already drawn there
    (``depth`` starts at inf, ``ids`` at -1; ties keep the earlier segment). ``ids`` receives
    the segment's ``owner``. Returns the number of line pixels inside the region and how many
    of them the limit removed.
    """
    h, w = depth.shape
    inside = 0
    hidden = 0
    for e in range(screen.shape[0]):
        if not kept[e]:
            continue
        segment = screen[e]
        ia, ja, ib, jb, flipped = _end_pixels(segment, width, height)
        if max(ia, ib) < x0 or min(ia, ib) >= x0 + w or jb < y0 or ja >= y0 + h:
            continue
        # The real line's ends, in the order walked, for the depth interpolation.
        xa, ya, va = segment[0], segment[1], segment[2]
        xb, yb, vb = segment[3], segment[4], segment[5]
        if flipped:
            xa, ya, va, xb, yb, vb = xb, yb, vb, xa, ya, va
        dx, dy = abs(ib - ia), -abs(jb - ja)
        sx = 1 if ia < ib else -1
        sy = 1 if ja < jb else -1
        major_x = dx >= -dy
        i, j, error = ia, ja, dx + dy
        for _ in range(max(dx, -dy) + 1):
            col, row = i - x0, j - y0
            if 0 <= col < w and 0 <= row < h:
                inside += 1
                along = _along(i + 0.5, xa, xb) if major_x else _along(j + 0.5, ya, yb)
                distance = key_depth(va + along * (vb - va), orthographic, near, far)
                if distance > limit[row, col]:
                    hidden += 1
                elif distance < depth[row, col]:
                    depth[row, col] = distance
                    ids[row, col] = owner[e]
            i, j, error = _step(i, j, error, dx, dy, sx, sy)
    return inside, hidden


@njit(from_python=False)
def _along(coordinate, start, stop):
    """Position of ``coordinate`` between ``start`` and ``stop`` as a fraction in [0, 1]."""
    if stop == start:
        return 0.5
    return min(max((coordinate - start) / (stop - start), 0.0), 1.0)


def warmup() -> None:
    """Compile the line kernels on one segment crossing the near plane."""
    matrix = np.eye(4)
    matrix[3, 2], matrix[3, 3] = -1.0, 0.0  # w = -z: the eye at the origin looking down -z
    starts = np.array([[0.0, 0.0, 1.0]])
    ends = np.array([[0.5, 0.5, -2.0]])
    screen = np.empty((1, SEGMENT_FIELDS))
    kept = np.empty(1, dtype=np.bool_)
    clip_segments(starts, ends, matrix, False, screen, kept, 8, 8)
    bresenham_pixels(0, 0, 5, 2)
    draw_segments(screen, kept, np.zeros(1, dtype=np.intp), 8, 8, False, 0.1, 10.0, 0, 0,
                  np.full((8, 8), np.inf), np.full((8, 8), np.inf),
                  np.full((8, 8), -1, dtype=np.int32))
