"""Batch clipping: identical to one-by-one Sutherland-Hodgman, and its input checks."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from clip_strategies import convex_polygons, star_polygons
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.clip import (
    Rect,
    ZeroWidthBridgeWarning,
    clip_flat,
    clip_polygons,
    sutherland_hodgman,
)
from pixelpath.clip.batch import _LEAST_POLYGONS, _clip_batch

WINDOW = Rect(-0.5, -0.4, 0.6, 0.5)


def one_by_one(polygons, window):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        return [sutherland_hodgman(p, window) for p in polygons]


@given(polygons=st.lists(star_polygons(max_vertices=16), min_size=1, max_size=12))
@settings(max_examples=25, deadline=None)
def test_batch_equals_one_by_one_against_a_rect(polygons):
    results = clip_polygons(polygons, WINDOW)
    for got, expected in zip(results, one_by_one(polygons, WINDOW), strict=True):
        np.testing.assert_array_equal(got, expected)


@given(
    polygons=st.lists(star_polygons(max_vertices=16), min_size=1, max_size=8),
    window=convex_polygons(),
)
@settings(max_examples=20, deadline=None)
def test_batch_equals_one_by_one_against_a_convex_polygon(polygons, window):
    results = clip_polygons(polygons, window)
    for got, expected in zip(results, one_by_one(polygons, window), strict=True):
        np.testing.assert_array_equal(got, expected)


def test_results_too_big_for_their_staging_slot_are_clipped_again():
    rng = np.random.default_rng(7)
    polygons = [rng.uniform(-1, 1, (n, 2)) for n in (3, 9, 30)]
    coords = np.concatenate(polygons)
    offsets = np.array([0, 3, 12, 42])
    # slot_scale=0 gives every polygon an empty staging slot: all are clipped again in pass 3.
    out, out_offsets = _clip_batch(coords, offsets, WINDOW.table, slot_scale=0)
    for i, expected in enumerate(one_by_one(polygons, WINDOW)):
        np.testing.assert_array_equal(out[out_offsets[i] : out_offsets[i + 1]], expected)


def test_a_batch_big_enough_for_the_threads_equals_one_by_one():
    rng = np.random.default_rng(11)
    sizes = rng.integers(3, 12, 1500)
    assert len(sizes) >= 2 * _LEAST_POLYGONS  # handed out in runs to the threads
    polygons = [c + rng.uniform(-0.3, 0.3, (n, 2)) for n, c in
                zip(sizes, rng.uniform(-1, 1, (len(sizes), 2)), strict=True)]
    results = clip_polygons(polygons, WINDOW)
    fates = {"empty": 0, "clipped": 0, "unchanged": 0}
    for polygon, got, expected in zip(polygons, results, one_by_one(polygons, WINDOW),
                                      strict=True):
        np.testing.assert_array_equal(got, expected)
        kind = ("empty" if len(got) == 0 else "unchanged"
                if got.shape == polygon.shape and np.array_equal(got, polygon) else "clipped")
        fates[kind] += 1
    assert min(fates.values()) > 50  # every pass had work to do


def test_flat_interface_keeps_empty_results_in_the_offsets():
    coords = np.array([[1, 1], [9, 1], [9, 7], [1, 7], [20, 20], [21, 20], [20, 21.0]])
    out, offsets = clip_flat(coords, [0, 4, 7], Rect(2, 2, 8, 6))
    assert offsets.tolist() == [0, 4, 4]
    assert out.tolist() == [[2, 6], [2, 2], [8, 2], [8, 6]]


def test_empty_batch():
    assert clip_polygons([], WINDOW) == []
    out, offsets = clip_flat(np.zeros((0, 2)), [0], WINDOW)
    assert out.shape == (0, 2) and offsets.tolist() == [0]


def test_lists_of_tuples_and_integer_arrays_are_accepted():
    square = [(1, 1), (9, 1), (9, 7), (1, 7)]
    results = clip_polygons([square, np.array(square, dtype=np.int32)], Rect(2, 2, 8, 6))
    assert [r.tolist() for r in results] == [[[2, 6], [2, 2], [8, 2], [8, 6]]] * 2


@pytest.mark.parametrize(
    ("bad", "error", "match"),
    [
        ([(0, 0), (1, 1), (0, 0)], ValueError, "polygon 1 needs at least 3 distinct"),
        ([(0, 0), (1, 0), (np.nan, 1)], ValueError, "polygon 1 has a NaN or infinite"),
        ([(0, 0, 0), (1, 0, 0), (1, 1, 0)], ValueError, r"polygons\[1\] must have shape"),
        ([(0, 0), (1, 0)], ValueError, "polygon 1 needs at least 3 distinct"),
        ([("a", "b"), ("c", "d"), ("e", "f")], TypeError, r"polygons\[1\]"),
    ],
)
def test_bad_polygons_are_named_by_index(bad, error, match):
    good = [(0, 0), (1, 0), (0, 1)]
    with pytest.raises(error, match=match):
        clip_polygons([good, bad, good], WINDOW)


@pytest.mark.parametrize(
    ("offsets", "error", "match"),
    [
        ([0, 2, 1, 3], ValueError, "rise from 0"),
        ([1, 3], ValueError, "rise from 0"),
        ([0, 4], ValueError, "rise from 0"),
        ([], ValueError, "shape"),
        ([0.0, 3.0], TypeError, "integers"),
    ],
)
def test_bad_offsets_are_rejected(offsets, error, match):
    with pytest.raises(error, match=match):
        clip_flat(np.array([(0, 0), (1, 0), (0, 1.0)]), offsets, WINDOW)


def test_inside_outside_crossing_and_repeated_vertices_match_one_by_one():
    polygons = [
        [(0, 0), (0.1, 0), (0.1, 0.1)],  # inside
        [(0, 0), (0.1, 0), (0.1, 0), (0.1, 0.1), (0, 0)],  # inside, with repeats
        [(2, 2), (3, 2), (3, 3)],  # outside
        [(-1, -1), (1, -1), (1, 1), (-1, 1)],  # covers the window
        [(0.5, 0), (0.7, 0), (0.7, 0.1), (0.7, 0.1)],  # a triangle cut by x = 0.6, repeats
    ]
    results = clip_polygons(polygons, WINDOW)
    for got, expected in zip(results, one_by_one(polygons, WINDOW), strict=True):
        np.testing.assert_array_equal(got, expected)
    assert [len(r) for r in results] == [3, 3, 0, 4, 3]
