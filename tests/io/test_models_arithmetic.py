"""The model loader's written-out arithmetic gives the bits of the NumPy expressions it replaces."""

from __future__ import annotations

import numpy as np
from hypothesis import example, given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from pixelpath.io.models import _base_color, _center, _local_matrix

finite = st.floats(-1e150, 1e150, allow_nan=False, allow_infinity=False, allow_subnormal=True)
any_float = st.floats(allow_nan=True, allow_infinity=True)


def numpys_base_color(factor):
    """The colour and alpha as the loader took them from the factor before (the reference)."""
    rgba = np.ones(4) if factor is None else np.asarray(factor, dtype=np.float64)
    if rgba.max() > 1.0 or np.asarray(factor).dtype.kind in "ui":
        rgba = rgba / 255.0
    return np.clip(rgba[:3], 0.0, 1.0), rgba[3]


def assert_same_bits(actual, expected):
    np.testing.assert_array_equal(actual, expected)
    np.testing.assert_array_equal(np.signbit(actual), np.signbit(expected))


@given(hnp.arrays(np.float64, (2, 3), elements=finite))
@example(np.full((2, 3), -0.0))  # NumPy's sum starts from +0.0: the centre is +0.0
@example(np.array([[-0.0, 0.0, -0.0], [0.0, -0.0, -1.0]]))
def test_center_is_numpys_mean_of_the_corners(bounds):
    assert_same_bits(_center(bounds), bounds.mean(axis=0))


@given(st.one_of(
    st.none(),
    hnp.arrays(np.uint8, 4),  # as trimesh keeps it
    hnp.arrays(np.float64, 4, elements=any_float),
    hnp.arrays(np.int64, 4, elements=st.integers(-1000, 1000)),
))
def test_base_color_is_the_former_clip_of_the_factor(factor):
    rgba = _base_color(factor)
    color, alpha = numpys_base_color(factor)
    assert_same_bits(rgba[:3], color)
    assert_same_bits(rgba[3], alpha)


def test_a_node_without_translation_rotation_or_scale_is_trimeshs_identity_product():
    import trimesh.transformations as tf

    product = (tf.translation_matrix((0.0, 0.0, 0.0)) @ tf.quaternion_matrix((1.0, 0.0, 0.0, 0.0))
               @ np.diag([1.0, 1.0, 1.0, 1.0]))
    for node in ({}, {"mesh": 0}, {"children": [1], "name": "a"}):
        assert_same_bits(_local_matrix(node), product)
