"""Illumination and shading exercises: the Phong model's terms, Gouraud and Phong shading.

The intensities come from :func:`pixelpath.lighting.phong_terms` and the vectors from
:func:`pixelpath.lighting.phong_geometry`, the functions behind ``pixelpath phong --explain``.
"""

from __future__ import annotations

import math
import random

import numpy as np

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.topics import Solved, register

_PHONG_MARKING = ("Each value is accepted within ±0.01, so intermediate values rounded to "
                  "two or three decimals on the way are fine.")


def _count(low: float, high: float, step: float) -> int:
    return round((high - low) / step)


def _pick(rng: random.Random, low: float, high: float, step: float) -> float:
    """Pick a number of ``low, low + step, ..., high``, rounded to the step's decimals."""
    decimals = max(0, -math.floor(math.log10(step) + 1e-9))
    return round(low + step * rng.randint(0, _count(low, high, step)), decimals)


def _cosine(degrees: float) -> float:
    """Return cos of an angle rounded to 3 decimals, as an exam gives it (cos 45° = 0.707)."""
    return round(math.cos(math.radians(degrees)), 3)


# ---------------------------------------------------------------- Phong intensity (notes 5)

def pick_phong(rng: random.Random, difficulty: str) -> dict:
    """Pick the notes' given values: coefficients, intensities and the two cosines.

    Never a total above 1 (the clamped and unclamped answers would differ); outside ``edge``,
    always a visible highlight (specular >= 0.01) and a lit surface.
    """
    angles = (15, 30, 45, 60) if difficulty == "easy" else range(5, 76)
    while True:
        params = {
            "ka": _pick(rng, 0.1, 0.3, 0.05), "kd": _pick(rng, 0.3, 0.8, 0.05),
            "ks": _pick(rng, 0.2, 0.8, 0.1), "n": rng.choice((1, 2, 5, 10, 20, 50)),
            "Ia": _pick(rng, 0.1, 0.5, 0.1), "IL": _pick(rng, 0.5, 1.0, 0.1),
            "n_dot_l": _cosine(rng.choice(angles)), "r_dot_v": _cosine(rng.choice(angles)),
        }
        if difficulty == "edge" and rng.random() < 0.5:
            key = rng.choice(("n_dot_l", "r_dot_v"))
            params[key] = round(-abs(params[key]) if rng.random() < 0.8 else 0.0, 3)
        terms = _phong(params)
        lit = params["n_dot_l"] > 0 and terms.specular >= 0.01
        if terms.total <= 1.0 and (lit or difficulty == "edge"):
            return params


def _phong(params: dict):
    from pixelpath.lighting import phong_terms

    return phong_terms(ka=params["ka"], kd=params["kd"], ks=params["ks"],
                       shininess=params["n"], ambient=params["Ia"], light=params["IL"],
                       n_dot_l=params["n_dot_l"], r_dot_v=params["r_dot_v"])


def _phong_steps(p: dict, terms) -> tuple[Step, ...]:
    """Write the notes' four steps: ambient, diffuse, specular, total."""
    ambient = Step("ambient term", (
        f"I_a = k_a·I_a = {shown(p['ka'])} × {shown(p['Ia'])} = **{shown(terms.ambient)}**",))
    if p["n_dot_l"] > 0:
        diffuse = Step("diffuse term", (
            f"I_d = k_d·I_L·max(0, N·L) = {shown(p['kd'])} × {shown(p['IL'])} × "
            f"{shown(p['n_dot_l'])} = **{shown(terms.diffuse)}**",))
    else:
        diffuse = Step("diffuse term", (
            f"N·L = {shown(p['n_dot_l'])} ≤ 0: the light is behind the surface, so "
            f"I_d = **0**",))
    if p["n_dot_l"] <= 0:
        specular = Step("specular term", ("N·L ≤ 0: no highlight either, I_s = **0**",))
    elif p["r_dot_v"] <= 0:
        specular = Step("specular term", (
            f"R·V = {shown(p['r_dot_v'])} ≤ 0: the eye is outside the highlight, so "
            f"I_s = **0**",))
    else:
        power = p["r_dot_v"] ** p["n"]
        specular = Step("specular term", (
            f"(R·V)^n = {shown(p['r_dot_v'])}^{p['n']} = {shown(power)}",
            f"I_s = k_s·I_L·(R·V)^n = {shown(p['ks'])} × {shown(p['IL'])} × {shown(power)} "
            f"= **{shown(terms.specular)}**"))
    total = Step("total intensity", (
        f"I = I_a + I_d + I_s = {shown(terms.ambient)} + {shown(terms.diffuse)} + "
        f"{shown(terms.specular)} = **{shown(terms.total)}**",))
    return ambient, diffuse, specular, total


_TERM_FIELDS = (
    Field("ambient", "the ambient term k_a·I_a", 1, required=False),
    Field("diffuse", "the diffuse term k_d·I_L·max(0, N·L)", 2, required=False),
    Field("specular", "the specular term k_s·I_L·max(0, R·V)^n", 3, required=False),
)


def solve_phong(p: dict) -> Solved:
    """Solve the notes' Phong-intensity question (fixed names: ka ... r_dot_v -> I)."""
    terms = _phong(p)
    question = (
        f"A point is lit by one light. Given k_a = {shown(p['ka'])}, k_d = {shown(p['kd'])}, "
        f"k_s = {shown(p['ks'])}, n = {p['n']}, I_a = {shown(p['Ia'])}, "
        f"I_L = {shown(p['IL'])}, N·L = {shown(p['n_dot_l'])} and "
        f"R·V = {shown(p['r_dot_v'])}, compute the intensity I of the Phong model "
        f"I = k_a I_a + k_d I_L max(0, N·L) + k_s I_L max(0, R·V)^n.")
    return Solved(
        question=question,
        answer={"ambient": terms.ambient, "diffuse": terms.diffuse,
                "specular": terms.specular, "I": terms.total},
        fields=(*_TERM_FIELDS, Field("I", "the intensity I", 4)),
        steps=_phong_steps(p, terms),
        marking=_PHONG_MARKING,
    )


# ---------------------------------------------------------------- diffuse and specular alone

def _source(rng: random.Random) -> float:
    """Pick a light intensity: 1 (relative) or candela as in the notes' examples."""
    return float(rng.choice((1, 1, 50, 80, 100, 120, 150, 200)))


def pick_diffuse(rng: random.Random, difficulty: str) -> dict:
    """Pick k_d, I_L and θ; θ >= 90° (no diffuse light) only when ``edge``."""
    theta = rng.choice((0, 30, 45, 60)) if difficulty == "easy" else rng.randint(5, 85)
    if difficulty == "edge" and rng.random() < 0.3:
        theta = rng.randint(90, 150)
    return {"kd": _pick(rng, 0.3, 0.9, 0.05), "IL": _source(rng), "theta": theta}


def solve_diffuse(p: dict) -> Solved:
    """Solve Lambert's law for the given k_d, I_L and θ."""
    cos_theta = math.cos(math.radians(p["theta"]))
    intensity = p["kd"] * p["IL"] * max(0.0, cos_theta)
    tolerance = 0.01 * p["IL"]
    if cos_theta > 0:
        second = (f"I_d = k_d·I_L·cos θ = {shown(p['kd'])} × {shown(p['IL'])} × "
                  f"{shown(cos_theta)} = **{shown(intensity)}**")
    else:
        second = "cos θ ≤ 0: the light is behind the surface, so I_d = **0**"
    return Solved(
        question=(f"A light of intensity I_L = {shown(p['IL'])} falls on a surface with "
                  f"k_d = {shown(p['kd'])} at θ = {p['theta']}° to its normal. Find the "
                  f"diffuse reflected intensity I_d."),
        answer={"cos_theta": cos_theta, "Id": intensity},
        fields=(Field("cos_theta", "cos θ = N·L", 1, tolerance=0.005, required=False),
                Field("Id", "the diffuse intensity I_d", 2, tolerance=tolerance)),
        steps=(Step("cos θ", (f"cos {p['theta']}° = {shown(cos_theta)}",)),
               Step("Lambert's law", (second,))),
        marking=f"cos θ within ±0.005; I_d within ±{shown(tolerance)} (1 % of I_L).",
    )


def pick_specular(rng: random.Random, difficulty: str) -> dict:
    """Pick k_s, I_L, n and α, with a visible highlight ((cos α)^n >= 0.01) unless ``edge``."""
    while True:
        alpha = rng.choice((0, 15, 30, 45, 60)) if difficulty == "easy" else rng.randint(2, 60)
        if difficulty == "edge" and rng.random() < 0.3:
            alpha = rng.randint(90, 150)
        params = {"ks": _pick(rng, 0.2, 0.9, 0.1), "IL": _source(rng),
                  "n": rng.choice((1, 2, 5, 10, 20, 50, 100)), "alpha": alpha}
        if difficulty == "edge" or math.cos(math.radians(alpha)) ** params["n"] >= 0.01:
            return params


def solve_specular(p: dict) -> Solved:
    """Solve the Phong specular term for the given k_s, I_L, n and α."""
    cos_alpha = math.cos(math.radians(p["alpha"]))
    power = max(0.0, cos_alpha) ** p["n"]
    intensity = p["ks"] * p["IL"] * power
    tolerance = 0.01 * p["IL"]
    if cos_alpha > 0:
        lines = (f"(cos α)^n = {shown(cos_alpha)}^{p['n']} = {shown(power)}",
                 f"I_s = k_s·I_L·(cos α)^n = {shown(p['ks'])} × {shown(p['IL'])} × "
                 f"{shown(power)} = **{shown(intensity)}**")
    else:
        lines = ("cos α ≤ 0: the eye is outside the highlight, so I_s = **0**",)
    return Solved(
        question=(f"A light of intensity I_L = {shown(p['IL'])} is reflected by a surface with "
                  f"k_s = {shown(p['ks'])} and shininess n = {p['n']}. The angle between R "
                  f"and V is α = {p['alpha']}°. Find the specular reflected intensity I_s."),
        answer={"cos_alpha": cos_alpha, "cos_alpha_n": power, "Is": intensity},
        fields=(Field("cos_alpha", "cos α = R·V", 1, tolerance=0.005, required=False),
                Field("cos_alpha_n", "(cos α)^n", 2, tolerance=0.005, required=False),
                Field("Is", "the specular intensity I_s", 2, tolerance=tolerance)),
        steps=(Step("cos α", (f"cos {p['alpha']}° = {shown(cos_alpha)}",)),
               Step("the highlight", lines)),
        marking=(f"cos α and (cos α)^n within ±0.005; I_s within ±{shown(tolerance)} "
                 f"(1 % of I_L)."),
    )


# ---------------------------------------------------------------- Phong shading (normals)

def _integer_vector(rng: random.Random, low: int = -2, high: int = 3) -> list[int]:
    return [rng.randint(low, high) for _ in range(3)]


def pick_phong_shading(rng: random.Random, difficulty: str) -> dict:
    """Pick a span with a vertex normal at each end, a pixel on it, and L and V.

    Vectors have small integer components; outside ``edge`` the pixel is lit and sees a
    highlight (N·L >= 0.2 and a specular term >= 0.01) and the total stays <= 1.
    """
    while True:
        xa = rng.randint(0, 6)
        xb = xa + rng.choice((2, 4, 5, 8, 10))
        params = {
            "xa": xa, "xb": xb, "x": rng.randint(xa + 1, xb - 1),
            "na": _integer_vector(rng, -2, 2), "nb": _integer_vector(rng, -2, 2),
            "l": _integer_vector(rng), "v": _integer_vector(rng),
            "ka": _pick(rng, 0.1, 0.3, 0.05), "kd": _pick(rng, 0.3, 0.7, 0.05),
            "ks": _pick(rng, 0.2, 0.6, 0.1), "n": rng.choice((2, 5, 10, 20)),
            "Ia": _pick(rng, 0.1, 0.3, 0.1), "IL": 1.0,
        }
        if difficulty == "easy":
            params["x"] = (xa + xb) // 2 if (xa + xb) % 2 == 0 else params["x"]
        try:
            geometry, _, _, terms = _shade_span(params)
        except ValueError:  # a zero vector, or normals that cancel at the pixel
            continue
        lit = geometry.n_dot_l >= 0.2 and terms.specular >= 0.01
        if terms.total <= 1.0 and (lit or difficulty == "edge"):
            return params


def _shade_span(p: dict):
    """Interpolate the normal to the pixel (at t along the span), then light it there."""
    from pixelpath.lighting import phong_geometry, phong_terms

    if not all(np.any(p[k]) for k in ("na", "nb", "l", "v")):
        raise ValueError("a zero vector")
    na, nb = (np.asarray(p[k], float) / np.linalg.norm(p[k]) for k in ("na", "nb"))
    t = (p["x"] - p["xa"]) / (p["xb"] - p["xa"])
    blended = (1 - t) * na + t * nb
    if np.linalg.norm(blended) < 1e-6:
        raise ValueError("the normals cancel at the pixel")
    geometry = phong_geometry(blended, p["l"], p["v"])
    terms = phong_terms(ka=p["ka"], kd=p["kd"], ks=p["ks"], shininess=p["n"],
                        ambient=p["Ia"], light=p["IL"], n_dot_l=geometry.n_dot_l,
                        r_dot_v=geometry.r_dot_v)
    return geometry, t, blended, terms


def solve_phong_shading(p: dict) -> Solved:
    """Solve one pixel of Phong shading: interpolate the normal, normalize, light it."""
    geometry, t, blended, terms = _shade_span(p)
    interpolate = Step("interpolate the normal", (
        f"t = (x − x_A)/(x_B − x_A) = ({p['x']} − {p['xa']})/({p['xb']} − {p['xa']}) "
        f"= {shown(t)}",
        f"N_A = {shown(_unit(p['na']))}, N_B = {shown(_unit(p['nb']))} (unit)",
        f"N' = (1 − t)·N_A + t·N_B = {shown(blended.tolist())}",
        f"N = N'/|N'| = **{shown(geometry.normal.tolist())}**"))
    vectors = Step("N·L, R and R·V", (
        f"L = {shown(geometry.to_light.tolist())}, V = {shown(geometry.to_eye.tolist())} "
        f"(unit)",
        f"N·L = **{shown(geometry.n_dot_l)}**",
        f"R = 2(N·L)N − L = {shown(geometry.reflected.tolist())}",
        f"R·V = **{shown(geometry.r_dot_v)}**"))
    cosines = {**p, "n_dot_l": geometry.n_dot_l, "r_dot_v": geometry.r_dot_v}
    ambient, diffuse, specular, total = _phong_steps(cosines, terms)
    return Solved(
        question=(
            f"Phong shading: along a scan line, a polygon's span runs from x_A = {p['xa']} "
            f"with vertex normal N_A along {shown(p['na'])} to x_B = {p['xb']} with N_B along "
            f"{shown(p['nb'])}. At the pixel x = {p['x']}, the direction to the light is "
            f"{shown(p['l'])} and to the eye {shown(p['v'])}. With k_a = {shown(p['ka'])}, "
            f"k_d = {shown(p['kd'])}, k_s = {shown(p['ks'])}, n = {p['n']}, "
            f"I_a = {shown(p['Ia'])} and I_L = {shown(p['IL'])}, find the pixel's unit "
            f"normal N, N·L, R·V and the intensity I. (Normalize every direction first.)"),
        answer={"N": geometry.normal.tolist(), "n_dot_l": geometry.n_dot_l,
                "r_dot_v": geometry.r_dot_v, "I": terms.total},
        fields=(Field("N", "the pixel's unit normal N", 1, kind="vector"),
                Field("n_dot_l", "N·L", 2), Field("r_dot_v", "R·V", 2),
                Field("I", "the intensity I", 6)),
        steps=(interpolate, vectors, ambient, diffuse, specular, total),
        marking=_PHONG_MARKING,
    )


def _unit(vector: list) -> list[float]:
    array = np.asarray(vector, dtype=float)
    return (array / np.linalg.norm(array)).tolist()


# ---------------------------------------------------------------- Gouraud shading (notes 6)

def pick_gouraud(rng: random.Random, difficulty: str) -> dict:
    """Pick a triangle with vertex intensities, a scan line through it and a pixel on it.

    Outside ``edge`` the scan line misses every vertex (one edge pair is crossed) and the
    span is at least 2 pixels wide with the pixel at least half a pixel inside it.
    """
    step = 0.1 if difficulty == "easy" else 0.05
    while True:
        vertices = [[rng.randint(0, 12), rng.randint(0, 12)] for _ in range(3)]
        (ax, ay), (bx, by), (cx, cy) = vertices
        if abs((bx - ax) * (cy - ay) - (cx - ax) * (by - ay)) < 20:
            continue  # too thin to read off a figure
        ys = sorted(v[1] for v in vertices)
        if ys[2] - ys[0] < 2:
            continue
        scan = rng.randint(ys[0] + 1, ys[2] - 1)
        if scan in ys and difficulty != "edge":
            continue
        intensities = [_pick(rng, 0.1, 1.0, step) for _ in range(3)]
        if len(set(intensities)) < 3:
            continue
        params = {"vertices": vertices, "intensities": intensities, "scan_line": scan, "x": 0}
        (*_, x_left, _), (*_, x_right, _) = _span(params)
        inside = [x for x in range(math.ceil(x_left), math.floor(x_right) + 1)
                  if x - x_left >= 0.5 and x_right - x >= 0.5]
        if x_right - x_left >= 2 and inside:
            params["x"] = rng.choice(inside)
            return params


def _crossings(p: dict) -> list[tuple[int, int, float, float, float]]:
    """Return the edges the scan line crosses: (from, to, t, x, I) with t along from -> to."""
    names, y = p["vertices"], p["scan_line"]
    found = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        (xa, ya), (xb, yb) = names[a], names[b]
        if ya == yb or not min(ya, yb) <= y <= max(ya, yb):
            continue
        t = (y - ya) / (yb - ya)
        x = xa + t * (xb - xa)
        intensity = p["intensities"][a] + t * (p["intensities"][b] - p["intensities"][a])
        if all(abs(x - other[3]) > 1e-12 for other in found):
            found.append((a, b, t, x, intensity))
    return sorted(found, key=lambda crossing: crossing[3])


def _span(p: dict) -> tuple[tuple, tuple]:
    """Return the crossings where the scan line enters and leaves the triangle."""
    crossings = _crossings(p)
    return crossings[0], crossings[-1]


_VERTEX_NAMES = "ABC"


def solve_gouraud(p: dict) -> Solved:
    """Solve Gouraud shading at one pixel: interpolate down the edges, then along the span."""
    left, right = _span(p)
    x_left, i_left, x_right, i_right = left[3], left[4], right[3], right[4]
    s = (p["x"] - x_left) / (x_right - x_left)
    intensity = i_left + (i_right - i_left) * s
    steps = tuple(_edge_step(p, crossing, side)
                  for crossing, side in ((left, "left"), (right, "right")))
    along = Step("interpolate along the scan line", (
        f"I(x) = I_L + (I_R − I_L)·(x − x_L)/(x_R − x_L) = {shown(i_left)} + "
        f"({shown(i_right)} − {shown(i_left)}) × ({p['x']} − {shown(x_left)})/"
        f"({shown(x_right)} − {shown(x_left)}) = **{shown(intensity)}**",))
    vertices = ", ".join(f"{_VERTEX_NAMES[k]}{tuple(v)} with I = {shown(i)}"
                         for k, (v, i) in enumerate(zip(p["vertices"], p["intensities"],
                                                         strict=True)))
    return Solved(
        question=(f"Gouraud shading: a triangle has the vertices {vertices} (screen "
                  f"coordinates, y up). Find where the scan line y = {p['scan_line']} crosses "
                  f"the triangle's edges (x_L, x_R) with the intensities there (I_L, I_R), and "
                  f"the intensity of the pixel x = {p['x']} on that scan line.\n\n"
                  f"![The triangle and the scan line](FIGURE)"),
        answer={"x_left": x_left, "I_left": i_left, "x_right": x_right, "I_right": i_right,
                "I": intensity},
        fields=(Field("x_left", "x_L, where the scan line enters", 1, required=False),
                Field("I_left", "I_L, the intensity there", 1, required=False),
                Field("x_right", "x_R, where it leaves", 2, required=False),
                Field("I_right", "I_R, the intensity there", 2, required=False),
                Field("I", "the pixel's intensity I", 3)),
        steps=(*steps, along),
        marking="x within ±0.01 pixel, intensities within ±0.01.",
        draw=lambda solution: _gouraud_figure(p, solution),
    )


def _edge_step(p: dict, crossing: tuple, side: str) -> Step:
    a, b, t, x, intensity = crossing
    (xa, ya), (xb, yb) = p["vertices"][a], p["vertices"][b]
    ia, ib = p["intensities"][a], p["intensities"][b]
    edge = f"{_VERTEX_NAMES[a]}{_VERTEX_NAMES[b]}"
    letter = side[0].upper()
    return Step(f"the {side} edge {edge}", (
        f"t = (y − y_{_VERTEX_NAMES[a]})/(y_{_VERTEX_NAMES[b]} − y_{_VERTEX_NAMES[a]}) = "
        f"({p['scan_line']} − {ya})/({yb} − {ya}) = {shown(t)}",
        f"x_{letter} = {xa} + t × ({xb} − {xa}) = **{shown(x)}**",
        f"I_{letter} = I_{_VERTEX_NAMES[a]} + (I_{_VERTEX_NAMES[b]} − I_{_VERTEX_NAMES[a]})·t = "
        f"{shown(ia)} + ({shown(ib)} − {shown(ia)}) × {shown(t)} = **{shown(intensity)}**"))


def _gouraud_figure(p: dict, solution: bool):
    """Draw the triangle shaded by its intensities, the scan line and the pixel."""
    from pixelpath.figures._canvas import Sketch, View

    vertices = np.asarray(p["vertices"], dtype=float)
    y = p["scan_line"]
    low, high = vertices[:, 0].min() - 1, vertices[:, 0].max() + 1
    view = View(np.vstack([vertices, [[low, y], [high, y]]]), (20, 24, 260, 272))
    sketch = Sketch(340, 320)
    sketch.fill(view, vertices, "subject fill")
    sketch.outline(view, vertices, "subject")
    sketch.segment(view, np.array([low, y]), np.array([high, y]), "window", width=1, dashed=True)
    for name, vertex, intensity in zip(_VERTEX_NAMES, vertices, p["intensities"], strict=True):
        sketch.label(view, vertex, f"{name} I={shown(intensity)}")
    sketch.dots(view, vertices, "subject", radius=3)
    pixel = np.array([[p["x"], y]], dtype=float)
    sketch.rings(view, pixel, "edge")
    if solution:
        (*_, x_left, i_left), (*_, x_right, i_right) = _span(p)
        ends = np.array([[x_left, y], [x_right, y]])
        sketch.segment(view, ends[0], ends[1], "output", width=3)
        sketch.dots(view, ends, "output", radius=4)
        sketch.label(view, ends[0], f"I_L={shown(i_left)}", "output")
        sketch.label(view, ends[1], f"I_R={shown(i_right)}", "output")
    ((px, py),) = view.xy(pixel)
    sketch.text(px - 8, py + 8, f"x={p['x']}", "edge")
    return sketch.image


register("phong-intensity", "Phong intensity", "Illumination: the Phong model", pick_phong,
         solve_phong)
register("diffuse", "Diffuse reflection", "Illumination: diffuse reflection", pick_diffuse,
         solve_diffuse)
register("specular", "Specular reflection", "Illumination: specular reflection", pick_specular,
         solve_specular)
register("phong-shading", "Phong shading", "Shading: Phong shading", pick_phong_shading,
         solve_phong_shading)
register("gouraud", "Gouraud shading", "Shading: Gouraud shading", pick_gouraud, solve_gouraud)
