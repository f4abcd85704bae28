"""What the playground accepts: caps on every request and the checks that enforce them.

Every value a request carries passes through one of these functions before the library sees
it, so a bad request ends as a :class:`BadRequest` (a 4xx JSON answer naming the field and
what came in) and never as a traceback. Scenes are chosen by name from the bundled ones only:
no string from a request is ever used as a path.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Sequence
from typing import Any

__all__ = ["BadRequest", "Limits", "choice", "image_size", "number", "parse_json", "points"]


@dataclasses.dataclass(frozen=True)
class Limits:
    """The caps of one playground app.

    Attributes
    ----------
    max_side : int
        Largest image width or height, in pixels.
    max_vertices : int
        Most vertices a clipping polygon may have.
    max_body_bytes : int
        Largest request body.
    render_seconds : float
        Time limit of one computation; past it the request gets a 503 (the work already
        started finishes in the background, and later requests queue behind it).
    workers : int
        Computations run at once, off the event loop.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> Limits().max_side
    1024
    """

    max_side: int = 1024
    max_vertices: int = 64
    max_body_bytes: int = 64 * 1024
    render_seconds: float = 60.0
    workers: int = 2


class BadRequest(Exception):
    """A request the playground refuses; ``status`` is the HTTP status to answer with.

    Examples
    --------
    >>> from pixelpath.web import BadRequest
    >>> BadRequest("width must be an integer").status
    400
    """

    def __init__(self, message: str, status: int = 400) -> None:
        super().__init__(message)
        self.status = status


DEFAULT_SIZE = (320, 200)
COORDINATE_LIMIT = 1e6  # clipping coordinates; the canvas shows a few dozen units


def parse_json(body: bytes, limits: Limits) -> dict[str, Any]:
    """Return the JSON object in ``body``; NaN and Infinity literals are refused.

    Examples
    --------
    >>> from pixelpath.web._limits import Limits, parse_json
    >>> parse_json(b'{"ka": 0.2}', Limits())
    {'ka': 0.2}
    >>> parse_json(b'{"ka": NaN}', Limits())
    Traceback (most recent call last):
    ...
    pixelpath.web._limits.BadRequest: the request body is not valid JSON: NaN is not a number ...
    """
    if len(body) > limits.max_body_bytes:
        raise BadRequest(
            f"the request body holds {len(body)} bytes, more than the {limits.max_body_bytes} "
            "allowed", status=413)
    try:
        data = json.loads(body or b"{}", parse_constant=_refuse_constant)
    except (ValueError, RecursionError) as exc:
        raise BadRequest(f"the request body is not valid JSON: {exc}") from None
    if not isinstance(data, dict):
        raise BadRequest(f"the request body must be a JSON object, got {type(data).__name__}")
    return data


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number JSON allows (non-finite values are refused)")


def number(data: dict[str, Any], key: str, default: float, low: float, high: float) -> float:
    """Return ``data[key]`` (or ``default``), a finite number in ``[low, high]``.

    Examples
    --------
    >>> from pixelpath.web._limits import number
    >>> number({"n": 20}, "n", 1, 0, 1000)
    20.0
    >>> number({"n": "20"}, "n", 1, 0, 1000)
    Traceback (most recent call last):
    ...
    pixelpath.web._limits.BadRequest: n must be a number, got '20'
    """
    value = data.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise BadRequest(f"{key} must be a number, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise BadRequest(f"{key} must be finite, got {value}")
    if not low <= value <= high:
        raise BadRequest(f"{key} must lie in [{low:g}, {high:g}], got {value:g}")
    return value


def integer(data: dict[str, Any], key: str, default: int, low: int, high: int) -> int:
    """Return ``data[key]`` (or ``default``), an integer in ``[low, high]``.

    Examples
    --------
    >>> from pixelpath.web._limits import integer
    >>> integer({}, "max_depth", 3, 0, 8)
    3
    """
    value = data.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int):
        raise BadRequest(f"{key} must be an integer, got {value!r}")
    if not low <= value <= high:
        raise BadRequest(f"{key} must lie in {low}..{high}, got {value}")
    return value


def image_size(data: dict[str, Any], limits: Limits) -> tuple[int, int]:
    """Return (width, height) from the request, each in ``1..limits.max_side``.

    Examples
    --------
    >>> from pixelpath.web._limits import Limits, image_size
    >>> image_size({}, Limits())
    (320, 200)
    >>> image_size({"width": 4096}, Limits())
    Traceback (most recent call last):
    ...
    pixelpath.web._limits.BadRequest: width must lie in 1..1024, got 4096
    """
    width = integer(data, "width", DEFAULT_SIZE[0], 1, limits.max_side)
    height = integer(data, "height", DEFAULT_SIZE[1], 1, limits.max_side)
    return width, height


def choice(data: dict[str, Any], key: str, default: str, options: Sequence[str]) -> str:
    """Return ``data[key]`` (or ``default``), which must be one of ``options``.

    Examples
    --------
    >>> from pixelpath.web._limits import choice
    >>> choice({"shading": "toon"}, "shading", "phong", ("flat", "phong"))
    Traceback (most recent call last):
    ...
    pixelpath.web._limits.BadRequest: unknown shading 'toon'; choose from flat, phong
    """
    value = data.get(key, default)
    if not isinstance(value, str) or value not in options:
        shown = value if isinstance(value, str) else repr(value)
        raise BadRequest(f"unknown {key} {shown[:80]!r}; choose from {', '.join(options)}")
    return value


def vector(data: dict[str, Any], key: str, default: Sequence[float], size: int,
           bound: float) -> tuple[float, ...]:
    """Return ``data[key]`` (or ``default``): ``size`` finite numbers within ``±bound``.

    Examples
    --------
    >>> from pixelpath.web._limits import vector
    >>> vector({"light": [1, 2, 3]}, "light", (0, 0, 0), 3, 100)
    (1.0, 2.0, 3.0)
    """
    value = data.get(key, default)
    if not isinstance(value, list | tuple) or len(value) != size:
        raise BadRequest(f"{key} must be a list of {size} numbers, got {_short(value)}")
    return tuple(number({key: v}, key, 0.0, -bound, bound) for v in value)


def points(data: dict[str, Any], key: str, limits: Limits) -> list[tuple[float, float]]:
    """Return ``data[key]`` as a polygon: 3 to ``limits.max_vertices`` finite (x, y) pairs.

    Examples
    --------
    >>> from pixelpath.web._limits import Limits, points
    >>> points({"subject": [[0, 0], [4, 0], [0, 3]]}, "subject", Limits())
    [(0.0, 0.0), (4.0, 0.0), (0.0, 3.0)]
    >>> points({"subject": [[0, 0], [4, 0]]}, "subject", Limits())
    Traceback (most recent call last):
    ...
    pixelpath.web._limits.BadRequest: subject must have 3 to 64 vertices, got 2
    """
    value = data.get(key)
    if not isinstance(value, list):
        raise BadRequest(f"{key} must be a list of [x, y] points, got {_short(value)}")
    if not 3 <= len(value) <= limits.max_vertices:
        raise BadRequest(f"{key} must have 3 to {limits.max_vertices} vertices, got {len(value)}")
    polygon = []
    for k, point in enumerate(value):
        if not isinstance(point, list) or len(point) != 2:
            raise BadRequest(f"{key}[{k}] must be a point [x, y], got {_short(point)}")
        name = f"{key}[{k}]"
        polygon.append(tuple(number({name: c}, name, 0.0, -COORDINATE_LIMIT, COORDINATE_LIMIT)
                             for c in point))
    return polygon


def _short(value: Any) -> str:
    """Return a request value as JSON, cut to a length that fits in a message."""
    text = json.dumps(value)
    return text if len(text) <= 60 else text[:57] + "..."
