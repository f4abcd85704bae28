"""The exercise record, its answer fields and the marking of a student's answer.

An :class:`Exercise` is plain data: the given values (``params``), the question and worked
solution as Markdown, the answer as a dict, and one :class:`Field` per answer value saying how
it is typed, how it is marked and which step of the solution computes it. Topic modules build
exercises; nothing here knows any topic.
"""

from __future__ import annotations

import base64
import contextlib
import dataclasses
import io
import json
import math
import re
from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["KINDS", "CheckResult", "Exercise", "Field", "Step"]

#: How an answer value is typed and compared (see :class:`Field`).
KINDS = ("number", "vector", "polygon", "polygons", "sequence", "set", "choice", "grid")

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_NONE_WORDS = {"", "none", "miss", "no hit", "null", "-", "nothing", "empty", "inf", "∞"}


@dataclasses.dataclass(frozen=True)
class Field:
    """One named value of an exercise's answer.

    Attributes
    ----------
    name : str
        The key in :attr:`Exercise.answer` and in the dict given to :meth:`Exercise.check`.
    label : str
        What the value is, in words (``"the intensity I"``).
    step : int
        The number (from 1) of the solution step that computes it.
    kind : str
        One of :data:`KINDS`: ``"number"`` (None allowed where there is no value, such as a
        ray that misses), ``"vector"`` (numbers in order; None where there is none, such
        as the refracted ray of a total internal reflection), ``"polygon"`` (vertices, compared
        up to the starting vertex and direction), ``"polygons"`` (several, in any order),
        ``"sequence"`` (labels in order), ``"set"`` (labels in any order), ``"choice"`` (one
        label) or ``"grid"`` (rows of one-character labels).
    tolerance : float
        For numbers, vectors and vertices: the largest accepted absolute error of each number.
    required : bool
        Intermediate values a student may give for credit on the way (``False``) or values
        the exercise asks for (``True``).
    """

    name: str
    label: str
    step: int
    kind: str = "number"
    tolerance: float = 0.01
    required: bool = True

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown field kind {self.kind!r}; choose from {', '.join(KINDS)}")

    def parse(self, value: Any) -> Any:
        """Read a value a student typed (a string) or gave (a number, a list) into this kind.

        Raises
        ------
        ValueError
            If the text cannot be read as this kind of value.

        Examples
        --------
        >>> Field("T", "the direction", 1, kind="vector").parse("(0.5, -0.25, 1)")
        [0.5, -0.25, 1.0]
        >>> Field("P", "the polygon", 1, kind="polygon").parse("(1,2) (3, 4) (5,6)")
        [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
        >>> Field("order", "the order", 1, kind="sequence").parse("b, A ,c")
        ['B', 'A', 'C']
        >>> Field("order", "the order", 1, kind="sequence").parse('["B", "A", "C"]')  # JSON
        ['B', 'A', 'C']
        """
        value = _json_list(value)
        if self.kind == "number":
            return _parse_number(value)
        if self.kind == "vector":
            return _parse_numbers(value)
        if self.kind == "polygon":
            return _parse_points(value)
        if self.kind == "polygons":
            if isinstance(value, str):
                return [_parse_points(part) for part in value.split(";") if part.strip()]
            return [_parse_points(part) for part in value]
        if self.kind in ("sequence", "set"):
            parts = re.split(r"[,\s]+", value.strip()) if isinstance(value, str) else value
            return [_label(part) for part in parts if _label(part)]
        if self.kind == "choice":
            return _label(value)
        rows = re.split(r"[,\s]+", value.strip()) if isinstance(value, str) else value
        return [_label(row) for row in rows]

    def matches(self, given: Any, expected: Any) -> bool:
        """Whether a parsed value is right, within the tolerance (see :attr:`kind`)."""
        if self.kind == "number":
            if expected is None or given is None:
                return expected is None and given is None
            return abs(given - expected) <= self.tolerance
        if self.kind == "vector":
            if expected is None or not given:
                return expected is None and not given
            return _close(given, expected, self.tolerance)
        if self.kind == "polygon":
            return _same_polygon(given, expected, self.tolerance)
        if self.kind == "polygons":
            return _same_polygons(given, expected, self.tolerance)
        if self.kind == "set":
            return sorted(given) == sorted(_label(x) for x in expected)
        if self.kind == "choice":
            return given == _label(expected)
        return list(given) == [_label(x) for x in expected]


@dataclasses.dataclass(frozen=True)
class Step:
    """One step of a worked solution: a short title and its lines of Markdown."""

    title: str
    lines: tuple[str, ...]


@dataclasses.dataclass(frozen=True)
class CheckResult:
    """The marking of one answer.

    Attributes
    ----------
    correct : bool
        Every required value is given and right, and every optional value given is right.
    first_wrong : str or None
        The first field, in solution order, that is wrong or (if required) missing.
    feedback : str
        Which step of the solution to look at and the value it computes, or praise.
    marks : dict of str to bool
        Each field that was given (or is required) and whether it is right.
    """

    correct: bool
    first_wrong: str | None
    feedback: str
    marks: Mapping[str, bool]

    def __bool__(self) -> bool:
        return self.correct


@dataclasses.dataclass(frozen=True, eq=False)
class Exercise:
    """One exam question with its answer, worked solution and marking.

    Made by :func:`pixelpath.exercises.make`; the same topic, seed and difficulty give the
    same exercise on every machine.

    Attributes
    ----------
    topic, seed, difficulty : str, int or None, str
        What made it; ``seed`` is None for the notes' own examples (:func:`from_notes`).
    title : str
        A short heading (``"Phong intensity"``).
    params : dict
        The given values, JSON-serializable (lists, not tuples or arrays).
    question : str
        The question as Markdown. Where the notes would draw a figure, the question links
        to :attr:`figure_name` (see :meth:`figure`), which the exports write beside it.
    answer : dict
        The answer, one entry per :attr:`fields` name, exact (not rounded).
    fields : tuple of Field
        The answer's values in solution order, with their marking rules.
    steps : tuple of Step
        The worked solution.
    marking : str
        How answers are marked (tolerances), in words.
    errata : dict
        For the notes' own examples: the value the notes print where it is wrong, by field.
    """

    topic: str
    seed: int | None
    difficulty: str
    title: str
    params: dict
    question: str
    answer: dict
    fields: tuple[Field, ...]
    steps: tuple[Step, ...]
    marking: str
    draw: Callable[[bool], Any] | None = dataclasses.field(default=None, repr=False)
    errata: dict = dataclasses.field(default_factory=dict)

    @property
    def name(self) -> str:
        """A file-friendly identifier: ``"<topic>-<seed>"`` (``"notes-<topic>"`` for the notes)."""
        return exercise_name(self.topic, self.seed)

    @property
    def figure_name(self) -> str:
        """The file name the question's figure is linked under (``"<name>.png"``)."""
        return f"{self.name}.png"

    @property
    def solution(self) -> str:
        """The worked solution as Markdown: numbered steps, then the answer, rounded and exact."""
        parts = []
        for number, step in enumerate(self.steps, start=1):
            parts.append(f"**Step {number}. {step.title}**\n")
            # Two trailing spaces break a Markdown line; table rows and blank lines need none.
            parts.extend(line if not line or line.startswith("|") else f"{line}  "
                         for line in step.lines)
            parts.append("")
        parts.append("**Answer**\n")
        parts.append("| value | answer | exact |")
        parts.append("|---|---|---|")
        for field in self.fields:
            value = self.answer[field.name]
            cells = (f"{field.name}: {field.label}", shown(value), exact(value))
            # A "|" inside a cell (|P0 − C|²) would end it.
            parts.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
        for name, printed in self.errata.items():
            parts.append("")
            parts.append(f"The notes print {name} = {printed}; that is wrong (see the errata).")
        return "\n".join(parts)

    def figure(self, solution: bool = False):
        """Draw the question's figure, or with ``solution=True`` the solved one.

        Returns
        -------
        PIL.Image.Image or None
            None for topics that the notes do not draw (a colour conversion).
        """
        return None if self.draw is None else self.draw(solution)

    def check(self, answer: Mapping[str, Any]) -> CheckResult:
        """Mark an answer: a dict of field names to values, numbers or the text a student typed.

        Values may be given as text (``"0.49"``, ``"(1, 2) (3, 4)"``, ``"A, B, C"``). Required
        fields must all be given; optional (intermediate) ones are marked when given, so a
        student can find the first step that went wrong.

        Raises
        ------
        ValueError
            If the answer names a field the exercise does not have, or a value cannot be
            read as its field's kind.

        Examples
        --------
        >>> from pixelpath import exercises
        >>> ex = exercises.make("phong-intensity", seed=3)
        >>> ex.check(ex.answer).correct
        True
        >>> ex.check({"I": ex.answer["I"] + 0.1}).first_wrong
        'I'
        """
        if not isinstance(answer, Mapping):
            raise TypeError(f"answer must be a dict of field names to values, got "
                            f"{type(answer).__name__}")
        known = {field.name: field for field in self.fields}
        unknown = [name for name in answer if name not in known]
        if unknown:
            raise ValueError(f"unknown answer field(s) {', '.join(map(repr, unknown))} for "
                             f"{self.topic!r}; its fields are {', '.join(known)}")
        marks: dict[str, bool] = {}
        given: dict[str, Any] = {}
        for field in sorted(self.fields, key=lambda f: f.step):
            if field.name in answer:
                try:
                    given[field.name] = field.parse(answer[field.name])
                except (TypeError, ValueError) as exc:
                    raise ValueError(f"cannot read {field.name} = {answer[field.name]!r}: "
                                     f"{exc}") from None
                marks[field.name] = field.matches(given[field.name], self.answer[field.name])
            elif field.required:
                marks[field.name] = False
        first_wrong = next((name for name, right in marks.items() if not right), None)
        return CheckResult(first_wrong is None, first_wrong,
                           self._feedback(known.get(first_wrong), given), marks)

    def _feedback(self, field: Field | None, given: Mapping[str, Any]) -> str:
        if field is None:
            return "Correct."
        step = self.steps[field.step - 1]
        if field.name not in given:
            return (f"{field.name} ({field.label}) is missing: step {field.step} "
                    f"({step.title}) computes it.")
        text = (f"{field.name} is not right: look at step {field.step} ({step.title}); "
                f"{field.name} should be {shown(self.answer[field.name])}.")
        printed = self.errata.get(field.name)
        if printed is not None and field.matches(given[field.name], field.parse(printed)):
            text += f" {printed} is the value the notes print, and the notes are wrong here."
        return text

    def to_dict(self) -> dict:
        """Return the exercise as JSON-serializable data (what the playground and exports send)."""
        return {
            "topic": self.topic, "seed": self.seed, "difficulty": self.difficulty,
            "name": self.name, "title": self.title, "params": self.params,
            "question": self.question, "answer": self.answer, "solution": self.solution,
            "marking": self.marking,
            "fields": [dataclasses.asdict(field) for field in self.fields],
        }

    def figure_png(self, solution: bool = False) -> bytes | None:
        """Return the figure as PNG bytes, or None when the topic has no figure."""
        picture = self.figure(solution)
        if picture is None:
            return None
        buffer = io.BytesIO()
        picture.save(buffer, format="PNG", optimize=True)
        return buffer.getvalue()

    def _repr_markdown_(self) -> str:
        png = self.figure_png()
        if png is None:
            return self.question
        uri = "data:image/png;base64," + base64.b64encode(png).decode("ascii")
        return self.question.replace(f"({self.figure_name})", f"({uri})")


def exercise_name(topic: str, seed: int | None) -> str:
    """Return the identifier of an exercise: ``"<topic>-<seed>"``, or ``"notes-<topic>"``."""
    return f"notes-{topic}" if seed is None else f"{topic}-{seed}"


def shown(value: Any) -> str:
    """Write a value the way an exam answer does: numbers to 4 decimals at most.

    Examples
    --------
    >>> shown(0.492304), shown([1.0, 2.5]), shown(None), shown([[0, 1], [2.25, 3]])
    ('0.4923', '(1, 2.5)', 'none', '(0, 1) (2.25, 3)')
    """
    from pixelpath.color.explain import fmt  # the notes' way of writing a number

    return _written(value, fmt)


def exact(value: Any) -> str:
    """Write a value with up to 10 significant digits, for the answer key's last column.

    Examples
    --------
    >>> exact(2 / 3), exact([[0, 1 / 3], [1, 2]])
    ('0.6666666667', '(0, 0.3333333333) (1, 2)')
    """
    return _written(value, lambda number: f"{number:.10g}")


def _written(value: Any, number: Callable[[float], str]) -> str:
    """Write numbers, vectors, polygons (points), lists of polygons and labels."""
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, str):
        return value
    if isinstance(value, Sequence):
        items = [_written(v, number) for v in value]
        if value and all(isinstance(v, str) for v in value):
            return ", ".join(items)
        if value and all(_is_list(v) for v in value):
            return ("; " if all(_is_list(w) for v in value for w in v) else " ").join(items)
        return "(" + ", ".join(items) + ")"
    x = float(value) + 0.0  # no "-0"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    return number(x)


def _is_list(value: Any) -> bool:
    return isinstance(value, Sequence) and not isinstance(value, str)


def _label(value: Any) -> str:
    return str(value).strip().strip("()[]{}").strip().strip("\"'").upper()


def _json_list(value: Any) -> Any:
    """Return a JSON list typed as text (as scripts and autograders give it) as a list."""
    if isinstance(value, str) and value.lstrip().startswith("["):
        with contextlib.suppress(ValueError):
            return json.loads(value)
    return value


def _parse_number(value: Any) -> float | None:
    if value is None:
        return None
    if isinstance(value, str):
        text = value.strip().lower()
        if text in _NONE_WORDS:
            return None
        if not _NUMBER.fullmatch(text):
            raise ValueError(f"expected a number, got {value!r}")
        return float(text)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"expected a number, got {type(value).__name__}")
    return None if math.isinf(value) else float(value)


def _parse_numbers(value: Any) -> list[float]:
    if value is None:
        return []
    if isinstance(value, str):
        return [float(x) for x in _NUMBER.findall(value)]
    return [float(x) for x in value]


def _parse_points(value: Any) -> list[list[float]]:
    if value is None or (isinstance(value, str) and value.strip().lower() in _NONE_WORDS):
        return []
    numbers = _parse_numbers(value) if isinstance(value, str) else [
        float(x) for point in value for x in point]
    if len(numbers) % 2:
        raise ValueError("vertices need an x and a y each")
    return [numbers[k:k + 2] for k in range(0, len(numbers), 2)]


def _close(given: Sequence[float], expected: Sequence[float], tolerance: float) -> bool:
    return len(given) == len(expected) and all(
        abs(g - e) <= tolerance for g, e in zip(given, expected, strict=True))


def _same_polygon(given: list, expected: list, tolerance: float) -> bool:
    """Equal up to the starting vertex and the direction of travel."""
    flat = [[float(x) for x in p] for p in expected]
    if len(given) != len(flat):
        return False
    if not flat:
        return True
    for candidate in (given, given[::-1]):
        for shift in range(len(candidate)):
            turned = candidate[shift:] + candidate[:shift]
            if all(_close(g, e, tolerance) for g, e in zip(turned, flat, strict=True)):
                return True
    return False


def _same_polygons(given: list, expected: list, tolerance: float) -> bool:
    unmatched = list(expected)
    for polygon in given:
        match = next((k for k, e in enumerate(unmatched)
                      if _same_polygon(polygon, e, tolerance)), None)
        if match is None:
            return False
        unmatched.pop(match)
    return not unmatched
