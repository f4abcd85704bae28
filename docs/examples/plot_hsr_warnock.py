"""
Warnock's area subdivision
==========================

From the whole image down: an area with no polygon, one polygon, or a surrounding polygon in
front of all others is decided whole; any other area is cut in four. One frame per level, the
areas coloured by how they were decided.
"""

import pixelpath as pp

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="warnock", explain=True)
print(report)

# %%

report.animate("warnock.gif")
report.figure().save("warnock.png")
