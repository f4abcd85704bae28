"""Compiled kernels of Warnock's area subdivision (:mod:`pixelpath.hsr.warnock`).

An *area* is a rectangle of pixels, columns [x0, x1) and rows [y0, y1) of the image (rows
``areas[a]``), and "triangle t covers pixel (i, j)" means exactly what the scan converter draws
(``scanline_span``, the top-left rule). Classifying a triangle against an area on those terms:

* **disjoint**: it covers no pixel of the area;
* **contained**: every pixel it covers lies in the area (its coverage's bounding box does);
* **surrounding**: it covers every pixel of the area;
* **intersecting**: anything else: it covers some of the area's pixels and some outside.

The exact bounding box of each triangle's coverage (:func:`coverage_boxes`) settles most
classifications at once; the rest scan the triangle's spans on the area's rows, stopping as
soon as the answer is known.

:func:`decide_level` takes one level of areas (threads take ranges of them: areas never
overlap), each with the triangles that were not disjoint from its parent, and decides each
area whole where the rules allow, writing its pixels; :func:`subdivide` makes the next level
from the rest.

An alpha-tested triangle (``Cutouts.masked``) covers only the pixels its alpha test keeps, which
no classification of its outline can tell: it is never taken as the surrounding polygon in
front (rule 3), and where it decides pixels (alone in an area, or nearest at a pixel) each
pixel's sample is tested.
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._scan_kernels import cut_away_at
from pixelpath.raster._setup_kernels import (
    KEY_PLANE,
    clearly_nearer,
    scanline_span,
    wins_depth_test,
)

# Classes of a triangle against an area.
DISJOINT, INTERSECTING, CONTAINED, SURROUNDING = 0, 1, 2, 3
# How an area was decided (the report's columns, in this order).
EMPTY, SINGLE, IN_FRONT, SUBDIVIDED, PIXEL = 0, 1, 2, 3, 4
DECISIONS = 5
NONE = np.intp(-1)  # no triangle: the background
CLIPPED, WHOLE = np.bool_(True), np.bool_(False)  # _fill_area: covered pixels only, or all
# Columns of a coverage box and of an area: the first and stop rows, then columns.
ROW_FIRST, ROW_STOP, COL_FIRST, COL_STOP = 0, 1, 2, 3


@njit
def coverage_boxes(setup, rows, col_first, col_stop, boxes, first, stop):
    """Write the bounding box (rows, then columns, [first, stop)) of triangles first..stop-1.

    The box of the pixels each covers inside the region's columns [col_first, col_stop); a
    triangle that covers none gets an empty box (all zeros).
    """
    for t in range(first, stop):
        row_first, row_stop, first, stop = 0, 0, 0, 0
        for j in range(rows[t, 0], rows[t, 1]):
            span_first, span_stop = scanline_span(setup[t], j + 0.5, col_first, col_stop)
            if span_first >= span_stop:
                continue
            if row_first == row_stop:  # the first row with a pixel
                row_first, first, stop = j, span_first, span_stop
            row_stop = j + 1
            first = min(first, span_first)
            stop = max(stop, span_stop)
        boxes[t, ROW_FIRST] = row_first
        boxes[t, ROW_STOP] = row_stop
        boxes[t, COL_FIRST] = first
        boxes[t, COL_STOP] = stop


@njit
def classify(record, box, area):
    """Classify a set-up triangle, with coverage box ``box``, against ``area``."""
    x0, y0, x1, y1 = area[COL_FIRST], area[ROW_FIRST], area[COL_STOP], area[ROW_STOP]
    if (box[ROW_STOP] <= y0 or box[ROW_FIRST] >= y1 or box[COL_STOP] <= x0
            or box[COL_FIRST] >= x1 or box[ROW_FIRST] >= box[ROW_STOP]):
        return DISJOINT
    if (box[ROW_FIRST] >= y0 and box[ROW_STOP] <= y1 and box[COL_FIRST] >= x0
            and box[COL_STOP] <= x1):
        return CONTAINED
    full = (box[ROW_FIRST] <= y0 and box[ROW_STOP] >= y1 and box[COL_FIRST] <= x0
            and box[COL_STOP] >= x1)
    covered = False
    for j in range(max(y0, box[ROW_FIRST]), min(y1, box[ROW_STOP])):
        first, stop = scanline_span(record, j + 0.5, x0, x1)
        if first < stop:
            covered = True
        if first != x0 or stop != x1:
            full = False
        if covered and not full:
            return INTERSECTING
    return SURROUNDING if full else DISJOINT


@njit(refcount=False)
def decide_level(areas, offsets, candidates, setup, boxes, x0, y0, inv_depth, triangle_id,
                 cutouts, kept, decisions, first, stop):
    """Decide areas first..stop-1 of one level, or mark them for subdivision.

    Areas never overlap, so callers run several ranges of a level in parallel threads (the
    kernel releases the GIL). Area a's candidates are ``candidates[offsets[a]:offsets[a + 1]]``
    (ascending triangle indices); ``kept`` receives, per candidate, whether it is not disjoint
    from the area (the next level's candidates) and ``decisions`` how each area was decided.
    Decided areas' pixels are written to the buffers (h, w), whose top-left pixel is image
    pixel (x0, y0). ``cutouts`` (the raster kernels' ``Cutouts``) marks the alpha-tested
    triangles.
    """
    for a in range(first, stop):
        decisions[a] = _decide_area(areas[a], offsets[a], offsets[a + 1], candidates, setup,
                                    boxes, x0, y0, inv_depth, triangle_id, kept, cutouts)


# Inlined by Numba into its one caller, the loop over a level's areas (see pixelpath._jit).
@njit(inline="always")
def _decide_area(area, lo, hi, candidates, setup, boxes, x0, y0, inv_depth, triangle_id, kept,
                 cutouts):
    """Classify an area's candidates and apply the first rule that decides it.

    No triangle left: background. One: draw it, clipped to the area (and to its alpha test).
    One pixel: the z-buffer's test at its centre, among the samples the alpha test keeps. A
    surrounding triangle that is not alpha-tested, nearer than every other over the whole
    area (compared at the corner pixel centres): fill the area with it. Otherwise: subdivide.

    This and the helpers it calls per area (:func:`_fill_area`, :func:`_nearest`) count no
    references (``njit(refcount=False)``): counted, every array handed down, the alpha
    test's record among them, had its count updated atomically at each call, per area, from
    both threads (Warnock's method was 30 % slower for it).
    """
    count, only, front, front_value = 0, NONE, NONE, 0.0
    corner_x, corner_y = area[COL_FIRST] + 0.5, area[ROW_FIRST] + 0.5
    masked = cutouts.masked
    for k in range(lo, hi):
        t = candidates[k]
        kind = classify(setup[t], boxes[t], area)
        kept[k] = kind != DISJOINT
        if kind == DISJOINT:
            continue
        count += 1
        only = t
        if kind == SURROUNDING and not masked[t]:  # one with holes hides nothing for sure
            value = _inv_w(setup[t], corner_x, corner_y)
            if wins_depth_test(value, t, front_value, front):
                front, front_value = t, value
    if count == 0:
        _fill_area(area, NONE, setup, boxes, x0, y0, inv_depth, triangle_id, WHOLE, cutouts)
        return EMPTY
    if count == 1:
        _fill_area(area, only, setup, boxes, x0, y0, inv_depth, triangle_id, CLIPPED, cutouts)
        return SINGLE
    if area[COL_STOP] - area[COL_FIRST] == 1 and area[ROW_STOP] - area[ROW_FIRST] == 1:
        nearest = _nearest(corner_x, corner_y, lo, hi, candidates, kept, setup, cutouts)
        _fill_area(area, nearest, setup, boxes, x0, y0, inv_depth, triangle_id, WHOLE, cutouts)
        return PIXEL
    if front >= 0 and _in_front(front, area, lo, hi, candidates, kept, setup):
        _fill_area(area, front, setup, boxes, x0, y0, inv_depth, triangle_id, WHOLE, cutouts)
        return IN_FRONT
    return SUBDIVIDED


@njit(inline="always")
def _inv_w(record, x, y):
    """1/w of a set-up triangle's plane at (x, y), computed as the z-buffer computes it."""
    return record[KEY_PLANE] * x + (record[KEY_PLANE + 1] * y + record[KEY_PLANE + 2])


@njit(refcount=False, from_python=False)
def _nearest(x, y, lo, hi, candidates, kept, setup, cutouts):
    """Return the kept candidate the z-buffer shows at (x, y), or -1.

    An alpha-tested candidate whose surface is cut away at (x, y) shows nothing there.
    """
    best, best_value = -1, 0.0
    masked = cutouts.masked
    for k in range(lo, hi):
        if kept[k]:
            t = candidates[k]
            value = _inv_w(setup[t], x, y)
            if wins_depth_test(value, t, best_value, best) and not (
                masked[t] and cut_away_at(cutouts, t, x, y)
            ):
                best, best_value = t, value
    return best


@njit(from_python=False)
def _in_front(front, area, lo, hi, candidates, kept, setup):
    """Whether triangle ``front``'s plane is clearly nearer than every other kept candidate's.

    And than nothing (1/w = 0), at all four corner pixel centres of the area: planes are affine,
    so it is then nearer at every pixel centre between them, by more than rounding could
    explain (``clearly_nearer``, with the size of the terms at the area's far corner).
    """
    reach_x, reach_y = area[COL_STOP] - 0.5, area[ROW_STOP] - 0.5
    own = _size(setup[front], reach_x, reach_y)
    for corner in range(4):
        x = area[COL_FIRST] + 0.5 if corner % 2 == 0 else reach_x
        y = area[ROW_FIRST] + 0.5 if corner < 2 else reach_y
        value = _inv_w(setup[front], x, y)
        if not clearly_nearer(value, 0.0, own):
            return False
        for k in range(lo, hi):
            t = candidates[k]
            if kept[k] and t != front:
                scale = own + _size(setup[t], reach_x, reach_y)
                if not clearly_nearer(value, _inv_w(setup[t], x, y), scale):
                    return False
    return True


@njit(inline="always")
def _size(record, reach_x, reach_y):
    """Size of the terms of a plane's 1/w up to |x| = reach_x, |y| = reach_y (rounding scale)."""
    return (abs(record[KEY_PLANE]) * reach_x + abs(record[KEY_PLANE + 1]) * reach_y
            + abs(record[KEY_PLANE + 2]))


@njit(refcount=False, from_python=False)
def _fill_area(area, t, setup, boxes, x0, y0, inv_depth, triangle_id, clipped, cutouts):
    """Write triangle t (-1: background) over the area: its covered pixels only if ``clipped``.

    1/w is computed as the z-buffer computes it; a pixel where it is not positive shows
    nothing, as in the z-buffer, nor does one where an alpha-tested t is cut away.
    """
    col_first, col_stop = area[COL_FIRST], area[COL_STOP]
    tested = t >= 0 and cutouts.masked[t]
    for j in range(area[ROW_FIRST], area[ROW_STOP]):
        first, stop = col_first, col_stop
        if clipped:
            first, stop = col_first, col_first
            if boxes[t, ROW_FIRST] <= j < boxes[t, ROW_STOP]:  # spans exist on its rows only
                first, stop = scanline_span(setup[t], j + 0.5, col_first, col_stop)
        depth_row, id_row = inv_depth[j - y0], triangle_id[j - y0]
        for i in range(col_first, col_stop):
            value = 0.0
            if t >= 0 and first <= i < stop:
                value = _inv_w(setup[t], i + 0.5, j + 0.5)
                if tested and cut_away_at(cutouts, t, i + 0.5, j + 0.5):
                    value = 0.0
            if value > 0.0:
                depth_row[i - x0] = value
                id_row[i - x0] = t
            else:
                depth_row[i - x0] = 0.0
                id_row[i - x0] = -1


@njit
def subdivide(areas, offsets, candidates, kept, decisions):
    """Return the next level: the four quarters of each subdivided area, with its kept triangles.

    An area is halved across each side longer than one pixel (the first half takes the odd
    pixel), so it has two or four parts. Returns areas (m, 4), offsets (m + 1,), candidates.
    """
    n_areas, n_candidates = 0, 0
    for a in range(areas.shape[0]):
        if decisions[a] == SUBDIVIDED:
            parts = _parts(areas[a])
            n_areas += parts
            for k in range(offsets[a], offsets[a + 1]):
                if kept[k]:
                    n_candidates += parts
    children = np.empty((n_areas, 4), dtype=np.intp)
    child_offsets = np.empty(n_areas + 1, dtype=np.intp)
    child_candidates = np.empty(n_candidates, dtype=np.intp)
    child_offsets[0] = 0
    c, filled = 0, 0
    for a in range(areas.shape[0]):
        if decisions[a] != SUBDIVIDED:
            continue
        x0, y0, x1, y1 = areas[a, COL_FIRST], areas[a, ROW_FIRST], areas[a, COL_STOP], areas[
            a, ROW_STOP]
        x_mid = x0 + (x1 - x0 + 1) // 2 if x1 - x0 > 1 else x1
        y_mid = y0 + (y1 - y0 + 1) // 2 if y1 - y0 > 1 else y1
        for part in range(4):
            left, right = (x0, x_mid) if part % 2 == 0 else (x_mid, x1)
            top, bottom = (y0, y_mid) if part < 2 else (y_mid, y1)
            if left == right or top == bottom:
                continue
            children[c, ROW_FIRST], children[c, ROW_STOP] = top, bottom
            children[c, COL_FIRST], children[c, COL_STOP] = left, right
            for k in range(offsets[a], offsets[a + 1]):
                if kept[k]:
                    child_candidates[filled] = candidates[k]
                    filled += 1
            c += 1
            child_offsets[c] = filled
    return children, child_offsets, child_candidates


@njit(inline="always")
def _parts(area):
    """How many parts an area splits into: 2 per side longer than one pixel, multiplied."""
    across = 2 if area[COL_STOP] - area[COL_FIRST] > 1 else 1
    down = 2 if area[ROW_STOP] - area[ROW_FIRST] > 1 else 1
    return across * down


@njit
def mark_areas(areas, decisions, level, x0, y0, level_map, decision_map):
    """Write, over every decided area's pixels, the level and the way it was decided."""
    for a in range(areas.shape[0]):
        if decisions[a] == SUBDIVIDED:
            continue
        for j in range(areas[a, ROW_FIRST], areas[a, ROW_STOP]):
            for i in range(areas[a, COL_FIRST], areas[a, COL_STOP]):
                level_map[j - y0, i - x0] = level
                decision_map[j - y0, i - x0] = decisions[a]


def warmup() -> None:
    """Compile the subdivision kernels on two overlapping triangles."""
    from pixelpath.raster._scan_kernels import tiny_cutouts
    from pixelpath.raster._setup_kernels import overlapping_pair

    setup, rows = overlapping_pair()
    cutouts = tiny_cutouts(setup, np.array([[0, 1, 2], [0, 1, 2]], dtype=np.intp))
    boxes = np.zeros((2, 4), dtype=np.intp)
    coverage_boxes(setup, rows, 0, 8, boxes, 0, 2)
    areas = np.array([[0, 8, 0, 8]], dtype=np.intp)
    offsets = np.array([0, 2], dtype=np.intp)
    candidates = np.arange(2, dtype=np.intp)
    inv_depth, triangle_id = np.empty((8, 8)), np.empty((8, 8), dtype=np.int32)
    while areas.shape[0]:
        kept = np.empty(candidates.shape[0], dtype=np.bool_)
        decisions = np.empty(areas.shape[0], dtype=np.int8)
        decide_level(areas, offsets, candidates, setup, boxes, 0, 0, inv_depth, triangle_id,
                     cutouts, kept, decisions, 0, areas.shape[0])
        mark_areas(areas, decisions, 0, 0, 0, np.empty((8, 8), dtype=np.int8),
                   np.empty((8, 8), dtype=np.int8))
        areas, offsets, candidates = subdivide(areas, offsets, candidates, kept, decisions)
