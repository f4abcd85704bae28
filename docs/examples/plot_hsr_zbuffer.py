"""
The z-buffer
============

The depth-buffer method on a small scene of 53 polygons: the colour buffer, the depth
buffer and how many triangles were depth-tested at each pixel, band by band as the kernel
renders them. The scene file is ``docs/scenes/hidden-surfaces.toml``.
"""

import numpy as np

import pixelpath as pp

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="zbuffer", explain=True)
print(report.summary)

# %%
# ``Image.depth`` holds the distance along the viewing axis (``inf`` where nothing was drawn):
# the z-buffer's own contents.

drawn = np.isfinite(image.depth)
print("nearest", image.depth.min(), "farthest drawn", image.depth[drawn].max())

# %%
# The fill, band by band:

report.animate("zbuffer.gif")
report.figure().save("zbuffer.png")
