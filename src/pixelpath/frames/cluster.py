"""Dask clusters for frames: a local one sized to the machine, or an existing scheduler.

Only this module imports ``dask.distributed`` (the ``dask`` extra); rendering one image never
loads it. Workers warm pixelpath's kernels once, when they start (:class:`WarmKernels`).
"""

from __future__ import annotations

import logging
import os
import time
from typing import Any

from distributed import Client, LocalCluster
from distributed.diagnostics.plugin import WorkerPlugin

CONNECT_TIMEOUT_S = 5.0


class WarmKernels(WorkerPlugin):
    """Compile (or load from the disk cache) every kernel when a worker starts.

    Registered with ``client.register_plugin``, it runs on the workers present and on every
    worker that joins later (a replacement for one that died included), so no frame waits for
    a compile and a worker compiles once, not once per task. Workers on one machine share
    pixelpath's compile cache folder (``PIXELPATH_CACHE_DIR`` can point several machines at
    a shared one).
    """

    name = "pixelpath-warm-kernels"

    def setup(self, worker: Any) -> None:
        """Run :func:`pixelpath.warmup` in the worker process."""
        import pixelpath

        pixelpath.warmup()


def warm_workers(client: Client) -> float:
    """Register :class:`WarmKernels` on ``client``'s workers; return the seconds it took."""
    start = time.perf_counter()
    client.register_plugin(WarmKernels())
    return time.perf_counter() - start


def available_cores() -> int:
    """Return the number of cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def local_client(workers: int | None = None) -> Client:
    """Start a local cluster of ``workers`` processes (default: one per core) and connect.

    Each worker runs one task at a time with ``cores // workers`` Numba threads (at least
    one), so workers do not fight over cores. Closing the client closes the cluster.
    """
    cores = available_cores()
    count = workers or cores
    cluster = LocalCluster(
        n_workers=count,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,  # no dashboard; its HTTP server on a free local port, not 8787
        scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
        silence_logs=logging.ERROR,
        env={"NUMBA_NUM_THREADS": str(max(1, cores // count))},
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
