"""A newcomer's first minute: the CLI timed in fresh processes, with an empty and a warm cache.

    python benchmarks/bench_coldstart.py [--runs 3] [--warm-runs 3]

Each first ("cold") run gets a new, empty kernel cache (``PIXELPATH_CACHE_DIR`` set to a fresh
temporary folder), as on a fresh installation; the warm runs that follow reuse the last one's
cache. A cold run is timed two ways:

* **shipped**: as installed. ``pip install .`` compiles the render kernels while it builds the
  package (``pixelpath._precompiled``), and the first run copies them into the empty cache.
  Only measured when the installed package has them (not in an editable install);
* **compiled here**: with ``PIXELPATH_PRECOMPILED=0``, every kernel the command needs compiles
  on first use, as without that step.

Three commands are timed, wall clock, process start to exit:

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
import shutil
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


def cold_runs(args: list[str], runs: int, **environment: str) -> tuple[list[float], str]:
    """Time ``args`` ``runs`` times, each with a fresh cache; return the times and the last cache.

    The last cache folder is left for the warm runs (the caller removes it).
    """
    times, cache = [], ""
    for run in range(runs):
        cache = tempfile.mkdtemp(prefix="pixelpath-cold-")
        env = {**os.environ, **environment, "PIXELPATH_CACHE_DIR": cache}
        with tempfile.TemporaryDirectory() as out:
            times.append(timed(command_line(args, out), env))
        if run < runs - 1:
            shutil.rmtree(cache)
    return times, cache


def command_line(args: list[str], out: str) -> list[str]:
    return [sys.executable, "-m", "pixelpath", *(a.format(out=out) for a in args)]


def warm_runs(args: list[str], runs: int, cache: str) -> list[float]:
    """Time ``args`` ``runs`` times on the kernel cache ``cache``."""
    env = {**os.environ, "PIXELPATH_CACHE_DIR": cache}
    with tempfile.TemporaryDirectory() as out:
        return [timed(command_line(args, out), env) for _ in range(runs)]


def row(label: str, *columns: list[float]) -> str:
    def cell(values):
        if not values:
            return f"{'':28s}"
        runs = " ".join(f"{v:.1f}" for v in values)
        return f"{statistics.median(values):6.1f}  ({runs})".ljust(28)

    return f"  {label:30s} " + " ".join(cell(values) for values in columns)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="cold runs, each with an empty cache")
    parser.add_argument("--warm-runs", type=int, default=3)
    args = parser.parse_args()
    if os.environ.get("NUMBA_DISABLE_JIT") == "1":
        sys.exit("NUMBA_DISABLE_JIT=1 is set: nothing would compile; unset it to measure")

    from pixelpath._precompiled import MANIFEST, SHIPPED

    shipped = (SHIPPED / MANIFEST).is_file()
    python = sys.version.split()[0]
    print(f"seconds, wall clock per process; {os.cpu_count()} cores; Python {python}")
    print("cold: each run with an empty cache folder; warm: again with the last cold run's cache")
    if not shipped:
        print("  (no kernels compiled at install here, an editable install: 'shipped' not run)")
    print(f"  {'command':30s} {'cold, shipped':28s} {'cold, compiled here':28s} {'warm':28s}")
    for label, command in COMMANDS.items():
        from_install, cache = (
            cold_runs(command, args.runs, PIXELPATH_PRECOMPILED="1") if shipped else ([], "")
        )
        if cache:
            shutil.rmtree(cache)
        compiled, cache = cold_runs(command, args.runs, PIXELPATH_PRECOMPILED="0")
        warm = warm_runs(command, args.warm_runs, cache)
        shutil.rmtree(cache)
        print(row(label, from_install, compiled, warm), flush=True)
    baseline = {**os.environ}
    floor = [timed([sys.executable, "-c", "pass"], baseline) for _ in range(args.warm_runs)]
    print(row("python -c pass (the floor)", [], [], floor))
    try:
        import cv2  # noqa: F401  (only to know it is there; timed in its own processes)
    except ImportError:
        print("  (OpenCV not installed: pip install '.[bench]' to compare with it)")
    else:
        opencv = [
            timed([sys.executable, "-c", "import cv2"], baseline) for _ in range(args.warm_runs)
        ]
        print(row("python -c 'import cv2'", [], [], opencv))


if __name__ == "__main__":
    main()
