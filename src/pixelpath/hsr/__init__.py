"""Hidden-surface elimination: the methods of the notes, one module each.

Object space vs image space (SPEC §9 errata): back-face elimination
(:mod:`~pixelpath.hsr.backface`) works in object space; the z-buffer
(:mod:`~pixelpath.hsr.zbuffer`), scan-line and area subdivision (Warnock) in image space;
painter's, BSP and octree order objects in object space and resolve visibility in image space.
All raster methods share the front end and the shading pass of :mod:`pixelpath.hsr.pipeline`
and differ only in how they decide which surface each pixel shows.

Examples
--------
>>> from pixelpath.hsr import front_facing
>>> front_facing([[0.0, 0.0, 1.0]], [[0.0, 0.0, 0.0]], eye=(0, 0, 5)).tolist()
[True]
"""

from __future__ import annotations

from pixelpath.hsr.backface import front_facing

__all__ = ["front_facing"]
