"""pixelpath.io.aovs: names, paths, and the files written for depth, normal, id, alpha, mask."""

from __future__ import annotations

import io

import hypothesis.extra.numpy as hnp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image as PILImage

import pixelpath as pp
from pixelpath.io.aovs import AOVS, aov_path, encode_aov, parse_aovs, write_aovs


def test_parse_aovs():
    assert AOVS == ("depth", "normal", "id", "alpha", "mask")
    assert parse_aovs("depth") == ("depth",)
    assert parse_aovs(" Normal ,DEPTH,normal,id") == ("normal", "depth", "id")
    assert parse_aovs(["alpha", "id", "alpha"]) == ("alpha", "id")
    assert parse_aovs([]) == ()
    for bad in ("depth,colour", "", "depth,", ["masks"]):
        with pytest.raises(ValueError, match="unknown AOV") as info:
            parse_aovs(bad)
        assert "depth, normal, id, alpha, mask" in str(info.value)
    assert parse_aovs("mask,depth", allowed=("depth", "mask")) == ("mask", "depth")
    with pytest.raises(ValueError, match="unknown AOV 'id'; choose from depth, mask"):
        parse_aovs("id", allowed=("depth", "mask"))


def test_aov_paths():
    assert aov_path("out/duck.png", "depth").as_posix() == "out/duck.depth.npy"
    assert aov_path("out/duck.png", "normal").as_posix() == "out/duck.normal.png"
    assert aov_path("duck.jpg", "id").as_posix() == "duck.id.png"
    assert aov_path("a.b.png", "alpha").as_posix() == "a.b.alpha.png"


def read(path) -> tuple[np.ndarray, str]:
    with PILImage.open(path) as img:
        return np.asarray(img), img.mode


def handmade_image() -> pp.Image:
    object_id = np.array([[-1, 0, 3], [1, -1, 2]])
    depth = np.array([[np.inf, 2.5, 7.25], [1e-3, np.inf, 100.0]])
    normal = np.zeros((2, 3, 3))
    normal[0, 1] = (1, 0, 0)
    normal[0, 2] = (-1, 0, 0)
    normal[1, 0] = (0.28, 0.96, 0)
    normal[1, 1] = (0, 0, 1)  # a background pixel with a normal: written black anyway
    normal[1, 2] = (0, -0.6, 0.8)
    alpha = np.array([[0, 1, 0.5], [0.25, 0, 1]])
    return pp.Image(np.zeros((2, 3, 3)), depth, object_id, alpha=alpha, normal=normal)


def test_write_every_aov(tmp_path):
    image = handmade_image()
    target = tmp_path / "shot.png"
    written = write_aovs(image, target, "depth,normal,id,alpha,mask")
    assert [p.name for p in written] == [
        "shot.depth.npy", "shot.normal.png", "shot.id.png", "shot.alpha.png", "shot.mask.png",
    ]
    assert not target.exists()  # only the AOVs are written here

    depth = np.load(tmp_path / "shot.depth.npy")
    assert depth.dtype == np.float32 and depth.shape == (2, 3)
    assert np.isinf(depth[0, 0]) and np.isinf(depth[1, 1])
    assert depth[0, 1] == 2.5 and depth[0, 2] == 7.25 and depth[1, 2] == 100.0

    normal, mode = read(tmp_path / "shot.normal.png")
    assert mode == "RGB" and normal.shape == (2, 3, 3)
    expected = (image.normal.astype(np.float64) + 1) / 2 * 255  # (n + 1) / 2 in 0..255
    drawn = image.object_id >= 0
    assert np.all(np.abs(normal[drawn] - expected[drawn]) <= 0.5 + 1e-6)
    assert normal[0, 1].tolist()[0] == 255 and normal[0, 2].tolist()[0] == 0
    assert np.all(normal[~drawn] == 0)  # black background, even where a normal was given

    ids, mode = read(tmp_path / "shot.id.png")
    assert mode.startswith("I;16") or mode == "I"
    assert ids.tolist() == [[0, 1, 4], [2, 0, 3]]

    alpha, mode = read(tmp_path / "shot.alpha.png")
    assert mode == "L"
    assert alpha[0, 0] == 0 and alpha[0, 1] == 255 and alpha[1, 2] == 255
    assert abs(int(alpha[0, 2]) - 127.5) <= 0.5 and abs(int(alpha[1, 0]) - 63.75) <= 0.5

    mask, mode = read(tmp_path / "shot.mask.png")
    assert mode == "L" and mask.tolist() == [[0, 255, 255], [255, 0, 255]]  # where drawn


def test_id_aov_limit(tmp_path):
    image = pp.Image(np.zeros((1, 2, 3)), object_id=[[65534, 70000]])
    with pytest.raises(ValueError, match="65534"):
        write_aovs(image, tmp_path / "x.png", ["id"])
    fine = pp.Image(np.zeros((1, 2, 3)), object_id=[[65534, -1]])
    write_aovs(fine, tmp_path / "x.png", ["id"])
    assert read(tmp_path / "x.id.png")[0].tolist() == [[65535, 0]]


def test_unknown_aov_writes_nothing(tmp_path):
    with pytest.raises(ValueError, match="unknown AOV"):
        write_aovs(handmade_image(), tmp_path / "x.png", ["depth", "colour"])
    assert list(tmp_path.iterdir()) == []


def _png_pixels(data: bytes) -> np.ndarray:
    with PILImage.open(io.BytesIO(data)) as img:
        return np.asarray(img)


@pytest.mark.parametrize("aov", ["normal", "id", "alpha", "mask"])
def test_png_level_changes_the_size_of_a_png_aov_and_not_its_pixels(aov, tmp_path):
    # A smooth picture, as renders are: level 0 stores every byte, 9 squeezes them.
    y, x = np.mgrid[0:24, 0:32] / 32.0
    normal = np.stack([x - 0.5, y - 0.4, np.ones_like(x)], axis=-1)
    normal /= np.linalg.norm(normal, axis=2, keepdims=True)
    object_id = np.where(x + y < 1.1, 2, -1)
    image = pp.Image(np.zeros((24, 32, 3)), object_id=object_id, alpha=(x + y) / 2,
                     normal=normal)
    default = encode_aov(image, aov)
    assert encode_aov(image, aov, png_level=6) == default  # Pillow's default, Image.save's
    stored = encode_aov(image, aov, png_level=0)
    assert len(stored) > _png_pixels(default).nbytes > len(encode_aov(image, aov, png_level=9))
    for level in (0, 1, 9):
        assert np.array_equal(_png_pixels(encode_aov(image, aov, png_level=level)),
                              _png_pixels(default))
    written = write_aovs(image, tmp_path / "x.png", [aov], png_level=0)
    assert written[0].read_bytes() == stored


def test_a_bad_png_level_is_refused_for_every_aov(tmp_path):
    for bad in (10, -1, 1.5, "1"):
        for aov in AOVS:  # the depth's .npy too, as encode_image checks it for every format
            with pytest.raises(ValueError, match="png_level must be an int from 0 to 9"):
                encode_aov(handmade_image(), aov, png_level=bad)
    with pytest.raises(ValueError, match="png_level"):
        write_aovs(handmade_image(), tmp_path / "x.png", ["depth"], png_level=10)
    assert list(tmp_path.iterdir()) == []


@settings(max_examples=60, deadline=None)
@given(
    hnp.arrays(np.float32, (5, 7, 3), elements=st.floats(-1, 1, width=32)),
    hnp.arrays(np.bool_, (5, 7)),
)
def test_normal_codes_are_the_rounded_normals_where_drawn(normal, drawn):
    # +-1, 0 and the normals whose codes fall on a half (rint rounds those to even) included
    normal[0, 0] = (-1.0, 0.0, 1.0)
    normal[0, 1] = (np.float32(1 / 255), np.float32(-1 / 255), np.float32(-0.0))
    object_id = np.where(drawn, 0, -1)
    image = pp.Image(np.zeros((5, 7, 3)), object_id=object_id, normal=normal)
    codes = _png_pixels(encode_aov(image, "normal"))
    expected = np.where(drawn[..., None], np.rint((normal.astype(np.float64) + 1) * 127.5), 0)
    assert np.all(np.abs(codes.astype(np.float64) - expected) <= 1.0)
    exact = np.rint((normal + np.float32(1.0)) * np.float32(127.5))  # the float32 arithmetic
    assert np.array_equal(codes, np.where(drawn[..., None], exact, 0).astype(np.uint8))
