"""
The painter's algorithm
=======================

Newell, Newell and Sancha's depth sort: the polygons sorted by depth, reordered or split
where the notes' overlap tests say so, then painted back to front with no depth test. The
two crossed panels of the scene cut through each other, so one is split.
"""

import pixelpath as pp

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="painter", explain=True)
print(report.summary["comparisons"], "comparisons,", report.summary["splits"], "splits")

# %%
# The order of painting, two polygons a frame; the pieces made by splitting are outlined:

report.animate("painter.gif")
report.figure().save("painter.png")
