"""New memory for big buffers, on huge pages where the system gives them.

Memory fresh from the system costs a page fault per 4 KiB page on first touch. Linux can back
memory with 2 MiB transparent huge pages instead, one fault each, where a program asks for
them (``madvise``) and the 2 MiB span lies wholly inside its mapping, aligned. NumPy asks on
allocations of 4 MiB or more (see its ``NUMPY_MADVISE_HUGEPAGE``), but allocations start where
they fall, so a frame's 3 MiB colour buffer was faulted in 768 small pages.

:func:`fresh` maps a buffer of 2 MiB or more on its own, starting on a 2 MiB boundary, and
asks for huge pages over the whole 2 MiB spans inside it; the rest of its last span stays in
small pages, so a buffer holds no more memory than its size (where, as by default, Linux
gives huge pages only where asked). Internal scratch buffers, reused frame after frame, may
ask for ``whole_pages``: from half a MiB up, rounded up to whole spans, all huge pages. Where
huge pages are off, or on systems without ``madvise``, these are ordinary buffers. A first
640×400 render page-faulted 1,830 times with them, 3,600 times before (``docs/performance.md``).
"""

from __future__ import annotations

import contextlib
import math
import mmap

import numpy as np

HUGE_PAGE = 1 << 21  # bytes: a transparent huge page on x86-64 (and arm64 with 4 KiB pages)
WHOLE_PAGES_FROM = HUGE_PAGE // 4  # bytes; smaller scratch buffers are not worth 2 MiB


def fresh(shape: tuple[int, ...], dtype: type, *, whole_pages: bool = False) -> np.ndarray:
    """Return a new uninitialized C-contiguous array, on huge pages where the system gives them.

    Parameters
    ----------
    shape : tuple of int
    dtype : numpy dtype
    whole_pages : bool
        Round the huge pages up to cover the whole buffer (from half a MiB up), for internal
        scratch buffers: up to 2 MiB more memory once its end is written.

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
    spans = -(-nbytes // HUGE_PAGE) if whole_pages and nbytes >= WHOLE_PAGES_FROM else (
        nbytes // HUGE_PAGE)
    if spans == 0 or not hasattr(mmap, "MADV_HUGEPAGE"):
        return np.empty(shape, dtype=dtype)
    try:
        # Private: a shared anonymous mapping is shared memory, which gets no huge pages.
        mapping = mmap.mmap(-1, max(spans * HUGE_PAGE, nbytes) + HUGE_PAGE,
                            flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS)
    except OSError:  # out of memory or of mappings: NumPy's allocation, and its MemoryError
        return np.empty(shape, dtype=dtype)
    block = np.frombuffer(mapping, dtype=np.uint8)
    start = -block.ctypes.data % HUGE_PAGE
    with contextlib.suppress(OSError):  # a kernel without huge pages: small ones it is
        mapping.madvise(mmap.MADV_HUGEPAGE, start, spans * HUGE_PAGE)
    return block[start : start + nbytes].view(dtype).reshape(shape)
