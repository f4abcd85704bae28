"""The Examples sections of the raster, hsr, image and render docstrings run as shown."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "pixelpath.clip._halfspace",
    "pixelpath.cli.render",
    "pixelpath.hsr",
    "pixelpath.hsr.backface",
    "pixelpath.hsr.zbuffer",
    "pixelpath.image",
    "pixelpath.raster",
    "pixelpath.raster.frustum",
    "pixelpath.raster.scan",
    "pixelpath.raster.shading",
    "pixelpath.raster.tessellate",
    "pixelpath.raster.transform",
    "pixelpath.renderer",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
