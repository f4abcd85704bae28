"""The first-run notice: on a terminal before kernels compile, never when piped or quiet."""

from __future__ import annotations

import contextlib
import io

import pytest

from pixelpath import _warm
from pixelpath.cli._common import compile_kernels


class Terminal(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True


@pytest.fixture
def compiled(monkeypatch):
    """Stand-ins for the group compiler: every group cold, compiling records the request."""
    for variable in ("FORCE_COLOR", "TTY_INTERACTIVE", "TTY_COMPATIBLE"):
        monkeypatch.delenv(variable, raising=False)  # rich would take them over isatty()
    requests = []
    monkeypatch.setattr(_warm, "cold_groups", lambda groups, markers: list(groups))
    monkeypatch.setattr(_warm, "estimate_seconds", lambda groups, markers: 12.4)
    monkeypatch.setattr(_warm, "compile_groups", lambda groups, markers: requests.append(groups))
    return requests


@pytest.mark.parametrize(
    ("stream", "quiet", "shown"),
    [(Terminal(), False, True), (io.StringIO(), False, False), (Terminal(), True, False)],
    ids=["terminal", "piped", "terminal-quiet"],
)
def test_the_notice_shows_only_on_a_terminal_and_the_kernels_compile_either_way(
    compiled, monkeypatch, stream, quiet, shown
):
    monkeypatch.setattr("sys.stderr", stream)
    compile_kernels(["warnock"], ["phong"], quiet=quiet)
    expected = "compiling kernels for the first run, about 12 s; later runs are instant\n"
    assert stream.getvalue() == (expected if shown else "")
    # not told whether the scenes are plain: the passes for both kinds of surfaces
    assert compiled == [["front", "rows", "colours", "shade", "shade-lookups", "warnock"]]


def test_a_render_compiles_the_lookups_only_for_a_scene_that_has_them(
    compiled, tmp_path
):
    from pathlib import Path

    from pixelpath.cli import main

    duck = Path(__file__).parents[1] / "data" / "models" / "Duck.glb"
    for scene, lookups in (("showcase", False), (str(duck), True)):
        compiled.clear()
        assert main(["render", scene, "-o", str(tmp_path / "x.png"), "--size", "16x10",
                     "-q"]) == 0
        passes = (["depth-test-lookups", "rows", "colours", "back-lookups"] if lookups
                  else ["depth-test", "rows", "back"])
        assert compiled == [["front", *passes]]


def test_frames_compile_their_groups_first_unless_a_cluster_elsewhere_renders_them(
    compiled, tmp_path, monkeypatch
):
    from pixelpath.cli import _frames, main

    pattern = str(tmp_path / "f_{frame}.png")
    assert main(["render", "showcase", "--frames", "0:2", "-o", pattern, "--size", "16x10",
                 "-q"]) == 0
    assert compiled == [["front", "depth-test", "rows", "back"]]
    compiled.clear()
    # no scheduler here: the cluster (and the render) stand in, to see what compiles first
    monkeypatch.setattr(_frames, "cluster_for", lambda *args: contextlib.nullcontext())
    monkeypatch.setattr("pixelpath.frames.run_plan", lambda plan, client, advance: None)
    assert main(["render", "showcase", "--frames", "0:2", "-o", pattern, "--size", "16x10",
                 "-q", "--scheduler", "tcp://127.0.0.1:1"]) == 0
    assert compiled == []


def test_a_function_saying_whether_a_scene_needs_lookups_is_called_only_on_a_first_run(
    compiled, monkeypatch
):
    asked = []
    compile_kernels(["zbuffer"], ["phong"], lookups=lambda: asked.append(1) or True)
    assert asked == [1] and compiled == [["front", "depth-test-lookups", "rows", "colours",
                                          "back-lookups"]]
    monkeypatch.setattr(_warm, "cold_groups", lambda groups, markers: [])
    compile_kernels(["zbuffer"], ["phong"], lookups=lambda: asked.append(2) or True)
    assert asked == [1]


def test_a_warm_cache_means_no_notice_and_no_compiling(compiled, monkeypatch):
    monkeypatch.setattr(_warm, "cold_groups", lambda groups, markers: [])
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    compile_kernels(["zbuffer"])
    assert terminal.getvalue() == ""
    assert compiled == []


def test_without_a_writable_cache_no_group_counts_as_cold():
    assert _warm.cold_groups(["front", "back"], None) == []
    assert _warm.estimate_seconds(["front"], None, processes=1) == _warm.GROUPS["front"][1]
