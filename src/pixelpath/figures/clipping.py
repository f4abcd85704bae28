"""Step-by-step pictures of the clipping algorithms, drawn from their traces.

* Sutherland-Hodgman (:class:`~pixelpath.clip.ClipTrace`): one frame per (S, E) step, with
  the current boundary and its inside shaded, the stage's input, the edge S -> E, the points
  earlier steps emitted (green) and, in red, the points this step emits; the stage's table
  beside it up to the current row. A last frame shows the clipped polygon.
* Weiler-Atherton (:class:`~pixelpath.clip.WeilerAthertonTrace`): the two polygons, their
  contact points, the subject's boundary inside the window, the window's boundary inside the
  subject, then one frame per piece of boundary the walk follows (switches marked), and the
  pieces.

Examples
--------
>>> from pixelpath.clip import Rect, sutherland_hodgman
>>> from pixelpath.figures.clipping import clip_frames
>>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6), trace=True)
>>> frames = clip_frames(trace)
>>> len(frames), frames[0].size
(17, (760, 420))
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PIL import Image

from pixelpath.clip import _kernels
from pixelpath.clip.sutherland_hodgman import ClipTrace, _describe, _point, _points
from pixelpath.clip.weiler_atherton_trace import WeilerAthertonTrace
from pixelpath.figures._canvas import (
    LINE_HEIGHT,
    Sketch,
    View,
    font,
    paste_row,
    save_animation,
)

__all__ = [
    "FRAME_SIZE",
    "animate_clip",
    "animate_walk",
    "clip_figure",
    "clip_frames",
    "walk_figure",
    "walk_frames",
]

FRAME_SIZE = (760, 420)
# Where the drawing goes in a frame (left, top, width, height); the text panel is to its right.
DRAWING_BOX = (10, 56, 360, 354)
PANEL_X = 392
STEP_MS, LAST_MS = 900, 2500

RULES = {
    "in -> in": "E is inside: emit E",
    "out -> in": "entering: emit the intersection, then E",
    "in -> out": "leaving: emit the intersection",
    "out -> out": "both outside: emit nothing",
}


def clip_frames(trace: ClipTrace) -> list[Image.Image]:
    """Return one frame per (S, E) step of a Sutherland-Hodgman trace, then the result.

    Parameters
    ----------
    trace : ClipTrace
        From ``sutherland_hodgman(subject, window, trace=True)``.

    Returns
    -------
    list of PIL.Image.Image
        ``sum(len(stage.steps) for stage in trace.stages) + 1`` RGB frames of
        :data:`FRAME_SIZE`.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> from pixelpath.figures.clipping import clip_frames
    >>> _, trace = sutherland_hodgman([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> len(clip_frames(trace)) == sum(len(s.steps) for s in trace.stages) + 1
    True
    """
    view = _clip_view(trace)
    frames = []
    for number, (stage, row) in enumerate(zip(trace.stages, trace.window.table, strict=True)):
        for index in range(len(stage.steps)):
            frames.append(_step_frame(trace, view, number, row, index))
    frames.append(_result_frame(trace, view))
    return frames


def animate_clip(trace: ClipTrace, path: str | os.PathLike) -> Path:
    """Write :func:`clip_frames` as a looping GIF, atomically; return the path.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> from pixelpath.figures.clipping import animate_clip
    >>> _, trace = sutherland_hodgman([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> animate_clip(trace, "steps.gif").name
    'steps.gif'
    """
    frames = clip_frames(trace)
    return save_animation(frames, [STEP_MS] * (len(frames) - 1) + [LAST_MS], path)


def clip_figure(trace: ClipTrace, panel: int = 200) -> Image.Image:
    """Return the subject and window, then each stage's output, side by side.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> from pixelpath.figures.clipping import clip_figure
    >>> _, trace = sutherland_hodgman([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> clip_figure(trace).height
    238
    """
    points = _clip_points(trace)
    view = View(points, (0, 0, panel, panel))
    subject, window = trace.stages[0].input, trace.window.vertices
    first = Sketch(panel, panel)
    first.fill(view, subject, "subject fill")
    first.outline(view, subject, "subject")
    first.outline(view, window, "window", width=1, dashed=True)
    pictures, captions = [first.image], ["subject and window"]
    for stage, row in zip(trace.stages, trace.window.table, strict=True):
        sketch = Sketch(panel, panel)
        sketch.fill(view, _inside(view, row), "inside")
        sketch.fill(view, subject, "faint")
        sketch.fill(view, stage.output, "output fill")
        sketch.outline(view, window, "window", width=1, dashed=True)
        _boundary_line(sketch, view, row)
        sketch.outline(view, stage.output, "output")
        sketch.dots(view, stage.output, "output", radius=3)
        pictures.append(sketch.image)
        captions.append(f"after the {stage.boundary} boundary")
    return paste_row(pictures, captions)


def _step_frame(trace: ClipTrace, view: View, number: int, row: np.ndarray,
                index: int) -> Image.Image:
    stage = trace.stages[number]
    step = stage.steps[index]
    sketch = Sketch(*FRAME_SIZE)
    sketch.fill(view, _inside(view, row), "inside")
    sketch.fill(view, trace.stages[0].input, "faint")
    sketch.fill(view, stage.input, "subject fill")
    sketch.outline(view, trace.window.vertices, "window", width=1, dashed=True)
    _boundary_line(sketch, view, row)
    sketch.outline(view, stage.input, "subject", width=1)
    earlier = [p for s in stage.steps[:index] for p in s.emitted]
    if earlier:
        sketch.draw.line(view.xy(np.array(earlier)), fill=(0, 140, 80), width=2)
        sketch.dots(view, np.array(earlier), "output", radius=4)
    sketch.segment(view, step.s, step.e, "edge", width=4)
    sketch.rings(view, np.array([step.s, step.e]), "edge")
    sketch.label(view, step.s, "S", "edge")
    sketch.label(view, step.e, "E", "edge")
    if len(step.emitted):
        sketch.dots(view, step.emitted, "emitted", radius=6)
    steps_total = sum(len(s.steps) for s in trace.stages)
    done = sum(len(s.steps) for s in trace.stages[:number]) + index + 1
    sketch.text(10, 8, f"Stage {number + 1} of {len(trace.stages)}: clip against the "
                f"{stage.boundary} boundary ({_describe(row)})")
    sketch.text(10, 8 + LINE_HEIGHT,
                f"Step {done} of {steps_total}: S = {_point(step.s)}, E = {_point(step.e)}, "
                f"{step.case}: {RULES[step.case]}", colour="edge")
    y = _wrapped(sketch, PANEL_X, DRAWING_BOX[1], "input:", stage.input)
    rows = [("S", "E", "case", "output")]
    rows += [
        (_point(s.s), _point(s.e), s.case, _points(s.emitted) if len(s.emitted) else "nothing")
        for s in stage.steps[: index + 1]
    ]
    sketch.columns(PANEL_X, y + 6, rows, highlight=index + 1)
    return sketch.image


def _result_frame(trace: ClipTrace, view: View) -> Image.Image:
    sketch = Sketch(*FRAME_SIZE)
    sketch.fill(view, trace.stages[0].input, "faint")
    sketch.fill(view, trace.result, "output fill")
    sketch.outline(view, trace.window.vertices, "window", width=1, dashed=True)
    sketch.outline(view, trace.result, "output")
    sketch.dots(view, trace.result, "output", radius=4)
    sketch.text(10, 8, "The clipped polygon")
    y = _wrapped(sketch, PANEL_X, DRAWING_BOX[1], "result:", trace.result)
    rows = [("boundary", "in", "out")]
    rows += [(s.boundary, str(len(s.input)), str(len(s.output))) for s in trace.stages]
    sketch.columns(PANEL_X, y + 6, rows)
    return sketch.image


def walk_frames(trace: WeilerAthertonTrace) -> list[Image.Image]:
    """Return the frames of Weiler-Atherton's walk: 4 set-up frames, one per step, the result.

    The set-up frames show the two polygons, the points where their boundaries meet, the
    subject's boundary inside the window and the window's boundary inside the subject.

    Returns
    -------
    list of PIL.Image.Image
        ``4 + len(trace.steps) + 1`` RGB frames of :data:`FRAME_SIZE`.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> from pixelpath.figures.clipping import walk_frames
    >>> _, trace = weiler_atherton([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> len(walk_frames(trace)) == 4 + len(trace.steps) + 1
    True
    """
    view = View(np.vstack([trace.subject, trace.window]), DRAWING_BOX)
    frames = [
        _walk_setup(trace, view, "The subject (blue) and the window (black), both "
                    "counter-clockwise"),
        _walk_setup(trace, view, f"{len(trace.contacts)} points where the two boundaries meet",
                    contacts=True),
        _walk_setup(trace, view, "The subject's boundary inside the window is kept",
                    contacts=True, kept=("subject", "both")),
        _walk_setup(trace, view, "The window's boundary inside the subject is kept",
                    contacts=True, kept=("subject", "window", "both")),
    ]
    frames += [_walk_step(trace, view, index) for index in range(len(trace.steps))]
    frames.append(_walk_result(trace, view))
    return frames


def animate_walk(trace: WeilerAthertonTrace, path: str | os.PathLike) -> Path:
    """Write :func:`walk_frames` as a looping GIF, atomically; return the path.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> from pixelpath.figures.clipping import animate_walk
    >>> _, trace = weiler_atherton([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> animate_walk(trace, "walk.gif").name
    'walk.gif'
    """
    frames = walk_frames(trace)
    durations = [1500] * 4 + [STEP_MS] * len(trace.steps) + [LAST_MS]
    return save_animation(frames, durations, path)


def walk_figure(trace: WeilerAthertonTrace, panel: int = 240) -> Image.Image:
    """Return the two polygons beside the pieces of their intersection.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> from pixelpath.figures.clipping import walk_figure
    >>> _, trace = weiler_atherton([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
    >>> walk_figure(trace).height
    278
    """
    view = View(np.vstack([trace.subject, trace.window]), (0, 0, panel, panel))
    before = Sketch(panel, panel)
    before.fill(view, trace.subject, "subject fill")
    before.outline(view, trace.subject, "subject")
    before.outline(view, trace.window, "window", width=1, dashed=True)
    before.dots(view, trace.contacts, "contact", radius=3)
    after = Sketch(panel, panel)
    after.fill(view, trace.subject, "faint")
    for piece in trace.result:
        after.fill(view, piece, "output fill")
        after.outline(view, piece, "output")
    after.outline(view, trace.window, "window", width=1, dashed=True)
    count = len(trace.result)
    return paste_row([before.image, after.image],
                     ["subject, window, contacts", f"{count} piece{'s' * (count != 1)}"])


def _walk_base(trace: WeilerAthertonTrace, view: View, title: str) -> Sketch:
    sketch = Sketch(*FRAME_SIZE)
    sketch.fill(view, trace.subject, "subject fill")
    sketch.outline(view, trace.subject, "subject", width=1)
    sketch.outline(view, trace.window, "window", width=1, dashed=True)
    sketch.text(10, 8, title)
    return sketch


def _walk_setup(trace: WeilerAthertonTrace, view: View, title: str, contacts: bool = False,
                kept: tuple[str, ...] = ()) -> Image.Image:
    sketch = _walk_base(trace, view, title)
    colours = {"subject": "subject", "window": "window", "both": "edge"}
    for step in trace.steps:
        if step.along in kept:
            sketch.segment(view, step.start, step.end, colours[step.along], width=4)
    if contacts:
        sketch.dots(view, trace.contacts, "contact", radius=5)
    rows = [("contact",)] + [(_point(p),) for p in trace.contacts]
    sketch.columns(PANEL_X, DRAWING_BOX[1], rows if contacts else [("",)])
    return sketch.image


def _walk_step(trace: WeilerAthertonTrace, view: View, index: int) -> Image.Image:
    step = trace.steps[index]
    walked = [s for s in trace.steps[:index] if s.loop == step.loop]
    length = sum(s.loop == step.loop for s in trace.steps)
    sketch = _walk_base(trace, view, f"Piece {step.loop + 1}, step {len(walked) + 1} of "
                        f"{length}: along the {_boundary(step.along)}")
    for piece in trace.result[: step.loop]:
        sketch.fill(view, piece, "output fill")
    sketch.dots(view, trace.contacts, "contact", radius=4)
    for earlier in walked:
        sketch.segment(view, earlier.start, earlier.end, "output", width=3)
    sketch.segment(view, step.start, step.end, "emitted", width=5)
    sketch.dots(view, np.array([step.end]), "emitted", radius=5)
    if step.switch:
        sketch.rings(view, np.array([step.start]), "edge", radius=9)
    note = f"switch to the {_boundary(step.along)} at {_point(step.start)}" if step.switch else ""
    sketch.text(10, 8 + LINE_HEIGHT, note, colour="edge")
    rows = [("from", "to", "along")]
    rows += [(_point(s.start), _point(s.end), s.along) for s in [*walked, step]]
    sketch.columns(PANEL_X, DRAWING_BOX[1], rows, highlight=len(rows) - 1)
    return sketch.image


def _walk_result(trace: WeilerAthertonTrace, view: View) -> Image.Image:
    count = len(trace.result)
    title = (f"The intersection: {count} piece{'s' * (count != 1)}" if count
             else "Nothing is left: the polygons do not overlap")
    sketch = _walk_base(trace, view, title)
    rows = [("piece", "vertices")]
    for number, piece in enumerate(trace.result, start=1):
        sketch.fill(view, piece, "output fill")
        sketch.outline(view, piece, "output")
        rows.append((str(number), " ".join(_point(p) for p in piece)))
    sketch.columns(PANEL_X, DRAWING_BOX[1], rows)
    return sketch.image


def _boundary(along: str) -> str:
    return {"subject": "subject", "window": "window", "both": "shared boundary"}[along]


def _clip_points(trace: ClipTrace) -> np.ndarray:
    return np.vstack([trace.stages[0].input, trace.window.vertices])


def _clip_view(trace: ClipTrace) -> View:
    return View(_clip_points(trace), DRAWING_BOX)


def _inside(view: View, row: np.ndarray) -> np.ndarray:
    """Return the part of the view inside one window boundary (clipped by the stage kernel)."""
    corners = np.ascontiguousarray(view.world_corners, dtype=np.float64)
    inside, _, _ = _kernels.trace_stage(corners, np.ascontiguousarray(row, dtype=np.float64))
    return inside


def _boundary_line(sketch: Sketch, view: View, row: np.ndarray) -> None:
    """Draw a window boundary's whole line across the view."""
    point, direction = _line(row)
    reach = 4.0 * float(np.ptp(view.world_corners, axis=0).max())
    sketch.segment(view, point - reach * direction, point + reach * direction, "boundary", width=3)


def _line(row: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return a point on a boundary and the boundary's unit direction."""
    kind = int(row[0])
    if kind == _kernels.EDGE:
        start, end = row[1:3], row[3:5]
        return start, (end - start) / np.linalg.norm(end - start)
    if kind in (_kernels.LEFT, _kernels.RIGHT):
        return np.array([row[1], 0.0]), np.array([0.0, 1.0])
    return np.array([0.0, row[1]]), np.array([1.0, 0.0])


def _wrapped(sketch: Sketch, x: float, y: float, label: str, points: np.ndarray,
             width: float = 350) -> float:
    """Write a label and points, wrapped between points to ``width`` pixels; return the y below."""
    line = label
    for word in [_point(p) for p in points] or ["(empty)"]:
        candidate = f"{line} {word}"
        if sketch.draw.textlength(candidate, font=font()) > width:
            sketch.text(x, y, line)
            y += LINE_HEIGHT
            line = "    " + word
        else:
            line = candidate
    sketch.text(x, y, line)
    return y + LINE_HEIGHT
