"""Dask clusters for frames: a local one sized to the machine, or an existing scheduler.

Only this module imports ``dask.distributed`` (the ``dask`` extra); rendering one image never
loads it. Workers warm pixelpath's kernels once, when they start (:class:`WarmKernels`).
"""

from __future__ import annotations

import logging
import time
from typing import Any

import dask
from distributed import Client, LocalCluster
from distributed.diagnostics.plugin import WorkerPlugin

from pixelpath.frames.plan import available_cores

CONNECT_TIMEOUT_S = 5.0

# Dask settings for the local clusters pixelpath starts (not for a cluster it connects to).
# Measured with benchmarks/bench_frames.py on 2 cores, where every CPU-millisecond the workers'
# event loops spend is one the other worker cannot render with.
LOCAL_CLUSTER_CONFIG = {
    # The statistical profiler samples each worker's task thread 100 times a second, on its
    # event loop, for a dashboard profile page that frames never need.
    "distributed.worker.profile.enabled": False,
    # Dask's nanny starts workers with MALLOC_TRIM_THRESHOLD_=65536, so that glibc hands freed
    # memory back to the system at once. A render allocates its buffers anew each frame, and
    # under that setting each frame maps them afresh and faults in every page: frames rendered
    # 20 % slower. Unset, the variable is whatever this process's environment says.
    "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
    # Housekeeping timers, slowed from 20 ms, 500 ms and 100 ms: the event-loop health tick,
    # the CPU/memory/network monitor behind the dashboard's graphs, and the memory checks that
    # pause or restart a worker near its memory limit (a render's memory does not creep).
    # Together they took 67 ms of CPU a second on an idle 2-worker cluster; now 25 ms.
    "distributed.admin.tick.interval": "200ms",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "500ms",
}


class WarmKernels(WorkerPlugin):
    """Compile (or load from the disk cache) the kernels frames will use, as a worker starts.

    Registered with ``client.register_plugin``, it runs on the workers present and on every
    worker that joins later (a replacement for one that died included), so no frame waits for
    a compile and a worker compiles once, not once per task. It renders a tiny scene with the
    run's render options (:func:`pixelpath.frames.work.warm_up`), which compiles exactly the
    kernels of that method and shading, not all of pixelpath's. Workers on one machine share
    pixelpath's compile cache folder (``PIXELPATH_CACHE_DIR`` can point machines at a shared
    one), so what one process compiled the others load.
    """

    def __init__(self, options: dict[str, Any]) -> None:
        self.options = dict(options)
        self.name = "pixelpath-warm-" + ",".join(f"{k}={v!r}" for k, v in sorted(options.items()))

    def setup(self, worker: Any) -> None:
        """Render the warm-up scene in the worker process."""
        from pixelpath.frames.work import warm_up

        warm_up(self.options)


def warm_workers(client: Client, options: dict[str, Any]) -> float:
    """Warm ``client``'s workers for frames with render ``options``; return the seconds taken.

    Registering the same options again is quick: each worker keeps its compiled kernels.
    """
    start = time.perf_counter()
    client.register_plugin(WarmKernels(options))
    return time.perf_counter() - start


def local_client(workers: int | None = None, numba_threads: int | None = None) -> Client:
    """Start a local cluster of ``workers`` processes (default: one per core) and connect.

    Each worker runs one task at a time with ``numba_threads`` Numba threads (default:
    ``cores // workers``, at least one), so workers do not fight over cores. The cluster runs
    with :data:`LOCAL_CLUSTER_CONFIG` (no statistical profiler, glibc's own memory trimming).
    Closing the client closes the cluster.

    Examples
    --------
    >>> client = local_client(workers=1)
    >>> len(client.scheduler_info()["workers"])
    1
    >>> client.close()
    """
    cores = available_cores()
    count = workers or cores
    threads = numba_threads or max(1, cores // count)
    with dask.config.set(LOCAL_CLUSTER_CONFIG):  # workers take the config they start with
        cluster = LocalCluster(
            n_workers=count,
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,  # nothing on port 8787; the scheduler's HTTP on a free port
            scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
            silence_logs=logging.CRITICAL,  # worker chatter at shutdown; task errors reach us
            env={"NUMBA_NUM_THREADS": str(threads)},
        )
    client = Client(cluster)
    client.close = _closing_cluster(client.close, cluster)
    return client


def _closing_cluster(close: Any, cluster: LocalCluster) -> Any:
    def close_both(*args: Any, **kwargs: Any) -> Any:
        result = close(*args, **kwargs)
        cluster.close()
        return result

    return close_both


def connect(address: str, timeout: float = CONNECT_TIMEOUT_S) -> Client:
    """Connect to the Dask scheduler at ``address``; ``ConnectionError`` after ``timeout`` s."""
    try:
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError, ValueError) as exc:
        raise ConnectionError(
            f"could not reach the Dask scheduler at {address} within {timeout:g} s "
            f"({type(exc).__name__}: {exc}); is it running, and is the address right?"
        ) from None
