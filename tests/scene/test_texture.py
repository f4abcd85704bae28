"""Textures: sRGB decoding, the mip pyramid, inputs and errors, and the sampling kernel.

The sampling kernel is checked against a NumPy reference written here from the documented
conventions (texel (col, row) centred at u = (col + 0.5) / W, v = 1 - (row + 0.5) / H; the
wrap modes built by tiling the index sequence), and against hand-derived values.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image as PILImage

from pixelpath.scene import Material, Mesh
from pixelpath.scene import _texture_kernels as tk
from pixelpath.scene.texture import (
    MAX_SIDE,
    Texture,
    _decoded,
    _half,
    linear_to_srgb,
    needs_lookups,
    srgb_to_linear,
    surface_tables,
)

QUAD = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
QUAD_UV = [[0, 0], [1, 0], [1, 1], [0, 1]]


# --- sRGB ----------------------------------------------------------------------------------


def test_srgb_decode_of_known_codes():
    # IEC 61966-2-1: linear segment below 0.04045, power 2.4 above.
    codes = np.array([0, 10, 11, 128, 188, 255]) / 255.0
    expected = [
        0.0,
        (10 / 255) / 12.92,
        ((11 / 255 + 0.055) / 1.055) ** 2.4,
        ((128 / 255 + 0.055) / 1.055) ** 2.4,  # ~0.2158
        ((188 / 255 + 0.055) / 1.055) ** 2.4,  # ~0.5029
        1.0,
    ]
    assert srgb_to_linear(codes) == pytest.approx(expected, rel=1e-12)
    assert srgb_to_linear(128 / 255) == pytest.approx(0.21586, abs=1e-5)
    assert linear_to_srgb(0.5) * 255 == pytest.approx(187.5, abs=0.1)  # 0.5 encodes to 188
    grid = np.linspace(0, 1, 1001)
    assert linear_to_srgb(srgb_to_linear(grid)) == pytest.approx(grid, abs=1e-12)


def test_uint8_texture_is_decoded_float_texture_is_linear():
    codes = np.array([[[0, 128, 255], [64, 188, 10]]], dtype=np.uint8)
    eight = Texture(codes)
    assert eight.srgb is True
    assert eight.linear()[..., :3] == pytest.approx(srgb_to_linear(codes / 255.0), abs=1e-12)
    assert np.all(eight.linear()[..., 3] == 1.0)
    floats = np.array([[[0.0, 0.25, 1.0], [0.5, 0.75, 0.125]]])
    linear = Texture(floats)
    assert linear.srgb is False
    # Stored as 8-bit sRGB codes: the round trip is within half a code step.
    stored = linear.linear()[..., :3]
    step = srgb_to_linear(np.minimum(linear_to_srgb(floats) + 1 / 255, 1)) - floats
    assert np.all(np.abs(stored - floats) <= step / 2 + 1e-12)
    # srgb= overrides the guess either way.
    assert Texture(codes, srgb=False).linear()[0, 0, 1] == pytest.approx(128 / 255, abs=3e-3)
    # (sRGB floats are stored as the nearest 8-bit code: 0.25 -> 64.)
    assert Texture(floats, srgb=True).linear()[0, 0, 1] == pytest.approx(
        srgb_to_linear(64 / 255), abs=1e-12
    )


# --- the pyramid ---------------------------------------------------------------------------


def numpy_half(linear: np.ndarray) -> np.ndarray:
    """2 x 2 averages, an odd side repeating its last row/column (written independently)."""
    h, w = linear.shape[:2]
    out_h, out_w = max(1, (h + 1) // 2), max(1, (w + 1) // 2)
    out = np.zeros((out_h, out_w, linear.shape[2]))
    for r in range(out_h):
        for c in range(out_w):
            rows = [min(2 * r, h - 1), min(2 * r + 1, h - 1)] if h > 1 else [0]
            cols = [min(2 * c, w - 1), min(2 * c + 1, w - 1)] if w > 1 else [0]
            out[r, c] = np.mean([linear[i, j] for i in rows for j in cols], axis=0)
    return out


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 9), st.integers(1, 9), st.integers(0, 2**32 - 1))
def test_halving_keeps_the_bits_of_numpys_block_mean(height, width, seed):
    # Each level is made by adding a block's texels by slices; the sum must be NumPy's own
    # (same order, same bits), so that the pyramid did not change when it became faster.
    codes = np.random.default_rng(seed).integers(0, 256, (height, width, 4), dtype=np.uint8)
    linear = _decoded(codes)
    padded = np.concatenate([linear, linear[-1:]], 0) if height > 1 and height % 2 else linear
    if width > 1 and width % 2:
        padded = np.concatenate([padded, padded[:, -1:]], 1)
    rows, cols = min(padded.shape[0], 2), min(padded.shape[1], 2)
    h, w = padded.shape[0] // rows, padded.shape[1] // cols
    expected = padded.reshape(h, rows, w, cols, 4).mean(axis=(1, 3))
    assert np.array_equal(_half(linear), expected)
    # Decoding the codes quarter by quarter gives the same as decoding them first.
    assert np.array_equal(_half(codes, _decoded), expected)


@settings(max_examples=30, deadline=None)
@given(st.integers(1, 40), st.integers(1, 40), st.integers(0, 2**32 - 1))
def test_every_level_is_the_encoded_block_mean_of_the_exact_level_above(height, width, seed):
    # The whole pyramid, byte for byte, against a chain written plainly: decode the base,
    # then take NumPy's block mean of the unrounded level above (an odd side padded with its
    # last row or column) and encode each level with the sRGB formula.
    codes = np.random.default_rng(seed).integers(0, 256, (height, width, 4), dtype=np.uint8)
    linear = _decoded(codes)
    expected = []
    while linear.shape[0] > 1 or linear.shape[1] > 1:
        h, w = linear.shape[:2]
        linear = np.pad(linear, ((0, h % 2 if h > 1 else 0), (0, w % 2 if w > 1 else 0), (0, 0)),
                        mode="edge")
        rows, cols = min(linear.shape[0], 2), min(linear.shape[1], 2)
        linear = linear.reshape(linear.shape[0] // rows, rows, linear.shape[1] // cols, cols,
                                4).mean(axis=(1, 3))
        level = np.empty(linear.shape, dtype=np.uint8)
        level[..., :3] = np.rint(piecewise_srgb(np.clip(linear[..., :3], 0, 1)) * 255)
        level[..., 3] = np.rint(np.clip(linear[..., 3], 0, 1) * 255)
        expected.append(level)
    levels = Texture(codes).levels
    assert len(levels) == len(expected) + 1
    for got, want in zip(levels[1:], expected, strict=True):
        assert np.array_equal(got, want)


def piecewise_srgb(x: np.ndarray) -> np.ndarray:
    """The sRGB encoding as IEC 61966-2-1 writes it, one expression."""
    return np.where(x <= 0.0031308, x * 12.92, 1.055 * x ** (1.0 / 2.4) - 0.055)


def test_srgb_encoding_is_the_piecewise_formula_bit_for_bit():
    rng = np.random.default_rng(7)
    values = np.concatenate([rng.random(100_000), rng.random(1000) * 0.004,  # the dark segment
                             [0.0, 0.0031308, np.nextafter(0.0031308, 1.0), 1.0]])
    assert np.array_equal(linear_to_srgb(values), piecewise_srgb(values))
    # out of range values are clipped first; NaN stays NaN; scalars give 0-d arrays
    assert np.array_equal(linear_to_srgb([-0.5, 1.5]), piecewise_srgb(np.array([0.0, 1.0])))
    assert np.isnan(linear_to_srgb(np.nan))
    assert linear_to_srgb(0.001).shape == () and linear_to_srgb(0.001) == 0.001 * 12.92


def test_level_sizes_for_odd_sides():
    texture = Texture(np.zeros((7, 5, 3), dtype=np.uint8))
    shapes = [level.shape for level in texture.levels]
    assert shapes == [(7, 5, 4), (4, 3, 4), (2, 2, 4), (1, 1, 4)]
    assert [level.dtype for level in texture.levels] == [np.uint8] * 4
    strip = Texture(np.zeros((1, 6, 3)))
    assert [level.shape[:2] for level in strip.levels] == [(1, 6), (1, 3), (1, 2), (1, 1)]


def test_levels_average_in_linear_light():
    rng = np.random.default_rng(3)
    codes = rng.integers(0, 256, (7, 5, 4), dtype=np.uint8)
    texture = Texture(codes)
    expected = texture.linear(0)
    for k in range(1, len(texture.levels)):
        # Each level averages the exact (unrounded) linear values of the one above.
        expected = numpy_half(expected)
        got = texture.linear(k)
        # Each level is stored as 8-bit sRGB: within half a code of the exact average.
        assert np.allclose(got[..., 3], expected[..., 3], atol=0.5 / 255 + 1e-12)
        encoded = linear_to_srgb(expected[..., :3]) * 255
        assert np.all(np.abs(texture.levels[k][..., :3] - encoded) <= 0.5 + 1e-9)
    # Black and white average to linear 0.5 (sRGB code 188), not to code 128.
    stripes = Texture(np.array([[[0, 0, 0], [255, 255, 255]]], dtype=np.uint8))
    assert stripes.levels[1][0, 0, :3].tolist() == [188, 188, 188]
    assert stripes.linear(1)[0, 0, 0] == pytest.approx(0.5, abs=3e-3)


@pytest.mark.parametrize("channels", [3, 4])
def test_array_inputs(channels):
    rng = np.random.default_rng(channels)
    codes = rng.integers(0, 256, (3, 4, channels), dtype=np.uint8)
    by_uint8 = Texture(codes)
    assert (by_uint8.width, by_uint8.height) == (4, 3)
    assert np.array_equal(by_uint8.levels[0][..., :channels], codes)
    if channels == 3:
        assert np.all(by_uint8.levels[0][..., 3] == 255)
    # uint16 is scaled by 1/65535 and taken as linear.
    wide = (codes.astype(np.uint32) * 257).astype(np.uint16)
    by_uint16 = Texture(wide)
    assert by_uint16.srgb is False
    assert np.allclose(by_uint16.linear()[..., :3], Texture(codes / 255.0).linear()[..., :3])
    # A float array of the same codes with srgb=True is the uint8 texture.
    assert Texture(codes / 255.0, srgb=True) == by_uint8
    # A nested list works as an array.
    assert Texture((codes / 255.0).tolist(), srgb=True) == by_uint8


def test_pil_and_path_inputs(tmp_path):
    rng = np.random.default_rng(5)
    codes = rng.integers(0, 256, (5, 6, 3), dtype=np.uint8)
    picture = PILImage.fromarray(codes)
    path = tmp_path / "picture.png"
    picture.save(path)
    from_pil = Texture(picture)
    from_path = Texture(path)
    from_str = Texture(str(path))
    assert from_pil == Texture(codes) == from_path == from_str
    assert from_path.name == "picture.png" and from_path.srgb is True
    assert np.all(from_path.linear()[..., 3] == 1.0)
    # Greyscale and RGBA pictures.
    grey = PILImage.fromarray(codes[..., 0])
    assert np.array_equal(Texture(grey).levels[0][..., 0], codes[..., 0])
    assert np.array_equal(Texture(grey).levels[0][..., 2], codes[..., 0])
    rgba = np.dstack([codes, np.full((5, 6), 77, np.uint8)])
    assert np.all(Texture(PILImage.fromarray(rgba, "RGBA")).linear()[..., 3] == 77 / 255)


@pytest.mark.parametrize(
    ("image", "error", "match"),
    [
        (np.zeros((4, 4)), ValueError, "shape"),
        (np.zeros((4, 4, 2)), ValueError, "shape"),
        (np.zeros((4, 4, 5)), ValueError, "shape"),
        (np.zeros((0, 4, 3)), ValueError, "shape"),
        (np.full((2, 2, 3), np.nan), ValueError, "finite"),
        (np.full((2, 2, 3), np.inf), ValueError, "finite"),
        (np.full((2, 2, 3), 1.5), ValueError, r"\[0, 1\]"),
        (np.full((2, 2, 3), -0.1), ValueError, r"\[0, 1\]"),
        (np.zeros((2, 2, 3), dtype=bool), TypeError, "bool"),
        (np.full((2, 2, 3), "a"), TypeError, "dtype"),
    ],
)
def test_bad_arrays(image, error, match):
    with pytest.raises(error, match=match):
        Texture(image)


def test_bad_files(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"missing\.png"):
        Texture(tmp_path / "missing.png")
    corrupt = tmp_path / "corrupt.png"
    corrupt.write_bytes(b"\x89PNG\r\n\x1a\n" + b"garbage" * 20)
    with pytest.raises(ValueError, match=r"corrupt\.png"):
        Texture(corrupt)
    text = tmp_path / "notes.jpg"
    text.write_text("not a picture")
    with pytest.raises(ValueError, match=r"notes\.jpg"):
        Texture(text)
    # A truncated PNG: the header reads, the pixels do not.
    good = tmp_path / "good.png"
    PILImage.fromarray(np.random.default_rng(0).integers(0, 256, (64, 64, 3), np.uint8)).save(good)
    truncated = tmp_path / "truncated.png"
    truncated.write_bytes(good.read_bytes()[:200])
    with pytest.raises(ValueError, match=r"truncated\.png"):
        Texture(truncated)


def test_bad_keywords():
    with pytest.raises(TypeError, match="srgb"):
        Texture(np.zeros((1, 1, 3)), srgb="yes")
    with pytest.raises(TypeError, match="name"):
        Texture(np.zeros((1, 1, 3)), name=3)


def test_oversized_texture_is_reduced_with_a_warning():
    wide = np.zeros((1, 2 * MAX_SIDE + 2, 3), dtype=np.uint8)  # 16386 texels: every 3rd kept
    wide[0, ::3] = 255
    with pytest.warns(UserWarning, match=str(MAX_SIDE)):
        texture = Texture(wide)
    assert texture.width <= MAX_SIDE and texture.width == -(-wide.shape[1] // 3)
    assert np.all(texture.levels[0][..., :3] == 255)  # the kept texels are the 0th, 3rd, ...
    picture = PILImage.fromarray(np.zeros((1, MAX_SIDE + 1, 3), dtype=np.uint8))
    with pytest.warns(UserWarning, match=str(MAX_SIDE)):
        assert Texture(picture).width <= MAX_SIDE
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert Texture(np.zeros((1, MAX_SIDE, 3), dtype=np.uint8)).width == MAX_SIDE


def test_a_picture_file_past_pillows_guards(tmp_path, monkeypatch):
    """Past Pillow's warning a file loads (reduced when a side is over MAX_SIDE), as a model
    file's picture does; past its error it is refused by name. A lower MAX_IMAGE_PIXELS
    stands for the sizes (about 89 and 179 million pixels): the 2 x 2 picture has 4."""
    path = tmp_path / "big.png"
    PILImage.fromarray(np.full((2, 2, 3), 255, dtype=np.uint8)).save(path)
    monkeypatch.setattr(PILImage, "MAX_IMAGE_PIXELS", 3)  # 4 > 3: Pillow only warns
    assert Texture(path).width == 2
    monkeypatch.setattr(PILImage, "MAX_IMAGE_PIXELS", 1)  # 4 > 2 x 1: Pillow refuses
    with pytest.raises(ValueError, match=r"big\.png: not a readable image .*Image size"):
        Texture(path)


def test_equality_by_value_and_unhashable():
    a = Texture(np.full((2, 2, 3), 0.5))
    assert a == Texture(np.full((2, 2, 3), 0.5))
    assert a != Texture(np.full((2, 2, 3), 0.25))
    with pytest.raises(TypeError):
        hash(a)


# --- surface tables and the sampling kernel ------------------------------------------------


def wrap_index(index: np.ndarray, size: int, wrap: str) -> np.ndarray:
    if wrap == "clamp":
        return np.clip(index, 0, size - 1)
    if wrap == "repeat":
        return np.mod(index, size)
    tiled = np.concatenate([np.arange(size), np.arange(size)[::-1]])  # 0 1 .. n-1 n-1 .. 0
    return tiled[np.mod(index, 2 * size)]


def reference_nearest(level: np.ndarray, u, v, wrap: str) -> np.ndarray:
    h, w = level.shape[:2]
    col = wrap_index(np.floor(np.asarray(u) * w).astype(int), w, wrap)
    row = wrap_index(np.floor((1 - np.asarray(v)) * h).astype(int), h, wrap)
    return level[row, col]


def reference_bilinear(level: np.ndarray, u, v, wrap: str) -> np.ndarray:
    h, w = level.shape[:2]
    x = np.asarray(u) * w - 0.5  # texel centres at integers
    y = (1 - np.asarray(v)) * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    c0, c1 = (wrap_index(x0.astype(int) + d, w, wrap) for d in (0, 1))
    r0, r1 = (wrap_index(y0.astype(int) + d, h, wrap) for d in (0, 1))
    top = (1 - fx) * level[r0, c0] + fx * level[r0, c1]
    bottom = (1 - fx) * level[r1, c0] + fx * level[r1, c1]
    return (1 - fy) * top + fy * bottom


def tables_for(texture: Texture, texture_filter: str, wrap: str):
    material = Material(texture=texture, texture_filter=texture_filter, texture_wrap=wrap)
    return surface_tables([Mesh(QUAD, [[0, 1, 2, 3]], material, uv=QUAD_UV)])


def kernel(tables, u, v, footprint=1.0) -> np.ndarray:
    return np.array([tk.sample(tables, 0, float(a), float(b), footprint) for a, b in zip(
        np.atleast_1d(u), np.atleast_1d(v), strict=True)])


RNG_TEXTURE = Texture(np.random.default_rng(11).integers(0, 256, (6, 5, 4), dtype=np.uint8))


@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
@pytest.mark.parametrize("texture_filter", ["nearest", "bilinear"])
def test_sample_matches_numpy_reference(texture_filter, wrap):
    rng = np.random.default_rng(7)
    u, v = rng.uniform(-2.5, 2.5, (2, 400))
    tables = tables_for(RNG_TEXTURE, texture_filter, wrap)
    reference = reference_nearest if texture_filter == "nearest" else reference_bilinear
    expected = reference(RNG_TEXTURE.linear(0), u, v, wrap)
    assert np.allclose(kernel(tables, u, v, footprint=7.0), expected, atol=1e-12)


@settings(max_examples=50, deadline=None)
@given(
    st.floats(-3, 3, allow_nan=False),
    st.floats(-3, 3, allow_nan=False),
    st.sampled_from(["repeat", "clamp", "mirror"]),
    st.integers(0, 3),
    st.floats(0.0, 1.0),
)
def test_trilinear_blends_the_two_levels_around_log2_footprint(u, v, wrap, k, frac):
    tables = tables_for(RNG_TEXTURE, "trilinear", wrap)
    count = len(RNG_TEXTURE.levels)  # 6x5 -> 3x3 -> 2x2 -> 1x1: four levels
    assert count == 4
    exact = kernel(tables, u, v, footprint=2.0**k)[0]
    assert np.allclose(exact, reference_bilinear(RNG_TEXTURE.linear(k), u, v, wrap), atol=1e-12)
    if k < count - 1:
        between = kernel(tables, u, v, footprint=2.0 ** (k + frac))[0]
        lower = reference_bilinear(RNG_TEXTURE.linear(k), u, v, wrap)
        upper = reference_bilinear(RNG_TEXTURE.linear(k + 1), u, v, wrap)
        assert np.allclose(between, (1 - frac) * lower + frac * upper, atol=1e-12)
    # Below one texel per pixel: the base level; far beyond the pyramid: the last level.
    base = reference_bilinear(RNG_TEXTURE.linear(0), u, v, wrap)
    assert np.allclose(kernel(tables, u, v, footprint=0.3)[0], base, atol=1e-12)
    top = RNG_TEXTURE.linear(count - 1)[0, 0]
    assert np.allclose(kernel(tables, u, v, footprint=1e6)[0], top, atol=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.one_of(
    st.floats(0.0, 1e12),
    st.floats(0.999999, 1.000001),
    st.sampled_from([0.0, 1.0, np.nextafter(1.0, 2.0), np.nextafter(1.0, 0.0), 4.0,
                     float("inf"), float("nan")]),
))
def test_the_level_of_a_squared_footprint_is_the_level_of_its_root(squared):
    tables = tables_for(RNG_TEXTURE, "trilinear", "repeat")
    level, blend = tk.mip_level_squared(tables, 0, squared)
    expected_level, expected_blend = tk.mip_level(tables, 0, np.sqrt(squared))
    assert level == expected_level
    assert blend == expected_blend or (np.isnan(blend) and np.isnan(expected_blend))


def test_sample_hand_values_on_a_two_by_two_texture():
    # Rows top to bottom: red, green / blue, white. v up: (0.25, 0.75) is the top-left texel.
    codes = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], np.uint8)
    texture = Texture(codes)
    red, green, blue, white = [1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [1, 1, 1, 1]
    nearest = tables_for(texture, "nearest", "repeat")
    assert kernel(nearest, [0.25, 0.75, 0.25, 0.75], [0.75, 0.75, 0.25, 0.25]).tolist() == [
        red, green, blue, white,
    ]
    bilinear = tables_for(texture, "bilinear", "clamp")
    # Texel centres give the texel; the middle of the picture the average of all four.
    assert np.allclose(kernel(bilinear, 0.25, 0.75), [red])
    assert np.allclose(kernel(bilinear, 0.5, 0.5), [[0.5, 0.5, 0.5, 1.0]])
    # Halfway between the top two texels.
    assert np.allclose(kernel(bilinear, 0.5, 0.75), [[0.5, 0.5, 0, 1]])
    # Clamp: outside the picture is the nearest edge texel.
    assert np.allclose(kernel(bilinear, [-0.3, 1.7], [0.75, 0.25]), [red, white])


@pytest.mark.parametrize(
    ("wrap", "u", "expected_u"),
    [
        ("repeat", -0.33, 0.67),
        ("repeat", 1.74, 0.74),
        ("repeat", 2.16, 0.16),
        ("clamp", -0.33, 0.05),
        ("clamp", 1.74, 0.95),
        ("mirror", -0.33, 0.33),
        ("mirror", 1.74, 0.26),
        ("mirror", 2.16, 0.16),
        ("mirror", -1.24, 0.76),
    ],
)
def test_wrap_modes_by_hand(wrap, u, expected_u):
    # A 10-texel ramp: texel c holds c / 9 in red (linear floats), so the nearest sample
    # at u tells which column was read (u chosen away from texel borders).
    ramp = np.zeros((1, 10, 3))
    ramp[0, :, 0] = np.arange(10) / 9
    texture = Texture(ramp)
    tables = tables_for(texture, "nearest", wrap)
    got = kernel(tables, u, 0.5)[0, 0]
    want = texture.linear()[0, int(np.floor(expected_u * 10)), 0]
    assert got == pytest.approx(want, abs=1e-12)
    # The same along v (rows run downwards: v = 1 - (row + 0.5) / H).
    column = np.ascontiguousarray(ramp.transpose(1, 0, 2)[::-1])  # row 9 at the top
    tables_v = tables_for(Texture(column), "nearest", wrap)
    assert kernel(tables_v, 0.5, u)[0, 0] == pytest.approx(want, abs=1e-12)


def test_surface_tables_pack_each_texture_once():
    shared = Texture(np.ones((4, 4, 3)))
    mat_a = Material(texture=shared, texture_filter="nearest")
    mat_b = Material(texture=shared, texture_filter="bilinear", texture_wrap="mirror")
    with_uv = Mesh(QUAD, [[0, 1, 2, 3]], mat_a, uv=QUAD_UV)
    other = Mesh(QUAD, [[0, 1, 2, 3]], mat_b, uv=QUAD_UV, colors=[[1, 0, 0]] * 4)
    no_uv = Mesh(QUAD, [[0, 1, 2, 3]], mat_a)  # a texture without uv is left out
    tables = surface_tables([with_uv, other, no_uv, with_uv])
    assert tables.levels.tolist() == [[0, 4, 4], [16, 2, 2], [20, 1, 1]]
    assert len(tables.texels) == 21
    assert tables.textures.tolist() == [[0, 3, tk.NEAREST, tk.REPEAT],
                                        [0, 3, tk.BILINEAR, tk.MIRROR]]
    assert tables.objects.tolist() == [[0, 0, -1], [1, 1, -1], [-1, 0, -1], [0, 0, -1]]
    assert tables.decode[128] == pytest.approx(srgb_to_linear(128 / 255))


def test_surface_tables_pack_emission_textures_where_they_show():
    """An emission texture shares the rows of the same picture read the same way; it is left
    out without texture coordinates, or where the material emits nothing."""
    shared, glow = Texture(np.ones((4, 4, 3))), Texture(np.ones((2, 2, 3)))
    both = Material(texture=shared, emission=(1, 1, 1), emission_texture=shared)
    own = Material(emission=(1, 0, 0), emission_texture=glow)
    dark = Material(emission_texture=glow)  # emission (0, 0, 0)
    tables = surface_tables([Mesh(QUAD, [[0, 1, 2, 3]], both, uv=QUAD_UV),
                             Mesh(QUAD, [[0, 1, 2, 3]], own, uv=QUAD_UV),
                             Mesh(QUAD, [[0, 1, 2, 3]], own),
                             Mesh(QUAD, [[0, 1, 2, 3]], dark, uv=QUAD_UV)])
    assert tables.objects.tolist() == [[0, 0, 0], [-1, 0, 1], [-1, 0, -1], [-1, 0, -1]]
    assert tables.levels.tolist() == [[0, 4, 4], [16, 2, 2], [20, 1, 1], [21, 2, 2], [25, 1, 1]]


@given(st.lists(st.tuples(st.booleans(), st.booleans(),
                          st.sampled_from(["none", "texture", "glow", "dark glow", "cut",
                                           "uncut", "cut texture"])),
                min_size=1, max_size=4))
def test_lookups_are_needed_for_the_objects_surface_tables_look_up(choices):
    """Meshes with uv or not, vertex colours or not; a texture, an emission texture that
    shows or one on a material that emits nothing, an alpha test that can cut or cannot; and
    a sphere, which has no uv or colours."""
    from pixelpath.scene import Sphere

    picture = Texture(np.ones((2, 2, 3)))
    holes = Texture(np.dstack([np.ones((2, 2, 3)), [[1.0, 0.0], [1.0, 1.0]]]))
    materials = {"none": Material(), "texture": Material(texture=picture),
                 "glow": Material(emission=(1, 0, 0), emission_texture=picture),
                 "dark glow": Material(emission_texture=picture),
                 "cut": Material(alpha=0.3, alpha_cutoff=0.5),
                 "uncut": Material(alpha=0.8, alpha_cutoff=0.5),
                 "cut texture": Material(texture=holes, alpha_cutoff=0.5)}
    objects = [Sphere((0, 0, 0), 1.0, materials["texture"])]
    for with_uv, with_colors, kind in choices:
        objects.append(Mesh(QUAD, [[0, 1, 2, 3]], materials[kind],
                            uv=QUAD_UV if with_uv else None,
                            colors=[[1, 0, 0]] * 4 if with_colors else None))
    for obj in objects:
        tables = surface_tables([obj])
        row = tables.objects[0]
        looked_up = (row[tk.TEXTURE] >= 0 or row[tk.HAS_COLORS] != 0 or row[tk.GLOW] >= 0
                     or tables.alpha[0, tk.CUTOFF] > 0.0)
        assert needs_lookups([obj]) == looked_up
    assert needs_lookups(objects) == any(needs_lookups([obj]) for obj in objects)


def test_packed_texels_are_the_levels_and_shared_without_a_copy():
    one = Texture(np.random.default_rng(3).integers(0, 256, (6, 5, 4), dtype=np.uint8))
    two = Texture(np.random.default_rng(4).integers(0, 256, (2, 3, 3), dtype=np.uint8))
    levels = [level.copy() for level in one.levels]
    alone = surface_tables([Mesh(QUAD, [[0, 1, 2, 3]], Material(texture=one), uv=QUAD_UV)])
    assert alone.texels is one._packed[0]  # one texture: its own packed words, no copy
    assert not alone.texels.flags.writeable
    both = surface_tables([Mesh(QUAD, [[0, 1, 2, 3]], Material(texture=t), uv=QUAD_UV)
                           for t in (one, two)])
    for texture, rows in ((one, both.levels[:4]), (two, both.levels[4:])):
        for level, (first, width, height) in zip(texture.levels, rows.tolist(), strict=True):
            words = both.texels[first:first + width * height].reshape(height, width)
            channels = np.stack([(words >> shift) & 255 for shift in (0, 8, 16, 24)], axis=2)
            assert np.array_equal(channels, level)
    assert all(np.array_equal(a, b) for a, b in zip(levels, one.levels, strict=True))


@pytest.mark.parametrize("size", [1, 2, 4, 512, 3, 6])
def test_repeat_wrap_is_the_true_modulo(size):
    # Powers of two wrap with a mask, other sides in floating point: both the true modulo
    # for coordinates far beyond the picture and below it.
    x = np.concatenate([np.linspace(-3000.3, 3000.7, 1001), [-1e15 - 0.5, 1e15 + 0.25]])
    for value in x:
        i0, i1, fraction = tk._neighbours(value, size, tk.REPEAT)
        floor = int(np.floor(value))
        assert (i0, i1) == (floor % size, (floor + 1) % size)
        assert fraction == value - floor
