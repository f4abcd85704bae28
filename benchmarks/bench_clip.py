"""Batch polygon clipping: pixelpath beside shapely (GEOS) and pyclipper, from the same run.

100,000 random star-shaped polygons of 8-64 vertices (radii jittered, so most are concave):
about a third inside the window, a third crossing its boundary and a third outside, clipped
against a rectangle; seed fixed. Also the latency of one small clip call from Python.

    python benchmarks/bench_clip.py [--count 100000] [--seed 1] [--repeat 5]

Timings are the best of ``--repeat`` runs. shapely's geometry construction is reported on its
own line (pixelpath needs no construction: it clips the coordinate arrays themselves), and so is
pixelpath's list interface (flattening the list of arrays and splitting the result).
"""

from __future__ import annotations

import argparse
import time
import timeit

import numpy as np

from pixelpath.clip import Rect, clip_flat, clip_polygons, sutherland_hodgman

WINDOW = (0.0, 0.0, 100.0, 100.0)


def star_polygons(count: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Return the flat coordinates and offsets of ``count`` random star-shaped polygons."""
    rng = np.random.default_rng(seed)
    sizes = rng.integers(8, 65, count)
    offsets = np.zeros(count + 1, dtype=np.intp)
    np.cumsum(sizes, out=offsets[1:])
    radius = rng.uniform(1.0, 5.0, count)
    centres = _centres(rng, radius)
    owner = np.repeat(np.arange(count), sizes)
    index = np.arange(offsets[-1]) - offsets[owner]
    angles = (index + rng.uniform(0, 0.45, owner.size)) * (2 * np.pi / sizes[owner])
    reach = radius[owner] * rng.uniform(0.5, 1.0, owner.size)
    coords = centres[owner] + reach[:, None] * np.column_stack([np.cos(angles), np.sin(angles)])
    return np.ascontiguousarray(coords), offsets


def _centres(rng: np.random.Generator, radius: np.ndarray) -> np.ndarray:
    """A third well inside, a third on the boundary, a third well outside the window."""
    count = radius.size
    kind = rng.integers(0, 3, count)
    inside = rng.uniform(radius[:, None] + 1, 100 - radius[:, None] - 1, (count, 2))
    along = rng.uniform(0, 100, count)
    side = rng.integers(0, 4, count)
    crossing = np.where(
        (side < 2)[:, None],
        np.column_stack([100.0 * side, along]),
        np.column_stack([along, 100.0 * (side - 2)]),
    )
    angle = rng.uniform(0, 2 * np.pi, count)
    far = 50 + (71 + radius) * rng.uniform(1.0, 1.5, count)
    outside = 50 + far[:, None] * np.column_stack([np.cos(angle), np.sin(angle)])
    return np.choose(kind[:, None], [inside, crossing, outside])


def best_of(repeat: int, fn) -> tuple[float, object]:
    best, result = np.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result


def signed_areas(coords: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    x, y = coords[:, 0], coords[:, 1]
    owner = np.repeat(np.arange(offsets.size - 1), np.diff(offsets))
    nxt = np.arange(coords.shape[0]) + 1
    nxt[offsets[1:][np.diff(offsets) > 0] - 1] = offsets[:-1][np.diff(offsets) > 0]
    terms = x * y[nxt] - x[nxt] * y
    return 0.5 * np.bincount(owner, weights=terms, minlength=offsets.size - 1)


def bench_pixelpath(coords, offsets, repeat):
    window = Rect(*WINDOW)
    clip_flat(coords[: offsets[2]], offsets[:3], window)  # load the compiled kernel first
    flat_time, (out, out_offsets) = best_of(repeat, lambda: clip_flat(coords, offsets, window))
    polygons = np.split(coords, offsets[1:-1])
    list_time, _ = best_of(repeat, lambda: clip_polygons(polygons, window))
    area = np.abs(signed_areas(out, out_offsets)).sum()
    return flat_time, list_time, out_offsets[-1], area


def bench_shapely(coords, offsets, repeat):
    import shapely

    owner = np.repeat(np.arange(offsets.size - 1), np.diff(offsets))

    def build():
        return shapely.polygons(shapely.linearrings(coords, indices=owner))

    build_time, geoms = best_of(repeat, build)
    clip_time, clipped = best_of(repeat, lambda: shapely.clip_by_rect(geoms, *WINDOW))
    return build_time, clip_time, float(shapely.area(clipped).sum())


def bench_pyclipper(coords, offsets):
    import pyclipper

    scale = 2**20
    x0, y0, x1, y1 = WINDOW
    window = pyclipper.scale_to_clipper([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], scale)
    paths = [pyclipper.scale_to_clipper(p.tolist(), scale) for p in np.split(coords, offsets[1:-1])]
    start = time.perf_counter()
    area = 0.0
    for path in paths:
        clipper = pyclipper.Pyclipper()
        clipper.AddPath(window, pyclipper.PT_CLIP, True)
        clipper.AddPath(path, pyclipper.PT_SUBJECT, True)
        for piece in clipper.Execute(pyclipper.CT_INTERSECTION):
            area += abs(pyclipper.Area(piece))
    return time.perf_counter() - start, area / scale**2


def bench_latency(number: int = 20000) -> tuple[float, float | None]:
    square = np.array([[1.0, 1.0], [9.0, 1.0], [9.0, 7.0], [1.0, 7.0]])
    window = Rect(2, 2, 8, 6)
    sutherland_hodgman(square, window)
    ours = min(timeit.repeat(lambda: sutherland_hodgman(square, window), number=number, repeat=5))
    try:
        import shapely
    except ImportError:
        return ours / number, None
    polygon = shapely.Polygon(square)
    theirs = min(timeit.repeat(lambda: shapely.clip_by_rect(polygon, 2, 2, 8, 6), number=number,
                               repeat=5))
    return ours / number, theirs / number


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()

    import numba

    coords, offsets = star_polygons(args.count, args.seed)
    print(f"{args.count:,} polygons, {len(coords):,} vertices, window {WINDOW}, "
          f"numba threads: {numba.get_num_threads()}, best of {args.repeat}")
    flat_time, list_time, out_vertices, area = bench_pixelpath(coords, offsets, args.repeat)
    print(f"pixelpath clip_flat (clipping)        {flat_time * 1e3:9.1f} ms   "
          f"area {area:.6f}, {out_vertices:,} vertices out")
    print(f"pixelpath clip_polygons (list in/out) {list_time * 1e3:9.1f} ms")
    try:
        build_time, clip_time, shapely_area = bench_shapely(coords, offsets, args.repeat)
    except ImportError:
        print("shapely not installed: skipped (pip install 'pixelpath[bench]')")
    else:
        print(f"shapely clip_by_rect (clipping)       {clip_time * 1e3:9.1f} ms   "
              f"area {shapely_area:.6f}")
        print(f"shapely geometry construction         {build_time * 1e3:9.1f} ms")
        print(f"speed-up on the clipping itself: {clip_time / flat_time:.1f}x")
    try:
        pyclipper_time, pyclipper_area = bench_pyclipper(coords, offsets)
    except ImportError:
        print("pyclipper not installed: skipped (pip install 'pixelpath[bench]')")
    else:
        print(f"pyclipper (one Pyclipper per polygon) {pyclipper_time * 1e3:9.1f} ms   "
              f"area {pyclipper_area:.6f}")
    ours, theirs = bench_latency()
    line = f"one small clip from Python: pixelpath {ours * 1e6:.2f} us"
    if theirs is not None:
        line += f", shapely.clip_by_rect {theirs * 1e6:.2f} us"
    print(line)


if __name__ == "__main__":
    main()
