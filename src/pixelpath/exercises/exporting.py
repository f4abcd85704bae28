"""Exports of exercises: worksheets, answer keys, Moodle XML and PrairieLearn questions.

Every format is made from the exercises' own Markdown (:attr:`Exercise.question` and
:attr:`Exercise.solution`); HTML is rendered from it by ``markdown-it-py``. ``path`` is a folder
(made if missing) that the export owns: the files it writes there (``worksheet.md``,
``answers.md``, the figures, ``quiz.xml``, one folder per PrairieLearn question) are replaced
if they exist, each written atomically (a temporary file, then a rename); nothing else in it
is touched or removed. A Moodle export may instead name its ``.xml`` file.

Formats
-------
``"markdown"``
    ``worksheet.md`` (numbered questions and blanks for the answers), ``answers.md`` (the
    answer key: each question, its worked solution and marking) and the figures as PNG
    beside them, under the names the questions link (``<topic>-<seed>.png``; the solved
    figure ``<topic>-<seed>-solution.png``).
``"html"``
    ``worksheet.html`` and ``answers.html``, printable pages of the same Markdown with the
    figures embedded, so each file stands alone.
``"moodle"``
    One Moodle XML file (``quiz.xml``): a category per topic (``$course$/top/pixelpath/<topic>``,
    so a quiz can draw a random question, a different seed for each student), then one
    question per exercise. An exercise that asks for one number is a ``numerical`` question
    with its tolerance; any other is a ``cloze`` question with one box per number (vectors
    and vertices too, each with its tolerance; vertices in the order the algorithm outputs
    them) and one short-answer box per label (sets in alphabetical order); a value that is
    "none" (a ray that misses) is the short answer ``none``. Optional (intermediate) fields
    are left out. The worked solution is the general feedback; figures are embedded files.
``"prairielearn"``
    A question folder per exercise, named ``<topic>-<seed>``: ``info.json`` (a uuid derived
    from topic, seed and difficulty, so a re-export updates the same question),
    ``question.html`` and ``server.py``. Each variant is ``make(topic, seed, difficulty)``
    with the seed from PrairieLearn's variant seed, so every student gets their own numbers;
    grading calls :meth:`Exercise.check` (a score per answer box, the feedback of the first
    wrong value). The course's Python needs pixelpath installed.
"""

from __future__ import annotations

import base64
import functools
import html
import json
import os
import re
import uuid
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

from pixelpath import __version__
from pixelpath.exercises.exercise import Exercise, Field, shown
from pixelpath.io.images import write_bytes

__all__ = ["FORMATS", "export_exercises", "markdown_html"]

#: The export formats of :func:`export_exercises`.
FORMATS = ("markdown", "html", "moodle", "prairielearn")

# The PrairieLearn uuids of pixelpath's questions: uuid5 of this namespace and the question.
_UUID_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "https://pixelpath/exercises")
_MOODLE_FILE = "quiz.xml"
_TITLES = {"worksheet": "Exercises", "answers": "Answer key"}
# Characters that end or split a cloze answer unless escaped (Moodle's Embedded Answers docs).
_CLOZE_SPECIAL = re.compile(r'([}#~/"\\])')
_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}</title>
<style>
body {{ font-family: Georgia, serif; max-width: 48em; margin: 2em auto; padding: 0 1em; }}
section {{ break-inside: avoid; margin-bottom: 2em; }}
table {{ border-collapse: collapse; }}
th, td {{ border: 1px solid #999; padding: 0.2em 0.6em; text-align: left; }}
img {{ max-width: 100%; }}
@media print {{ section {{ page-break-inside: avoid; }} }}
</style>
</head>
<body>
{body}
</body>
</html>
"""


def export_exercises(exercises: Sequence[Exercise], path: str | os.PathLike,
                     format: str = "markdown") -> list[Path]:
    """Write exercises as a worksheet and answer key, or for Moodle or PrairieLearn.

    Parameters
    ----------
    exercises : sequence of Exercise
        What to export, in order (from :func:`pixelpath.exercises.make`).
    path : str or os.PathLike
        The folder to write into, made if missing (see the module's notes on what is
        replaced); for ``"moodle"`` it may also be the ``.xml`` file itself.
    format : {"markdown", "html", "moodle", "prairielearn"}, default "markdown"
        See the module's notes.

    Returns
    -------
    list of Path
        Every file written, in the order written.

    Raises
    ------
    ValueError
        If the format is unknown (the message lists the formats), the list is empty, two
        exercises share a name (the same topic and seed) or ``path`` is a file.
    TypeError
        If an item is not an :class:`Exercise`.

    Examples
    --------
    >>> from pixelpath import exercises
    >>> from pixelpath.exercises.exporting import export_exercises
    >>> sheet = [exercises.make("rgb-hsv", seed=s) for s in (1, 2)]
    >>> [p.name for p in export_exercises(sheet, "sheet")]
    ['worksheet.md', 'answers.md']
    >>> [p.name for p in export_exercises(sheet, "sheet", format="moodle")]
    ['quiz.xml']
    """
    if format not in _WRITERS:
        raise ValueError(f"unknown export format {format!r}; choose from {', '.join(FORMATS)}")
    items = _checked(exercises)
    return _WRITERS[format](items, Path(path))


def markdown_html(text: str) -> str:
    r"""Render Markdown (an exercise's question or solution) as HTML, tables included.

    Examples
    --------
    >>> print(markdown_html("**Step 1.** I = 0.49\n\n| a | b |\n|---|---|\n| 1 | 2 |"))
    <p><strong>Step 1.</strong> I = 0.49</p>
    <table>
    ...
    <td>1</td>
    ...
    """
    return markdown_parser().render(text)


@functools.cache
def markdown_parser() -> Any:
    """Return the parser of exercises' Markdown: CommonMark with tables, raw HTML as text."""
    from markdown_it import MarkdownIt

    return MarkdownIt("commonmark", {"html": False}).enable("table")


def _checked(exercises: Sequence[Exercise]) -> list[Exercise]:
    if isinstance(exercises, Exercise) or not isinstance(exercises, Iterable):
        raise TypeError(f"exercises must be a list of Exercise, got {type(exercises).__name__}")
    items = list(exercises)
    if not items:
        raise ValueError("nothing to export: the list of exercises is empty")
    names: set[str] = set()
    for position, item in enumerate(items, start=1):
        if not isinstance(item, Exercise):
            raise TypeError(f"item {position} is a {type(item).__name__}, not an Exercise")
        # The name becomes file and folder names: it must stay inside the export folder.
        if not re.fullmatch(r"[\w.-]+", item.name) or item.name.startswith("."):
            raise ValueError(f"item {position}: {item.name!r} cannot name a file")
        if item.name in names:
            raise ValueError(f"two exercises are named {item.name!r} (the same topic and seed); "
                             "their files would overwrite each other")
        names.add(item.name)
    return items


def _folder(path: Path) -> Path:
    if path.exists() and not path.is_dir():
        raise ValueError(f"{path} is a file; exports write into a folder")
    path.mkdir(parents=True, exist_ok=True)
    return path


def _write(path: Path, data: bytes | str) -> Path:
    write_bytes(path, data.encode("utf-8") if isinstance(data, str) else data)
    return path


def _solution_figure_name(exercise: Exercise) -> str:
    return f"{exercise.name}-solution.png"


def _figures(exercise: Exercise) -> dict[str, bytes]:
    """Draw the exercise's figures as PNG by file name: the question's, then the solved one."""
    pictures = {exercise.figure_name: exercise.figure_png(),
                _solution_figure_name(exercise): exercise.figure_png(solution=True)}
    return {name: png for name, png in pictures.items() if png is not None}


def _image(name: str, alt: str) -> str:
    return f"![{alt}]({name})"


def _question(exercise: Exercise, figures: dict[str, bytes]) -> str:
    """Return the question's Markdown, linking its figure where the question does not."""
    name = exercise.figure_name
    if name in figures and f"({name})" not in exercise.question:
        return f"{exercise.question}\n\n{_image(name, 'Figure')}"
    return exercise.question


def _solution(exercise: Exercise, figures: dict[str, bytes]) -> str:
    name = _solution_figure_name(exercise)
    if name in figures:
        return f"{exercise.solution}\n\n{_image(name, 'The solved figure')}"
    return exercise.solution


def _heading(number: int, exercise: Exercise) -> str:
    source = ("the notes' example" if exercise.seed is None
              else f"seed {exercise.seed}, {exercise.difficulty}")
    return f"## {number}. {exercise.title}\n\n*{exercise.topic}, {source}*"


def _blanks(exercise: Exercise) -> str:
    return "\n".join(f"- {field.name} ({field.label}) = ____________"
                     for field in exercise.fields if field.required)


def _worksheet_entry(number: int, exercise: Exercise, figures: dict[str, bytes]) -> str:
    return "\n\n".join([_heading(number, exercise), _question(exercise, figures),
                        _blanks(exercise)])


def _answer_entry(number: int, exercise: Exercise, figures: dict[str, bytes]) -> str:
    return "\n\n".join([_heading(number, exercise), _question(exercise, figures),
                        "### Worked solution", _solution(exercise, figures),
                        f"*Marking:* {exercise.marking}"])


def _markdown_pages(exercises: list[Exercise]) -> tuple[dict[str, list[str]], dict[str, bytes]]:
    """Each page's entries (one Markdown text an exercise) by page name, and every figure."""
    figures = [_figures(exercise) for exercise in exercises]
    numbered = list(enumerate(zip(exercises, figures, strict=True), start=1))
    pages = {"worksheet": [_worksheet_entry(n, ex, pictures) for n, (ex, pictures) in numbered],
             "answers": [_answer_entry(n, ex, pictures) for n, (ex, pictures) in numbered]}
    return pages, {name: png for pictures in figures for name, png in pictures.items()}


def _write_markdown(exercises: list[Exercise], path: Path) -> list[Path]:
    folder = _folder(path)
    pages, figures = _markdown_pages(exercises)
    written = [_write(folder / f"{page}.md", "\n\n".join([f"# {_TITLES[page]}", *entries]) + "\n")
               for page, entries in pages.items()]
    return written + [_write(folder / name, png) for name, png in figures.items()]


def _relinked(text: str, figures: dict[str, bytes], target: Callable[[str, bytes], str]) -> str:
    """Point the Markdown links to each figure at ``target(name, png)``."""
    for name, png in figures.items():
        text = text.replace(f"({name})", f"({target(name, png)})")
    return text


def _data_uri(name: str, png: bytes) -> str:
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def _write_html(exercises: list[Exercise], path: Path) -> list[Path]:
    folder = _folder(path)
    pages, figures = _markdown_pages(exercises)
    written = []
    for page, entries in pages.items():
        # A <section> an exercise, kept on one printed page where it fits.
        sections = [f"<section>\n{markdown_html(_relinked(entry, figures, _data_uri))}</section>"
                    for entry in entries]
        title = html.escape(_TITLES[page])
        body = "\n".join([f"<h1>{title}</h1>", *sections])
        written.append(_write(folder / f"{page}.html", _PAGE.format(title=title, body=body)))
    return written


def _number(value: float) -> str:
    return f"{float(value):.10g}"


def _cloze_number(value: float, field: Field) -> str:
    return f"{{1:NUMERICAL:={_number(value)}:{field.tolerance:g}}}"


def _cloze_text(text: str) -> str:
    escaped = _CLOZE_SPECIAL.sub(r"\\\1", html.escape(text, quote=False))
    return f"{{1:SHORTANSWER:={escaped}}}"


def _cloze_point(point: Sequence[float], field: Field) -> str:
    return "(" + ", ".join(_cloze_number(x, field) for x in point) + ")"


def _cloze_polygon(polygon: Sequence[Sequence[float]], field: Field) -> str:
    return " ".join(_cloze_point(point, field) for point in polygon)


def _cloze(field: Field, value) -> str:
    """Write the cloze boxes of one value: a box per number, a short answer per label."""
    if value is None or (field.kind in ("polygon", "polygons") and not value):
        return _cloze_text("none")
    if field.kind == "number":
        return _cloze_number(value, field)
    if field.kind == "vector":
        return _cloze_point(value, field)
    if field.kind == "polygon":
        return _cloze_polygon(value, field)
    if field.kind == "polygons":
        return "; ".join(_cloze_polygon(polygon, field) for polygon in value)
    if field.kind == "choice":
        return _cloze_text(shown(value))
    labels = sorted(map(shown, value)) if field.kind == "set" else [shown(v) for v in value]
    separator = "<br>" if field.kind == "grid" else ", "
    return separator.join(_cloze_text(label) for label in labels)


def _cloze_hint(field: Field) -> str:
    return {"polygon": " (vertices in the order the algorithm outputs them)",
            "polygons": " (each piece's vertices in the order the algorithm outputs them)",
            "set": " (in alphabetical order)",
            "grid": " (one row a box, top row first)"}.get(field.kind, "")


def _is_numerical(exercise: Exercise) -> bool:
    """Whether the exercise asks for one number (a Moodle ``numerical`` question)."""
    required = [field for field in exercise.fields if field.required]
    return (len(required) == 1 and required[0].kind == "number"
            and exercise.answer[required[0].name] is not None)


def _sub(parent: ET.Element, tag: str, text: str | None = None, **attributes: str) -> ET.Element:
    element = ET.SubElement(parent, tag, attributes)
    if text is not None:
        element.text = text
    return element


def _moodle_text(parent: ET.Element, tag: str, markdown: str, files: dict[str, bytes],
                 after: str = "") -> None:
    """Add a Moodle HTML text (Markdown, then ``after`` as HTML) with the figures it links."""
    element = _sub(parent, tag, format="html")
    linked = {name: png for name, png in files.items() if f"({name})" in markdown}
    _sub(element, "text", markdown_html(_relinked(
        markdown, linked, lambda name, png: f"@@PLUGINFILE@@/{name}")) + after)
    for name, png in linked.items():
        _sub(element, "file", base64.b64encode(png).decode("ascii"),
             name=name, path="/", encoding="base64")


def _cloze_boxes(exercise: Exercise) -> str:
    # HTML, not Markdown: Markdown would eat the backslashes that escape cloze answers.
    return "".join(
        f"<p>{html.escape(field.label)} ({field.name}){_cloze_hint(field)}: "
        f"{_cloze(field, exercise.answer[field.name])}</p>\n"
        for field in exercise.fields if field.required)


def _moodle_question(quiz: ET.Element, exercise: Exercise) -> None:
    figures = _figures(exercise)
    numerical = _is_numerical(exercise)
    question = _sub(quiz, "question", type="numerical" if numerical else "cloze")
    _sub(_sub(question, "name"), "text", f"{exercise.title} ({exercise.name})")
    _moodle_text(question, "questiontext", _question(exercise, figures), figures,
                 after="" if numerical else _cloze_boxes(exercise))
    _moodle_text(question, "generalfeedback",
                 f"{_solution(exercise, figures)}\n\n*Marking:* {exercise.marking}", figures)
    _sub(question, "defaultgrade", "1")
    _sub(question, "penalty", "0.3333333")
    _sub(question, "hidden", "0")
    _sub(question, "idnumber", exercise.name)
    if numerical:
        field = next(field for field in exercise.fields if field.required)
        answer = _sub(question, "answer", fraction="100", format="moodle_auto_format")
        _sub(answer, "text", _number(exercise.answer[field.name]))
        _sub(answer, "tolerance", f"{field.tolerance:g}")
        _sub(_sub(answer, "feedback", format="html"), "text", "")


def _moodle_xml(exercises: list[Exercise]) -> bytes:
    quiz = ET.Element("quiz")
    topic = None
    for exercise in exercises:
        if exercise.topic != topic:
            topic = exercise.topic
            category = _sub(quiz, "question", type="category")
            _sub(_sub(category, "category"), "text", f"$course$/top/pixelpath/{topic}")
            _sub(_sub(category, "info", format="html"), "text", exercise.title)
        _moodle_question(quiz, exercise)
    ET.indent(quiz)
    return ET.tostring(quiz, encoding="utf-8", xml_declaration=True) + b"\n"


def _write_moodle(exercises: list[Exercise], path: Path) -> list[Path]:
    target = path if path.suffix.lower() == ".xml" else _folder(path) / _MOODLE_FILE
    if not target.parent.is_dir():
        raise FileNotFoundError(f"output directory does not exist: {target.parent}")
    return [_write(target, _moodle_xml(exercises))]


def _number_input(field: Field, exercise: Exercise) -> bool:
    """Whether PrairieLearn asks for the field in a number box (else a text box).

    A number that can be "none" (a ray that misses, in edge cases) needs a text box.
    """
    return field.kind == "number" and exercise.difficulty != "edge"


def _pl_info(exercise: Exercise) -> dict:
    key = f"pixelpath:{exercise.topic}:{exercise.seed}:{exercise.difficulty}"
    return {"uuid": str(uuid.uuid5(_UUID_NAMESPACE, key)), "type": "v3",
            "title": f"{exercise.title} ({exercise.name})", "topic": exercise.title,
            "tags": ["pixelpath", exercise.topic, exercise.difficulty]}


def _pl_input(field: Field, exercise: Exercise) -> str:
    label = html.escape(f"{field.name} =", quote=True)
    if _number_input(field, exercise):
        return (f'<pl-number-input answers-name="{field.name}" label="{label}" '
                f'comparison="relabs" rtol="0" atol="{field.tolerance:g}"></pl-number-input>')
    return (f'<pl-string-input answers-name="{field.name}" label="{label}" '
            f'placeholder="{_PLACEHOLDERS[field.kind]}"></pl-string-input>')


# What a student types in a PrairieLearn text box, by field kind (Field.parse reads it).
_PLACEHOLDERS = {"number": "a number, or none", "vector": "(x, y, z), or none",
                 "polygon": "(x, y) (x, y) ...", "polygons": "(x, y) (x, y) ...; (x, y) ...",
                 "sequence": "A, B, C", "set": "A, B, C", "choice": "A", "grid": "AB BA"}


def _pl_figure(name: str) -> str:
    return f'<pl-figure file-name="{name}" type="dynamic"></pl-figure>'


def _pl_question_html(exercise: Exercise) -> str:
    figures = _figures(exercise)
    question = ["<pl-question-panel>", "{{{params.question_html}}}"]
    if exercise.figure_name in figures:
        question.append(_pl_figure("figure.png"))
    inputs = [f"<p>{html.escape(field.label)}: {_pl_input(field, exercise)}</p>"
              for field in exercise.fields if field.required]
    answer = ["<pl-answer-panel>", "{{{params.solution_html}}}"]
    if _solution_figure_name(exercise) in figures:
        answer.append(_pl_figure("solution.png"))
    return "\n".join([*question, "</pl-question-panel>", "", *inputs, "",
                      "<pl-submission-panel>{{feedback.check}}</pl-submission-panel>", "",
                      *answer, "</pl-answer-panel>", ""])


def _pl_server(exercise: Exercise) -> str:
    numbers = tuple(field.name for field in exercise.fields
                    if field.required and _number_input(field, exercise))
    return _SERVER.format(topic=exercise.topic, difficulty=exercise.difficulty,
                          version=__version__, numbers=numbers)


def _write_prairielearn(exercises: list[Exercise], path: Path) -> list[Path]:
    folder = _folder(path)
    written = []
    for exercise in exercises:
        question = folder / exercise.name
        question.mkdir(exist_ok=True)
        written += [
            _write(question / "info.json", json.dumps(_pl_info(exercise), indent=2) + "\n"),
            _write(question / "question.html", _pl_question_html(exercise)),
            _write(question / "server.py", _pl_server(exercise)),
        ]
    return written


_WRITERS: dict[str, Callable[[list[Exercise], Path], list[Path]]] = {
    "markdown": _write_markdown, "html": _write_html, "moodle": _write_moodle,
    "prairielearn": _write_prairielearn,
}

# The server.py of a PrairieLearn question (str.format fills the braces that are not doubled).
_SERVER = '''"""PrairieLearn question: the pixelpath exercise {topic!r} ({difficulty}).

Written by pixelpath {version}. Each variant is pixelpath.exercises.make({topic!r}, seed,
{difficulty!r}) with the seed taken from PrairieLearn's variant seed, so every student gets
their own numbers; grading calls the exercise's own check. Needs pixelpath installed.
"""

import re

from pixelpath.exercises import make
from pixelpath.exercises.exercise import shown
from pixelpath.exercises.exporting import markdown_html

TOPIC = {topic!r}
DIFFICULTY = {difficulty!r}
# Answers asked in a number box; the others are typed as text.
NUMBER_INPUTS = {numbers!r}


def _exercise(data):
    return make(TOPIC, seed=data["params"]["seed"], difficulty=DIFFICULTY)


def _typed(field, value):
    """The answer as a student types it in a text box (grid rows apart by spaces)."""
    return " ".join(value) if field.kind == "grid" and value else shown(value)


def generate(data):
    seed = abs(int(data["variant_seed"]))
    exercise = make(TOPIC, seed=seed, difficulty=DIFFICULTY)
    # The figure is shown by a pl-figure element (question.html), not by the Markdown link.
    question = re.sub(r"!\\[[^\\]]*\\]\\(" + re.escape(exercise.figure_name) + r"\\)", "",
                      exercise.question)
    data["params"]["seed"] = seed
    data["params"]["given"] = exercise.params
    data["params"]["question_html"] = markdown_html(question)
    data["params"]["solution_html"] = markdown_html(
        exercise.solution + "\\n\\n*Marking:* " + exercise.marking)
    for field in exercise.fields:
        if field.required:
            value = exercise.answer[field.name]
            data["correct_answers"][field.name] = (
                float(value) if field.name in NUMBER_INPUTS else _typed(field, value))


def parse(data):
    for field in _exercise(data).fields:
        given = data["submitted_answers"].get(field.name)
        if given is None or field.name in data["format_errors"]:
            continue
        try:
            field.parse(given)
        except (TypeError, ValueError) as exc:
            data["format_errors"][field.name] = str(exc)


def grade(data):
    exercise = _exercise(data)
    required = [field.name for field in exercise.fields if field.required]
    given = {{name: data["submitted_answers"][name] for name in required
             if data["submitted_answers"].get(name) is not None}}
    result = exercise.check(given)
    for name in required:
        right = result.marks.get(name, False)
        feedback = result.feedback if name == result.first_wrong else ""
        data["partial_scores"][name] = {{"score": float(right), "weight": 1,
                                         "feedback": feedback}}
    data["score"] = sum(result.marks.get(name, False) for name in required) / len(required)
    data["feedback"]["check"] = result.feedback


def file(data):
    return _exercise(data).figure_png(solution=data["filename"] == "solution.png")
'''
