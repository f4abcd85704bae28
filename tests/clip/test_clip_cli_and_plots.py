"""``pixelpath clip`` and the clipping pictures."""

from __future__ import annotations

import sys

import pytest

from pixelpath.cli import main
from pixelpath.clip import Rect, sutherland_hodgman

SUBJECT = "1,1 9,1 9,7 1,7"
NOTCHED = "0,0 6,0 6,6 0,6 0,4 4,4 4,2 0,2"


def test_clip_prints_the_clipped_polygon(capsys):
    assert main(["clip", SUBJECT, "--window", "2,2,8,6"]) == 0
    expected = "clipped polygon: (2, 6) -> (2, 2) -> (8, 2) -> (8, 6)"
    assert capsys.readouterr().out.strip() == expected


def test_clip_trace_prints_every_stage(capsys):
    assert main(["clip", SUBJECT, "--window", "2,2,8,6", "--trace"]) == 0
    out = capsys.readouterr().out
    for boundary in ("left", "right", "bottom", "top"):
        assert f"Clip against the {boundary} boundary" in out
    assert "(9, 7)  (1, 7)  in -> out   (2, 7)" in out


def test_clip_with_a_polygon_window(capsys):
    assert main(["clip", SUBJECT, "--window", "2,2 8,2 8,6 2,6"]) == 0
    assert "(2, 6)" in capsys.readouterr().out


def test_clip_notes_bridges_and_weiler_atherton_gives_pieces(capsys):
    assert main(["clip", NOTCHED, "--window=-1,-1,3,7"]) == 0
    assert "zero-width bridges" in capsys.readouterr().err
    assert main(["clip", NOTCHED, "--window=-1,-1,3,7", "--method", "weiler-atherton"]) == 0
    out = capsys.readouterr().out
    assert "piece 1: (0, 0) -> (3, 0) -> (3, 2) -> (0, 2)" in out
    assert "piece 2: (0, 4) -> (3, 4) -> (3, 6) -> (0, 6)" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        ([SUBJECT, "--window", "2,2,8"], "window: expected x,y pairs"),
        ([SUBJECT, "--window", "8,2,2,6"], "empty"),
        (["1,1 9,x", "--window", "2,2,8,6"], "not a pair of numbers"),
        ([SUBJECT, "--window", "0,0 4,2 0,4 1,2"], "reflex"),
        ([SUBJECT, "--window", "2,2,8,6", "--method", "weiler-atherton", "--trace"], "--trace"),
        (["1,1 2,2", "--window", "2,2,8,6"], "3 distinct"),
    ],
)
def test_clip_bad_input_exits_2_with_a_message(argv, message, capsys):
    assert main(["clip", *argv]) == 2
    assert message in capsys.readouterr().err


def test_plot_writes_pngs(tmp_path):
    pytest.importorskip("matplotlib")
    stages = tmp_path / "stages.png"
    assert main(["clip", SUBJECT, "--window", "2,2,8,6", "--plot", str(stages)]) == 0
    bridges = tmp_path / "bridges.png"
    argv = ["clip", NOTCHED, "--window=-1,-1,3,7", "--method", "weiler-atherton"]
    assert main([*argv, "--plot", str(bridges)]) == 0
    for path in (stages, bridges):
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bridges.png", "stages.png"]


def test_weiler_atherton_plot_with_a_concave_window(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    path = tmp_path / "pieces.png"
    argv = ["clip", "0,0 6,0 6,6 0,6", "--window", "1,1 5,1 5,5 3,2 1,5"]
    assert main([*argv, "--method", "weiler-atherton", "--plot", str(path)]) == 0
    assert "piece 1: (1, 1) -> (5, 1) -> (5, 5) -> (3, 2) -> (1, 5)" in capsys.readouterr().out
    assert path.read_bytes()[:4] == b"\x89PNG"


def test_plot_without_matplotlib_says_how_to_install_it(monkeypatch, tmp_path, capsys):
    from pixelpath.clip.plot import plot_trace

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7)], Rect(2, 2, 8, 6), trace=True)
    with pytest.raises(ImportError, match=r"pixelpath\[plot\]"):
        plot_trace(trace, tmp_path / "x.png")
    assert main(["clip", SUBJECT, "--window", "2,2,8,6", "--plot", str(tmp_path / "x.png")]) == 2
    assert "pixelpath[plot]" in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()
