"""pixelpath's thread pool: as many threads as Numba's setting, without starting Numba's own."""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
import textwrap
import threading
import time
import warnings
from concurrent.futures.thread import ThreadPoolExecutor

import pytest

from pixelpath import _threads
from pixelpath._threads import _started_pool, in_threads, stop_pools

SCRIPT = """
import json, threading, time
import numba
from numba.np.ufunc import parallel
from pixelpath._threads import in_threads, thread_count

def threads_used():
    seen = set()
    def work(start, stop):
        seen.add(threading.get_ident())
        time.sleep(0.002)  # long enough that every pool thread takes a run
    in_threads(work, 64, runs=32)
    return len(seen)

report = {"count": thread_count(), "used": threads_used(), "started": parallel._is_initialized}
numba.set_num_threads(1)
report.update(after_set=thread_count(), used_after_set=threads_used())
print(json.dumps(report))
"""


def test_the_pool_follows_numbas_thread_count_and_leaves_numbas_pool_unstarted():
    env = {**os.environ, "NUMBA_NUM_THREADS": "3"}
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(SCRIPT)],
        capture_output=True, text=True, env=env, timeout=120,
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout.splitlines()[-1])
    assert report == {
        "count": 3, "used": 3, "started": False, "after_set": 1, "used_after_set": 1
    }


def test_the_calling_thread_takes_runs_beside_the_pool_and_each_run_is_done_once(monkeypatch):
    monkeypatch.setattr(_threads, "thread_count", lambda: 3)
    done = []
    lock = threading.Lock()

    def work(start, stop):
        time.sleep(0.001)  # the calling thread takes runs while the helpers wake
        with lock:
            done.append((start, stop, threading.get_ident()))

    in_threads(work, 1000, runs=40)
    spans = sorted((start, stop) for start, stop, _ in done)
    assert len(spans) == 40 and spans[0][0] == 0 and spans[-1][1] == 1000
    assert all(a[1] == b[0] for a, b in itertools.pairwise(spans))  # no gap, no overlap
    assert threading.get_ident() in {ident for _, _, ident in done}


def test_progress_is_reported_once_per_run_and_in_the_calling_thread(monkeypatch):
    monkeypatch.setattr(_threads, "thread_count", lambda: 3)
    reported = []

    def work(start, stop):
        time.sleep(0.001)

    in_threads(work, 1000, runs=40, done=lambda: reported.append(threading.get_ident()))
    assert reported == [threading.get_ident()] * 40


@pytest.mark.parametrize("failing", [0, 39])  # the first run (the caller's) and the last
def test_an_exception_in_any_run_is_raised_by_in_threads(monkeypatch, failing):
    monkeypatch.setattr(_threads, "thread_count", lambda: 3)
    started = []

    def work(start, stop):
        started.append(start)
        time.sleep(0.001)
        if start == failing * 25:
            raise ValueError(f"run {failing}")

    with pytest.raises(ValueError, match=f"run {failing}"):
        in_threads(work, 1000, runs=40)
    if failing == 0:  # the calling thread's own first run: the helpers stopped soon after
        assert len(started) < 10
    in_threads(lambda start, stop: None, 1000, runs=40)  # the pool still works afterwards


def new_pool_threads(before: set[threading.Thread]) -> set[threading.Thread]:
    """Pool threads started since ``before`` (other tests' helpers may start threads too)."""
    return {t for t in set(threading.enumerate()) - before if t.name.startswith("pixelpath_")}


def test_a_new_pool_has_started_every_thread_before_its_first_run():
    before = set(threading.enumerate())
    pool = _started_pool(4)
    try:
        assert len(new_pool_threads(before)) == 4
    finally:
        pool.shutdown()


def test_a_pool_whose_thread_cannot_start_raises_and_frees_the_started_ones(monkeypatch):
    submit = ThreadPoolExecutor.submit
    submitted = []

    def second_fails(self, *args, **kwargs):
        submitted.append(args)
        if len(submitted) == 2:
            raise RuntimeError("can't start new thread")
        return submit(self, *args, **kwargs)

    before = set(threading.enumerate())
    monkeypatch.setattr(ThreadPoolExecutor, "submit", second_fails)
    with pytest.raises(RuntimeError, match="can't start new thread"):
        _started_pool(3)
    started = new_pool_threads(before)
    assert len(started) == 1
    # its task was waiting for the other two at the barrier: broken, it ends, and the thread
    # of a pool shut down exits instead of blocking for ever
    for thread in started:
        thread.join(timeout=30)
        assert not thread.is_alive()


def _sum_in_threads(results) -> None:
    total = []
    in_threads(lambda start, stop: total.append(sum(range(start, stop))), 100, runs=4)
    results.put(sum(total))


@pytest.mark.skipif(not sys.platform.startswith("linux"),
                    reason="forking a process that runs threads is only dependable on Linux")
def test_a_child_forked_after_the_pool_started_runs_work_on_a_pool_of_its_own(monkeypatch):
    import multiprocessing

    monkeypatch.setattr(_threads, "thread_count", lambda: 2)  # a pool even on one core
    parent = multiprocessing.Queue()
    _sum_in_threads(parent)  # the parent's pool is started
    assert parent.get(timeout=30) == sum(range(100))
    context = multiprocessing.get_context("fork")
    results = context.Queue()
    with warnings.catch_warnings():  # Python 3.12+ warns of fork in a threaded process
        warnings.simplefilter("ignore", DeprecationWarning)
        child = context.Process(target=_sum_in_threads, args=(results,))
        child.start()
    child.join(timeout=60)
    if child.is_alive():
        child.kill()
    assert child.exitcode == 0, "the forked child's runs never ran (its parent's pool)"
    assert results.get(timeout=5) == sum(range(100))


def test_stopped_pools_end_their_threads_and_later_work_starts_new_ones():
    def pool_threads():
        return [t for t in threading.enumerate() if t.name.startswith("pixelpath_")]

    done = []
    in_threads(lambda start, stop: done.append((start, stop)), 64, least=1)
    stop_pools()
    assert pool_threads() == []
    again = []
    in_threads(lambda start, stop: again.append((start, stop)), 64, least=1)
    assert sorted(again) == sorted(done)
    assert sum(stop - start for start, stop in again) == 64
