"""Image-space hidden-surface exercises on a small screen: the z-buffer and the scan line.

The given values are a few planar polygons on a small screen, in screen coordinates: x to
the right, y up, pixel (i, j) the unit square with its centre at (i + 0.5, j + 0.5), and a
depth z at every vertex (smaller z is nearer, as the notes' test "Z_new < Z_buffer → update"
reads it). The exam-scale solutions here work pixel by pixel the way a student does; the tests
hold them against the renderer's own methods (``pp.render(..., method=...)`` with an
orthographic camera), pixel for pixel.

Generators keep every pixel centre off every edge and, outside ``edge``, every two depths at a
pixel apart, so that the answer is never a matter of a fill or tie rule.
"""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Callable, Sequence

import numpy as np

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.topics import Solved

__all__ = ["BACKGROUND", "covers", "depth_at", "frame_buffer", "picker", "plane_of",
           "polygon_table", "samples", "screen_figure", "screen_words"]

#: What the background is written as in a frame buffer's rows.
BACKGROUND = "."
# Slopes of the depth planes (dz per pixel along x and along y) a generator draws from: they
# keep every depth at a pixel centre a multiple of 1/8, exact in binary, so ties are exact.
_SLOPES = (-0.5, -0.25, 0.0, 0.25, 0.5)
GRID_MARKING = ("The frame buffer must match pixel for pixel; depths are accepted within "
                 "±0.01.")

Vertex = Sequence[float]


# ------------------------------------------------------------------ geometry of the screen

def plane_of(vertices: Sequence[Vertex]) -> tuple[float, float, float, float]:
    """Return the plane A x + B y + C z + D = 0 through a polygon's first three vertices.

    (A, B, C) = (V2 − V1) × (V3 − V1); C > 0 for vertices listed counter-clockwise on the
    screen.

    Examples
    --------
    >>> plane_of([[0, 0, 2], [4, 0, 4], [0, 2, 2]])
    (-4.0, 0.0, 8.0, -16.0)
    """
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = (map(float, v) for v in vertices[:3])
    ux, uy, uz, vx, vy, vz = x2 - x1, y2 - y1, z2 - z1, x3 - x1, y3 - y1, z3 - z1
    a, b, c = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    return a, b, c, -(a * x1 + b * y1 + c * z1)


def depth_at(vertices: Sequence[Vertex], x: float, y: float) -> float:
    """Return the depth z = −(A x + B y + D) / C of a polygon's plane at a screen point.

    Examples
    --------
    >>> depth_at([[0, 0, 2], [4, 0, 4], [0, 2, 2]], 1.5, 0.5)
    2.75
    """
    a, b, c, d = plane_of(vertices)
    return -(a * x + b * y + d) / c


def _edge_sides(vertices: Sequence[Vertex], x: float, y: float) -> list[float]:
    """Cross products of each edge with the point: all positive inside a CCW polygon."""
    count = len(vertices)
    return [(vertices[(k + 1) % count][0] - vertices[k][0]) * (y - vertices[k][1])
            - (vertices[(k + 1) % count][1] - vertices[k][1]) * (x - vertices[k][0])
            for k in range(count)]


def covers(vertices: Sequence[Vertex], x: float, y: float) -> bool:
    """Whether a convex polygon (vertices counter-clockwise) has the point strictly inside.

    Examples
    --------
    >>> square = [[0, 0, 1], [2, 0, 1], [2, 2, 1], [0, 2, 1]]
    >>> covers(square, 1.5, 0.5), covers(square, 2.5, 0.5)
    (True, False)
    """
    return all(side > 0 for side in _edge_sides(vertices, x, y))


def _centres(width: int, height: int) -> list[tuple[int, int]]:
    """Pixels (i, j) row by row from the top, as a frame buffer is written."""
    return [(i, j) for j in range(height - 1, -1, -1) for i in range(width)]


def samples(params: dict) -> list[tuple[int, int, list[tuple[str, float]], bool]]:
    """Sample every pixel centre, row by row from the top.

    Returns (i, j, the polygons covering the centre with their depths there, in the order
    listed, whether the centre lies on an outline) per pixel.

    Examples
    --------
    >>> params = {"width": 2, "height": 1, "polygons": {
    ...     "A": [[0, 0, 5], [2, 0, 5], [2, 1, 5], [0, 1, 5]],
    ...     "B": [[1, 0, 3], [1.5, 0, 3], [1.5, 1, 3], [1, 1, 3]]}}
    >>> samples(params)
    [(0, 0, [('A', 5.0)], False), (1, 0, [('A', 5.0)], True)]
    """
    centres = _centres(params["width"], params["height"])
    x = np.array([i for i, _ in centres]) + 0.5
    y = np.array([j for _, j in centres]) + 0.5
    found: list[list[tuple[str, float]]] = [[] for _ in centres]
    touching = np.zeros(len(centres), dtype=bool)
    for name, vertices in params["polygons"].items():
        corners = np.array(vertices, dtype=np.float64)[:, :2]
        step = np.roll(corners, -1, axis=0) - corners
        sides = (step[:, :1] * (y - corners[:, 1:]) - step[:, 1:] * (x - corners[:, :1]))
        inside = (sides > 0).all(axis=0)
        touching |= (sides >= 0).all(axis=0) & ~inside
        a, b, c, d = plane_of(vertices)
        depth = -(a * x + b * y + d) / c
        for k in np.flatnonzero(inside):
            found[k].append((name, float(depth[k])))
    return [(i, j, f, bool(t)) for (i, j), f, t in zip(centres, found, touching, strict=True)]


def _nearest(found: list[tuple[str, float]]) -> tuple[str, float]:
    """Return the polygon seen and its depth; the first listed keeps a tie (Z_new < Z)."""
    seen, stored = BACKGROUND, float("inf")
    for name, z in found:
        if z < stored:
            seen, stored = name, z
    return seen, stored


def frame_buffer(params: dict) -> tuple[list[str], list[list[float]]]:
    """Return the frame buffer (rows of polygon names from the top) and the z-buffer.

    Every pixel shows the polygon nearest at its centre (``"."`` and ``inf`` where none).

    Examples
    --------
    >>> params = {"width": 3, "height": 2, "polygons": {
    ...     "A": [[0, 0, 5], [2, 0, 5], [2, 2, 5], [0, 2, 5]],
    ...     "B": [[1, 0, 3], [3, 0, 3], [3, 1, 3], [1, 1, 3]]}}
    >>> frame_buffer(params)[0]
    ['AA.', 'ABB']
    """
    seen = [_nearest(found) for _, _, found, _ in samples(params)]
    width = params["width"]
    rows = [seen[k:k + width] for k in range(0, len(seen), width)]
    return ["".join(name for name, _ in row) for row in rows], [[z for _, z in row]
                                                                   for row in rows]


# ------------------------------------------------------------------ picking polygons

def _rectangle(rng: random.Random, width: int, height: int, step: int) -> list[list[int]]:
    x0 = step * rng.randint(0, (width - 2) // step)
    y0 = step * rng.randint(0, (height - 2) // step)
    x1 = step * rng.randint(x0 // step + 1, width // step)
    y1 = step * rng.randint(y0 // step + 1, height // step)
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def _triangle(rng: random.Random, width: int, height: int) -> list[list[int]]:
    while True:
        corners = [[rng.randint(0, width), rng.randint(0, height)] for _ in range(3)]
        (ax, ay), (bx, by), (cx, cy) = corners
        area2 = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if abs(area2) >= 8 and _clear_of_centres(corners):
            return corners if area2 > 0 else corners[::-1]


def _clear_of_centres(corners: list[list[int]]) -> bool:
    """Check that no pixel centre lies on an edge.

    The points P + m/(2g)·(Q − P) are all the half-integer points of the edge PQ (g the gcd
    of its integer steps); a pixel centre is one whose two coordinates are both odd halves.
    """
    for (px, py), (qx, qy) in zip(corners, corners[1:] + corners[:1], strict=True):
        steps = 2 * math.gcd(qx - px, qy - py)
        for m in range(steps + 1):
            doubled_x = 2 * px + 2 * m * (qx - px) // steps
            doubled_y = 2 * py + 2 * m * (qy - py) // steps
            if doubled_x % 2 and doubled_y % 2:
                return False
    return True


def _with_depths(rng: random.Random, corners: list[list[int]], width: int, height: int,
                 sloped: bool) -> list[list[float]]:
    """Give the corners depths on a plane: an integer depth mid-screen, slopes of _SLOPES."""
    middle = rng.randint(4, 9)
    sx, sy = (rng.choice(_SLOPES), rng.choice(_SLOPES)) if sloped else (0.0, 0.0)
    return [[x, y, middle + sx * (x - width / 2) + sy * (y - height / 2)] for x, y in corners]


def _pick_polygons(rng: random.Random, difficulty: str, width: int, height: int,
                   rectangles: bool) -> dict:
    """Two or three polygons (three unless easy): triangles and rectangles, or rectangles."""
    count = 2 if difficulty == "easy" else 3
    polygons = {}
    for name in "ABC"[:count]:
        if rectangles or rng.random() < 0.4:
            corners = _rectangle(rng, width, height, 2 if rng.random() < 0.7 else 1)
        else:
            corners = _triangle(rng, width, height)
        polygons[name] = _with_depths(rng, corners, width, height,
                                      sloped=not rectangles and difficulty != "easy")
    return {"width": width, "height": height, "polygons": polygons}


def _fair(params: dict, difficulty: str) -> bool:
    """No centre on an outline; every polygon seen; an overlap; no tie unless ``edge``."""
    pixels = samples(params)
    if any(touching for _, _, _, touching in pixels):
        return False
    seen = {_nearest(found)[0] for _, _, found, _ in pixels}
    if any(name not in seen for name in params["polygons"]):
        return False
    if difficulty != "edge" and any(
            b - a < 0.1 for _, _, found, _ in pixels
            for a, b in itertools.pairwise(sorted(z for _, z in found))):
        return False
    return any(len(found) > 1 for _, _, found, _ in pixels)


def picker(width: int, height: int, rectangles: bool,
           accept: Callable[[dict, str], bool]) -> Callable[[random.Random, str], dict]:
    """Make a topic's pick: polygons on a ``width`` × ``height`` screen, redrawn until fair.

    A draw is fair when no pixel centre lies on an outline, every polygon shows somewhere,
    two polygons overlap, no two depths at a pixel tie (unless ``edge``), and ``accept``
    agrees.

    Examples
    --------
    >>> import random
    >>> pick = picker(8, 6, False, lambda params, difficulty: True)
    >>> params = pick(random.Random(1), "standard")
    >>> params["width"], params["height"], sorted(params["polygons"])
    (8, 6, ['A', 'B', 'C'])
    """

    def pick(rng: random.Random, difficulty: str) -> dict:
        while True:
            params = _pick_polygons(rng, difficulty, width, height, rectangles)
            if _fair(params, difficulty) and accept(params, difficulty):
                return params

    return pick


# ------------------------------------------------------------------ shared wording

def polygon_table(polygons: dict) -> str:
    """Write the given polygons as a Markdown table: name, vertices (x, y, z) in order.

    Examples
    --------
    >>> print(polygon_table({"A": [[0, 0, 2], [4, 0, 3.5], [0, 2, 2]]}))
    | polygon | vertices (x, y, z), counter-clockwise |
    |---|---|
    | A | (0, 0, 2) (4, 0, 3.5) (0, 2, 2) |
    """
    lines = ["| polygon | vertices (x, y, z), counter-clockwise |", "|---|---|"]
    for name, vertices in polygons.items():
        lines.append(f"| {name} | {' '.join(shown(v) for v in vertices)} |")
    return "\n".join(lines)


def screen_words(params: dict) -> str:
    """Describe the screen and its coordinates, for a question.

    Examples
    --------
    >>> screen_words({"width": 8, "height": 6})[:32]
    'A screen of 8 × 6 pixels: x to t'
    """
    return (f"A screen of {params['width']} × {params['height']} pixels: x to the right, y "
            f"up, pixel (i, j) is the unit square whose centre is (i + 0.5, j + 0.5). Each "
            f"polygon is planar, with the depth z given at its vertices (smaller z is nearer).")


def _plane_lines(polygons: dict) -> list[str]:
    lines = []
    for name, vertices in polygons.items():
        a, b, c, d = plane_of(vertices)
        lines.append(f"{name}: (A, B, C, D) = {shown([a, b, c, d])}, so z = −(A x + B y + D)/C"
                     f" = {_linear(-d / c, -a / c, -b / c)}; along a scan line z changes by "
                     f"−A/C = {shown(-a / c)} per pixel, from one line to the next by −B/C = "
                     f"{shown(-b / c)}.")
    return lines


def _linear(constant: float, dx: float, dy: float) -> str:
    """Write c + dx·x + dy·y with its signs (``9.25 − 0.25 x + 0.5 y``)."""
    text = shown(constant)
    for coefficient, variable in ((dx, "x"), (dy, "y")):
        if coefficient:
            sign = "−" if coefficient < 0 else "+"
            text += f" {sign} {shown(abs(coefficient))} {variable}"
    return text


def grid_lines(grid: list[str]) -> list[str]:
    """Write a frame buffer's rows as lines of code, for a worked step.

    Examples
    --------
    >>> grid_lines(["AB.", "..C"])
    ['`AB.`', '`..C`']
    """
    return [f"`{row}`" for row in grid]


# ------------------------------------------------------------------ the z-buffer

def _zbuffer_matters(params: dict, difficulty: str) -> bool:
    """Painting in the listed order without the depth test would be wrong somewhere."""
    grid = frame_buffer(params)[0]
    last = {"width": params["width"], "height": params["height"],
            "polygons": {name: [[x, y, -rank] for x, y, _ in v]
                         for rank, (name, v) in enumerate(params["polygons"].items())}}
    return frame_buffer(last)[0] != grid or difficulty == "edge"


def _named_pixels(params: dict) -> list[list[int]]:
    """Two pixels to ask the depth of: where polygons overlap first, then any covered one."""
    ranked = sorted(samples(params), key=lambda pixel: -min(len(pixel[2]), 2))
    return [[i, j] for i, j, _, _ in ranked[:2]]


def _pick_zbuffer(rng: random.Random, difficulty: str) -> dict:
    params = picker(8, 6, False, _zbuffer_matters)(rng, difficulty)
    named = _named_pixels(params)
    rng.shuffle(named)
    return {**params, "pixels": named}


def solve_zbuffer(params: dict) -> Solved:
    """Solve a z-buffer exercise: plane equations, the depths at two pixels, the frame buffer.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_zbuffer(exercises.make("z-buffer", seed=1).params).answer["z1"]
    4.25
    """
    polygons = params["polygons"]
    grid, depths = frame_buffer(params)
    height = params["height"]
    found_at = {(i, j): found for i, j, found, _ in samples(params)}
    depth_lines, answer = [], {}
    fields = [Field(f"dz_{name}", f"dz along a scan line for {name} (−A/C)", 1,
                    required=False) for name in polygons]
    for name, vertices in polygons.items():
        a, _, c, _ = plane_of(vertices)
        answer[f"dz_{name}"] = -a / c
    for number, (i, j) in enumerate(params["pixels"], start=1):
        x, y = i + 0.5, j + 0.5
        listed = ", ".join(f"z_{name} = {shown(z)}" for name, z in found_at[i, j])
        stored = depths[height - 1 - j][i]
        depth_lines.append(f"pixel {number}: ({i}, {j}), centre ({shown(x)}, {shown(y)}): "
                           f"{listed}; the z-buffer keeps {shown(stored)}.")
        answer[f"z{number}"] = stored
        fields.append(Field(f"z{number}", f"the z-buffer's depth at pixel ({i}, {j})", 2))
    answer["frame"] = grid
    fields.append(Field("frame", "the frame buffer, rows from the top", 3, kind="grid"))
    buffer_rows = [" ".join(shown(z) if z != float("inf") else "∞" for z in row)
                   for row in depths]
    steps = (
        Step("Plane equations", tuple(_plane_lines(polygons))),
        Step("Depths at the named pixels", tuple(depth_lines)),
        Step("Draw the polygons in turn with the depth test", (
            "Start with every depth ∞ and every pixel background (.). Draw "
            f"{', '.join(polygons)} in turn: at each pixel centre a polygon covers, compute z "
            "(incrementally along the scan line) and write the pixel when z < the stored z.",
            "The z-buffer at the end, rows from the top:", *(f"`{r}`" for r in buffer_rows),
            "The frame buffer:", *grid_lines(grid))),
    )
    named = " and ".join(f"({i}, {j})" for i, j in params["pixels"])
    question = (
        f"{screen_words(params)}\n\n{polygon_table(polygons)}\n\n"
        "![The polygons on the screen](FIGURE)\n\n"
        f"Apply the z-buffer algorithm, drawing {', '.join(polygons)} in that order. "
        "(a) Give each polygon's plane equation and its depth increment along a scan line "
        "(dz_A, …). "
        f"(b) Give the depth stored at pixels {named} at the end (z1, z2). "
        "(c) Give the frame buffer: one row of letters per scan line from the top, "
        f"{BACKGROUND!r} for the background."
    )
    return Solved(question, answer, tuple(fields), steps, GRID_MARKING,
                  draw=lambda solution: screen_figure(params, grid if solution else None))


# ------------------------------------------------------------------ the scan line

def _crossings(polygons: dict, y: float) -> list[tuple[float, str, str]]:
    """(x, edge name, polygon) of every edge the scan line crosses, sorted by x."""
    found = []
    for name, vertices in polygons.items():
        for k, (x1, y1, _) in enumerate(vertices):
            x2, y2, _ = vertices[(k + 1) % len(vertices)]
            if min(y1, y2) < y < max(y1, y2):
                found.append((x1 + (y - y1) * (x2 - x1) / (y2 - y1), f"{name}{k + 1}", name))
    return sorted(found)


def _spans(polygons: dict, y: float) -> list[tuple[float, float, list[str]]]:
    """Return the spans between successive crossings and the polygons each lies inside."""
    crossings = _crossings(polygons, y)
    inside: set[str] = set()
    spans = []
    for (left, _, name), (right, _, _) in itertools.pairwise(crossings):
        inside ^= {name}
        spans.append((left, right, [p for p in polygons if p in inside]))
    return spans


def _span_winner(polygons: dict, span: tuple[float, float, list[str]], y: float) -> str:
    left, right, inside = span
    middle = (left + right) / 2
    return min(inside, key=lambda p: depth_at(polygons[p], middle, y), default=BACKGROUND)


def _scanline_fair(params: dict, _difficulty: str) -> bool:
    """Check for a scan line where two polygons share a span and no span swaps depths."""
    return _scan_rows(params) != []


def _scan_rows(params: dict) -> list[int]:
    """Rows whose crossings are apart and where two polygons share a span, no span swapping."""
    rows = []
    for j in range(params["height"]):
        y = j + 0.5
        xs = [x for x, _, _ in _crossings(params["polygons"], y)]
        spans = _spans(params["polygons"], y)
        if len(set(xs)) < len(xs) or not any(len(s[2]) > 1 for s in spans):
            continue
        # Even at the edge, a span shows one polygon: the answer names one per span.
        if all(_no_swap(params["polygons"], s, y) for s in spans):
            rows.append(j)
    return rows


def _no_swap(polygons: dict, span: tuple[float, float, list[str]], y: float) -> bool:
    """Check that the nearest polygon is the same at both ends of the span."""
    left, right, inside = span
    ends = [sorted((depth_at(polygons[p], x, y), p) for p in inside) for x in (left, right)]
    return len(inside) < 2 or (ends[0][0][1] == ends[1][0][1] and all(
        e[1][0] - e[0][0] >= 0.1 for e in ends))


def _pick_scanline(rng: random.Random, difficulty: str) -> dict:
    params = picker(10, 6, False, _scanline_fair)(rng, difficulty)
    return {**params, "row": rng.choice(_scan_rows(params))}


def solve_scanline(params: dict) -> Solved:
    """Solve a scan-line exercise: the active edges, the spans and the pixels of one line.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_scanline(exercises.make("scan-line", seed=1).params).answer["pixels"]
    ['CCCCCCBB..']
    """
    polygons, j = params["polygons"], params["row"]
    y = j + 0.5
    crossings = _crossings(polygons, y)
    spans = _spans(polygons, y)
    winners = [_span_winner(polygons, span, y) for span in spans]
    row = frame_buffer(params)[0][params["height"] - 1 - j]
    span_lines = []
    for (left, right, inside), winner in zip(spans, winners, strict=True):
        middle = (left + right) / 2
        depths = ", ".join(f"z_{p} = {shown(depth_at(polygons[p], middle, y))}"
                           for p in inside) or "no polygon"
        span_lines.append(f"[{shown(left)}, {shown(right)}]: inside {', '.join(inside) or '-'}"
                          f"; at x = {shown(middle)}: {depths} → {winner}")
    answer = {"ael": [name for _, name, _ in crossings], "x": [x for x, _, _ in crossings],
              "spans": winners, "pixels": [row]}
    fields = (
        Field("ael", "the active edges, sorted by x", 1, kind="sequence", required=False),
        Field("x", "the x of each crossing, sorted", 1, kind="vector"),
        Field("spans", "the polygon seen in each span", 2, kind="sequence"),
        Field("pixels", "the pixels of the scan line", 3, kind="grid"),
    )
    steps = (
        Step("The active edge list", (
            f"The scan line y = {shown(y)} crosses the edges whose ends lie on either side of "
            "it; each crossing is x = x1 + (y − y1)(x2 − x1)/(y2 − y1) (the next line adds "
            "1/m = Δx/Δy to it).",
            *(f"{name}: x = {shown(x)}" for x, name, _ in crossings))),
        Step("Spans and depths", (
            "Walking left to right, each crossing switches its polygon's in/out flag. In a "
            "span with several polygons in, the depths from the plane equations decide:",
            *span_lines)),
        Step("The pixels", (f"Pixel centres x = 0.5, 1.5, … take the span they lie in: `{row}`",)),
    )
    edges = ", ".join(f"{name}1 = {name}'s edge from its 1st to its 2nd vertex"
                      for name in list(polygons)[:1])
    question = (
        f"{screen_words(params)}\n\n{polygon_table(polygons)}\n\n"
        "![The polygons and the scan line](FIGURE)\n\n"
        f"Process the scan line y = {shown(y)} (pixel row j = {j}) with the scan-line "
        f"algorithm. Edges are named by polygon and number ({edges}, and so on). "
        "(a) Give the active edge list sorted by x, and the x of each crossing. "
        "(b) For each span between successive crossings, give the polygon seen "
        f"({BACKGROUND!r} for none). (c) Give the pixels of the line as letters."
    )
    return Solved(question, answer, fields, steps, GRID_MARKING.replace(
        "depths", "crossings x"),
        draw=lambda solution: screen_figure(params, [row] if solution else None, scan_row=j))


# ------------------------------------------------------------------ the figure

def screen_figure(params: dict, grid: list[str] | None = None, scan_row: int | None = None,
                  areas: list | None = None):
    """Draw the screen: pixel grid, polygons with their vertex depths; solved, the pixels.

    ``grid`` (rows from the top, or one row with ``scan_row``) fills each pixel with the
    colour of the polygon it shows; ``areas`` (rows of
    :func:`pixelpath.exercises.hidden_warnock.warnock_areas`) are outlined.

    Examples
    --------
    >>> params = {"width": 3, "height": 2, "polygons": {
    ...     "A": [[0, 0, 5], [2, 0, 5], [2, 2, 5], [0, 2, 5]]}}
    >>> screen_figure(params, ["AA.", "AA."]).size
    (180, 150)
    """
    from pixelpath.figures._canvas import Sketch, View

    width, height, polygons = params["width"], params["height"], params["polygons"]
    scale = 40
    sketch = Sketch(width * scale + 60, height * scale + 70)
    view = View([[0, 0], [width, height]], (30, 30, width * scale, height * scale), pad=0.0)
    colour = {name: f"object {k}" for k, name in enumerate(polygons, start=1)}
    if grid is not None:
        top = height - 1 if scan_row is None else scan_row
        for r, row in enumerate(grid):
            for i, name in enumerate(row):
                if name != BACKGROUND:
                    cell = [[i, top - r], [i + 1, top - r], [i + 1, top - r + 1],
                            [i, top - r + 1]]
                    sketch.fill(view, cell, colour[name])
    for k in range(width + 1):
        sketch.segment(view, (k, 0), (k, height), "faint", width=1)
    for k in range(height + 1):
        sketch.segment(view, (0, k), (width, k), "faint", width=1)
    if scan_row is not None:
        y = scan_row + 0.5
        sketch.segment(view, (0, y), (width, y), "emitted", width=2, dashed=True)
    for name, vertices in polygons.items():
        corners = [v[:2] for v in vertices]
        sketch.outline(view, corners, colour[name])
        sketch.label(view, [sum(c[0] for c in corners) / len(corners),
                            sum(c[1] for c in corners) / len(corners)], name)
        for x, y, z in vertices:
            sketch.label(view, [x, y], f"{shown(z)}", colour="muted")
    for _, (x0, x1, y0, y1), _, _ in areas or ():
        sketch.outline(view, [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "area edge", width=1)
    return sketch.image
