"""``pixelpath render --figure/--animate`` and ``pixelpath ray --figure``: files and errors."""

from __future__ import annotations

import textwrap

import pytest
from PIL import Image

from pixelpath.cli import main

# A sphere and a box behind it, apart: at least two levels of Warnock's subdivision
# (the whole image holds many polygons, none surrounding it).
SCENE = textwrap.dedent(
    """\
    [camera]
    eye = [0, 0, 5]
    target = [0, 0, 0]
    width = 32
    height = 24

    [[lights]]
    type = "point"
    position = [2, 3, 4]

    [[objects]]
    type = "box"
    minimum = [-2, -1, -3]
    maximum = [-0.5, 1, -2]

    [[objects]]
    type = "sphere"
    center = [1, 0, 0]
    radius = 0.8
    """
)


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def _frames(path) -> int:
    with Image.open(path) as gif:
        return gif.n_frames


def test_render_writes_the_figure_and_the_animation(scene_file, tmp_path, capsys):
    figure, animation = tmp_path / "warnock.png", tmp_path / "levels.gif"
    args = ["render", str(scene_file), "-o", str(tmp_path / "out.png"), "--method", "warnock",
            "--figure", str(figure), "--animate", str(animation)]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert f"wrote {figure}" in out and f"wrote {animation}" in out
    assert "subdivision levels" not in out  # the report is printed with --explain only
    with Image.open(figure) as picture:
        assert picture.format == "PNG"
    assert _frames(animation) >= 2
    assert main([*args, "--explain"]) == 0
    assert "subdivision levels" in capsys.readouterr().out


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--method", "raytrace", "--figure", "f.png"], "'raytrace' has no figure"),
        (["--method", "warnock", "--animate", "f.png"], ".gif"),
        (["--method", "warnock", "--figure", "f.png", "--ssaa", "2"], "--ssaa"),
        (["--method", "bsp", "--figure", "f.png", "--style", "hidden-line"], "--style"),
        (["--method", "painter", "--animate", "missing/f.gif"], "does not exist"),
    ],
)
def test_render_figure_errors_are_clean(scene_file, tmp_path, capsys, extra, message):
    extra = [str(tmp_path / a) if a.endswith((".png", ".gif")) else a for a in extra]
    args = ["render", str(scene_file), "-o", str(tmp_path / "out.png"), *extra]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert message in err
    assert "Traceback" not in err


def test_ray_figure(scene_file, tmp_path, capsys):
    path = tmp_path / "tree.png"
    assert main(["ray", str(scene_file), "--pixel", "24,12", "--figure", str(path)]) == 0
    assert f"wrote {path}" in capsys.readouterr().err
    with Image.open(path) as picture:
        assert picture.format == "PNG"
    assert main(["ray", str(scene_file), "--pixel", "24,12", "--figure",
                 str(tmp_path / "tree.xyz")]) == 2
    assert "unknown image extension" in capsys.readouterr().err
