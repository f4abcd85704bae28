"""
The scan-line method
====================

Down the image line by line, with the edge table and the active edge list: beside the
picture, per line, the length of the active edge list, the spans and the spans that needed
a depth comparison.
"""

import pixelpath as pp

scene = pp.load_scene("../scenes/hidden-surfaces.toml")   # run from docs/examples
image, report = pp.render(scene, method="scanline", explain=True)
print(report.summary)

# %%

report.animate("scanline.gif")
report.figure().save("scanline.png")
