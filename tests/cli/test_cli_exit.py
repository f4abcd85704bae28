"""How the ``pixelpath`` command ends: at once after its work, its output and exit handlers done.

Each case runs the command in a process of its own, as a user's shell does, through
:func:`pixelpath.cli.run` (the console script and ``python -m pixelpath``), with ``os._exit``
wrapped so that the process says when it took the quick way out.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

PRELUDE = """
import atexit, os, sys
real_exit = os._exit
def quick_exit(code):
    print("quick exit", code, flush=True)
    real_exit(code)
os._exit = quick_exit
atexit.register(lambda: print("exit handler ran"))
"""


def run_command(argv: list[str], before: str = "") -> subprocess.CompletedProcess:
    """Run ``pixelpath ARGV`` through ``pixelpath.cli.run`` after the prelude and ``before``."""
    code = (f"{PRELUDE}{before}\nsys.argv = ['pixelpath', *{argv!r}]\n"
            "print('before the command', end=' ')\n"  # left in the buffer: flushed at the end
            "from pixelpath.cli import run\nrun()\n")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=False, timeout=300)


def test_a_render_ends_quickly_with_its_output_written(scene_file, tmp_path):
    # The render ran its kernels on pixelpath's thread pool, whose idle threads are stopped.
    out = tmp_path / "out.png"
    result = run_command(["render", str(scene_file), "-o", str(out), "--size", "32x24"])
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("before the command")
    assert f"wrote {out} (32x24" in result.stdout
    assert lines[-2:] == ["exit handler ran", "quick exit 0"]
    assert out.stat().st_size > 0


@pytest.mark.parametrize(("argv", "code"), [
    (["color", "0,0,255", "--to", "hsv"], 0),
    (["render", "no-such-scene.toml", "-o", "x.png"], 2),
])
def test_the_exit_status_is_the_commands(argv, code):
    result = run_command(argv)
    assert result.returncode == code, result.stderr
    assert result.stdout.splitlines()[-1] == f"quick exit {code}"
    assert "before the command" in result.stdout


def test_a_thread_still_running_is_waited_for():
    # Someone else's thread (a plug-in's, a user's script's) is not cut short: Python's own
    # exit joins it, as without pixelpath.
    before = ("import threading, time\n"
              "import pixelpath.cli as cli\n"
              "returned, command = threading.Event(), cli.main\n"
              "def main_then_signal(*args):\n"
              "    try:\n"
              "        return command(*args)\n"
              "    finally:\n"
              "        returned.set()\n"
              "cli.main = main_then_signal\n"
              "def late():\n"  # still running when the command is done
              "    returned.wait()\n"
              "    time.sleep(0.3)\n"
              "    print('thread finished', flush=True)\n"
              "threading.Thread(target=late).start()\n")
    result = run_command(["color", "0,0,255", "--to", "hsv"], before)
    assert result.returncode == 0, result.stderr
    assert "thread finished" in result.stdout and "exit handler ran" in result.stdout
    assert "quick exit" not in result.stdout
