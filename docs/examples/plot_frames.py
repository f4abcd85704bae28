"""
Many frames
===========

The bundled showcase turns once in 120 frames (its ``[animation]`` table). ``render_frames``
renders any frames of it; given a ``dask.distributed.Client`` it spreads them over a cluster
(``pixelpath render --frames ... --workers N`` on the command line). Here, six small frames in
this process.
"""

import dataclasses

import numpy as np

import pixelpath as pp

scene = pp.load_scene(pp.scene.bundled_scene("showcase"))
small = dataclasses.replace(scene, camera=scene.camera.with_size(160, 100))
images = pp.render_frames(small, range(0, 120, 20))
strip = np.hstack([np.asarray(img) for img in images])
pp.io.write_image("turntable.png", strip)

# %%
# Each frame is a still scene of its own, and one frame's work is a pure function of plain
# arguments (``pixelpath.frames.render_frame``), which any executor can map:

print(small.at_frame(20).camera.eye)

# %%
# With Dask (the ``dask`` extra), the same call on a cluster, files written as frames finish::
#
#     from dask.distributed import Client
#     paths = pp.render_frames(small, range(120), Client(), out="spin/f_{frame:03d}.png")
