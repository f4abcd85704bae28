"""Reading animations back in the figure tests."""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageSequence


def gif_frames(path) -> list[np.ndarray]:
    """Every frame of the GIF at ``path`` as an (h, w, 3) uint8 array, in order."""
    with Image.open(path) as gif:
        return [np.asarray(frame.convert("RGB")) for frame in ImageSequence.Iterator(gif)]
