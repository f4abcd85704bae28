"""The registry of exercise topics: each one picks given values and solves them.

A topic is two functions. ``pick(rng, difficulty)`` draws the given values from a
:class:`random.Random` (Python's generator: seeded by a string, its sequence is the same on
every platform and Python version that pixelpath supports) and returns them as a
JSON-serializable dict; ``solve(params)`` returns a :class:`Solved` with the question, the
answer, its fields and the worked solution. Keeping the two apart lets the notes' own examples
(:func:`pixelpath.exercises.from_notes`) and a PrairieLearn ``server.py`` solve given values
without drawing any.
"""

from __future__ import annotations

import dataclasses
import random
from collections.abc import Callable
from typing import Any

from pixelpath.exercises.exercise import Exercise, Field, Step, exercise_name

__all__ = ["DIFFICULTIES", "TOPIC_REGISTRY", "Solved", "Topic", "exercise_for", "register",
           "rng_for"]

#: ``"easy"``: round numbers and few vertices; ``"standard"``: exam numbers, no degenerate
#: variants; ``"edge"``: edge cases too (a grey, a ray that misses, a polygon left whole).
DIFFICULTIES = ("easy", "standard", "edge")


@dataclasses.dataclass(frozen=True)
class Solved:
    """What a topic's ``solve`` returns: everything of an exercise but its identity."""

    question: str  # a figure's link target is written "(FIGURE)"
    answer: dict
    fields: tuple[Field, ...]
    steps: tuple[Step, ...]
    marking: str
    draw: Callable[[bool], Any] | None = None


@dataclasses.dataclass(frozen=True)
class Topic:
    """One kind of exam question of the notes."""

    name: str
    title: str
    chapter: str
    pick: Callable[[random.Random, str], dict]
    solve: Callable[[dict], Solved]


TOPIC_REGISTRY: dict[str, Topic] = {}


def register(name: str, title: str, chapter: str, pick: Callable[[random.Random, str], dict],
             solve: Callable[[dict], Solved]) -> None:
    """Add a topic to :data:`TOPIC_REGISTRY` (each topic module calls this once per topic)."""
    TOPIC_REGISTRY[name] = Topic(name, title, chapter, pick, solve)


def exercise_for(topic: Topic, params: dict, seed: int | None, difficulty: str,
                 errata: dict | None = None) -> Exercise:
    """Solve ``params`` of ``topic`` into an :class:`Exercise`."""
    solved = topic.solve(params)
    question = solved.question.replace("(FIGURE)", f"({exercise_name(topic.name, seed)}.png)")
    return Exercise(
        topic=topic.name, seed=seed, difficulty=difficulty, title=topic.title,
        params=params, question=question, answer=solved.answer, fields=solved.fields,
        steps=solved.steps, marking=solved.marking, draw=solved.draw, errata=errata or {},
    )


def rng_for(topic: str, seed: int, difficulty: str) -> random.Random:
    """Return the generator of one exercise: a string seed, hashed the same way everywhere."""
    return random.Random(f"pixelpath-exercise:{topic}:{seed}:{difficulty}")
