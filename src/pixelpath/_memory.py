"""Long-lived scratch buffers on huge pages, where the system gives them.

Memory fresh from the system costs a page fault per 4 KiB page on first touch. Linux can back
memory with 2 MiB transparent huge pages instead, one fault each, where a program asks for
them (``madvise``) and the 2 MiB span lies wholly inside its mapping, aligned. NumPy asks on
allocations of 4 MiB or more (see its ``NUMPY_MADVISE_HUGEPAGE``), but allocations start where
they fall, and a 640×400 frame's per-thread visibility buffers (2 and 1 MB) were faulted in
750 small pages by a process's first render.

:func:`fresh` maps such a buffer on its own, from a 2 MiB boundary, rounded up to whole
2 MiB spans, and asks for huge pages over all of them. It is for buffers that are reused frame
after frame, where rounding up costs at most 2 MiB once: the visibility buffers each thread
keeps, and the first output blocks of each size that :mod:`pixelpath.raster._pool` recycles.
It is not for a new buffer every frame: frames whose images were all kept (each frame new
buffers, on huge pages) ran 20 % slower here (``docs/performance.md``; finding free 2 MiB
blocks for every frame is the likely cause, not measured).
Where huge pages are off, or on systems without ``madvise``, these are ordinary buffers.
"""

from __future__ import annotations

import contextlib
import math
import mmap

import numpy as np

HUGE_PAGE = 1 << 21  # bytes: a transparent huge page on x86-64 (and arm64 with 4 KiB pages)
HUGE_FROM = HUGE_PAGE // 4  # bytes; smaller buffers are not worth 2 MiB


def fresh(shape: tuple[int, ...], dtype: type) -> np.ndarray:
    """Return a new uninitialized C-contiguous scratch array, on huge pages where possible.

    From half a MiB up, the array starts on a 2 MiB boundary and its mapping covers whole
    2 MiB spans (up to 2 MiB more memory once its end is written); smaller ones are NumPy's.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath._memory import fresh
    >>> a = fresh((1024, 1024), np.float32)  # on Linux, two huge pages from a 2 MiB boundary
    >>> a.shape, a.dtype.name, a.flags.c_contiguous, a.flags.writeable
    ((1024, 1024), 'float32', True, True)
    """
    dtype = np.dtype(dtype)
    nbytes = math.prod(shape) * dtype.itemsize
    if nbytes < HUGE_FROM or not hasattr(mmap, "MADV_HUGEPAGE"):
        return np.empty(shape, dtype=dtype)
    spans = -(-nbytes // HUGE_PAGE)
    try:
        # Private: a shared anonymous mapping is shared memory, which gets no huge pages.
        mapping = mmap.mmap(-1, (spans + 1) * HUGE_PAGE,
                            flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS)
    except OSError:  # out of memory or of mappings: NumPy's allocation, and its MemoryError
        return np.empty(shape, dtype=dtype)
    block = np.frombuffer(mapping, dtype=np.uint8)
    start = -block.ctypes.data % HUGE_PAGE
    with contextlib.suppress(OSError):  # a kernel without huge pages: small ones it is
        mapping.madvise(mmap.MADV_HUGEPAGE, start, spans * HUGE_PAGE)
    return block[start : start + nbytes].view(dtype).reshape(shape)
