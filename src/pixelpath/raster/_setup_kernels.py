"""Compiled raster set-up: culling, frustum classes and clipping, the screen, triangle records.

Steps 1 and 2 of the pipeline :mod:`pixelpath.raster._kernels` outlines, and what the methods
read off their result: back faces (``faces_away``), the triangles' frustum classes and their
clipping by the six planes (``classify_triangles``, ``clip_triangles``; ``cut_triangle`` cuts
by any plane, for the painter's and the BSP methods), the perspective divide and viewport
(``clip_to_screen``, ``key_depth``), the set-up record of each triangle (``setup_triangles``)
and what it says at a pixel: a scan line's span (``scanline_span``), the perspective-correct
weights (``perspective_weights``) and the depth comparisons every method shares
(``clearly_nearer``, ``wins_depth_test``).
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit
from pixelpath.clip._kernels import PLANE, clip_stage

# Column layout of the per-triangle set-up record (float64).
SORTED_XY = 0  # x0, y0, x1, y1, x2, y2 sorted by y: the triangle's edge table
S1_PLANE = 6  # screen weight of vertex 1: s1 = a x + b y + c
S2_PLANE = 9  # screen weight of vertex 2
KEY_PLANE = 12  # depth key (1/w in perspective; larger is nearer) = a x + b y + c
VERTEX_INVW = 15  # 1/w at vertices 0, 1, 2 (in the triangle's own order; 1 when orthographic)
SLOPES = 18  # dx/dy of the sorted edges (v0, v2), (v0, v1), (v1, v2); 0 for a horizontal one
SETUP_FIELDS = 21

# Frustum triangle classes.
OUTSIDE = 0  # every vertex outside one frustum plane: dropped
INSIDE = 1  # in front of the near plane, behind the far plane, inside the guard band: drawn as is
CROSSING = 2  # clipped against the six planes

# The six frustum planes in clip space as boundary rows of the clipping kernel:
# [PLANE, c0, c1, c2, c3], the half-space c · (x, y, z, w) >= 0.
FRUSTUM_PLANES = np.array(
    [
        [PLANE, 0.0, 0.0, 1.0, 1.0],  # near: z >= -w
        [PLANE, 0.0, 0.0, -1.0, 1.0],  # far: z <= w
        [PLANE, 1.0, 0.0, 0.0, 1.0],  # left: x >= -w
        [PLANE, -1.0, 0.0, 0.0, 1.0],  # right: x <= w
        [PLANE, 0.0, 1.0, 0.0, 1.0],  # bottom: y >= -w
        [PLANE, 0.0, -1.0, 0.0, 1.0],  # top: y <= w
    ]
)
# Triangles within GUARD_BAND times the view's half-width are rasterized without x/y clipping
# (the scan converter clamps spans to the image); only larger ones are clipped exactly.
GUARD_BAND = 8.0
# Room for a triangle clipped by the six planes. In exact arithmetic it stays convex and gains
# at most one vertex per plane (9); rounding on nearly degenerate input could break convexity,
# so the buffers follow the general bound of a stage, n + n // 2 vertices: 3, 4, 6, 9, 13, 19,
# 28.
MAX_CLIPPED = 28


@njit(inline="always")
def faces_away(normal, point, eye):
    """Return the object-space back-face test N · (w P − E) >= 0 (V from the eye inwards).

    ``eye`` (4,) is homogeneous (``Camera.viewpoint``): (eye, 1) gives N · (P − eye), and the
    orthographic viewer at infinity, (−d, 0), gives N · d with d the viewing direction.
    """
    return (
        normal[0] * (eye[3] * point[0] - eye[0])
        + normal[1] * (eye[3] * point[1] - eye[1])
        + normal[2] * (eye[3] * point[2] - eye[2])
        >= 0.0
    )


@njit
def front_facing_many(normals, points, eye, out):
    """Write whether each face (F,) turns towards the eye (not :func:`faces_away`)."""
    for f in range(normals.shape[0]):
        out[f] = not faces_away(normals[f], points[f], eye)


_ALL_PLANES = 63  # the six bits of _outcode
_NEEDS_CLIP = 64  # a vertex's classify bit: outside the near, far or guard-band planes


@njit(inline="always")
def _outcode(x, y, z, w):
    """Return bit p set when the vertex is outside FRUSTUM_PLANES[p]."""
    code = 0
    if z < -w:
        code |= 1
    if z > w:
        code |= 2
    if x < -w:
        code |= 4
    if x > w:
        code |= 8
    if y < -w:
        code |= 16
    if y > w:
        code |= 32
    return code


@njit
def classify_triangles(clip, triangles, keep, status):
    """Sort each kept triangle (T,) into OUTSIDE, INSIDE or CROSSING the view frustum.

    Each vertex is classified once (its outcode, and whether it lies outside the near, far or
    guard-band planes), then each triangle combines its corners' bytes: a mesh's vertices are
    shared by about six triangles, and testing the corners triangle by triangle took three
    times as long for the bunny.
    """
    codes = np.empty(clip.shape[0], dtype=np.uint8)
    for v in range(clip.shape[0]):
        x, y, z, w = clip[v, 0], clip[v, 1], clip[v, 2], clip[v, 3]
        code = _outcode(x, y, z, w)
        band = GUARD_BAND * w
        if z < -w or z > w or abs(x) > band or abs(y) > band:
            code |= _NEEDS_CLIP
        codes[v] = code
    for t in range(triangles.shape[0]):
        status[t] = OUTSIDE
        if not keep[t]:
            continue
        a, b, c = codes[triangles[t, 0]], codes[triangles[t, 1]], codes[triangles[t, 2]]
        if a & b & c & _ALL_PLANES == 0:
            status[t] = CROSSING if (a | b | c) & _NEEDS_CLIP else INSIDE


@njit
def clip_triangles(attributes, triangles, crossing):
    """Clip the listed triangles against the frustum with Sutherland-Hodgman.

    Returns the new vertices (N, k) (indices continue after ``attributes``), their fan
    triangles (M, 3) and, per new triangle, the index of the triangle it came from.
    """
    k = attributes.shape[1]
    offset = attributes.shape[0]
    # Sized for the usual case (a convex piece of at most 9 vertices), grown when exceeded.
    vertices = np.empty((crossing.shape[0] * 9, k))
    new_triangles = np.empty((crossing.shape[0] * 7, 3), dtype=np.intp)
    source = np.empty(crossing.shape[0] * 7, dtype=np.intp)
    polygon = np.empty((MAX_CLIPPED + 1, k))
    scratch = np.empty((MAX_CLIPPED + 1, k))
    untraced = np.empty((0, 2))  # no room to record crossings: the stages keep no trace
    n_vertices = 0
    n_triangles = 0
    for t in crossing:
        for corner in range(3):
            _copy_row(attributes, triangles[t, corner], polygon, corner)
        n = 3  # the triangle's corners
        src, dst = polygon, scratch
        for p in range(6):
            n = clip_stage(src, n, FRUSTUM_PLANES[p], dst, untraced)
            src, dst = dst, src
        if n < 3:
            continue
        if n_vertices + n > vertices.shape[0]:
            vertices = _grown_rows(vertices, n_vertices + n)
        if n_triangles + n - 2 > source.shape[0]:
            new_triangles = _grown_rows(new_triangles, n_triangles + n - 2)
            source = _grown(source, n_triangles + n - 2)
        for corner in range(n):
            _copy_row(src, corner, vertices, n_vertices + corner)
        for fan in range(1, n - 1):
            new_triangles[n_triangles, 0] = offset + n_vertices
            new_triangles[n_triangles, 1] = offset + n_vertices + fan
            new_triangles[n_triangles, 2] = offset + n_vertices + fan + 1
            source[n_triangles] = t
            n_triangles += 1
        n_vertices += n
    return vertices[:n_vertices], new_triangles[:n_triangles], source[:n_triangles]


# Element-by-element copies: slice assignment would make Numba compile its shape-mismatch error
# messages (string formatting), seconds of first-run compile time for code that never runs.
@njit(inline="always")
def _copy_row(source, source_row, target, target_row):
    for column in range(source.shape[1]):
        target[target_row, column] = source[source_row, column]


@njit
def _grown_rows(array, needed):
    """Return a copy of the 2-D ``array`` with room for at least ``needed`` rows (doubling)."""
    bigger = np.empty((max(needed, 2 * array.shape[0]), array.shape[1]), dtype=array.dtype)
    for row in range(array.shape[0]):
        _copy_row(array, row, bigger, row)
    return bigger


@njit
def _grown(array, needed):
    """Return a copy of the 1-D ``array`` with room for at least ``needed`` items (doubling)."""
    bigger = np.empty(max(needed, 2 * array.shape[0]), dtype=array.dtype)
    for k in range(array.shape[0]):
        bigger[k] = array[k]
    return bigger


# Cutting a triangle by a plane (the painter's and BSP methods' polygon splitting).
@njit(from_python=False)
def cut_triangle(vertices, count, corners, distances, eps, pieces, cut_edges, cut_params):
    """Cut a triangle by a plane into pieces that each lie on one side of it.

    Parameters
    ----------
    vertices : (V, k) float64
        Per-vertex rows (a position and any attributes, all interpolated linearly along a cut
        edge); rows ``[0, count)`` are in use. Grown (doubled) when full: keep the returned one.
    corners : (3,) intp
        The triangle's vertex indices.
    distances : (3,) float64
        Signed distances of its corners to the plane; within ``eps`` a corner lies on it.
    pieces : (3, 4) intp, out
        Per piece: its three vertex indices (in the triangle's winding) and its side, +1 where
        the distances are positive, -1 where negative.
    cut_edges : (2, 2) intp, out; cut_params : (2,) float64, out
        Per new vertex: the edge it cuts (lower vertex index first) and its parameter along it.

    Returns
    -------
    (vertices, count, n_pieces)
        ``n_pieces`` is 0 when the triangle does not straddle the plane (nothing is written),
        else 2 (a corner on the plane: one new vertex) or 3 (two new vertices).
    """
    s0, s1, s2 = _side(distances[0], eps), _side(distances[1], eps), _side(distances[2], eps)
    if max(s0, s1, s2) < 1 or min(s0, s1, s2) > -1:
        return vertices, count, 0
    if count + 2 > vertices.shape[0]:
        vertices = _grown_rows(vertices, count + 2)
    # The corner on the plane, or else the corner alone on its side, comes first.
    if s0 * s1 * s2 == 0:
        lone = 0 if s0 == 0 else (1 if s1 == 0 else 2)
    else:
        lone = 0 if s1 == s2 else (1 if s0 == s2 else 2)
    a, b, c = corners[lone], corners[(lone + 1) % 3], corners[(lone + 2) % 3]
    da, db, dc = distances[lone], distances[(lone + 1) % 3], distances[(lone + 2) % 3]
    side_a, side_b = _side(da, eps), _side(db, eps)
    if side_a == 0:
        m = _cut_edge(vertices, count, b, db, c, dc, cut_edges, cut_params, 0)
        _store_piece(pieces, 0, a, b, m, side_b)
        _store_piece(pieces, 1, a, m, c, -side_b)
        return vertices, count + 1, 2
    m_ab = _cut_edge(vertices, count, a, da, b, db, cut_edges, cut_params, 0)
    m_ca = _cut_edge(vertices, count + 1, c, dc, a, da, cut_edges, cut_params, 1)
    _store_piece(pieces, 0, a, m_ab, m_ca, side_a)
    _store_piece(pieces, 1, m_ab, b, c, side_b)
    _store_piece(pieces, 2, m_ab, c, m_ca, side_b)
    return vertices, count + 2, 3


@njit(inline="always")
def _cut_edge(vertices, row, i, di, j, dj, cut_edges, cut_params, slot):
    """Write at ``row`` the point where edge (i, j) meets the plane; return ``row``.

    Always interpolated from the lower vertex index, so an edge shared by two triangles gets
    the same bits from both.
    """
    if j < i:
        i, di, j, dj = j, dj, i, di
    s = di / (di - dj)
    for column in range(vertices.shape[1]):
        start = vertices[i, column]
        vertices[row, column] = start + s * (vertices[j, column] - start)
    cut_edges[slot, 0] = i
    cut_edges[slot, 1] = j
    cut_params[slot] = s
    return row


@njit(inline="always")
def _side(distance, eps):
    """+1, -1 or 0 (on the plane, within eps)."""
    if distance > eps:
        return 1
    if distance < -eps:
        return -1
    return 0


@njit(inline="always")
def _store_piece(pieces, slot, a, b, c, side):
    pieces[slot, 0] = a
    pieces[slot, 1] = b
    pieces[slot, 2] = c
    pieces[slot, 3] = side


@njit(error_model="numpy")
def clip_to_screen(clip, width, height, orthographic, screen):
    """Write (x_screen, y_screen, key) of each clip-space vertex (V, 4) into screen (V, 3).

    A vertex in the eye's plane (w = 0, such as the point of a plane's grid under an eye
    looking along the plane) maps to infinity, not an error: only vertices of triangles that
    were dropped or clipped can lie there, and those are never drawn.
    """
    for v in range(clip.shape[0]):
        screen_point(clip, v, width, height, orthographic, screen, v)


@njit(inline="always")
def screen_point(clip, row, width, height, orthographic, screen, screen_row):
    """Divide and map one clip-space vertex: ``screen[screen_row] = (x, y, key)``.

    The one formula of the viewport and of the depth key, shared by :func:`clip_to_screen`
    and by the methods that make vertices of their own (the painter's splits), so equal inputs
    give equal bits.
    """
    inv_w = 1.0 / clip[row, 3]
    screen[screen_row, 0] = (clip[row, 0] * inv_w + 1.0) * 0.5 * width
    screen[screen_row, 1] = (1.0 - clip[row, 1] * inv_w) * 0.5 * height
    key = ORTHO_KEY_AT_NDC_0 - 0.5 * clip[row, 2] * inv_w if orthographic else inv_w
    screen[screen_row, 2] = key


# The orthographic depth key is ORTHO_KEY_AT_NDC_0 - z_ndc / 2: 2 on the near plane
# (z_ndc = -1) and 1 on the far one, positive everywhere in the view volume, so "nothing drawn"
# stays key 0 as in perspective. It spends the doubles' resolution evenly over [near, far].
ORTHO_KEY_AT_NDC_0 = 1.5


@njit(inline="always")
def key_depth(key, orthographic, near, far):
    """Return the view-axis depth of a depth key (``inf`` for 0: nothing drawn).

    Conditional expressions on cheap values, not branches: the shading pass's row loop,
    which turns every pixel's key into its depth, stays vectorizable.
    """
    affine = 0.5 * ((far - near) * (2.0 * (ORTHO_KEY_AT_NDC_0 - key)) + (far + near))
    return (affine if orthographic else 1.0 / key) if key > 0.0 else np.inf


@njit(inline="always")
def _plane(xa, ya, va, xb, yb, vb, xc, yc, vc, inv_area2):
    """Coefficients (a, b, c) of the affine function through three screen points' values."""
    a = ((vb - va) * (yc - ya) - (vc - va) * (yb - ya)) * inv_area2
    b = ((vc - va) * (xb - xa) - (vb - va) * (xc - xa)) * inv_area2
    return a, b, va - a * xa - b * ya


@njit(inline="always")
def _store3(record, start, values):
    record[start] = values[0]
    record[start + 1] = values[1]
    record[start + 2] = values[2]


@njit(inline="always")
def _above(xa, ya, xb, yb):
    """Whether point a comes before point b in scan order (smaller y, then smaller x)."""
    return ya < yb or (ya == yb and xa < xb)


# A triangle thinner than this (twice its area, in square pixels) draws nothing, and an edge
# rising less than MIN_EDGE_RISE pixels counts as horizontal: their plane coefficients and
# slopes would overflow (a warning without the JIT, inf and NaN spans with it), for shapes that
# could hold a pixel centre only by exact coincidence. Every method shares this set-up, so they
# all agree on such triangles.
MIN_AREA2 = 1e-200
MIN_EDGE_RISE = 1e-200


@njit
def setup_triangles(screen, triangles, orthographic, row_first, row_stop, setup, rows):
    """Fill the set-up record (T, SETUP_FIELDS) and the covered rows [first, stop) (T, 2).

    Rows are image rows, clipped to the rendered region's rows [row_first, row_stop).
    ``screen`` (V, 3) holds (x, y, depth key); perspective keys are the vertices' 1/w, the
    weights of perspective-correct interpolation, while orthographic vertices all weigh 1.

    Serial on purpose: it costs well under a millisecond for 70k triangles, less than waking
    the worker threads for a parallel loop (only ``render_bands`` is worth that).
    """
    for t in range(triangles.shape[0]):
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        xa, ya, wa = screen[a, 0], screen[a, 1], screen[a, 2]
        xb, yb, wb = screen[b, 0], screen[b, 1], screen[b, 2]
        xc, yc, wc = screen[c, 0], screen[c, 1], screen[c, 2]
        area2 = (xb - xa) * (yc - ya) - (xc - xa) * (yb - ya)
        rows[t, 0] = 0
        rows[t, 1] = 0
        # Degenerate, non-finite, or too thin for its planes (MIN_AREA2): no pixel.
        if not (math.isfinite(area2) and abs(area2) >= MIN_AREA2):
            continue
        inv = 1.0 / area2
        record = setup[t]
        _store3(record, S1_PLANE, _plane(xa, ya, 0.0, xb, yb, 1.0, xc, yc, 0.0, inv))
        _store3(record, S2_PLANE, _plane(xa, ya, 0.0, xb, yb, 0.0, xc, yc, 1.0, inv))
        _store3(record, KEY_PLANE, _plane(xa, ya, wa, xb, yb, wb, xc, yc, wc, inv))
        _store3(record, VERTEX_INVW, (1.0, 1.0, 1.0) if orthographic else (wa, wb, wc))
        # Edge table: vertices sorted by y, ties by x, so every edge runs from its upper end.
        if _above(xb, yb, xa, ya):
            xa, ya, xb, yb = xb, yb, xa, ya
        if _above(xc, yc, xb, yb):
            xb, yb, xc, yc = xc, yc, xb, yb
            if _above(xb, yb, xa, ya):
                xa, ya, xb, yb = xb, yb, xa, ya
        _store3(record, SORTED_XY, (xa, ya, xb))
        _store3(record, SORTED_XY + 3, (yb, xc, yc))
        long_edge = _slope(xa, ya, xc, yc)
        _store3(record, SLOPES, (long_edge, _slope(xa, ya, xb, yb), _slope(xb, yb, xc, yc)))
        # Rows whose centre j + 0.5 lies in [y_top, y_bottom).
        first = max(math.ceil(ya - 0.5), float(row_first))
        stop = min(math.ceil(yc - 0.5), float(row_stop))
        if first < stop:
            rows[t, 0] = int(first)
            rows[t, 1] = int(stop)


@njit(inline="always")
def _slope(x_top, y_top, x_bottom, y_bottom):
    """Return dx/dy of an edge from its upper end to its lower end (0 when horizontal)."""
    if y_bottom - y_top < MIN_EDGE_RISE:
        return 0.0
    return (x_bottom - x_top) / (y_bottom - y_top)


@njit(inline="always")
def scanline_span(record, y, col_first, col_stop):
    """Pixel columns [first, stop) drawn by a set-up triangle on the scan line at height y.

    The active edge list on scan line y is the long edge (v0, v2) and whichever of (v0, v1),
    (v1, v2) spans y; a horizontal edge is never active. Columns are clipped to the rendered
    region's [col_first, col_stop).
    """
    x0, y0 = record[SORTED_XY], record[SORTED_XY + 1]
    x_long = x0 + (y - y0) * record[SLOPES]
    if y < record[SORTED_XY + 3]:
        x_short = x0 + (y - y0) * record[SLOPES + 1]
    else:
        x1, y1 = record[SORTED_XY + 2], record[SORTED_XY + 3]
        x_short = x1 + (y - y1) * record[SLOPES + 2]
    x_left = min(x_long, x_short)
    x_right = max(x_long, x_short)
    first = max(math.ceil(x_left - 0.5), float(col_first))
    stop = min(math.ceil(x_right - 0.5), float(col_stop))
    return int(first), int(stop)


# How much nearer (larger 1/w) one surface must be than another, relative to the size of the
# terms its value is computed from, before a method decides a whole span or area from its ends
# or corners (scan-line, Warnock). Rounding moves a computed 1/w by a few units in the last place
# of those terms (about 1e-16 of them); with a margin far above that, the surface found nearer
# at the ends is nearer, as the z-buffer computes it, at every pixel between them. Closer calls
# are settled pixel by pixel with the z-buffer's own test (:func:`wins_depth_test`).
NEARER_MARGIN = 1e-12


@njit(inline="always")
def clearly_nearer(value, other, scale):
    """Whether 1/w ``value`` beats ``other`` by more than rounding of terms of size ``scale``."""
    return value - other > NEARER_MARGIN * scale


@njit(inline="always")
def wins_depth_test(value, t, best_value, best_t):
    """Return whether triangle t, at 1/w ``value``, replaces the best: the z-buffer's test.

    Larger 1/w is nearer; a tie goes to the lower triangle index (the z-buffer visits triangles
    in ascending order and replaces only on strictly nearer). Start from (0.0, -1): nothing at
    1/w <= 0 is drawn, as in the z-buffer, whose buffer starts at 0.
    """
    return value > best_value or (value == best_value and t < best_t)


@njit(inline="always")
def perspective_weights(setup, t, x, y):
    """Perspective-correct barycentric weights (b0, b1, b2) of set-up triangle t at (x, y).

    The triangle is indexed in the table rather than handed over as a row of it: a row view
    would update the table's reference count at every pixel of a counted kernel.
    """
    s1 = setup[t, S1_PLANE] * x + setup[t, S1_PLANE + 1] * y + setup[t, S1_PLANE + 2]
    s2 = setup[t, S2_PLANE] * x + setup[t, S2_PLANE + 1] * y + setup[t, S2_PLANE + 2]
    t0 = (1.0 - s1 - s2) * setup[t, VERTEX_INVW]
    t1 = s1 * setup[t, VERTEX_INVW + 1]
    t2 = s2 * setup[t, VERTEX_INVW + 2]
    scale = 1.0 / (t0 + t1 + t2)
    return t0 * scale, t1 * scale, t2 * scale


def overlapping_pair():
    """Return the set-up records and rows of two triangles crossing each other on an 8x8 image.

    For the warm-ups of the methods that decide visibility from set-up triangles (scan-line,
    Warnock): real values, so their warm-ups run the kernels' main paths, not only compile them.
    """
    screen = np.array(
        [[1.0, 1.0, 0.5], [7.0, 2.0, 0.5], [3.0, 7.0, 0.5], [0.5, 4.0, 0.2], [7.5, 5.0, 0.9],
         [6.0, 0.5, 0.2]]
    )
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    setup = np.zeros((2, SETUP_FIELDS))
    rows = np.zeros((2, 2), dtype=np.intp)
    setup_triangles(screen, triangles, False, 0, 8, setup, rows)
    return setup, rows
