"""
Back faces, wireframes and hidden lines
=======================================

The notes' figures "without HSE" and "with HSE": every edge of every polygon, then only the
edges the filled render shows. And back-face culling, the notes' first method, in object
space: with V from the eye into the scene, a face is drawn when N·V < 0.
"""

import numpy as np

import pixelpath as pp
from pixelpath.hsr.backface import front_facing

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
pp.render(scene, style="wireframe").save("wireframe.png")
pp.render(scene, style="hidden-line").save("hidden-line.png")

# %%
# Back-face test on two faces of a cube seen from +z: the face towards the eye is kept.

normals = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
points = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
print(front_facing(normals, points, eye=(0, 0, 5)))
