"""Numba configuration shared by every compiled kernel.

Importing this module imports Numba, so the public modules import their ``_kernels``
lazily (at first call) and ``import pixelpath`` stays fast.

The rules live here, once:

* Kernels are cached on disk in a per-user folder, never inside site-packages, through a cache
  of their own (:mod:`pixelpath._cache`): no environment variable and no Numba setting is
  changed, so other Numba code in the process, and child processes, cache where they would
  without pixelpath.
* ``fastmath`` is off: the colour and clipping kernels compare floats exactly (ties at hue
  sector borders, points on window edges) and must agree with the pure-Python path.
* ``NUMBA_DISABLE_JIT=1`` turns every kernel into plain Python (the test suite passes both ways).
* Kernels that do the same arithmetic on several rays side by side (``njit(simd=True)``) are
  compiled with LLVM's SLP vectorizer, which Numba leaves off: the setting is switched on only
  while such a kernel compiles, under Numba's compiler lock, so no other compilation sees it.
* Numba wraps every function it compiles twice, for callers outside compiled code: a C-callable
  wrapper, which only serves functions passed around as values (no kernel here is), and a
  CPython wrapper, which unboxes Python arguments (for a record of twenty arrays, a large
  function of its own). Neither wrapper is made for any kernel (``no_cfunc_wrapper``), nor the
  CPython one for the helpers that only other kernels call (``njit(from_python=False)``):
  their Python call would jump to a null address, so it raises a TypeError instead. The
  render kernels of a build took about 9 % less CPU time to compile (``docs/performance.md``).
* A kernel is compiled for the types of its callers' arguments, never for a constant's value
  (:class:`Kernel`): Numba types a literal written at a call (``0``, ``-1``, ``True``) as a
  type of its own, and compiled a helper called with a literal at one place and a variable at
  another once for each; the z-buffer's pass, for one, compiled its batch shading twice.
* Kernels that only work on the arrays they are given (``njit(refcount=False)``) are compiled
  without Numba's reference counting: its atomic updates of the arrays' counts, at every call
  and inlined helper, made the threads tracing one scene contend for the same cache lines.
* The ray tracer's small helpers, and the texture lookup's texel read and wrap, are compiled
  as functions of their own (``njit(refcount=False)``), which LLVM inlines into their callers,
  rather than with ``njit(inline="always")``, which inlines them in Numba's own IR and so types
  them afresh at every call site, in Python: the ray tracer's compile went from 43 s to 32 s
  of CPU that way, with the same pixels and speed.
* Where LLVM would leave such a helper a call, and the call costs speed (the triangle and
  sphere tests in the traversal loops, the texture lookups in the shading pass), the helper
  is still compiled once, as a function of its own, and marked for LLVM to inline into every
  caller (:func:`inlined`: ``njit(refcount=False, forceinline=True)``, Numba's
  ``forceinline``: LLVM's ``alwaysinline``). Copied by Numba instead (``inline="always"``),
  it was typed again at each call site: the triangle test six times in the ray tracer's
  kernels, the bilinear lookup twice in every shading pass. Numba hands ``forceinline`` on
  to the callees it compiles for the first time inside such a helper, which LLVM then
  inlines too.
  ``inline="always"`` stays for helpers with one call site, for small ones whose conversion
  saved no compile time (the ray tracer's ``_unit`` and ``_offset``), and where a benchmark
  showed LLVM's inlined code slower (the BVH build's helpers). The clipping, colour and
  lighting kernels' helpers and the raster shading pass's are compiled so too (the clipping
  and colour groups compiled in 8.1 and 6.7 s instead of 9.7 and 8.1, the front end's in
  4.3 instead of 4.8, the shading pass's in 5.2-5.4 instead of 5.7, at the same speed); the
  other kernels' helpers (set-up, scan, texture lookups, the hidden-surface methods) stay
  inlined by Numba: converting them saved little or no compile time
  (``docs/performance.md``).
* A kernel that only loops over bands (or rows, or areas) and calls one big kernel for each
  is not a kernel of its own: Numba links each callee's compiled code into its caller, and
  LLVM optimizes and generates all of it again there, so a thin loop around a big kernel
  compiled the big one twice. The loop and the band's work are one kernel (the ray tracer's
  ``render_rows``, 3.8 s less of LLVM's time), or the band's kernel is inlined by Numba into
  its only caller (the hidden-surface methods, where the saving did not show through the
  machine's noise: ``docs/performance.md``).
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import contextmanager

import numba
from numba.core import config, types
from numba.core.compiler_lock import global_compiler_lock
from numba.core.registry import CPUDispatcher

from pixelpath._cache import cache_dir, enable_cache
from pixelpath._precompiled import cache_root

__all__ = ["cache_dir", "compile_for", "inlined", "njit"]


class Kernel(CPUDispatcher):
    """A kernel that other kernels call with the types of their arguments, never their values.

    Numba types a constant written at a call (``0``, ``-1``, ``True``, a module's global) as a
    literal, a type of its own, and compiles the callee for it: a helper called with a literal
    at one place and a variable (or another literal) at another was compiled once per call.
    Here the callee is typed for what the literal is a value of (``int64``, ``bool``).
    """

    def get_call_template(self, args, kws):
        """Numba's call template for the arguments' types, literals taken as their base types."""
        return super().get_call_template(
            [types.unliteral(arg) for arg in args],
            {name: types.unliteral(arg) for name, arg in kws.items()},
        )


class KernelOnly(Kernel):
    """A kernel compiled without the CPython wrapper: other kernels call it, Python may not."""

    def __call__(self, *args, **kwargs):
        raise TypeError(
            f"{self.py_func.__module__}.{self.py_func.__qualname__} is compiled for other "
            "kernels to call (njit(from_python=False)), not for Python"
        )


def njit(function: Callable | None = None, /, **options) -> Callable:
    """Compile a kernel with the project's defaults (cached on disk, ``fastmath`` off, nogil).

    Used bare (``@njit``) or with Numba options (``@njit(error_model="numpy")``).
    ``from_python=False`` compiles a helper that only other kernels call without the wrapper
    through which Python calls a kernel; calling it from Python raises a TypeError (unless
    ``NUMBA_DISABLE_JIT=1``, where every kernel is plain Python). ``simd=True``
    compiles the kernel, and the kernels it calls that are compiled with it, with LLVM's SLP
    vectorizer (without ``fastmath`` it keeps every result bit for bit).

    ``refcount=False`` compiles the kernel without Numba's reference counting of arrays
    (its runtime, NRT), for kernels that allocate no array and return none: they only read
    and write the arrays they are given, which their caller keeps alive. Numba refuses to
    compile an allocation in such a kernel. With counting on, every array handed to a call or
    to an inlined helper gets an atomic increment and decrement of its count: per ray in the
    ray tracer, on the scene's arrays, whose counts threads tracing the same scene then pass
    back and forth between cores.

    Examples
    --------
    >>> from pixelpath._jit import njit
    >>> @njit
    ... def twice(x):
    ...     return 2 * x
    >>> twice(21)
    42
    """
    options = {"fastmath": False, "nogil": True, "no_cfunc_wrapper": True, **options}
    cache = options.pop("cache", True)
    simd = options.pop("simd", False)
    if not options.pop("refcount", True):
        options["_nrt"] = False  # the option Numba uses itself for kernels such as its sorts
    from_python = options.pop("from_python", True)
    options["no_cpython_wrapper"] = not from_python

    def compile_kernel(kernel: Callable) -> Callable:
        dispatcher = numba.njit(**options)(kernel)
        if config.DISABLE_JIT:
            return dispatcher
        dispatcher.__class__ = Kernel if from_python else KernelOnly
        if cache:
            # The kernels compiled at build time go into the cache before Numba first looks
            # there, so that it loads them instead of compiling.
            cache_root()
            enable_cache(dispatcher)
        if simd:
            dispatcher.compile = _with_slp_vectorizer(dispatcher.compile)
        return dispatcher

    return compile_kernel if function is None else compile_kernel(function)


def inlined(function: Callable | None = None, /, **options) -> Callable:
    """Compile a helper of kernels once, for LLVM to inline into every kernel that calls it.

    :func:`njit` with ``refcount=False`` (the helper allocates nothing), ``forceinline=True``
    and ``from_python=False`` (only kernels call it), the module's rule for small helpers in
    hot loops; ``options`` override them (``from_python=True`` for one Python calls too).

    Examples
    --------
    >>> from pixelpath._jit import inlined, njit
    >>> @inlined(cache=False)
    ... def square(x):
    ...     return x * x
    >>> @njit(cache=False)
    ... def fourth_power(x):
    ...     return square(square(x))
    >>> fourth_power(3)
    81
    """
    defaults = {"refcount": False, "forceinline": True, "from_python": False}
    return njit(function, **{**defaults, **options})


def compile_for(kernel: Callable, *arguments) -> None:
    """Compile ``kernel`` for the types of ``arguments`` without running it.

    For warm-ups of helpers that only kernels call (``njit(from_python=False)``), which
    Python cannot call; with ``NUMBA_DISABLE_JIT=1`` there is nothing to compile.

    Examples
    --------
    >>> from pixelpath._jit import compile_for, njit
    >>> @njit(from_python=False, cache=False)
    ... def halve(x):
    ...     return x / 2
    >>> compile_for(halve, 1.0)
    """
    if not config.DISABLE_JIT:
        kernel.compile(tuple(numba.typeof(argument) for argument in arguments))


@contextmanager
def _slp_vectorizer():
    """Switch Numba's SLP setting on for the compilations in this thread, and back afterwards.

    Numba reads ``config.SLP_VECTORIZE`` when it builds the optimization passes of a module,
    inside a compilation; holding its (reentrant) compiler lock keeps every other thread's
    compilation out until the setting is restored.
    """
    with global_compiler_lock:
        saved = config.SLP_VECTORIZE
        config.SLP_VECTORIZE = True
        try:
            yield
        finally:
            config.SLP_VECTORIZE = saved


def _with_slp_vectorizer(compile_signature: Callable) -> Callable:
    def compile_vectorized(signature):
        with _slp_vectorizer():
            return compile_signature(signature)

    return compile_vectorized
