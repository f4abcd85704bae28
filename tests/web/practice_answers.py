"""Helpers of the Practice tests: an exercise's answer written as a student types it."""

from __future__ import annotations

import math
from typing import Any


def typed(kind: str, value: Any) -> str:
    """Return ``value`` written the way the Practice page's placeholder for ``kind`` asks."""
    if kind == "number":
        return "none" if value is None or math.isinf(value) else repr(float(value))
    if kind == "vector":
        return "none" if value is None else "(" + ", ".join(map(repr, value)) + ")"
    if kind == "polygon":
        return " ".join(f"({x!r}, {y!r})" for x, y in value) or "none"
    if kind == "polygons":
        return "; ".join(typed("polygon", polygon) for polygon in value)
    if kind in ("sequence", "set"):
        return ", ".join(map(str, value))
    if kind == "choice":
        return str(value)
    return " ".join(value)  # grid: one word a row


def typed_answer(exercise: Any) -> dict[str, str]:
    """Return every field of ``exercise``'s answer, typed."""
    return {field.name: typed(field.kind, exercise.answer[field.name])
            for field in exercise.fields}
