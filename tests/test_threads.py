"""pixelpath's thread pool: as many threads as Numba's setting, without starting Numba's own."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

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
