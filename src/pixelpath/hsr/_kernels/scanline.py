"""Compiled kernels of the polygon scan-line method (:mod:`pixelpath.hsr.scanline`).

The region is cut into bands of rows, scanned in parallel (threads take lists of bands: the
kernels release the GIL); each band runs the whole algorithm:

1. **Edge table.** Every triangle of the band gives its non-horizontal edges, as its set-up
   record lists them (:mod:`pixelpath.raster._setup_kernels`): the long edge (v0, v2) on every row
   the triangle covers, the upper short edge (v0, v1) on the rows whose centre lies above v1
   and the lower one (v1, v2) on the rest: the very rows on which ``scanline_span`` uses each.
   Edges are bucketed by the first row of the band they are active on, so an edge that began
   above the band enters at the band's first line.
2. **Active edge list (AEL).** Per scan line the edges whose rows ended leave, the line's
   bucket enters, every active edge's x is computed from its upper end exactly as
   ``scanline_span`` computes it, and the list is re-sorted by x with an insertion sort: the
   order changes little from one line to the next (edge coherence), so that is nearly linear.
3. **Walk.** The crossings are visited left to right; each toggles its triangle in or out of
   the set of triangles covering the pixels to its right. An edge crossing at x starts or ends
   coverage at column ``ceil(x - 0.5)`` (the top-left rule), so a triangle is "in" exactly on
   the columns ``scanline_span`` draws, and between two crossing columns the set is fixed: a
   span.
4. **Spans.** A span with one triangle needs no depth at all. With several, 1/w of each is
   affine along the line, so the triangle nearest at both end pixels is nearest throughout;
   when it is clearly so (by more than rounding could explain, ``NEARER_MARGIN``) the whole
   span is filled with it. If the ends disagree (the triangles interpenetrate) the span is
   split where the two nearest planes cross, and each part is resolved the same way; a part
   one pixel wide is decided by the z-buffer's test at that pixel, which is also where near
   ties (nearly coplanar overlaps) end up. The result is the z-buffer's, pixel for pixel.
5. **Holes.** An alpha-tested triangle (``Cutouts.masked``) covers its span only where its
   alpha test keeps it, which no end of the span can tell: a span it takes part in is
   decided pixel by pixel, each pixel by the z-buffer's test among the triangles in the
   list whose surface is not cut away there (:func:`_by_pixel`).
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._jit import njit
from pixelpath.hsr.scanline import LINE_COUNTS
from pixelpath.raster._scan_kernels import cut_away_at
from pixelpath.raster._setup_kernels import (
    KEY_PLANE,
    SLOPES,
    SORTED_XY,
    clearly_nearer,
    wins_depth_test,
)

# Columns of the per-scan-line counts (one row of ``counts`` per image row of the region).
ACTIVE, ENTERING, LEAVING, MOVES, CROSSINGS, SPANS, ONE_POLYGON, BY_DEPTH, SPLITS, PIXELS = range(
    len(LINE_COUNTS)
)

# Columns of the edge table: where an edge starts (x, y) and its dx/dy; its owner and rows.
EDGE_X, EDGE_Y, EDGE_SLOPE = 0, 1, 2
EDGE_OWNER, EDGE_FIRST, EDGE_STOP = 0, 1, 2


@njit
def scan_bands(bands, setup, rows, offsets, items, band_rows, x0, y0, inv_depth, triangle_id,
               counts, cutouts):
    """Decide the visible triangle of every pixel of the listed bands with the scan-line method.

    ``offsets``/``items`` bin the triangles per band (ascending); the buffers (h, w) cover image
    columns [x0, x0 + w) and rows [y0, y0 + h); every pixel of the bands is written (1/w 0 and
    triangle -1 where nothing is seen). ``counts`` (h, len(LINE_COUNTS)) receives what
    happened on each scan line. ``cutouts`` (the raster kernels' ``Cutouts``) marks the
    alpha-tested triangles. Bands are independent: callers run lists of them in parallel
    threads (the kernel releases the GIL).
    """
    height = inv_depth.shape[0]
    for band in bands:
        first = y0 + band * band_rows
        stop = min(first + band_rows, y0 + height)
        _scan_band(setup, rows, items[offsets[band] : offsets[band + 1]], first, stop, x0, y0,
                   inv_depth, triangle_id, counts, cutouts)


# Inlined by Numba into its one caller, the loop over bands (see pixelpath._jit).
@njit(inline="always")
def _scan_band(setup, rows, band_items, first_row, stop_row, x0, y0, inv_depth, triangle_id,
               counts, cutouts):
    """Scan rows [first_row, stop_row) with the band's triangles ``band_items``.

    Work arrays are plain arrays, allocated once per band and passed down as such (arrays
    taken out of a tuple inside a hot loop cost Numba a reference count each time).
    """
    width = inv_depth.shape[1]
    n = band_items.shape[0]
    floats, ints, entering = _edge_table(setup, rows, band_items, first_row, stop_row)
    count = floats.shape[0]
    # The AEL (row 0) and room to sort the edges entering it (rows 1 and 2): edges and x.
    edges = np.empty((3, count), dtype=np.intp)
    xs = np.empty((3, count))
    # The in-list: per place, the band index and triangle index of a triangle covering the
    # current span, and its 1/w along the line (slope, value at x = 0, value at a pixel);
    # where[k] is band triangle k's place (-1 when out).
    held = np.empty((n, 2), dtype=np.intp)
    planes = np.empty((n, 3))
    where = np.empty(n, dtype=np.intp)
    for k in range(n):
        where[k] = -1
    stack = np.empty((width + 1, 2), dtype=np.intp)  # spans [first, stop) still to resolve
    active = 0
    masked = cutouts.masked
    tested = False  # does the band hold an alpha-tested triangle?
    for k in range(n):
        if masked[band_items[k]]:
            tested = True
            break
    for j in range(first_row, stop_row):
        line = counts[j - y0]
        start, stop = entering[j - first_row], entering[j - first_row + 1]
        active = _next_line(floats, ints, start, stop, edges, xs, active, j, line)
        _walk(setup, band_items, ints, edges[0], xs[0], active, j + 0.5, x0, x0 + width,
              inv_depth[j - y0], triangle_id[j - y0], line, held, planes, where, stack, tested,
              masked, cutouts)


@njit(from_python=False)
def _edge_table(setup, rows, band_items, first_row, stop_row):
    """Return the band's edge table, sorted by first row, and where each row's edges start.

    Returns (m, 3) floats: start x, start y, dx/dy; (m, 3) ints: owner (the triangle's place
    in ``band_items``), rows [first, stop) clipped to the band; and (rows + 1,) offsets: the
    edges entering on row ``first_row + r`` are ``offsets[r]:offsets[r + 1]``. A short edge is
    used on rows whose centre lies above the middle vertex (upper edge) or not (lower edge),
    the comparison ``scanline_span`` makes.
    """
    n = band_items.shape[0]
    floats = np.empty((3 * n, 3))
    ints = np.empty((3 * n, 3), dtype=np.intp)
    count = 0
    for k in range(n):
        t = band_items[k]
        record = setup[t]
        first = max(rows[t, 0], first_row)
        stop = min(rows[t, 1], stop_row)
        if first >= stop:
            continue
        x_top, y_top = record[SORTED_XY], record[SORTED_XY + 1]
        x_mid, y_mid = record[SORTED_XY + 2], record[SORTED_XY + 3]
        middle = first
        while middle < stop and middle + 0.5 < y_mid:
            middle += 1
        count = _add_edge(floats, ints, count, k, x_top, y_top, record[SLOPES], first, stop)
        count = _add_edge(floats, ints, count, k, x_top, y_top, record[SLOPES + 1], first, middle)
        count = _add_edge(floats, ints, count, k, x_mid, y_mid, record[SLOPES + 2], middle, stop)
    # Bucket by first row: a counting sort.
    n_rows = stop_row - first_row
    offsets = np.zeros(n_rows + 1, dtype=np.intp)
    for e in range(count):
        offsets[ints[e, EDGE_FIRST] - first_row + 1] += 1
    for r in range(n_rows):
        offsets[r + 1] += offsets[r]
    sorted_floats = np.empty((count, 3))
    sorted_ints = np.empty((count, 3), dtype=np.intp)
    for e in range(count):
        r = ints[e, EDGE_FIRST] - first_row
        for column in range(3):
            sorted_floats[offsets[r], column] = floats[e, column]
            sorted_ints[offsets[r], column] = ints[e, column]
        offsets[r] += 1
    for r in range(n_rows, 0, -1):  # each offset now points past its bucket: shift back
        offsets[r] = offsets[r - 1]
    offsets[0] = 0
    return sorted_floats, sorted_ints, offsets


@njit(inline="always")
def _add_edge(floats, ints, count, owner, x, y, slope, first, stop):
    """Append an edge active on rows [first, stop) unless that is empty; return the count."""
    if first >= stop:
        return count
    floats[count, EDGE_X] = x
    floats[count, EDGE_Y] = y
    floats[count, EDGE_SLOPE] = slope
    ints[count, EDGE_OWNER] = owner
    ints[count, EDGE_FIRST] = first
    ints[count, EDGE_STOP] = stop
    return count + 1


@njit(inline="always")
def _edge_x(floats, e, y):
    """Return edge e's x on the scan line at height y, computed as ``scanline_span`` does."""
    return floats[e, EDGE_X] + (y - floats[e, EDGE_Y]) * floats[e, EDGE_SLOPE]


@njit(from_python=False)
def _next_line(floats, ints, start, stop, edges, xs, active, j, line):
    """Bring the AEL to scan line j: drop leaving edges, move the rest, add edges start..stop.

    The edges already active keep their order and move by their slope: an insertion sort puts
    right the few that crossed (edge coherence; ``line[MOVES]`` counts the places they moved).
    The entering edges are sorted among themselves and merged in. Returns the new length.
    """
    y = j + 0.5
    ael, ael_x = edges[0], xs[0]
    kept = 0
    for q in range(active):
        e = ael[q]
        if ints[e, EDGE_STOP] > j:
            ael[kept] = e
            ael_x[kept] = _edge_x(floats, e, y)
            kept += 1
    moves = 0
    for q in range(1, kept):
        e, x = ael[q], ael_x[q]
        p = q
        while p > 0 and ael_x[p - 1] > x:
            ael[p], ael_x[p] = ael[p - 1], ael_x[p - 1]
            p -= 1
        ael[p], ael_x[p] = e, x
        moves += q - p
    n = stop - start
    new, new_x = edges[1], xs[1]
    for b in range(n):
        new[b] = start + b
        new_x[b] = _edge_x(floats, start + b, y)
    _merge_sort(new, new_x, n, edges[2], xs[2])
    out, q = kept + n - 1, kept - 1
    for b in range(n - 1, -1, -1):  # merge from the back, in place
        while q >= 0 and ael_x[q] > new_x[b]:
            ael[out], ael_x[out] = ael[q], ael_x[q]
            q -= 1
            out -= 1
        ael[out], ael_x[out] = new[b], new_x[b]
        out -= 1
    line[ACTIVE] = kept + n
    line[ENTERING] = n
    line[LEAVING] = active - kept
    line[MOVES] = moves
    return kept + n


@njit(from_python=False)
def _merge_sort(edges, xs, n, scratch, scratch_x):
    """Sort the first n edges by x, in place (bottom-up merge sort: many edges enter at once)."""
    width = 1
    in_scratch = False
    while width < n:
        source, source_x = (scratch, scratch_x) if in_scratch else (edges, xs)
        target, target_x = (edges, xs) if in_scratch else (scratch, scratch_x)
        for low in range(0, n, 2 * width):
            middle, high = min(low + width, n), min(low + 2 * width, n)
            a, b = low, middle
            for out in range(low, high):
                if b >= high or (a < middle and source_x[a] <= source_x[b]):
                    target[out], target_x[out] = source[a], source_x[a]
                    a += 1
                else:
                    target[out], target_x[out] = source[b], source_x[b]
                    b += 1
        in_scratch = not in_scratch
        width *= 2
    if in_scratch:
        for q in range(n):
            edges[q], xs[q] = scratch[q], scratch_x[q]


@njit(refcount=False, from_python=False)
def _walk(setup, band_items, ints, ael, ael_x, active, y, col_first, col_stop, depth_row, id_row,
          line, held, planes, where, stack, tested, masked, cutouts):
    """Walk one scan line's crossings left to right, filling the span before each.

    Each crossing puts its triangle into the in-list (with its 1/w along the line) or takes
    it out (the last place moves into its place). While an alpha-tested triangle is in the
    list, spans are decided pixel by pixel (:func:`_by_pixel`); they are only counted when
    the band holds one (``tested``). Called per scan line with a score of arrays (the alpha
    test's record among them): compiled without reference counting, which would update each
    array's count atomically at every call.
    """
    inside = 0
    holes = 0  # alpha-tested triangles in the list
    current = col_first
    crossings = 0
    for q in range(active + 1):
        column = col_stop  # after the last crossing: the rest of the line
        if q < active:
            column = math.ceil(ael_x[q] - 0.5)
            if col_first <= column <= col_stop:
                crossings += 1
            column = min(max(column, col_first), col_stop)
        if column > current:
            if inside == 0:
                _fill(current, column, 0.0, 0.0, -1, col_first, depth_row, id_row)
            elif holes > 0:
                line[ONE_POLYGON if inside == 1 else BY_DEPTH] += 1
                line[PIXELS] += column - current
                _by_pixel(current, column, y, inside, col_first, depth_row, id_row, held, planes,
                          masked, cutouts)
            elif inside == 1:
                line[ONE_POLYGON] += 1
                _fill(current, column, planes[0, 0], planes[0, 1], held[0, 1], col_first,
                      depth_row, id_row)
            else:
                line[BY_DEPTH] += 1
                _by_depth(current, column, inside, col_first, depth_row, id_row, line, held,
                          planes, stack)
            current = column
        if q == active:
            break
        owner = ints[ael[q], EDGE_OWNER]
        place = where[owner]
        if place < 0:
            t = band_items[owner]
            where[owner] = inside
            held[inside, 0], held[inside, 1] = owner, t
            planes[inside, 0] = setup[t, KEY_PLANE]
            planes[inside, 1] = setup[t, KEY_PLANE + 1] * y + setup[t, KEY_PLANE + 2]
            inside += 1
            if tested:
                holes += 1 if masked[t] else 0
        else:
            inside -= 1
            if tested:
                holes -= 1 if masked[held[place, 1]] else 0
            where[owner] = -1
            if place != inside:
                where[held[inside, 0]] = place
                held[place, 0], held[place, 1] = held[inside, 0], held[inside, 1]
                planes[place, 0], planes[place, 1] = planes[inside, 0], planes[inside, 1]
    line[CROSSINGS] = crossings
    line[SPANS] = line[ONE_POLYGON] + line[BY_DEPTH]


@njit(from_python=False)
def _by_depth(first, stop, inside, col_first, depth_row, id_row, line, held, planes, stack):
    """Fill a span covered by several triangles, deciding it from 1/w at its ends.

    The triangle nearest at both end pixels fills the span when it is clearly nearest at both;
    otherwise the span is split where the two end winners' planes cross (or in the middle)
    and the parts go on the stack. A part one pixel wide takes the z-buffer's test there.
    """
    stack[0, 0], stack[0, 1] = first, stop
    pending = 1
    while pending > 0:
        pending -= 1
        left, right = stack[pending, 0], stack[pending, 1]
        reach = right - 0.5  # the largest |x| on the span: it bounds the rounding of 1/w
        at_left, clear = _winner(left + 0.5, reach, inside, held, planes)
        if right - left == 1:
            line[PIXELS] += 1
            _fill_place(left, right, at_left, col_first, depth_row, id_row, held, planes)
            continue
        at_right, clear_right = _winner(right - 0.5, reach, inside, held, planes)
        if at_left == at_right and clear and clear_right:
            _fill_place(left, right, at_left, col_first, depth_row, id_row, held, planes)
            continue
        line[SPLITS] += 1
        middle = (left + right) // 2
        if at_left >= 0 and at_right >= 0 and at_left != at_right:
            middle = _crossing_column(left, right, planes[at_left], planes[at_right])
        stack[pending, 0], stack[pending, 1] = middle, right
        stack[pending + 1, 0], stack[pending + 1, 1] = left, middle
        pending += 2


@njit(refcount=False, from_python=False)
def _by_pixel(first, stop, y, inside, col_first, depth_row, id_row, held, planes, masked,
              cutouts):
    """Fill columns [first, stop) pixel by pixel: the z-buffer's test among the kept surfaces.

    At each pixel centre, the triangle of the in-list that the z-buffer keeps, leaving out
    the alpha-tested ones whose surface is cut away there; the background where none is left.
    """
    for i in range(first, stop):
        x = i + 0.5
        best, best_value, best_triangle = -1, 0.0, -1
        for p in range(inside):
            value = planes[p, 0] * x + planes[p, 1]
            t = held[p, 1]
            if wins_depth_test(value, t, best_value, best_triangle) and not (
                masked[t] and cut_away_at(cutouts, t, x, y)
            ):
                best, best_value, best_triangle = p, value, t
        _fill_place(i, i + 1, best, col_first, depth_row, id_row, held, planes)


@njit(from_python=False)
def _winner(x, reach, inside, held, planes):
    """Return the in-list place the z-buffer keeps at x (-1: none), and if it wins clearly.

    Clearly: nearer than every other, and than nothing, by more than rounding could explain
    on a span whose largest |x| is ``reach``. Leaves each triangle's 1/w at x in planes[:, 2].
    """
    best, best_value, best_triangle = -1, 0.0, -1
    for p in range(inside):
        value = planes[p, 0] * x + planes[p, 1]
        planes[p, 2] = value
        if wins_depth_test(value, held[p, 1], best_value, best_triangle):
            best, best_value, best_triangle = p, value, held[p, 1]
    if best < 0:
        return best, False
    own = abs(planes[best, 0]) * reach + abs(planes[best, 1])
    clear = clearly_nearer(best_value, 0.0, own)
    for p in range(inside):
        scale = own + abs(planes[p, 0]) * reach + abs(planes[p, 1])
        if p != best and not clearly_nearer(best_value, planes[p, 2], scale):
            clear = False
    return best, clear


@njit(inline="always")
def _crossing_column(left, right, plane, other):
    """Column where [left, right) splits: where the two planes of 1/w along the line cross.

    Pixels whose centre lies before the crossing go left; kept inside (left, right) so that
    both parts are smaller (the middle if the planes are parallel).
    """
    crossing = (other[1] - plane[1]) / (plane[0] - other[0])
    if not math.isfinite(crossing):
        return (left + right) // 2
    crossing = min(max(crossing, left + 0.5), right - 0.5)
    return min(max(math.ceil(crossing - 0.5), left + 1), right - 1)


@njit(inline="always")
def _fill_place(first, stop, place, col_first, depth_row, id_row, held, planes):
    """Fill columns [first, stop) with in-list place ``place`` (-1: background)."""
    if place < 0:
        _fill(first, stop, 0.0, 0.0, -1, col_first, depth_row, id_row)
    else:
        _fill(first, stop, planes[place, 0], planes[place, 1], held[place, 1], col_first,
              depth_row, id_row)


@njit(inline="always")
def _fill(first, stop, slope, offset, t, col_first, depth_row, id_row):
    """Write triangle t's 1/w over image columns [first, stop) of a row (t = -1: background).

    1/w is computed as the z-buffer computes it, so depths agree to the bit; like the z-buffer,
    a pixel where 1/w is not positive shows nothing.
    """
    for i in range(first, stop):
        value = slope * (i + 0.5) + offset
        if value > 0.0:
            depth_row[i - col_first] = value
            id_row[i - col_first] = t
        else:
            depth_row[i - col_first] = 0.0
            id_row[i - col_first] = -1


def warmup() -> None:
    """Compile the scan-line kernel on two overlapping triangles."""
    from pixelpath.raster._scan_kernels import tiny_cutouts
    from pixelpath.raster._setup_kernels import overlapping_pair

    setup, rows = overlapping_pair()
    offsets = np.array([0, 2], dtype=np.intp)
    items = np.arange(2, dtype=np.intp)
    counts = np.zeros((8, len(LINE_COUNTS)), dtype=np.intp)
    cutouts = tiny_cutouts(setup, np.array([[0, 1, 2], [0, 1, 2]], dtype=np.intp))
    scan_bands(np.zeros(1, dtype=np.intp), setup, rows, offsets, items, 32, 0, 0,
               np.empty((8, 8)), np.empty((8, 8), dtype=np.int32), counts, cutouts)
