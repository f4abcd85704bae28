"""``pixelpath render`` and ``pixelpath demo``: files written, options, clean errors."""

from __future__ import annotations

import logging
import subprocess
import sys
import warnings

import numpy as np
import pytest
from box_scene import SCENE

from pixelpath.cli import main
from pixelpath.io import read_image
from pixelpath.scene import bundled_scenes


def test_render_writes_the_image(scene_file, tmp_path, capsys):
    out = tmp_path / "out.png"
    assert main(["render", str(scene_file), "-o", str(out)]) == 0
    image = read_image(out)
    assert image.shape == (16, 24, 3)
    assert image[0, 0].tolist() == pytest.approx([0, 0, 128 / 255])  # background
    assert image[8, 12].sum() > 0
    printed = capsys.readouterr().out
    assert "wrote" in printed
    assert "nothing was drawn" not in printed


@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_a_picture_of_back_faces_alone_says_why_it_is_empty(tmp_path, capsys, method):
    # One triangle wound clockwise as the framing camera (in front, +z) sees it: a back face.
    sheet = tmp_path / "sheet.obj"
    sheet.write_text("v 0 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3\n")
    out = tmp_path / "sheet.png"
    argv = ["render", str(sheet), "-o", str(out), "--size", "32x24", "--method", method]
    assert main(argv) == 0
    assert not read_image(out).any()
    assert "nothing was drawn" in capsys.readouterr().out
    assert main([*argv, "--no-cull"]) == 0
    assert read_image(out).any()
    assert "nothing was drawn" not in capsys.readouterr().out


def test_an_empty_picture_with_back_faces_drawn_blames_the_view():
    from pixelpath.cli.render import empty_image_hint
    from pixelpath.image import Image

    blank = Image(np.zeros((2, 3, 3)))
    assert "--no-cull" not in empty_image_hint(blank, drew_back_faces=True)
    assert "--no-cull" in empty_image_hint(blank, drew_back_faces=False)
    drawn = Image(np.zeros((2, 3, 3)), object_id=np.zeros((2, 3), dtype=np.int32))
    assert empty_image_hint(drawn, drew_back_faces=False) is None


def test_render_options(scene_file, tmp_path):
    out = tmp_path / "flat.png"
    argv = ["render", str(scene_file), "-o", str(out), "--method", "zbuffer",
            "--shading", "flat", "--size", "30x20", "--ssaa", "2", "--no-cull", "-q"]
    assert main(argv) == 0
    image = read_image(out)
    assert image.shape == (20, 30, 3)
    # The box's front face is flat-shaded: one value over its interior.
    face = image[8:12, 13:17]
    assert np.all(face == face[0, 0])


def test_render_a_bundled_scene_by_name(tmp_path):
    name = sorted(bundled_scenes())[0]
    out = tmp_path / "b.png"
    assert main(["render", name, "-o", str(out), "--size", "32x20", "-q"]) == 0
    assert read_image(out).shape == (20, 32, 3)


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--size", "big"], "--size"),
        (["--size", "0x10"], "--size"),
        (["--ssaa", "0"], "ssaa"),
    ],
)
def test_render_bad_options_exit_2(scene_file, tmp_path, capsys, extra, message):
    assert main(["render", str(scene_file), "-o", str(tmp_path / "x.png"), *extra]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()


def test_render_load_errors_name_the_file(tmp_path, capsys):
    broken = tmp_path / "broken.toml"
    broken.write_text(SCENE.replace("minimum", "minimun"))
    assert main(["render", str(broken), "-o", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err
    assert "broken.toml" in err and "minimun" in err
    assert main(["render", str(tmp_path / "none.toml"), "-o", str(tmp_path / "x.png")]) == 2
    assert "not found" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("name", "extra", "message"),
    [
        ("x.xyz", [], "unknown image extension '.xyz'"),
        ("x.jpg", ["--transparent"], ".jpg files have no alpha channel; write .png for RGBA"),
    ],
)
def test_an_output_it_cannot_write_fails_before_rendering(scene_file, tmp_path, capsys,
                                                          monkeypatch, name, extra, message):
    import pixelpath.renderer

    def no_render(*args, **kwargs):
        raise AssertionError("rendered before the output was checked")

    monkeypatch.setattr(pixelpath.renderer, "render", no_render)
    assert main(["render", str(scene_file), "-o", str(tmp_path / name), *extra]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / name).exists()


def test_a_model_trimesh_cannot_read_gives_one_error_and_no_traceback(tmp_path, capsys):
    # trimesh logs the picture it cannot open with a traceback; the command shows its own error
    (tmp_path / "bad.png").write_bytes(bytes(range(256)))
    (tmp_path / "t.ply").write_text(
        "ply\nformat ascii 1.0\ncomment TextureFile bad.png\nelement vertex 3\n"
        "property float x\nproperty float y\nproperty float z\nproperty float s\n"
        "property float t\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n"
    )
    # In a process of its own: pytest's log capture would stand in for the handler checked here
    done = subprocess.run(
        [sys.executable, "-m", "pixelpath", "render", str(tmp_path / "t.ply"), "-o",
         str(tmp_path / "t.png")], capture_output=True, text=True, check=False,
    )
    assert done.returncode == 2
    assert "t.ply: the texture 'bad.png' is not a picture pixelpath can read" in done.stderr
    assert "Traceback" not in done.stderr and "unable to load image" not in done.stderr
    assert main(["render", str(tmp_path / "t.ply"), "-o", str(tmp_path / "t.png")]) == 2
    assert "bad.png" in capsys.readouterr().err
    assert not any(isinstance(handler, logging.NullHandler)  # the command's is gone after it
                   for handler in logging.getLogger("trimesh").handlers)


def test_render_into_a_missing_folder_fails_cleanly(scene_file, tmp_path, capsys):
    assert main(["render", str(scene_file), "-o", str(tmp_path / "no" / "x.png")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_demo_renders_every_bundled_scene(tmp_path, capsys):
    folder = tmp_path / "demo"
    assert main(["demo", "-o", str(folder), "--size", "32x20", "--ssaa", "1", "--quick",
                 "-q"]) == 0
    written = sorted(p.name for p in folder.iterdir())
    assert written == sorted(f"{name}.png" for name in bundled_scenes())
    assert len(written) >= 2
    for path in folder.iterdir():
        assert read_image(path).shape == (20, 32, 3)
    out = capsys.readouterr().out
    assert all(name in out for name in written)


def test_demo_all_shadings(tmp_path):
    folder = tmp_path / "all"
    assert main(["demo", "-o", str(folder), "--shading", "all", "--size", "16x12",
                 "--ssaa", "1", "--quick", "-q"]) == 0
    names = {p.name for p in folder.iterdir()}
    for scene in bundled_scenes():
        assert {f"{scene}-{s}.png" for s in ("flat", "gouraud", "phong")} <= names


def test_demo_output_must_be_a_folder(tmp_path, capsys):
    file = tmp_path / "file"
    file.write_text("")
    assert main(["demo", "-o", str(file)]) == 2
    assert "folder" in capsys.readouterr().err


def test_render_explain_prints_the_pipeline_counts(scene_file, tmp_path, capsys):
    # A box seen from the front: 12 triangles, the 6 of the three hidden faces are culled.
    out = tmp_path / "e.png"
    assert main(["render", str(scene_file), "-o", str(out), "--explain", "-q"]) == 0
    text = capsys.readouterr().out
    for stage in ("triangles", "back faces culled", "triangles scan-converted", "pixels covered"):
        assert stage in text
    assert out.is_file()


def test_warnings_read_like_the_errors(tmp_path):
    """A warning while a command runs names the command, not pixelpath's source line (run as
    a user runs it: pytest records warnings in its own process instead of showing them)."""
    (tmp_path / "part.mtl").write_text("newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd missing.png\n")
    (tmp_path / "part.obj").write_text("mtllib part.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nusemtl wood\nf 1/1 2/2 3/3\n")
    argv = [sys.executable, "-m", "pixelpath", "render", str(tmp_path / "part.obj"), "-o",
            str(tmp_path / "out.png"), "--size", "16x12", "-q"]
    result = subprocess.run(argv, capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith("pixelpath render: warning: ")
    assert "'missing.png' not found" in result.stderr and ".py:" not in result.stderr


def test_the_warning_format_is_restored(scene_file, tmp_path):
    formatting = warnings.formatwarning
    assert main(["render", str(scene_file), "-o", str(tmp_path / "out.png"), "-q"]) == 0
    assert warnings.formatwarning is formatting
