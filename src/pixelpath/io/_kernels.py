"""Compiled kernels of 8-bit encoding (see :func:`pixelpath.io.images.to_uint8`).

Both kernels read a float32 picture, flattened, and write its 8-bit codes into ``out``; they
allocate nothing and hold no state, so any thread may run them (the GIL is released) while
another renders.

* ``linear_codes``: ``rint(clip(value, 0, 1) · 255)`` with the value widened to float64 first,
  the very operations of the general NumPy path, so the bytes are the same (NaN gives 0, as
  NumPy's cast of a NaN does on x86-64 and ARM). The loop has no table and no branch: LLVM
  vectorizes it.
* ``table_codes``: any other encoding (the sRGB curve, a display gamma) through a step table
  built from the general path (:func:`pixelpath.io.images.code_table`). It works on the
  float32 values' bits as int32: for non-negative floats the integers are ordered as the
  floats, so a value's bucket is ``bits >> BUCKET_BITS`` and its code is the bucket's first
  code, plus one from the bucket's step on. Negative values (and -0.0) give the code of 0,
  values above 1 (and +inf) the code of 1, and a NaN the code the general path gives it.
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import njit

# The float32 values of [0, 1] fall into buckets of 2**BUCKET_BITS consecutive floats (at most
# 2.4e-4 wide); a table is only used when no bucket holds two steps of the code.
BUCKET_BITS = 12
ONE_BITS = 0x3F800000  # the bits of float32 1.0
INF_BITS = 0x7F800000  # the bits of float32 +inf; larger positive integers are NaNs


@njit(refcount=False)
def linear_codes(values, out):  # pragma: no cover - compiled
    """Write ``rint(clip(values, 0, 1) * 255)`` (float64 arithmetic) into the uint8 ``out``."""
    for i in range(values.size):
        value = np.float64(values[i])
        # The conditional expressions send NaN to 0 and keep the loop free of branches.
        value = value if value > 0.0 else 0.0
        value = value if value < 1.0 else 1.0
        out[i] = np.uint8(np.rint(value * 255.0))


@njit(refcount=False)
def table_codes(bits, first_code, step, codes, out):  # pragma: no cover - compiled
    """Write the code of each float32 value (given as its int32 ``bits``) into ``out``.

    ``first_code[b]`` is bucket b's first code and ``step[b]`` the bits where its code steps
    up by one (past ``ONE_BITS`` where it does not); ``codes`` holds the codes of 0, 1, a
    positive NaN and a negative NaN.
    """
    for i in range(bits.size):
        b = bits[i]
        if b <= 0:  # +0.0, negative values, -0.0, -inf and negative NaNs
            out[i] = codes[3] if (b & 0x7FFFFFFF) > INF_BITS else codes[0]
        elif b > ONE_BITS:  # values above 1, +inf and positive NaNs
            out[i] = codes[2] if b > INF_BITS else codes[1]
        else:
            bucket = b >> BUCKET_BITS
            out[i] = first_code[bucket] + (1 if b >= step[bucket] else 0)


def warmup() -> None:
    """Compile both kernels for the float32 pictures and tables they are given."""
    values = np.zeros(4, np.float32)
    out = np.empty(4, np.uint8)
    linear_codes(values, out)
    buckets = (ONE_BITS >> BUCKET_BITS) + 1
    table_codes(
        values.view(np.int32),
        np.zeros(buckets, np.uint8),
        np.full(buckets, ONE_BITS + 1, np.int32),
        np.zeros(4, np.uint8),
        out,
    )
