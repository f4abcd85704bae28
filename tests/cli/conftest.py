"""Fixtures of the command-line tests."""

from __future__ import annotations

import pytest
from box_scene import SCENE


@pytest.fixture
def scene_file(tmp_path):
    """The cube scene of :mod:`box_scene`, written to a file."""
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path
