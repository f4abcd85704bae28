"""HTML tables for Jupyter's rich display of traces and reports (``_repr_html_``).

Every value is escaped, so a table is safe to show whatever a name or number holds.

Examples
--------
>>> from pixelpath.figures.html import table
>>> html = table("steps", ("S", "E"), [("(1, 7)", "(1, 1)")])
>>> html.startswith('<table class="pixelpath"><caption>steps</caption>')
True
>>> "<tr><td>(1, 7)</td><td>(1, 1)</td></tr>" in html
True
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from html import escape
from typing import Any

__all__ = ["table"]


def table(caption: str, columns: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """Return an HTML table with a caption, a header row and one row per item.

    Parameters
    ----------
    caption : str
        The table's title.
    columns : sequence of str
        Column names.
    rows : iterable of sequences
        Cells, turned into text with ``str`` and escaped.

    Returns
    -------
    str
        ``<table class="pixelpath">...</table>``.

    Examples
    --------
    >>> from pixelpath.figures.html import table
    >>> "<td>a &lt; b</td>" in table("t", ("x",), [("a < b",)])
    True
    """
    head = "".join(f"<th>{escape(str(name))}</th>" for name in columns)
    body = "".join(
        "<tr>" + "".join(f"<td>{escape(str(cell))}</td>" for cell in row) + "</tr>" for row in rows
    )
    return (
        f'<table class="pixelpath"><caption>{escape(caption)}</caption>'
        f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
    )
