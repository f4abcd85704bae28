"""The first big call of a process: a 4K colour conversion and a render, beside their second.

A script that converts or renders one image lives in its first call. Each round starts a fresh
interpreter (kernels already in the cache), makes a tiny call first (a 1-pixel conversion, a
1-pixel render: imports and dispatch are paid there), then times the first full-size call and a
second one:

- ``rgb_to_hsv`` of a 3840x2160 float32 image, beside OpenCV's ``cvtColor(..., RGB2HSV)`` of the
  same image in its own fresh interpreter (the anchor; skipped with a message without OpenCV:
  ``pip install opencv-python-headless``);
- a render of the bundled showcase (z-buffer, Phong, 640x400), first against second.

Medians of ``--rounds`` rounds, in milliseconds::

    python benchmarks/bench_first_call.py [--rounds 7]
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys

PIXELPATH_COLOR = """
import json, time
import numpy as np
from pixelpath.color import rgb_to_hsv
image = np.random.default_rng(0).random((2160, 3840, 3), dtype=np.float32)
rgb_to_hsv(image[:1, :1])
times = []
for _ in range(2):
    start = time.perf_counter(); rgb_to_hsv(image); times.append(time.perf_counter() - start)
print(json.dumps(times))
"""

OPENCV_COLOR = """
import json, time
import numpy as np
import cv2
image = np.random.default_rng(0).random((2160, 3840, 3), dtype=np.float32)
cv2.cvtColor(image[:1, :1], cv2.COLOR_RGB2HSV)
times = []
for _ in range(2):
    start = time.perf_counter(); cv2.cvtColor(image, cv2.COLOR_RGB2HSV)
    times.append(time.perf_counter() - start)
print(json.dumps(times))
"""

PIXELPATH_RENDER = """
import dataclasses, json, time
import pixelpath as pp
from pixelpath.scene import bundled_scenes, load_scene
scene = load_scene(bundled_scenes()["showcase"])
pp.render(dataclasses.replace(scene, camera=scene.camera.with_size(1, 1)), "zbuffer", "phong")
times = []
for _ in range(2):
    start = time.perf_counter(); pp.render(scene, "zbuffer", "phong")
    times.append(time.perf_counter() - start)
print(json.dumps(times))
"""


def rounds_of(script: str, rounds: int) -> tuple[float, float] | None:
    """Return the median first and second call, in ms, over fresh interpreters (None: failed)."""
    firsts, seconds = [], []
    for _ in range(rounds):
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
        if done.returncode != 0:
            print(f"  (could not run: {done.stderr.strip().splitlines()[-1]})")
            return None
        first, second = json.loads(done.stdout)
        firsts.append(first * 1e3)
        seconds.append(second * 1e3)
    return statistics.median(firsts), statistics.median(seconds)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    rounds_of(PIXELPATH_RENDER, 1)  # fill the kernel cache before anything is timed
    rows = [
        ("rgb_to_hsv 3840x2160 float32", PIXELPATH_COLOR),
        ("cv2.cvtColor RGB2HSV (anchor)", OPENCV_COLOR),
        ("render showcase 640x400", PIXELPATH_RENDER),
    ]
    print(f"{'call':32} {'first ms':>9} {'second ms':>10} {'first/second':>13}")
    results = {}
    for label, script in rows:
        timed = rounds_of(script, args.rounds)
        if timed is None:
            continue
        results[label] = timed
        first, second = timed
        print(f"{label:32} {first:9.1f} {second:10.1f} {first / second:13.2f}")
    ours, anchor = (results.get(label) for label, _ in rows[:2])
    if ours and anchor:
        print(f"\nfirst 4K conversion: pixelpath / OpenCV = {ours[0] / anchor[0]:.2f}")


if __name__ == "__main__":
    main()
