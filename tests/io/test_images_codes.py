"""to_uint8's compiled float32 paths give the bytes of the general path, for every encoding."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from pixelpath.io import images
from pixelpath.io.images import to_uint8

ONE = int(np.float32(1.0).view(np.int32))
GAMMAS = (None, "linear", "srgb", 2.2, 1.0, 0.5, 2, 1.8, 0.4)


def _reference(values: np.ndarray, gamma) -> np.ndarray:
    """The straightforward computation, in float64 (NaN → 0, as NumPy's cast gives on x86)."""
    values = np.clip(np.asarray(values, np.float64), 0.0, 1.0)
    if gamma == "srgb":
        from pixelpath.scene.texture import linear_to_srgb

        values = linear_to_srgb(values)
    elif gamma not in (None, "linear"):
        values = values ** (1.0 / gamma)
    with np.errstate(invalid="ignore"):
        return np.rint(values * 255.0).astype(np.uint8)


def _edges() -> np.ndarray:
    """0, 1, -0.0, infinities, tiny values, and the floats around every k + 0.5 of 255·x."""
    odd = [0.0, 1.0, -0.0, 2.0, -1.0, np.inf, -np.inf, 1e-40, -1e-40, 1e-45, 0.9999999]
    halves = ((np.arange(256) + 0.5) / 255).astype(np.float32).view(np.int32)
    near = (halves[:, None] + np.arange(-3, 4)).ravel().astype(np.int32).view(np.float32)
    return np.concatenate([np.array(odd, np.float32), near])


def _spread() -> np.ndarray:
    """Every 97th float32 of [0, 1] (about 11 million values)."""
    return np.arange(0, ONE + 1, 97, dtype=np.int64).astype(np.int32).view(np.float32)


@pytest.mark.parametrize("gamma", GAMMAS)
def test_edge_values_and_a_spread_of_all_float32_match_the_reference(gamma):
    for values in (_edges(), _spread()):
        assert np.array_equal(to_uint8(values, gamma), _reference(values, gamma))


def test_the_linear_path_is_rint_of_the_clipped_value_times_255():
    values = _edges()
    expected = np.rint(np.clip(values.astype(np.float64), 0, 1) * 255).astype(np.uint8)
    assert np.array_equal(to_uint8(values), expected)
    assert to_uint8(np.array([0.5 / 255, 1.5 / 255, 2.5 / 255])).tolist() == [0, 2, 2]  # ties


def test_nan_gives_what_the_earlier_paths_gave():
    nan = np.array([np.nan, -np.nan], np.float32)
    for gamma in (None, 2.2):
        assert to_uint8(nan, gamma).tolist() == [0, 0]
    assert to_uint8(nan, "srgb").tolist() == [255, 0]  # the sRGB table's NaNs, by their bits


@given(
    arrays(np.float32, st.integers(1, 300), elements=st.floats(-0.5, 1.5, width=32)),
    st.sampled_from(GAMMAS),
)
def test_random_pictures(values, gamma):
    assert np.array_equal(to_uint8(values, gamma), _reference(values, gamma))


def test_pictures_keep_their_shape_and_strided_views_work():
    rgb = np.random.default_rng(3).random((5, 7, 3), dtype=np.float32)
    for picture in (rgb, rgb[:, ::2], rgb.transpose(1, 0, 2)):
        for gamma in (None, "srgb", 2.2):
            codes = to_uint8(picture, gamma)
            assert codes.shape == picture.shape and codes.dtype == np.uint8
            assert np.array_equal(codes, _reference(picture, gamma))


def test_a_gamma_whose_steps_crowd_takes_the_general_path():
    assert images.code_table(0.02) is None
    values = _edges()
    assert np.array_equal(to_uint8(values, 0.02), _reference(values, 0.02))


@pytest.mark.parametrize("gamma", [0, -1.0, "sRGBX", float("nan")])
def test_bad_gammas_are_refused(gamma):
    with pytest.raises(ValueError, match="gamma must be"):
        to_uint8(np.zeros(3, np.float32), gamma)


@pytest.mark.parametrize("gamma", [None, "srgb", 2.2])
def test_the_kernels_called_directly_agree(gamma):
    # also as plain Python under NUMBA_DISABLE_JIT=1, where to_uint8 takes NumPy's path
    from pixelpath.io import _kernels

    values = _edges()
    out = np.empty(values.shape, np.uint8)
    if gamma is None:
        _kernels.linear_codes(values, out)
    else:
        _kernels.table_codes(values.view(np.int32), *images.code_table(gamma), out)
    assert np.array_equal(out, _reference(values, gamma))
