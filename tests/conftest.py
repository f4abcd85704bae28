"""Shared fixtures: the real meshes of ../shared/data, skipped cleanly when absent."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

# CI replays the same examples on every run (derandomize, no example database), so whether a
# submission lands does not depend on which random examples were drawn; runs on a developer's
# machine keep exploring new ones.
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

SHARED_MESHES = Path(__file__).resolve().parents[2] / "shared" / "data" / "meshes"


@pytest.fixture
def shared_mesh():
    """Return a function mapping a mesh file name to its path, skipping when it is absent."""

    def find(name: str) -> Path:
        path = SHARED_MESHES / name
        if not path.is_file():
            pytest.skip(f"{path} not found: the shared test meshes are not beside this checkout")
        return path

    return find


@pytest.fixture
def block(tmp_path) -> Path:
    """An STL block 1 wide (x), 2 deep (y) and 4 tall (z), centred on (3, -5, 2): a Z-up part."""
    import trimesh

    box = trimesh.creation.box(extents=(1.0, 2.0, 4.0))
    box.apply_translation((3.0, -5.0, 2.0))
    path = tmp_path / "block.stl"
    box.export(path)
    return path
