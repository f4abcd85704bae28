"""The clipping figures: GIF frame counts, and frames that show what they claim."""

from __future__ import annotations

import numpy as np
import pytest
from gif_frames import gif_frames

from pixelpath.cli import main
from pixelpath.clip import Rect, sutherland_hodgman, weiler_atherton
from pixelpath.figures._canvas import COLOURS
from pixelpath.figures.clipping import DRAWING_BOX, _clip_view, clip_frames, walk_frames

SQUARE = [(1, 1), (9, 1), (9, 7), (1, 7)]
WINDOW = Rect(2, 2, 8, 6)
NOTCHED = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]


def _mask(frame: np.ndarray, colour: str) -> np.ndarray:
    return np.all(frame == np.array(COLOURS[colour], dtype=frame.dtype), axis=-1)


def test_animation_has_one_frame_per_step_and_the_result(tmp_path):
    _, trace = sutherland_hodgman(SQUARE, WINDOW, trace=True)
    steps = sum(len(stage.steps) for stage in trace.stages)
    path = trace.animate(tmp_path / "steps.gif")
    assert steps == 16
    assert len(gif_frames(path)) == steps + 1


def test_each_frame_highlights_exactly_the_points_its_step_emits(tmp_path):
    """The red dots of frame k sit on the pixels of step k's emitted points, and nowhere else."""
    _, trace = sutherland_hodgman(SQUARE, WINDOW, trace=True)
    frames = gif_frames(trace.animate(tmp_path / "steps.gif"))
    view = _clip_view(trace)
    left, width = DRAWING_BOX[0], DRAWING_BOX[2]
    steps = [step for stage in trace.stages for step in stage.steps]
    for frame, step in zip(frames, steps, strict=False):
        red = _mask(frame, "emitted")
        red[:, left + width:] = False  # the text panel may print in other colours only
        if not len(step.emitted):
            assert not red.any(), f"{step.case} emits nothing but the frame shows red"
            continue
        for x, y in np.rint(view.pixel(step.emitted)).astype(int):
            assert red[y - 2:y + 3, x - 2:x + 3].all(), f"no red dot at {step.emitted}"
        ys, xs = np.nonzero(red)
        centres = np.rint(view.pixel(step.emitted))
        distance = np.hypot(xs[:, None] - centres[:, 0], ys[:, None] - centres[:, 1])
        nearest = distance.min(axis=1)  # a dot has radius 6 around a rounded centre
        assert nearest.max() <= 8, "red pixels away from every emitted point"


def test_first_stage_frame_shades_the_inside_of_the_left_boundary():
    _, trace = sutherland_hodgman(SQUARE, WINDOW, trace=True)
    frame = np.asarray(clip_frames(trace)[0])
    view = _clip_view(trace)
    (x_in, y), (x_out, _) = np.rint(view.pixel(np.array([[5.0, 0.5], [1.5, 0.5]]))).astype(int)
    assert _mask(frame, "inside")[y, x_in]
    assert not _mask(frame, "inside")[y, x_out]


def test_walk_animation_frame_count(tmp_path):
    _, trace = weiler_atherton(NOTCHED, Rect(-1, -1, 3, 7), trace=True)
    assert len(gif_frames(trace.animate(tmp_path / "walk.gif"))) == 4 + len(trace.steps) + 1
    assert len(walk_frames(trace)) == 4 + len(trace.steps) + 1


def test_figures_and_rich_display():
    _, trace = sutherland_hodgman(SQUARE, WINDOW, trace=True)
    assert trace._repr_png_().startswith(b"\x89PNG")
    html = trace._repr_html_()
    assert "Clip against the left boundary" in html
    assert "in -&gt; out" in html
    _, walk = weiler_atherton(NOTCHED, Rect(-1, -1, 3, 7), trace=True)
    assert walk._repr_png_().startswith(b"\x89PNG")
    assert "<table" in walk._repr_html_()


def test_cli_animate_writes_the_gif(tmp_path, capsys):
    path = tmp_path / "steps.gif"
    assert main(["clip", "1,1 9,1 9,7 1,7", "--window", "2,2,8,6", "--animate", str(path)]) == 0
    assert len(gif_frames(path)) == 17
    walk = tmp_path / "walk.gif"
    args = ["clip", "0,0 6,0 6,6 0,6 0,4 4,4 4,2 0,2", "--window=-1,-1,3,7",
            "--method", "weiler-atherton", "--animate", str(walk)]
    assert main(args) == 0
    assert walk.stat().st_size > 0


@pytest.mark.parametrize("name", ["steps.png", "missing-dir/steps.gif"])
def test_cli_animate_rejects_bad_paths_clearly(tmp_path, capsys, name):
    args = ["clip", "1,1 9,1 9,7 1,7", "--window", "2,2,8,6", "--animate", str(tmp_path / name)]
    assert main(args) != 0
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert ".gif" in err or "does not exist" in err
