"""Output buffers recycled between frames.

A frame's colour, depth, object-id and normal buffers (32 bytes a pixel) are new arrays each
time, because the :class:`~pixelpath.Image` owns them. Memory fresh from the system costs a page
fault per 4 KiB page on first touch: at 1024×1024 that took 5-8 ms here, as long as shading the
frame. So the buffers come from a small pool instead. Each is a view of a flat array over a
memoryview of a pooled block of bytes; when the last view of it is gone (the image and every
array taken from it), a finalizer gives the block back for the next frame. Memory still in use
is never handed out again, and only a couple of spare buffers per size are kept.

A frame's four buffers share one block (:func:`frame_outputs`): NumPy asks the system for huge
pages for blocks of 4 MiB or more, so a 640×400 frame's 8 MB fault in as a few 2 MiB pages
instead of 2,000 small ones. The block goes back when none of the four is in use: an array kept
from an image keeps the other three's memory too.

A new block is an uninitialized NumPy array, not a ``bytearray``, which fills itself with
zeros: that pass touched every page of a frame's fresh buffers in the calling thread before
the kernels wrote them (5 ms of a first 640×400 render's 20-24), where now the kernels' first
writes fault the pages in, from every thread. The memoryview ends the chain of bases: a view
of the flat array has the flat array as its base, so the finalizer waits for every view.
"""

from __future__ import annotations

import math
import weakref

import numpy as np

SPARES_PER_SIZE = 2
LARGEST_KEPT = 1 << 27  # bytes; bigger buffers go back to the system
ALIGN = 64  # bytes: a cache line

_spares: dict[int, list[np.ndarray]] = {}


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


def frame_outputs(shape: tuple[int, int]) -> tuple[np.ndarray, ...]:
    """Return a frame's uninitialized colour, depth, object-id and normal buffers.

    ``(h, w, 3)`` float32, ``(h, w)`` float32, ``(h, w)`` int32 and ``(h, w, 3)`` float32 arrays,
    each at an offset into one pooled block that is a multiple of 64 bytes (a cache line).

    Examples
    --------
    >>> from pixelpath.raster import _pool
    >>> rgb, depth, object_id, normal = _pool.frame_outputs((2, 3))
    >>> rgb.shape, depth.dtype.name, object_id.dtype.name, normal.shape
    ((2, 3, 3), 'float32', 'int32', (2, 3, 3))
    """
    kinds = (((*shape, 3), np.float32), (shape, np.float32), (shape, np.int32),
             ((*shape, 3), np.float32))
    sizes = [math.prod(part) * np.dtype(dtype).itemsize for part, dtype in kinds]
    rooms = [-(-size // ALIGN) * ALIGN for size in sizes]  # sizes rounded up to ALIGN
    block = empty((sum(rooms),), np.uint8)
    arrays, start = [], 0
    for (part, dtype), size, room in zip(kinds, sizes, rooms, strict=True):
        arrays.append(block[start : start + size].view(dtype).reshape(part))
        start += room
    return tuple(arrays)


def _take(nbytes: int) -> np.ndarray:
    try:
        return _spares.get(nbytes, []).pop()
    except IndexError:
        return np.empty(nbytes, dtype=np.uint8)


def _give_back(raw: np.ndarray) -> None:
    spares = _spares.setdefault(raw.nbytes, [])
    if len(spares) < SPARES_PER_SIZE:
        spares.append(raw)
