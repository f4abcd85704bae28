"""Every Examples section in pixelpath's docstrings runs as shown (one test per module)."""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import pixelpath

# Modules that run a program when imported, not a library.
NOT_IMPORTABLE = {"pixelpath.__main__"}

MODULES = sorted(
    {"pixelpath"}
    | {
        info.name
        for info in pkgutil.walk_packages(pixelpath.__path__, prefix="pixelpath.")
        if info.name not in NOT_IMPORTABLE
    }
)


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # examples that write files write them here
    module = importlib.import_module(name)
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testmod(module, optionflags=flags, verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"
