"""The first-run notice: printed on a terminal before a cold command, never when piped."""

from __future__ import annotations

import io
import json

import pytest

from pixelpath import _cache, _firstrun
from pixelpath._firstrun import ESTIMATED_SECONDS, FirstRun, announce, for_command
from pixelpath.cli import main

STAMP = "a" * 64


class Terminal(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True


def test_a_need_is_cold_until_it_finished_once(tmp_path):
    run = FirstRun("render:zbuffer:phong", tmp_path, STAMP)
    assert run.cold
    run.record(3.0)
    assert not run.cold
    assert FirstRun("render:zbuffer:phong", tmp_path, STAMP).cold is False
    # Other kernel variants, and the same need after the kernel sources changed, are cold.
    assert FirstRun("render:painter:flat", tmp_path, STAMP).cold
    assert FirstRun("render:zbuffer:phong", tmp_path, "b" * 64).cold


def test_warmup_makes_every_need_warm(tmp_path):
    FirstRun("warmup", tmp_path, STAMP).record(40.0)
    assert not FirstRun("demo", tmp_path, STAMP).cold
    assert not FirstRun("render:warnock:gouraud", tmp_path, STAMP).cold


def test_without_a_disk_cache_every_run_is_cold(tmp_path):
    run = FirstRun("demo", None, STAMP)
    run.record(9.0)
    assert run.cold


def test_the_notice_quotes_the_last_measured_cold_run_else_the_estimate(tmp_path):
    first = FirstRun("demo", tmp_path, STAMP)
    assert first.expected_seconds() == ESTIMATED_SECONDS["demo"]
    first.record(12.4)
    after_an_upgrade = FirstRun("demo", tmp_path, "c" * 64)
    assert after_an_upgrade.notice() == (
        "compiling kernels for the first run, about 12 s; later runs are instant"
    )
    # A warm run's time says nothing about compiling: it is not kept.
    FirstRun("demo", tmp_path, STAMP).record(0.5)
    assert after_an_upgrade.expected_seconds() == 12.4


def test_corrupt_marker_files_count_as_cold_and_are_replaced(tmp_path):
    run = FirstRun("demo", tmp_path, STAMP)
    (tmp_path / "first-runs.json").write_text("{not json")
    (tmp_path / f"warm-{STAMP[:20]}.json").write_text("[1, 2]")
    assert run.cold
    assert run.expected_seconds() == ESTIMATED_SECONDS["demo"]
    run.record(7.0)
    assert not run.cold
    assert json.loads((tmp_path / "first-runs.json").read_text()) == {"demo": 7.0}


@pytest.mark.parametrize(
    ("stream", "cold", "printed"),
    [(Terminal(), True, True), (io.StringIO(), True, False), (Terminal(), False, False)],
    ids=["terminal-cold", "piped-cold", "terminal-warm"],
)
def test_announce_only_on_a_terminal_when_cold(tmp_path, stream, cold, printed):
    run = FirstRun("demo", tmp_path, STAMP)
    if not cold:
        run.record(1.0)
    assert announce(run, stream) is printed
    text = stream.getvalue()
    assert ("compiling kernels for the first run" in text) is printed
    assert text == (run.notice() + "\n" if printed else "")


def test_commands_that_compile_nothing_have_no_first_run():
    assert for_command("info", {"scene": "x.toml"}) is None
    assert announce(None, Terminal()) is False


def test_render_needs_are_keyed_by_the_options_that_choose_kernels():
    run = for_command("render", {"method": "zbuffer", "shading": "phong", "size": "64x48"})
    assert run.need == "render:zbuffer:phong"


@pytest.fixture
def marker_folder(tmp_path, monkeypatch):
    """Point the CLI's markers at an empty folder (the kernels keep their real cache)."""
    monkeypatch.setattr(_cache, "writable_cache_dir", lambda: tmp_path)
    return tmp_path


def test_cli_prints_the_notice_on_a_terminal_for_a_cold_command_then_not(
    marker_folder, monkeypatch, capsys
):
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["color", "255,255,0", "--to", "hsv"]) == 0
    assert terminal.getvalue().startswith("compiling kernels for the first run, about ")
    assert "compiling" not in capsys.readouterr().out
    again = Terminal()
    monkeypatch.setattr("sys.stderr", again)
    assert main(["color", "255,255,0", "--to", "hsv"]) == 0
    assert again.getvalue() == ""


def test_cli_stays_silent_when_stderr_is_not_a_terminal(marker_folder, capsys):
    assert main(["color", "255,255,0", "--to", "hsv"]) == 0
    assert capsys.readouterr().err == ""
    # The run still counts: the command is warm afterwards.
    assert not _firstrun.for_command("color", {}).cold
