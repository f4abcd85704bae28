"""Polygon clipping: Sutherland-Hodgman (with its trace), Weiler-Atherton, batch clipping.

Examples
--------
>>> from pixelpath.clip import Rect, sutherland_hodgman
>>> sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6)).tolist()
[[2.0, 6.0], [2.0, 2.0], [8.0, 2.0], [8.0, 6.0]]
"""

from __future__ import annotations

from pixelpath.clip.batch import clip_flat, clip_polygons
from pixelpath.clip.sutherland_hodgman import (
    ClipStage,
    ClipStep,
    ClipTrace,
    ZeroWidthBridgeWarning,
    sutherland_hodgman,
    zero_width_bridges,
)
from pixelpath.clip.weiler_atherton import weiler_atherton
from pixelpath.clip.weiler_atherton_trace import WalkStep, WeilerAthertonTrace
from pixelpath.clip.window import Rect

__all__ = [
    "ClipStage",
    "ClipStep",
    "ClipTrace",
    "Rect",
    "WalkStep",
    "WeilerAthertonTrace",
    "ZeroWidthBridgeWarning",
    "clip_flat",
    "clip_polygons",
    "sutherland_hodgman",
    "weiler_atherton",
    "zero_width_bridges",
]
