"""Compiled kernels of the octree method: build the tree, find each cell's footprint, traverse.

The tree (:class:`Tree`) is a cube cut into eight equal children, recursively. A triangle is
stored in every leaf its (slightly padded) bounding box overlaps, so a point of a triangle
always lies in a leaf that holds the triangle. Cells are closed boxes: a point on a face
shared by two cells belongs to both.

Child octants are numbered by three bits: bit 0 set for the upper half in x, bit 1 in y,
bit 2 in z. Seen from the eye, whose own octant relative to the node's centre is ``e``, child
``e ^ s`` lies across the splitting planes whose bits are set in ``s``. A ray from the eye
crosses each plane at most once, away from the eye's side, so along any ray the set of planes
crossed only grows: listing the children by how many planes separate them from the eye's
child (``FRONT_TO_BACK``) lists every ray's cells in the order the ray meets them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._scan_kernels import BAND_ROWS, cut_away_at, tiny_cutouts
from pixelpath.raster._setup_kernels import (
    KEY_PLANE,
    SETUP_FIELDS,
    _grown,
    _grown_rows,
    _outcode,
    perspective_weights,
    scanline_span,
)

# The children of a node, front to back, as the planes crossed from the eye's own child:
# none; one (x, y or z); two; all three. Child octant k of the order is eye_octant ^ entry k.
FRONT_TO_BACK = np.array([0, 1, 2, 4, 3, 5, 6, 7], dtype=np.intp)

TILE = 8  # side in pixels of the tiles whose undecided pixels are counted
FOOTPRINT_PAD = 1e-3  # pixels added around a cell's projected box, against rounding

# Columns of the per-level statistics (one row per tree level).
VISITED = 0  # nodes entered
CULLED = 1  # outside the view frustum (of the rendered region)
OTHER_BAND = 2  # inside it, but not over the rows of the band being traversed
SKIPPED = 3  # every pixel of the footprint already decided
DECIDED = 4  # pixels decided in a leaf of this level
DRAWN = 5  # triangles scan-converted in leaves of this level
TESTED = 6  # pixel samples depth-tested in leaves of this level
STAT_COLUMNS = 7

# What a band's traversal did with a node (recorded for the figures when explaining).
OUTCOME_CULLED = 1  # outside the view frustum or the region
OUTCOME_SKIPPED = 2  # every pixel of its footprint already decided: skipped with its subtree
OUTCOME_ENTERED = 3  # an inner node entered: its children were taken front to back
OUTCOME_DRAWN = 4  # a leaf whose triangles were scan-converted


# Columns of a node's cell (float64) and of its links (intp).
SIDE = 3  # cells: x, y, z of the minimum corner, then the side of the cube
LEVEL = 0  # links: level (0 for the root), leaf flag, range of its triangles in ``items``,
LEAF = 1  # then the child node of each octant (-1 where there is none)
START = 2
STOP = 3
CHILD = 4
LINK_FIELDS = 12


class Tree(NamedTuple):
    """An octree over triangles, nodes in breadth-first order (children after their parent)."""

    cells: np.ndarray  # (N, 4) float64 minimum corner and side of each cubic cell
    links: np.ndarray  # (N, LINK_FIELDS) intp level, leaf flag, item range, children
    items: np.ndarray  # (R,) intp triangles of the leaves, ascending within each leaf


@njit
def triangle_boxes(positions, screen, triangles, rows, col_first, col_stop, bounds, rects):
    """Each triangle's world box and screen box; return the triangles covering the region.

    ``bounds`` (T, 6) receives min x, y, z then max x, y, z of the world positions; ``rects``
    (T, 4) x min, x max, y min, y max in pixels. A triangle may cover a pixel of the region
    when it covers one of its rows (``rows``, already cut to the region) and its x extent
    meets columns [col_first, col_stop).
    """
    covering = np.empty(triangles.shape[0], dtype=np.intp)
    count = 0
    for t in range(triangles.shape[0]):
        for axis in range(3):
            low, high = np.inf, -np.inf
            for corner in range(3):
                value = positions[triangles[t, corner], axis]
                low, high = min(low, value), max(high, value)
            bounds[t, axis], bounds[t, 3 + axis] = low, high
        for axis in range(2):
            low, high = np.inf, -np.inf
            for corner in range(3):
                value = screen[triangles[t, corner], axis]
                low, high = min(low, value), max(high, value)
            rects[t, 2 * axis], rects[t, 2 * axis + 1] = low, high
        if rows[t, 0] < rows[t, 1] and rects[t, 0] < col_stop and rects[t, 1] > col_first:
            covering[count] = t
            count += 1
    return covering[:count]


@njit
def build_tree(bounds, candidates, root_lo, root_size, pad, leaf_size, max_depth, max_growth):
    """Build the octree of the ``candidates`` triangles; return its :class:`Tree` arrays.

    ``bounds`` (T, 6) holds each triangle's box (min x, y, z, then max x, y, z), widened by
    ``pad`` on every side when testing which cells it overlaps. A node with more than
    ``leaf_size`` triangles, above ``max_depth``, is split unless its children would together
    hold more than ``max_growth`` times its triangles (triangles large for the cell, which
    splitting would only copy). Breadth first: a node's triangle list is a range of the
    ``work`` array (kept in its START/STOP links until it becomes a leaf's range of
    ``items``); its children's lists are appended after it.
    """
    cells = np.empty((64, 4))
    links = np.empty((64, LINK_FIELDS), dtype=np.intp)
    count = candidates.shape[0]
    work = np.empty(max(2 * count, 16), dtype=np.intp)
    for k in range(count):
        work[k] = candidates[k]
    items = np.empty(max(count, 16), dtype=np.intp)
    n_items = 0
    _new_node(cells, links, 0, root_lo[0], root_lo[1], root_lo[2], root_size, 0, 0, count)
    n_nodes = 1
    work_end = count
    counts = np.empty(8, dtype=np.intp)
    fill = np.empty(8, dtype=np.intp)
    masks = np.empty(max(count, 1), dtype=np.intp)  # children each triangle of a node overlaps
    node = 0
    while node < n_nodes:
        start, stop = links[node, START], links[node, STOP]
        half = 0.5 * cells[node, SIDE]
        split = stop - start > leaf_size and links[node, LEVEL] < max_depth
        total = 0
        if split:
            if stop - start > masks.shape[0]:
                masks = np.empty(2 * (stop - start), dtype=np.intp)
            for octant in range(8):
                counts[octant] = 0
            for r in range(start, stop):
                mask = _child_mask(bounds, pad, work[r], cells[node], half)
                masks[r - start] = mask
                for octant in range(8):
                    if (mask >> octant) & 1:
                        counts[octant] += 1
                        total += 1
            split = total <= max_growth * (stop - start)
        links[node, LEAF] = 0 if split else 1
        if not split:
            if n_items + stop - start > items.shape[0]:
                items = _grown(items, n_items + stop - start)
            links[node, START] = n_items
            for r in range(start, stop):
                items[n_items] = work[r]
                n_items += 1
            links[node, STOP] = n_items
            node += 1
            continue
        if n_nodes + 8 > cells.shape[0]:
            cells, links = _grown_rows(cells, n_nodes + 8), _grown_rows(links, n_nodes + 8)
        if work_end + total > work.shape[0]:
            work = _grown(work, work_end + total)
        for octant in range(8):
            if counts[octant] == 0:
                continue
            _new_node(cells, links, n_nodes, cells[node, 0] + half * (octant & 1),
                      cells[node, 1] + half * ((octant >> 1) & 1),
                      cells[node, 2] + half * ((octant >> 2) & 1), half,
                      links[node, LEVEL] + 1, work_end, work_end + counts[octant])
            links[node, CHILD + octant] = n_nodes
            fill[octant] = work_end
            work_end += counts[octant]
            n_nodes += 1
        for r in range(start, stop):
            for octant in range(8):
                if (masks[r - start] >> octant) & 1:
                    work[fill[octant]] = work[r]
                    fill[octant] += 1
        node += 1
    return cells[:n_nodes], links[:n_nodes], items[:n_items]


@njit(from_python=False)
def _new_node(cells, links, node, x, y, z, side, level, start, stop):
    """Write a node's cell, level and (for now) its range of the work array; no children."""
    cells[node, 0], cells[node, 1], cells[node, 2], cells[node, SIDE] = x, y, z, side
    links[node, LEVEL] = level
    links[node, LEAF] = 0
    links[node, START] = start
    links[node, STOP] = stop
    for octant in range(8):
        links[node, CHILD + octant] = -1


@njit(from_python=False)
def _child_mask(bounds, pad, t, cell, half):
    """Bit k set when triangle t's padded box overlaps child octant k of ``cell``.

    Per axis, the box reaches the lower half (bit 0 of ``sides``) when its minimum is at most
    the centre, the upper half (bit 1) when its maximum is at least the centre: closed cells.
    """
    mask = 255
    for axis in range(3):
        centre = cell[axis] + half
        sides = (1 if bounds[t, axis] - pad <= centre else 0) | (
            2 if bounds[t, 3 + axis] + pad >= centre else 0)
        for octant in range(8):
            if not (sides >> ((octant >> axis) & 1)) & 1:
                mask &= ~(1 << octant)
    return mask


@njit
def cell_footprints(tree, triangle_rects, matrix, width, height, rects, outside):
    """Screen rectangle (N, 4) of each cell and whether it lies outside the view frustum.

    A cell is outside when its eight corners are all outside one of the six frustum planes
    (in clip coordinates, ``matrix`` mapping world to clip). Its rectangle
    (x min, x max, y min, y max, in pixels) is the box of its projected corners (the whole
    image when the cell reaches behind the eye), cut down to the box of the triangles it holds
    (``triangle_rects`` (T, 4), each triangle's screen box); ``FOOTPRINT_PAD`` keeps it
    conservative under rounding.
    """
    n_nodes = tree.cells.shape[0]
    for node in range(n_nodes - 1, -1, -1):
        _triangle_box(tree, node, triangle_rects, rects)
        all_out = 63
        behind = False
        x_min, x_max, y_min, y_max = np.inf, -np.inf, np.inf, -np.inf
        for corner in range(8):
            x, y, z, w = _corner_clip(tree, node, corner, matrix)
            all_out &= _outcode(x, y, z, w)
            if w <= 0.0:
                behind = True
                continue
            sx = (x / w + 1.0) * 0.5 * width
            sy = (1.0 - y / w) * 0.5 * height
            x_min, x_max = min(x_min, sx), max(x_max, sx)
            y_min, y_max = min(y_min, sy), max(y_max, sy)
        outside[node] = all_out != 0
        if behind:
            x_min, x_max, y_min, y_max = 0.0, float(width), 0.0, float(height)
        rects[node, 0] = max(rects[node, 0], x_min - FOOTPRINT_PAD)
        rects[node, 1] = min(rects[node, 1], x_max + FOOTPRINT_PAD)
        rects[node, 2] = max(rects[node, 2], y_min - FOOTPRINT_PAD)
        rects[node, 3] = min(rects[node, 3], y_max + FOOTPRINT_PAD)


@njit(from_python=False)
def _triangle_box(tree, node, triangle_rects, rects):
    """Screen box of a node's triangles: of a leaf's items, or the union of its children's.

    Nodes are visited from the last to the first, so children (after their parent in
    breadth-first order) come first; their rectangles are already cut to their cells, still a
    box holding every pixel at which the node's triangles lie inside it.
    """
    rects[node, 0], rects[node, 1] = np.inf, -np.inf
    rects[node, 2], rects[node, 3] = np.inf, -np.inf
    if tree.links[node, LEAF]:
        for r in range(tree.links[node, START], tree.links[node, STOP]):
            _widen(rects, node, triangle_rects, tree.items[r])
    else:
        for octant in range(8):
            child = tree.links[node, CHILD + octant]
            if child >= 0:
                _widen(rects, node, rects, child)


@njit(from_python=False)
def _widen(rects, node, boxes, k):
    rects[node, 0] = min(rects[node, 0], boxes[k, 0])
    rects[node, 1] = max(rects[node, 1], boxes[k, 1])
    rects[node, 2] = min(rects[node, 2], boxes[k, 2])
    rects[node, 3] = max(rects[node, 3], boxes[k, 3])


@njit(from_python=False)
def _corner_clip(tree, node, corner, matrix):
    """Clip coordinates of corner ``corner`` (octant bits) of a node's cell."""
    side = tree.cells[node, SIDE]
    px = tree.cells[node, 0] + side * (corner & 1)
    py = tree.cells[node, 1] + side * ((corner >> 1) & 1)
    pz = tree.cells[node, 2] + side * ((corner >> 2) & 1)
    return (
        matrix[0, 0] * px + matrix[0, 1] * py + matrix[0, 2] * pz + matrix[0, 3],
        matrix[1, 0] * px + matrix[1, 1] * py + matrix[1, 2] * pz + matrix[1, 3],
        matrix[2, 0] * px + matrix[2, 1] * py + matrix[2, 2] * pz + matrix[2, 3],
        matrix[3, 0] * px + matrix[3, 1] * py + matrix[3, 2] * pz + matrix[3, 3],
    )


@njit(from_python=False)
def eye_octant(tree, node, eye):
    """Return the eye's octant relative to a node's centre (bit set: eye on the upper side).

    ``eye`` (4,) is homogeneous (``Camera.viewpoint``): an orthographic viewer at infinity
    (w = 0) is on the upper side of an axis its direction points up.
    """
    half = 0.5 * tree.cells[node, SIDE]
    octant = 0
    for axis in range(3):
        if eye[axis] >= eye[3] * (tree.cells[node, axis] + half):
            octant |= 1 << axis
    return octant


@njit(from_python=False)
def _push_children(tree, node, eye, stack, top):
    """Push a node's children so that they pop front to back; return the new stack top."""
    octant = eye_octant(tree, node, eye)
    for k in range(7, -1, -1):
        child = tree.links[node, CHILD + (octant ^ FRONT_TO_BACK[k])]
        if child >= 0:
            stack[top] = child
            top += 1
    return top


@njit
def leaf_order(tree, eye):
    """Every leaf in the order a front-to-back traversal from ``eye`` reaches it (no culling)."""
    n_nodes = tree.cells.shape[0]
    order = np.empty(n_nodes, dtype=np.intp)
    n = 0
    stack = np.empty(8 * n_nodes + 1, dtype=np.intp)
    stack[0] = 0
    top = 1 if n_nodes else 0
    while top > 0:
        top -= 1
        node = stack[top]
        if tree.links[node, LEAF]:
            order[n] = node
            n += 1
        else:
            top = _push_children(tree, node, eye, stack, top)
    return order[:n]


class Scan(NamedTuple):
    """What the traversal reads about the drawable triangles."""

    setup: np.ndarray  # (T, SETUP_FIELDS) set-up records of the raster kernels
    rows: np.ndarray  # (T, 2) intp image rows [first, stop) each triangle covers
    triangles: np.ndarray  # (T, 3) intp vertex indices
    positions: np.ndarray  # (V, 3) world positions of the vertices
    cutouts: object  # the raster kernels' Cutouts: which triangles are alpha-tested, and how


@njit
def traverse(tree, rects, outside, eye, scan, bands, x0, y0, inv_depth, triangle_id, decided,
             stamp, stats, outcomes):
    """Decide the visible triangle of every pixel of the listed bands, front to back.

    Each band of ``BAND_ROWS`` rows of the region (image pixel (x0 + i, y0 + j) at buffer
    (j, i)) traverses the tree on its own, with its own undecided pixels, so bands may run in
    parallel threads (the kernel releases the GIL; a plain loop compiles far faster than a
    ``prange``) and the result does not depend on the threads. Fills ``inv_depth`` (1/w, 0
    where none) and ``triangle_id`` (-1 where none) like the z-buffer would; ``decided``
    (h, w) uint8 and ``stamp`` (h, w) int32 are work buffers; ``stats`` (bands, levels,
    STAT_COLUMNS) int64 receives each band's counts per tree level. ``outcomes`` (bands, N)
    int8 receives what each band did with each node (the ``OUTCOME_*`` codes, 0 where it did
    not reach it) when it has a column per node; (bands, 0) records nothing (explain only).
    """
    for k in range(bands.shape[0]):
        _traverse_band(tree, rects, outside, eye, scan, bands[k], x0, y0, inv_depth,
                       triangle_id, decided, stamp, stats[bands[k]], outcomes[bands[k]])


# Inlined by Numba into its one caller, the loop over bands (see pixelpath._jit).
@njit(inline="always")
def _traverse_band(tree, rects, outside, eye, scan, band, x0, y0, inv_depth, triangle_id,
                   decided, stamp, stats, outcome):
    height, width = inv_depth.shape
    first = y0 + band * BAND_ROWS
    stop = min(first + BAND_ROWS, y0 + height)
    for j in range(first - y0, stop - y0):
        for i in range(width):
            inv_depth[j, i] = 0.0
            triangle_id[j, i] = -1
            decided[j, i] = 0
            stamp[j, i] = 0
    undecided = _tile_counts(stop - first, width)
    touched = np.empty((stop - first) * width, dtype=np.intp)
    n_nodes = tree.cells.shape[0]
    stack = np.empty(8 * (stats.shape[0] + 1), dtype=np.intp)
    top = 0
    if n_nodes:
        stack[0] = 0
        top = 1
    visit = np.int32(0)
    while top > 0:
        top -= 1
        node = stack[top]
        level = stats[tree.links[node, LEVEL]]
        c0, c1, r0, r1 = _pixel_range(rects[node], x0, x0 + width, y0, y0 + height)
        if outside[node] or c0 >= c1 or r0 >= r1:
            level[CULLED] += 1
            _record(outcome, node, OUTCOME_CULLED)
            continue
        r0, r1 = max(r0, first), min(r1, stop)
        if r0 >= r1:
            level[OTHER_BAND] += 1
            continue
        if not _any_undecided(undecided, c0 - x0, c1 - x0, r0 - first, r1 - first):
            level[SKIPPED] += 1
            _record(outcome, node, OUTCOME_SKIPPED)
            continue
        level[VISITED] += 1
        if not tree.links[node, LEAF]:
            _record(outcome, node, OUTCOME_ENTERED)
            top = _push_children(tree, node, eye, stack, top)
            continue
        _record(outcome, node, OUTCOME_DRAWN)
        visit += np.int32(1)
        n_touched = _draw_leaf(tree, node, scan, c0, c1, r0, r1, x0, y0, inv_depth,
                               triangle_id, decided, stamp, visit, touched, level)
        level[DECIDED] += _decide(tree, node, scan, touched, n_touched, x0, y0, first,
                                  triangle_id, decided, undecided)


@njit(inline="always")
def _record(outcome, node, code):
    """Note what a band did with a node, when recording (explain only)."""
    if outcome.shape[0]:
        outcome[node] = code


@njit(from_python=False)
def _tile_counts(rows, width):
    """Pixels per TILE × TILE tile of a band of ``rows`` × ``width`` pixels (all undecided)."""
    counts = np.empty(((rows + TILE - 1) // TILE, (width + TILE - 1) // TILE), dtype=np.intp)
    for ty in range(counts.shape[0]):
        for tx in range(counts.shape[1]):
            counts[ty, tx] = (min(TILE, rows - ty * TILE)) * (min(TILE, width - tx * TILE))
    return counts


@njit(from_python=False)
def _pixel_range(rect, col_first, col_stop, row_first, row_stop):
    """Columns [c0, c1) and rows [r0, r1) whose pixel centres lie in a screen rectangle."""
    x_lo = max(rect[0] - 0.5, col_first - 1.0)
    x_hi = min(rect[1] - 0.5, col_stop + 1.0)
    y_lo = max(rect[2] - 0.5, row_first - 1.0)
    y_hi = min(rect[3] - 0.5, row_stop + 1.0)
    if not (x_lo <= x_hi and y_lo <= y_hi):  # also catches an empty (inf, -inf) box
        return 0, 0, 0, 0
    c0 = max(int(np.ceil(x_lo)), col_first)
    c1 = min(int(np.floor(x_hi)) + 1, col_stop)
    r0 = max(int(np.ceil(y_lo)), row_first)
    r1 = min(int(np.floor(y_hi)) + 1, row_stop)
    return c0, c1, r0, r1


@njit(from_python=False)
def _any_undecided(undecided, c0, c1, r0, r1):
    """Whether a tile overlapping local columns [c0, c1), rows [r0, r1) has undecided pixels."""
    for ty in range(r0 // TILE, (r1 - 1) // TILE + 1):
        for tx in range(c0 // TILE, (c1 - 1) // TILE + 1):
            if undecided[ty, tx] > 0:
                return True
    return False


@njit(refcount=False, from_python=False)
def _draw_leaf(tree, node, scan, c0, c1, r0, r1, x0, y0, inv_depth, triangle_id, decided,
               stamp, visit, touched, level):
    """Scan-convert a leaf's triangles inside its footprint, with the depth test on 1/w.

    Decided pixels are left alone. A sample replaces the stored one when it is nearer, or as
    near with a lower triangle index (the z-buffer's tie rule, whatever the order of cells),
    unless the alpha test of an alpha-tested triangle cuts it away there.
    Returns how many pixels were tested, each listed once in ``touched``. Called per leaf, as
    :func:`_decide` is, with the records ``tree`` and ``scan``: both count no references
    (``njit(refcount=False)``), which would update each of their arrays' counts atomically at
    every call.
    """
    width = inv_depth.shape[1]
    n_touched = 0
    tested = 0
    cutouts = scan.cutouts
    masked = cutouts.masked
    for r in range(tree.links[node, START], tree.links[node, STOP]):
        t = tree.items[r]
        holes = masked[t]
        record = scan.setup[t]
        row_first = max(scan.rows[t, 0], r0)
        row_stop = min(scan.rows[t, 1], r1)
        if row_first >= row_stop:
            continue
        level[DRAWN] += 1
        pa, pb, pc = record[KEY_PLANE], record[KEY_PLANE + 1], record[KEY_PLANE + 2]
        for j in range(row_first, row_stop):
            y = j + 0.5
            span_first, span_stop = scanline_span(record, y, c0, c1)
            row_value = pb * y + pc
            row = j - y0
            for i in range(span_first, span_stop):
                col = i - x0
                if decided[row, col]:
                    continue
                tested += 1
                inv_w = pa * (i + 0.5) + row_value
                stored = inv_depth[row, col]
                if (inv_w > stored or (inv_w == stored and t < triangle_id[row, col])) and not (
                    holes and cut_away_at(cutouts, t, i + 0.5, y)
                ):
                    inv_depth[row, col] = inv_w
                    triangle_id[row, col] = t
                if stamp[row, col] != visit:
                    stamp[row, col] = visit
                    touched[n_touched] = row * width + col
                    n_touched += 1
    level[TESTED] += tested
    return n_touched


@njit(refcount=False, from_python=False)
def _decide(tree, node, scan, touched, n_touched, x0, y0, band_first, triangle_id, decided,
            undecided):
    """Mark decided the touched pixels whose nearest hit lies inside this leaf's cell.

    Every cell met later along the pixel's ray lies farther away, so nothing can come in
    front of that hit any more. The hit is rebuilt from its triangle's perspective-correct
    weights at the pixel centre. Returns how many pixels were decided.
    """
    width = triangle_id.shape[1]
    side = tree.cells[node, SIDE]
    count = 0
    for k in range(n_touched):
        row, col = touched[k] // width, touched[k] % width
        t = triangle_id[row, col]
        b0, b1, b2 = perspective_weights(scan.setup, t, x0 + col + 0.5, y0 + row + 0.5)
        a, b, c = scan.triangles[t, 0], scan.triangles[t, 1], scan.triangles[t, 2]
        inside = True
        for axis in range(3):
            p = b0 * scan.positions[a, axis] + b1 * scan.positions[b, axis]
            p += b2 * scan.positions[c, axis]
            offset = p - tree.cells[node, axis]
            inside = inside and 0.0 <= offset <= side
        if inside:
            decided[row, col] = 1
            undecided[(y0 + row - band_first) // TILE, col // TILE] -= 1
            count += 1
    return count


def warmup() -> None:
    """Compile the octree kernels on two triangles in a tiny tree."""
    positions = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 0.5]])
    screen = np.array([[0.0, 8.0, 0.2], [8.0, 8.0, 0.2], [4.0, 0.0, 0.2], [6.0, 2.0, 0.25]])
    triangles = np.array([[0, 1, 2], [0, 1, 3]], dtype=np.intp)
    rows = np.zeros((2, 2), dtype=np.intp)
    bounds = np.empty((2, 6))
    triangle_rects = np.empty((2, 4))
    triangle_boxes(positions, screen, triangles, rows, 0, 8, bounds, triangle_rects)
    everything = np.arange(2, dtype=np.intp)
    tree = Tree(*build_tree(bounds, everything, np.full(3, -1.0), 2.0, 1e-9, 1, 2, 8))
    eye = np.array([0.0, 0.0, 5.0, 1.0])
    leaf_order(tree, eye)
    matrix = np.eye(4)
    matrix[3, 2], matrix[3, 3] = -1.0, 5.0
    rects = np.empty((tree.cells.shape[0], 4))
    outside = np.empty(tree.cells.shape[0], dtype=np.bool_)
    cell_footprints(tree, triangle_rects, matrix, 8, 8, rects, outside)
    setup = np.zeros((2, SETUP_FIELDS))
    scan = Scan(setup, rows, triangles, positions, tiny_cutouts(setup, triangles))
    shape = (8, 8)
    stats = np.zeros((1, 3, STAT_COLUMNS), dtype=np.int64)
    traverse(tree, rects, outside, eye, scan, np.zeros(1, dtype=np.intp), 0, 0,
             np.empty(shape), np.empty(shape, dtype=np.int32), np.empty(shape, dtype=np.uint8),
             np.empty(shape, dtype=np.int32), stats, np.zeros((1, 0), dtype=np.int8))
