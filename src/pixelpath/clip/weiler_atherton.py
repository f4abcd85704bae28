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
   the window's boundary when it lies inside the subject (tested at its midpoint, which is
   never on the other boundary). A piece both boundaries share is kept once when both
   interiors lie on the same side of it and dropped when they lie on opposite sides (the
   polygons only touch there).
4. The kept pieces are linked into loops: arriving at a point, the walk leaves along the first
   kept piece clockwise from the way it came, which is Weiler-Atherton's switch between the
   two vertex lists. This turn rule keeps pieces that touch at a single point apart. Every
   piece is used once, so the walk ends after at most as many steps as there are pieces.

Because the arithmetic is exact, no symbolic perturbation is needed: a vertex on an edge is on
it, and touching is touching. Results: subject inside the window gives the subject, window
inside the subject gives the window, identical polygons give the polygon, touching without
overlap (at a point or along an edge) gives nothing. Collinear vertices are dropped from the
output and each piece starts at its lowest-leftmost vertex. Self-intersecting input is
rejected with a ``ValueError`` naming the two edges that meet.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import numpy as np

from pixelpath.clip import _validate
from pixelpath.clip.window import ConvexWindow, Rect

__all__ = ["weiler_atherton"]

Point = tuple[Fraction, Fraction]
Segment = tuple[Point, Point]


def weiler_atherton(subject: np.ndarray, window: object) -> list[np.ndarray]:
    """Clip a polygon against a window, either of them concave, into separate pieces.

    Parameters
    ----------
    subject : (N, 2) array_like
        A simple polygon (no self-intersection), either orientation.
    window : Rect or (K, 2) array_like
        A :class:`~pixelpath.clip.Rect` or a simple polygon, either orientation.

    Returns
    -------
    list of (Mi, 2) ndarray
        The pieces of the intersection, each counter-clockwise; an empty list when the
        polygons do not overlap. Pieces that touch only at a vertex are separate.

    Raises
    ------
    ValueError
        For fewer than 3 distinct vertices, a non-finite coordinate, zero area or a
        self-intersecting polygon.
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
    subject_cuts, window_cuts, contacts = _cut_points(subject_ring, window_ring)
    subject_pieces = _split(subject_ring, subject_cuts)
    window_pieces = _split(window_ring, window_cuts)
    kept = _keep_inside(subject_pieces, window_pieces, subject_ring, window_ring, contacts)
    loops = [_drop_straight_vertices(loop) for loop in _link(kept)]
    return sorted((_to_array(loop) for loop in loops), key=lambda a: (a[0, 0], a[0, 1]))


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


def _cut_points(
    subject: list[Point], window: list[Point]
) -> tuple[list[set[Fraction]], list[set[Fraction]], set[Point]]:
    """Find every contact of the two boundaries.

    Returns, per subject edge and per window edge, the parameters in (0, 1) where the edge must
    be cut, and the set of all contact points.
    """
    subject_edges, window_edges = _edges(subject), _edges(window)
    subject_cuts: list[set[Fraction]] = [set() for _ in subject_edges]
    window_cuts: list[set[Fraction]] = [set() for _ in window_edges]
    contacts: set[Point] = set()
    for i, j in _candidate_pairs(subject, window):
        for t, u in _contacts(*subject_edges[i], *window_edges[j]):
            contacts.add(_along(subject_edges[i], t))
            if 0 < t < 1:
                subject_cuts[i].add(t)
            if 0 < u < 1:
                window_cuts[j].add(u)
    return subject_cuts, window_cuts, contacts


def _candidate_pairs(a: list[Point], b: list[Point]) -> list[tuple[int, int]]:
    """Pairs of edges whose bounding boxes meet (a cheap float filter; floats are exact here)."""
    boxes_a, boxes_b = _boxes(a), _boxes(b)
    meet = (
        (boxes_a[:, None, 0] <= boxes_b[None, :, 2])
        & (boxes_b[None, :, 0] <= boxes_a[:, None, 2])
        & (boxes_a[:, None, 1] <= boxes_b[None, :, 3])
        & (boxes_b[None, :, 1] <= boxes_a[:, None, 3])
    )
    return list(zip(*(idx.tolist() for idx in np.nonzero(meet)), strict=True))


def _boxes(ring: list[Point]) -> np.ndarray:
    points = np.array([(float(x), float(y)) for x, y in ring])
    ends = np.roll(points, -1, axis=0)
    return np.hstack([np.minimum(points, ends), np.maximum(points, ends)])


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


def _keep_inside(
    subject_pieces: list[Segment],
    window_pieces: list[Segment],
    subject: list[Point],
    window: list[Point],
    contacts: set[Point],
) -> list[Segment]:
    """Return the boundary pieces of the intersection, each directed counter-clockwise."""
    window_set = set(window_pieces)
    shared = [p for p in subject_pieces if p in window_set]
    opposed = [p for p in subject_pieces if (p[1], p[0]) in window_set]
    on_both = {*shared, *opposed, *((b, a) for a, b in opposed)}
    kept = shared
    kept += _inside_pieces(subject_pieces, window, contacts, on_both)
    kept += _inside_pieces(window_pieces, subject, contacts, on_both)
    return kept


def _inside_pieces(
    pieces: list[Segment], other: list[Point], contacts: set[Point], skip: set[Segment]
) -> list[Segment]:
    """Pieces strictly inside ``other``; one midpoint test per run between contact points."""
    kept, inside = [], False
    fresh_run = True
    for piece in pieces:
        if piece in skip:
            fresh_run = True
            continue
        if fresh_run or piece[0] in contacts:
            inside = _strictly_inside(_midpoint(piece), other)
            fresh_run = False
        if inside:
            kept.append(piece)
    return kept


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
    """Return the candidate reached first turning clockwise from the reverse of piece ``k``."""
    start, end = pieces[k]
    back = _sub(start, end)
    best, best_key = -1, None
    for c in candidates:
        d = _sub(pieces[c][1], end)
        if best_key is None or _turns_before(back, d, best_key):
            best, best_key = c, d
    return best


def _turns_before(ref: Point, d1: Point, d2: Point) -> bool:
    """Whether d1 comes strictly before d2 turning clockwise from ``ref``."""
    h1, h2 = _clockwise_half(ref, d1), _clockwise_half(ref, d2)
    if h1 != h2:
        return h1 < h2
    return h1 in (0, 2) and _cross(d1, d2) < 0


def _clockwise_half(ref: Point, d: Point) -> int:
    """0: clockwise angle in (0, pi); 1: pi; 2: (pi, 2 pi); 3: zero (going straight back)."""
    cross, dot = _cross(ref, d), _dot(ref, d)
    if cross < 0:
        return 0
    if cross > 0:
        return 2
    return 1 if dot < 0 else 3


def _drop_straight_vertices(loop: list[Point]) -> list[Point]:
    n = len(loop)
    kept = [
        loop[i]
        for i in range(n)
        if _cross(_sub(loop[i], loop[i - 1]), _sub(loop[(i + 1) % n], loop[i])) != 0
    ]
    lowest = min(range(len(kept)), key=lambda i: (kept[i][0], kept[i][1]))
    return kept[lowest:] + kept[:lowest]


def _to_array(loop: list[Point]) -> np.ndarray:
    return np.array([(float(x), float(y)) for x, y in loop], dtype=np.float64)


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
