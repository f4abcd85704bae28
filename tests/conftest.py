"""Shared fixtures: the real meshes of ../shared/data, skipped cleanly when absent."""

from __future__ import annotations

from pathlib import Path

import pytest

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
