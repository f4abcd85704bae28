"""Colour conversions over a 3840x2160 image: pixelpath beside OpenCV, scikit-image, colorsys
and a plain np.copyto of the same image (the memory-bandwidth floor), all from the same run.

    python benchmarks/bench_color.py [--repeat 15] [--threads N]

Each conversion is timed both ways: allocating its result (the common call, ``fn(image)``,
``cv2.cvtColor(image, code)``) and writing into a reused buffer (``out=``, ``dst=``). Each row's
pixelpath and OpenCV calls alternate, so a change in the machine's load reaches both; times are
the best of ``--repeat`` rounds, in milliseconds, and the last columns are pixelpath's time over
OpenCV's. uint8 images are converted by pixelpath to float64 (the default) and to float32
(``dtype="float32"``); OpenCV's nearest call is its float32 path after ``astype`` and scaling
(its uint8 path returns uint8, hue in 0..180). colorsys converts one pixel per call, so it is
timed on 200,000 pixels and scaled to the image (stated in the table).
"""

from __future__ import annotations

import argparse
import colorsys
import time

import numpy as np

import pixelpath
from pixelpath import color

HEIGHT, WIDTH = 2160, 3840

# pixelpath's converter, its OpenCV twin (None: OpenCV has none) and the input model.
PAIRS = [
    ("RGB → HSV", color.rgb_to_hsv, "RGB2HSV", "rgb"),
    ("RGB → HSL", color.rgb_to_hsl, "RGB2HLS", "rgb"),
    ("HSV → RGB", color.hsv_to_rgb, "HSV2RGB", "hsv"),
    ("HSL → RGB", color.hsl_to_rgb, "HLS2RGB", "hsl"),
    ("RGB → YCbCr", color.rgb_to_ycbcr, "RGB2YCrCb", "rgb"),
    ("RGB → YIQ", color.rgb_to_yiq, None, "rgb"),
    ("RGB → CMY", color.rgb_to_cmy, None, "rgb"),
    ("RGB → CMYK", color.rgb_to_cmyk, None, "rgb"),
]


def best_ms(calls: dict, repeat: int) -> dict:
    """Time each call ``repeat`` times, alternating between them; return the best, in ms."""
    for fn in calls.values():
        fn()
    times = {name: [] for name in calls}
    for _ in range(repeat):
        for name, fn in calls.items():
            start = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - start)
    return {name: 1e3 * min(values) for name, values in times.items()}


def optional(module):
    try:
        return __import__(module)
    except ImportError:
        print(f"  ({module} not installed: pip install '.[bench]' to compare with it)")
        return None


def float32_rows(image: np.ndarray, repeat: int, cv2) -> list[tuple]:
    """(label, pixelpath new, pixelpath out=, OpenCV new, OpenCV dst=) for float32 input."""
    inputs = {"rgb": image, "hsv": color.rgb_to_hsv(image), "hsl": color.rgb_to_hsl(image)}
    copy_dst = np.empty_like(image)
    floor = best_ms({"copy": lambda: np.copyto(copy_dst, image)}, repeat)["copy"]
    rows = [("np.copyto (the floor)", None, floor, None, None)]
    for label, fn, code, model in PAIRS:
        twin = None
        if cv2 is not None and code is not None:
            flag = getattr(cv2, f"COLOR_{code}")
            # OpenCV converts its own HSV/HLS images (HLS orders L before S).
            source = (
                image
                if model == "rgb"
                else cv2.cvtColor(image, getattr(cv2, f"COLOR_RGB2{code[:3]}"))
            )
            twin = _opencv_calls(cv2, flag, source)
        rows.append(_row(label, fn, inputs[model], {}, twin, repeat))
    return rows


def uint8_rows(image: np.ndarray, repeat: int, cv2) -> list[tuple]:
    """The same for uint8 input: pixelpath to float64 and to float32, OpenCV's float path."""
    rows = []
    for label, fn, code, _ in PAIRS[:2] + PAIRS[4:6]:
        twin = None
        if cv2 is not None and code is not None:
            twin = _opencv_calls(cv2, getattr(cv2, f"COLOR_{code}"), image, scale=1 / 255)
        rows.append(_row(f"{label}, float64", fn, image, {}, None, repeat))
        rows.append(_row(f"{label}, float32", fn, image, {"dtype": "float32"}, twin, repeat))
    return rows


def _opencv_calls(cv2, flag: int, source: np.ndarray, scale: float | None = None) -> dict:
    """OpenCV's allocating and ``dst=`` calls; with ``scale``, from integers via float32."""
    dst = np.empty(source.shape, np.float32)
    if scale is None:
        return {
            "cv new": lambda: cv2.cvtColor(source, flag),
            "cv dst": lambda: cv2.cvtColor(source, flag, dst=dst),
        }
    scaled = np.empty(source.shape, np.float32)

    def into_buffers():
        np.multiply(source, np.float32(scale), out=scaled)
        return cv2.cvtColor(scaled, flag, dst=dst)

    return {
        "cv new": lambda: cv2.cvtColor(source.astype(np.float32) * np.float32(scale), flag),
        "cv dst": into_buffers,
    }


def _row(label: str, fn, values: np.ndarray, options: dict, twin: dict | None, repeat: int):
    out = fn(values, **options)  # a result-shaped buffer for out=
    calls = {"new": lambda: fn(values, **options), "out": lambda: fn(values, out=out, **options)}
    ms = best_ms(calls | (twin or {}), repeat)
    return label, ms["new"], ms["out"], ms.get("cv new"), ms.get("cv dst")


def print_rows(rows: list[tuple]) -> None:
    def cell(value):
        return f"{value:9.1f}" if value is not None else f"{'':9s}"

    def ratio(a, b):
        return f"{a / b:7.2f}×" if a is not None and b is not None else f"{'':8s}"

    header = ("conversion", "pp new", "pp out=", "cv new", "cv dst=", "new", "out=")
    print(
        f"  {header[0]:24s}"
        + "".join(f"{h:>9s}" for h in header[1:5])
        + f"{'pp/cv ' + header[5]:>12s}{header[6]:>8s}"
    )
    for label, new, out, cv_new, cv_dst in rows:
        print(
            f"  {label:24s}{cell(new)}{cell(out)}{cell(cv_new)}{cell(cv_dst)}"
            f"    {ratio(new, cv_new)}{ratio(out, cv_dst)}"
        )


def others(image: np.ndarray, repeat: int) -> None:
    """scikit-image (a few runs: it is slow) and colorsys, one pixel per call."""
    try:
        from skimage import color as skcolor
    except ImportError:
        print("  (scikit-image not installed: pip install '.[bench]' to compare with it)")
    else:
        few = max(1, repeat // 5)
        for name in ("rgb2hsv", "rgb2yiq", "rgb2ycbcr"):
            fn = getattr(skcolor, name)
            ms = best_ms({name: lambda fn=fn: fn(image)}, few)[name]
            print(f"  scikit-image {name:11s} {ms:9.1f}  (best of {few})")
    sample = image.reshape(-1, 3)[:200_000].tolist()
    start = time.perf_counter()
    for r, g, b in sample:
        colorsys.rgb_to_hsv(r, g, b)
    per_image = (time.perf_counter() - start) * (HEIGHT * WIDTH / len(sample)) * 1e3
    print(f"  colorsys.rgb_to_hsv      {per_image:9.1f}  (200k pixels, scaled to the image)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--threads", type=int, default=None, help="Numba and OpenCV threads")
    args = parser.parse_args()

    import numba

    if args.threads:
        numba.set_num_threads(args.threads)
    pixelpath.warmup()
    cv2 = optional("cv2")
    if cv2 is not None and args.threads:
        cv2.setNumThreads(args.threads)
    print(
        f"image {WIDTH}x{HEIGHT}; best of {args.repeat}, ms; numba threads "
        f"{numba.get_num_threads()}"
        + (f", OpenCV threads {cv2.getNumThreads()}" if cv2 is not None else "")
    )
    rng = np.random.default_rng(0)
    image = rng.random((HEIGHT, WIDTH, 3), dtype=np.float32)
    print("\nfloat32 input")
    print_rows(float32_rows(image, args.repeat, cv2))
    others(image, args.repeat)
    print("\nuint8 input (pixelpath to float64 and, with dtype=, float32; OpenCV via float32)")
    print_rows(
        uint8_rows(rng.integers(0, 256, (HEIGHT, WIDTH, 3), dtype=np.uint8), args.repeat, cv2)
    )


if __name__ == "__main__":
    main()
