"""Output buffers recycled between frames.

A frame's colour, depth, object-id and normal buffers (32 bytes a pixel) are new arrays each
time, because the :class:`~pixelpath.Image` owns them. Memory fresh from the system costs a page
fault per 4 KiB page on first touch: at 1024×1024 that took 5-8 ms here, as long as shading the
frame. So the buffers come from a small pool instead, all four in one block of bytes. Each is a
view of a flat array over a memoryview of the pooled block; when the last view of it is gone
(the image and every array taken from it), a finalizer gives the block back for the next
frame. Memory still in use is never handed out again, and only a couple of spare blocks per
size are kept.

A new block is an uninitialized NumPy array, not a ``bytearray``, which fills itself with
zeros: that pass touched every page of a frame's fresh buffers in the calling thread before
the kernels wrote them (5 ms of a first 640×400 render's 20-24), where now the kernels' first
writes fault the pages in, from every thread. The memoryview ends the chain of bases: a view
of the flat array has the flat array as its base, so the finalizer waits for every view.

New blocks come from :func:`pixelpath._memory.fresh`, on huge pages where the system gives
them; one block a frame rather than one a buffer rounds the frame, not each buffer, up to
whole huge pages (at 640×400, 10 MiB for 8, where four blocks would have taken 12).
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from pixelpath._memory import fresh

SPARES_PER_SIZE = 2
LARGEST_KEPT = 1 << 29  # bytes; bigger blocks (frames over 16 megapixels) go back to the system
ALIGNMENT = 64  # bytes between the starts of a block's arrays: a cache line

_spares: dict[int, list[np.ndarray]] = {}


def frame_buffers(shape: tuple[int, int]) -> tuple[np.ndarray, ...]:
    """Return a frame's (rgb, depth, object_id, normal) buffers, uninitialized, in one block.

    ``rgb`` and ``normal`` (h, w, 3) float32, ``depth`` (h, w) float32, ``object_id`` (h, w)
    int32: :func:`arrays` of those.

    Examples
    --------
    >>> from pixelpath.raster import _pool
    >>> [(a.shape, a.dtype.name) for a in _pool.frame_buffers((2, 3))]
    [((2, 3, 3), 'float32'), ((2, 3), 'float32'), ((2, 3), 'int32'), ((2, 3, 3), 'float32')]
    """
    return arrays(((*shape, 3), np.float32), (shape, np.float32), (shape, np.int32),
                  ((*shape, 3), np.float32))


def arrays(*specs: tuple[tuple[int, ...], type]) -> tuple[np.ndarray, ...]:
    """Return uninitialized C-contiguous arrays of the given (shape, dtype), in one block.

    The block's memory is reused once no array uses any of them (see the module docstring).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raster import _pool
    >>> a, b = _pool.arrays(((2, 3), np.float32), ((4,), np.int32))
    >>> a.shape, b.dtype.name, a.flags.writeable, np.shares_memory(a, b)
    ((2, 3), 'int32', True, False)
    """
    dtypes = [np.dtype(dtype) for _, dtype in specs]
    sizes = [math.prod(shape) * dtype.itemsize for (shape, _), dtype in zip(specs, dtypes,
                                                                              strict=True)]
    starts = [0]
    for size in sizes:
        starts.append(starts[-1] + -(-size // ALIGNMENT) * ALIGNMENT)
    raw = _take(starts[-1])
    flat = np.frombuffer(memoryview(raw), dtype=np.uint8)
    if starts[-1] <= LARGEST_KEPT:
        # Every view of flat keeps it alive, so this runs only when no array uses raw.
        weakref.finalize(flat, _give_back, raw).atexit = False
    return tuple(
        flat[start : start + size].view(dtype).reshape(shape)
        for (shape, _), dtype, start, size in zip(specs, dtypes, starts, sizes, strict=False)
    )


def _take(nbytes: int) -> np.ndarray:
    try:
        return _spares.get(nbytes, []).pop()
    except IndexError:
        return fresh((nbytes,), np.uint8)


def _give_back(raw: np.ndarray) -> None:
    spares = _spares.setdefault(raw.nbytes, [])
    if len(spares) < SPARES_PER_SIZE:
        spares.append(raw)
