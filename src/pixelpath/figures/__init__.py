"""Pictures that teach: step-by-step frames and animations, shading comparisons.

Drawn with Pillow from the algorithms' own traces (no matplotlib needed):

* :mod:`pixelpath.figures.clipping`: Sutherland-Hodgman one (S, E) step per frame, and
  Weiler-Atherton's walk; ``trace.animate("steps.gif")``, ``trace.figure()`` on the traces;
* :mod:`pixelpath.figures.shading`: flat, Gouraud and Phong shading of one object side by
  side, and the highlight for several exponents n with the numbers of the notes' table;
* :mod:`pixelpath.figures.methods`: the figure and the animation of each hidden-surface
  method, from its rendered image and :class:`~pixelpath.report.Report` (``report.figure()``,
  ``report.animate("steps.gif")``), drawn by :mod:`pixelpath.figures.hidden_surfaces`;
* :mod:`pixelpath.figures.ray_tree`: a pixel's ray tree drawn over the scene
  (``ray_tree(scene, (x, y)).figure()``);
* :mod:`pixelpath.figures.texturing`: a receding checkerboard with affine and with
  perspective-correct texture coordinates side by side (``perspective_figure()``).

Examples
--------
>>> from pixelpath.clip import Rect, sutherland_hodgman
>>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6), trace=True)
>>> len(trace.frames())
17
"""

# The hidden-surface methods that have a figure and an animation (the keys of
# pixelpath.figures.methods.METHOD_FIGURES and METHOD_ANIMATIONS; here, so that the command
# line names them without importing the drawing code).
DRAWN_METHODS = ("zbuffer", "scanline", "warnock", "painter", "bsp", "octree")
