"""Hidden-surface methods side by side: each one's time beside the z-buffer's, from one run.

Renders one scene at three sizes (about 1k, 10k and 100k triangles after tessellation) at
1024×768 with per-pixel Phong shading and every raster method of the notes, and prints
milliseconds per frame (median of several frames after a warm-up frame) and each method's
ratio to the z-buffer measured in the same run, then how each method's time grows from one
size to the next. The scene: twelve interlocking tori and icospheres over a ground grid, so
objects overlap on screen and in depth (work for the painter's sort and the BSP splits).

The BSP tree is built once per scene and reused from any camera; its build time and size are
printed on their own line (the method's time is the traversal and drawing with the tree
already built).

Usage::

    python benchmarks/bench_hsr.py [--frames 5] [--sizes 1k,10k,100k] [--methods all]
"""

from __future__ import annotations

import argparse
import itertools
import statistics
import time

import numpy as np

import pixelpath as pp
from pixelpath.renderer import METHOD_NAMES
from pixelpath.scene import icosphere, torus

RASTER_METHODS = [name for name in METHOD_NAMES if name != "raytrace"]
# Tessellation per size: (icosphere subdivisions, torus segments around, torus segments across).
LEVELS = {"1k": (0, 12, 6), "10k": (3, 20, 10), "100k": (4, 104, 52)}


def scene_of(level: str) -> pp.Scene:
    """Twelve tori and icospheres in two interlocking rows, over a subdivided ground."""
    subdivisions, around, across = LEVELS[level]
    rng = np.random.default_rng(7)
    objects = []
    for k in range(12):
        x, z = -2.75 + (k % 6) * 1.1, -0.6 + (k // 6) * 1.2
        material = pp.Material(color=rng.uniform(0.2, 1.0, 3), ks=0.5, shininess=32)
        if k % 2:
            objects.append(icosphere(subdivisions, 0.55, (x, 0.6, z), material))
        else:
            ring = torus(0.6, 0.18, around, across, material=material)
            matrix = pp.scene.transform_matrix(translate=(x, 0.7, z), rotate=(80, 20 * k, 0))
            objects.append(ring.transformed(matrix))
    n = 8
    xs = np.linspace(-4, 4, n + 1)
    gx, gz = np.meshgrid(xs, xs)
    ground = np.stack([gx.ravel(), np.zeros(gx.size), gz.ravel()], axis=1)
    first = (np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]).ravel()
    quads = np.stack([first, first + n + 1, first + n + 2, first + 1], axis=1)
    objects.append(pp.Mesh(ground, quads, pp.Material(color=(0.7, 0.7, 0.65), ks=0.1)))
    camera = pp.Camera(eye=(0.5, 3.2, 6.0), target=(0.0, 0.5, 0.0), fov=45, width=1024,
                       height=768)
    lights = [pp.PointLight((4, 6, 5)), pp.DirectionalLight(direction=(-1, -1, -0.5),
                                                            intensity=0.4)]
    return pp.Scene(camera, objects=objects, lights=lights, ambient=0.15)


def triangle_count(scene: pp.Scene) -> int:
    """Triangles in the scene after tessellation."""
    return sum(len(obj.triangles) for obj in scene.objects)


def time_method(scene: pp.Scene, method: str, frames: int) -> float:
    """Median milliseconds per frame after one warm-up frame."""
    pp.render(scene, method)
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        pp.render(scene, method)
        times.append(1000 * (time.perf_counter() - start))
    return statistics.median(times)


def bsp_build(scene: pp.Scene) -> str:
    """The BSP tree's build time and size for this scene, or why it is not measured."""
    try:
        from pixelpath.hsr import bsp
    except ImportError:
        return "BSP not available"
    start = time.perf_counter()
    tree = bsp.build_tree(scene)
    seconds = time.perf_counter() - start
    return f"BSP build {1000 * seconds:.0f} ms: {tree}"


def available(methods: list[str]) -> list[str]:
    """The methods this installation implements (the others are reported and skipped)."""
    from pixelpath.renderer import _method_module

    found = []
    for method in methods:
        try:
            _method_module(method)
        except NotImplementedError:
            print(f"({method}: not implemented in this version, skipped)")
        else:
            found.append(method)
    return found


def main() -> None:
    """Time every method at every size and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--sizes", default="1k,10k,100k", help="comma-separated: 1k, 10k, 100k")
    parser.add_argument("--methods", default="all")
    args = parser.parse_args()
    unknown = set(args.sizes.split(",")) - set(LEVELS)
    if unknown:
        parser.error(f"unknown sizes {sorted(unknown)}; choose from {', '.join(LEVELS)}")
    methods = RASTER_METHODS if args.methods == "all" else args.methods.split(",")
    methods = available(["zbuffer", *[m for m in methods if m != "zbuffer"]])
    import numba

    print(f"1024x768, Phong shading, {numba.get_num_threads()} Numba threads, "
          f"median of {args.frames} frames")
    results: dict[str, dict[str, float]] = {}
    for level in args.sizes.split(","):
        scene = scene_of(level)
        print(f"\n{level}: {triangle_count(scene):,} triangles")
        if "bsp" in methods:
            print(f"  {bsp_build(scene)}")
        results[level] = {}
        for method in methods:
            ms = time_method(scene, method, args.frames)
            results[level][method] = ms
            ratio = ms / results[level]["zbuffer"]
            print(f"  {method:8s} {ms:9.1f} ms   {ratio:6.2f}x z-buffer")
    levels = list(results)
    if len(levels) > 1:
        print("\ngrowth of each method's time from one size to the next")
        for method in methods:
            steps = [results[b][method] / results[a][method] for a, b in itertools.pairwise(levels)]
            print(f"  {method:8s} " + "  ".join(f"{s:5.1f}x" for s in steps))


if __name__ == "__main__":
    main()
