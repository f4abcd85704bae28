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
from collections.abc import Mapping, Sequence
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
    """

    method: str
    summary: Mapping[str, Any]
    tables: tuple[Table, ...] = ()
    notes: tuple[str, ...] = ()
    arrays: Mapping[str, Any] = dataclasses.field(default_factory=dict)

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
