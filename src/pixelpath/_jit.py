"""Numba configuration shared by every compiled kernel.

Importing this module imports Numba, so the public modules import their ``_kernels``
lazily (at first call) and ``import pixelpath`` stays fast.

Three rules live here, once:

* Kernels are cached on disk (``cache=True``) in a per-user cache directory, never inside
  site-packages: ``$PIXELPATH_CACHE_DIR`` if set, else ``platformdirs.user_cache_dir("pixelpath")``.
  An explicit ``$NUMBA_CACHE_DIR`` is respected.
* ``fastmath`` is off: the colour and clipping kernels compare floats exactly (ties at hue
  sector borders, points on window edges) and must agree with the pure-Python path.
* ``NUMBA_DISABLE_JIT=1`` turns every kernel into plain Python (the test suite passes both ways).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import platformdirs


def cache_dir() -> Path:
    """Return the directory where compiled kernels are cached.

    Returns
    -------
    pathlib.Path
        ``$NUMBA_CACHE_DIR`` when the user set it, else ``$PIXELPATH_CACHE_DIR``, else the
        per-user cache directory of the platform (``~/.cache/pixelpath/numba`` on Linux).

    Examples
    --------
    >>> from pixelpath._jit import cache_dir
    >>> cache_dir().name
    'numba'
    """
    explicit = os.environ.get("NUMBA_CACHE_DIR")
    if explicit:
        return Path(explicit)
    root = os.environ.get("PIXELPATH_CACHE_DIR") or platformdirs.user_cache_dir("pixelpath")
    return Path(root) / "numba"


os.environ.setdefault("NUMBA_CACHE_DIR", str(cache_dir()))

import numba  # noqa: E402  (must come after NUMBA_CACHE_DIR is set)

numba.core.config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]

prange = numba.prange


def njit(*args, **kwargs) -> Callable:
    """Compile a kernel with the project's defaults (``cache=True, fastmath=False``).

    Used bare (``@njit``) or with Numba options (``@njit(parallel=True)``).
    """
    options = {"cache": True, "fastmath": False, "nogil": True}
    if args and callable(args[0]):
        return numba.njit(**options)(args[0])
    options.update(kwargs)
    return numba.njit(*args, **options)


_WARMUPS: list[Callable[[], None]] = []


def register_warmup(fn: Callable[[], None]) -> Callable[[], None]:
    """Register ``fn`` to be called by :func:`pixelpath.warmup` (usable as a decorator)."""
    _WARMUPS.append(fn)
    return fn


def run_warmups() -> int:
    """Call every registered warm-up function; return how many ran."""
    for fn in _WARMUPS:
        fn()
    return len(_WARMUPS)
