"""pixelpath.Image: array protocol, buffers, saving, Jupyter display."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image as PILImage

from pixelpath import Image
from pixelpath.io import read_image


def gradient(height=3, width=4):
    values = np.linspace(0, 1, height * width * 3, dtype=np.float32)
    return values.reshape(height, width, 3)


def test_asarray_is_float32_rgb_and_read_only():
    img = Image(gradient())
    array = np.asarray(img)
    assert array.shape == (3, 4, 3) and array.dtype == np.float32
    assert img.shape == (3, 4, 3) and (img.width, img.height) == (4, 3)
    with pytest.raises(ValueError):
        array[0, 0, 0] = 1.0


def test_values_are_clamped_and_input_is_not_modified():
    rgb = np.array([[[-0.5, 0.5, 2.0]]])
    img = Image(rgb)
    assert np.asarray(img).tolist() == [[[0.0, 0.5, 1.0]]]
    assert rgb.tolist() == [[[-0.5, 0.5, 2.0]]]


def test_default_buffers_mean_nothing_drawn():
    img = Image(np.zeros((2, 2, 3)))
    assert np.all(np.isinf(img.depth)) and img.depth.dtype == np.float32
    assert np.all(img.object_id == -1) and img.object_id.dtype == np.int32


def test_buffers_are_checked_against_the_image_size():
    with pytest.raises(ValueError, match="depth"):
        Image(np.zeros((2, 2, 3)), depth=np.zeros((3, 2)))
    with pytest.raises(ValueError, match="rgb"):
        Image(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="finite"):
        Image(np.full((2, 2, 3), np.nan))


def test_save_round_trips_through_png(tmp_path):
    rgb = np.round(gradient() * 255) / 255
    path = tmp_path / "g.png"
    Image(rgb).save(path)
    assert np.array_equal(read_image(path), rgb.astype(np.float32))
    assert [p.name for p in tmp_path.iterdir()] == ["g.png"]  # no temporary file left behind


def test_save_with_gamma_encodes(tmp_path):
    path = tmp_path / "grey.png"
    Image(np.full((1, 1, 3), 0.25)).save(path, gamma=2.0)
    assert read_image(path)[0, 0, 0] == pytest.approx(np.rint(0.5 * 255) / 255)


def test_save_into_a_missing_folder_is_a_clear_error(tmp_path):
    with pytest.raises(FileNotFoundError, match="directory"):
        Image(gradient()).save(tmp_path / "missing" / "x.png")


def test_repr_png_is_a_png_of_the_picture():
    img = Image(gradient())
    decoded = PILImage.open(io.BytesIO(img._repr_png_()))
    assert decoded.format == "PNG"
    assert np.array_equal(np.asarray(decoded.convert("RGB")), img.to_uint8())


def test_to_uint8_maps_value_times_255():
    img = Image(np.array([[[0.0, 0.5, 1.0]]]))
    assert img.to_uint8().tolist() == [[[0, 128, 255]]]


def test_saved_file_gets_the_usual_permissions(tmp_path):
    import os

    path = tmp_path / "p.png"
    Image(gradient()).save(path)
    mask = os.umask(0o022)
    os.umask(mask)
    assert path.stat().st_mode & 0o777 == 0o666 & ~mask


def test_array_protocol_copies_only_when_asked():
    img = Image(gradient())
    assert np.asarray(img) is np.asarray(img)  # the read-only buffer itself
    copied = np.array(img)
    copied[0, 0, 0] = 0.5  # a copy is writeable and independent
    assert np.asarray(img)[0, 0, 0] == 0.0
    assert np.asarray(img, dtype=np.float64).dtype == np.float64
    with pytest.raises(ValueError, match="copy"):
        np.asarray(img, dtype=np.float64, copy=False)
