"""Clipping windows: the notes' rectangle and convex polygons, validated once.

A window is turned into a *boundary table* for the kernels (see :mod:`pixelpath.clip._kernels`)
with one row per boundary in clipping order:

* :class:`Rect` has the notes' four boundaries in the notes' order Left, Right, Bottom, Top
  (section 3), with the inside tests of section 4 (``x >= xmin``, ``x <= xmax``, ``y >= ymin``,
  ``y <= ymax``). Points on a boundary are inside.
* A convex polygon window, in either orientation, has one boundary per edge, in the order given
  (``"edge 1"`` runs from vertex 0 to vertex 1). Repeated consecutive vertices are dropped and
  collinear vertices are allowed. A reflex vertex is rejected: Sutherland-Hodgman needs a convex
  window (notes, section 9); :func:`pixelpath.clip.weiler_atherton` takes concave ones.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from pixelpath.clip import _validate
from pixelpath.clip._kernels import BOTTOM, EDGE, LEFT, RIGHT, TOP

RECT_BOUNDARIES = ("left", "right", "bottom", "top")


@dataclass(frozen=True)
class Rect:
    """An axis-aligned clipping window ``xmin <= x <= xmax``, ``ymin <= y <= ymax``.

    Parameters
    ----------
    xmin, ymin, xmax, ymax : float
        The window's bounds; finite, with ``xmin < xmax`` and ``ymin < ymax``.

    Raises
    ------
    ValueError
        If a bound is not finite or the window is empty.
    TypeError
        If a bound is not a real number.

    Examples
    --------
    >>> from pixelpath.clip import Rect
    >>> Rect(2, 2, 8, 6).vertices.tolist()
    [[2.0, 2.0], [8.0, 2.0], [8.0, 6.0], [2.0, 6.0]]
    """

    xmin: float
    ymin: float
    xmax: float
    ymax: float
    table: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for name in ("xmin", "ymin", "xmax", "ymax"):
            value = getattr(self, name)
            real = isinstance(value, (int, float, np.integer, np.floating))
            if isinstance(value, bool) or not real:
                raise TypeError(f"Rect: {name} must be a real number, got {type(value).__name__}")
            if not math.isfinite(value):
                raise ValueError(f"Rect: {name} must be finite, got {value}")
            object.__setattr__(self, name, float(value))
        if not (self.xmin < self.xmax and self.ymin < self.ymax):
            raise ValueError(
                f"Rect: the window is empty; need xmin < xmax and ymin < ymax, got {self}"
            )
        table = np.zeros((4, 5))
        table[:, 0] = (LEFT, RIGHT, BOTTOM, TOP)
        table[:, 1] = (self.xmin, self.xmax, self.ymin, self.ymax)
        table.flags.writeable = False
        object.__setattr__(self, "table", table)

    @property
    def vertices(self) -> np.ndarray:
        """The corners, counter-clockwise from ``(xmin, ymin)``: a ``(4, 2)`` array."""
        return np.array(
            [[self.xmin, self.ymin], [self.xmax, self.ymin], [self.xmax, self.ymax],
             [self.xmin, self.ymax]]
        )


@dataclass(frozen=True, eq=False)  # compared by identity: its fields are arrays
class ConvexWindow:
    """A validated convex polygon window (built by :func:`as_window`).

    Examples
    --------
    >>> from pixelpath.clip.window import as_window
    >>> as_window([(0, 0), (0, 2), (2, 0)]).boundary_names
    ('edge 1', 'edge 2', 'edge 3')
    """

    vertices: np.ndarray
    table: np.ndarray

    @property
    def boundary_names(self) -> tuple[str, ...]:
        """``"edge 1"``, ``"edge 2"``, ... in clipping order."""
        return tuple(f"edge {k + 1}" for k in range(len(self.vertices)))


def boundary_names(window: Rect | ConvexWindow) -> tuple[str, ...]:
    """Return the names of the window's boundaries in clipping order.

    Examples
    --------
    >>> from pixelpath.clip import Rect
    >>> from pixelpath.clip.window import boundary_names
    >>> boundary_names(Rect(0, 0, 1, 1))
    ('left', 'right', 'bottom', 'top')
    """
    return RECT_BOUNDARIES if isinstance(window, Rect) else window.boundary_names


def as_window(window: object) -> Rect | ConvexWindow:
    """Return ``window`` as a :class:`Rect` or a validated :class:`ConvexWindow`.

    Raises
    ------
    ValueError
        If the polygon is degenerate or not convex (the message names the reflex vertex).

    Examples
    --------
    >>> from pixelpath.clip.window import as_window
    >>> as_window([(0, 0), (2, 0), (2, 2), (0, 2)]).vertices.shape
    (4, 2)
    >>> as_window([(0, 0), (4, 2), (0, 4), (1, 2)])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: window: not convex, vertex 3 at (1, 2) is reflex; ...
    """
    if isinstance(window, (Rect, ConvexWindow)):
        return window
    vertices = _validate.distinct_ring(_validate.polygon_array(window, "window"), "window")
    _validate.bounded(vertices, "window")  # the slanted-edge arithmetic multiplies coordinates
    turns = _turns(vertices)
    area2 = _validate.twice_signed_area(vertices)
    if area2 == 0.0:
        raise ValueError("window: the polygon has zero area (all its vertices are collinear)")
    orientation = 1.0 if area2 > 0 else -1.0
    reflex = np.flatnonzero(turns * orientation < 0)
    if reflex.size:
        i = int(reflex[0])
        x, y = vertices[i]
        raise ValueError(
            f"window: not convex, vertex {i} at ({x:g}, {y:g}) is reflex; Sutherland-Hodgman "
            "needs a convex window, use weiler_atherton(subject, window) for concave windows"
        )
    _check_single_turn(vertices)
    starts, ends = vertices, np.roll(vertices, -1, axis=0)
    if orientation < 0:  # keep the inside on each edge's left
        starts, ends = ends, starts
    table = np.empty((len(vertices), 5))
    table[:, 0] = EDGE
    table[:, 1:3] = starts
    table[:, 3:5] = ends
    table.flags.writeable = False
    vertices.flags.writeable = False
    return ConvexWindow(vertices=vertices, table=table)


def _turns(vertices: np.ndarray) -> np.ndarray:
    """Cross product of the edges into and out of each vertex (> 0: a left turn)."""
    incoming = vertices - np.roll(vertices, 1, axis=0)
    outgoing = np.roll(vertices, -1, axis=0) - vertices
    turns = incoming[:, 0] * outgoing[:, 1] - incoming[:, 1] * outgoing[:, 0]
    # A vertex where the boundary doubles back on itself is as bad as a reflex one.
    folds = (turns == 0) & (np.einsum("ij,ij->i", incoming, outgoing) < 0)
    return np.where(folds, -np.sign(_validate.twice_signed_area(vertices)), turns)


def _check_single_turn(vertices: np.ndarray) -> None:
    """Reject a star-shaped loop that turns the same way but winds around more than once."""
    edges = np.roll(vertices, -1, axis=0) - vertices
    angles = np.arctan2(edges[:, 1], edges[:, 0])
    total = np.abs(np.sum(np.angle(np.exp(1j * (np.roll(angles, -1) - angles)))))
    if total > 3 * np.pi:
        raise ValueError("window: the polygon winds around more than once, it is not convex")
