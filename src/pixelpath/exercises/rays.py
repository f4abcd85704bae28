"""Ray-tracing exercises: where a ray meets a sphere or a plane, and how it refracts.

The hits come from :func:`pixelpath.raytrace.ray_sphere` and :func:`~pixelpath.raytrace.ray_plane`
and the notes' quadratic from :func:`pixelpath.raytrace.explain.sphere_quadratic` (what
``pixelpath ray --explain`` prints); refraction from :func:`pixelpath.raytrace.refract`.
"""

from __future__ import annotations

import math
import random

import numpy as np

from pixelpath.exercises.exercise import Field, Step, shown
from pixelpath.exercises.topics import Solved, register

_T_MARKING = "t within ±0.01; the quadratic's a, b, c and discriminant within ±0.01."


def _point(rng: random.Random, low: int = -5, high: int = 5) -> list[int]:
    return [rng.randint(low, high) for _ in range(3)]


# ---------------------------------------------------------------- ray-sphere

def pick_ray_sphere(rng: random.Random, difficulty: str) -> dict:
    """Pick a ray and a sphere with integer coordinates.

    Outside ``edge`` the ray starts outside the sphere and hits it at two distinct points in
    front of the origin; ``edge`` also gives (in 4 of 10) misses, tangents and origins inside.
    """
    from pixelpath.raytrace.explain import sphere_quadratic

    high = 3 if difficulty == "easy" else 5
    anything = difficulty == "edge" and rng.random() < 0.4
    while True:
        params = {"origin": _point(rng, -high, high), "direction": _point(rng, -2, 2),
                  "center": _point(rng, -high, high), "radius": rng.randint(1, 4)}
        if not any(params["direction"]):
            continue
        q = sphere_quadratic(params["origin"], params["direction"], params["center"],
                             params["radius"])
        if anything or (q.c > 0 and q.discriminant > 0 and q.roots[0] > 0):
            return params


def solve_ray_sphere(p: dict) -> Solved:
    """Solve the notes' quadratic for the nearest hit with t > 0 (fixed names -> t)."""
    from pixelpath.raytrace import ray_sphere
    from pixelpath.raytrace.explain import sphere_quadratic

    q = sphere_quadratic(p["origin"], p["direction"], p["center"], p["radius"])
    t = float(ray_sphere(p["origin"], p["direction"], p["center"], p["radius"]))
    t_answer = None if math.isinf(t) else t
    f = (np.asarray(p["origin"]) - np.asarray(p["center"])).tolist()
    steps = [
        Step("the vector from the centre", (f"P0 − C = {shown(f)}",)),
        Step("the quadratic a t² + b t + c = 0", (
            f"a = d·d = **{shown(q.a)}**",
            f"b = 2 d·(P0 − C) = **{shown(q.b)}**",
            f"c = |P0 − C|² − r² = **{shown(q.c)}**")),
        Step("the discriminant", (f"b² − 4ac = **{shown(q.discriminant)}**",)),
    ]
    if q.discriminant < 0:
        pick = "b² − 4ac < 0: the ray misses the sphere, t = **none**"
        steps.append(Step("the nearest hit", (pick,)))
    else:
        roots = " and ".join(shown(r) for r in q.roots)
        chosen = ("both roots are behind the origin: no hit, t = **none**" if t_answer is None
                  else f"the smallest root with t > 0: t = **{shown(t)}**")
        point = ([] if t_answer is None else
                 [f"the hit point P0 + t d = "
                  f"{shown((np.asarray(p['origin']) + t * np.asarray(p['direction'])).tolist())}"])
        steps.append(Step("the nearest hit", (
            f"t = (−b ∓ √(b² − 4ac))/2a = {roots}", chosen, *point)))
    return Solved(
        question=(f"A ray R(t) = P0 + t·d starts at P0 = {shown(p['origin'])} in the direction "
                  f"d = {shown(p['direction'])}. A sphere has centre C = {shown(p['center'])} "
                  f"and radius r = {p['radius']}. Set up the quadratic a t² + b t + c = 0, "
                  f"find its discriminant, and give the t of the nearest hit with t > 0 "
                  f"(answer 'none' if the ray misses). t is in units of |d|."),
        answer={"a": q.a, "b": q.b, "c": q.c, "discriminant": q.discriminant, "t": t_answer},
        fields=(Field("a", "a = d·d", 2, required=False),
                Field("b", "b = 2 d·(P0 − C)", 2, required=False),
                Field("c", "c = |P0 − C|² − r²", 2, required=False),
                Field("discriminant", "b² − 4ac", 3, required=False),
                Field("t", "t of the nearest hit (none on a miss)", 4)),
        steps=tuple(steps),
        marking=_T_MARKING,
    )


# ---------------------------------------------------------------- ray-plane

def pick_ray_plane(rng: random.Random, difficulty: str) -> dict:
    """Pick a ray and a plane (a point and a normal); a hit in front unless ``edge``."""
    from pixelpath.raytrace import ray_plane

    while True:
        params = {"origin": _point(rng), "direction": _point(rng, -2, 2),
                  "point": _point(rng), "normal": _point(rng, -1, 2)}
        if not any(params["direction"]) or not any(params["normal"]):
            continue
        if difficulty == "edge" and rng.random() < 0.3:
            return params
        t = float(ray_plane(params["origin"], params["direction"], params["point"],
                            params["normal"]))
        if math.isfinite(t) and t > 0.05:
            return params


def solve_ray_plane(p: dict) -> Solved:
    """Solve t = n·(Q − P0)/(n·d) (the notes print P0 twice; Q is the plane's point)."""
    from pixelpath.raytrace import ray_plane

    n, d = np.asarray(p["normal"], float), np.asarray(p["direction"], float)
    gap = np.asarray(p["point"], float) - np.asarray(p["origin"], float)
    n_dot_d, n_dot_gap = float(n @ d), float(n @ gap)
    t = float(ray_plane(p["origin"], p["direction"], p["point"], p["normal"]))
    t_answer = None if math.isinf(t) else t
    if n_dot_d == 0:
        last = "n·d = 0: the ray is parallel to the plane, t = **none**"
    elif t_answer is None:
        last = (f"t = {shown(n_dot_gap)}/{shown(n_dot_d)} = {shown(n_dot_gap / n_dot_d)} ≤ 0: "
                f"the plane is behind the ray, t = **none**")
    else:
        last = f"t = n·(Q − P0)/(n·d) = {shown(n_dot_gap)}/{shown(n_dot_d)} = **{shown(t)}**"
    return Solved(
        question=(f"A ray R(t) = P0 + t·d starts at P0 = {shown(p['origin'])} in the direction "
                  f"d = {shown(p['direction'])}. A plane passes through Q = {shown(p['point'])} "
                  f"with normal n = {shown(p['normal'])}. Find n·d and the t of the hit "
                  f"(answer 'none' if the ray is parallel to the plane or the plane is "
                  f"behind it)."),
        answer={"n_dot_d": n_dot_d, "t": t_answer},
        fields=(Field("n_dot_d", "n·d", 1, required=False),
                Field("t", "t of the hit (none when there is none)", 2)),
        steps=(Step("n·d", (f"n·d = **{shown(n_dot_d)}**",
                            f"Q − P0 = {shown(gap.tolist())}, n·(Q − P0) = {shown(n_dot_gap)}")),
               Step("t", (last,))),
        marking="n·d and t within ±0.01.",
    )


# ---------------------------------------------------------------- refraction

_MEDIA = {"air": 1.0, "water": 1.33, "glass": 1.5, "diamond": 2.42}


def pick_refraction(rng: random.Random, difficulty: str) -> dict:
    """Pick an angle of incidence and two media; total internal reflection only when ``edge``.

    The ray travels in the x-y plane towards a surface whose normal is +y.
    """
    angles = (0, 30, 45, 60) if difficulty == "easy" else range(5, 81)
    while True:
        n1, n2 = rng.sample(sorted(_MEDIA), 2)
        theta = rng.choice(angles)
        params = {"theta_i": theta, "n1": _MEDIA[n1], "n2": _MEDIA[n2],
                  "media": [n1, n2]}
        sin_t = _MEDIA[n1] / _MEDIA[n2] * math.sin(math.radians(theta))
        if difficulty == "edge" or sin_t < 0.98:
            return params


def solve_refraction(p: dict) -> Solved:
    """Solve Snell's law and the notes' vector form T = ηd + (η cos θi − cos θt)N."""
    from pixelpath.raytrace import refract

    theta = math.radians(p["theta_i"])
    d = [math.sin(theta), -math.cos(theta), 0.0]
    eta = p["n1"] / p["n2"]
    cos_i = -d[1]  # −d·N with N = (0, 1, 0)
    sin_t = eta * math.sin(theta)
    transmitted = refract(d, (0.0, 1.0, 0.0), eta)
    steps = [Step("η and cos θi", (f"η = n1/n2 = {shown(p['n1'])}/{shown(p['n2'])} = "
                                   f"**{shown(eta)}**",
                                   f"cos θi = −d·N = **{shown(cos_i)}**")),
             Step("Snell's law", (f"sin θt = η sin θi = {shown(eta)} × "
                                  f"{shown(math.sin(theta))} = "
                                  f"**{shown(sin_t)}**",))]
    if transmitted is None:
        steps.append(Step("the transmitted ray", (
            "sin θt > 1: total internal reflection, no transmitted ray (T = **none**)",)))
        theta_t, t_vector = None, None
    else:
        cos_t = math.sqrt(1.0 - sin_t * sin_t)
        theta_t = math.degrees(math.asin(sin_t))
        t_vector = [float(x) for x in transmitted]
        steps.append(Step("the transmitted ray", (
            f"θt = asin({shown(sin_t)}) = **{shown(theta_t)}°**, cos θt = {shown(cos_t)}",
            f"T = ηd + (η cos θi − cos θt)N = {shown(eta)}·{shown(d)} + "
            f"({shown(eta)} × {shown(cos_i)} − {shown(cos_t)})·(0, 1, 0) = "
            f"**{shown(t_vector)}**")))
    medium_1, medium_2 = p["media"]
    return Solved(
        question=(f"A ray in {medium_1} (n1 = {shown(p['n1'])}) meets the flat surface of "
                  f"{medium_2} (n2 = {shown(p['n2'])}) at θi = {p['theta_i']}° to the normal. "
                  f"The surface normal on the incident side is N = (0, 1, 0) and the unit "
                  f"incident direction is d = {shown(d)}. Find η, sin θt, the refraction angle "
                  f"θt and the transmitted direction T (answer 'none' for θt and T on total "
                  f"internal reflection)."),
        answer={"eta": eta, "sin_theta_t": sin_t, "theta_t": theta_t, "T": t_vector},
        fields=(Field("eta", "η = n1/n2", 1, tolerance=0.005, required=False),
                Field("sin_theta_t", "sin θt", 2, tolerance=0.005, required=False),
                Field("theta_t", "θt in degrees (none on total internal reflection)", 3,
                      tolerance=0.5),
                Field("T", "the unit transmitted direction T", 3, kind="vector")),
        steps=tuple(steps),
        marking="η and sin θt within ±0.005, θt within ±0.5°, each component of T within ±0.01.",
    )


register("ray-sphere", "Ray-sphere intersection", "Ray tracing: intersections", pick_ray_sphere,
         solve_ray_sphere)
register("ray-plane", "Ray-plane intersection", "Ray tracing: intersections", pick_ray_plane,
         solve_ray_plane)
register("refraction", "Refraction (Snell's law)", "Ray tracing: secondary rays",
         pick_refraction, solve_refraction)
