"""Every converter through the shared rules: dtypes, shapes, untouched input, errors, out=."""

import numpy as np
import pytest

from pixelpath import color

# (function, input model, output channels)
CONVERTERS = [
    (color.rgb_to_hsv, "rgb", 3),
    (color.hsv_to_rgb, "hsv", 3),
    (color.rgb_to_hsl, "rgb", 3),
    (color.hsl_to_rgb, "hsl", 3),
    (color.rgb_to_cmy, "rgb", 3),
    (color.cmy_to_rgb, "cmy", 3),
    (color.rgb_to_cmyk, "rgb", 4),
    (color.cmyk_to_rgb, "cmyk", 3),
    (color.rgb_to_yiq, "rgb", 3),
    (color.yiq_to_rgb, "yiq", 3),
    (color.rgb_to_ycbcr, "rgb", 3),
    (color.ycbcr_to_rgb, "ycbcr", 3),
]
IDS = [fn.__name__ for fn, _, _ in CONVERTERS]
RGB_INPUT = [c for c in CONVERTERS if c[1] == "rgb"]


def sample(model, shape=(4, 5), dtype=np.float64):
    channels = color.MODELS[model]
    values = np.random.default_rng(0).random((*shape, channels))
    if model in ("hsv", "hsl"):
        values[..., 0] *= 360
    return values.astype(dtype)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
@pytest.mark.parametrize(
    ("dtype", "expected"),
    [(np.float64, np.float64), (np.float32, np.float32), (np.float16, np.float64)],
)
def test_float_dtype_policy_and_shape(fn, model, out_channels, dtype, expected):
    values = sample(model, dtype=dtype)
    result = fn(values)
    assert result.dtype == expected
    assert result.shape == (4, 5, out_channels)


@pytest.mark.parametrize(
    ("fn", "model", "out_channels"), RGB_INPUT, ids=[c[0].__name__ for c in RGB_INPUT]
)
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.int32, np.int64])
def test_integer_rgb_gives_float64_scaled(fn, model, out_channels, dtype):
    top = 65535 if dtype == np.uint16 else 255
    values = np.array([[top, top // 2, 0]], dtype=dtype)
    result = fn(values)
    assert result.dtype == np.float64
    np.testing.assert_allclose(result, fn(values / top), atol=1e-15)


def test_python_list_of_ints_is_8_bit():
    np.testing.assert_array_equal(color.rgb_to_hsv([255, 255, 0]), [60, 1, 1])
    np.testing.assert_array_equal(color.rgb_to_cmy([[255, 0, 0]]), [[0, 1, 1]])


def test_integers_of_other_models_are_taken_at_face_value():
    np.testing.assert_array_equal(color.hsv_to_rgb([120, 1, 1]), [0, 1, 0])
    np.testing.assert_array_equal(color.cmy_to_rgb([1, 1, 0]), [0, 0, 1])


@pytest.mark.parametrize("bad", [[256, 0, 0], [-1, 0, 0]])
def test_integer_rgb_outside_8_bit_is_rejected(bad):
    with pytest.raises(ValueError, match=r"0\.\.255"):
        color.rgb_to_hsv(bad)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
def test_input_is_never_modified(fn, model, out_channels):
    values = sample(model)
    before = values.copy()
    fn(values)
    np.testing.assert_array_equal(values, before)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
def test_single_colour_and_empty_and_nd(fn, model, out_channels):
    assert fn(sample(model, shape=())).shape == (out_channels,)
    assert fn(np.zeros((0, color.MODELS[model]))).shape == (0, out_channels)
    assert fn(sample(model, shape=(2, 3, 4))).shape == (2, 3, 4, out_channels)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
def test_non_contiguous_input(fn, model, out_channels):
    values = sample(model, shape=(6, 8))
    np.testing.assert_array_equal(fn(values[::2, ::3]), fn(values[::2, ::3].copy()))


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
def test_wrong_last_axis_names_argument_and_shape(fn, model, out_channels):
    wrong = np.zeros((4, 5, color.MODELS[model] + 1))
    with pytest.raises(ValueError, match=rf"{model} must have shape \(\.\.\., \d\).*\(4, 5, \d\)"):
        fn(wrong)
    with pytest.raises(ValueError, match=model):
        fn(1.0)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
@pytest.mark.parametrize(
    "bad",
    [
        np.array(["a", "b", "c", "d"][:3]),
        np.zeros(3, complex),
        np.array([1, 2, object()]),
        np.array([True, False, True]),
    ],
    ids=["strings", "complex", "object", "bool"],
)
def test_non_numeric_input_is_a_type_error(fn, model, out_channels, bad):
    if color.MODELS[model] == 4:
        bad = np.concatenate([bad, bad[:1]])
    with pytest.raises(TypeError, match=rf"{model} must hold real numbers.*dtype"):
        fn(bad)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
@pytest.mark.parametrize("bad_value", [np.nan, np.inf, -np.inf])
def test_non_finite_components_are_rejected(fn, model, out_channels, bad_value):
    values = sample(model)
    values[1, 2, 0] = bad_value
    with pytest.raises(ValueError, match=rf"{model} has 1 colour\(s\) with NaN or infinite"):
        fn(values)


def test_ragged_input_is_a_value_error():
    with pytest.raises(ValueError, match="rectangular"):
        color.rgb_to_hsv([[1, 2, 3], [1, 2]])


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
def test_out_buffer_is_filled_and_returned(fn, model, out_channels):
    values = sample(model, dtype=np.float32)
    out = np.empty((4, 5, out_channels), np.float32)
    assert fn(values, out=out) is out
    np.testing.assert_array_equal(out, fn(values))


def test_out_may_be_the_input_buffer():
    rgb = np.random.default_rng(5).random((10, 3))
    expected = color.rgb_to_hsv(rgb)
    assert color.rgb_to_hsv(rgb, out=rgb) is rgb
    np.testing.assert_array_equal(rgb, expected)


@pytest.mark.parametrize(
    "out",
    [
        np.empty((4, 5, 3), np.float32),
        np.empty((4, 5, 4)),
        np.empty((5, 4, 3))[::1].transpose(1, 0, 2),
    ],
    ids=["dtype", "shape", "layout"],
)
def test_bad_out_buffer_is_rejected(out):
    with pytest.raises(ValueError, match="out must be a C-contiguous float64 array"):
        color.rgb_to_hsv(sample("rgb"), out=out)


def test_out_must_be_an_array():
    with pytest.raises(TypeError, match="out must be a numpy array"):
        color.rgb_to_hsv([0.1, 0.2, 0.3], out=[0, 0, 0])


@pytest.mark.parametrize(("src", "dst"), [("rgb", "lab"), ("HSV", "rgb"), ("xyz", "hsv")])
def test_convert_rejects_unknown_models_listing_the_valid_ones(src, dst):
    with pytest.raises(ValueError, match=r"unknown colour model.*rgb, hsv, hsl, cmy, cmyk"):
        color.convert([0.1, 0.2, 0.3], src, dst)


def test_convert_same_model_copies_with_the_dtype_policy():
    rgb = np.array([255, 0, 128], np.uint8)
    result = color.convert(rgb, "rgb", "rgb")
    np.testing.assert_allclose(result, rgb / 255)
    cmyk = np.array([0.1, 0.2, 0.3, 0.4], np.float32)
    same = color.convert(cmyk, "cmyk", "cmyk")
    assert same.dtype == np.float32 and same is not cmyk
    np.testing.assert_array_equal(same, cmyk)


@pytest.mark.parametrize("fn", [color.rgb_to_hsv, color.rgb_to_cmyk, color.rgb_to_yiq])
def test_parallel_path_equals_the_small_input_path(fn):
    from pixelpath.color._kernels import CHUNK

    rgb = np.random.default_rng(9).random((2 * CHUNK + 3, 3))
    whole = fn(rgb)  # above one chunk: the parallel kernel
    pieces = np.concatenate([fn(rgb[k : k + 1000]) for k in range(0, len(rgb), 1000)])
    np.testing.assert_array_equal(whole, pieces)


@pytest.mark.parametrize(
    ("fn", "model", "out_channels"), RGB_INPUT, ids=[c[0].__name__ for c in RGB_INPUT]
)
@pytest.mark.parametrize("int_dtype", [np.uint8, np.uint16, np.int64])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_integer_rgb_converts_straight_into_the_requested_dtype(
    fn, model, out_channels, int_dtype, dtype
):
    top = 65535 if int_dtype == np.uint16 else 255
    values = np.random.default_rng(3).integers(0, top + 1, (50, 3)).astype(int_dtype)
    result = fn(values, dtype=dtype)
    assert result.dtype == dtype and result.shape == (50, out_channels)
    # The float32 path scales and converts in float32: equal to float32 rounding of the exact.
    exact = fn(values / top)
    tolerance = 2e-5 if dtype == np.float32 else 1e-12
    np.testing.assert_allclose(result, exact, rtol=tolerance, atol=tolerance * 360)


@pytest.mark.parametrize(("fn", "model", "out_channels"), CONVERTERS, ids=IDS)
@pytest.mark.parametrize(
    ("given", "requested"), [(np.float64, np.float32), (np.float32, np.float64)]
)
def test_float_input_of_the_other_precision_is_cast_first(
    fn, model, out_channels, given, requested
):
    values = sample(model, dtype=given)
    result = fn(values, dtype=requested)
    assert result.dtype == requested
    np.testing.assert_array_equal(result, fn(values.astype(requested)))


def test_integers_of_other_models_go_straight_into_the_requested_dtype():
    green = color.hsv_to_rgb(np.array([120, 1, 1], np.int16), dtype="float32")
    assert green.dtype == np.float32
    np.testing.assert_array_equal(green, [0, 1, 0])


@pytest.mark.parametrize("spelling", ["float32", np.float32, np.dtype("float32"), "f4"])
def test_dtype_may_be_spelled_any_numpy_way(spelling):
    assert color.rgb_to_yiq(np.zeros((2, 3), np.uint8), dtype=spelling).dtype == np.float32


@pytest.mark.parametrize(
    ("dtype", "error", "match"),
    [
        (np.int16, ValueError, "dtype must be float32 or float64, got int16"),
        ("float16", ValueError, "dtype must be float32 or float64, got float16"),
        ("colour", TypeError, "dtype must be float32 or float64, got 'colour'"),
    ],
)
def test_other_dtypes_are_rejected_naming_the_argument(dtype, error, match):
    with pytest.raises(error, match=match):
        color.rgb_to_hsv([1.0, 0.5, 0.0], dtype=dtype)
    with pytest.raises(error, match=match):
        color.convert([1.0, 0.5, 0.0], "rgb", "cmyk", dtype=dtype)


def test_out_must_match_the_requested_dtype():
    values = np.zeros((4, 3), np.uint8)
    out = np.empty((4, 3), np.float32)
    assert color.rgb_to_hsl(values, dtype="float32", out=out) is out
    with pytest.raises(ValueError, match="out must be a C-contiguous float64 array"):
        color.rgb_to_hsl(values, out=out)


@pytest.mark.parametrize(
    ("src", "dst"), [("rgb", "rgb"), ("rgb", "hsv"), ("cmyk", "rgb"), ("hsl", "ycbcr")]
)
def test_convert_honours_dtype_for_every_route(src, dst):
    values = (sample(src) * 255).astype(np.uint8) if src == "rgb" else sample(src)
    result = color.convert(values, src, dst, dtype="float32")
    assert result.dtype == np.float32
    np.testing.assert_allclose(result, color.convert(values, src, dst), rtol=2e-5, atol=1e-4)


def test_uint8_to_float32_allocates_only_the_float32_result():
    import tracemalloc

    image = np.random.default_rng(4).integers(0, 256, (256, 256, 3), dtype=np.uint8)
    color.rgb_to_hsv(image, dtype="float32")  # compile outside the measurement
    tracemalloc.start()
    try:
        result = color.rgb_to_hsv(image, dtype="float32")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert result.dtype == np.float32
    assert peak < 1.1 * result.nbytes  # no float64 or float32 copy of the input on the way
