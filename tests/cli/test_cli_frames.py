"""``pixelpath render --frames/--tiles/--workers/--scheduler/--resume``."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.cli import main
from pixelpath.cli.render import load_scene_sized

SIZE = ["--size", "40x25"]


def _showcase():
    return load_scene_sized("showcase", "40x25")


def _expected(frame, folder):
    """The file of ``frame`` as Image.save writes it, at the frames' PNG level (1)."""
    from pixelpath.frames.work import encode

    return encode(pp.render(_showcase().at_frame(frame)), ".png", None, png_level=1)


def test_showcase_turntable_frames_out_of_the_box(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status = main(["render", "showcase", "--frames", "0:120:40", "-o", "spin/f_{frame:03d}.png",
                   *SIZE, "-q"])
    assert status == 0
    assert sorted(p.name for p in (tmp_path / "spin").iterdir()) == [
        "f_000.png", "f_040.png", "f_080.png"
    ]
    for frame in (0, 40, 80):
        assert (tmp_path / "spin" / f"f_{frame:03d}.png").read_bytes() == _expected(frame, tmp_path)


def test_many_frames_go_to_a_local_cluster_by_default(tmp_path, monkeypatch, capsys):
    import pixelpath.cli._frames as frames_cli

    monkeypatch.setattr(frames_cli, "TASKS_PER_CORE_FOR_A_CLUSTER", 1)  # 2 frames suffice
    monkeypatch.setattr(frames_cli, "available_cores", lambda: 2)
    pattern = str(tmp_path / "f_{frame}.png")
    assert main(["render", "showcase", "--frames", "3,7", "-o", pattern, *SIZE]) == 0
    assert "Dask cluster of 2 workers" in capsys.readouterr().err
    for frame in (3, 7):
        assert (tmp_path / f"f_{frame}.png").read_bytes() == _expected(frame, tmp_path)


def test_a_plain_render_draws_frame_zero(tmp_path):
    assert main(["render", "showcase", "-o", str(tmp_path / "plain.png"), *SIZE, "-q"]) == 0
    assert main(["render", "showcase", "--frames", "0", "-o", str(tmp_path / "f0.png"),
                 *SIZE, "-q"]) == 0
    plain, frame = (pp.io.read_image(tmp_path / name) for name in ("plain.png", "f0.png"))
    assert np.array_equal(plain, frame)  # the same pixels, by another PNG encoder


def test_png_level_sets_the_compression_of_frames_and_of_a_single_image(tmp_path):
    for level in ("0", "9"):
        assert main(["render", "showcase", "--frames", "0,1", "-o", str(tmp_path / "f{frame}.png"),
                     *SIZE, "-q", "--png-level", level]) == 0
        assert main(["render", "showcase", "-o", str(tmp_path / f"one{level}.png"), *SIZE, "-q",
                     "--png-level", level, "--aov", "normal"]) == 0
        assert (tmp_path / f"one{level}.png").read_bytes() == (tmp_path / "f0.png").read_bytes()
    # the picture and its AOVs' PNG files alike: stored, or compressed
    for name in ("one{}.png", "one{}.normal.png"):
        assert len((tmp_path / name.format(0)).read_bytes()) > 3 * 40 * 25
        assert len((tmp_path / name.format(9)).read_bytes()) < 3 * 40 * 25


@pytest.mark.parametrize("level", ["10", "-1", "fast"])
def test_a_bad_png_level_is_refused(level, capsys):
    with pytest.raises(SystemExit):
        main(["render", "showcase", "-o", "x.png", "--png-level", level])
    assert "--png-level" in capsys.readouterr().err


def test_tiles_on_one_worker_equal_the_plain_render(tmp_path):
    assert main(["render", "showcase", "-o", str(tmp_path / "tiled.png"), "--tiles", "3x2",
                 "--workers", "1", "--ssaa", "2", *SIZE, "-q", "--png-level", "1"]) == 0
    assert main(["render", "showcase", "-o", str(tmp_path / "plain.png"), "--ssaa", "2",
                 *SIZE, "-q", "--png-level", "1"]) == 0
    assert (tmp_path / "tiled.png").read_bytes() == (tmp_path / "plain.png").read_bytes()


def test_resume_reports_what_it_skipped(tmp_path, capsys):
    pattern = str(tmp_path / "f_{frame}.png")
    pp.render_frames(_showcase(), [0, 5], out=pattern)
    assert main(["render", "showcase", "--frames", "0,5", "-o", pattern, *SIZE, "--resume"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "wrote 0 frames" in out and "skipped 2 complete on disk" in out


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--frames", "0:130", "-o", "f_{frame}.png"], "frame 120 is outside the animation"),
        (["--frames", "0:3", "-o", "f.png"], r"put {frame} in it"),
        (["--frames", "3:1", "-o", "f_{frame}.png"], "holds no frame"),
        (["--frames", "zero", "-o", "f_{frame}.png"], "--frames must look like 0:120"),
        (["--tiles", "41x1", "-o", "f.png"], "at least one pixel wide"),
        (["--tiles", "4", "-o", "f.png"], "--tiles must look like 4x4"),
        (["--workers", "0", "-o", "f.png"], "--workers must be at least 1"),
        (["--workers", "2", "--scheduler", "tcp://a:1", "-o", "f.png"], "not both"),
        (["--frames", "0:2", "--explain", "-o", "f_{frame}.png"], "--explain describes one"),
        (["--resume", "--method", "zbufer", "-o", "f.png"], "invalid choice"),
    ],
)
def test_bad_requests_fail_before_any_work(options, message, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    try:
        status = main(["render", "showcase", *SIZE, *options])
    except SystemExit as exc:  # argparse's own errors
        status = exc.code
    assert status == 2
    captured = capsys.readouterr()
    assert message in " ".join((captured.err + captured.out).split())
    assert not list(tmp_path.iterdir())


@pytest.mark.slow  # waits out the 5 s the connection is given
def test_an_unreachable_scheduler_fails_within_seconds(tmp_path, capsys):
    pattern = str(tmp_path / "f_{frame}.png")
    status = main(["render", "showcase", "--frames", "0:2", "-o", pattern, *SIZE,
                   "--scheduler", "tcp://127.0.0.1:9"])
    assert status == 2
    err = " ".join(capsys.readouterr().err.split())
    assert "could not reach the Dask scheduler at tcp://127.0.0.1:9 within 5 s" in err
    assert not list(tmp_path.iterdir())
