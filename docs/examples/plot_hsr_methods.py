"""
Seven hidden-surface methods, one picture
=========================================

The bundled showcase drawn by every method of the notes: the six raster methods decide
visibility in their own ways and agree up to pixels on silhouettes; the ray tracer adds
shadows, reflection and refraction. Back-face culling, the notes' first method, is on for all.
"""

import dataclasses

import pixelpath as pp
from pixelpath.figures.methods import methods_side_by_side

scene = pp.load_scene(pp.scene.bundled_scene("showcase"))
small = dataclasses.replace(scene, camera=scene.camera.with_size(160, 100))
methods_side_by_side(small).save("methods.png")

# %%
# Each method explains itself: ``explain=True`` returns a report beside the image, with the
# counts the notes' description of the method names.

image, report = pp.render(small, method="zbuffer", explain=True)
print(report)
