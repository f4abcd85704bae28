"""Hostile coordinates for every public clip function: near the float64 limit (±1.8e308) and
at the limit the floating-point clippers take. Warnings are errors in this suite, so a NumPy
overflow warning escaping any of these calls fails it.

Weiler-Atherton computes exactly, so it takes any finite coordinates; Sutherland-Hodgman, the
batch clippers and the bridge finder compute in floating point and reject coordinates beyond
±1e150 (beyond which products of coordinate differences could overflow) with a ValueError
naming the polygon and the vertex. Scaling by a power of two is exact in floating point, so
both kinds of clipper must give exactly the scaled result of the unscaled problem.
"""

from __future__ import annotations

import numpy as np
import pytest

from pixelpath.clip import (
    Rect,
    clip_flat,
    clip_polygons,
    sutherland_hodgman,
    weiler_atherton,
    zero_width_bridges,
)

LARGEST = np.finfo(np.float64).max
NOTCHED = np.array([(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)], float)
SLANTED = np.array([(-1, 1), (2, -1), (7, 3), (1, 6)], float)  # a convex window, slanted edges
TRIANGLE = np.array([(0, 0), (5, 1), (2, 4)], float)


def test_weiler_atherton_near_the_float_limit_is_exact():
    # Differences of these coordinates overflow (8 * 2**1021 = 2**1024 > the largest float).
    scale = 2.0**1021
    window = Rect(-1, -1, 3, 7)
    big_window = Rect(-scale, -scale, 3 * scale, 7 * scale)
    expected = weiler_atherton(NOTCHED, window)
    got = weiler_atherton(NOTCHED * scale, big_window)
    assert len(got) == len(expected) == 2
    for piece, small in zip(got, expected, strict=True):
        np.testing.assert_array_equal(piece, small * scale)


@pytest.mark.parametrize(
    ("subject", "window", "expected"),
    [
        # The window lies inside a triangle spanning the whole float range: it is the answer.
        (
            [(-LARGEST, -LARGEST), (LARGEST, -LARGEST), (0, LARGEST)],
            Rect(-1, -1, 1, 1),
            [[[-1, -1], [1, -1], [1, 1], [-1, 1]]],
        ),
        # The edge from (-1e308, 0) to (1e308, 1) crosses x = ±1 at y = 0.5 ∓ 5e-309: 0.5.
        (
            [(-1e308, 0), (1e308, 1), (0, 1e308)],
            Rect(-1, -1, 1, 1),
            [[[-1, 0.5], [1, 0.5], [1, 1], [-1, 1]]],
        ),
        # A small subject against a window of near-limit vertices is itself the answer.
        (
            [(0, 0), (1, 0), (0, 1)],
            [(-1e308, -1e308), (1e308, -1e308), (0, 1e308)],
            [[[0, 0], [1, 0], [0, 1]]],
        ),
    ],
    ids=["window-inside-huge-triangle", "huge-slanted-edge", "huge-window"],
)
def test_weiler_atherton_with_hand_derived_results_near_the_limit(subject, window, expected):
    assert [piece.tolist() for piece in weiler_atherton(subject, window)] == expected


HUGE_SUBJECT = [(0, 0), (1e308, 0), (0, 1)]  # vertex 1 is beyond the limit
UNIT = Rect(0, 0, 1, 1)

# Each call with what its message must name.
BEYOND_THE_LIMIT = {
    "sh-rect": (
        lambda: sutherland_hodgman(HUGE_SUBJECT, UNIT),
        r"subject vertex 1 at \(1e\+308, 0\)",
    ),
    "sh-slanted": (lambda: sutherland_hodgman(np.array(HUGE_SUBJECT), SLANTED), "subject vertex 1"),
    "sh-trace": (lambda: sutherland_hodgman(HUGE_SUBJECT, UNIT, trace=True), "subject vertex 1"),
    "sh-window": (
        lambda: sutherland_hodgman(TRIANGLE, SLANTED * 1e300),
        r"window vertex 0 at \(-1e\+300",
    ),
    "batch": (
        lambda: clip_polygons([TRIANGLE, TRIANGLE, HUGE_SUBJECT], UNIT),
        "polygon 2 vertex 1",
    ),
    "flat": (
        lambda: clip_flat(np.vstack([TRIANGLE, HUGE_SUBJECT]), [0, 3, 6], SLANTED),
        "polygon 1 vertex 1",
    ),
    "bridges": (lambda: zero_width_bridges(HUGE_SUBJECT, UNIT), "polygon vertex 1"),
    "bridges-window": (lambda: zero_width_bridges(TRIANGLE, SLANTED * -1e200), "window vertex 0"),
}


@pytest.mark.parametrize("name", BEYOND_THE_LIMIT)
def test_floating_point_clippers_reject_coordinates_beyond_the_limit(name):
    call, names = BEYOND_THE_LIMIT[name]
    with pytest.raises(ValueError, match=names + r".*beyond ±1e\+150.*weiler_atherton"):
        call()


def test_huge_rectangle_bounds_need_no_limit():
    # A rectangle's bounds are only compared with coordinates, never multiplied.
    result = sutherland_hodgman(TRIANGLE, Rect(-LARGEST, -LARGEST, LARGEST, 2.0))
    np.testing.assert_array_equal(result, sutherland_hodgman(TRIANGLE, Rect(-1, -1, 9, 2.0)))


def scaled(window: Rect | np.ndarray, scale: float) -> Rect | np.ndarray:
    if isinstance(window, Rect):
        return Rect(
            window.xmin * scale, window.ymin * scale, window.xmax * scale, window.ymax * scale
        )
    return window * scale


# The notched subject comes apart in both windows: the bridge warning is expected here.
@pytest.mark.filterwarnings("ignore::pixelpath.clip.ZeroWidthBridgeWarning")
@pytest.mark.parametrize("window", [Rect(-1, 1, 3, 7), SLANTED], ids=["rect", "slanted"])
@pytest.mark.parametrize("scale", [2.0**-500, 2.0**490], ids=["tiny", "at-the-limit"])
def test_floating_point_clippers_scale_exactly_up_to_the_limit(window, scale):
    # 7 * 2**490 is about 2.2e148, inside the limit; 2**-500 keeps clear of subnormals.
    subject = NOTCHED - 0.5
    expected = sutherland_hodgman(subject, window)
    assert len(expected) > 0
    got = sutherland_hodgman(subject * scale, scaled(window, scale))
    np.testing.assert_array_equal(got, expected * scale)
    (batch,) = clip_polygons([subject * scale], scaled(window, scale))
    np.testing.assert_array_equal(batch, expected * scale)
    np.testing.assert_array_equal(
        zero_width_bridges(got, scaled(window, scale)), zero_width_bridges(expected, window) * scale
    )
