"""``pixelpath color``: the table, --explain, input forms, files and errors."""

import numpy as np
import pytest

from pixelpath.cli import main
from pixelpath.io import read_image, write_image


def run(capsys, *argv):
    status = main(["color", *argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_table_for_yellow(capsys):
    status, out, _ = run(capsys, "255,255,0", "--to", "hsv,yiq,cmy,cmyk")
    assert status == 0
    assert "60, 1, 1" in out  # HSV
    assert "0.886, 0.322, -0.312" in out  # YIQ
    assert "0, 0, 1, 0" in out  # CMYK


@pytest.mark.parametrize("value", ["#ffff00", "#ff0", "ffff00", "1,1,0.0"])
def test_other_spellings_of_yellow(capsys, value):
    status, out, _ = run(capsys, value, "--to", "hsv")
    assert status == 0 and "60, 1, 1" in out


def test_explain_prints_the_notes_steps(capsys):
    status, out, _ = run(capsys, "255,255,0", "--to", "hsv,cmy,yiq", "--explain")
    assert status == 0
    assert "Cmax = R, so H = 60 × ((G − B)/Δ mod 6)" in out
    assert "C, M, Y = 1 − R, 1 − G, 1 − B = 0, 0, 1" in out
    assert "Y = 0.299×R + 0.587×G + 0.114×B = 0.886" in out


def test_from_hsv_with_sector_row(capsys):
    status, out, _ = run(capsys, "200,0.5,0.8", "--from", "hsv", "--to", "rgb", "--explain")
    assert status == 0
    assert "8-bit 102, 170, 204" in out
    assert "lies in 180-240°" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["300,0,0"], "0..255"),
        (["1,2"], "3 components"),
        (["red"], "cannot read 'red'"),
        (["1,1,1", "--to", "lab"], "unknown model 'lab'"),
        (["1,1,1", "-o", "x.npy"], "-o is for converting files"),
    ],
)
def test_errors_exit_2_with_a_message(capsys, argv, message):
    status, _, err = run(capsys, *argv)
    assert status == 2
    assert message in err


def test_image_file_round_trip(capsys, tmp_path):
    rgb = np.random.default_rng(0).integers(0, 256, (8, 6, 3)) / 255.0
    write_image(tmp_path / "in.png", rgb)
    status, out, _ = run(
        capsys, str(tmp_path / "in.png"), "--to", "hsv", "-o", str(tmp_path / "hsv.npy")
    )
    assert status == 0 and "shape (8, 6, 3)" in out
    hsv = np.load(tmp_path / "hsv.npy")
    assert hsv.shape == (8, 6, 3) and hsv.dtype == np.float32
    status, _, _ = run(
        capsys,
        str(tmp_path / "hsv.npy"),
        "--from",
        "hsv",
        "--to",
        "rgb",
        "-o",
        str(tmp_path / "back.png"),
    )
    assert status == 0
    np.testing.assert_array_equal(
        read_image(tmp_path / "back.png"), read_image(tmp_path / "in.png")
    )


def test_image_output_needs_rgb(capsys, tmp_path):
    write_image(tmp_path / "in.png", np.zeros((2, 2, 3)))
    status, _, err = run(
        capsys, str(tmp_path / "in.png"), "--to", "hsv", "-o", str(tmp_path / "x.png")
    )
    assert status == 2 and "write .npy instead" in err
