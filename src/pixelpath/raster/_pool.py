"""Output buffers recycled between frames.

A frame's colour, depth, object-id and normal buffers (32 bytes a pixel) are new arrays each
time, because the :class:`~pixelpath.Image` owns them. Memory fresh from the system costs a page
fault per 4 KiB page on first touch: at 1024×1024 that took 5-8 ms here, as long as shading the
frame. So the buffers come from a small pool instead. Each is a view of a flat array over a
memoryview of a pooled block of bytes; when the last view of it is gone (the image and every
array taken from it), a finalizer gives the block back for the next frame. Memory still in use
is never handed out again, and only a couple of spare buffers per size are kept.

A new block is an uninitialized NumPy array, not a ``bytearray``, which fills itself with
zeros: that pass touched every page of a frame's fresh buffers in the calling thread before
the kernels wrote them (5 ms of a first 640×400 render's 20-24), where now the kernels' first
writes fault the pages in, from every thread. The memoryview ends the chain of bases: a view
of the flat array has the flat array as its base, so the finalizer waits for every view.
Each buffer has a block of its own. The first two blocks of each size, the ones a process's
first frame takes (its colour and normals, its depth and ids are two of a size), come on huge
pages (:func:`pixelpath._memory.fresh`): a first 640×400 render then faulted its buffers in
about 100 times instead of 2,100, and the pool recycles those blocks frame after frame. Later
blocks, made only while images are kept, are NumPy's: blocks on huge pages for every frame
made frames whose images were all kept run 20 % slower. An image that keeps a first block
holds up to 2 MiB more than its size. Also measured and not kept (``docs/performance.md``):
one block for a frame's four buffers would make an array kept from an image keep all four's
memory (a loop that collects depth maps would hold 32 bytes a pixel for the 4 it keeps).
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from pixelpath._memory import fresh

SPARES_PER_SIZE = 2
HUGE_BLOCKS_PER_SIZE = 2  # a frame's colour and normals (or depth and ids) are two of a size
LARGEST_KEPT = 1 << 27  # bytes; bigger buffers go back to the system

_spares: dict[int, list[np.ndarray]] = {}
_made: dict[int, int] = {}  # blocks made so far, per size


def empty(shape: tuple[int, ...], dtype: type) -> np.ndarray:
    """Return an uninitialized C-contiguous array, reusing memory no array refers to any more.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raster import _pool
    >>> a = _pool.empty((2, 3), np.float32)
    >>> a.shape, a.dtype.name, a.flags.writeable
    ((2, 3), 'float32', True)
    """
    dtype = np.dtype(dtype)
    nbytes = math.prod(shape) * dtype.itemsize
    raw = _take(nbytes)
    flat = np.frombuffer(memoryview(raw), dtype=dtype)
    if nbytes <= LARGEST_KEPT:
        # Every view of flat keeps it alive, so this runs only when no array uses raw.
        weakref.finalize(flat, _give_back, raw).atexit = False
    return flat.reshape(shape)


def _take(nbytes: int) -> np.ndarray:
    try:  # one pop, not a look then a pop: renders in other threads share the spares
        return _spares.get(nbytes, []).pop()
    except IndexError:
        pass
    made = _made.get(nbytes, 0)
    _made[nbytes] = made + 1
    if made < HUGE_BLOCKS_PER_SIZE:
        return fresh((nbytes,), np.uint8)
    return np.empty(nbytes, dtype=np.uint8)


def _give_back(raw: np.ndarray) -> None:
    spares = _spares.setdefault(raw.nbytes, [])
    if len(spares) < SPARES_PER_SIZE:
        spares.append(raw)
