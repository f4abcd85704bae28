"""The vector helpers that replace slow NumPy calls give NumPy's own bits."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from pixelpath._validate import cross3, row_lengths, unit_rows
from pixelpath.scene.mesh import bounding_box

finite = st.floats(-1e150, 1e150, allow_nan=False, allow_infinity=False, allow_subnormal=True)
vectors = hnp.arrays(np.float64, st.tuples(st.integers(1, 40), st.just(3)), elements=finite)
vector = hnp.arrays(np.float64, 3, elements=finite)


@given(vectors)
def test_row_lengths_are_numpys_norms_bit_for_bit(points):
    expected = np.linalg.norm(points, axis=-1, keepdims=True)
    np.testing.assert_array_equal(row_lengths(points), expected)
    np.testing.assert_array_equal(row_lengths(points[0]), expected[0])


@given(vector, vector)
def test_cross3_is_numpys_cross_bit_for_bit(a, b):
    np.testing.assert_array_equal(cross3(a, b), np.cross(a, b))


@given(vectors)
def test_unit_rows_have_unit_length_and_keep_unit_rows_as_they_are(points):
    points = points[np.linalg.norm(points, axis=1) > 1e-100]
    unit = unit_rows(points)
    np.testing.assert_allclose(np.linalg.norm(unit, axis=1), 1.0, rtol=1e-12)
    np.testing.assert_array_equal(unit_rows(unit), unit)


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
