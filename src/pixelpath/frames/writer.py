"""Frames' files encoded and written on a few threads while the next frames render.

Encoding a frame (8-bit conversion, then Pillow's PNG encoder, whose zlib releases the GIL) takes
about as long as rendering it: :class:`FrameWriter` hands each frame's encoding and its atomic
write to a small pool of threads, so that the caller renders frame n + 1 while frame n is
written. At most a few frames wait at a time (the caller blocks when the writers fall behind),
an error in a writer is raised in the caller, and leaving the ``with`` block waits for every
file handed over, also when the caller leaves it by an error (an interrupted run keeps the
frames it reported done).
"""

from __future__ import annotations

import concurrent.futures
import os
from collections import deque
from collections.abc import Callable
from pathlib import Path

from pixelpath.frames.plan import available_cores

# Frames may wait for a writer beside those being written: the render of the next frame goes
# on while a writer is busy, but memory stays bounded by a few frames.
WAITING_PER_WRITER = 2


class FrameWriter:
    """Encode and write files on a pool of threads; a context manager.

    Parameters
    ----------
    threads : int, optional
        Writer threads; default one per core, at most 2 (with Numba's render threads on the
        same cores, more only take turns).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pixelpath.frames.writer import FrameWriter
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> with FrameWriter() as writer:
    ...     for n in range(3):
    ...         writer.submit(folder / f"f_{n}.txt", lambda n=n: f"frame {n}".encode())
    >>> sorted(path.read_text() for path in folder.iterdir())
    ['frame 0', 'frame 1', 'frame 2']
    """

    def __init__(self, threads: int | None = None) -> None:
        self.threads = threads or max(1, min(2, available_cores()))
        self._pool = concurrent.futures.ThreadPoolExecutor(
            self.threads, thread_name_prefix="pixelpath-writer"
        )
        self._pending: deque[concurrent.futures.Future] = deque()

    def submit(self, path: str | os.PathLike, data: Callable[[], bytes]) -> None:
        """Write ``data()`` (called on a writer thread) to ``path`` atomically.

        Blocks while the writers are too far behind; raises the error of any earlier write
        that failed (the first one), so a failure stops the caller at its next frame.
        """
        self._collect(wait_for=len(self._pending) - self.threads * WAITING_PER_WRITER + 1)
        self._pending.append(self._pool.submit(_write, Path(path), data))

    def close(self) -> None:
        """Wait for every file; raise the first error of a write."""
        try:
            self._collect(wait_for=len(self._pending))
        finally:
            self._finish()

    def _collect(self, wait_for: int) -> None:
        """Drop finished writes, raising a failed one's error; wait for the first ``wait_for``."""
        while self._pending and (wait_for > 0 or self._pending[0].done()):
            self._pending.popleft().result()
            wait_for -= 1

    def _finish(self) -> None:
        """Wait for the writes still pending (their errors dropped), end the threads."""
        concurrent.futures.wait(self._pending)
        self._pending.clear()
        self._pool.shutdown(wait=True)

    def __enter__(self) -> FrameWriter:
        return self

    def __exit__(self, kind, error, traceback) -> None:
        if kind is None:
            self.close()
        else:  # the caller's error wins; the frames handed over are still written
            self._finish()


def _write(path: Path, data: Callable[[], bytes]) -> None:
    from pixelpath.io.images import write_bytes

    write_bytes(path, data())
