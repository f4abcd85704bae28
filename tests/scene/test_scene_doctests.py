"""The Examples sections of the scene package's docstrings run and give what they show."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "pixelpath.scene",
    "pixelpath.scene.bundled",
    "pixelpath.scene.camera",
    "pixelpath.scene.lights",
    "pixelpath.scene.loader",
    "pixelpath.scene.material",
    "pixelpath.scene.mesh",
    "pixelpath.scene.primitives",
    "pixelpath.scene.procedural",
    "pixelpath.scene.scene",
    "pixelpath.scene.schema",
    "pixelpath.scene.transform",
    "pixelpath.io.meshes",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    failed, attempted = doctest.testmod(module, optionflags=flags, verbose=False)
    assert attempted > 0 and failed == 0
