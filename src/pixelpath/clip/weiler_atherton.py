"""Weiler-Atherton clipping: concave subjects, concave windows, separate pieces.

The classic algorithm walks the subject's boundary while it is inside the window and switches
to the window's boundary at each intersection, so a concave subject comes out as separate
pieces instead of Sutherland-Hodgman's single polygon with zero-width bridges. This version
keeps that walk but makes every decision exactly, which is what the degenerate cases need:

1. Both polygons are validated (simple, non-zero area) and oriented counter-clockwise.
2. Every contact between a subject edge and a window edge is found in exact rational
   arithmetic (``fractions.Fraction`` of the float inputs, so nothing is rounded): crossings,
   vertices lying on the other polygon's edges, and the ends of collinear overlaps. Both
   polygons' edges are split there, so the two boundaries share those points exactly.
3. Each piece of the subject's boundary is kept when it lies inside the window, each piece of
   the window's boundary when it lies inside the subject. A piece's side can only change
   where the boundaries touch, so it is decided once per run of pieces, at the contact the run
   starts from, by where the run heads: into the open half-plane of the edge it starts on, or
   into the interior angle of the vertex (the entry/exit label of the classic algorithm, but
   also right when the boundaries only touch). A piece both boundaries share is kept once
   when both interiors lie on the same side of it and dropped when they lie on opposite sides
   (the polygons only touch there).
4. The kept pieces are linked into loops: arriving at a point, the walk leaves along the first
   kept piece clockwise from the way it came, which is Weiler-Atherton's switch between the
   two vertex lists. This turn rule keeps pieces that touch at a single point apart. Every
   piece is used once, so the walk ends after at most as many steps as there are pieces.

The intersection of two simple polygons has no holes (its complement is the union of two
connected unbounded sets), so every piece is one counter-clockwise ring. Because the
arithmetic is exact, no symbolic perturbation is needed: a vertex on an edge is on
it, and touching is touching. Results: subject inside the window gives the subject, window
inside the subject gives the window, identical polygons give the polygon, touching without
overlap (at a point or along an edge) gives nothing. Collinear vertices are dropped from the
output and each piece starts at its lowest-leftmost vertex. Self-intersecting input is
rejected with a ``ValueError`` naming the two edges that meet.
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from typing import Literal, overload

import numpy as np

from pixelpath.clip import _validate
from pixelpath.clip.weiler_atherton_trace import WeilerAthertonTrace
from pixelpath.clip.window import ConvexWindow, Rect

__all__ = ["weiler_atherton"]

Point = tuple[Fraction, Fraction]
Segment = tuple[Point, Point]

VERTEX, EDGE_INTERIOR = 0, 1  # where a contact point lies on a polygon


@overload
def weiler_atherton(
    subject: np.ndarray, window: object, trace: Literal[False] = False
) -> list[np.ndarray]: ...
@overload
def weiler_atherton(
    subject: np.ndarray, window: object, trace: Literal[True]
) -> tuple[list[np.ndarray], WeilerAthertonTrace]: ...
def weiler_atherton(
    subject: np.ndarray, window: object, trace: bool = False
) -> list[np.ndarray] | tuple[list[np.ndarray], WeilerAthertonTrace]:
    """Clip a polygon against a window, either of them concave, into separate pieces.

    Parameters
    ----------
    subject : (N, 2) array_like
        A simple polygon (no self-intersection), either orientation.
    window : Rect or (K, 2) array_like
        A :class:`~pixelpath.clip.Rect` or a simple polygon, either orientation.
    trace : bool, optional
        Also return a :class:`~pixelpath.clip.WeilerAthertonTrace` of the walk.

    Returns
    -------
    list of (Mi, 2) ndarray
        The pieces of the intersection, each counter-clockwise; an empty list when the
        polygons do not overlap. Pieces that touch only at a vertex are separate.
    WeilerAthertonTrace
        Only with ``trace=True``.

    Raises
    ------
    ValueError
        For fewer than 3 distinct vertices, a non-finite coordinate, zero area or a
        self-intersecting polygon. Every finite coordinate is taken, up to ±1.8e308: the
        arithmetic is exact.
    TypeError
        For non-numeric input.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> for piece in weiler_atherton(notched, Rect(-1, -1, 3, 7)):
    ...     print(piece.tolist())
    [[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]]
    [[0.0, 4.0], [3.0, 4.0], [3.0, 6.0], [0.0, 6.0]]
    """
    if isinstance(window, (Rect, ConvexWindow)):
        window = window.vertices
    subject_ring = _exact_ring(subject, "subject")
    window_ring = _exact_ring(window, "window")
    subject_cuts, window_cuts, on_window, on_subject = _cut_points(subject_ring, window_ring)
    subject_pieces = _split(subject_ring, subject_cuts)
    window_pieces = _split(window_ring, window_cuts)
    window_set = set(window_pieces)
    shared = [p for p in subject_pieces if p in window_set]
    opposed = [p for p in subject_pieces if (p[1], p[0]) in window_set]
    on_both = {*shared, *opposed, *((b, a) for a, b in opposed)}
    # Shared pieces (both interiors on the same side) are kept once.
    subject_kept = _inside_pieces(subject_pieces, window_ring, on_window, on_both)
    window_kept = _inside_pieces(window_pieces, subject_ring, on_subject, on_both)
    walked = _link(shared + subject_kept + window_kept)
    loops = [_drop_straight_vertices(loop) for loop in walked]
    pieces = sorted((_float_ring(loop) for loop in loops), key=lambda a: (a[0, 0], a[0, 1]))
    if not trace:
        return pieces
    along = {
        **dict.fromkeys(window_kept, "window"),
        **dict.fromkeys(subject_kept, "subject"),
        **dict.fromkeys(shared, "both"),
    }
    contacts = on_window.keys() | on_subject.keys()
    walk = WeilerAthertonTrace.from_walk(subject_ring, window_ring, contacts, walked, along, pieces)
    return pieces, walk


def _exact_ring(polygon: object, name: str) -> list[Point]:
    """Validate a polygon and return its vertices counter-clockwise, as exact fractions."""
    floats = _validate.distinct_ring(_validate.polygon_array(polygon, name), name)
    ring = [(Fraction(x), Fraction(y)) for x, y in floats.tolist()]
    first, second = ring[0], ring[1]
    if all(_cross(_sub(second, first), _sub(p, first)) == 0 for p in ring):
        raise ValueError(f"{name} has zero area (its vertices are collinear)")
    _check_simple(ring, name)
    if sum(_cross(a, b) for a, b in _edges(ring)) < 0:  # a simple polygon's area is not 0
        ring.reverse()
    return ring


def _check_simple(ring: list[Point], name: str) -> None:
    """Raise if two edges meet anywhere except where neighbours share their vertex."""
    n = len(ring)
    edges = _edges(ring)
    for i, j in _candidate_pairs(ring, ring):
        if j <= i:
            continue
        contacts = _contacts(*edges[i], *edges[j])
        if j == i + 1:
            contacts = [c for c in contacts if c != (1, 0)]
        elif i == 0 and j == n - 1:
            contacts = [c for c in contacts if c != (0, 1)]
        if contacts:
            t = contacts[0][0]
            x, y = _along(edges[i], t)
            raise ValueError(
                f"{name} is self-intersecting: edges {i} and {j} meet at ({float(x):g}, "
                f"{float(y):g}); weiler_atherton needs simple polygons"
            )


def _cut_points(subject: list[Point], window: list[Point]):
    """Find every contact of the two boundaries.

    Returns, per subject edge and per window edge, the parameters in (0, 1) where the edge must
    be cut, and for each contact point where it lies on the window and on the subject.
    """
    subject_edges, window_edges = _edges(subject), _edges(window)
    subject_cuts: list[set[Fraction]] = [set() for _ in subject_edges]
    window_cuts: list[set[Fraction]] = [set() for _ in window_edges]
    on_window: dict[Point, tuple[int, int]] = {}
    on_subject: dict[Point, tuple[int, int]] = {}
    for i, j in _candidate_pairs(subject, window):
        for t, u in _contacts(*subject_edges[i], *window_edges[j]):
            point = _along(subject_edges[i], t)
            _locate(on_window, point, j, u, len(window))
            _locate(on_subject, point, i, t, len(subject))
            if 0 < t < 1:
                subject_cuts[i].add(t)
            if 0 < u < 1:
                window_cuts[j].add(u)
    return subject_cuts, window_cuts, on_window, on_subject


def _locate(where: dict[Point, tuple[int, int]], point: Point, edge: int, t: Fraction,
            size: int) -> None:
    """Record that ``point`` is at parameter ``t`` of ``edge``: a vertex or inside the edge."""
    if t == 0:
        where[point] = (VERTEX, edge)
    elif t == 1:
        where[point] = (VERTEX, (edge + 1) % size)
    else:
        where.setdefault(point, (EDGE_INTERIOR, edge))


def _candidate_pairs(a: list[Point], b: list[Point]) -> list[tuple[int, int]]:
    """Pairs of edges (one of ``a``, one of ``b``) that may touch: a float filter.

    Their bounding boxes meet, and neither edge lies wholly on one side of the other's line by
    more than the rounding error of the orientation test (the coordinates are the exact float
    inputs; the error bound is Shewchuk's for ``orient2d``). The exact test decides the rest.
    """
    points_a, points_b = _float_ring(a), _float_ring(b)
    ends_a, ends_b = np.roll(points_a, -1, axis=0), np.roll(points_b, -1, axis=0)
    lo_a, hi_a = np.minimum(points_a, ends_a), np.maximum(points_a, ends_a)
    lo_b, hi_b = np.minimum(points_b, ends_b), np.maximum(points_b, ends_b)
    i, j = _x_overlaps(lo_a[:, 0], hi_a[:, 0], lo_b[:, 0], hi_b[:, 0])
    meet = np.all((lo_a[i] <= hi_b[j]) & (lo_b[j] <= hi_a[i]), axis=1)
    i, j = i[meet], j[meet]
    p0, p1, q0, q1 = points_a[i], ends_a[i], points_b[j], ends_b[j]
    apart = _surely_one_side(p0, p1, q0, q1) | _surely_one_side(q0, q1, p0, p1)
    return list(zip(i[~apart].tolist(), j[~apart].tolist(), strict=True))


def _x_overlaps(
    lo_a: np.ndarray, hi_a: np.ndarray, lo_b: np.ndarray, hi_b: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs whose x-intervals may overlap, without testing all n x m pairs.

    With b's intervals sorted by their left end, an interval of b that overlaps [lo, hi] of a
    starts in [lo - widest, hi] (widest: b's widest interval), a range found by bisection.
    """
    order = np.argsort(lo_b, kind="stable")
    starts = lo_b[order]
    # Near ±1.8e308 a width or a reach can overflow to inf: the search then starts at the
    # first interval, which only adds candidates for the exact test to discard.
    with np.errstate(over="ignore"):
        widest = float(np.max(hi_b - lo_b))
        reach = np.nextafter(lo_a - widest, -np.inf)  # rounding must not lose a candidate
    first = np.searchsorted(starts, reach, side="left")
    count = np.searchsorted(starts, hi_a, side="right") - first
    i = np.repeat(np.arange(lo_a.size), count)
    offset = np.arange(i.size) - np.repeat(np.cumsum(count) - count, count)
    return i, order[np.repeat(first, count) + offset]


# (3 + 16 eps) eps with eps = 2**-53, rounded up: bounds the error of the float orientation.
_ORIENT_ERROR = 3.4e-16


def _surely_one_side(a: np.ndarray, b: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Whether c and d lie strictly on the same side of line ab, beyond rounding doubt."""
    side_c, error_c = _orient(a, b, c)
    side_d, error_d = _orient(a, b, d)
    with np.errstate(invalid="ignore", over="ignore"):  # overflow: NaN, never "surely"
        return ((side_c > error_c) & (side_d > error_d)) | (
            (side_c < -error_c) & (side_d < -error_d)
        )


def _orient(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    with np.errstate(invalid="ignore", over="ignore"):
        left = (a[:, 0] - c[:, 0]) * (b[:, 1] - c[:, 1])
        right = (a[:, 1] - c[:, 1]) * (b[:, 0] - c[:, 0])
        return left - right, _ORIENT_ERROR * (np.abs(left) + np.abs(right))


def _float_ring(ring: list[Point]) -> np.ndarray:
    return np.array([(float(x), float(y)) for x, y in ring], dtype=np.float64).reshape(-1, 2)


def _contacts(p0: Point, p1: Point, q0: Point, q1: Point) -> list[tuple[Fraction, Fraction]]:
    """Parameters ``(t, u)`` of the points shared by segments p0p1 and q0q1.

    A crossing or touching gives one pair; a collinear overlap gives its end points.
    """
    r, s, qp = _sub(p1, p0), _sub(q1, q0), _sub(q0, p0)
    denom = _cross(r, s)
    if denom != 0:
        t, u = _cross(qp, s) / denom, _cross(qp, r) / denom
        return [(t, u)] if 0 <= t <= 1 and 0 <= u <= 1 else []
    if _cross(qp, r) != 0:
        return []  # parallel, on different lines
    rr, ss = _dot(r, r), _dot(s, s)
    found = []
    for q, u in ((q0, Fraction(0)), (q1, Fraction(1))):
        t = _dot(_sub(q, p0), r) / rr
        if 0 <= t <= 1:
            found.append((t, u))
    for p, t in ((p0, Fraction(0)), (p1, Fraction(1))):
        u = _dot(_sub(p, q0), s) / ss
        if 0 <= u <= 1:
            found.append((t, u))
    return found


def _split(ring: list[Point], cuts: list[set[Fraction]]) -> list[Segment]:
    """Cut each edge at its parameters; return the pieces in ring order."""
    pieces = []
    for edge, params in zip(_edges(ring), cuts, strict=True):
        points = [edge[0], *(_along(edge, t) for t in sorted(params)), edge[1]]
        pieces.extend(itertools.pairwise(points))
    return pieces


def _inside_pieces(
    pieces: list[Segment],
    other: list[Point],
    on_other: dict[Point, tuple[int, int]],
    skip: set[Segment],
) -> list[Segment]:
    """Return the pieces (not in ``skip``) strictly inside ``other``.

    A piece's side can change only where the ring touches ``other``, so it is decided once per
    run, locally, at the contact point the run starts from; a ring that never touches
    ``other`` takes one point-in-polygon test.
    """
    starts = [k for k, piece in enumerate(pieces) if piece[0] in on_other]
    if not starts:
        return pieces if _strictly_inside(_midpoint(pieces[0]), other) else []
    kept, inside = [], False
    for k in range(starts[0], starts[0] + len(pieces)):
        piece = pieces[k % len(pieces)]
        if piece in skip:
            continue
        if piece[0] in on_other:
            inside = _leaves_inside(piece, other, on_other[piece[0]])
        if inside:
            kept.append(piece)
    return kept


def _leaves_inside(piece: Segment, ring: list[Point], where: tuple[int, int]) -> bool:
    """Whether ``piece``, starting on the boundary of ``ring``, heads into its interior."""
    start, end = piece
    heading = _sub(end, start)
    kind, index = where
    if kind == EDGE_INTERIOR:  # the interior is the open half-plane left of the edge
        return _cross(_sub(ring[(index + 1) % len(ring)], ring[index]), heading) > 0
    # At a vertex the interior is the sector swept counter-clockwise from the outgoing edge
    # to the incoming edge reversed.
    outgoing = _sub(ring[(index + 1) % len(ring)], start)
    incoming_reversed = _sub(ring[index - 1], start)
    return _ccw_quarter(outgoing, heading) != 0 and _ccw_before(
        outgoing, heading, incoming_reversed
    )


def _strictly_inside(p: Point, ring: list[Point]) -> bool:
    """Winding-number test; ``p`` is known not to lie on the boundary."""
    winding = 0
    for a, b in _edges(ring):
        side = _cross(_sub(b, a), _sub(p, a))
        if a[1] <= p[1] < b[1] and side > 0:
            winding += 1
        elif b[1] <= p[1] < a[1] and side < 0:
            winding -= 1
    return winding != 0


def _link(pieces: list[Segment]) -> list[list[Point]]:
    """Join directed pieces into closed loops with the clockwise-first turn rule."""
    leaving: dict[Point, list[int]] = {}
    for k, (start, _) in enumerate(pieces):
        leaving.setdefault(start, []).append(k)
    successor = [_next_piece(pieces, k, leaving[pieces[k][1]]) for k in range(len(pieces))]
    used = [False] * len(pieces)
    loops = []
    for first in range(len(pieces)):
        loop, k = [], first
        while not used[k]:
            used[k] = True
            loop.append(pieces[k][0])
            k = successor[k]
        if loop:
            if k != first:
                raise RuntimeError("weiler_atherton: inconsistent boundary (please report)")
            loops.append(loop)
    return loops


def _next_piece(pieces: list[Segment], k: int, candidates: list[int]) -> int:
    """Return the candidate reached first turning clockwise from the reverse of piece ``k``.

    That is the one with the largest counter-clockwise angle from the reverse direction: it
    bounds the interior sector on the left of piece ``k``.
    """
    start, end = pieces[k]
    back = _sub(start, end)
    best, best_heading = candidates[0], _sub(pieces[candidates[0]][1], end)
    for c in candidates[1:]:
        heading = _sub(pieces[c][1], end)
        if _ccw_before(back, best_heading, heading):
            best, best_heading = c, heading
    return best


def _ccw_before(ref: Point, d1: Point, d2: Point) -> bool:
    """Whether d1 comes strictly before d2 turning counter-clockwise from ``ref``."""
    q1, q2 = _ccw_quarter(ref, d1), _ccw_quarter(ref, d2)
    if q1 != q2:
        return q1 < q2
    return q1 in (1, 3) and _cross(d1, d2) > 0


def _ccw_quarter(ref: Point, d: Point) -> int:
    """0: angle 0 from ``ref``; 1: in (0, pi); 2: pi; 3: in (pi, 2 pi)."""
    cross, dot = _cross(ref, d), _dot(ref, d)
    if cross > 0:
        return 1
    if cross < 0:
        return 3
    return 0 if dot > 0 else 2


def _drop_straight_vertices(loop: list[Point]) -> list[Point]:
    n = len(loop)
    kept = [
        loop[i]
        for i in range(n)
        if _cross(_sub(loop[i], loop[i - 1]), _sub(loop[(i + 1) % n], loop[i])) != 0
    ]
    lowest = min(range(len(kept)), key=lambda i: (kept[i][0], kept[i][1]))
    return kept[lowest:] + kept[:lowest]


def _edges(ring: list[Point]) -> list[Segment]:
    return list(zip(ring, ring[1:] + ring[:1], strict=True))


def _along(edge: Segment, t: Fraction) -> Point:
    (x0, y0), (x1, y1) = edge
    return (x0 + t * (x1 - x0), y0 + t * (y1 - y0))


def _midpoint(piece: Segment) -> Point:
    (x0, y0), (x1, y1) = piece
    return ((x0 + x1) / 2, (y0 + y1) / 2)


def _sub(a: Point, b: Point) -> Point:
    return (a[0] - b[0], a[1] - b[1])


def _cross(a: Point, b: Point) -> Fraction:
    return a[0] * b[1] - a[1] * b[0]


def _dot(a: Point, b: Point) -> Fraction:
    return a[0] * b[0] + a[1] * b[1]
