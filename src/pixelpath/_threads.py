"""Run a serial kernel on parts of its work from several threads at once.

No kernel is compiled with ``parallel=True``: Numba's parallel loops cost seconds more to
compile on a first run (a batch clip's five times, a colour conversion's four), for no speed a
thread pool does not give, and started Numba's own pool on a first call. The kernels release
the GIL (``nogil``), so runs of the work handed to them from Python threads go on in parallel.
"""

from __future__ import annotations

import functools
import itertools
import os
import queue
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import wait as wait_for

# Imported here, not looked up as concurrent.futures.ThreadPoolExecutor at the first big call:
# that name loads concurrent.futures.thread and queue on first use, 1.1 ms of that call.
from concurrent.futures.thread import ThreadPoolExecutor

import numpy as np

__all__ = ["in_runs", "in_threads", "stop_pools", "thread_count"]

RUNS_PER_THREAD = 4  # in_threads() hands out this many runs per thread: uneven work evens out
_EXECUTORS: dict[int, ThreadPoolExecutor] = {}
_EXECUTORS_LOCK = threading.Lock()


def _forget_pools() -> None:
    """In a child made by ``fork``: drop the parent's pools, whose threads the child lacks.

    Runs of work handed to them would wait for ever (a child process rendering after its
    parent had rendered hung); the child starts pools of its own on first use. The lock is
    made anew too, in case another thread of the parent held it at the fork.
    """
    global _EXECUTORS_LOCK
    _EXECUTORS.clear()
    _EXECUTORS_LOCK = threading.Lock()


if hasattr(os, "register_at_fork"):  # not on Windows, which has no fork
    os.register_at_fork(after_in_child=_forget_pools)


def stop_pools() -> None:
    """End the threads of pixelpath's pools, waiting for their work; later calls start new ones.

    What Python does at exit, done early by a process that ends itself
    (:func:`pixelpath.cli.run`).

    Examples
    --------
    >>> import threading
    >>> from pixelpath._threads import in_threads, stop_pools
    >>> in_threads(lambda start, stop: None, 64)
    >>> stop_pools()
    >>> [t.name for t in threading.enumerate() if t.name.startswith("pixelpath_")]
    []
    """
    with _EXECUTORS_LOCK:
        pools = list(_EXECUTORS.values())
        _EXECUTORS.clear()
    for pool in pools:
        pool.shutdown(wait=True)


def in_threads(
    work: Callable[[int, int], object],
    count: int,
    *,
    runs: int | None = None,
    least: int = 1,
    done: Callable[[], object] | None = None,
) -> None:
    """Call ``work(start, stop)`` on runs of ``range(count)`` from several threads at once.

    As many threads as Numba's (:func:`thread_count`, so ``NUMBA_NUM_THREADS`` and
    ``numba.set_num_threads`` apply), each taking runs in turn as it finishes one; the calling
    thread is one of them. The runs must write disjoint parts of the output. An exception in a
    run is raised here.

    ``runs`` sets how many runs (default: a few per thread, or one on a single thread), and
    ``least`` the fewest items a run is worth: fewer runs are made where ``count`` is small,
    down to one, run in the calling thread (handing out little work costs more than it saves);
    ``done()`` is called in the calling thread once per run, as the runs finish (those of other
    threads when the calling thread's own next run is done, or at the end), so a progress bar
    can follow the work without any barrier between its parts.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath._threads import in_threads
    >>> out = np.zeros(10)
    >>> def fill(start, stop):
    ...     out[start:stop] = np.arange(start, stop)
    >>> finished = []
    >>> in_threads(fill, 10, runs=5, done=lambda: finished.append(1))
    >>> out.tolist() == list(range(10)), len(finished)
    (True, 5)
    """
    threads = thread_count()
    if runs is None:
        runs = 1 if threads == 1 else RUNS_PER_THREAD * threads
    runs = max(min(count // least, runs), 1)
    # One run needs no division of the range (NumPy's took 7 µs, most of a small call's cost).
    bounds = [0, count] if runs == 1 else np.linspace(0, count, runs + 1).astype(int).tolist()
    if threads == 1 or runs == 1:
        for start, stop in itertools.pairwise(bounds):
            work(start, stop)
            if done is not None:
                done()
        return
    with _EXECUTORS_LOCK:
        executor = _EXECUTORS.get(threads)
        if executor is None:
            executor = _started_pool(threads)
            _EXECUTORS[threads] = executor
    _shared_runs(executor, work, bounds, min(threads, runs), done)


def _shared_runs(
    executor: ThreadPoolExecutor, work: Callable[[int, int], object], bounds: list[int],
    threads: int, done: Callable[[], object] | None,
) -> None:
    """Run ``work`` on the runs between consecutive ``bounds``: this thread and helpers.

    ``threads - 1`` tasks of the pool and the calling thread take the runs in turn from one
    counter, so a call hands out one task per helper, not one per run, and the calling thread
    works instead of sleeping until the runs are done: handing eight runs to the pool and
    waiting for them took 140 µs, two 80 µs, whatever the work. The helpers count their
    finished runs into a queue, which this thread turns into ``done()`` calls. A helper's
    exception is raised here once every helper has stopped; one of this thread's (or Ctrl-C)
    stops the helpers after their current run and is raised once they have.
    """
    take = itertools.count().__next__  # one C call: atomic under the GIL
    last = len(bounds) - 1
    stopped = False
    report = done if done is not None else _nothing
    finished = queue.SimpleQueue()  # a token per run a helper has done

    def take_runs(finish: Callable[[], object]) -> None:
        run = take()
        while run < last and not stopped:
            work(bounds[run], bounds[run + 1])
            finish()
            run = take()

    def report_helpers() -> None:
        while not finished.empty():
            finished.get()
            report()

    def report_here() -> None:  # this thread's run, and the helpers' since the last one
        report()
        report_helpers()

    helpers = [executor.submit(take_runs, functools.partial(finished.put, None))
               for _ in range(threads - 1)]
    try:
        take_runs(report_here)
    except BaseException:  # an error, or Ctrl-C: the helpers stop after their current run
        stopped = True
        raise
    finally:
        # A helper not started yet has no run left to take (or none wanted, after an error):
        # withdrawn, it is not waited for (a pool thread takes tens of microseconds to wake).
        wait_for([helper for helper in helpers if not helper.cancel()])
    report_helpers()
    for helper in helpers:
        if not helper.cancelled():
            helper.result()


def _nothing() -> None:
    """Report nothing: the end of a run when nobody follows the progress."""


def _started_pool(threads: int) -> ThreadPoolExecutor:
    """Return a pool of ``threads`` threads, every one of them already started.

    A ThreadPoolExecutor starts a thread at each submission while none is idle, so a first
    batch of runs would start threads while others already run kernels. Each new thread
    needs the GIL to boot, and a kernel returning then could wait out the interpreter's
    5 ms switch interval for it: a process's first 640x400 render took 14-21 ms, in two
    modes, against a steady 13-14 ms with the threads started first. Here one task per thread
    waits at a barrier until all have started, so each took a thread of its own.
    """
    pool = ThreadPoolExecutor(threads, "pixelpath")
    barrier = threading.Barrier(threads)
    waits = []
    try:
        for _ in range(threads):
            waits.append(pool.submit(barrier.wait))
    except BaseException:  # a thread that could not start: free the ones waiting
        barrier.abort()
        pool.shutdown(wait=False)
        raise
    for wait in waits:
        wait.result()
    return pool


def thread_count() -> int:
    """Return how many threads pixelpath's pool runs: Numba's ``get_num_threads()``.

    Until something starts Numba's own threading layer (a ``parallel=True`` kernel of the
    user's, or ``numba.set_num_threads``), that number is ``NUMBA_NUM_THREADS`` from Numba's
    configuration, read without asking: ``get_num_threads()`` starts the layer's threads
    first, which took 3.3 ms of a process's first big call and left threads that no
    pixelpath kernel uses.

    Examples
    --------
    >>> import numba
    >>> from pixelpath._threads import thread_count
    >>> thread_count() == numba.get_num_threads()
    True
    """
    import numba
    from numba.np.ufunc import parallel

    if getattr(parallel, "_is_initialized", True):  # started, or a Numba that names it otherwise
        return numba.get_num_threads()
    return numba.config.NUMBA_NUM_THREADS


def in_runs(
    work: Callable[[Sequence], object],
    items: Sequence,
    *,
    runs: int | None = None,
    done: Callable[[], object] | None = None,
) -> None:
    """Call ``work(run)`` on consecutive runs of ``items`` from several threads at once.

    List the items so that every run holds a fair share of the work (the raster methods list
    their bands of rows interleaved, even ones then odd ones, so each run spans the image).
    ``runs`` and ``done`` are :func:`in_threads`'.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath._threads import in_runs
    >>> seen = []
    >>> in_runs(lambda run: seen.extend(run.tolist()), np.arange(6))
    >>> sorted(seen)
    [0, 1, 2, 3, 4, 5]
    """
    in_threads(lambda start, stop: work(items[start:stop]), len(items), runs=runs, done=done)
