"""
Perspective-correct texturing
=============================

A receding checkerboard floor with its texture coordinates interpolated affinely in screen
space (left) and perspective-correctly through 1/w (right): why the division by w matters.
"""

from pixelpath.figures.texturing import perspective_figure

perspective_figure(width=200, height=150).save("texturing.png")
