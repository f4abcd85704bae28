"""The package itself: fast import with nothing compiled, the command line (the kernel cache:
test_environment.py)."""

from __future__ import annotations

import subprocess
import sys

import pytest

import pixelpath
from pixelpath._warm import kernel_modules
from pixelpath.cli import COMMANDS, build_parser, main


def python(code: str) -> str:
    """Run ``code`` in a fresh interpreter and return what it printed."""
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    return result.stdout.strip()


def test_import_compiles_nothing_and_does_not_import_numba():
    heavy = "('numba', 'llvmlite', 'trimesh', 'starlette', 'uvicorn')"
    code = f"import sys, pixelpath; print([m for m in sys.modules if m.startswith({heavy})])"
    loaded = python(code)
    assert loaded == "[]"


def test_public_names_resolve_lazily():
    for name in pixelpath.__all__:
        assert getattr(pixelpath, name) is not None
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        _ = pixelpath.nope


def test_every_command_is_registered_with_an_example(capsys):
    parser = build_parser()
    subparsers = next(a for a in parser._actions if a.dest == "command")
    assert list(subparsers.choices) == list(COMMANDS)
    for name in COMMANDS:
        with pytest.raises(SystemExit) as exit_info:
            main([name, "--help"])
        assert exit_info.value.code == 0
        help_text = capsys.readouterr().out
        assert f"examples:\n  pixelpath {name}" in help_text


def test_top_level_help_and_version(capsys):
    assert main([]) == 2
    listing = capsys.readouterr().out
    assert all(name in listing for name in COMMANDS)
    with pytest.raises(SystemExit):
        main(["--version"])
    assert capsys.readouterr().out.strip() == f"pixelpath {pixelpath.__version__}"


def test_python_dash_m_runs_the_cli():
    result = subprocess.run(
        [sys.executable, "-m", "pixelpath", "color", "0,0,255", "--to", "hsv"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "240, 1, 1" in result.stdout


@pytest.mark.slow
def test_warmup_compiles_every_kernel_group(capsys):
    assert main(["warmup"]) == 0
    out = capsys.readouterr().out
    assert "warmed up" in out
    # One row per kernel module, then the total; a second run only loads from the cache.
    rows = [line.split() for line in out.splitlines()]
    modules = [row[0] for row in rows if row and row[0].startswith("pixelpath.")]
    assert sorted(modules) == sorted(kernel_modules())
    assert main(["warmup"]) == 0
    assert " 0 specializations compiled" in capsys.readouterr().out
