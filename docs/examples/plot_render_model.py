"""
Render your own model
=====================

A glTF file rendered with no scene file: its nodes become named objects, its camera (or one
framing the model) and a light rig come with it. The Duck is one of the models in
``tests/data/models`` (Khronos glTF sample models; licences there).
"""

import dataclasses

import numpy as np

import pixelpath as pp

duck = pp.load_scene("../../tests/data/models/Duck.glb")   # run from docs/examples
scene = dataclasses.replace(duck, camera=duck.camera.with_size(240, 180))
print([obj.name for obj in scene.objects])

# %%
# The z-buffer with Phong shading, and the ray tracer with shadows. ``save`` encodes sRGB,
# as a model file's scene asks.

pp.render(scene).save("duck.png")
pp.render(scene, method="raytrace").save("duck-raytrace.png")

# %%
# What else a render holds: world-space normals, coverage and the object seen at each pixel.

img = pp.render(scene)
print(np.asarray(img).shape, img.depth.shape, np.unique(img.object_id))
pp.io.write_image("duck-normal.png", (img.normal + 1) / 2 * img.alpha[..., None])
