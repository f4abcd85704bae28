"""Compiled colour conversions: one pass over a span of flat, interleaved pixel buffers.

:func:`convert_span` takes the pixels as flat 1-D arrays (``r0 g0 b0 r1 g1 b1 ...``) and runs
one conversion loop over them; :mod:`pixelpath.color.models` hands runs of a big image to it
from several threads (serial kernels that release the GIL: a ``parallel=True`` loop took four
times as long to compile, and started Numba's own thread pool on the first call). The loop
reads a pixel, scales it (1/255 for uint8, 1/65535 for uint16, 1 for floats), notes whether a
component is not finite, converts it and writes it. The arithmetic runs in the output's precision —
the type of ``scale``, from which every constant is derived (:func:`numbers`) — so a float32 image
is converted with full-width float32 vectors, as OpenCV does, and a float64 one to full double
precision. A pixel is read whole before it is written, so the output may be the input's own buffer.

Written this way — flat arrays indexed ``3*i + k`` from zero, no data-dependent branches
(conditional expressions on cheap values become selects) — LLVM vectorizes the loops; indexing
an ``(N, 3)`` array, or branching on the hue case, keeps them scalar and several times slower.
The loops use ``error_model="numpy"`` (division by zero gives inf instead of raising) because
Python's zero-division check also blocks vectorization; every division here has a denominator
guarded away from zero, so results equal the pure-Python run's.

The formulas are the notes' ones:

* RGB -> HSV/HSL: Cmax, Cmin, Δ; H = 60° × (the notes' hue case), 0 when Δ = 0; V = Cmax,
  S = Δ/Cmax; or L = (Cmax + Cmin)/2, S = Δ/(1 − |2L − 1|).
* HSV/HSL -> RGB: C and m from S and V (or L); each channel is ``m + C·f`` with ``s = H/60 mod
  6`` and ``f = clamp(|s − 3| − 1)`` for R, ``clamp(2 − |s − 2|)`` for G and ``clamp(2 − |s − 4|)``
  for B (clamped to [0, 1]): the notes' sector table in closed form (``f`` is 1 where the table
  has C, 0 where it has 0, and X/C on the ramps between), five vector operations a channel.
* CMY and YIQ and YCbCr: an affine map ``M·rgb + offset``; CMYK: K = min(C, M, Y),
  C' = (C − K)/(1 − K), with pure black (0, 0, 0, 1).
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import inlined, njit

AFFINE = 0
RGB_TO_HSV = 1
RGB_TO_HSL = 2
HSV_TO_RGB = 3
HSL_TO_RGB = 4
RGB_TO_CMYK = 5
CMYK_TO_RGB = 6

# Images of at most this many pixels are converted on the calling thread alone.
CHUNK = 8192


@inlined
def larger(a, b):
    return a if a > b else b


@inlined
def smaller(a, b):
    return a if a < b else b


@inlined
def numbers(scale):
    """0, 1, 2, 4, 6, 1/6, 1/60 and 60 in the precision of ``scale`` (float32 or float64).

    Derived by exact arithmetic from ``scale / scale`` = 1: a float literal would be float64 and
    promote a float32 computation to float64.
    """
    one = scale / scale
    two = one + one
    four = two + two
    six = four + two
    sixty = six * (four + six)
    return one - one, one, two, four, six, one / six, one / sixty, sixty


@inlined
def not_finite(residue):
    """Tell whether ``residue``, a sum of terms x − x, is NaN (some x is NaN or ±inf).

    Each x − x is 0 for finite x and NaN otherwise, so the test needs no float64 constant
    (which would turn a float32 loop into float64) and cannot overflow, as |a| + |b| can.
    """
    return residue != residue


@inlined
def load3(src, i, scale):
    """Return pixel ``i``'s three components, scaled, and whether one of them is not finite."""
    a = src[3 * i] * scale
    b = src[3 * i + 1] * scale
    c = src[3 * i + 2] * scale
    return a, b, c, not_finite((a - a) + (b - b) + (c - c))


@njit(error_model="numpy", from_python=False)
def affine_span(src, dst, scale, matrix, offset):
    m00, m01, m02 = matrix[0, 0], matrix[0, 1], matrix[0, 2]
    m10, m11, m12 = matrix[1, 0], matrix[1, 1], matrix[1, 2]
    m20, m21, m22 = matrix[2, 0], matrix[2, 1], matrix[2, 2]
    o0, o1, o2 = offset[0], offset[1], offset[2]
    bad = False
    for i in range(src.shape[0] // 3):
        a, b, c, flag = load3(src, i, scale)
        bad |= flag
        dst[3 * i] = m00 * a + m01 * b + m02 * c + o0
        dst[3 * i + 1] = m10 * a + m11 * b + m12 * c + o1
        dst[3 * i + 2] = m20 * a + m21 * b + m22 * c + o2
    return bad


@njit(error_model="numpy", from_python=False)
def rgb_to_hsx_span(src, dst, scale, lightness):
    zero, one, two, four, six, _, _, sixty = numbers(scale)
    bad = False
    for i in range(src.shape[0] // 3):
        r, g, b, flag = load3(src, i, scale)
        bad |= flag
        cmax = larger(larger(r, g), b)
        cmin = smaller(smaller(r, g), b)
        delta = cmax - cmin
        # The notes' hue cases as a position in sextants: Cmax = R, else G, else B.
        is_r = cmax == r
        is_g = cmax == g
        numerator = (g - b) if is_r else ((b - r) if is_g else (r - g))
        base = zero if is_r else (two if is_g else four)
        sextant = base + numerator / (delta if delta > zero else one)  # greys: 0
        sextant = sextant + six if sextant < zero else sextant
        hue = sixty * sextant
        # Round-off can land exactly on 360°: H stays strictly below 360.
        dst[3 * i] = hue - sixty * six if hue >= sixty * six else hue
        if lightness:
            # 1 − |2L − 1| written as min(Cmax + Cmin, 2 − Cmax − Cmin): no cancellation for
            # dark colours, so S stays within [0, 1] to the last bit.
            spread = smaller(cmax + cmin, two - cmax - cmin)
            dst[3 * i + 1] = delta / spread if spread > zero else zero
            dst[3 * i + 2] = (cmax + cmin) / two
        else:
            dst[3 * i + 1] = delta / cmax if cmax > zero else zero
            dst[3 * i + 2] = cmax
    return bad


@inlined
def clamp(x, zero, one):
    return smaller(larger(x, zero), one)


@njit(error_model="numpy", from_python=False)
def hsx_to_rgb_span(src, dst, scale, lightness):
    zero, one, two, four, six, sixth, per_degree, _ = numbers(scale)
    three = two + one
    half = one / two
    bad = False
    for i in range(src.shape[0] // 3):
        h, s, v, flag = load3(src, i, scale)
        bad |= flag
        sextant = h * per_degree
        sextant = sextant - six * np.floor(sextant * sixth)  # H mod 360: 360 and −60 wrap
        sextant = zero if sextant >= six else sextant
        if lightness:
            chroma = smaller(two * v, two - two * v) * s  # (1 − |2L − 1|)·S, no cancellation
            low = v - chroma * half
        else:
            chroma = v * s
            low = v - chroma
        dst[3 * i] = low + chroma * clamp(abs(sextant - three) - one, zero, one)
        dst[3 * i + 1] = low + chroma * clamp(two - abs(sextant - two), zero, one)
        dst[3 * i + 2] = low + chroma * clamp(two - abs(sextant - four), zero, one)
    return bad


@njit(error_model="numpy", from_python=False)
def rgb_to_cmyk_span(src, dst, scale):
    zero, one, _, _, _, _, _, _ = numbers(scale)
    bad = False
    for i in range(src.shape[0] // 3):
        r, g, b, flag = load3(src, i, scale)
        bad |= flag
        cyan = one - r
        magenta = one - g
        yellow = one - b
        black = smaller(smaller(cyan, magenta), yellow)
        ink = one - black
        inv = one / (ink if ink > zero else one)  # pure black: K = 1 and C' = M' = Y' = 0
        dst[4 * i] = (cyan - black) * inv
        dst[4 * i + 1] = (magenta - black) * inv
        dst[4 * i + 2] = (yellow - black) * inv
        dst[4 * i + 3] = black
    return bad


@njit(error_model="numpy", from_python=False)
def cmyk_to_rgb_span(src, dst, scale):
    _, one, _, _, _, _, _, _ = numbers(scale)
    bad = False
    for i in range(src.shape[0] // 4):
        c = src[4 * i] * scale
        m = src[4 * i + 1] * scale
        y = src[4 * i + 2] * scale
        k = src[4 * i + 3] * scale
        bad |= not_finite((c - c) + (m - m) + (y - y) + (k - k))
        white = one - k
        dst[3 * i] = (one - c) * white
        dst[3 * i + 1] = (one - m) * white
        dst[3 * i + 2] = (one - y) * white
    return bad


@njit
def convert_span(src, dst, scale, op, matrix, offset):
    """Convert the pixels of one flat chunk with operation ``op``."""
    if op == AFFINE:
        return affine_span(src, dst, scale, matrix, offset)
    if op == RGB_TO_HSV or op == RGB_TO_HSL:
        return rgb_to_hsx_span(src, dst, scale, op == RGB_TO_HSL)
    if op == HSV_TO_RGB or op == HSL_TO_RGB:
        return hsx_to_rgb_span(src, dst, scale, op == HSL_TO_RGB)
    if op == RGB_TO_CMYK:
        return rgb_to_cmyk_span(src, dst, scale)
    return cmyk_to_rgb_span(src, dst, scale)


def warmup() -> None:
    """Compile the kernel for every pair of input and result dtypes the public API passes it."""
    matrix = np.eye(3)
    offset = np.zeros(3)
    for dtype, out_dtype in (
        (np.uint8, np.float64),
        (np.uint16, np.float64),
        (np.uint8, np.float32),  # dtype="float32"
        (np.uint16, np.float32),
        (np.float32, np.float32),
        (np.float64, np.float64),
    ):
        src = np.zeros(3, dtype=dtype)
        dst = np.zeros(3, dtype=out_dtype)
        one = out_dtype(1.0)
        convert_span(src, dst, one, AFFINE, matrix.astype(out_dtype), offset.astype(out_dtype))
