"""Clipping windows: Rect validation, convex polygon windows, rejection of concave ones."""

from __future__ import annotations

import numpy as np
import pytest

from pixelpath.clip import Rect, sutherland_hodgman

SUBJECT = [(1, 1), (9, 1), (9, 7), (1, 7)]


@pytest.mark.parametrize(
    ("bounds", "error", "match"),
    [
        ((8, 2, 2, 6), ValueError, "empty"),
        ((2, 2, 2, 6), ValueError, "empty"),
        ((2, 6, 8, 2), ValueError, "empty"),
        ((np.nan, 2, 8, 6), ValueError, "xmin must be finite"),
        ((2, 2, np.inf, 6), ValueError, "xmax must be finite"),
        (("2", 2, 8, 6), TypeError, "xmin must be a real number"),
        ((2, None, 8, 6), TypeError, "ymin must be a real number"),
        ((2, 2, 8, True), TypeError, "ymax must be a real number"),
    ],
)
def test_bad_rects_are_rejected(bounds, error, match):
    with pytest.raises(error, match=match):
        Rect(*bounds)


def test_rect_is_a_value():
    assert Rect(2, 2, 8, 6) == Rect(2.0, 2.0, 8.0, 6.0)
    assert Rect(np.int64(2), 2, 8, np.float32(6)).xmin == 2.0
    assert "xmin=2.0" in repr(Rect(2, 2, 8, 6))


@pytest.mark.parametrize("orientation", [1, -1])
def test_convex_window_in_either_orientation(orientation):
    hexagon = np.array([(5, 1), (8, 3), (8, 5), (5, 7), (2, 5), (2, 3)], float)[::orientation]
    result = sutherland_hodgman(SUBJECT, hexagon)
    x, y = result[:, 0], result[:, 1]
    # The hexagon lies inside the subject, so it is the result: a 6 x 2 band and two
    # triangles of base 6 and height 2, area 12 + 6 + 6.
    assert 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) == pytest.approx(24.0)
    assert sorted(map(tuple, result.tolist())) == sorted(map(tuple, hexagon.tolist()))


def test_collinear_and_repeated_window_vertices_are_tolerated():
    window = [(2, 2), (5, 2), (8, 2), (8, 2), (8, 6), (2, 6)]
    result, trace = sutherland_hodgman(SUBJECT, window, trace=True)
    assert len(trace.stages) == 5
    assert sorted(map(tuple, result.tolist())) == [(2, 2), (2, 6), (8, 2), (8, 6)]


def test_concave_window_names_its_reflex_vertex():
    arrow = [(0, 0), (4, 2), (0, 4), (1, 2)]
    with pytest.raises(ValueError, match=r"vertex 3 at \(1, 2\) is reflex.*weiler_atherton"):
        sutherland_hodgman(SUBJECT, arrow)


def test_clockwise_concave_window_names_its_reflex_vertex():
    arrow = [(0, 0), (4, 2), (0, 4), (1, 2)][::-1]
    with pytest.raises(ValueError, match=r"vertex 0 at \(1, 2\) is reflex"):
        sutherland_hodgman(SUBJECT, arrow)


def test_pentagram_winding_twice_is_rejected():
    angles = np.pi / 2 + 4 * np.pi * np.arange(5) / 5
    pentagram = np.column_stack([np.cos(angles), np.sin(angles)])
    with pytest.raises(ValueError, match="winds around more than once"):
        sutherland_hodgman(SUBJECT, pentagram)


@pytest.mark.parametrize(
    ("window", "match"),
    [
        ([(0, 0), (1, 1), (2, 2)], "zero area"),
        ([(0, 0), (1, 1), (0, 0)], "3 distinct"),
        ([(0, 0), (1, 0), (np.nan, 1)], "NaN or infinite"),
        ([(0, 0, 1), (1, 0, 1), (1, 1, 1)], "shape"),
        ([(0, 0), (2, 0), (1, 0), (1, 1)], "reflex"),  # doubles back along its first edge
    ],
)
def test_degenerate_windows_are_rejected(window, match):
    with pytest.raises(ValueError, match=match):
        sutherland_hodgman(SUBJECT, window)


def test_window_of_the_wrong_type_is_rejected():
    with pytest.raises(TypeError, match="window"):
        sutherland_hodgman(SUBJECT, "2,2,8,6")
