"""The demo scenes shipped inside the package (``pixelpath/data/scenes/*.toml``)."""

from __future__ import annotations

from importlib import resources
from pathlib import Path


def bundled_scenes() -> dict[str, Path]:
    """Return the bundled scene files by name (the file stem), sorted by name.

    Examples
    --------
    >>> from pixelpath.scene import bundled_scenes, load_scene
    >>> scenes = bundled_scenes()
    >>> all(path.suffix == ".toml" for path in scenes.values())
    True
    """
    folder = resources.files("pixelpath") / "data" / "scenes"
    if not folder.is_dir():
        return {}
    files = (Path(str(entry)) for entry in folder.iterdir() if entry.name.endswith(".toml"))
    return {path.stem: path for path in sorted(files)}


def bundled_scene(name: str) -> Path:
    """Return the path of the bundled scene ``name``; a ValueError lists the valid names.

    Examples
    --------
    >>> from pixelpath.scene import bundled_scene
    >>> bundled_scene("no such scene")
    Traceback (most recent call last):
    ...
    ValueError: unknown bundled scene 'no such scene'; ...
    """
    scenes = bundled_scenes()
    if name not in scenes:
        available = ", ".join(scenes) or "none installed"
        raise ValueError(f"unknown bundled scene {name!r}; available: {available}")
    return scenes[name]
