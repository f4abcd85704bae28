"""A newcomer's first minute: the CLI timed in fresh processes, with an empty and a warm cache.

    python benchmarks/bench_coldstart.py [--runs 3] [--warm-runs 3]

Each cold run gets a new, empty compile cache (``PIXELPATH_CACHE_DIR`` set to a fresh temporary
folder), so it compiles every kernel the command needs, as on a fresh installation; the warm
runs that follow reuse that cache. Three commands are timed, wall clock, process start to exit:

* ``pixelpath demo -o DIR --quick`` (the three bundled scenes, z-buffer);
* ``pixelpath demo -o DIR`` (those, then the showcase ray-traced and by every method);
* ``pixelpath render facets --size 160x120 -o out.png`` (a small bundled scene).

Beside them, from the same run, the floor every Python CLI pays: ``python -c pass`` (the
interpreter alone) and ``python -c "import cv2"`` when OpenCV is installed (a library that ships
compiled code, so it has no first-run step). Times in seconds; the table gives
every run and the median.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

COMMANDS = {
    "pixelpath demo --quick": ["demo", "-o", "{out}/quick", "--quick"],
    "pixelpath demo": ["demo", "-o", "{out}/demo"],
    "pixelpath render (160x120)": ["render", "facets", "--size", "160x120", "-o", "{out}/r.png"],
}


def timed(argv: list[str], env: dict[str, str]) -> float:
    """Run ``argv`` to completion; return its wall-clock seconds (fail loudly on an error)."""
    start = time.perf_counter()
    result = subprocess.run(argv, env=env, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit(f"{' '.join(argv)} failed ({result.returncode}):\n{result.stderr}")
    return seconds


def pixelpath_runs(args: list[str], cold_runs: int, warm_runs: int) -> tuple[list, list]:
    """Time ``args`` cold (each in a fresh cache) and then warm (in the last run's cache)."""
    cold, warm = [], []
    for _ in range(cold_runs):
        with tempfile.TemporaryDirectory() as cache, tempfile.TemporaryDirectory() as out:
            env = {**os.environ, "PIXELPATH_CACHE_DIR": cache}
            argv = [sys.executable, "-m", "pixelpath", *(a.format(out=out) for a in args)]
            cold.append(timed(argv, env))
            if len(cold) == cold_runs:
                warm = [timed(argv, env) for _ in range(warm_runs)]
    return cold, warm


def row(label: str, cold: list[float], warm: list[float]) -> str:
    def cell(values):
        if not values:
            return f"{'':28s}"
        runs = " ".join(f"{v:.1f}" for v in values)
        return f"{statistics.median(values):6.1f}  ({runs})".ljust(28)

    return f"  {label:30s} {cell(cold)} {cell(warm)}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="cold runs, each with an empty cache")
    parser.add_argument("--warm-runs", type=int, default=3)
    args = parser.parse_args()
    if os.environ.get("NUMBA_DISABLE_JIT") == "1":
        sys.exit("NUMBA_DISABLE_JIT=1 is set: nothing would compile; unset it to measure")

    python = sys.version.split()[0]
    print(f"seconds, wall clock per process; {os.cpu_count()} cores; Python {python}")
    print("cold: each run with an empty cache folder; warm: again with the last cold run's cache")
    print(f"  {'command':30s} {'cold: median (runs)':28s} {'warm: median (runs)':28s}")
    for label, command in COMMANDS.items():
        cold, warm = pixelpath_runs(command, args.runs, args.warm_runs)
        print(row(label, cold, warm), flush=True)
    baseline = {**os.environ}
    floor = [timed([sys.executable, "-c", "pass"], baseline) for _ in range(args.warm_runs)]
    print(row("python -c pass (the floor)", [], floor))
    try:
        import cv2  # noqa: F401  (only to know it is there; timed in its own processes)
    except ImportError:
        print("  (OpenCV not installed: pip install '.[bench]' to compare with it)")
    else:
        opencv = [
            timed([sys.executable, "-c", "import cv2"], baseline) for _ in range(args.warm_runs)
        ]
        print(row("python -c 'import cv2'", [], opencv))


if __name__ == "__main__":
    main()
