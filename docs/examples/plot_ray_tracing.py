"""
Ray tracing
===========

The notes' recursive ray tracer on the bundled showcase (shadows, a chrome sphere, a glass
one), one pixel's ray tree as data and as a picture, and the ray geometry of the notes:
ray-sphere, ray-plane, refraction by Snell's law.
"""

import dataclasses

import pixelpath as pp
from pixelpath import raytrace

scene = pp.load_scene(pp.scene.bundled_scene("showcase"))
small = dataclasses.replace(scene, camera=scene.camera.with_size(240, 150))
pp.render(small, method="raytrace", max_depth=4).save("showcase-raytrace.png")

# %%
# One pixel's tree: the eye ray hits the chrome sphere, a reflected ray the box behind it.
# The tree runs the renderer's own kernel, so it adds up to the rendered pixel.

tree = raytrace.ray_tree(small, (106, 94))
print(tree.root.t, tree.root.object)
tree.figure().save("ray-tree.png")

# %%
# The geometry, one ray at a time (``t`` in units of the direction's length):

print(raytrace.ray_sphere((0, 0, 5), (0, 0, -1), (0, 0, 0), 1.0))    # 4.0
print(raytrace.ray_plane((0, 1, 0), (0, -1, 0), (0, 0, 0), (0, 1, 0)))  # 1.0
print(raytrace.refract((0.6, -0.8, 0.0), (0, 1, 0), 1 / 1.5))        # into glass
print(raytrace.refract((0.8, -0.6, 0.0), (0, 1, 0), 1.5))            # None: total reflection
