"""Compiled kernels of the painter's algorithm: the depth sort of Newell, Newell and Sancha.

The polygons are the drawable triangles of the shared front end. Each has a record:
its extents in depth (w, the distance along the viewing axis; for an orthographic camera,
whose w is 1, minus the depth key, which orders depth the same way), in screen x and in screen
y, and its plane in world space (unit normal, offset) with the side the eye is on (for an
orthographic camera the viewer at infinity: the eye is homogeneous, see ``Camera.viewpoint``).
The list is sorted by farthest depth; the polygon at its head, P, is compared with every Q
whose depth extent overlaps P's by the notes' tests, cheapest first:

1. Q lies entirely nearer than P (depth extents do not overlap);
2. the screen x extents do not overlap;
3. the screen y extents do not overlap;
4. P lies entirely on the far side of Q's plane, seen from the eye;
5. Q lies entirely on the eye's side of P's plane;
6. the projections do not overlap (a 2-D triangle test; a shared edge is not an overlap).

Any test that succeeds means P cannot hide Q. When all fail and Q can be drawn first (the
reversed tests 4 and 5), Q is moved before P and marked; a marked polygon that must move
again closes a cycle of overlaps, and an interpenetrating pair admits neither order: then a
polygon is split by the other's plane (world space; every vertex attribute is interpolated
along the cut edges: clip coordinates are affine in world coordinates, so this is exact) and
the pieces go back into the sorted list.

Since the list is sorted by farthest depth, the candidates Q of a head P are the polygons
that follow it until the first one lying entirely nearer (test 1 settles that one and, by the
sort, every later one): the work is O(n log n + n k) for k overlapping depth extents.

The helpers are compiled as functions of their own, not inlined into both :func:`compare`
and :func:`depth_sort` (``inline="always"``): that cut the first compile by about a quarter.
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._setup_kernels import _grown, _grown_rows, cut_triangle, screen_point

# Columns of a polygon record.
ZMIN, ZMAX, XMIN, XMAX, YMIN, YMAX = 0, 1, 2, 3, 4, 5
NORMAL = 6  # unit normal of the polygon's plane in world space (3 columns)
OFFSET = 9  # the plane is normal · x + offset = 0
EYE_SIGN = 10  # +1 or -1: the sign of normal · eye + offset
RECORD = 11
PLANE_COLUMNS = 5  # NORMAL, OFFSET and EYE_SIGN, as given for the input triangles

# Columns of the vertex rows: clip coordinates, then the world position, then the rest.
W = 3
POSITION = 4

# Outcomes of comparing the head P with a polygon Q: 1..6 the test that settled the pair,
MOVE = 7  # P might hide Q but Q cannot hide P: Q goes first
SPLIT = 8  # neither order is proved by the tests: a plane must cut one of them

# Slots of the counts array.
COMPARISONS = 0  # then slots 1..6: pairs settled by each test
MOVES = 7
CYCLES = 8
SPLITS = 9
PIECES = 10
UNRESOLVED = 11  # pairs drawn in the sorted order because no plane could cut them
LIMITED = 12  # of those, pairs left uncut because the polygon limit was reached
COUNTS = 13

NO_ROOM = -2  # _plane_cut's answer once the polygon limit is reached

# A projection-overlap tolerance, in pixels per pixel of edge length: edges that coincide up
# to rounding (a split line drawn from both sides) count as touching, not overlapping.
TOUCHING = 1e-9


@njit
def _describe(corners, attrs, screen, orthographic, record):
    """Fill the extents of a triangle (its three vertex indices) into ``record``."""
    a, b, c = corners[0], corners[1], corners[2]
    if orthographic:
        # Clip w is 1 everywhere; the depth key is affine in depth and larger when nearer.
        record[ZMIN] = -max(screen[a, 2], screen[b, 2], screen[c, 2])
        record[ZMAX] = -min(screen[a, 2], screen[b, 2], screen[c, 2])
    else:
        record[ZMIN] = min(attrs[a, W], attrs[b, W], attrs[c, W])
        record[ZMAX] = max(attrs[a, W], attrs[b, W], attrs[c, W])
    record[XMIN] = min(screen[a, 0], screen[b, 0], screen[c, 0])
    record[XMAX] = max(screen[a, 0], screen[b, 0], screen[c, 0])
    record[YMIN] = min(screen[a, 1], screen[b, 1], screen[c, 1])
    record[YMAX] = max(screen[a, 1], screen[b, 1], screen[c, 1])


@njit(from_python=False)
def _side_range(x, y, records, corners, attrs):
    """Smallest and largest distance of x's corners to y's plane, positive on the eye's side."""
    record = records[y]
    nx, ny, nz = record[NORMAL], record[NORMAL + 1], record[NORMAL + 2]
    low = np.inf
    high = -np.inf
    for k in range(3):
        v = corners[x, k]
        d = nx * attrs[v, POSITION] + ny * attrs[v, POSITION + 1] + nz * attrs[v, POSITION + 2]
        d = (d + record[OFFSET]) * record[EYE_SIGN]
        low = min(low, d)
        high = max(high, d)
    return low, high


@njit(from_python=False)
def _separated(a, b, corners, screen):
    """Whether some edge of triangle a has all of triangle b on its outer side (or on it)."""
    i0, i1, i2 = corners[a, 0], corners[a, 1], corners[a, 2]
    area2 = (screen[i1, 0] - screen[i0, 0]) * (screen[i2, 1] - screen[i0, 1]) - (
        screen[i2, 0] - screen[i0, 0]
    ) * (screen[i1, 1] - screen[i0, 1])
    orient = 1.0 if area2 > 0.0 else -1.0
    for e in range(3):
        i, j = corners[a, e], corners[a, (e + 1) % 3]
        ex = screen[j, 0] - screen[i, 0]
        ey = screen[j, 1] - screen[i, 1]
        limit = TOUCHING * (abs(ex) + abs(ey))
        outside = True
        for v in range(3):
            k = corners[b, v]
            dx, dy = screen[k, 0] - screen[i, 0], screen[k, 1] - screen[i, 1]
            inward = orient * (ex * dy - ey * dx)
            if inward > limit:
                outside = False
                break
        if outside:
            return True
    return False


@njit
def compare(p, q, records, corners, attrs, screen, eps):
    """Return the test (1..6) that shows P cannot hide Q, or ``MOVE`` or ``SPLIT``."""
    rp, rq = records[p], records[q]
    if rq[ZMAX] <= rp[ZMIN]:
        return 1
    if rq[XMIN] >= rp[XMAX] or rp[XMIN] >= rq[XMAX]:
        return 2
    if rq[YMIN] >= rp[YMAX] or rp[YMIN] >= rq[YMAX]:
        return 3
    return _plane_tests(p, q, records, corners, attrs, screen, eps)


@njit(from_python=False)
def _plane_tests(p, q, records, corners, attrs, screen, eps):
    """Run tests 4 to 6 on a pair whose extents overlap; ``MOVE`` or ``SPLIT`` if all fail."""
    p_low, p_high = _side_range(p, q, records, corners, attrs)
    if p_high <= eps:
        return 4
    q_low, q_high = _side_range(q, p, records, corners, attrs)
    if q_low >= -eps:
        return 5
    if _separated(p, q, corners, screen) or _separated(q, p, corners, screen):
        return 6
    if q_high <= eps or p_low >= -eps:
        return MOVE
    return SPLIT


@njit(from_python=False)
def _straddles(x, y, records, corners, attrs, eps):
    """Whether polygon x has corners on both sides of y's plane."""
    low, high = _side_range(x, y, records, corners, attrs)
    return low < -eps and high > eps


@njit
def triangle_planes(vertices, triangles, source, eye, planes):
    """Fill ``planes`` (T, PLANE_COLUMNS) with the plane of triangle ``source[t]``.

    Columns: unit normal, offset (normal · x + offset = 0) and the eye's signed distance
    (the caller turns it into a sign); zeros for a triangle of zero area. ``eye`` (4,) is
    homogeneous (``Camera.viewpoint``): w = 0 is the orthographic viewer at infinity.
    """
    for t in range(source.shape[0]):
        a, b, c = triangles[source[t], 0], triangles[source[t], 1], triangles[source[t], 2]
        ux, vx = vertices[b, 0] - vertices[a, 0], vertices[c, 0] - vertices[a, 0]
        uy, vy = vertices[b, 1] - vertices[a, 1], vertices[c, 1] - vertices[a, 1]
        uz, vz = vertices[b, 2] - vertices[a, 2], vertices[c, 2] - vertices[a, 2]
        nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
        length = np.sqrt(nx * nx + ny * ny + nz * nz)
        if length > 0.0:
            nx, ny, nz = nx / length, ny / length, nz / length
        offset = -(nx * vertices[a, 0] + ny * vertices[a, 1] + nz * vertices[a, 2])
        planes[t, 0], planes[t, 1], planes[t, 2], planes[t, 3] = nx, ny, nz, offset
        planes[t, 4] = nx * eye[0] + ny * eye[1] + nz * eye[2] + offset * eye[3]


@njit
def depth_sort(attrs, screen, count, triangles, planes, width, height, orthographic, eps,
               max_polygons, counts):
    """Order triangles back to front with the depth sort, splitting where it must.

    Parameters
    ----------
    attrs : (V, k) float64
        Vertex rows (clip x, y, z, w; world position; any attributes to interpolate); the
        first ``count`` rows are in use, the rest is room for split vertices.
    screen : (V, 3) float64
        Screen x, y and depth key of the vertices (rows as ``attrs``).
    triangles : (n, 3) intp
        The triangles to order (vertex indices).
    planes : (n, PLANE_COLUMNS) float64
        Their planes in world space: unit normal, offset, sign of the eye's side (+1 or -1).
    width, height : int
        Image size, to map split vertices to the screen.
    orthographic : bool
        The camera's projection (how split vertices map, how depth is read).
    eps : float
        Distance (world units) within which a point counts as on a plane.
    max_polygons : int
        Splitting stops (and pairs are left in sorted order) once this many polygons exist.
    counts : (COUNTS,) int64, out
        Comparisons, pairs settled by each test, moves, cycles, splits, pieces, unresolved
        and, of those, unresolved for want of room (``max_polygons`` reached).

    Returns
    -------
    order : (m,) intp
        Polygons back to front. Polygon i < n is ``triangles[root[i]]``; polygons from n on
        are pieces made by splitting.
    attrs, screen, count
        The vertex rows with the split vertices appended, and how many are in use.
    corners : (P, 3) intp
        Vertex indices of every polygon (sorted input triangles, then pieces).
    root : (P,) intp
        The input triangle each polygon is, or was cut from.
    """
    n = triangles.shape[0]
    records = np.empty((n + n // 4 + 16, RECORD))
    corners = np.empty((records.shape[0], 3), dtype=np.intp)
    root = np.empty(records.shape[0], dtype=np.intp)
    farthest = np.empty(n)
    for t in range(n):
        _describe(triangles[t], attrs, screen, orthographic, records[t])
        farthest[t] = -records[t, ZMAX]
    by_depth = np.argsort(farthest, kind="mergesort")
    sorted_records = np.empty((n, RECORD))
    for i in range(n):
        t = by_depth[i]
        for column in range(NORMAL):
            sorted_records[i, column] = records[t, column]
        for column in range(PLANE_COLUMNS):
            sorted_records[i, NORMAL + column] = planes[t, column]
        for k in range(3):
            corners[i, k] = triangles[t, k]
        root[i] = t
    for i in range(n):
        for column in range(RECORD):
            records[i, column] = sorted_records[i, column]
    gone = np.zeros(records.shape[0], dtype=np.bool_)  # drawn, moved out of the list, or cut
    stacked = np.zeros(records.shape[0], dtype=np.bool_)
    polygons = n
    # The sorted list, with room in front for pieces, and the stack of moved polygons.
    slack = 64 + n // 8
    rest = np.empty(slack + n, dtype=np.intp)
    for i in range(n):
        rest[slack + i] = i
    first, end = slack, slack + n
    stack = np.empty(16, dtype=np.intp)
    top = 0
    order = np.empty(n, dtype=np.intp)
    drawn = 0
    pieces = np.empty((3, 4), dtype=np.intp)
    cut_edges = np.empty((2, 2), dtype=np.intp)
    cut_params = np.empty(2)
    distances = np.empty(3)
    settled = np.zeros(7, dtype=np.int64)  # pairs settled by tests 1..6
    compared = 0
    while True:
        if top > 0:
            p = stack[top - 1]
            scan_from = first
        else:
            while first < end and gone[rest[first]]:
                first += 1
            if first == end:
                break
            p = rest[first]
            scan_from = first + 1
        # Compare P with the polygons moved before it, then with the sorted list.
        room = polygons + 3 <= max_polygons
        cut, by, move = -1, -1, -1
        for s in range(top - 1):
            q = stack[s]
            outcome = compare(p, q, records, corners, attrs, screen, eps)
            compared += 1
            if outcome <= 6:
                settled[outcome] += 1
                continue
            # Q was moved before: if it must go before P again, the overlaps form a cycle.
            cycle = outcome == MOVE
            cut, by = _plane_cut(p, q, cycle, stack, top, records, corners, attrs, eps, room)
            if cut >= 0:
                counts[CYCLES] += int(cycle)
                break
            counts[UNRESOLVED] += 1
            counts[LIMITED] += int(cut == NO_ROOM)
        # The sorted list: every Q up to the first entirely nearer than P.
        near, left, right = records[p, ZMIN], records[p, XMIN], records[p, XMAX]
        low, high = records[p, YMIN], records[p, YMAX]
        k = scan_from
        while cut < 0 and k < end:
            q = rest[k]
            k += 1
            if gone[q]:
                continue
            compared += 1
            if records[q, ZMAX] <= near:
                settled[1] += 1
                break  # and every later polygon of the sorted list is nearer still
            if records[q, XMIN] >= right or left >= records[q, XMAX]:
                settled[2] += 1
                continue
            if records[q, YMIN] >= high or low >= records[q, YMAX]:
                settled[3] += 1
                continue
            outcome = _plane_tests(p, q, records, corners, attrs, screen, eps)
            if outcome <= 6:
                settled[outcome] += 1
            elif outcome == MOVE:
                move = q
                break
            else:
                cut, by = _plane_cut(p, q, False, stack, top, records, corners, attrs, eps, room)
                counts[UNRESOLVED] += int(cut < 0)
                counts[LIMITED] += int(cut == NO_ROOM)
        if move >= 0:
            # Q cannot hide P but P might hide Q: move Q before P and mark it.
            gone[move] = True
            if top == stack.shape[0]:
                stack = _grown(stack, top + 1)
            stack[top] = move
            stacked[move] = True
            top += 1
            counts[MOVES] += 1
            continue
        if cut >= 0:
            # Cut one polygon by the other's plane; the pieces go back into the sorted list.
            if polygons + 3 > records.shape[0]:
                records = _grown_rows(records, polygons + 3)
                corners = _grown_rows(corners, polygons + 3)
                root = _grown(root, polygons + 3)
                gone = _grown(gone, polygons + 3)
                stacked = _grown(stacked, polygons + 3)
            if count + 2 > attrs.shape[0]:
                attrs = _grown_rows(attrs, count + 2)
                screen = _grown_rows(screen, attrs.shape[0])
            if first < 3:
                rest, first, end = _room_in_front(rest, first, end)
            record = records[by]
            for k in range(3):
                v = corners[cut, k]
                distances[k] = (
                    record[NORMAL] * attrs[v, POSITION]
                    + record[NORMAL + 1] * attrs[v, POSITION + 1]
                    + record[NORMAL + 2] * attrs[v, POSITION + 2]
                    + record[OFFSET]
                )
            before = count
            attrs, count, made = cut_triangle(
                attrs, count, corners[cut], distances, eps, pieces, cut_edges, cut_params
            )
            for v in range(before, count):
                screen_point(attrs, v, width, height, orthographic, screen, v)
            for piece in range(made):
                new = polygons
                polygons += 1
                for k in range(3):
                    corners[new, k] = pieces[piece, k]
                _describe(corners[new], attrs, screen, orthographic, records[new])
                for column in range(PLANE_COLUMNS):
                    records[new, NORMAL + column] = records[cut, NORMAL + column]
                root[new] = root[cut]
                gone[new] = False
                stacked[new] = False
                first = _insert_sorted(rest, first, end, new, records)
            counts[SPLITS] += 1
            counts[PIECES] += made
            gone[cut] = True
            if stacked[cut]:
                top = _remove(stack, top, cut)
                stacked[cut] = False
            continue
        # Nothing P might hide is left behind it: draw P.
        if drawn == order.shape[0]:
            order = _grown(order, drawn + 1)
        order[drawn] = p
        drawn += 1
        gone[p] = True
        if top > 0:
            top -= 1
            stacked[p] = False
        else:
            first += 1
    counts[COMPARISONS] += compared
    for test in range(1, 7):
        counts[test] += settled[test]
    return order[:drawn], attrs, screen, count, corners[:polygons], root[:polygons]


@njit(from_python=False)
def _plane_cut(p, q, cycle, stack, top, records, corners, attrs, eps, room):
    """(polygon to cut, polygon whose plane cuts it) for a pair the tests left undecided.

    Q by P's plane if Q straddles it, else P by Q's plane; for a cycle (Q is on the stack,
    moved before), any member of the cycle from Q up to P that straddles another member's
    plane. (-1, -1) when no plane cuts (the pair stays in sorted order), (NO_ROOM, -1) when
    ``room`` is False.
    """
    if not room:
        return NO_ROOM, -1
    if _straddles(q, p, records, corners, attrs, eps):
        return q, p
    if _straddles(p, q, records, corners, attrs, eps):
        return p, q
    if cycle:
        start = 0
        while stack[start] != q:
            start += 1
        for i in range(start, top):
            for j in range(start, top):
                if i != j and _straddles(stack[i], stack[j], records, corners, attrs, eps):
                    return stack[i], stack[j]
    return -1, -1


@njit(from_python=False)
def _room_in_front(rest, first, end):
    """Return the list with room for pieces in front: (array, first, end)."""
    slack = max(64, end - first)
    bigger = np.empty(slack + end - first, dtype=np.intp)
    for k in range(first, end):
        bigger[slack + k - first] = rest[k]
    return bigger, slack, slack + end - first


@njit(from_python=False)
def _insert_sorted(rest, first, end, polygon, records):
    """Insert ``polygon`` by farthest depth into rest[first:end]; return the new ``first``.

    The polygons before its place shift one slot towards the front (the list keeps room
    there), which costs as many moves as polygons lie farther than it.
    """
    farthest = records[polygon, ZMAX]
    low, high = first, end
    while low < high:  # first position whose polygon is nearer than the new one
        middle = (low + high) // 2
        if records[rest[middle], ZMAX] >= farthest:
            low = middle + 1
        else:
            high = middle
    for k in range(first, low):
        rest[k - 1] = rest[k]
    rest[low - 1] = polygon
    return first - 1


@njit(from_python=False)
def _remove(stack, top, polygon):
    """Remove ``polygon`` from stack[:top]; return the new top."""
    k = 0
    while stack[k] != polygon:
        k += 1
    for i in range(k, top - 1):
        stack[i] = stack[i + 1]
    return top - 1


def warmup() -> None:
    """Compile the depth sort on two interpenetrating triangles (one split)."""
    attrs = np.zeros((8, 10))
    points = [(-1.0, -1.0, -3.0), (1.0, -1.0, -3.0), (0.0, 1.0, -3.0),
              (-1.0, 0.0, -2.0), (1.0, 0.0, -4.0), (0.0, 0.5, -2.0)]
    for v, (x, y, z) in enumerate(points):
        attrs[v, 0], attrs[v, 1], attrs[v, 2], attrs[v, 3] = x, y, 0.0, -z
        attrs[v, POSITION], attrs[v, POSITION + 1], attrs[v, POSITION + 2] = x, y, z
    screen = np.zeros((8, 3))
    for v in range(6):
        screen_point(attrs, v, 8, 8, False, screen, v)
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    planes = np.empty((2, PLANE_COLUMNS))
    triangle_planes(np.array(points), triangles, np.arange(2), np.zeros(4), planes)
    planes[:, 4] = np.where(planes[:, 4] < 0, -1.0, 1.0)
    depth_sort(attrs, screen, 6, triangles, planes, 8, 8, False, 1e-9, 64,
               np.zeros(COUNTS, dtype=np.int64))
