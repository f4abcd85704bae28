"""
Polygon clipping
================

The notes' Sutherland-Hodgman example, traced stage by stage and drawn one step at a time,
then a concave subject that Sutherland-Hodgman joins with a zero-width bridge and
Weiler-Atherton cuts into separate pieces.
"""

import warnings

from pixelpath.clip import (
    Rect,
    ZeroWidthBridgeWarning,
    sutherland_hodgman,
    weiler_atherton,
    zero_width_bridges,
)

# %%
# The notes' example: the square (1, 1) - (9, 7) against the window x in [2, 8], y in [2, 6].
# The trace prints the table a student writes, one stage per boundary (Left, Right, Bottom,
# Top), S starting as the last vertex.

window = Rect(2, 2, 8, 6)
subject = [(1, 1), (9, 1), (9, 7), (1, 7)]
result, trace = sutherland_hodgman(subject, window, trace=True)
print(trace)

# %%
# Each stage's output drawn beside the subject and window, and one frame per (S, E) step:

trace.figure().save("stages.png")
trace.animate("steps.gif")

# %%
# A concave subject cut in two by the window: Sutherland-Hodgman returns one polygon whose
# pieces are joined along the window's edge (it warns); Weiler-Atherton returns the pieces.

comb = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
narrow = Rect(-1, -1, 3, 7)
with warnings.catch_warnings():
    warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
    joined = sutherland_hodgman(comb, narrow)
print(joined)
print("bridges:", zero_width_bridges(joined, narrow))

pieces, walk = weiler_atherton(comb, narrow, trace=True)
for number, piece in enumerate(pieces, 1):
    print(f"piece {number}:", piece.tolist())
walk.figure().save("pieces.png")
walk.animate("walk.gif")
