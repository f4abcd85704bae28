"""
The BSP tree
============

A binary space partition built once from the objects, independent of the camera, then
traversed from the eye: far side, the node's polygons, near side. The figure numbers each
node by when it is painted.
"""

import dataclasses

import pixelpath as pp
from pixelpath.hsr.bsp import build_tree

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="bsp", explain=True)
report.figure().save("bsp.png")

# %%
# The tree is kept for the same objects: another camera reuses it.

tree = build_tree(scene)
print(tree)
side = dataclasses.replace(scene, camera=pp.Camera(eye=(5, 1.5, 0), target=(0, 0.5, 0),
                                                   width=160, height=120))
image, report = pp.render(side, method="bsp", explain=True)
print(report.summary["tree"])
