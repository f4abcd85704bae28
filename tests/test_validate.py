"""The vector helpers that replace slow NumPy calls give NumPy's own bits."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from pixelpath._validate import (
    all_finite,
    cross3,
    float_array,
    row_lengths,
    unit_rows,
    vector_length,
)
from pixelpath.scene.mesh import bounding_box, moved

finite = st.floats(-1e150, 1e150, allow_nan=False, allow_infinity=False, allow_subnormal=True)
vectors = hnp.arrays(np.float64, st.tuples(st.integers(1, 40), st.just(3)), elements=finite)
vector = hnp.arrays(np.float64, 3, elements=finite)
# rows near length 1 (kept as they are) and zero rows (left zero) beside any others
near_unit = st.floats(0.57735026918962, 0.57735026918963)
rows = st.one_of(
    st.tuples(finite, finite, finite),
    st.tuples(near_unit, near_unit, near_unit),
    st.just((0.0, 0.0, 0.0)),
    st.just((-0.0, 1.0, 0.0)),
)
any_floats = st.floats(allow_nan=True, allow_infinity=True)


def numpys_unit_rows(points):
    """unit_rows as it was written with NumPy's broadcasting (the reference for its bits)."""
    lengths = np.linalg.norm(points, axis=-1, keepdims=True)
    unit = np.abs(lengths - 1.0) <= 4.0 * np.finfo(np.float64).eps
    return np.where(unit, points, points / np.where(lengths == 0.0, 1.0, lengths))


@given(vectors)
def test_row_lengths_are_numpys_norms_bit_for_bit(points):
    expected = np.linalg.norm(points, axis=-1, keepdims=True)
    np.testing.assert_array_equal(row_lengths(points), expected)
    np.testing.assert_array_equal(row_lengths(points[0]), expected[0])


@given(vector, vector)
def test_cross3_is_numpys_cross_bit_for_bit(a, b):
    np.testing.assert_array_equal(cross3(a, b), np.cross(a, b))


@given(vectors, vector)
def test_cross3_of_rows_is_numpys_cross_bit_for_bit(rows_, b):
    np.testing.assert_array_equal(cross3(rows_, b), np.cross(rows_, b))
    np.testing.assert_array_equal(cross3(b, rows_), np.cross(b, rows_))
    np.testing.assert_array_equal(cross3(rows_, rows_[::-1]), np.cross(rows_, rows_[::-1]))


@given(vectors)
def test_unit_rows_have_unit_length_and_keep_unit_rows_as_they_are(points):
    points = points[np.linalg.norm(points, axis=1) > 1e-100]
    unit = unit_rows(points)
    np.testing.assert_allclose(np.linalg.norm(unit, axis=1), 1.0, rtol=1e-12)
    again = unit_rows(unit)
    np.testing.assert_array_equal(again, unit)
    assert not np.shares_memory(again, unit)  # a copy, which callers may freeze or write


@given(st.lists(rows, min_size=1, max_size=40))
def test_unit_rows_are_numpys_broadcast_division_bit_for_bit(listed):
    points = np.array(listed, dtype=np.float64)
    expected = numpys_unit_rows(points)
    np.testing.assert_array_equal(unit_rows(points), expected)
    np.testing.assert_array_equal(unit_rows(points, row_lengths(points)), expected)
    np.testing.assert_array_equal(unit_rows(points[0]), expected[0])
    # the same signs of zero, which assert_array_equal does not tell apart
    np.testing.assert_array_equal(np.signbit(unit_rows(points)), np.signbit(expected))
    np.testing.assert_array_equal(np.signbit(unit_rows(points[0])), np.signbit(expected[0]))


@given(hnp.arrays(np.float64, hnp.array_shapes(min_dims=0, max_dims=3, max_side=6),
                  elements=any_floats))
def test_all_finite_is_numpys_isfinite_all(array):
    assert all_finite(array) == bool(np.isfinite(array).all())


@given(vectors)
def test_vector_length_is_numpys_norm_bit_for_bit(points):
    for vector in (points[0], points[:, 1], points.ravel()):  # contiguous, strided, longer
        assert vector_length(vector) == float(np.linalg.norm(vector))


@given(vectors, hnp.arrays(np.float64, (3, 3), elements=finite), vector)
def test_moved_points_are_the_matrix_product_plus_the_shift_bit_for_bit(points, linear, shift):
    expected = points @ linear.T + shift
    np.testing.assert_array_equal(moved(points, linear, shift), expected)
    np.testing.assert_array_equal(np.signbit(moved(points, linear, shift)), np.signbit(expected))


@given(vectors)
def test_bounding_box_is_the_columns_minimum_and_maximum(points):
    np.testing.assert_array_equal(bounding_box(points), [points.min(axis=0), points.max(axis=0)])


def test_row_lengths_sum_the_squares_in_numpys_order():
    # (x² + y²) + z² and x² + (y² + z²) differ in the last bit here: NumPy's order is the first.
    rng = np.random.default_rng(7)
    points = rng.standard_normal((100_000, 3))
    other_order = np.sqrt(points[:, 0] ** 2 + (points[:, 1] ** 2 + points[:, 2] ** 2))[:, None]
    assert (other_order != np.linalg.norm(points, axis=-1, keepdims=True)).any()
    np.testing.assert_array_equal(row_lengths(points), np.linalg.norm(points, axis=-1,
                                                                      keepdims=True))


def test_float_array_copies_unless_told_not_to_and_checks_either_way():
    values = np.array([[1.0, 2.0, 3.0]])
    assert float_array(values, "x", (None, 3), copy=False) is values
    assert not np.shares_memory(float_array(values, "x", (None, 3)), values)
    assert float_array([[1, 2, 3]], "x", (None, 3), copy=False).dtype == np.float64
    values[0, 1] = np.nan
    with pytest.raises(ValueError, match="x must be finite, got nan at index"):
        float_array(values, "x", (None, 3), copy=False)
