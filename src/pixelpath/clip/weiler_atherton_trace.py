"""What Weiler-Atherton's walk did: ``weiler_atherton(subject, window, trace=True)``.

The trace is built only when asked for, from what the clipper computed anyway (the oriented
rings, the contact points, the kept boundary pieces and the loops the walk linked), so the
plain call is not slowed down. Each :class:`WalkStep` is one boundary piece the walk
followed, on the subject's boundary, the window's, or on both where they coincide; a
*switch* is where the walk changes from one polygon's boundary to the other's, the
vertex-list switch of the classic algorithm.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import numpy as np

__all__ = ["WalkStep", "WeilerAthertonTrace"]

ExactPoint = tuple[Fraction, Fraction]


@dataclass(frozen=True)
class WalkStep:
    """One boundary piece the walk followed.

    Attributes
    ----------
    loop : int
        Which closed loop (output piece, counted from 0 in walking order) it belongs to.
    start, end : (2,) ndarray
        Its end points, in walking order (counter-clockwise around the piece).
    along : {"subject", "window", "both"}
        The boundary it lies on: the subject's inside the window, the window's inside the
        subject, or a stretch both boundaries share.
    switch : bool
        Whether the walk changed boundary at ``start``.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> _, trace = weiler_atherton(notched, Rect(-1, -1, 3, 7), trace=True)
    >>> step = trace.steps[3]
    >>> step.start.tolist(), step.end.tolist(), step.along, step.switch
    ([3.0, 0.0], [3.0, 2.0], 'window', True)
    """

    loop: int
    start: np.ndarray
    end: np.ndarray
    along: str
    switch: bool


@dataclass(frozen=True)
class WeilerAthertonTrace:
    """Every piece of boundary Weiler-Atherton's walk followed, loop by loop.

    Attributes
    ----------
    subject, window : (N, 2) ndarray
        The two polygons as the walk used them: counter-clockwise, repeated vertices dropped.
    contacts : (C, 2) ndarray
        Every point where the two boundaries meet (crossings, touchings, ends of shared
        stretches), sorted by x then y.
    steps : tuple of WalkStep
        The walk, loop after loop.
    result : tuple of (M, 2) ndarray
        The pieces :func:`~pixelpath.clip.weiler_atherton` returned.

    Examples
    --------
    >>> from pixelpath.clip import Rect, weiler_atherton
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> pieces, trace = weiler_atherton(notched, Rect(-1, -1, 3, 7), trace=True)
    >>> len(trace.contacts), len(trace.steps), trace.loops
    (4, 8, 2)
    >>> print(str(trace).splitlines()[0])
    Weiler-Atherton walk: subject of 8 vertices, window of 4 vertices (both counter-clockwise)
    """

    subject: np.ndarray
    window: np.ndarray
    contacts: np.ndarray
    steps: tuple[WalkStep, ...]
    result: tuple[np.ndarray, ...]

    @classmethod
    def from_walk(
        cls,
        subject: Sequence[ExactPoint],
        window: Sequence[ExactPoint],
        contacts: Iterable[ExactPoint],
        loops: Sequence[Sequence[ExactPoint]],
        along: Mapping[tuple[ExactPoint, ExactPoint], str],
        result: Sequence[np.ndarray],
    ) -> WeilerAthertonTrace:
        """Build the trace from the clipper's exact rings, contacts and linked loops.

        Loops are numbered like the result (by lowest-leftmost vertex) and each starts where
        the subject enters the window, as the classic walk does (at its lowest-leftmost
        vertex when the walk never switches).
        """
        steps = []
        for number, loop in enumerate(sorted(loops, key=min)):
            pieces = list(zip(loop, [*loop[1:], loop[0]], strict=True))
            sides = [along[piece] for piece in pieces]
            entries = [
                k for k in range(len(pieces)) if sides[k] == "subject" and sides[k - 1] != "subject"
            ]
            first = entries[0] if entries else loop.index(min(loop))
            pieces, sides = pieces[first:] + pieces[:first], sides[first:] + sides[:first]
            for k, (start, end) in enumerate(pieces):
                steps.append(
                    WalkStep(
                        loop=number,
                        start=_floats([start])[0],
                        end=_floats([end])[0],
                        along=sides[k],
                        switch=sides[k] != sides[k - 1],
                    )
                )
        return cls(
            subject=_floats(subject),
            window=_floats(window),
            contacts=_floats(sorted(contacts)),
            steps=tuple(steps),
            result=tuple(result),
        )

    @property
    def loops(self) -> int:
        """How many closed loops (pieces) the walk made."""
        return len({step.loop for step in self.steps})

    def __str__(self) -> str:
        lines = [
            f"Weiler-Atherton walk: subject of {len(self.subject)} vertices, window of "
            f"{len(self.window)} vertices (both counter-clockwise)",
            f"contacts of the two boundaries: {_points(self.contacts) or 'none'}",
        ]
        for number in range(self.loops):
            lines += ["", f"piece {number + 1}", "  from        to          along"]
            for step in self.steps:
                if step.loop == number:
                    note = "  (switch)" if step.switch else ""
                    lines.append(
                        f"  {_point(step.start):<12}{_point(step.end):<12}{step.along}{note}"
                    )
        if not self.steps:
            lines += ["", "nothing is left: the polygons do not overlap"]
        return "\n".join(lines)

    def frames(self) -> list:
        """Return one picture per stage of the walk (see :func:`pixelpath.figures.walk_frames`).

        Examples
        --------
        >>> from pixelpath.clip import Rect, weiler_atherton
        >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
        >>> _, trace = weiler_atherton(notched, Rect(-1, -1, 3, 7), trace=True)
        >>> len(trace.frames()) == 4 + len(trace.steps) + 1
        True
        """
        from pixelpath.figures.clipping import walk_frames

        return walk_frames(self)

    def animate(self, path: str | os.PathLike) -> Path:
        """Write the walk as an animated GIF: the contacts, the kept pieces, each step.

        Examples
        --------
        >>> from pixelpath.clip import Rect, weiler_atherton
        >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
        >>> _, trace = weiler_atherton(notched, Rect(-1, -1, 3, 7), trace=True)
        >>> trace.animate("walk.gif").name
        'walk.gif'
        """
        from pixelpath.figures.clipping import animate_walk

        return animate_walk(self, path)

    def figure(self):
        """Return the subject and window beside the pieces the walk cut out (a PIL image).

        Examples
        --------
        >>> from pixelpath.clip import Rect, weiler_atherton
        >>> _, trace = weiler_atherton([(0, 0), (4, 0), (0, 4)], Rect(1, -1, 5, 5), trace=True)
        >>> trace.figure().mode
        'RGB'
        """
        from pixelpath.figures.clipping import walk_figure

        return walk_figure(self)

    def _repr_png_(self) -> bytes:
        from pixelpath.figures._canvas import png_bytes

        return png_bytes(self.figure())

    def _repr_html_(self) -> str:
        from pixelpath.figures.html import table

        rows = [
            (step.loop + 1, _point(step.start), _point(step.end), step.along,
             "switch" if step.switch else "")
            for step in self.steps
        ]
        caption = f"Weiler-Atherton walk: {self.loops} piece(s); contacts {_points(self.contacts)}"
        return table(caption, ("piece", "from", "to", "along", ""), rows)


def _floats(points: Iterable[ExactPoint]) -> np.ndarray:
    return np.array([(float(x), float(y)) for x, y in points], dtype=np.float64).reshape(-1, 2)


def _point(p: np.ndarray) -> str:
    return f"({p[0]:g}, {p[1]:g})"


def _points(points: np.ndarray) -> str:
    return " ".join(_point(p) for p in points)
