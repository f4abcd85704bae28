"""Frames per second of the showcase turntable: one process beside local Dask clusters.

Renders frames of the bundled showcase's turntable (640×400, z-buffer, Phong shading) to PNG
files three ways, in the same run:

- serially in this process, Numba's threads on every core (``render_frames(..., client=None)``);
- on a local Dask cluster of 1 worker process and of 2 worker processes, one Numba thread each
  (workers warmed and the scene scattered before the clock starts: that cost is printed apart);

in ``--rounds`` rounds (3), each in another order (the shared machine's speed drifts over a run,
so no run always goes first), printing every round and the medians;

then Dask's per-task overhead: tasks that take the scattered scene and return nothing, timed
over many, on the 2-worker cluster. The anchor is the serial run: a cluster must beat it.

``--cold`` instead measures what a cold run costs before its first frame, in the order of the
command line (the request is checked by rendering one pixel here, then the cluster starts and
its workers warm up): run it with an empty compile cache, where an installed package copies in
the kernels it was built with (``PIXELPATH_PRECOMPILED=0`` compiles them instead)::

    python benchmarks/bench_frames.py [--frames 120] [--size 640x400] [--rounds 3]
        [--empty-tasks 2000]
    PIXELPATH_CACHE_DIR=$(mktemp -d) python benchmarks/bench_frames.py --cold
    PIXELPATH_PRECOMPILED=0 PIXELPATH_CACHE_DIR=$(mktemp -d) \\
        python benchmarks/bench_frames.py --cold
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path


def showcase(size: str):
    from pixelpath.cli.render import load_scene_sized

    return load_scene_sized("showcase", size)


def serial(scene, frames: range, folder: Path) -> float:
    import pixelpath as pp

    pp.render_frames(scene, [0], out=folder / "warm_{frame}.png")  # compile/load kernels here
    start = time.perf_counter()
    pp.render_frames(scene, frames, out=folder / "serial_{frame:03d}.png")
    return time.perf_counter() - start


def on_cluster(scene, frames: range, folder: Path, workers: int) -> tuple[float, float]:
    """Return (seconds to start and warm the cluster, seconds for the frames)."""
    import pixelpath as pp
    from pixelpath.frames.cluster import local_client, warm_workers

    start = time.perf_counter()
    with local_client(workers, numba_threads=1) as client:
        warm_workers(client, {})
        ready = time.perf_counter() - start
        pp.render_frames(scene, [0], client, out=folder / "warm_{frame}.png")
        start = time.perf_counter()
        pp.render_frames(scene, frames, client, out=folder / f"w{workers}_{{frame:03d}}.png")
        return ready, time.perf_counter() - start


def empty_task(scene, frame: int) -> bytes:
    return b""


def task_overhead(scene, tasks: int) -> tuple[float, float]:
    """Return (ms per empty task on 2 workers, ms per empty task on 1 worker)."""
    from distributed import wait

    from pixelpath.frames.cluster import local_client

    results = []
    for workers in (2, 1):
        with local_client(workers, numba_threads=1) as client:
            shared = client.scatter(scene, broadcast=True, hash=False)
            wait([client.submit(empty_task, shared, -1, pure=False)])
            start = time.perf_counter()
            futures = [client.submit(empty_task, shared, i, pure=False) for i in range(tasks)]
            wait(futures)
            results.append((time.perf_counter() - start) / tasks * 1e3)
    return results[0], results[1]


def cold(scene) -> None:
    """Time a cold run in the order of the command line: check, start, warm, first frames."""
    import pixelpath as pp
    from pixelpath._jit import cache_dir
    from pixelpath.frames.cluster import local_client, warm_workers

    print(f"compile cache: {cache_dir()} ({len(list(cache_dir().glob('*')))} files)")
    with tempfile.TemporaryDirectory() as folder:
        start = time.perf_counter()
        plan = pp.frames.plan_frames(scene, [0, 1], Path(folder) / "f_{frame}.png")
        planned = time.perf_counter() - start
        with local_client(2, numba_threads=1) as client:
            up = time.perf_counter() - start
            warm_workers(client, plan.options)
            warmed = time.perf_counter() - start
            pp.frames.run_plan(plan, client)
            frames = time.perf_counter() - start
    print(f"client checks the request (renders 1 pixel, compiling?):  {planned:6.1f} s")
    print(f"cluster of 2 processes up:                                {up - planned:6.1f} s")
    print(f"workers warmed (render a tiny scene, kernels from cache): {warmed - up:6.1f} s")
    print(f"first two frames:                                         {frames - warmed:6.1f} s")
    print(f"cold total before the first frame:                        {warmed:6.1f} s")


RUNS = ("serial", 1, 2)  # the serial run, then local clusters of 1 and 2 worker processes


def timed_round(scene, frames: range, folder: Path, order: tuple) -> dict:
    """Return {run: (seconds to start and warm, seconds for the frames)} for runs in ``order``."""
    times = {}
    for run in order:
        if run == "serial":
            times[run] = (None, serial(scene, frames, folder))
        else:
            times[run] = on_cluster(scene, frames, folder, run)
    return times


def rotations(runs: tuple, count: int) -> list[tuple]:
    """``count`` orders of ``runs``, each starting one later: each run goes first in turn.

    The machine's speed drifts over a run (a shared host): rotating the order keeps a run that
    always comes first, or last, from taking the drift alone.
    """
    return [runs[i % len(runs) :] + runs[: i % len(runs)] for i in range(count)]


def same_files(folder: Path) -> bool:
    names = sorted(path.name for path in folder.glob("serial_*.png"))
    return bool(names) and all(
        (folder / name).read_bytes() == (folder / name.replace("serial", "w2")).read_bytes()
        for name in names
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--size", default="640x400")
    parser.add_argument("--rounds", type=int, default=3, help="rounds of all three runs")
    parser.add_argument("--empty-tasks", type=int, default=2000)
    parser.add_argument("--cold", action="store_true", help="time a cold cluster instead")
    args = parser.parse_args()
    scene = showcase(args.size)
    if args.cold:
        cold(scene)
        return
    frames = range(args.frames)
    cores = len(os.sched_getaffinity(0))
    print(f"showcase turntable, {args.frames} frames at {args.size}, PNG files, {cores} cores")
    rounds = []
    with tempfile.TemporaryDirectory() as folder:
        for order in rotations(RUNS, args.rounds):
            times = timed_round(scene, frames, Path(folder), order)
            rounds.append(times)
            fps = "  ".join(f"{run}: {args.frames / times[run][1]:5.1f}" for run in order)
            ratio = times[1][1] / times[2][1]
            print(f"round, frames/s in the order run: {fps}  2w/1w {ratio:.2f}x")
        same = same_files(Path(folder))
    seconds = {run: statistics.median(times[run][1] for times in rounds) for run in RUNS}
    ready = {run: statistics.median(times[run][0] for times in rounds) for run in RUNS[1:]}
    labels = {
        "serial": "serial, 1 process, Numba threads on all cores",
        1: "Dask, 1 worker process, 1 Numba thread each",
        2: "Dask, 2 worker processes, 1 Numba thread each",
    }
    print(f"medians of {args.rounds} rounds:")
    print(f"{'':52} {'frames/s':>9} {'vs serial':>10} {'start+warm':>11}")
    for run, label in labels.items():
        start = f"{ready[run]:.1f} s" if run in ready else ""
        print(
            f"{label:52} {args.frames / seconds[run]:9.1f} "
            f"{seconds['serial'] / seconds[run]:9.2f}x {start:>11}"
        )
    ratios = sorted(times[1][1] / times[2][1] for times in rounds)
    print(
        f"2 workers / 1 worker: {statistics.median(ratios):.2f}x median of the rounds' ratios "
        f"({', '.join(f'{ratio:.2f}' for ratio in ratios)})"
    )
    print(f"files of the 2-worker run byte-identical to the serial run: {same}")
    two, one = task_overhead(scene, args.empty_tasks)
    print(
        f"Dask per-task overhead, {args.empty_tasks} empty tasks on the scattered scene: "
        f"{two:.2f} ms a task with 2 workers, {one:.2f} ms with 1"
    )


if __name__ == "__main__":  # worker processes re-import this file: keep the work behind main
    main()
