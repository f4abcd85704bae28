"""Stress tests of the clipping, illumination, shading, ray and colour generators.

As R/exams' ``stresstest_exercise`` does: make many exercises and check each one. Every
exercise's own answer must mark as correct and its solution must be written; outside the
``edge`` difficulty none may be degenerate (the conditions below, one per topic, are the
ones the issue names: nothing clipped, no highlight, a grey's hue, ...); and ``edge`` must
actually produce its edge cases. The hidden-surface topics have theirs in test_hidden.py.
"""

from __future__ import annotations

import json

import pytest

from pixelpath import exercises
from pixelpath.exercises.topics import TOPIC_REGISTRY

HIDDEN_TOPICS = [name for name, topic in TOPIC_REGISTRY.items()
                 if topic.chapter == "Hidden-surface elimination"]


def _grey(rgb) -> bool:
    return max(rgb) == min(rgb)


def _on_boundary(p) -> bool:
    xmin, ymin, xmax, ymax = p["window"]
    return any(x in (xmin, xmax) or y in (ymin, ymax) for x, y in p["polygon"])


def _area(points) -> float:
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                         in zip(points, points[1:] + points[:1], strict=True)))


# topic -> (is the exercise degenerate?, the edge case that ``edge`` must produce)
DEGENERATE = {
    "sutherland-hodgman": lambda ex: (
        _on_boundary(ex.params) or not ex.answer["polygon"]
        or _area(ex.answer["polygon"]) >= _area(ex.params["polygon"]) - 1e-9),
    "weiler-atherton": lambda ex: ex.answer["count"] < 2 or _on_boundary(ex.params),
    "phong-intensity": lambda ex: ex.params["n_dot_l"] <= 0 or ex.answer["specular"] < 0.01,
    "diffuse": lambda ex: ex.answer["Id"] <= 0,
    "specular": lambda ex: ex.answer["cos_alpha_n"] < 0.01,
    "phong-shading": lambda ex: ex.answer["n_dot_l"] < 0.2 or ex.answer["r_dot_v"] <= 0,
    "gouraud": lambda ex: (ex.params["scan_line"] in [v[1] for v in ex.params["vertices"]]
                           or not ex.answer["x_left"] < ex.params["x"] < ex.answer["x_right"]),
    "ray-sphere": lambda ex: ex.answer["t"] is None or ex.answer["discriminant"] <= 0
    or ex.answer["c"] <= 0,
    "ray-plane": lambda ex: ex.answer["t"] is None,
    "refraction": lambda ex: ex.answer["T"] is None,
    "rgb-hsv": lambda ex: _grey(ex.params["rgb"]),
    "hsv-rgb": lambda ex: ex.params["hsv"][1] == 0 or ex.params["hsv"][2] == 0,
    "rgb-cmy": lambda ex: _grey(ex.params["rgb"]),
    "hsv-cmy": lambda ex: ex.params["hsv"][1] == 0 or ex.params["hsv"][2] == 0,
    "rgb-cmyk": lambda ex: _grey(ex.params["rgb"]),
    "rgb-yiq": lambda ex: _grey(ex.params["rgb"]),
}
#: Topics whose ``edge`` variants include a degenerate case within a few hundred seeds.
EDGE_SHOWS_ITSELF = ("sutherland-hodgman", "weiler-atherton", "phong-intensity", "diffuse",
                     "specular", "ray-sphere", "ray-plane", "refraction", "rgb-hsv",
                     "hsv-rgb")


def test_every_topic_has_a_stress_condition():
    assert set(DEGENERATE) | set(HIDDEN_TOPICS) == set(exercises.TOPICS)


def _stress(topic: str, seeds: range, difficulty: str) -> int:
    """Check every exercise of the seeds; return how many were degenerate."""
    degenerate = 0
    for seed in seeds:
        ex = exercises.make(topic, seed, difficulty)
        assert ex.check(ex.answer).correct, seed
        assert ex.solution and json.dumps(ex.params), seed
        degenerate += bool(DEGENERATE[topic](ex))
    return degenerate


@pytest.mark.parametrize("difficulty", ["easy", "standard"])
@pytest.mark.parametrize("topic", sorted(DEGENERATE))
def test_no_degenerate_exercise_in_three_hundred_seeds(topic, difficulty):
    assert _stress(topic, range(300), difficulty) == 0


@pytest.mark.parametrize("topic", EDGE_SHOWS_ITSELF)
def test_edge_difficulty_produces_edge_cases(topic):
    assert _stress(topic, range(300), "edge") > 0


@pytest.mark.slow
@pytest.mark.parametrize("topic", sorted(DEGENERATE))
def test_no_degenerate_exercise_in_three_thousand_seeds(topic):
    assert _stress(topic, range(300, 3300), "standard") == 0
