"""Object-space hidden-surface exercises: back-face elimination and the octree.

Back faces use the project's convention (SPEC §9 errata): V points from the eye into the
scene, V = P − E for a point P of the face, and a face is visible when N · V < 0
(:func:`pixelpath.hsr.backface.front_facing` decides it). The octree's order of children is
:func:`pixelpath.hsr.octree.front_to_back`, the order the renderer visits cells in.
"""

from __future__ import annotations

import random
from collections.abc import Sequence

import numpy as np

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.topics import Solved

__all__ = ["face_normal", "octree_cells"]

# The cabinet projection of the figures: z recedes up and to the right at half scale.
_RECEDE = np.array([0.35, 0.35])


# ------------------------------------------------------------------ back faces

def _box(rng: random.Random) -> dict:
    x0, y0, z0 = (rng.randint(-2, 1) for _ in range(3))
    x1, y1, z1 = x0 + rng.randint(2, 4), y0 + rng.randint(2, 4), z0 + rng.randint(2, 4)
    corners = {f"P{k}": [(x0, x1)[k & 1], (y0, y1)[k >> 1 & 1], (z0, z1)[k >> 2 & 1]]
               for k in range(8)}
    faces = {"A": ["P0", "P4", "P6", "P2"], "B": ["P1", "P3", "P7", "P5"],
             "C": ["P0", "P1", "P5", "P4"], "D": ["P2", "P6", "P7", "P3"],
             "E": ["P0", "P2", "P3", "P1"], "F": ["P4", "P5", "P7", "P6"]}
    return {"vertices": corners, "faces": faces}


def _pyramid(rng: random.Random) -> dict:
    x0, y0, z0 = (rng.randint(-2, 1) for _ in range(3))
    side = rng.choice((2, 4))
    apex = [x0 + side // 2 + rng.randint(-1, 1), y0 + rng.randint(2, 4),
            z0 + side // 2 + rng.randint(-1, 1)]
    corners = {"P0": [x0, y0, z0], "P1": [x0 + side, y0, z0],
               "P2": [x0 + side, y0, z0 + side], "P3": [x0, y0, z0 + side], "P4": apex}
    faces = {"A": ["P0", "P1", "P2", "P3"], "B": ["P0", "P4", "P1"], "C": ["P1", "P4", "P2"],
             "D": ["P2", "P4", "P3"], "E": ["P3", "P4", "P0"]}
    return {"vertices": corners, "faces": faces}


def face_normal(points: Sequence[Sequence[float]]) -> list[float]:
    """Return the outward normal (P2 − P1) × (P3 − P1) of a face listed counter-clockwise.

    Examples
    --------
    >>> face_normal([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    [0.0, 0.0, 1.0]
    """
    p1, p2, p3 = (np.asarray(p, dtype=np.float64) for p in points[:3])
    return np.cross(p2 - p1, p3 - p1).tolist()


def _view_vectors(params: dict) -> dict[str, list[float]]:
    """V of each face: P1 − E from the eye, or the viewing direction when one is given."""
    vertices = params["vertices"]
    if "direction" in params:
        return {face: list(map(float, params["direction"])) for face in params["faces"]}
    eye = np.asarray(params["eye"], dtype=np.float64)
    return {face: (np.asarray(vertices[names[0]], dtype=np.float64) - eye).tolist()
            for face, names in params["faces"].items()}


def _dots(params: dict) -> dict[str, float]:
    vertices, views = params["vertices"], _view_vectors(params)
    return {face: float(np.dot(face_normal([vertices[n] for n in names]), views[face]))
            for face, names in params["faces"].items()}


def _pick_backface(rng: random.Random, difficulty: str) -> dict:
    """Pick a box or a pyramid and an eye outside it (a viewing direction when easy)."""
    while True:
        params = (_box if rng.random() < 0.5 else _pyramid)(rng)
        if difficulty == "easy":
            params["direction"] = [rng.choice((-1, 1)) * rng.randint(1, 3) for _ in range(3)]
        else:
            params["eye"] = [rng.randint(-8, 8) for _ in range(3)]
        dots = _dots(params).values()
        # A convex solid shows some face to an eye outside it, none to one inside.
        outside = any(d < 0 for d in dots)
        if outside and (difficulty == "edge" or all(d != 0 for d in dots)):
            return params


def solve_backface(params: dict) -> Solved:
    """Solve a back-face exercise: N · V for every face and the faces that are visible.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_backface(exercises.make("back-face", seed=1).params).answer["visible"]
    ['A', 'D', 'E']
    """
    from pixelpath.hsr.backface import front_facing

    vertices, faces = params["vertices"], params["faces"]
    normals = {f: face_normal([vertices[n] for n in names]) for f, names in faces.items()}
    views, dots = _view_vectors(params), _dots(params)
    viewpoint = ([-x for x in params["direction"]] + [0] if "direction" in params
                 else params["eye"])
    kept = front_facing(np.array(list(normals.values())),
                        np.array([vertices[names[0]] for names in faces.values()],
                                 dtype=np.float64), viewpoint)
    visible = [face for face, keep in zip(faces, kept, strict=True) if keep]
    answer = {**{f"NV_{face}": dots[face] for face in faces}, "visible": visible}
    fields = (*(Field(f"NV_{face}", f"N · V for face {face}", 2, required=False)
                for face in faces),
              Field("visible", "the visible faces", 3, kind="set"))
    where = ("V = the viewing direction " + shown(params["direction"])
             if "direction" in params else
             f"V = P1 − E, from the eye E = {shown(params['eye'])} to the face's first vertex")
    steps = (
        Step("Outward normals", tuple(
            f"{face}: N = (P2 − P1) × (P3 − P1) = {shown(normals[face])}" for face in faces)),
        Step("N · V", (where + ":", *(
            f"{face}: V = {shown(views[face])}, N · V = {shown(dots[face])}"
            f" → {'visible' if dots[face] < 0 else 'back face'}" for face in faces))),
        Step("The visible faces", (
            f"N · V < 0 for {', '.join(visible)}: those are drawn, the others culled.",)),
    )
    table = "\n".join(["| face | vertices (counter-clockwise seen from outside) |", "|---|---|",
                       *(f"| {face} | {', '.join(names)} |" for face, names in faces.items())])
    points = ", ".join(f"{name} = {shown(p)}" for name, p in vertices.items())
    viewer = (f"The view is parallel, in the direction V = {shown(params['direction'])} "
              "(into the scene)." if "direction" in params else
              f"The eye is at E = {shown(params['eye'])}.")
    question = (
        f"A solid has the vertices {points}, and the faces\n\n{table}\n\n"
        f"![The solid and its faces](FIGURE)\n\n{viewer} Take N = (P2 − P1) × (P3 − P1) from "
        "each face's first three vertices and V pointing from the eye into the scene (V = P1 − "
        "E for a face's first vertex P1, or the viewing direction); a face is visible when "
        "N · V < 0. (a) Give N · V for each face (NV_A, NV_B, …). (b) Which faces are visible?"
    )
    return Solved(question, answer, fields, steps,
                  "N · V is accepted within ±0.01; the set of visible faces must be exact.",
                  draw=lambda solution: _backface_figure(params, visible if solution else None))


def _backface_figure(params: dict, visible: list[str] | None):
    vertices = {name: np.asarray(p, dtype=np.float64) for name, p in params["vertices"].items()}
    sketch, view = _sketch(list(vertices.values()))
    faces = {face: _project([vertices[n] for n in names])
             for face, names in params["faces"].items()}
    for k, (face, corners) in enumerate(faces.items()):
        if visible is not None and face in visible:
            sketch.fill(view, corners, f"object {k % 6 + 1}")
    # Outlines and labels go on top of every fill, so no face hides another's name.
    for face, corners in faces.items():
        sketch.outline(view, corners, "subject", width=2,
                       dashed=visible is not None and face not in visible)
        sketch.label(view, corners.mean(axis=0), face)
    for name, point in vertices.items():
        sketch.label(view, _project([point])[0], name, colour="muted")
    return sketch.image


# ------------------------------------------------------------------ the octree

_SIZE = 8


def octree_cells(points: dict, eye: Sequence[float]) -> tuple[list[str], list[str]]:
    """Subdivide the cube [0, 8]³ while a cell holds more than one point; walk it front to back.

    Cells are named ``"R"`` (the cube), then one digit per level: the child's octant,
    1 for the upper half in x, + 2 for the upper half in y, + 4 for the upper half in z.

    Returns
    -------
    subdivided : list of str
        The cells that were cut into eight, in the order they are visited.
    order : list of str
        The points' names as their leaves are reached front to back from ``eye``.

    Examples
    --------
    >>> octree_cells({"A": [1, 1, 1], "B": [7, 7, 7], "C": [3, 1, 1]}, eye=(12, 9, 10))
    (['R', 'R0'], ['B', 'C', 'A'])
    """
    subdivided, order = _walk(points, eye)
    return [name for name, _ in subdivided], order


def _walk(points: dict, eye: Sequence[float]) -> tuple[list[tuple[str, list[str]]], list[str]]:
    """Return the cells subdivided with the points each held, and the points in order."""
    from pixelpath.hsr.octree import front_to_back

    subdivided: list[tuple[str, list[str]]] = []
    order: list[str] = []

    def visit(name: str, corner: np.ndarray, side: float, inside: list[str]) -> None:
        if len(inside) <= 1:
            order.extend(inside)
            return
        subdivided.append((name, inside))
        half = side / 2
        centre = corner + half
        for octant in front_to_back(np.asarray(eye, dtype=np.float64), centre).tolist():
            offset = np.array([octant & 1, octant >> 1 & 1, octant >> 2 & 1]) * half
            child = corner + offset
            members = [p for p in inside
                       if all(child[k] <= points[p][k] < child[k] + half for k in range(3))]
            visit(f"{name}{octant}", child, half, members)

    visit("R", np.zeros(3), float(_SIZE), list(points))
    return subdivided, order


def _pick_octree(rng: random.Random, difficulty: str) -> dict:
    """Points at odd coordinates (never on a splitting plane) and an eye outside the cube."""
    count = 4 if difficulty == "easy" else rng.randint(5, 6)
    while True:
        spots = {tuple(rng.choice((1, 3, 5, 7)) for _ in range(3)) for _ in range(count)}
        eye = [rng.choice((-3, -1, 1, 3, 5, 7, 9, 11)) for _ in range(3)]
        outside = any(c < 0 or c > _SIZE for c in eye)
        if len(spots) < count or not outside:
            continue
        shuffled = sorted(spots)
        rng.shuffle(shuffled)
        points = {"ABCDEF"[k]: list(p) for k, p in enumerate(shuffled)}
        subdivided, _ = octree_cells(points, eye)
        if len(subdivided) >= 2 or difficulty == "easy":
            return {"points": points, "eye": eye}


def solve_octree(params: dict) -> Solved:
    """Solve an octree exercise: the cells subdivided, the octant order, the points' order.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> solve_octree(exercises.make("octree", seed=1).params).answer["subdivided"]
    ['R', 'R7', 'R2']
    """
    from pixelpath.hsr.octree import front_to_back

    points, eye = params["points"], params["eye"]
    held, order = _walk(points, eye)
    subdivided = [name for name, _ in held]
    octants = [str(k) for k in front_to_back(np.asarray(eye, dtype=np.float64),
                                             np.full(3, _SIZE / 2))]
    answer = {"subdivided": subdivided, "octants": octants, "order": order}
    fields = (Field("subdivided", "the cells subdivided", 1, kind="set"),
              Field("octants", "the root's octants front to back", 2, kind="sequence"),
              Field("order", "the points front to back", 3, kind="sequence"))
    eye_octant = sum(1 << k for k in range(3) if eye[k] >= _SIZE / 2)
    steps = (
        Step("Subdivide", (
            "A cell holding more than one point is cut into eight at its centre.",
            *(f"{name} holds {', '.join(inside)} → subdivided" for name, inside in held))),
        Step("Order of the octants", (
            f"The eye {shown(eye)} lies in octant {eye_octant} of R; octants are taken by how "
            "many splitting planes lie between them and the eye's: none, one (x, y, z), two, "
            f"three: {', '.join(octants)}. Every subdivided cell orders its children the same "
            "way around its own centre.",)),
        Step("Points front to back", (f"Visiting leaves front to back: {', '.join(order)}",)),
    )
    listed = ", ".join(f"{name} = {shown(p)}" for name, p in points.items())
    question = (
        f"The cube [0, 8]³ holds the points {listed}. The eye is at {shown(eye)}.\n\n"
        "![The points in the cube](FIGURE)\n\n"
        "Build an octree: a cell holding more than one point is cut into eight equal cells. "
        "Name the cube R and a child by appending its octant: 1 for the upper half in x, + 2 "
        "for the upper half in y, + 4 for the upper half in z (R5 is x ≥ 4, y < 4, z ≥ 4). "
        "(a) Which cells are subdivided? (b) List R's octants front to back from the eye: its "
        "own, then those across one splitting plane (x, then y, then z), across two (x and y, "
        "x and z, y and z), across all three. (c) List the points in the order a front-to-back "
        "traversal reaches them."
    )
    return Solved(question, answer, fields, steps,
                  "The cells subdivided, the octant order and the point order must be exact.",
                  draw=lambda solution: _octree_figure(params, order if solution else None))


def _octree_figure(params: dict, order: list[str] | None):
    cube = np.array([[(k & 1) * _SIZE, (k >> 1 & 1) * _SIZE, (k >> 2 & 1) * _SIZE]
                     for k in range(8)], dtype=np.float64)
    sketch, view = _sketch(list(cube))
    for a in range(8):
        for bit in (1, 2, 4):
            if not a & bit:
                sketch.segment(view, *_project([cube[a], cube[a | bit]]), "window", width=1)
    half = _SIZE / 2
    for axis in range(3):
        u, v = [k for k in range(3) if k != axis]
        ring = []
        for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            point = np.zeros(3)
            point[axis], point[u], point[v] = half, du * _SIZE, dv * _SIZE
            ring.append(point)
        sketch.outline(view, _project(ring), "faint", width=1, dashed=True)
    for name, xyz in params["points"].items():
        at = _project([xyz])
        sketch.dots(view, at, "emitted")
        text = name if order is None else f"{name} ({order.index(name) + 1})"
        sketch.label(view, at[0], text)
    return sketch.image


# ------------------------------------------------------------------ shared drawing

def _project(points: Sequence[Sequence[float]]) -> np.ndarray:
    """Cabinet projection of 3-D points onto the page."""
    xyz = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    return xyz[:, :2] + xyz[:, 2:] * _RECEDE


def _sketch(points: list):
    from pixelpath.figures._canvas import Sketch, View

    sketch = Sketch(420, 380)
    return sketch, View(_project(points), (20, 20, 380, 340), pad=0.12)
