"""Hidden-surface exercises about an order of drawing: the painter's depth sort and a BSP tree.

The painter's exercise decides each pair with :func:`pixelpath.hsr.painter.compare`, the
renderer's own six tests, seen by an orthographic camera looking down the depth axis; only the
bookkeeping of the sorted list (which pair is compared next, which polygon moves) is written
out here, at exam scale. The BSP exercise is a tree of walls in the plane seen from above, built
with the splitting walls taken in a given order, as an exam fixes it (the renderer's
:func:`pixelpath.hsr.bsp.build_tree` chooses its own planes).
"""

from __future__ import annotations

import dataclasses
import random
from fractions import Fraction

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.hidden_screen import frame_buffer, polygon_table, screen_figure
from pixelpath.exercises.topics import Solved

__all__ = ["Wall", "back_to_front", "build_bsp", "depth_sort"]

# The painter's screen: 10 × 10 units, depth z from 1 to 9 (smaller is nearer).
_SCREEN = 10


# ------------------------------------------------------------------ the painter's algorithm

class _Split(Exception):
    """Neither order of a pair is proved, or a polygon must move twice: it would be split."""


def _camera():
    from pixelpath.scene import Camera

    # Looking down −z: world (x, y, −z) for a screen point (x, y) at depth z.
    middle = _SCREEN / 2
    return Camera(eye=(middle, middle, 50.0), target=(middle, middle, 0.0), width=100,
                  height=100, projection="orthographic", view_height=float(_SCREEN))


def depth_sort(polygons: dict) -> tuple[list[str], list[tuple[str, str, str]], list[str]]:
    """Run the depth sort of the painter's algorithm on triangles given as (x, y, z) corners.

    Returns
    -------
    sorted : list of str
        The triangles by farthest depth, farthest first (ties alphabetically).
    comparisons : list of (P, Q, result)
        Each pair whose depth extents overlap, as first compared: the test (``"2"`` to
        ``"6"``) that lets P be painted before Q, or ``"swap"`` when all fail and Q moves
        before P.
    order : list of str
        The drawing order, far to near.

    Raises
    ------
    ValueError
        If a pair would have to be split (interpenetrating or cyclically overlapping).

    Examples
    --------
    >>> far = [[0, 0, 8], [6, 0, 8], [0, 6, 8]]
    >>> near = [[1, 1, 3], [7, 1, 9], [1, 7, 3]]
    >>> depth_sort({"A": far, "B": near})
    (['B', 'A'], [('B', 'A', 'swap'), ('A', 'B', '4')], ['A', 'B'])
    """
    camera = _camera()
    world = {name: [(x, y, -z) for x, y, z in v] for name, v in polygons.items()}
    pending = sorted(polygons, key=lambda name: (-max(v[2] for v in polygons[name]), name))
    ranked = list(pending)
    comparisons: dict[tuple[str, str], str] = {}
    moved: set[str] = set()
    order: list[str] = []
    while pending:
        mover = _first_to_move(pending, world, camera, comparisons)
        if mover is None:
            order.append(pending.pop(0))
            continue
        if mover in moved:
            raise ValueError(f"{pending[0]} and {mover} cannot be ordered without splitting")
        moved.add(mover)
        pending.remove(mover)
        pending.insert(0, mover)
    return ranked, [(p, q, r) for (p, q), r in comparisons.items()], order


def _first_to_move(pending: list[str], world: dict, camera,
                   comparisons: dict[tuple[str, str], str]) -> str | None:
    """Compare the head P with the rest; return the first Q that must be painted before it."""
    from pixelpath.hsr.painter import compare

    p = pending[0]
    for q in pending[1:]:
        test, outcome = compare(world[p], world[q], camera)
        if test == 1:
            return None  # sorted by farthest depth: every later Q is entirely nearer too
        comparisons.setdefault((p, q), str(test) if test else "swap")
        if outcome == "split":
            raise ValueError(f"{p} and {q} cannot be ordered without splitting")
        if outcome == "Q first":
            return q
    return None


def _triangle(rng: random.Random, far: int) -> list[list[int]]:
    """Draw a triangle with a corner at depth ``far`` and the others up to 5 nearer."""
    while True:
        depths = [far, rng.randint(max(1, far - 5), far), rng.randint(max(1, far - 5), far)]
        rng.shuffle(depths)
        corners = [[rng.randint(0, _SCREEN), rng.randint(0, _SCREEN), z] for z in depths]
        (ax, ay, _), (bx, by, _), (cx, cy, _) = corners
        area2 = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if abs(area2) >= 12:
            return corners if area2 > 0 else corners[::-1]


def _pick_painter(rng: random.Random, difficulty: str) -> dict:
    """Triangles that overlap in depth somewhere, no two farthest depths alike, no split."""
    count = 3 if difficulty == "easy" else rng.choice((3, 4))
    while True:
        fars = list(range(4, 10))
        rng.shuffle(fars)
        if difficulty == "edge" and rng.random() < 0.3:
            fars[1] = fars[0]  # a tie in farthest depth, broken alphabetically
        polygons = {name: _triangle(rng, fars[k]) for k, name in enumerate("ABCD"[:count])}
        try:
            _, comparisons, _ = depth_sort(polygons)
        except ValueError:
            continue
        if comparisons:
            return {"width": _SCREEN, "height": _SCREEN, "polygons": polygons}


_TESTS = (
    "1. the depth extents do not overlap (Q is entirely nearer)",
    "2. the x extents on the screen do not overlap",
    "3. the y extents on the screen do not overlap",
    "4. P lies entirely on the far side of Q's plane",
    "5. Q lies entirely on the near side of P's plane",
    "6. the projections of P and Q do not overlap",
)


def solve_painter(params: dict) -> Solved:
    """Solve a painter's exercise: the sorted list, the tests that settled each pair, the order.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_painter(exercises.make("painter", seed=1).params).answer["order"]
    ['D', 'C', 'B', 'A']
    """
    polygons = params["polygons"]
    ranked, comparisons, order = depth_sort(polygons)
    extents = [f"{name}: z from {shown(min(v[2] for v in polygons[name]))} to "
               f"{shown(max(v[2] for v in polygons[name]))}" for name in ranked]
    answer = {"sorted": ranked, **{f"test_{p}{q}": r for p, q, r in comparisons},
              "order": order}
    fields = (Field("sorted", "the polygons by farthest depth, farthest first", 1,
                    kind="sequence", required=False),
              *(Field(f"test_{p}{q}", f"the test that settles P = {p}, Q = {q}", 2,
                      kind="choice", required=False) for p, q, _ in comparisons),
              Field("order", "the drawing order, far to near", 3, kind="sequence"))
    pair_lines = [f"P = {p}, Q = {q}: " + (f"test {r} holds → {p} may be painted before {q}"
                                           if r != "swap" else
                                           f"all tests fail, and reversed ({q} cannot hide "
                                           f"{p}) → {q} moves before {p}")
                  for p, q, r in comparisons]
    steps = (
        Step("Sort by farthest depth", (*extents, f"Sorted: {', '.join(ranked)}")),
        Step("Test the pairs whose depth extents overlap", (*pair_lines,)),
        Step("Paint", (f"Painting far to near: {', '.join(order)}",)),
    )
    question = (
        f"Three-dimensional triangles are seen in parallel projection along z (smaller z is "
        f"nearer); their screen coordinates are (x, y).\n\n{polygon_table(polygons)}\n\n"
        "![The triangles on the screen](FIGURE)\n\n"
        "Apply the painter's algorithm (depth sort). (a) Sort the triangles by farthest depth, "
        "farthest first (a tie in alphabetical order). (b) Take P, the first of the list; for "
        "each Q whose depth extent overlaps P's, give the first of these tests that holds "
        "(extents that only touch do not overlap; a vertex on a plane counts as on either "
        "side):\n\n"
        + "\n".join(f"- {test}" for test in _TESTS[1:]) +
        "\n\nor 'swap' when none holds and Q is moved before P (as test_PQ, e.g. test_AB). "
        "Paint P when every such Q is settled and go on with the rest of the list. "
        "(c) Give the drawing order, far to near."
    )
    return Solved(question, answer, fields, steps,
                  "The order must be exact; each test number must be the first test that holds.",
                  draw=lambda solution: screen_figure(
                      params, frame_buffer(params)[0] if solution else None))


# ------------------------------------------------------------------ BSP trees

@dataclasses.dataclass
class Wall:
    """A wall (or a piece of one) seen from above, and its place in a BSP tree.

    Its front is the side its normal (−(y2 − y1), x2 − x1) points to: the left of the walk
    from ``start`` to ``end``.

    Examples
    --------
    >>> wall = Wall("A", (0, 0), (4, 0))
    >>> wall.normal, wall.side((1, 3)), wall.side((1, -1))
    ((0, 4), 12, -4)
    """

    name: str
    start: tuple[Fraction, Fraction]
    end: tuple[Fraction, Fraction]
    front: Wall | None = None
    back: Wall | None = None

    @property
    def normal(self) -> tuple[Fraction, Fraction]:
        """The front normal (not of unit length)."""
        return -(self.end[1] - self.start[1]), self.end[0] - self.start[0]

    def side(self, point) -> Fraction:
        """N · (X − start): positive in front, negative behind, zero on the wall's line."""
        nx, ny = self.normal
        return nx * (point[0] - self.start[0]) + ny * (point[1] - self.start[1])


def build_bsp(walls: dict) -> Wall | None:
    """Build the BSP tree of walls, each list's first wall splitting the rest.

    A wall crossing the splitting wall's line is cut there: the piece in front is named
    with ``1`` appended, the piece behind with ``2``.

    Examples
    --------
    >>> root = build_bsp({"A": [[0, 0], [4, 0]], "B": [[1, 1], [3, 2]], "C": [[2, -1], [2, -3]]})
    >>> root.name, root.front.name, root.back.name
    ('A', 'B', 'C')
    """
    pieces = [Wall(name, *(tuple(map(Fraction, point)) for point in ends))
              for name, ends in walls.items()]
    return _build(pieces)


def _build(pieces: list[Wall]) -> Wall | None:
    if not pieces:
        return None
    root, front, back = pieces[0], [], []
    for wall in pieces[1:]:
        a, b = root.side(wall.start), root.side(wall.end)
        if a >= 0 and b >= 0:
            front.append(wall)
        elif a <= 0 and b <= 0:
            back.append(wall)
        else:
            t = a / (a - b)
            cut = tuple(s + t * (e - s) for s, e in zip(wall.start, wall.end, strict=True))
            ahead, behind = (wall.start, wall.end) if a > 0 else (wall.end, wall.start)
            front.append(Wall(f"{wall.name}1", *_same_way(wall, ahead, cut)))
            back.append(Wall(f"{wall.name}2", *_same_way(wall, behind, cut)))
    root.front, root.back = _build(front), _build(back)
    return root


def _same_way(wall: Wall, end, cut) -> tuple:
    """Order a piece (``end`` to the cut) like its wall, so that it keeps the wall's front."""
    return (end, cut) if end == wall.start else (cut, end)


def _preorder(node: Wall | None) -> list[str]:
    if node is None:
        return ["-"]
    return [node.name, *_preorder(node.front), *_preorder(node.back)]


def _nodes(node: Wall | None) -> list[Wall]:
    return [] if node is None else [node, *_nodes(node.front), *_nodes(node.back)]


def back_to_front(node: Wall | None, eye) -> list[str]:
    """List a BSP tree's walls back to front from ``eye``: the far side, the node, the near side.

    Examples
    --------
    >>> root = build_bsp({"A": [[0, 0], [4, 0]], "B": [[1, 1], [3, 2]], "C": [[2, -1], [2, -3]]})
    >>> back_to_front(root, (2, 5)), back_to_front(root, (2, -5))
    (['C', 'A', 'B'], ['B', 'A', 'C'])
    """
    if node is None:
        return []
    near, far = (node.front, node.back) if node.side(eye) > 0 else (node.back, node.front)
    return [*back_to_front(far, eye), node.name, *back_to_front(near, eye)]


def _orientation(a, b, c) -> int:
    value = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (value > 0) - (value < 0)


def _fair_walls(walls: dict, eye: list[int]) -> bool:
    """Walls apart, no end on another's line, the eye on no line, no piece cut twice."""
    segments = list(walls.values())
    for wall in segments:
        if _orientation(*wall, eye) == 0:
            return False
        for other in segments:
            if other is wall:
                continue
            sides = {_orientation(*wall, other[0]), _orientation(*wall, other[1])}
            if 0 in sides:
                return False
            # With no end on the other's line, two walls cross exactly when each one's
            # ends lie on both sides of the other's line.
            if len(sides) == 2 and len({_orientation(*other, end) for end in wall}) == 2:
                return False
    return all(len(node.name) <= 2 for node in _nodes(build_bsp(walls)))


def _pick_bsp(rng: random.Random, difficulty: str) -> dict:
    count = 3 if difficulty == "easy" else 4
    while True:
        walls = {}
        for name in "ABCD"[:count]:
            start = [rng.randint(0, _SCREEN), rng.randint(0, _SCREEN)]
            end = [min(max(c + rng.randint(-4, 4), 0), _SCREEN) for c in start]
            walls[name] = [start, end]
        eye = [rng.randint(0, _SCREEN), rng.randint(0, _SCREEN)]
        if any(s == e for s, e in walls.values()) or not _fair_walls(walls, eye):
            continue
        splits = sum(len(node.name) > 1 for node in _nodes(build_bsp(walls)))
        if difficulty == "edge" or (splits <= 2 and (splits > 0) == (difficulty != "easy")):
            return {"walls": walls, "eye": eye}


def solve_bsp(params: dict) -> Solved:
    """Solve a BSP exercise: the tree in preorder, the eye's sides, the back-to-front order.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_bsp(exercises.make("bsp", seed=1).params).answer["order"]
    ['C1', 'A', 'C2', 'B', 'D']
    """
    walls, eye = params["walls"], params["eye"]
    root = build_bsp(walls)
    nodes = _nodes(root)
    tree = _preorder(root)
    order = back_to_front(root, eye)
    eye_front = [node.name for node in nodes if node.side(eye) > 0]
    answer = {"tree": tree, "eye_front": eye_front, "order": order}
    fields = (Field("tree", "the tree in preorder (node, front, back; - for none)", 1,
                    kind="sequence"),
              Field("eye_front", "the nodes whose front side the eye is on", 2, kind="set",
                    required=False),
              Field("order", "the walls back to front", 3, kind="sequence"))
    build_lines = [f"{node.name}: front {_name(node.front)}, back {_name(node.back)}"
                   for node in nodes]
    cuts = [f"{node.name} = {_segment(node)}" for node in nodes if len(node.name) > 1]
    steps = (
        Step("Build the tree", (
            "Each list's first wall splits the rest by the sign of N · (X − P1) at both ends; "
            "a wall with ends on both sides is cut where it crosses the line.",
            *build_lines, *(["Pieces: " + "; ".join(cuts)] if cuts else []),
            f"Preorder: {' '.join(tree)}")),
        Step("Which side the eye is on", tuple(
            f"{node.name}: N · (E − P1) = {shown(float(node.side(eye)))} → eye "
            f"{'in front' if node.side(eye) > 0 else 'behind'}" for node in nodes)),
        Step("Back to front", (
            "At each node draw the subtree on the far side from the eye, the node, then the "
            f"near side: {', '.join(order)}",)),
    )
    table = "\n".join(["| wall | from P1 | to P2 | front normal N |", "|---|---|---|---|",
                       *(f"| {node.name} | {shown(ends[0])} | {shown(ends[1])} | "
                         f"{shown([float(v) for v in node.normal])} |"
                         for node, ends in zip(_flat(walls), walls.values(), strict=True))])
    question = (
        f"Walls seen from above (x, y in the plane):\n\n{table}\n\n"
        f"![The walls and the eye](FIGURE)\n\nThe front of a wall is the side its normal "
        f"N = (−(y2 − y1), x2 − x1) points to. The eye is at E = {shown(eye)}. "
        "(a) Build the BSP tree taking the splitting walls in alphabetical order (the first "
        "of each list). A wall cut by a splitting line becomes two pieces: the one in front "
        "gets 1 appended to its name, the one behind 2 (C1, C2). Write the tree in preorder: "
        "a node, its front subtree, its back subtree, '-' for an empty subtree. (b) Which "
        "nodes have the eye on their front side? (c) Give the back-to-front display order "
        "from E."
    )
    return Solved(question, answer, fields, steps,
                  "The tree, the set and the order must be exact.",
                  draw=lambda solution: _bsp_figure(params, root if solution else None))


def _flat(walls: dict) -> list[Wall]:
    return [Wall(name, *(tuple(map(Fraction, p)) for p in ends)) for name, ends in walls.items()]


def _name(node: Wall | None) -> str:
    return "-" if node is None else node.name


def _segment(node: Wall) -> str:
    return " to ".join(shown([float(v) for v in point]) for point in (node.start, node.end))


def _bsp_figure(params: dict, root: Wall | None):
    from pixelpath.figures._canvas import Sketch, View

    walls = params["walls"]
    points = [p for ends in walls.values() for p in ends] + [params["eye"]]
    sketch = Sketch(640, 420)
    view = View(points, (20, 20, 380, 380), pad=0.12)
    pieces = _flat(walls) if root is None else _nodes(root)
    order = back_to_front(root, params["eye"]) if root is not None else []
    for k, piece in enumerate(pieces):
        start, end = ([float(v) for v in p] for p in (piece.start, piece.end))
        sketch.segment(view, start, end, f"object {k % 6 + 1}", width=4)
        middle = [(start[0] + end[0]) / 2, (start[1] + end[1]) / 2]
        nx, ny = (float(v) for v in piece.normal)
        length = max((nx * nx + ny * ny) ** 0.5, 1e-9)
        tip = [middle[0] + 0.6 * nx / length, middle[1] + 0.6 * ny / length]
        sketch.segment(view, middle, tip, "muted", width=2)
        label = piece.name if root is None else f"{piece.name} ({order.index(piece.name) + 1})"
        sketch.label(view, middle, label)
    sketch.dots(view, [params["eye"]], "emitted")
    sketch.label(view, params["eye"], "E")
    if root is not None:
        rows = [[f"{'   ' * depth}{side}{node.name}"] for depth, side, node in _outline(root)]
        sketch.columns(420, 30, [["BSP tree (front, back)"], *rows])
    return sketch.image


def _outline(node: Wall, depth: int = 0, side: str = "") -> list[tuple[int, str, Wall]]:
    rows = [(depth, side, node)]
    for child, mark in ((node.front, "front: "), (node.back, "back: ")):
        if child is not None:
            rows.extend(_outline(child, depth + 1, mark))
    return rows
