"""8-bit sRGB encoding of float32 pictures through the step table equals the general path."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from pixelpath.io import images
from pixelpath.io.images import to_uint8


def _general(values: np.ndarray) -> np.ndarray:
    """The float64 path of to_uint8 (what any non-float32 input takes)."""
    return to_uint8(values.astype(np.float64), "srgb")


def test_every_step_of_the_code_and_its_neighbours():
    _, step, _ = images.code_table("srgb")
    steps = step[step <= 0x3F800000].astype(np.int64)
    assert len(steps) == 255  # every code from 1 to 255 starts inside a bucket
    near = (steps[:, None] + np.arange(-4, 5)).ravel().astype(np.int32).view(np.float32)
    assert np.array_equal(to_uint8(near, "srgb"), _general(near))


def test_a_spread_of_all_float32_in_0_1_and_out_of_range_values():
    one = int(np.float32(1.0).view(np.int32))
    spread = np.arange(0, one + 1, 89, dtype=np.int64).astype(np.int32).view(np.float32)
    assert np.array_equal(to_uint8(spread, "srgb"), _general(spread))
    odd = np.array([-1.0, -0.0, 1.0, 1.5, np.inf, -np.inf, 1e-40], np.float32)
    assert to_uint8(odd, "srgb").tolist() == [0, 0, 255, 255, 255, 0, 0]


@given(arrays(np.float32, st.integers(1, 200), elements=st.floats(-0.5, 1.5, width=32)))
def test_random_pictures(values):
    assert np.array_equal(to_uint8(values, "srgb"), _general(values))
