"""Weiler-Atherton: named degenerate fixtures (hand-derived) and agreement with shapely."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from clip_strategies import is_valid_polygon, polygonal_parts, signed_area, star_polygons
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pixelpath.clip import Rect, weiler_atherton

SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]
NOTCHED = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]


def as_lists(pieces):
    return [piece.tolist() for piece in pieces]


def test_notched_square_comes_apart_into_two_pieces():
    pieces = weiler_atherton(NOTCHED, Rect(-1, -1, 3, 7))
    assert as_lists(pieces) == [
        [[0, 0], [3, 0], [3, 2], [0, 2]],
        [[0, 4], [3, 4], [3, 6], [0, 6]],
    ]


def test_pieces_are_counter_clockwise_for_clockwise_input():
    pieces = weiler_atherton(NOTCHED[::-1], Rect(-1, -1, 3, 7).vertices[::-1])
    assert len(pieces) == 2
    assert all(signed_area(p) > 0 for p in pieces)


def test_concave_window_cuts_a_convex_subject_into_pieces():
    comb = [(0, 0), (5, 0), (5, 3), (4, 3), (4, 1), (1, 1), (1, 3), (0, 3)]
    pieces = weiler_atherton([(-1, 2), (6, 2), (6, 4), (-1, 4)], comb)
    assert as_lists(pieces) == [[[0, 2], [1, 2], [1, 3], [0, 3]], [[4, 2], [5, 2], [5, 3], [4, 3]]]


def test_subject_inside_the_window_is_the_result():
    inner = [(1, 1), (2, 1), (2, 2), (1, 2)]
    assert as_lists(weiler_atherton(inner, SQUARE)) == [[[1, 1], [2, 1], [2, 2], [1, 2]]]


def test_window_inside_the_subject_is_the_result():
    window = [(1, 1), (3, 1), (2, 3)]
    assert as_lists(weiler_atherton(SQUARE, window)) == [[[1, 1], [3, 1], [2, 3]]]


def test_identical_polygons_give_the_polygon():
    assert as_lists(weiler_atherton(NOTCHED, NOTCHED)) == [
        [[0, 0], [6, 0], [6, 6], [0, 6], [0, 4], [4, 4], [4, 2], [0, 2]]
    ]


def test_identical_polygons_in_opposite_orientations_give_the_polygon():
    assert len(weiler_atherton(NOTCHED, NOTCHED[::-1])) == 1


def test_disjoint_polygons_give_nothing():
    assert weiler_atherton(SQUARE, [(10, 10), (11, 10), (11, 11)]) == []


def test_touching_at_a_single_point_gives_nothing():
    assert weiler_atherton(SQUARE, [(4, 4), (6, 4), (6, 6), (4, 6)]) == []


def test_touching_along_an_edge_gives_nothing():
    assert weiler_atherton(SQUARE, [(4, 1), (6, 1), (6, 3), (4, 3)]) == []


def test_vertex_of_the_subject_on_a_window_edge():
    diamond = [(4, 2), (6, 0), (8, 2), (6, 4)]  # its left vertex lies on the square's edge
    assert weiler_atherton(diamond, SQUARE) == []
    dent = [(2, 4), (3, 6), (1, 6)]  # a triangle standing on the square's top edge
    assert weiler_atherton(dent, SQUARE) == []


def test_vertex_on_edge_with_overlap():
    diamond = [(2, 2), (5, -1), (8, 2), (5, 5)]  # crosses x = 4; (4, 4) corner inside
    pieces = weiler_atherton(diamond, SQUARE)
    expected = shapely.Polygon(diamond).intersection(shapely.Polygon(SQUARE))
    assert len(pieces) == 1
    assert abs(signed_area(pieces[0])) == pytest.approx(expected.area)


def test_window_vertex_on_a_subject_edge():
    triangle = [(0, 0), (8, 0), (0, 8)]  # hypotenuse passes through the square's corner (4, 4)
    assert as_lists(weiler_atherton(triangle, SQUARE)) == [[[0, 0], [4, 0], [4, 4], [0, 4]]]


def test_collinear_overlapping_edges_on_the_same_side():
    # Shares part of the square's bottom edge, both interiors above it.
    pieces = weiler_atherton([(1, 0), (6, 0), (6, 2), (1, 2)], SQUARE)
    assert as_lists(pieces) == [[[1, 0], [4, 0], [4, 2], [1, 2]]]


def test_shared_edge_with_the_subject_reaching_outside():
    pieces = weiler_atherton([(0, 0), (4, 0), (4, 6), (0, 6)], SQUARE)
    assert as_lists(pieces) == [[[0, 0], [4, 0], [4, 4], [0, 4]]]


def test_pieces_touching_at_a_vertex_are_separate():
    bowtie_window = [(0, 0), (2, 2), (4, 0), (4, 4), (2, 2), (0, 4)]
    with pytest.raises(ValueError, match="self-intersecting"):
        weiler_atherton(SQUARE, bowtie_window)  # a window touching itself is not simple
    notch = [(0, 0), (4, 0), (4, 4), (2, 2), (0, 4)]  # a concave V reaching the centre
    pieces = weiler_atherton(notch, [(0, 2), (4, 2), (4, 4), (0, 4)])
    assert as_lists(pieces) == [[[0, 2], [2, 2], [0, 4]], [[2, 2], [4, 2], [4, 4]]]


def test_results_are_independent_of_the_starting_vertex():
    rotated = np.roll(np.array(NOTCHED), 3, axis=0)
    assert as_lists(weiler_atherton(rotated, Rect(-1, -1, 3, 7))) == as_lists(
        weiler_atherton(NOTCHED, Rect(-1, -1, 3, 7))
    )


@pytest.mark.parametrize(
    ("subject", "error", "match"),
    [
        ([(0, 0), (4, 4), (4, 0), (0, 4)], ValueError, r"self-intersecting: edges 0 and 2"),
        ([(0, 0), (4, 0), (2, 0), (2, 3)], ValueError, "self-intersecting"),
        ([(0, 0), (1, 1), (2, 2)], ValueError, "zero area"),
        ([(0, 0), (1, 1), (0, 0)], ValueError, "3 distinct"),
        ([(0, 0), (1, 0), (np.nan, 1)], ValueError, "NaN or infinite"),
        ([(0, 0, 0), (1, 0, 0), (1, 1, 0)], ValueError, "shape"),
        ([("a", "b"), ("c", "d"), ("e", "f")], TypeError, "real coordinates"),
    ],
)
def test_bad_input_is_rejected(subject, error, match):
    with pytest.raises(error, match=match):
        weiler_atherton(subject, SQUARE)
    with pytest.raises(error, match=match.replace("subject", "window")):
        weiler_atherton(SQUARE, subject)


def check_against_shapely(subject, window):
    pieces = weiler_atherton(subject, window)
    expected = polygonal_parts(shapely.Polygon(subject).intersection(shapely.Polygon(window)))
    assert len(pieces) == len(expected)
    total = sum(signed_area(p) for p in pieces)
    assert total == pytest.approx(sum(p.area for p in expected), rel=1e-9, abs=1e-12)
    assert all(signed_area(p) > 0 for p in pieces)
    for piece in pieces:  # each piece is a valid, simple polygon of its own
        assert shapely.Polygon(piece).is_valid


@given(subject=star_polygons(max_vertices=10), window=star_polygons(max_vertices=10))
@settings(max_examples=40, deadline=None)
def test_random_concave_pairs_agree_with_shapely(subject, window):
    check_against_shapely(subject, window)


@given(
    subject=star_polygons(max_vertices=8, grid=True),
    window=star_polygons(max_vertices=8, grid=True),
)
@settings(max_examples=60, deadline=None)
def test_random_grid_pairs_with_degenerate_contacts_agree_with_shapely(subject, window):
    assume(is_valid_polygon(subject) and is_valid_polygon(window))
    check_against_shapely(subject, window)


def test_subject_inside_touching_the_window_from_inside():
    # Shares the square's left edge partly and touches its top edge at one vertex.
    inner = [(0, 1), (2, 1), (2, 2), (1, 4), (0, 3)]
    assert as_lists(weiler_atherton(inner, SQUARE)) == [[[0, 1], [2, 1], [2, 2], [1, 4], [0, 3]]]


def test_window_inside_touching_the_subject_at_a_vertex():
    window = [(0, 0), (2, 1), (1, 2)]  # its first vertex is the square's corner
    assert as_lists(weiler_atherton(SQUARE, window)) == [[[0, 0], [2, 1], [1, 2]]]


def test_window_edges_collinear_with_a_concave_subject_notch():
    # The window's top edge runs exactly along the notch's floor, y = 2.
    pieces = weiler_atherton(NOTCHED, [(1, 0), (5, 0), (5, 2), (1, 2)])
    assert as_lists(pieces) == [[[1, 0], [5, 0], [5, 2], [1, 2]]]
    pieces = weiler_atherton(NOTCHED, [(1, 2), (5, 2), (5, 4), (1, 4)])  # fills the notch
    assert as_lists(pieces) == [[[4, 2], [5, 2], [5, 4], [4, 4]]]


@given(subject=star_polygons(max_vertices=8, grid=True), corners=star_polygons(3, 3, grid=True))
@settings(max_examples=40, deadline=None)
def test_random_grid_subjects_against_rects_agree_with_shapely(subject, corners):
    assume(is_valid_polygon(subject))
    (xmin, ymin), (xmax, ymax) = corners.min(axis=0), corners.max(axis=0)
    assume(xmin < xmax and ymin < ymax)
    check_against_shapely(subject, Rect(xmin, ymin, xmax, ymax).vertices)
    pieces = weiler_atherton(subject, Rect(xmin, ymin, xmax, ymax))
    assert len(pieces) == len(weiler_atherton(subject, Rect(xmin, ymin, xmax, ymax).vertices))


@given(seed=st.integers(0, 2**32 - 1))
@settings(max_examples=30, deadline=None)
def test_interval_sweep_finds_every_overlapping_pair(seed):
    from pixelpath.clip.weiler_atherton import _x_overlaps

    rng = np.random.default_rng(seed)
    ends_a, ends_b = rng.integers(0, 20, (2, 15, 2)) / 4  # small grid: many touching ends
    lo_a, hi_a = ends_a.min(axis=1), ends_a.max(axis=1)
    lo_b, hi_b = ends_b.min(axis=1), ends_b.max(axis=1)
    i, j = _x_overlaps(lo_a, hi_a, lo_b, hi_b)
    found = {(a, b) for a, b in zip(i.tolist(), j.tolist(), strict=True)}
    brute = {(a, b) for a in range(15) for b in range(15)
             if lo_a[a] <= hi_b[b] and lo_b[b] <= hi_a[a]}
    assert brute <= found
