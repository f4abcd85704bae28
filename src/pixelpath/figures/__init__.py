"""Pictures that teach: step-by-step frames and animations, shading comparisons.

Drawn with Pillow from the algorithms' own traces (no matplotlib needed):

* :mod:`pixelpath.figures.clipping`: Sutherland-Hodgman one (S, E) step per frame, and
  Weiler-Atherton's walk; ``trace.animate("steps.gif")``, ``trace.figure()`` on the traces;
* :mod:`pixelpath.figures.shading`: flat, Gouraud and Phong shading of one object side by
  side, and the highlight for several exponents n with the numbers of the notes' table;
* :mod:`pixelpath.figures.methods`: the figure of each hidden-surface method, from its
  rendered image and :class:`~pixelpath.report.Report`.

Examples
--------
>>> from pixelpath.clip import Rect, sutherland_hodgman
>>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6), trace=True)
>>> len(trace.frames())
17
"""
