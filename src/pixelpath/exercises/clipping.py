"""Polygon-clipping exercises: Sutherland-Hodgman stage by stage, Weiler-Atherton's pieces.

The solutions are the clippers' own traces (``sutherland_hodgman(..., trace=True)``,
``weiler_atherton(..., trace=True)``), the tables ``pixelpath clip --trace`` prints, and the
solved figures are the clipping figures of :mod:`pixelpath.figures.clipping`.
"""

from __future__ import annotations

import itertools
import math
import random

import numpy as np

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.topics import Solved, register

_MARKING = ("Vertices within ±0.01 in each coordinate; a polygon may start at any vertex and "
            "run either way round.")


def _window(rng: random.Random) -> list[int]:
    xmin, ymin = rng.randint(1, 4), rng.randint(1, 4)
    return [xmin, ymin, xmin + rng.randint(4, 7), ymin + rng.randint(3, 6)]


def _star(rng: random.Random, count: int, centre: tuple[float, float], radii: tuple[int, int],
          alternate: bool) -> list[list[int]]:
    """Make a simple polygon: integer points at increasing angles around a centre.

    With ``alternate`` every other vertex is pulled in, so the polygon is concave.
    """
    points = []
    for k in range(count):
        angle = 2 * math.pi * (k + rng.random() * 0.6) / count
        low, high = radii
        radius = rng.uniform(low, high) * (0.45 if alternate and k % 2 else 1.0)
        points.append([round(centre[0] + radius * math.cos(angle)),
                       round(centre[1] + radius * math.sin(angle))])
    return points


def _is_simple(points: list[list[int]]) -> bool:
    """No repeated vertex, no three in a row on a line, no two edges that meet off a corner.

    Exact on integers: orientation signs of integer points need no tolerance.
    """
    count = len(points)
    if len({tuple(p) for p in points}) < count:
        return False
    edges = [(points[k], points[(k + 1) % count]) for k in range(count)]
    if any(_turn(a, b, points[(k + 2) % count]) == 0 for k, (a, b) in enumerate(edges)):
        return False
    return not any(_cross(*edges[i], *edges[j]) for i in range(count)
                   for j in range(i + 2, count) if (i, j) != (0, count - 1))


def _turn(a, b, c) -> int:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _cross(a, b, c, d) -> bool:
    """Whether segments ab and cd share a point (touching counts)."""
    d1, d2, d3, d4 = _turn(c, d, a), _turn(c, d, b), _turn(a, b, c), _turn(a, b, d)
    if d1 * d2 < 0 and d3 * d4 < 0:
        return True
    return any(turn == 0 and _between(p, q, r) for turn, p, q, r in
               ((d1, c, d, a), (d2, c, d, b), (d3, a, b, c), (d4, a, b, d)))


def _between(p, q, r) -> bool:
    return min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])


def _touches_boundary(points: list[list[int]], window: list[int]) -> bool:
    xmin, ymin, xmax, ymax = window
    return any(x in (xmin, xmax) or y in (ymin, ymax) for x, y in points)


def _area(points) -> float:
    from pixelpath.clip._validate import twice_signed_area

    return 0.0 if len(points) < 3 else 0.5 * abs(twice_signed_area(np.asarray(points, float)))


# ---------------------------------------------------------------- Sutherland-Hodgman

def pick_sutherland_hodgman(rng: random.Random, difficulty: str) -> dict:
    """Pick a window and a simple polygon with integer vertices.

    Outside ``edge`` (and in 6 of 10 ``edge`` exercises) the polygon is partly inside and
    partly outside the window (something is clipped and something is left) and no vertex
    lies on a window boundary.
    """
    from pixelpath.clip import Rect, sutherland_hodgman

    counts = (3, 4) if difficulty == "easy" else (3, 4, 5, 6)
    anything = difficulty == "edge" and rng.random() < 0.4
    while True:
        window = _window(rng)
        centre = ((window[0] + window[2]) / 2 + rng.randint(-3, 3),
                  (window[1] + window[3]) / 2 + rng.randint(-3, 3))
        polygon = _star(rng, rng.choice(counts), centre, (3, 7), alternate=False)
        if not _is_simple(polygon) or _area(polygon) < 6:
            continue
        if anything:
            return {"window": window, "polygon": polygon}
        clipped = sutherland_hodgman(polygon, Rect(*window))
        if (not _touches_boundary(polygon, window)
                and 0.5 <= _area(clipped) <= _area(polygon) - 0.5):
            return {"window": window, "polygon": polygon}


_BOUNDARY_FIELDS = ("after_left", "after_right", "after_bottom", "after_top")


def solve_sutherland_hodgman(p: dict) -> Solved:
    """Clip against Left, Right, Bottom, Top, one table of (S, E) pairs per boundary."""
    from pixelpath.clip import Rect, sutherland_hodgman

    xmin, ymin, xmax, ymax = p["window"]
    result, trace = sutherland_hodgman(p["polygon"], Rect(*p["window"]), trace=True)
    steps = tuple(_stage_step(stage, limit)
                  for stage, limit in zip(trace.stages, (xmin, xmax, ymin, ymax), strict=True))
    stage_fields = tuple(
        Field(name, f"the vertex list after the {stage.boundary} boundary", k + 1,
              kind="polygon", required=False)
        for k, (name, stage) in enumerate(zip(_BOUNDARY_FIELDS, trace.stages, strict=True)))
    answer = {name: stage.output.tolist()
              for name, stage in zip(_BOUNDARY_FIELDS, trace.stages, strict=True)}
    answer["polygon"] = result.tolist()
    vertices = ", ".join(f"P{k + 1}{_pair(v)}" for k, v in enumerate(p["polygon"]))
    return Solved(
        question=(f"Clip the polygon {vertices} (vertices in order) against the window "
                  f"x_min = {xmin}, x_max = {xmax}, y_min = {ymin}, y_max = {ymax} with the "
                  f"Sutherland-Hodgman algorithm, boundary by boundary: Left, Right, Bottom, "
                  f"Top. Give the vertex list after each boundary and the clipped polygon "
                  f"('none' if nothing is left).\n\n![The polygon and the window](FIGURE)"),
        answer=answer,
        fields=(*stage_fields, Field("polygon", "the clipped polygon", 4, kind="polygon")),
        steps=steps,
        marking=_MARKING,
        draw=lambda solution: _clip_picture(trace, p, solution),
    )


def _pair(point) -> str:
    return "(" + ", ".join(shown(float(x)) for x in point) + ")"


def _stage_step(stage, limit: int) -> Step:
    rule = {"left": f"x ≥ {limit}", "right": f"x ≤ {limit}", "bottom": f"y ≥ {limit}",
            "top": f"y ≤ {limit}"}[stage.boundary]
    rows = [f"input: {_points(stage.input)}", "", "| S | E | case | output |",
            "|---|---|---|---|"]
    rows += [f"| {_pair(step.s)} | {_pair(step.e)} | {step.case} | "
             f"{_points(step.emitted) if len(step.emitted) else 'nothing'} |"
             for step in stage.steps]
    rows += ["", f"output: **{_points(stage.output)}**"]
    return Step(f"clip against the {stage.boundary} boundary (inside: {rule})", tuple(rows))


def _points(points) -> str:
    return " ".join(_pair(p) for p in points) if len(points) else "none"


def _clip_picture(trace, p: dict, solution: bool):
    """Draw the question's polygon and window, or the clipper's stage-by-stage figure."""
    from pixelpath.figures.clipping import clip_figure

    if solution:
        return clip_figure(trace)
    xmin, ymin, xmax, ymax = p["window"]
    window = [[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]]
    return _question_picture(p["polygon"], window)


def _question_picture(polygon: list, window: list):
    """Draw the subject with its vertices named as the question lists them, and the window."""
    from pixelpath.figures._canvas import Sketch, View

    subject = np.asarray(polygon, dtype=float)
    view = View(np.vstack([subject, window]), (24, 24, 272, 272))
    sketch = Sketch(320, 320)
    sketch.fill(view, subject, "subject fill")
    sketch.outline(view, subject, "subject")
    sketch.outline(view, np.asarray(window, dtype=float), "window", width=1, dashed=True)
    sketch.dots(view, subject, "subject", radius=3)
    for k, vertex in enumerate(subject):
        sketch.label(view, vertex, f"P{k + 1}")
    return sketch.image


# ---------------------------------------------------------------- Weiler-Atherton

def pick_weiler_atherton(rng: random.Random, difficulty: str) -> dict:
    """Pick a window and a comb: prongs rising from a base outside the window through it.

    The classic case for Weiler-Atherton: each prong reaches into the window and is a
    separate piece, so there are as many pieces as prongs (2, or 2 to 3). The comb is turned
    by a multiple of 90°. Outside ``edge`` (and in 6 of 10 ``edge`` exercises) no vertex
    lies on a window boundary.
    """
    anything = difficulty == "edge" and rng.random() < 0.4
    width, height = rng.randint(6, 9), rng.randint(4, 6)
    # In the comb's own frame the window is [0, width] × [0, height] and the base lies below.
    xs = [x for x in range(-1, width + 2) if anything or x not in (0, width)]
    while True:
        prongs = _prongs(rng, 2 if difficulty == "easy" else rng.choice((2, 3)), xs, width)
        if prongs is not None:
            break
    low = -rng.randint(2, 3)
    tops = [rng.choice([y for y in range(2, height + 3) if anything or y != height])
            for _ in prongs]
    comb = [[prongs[0][0], low], [prongs[-1][1], low]]
    for k in range(len(prongs) - 1, -1, -1):
        left, right = prongs[k]
        comb += [[right, tops[k]], [left, tops[k]]]
        if k:
            comb += [[left, -1], [prongs[k - 1][1], -1]]
    turns = rng.randint(0, 3)
    polygon, window = _turned(comb, turns), _turned([[0, 0], [width, height]], turns)
    shift = np.array([rng.randint(1, 4), rng.randint(1, 4)]) - np.min(window, axis=0)
    (xmin, ymin), (xmax, ymax) = np.min(window, axis=0) + shift, np.max(window, axis=0) + shift
    return {"window": [int(xmin), int(ymin), int(xmax), int(ymax)],
            "polygon": (np.asarray(polygon) + shift).tolist()}


def _prongs(rng: random.Random, count: int, xs: list[int],
            width: int) -> list[tuple[int, int]] | None:
    """Pick x-intervals of ``count`` prongs, apart and each across part of ``[0, width]``.

    None when the draw does not give that (the caller draws again).
    """
    edges = sorted(rng.sample(xs, 2 * count))
    prongs = [(edges[2 * k], edges[2 * k + 1]) for k in range(count)]
    apart = all(b[0] - a[1] >= 1 for a, b in itertools.pairwise(prongs))
    return prongs if apart and all(0 < right and left < width for left, right in prongs) \
        else None


def _turned(points: list, quarter_turns: int) -> list[list[int]]:
    """Turn integer points by quarter turns about the origin (they stay integers)."""
    turned = [list(p) for p in points]
    for _ in range(quarter_turns):
        turned = [[-y, x] for x, y in turned]
    return turned


def solve_weiler_atherton(p: dict) -> Solved:
    """Walk the subject and window boundaries, switching at each entry and exit."""
    from pixelpath.clip import Rect, weiler_atherton

    xmin, ymin, xmax, ymax = p["window"]
    pieces, trace = weiler_atherton(p["polygon"], Rect(*p["window"]), trace=True)
    contacts = Step("the intersection points of the two boundaries", (
        f"{_points(trace.contacts)} (sorted by x, then y)",))
    walk = tuple(_walk_step(trace, loop) for loop in range(trace.loops))
    answer = {"count": len(pieces), "pieces": [piece.tolist() for piece in pieces]}
    vertices = ", ".join(f"P{k + 1}{_pair(v)}" for k, v in enumerate(p["polygon"]))
    return Solved(
        question=(f"Clip the concave polygon {vertices} (vertices in order) against the "
                  f"window x_min = {xmin}, x_max = {xmax}, y_min = {ymin}, y_max = {ymax} "
                  f"with the Weiler-Atherton algorithm. How many separate pieces are left, "
                  f"and what are their vertices?\n\n![The polygon and the window](FIGURE)"),
        answer=answer,
        fields=(Field("count", "the number of pieces", 1 + len(walk), tolerance=0,
                      required=False),
                Field("pieces", "the pieces' vertex lists", 1 + len(walk), kind="polygons")),
        steps=(contacts, *walk) if walk else (contacts, Step("the walk", (
            "the boundaries do not cross: nothing of the polygon is inside the window"
            if not pieces else "the polygon lies inside the window: it is its own piece",))),
        marking=_MARKING + " Pieces may be given in any order.",
        draw=lambda solution: _walk_picture(trace, p, solution),
    )


def _walk_step(trace, loop: int) -> Step:
    steps = [step for step in trace.steps if step.loop == loop]
    rows = ["| from | to | along |", "|---|---|---|"]
    rows += [f"| {_pair(s.start)} | {_pair(s.end)} | {s.along}"
             f"{' (switch)' if s.switch else ''} |" for s in steps]
    piece = trace.result[loop]
    rows += ["", f"piece {loop + 1}: **{_points(piece)}**"]
    return Step(f"walk piece {loop + 1}", tuple(rows))


def _walk_picture(trace, p: dict, solution: bool):
    from pixelpath.figures.clipping import walk_figure

    if solution:
        return walk_figure(trace)
    xmin, ymin, xmax, ymax = p["window"]
    return _question_picture(p["polygon"], [[xmin, ymin], [xmax, ymin], [xmax, ymax],
                                            [xmin, ymax]])


register("sutherland-hodgman", "Sutherland-Hodgman clipping", "Polygon clipping",
         pick_sutherland_hodgman, solve_sutherland_hodgman)
register("weiler-atherton", "Weiler-Atherton clipping", "Polygon clipping",
         pick_weiler_atherton, solve_weiler_atherton)
