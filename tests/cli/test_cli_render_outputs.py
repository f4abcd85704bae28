"""``pixelpath render --transparent --aov ... --gamma ...``: the files and the clean errors."""

from __future__ import annotations

import numpy as np
import pytest

# scene_file (tests/cli/conftest.py) is the cube of box_scene: its front face (z = 1) fills
# the middle, 4 units from the eye.
from box_scene import SCENE
from PIL import Image as PILImage

from pixelpath.cli import main


def read(path) -> np.ndarray:
    with PILImage.open(path) as img:
        return np.asarray(img)


def test_aovs_beside_the_image(scene_file, tmp_path, capsys):
    out = tmp_path / "cube.png"
    argv = ["render", str(scene_file), "-o", str(out), "--aov", "depth,normal,id,alpha"]
    assert main(argv) == 0
    printed = capsys.readouterr().out
    for name in ("cube.depth.npy", "cube.normal.png", "cube.id.png", "cube.alpha.png"):
        assert (tmp_path / name).is_file() and name in printed
    assert read(out).shape == (16, 24, 3)
    depth = np.load(tmp_path / "cube.depth.npy")
    assert depth.dtype == np.float32 and depth.shape == (16, 24)
    assert np.isinf(depth[0, 0]) and depth[8, 12] == pytest.approx(4.0, abs=1e-5)
    ids = read(tmp_path / "cube.id.png")
    assert ids[0, 0] == 0 and ids[8, 12] == 1  # object 0 written as 1
    drawn = ids == 1
    assert np.array_equal(drawn, np.isfinite(depth))
    normal = read(tmp_path / "cube.normal.png")
    assert normal[8, 12].tolist() in ([128, 128, 255], [127, 127, 255])  # (0, 0, 1)
    assert np.all(normal[~drawn] == 0)
    alpha = read(tmp_path / "cube.alpha.png")
    assert alpha.dtype == np.uint8 and np.array_equal(alpha, np.where(drawn, 255, 0))


def test_transparent_png(scene_file, tmp_path):
    out = tmp_path / "cut.png"
    assert main(["render", str(scene_file), "-o", str(out), "--transparent", "-q"]) == 0
    rgba = read(out)
    assert rgba.shape == (16, 24, 4)
    assert rgba[0, 0].tolist() == [0, 0, 0, 0]  # the blue background taken out
    assert rgba[8, 12, 3] == 255 and rgba[8, 12, :3].sum() > 0
    plain = tmp_path / "plain.png"
    assert main(["render", str(scene_file), "-o", str(plain), "-q"]) == 0
    opaque = read(plain)
    inside = rgba[..., 3] == 255
    assert np.array_equal(rgba[inside][:, :3], opaque[inside])


@pytest.mark.parametrize(("gamma", "code"), [
    ([], 128), (["--gamma", "linear"], 128), (["--gamma", "srgb"], 188),
    (["--gamma", "SRGB"], 188), (["--gamma", "2.2"], 186),
])
def test_gamma_option(scene_file, tmp_path, gamma, code):
    out = tmp_path / "g.png"
    assert main(["render", str(scene_file), "-o", str(out), "-q", *gamma]) == 0
    assert read(out)[0, 0].tolist() == [0, 0, code]  # background blue 0.5, encoded


def test_model_file_renders_srgb_by_default(tmp_path):
    model = tmp_path / "tri.obj"
    model.write_text("v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n")
    srgb, linear = tmp_path / "s.png", tmp_path / "l.png"
    size = ["--size", "24x18", "-q"]
    assert main(["render", str(model), "-o", str(srgb), *size]) == 0
    assert main(["render", str(model), "-o", str(linear), *size, "--gamma", "linear"]) == 0
    a, b = read(srgb).astype(int), read(linear).astype(int)
    lit = b > 8
    assert lit.any()
    # sRGB brightens every mid-tone: value v goes to ~255 * srgb(v / 255) >= v.
    assert np.all(a[lit] >= b[lit]) and np.any(a[lit] > b[lit] + 20)


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--aov", "depth,colour"], "unknown AOV"),
        (["--aov", ""], "unknown AOV"),
        (["--gamma", "-1"], "--gamma"),
        (["--gamma", "bright"], "--gamma"),
        (["--gamma", "nan"], "--gamma"),
    ],
)
def test_bad_output_options_exit_2(scene_file, tmp_path, capsys, extra, message):
    try:
        status = main(["render", str(scene_file), "-o", str(tmp_path / "x.png"), *extra])
    except SystemExit as exc:  # argparse's usage errors
        status = exc.code
    assert status == 2
    err = capsys.readouterr().err
    assert message in err and "usage:" in err and "Traceback" not in err
    assert list(tmp_path.glob("x*")) == []


def test_transparent_jpeg_is_a_clear_error(scene_file, tmp_path, capsys):
    out = tmp_path / "x.jpg"
    assert main(["render", str(scene_file), "-o", str(out), "--transparent"]) == 2
    err = capsys.readouterr().err
    assert ".jpg" in err and "alpha" in err and "Traceback" not in err
    assert not out.exists()


@pytest.mark.parametrize("extra", [["--aov", "depth"], ["--transparent"]])
def test_frames_with_aov_or_transparent_is_a_clear_error(scene_file, tmp_path, capsys, extra):
    pattern = str(tmp_path / "f_{frame}.png")
    assert main(["render", str(scene_file), "-o", pattern, "--frames", "0", *extra]) == 2
    err = capsys.readouterr().err
    assert "--aov" in err and "--transparent" in err and "Traceback" not in err
    assert list(tmp_path.glob("f_*")) == []


def test_turntable_orbits_a_scene_without_an_animation(scene_file, tmp_path):
    pattern = str(tmp_path / "spin_{frame}.png")
    assert main(["render", str(scene_file), "--turntable", "4", "-o", pattern, "-q"]) == 0
    frames = [np.asarray(PILImage.open(tmp_path / f"spin_{k}.png")) for k in range(4)]
    # A quarter turn apart: the camera sees the cube's front (+Z), then the +X side (both lit,
    # differently, by the light at (2, 3, 4)), then the back and the -X side, which face away
    # from the light and show the ambient light alone.
    front, right, back, left = frames
    assert len({front.tobytes(), right.tobytes(), back.tobytes()}) == 3
    np.testing.assert_array_equal(back, left)
    assert not (tmp_path / "spin_4.png").exists()


def test_turntable_with_frames_renders_only_those(scene_file, tmp_path):
    pattern = str(tmp_path / "f_{frame}.png")
    assert main(["render", str(scene_file), "--turntable", "8", "--frames", "2,5", "-o",
                 pattern, "-q"]) == 0
    assert sorted(p.name for p in tmp_path.glob("f_*.png")) == ["f_2.png", "f_5.png"]


def test_turntable_refuses_a_scene_with_its_own_animation(tmp_path, capsys):
    path = tmp_path / "animated.toml"
    path.write_text(SCENE + "\n[animation]\nframes = 3\nturntable = { turns = 1 }\n")
    code = main(["render", str(path), "--turntable", "4", "-o", str(tmp_path / "f_{frame}.png")])
    assert code != 0
    assert "has an [animation] of its own" in capsys.readouterr().err
