"""Warnock's area subdivision as an exam question: rectangles of one depth each on 8 × 8 pixels.

Rectangles with whole-number corners make the classification of a polygon against an area
(surrounding, intersecting, contained, disjoint) the same whether it is read off the outlines,
as a student does, or off the pixel centres, as the renderer's Warnock method does; its frame
is the one these subdivisions give (the tests compare them). The renderer cuts polygons into
triangles, so its own areas differ from an exam's; the rules are the same:

1. no polygon reaches the area: empty;
2. exactly one reaches it: draw it (single);
3. a surrounding polygon is nearer than every other reaching the area: fill with it (front);

otherwise the area is cut into four, down to single pixels, where the nearest polygon at the
centre wins (pixel).
"""

from __future__ import annotations

import random
from collections.abc import Sequence

from pixelpath.exercises.exercise import Field, Step
from pixelpath.exercises.hidden_screen import (
    BACKGROUND,
    frame_buffer,
    grid_lines,
    picker,
    polygon_table,
    screen_figure,
    screen_words,
)
from pixelpath.exercises.topics import Solved

__all__ = ["warnock_areas"]

Vertex = Sequence[float]

_CASES = {"surrounding": "S", "intersecting": "I", "contained": "C", "disjoint": "D"}
_DECISIONS = ("empty", "single", "front", "pixel")


def _box(vertices: Sequence[Vertex]) -> tuple[float, float, float, float]:
    xs, ys = [v[0] for v in vertices], [v[1] for v in vertices]
    return min(xs), max(xs), min(ys), max(ys)


def _classify(vertices: Sequence[Vertex], area: tuple[int, int, int, int]) -> str:
    """Classify a rectangle against an area (x0, x1, y0, y1): surrounding, intersecting, ..."""
    x0, x1, y0, y1 = _box(vertices)
    ax0, ax1, ay0, ay1 = area
    if x1 <= ax0 or x0 >= ax1 or y1 <= ay0 or y0 >= ay1:
        return "disjoint"
    if x0 <= ax0 and x1 >= ax1 and y0 <= ay0 and y1 >= ay1:
        return "surrounding"
    if x0 >= ax0 and x1 <= ax1 and y0 >= ay0 and y1 <= ay1:
        return "contained"
    return "intersecting"


def _quadrants(area: tuple[int, int, int, int]) -> list[tuple[int, int, int, int]]:
    """Quadrants 1..4: top left, top right, bottom left, bottom right."""
    x0, x1, y0, y1 = area
    xm, ym = (x0 + x1) // 2, (y0 + y1) // 2
    return [(x0, xm, ym, y1), (xm, x1, ym, y1), (x0, xm, y0, ym), (xm, x1, y0, ym)]


def warnock_areas(params: dict) -> list[tuple[str, tuple[int, int, int, int], str, list[str]]]:
    """Run Warnock's subdivision on rectangles of constant depth, depth first.

    Returns one row per area examined: its name (``"R"`` the screen, then a digit per
    quadrant: 1 top left, 2 top right, 3 bottom left, 4 bottom right), its extent (x0, x1,
    y0, y1), how it was decided (``"empty"``, ``"single"``, ``"front"``, ``"pixel"`` or
    ``"subdivided"``) and the polygons reaching it.

    Examples
    --------
    >>> params = {"width": 2, "height": 2, "polygons": {
    ...     "A": [[0, 0, 5], [2, 0, 5], [2, 2, 5], [0, 2, 5]],
    ...     "B": [[1, 0, 3], [2, 0, 3], [2, 1, 3], [1, 1, 3]]}}
    >>> [(name, decision) for name, _, decision, _ in warnock_areas(params)]
    [('R', 'subdivided'), ('R1', 'single'), ('R2', 'single'), ('R3', 'single'), ('R4', 'front')]
    """
    polygons = params["polygons"]
    rows: list = []

    def visit(name: str, area: tuple[int, int, int, int], candidates: list[str]) -> None:
        reaching = [p for p in candidates if _classify(polygons[p], area) != "disjoint"]
        rows.append((name, area, _decide(polygons, area, reaching), reaching))
        if rows[-1][2] == "subdivided":
            for k, quadrant in enumerate(_quadrants(area), start=1):
                visit(f"{name}{k}", quadrant, reaching)

    visit("R", (0, params["width"], 0, params["height"]), list(polygons))
    return rows


def _decide(polygons: dict, area: tuple[int, int, int, int], reaching: list[str]) -> str:
    if not reaching:
        return "empty"
    if len(reaching) == 1:
        return "single"
    depth = {p: polygons[p][0][2] for p in reaching}
    nearest = min(reaching, key=depth.get)
    if (_classify(polygons[nearest], area) == "surrounding"
            and sorted(depth.values())[1] > depth[nearest]):
        return "front"
    return "pixel" if area[1] - area[0] == 1 else "subdivided"


def _warnock_fair(params: dict, difficulty: str) -> bool:
    """Depths apart; a front decision and 2 to 10 subdivisions (any count when ``edge``)."""
    depths = [v[0][2] for v in params["polygons"].values()]
    rows = warnock_areas(params)
    subdivided = sum(decision == "subdivided" for _, _, decision, _ in rows)
    if difficulty == "edge":
        return True
    return (len(set(depths)) == len(depths) and 2 <= subdivided <= 10
            and any(decision == "front" for _, _, decision, _ in rows))


def solve_warnock(params: dict) -> Solved:
    """Solve a Warnock exercise: the classes in the quadrants, the subdivisions, the leaves.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_warnock(exercises.make("warnock", seed=1).params).answer["subdivided"]
    ['R', 'R4', 'R41', 'R43']
    """
    polygons = params["polygons"]
    rows = warnock_areas(params)
    screen = (0, params["width"], 0, params["height"])
    quadrants = {f"R{k}": area for k, area in enumerate(_quadrants(screen), start=1)}
    classes = {name: [_CASES[_classify(v, area)] for v in polygons.values()]
               for name, area in quadrants.items()}
    grid = frame_buffer(params)[0]
    counts = {d: sum(decision == d for _, _, decision, _ in rows) for d in _DECISIONS}
    answer = {**classes,
              "subdivided": [name for name, _, d, _ in rows if d == "subdivided"],
              **counts, "frame": grid}
    fields = (
        *(Field(name, f"each polygon against {name} (S, I, C or D)", 1, kind="sequence",
                required=False) for name in quadrants),
        Field("subdivided", "the areas subdivided", 2, kind="set"),
        *(Field(d, f"how many areas are decided '{d}'", 2, tolerance=0, required=False)
          for d in _DECISIONS),
        Field("frame", "the frame buffer, rows from the top", 3, kind="grid"),
    )
    area_lines = [f"{name} x {area[0]}..{area[1]}, y {area[2]}..{area[3]}: "
                  f"{', '.join(reaching) or 'no polygon'} → {decision}"
                  for name, area, decision, reaching in rows]
    steps = (
        Step("Classify against the quadrants", (
            "Against the whole screen: " + ", ".join(
                f"{p} {_classify(v, screen)}" for p, v in polygons.items()) + ".",
            *(f"{name}: " + ", ".join(f"{p} {_classify(v, quadrants[name])}"
                                      for p, v in polygons.items()) for name in quadrants))),
        Step("Subdivide", (
            "An area is decided when no polygon reaches it (empty), when exactly one does "
            "(single: draw it), or when a surrounding polygon is nearer than every other "
            "(front: fill with it); otherwise it is cut into quadrants 1 2 / 3 4, down to "
            "pixels, where the nearest polygon at the centre wins (pixel).", *area_lines,
            "Counts: " + ", ".join(f"{d} {n}" for d, n in counts.items()))),
        Step("The frame buffer", tuple(grid_lines(grid))),
    )
    question = (
        f"{screen_words(params)} Each polygon is a rectangle at one depth.\n\n"
        f"{polygon_table(polygons)}\n\n![The rectangles on the screen](FIGURE)\n\n"
        "Apply Warnock's area subdivision. Name the screen R and the quadrants of an area by "
        "appending 1 (top left), 2 (top right), 3 (bottom left) or 4 (bottom right): R2, "
        "R24, … (a) Classify each polygon against each quadrant R1 to R4 of the screen: "
        "S(urrounding), I(ntersecting), C(ontained) or D(isjoint), in the order "
        f"{', '.join(polygons)}. (b) Which areas are subdivided? How many areas are "
        "decided empty, by a single polygon, by a surrounding polygon in front, and at "
        "pixel level (where a tie goes to the polygon listed first)? (c) Give the frame "
        "buffer, rows from the top, "
        f"{BACKGROUND!r} for the background."
    )
    return Solved(question, answer, fields, steps,
                  "The areas subdivided must be exactly those; counts must be exact; the "
                  "frame buffer must match pixel for pixel.",
                  draw=lambda solution: screen_figure(params, grid if solution else None,
                                                      areas=rows if solution else None))


def _pick_warnock(rng: random.Random, difficulty: str) -> dict:
    return picker(8, 8, True, _warnock_fair)(rng, difficulty)
