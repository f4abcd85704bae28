"""pixelpath: the classic rendering pipeline of a graphics course, headless on the CPU.

Submodules and the scene/rendering names load on first use, so ``import pixelpath`` is quick
and compiles nothing (Numba itself is imported only when a kernel is first needed).

Examples
--------
>>> import pixelpath as pp
>>> pp.color.rgb_to_hsv([1.0, 1.0, 0.0]).tolist()
[60.0, 1.0, 1.0]
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

_SUBMODULES = (
    "color", "clip", "lighting", "scene", "raster", "hsr", "io", "frames", "raytrace", "exercises"
)

# Public name -> module that defines it, imported on first access.
_LAZY_NAMES = {
    "Camera": "pixelpath.scene",
    "Material": "pixelpath.scene",
    "PointLight": "pixelpath.scene",
    "DirectionalLight": "pixelpath.scene",
    "Sphere": "pixelpath.scene",
    "Plane": "pixelpath.scene",
    "Box": "pixelpath.scene",
    "Mesh": "pixelpath.scene",
    "Scene": "pixelpath.scene",
    "Texture": "pixelpath.scene",
    "load_scene": "pixelpath.scene",
    "Image": "pixelpath.image",
    "render": "pixelpath.renderer",  # a module named "render" would shadow the function
    "render_frames": "pixelpath.frames",
    "render_views": "pixelpath.frames",
}

__all__ = [
    "Box",
    "Camera",
    "DirectionalLight",
    "Image",
    "Material",
    "Mesh",
    "Plane",
    "PointLight",
    "Scene",
    "Sphere",
    "Texture",
    "clip",
    "color",
    "exercises",
    "frames",
    "hsr",
    "io",
    "lighting",
    "load_scene",
    "raster",
    "raytrace",
    "render",
    "render_frames",
    "render_views",
    "scene",
    "warmup",
]

if TYPE_CHECKING:
    from pixelpath import (
        clip,
        color,
        exercises,
        frames,
        hsr,
        io,
        lighting,
        raster,
        raytrace,
        scene,
    )
    from pixelpath.frames import render_frames, render_views
    from pixelpath.image import Image
    from pixelpath.renderer import render
    from pixelpath.scene import (
        Box,
        Camera,
        DirectionalLight,
        Material,
        Mesh,
        Plane,
        PointLight,
        Scene,
        Sphere,
        Texture,
        load_scene,
    )


def __getattr__(name: str) -> Any:
    if name in _SUBMODULES:
        return importlib.import_module(f"pixelpath.{name}")
    if name in _LAZY_NAMES:
        return getattr(importlib.import_module(_LAZY_NAMES[name]), name)
    raise AttributeError(f"module 'pixelpath' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


def warmup() -> int:
    """Compile every Numba kernel now, so that later calls start at full speed.

    Compiled code is cached on disk (see :func:`pixelpath._jit.cache_dir`), so this is
    needed once per installation; ``pixelpath warmup`` does the same from the shell.

    Returns
    -------
    int
        The number of kernel modules warmed up.

    Examples
    --------
    >>> import pixelpath as pp
    >>> pp.warmup() > 0
    True
    """
    from pixelpath._precompiled import markers
    from pixelpath._warm import run_warmups

    return len(run_warmups(markers()))
