"""Numba configuration shared by every compiled kernel.

Importing this module imports Numba, so the public modules import their ``_kernels``
lazily (at first call) and ``import pixelpath`` stays fast.

Three rules live here, once:

* Kernels are cached on disk in a per-user folder, never inside site-packages, through a cache
  of their own (:mod:`pixelpath._cache`): no environment variable and no Numba setting is
  changed, so other Numba code in the process, and child processes, cache where they would
  without pixelpath.
* ``fastmath`` is off: the colour and clipping kernels compare floats exactly (ties at hue
  sector borders, points on window edges) and must agree with the pure-Python path.
* ``NUMBA_DISABLE_JIT=1`` turns every kernel into plain Python (the test suite passes both ways).
"""

from __future__ import annotations

from collections.abc import Callable

import numba

from pixelpath._cache import cache_dir, enable_cache

__all__ = ["cache_dir", "njit", "prange"]

prange = numba.prange


def njit(function: Callable | None = None, /, **options) -> Callable:
    """Compile a kernel with the project's defaults (cached on disk, ``fastmath`` off, nogil).

    Used bare (``@njit``) or with Numba options (``@njit(parallel=True)``).

    Examples
    --------
    >>> from pixelpath._jit import njit
    >>> @njit
    ... def twice(x):
    ...     return 2 * x
    >>> twice(21)
    42
    """
    options = {"fastmath": False, "nogil": True, **options}
    cache = options.pop("cache", True)

    def compile_kernel(kernel: Callable) -> Callable:
        dispatcher = numba.njit(**options)(kernel)
        if cache and not numba.config.DISABLE_JIT:
            enable_cache(dispatcher)
        return dispatcher

    return compile_kernel if function is None else compile_kernel(function)
