"""Hidden-surface elimination: the methods of the notes, by name.

``METHODS`` maps each method name accepted by :func:`pixelpath.render` to the function that
renders a frame with it, or to ``None`` for a method this version does not implement yet.
Object space vs image space (SPEC §9 errata): back-face elimination works in object space;
z-buffer, scan-line and area subdivision (Warnock) in image space; painter's, BSP and octree
order objects in object space and resolve visibility in image space.

Examples
--------
>>> from pixelpath.hsr import METHODS
>>> sorted(name for name, fn in METHODS.items() if fn is not None)
['zbuffer']
"""

from __future__ import annotations

from pixelpath.hsr import zbuffer
from pixelpath.hsr.backface import front_facing

__all__ = ["METHODS", "front_facing"]

METHODS = {
    "zbuffer": zbuffer.zbuffer,
    "scanline": None,
    "painter": None,
    "bsp": None,
    "warnock": None,
    "octree": None,
}
