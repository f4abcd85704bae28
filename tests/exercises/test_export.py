"""Exports of exercises: Markdown and HTML sheets, Moodle XML, PrairieLearn question folders."""

from __future__ import annotations

import base64
import colorsys
import dataclasses
import html
import importlib.util
import io
import json
import re
import uuid
import xml.etree.ElementTree as ET

import pytest
from PIL import Image

from pixelpath import exercises
from pixelpath.exercises import Field, Step
from pixelpath.exercises.exporting import export_exercises
from pixelpath.exercises.topics import TOPIC_REGISTRY, Solved, Topic

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
CLOZE_NUMBER = re.compile(r"\{1:NUMERICAL:=([^:}]+):([^}]+)\}")
CLOZE_TEXT = re.compile(r"\{1:SHORTANSWER:=((?:\\.|[^}\\])*)\}")


# A topic with a figure and one number to find: a size x (size + 1) picture, count its pixels.
def _pick_pixels(rng, difficulty):
    return {"size": rng.randint(2, 40)}


def _solve_pixels(params):
    size = params["size"]

    def draw(solution):
        return Image.new("RGB", (size, size + 1), (255, 0, 0) if solution else (0, 0, 255))

    return Solved(
        question=f"How many pixels has a picture of {size} by {size + 1} pixels?",
        answer={"n": size * (size + 1)},
        fields=(Field("n", "the number of pixels", 1, tolerance=0.5),),
        steps=(Step("count", (f"n = {size} × {size + 1}",)),),
        marking="Exact.",
        draw=draw,
    )


@pytest.fixture
def pixels(monkeypatch):
    """Register the test topic ``test-pixels`` for the test's duration; return its name."""
    monkeypatch.setitem(TOPIC_REGISTRY, "test-pixels",
                        Topic("test-pixels", "Count pixels", "tests", _pick_pixels, _solve_pixels))
    return "test-pixels"


def png_size(data: bytes) -> tuple[int, int]:
    assert data.startswith(PNG_SIGNATURE)
    with Image.open(io.BytesIO(data)) as picture:
        return picture.size


def hsv(rgb):
    h, s, v = colorsys.rgb_to_hsv(*rgb)
    return [h * 360, s, v]


def plain_text(page: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", "", page))


def load_server(path):
    spec = importlib.util.spec_from_file_location(f"pl_server_{path.parent.name}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def pl_data(variant_seed):
    return {"variant_seed": variant_seed, "params": {}, "correct_answers": {},
            "submitted_answers": {}, "raw_submitted_answers": {}, "format_errors": {},
            "partial_scores": {}, "feedback": {}, "score": 0.0}


# --- Markdown and HTML ---------------------------------------------------------------------

def test_markdown_has_every_question_in_the_worksheet_and_every_solution_in_the_key(
        tmp_path, pixels):
    sheet = [exercises.make("rgb-hsv", seed=1), exercises.make("rgb-cmyk", seed=2),
             exercises.make(pixels, seed=3)]
    written = export_exercises(sheet, tmp_path / "sheet")
    worksheet = (tmp_path / "sheet" / "worksheet.md").read_text()
    answers = (tmp_path / "sheet" / "answers.md").read_text()
    assert set(written) >= {tmp_path / "sheet" / "worksheet.md", tmp_path / "sheet" / "answers.md"}
    for number, exercise in enumerate(sheet, start=1):
        assert f"## {number}. {exercise.title}" in worksheet
        assert exercise.question in worksheet and exercise.question in answers
        assert exercise.solution in answers
        assert exercise.marking in answers
        for field in exercise.fields:
            assert f"{field.name} ({field.label}) = ____" in worksheet
    assert "**Step 1." not in worksheet and "Worked solution" not in worksheet


def test_markdown_figures_are_written_under_the_names_the_pages_link(tmp_path, pixels):
    exercise = exercises.make(pixels, seed=5)
    size = exercise.params["size"]
    # One question that links its figure itself, one that does not (the export links it).
    linked = dataclasses.replace(exercises.make(pixels, seed=6), question=(
        f"{exercises.make(pixels, seed=6).question}\n\n![the picture](test-pixels-6.png)"))
    export_exercises([exercise, linked], tmp_path)
    worksheet = (tmp_path / "worksheet.md").read_text()
    answers = (tmp_path / "answers.md").read_text()
    assert worksheet.count("(test-pixels-6.png)") == 1
    targets = set(re.findall(r"\]\(([^)]+\.png)\)", worksheet + answers))
    assert targets == {"test-pixels-5.png", "test-pixels-5-solution.png",
                       "test-pixels-6.png", "test-pixels-6-solution.png"}
    for name in targets:
        assert (tmp_path / name).is_file()
    assert png_size((tmp_path / "test-pixels-5.png").read_bytes()) == (size, size + 1)
    question, solved = (Image.open(tmp_path / f"test-pixels-5{tail}.png").convert("RGB")
                        for tail in ("", "-solution"))
    assert question.getpixel((0, 0)) == (0, 0, 255) and solved.getpixel((0, 0)) == (255, 0, 0)


def test_html_pages_render_the_markdown_with_tables_and_embedded_figures(tmp_path, pixels):
    sheet = [exercises.make("rgb-hsv", seed=1), exercises.make(pixels, seed=2)]
    written = export_exercises(sheet, tmp_path, format="html")
    assert sorted(p.name for p in written) == ["answers.html", "worksheet.html"]
    assert not list(tmp_path.glob("*.png"))  # the figures are inside the pages
    worksheet = (tmp_path / "worksheet.html").read_text()
    answers = (tmp_path / "answers.html").read_text()
    for page in (worksheet, answers):
        assert page.startswith("<!DOCTYPE html>") and page.count("<section>") == 2
        for exercise in sheet:
            assert exercise.question in plain_text(page)
    # The solution's answer table is an HTML table, not Markdown source.
    assert "<table>" in answers and "|---|" not in answers and "**" not in answers
    assert "Step 6. saturation S" in plain_text(answers)
    assert "Step 1." not in plain_text(worksheet)
    sources = re.findall(r'src="data:image/png;base64,([^"]+)"', answers)
    size = sheet[1].params["size"]
    assert [png_size(base64.b64decode(s)) for s in sources] == [(size, size + 1)] * 2


# --- Moodle ----------------------------------------------------------------------------------

def test_moodle_quiz_has_categories_numerical_and_cloze_questions(tmp_path, pixels):
    sheet = [exercises.make("rgb-hsv", seed=1), exercises.make("rgb-hsv", seed=2),
             exercises.make(pixels, seed=3)]
    (path,) = export_exercises(sheet, tmp_path, format="moodle")
    assert path == tmp_path / "quiz.xml"
    assert path.read_bytes().startswith(b"<?xml")
    quiz = ET.parse(path).getroot()
    assert quiz.tag == "quiz"
    questions = quiz.findall("question")
    assert [q.get("type") for q in questions] == [
        "category", "cloze", "cloze", "category", "numerical"]
    assert [q.findtext("category/text") for q in questions if q.get("type") == "category"] == [
        "$course$/top/pixelpath/rgb-hsv", "$course$/top/pixelpath/test-pixels"]
    for question, exercise in zip(
            [q for q in questions if q.get("type") != "category"], sheet, strict=True):
        assert exercise.name in question.findtext("name/text")
        assert question.find("questiontext").get("format") == "html"
        feedback = question.find("generalfeedback")
        assert feedback.get("format") == "html"
        for step in exercise.steps:
            assert step.title in plain_text(feedback.findtext("text"))


def test_moodle_cloze_boxes_hold_each_value_with_its_tolerance(tmp_path):
    exercise = exercises.make("rgb-hsv", seed=4)
    (path,) = export_exercises([exercise], tmp_path / "hsv.xml", format="moodle")
    assert path == tmp_path / "hsv.xml"
    text = ET.parse(path).getroot().find("question[@type='cloze']").findtext("questiontext/text")
    boxes = [(float(v), float(t)) for v, t in CLOZE_NUMBER.findall(text)]
    # h, s, v in field order; the hue is marked to a degree, the others to 0.01.
    expected = hsv(exercise.params["rgb"])
    assert [t for _, t in boxes] == [1.0, 0.01, 0.01]
    for (value, _), right in zip(boxes, expected, strict=True):
        assert value == pytest.approx(right, abs=1e-6)


def test_moodle_cloze_of_vertices_labels_and_none(tmp_path):
    base = exercises.make("rgb-hsv", seed=1)
    fields = (Field("P", "the clipped polygon", 1, kind="polygon", tolerance=0.05),
              Field("S", "the subdivided areas", 1, kind="set"),
              Field("C", "the choice", 1, kind="choice"),
              Field("t", "the hit", 1),
              Field("x", "an intermediate value", 1, required=False))
    answer = {"P": [[0, 1], [2.5, 3], [1, 1]], "S": ["R2", "R1"], "C": "A/B}", "t": None, "x": 7}
    odd = dataclasses.replace(base, fields=fields, answer=answer)
    (path,) = export_exercises([odd], tmp_path, format="moodle")
    question = ET.parse(path).getroot().find("question[@type='cloze']")
    text = question.findtext("questiontext/text")
    assert CLOZE_NUMBER.findall(text) == [("0", "0.05"), ("1", "0.05"), ("2.5", "0.05"),
                                          ("3", "0.05"), ("1", "0.05"), ("1", "0.05")]
    # Sets in alphabetical order; cloze's special characters escaped; a missing value: none.
    assert CLOZE_TEXT.findall(text) == ["R1", "R2", r"A\/B\}", "none"]
    assert "an intermediate value" not in text  # optional fields are not asked


def test_moodle_figures_are_embedded_files(tmp_path, pixels):
    exercise = exercises.make(pixels, seed=8)
    size = exercise.params["size"]
    (path,) = export_exercises([exercise], tmp_path, format="moodle")
    question = ET.parse(path).getroot().find("question[@type='numerical']")
    answer = question.find("answer")
    assert answer.get("fraction") == "100"
    assert float(answer.findtext("text")) == size * (size + 1)
    assert float(answer.findtext("tolerance")) == 0.5
    files = {f.get("name"): f for f in question.iter("file")}
    assert set(files) == {"test-pixels-8.png", "test-pixels-8-solution.png"}
    for element in files.values():
        assert element.get("encoding") == "base64"
        assert png_size(base64.b64decode(element.text)) == (size, size + 1)
    assert question.find("questiontext/file").get("name") == "test-pixels-8.png"
    assert '"@@PLUGINFILE@@/test-pixels-8.png"' in question.findtext("questiontext/text")
    assert question.find("generalfeedback/file").get("name") == "test-pixels-8-solution.png"


# --- PrairieLearn ------------------------------------------------------------------------------

def test_prairielearn_folders_have_the_layout_and_info(tmp_path, pixels):
    sheet = [exercises.make("rgb-hsv", seed=1), exercises.make(pixels, seed=2)]
    written = export_exercises(sheet, tmp_path, format="prairielearn")
    assert {p.parent.name for p in written} == {"rgb-hsv-1", "test-pixels-2"}
    uuids = []
    for exercise in sheet:
        folder = tmp_path / exercise.name
        assert {p.name for p in folder.iterdir()} == {"info.json", "question.html", "server.py"}
        info = json.loads((folder / "info.json").read_text())
        assert info["type"] == "v3" and exercise.topic in info["tags"]
        assert info["title"] and info["topic"]
        uuids.append(uuid.UUID(info["uuid"]))
        page = (folder / "question.html").read_text()
        assert "<pl-answer-panel>" in page and "<pl-question-panel>" in page
        for field in exercise.fields:
            assert f'<pl-number-input answers-name="{field.name}"' in page
    assert len(set(uuids)) == 2
    assert 'type="dynamic"' in (tmp_path / "test-pixels-2" / "question.html").read_text()
    # A re-export keeps the uuids, so the course's question is updated, not duplicated.
    export_exercises(sheet, tmp_path, format="prairielearn")
    assert uuids == [uuid.UUID(json.loads((tmp_path / e.name / "info.json").read_text())["uuid"])
                     for e in sheet]


def test_prairielearn_server_gives_each_variant_its_numbers_and_grades_with_check(tmp_path):
    export_exercises([exercises.make("rgb-hsv", seed=1)], tmp_path, format="prairielearn")
    server = load_server(tmp_path / "rgb-hsv-1" / "server.py")
    first, second = pl_data(11), pl_data(12)
    server.generate(first)
    server.generate(second)
    assert first["params"]["given"] != second["params"]["given"]
    for data in (first, second):
        right = hsv(data["params"]["given"]["rgb"])
        assert [data["correct_answers"][k] for k in "hsv"] == pytest.approx(right)
        assert "<p>" in data["params"]["question_html"]
        assert "<table>" in data["params"]["solution_html"]
    first["submitted_answers"] = dict(first["correct_answers"])
    server.parse(first)
    server.grade(first)
    assert first["format_errors"] == {} and first["score"] == 1.0
    first["submitted_answers"]["s"] = first["correct_answers"]["s"] + 0.2
    server.grade(first)
    assert first["score"] < 1
    assert first["partial_scores"]["s"]["score"] == 0 and first["partial_scores"]["h"]["score"] == 1
    assert "step 6" in first["feedback"]["check"]


def test_prairielearn_server_draws_the_variants_figure(tmp_path, pixels):
    export_exercises([exercises.make(pixels, seed=1)], tmp_path, format="prairielearn")
    server = load_server(tmp_path / "test-pixels-1" / "server.py")
    data = pl_data(2024)
    server.generate(data)
    size = data["params"]["given"]["size"]
    assert data["correct_answers"] == {"n": size * (size + 1)}
    assert png_size(server.file({**data, "filename": "figure.png"})) == (size, size + 1)
    data["submitted_answers"] = {"n": "not a number"}
    server.parse(data)
    assert "n" in data["format_errors"]


@pytest.mark.parametrize("difficulty", ["standard", "edge"])
def test_every_topic_exports_in_every_format_and_its_server_grades_its_answer(tmp_path,
                                                                             difficulty):
    sheet = [exercises.make(topic, seed=1, difficulty=difficulty) for topic in exercises.TOPICS]
    for format in ("markdown", "html", "moodle", "prairielearn"):
        export_exercises(sheet, tmp_path / format, format=format)
    worksheet = (tmp_path / "markdown" / "worksheet.md").read_text()
    for target in re.findall(r"\]\(([^)]+\.png)\)", worksheet):
        assert (tmp_path / "markdown" / target).read_bytes().startswith(PNG_SIGNATURE)
    quiz = ET.parse(tmp_path / "moodle" / "quiz.xml").getroot()
    assert len(quiz.findall("question[@type='numerical']")) + len(
        quiz.findall("question[@type='cloze']")) == len(sheet)
    for exercise in sheet:
        assert exercise.question in worksheet
        server = load_server(tmp_path / "prairielearn" / exercise.name / "server.py")
        data = pl_data(99)
        server.generate(data)
        if exercise.figure() is not None:  # shown by pl-figure, not by a broken <img>
            assert "<img" not in data["params"]["question_html"]
        data["submitted_answers"] = dict(data["correct_answers"])
        server.parse(data)
        assert data["format_errors"] == {}, exercise.topic
        server.grade(data)
        assert data["score"] == 1.0, (exercise.topic, data["feedback"])


# --- Errors and the folder --------------------------------------------------------------------

def test_unknown_format_lists_the_formats(tmp_path):
    with pytest.raises(ValueError, match="markdown, html, moodle, prairielearn"):
        export_exercises([exercises.make("rgb-hsv")], tmp_path, format="pdf")


@pytest.mark.parametrize(("items", "error", "message"), [
    ([], ValueError, "empty"),
    (["rgb-hsv"], TypeError, "item 1 is a str, not an Exercise"),
    (None, TypeError, "list of Exercise"),
])
def test_bad_lists_are_refused(tmp_path, items, error, message):
    with pytest.raises(error, match=message):
        export_exercises(items, tmp_path)


def test_a_single_exercise_is_not_a_list(tmp_path):
    with pytest.raises(TypeError, match="list of Exercise"):
        export_exercises(exercises.make("rgb-hsv"), tmp_path)


def test_two_exercises_with_one_name_are_refused(tmp_path):
    twins = [exercises.make("rgb-hsv", seed=1), exercises.make("rgb-hsv", seed=1,
                                                               difficulty="easy")]
    with pytest.raises(ValueError, match="rgb-hsv-1"):
        export_exercises(twins, tmp_path, format="prairielearn")


def test_a_file_in_place_of_the_folder_is_refused(tmp_path):
    (tmp_path / "taken").write_text("mine")
    with pytest.raises(ValueError, match="is a file"):
        export_exercises([exercises.make("rgb-hsv")], tmp_path / "taken")
    assert (tmp_path / "taken").read_text() == "mine"


def test_a_reexport_replaces_its_own_files_and_leaves_others(tmp_path):
    (tmp_path / "notes.txt").write_text("keep me")
    (tmp_path / "worksheet.md").write_text("old")
    export_exercises([exercises.make("rgb-hsv", seed=1)], tmp_path)
    export_exercises([exercises.make("rgb-hsv", seed=2)], tmp_path)
    assert (tmp_path / "notes.txt").read_text() == "keep me"
    assert exercises.make("rgb-hsv", seed=2).question in (tmp_path / "worksheet.md").read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["answers.md", "notes.txt",
                                                          "worksheet.md"]


def test_the_notes_examples_export_with_the_corrected_values(tmp_path):
    (path,) = export_exercises(exercises.from_notes(), tmp_path, format="moodle")
    quiz = ET.parse(path).getroot()
    phong = next(q for q in quiz.findall("question")
                 if q.findtext("idnumber") == "notes-phong-intensity")
    # The notes' example: I = ka Ia + kd IL N.L + ks IL (R.V)^n, which the notes misprint.
    right = 0.2 * 0.2 + 0.6 * 1 * 0.707 + 0.5 * 1 * 0.866 ** 20
    assert phong.get("type") == "numerical"
    assert float(phong.findtext("answer/text")) == pytest.approx(right, abs=1e-4)
    assert "0.47005" in plain_text(phong.findtext("generalfeedback/text"))  # named as wrong
