"""What a rendering method did: ``render(..., explain=True)``, ``pixelpath render --explain``.

A :class:`Report` holds a method's counts (``summary``), tables of its steps (scan lines,
subdivision levels, comparisons, ...) and a few sentences on how it works. ``str(report)``
prints it as plain text; the command line prints the same with rich tables.

Examples
--------
>>> from pixelpath.report import Report, Table
>>> report = Report("demo", {"triangles": 2}, (Table("steps", ("step", "count"), [("a", 1)]),))
>>> print(report)
demo
  triangles: 2
<BLANKLINE>
steps
  step  count
  a     1
>>> "<td>triangles</td><td>2</td>" in report._repr_html_()
True
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

__all__ = ["Report", "Table"]


@dataclasses.dataclass(frozen=True)
class Table:
    """A titled table of a method's steps: column names and rows of values."""

    title: str
    columns: tuple[str, ...]
    rows: Sequence[tuple[Any, ...]]

    def __str__(self) -> str:
        cells = [list(self.columns)] + [[_text(value) for value in row] for row in self.rows]
        widths = [max(len(row[k]) for row in cells) for k in range(len(self.columns))]
        lines = ["  " + "  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip()
                 for row in cells]
        return "\n".join([self.title, *lines])


@dataclasses.dataclass(frozen=True)
class Report:
    """What one method did while rendering one frame.

    Attributes
    ----------
    method : str
        The method's name.
    summary : mapping of str to number or str
        Its counts, in the order they happen.
    tables : tuple of Table
        Its steps in detail.
    notes : tuple of str
        Sentences on what the method does and in which space it works.
    arrays : mapping of str to ndarray
        The method's complete per-step data for use from Python (for example every scan
        line's counts, where the printed table shows a sample); each method's documentation
        lists its keys. Not printed.
    image : pixelpath.Image or None
        The picture the method rendered, attached by :func:`pixelpath.render`; the figures
        (:meth:`figure`, :meth:`animate`) draw over it.
    """

    method: str
    summary: Mapping[str, Any]
    tables: tuple[Table, ...] = ()
    notes: tuple[str, ...] = ()
    arrays: Mapping[str, Any] = dataclasses.field(default_factory=dict)
    image: Any = dataclasses.field(default=None, repr=False, compare=False)

    def figure(self):
        """Return the method's figure (a PIL image) drawn from this report and its image.

        Warnock's subdivision coloured by how each area was decided, the painter's and the
        BSP tree's drawing order, the octree's cells, the z-buffer's depth buffer, the
        scan-line method's counts per line (see :mod:`pixelpath.figures.hidden_surfaces`).

        Raises
        ------
        ValueError
            The method has no figure, or the report has no image (it did not come from
            ``pixelpath.render(..., explain=True)``).

        Examples
        --------
        >>> import pixelpath as pp
        >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
        ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
        >>> image, report = pp.render(scene, method="warnock", explain=True)
        >>> report.figure().mode
        'RGB'
        """
        from pixelpath.figures.methods import report_figure

        return report_figure(self)

    def frames(self) -> list:
        """Return the frames of the method's animation (PIL images), in order.

        The z-buffer and the scan-line method filling the image, Warnock's levels, the
        painter's and the BSP tree's drawing order, the octree's levels.

        Raises
        ------
        ValueError
            The method has no animation, or the report has no image.

        Examples
        --------
        >>> import pixelpath as pp
        >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
        ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
        >>> image, report = pp.render(scene, method="warnock", explain=True)
        >>> len(report.frames()) == report.summary["levels"]
        True
        """
        from pixelpath.figures.methods import report_frames

        return report_frames(self)[0]

    def animate(self, path: str | os.PathLike) -> Path:
        """Write :meth:`frames` as a looping GIF, atomically; return the path.

        Examples
        --------
        >>> import pixelpath as pp
        >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
        ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
        >>> image, report = pp.render(scene, method="scanline", explain=True)
        >>> report.animate("fill.gif").name
        'fill.gif'
        """
        from pixelpath.figures._canvas import save_animation
        from pixelpath.figures.methods import report_frames

        frames, durations = report_frames(self)
        return save_animation(frames, durations, path, pictures=True)

    def _repr_png_(self) -> bytes | None:
        """Return the method's figure as PNG for Jupyter, or None when it has none."""
        from pixelpath.figures._canvas import png_bytes
        from pixelpath.figures.methods import has_figure

        return png_bytes(self.figure()) if has_figure(self) else None

    def __str__(self) -> str:
        lines = [self.method]
        lines += [f"  {key}: {_text(value)}" for key, value in self.summary.items()]
        lines += [f"  ({note})" for note in self.notes]
        for table in self.tables:
            lines += ["", str(table)]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """Return the report as HTML tables, for Jupyter's rich display."""
        from html import escape

        from pixelpath.figures.html import table

        parts = [table(self.method, ("", ""), [(k, _text(v)) for k, v in self.summary.items()])]
        parts += [f"<p>{escape(note)}</p>" for note in self.notes]
        parts += [
            table(t.title, t.columns, [[_text(value) for value in row] for row in t.rows])
            for t in self.tables
        ]
        return "".join(parts)


def _text(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, int) and not isinstance(value, bool):
        return f"{value:,}" if abs(value) >= 10_000 else str(value)
    return str(value)
