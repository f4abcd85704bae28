"""The playground's Practice endpoints: seeded exam questions, answers marked, solutions shown.

An exercise is identified by its topic, seed and difficulty alone (:func:`pixelpath.exercises.make`
draws the same one from them on every call), so the app keeps no state: making an exercise
answers what a student may see (never the answer), and checking makes it again to mark the
typed values and only then hands over the worked solution.

Examples
--------
>>> from pixelpath.web import Limits
>>> from pixelpath.web.practice import check_exercise, make_exercise
>>> shown = make_exercise({"topic": "rgb-hsv", "seed": 1}, Limits())
>>> [field["name"] for field in shown["fields"]], "answer" in shown
(['h', 's', 'v'], False)
>>> marked = check_exercise({"topic": "rgb-hsv", "seed": 1,
...                          "values": {"h": "72", "s": "0.5", "v": "0.8"}}, Limits())
>>> marked["correct"], marked["first_wrong"]
(False, 's')
"""

from __future__ import annotations

import base64
import math
import random
from typing import Any

from pixelpath.web._limits import BadRequest, Limits, choice, integer

__all__ = ["MAX_SEED", "check_exercise", "exercise_topics", "make_exercise", "markdown_html"]

MAX_SEED = 2**32 - 1
RANDOM_SEEDS = 100_000  # a seed drawn for the student stays short enough to note down and retype
MAX_VALUE_CHARS = 2000  # one typed value: a polygon of the notes is a few dozen numbers


def exercise_topics(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Return the exercise topics (name and title, in the notes' order) and the difficulties.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.practice import exercise_topics
    >>> answer = exercise_topics({}, Limits())
    >>> {"name": "rgb-hsv", "title": "RGB to HSV"} in answer["topics"], answer["difficulties"]
    (True, ['easy', 'standard', 'edge'])
    """
    from pixelpath import exercises

    return {
        "topics": [{"name": name, "title": exercises.topic_title(name)}
                   for name in exercises.TOPICS],
        "difficulties": list(exercises.DIFFICULTIES),
    }


def make_exercise(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Make an exercise and return what a student may see: no answer, no solution.

    Inputs: ``topic``, ``difficulty`` (default ``"standard"``) and ``seed`` (0 to
    :data:`MAX_SEED`; drawn at random when absent or null). The answer holds the seed used,
    the title, the question as HTML with its figure in place, the figure as a
    ``data:image/png`` URL (null for topics without one), how answers are marked, and the
    fields to fill in (name, label, kind, whether required, the solution step computing it).

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.practice import make_exercise
    >>> shown = make_exercise({"topic": "rgb-hsv", "seed": 1, "difficulty": "easy"}, Limits())
    >>> shown["seed"], shown["figure"], shown["question"][:3]
    (1, None, '<p>')
    """
    exercise = _exercise(data, _seed(data, default=random.randrange(RANDOM_SEEDS)))
    figure = _png_url(exercise.figure_png())
    return {
        "topic": exercise.topic,
        "seed": exercise.seed,
        "difficulty": exercise.difficulty,
        "title": exercise.title,
        "question": markdown_html(exercise.question, exercise.figure_name, figure),
        "figure": figure,
        "marking": exercise.marking,
        "fields": [{"name": field.name, "label": field.label, "kind": field.kind,
                    "required": field.required, "step": field.step}
                   for field in exercise.fields],
    }


def check_exercise(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Mark typed values against the exercise ``topic``, ``seed``, ``difficulty`` names.

    ``values`` maps field names to what the student typed (text, or numbers); a field left
    out is unanswered (a required one is then marked wrong). The answer holds the marking
    (``correct``, ``first_wrong``, ``feedback``, ``marks`` of each field given or required),
    then the worked solution as HTML and the solved figure as a ``data:image/png`` URL
    (null for topics without one).

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.practice import check_exercise
    >>> marked = check_exercise({"topic": "rgb-hsv", "seed": 1,
    ...                          "values": {"h": "72", "s": "0.9375", "v": "0.8"}}, Limits())
    >>> marked["correct"], marked["marks"], marked["feedback"]
    (True, {'h': True, 'v': True, 's': True}, 'Correct.')
    """
    exercise = _exercise(data, _seed(data))
    result = exercise.check(_typed_values(data))
    return {
        "correct": result.correct,
        "first_wrong": result.first_wrong,
        "feedback": result.feedback,
        "marks": dict(result.marks),
        "solution": markdown_html(exercise.solution),
        "solved_figure": _png_url(exercise.figure_png(solution=True)),
    }


def _seed(data: dict[str, Any], default: int | None = None) -> int:
    """Return the request's seed; ``default`` where it is absent or null (else it is required)."""
    if data.get("seed") is None:
        if default is None:
            raise BadRequest("seed is required: the seed of the exercise being answered")
        return default
    return integer(data, "seed", 0, 0, MAX_SEED)


def _exercise(data: dict[str, Any], seed: int) -> Any:
    from pixelpath import exercises

    topic = choice(data, "topic", "", exercises.TOPICS)
    difficulty = choice(data, "difficulty", "standard", exercises.DIFFICULTIES)
    return exercises.make(topic, seed, difficulty)


def _typed_values(data: dict[str, Any]) -> dict[str, str | float]:
    """Return ``data["values"]``: field names to typed text (or finite numbers), each short."""
    values = data.get("values", {})
    if not isinstance(values, dict):
        raise BadRequest(f"values must be an object of field names to typed values, got "
                         f"{type(values).__name__}")
    for name, value in values.items():
        number = isinstance(value, int | float) and not isinstance(value, bool)
        if not isinstance(value, str) and not (number and math.isfinite(value)):
            raise BadRequest(f"the value of {name[:40]!r} must be typed text or a finite "
                             f"number, got {value!r}"[:160])
        if isinstance(value, str) and len(value) > MAX_VALUE_CHARS:
            raise BadRequest(f"the value of {name[:40]!r} holds {len(value)} characters, "
                             f"more than the {MAX_VALUE_CHARS} allowed")
    return values


def markdown_html(text: str, figure_name: str = "", figure: str | None = None) -> str:
    r"""Render an exercise's Markdown as HTML the playground's pages can show.

    An image whose source is ``figure_name`` shows ``figure`` (a ``data:`` URL) in its place;
    a link to it leads to the page's ``#figure-box``. Table columns are aligned by the classes
    ``align-left``, ``align-center``, ``align-right``, not by ``style`` attributes, which the
    playground's Content-Security-Policy refuses.

    Examples
    --------
    >>> from pixelpath.web.practice import markdown_html
    >>> markdown_html("See ![the polygon](q.png).", "q.png", "data:image/png;base64,AA==")
    '<p>See <img src="data:image/png;base64,AA==" alt="the polygon" class="figure" />.</p>\n'
    >>> markdown_html("| a |\n|--:|\n| 1 |").count('class="align-right"')
    2
    """
    from pixelpath.exercises.exporting import markdown_parser

    # Raw HTML in the Markdown is shown as text, never passed on to the page.
    renderer = markdown_parser()
    tokens = renderer.parse(text)
    for token in _walk(tokens):
        style = token.attrs.pop("style", None)
        if isinstance(style, str) and style.startswith("text-align:"):
            token.attrs["class"] = "align-" + style.removeprefix("text-align:")
        if figure is not None and token.attrs.get("src") == figure_name:
            token.attrs["src"] = figure
            token.attrs["class"] = "figure"
        if figure is not None and token.attrs.get("href") == figure_name:
            token.attrs["href"] = "#figure-box"
    return renderer.renderer.render(tokens, renderer.options, {})


def _walk(tokens: list) -> Any:
    for token in tokens:
        yield token
        yield from _walk(token.children or [])


def _png_url(png: bytes | None) -> str | None:
    return None if png is None else "data:image/png;base64," + base64.b64encode(png).decode()
