"""Colour models of the notes (RGB, CMY, CMYK, YIQ, HSV) plus HSL and BT.601 YCbCr.

Conversions run over whole arrays of colours (``(..., 3)``, ``(..., 4)`` for CMYK) in one
compiled, parallel pass; :func:`convert` goes between any two models through RGB. See
:mod:`pixelpath.color.models` for the input policy (dtypes, integer scaling, ranges).

Examples
--------
>>> from pixelpath import color
>>> color.rgb_to_hsv([255, 255, 0]).tolist()
[60.0, 1.0, 1.0]
>>> color.convert([0.0, 1.0, 1.0], "rgb", "cmy").tolist()
[1.0, 0.0, 0.0]
"""

from pixelpath.color.models import (
    MODELS,
    cmy_to_rgb,
    cmyk_to_rgb,
    convert,
    hsl_to_rgb,
    hsv_to_rgb,
    rgb_to_cmy,
    rgb_to_cmyk,
    rgb_to_hsl,
    rgb_to_hsv,
    rgb_to_ycbcr,
    rgb_to_yiq,
    ycbcr_to_rgb,
    yiq_to_rgb,
)

__all__ = [
    "MODELS",
    "cmy_to_rgb",
    "cmyk_to_rgb",
    "convert",
    "hsl_to_rgb",
    "hsv_to_rgb",
    "rgb_to_cmy",
    "rgb_to_cmyk",
    "rgb_to_hsl",
    "rgb_to_hsv",
    "rgb_to_ycbcr",
    "rgb_to_yiq",
    "ycbcr_to_rgb",
    "yiq_to_rgb",
]
