"""Sutherland-Hodgman polygon clipping, exactly as the notes run it, with a trace to show it.

Conventions (graphics notes, Sutherland-Hodgman chapter):

* The window's boundaries are visited in order, Left, Right, Bottom, Top for a :class:`Rect`
  (section 3), the edges in order for a convex polygon window; each stage's output is the next
  stage's input.
* In each stage S starts as the **last** vertex and E runs over the vertices in order; the four
  cases of section 5 decide what is emitted: in→in emits E, out→in emits the intersection then
  E, in→out emits the intersection, out→out emits nothing.
* Intersections use the formulas of section 6 (``y = y1 + (y2 - y1)(xmin - x1)/(x2 - x1)`` and
  friends) with S as ``(x1, y1)``; slanted window edges use the parametric form
  ``P = S + t (E - S)``.
* The output keeps the subject's orientation and drops consecutive duplicate vertices; fewer
  than three vertices left means nothing is left, an empty ``(0, 2)`` array.

Erratum (SPEC section 9): the notes' worked example, traced as the algorithm runs, ends with
``(2,6) → (2,2) → (8,2) → (8,6)``: the notes' square, in the input's orientation.

Known limitation: a concave subject can come back as one polygon whose pieces are joined by
*zero-width bridges* running along the window boundary and back. :func:`sutherland_hodgman`
warns with :class:`ZeroWidthBridgeWarning`, :func:`zero_width_bridges` lists them, and
:func:`pixelpath.clip.weiler_atherton` returns the separate pieces instead.
"""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, overload

import numpy as np

from pixelpath.clip import _kernels, _validate
from pixelpath.clip.window import ConvexWindow, Rect, as_window, boundary_names

__all__ = [
    "ClipStage",
    "ClipStep",
    "ClipTrace",
    "ZeroWidthBridgeWarning",
    "sutherland_hodgman",
    "zero_width_bridges",
]


class ZeroWidthBridgeWarning(UserWarning):
    """The clipped polygon runs along the window boundary and back (a concave subject).

    Examples
    --------
    >>> import warnings
    >>> from pixelpath.clip import Rect, ZeroWidthBridgeWarning, sutherland_hodgman
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     _ = sutherland_hodgman(notched, Rect(-1, -1, 3, 7))
    >>> caught[0].category is ZeroWidthBridgeWarning
    True
    """


@dataclass(frozen=True)
class ClipStep:
    """One (S, E) pair of a stage: where each end lies and what the notes' rule emitted.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
    ...                               trace=True)
    >>> step = trace.stages[0].steps[1]  # S = (1, 1) outside, E = (9, 1) inside the left edge
    >>> step.case, step.emitted.tolist()
    ('out -> in', [[2.0, 1.0], [9.0, 1.0]])
    """

    s: np.ndarray
    e: np.ndarray
    s_inside: bool
    e_inside: bool
    emitted: np.ndarray

    @property
    def case(self) -> str:
        """The notes' case, such as ``"out -> in"``."""
        return f"{_side(self.s_inside)} -> {_side(self.e_inside)}"


@dataclass(frozen=True)
class ClipStage:
    """The work of one boundary: its input list, its (S, E) steps and its output list.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
    ...                               trace=True)
    >>> stage = trace.stages[1]
    >>> stage.boundary, stage.output.tolist()
    ('right', [[2.0, 1.0], [8.0, 1.0], [8.0, 7.0], [2.0, 7.0]])
    """

    boundary: str
    input: np.ndarray
    output: np.ndarray
    steps: tuple[ClipStep, ...]


@dataclass(frozen=True)
class ClipTrace:
    """Every stage of a Sutherland-Hodgman run; ``str(trace)`` is the table a student writes.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
    ...                               trace=True)
    >>> [stage.boundary for stage in trace.stages]
    ['left', 'right', 'bottom', 'top']
    >>> trace.stages[0].output.tolist()
    [[2.0, 1.0], [9.0, 1.0], [9.0, 7.0], [2.0, 7.0]]
    """

    window: Rect | ConvexWindow
    stages: tuple[ClipStage, ...]
    result: np.ndarray

    def __str__(self) -> str:
        lines = [f"Sutherland-Hodgman against {_describe_window(self.window)}"]
        for stage, row in zip(self.stages, self.window.table, strict=True):
            lines += ["", f"Clip against the {stage.boundary} boundary ({_describe(row)})"]
            lines.append(f"  input:  {_points(stage.input)}")
            width = 2 + max([len(_point(p)) for p in stage.input], default=0)
            lines.append(f"  {'S':<{width}}{'E':<{width}}{'case':<12}output")
            for step in stage.steps:
                emitted = _points(step.emitted) if len(step.emitted) else "nothing"
                s, e = _point(step.s), _point(step.e)
                lines.append(f"  {s:<{width}}{e:<{width}}{step.case:<12}{emitted}")
            lines.append(f"  output: {_points(stage.output)}")
        lines.append("")
        if len(self.result):
            lines.append(f"Clipped polygon: {' -> '.join(_point(p) for p in self.result)}")
        else:
            lines.append("Clipped polygon: nothing is left (fewer than 3 vertices)")
        return "\n".join(lines)

    def frames(self) -> list:
        """One picture per (S, E) step, then the result (see :mod:`pixelpath.figures`).

        Each step's frame shows the current boundary with its inside shaded, the stage's
        input, the S -> E edge, what earlier steps emitted and, highlighted in red, what this
        step emits, beside the stage's table up to this row.

        Returns
        -------
        list of PIL.Image.Image

        Examples
        --------
        >>> from pixelpath.clip import Rect, sutherland_hodgman
        >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
        ...                               trace=True)
        >>> len(trace.frames())  # 4 stages of 4 steps each, then the clipped polygon
        17
        """
        from pixelpath.figures.clipping import clip_frames

        return clip_frames(self)

    def animate(self, path: str | os.PathLike) -> Path:
        """Write :meth:`frames` as an animated GIF (atomically); return the path.

        Examples
        --------
        >>> from pixelpath.clip import Rect, sutherland_hodgman
        >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
        ...                               trace=True)
        >>> trace.animate("steps.gif").name
        'steps.gif'
        """
        from pixelpath.figures.clipping import animate_clip

        return animate_clip(self, path)

    def figure(self):
        """Return the subject and window, then each stage's output, side by side (a PIL image).

        Examples
        --------
        >>> from pixelpath.clip import Rect, sutherland_hodgman
        >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
        ...                               trace=True)
        >>> trace.figure().height  # 200-pixel panels under their captions
        238
        """
        from pixelpath.figures.clipping import clip_figure

        return clip_figure(self)

    def _repr_png_(self) -> bytes:
        from pixelpath.figures._canvas import png_bytes

        return png_bytes(self.figure())

    def _repr_html_(self) -> str:
        from pixelpath.figures.html import table

        parts = []
        for stage, row in zip(self.stages, self.window.table, strict=True):
            rows = [
                (_point(step.s), _point(step.e), step.case,
                 _points(step.emitted) if len(step.emitted) else "nothing")
                for step in stage.steps
            ]
            caption = (
                f"Clip against the {stage.boundary} boundary ({_describe(row)}); "
                f"input {_points(stage.input)}; output {_points(stage.output)}"
            )
            parts.append(table(caption, ("S", "E", "case", "output"), rows))
        result = " → ".join(_point(p) for p in self.result) or "nothing is left"
        return "".join(parts) + f"<p>Clipped polygon: {result}</p>"


@overload
def sutherland_hodgman(
    subject: np.ndarray, window: object, trace: Literal[False] = False
) -> np.ndarray: ...
@overload
def sutherland_hodgman(
    subject: np.ndarray, window: object, trace: Literal[True]
) -> tuple[np.ndarray, ClipTrace]: ...
def sutherland_hodgman(
    subject: np.ndarray, window: object, trace: bool = False
) -> np.ndarray | tuple[np.ndarray, ClipTrace]:
    """Clip a polygon against a convex window with the Sutherland-Hodgman algorithm.

    Parameters
    ----------
    subject : (N, 2) array_like
        The polygon's vertices in order, either orientation, at least 3 distinct.
    window : Rect or (K, 2) array_like
        A :class:`Rect`, or a convex polygon in either orientation.
    trace : bool, optional
        Also return a :class:`ClipTrace` of every stage.

    Returns
    -------
    (M, 2) ndarray
        The clipped polygon in the subject's orientation; ``(0, 2)`` when nothing is left.
    ClipTrace
        Only with ``trace=True``.

    Raises
    ------
    ValueError
        For a malformed or non-finite subject, a degenerate or non-convex window, or a
        coordinate beyond ±1e150 (the floating-point arithmetic could overflow; the message
        names the vertex; :func:`~pixelpath.clip.weiler_atherton` takes any finite ones).
    TypeError
        For non-numeric input.

    Warns
    -----
    ZeroWidthBridgeWarning
        When the result joins separate pieces along the window boundary (concave subject).

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6)).tolist()
    [[2.0, 6.0], [2.0, 2.0], [8.0, 2.0], [8.0, 6.0]]
    """
    if trace:
        return _traced(subject, window)
    # Fast path: an already valid float64 array and a Rect go straight to one kernel call.
    if not (
        type(subject) is np.ndarray
        and subject.dtype == np.float64
        and subject.ndim == 2
        and subject.shape[1] == 2
        and subject.flags.c_contiguous
    ):
        subject = _validate.polygon_array(subject, "subject")
    table = window.table if type(window) is Rect else as_window(window).table
    result, status, bridge_count = _kernels.sutherland_hodgman(subject, table)
    if status:
        raise _validate.subject_error(status, "subject", subject)
    if bridge_count:
        warnings.warn(
            f"sutherland_hodgman: the result runs along the window boundary and back "
            f"({bridge_count} zero-width bridge(s) joining pieces of a concave subject); "
            "use weiler_atherton(subject, window) to get the separate pieces",
            ZeroWidthBridgeWarning,
            stacklevel=2,
        )
    return result


def zero_width_bridges(polygon: np.ndarray, window: object) -> np.ndarray:
    """Return the zero-width bridges of a clipped polygon along the window's boundaries.

    A bridge is a stretch of a boundary that the polygon runs along twice in opposite
    directions: how Sutherland-Hodgman joins the separate pieces of a concave subject.

    Parameters
    ----------
    polygon : (M, 2) array_like
        A polygon, typically a result of :func:`sutherland_hodgman`.
    window : Rect or (K, 2) array_like
        The window it was clipped against.

    Returns
    -------
    (B, 2, 2) ndarray
        Each bridge as its two end points; empty when there is none.

    Raises
    ------
    ValueError
        For a malformed polygon or window, or a coordinate beyond ±1e150.

    Examples
    --------
    >>> import warnings
    >>> from pixelpath.clip import Rect, sutherland_hodgman, zero_width_bridges
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> window = Rect(-1, -1, 3, 7)  # cuts the notched square into two pieces
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     clipped = sutherland_hodgman(notched, window)
    >>> zero_width_bridges(clipped, window).tolist()
    [[[3.0, 2.0], [3.0, 4.0]]]
    """
    points = _validate.bounded(_validate.polygon_array(polygon, "polygon"), "polygon")
    return _kernels.bridges(points, as_window(window).table)


def _traced(subject: object, window: object) -> tuple[np.ndarray, ClipTrace]:
    points = _validate.polygon_array(subject, "subject")
    status = _kernels.check_subject(points)
    if status:
        raise _validate.subject_error(status, "subject", points)
    window = as_window(window)
    stages = []
    for name, row in zip(boundary_names(window), window.table, strict=True):
        output, flags, crossings = _kernels.trace_stage(points, row)
        stages.append(ClipStage(name, points, output, _steps(points, flags, crossings)))
        points = output
    result = points if len(points) >= 3 else np.empty((0, 2))
    return result.copy(), ClipTrace(window=window, stages=tuple(stages), result=result)


def _steps(points: np.ndarray, flags: np.ndarray, crossings: np.ndarray) -> tuple[ClipStep, ...]:
    steps = []
    for i in range(len(points)):
        emitted = [crossings[i]] if flags[i - 1] != flags[i] else []
        if flags[i]:
            emitted.append(points[i])
        steps.append(
            ClipStep(
                s=points[i - 1],
                e=points[i],
                s_inside=bool(flags[i - 1]),
                e_inside=bool(flags[i]),
                emitted=np.array(emitted, dtype=np.float64).reshape(-1, 2),
            )
        )
    return tuple(steps)


def _side(is_inside: bool) -> str:
    return "in" if is_inside else "out"


def _point(p: np.ndarray) -> str:
    return f"({p[0]:g}, {p[1]:g})"


def _points(points: np.ndarray) -> str:
    return " ".join(_point(p) for p in points) if len(points) else "(empty)"


def _describe(row: np.ndarray) -> str:
    kind = int(row[0])
    if kind == _kernels.EDGE:
        return f"{_point(row[1:3])} to {_point(row[3:5])}, inside on its left"
    axis = "x" if kind in (_kernels.LEFT, _kernels.RIGHT) else "y"
    relation = ">=" if kind in (_kernels.LEFT, _kernels.BOTTOM) else "<="
    return f"inside: {axis} {relation} {row[1]:g}"


def _describe_window(window: Rect | ConvexWindow) -> str:
    if isinstance(window, Rect):
        return (
            f"the window xmin = {window.xmin:g}, xmax = {window.xmax:g}, "
            f"ymin = {window.ymin:g}, ymax = {window.ymax:g}"
        )
    return f"the convex window {_points(window.vertices)}"
