"""One rule for arrays handed to the raster kernels."""

from __future__ import annotations

import numpy as np


def kernel_array(values, dtype: type = np.float64) -> np.ndarray:
    """Return ``values`` as a C-contiguous, writeable array of ``dtype``, copying only if needed.

    Numba compiles (and caches) one version of a kernel per argument layout, and read-only
    arrays (the scene's frozen vectors, a mesh's arrays) are a layout of their own; handing the
    kernels one layout keeps ``pixelpath warmup`` complete and start-up fast.
    """
    return np.require(values, dtype=dtype, requirements=["C", "W"])
