"""The raster pipeline: transforms, frustum clipping, scan conversion and shading.

* :mod:`~pixelpath.raster.transform`: world → camera → clip space, divide and viewport;
* :mod:`~pixelpath.raster.frustum`: Sutherland-Hodgman in homogeneous coordinates;
* :mod:`~pixelpath.raster.scan`: scan conversion with an edge table, an active edge list and
  the top-left fill rule, perspective-correct interpolation;
* :mod:`~pixelpath.raster.shading`: flat, Gouraud and Phong shading;
* :mod:`~pixelpath.raster.tessellate`: spheres and planes as triangles.

The hidden-surface methods that use them live in :mod:`pixelpath.hsr`.

Examples
--------
>>> import numpy as np
>>> from pixelpath.raster import scan_convert
>>> ids = scan_convert(np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]), [[0, 1, 2]], 4, 4)
>>> int((ids == 0).sum())  # the pixel centres strictly inside or on a top/left edge
6
"""

from pixelpath.raster.frustum import clip_to_frustum
from pixelpath.raster.scan import coverage, interpolate, scan_convert
from pixelpath.raster.transform import clip_to_screen, world_to_clip

__all__ = [
    "clip_to_frustum",
    "clip_to_screen",
    "coverage",
    "interpolate",
    "scan_convert",
    "world_to_clip",
]
