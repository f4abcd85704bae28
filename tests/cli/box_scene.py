"""A scene file the command-line tests share: a cube seen straight on.

Its front face (z = 1) fills the middle of a 24x16 picture, 4 units from the eye, lit by a point
light at (2, 3, 4), on a dark blue background.
"""

from __future__ import annotations

import textwrap

SCENE = textwrap.dedent(
    """\
    background = [0, 0, 0.5]

    [camera]
    eye = [0, 0, 5]
    target = [0, 0, 0]
    width = 24
    height = 16

    [[lights]]
    type = "point"
    position = [2, 3, 4]

    [[objects]]
    type = "box"
    minimum = [-1, -1, -1]
    maximum = [1, 1, 1]
    """
)
