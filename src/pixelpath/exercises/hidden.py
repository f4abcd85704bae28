"""Hidden-surface exercises, registered in the order of the notes' chapter.

The topics live in four modules: :mod:`~pixelpath.exercises.hidden_space` (back faces and
the octree, solids in object space), :mod:`~pixelpath.exercises.hidden_screen` (the z-buffer
and the scan line, polygons on a small screen), :mod:`~pixelpath.exercises.hidden_warnock`
(Warnock's subdivision of such a screen) and
:mod:`~pixelpath.exercises.hidden_order` (the painter's depth sort and the BSP tree, orders of
drawing).

Examples
--------
>>> from pixelpath import exercises
>>> ex = exercises.make("z-buffer", seed=4)
>>> ex.check(ex.answer).correct
True
>>> len(ex.answer["frame"]), len(ex.answer["frame"][0])  # 6 rows of 8 pixels
(6, 8)
"""

from __future__ import annotations

from pixelpath.exercises import hidden_order as order
from pixelpath.exercises import hidden_screen as screen
from pixelpath.exercises import hidden_space as space
from pixelpath.exercises import hidden_warnock as warnock
from pixelpath.exercises.topics import register

_CHAPTER = "Hidden-surface elimination"

register("back-face", "Back-face elimination", _CHAPTER, space._pick_backface,
         space.solve_backface)

register("z-buffer", "Z-buffer", _CHAPTER, screen._pick_zbuffer, screen.solve_zbuffer)
register("scan-line", "Scan-line method", _CHAPTER, screen._pick_scanline,
         screen.solve_scanline)
register("painter", "The painter's algorithm", _CHAPTER, order._pick_painter,
         order.solve_painter)
register("bsp", "BSP trees", _CHAPTER, order._pick_bsp, order.solve_bsp)
register("warnock", "Warnock's area subdivision", _CHAPTER, warnock._pick_warnock,
         warnock.solve_warnock)
register("octree", "The octree method", _CHAPTER, space._pick_octree, space.solve_octree)
