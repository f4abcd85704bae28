"""``pixelpath exercise``: list, print, mark, draw and export the notes' exam questions."""

from __future__ import annotations

import colorsys
import xml.etree.ElementTree as ET

import pytest
from PIL import Image

from pixelpath import exercises
from pixelpath.cli import main
from pixelpath.exercises import Field, Step
from pixelpath.exercises.topics import TOPIC_REGISTRY, Solved, Topic


def run(capsys, *argv):
    code = main(["exercise", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def hsv_answer(seed):
    """The right answer of rgb-hsv at ``seed``, computed with colorsys, as --check text."""
    h, s, v = colorsys.rgb_to_hsv(*exercises.make("rgb-hsv", seed=seed).params["rgb"])
    return f"h={h * 360:.2f}; s={s:.3f}; v={v:.3f}"


@pytest.fixture
def square(monkeypatch):
    """A test topic with a figure: a blue square of side ``size`` (the solved one red)."""

    def solve(params):
        size = params["size"]
        return Solved(
            question=f"How many pixels has a {size} by {size} square?",
            answer={"n": size * size}, fields=(Field("n", "the pixels", 1),),
            steps=(Step("count", (f"{size} × {size}",)),), marking="Exact.",
            draw=lambda solved: Image.new("RGB", (size, size), "red" if solved else "blue"))

    monkeypatch.setitem(TOPIC_REGISTRY, "test-square", Topic(
        "test-square", "Squares", "tests", lambda rng, difficulty: {"size": rng.randint(2, 9)},
        solve))
    return "test-square"


def test_list_shows_every_topic_with_its_title(capsys):
    code, out, _ = run(capsys, "--list")
    assert code == 0
    lines = out.splitlines()
    assert len(lines) == len(exercises.TOPICS)
    for line, topic in zip(lines, exercises.TOPICS, strict=True):
        assert line.split()[0] == topic and line.endswith(exercises.topic_title(topic))


def test_prints_the_question_and_with_solution_the_worked_solution(capsys):
    exercise = exercises.make("rgb-hsv", seed=3)
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "3")
    assert code == 0
    assert exercise.question in out and "Step 1." not in out
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "3", "--solution")
    assert code == 0
    assert exercise.question in out
    for step in exercise.steps:
        assert step.title in out
    assert exercise.marking in out


def test_difficulty_changes_the_numbers(capsys):
    _, standard, _ = run(capsys, "rgb-hsv", "--seed", "3")
    _, easy, _ = run(capsys, "rgb-hsv", "--seed", "3", "--difficulty", "easy")
    assert exercises.make("rgb-hsv", 3, "easy").question in easy and easy != standard


def test_check_of_a_right_answer_exits_0(capsys):
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "3", "--check", hsv_answer(3))
    assert code == 0
    assert out.startswith("correct") and "Correct." in out


def test_check_of_a_wrong_answer_exits_1_naming_the_first_wrong_value(capsys):
    right = exercises.make("rgb-hsv", seed=3).answer
    answer = f"h={right['h']:.1f}; s={right['s'] + 0.3:.3f}; v={right['v']:.3f}"
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "3", "--check", answer)
    assert code == 1
    assert "the first wrong value is s" in out
    assert "s: wrong" in out and "h: right" in out and "step 6" in out


def test_check_reads_polygons_with_semicolons_between_pieces(capsys):
    from pixelpath.cli.exercise import parse_answers

    assert parse_answers("pieces=(0, 0) (1, 0) (0, 1); (2, 2) (3, 2) (2, 3); count=2;") == {
        "pieces": "(0, 0) (1, 0) (0, 1); (2, 2) (3, 2) (2, 3)", "count": "2"}


@pytest.mark.parametrize(("argv", "message"), [
    (["no-such-topic"], "rgb-hsv"),  # the message lists the topics
    ([], "give a TOPIC"),
    (["rgb-hsv", "--check", "0.5"], "name=value"),
    (["rgb-hsv", "--check", "q=1"], "unknown answer field"),
    (["rgb-hsv", "--count", "3"], "--count needs --export"),
    (["rgb-hsv", "--seed", "-1"], "seed must be >= 0"),
    (["rgb-hsv", "--difficulty", "hard"], "easy, standard, edge"),
    (["rgb-hsv", "--figure", "x.png"], "no figure"),
    (["rgb-hsv", "--export", "out", "--format", "pdf"], "markdown, html, moodle, prairielearn"),
])
def test_usage_errors_exit_2(capsys, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert message in err and out == ""


def test_figure_writes_the_png_and_with_solution_the_solved_one(capsys, tmp_path, square):
    size = exercises.make(square, seed=4).params["size"]
    code, _, _ = run(capsys, square, "--seed", "4", "--figure", str(tmp_path / "q.png"))
    assert code == 0
    code, _, _ = run(capsys, square, "--seed", "4", "--solution",
                     "--figure", str(tmp_path / "a.png"))
    assert code == 0
    with Image.open(tmp_path / "q.png") as question, Image.open(tmp_path / "a.png") as solved:
        assert question.size == solved.size == (size, size)
        assert question.convert("RGB").getpixel((0, 0)) == (0, 0, 255)
        assert solved.convert("RGB").getpixel((0, 0)) == (255, 0, 0)


def test_export_with_count_writes_seeds_from_seed_on(capsys, tmp_path):
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "5", "--export", str(tmp_path),
                       "--format", "moodle", "--count", "3")
    assert code == 0 and str(tmp_path) in out
    quiz = ET.parse(tmp_path / "quiz.xml").getroot()
    names = [q.findtext("idnumber") for q in quiz.findall("question[@type='cloze']")]
    assert names == ["rgb-hsv-5", "rgb-hsv-6", "rgb-hsv-7"]


def test_export_defaults_to_markdown(capsys, tmp_path):
    code, _, _ = run(capsys, "rgb-hsv", "--export", str(tmp_path / "sheet"))
    assert code == 0
    worksheet = (tmp_path / "sheet" / "worksheet.md").read_text()
    assert exercises.make("rgb-hsv", seed=0).question in worksheet


def test_help_shows_examples(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["exercise", "--help"])
    assert exit_info.value.code == 0
    assert "pixelpath exercise rgb-hsv --seed 3 --check" in capsys.readouterr().out


def test_exercise_is_listed_in_the_commands(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    assert "exercise" in capsys.readouterr().out


def test_a_terminal_gets_the_markdown_formatted(capsys, monkeypatch):
    import io

    from rich.console import Console

    import pixelpath.cli.exercise as command

    screen = io.StringIO()
    monkeypatch.setattr(command, "console", lambda: Console(file=screen, force_terminal=True,
                                                            width=100))
    code, out, _ = run(capsys, "rgb-hsv", "--seed", "3", "--solution")
    assert code == 0 and out == ""
    shown = screen.getvalue()
    assert "Step 1. Cmax" in shown and "\x1b[" in shown  # styled text
    assert "**Step" not in shown and "|---|" not in shown  # Markdown formatted, not its source
