"""Colour conversions over a 3840x2160 image: pixelpath beside OpenCV, scikit-image, colorsys
and a plain np.copyto of the same image (the memory-bandwidth floor), all from the same run.

    python benchmarks/bench_color.py [--repeat 7] [--threads N]

Times are the best of ``--repeat`` runs, in milliseconds. pixelpath is timed twice: writing a
fresh array (``new``) and reusing a buffer through ``out=`` (``out=``), which is what
``np.copyto`` and ``cv2.cvtColor(..., dst=)`` are timed with. colorsys converts one pixel per
call, so it is timed on 200,000 pixels and scaled to the image (stated in the table).
"""

from __future__ import annotations

import argparse
import colorsys
import time

import numpy as np

import pixelpath
from pixelpath import color

HEIGHT, WIDTH = 2160, 3840


def best_ms(fn, repeat):
    fn()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return 1e3 * min(times)


def optional(module):
    try:
        return __import__(module)
    except ImportError:
        print(f"  ({module} not installed: pip install '.[bench]' to compare with it)")
        return None


def bench_dtype(dtype, repeat, cv2, skcolor):
    rng = np.random.default_rng(0)
    if dtype == np.uint8:
        image = rng.integers(0, 256, (HEIGHT, WIDTH, 3), dtype=np.uint8)
    else:
        image = rng.random((HEIGHT, WIDTH, 3), dtype=np.float32)
    result_dtype = np.float32 if dtype == np.float32 else np.float64
    rows = []

    copy_dst = np.empty_like(image)
    rows.append(("np.copyto (floor)", "", best_ms(lambda: np.copyto(copy_dst, image), repeat)))

    buffers = {
        3: np.empty((HEIGHT, WIDTH, 3), result_dtype),
        4: np.empty((HEIGHT, WIDTH, 4), result_dtype),
    }
    conversions = [
        ("rgb_to_hsv", color.rgb_to_hsv, 3),
        ("rgb_to_hsl", color.rgb_to_hsl, 3),
        ("rgb_to_yiq", color.rgb_to_yiq, 3),
        ("rgb_to_ycbcr", color.rgb_to_ycbcr, 3),
        ("rgb_to_cmy", color.rgb_to_cmy, 3),
        ("rgb_to_cmyk", color.rgb_to_cmyk, 4),
    ]
    for name, fn, channels in conversions:
        new = best_ms(lambda fn=fn: fn(image), repeat)
        reuse = best_ms(lambda fn=fn, c=channels: fn(image, out=buffers[c]), repeat)
        rows.append((f"pixelpath {name}", f"new {new:.1f} / out= {reuse:.1f}", reuse))
    hsv = color.rgb_to_hsv(image)
    hsl = color.rgb_to_hsl(image)
    for name, fn, values in (
        ("hsv_to_rgb", color.hsv_to_rgb, hsv),
        ("hsl_to_rgb", color.hsl_to_rgb, hsl),
    ):
        new = best_ms(lambda fn=fn, v=values: fn(v), repeat)
        reuse = best_ms(lambda fn=fn, v=values: fn(v, out=buffers[3]), repeat)
        rows.append((f"pixelpath {name}", f"new {new:.1f} / out= {reuse:.1f}", reuse))

    if cv2 is not None:
        cv_dst = np.empty_like(image)
        hsv_cv = cv2.cvtColor(image, cv2.COLOR_RGB2HSV)
        hls_cv = cv2.cvtColor(image, cv2.COLOR_RGB2HLS)
        for code, source in (
            ("RGB2HSV", image),
            ("RGB2HLS", image),
            ("HSV2RGB", hsv_cv),
            ("HLS2RGB", hls_cv),
            ("RGB2YCrCb", image),
        ):
            flag = getattr(cv2, f"COLOR_{code}")
            ms = best_ms(lambda f=flag, src=source: cv2.cvtColor(src, f, dst=cv_dst), repeat)
            rows.append((f"OpenCV cvtColor {code}", "dst=", ms))
    if skcolor is not None:
        few = max(1, repeat // 3)
        rows.append(
            ("scikit-image rgb2hsv", f"best of {few}", best_ms(lambda: skcolor.rgb2hsv(image), few))
        )
        rows.append(("scikit-image rgb2yiq", "", best_ms(lambda: skcolor.rgb2yiq(image), few)))
        rows.append(("scikit-image rgb2ycbcr", "", best_ms(lambda: skcolor.rgb2ycbcr(image), few)))

    sample = (image.reshape(-1, 3)[:200_000] / (255.0 if dtype == np.uint8 else 1.0)).tolist()
    start = time.perf_counter()
    for r, g, b in sample:
        colorsys.rgb_to_hsv(r, g, b)
    per_image = (time.perf_counter() - start) * (HEIGHT * WIDTH / len(sample)) * 1e3
    rows.append(("colorsys.rgb_to_hsv (per pixel)", "200k px, scaled", per_image))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--threads", type=int, default=None, help="Numba and OpenCV threads")
    args = parser.parse_args()

    import numba

    if args.threads:
        numba.set_num_threads(args.threads)
    pixelpath.warmup()
    cv2 = optional("cv2")
    if cv2 is not None and args.threads:
        cv2.setNumThreads(args.threads)
    try:
        from skimage import color as skcolor
    except ImportError:
        skcolor = None
        print("  (scikit-image not installed: pip install '.[bench]' to compare with it)")

    print(
        f"image {WIDTH}x{HEIGHT}; numba threads {numba.get_num_threads()}"
        + (f", OpenCV threads {cv2.getNumThreads()}" if cv2 is not None else "")
    )
    for dtype in (np.float32, np.uint8):
        print(f"\n{np.dtype(dtype).name} input")
        print(f"  {'conversion':34s} {'ms':>9s}  note")
        for name, note, ms in bench_dtype(dtype, args.repeat, cv2, skcolor):
            print(f"  {name:34s} {ms:9.1f}  {note}")


if __name__ == "__main__":
    main()
