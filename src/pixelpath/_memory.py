"""New memory for big buffers, on huge pages where the system gives them.

Memory fresh from the system costs a page fault per 4 KiB page on first touch. Linux can back
an allocation with 2 MiB transparent huge pages instead, one fault each: NumPy asks for them
(``madvise``) on allocations of 4 MiB or more (see NumPy's ``NUMPY_MADVISE_HUGEPAGE``), but
only the 2 MiB-aligned spans inside an allocation can be huge pages. A frame's 3 MiB colour
buffer, allocated as it came, was faulted in 768 small pages, and a 4K colour conversion's
100 MB result had up to 512 at its ends.

So :func:`fresh` starts every buffer of half a MiB or more on a 2 MiB boundary, inside an
allocation of whole 2 MiB steps plus one for the alignment. A first 640×400 render took 3,600
page faults before, under 900 after. Where huge pages are off, nothing changes but some
address space, never touched.
"""

from __future__ import annotations

import math

import numpy as np

HUGE_PAGE = 1 << 21  # bytes: a transparent huge page on x86-64 (and arm64 with 4 KiB pages)
ALIGNED_FROM = HUGE_PAGE // 4  # bytes; smaller buffers are allocated as they come


def fresh(shape: tuple[int, ...], dtype: type) -> np.ndarray:
    """Return a new uninitialized C-contiguous array, on huge pages where the system gives them.

    For buffers a kernel fills at once: from half a MiB up, the array starts on a 2 MiB
    boundary (see the module docstring).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath._memory import HUGE_PAGE, fresh
    >>> a = fresh((1024, 1024), np.float32)
    >>> a.shape, a.dtype.name, a.flags.c_contiguous, a.ctypes.data % HUGE_PAGE
    ((1024, 1024), 'float32', True, 0)
    """
    dtype = np.dtype(dtype)
    nbytes = math.prod(shape) * dtype.itemsize
    if nbytes < ALIGNED_FROM:
        return np.empty(shape, dtype=dtype)
    spans = -(-nbytes // HUGE_PAGE)
    block = np.empty((spans + 1) * HUGE_PAGE, dtype=np.uint8)
    start = -block.ctypes.data % HUGE_PAGE
    return block[start : start + nbytes].view(dtype).reshape(shape)
