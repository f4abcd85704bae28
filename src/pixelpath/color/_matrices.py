"""Matrices of the linear colour models, named ``<dst>_from_<src>``.

Inverses are computed, never typed in: the notes print the inverse YIQ matrix rounded to three
decimals (errors up to 3e-3, SPEC section 9), which would break exact round trips.
"""

from __future__ import annotations

import numpy as np

#: RGB -> YIQ, the notes' forward matrix (NTSC).
yiq_from_rgb = np.array(
    [
        [0.299, 0.587, 0.114],
        [0.596, -0.274, -0.322],
        [0.211, -0.523, 0.312],
    ]
)
rgb_from_yiq = np.linalg.inv(yiq_from_rgb)

# ITU-R BT.601 full range: Y = 0.299 R + 0.587 G + 0.114 B,
# Cb = 0.5 + (B - Y) / 1.772, Cr = 0.5 + (R - Y) / 1.402.
_luma = np.array([0.299, 0.587, 0.114])
ycbcr_from_rgb = np.array(
    [
        _luma,
        (np.array([0.0, 0.0, 1.0]) - _luma) / 1.772,
        (np.array([1.0, 0.0, 0.0]) - _luma) / 1.402,
    ]
)
ycbcr_offset = np.array([0.0, 0.5, 0.5])
rgb_from_ycbcr = np.linalg.inv(ycbcr_from_rgb)

# CMY is the complement C = 1 - R: an affine map with matrix -I and offset 1 (its own inverse).
cmy_from_rgb = -np.eye(3)
cmy_offset = np.ones(3)


def inverse_offset(matrix_inverse: np.ndarray, offset: np.ndarray) -> np.ndarray:
    """Offset of the inverse of ``x -> M x + offset``: ``x = M^-1 y - M^-1 offset``."""
    return -matrix_inverse @ offset
