"""``pixelpath phong``: the notes' example with the corrected total, vector and point modes."""

from __future__ import annotations

import pytest

from pixelpath.cli import main

NOTES = ["--ka", "0.2", "--kd", "0.6", "--ks", "0.5", "-n", "20", "--ia", "0.2", "--il", "1"]


def run(capsys, *argv):
    code = main(["phong", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_notes_example_prints_corrected_breakdown(capsys):
    # I_a = 0.04, I_d = 0.4242, (0.866)^20 = 0.0563, I_s = 0.0281, I = 0.4923 (not 0.47005).
    code, out, _ = run(capsys, *NOTES, "--ndotl", "0.707", "--rdotv", "0.866")
    assert code == 0
    for text in ("0.04", "0.4242", "0.0563", "0.0281", "0.4923"):
        assert text in out
    assert "0.47005" not in out and "0.0117" not in out


def test_explain_names_the_steps(capsys):
    code, out, _ = run(capsys, *NOTES, "--ndotl", "0.707", "--rdotv", "0.866", "--explain")
    assert code == 0
    # cos^-1(0.866) = 30.00 deg; cos^-1(0.707) = 45.01 deg.
    assert "α = 30.00°" in out and "θ_i = 45.01°" in out
    assert "8. Compute total intensity I = 0.4923" in out


def test_vector_mode_derives_dot_products_and_reflection(capsys):
    # N = z, L = (0, 1, 1)/sqrt 2, V = (0, -1, 1)/sqrt 2: N.L = 0.7071, R = (0, -0.7071, 0.7071)
    # = V, R.V = 1. I = 0.04 + 0.6 x 0.7071 + 0.5 x 1 = 0.04 + 0.4243 + 0.5 = 0.9643.
    code, out, _ = run(capsys, *NOTES, "--normal", "0,0,1", "--to-light", "0,1,1",
                       "--to-eye", "0,-1,1", "--explain")
    assert code == 0
    assert "(0, -0.7071, 0.7071)" in out
    assert "4. Compute reflection vector R = 2(N·L)N − L" in out
    assert "0.9643" in out


def test_point_mode_derives_l_and_v(capsys):
    # P = (1, 1, 0), light (1, 4, 4): L = (0, 0.6, 0.8); eye (1, 1, 2): V = (0, 0, 1); N = z.
    # N.L = 0.8, R = (0, -0.6, 0.8), R.V = 0.8, 0.8^20 = 0.011529.
    # I = 0.04 + 0.6 x 0.8 + 0.5 x 0.011529 = 0.04 + 0.48 + 0.005765 = 0.525765.
    code, out, _ = run(capsys, *NOTES, "--normal", "0,0,1", "--surface", "1,1,0",
                       "--light", "1,4,4", "--eye", "1,1,2")
    assert code == 0
    assert "(0, 0.6, 0.8)" in out and "(0, -0.6, 0.8)" in out
    assert "0.5258" in out


def test_per_channel_light(capsys):
    # IL = (1, 0.8, 0.8): I_d = 0.4242 x (1, 0.8, 0.8) = (0.4242, 0.3394, 0.3394);
    # I_s = 0.02814 x (1, 0.8, 0.8) = (0.02814, 0.02251, 0.02251);
    # I = 0.04 + I_d + I_s = (0.49234, 0.40187, 0.40187).
    code, out, _ = run(capsys, *NOTES[:-1], "1,0.8,0.8", "--ndotl", "0.707", "--rdotv", "0.866")
    assert code == 0
    assert "(0.4242, 0.3394, 0.3394)" in out
    assert "(0.4923, 0.4019, 0.4019)" in out


def test_blinn_model_uses_the_halfway_vector(capsys):
    # N = z, L = (0, 1, 1)/sqrt 2, V = z: H = (0, 0.7071, 1.7071)/|.| = (0, 0.3827, 0.9239),
    # N.H = cos 22.5 deg = 0.92388, ^20 = 0.20526; I_s = 0.5 x 0.20526 = 0.1026.
    code, out, _ = run(capsys, *NOTES, "--normal", "0,0,1", "--to-light", "0,1,1",
                       "--to-eye", "0,0,1", "--model", "blinn")
    assert code == 0
    assert "N·H" in out and "0.9239" in out and "0.1026" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--ndotl", "0.5"], "give --ndotl and --rdotv"),
        (["--ka", "-1", "--ndotl", "0.5", "--rdotv", "0.5"], "ka must be >= 0"),
        (["--ndotl", "1.5", "--rdotv", "0.5"], "n_dot_l is a cosine"),
        (["--il", "1,2", "--ndotl", "0.5", "--rdotv", "0.5"], "--il must be one number or r,g,b"),
        (["--ks", "shiny", "--ndotl", "0.5", "--rdotv", "0.5"], "--ks must be numbers"),
        (["--normal", "0,0,0", "--to-light", "1,1,1", "--to-eye", "0,1,1"], "zero-length"),
        (["--normal", "0,0,1", "--to-light", "1,1", "--to-eye", "0,1,1"], "--to-light must be"),
        (["--to-light", "1,1,1", "--to-eye", "0,1,1"], "--normal is required"),
        (["--normal", "0,0,1", "--to-light", "1,1,1", "--eye", "0,1,1"], "give --to-light"),
        (["--normal", "0,0,1", "--to-light", "1,1,1", "--to-eye", "0,1,1", "--ndotl", "0.5"],
         "not both"),
        (["--ndotl", "0.5", "--rdotv", "0.5", "--model", "blinn"], "needs vectors"),
        (["--normal", "0,0,1", "--surface", "0,0,0", "--light", "0,0,0", "--eye", "0,0,1"],
         "to_light"),
    ],
)
def test_bad_input_exits_2_with_a_clean_message(capsys, argv, message):
    code, _, err = run(capsys, *argv)
    assert code == 2
    assert message in err
    assert "Traceback" not in err
