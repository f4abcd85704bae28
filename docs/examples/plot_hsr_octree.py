"""
The octree method
=================

The frame's triangles in an octree, walked front to back from the eye; a cell whose pixels
are all decided already is skipped. The figure shows the cells' screen footprints: leaves
drawn, cells skipped, cells culled.
"""

import pixelpath as pp

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="octree", explain=True)
print(report.summary)

# %%

report.figure().save("octree.png")
