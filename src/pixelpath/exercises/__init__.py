"""Exercises: the notes' exam questions, seeded, with worked solutions, marking and exports.

Every "TYPICAL EXAM QUESTIONS" calculation of the notes is a topic: clip this polygon, find
the Phong intensity, convert RGB to HSV, show how Warnock subdivides, trace this ray.
:func:`make` draws an exercise from a seed (the same seed gives the same numbers on every
machine), solves it with the same machinery as ``--explain``, and marks answers.

Examples
--------
>>> from pixelpath import exercises
>>> ex = exercises.make("rgb-hsv", seed=1)
>>> ex.params
{'rgb': [0.65, 0.8, 0.05]}
>>> {k: round(v, 4) for k, v in ex.answer.items()}
{'h': 72.0, 's': 0.9375, 'v': 0.8}
>>> ex.check({"h": 72, "s": 0.94, "v": 0.8}).correct
True
>>> result = ex.check({"h": 72, "s": 0.6, "v": 0.8})
>>> result.first_wrong, result.feedback
('s', 's is not right: look at step 6 (saturation S); s should be 0.9375.')
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Sequence
from pathlib import Path

from pixelpath.exercises.exercise import CheckResult, Exercise, Field, Step
from pixelpath.exercises.topics import DIFFICULTIES, TOPIC_REGISTRY, exercise_for, rng_for

__all__ = ["DIFFICULTIES", "TOPICS", "CheckResult", "Exercise", "Field", "Step", "export",
           "from_notes", "make", "topic_title"]

# Importing a topic module registers its topics, in the order of the notes' chapters.
for _module in ("clipping", "hidden", "lighting", "rays", "color"):
    importlib.import_module(f"pixelpath.exercises.{_module}")

#: Every topic name, in the order of the notes' chapters.
TOPICS: tuple[str, ...] = tuple(TOPIC_REGISTRY)


def make(topic: str, seed: int = 0, difficulty: str = "standard") -> Exercise:
    """Draw one exercise of ``topic`` from ``seed`` and solve it.

    Parameters
    ----------
    topic : str
        One of :data:`TOPICS`.
    seed : int, default 0
        Any non-negative integer; the same topic, seed and difficulty give the same exercise
        on every machine, different seeds give different numbers.
    difficulty : {"easy", "standard", "edge"}, default "standard"
        ``"easy"`` uses round numbers; ``"standard"`` exam numbers with no degenerate variant
        (nothing clipped, no highlight, a grey's hue, a tie in depth); ``"edge"`` lets those in.

    Returns
    -------
    Exercise

    Raises
    ------
    ValueError
        If the topic or difficulty is unknown (the message lists the choices) or the seed is
        negative.
    TypeError
        If the seed is not an integer.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> ex = exercises.make("ray-sphere", seed=2)
    >>> sorted(ex.params)
    ['center', 'direction', 'origin', 'radius']
    >>> ex.check(ex.answer).correct
    True
    """
    if topic not in TOPIC_REGISTRY:
        raise ValueError(f"unknown exercise topic {topic!r}; choose from {', '.join(TOPICS)}")
    if difficulty not in DIFFICULTIES:
        raise ValueError(f"unknown difficulty {difficulty!r}; choose from "
                         f"{', '.join(DIFFICULTIES)}")
    if isinstance(seed, bool) or not isinstance(seed, int):
        raise TypeError(f"seed must be an int, got {type(seed).__name__}")
    if seed < 0:
        raise ValueError(f"seed must be >= 0, got {seed}")
    entry = TOPIC_REGISTRY[topic]
    return exercise_for(entry, entry.pick(rng_for(topic, seed, difficulty), difficulty),
                        seed, difficulty)


def topic_title(topic: str) -> str:
    """Return the heading of a topic (``"Phong intensity"``), for listings."""
    if topic not in TOPIC_REGISTRY:
        raise ValueError(f"unknown exercise topic {topic!r}; choose from {', '.join(TOPICS)}")
    return TOPIC_REGISTRY[topic].title


def from_notes() -> list[Exercise]:
    """Return the notes' own worked examples as exercises, with the errata applied.

    Where the notes print a wrong value (the Phong example's I = 0.47005), the exercise's
    answer is the right one and :attr:`Exercise.errata` names the printed value.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> phong = next(e for e in exercises.from_notes() if e.topic == "phong-intensity")
    >>> round(phong.answer["I"], 4), phong.errata["I"]
    (0.4923, '0.47005')
    """
    from pixelpath.exercises.notes import notes_exercises

    return notes_exercises()


def export(exercises_list: Sequence[Exercise], path: str | os.PathLike,
           format: str = "markdown") -> list[Path]:
    """Write exercises as a worksheet and answer key, or for a course platform.

    ``format`` is ``"markdown"``, ``"html"``, ``"moodle"`` or ``"prairielearn"``; see
    :func:`pixelpath.exercises.exporting.export_exercises` for what each writes. Returns the
    paths of the files written.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> quiz = [exercises.make("ray-sphere", seed=s) for s in range(3)]
    >>> [p.name for p in exercises.export(quiz, "quiz", format="moodle")]
    ['quiz.xml']
    """
    from pixelpath.exercises.exporting import export_exercises

    return export_exercises(exercises_list, path, format=format)
