"""Compiled Sutherland-Hodgman kernels: one stage, one polygon, many polygons.

A window reaches the kernels as a *boundary table*, a ``(K, 5)`` float64 array with one row per
boundary in clipping order: ``[kind, p0, p1, p2, p3]``. Kinds ``LEFT``, ``RIGHT``, ``BOTTOM`` and
``TOP`` keep their line's coordinate in ``p0`` (the notes' rectangle); kind ``EDGE`` is a window
edge from ``(p0, p1)`` to ``(p2, p3)`` directed so that the inside is on its left. One array
argument keeps the call from Python cheap (the single-clip latency is mostly dispatch).

The same stage generalizes beyond the plane: kind ``PLANE`` is the half-space
``p0·v0 + p1·v1 + p2·v2 + p3·v3 >= 0`` over the first four numbers of each vertex row, and the
rest of a row are attributes carried along. The raster pipeline clips triangles against the view
frustum this way, in homogeneous clip space (x, y, z, w), where the near plane is ``z + w >= 0``:
nothing in the notes' walk — S starting as the last vertex, the four in/out cases — depends on
the boundary being a line. For ``PLANE`` the crossing is computed from the inside end of the edge
towards the outside end, so two triangles sharing an edge get bit-identical points (clipped
meshes stay watertight); the 2-D kinds use the notes' formulas of section 6, from S to E.

Polygons travel as contiguous ``(n, 2)`` float64 arrays; many polygons as one flat coordinate
buffer plus an ``offsets`` array (polygon ``i`` is ``coords[offsets[i]:offsets[i + 1]]``).
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import inlined, njit

LEFT, RIGHT, BOTTOM, TOP, EDGE, PLANE = 0, 1, 2, 3, 4, 5

OK, NON_FINITE, TOO_FEW_VERTICES, TOO_LARGE = 0, 1, 2, 3

# The largest coordinate magnitude the floating-point kernels take. The slanted-edge tests and
# crossings multiply two coordinate differences and subtract such products: with every
# coordinate within ±1e150 no intermediate exceeds 16·1e300, far below the float64 maximum
# (1.8e308), so nothing overflows. (Rectangle bounds are only compared, and a crossing of one
# lies between the edge's two vertices, so they need no limit.)
LARGEST_COORDINATE = 1e150

WHOLLY_OUTSIDE, WHOLLY_INSIDE, STRADDLES = -1, 1, 0

# Relative distance under which a computed vertex counts as lying on a slanted window edge
# (rectangle boundaries are exact: the notes' formulas put x = xmin exactly).
ON_EDGE_RTOL = 1e-9


@inlined
def inside(row, x, y):
    kind = row[0]
    if kind == LEFT:
        return x >= row[1]
    if kind == RIGHT:
        return x <= row[1]
    if kind == BOTTOM:
        return y >= row[1]
    if kind == TOP:
        return y <= row[1]
    return (row[3] - row[1]) * (y - row[2]) - (row[4] - row[2]) * (x - row[1]) >= 0.0


@inlined
def _between(value, a, b):
    # Rounding can push an interpolated coordinate an ulp past the segment's end; keeping it
    # between the ends keeps earlier boundaries satisfied, so clipping again changes nothing.
    return min(max(value, min(a, b)), max(a, b))


@inlined
def intersection(row, x1, y1, x2, y2):
    """Where the edge S=(x1, y1) -> E=(x2, y2) crosses the boundary (notes, section 6)."""
    kind = row[0]
    if kind == LEFT or kind == RIGHT:
        x = row[1]
        return x, _between(y1 + (y2 - y1) * (x - x1) / (x2 - x1), y1, y2)
    if kind == BOTTOM or kind == TOP:
        y = row[1]
        return _between(x1 + (x2 - x1) * (y - y1) / (y2 - y1), x1, x2), y
    # Parametric form: P = S + t (E - S) with t = dS / (dS - dE), d the signed side value.
    ex, ey = row[3] - row[1], row[4] - row[2]
    d_s = ex * (y1 - row[2]) - ey * (x1 - row[1])
    d_e = ex * (y2 - row[2]) - ey * (x2 - row[1])
    t = d_s / (d_s - d_e)
    return _between(x1 + t * (x2 - x1), x1, x2), _between(y1 + t * (y2 - y1), y1, y2)


@inlined
def plane_value(row, v):
    """Signed value of a ``PLANE`` boundary at vertex row ``v``; inside when >= 0."""
    return row[1] * v[0] + row[2] * v[1] + row[3] * v[2] + row[4] * v[3]


@inlined
def vertex_inside(row, v):
    if row[0] == PLANE:
        return plane_value(row, v) >= 0.0
    return inside(row, v[0], v[1])


@inlined
def _same_rows(a, i, b, j):
    for c in range(a.shape[1]):
        if a[i, c] != b[j, c]:
            return False
    return True


@inlined
def _crossing(row, s, e, out):
    """Write where edge S -> E crosses the boundary into the row ``out``."""
    if row[0] == PLANE:
        d_s, d_e = plane_value(row, s), plane_value(row, e)
        inner, outer, d_in, d_out = (s, e, d_s, d_e) if d_s >= 0.0 else (e, s, d_e, d_s)
        t = d_in / (d_in - d_out)
        for c in range(out.shape[0]):
            out[c] = inner[c] + t * (outer[c] - inner[c])
    else:
        out[0], out[1] = intersection(row, s[0], s[1], e[0], e[1])


@njit
def clip_stage(src, n, row, dst, crossings):
    """Clip ``src[:n]`` against one boundary into ``dst``; return the output count.

    ``src`` and ``dst`` have rows of the same width (2 for the plane, 4 or more for ``PLANE``
    boundaries); ``dst`` needs room for ``n + n // 2 + 1`` rows. A vertex that repeats the
    previous one is not emitted. When ``crossings`` has ``n`` rows it records, per (S, E) pair,
    the intersection point emitted (NaN when none) for the trace.
    """
    if n == 0:
        return 0
    record = crossings.shape[0] == n
    m = 0
    s = src[n - 1]  # S starts as the last vertex
    s_in = vertex_inside(row, s)
    for i in range(n):
        e = src[i]
        e_in = vertex_inside(row, e)
        if record:
            crossings[i, 0], crossings[i, 1] = np.nan, np.nan
        if s_in != e_in:  # the edge crosses: emit the intersection first
            _crossing(row, s, e, dst[m])
            if record:
                crossings[i, 0], crossings[i, 1] = dst[m, 0], dst[m, 1]
            if m == 0 or not _same_rows(dst, m, dst, m - 1):
                m += 1
        if e_in and (m == 0 or not _same_rows(src, i, dst, m - 1)):
            for c in range(dst.shape[1]):  # element by element: no shape-error code to compile
                dst[m, c] = e[c]
            m += 1
        s, s_in = e, e_in
    if m > 1 and _same_rows(dst, m - 1, dst, 0):
        m -= 1  # the list is cyclic: its last vertex must not repeat the first
    return m


@njit
def check_subject(xy):
    """Return ``OK``, ``NON_FINITE``, ``TOO_LARGE`` or ``TOO_FEW_VERTICES`` (< 3 distinct)."""
    n = xy.shape[0]
    for i in range(n):
        x, y = xy[i, 0], xy[i, 1]
        if not (np.isfinite(x) and np.isfinite(y)):
            return NON_FINITE
        if abs(x) > LARGEST_COORDINATE or abs(y) > LARGEST_COORDINATE:
            return TOO_LARGE
    second = -1
    for i in range(1, n):
        if xy[i, 0] != xy[0, 0] or xy[i, 1] != xy[0, 1]:
            if second < 0:
                second = i
            elif xy[i, 0] != xy[second, 0] or xy[i, 1] != xy[second, 1]:
                return OK
    return TOO_FEW_VERTICES


@njit(from_python=False)
def _run_stages(xy, table, a, b):
    """Clip ``xy`` through every boundary, ping-ponging between scratch buffers ``a``, ``b``.

    Returns ``(count, a, b)``; the result is ``b[:count]``. A buffer that could overflow is
    replaced by a larger one, so callers keep the returned pair for their next polygon.

    Shortcut, exact for the notes' rectangle: a stage whose boundary has the whole bounding box
    inside would return its input unchanged (when no vertex repeats its predecessor, and stage
    outputs never do), so it is skipped; one with the box wholly outside leaves nothing.
    """
    n = xy.shape[0]
    box = _bounds(xy)
    untraced = np.empty((0, 2))  # no room to record crossings: the stages keep no trace
    fresh = True  # the current polygon is still xy itself
    for k in range(table.shape[0]):
        row = table[k]
        side = _box_side(row, box)
        if side == WHOLLY_OUTSIDE:
            return 0, a, b
        if side == WHOLLY_INSIDE and not box[4]:
            continue
        need = n + n // 2 + 1  # a stage emits at most 3 vertices per 2 input vertices
        if a.shape[0] < need:
            a = np.empty((2 * need, 2))
        if fresh:
            n = clip_stage(xy, n, row, a, untraced)
        else:
            n = clip_stage(b, n, row, a, untraced)
        a, b = b, a  # this stage's output is the next stage's input
        fresh = False
        if n == 0:
            break
    if fresh:
        if b.shape[0] < n:
            b = np.empty((2 * n, 2))
        b[:n] = xy
    return n, a, b


@inlined
def _box_side(row, box):
    """Where a bounding box lies for a rectangle boundary (``STRADDLES`` for slanted edges)."""
    if row[0] == EDGE:
        return STRADDLES
    lo_in, hi_in = inside(row, box[0], box[1]), inside(row, box[2], box[3])
    if lo_in and hi_in:
        return WHOLLY_INSIDE
    return STRADDLES if lo_in or hi_in else WHOLLY_OUTSIDE


@inlined
def _shortcut(xy, table):
    """``WHOLLY_OUTSIDE`` (nothing left), ``WHOLLY_INSIDE`` (unchanged) or ``STRADDLES``."""
    box = _bounds(xy)
    unchanged = not box[4]
    for k in range(table.shape[0]):
        side = _box_side(table[k], box)
        if side == WHOLLY_OUTSIDE:
            return WHOLLY_OUTSIDE
        unchanged = unchanged and side == WHOLLY_INSIDE
    return WHOLLY_INSIDE if unchanged else STRADDLES


@inlined
def _bounds(xy):
    """Bounding box of ``xy`` and whether a vertex repeats its predecessor (cyclically)."""
    n = xy.shape[0]
    xmin, ymin = xy[0, 0], xy[0, 1]
    xmax, ymax = xmin, ymin
    repeats = xy[n - 1, 0] == xy[0, 0] and xy[n - 1, 1] == xy[0, 1]
    for i in range(1, n):
        x, y = xy[i, 0], xy[i, 1]
        xmin, xmax = min(xmin, x), max(xmax, x)
        ymin, ymax = min(ymin, y), max(ymax, y)
        repeats = repeats or (x == xy[i - 1, 0] and y == xy[i - 1, 1])
    return xmin, ymin, xmax, ymax, repeats


@njit(from_python=False)
def _scan_bridges(poly, m, table, out):
    """Count the zero-width bridges of ``poly[:m]``; write them into ``out`` if it has room.

    A bridge is a stretch of a window boundary that the polygon runs along twice, in opposite
    directions: Sutherland-Hodgman's way of joining pieces of a concave subject.
    """
    count = 0
    spans = np.empty((m, 2))  # the polygon's edges lying on one boundary, as positions along it
    for k in range(table.shape[0]):
        row = table[k]
        # Along a slanted edge (positions in units of its length) a rounding-sized overlap is
        # no bridge: clipping a clipped polygon again can wiggle a vertex by an ulp.
        shortest = ON_EDGE_RTOL if row[0] == EDGE else 0.0
        found = 0
        for i in range(m):
            t0, t1, on = _edge_on_boundary(poly, m, i, row)
            if on:
                spans[found, 0], spans[found, 1] = t0, t1
                found += 1
        for i in range(found):
            t0, t1 = spans[i, 0], spans[i, 1]
            for j in range(i + 1, found):
                u0, u1 = spans[j, 0], spans[j, 1]
                if (t1 > t0) == (u1 > u0):
                    continue  # same direction: no doubling back
                lo = max(min(t0, t1), min(u0, u1))
                hi = min(max(t0, t1), max(u0, u1))
                if hi - lo > shortest:
                    if count < out.shape[0]:
                        _boundary_point(row, lo, out[count, 0])
                        _boundary_point(row, hi, out[count, 1])
                    count += 1
    return count


@inlined
def _boundary_coordinate(row, x, y):
    """Return (position along the boundary, whether (x, y) lies on its line)."""
    kind = row[0]
    if kind == LEFT or kind == RIGHT:
        return y, x == row[1]
    if kind == BOTTOM or kind == TOP:
        return x, y == row[1]
    ex, ey = row[3] - row[1], row[4] - row[2]
    length2 = ex * ex + ey * ey
    side = ex * (y - row[2]) - ey * (x - row[1])
    scale = abs(row[1]) + abs(row[2]) + np.sqrt(length2)  # relative: no floor for tiny windows
    t = (ex * (x - row[1]) + ey * (y - row[2])) / length2
    return t, abs(side) <= ON_EDGE_RTOL * scale * np.sqrt(length2)


@inlined
def _edge_on_boundary(poly, m, i, row):
    j = (i + 1) % m
    t0, on0 = _boundary_coordinate(row, poly[i, 0], poly[i, 1])
    t1, on1 = _boundary_coordinate(row, poly[j, 0], poly[j, 1])
    return t0, t1, on0 and on1 and t0 != t1


@inlined
def _boundary_point(row, t, point):
    kind = row[0]
    if kind == LEFT or kind == RIGHT:
        point[0], point[1] = row[1], t
    elif kind == BOTTOM or kind == TOP:
        point[0], point[1] = t, row[1]
    else:
        point[0] = row[1] + t * (row[3] - row[1])
        point[1] = row[2] + t * (row[4] - row[2])


@njit
def sutherland_hodgman(xy, table):
    """Clip one polygon; return ``(result, status, bridge_count)``.

    ``result`` is ``(M, 2)``, empty when fewer than 3 vertices are left.
    """
    status = check_subject(xy)
    if status != OK:
        return np.empty((0, 2)), status, 0
    n = xy.shape[0]
    m, _, res = _run_stages(xy, table, np.empty((2 * n + 2, 2)), np.empty((2 * n + 2, 2)))
    if m < 3:
        return np.empty((0, 2)), OK, 0
    return res[:m].copy(), OK, _scan_bridges(res, m, table, np.empty((0, 2, 2)))


@njit
def bridges(poly, table):
    """Return the zero-width bridges of a clipped polygon as a ``(B, 2, 2)`` array."""
    m = poly.shape[0]
    out = np.empty((_scan_bridges(poly, m, table, np.empty((0, 2, 2))), 2, 2))
    _scan_bridges(poly, m, table, out)
    return out


@njit
def trace_stage(src, row):
    """One traced stage: ``(output, inside flags of src, crossing point per (S, E) pair)``."""
    n = src.shape[0]
    flags = np.empty(n, dtype=np.bool_)
    for i in range(n):
        flags[i] = inside(row, src[i, 0], src[i, 1])
    dst = np.empty((n + n // 2 + 1, 2))
    crossings = np.empty((n, 2))
    m = clip_stage(src, n, row, dst, crossings) if n > 0 else 0
    return dst[:m].copy(), flags, crossings


# A batch of polygons (clip.batch.clip_flat) is clipped in three passes, each a serial kernel
# over a range of polygons that several threads run on disjoint ranges (a parallel=True kernel
# took five times as long to compile); the prefix sums between passes are NumPy's.


@njit
def sort_subjects(coords, offsets, table, start, stop, status, fate):
    """Pass 1, polygons start..stop-1: check each and sort it by its bounding box.

    ``status[i]`` gets :func:`check_subject`'s verdict; ``fate[i]`` whether the polygon lies
    wholly outside a boundary (nothing left; also for a bad polygon), wholly inside every
    boundary (unchanged) or is to be clipped (``STRADDLES``).
    """
    for i in range(start, stop):
        xy = coords[offsets[i] : offsets[i + 1]]
        status[i] = check_subject(xy)
        fate[i] = _shortcut(xy, table) if status[i] == OK else WHOLLY_OUTSIDE


@njit
def clip_straddling(coords, offsets, table, fate, slot, start, stop, staging, sizes):
    """Pass 2, polygons start..stop-1: clip those that straddle a boundary; note every size.

    A result goes into its staging rows ``slot[i]:slot[i + 1]`` when it fits (a subject
    crossing the boundaries many times may not: pass 3 clips it again where it belongs).
    """
    a = np.empty((256, 2))
    b = np.empty((256, 2))
    for i in range(start, stop):
        if fate[i] == WHOLLY_INSIDE:
            sizes[i] = offsets[i + 1] - offsets[i]
        elif fate[i] == STRADDLES:
            m, a, b = _run_stages(coords[offsets[i] : offsets[i + 1]], table, a, b)
            sizes[i] = m if m >= 3 else 0
            if 3 <= m <= slot[i + 1] - slot[i]:
                staging[slot[i] : slot[i] + m] = b[:m]
        else:
            sizes[i] = 0


@njit
def pack_clipped(coords, offsets, table, fate, slot, staging, sizes, out_offsets, start, stop,
                 out):
    """Pass 3, polygons start..stop-1: copy each result to its final place ``out_offsets[i]``."""
    for i in range(start, stop):
        m, first = sizes[i], out_offsets[i]
        if fate[i] == WHOLLY_INSIDE:
            out[first : first + m] = coords[offsets[i] : offsets[i + 1]]
        elif m > slot[i + 1] - slot[i]:
            xy = coords[offsets[i] : offsets[i + 1]]
            scratch = 2 * xy.shape[0] + 2
            m, _, res = _run_stages(xy, table, np.empty((scratch, 2)), np.empty((scratch, 2)))
            out[first : first + m] = res[:m]
        elif m > 0:
            out[first : first + m] = staging[slot[i] : slot[i] + m]


def warmup() -> None:
    """Compile every clipping kernel on a tiny input."""
    square = np.array([[1.0, 1.0], [9.0, 1.0], [9.0, 7.0], [1.0, 7.0]])
    rect = np.array([[LEFT, 2.0, 0, 0, 0], [RIGHT, 8.0, 0, 0, 0], [BOTTOM, 2.0, 0, 0, 0],
                     [TOP, 6.0, 0, 0, 0]])
    sutherland_hodgman(square, rect)
    trace_stage(square, rect[0])
    bridges(square, rect)
    offsets = np.array([0, 4], dtype=np.intp)
    status = np.zeros(1, dtype=np.intp)
    fate = np.empty(1, dtype=np.intp)
    sort_subjects(square, offsets, rect, 0, 1, status, fate)
    slot = np.array([0, 8], dtype=np.intp)
    sizes = np.zeros(1, dtype=np.intp)
    staging = np.empty((8, 2))
    clip_straddling(square, offsets, rect, fate, slot, 0, 1, staging, sizes)
    pack_clipped(square, offsets, rect, fate, slot, staging, sizes, offsets, 0, 1,
                 np.empty((4, 2)))
