"""Frames per second of the showcase turntable: one process beside local Dask clusters.

First, where one frame's time goes, each step timed alone over ``--breakdown`` frames (30;
medians): render (``render_frame``), convert (``to_uint8``, floats to 8 bits), encode (the
PNG file's bytes, at ``--png-level``, and Pillow's encoder at its default level as
``Image.save`` writes), write (the atomic file write). Then renders frames of the bundled
showcase's turntable (640×400, z-buffer, Phong shading) to PNG files (``--png-level``, default
the frames' 1) three ways, in the same run (``--runs serial`` for the first alone):

- serially in this process, Numba's threads on every core (``render_frames(..., client=None)``),
  while writer threads encode and write the frames already rendered;
- on a local Dask cluster of 1 worker process and of 2 worker processes, one Numba thread each
  (workers warmed and the scene scattered before the clock starts: that cost is printed apart);

in ``--rounds`` rounds (3), each in another order (the shared machine's speed drifts over a run,
so no run always goes first), printing every round and the medians;

then Dask's per-task overhead: tasks that take the scattered scene and return nothing, timed
over many, on the 2-worker cluster. The anchor is the serial run: a cluster must beat it.

``--methods M ...`` instead renders the turntable by each method in a loop, beside one of its
frames rendered again as many times (no files): the turntable should cost no more than
repeating a frame, since what depends on the objects alone is built once.

``--cold`` instead measures what a cold run costs before its first frame, in the order of the
command line (the request is checked by rendering one pixel here, then the cluster starts and
its workers warm up): run it with an empty compile cache, where an installed package copies in
the kernels it was built with (``PIXELPATH_PRECOMPILED=0`` compiles them instead)::

    python benchmarks/bench_frames.py [--frames 120] [--size 640x400] [--rounds 3]
        [--empty-tasks 2000] [--png-level 1] [--breakdown 30] [--runs serial]
    python benchmarks/bench_frames.py --methods zbuffer bsp raytrace [--frames 20]
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


PNG_LEVEL = 1  # set from --png-level


def serial(scene, frames: range, folder: Path) -> float:
    import pixelpath as pp

    out = folder / "warm_{frame}.png"
    pp.render_frames(scene, [0], out=out, png_level=PNG_LEVEL)  # compile/load kernels here
    start = time.perf_counter()
    pp.render_frames(scene, frames, out=folder / "serial_{frame:03d}.png", png_level=PNG_LEVEL)
    return time.perf_counter() - start


def serial_only(scene, frames: range, rounds: int) -> None:
    """Print the serial run's frames/s and process CPU per frame, with files and without."""
    import pixelpath as pp

    for label, out in (("PNG files", "serial_{frame:03d}.png"), ("no files (images kept)", None)):
        rates, cpu = [], []
        with tempfile.TemporaryDirectory() as folder:
            for _ in range(rounds):
                if out is None:
                    start, used = time.perf_counter(), time.process_time()
                    pp.render_frames(scene, frames)
                    seconds = time.perf_counter() - start
                else:
                    used = time.process_time()
                    seconds = serial(scene, frames, Path(folder))  # its warm-up frame counted
                rates.append(len(frames) / seconds)
                cpu.append((time.process_time() - used) / len(frames) * 1e3)
        print(
            f"serial, {label}: {statistics.median(rates):.1f} frames/s, "
            f"{statistics.median(cpu):.1f} ms of CPU a frame (medians of "
            f"{', '.join(f'{rate:.1f}' for rate in rates)} frames/s)"
        )


def by_method(scene, frames: int, methods: list[str]) -> None:
    """Print, per method, ms a frame for one frame rendered again and for the turning frames.

    The two cost the same when nothing that depends on the objects alone (triangles, BVH, BSP
    tree) is built again for each frame; the first is the anchor of the second.
    """
    import pixelpath as pp

    print(f"\nby method, {frames} renders each, no files: the same frame again / the turntable")
    count = scene.animation.frames
    for method in methods:
        pp.render(scene.at_frame(0), method)
        again = scene.at_frame(1)
        pp.render(again, method)
        start = time.perf_counter()
        for _ in range(frames):
            pp.render(again, method)
        same = (time.perf_counter() - start) / frames * 1e3
        start = time.perf_counter()
        for frame in range(2, 2 + frames):
            pp.render(scene.at_frame(frame % count), method)
        turning = (time.perf_counter() - start) / frames * 1e3
        print(f"  {method:9} {same:7.1f} ms / {turning:7.1f} ms a frame")


def breakdown(scene, count: int, folder: Path) -> None:
    """Print the median milliseconds of each step of a frame, each timed alone."""
    import io

    from PIL import Image as PILImage

    from pixelpath.frames.work import render_frame
    from pixelpath.io.images import to_uint8, write_bytes

    def pillow(pixels, level=6):
        buffer = io.BytesIO()
        PILImage.fromarray(pixels).save(buffer, format="PNG", compress_level=level)
        return buffer.getvalue()

    steps: dict[str, list[float]] = {}
    sizes: dict[str, list[int]] = {}

    def timed(name, function, *args):
        start = time.perf_counter()
        result = function(*args)
        steps.setdefault(name, []).append((time.perf_counter() - start) * 1e3)
        return result

    render_frame(scene, 0, {})  # compile/load kernels here
    to_uint8(render_frame(scene, 0, {}).rgb)
    level = PNG_LEVEL
    for frame in range(count):
        image = timed("render", render_frame, scene, frame, {})
        pixels = timed("convert", to_uint8, image.rgb, image.encoding)
        data = timed("encode", pillow, pixels, level) if level is not None else None
        pillows = timed("encode, Pillow (Image.save)", pillow, pixels)
        timed("write", write_bytes, folder / f"b_{frame:03d}.png", data or pillows)
        sizes.setdefault("encode", []).append(len(data or pillows))
        sizes.setdefault("encode, Pillow (Image.save)", []).append(len(pillows))
    print(f"one frame's steps, each timed alone (medians of {count} frames):")
    labels = {"encode": f"encode, PNG level {level}"} if level is not None else {}
    for name, times in steps.items():
        size = f"{statistics.median(sizes[name]) / 1e3:7.1f} kB" if name in sizes else ""
        print(f"  {labels.get(name, name):32} {statistics.median(times):7.2f} ms {size}")
    steps.pop("encode, Pillow (Image.save)")
    total = sum(statistics.median(times) for times in steps.values())
    print(
        f"  {'render + convert + encode + write':32} {total:7.2f} ms "
        f"({1e3 / total:.1f} frames/s one after another, on one thread but the render's)"
    )


def on_cluster(scene, frames: range, folder: Path, workers: int) -> tuple[float, float]:
    """Return (seconds to start and warm the cluster, seconds for the frames)."""
    import pixelpath as pp
    from pixelpath.frames.cluster import local_client, warm_workers

    start = time.perf_counter()
    with local_client(workers, numba_threads=1) as client:
        warm_workers(client, {})
        ready = time.perf_counter() - start
        out = folder / f"w{workers}_{{frame:03d}}.png"
        pp.render_frames(scene, [0], client, out=folder / "warm_{frame}.png", png_level=PNG_LEVEL)
        start = time.perf_counter()
        pp.render_frames(scene, frames, client, out=out, png_level=PNG_LEVEL)
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
    parser.add_argument(
        "--png-level", default="1", help="PNG compression 0-9, or 'pillow' for Image.save's default"
    )
    parser.add_argument("--breakdown", type=int, default=30, help="frames timed step by step")
    parser.add_argument("--runs", choices=("all", "serial"), default="all")
    parser.add_argument(
        "--methods", nargs="+", metavar="METHOD",
        help="instead: each method's turntable beside one frame rendered again (no files)",
    )
    args = parser.parse_args()
    global PNG_LEVEL
    PNG_LEVEL = None if args.png_level == "pillow" else int(args.png_level)
    scene = showcase(args.size)
    if args.cold:
        cold(scene)
        return
    if args.methods:
        by_method(scene, args.frames, args.methods)
        return
    frames = range(args.frames)
    cores = len(os.sched_getaffinity(0))
    print(
        f"showcase turntable, {args.frames} frames at {args.size}, PNG files "
        f"(level {args.png_level}), {cores} cores"
    )
    if args.breakdown:
        with tempfile.TemporaryDirectory() as folder:
            breakdown(scene, args.breakdown, Path(folder))
    if args.runs == "serial":
        serial_only(scene, frames, args.rounds)
        return
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
