"""The exercise record, make(), marking and from_notes, over every topic."""

from __future__ import annotations

import doctest
import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath import exercises
from pixelpath.exercises import Field
from pixelpath.exercises.exercise import exact, shown

REQUIRED_TOPICS = (
    "sutherland-hodgman", "weiler-atherton", "back-face", "z-buffer", "scan-line", "painter",
    "bsp", "warnock", "octree", "phong-intensity", "gouraud", "ray-sphere", "refraction",
    "rgb-hsv", "hsv-rgb", "rgb-cmy", "rgb-yiq",
)


def test_every_topic_the_issue_names_is_there():
    missing = [topic for topic in REQUIRED_TOPICS if topic not in exercises.TOPICS]
    assert not missing


@pytest.mark.parametrize("topic", exercises.TOPICS)
@pytest.mark.parametrize("difficulty", exercises.DIFFICULTIES)
def test_same_seed_same_exercise_and_its_own_answer_is_right(topic, difficulty):
    first, again = (exercises.make(topic, seed=7, difficulty=difficulty) for _ in range(2))
    assert first.params == again.params
    assert first.question == again.question
    assert first.solution == again.solution
    assert json.loads(json.dumps(first.params)) == first.params
    assert json.loads(json.dumps(first.to_dict()))["answer"] is not None
    result = first.check(first.answer)
    assert result.correct and result.first_wrong is None and result.feedback == "Correct."


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_different_seeds_give_different_numbers(topic):
    params = [json.dumps(exercises.make(topic, seed=seed).params) for seed in range(12)]
    assert len(set(params)) >= 9


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_fields_follow_the_solution_and_the_question_links_its_figure(topic):
    ex = exercises.make(topic, seed=3)
    assert [f.name for f in ex.fields] == list(ex.answer)
    assert all(1 <= f.step <= len(ex.steps) for f in ex.fields)
    assert any(f.required for f in ex.fields)
    picture = ex.figure()
    assert (f"({ex.figure_name})" in ex.question) == (picture is not None)
    if picture is not None:
        assert ex.figure(solution=True) is not None
        assert ex.figure_png().startswith(b"\x89PNG")
        assert "data:image/png;base64," in ex._repr_markdown_()
    for number in range(1, len(ex.steps) + 1):
        assert f"**Step {number}. " in ex.solution


def _wrong(field: Field, value):
    """A value of the field's kind that its marking must reject."""
    if field.kind == "number":
        return 1.0 if value is None else value + 10 * field.tolerance + 1.0
    if field.kind == "vector":
        return [1.0, 2.0, 3.0] if value is None else [v + 1.0 for v in value]
    if field.kind == "polygon":
        return [[0, 0], [1, 0], [0, 1]] if not value else [[x + 1, y] for x, y in value]
    if field.kind == "polygons":
        return [[[0, 0], [1, 0], [0, 1]]]
    if field.kind in ("sequence", "grid"):
        return list(reversed(value)) if len(set(value)) > 1 else [*value, "Z"]
    if field.kind == "set":
        return [*value, "ZZ"]
    return "not-" + str(value)


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_a_wrong_value_is_caught_as_the_first_wrong_field(topic):
    ex = exercises.make(topic, seed=11)
    for field in ex.fields:
        answer = dict(ex.answer)
        answer[field.name] = _wrong(field, ex.answer[field.name])
        result = ex.check(answer)
        assert not result.correct
        assert result.first_wrong == field.name
        assert f"step {field.step}" in result.feedback
        assert result.marks[field.name] is False


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_required_fields_alone_pass_and_missing_ones_fail(topic):
    ex = exercises.make(topic, seed=5)
    required = {f.name: ex.answer[f.name] for f in ex.fields if f.required}
    assert ex.check(required).correct
    first = next(f for f in sorted(ex.fields, key=lambda f: f.step) if f.required)
    result = ex.check({k: v for k, v in required.items() if k != first.name})
    assert result.first_wrong == first.name and "missing" in result.feedback


def test_answers_typed_as_text_are_read_and_rounded_answers_pass():
    ex = exercises.make("phong-intensity", seed=0)
    typed = {name: f"{value:.2f}" for name, value in ex.answer.items()}
    assert ex.check(typed).correct
    clipping = exercises.make("sutherland-hodgman", seed=0)
    polygon = clipping.answer["polygon"]
    text = " ".join(f"({x:.2f}, {y:.2f})" for x, y in reversed(polygon[1:] + polygon[:1]))
    assert clipping.check({"polygon": text}).correct


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_answers_typed_as_json_text_pass(topic):
    """A script or an autograder may type lists as JSON: ["C", "D"], [[3.0, 10.0], ...]."""
    ex = exercises.make(topic, seed=0)
    typed = {name: json.dumps(value) if isinstance(value, list | tuple) else value
             for name, value in ex.answer.items()}
    assert ex.check(typed).correct

def test_a_miss_is_answered_none():
    ex = next(e for e in (exercises.make("ray-sphere", s, "edge") for s in range(200))
              if e.answer["t"] is None)
    for miss in (None, "none", "miss", float("inf")):
        assert ex.check({"t": miss}).correct
    assert not ex.check({"t": 1.0}).correct


def test_bad_requests_raise_clear_errors():
    with pytest.raises(ValueError, match="rgb-hsv"):
        exercises.make("rgb-hsb")
    with pytest.raises(ValueError, match="standard"):
        exercises.make("rgb-hsv", difficulty="hard")
    with pytest.raises(ValueError, match=">= 0"):
        exercises.make("rgb-hsv", seed=-1)
    with pytest.raises(TypeError, match="int"):
        exercises.make("rgb-hsv", seed=1.5)
    ex = exercises.make("rgb-hsv")
    with pytest.raises(ValueError, match=r"'hue'.*h, s, v"):
        ex.check({"hue": 3})
    with pytest.raises(ValueError, match="cannot read h"):
        ex.check({"h": "sixty"})
    with pytest.raises(TypeError, match="dict"):
        ex.check([1, 2, 3])


def test_notes_examples_carry_the_errata_and_the_right_values():
    notes = {ex.topic: ex for ex in exercises.from_notes()}
    phong = notes["phong-intensity"]
    assert phong.seed is None and phong.name == "notes-phong-intensity"
    # Recomputed here: 0.2·0.2 + 0.6·1·0.707 + 0.5·1·0.866^20.
    assert phong.answer["I"] == pytest.approx(0.04 + 0.4242 + 0.5 * 0.866**20)
    assert phong.answer["I"] == pytest.approx(0.4923, abs=5e-5)
    marked = phong.check({"I": 0.47005})
    assert marked.first_wrong == "I" and "notes print" in marked.feedback
    assert "The notes print I = 0.47005" in phong.solution
    specular = notes["specular"]
    assert specular.answer["Is"] == pytest.approx(0.8 * 100 * 0.866025**20, rel=1e-5)
    assert not specular.check({"Is": 1.2}).correct
    assert notes["diffuse"].answer["Id"] == pytest.approx(42.0)
    assert notes["gouraud"].answer["I_left"] == pytest.approx(0.55)
    square = [[2, 6], [8, 6], [8, 2], [2, 2]]  # the notes' own list, the other way round
    assert notes["sutherland-hodgman"].check({"polygon": square}).correct
    assert notes["rgb-yiq"].check({"y": 0.886, "i": 0.322, "q": -0.312}).correct
    assert all(ex.check(ex.answer).correct for ex in notes.values())


def test_shown_and_exact_write_what_an_answer_key_needs():
    assert shown(0.49234) == "0.4923" and exact(0.49234) == "0.49234"
    assert shown(-0.0) == "0" and shown(float("inf")) == "∞"
    assert shown([[1, 2], [3.5, 4]]) == "(1, 2) (3.5, 4)"
    assert shown(["A", "B"]) == "A, B"


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(-9, 9), st.integers(-9, 9)), min_size=3, max_size=6,
                unique=True), st.integers(0, 5), st.booleans())
def test_polygons_match_from_any_start_either_way_round(points, shift, backwards):
    field = Field("p", "a polygon", 1, kind="polygon")
    expected = [list(p) for p in points]
    turned = expected[shift % len(expected):] + expected[:shift % len(expected)]
    given_points = turned[::-1] if backwards else turned
    assert field.matches(field.parse(given_points), expected)
    moved = [[x + 0.5, y] for x, y in given_points]
    assert not field.matches(field.parse(moved), expected)


def test_the_practice_page_s_example_prints_what_it_shows():
    page = Path(__file__).parents[2] / "docs" / "guide" / "practice.md"
    example = page.read_text(encoding="utf-8").split("```python\n", 1)[1].split("```", 1)[0]
    test = doctest.DocTestParser().get_doctest(example, {}, "docs/guide/practice.md", None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted >= 5 and result.failed == 0
