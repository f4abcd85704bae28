"""Sutherland-Hodgman: the notes' worked example stage by stage, properties against shapely.

Expected stage outputs below were traced by hand with the notes' rules (S starts as the last
vertex; section 5's four cases; section 6's formulas), not produced by the code.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import shapely
from clip_strategies import convex_polygons, signed_area, star_polygons
from hypothesis import example, given, settings
from hypothesis import strategies as st

from pixelpath.clip import (
    Rect,
    ZeroWidthBridgeWarning,
    sutherland_hodgman,
    zero_width_bridges,
)

NOTES_SUBJECT = [(1, 1), (9, 1), (9, 7), (1, 7)]
NOTES_WINDOW = Rect(2, 2, 8, 6)
NOTCHED = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]


def test_notes_example_final_polygon_follows_the_algorithm():
    # SPEC errata: the notes' square, in the order the algorithm produces it.
    result = sutherland_hodgman(NOTES_SUBJECT, NOTES_WINDOW)
    assert result.tolist() == [[2, 6], [2, 2], [8, 2], [8, 6]]


@pytest.mark.parametrize(
    ("index", "boundary", "output"),
    [
        (0, "left", [(2, 1), (9, 1), (9, 7), (2, 7)]),
        (1, "right", [(2, 1), (8, 1), (8, 7), (2, 7)]),
        (2, "bottom", [(2, 2), (8, 2), (8, 7), (2, 7)]),
        (3, "top", [(2, 6), (2, 2), (8, 2), (8, 6)]),
    ],
)
def test_notes_example_each_stage(index, boundary, output):
    _, trace = sutherland_hodgman(NOTES_SUBJECT, NOTES_WINDOW, trace=True)
    stage = trace.stages[index]
    assert stage.boundary == boundary
    assert stage.output.tolist() == [list(p) for p in output]
    expected_input = NOTES_SUBJECT if index == 0 else trace.stages[index - 1].output.tolist()
    assert stage.input.tolist() == [list(p) for p in expected_input]


def test_left_stage_steps_follow_the_four_cases():
    _, trace = sutherland_hodgman(NOTES_SUBJECT, NOTES_WINDOW, trace=True)
    steps = trace.stages[0].steps
    assert steps[0].s.tolist() == [1, 7]  # S starts as the last vertex
    assert [s.e.tolist() for s in steps] == [[1, 1], [9, 1], [9, 7], [1, 7]]
    assert [(s.s_inside, s.e_inside) for s in steps] == [
        (False, False), (False, True), (True, True), (True, False)
    ]
    assert [s.emitted.tolist() for s in steps] == [[], [[2, 1], [9, 1]], [[9, 7]], [[2, 7]]]
    assert [s.case for s in steps] == ["out -> out", "out -> in", "in -> in", "in -> out"]


def test_trace_prints_the_students_table():
    _, trace = sutherland_hodgman(NOTES_SUBJECT, NOTES_WINDOW, trace=True)
    text = str(trace)
    assert "Clip against the left boundary (inside: x >= 2)" in text
    assert "(1, 1)  (9, 1)  out -> in   (2, 1) (9, 1)" in text
    assert "output: (2, 6) (2, 2) (8, 2) (8, 6)" in text
    assert text.endswith("Clipped polygon: (2, 6) -> (2, 2) -> (8, 2) -> (8, 6)")


def test_trace_result_equals_untraced_result_and_names_polygon_edges():
    window = [(2, 2), (8, 2), (8, 6), (2, 6)]
    traced, trace = sutherland_hodgman(NOTES_SUBJECT, window, trace=True)
    assert [s.boundary for s in trace.stages] == ["edge 1", "edge 2", "edge 3", "edge 4"]
    np.testing.assert_array_equal(traced, sutherland_hodgman(NOTES_SUBJECT, window))
    assert abs(signed_area(traced)) == pytest.approx(24.0)


def test_trace_of_a_subject_outside_shows_empty_stages():
    result, trace = sutherland_hodgman([(20, 20), (21, 20), (21, 21)], NOTES_WINDOW, trace=True)
    assert result.shape == (0, 2)
    assert len(trace.stages[0].output) == 3  # x >= 2 holds everywhere
    assert trace.stages[1].output.shape == (0, 2)
    assert trace.stages[3].steps == ()
    assert "nothing is left" in str(trace)


def test_nothing_left_is_an_empty_float_array():
    result = sutherland_hodgman([(20, 20), (21, 20), (21, 21)], NOTES_WINDOW)
    assert result.shape == (0, 2) and result.dtype == np.float64


def test_touching_along_an_edge_leaves_nothing():
    assert sutherland_hodgman([(8, 2), (9, 2), (9, 6), (8, 6)], NOTES_WINDOW).shape == (0, 2)


def test_clockwise_subject_stays_clockwise():
    result = sutherland_hodgman(NOTES_SUBJECT[::-1], NOTES_WINDOW)
    assert signed_area(result) == pytest.approx(-24.0)


def test_consecutive_duplicates_are_dropped():
    # Vertex (2, 4) lies on the left boundary: the out->in intersection equals E.
    result = sutherland_hodgman([(0, 3), (2, 4), (5, 4), (5, 3), (3, 3)], NOTES_WINDOW)
    assert len(np.unique(result, axis=0)) == len(result)
    assert not np.any(np.all(result == np.roll(result, 1, axis=0), axis=1))


def test_fast_and_slow_paths_agree():
    subject = np.array(NOTES_SUBJECT, dtype=np.float64)
    expected = sutherland_hodgman(subject, NOTES_WINDOW)
    for variant in (NOTES_SUBJECT, subject.astype(np.int32), np.asfortranarray(subject),
                    subject.astype(np.float32)):
        np.testing.assert_array_equal(sutherland_hodgman(variant, NOTES_WINDOW), expected)


def test_input_is_not_modified():
    subject = np.array(NOTES_SUBJECT, dtype=np.float64)
    before = subject.copy()
    sutherland_hodgman(subject, NOTES_WINDOW)
    sutherland_hodgman(subject, NOTES_WINDOW, trace=True)
    np.testing.assert_array_equal(subject, before)


def test_concave_subject_warns_about_its_bridge():
    window = Rect(-1, -1, 3, 7)
    with pytest.warns(ZeroWidthBridgeWarning, match="weiler_atherton"):
        result = sutherland_hodgman(NOTCHED, window)
    assert zero_width_bridges(result, window).tolist() == [[[3, 2], [3, 4]]]
    assert signed_area(result) == pytest.approx(12.0)


def test_convex_results_have_no_bridges():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = sutherland_hodgman(NOTES_SUBJECT, NOTES_WINDOW)
    assert zero_width_bridges(result, NOTES_WINDOW).shape == (0, 2, 2)


def test_concave_subject_whose_notch_stays_inside_has_no_bridge():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = sutherland_hodgman(NOTCHED, Rect(-1, 1, 7, 5))
    assert signed_area(result) == pytest.approx(6 * 4 - 4 * 2)


@pytest.mark.parametrize(
    ("subject", "error", "match"),
    [
        ([(0, 0), (1, 0), (np.nan, 1)], ValueError, "NaN or infinite"),
        (np.array([(0, 0), (1, 0), (np.inf, 1)]), ValueError, "NaN or infinite"),
        ([(0, 0), (1, 1), (0, 0), (1, 1)], ValueError, "3 distinct"),
        (np.zeros((0, 2)), ValueError, "3 distinct"),
        ([(0, 0, 0), (1, 0, 0), (1, 1, 0)], ValueError, r"shape \(N, 2\), got shape \(3, 3\)"),
        ([0, 1, 2], ValueError, r"got shape \(3,\)"),
        ([("a", "b"), ("c", "d"), ("e", "f")], TypeError, "real coordinates"),
        ([(1 + 1j, 0), (1, 0), (0, 1)], TypeError, "real coordinates"),
    ],
)
def test_bad_subjects_are_rejected(subject, error, match):
    with pytest.raises(error, match=match):
        sutherland_hodgman(subject, NOTES_WINDOW)
    with pytest.raises(error, match=match):
        sutherland_hodgman(subject, NOTES_WINDOW, trace=True)


@given(subject=star_polygons(), window=convex_polygons())
@settings(max_examples=40, deadline=None)
def test_area_matches_shapely_and_vertices_lie_inside(subject, window):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        result = sutherland_hodgman(subject, window)
    expected = shapely.Polygon(subject).intersection(shapely.Polygon(window)).area
    area = abs(signed_area(result)) if len(result) else 0.0
    assert area == pytest.approx(expected, abs=1e-9)
    edges = np.roll(window, -1, axis=0) - window
    orientation = np.sign(signed_area(window))
    for point in result:
        side = edges[:, 0] * (point[1] - window[:, 1]) - edges[:, 1] * (point[0] - window[:, 0])
        assert np.all(side * orientation >= -1e-12)


@given(subject=star_polygons(), window=convex_polygons())
@settings(max_examples=30, deadline=None)
def test_orientation_is_kept(subject, window):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        result = sutherland_hodgman(subject, window)
    if len(result) and abs(signed_area(result)) > 1e-9:
        assert np.sign(signed_area(result)) == np.sign(signed_area(subject))


@given(
    subject=star_polygons(),
    bounds=st.tuples(*[st.floats(-1, 1, allow_nan=False) for _ in range(4)]),
)
@settings(max_examples=40, deadline=None)
def test_clipping_again_against_a_rect_changes_nothing(subject, bounds):
    x0, y0, x1, y1 = bounds
    if x0 == x1 or y0 == y1:
        return
    window = Rect(min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        once = sutherland_hodgman(subject, window)
        if len(np.unique(once, axis=0)) >= 3:
            np.testing.assert_array_equal(sutherland_hodgman(once, window), once)
    assert np.all((once[:, 0] >= window.xmin) & (once[:, 0] <= window.xmax))
    assert np.all((once[:, 1] >= window.ymin) & (once[:, 1] <= window.ymax))


@given(subject=convex_polygons(), window=convex_polygons())
@settings(max_examples=30, deadline=None)
@example(  # GEOS's overlay called these two results disjoint (symmetric difference = 2 areas)
    subject=np.array(
        [
            [0.6842608564395326, -0.2832108812778526],
            [-0.2694921915512043, -0.07174355873796978],
            [0.11749527991691555, -0.9273471629742218],
        ]
    ),
    window=np.array(
        [
            [-0.10602321240970985, -0.2090908922461836],
            [0.07518155503476864, 0.48735592356227825],
            [0.009608536817383273, 0.8973547405391179],
            [-0.44588861888710335, 1.072593489231842],
            [-0.8259426986973469, 1.1043058416266707],
            [-1.1715985713328025, 0.9356310089769575],
            [-1.460636945923874, 0.35504200347639364],
            [-0.6988898787235003, -0.25340855990508715],
        ]
    ),
)
def test_clipping_again_against_a_convex_window_changes_nothing(subject, window):
    once = sutherland_hodgman(subject, window)
    if len(np.unique(once, axis=0)) < 3:
        return
    twice = sutherland_hodgman(once, window)
    # The same shape: a slanted edge's intersections are rounded, so a vertex computed on the
    # window edge may be found a second time a little further along the same edge. Compared by
    # area and Hausdorff distance: GEOS's overlay (symmetric_difference) is not robust for two
    # polygons that agree to 1e-17 along nearly collinear edges, and can call them disjoint.
    before, after = shapely.Polygon(once), shapely.Polygon(twice)
    assert after.area == pytest.approx(before.area, rel=1e-9, abs=1e-15)
    assert before.hausdorff_distance(after) < 1e-9
    assert all(before.exterior.distance(shapely.Point(p)) < 1e-9 for p in twice)


@given(subject=star_polygons(), window=convex_polygons())
@settings(max_examples=25, deadline=None)
def test_rect_and_the_same_rect_as_polygon_give_the_same_area(subject, window):
    xmin, ymin = window.min(axis=0)
    xmax, ymax = window.max(axis=0)
    rect = Rect(xmin, ymin, xmax, ymax)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        by_rect = sutherland_hodgman(subject, rect)
        by_polygon = sutherland_hodgman(subject, rect.vertices[::-1])
    area = abs(signed_area(by_rect)) if len(by_rect) else 0.0
    other = abs(signed_area(by_polygon)) if len(by_polygon) else 0.0
    assert area == pytest.approx(other, abs=1e-9)


def test_subject_wholly_inside_comes_back_unchanged_but_without_repeats():
    inner = np.array([(3, 3), (4, 3), (4, 4), (3, 4)], dtype=float)
    np.testing.assert_array_equal(sutherland_hodgman(inner, NOTES_WINDOW), inner)
    repeated = [(3, 3), (4, 3), (4, 3), (4, 4), (3, 4), (3, 3)]
    np.testing.assert_array_equal(sutherland_hodgman(repeated, NOTES_WINDOW), inner)


def test_subject_wholly_outside_one_boundary_leaves_nothing():
    for subject in ([(0, 3), (1, 3), (1, 4)], [(3, 7), (4, 7), (4, 8)]):
        assert sutherland_hodgman(subject, NOTES_WINDOW).shape == (0, 2)
