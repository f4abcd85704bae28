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

import sys
import time
from collections.abc import Callable
from dataclasses import dataclass

import numba
from numba.core.dispatcher import Dispatcher

from pixelpath._cache import cache_dir, enable_cache

__all__ = ["WarmupReport", "cache_dir", "njit", "prange", "register_warmup", "run_warmups"]

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


_WARMUPS: list[Callable[[], None]] = []


@dataclass(frozen=True)
class WarmupReport:
    """What one kernel module's warm-up did: its module, seconds taken, specializations.

    ``compiled`` counts the specializations Numba compiled, ``loaded`` those it loaded from the
    disk cache (both 0 with ``NUMBA_DISABLE_JIT=1``, where nothing compiles).
    """

    module: str
    seconds: float
    compiled: int
    loaded: int


def register_warmup(fn: Callable[[], None]) -> Callable[[], None]:
    """Register ``fn`` to be called by :func:`pixelpath.warmup` (usable as a decorator)."""
    _WARMUPS.append(fn)
    return fn


def _specializations(module_name: str) -> tuple[int, int]:
    """Return (compiled, loaded from cache) over the kernels defined in module ``module_name``."""
    compiled = loaded = 0
    for value in vars(sys.modules[module_name]).values():
        if isinstance(value, Dispatcher) and value.py_func.__module__ == module_name:
            compiled += sum(value.stats.cache_misses.values())
            loaded += sum(value.stats.cache_hits.values())
    return compiled, loaded


def run_warmups() -> list[WarmupReport]:
    """Call every registered warm-up function; report each one's time and specializations.

    ``pixelpath warmup`` prints these reports (its test checks that a second run compiles
    nothing); the example only shows their shape, since running the warm-ups here would
    compile every kernel into whichever cache this process has.

    Examples
    --------
    >>> from pixelpath._jit import WarmupReport
    >>> WarmupReport("pixelpath.color._kernels", seconds=4.2, compiled=12, loaded=0).compiled
    12
    """
    reports = []
    for fn in _WARMUPS:
        before = _specializations(fn.__module__)
        start = time.perf_counter()
        fn()
        seconds = time.perf_counter() - start
        after = _specializations(fn.__module__)
        compiled, loaded = (now - then for now, then in zip(after, before, strict=True))
        reports.append(WarmupReport(fn.__module__, seconds, compiled, loaded))
    return reports
