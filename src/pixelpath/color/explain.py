"""Step-by-step conversions of one colour, in the words and order of the notes.

This is a second implementation of the formulas, deliberately in the notes' case-by-case form
(which hue case applied, which row of the sector table) and in plain Python floats: the teaching
output must match the notes, and the tests check that its results agree with the compiled,
branch-free kernels.
"""

from __future__ import annotations

from collections.abc import Sequence

from pixelpath.color import _matrices as mx
from pixelpath.color.models import MODELS

_SECTORS = (
    ("0-60", "C, X, 0"),
    ("60-120", "X, C, 0"),
    ("120-180", "0, C, X"),
    ("180-240", "0, X, C"),
    ("240-300", "X, 0, C"),
    ("300-360", "C, 0, X"),
)


def fmt(value: float) -> str:
    """Format a number the way a student writes it: up to 4 decimals, no trailing zeros."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _rgb_to_hsx(rgb: Sequence[float], model: str) -> tuple[list[str], list[float]]:
    r, g, b = rgb
    cmax, cmin = max(r, g, b), min(r, g, b)
    delta = cmax - cmin
    steps = [
        f"Cmax = max(R, G, B) = {fmt(cmax)}",
        f"Cmin = min(R, G, B) = {fmt(cmin)}",
        f"Δ = Cmax − Cmin = {fmt(cmax)} − {fmt(cmin)} = {fmt(delta)}",
    ]
    if delta == 0:
        hue = 0.0
        steps.append("Δ = 0: a grey, so H = 0° (hue is undefined; 0 by convention)")
    elif cmax == r:
        hue = 60.0 * (((g - b) / delta) % 6.0)
        steps.append(
            f"Cmax = R, so H = 60 × ((G − B)/Δ mod 6) = 60 × (({fmt(g)} − {fmt(b)})/{fmt(delta)}"
            f" mod 6) = {fmt(hue)}°"
        )
    elif cmax == g:
        hue = 60.0 * ((b - r) / delta + 2.0)
        steps.append(
            f"Cmax = G, so H = 60 × ((B − R)/Δ + 2) = 60 × (({fmt(b)} − {fmt(r)})/{fmt(delta)}"
            f" + 2) = {fmt(hue)}°"
        )
    else:
        hue = 60.0 * ((r - g) / delta + 4.0)
        steps.append(
            f"Cmax = B, so H = 60 × ((R − G)/Δ + 4) = 60 × (({fmt(r)} − {fmt(g)})/{fmt(delta)}"
            f" + 4) = {fmt(hue)}°"
        )
    hue = hue % 360.0
    if model == "hsv":
        sat = delta / cmax if cmax > 0 else 0.0
        steps.append(f"V = Cmax = {fmt(cmax)}")
        steps.append(
            "S = 0 because Cmax = 0"
            if cmax <= 0
            else f"S = Δ/Cmax = {fmt(delta)}/{fmt(cmax)} = {fmt(sat)}"
        )
        return steps, [hue, sat, cmax]
    light = (cmax + cmin) / 2.0
    spread = min(cmax + cmin, 2.0 - cmax - cmin)  # = 1 − |2L − 1|, without cancellation
    sat = delta / spread if delta > 0 and spread > 0 else 0.0
    steps.append(f"L = (Cmax + Cmin)/2 = {fmt(light)}")
    steps.append(
        "S = 0 because Δ = 0"
        if delta == 0
        else f"S = Δ/(1 − |2L − 1|) = {fmt(delta)}/{fmt(spread)} = {fmt(sat)}"
    )
    return steps, [hue, sat, light]


def _hsx_to_rgb(values: Sequence[float], model: str) -> tuple[list[str], list[float]]:
    hue, sat, third = values
    wrapped = hue % 360.0
    steps = [] if wrapped == hue else [f"H = {fmt(hue)}° wraps to {fmt(wrapped)}° (mod 360)"]
    if model == "hsv":
        chroma = third * sat
        steps.append(f"C = V × S = {fmt(third)} × {fmt(sat)} = {fmt(chroma)}")
    else:
        chroma = min(2.0 * third, 2.0 - 2.0 * third) * sat  # (1 − |2L − 1|)·S, no cancellation
        steps.append(f"C = (1 − |2L − 1|) × S = {fmt(chroma)}")
    x = chroma * (1.0 - abs((wrapped / 60.0) % 2.0 - 1.0))
    low = third - chroma if model == "hsv" else third - chroma / 2.0
    steps.append(f"X = C × (1 − |(H/60) mod 2 − 1|) = {fmt(x)}")
    steps.append(f"m = {'V − C' if model == 'hsv' else 'L − C/2'} = {fmt(low)}")
    sector = min(int(wrapped // 60.0), 5)
    span, row = _SECTORS[sector]
    primes = [{"C": chroma, "X": x, "0": 0.0}[name.strip()] for name in row.split(",")]
    steps.append(
        f"H = {fmt(wrapped)}° lies in {span}°: (R', G', B') = ({row}) = "
        f"({', '.join(fmt(v) for v in primes)})"
    )
    rgb = [p + low for p in primes]
    steps.append(f"(R, G, B) = (R' + m, G' + m, B' + m) = ({', '.join(fmt(v) for v in rgb)})")
    return steps, rgb


def _matrix_steps(names: str, inputs: str, matrix, offset, values) -> tuple[list[str], list[float]]:
    steps, out = [], []
    for k, name in enumerate(names):
        row = [float(c) for c in matrix[k]]
        terms = f"{fmt(row[0])}×{inputs[0]}"
        for coefficient, label in zip(row[1:], inputs[1:], strict=True):
            sign = "−" if coefficient < 0 else "+"
            terms += f" {sign} {fmt(abs(coefficient))}×{label}"
        value = sum(c * v for c, v in zip(row, values, strict=True)) + float(offset[k])
        shift = f" + {fmt(offset[k])}" if offset[k] else ""
        steps.append(f"{name} = {terms}{shift} = {fmt(value)}")
        out.append(value)
    return steps, out


def _rgb_to_cmyk(rgb: Sequence[float]) -> tuple[list[str], list[float]]:
    cmy = [1.0 - v for v in rgb]
    black = min(cmy)
    steps = [f"C, M, Y = 1 − R, 1 − G, 1 − B = {', '.join(fmt(v) for v in cmy)}"]
    steps.append(f"K = min(C, M, Y) = {fmt(black)}")
    if black >= 1.0:
        steps.append("K = 1 (pure black): C' = M' = Y' = 0, avoiding 0/0")
        return steps, [0.0, 0.0, 0.0, 1.0]
    primes = [(v - black) / (1.0 - black) for v in cmy]
    steps.append(f"C', M', Y' = (C − K)/(1 − K), ... = {', '.join(fmt(v) for v in primes)}")
    return steps, [*primes, black]


def _to_rgb(values: Sequence[float], model: str) -> tuple[list[str], list[float]]:
    if model in ("hsv", "hsl"):
        return _hsx_to_rgb(values, model)
    if model == "cmy":
        rgb = [1.0 - v for v in values]
        return [f"R, G, B = 1 − C, 1 − M, 1 − Y = {', '.join(fmt(v) for v in rgb)}"], rgb
    if model == "cmyk":
        c, m, y, k = values
        rgb = [(1.0 - v) * (1.0 - k) for v in (c, m, y)]
        return [f"R, G, B = (1 − C')(1 − K), ... = {', '.join(fmt(v) for v in rgb)}"], rgb
    if model == "yiq":
        return _matrix_steps("RGB", "YIQ", mx.rgb_from_yiq, [0.0] * 3, values)
    inverse_offset = mx.inverse_offset(mx.rgb_from_ycbcr, mx.ycbcr_offset)
    return _matrix_steps("RGB", ["Y", "Cb", "Cr"], mx.rgb_from_ycbcr, inverse_offset, values)


def _from_rgb(rgb: Sequence[float], model: str) -> tuple[list[str], list[float]]:
    if model in ("hsv", "hsl"):
        return _rgb_to_hsx(rgb, model)
    if model == "cmy":
        cmy = [1.0 - v for v in rgb]
        return [f"C, M, Y = 1 − R, 1 − G, 1 − B = {', '.join(fmt(v) for v in cmy)}"], cmy
    if model == "cmyk":
        return _rgb_to_cmyk(rgb)
    if model == "yiq":
        return _matrix_steps("YIQ", "RGB", mx.yiq_from_rgb, [0.0] * 3, rgb)
    return _matrix_steps(["Y", "Cb", "Cr"], "RGB", mx.ycbcr_from_rgb, mx.ycbcr_offset, rgb)


def explain(values: Sequence[float], src: str, dst: str) -> tuple[list[str], list[float]]:
    """Convert one colour from ``src`` to ``dst``, returning the steps and the result.

    Parameters
    ----------
    values : sequence of float
        One colour of model ``src`` (RGB as floats in [0, 1]).
    src, dst : str
        Model names, as for :func:`pixelpath.color.convert`.

    Returns
    -------
    steps : list of str
        One line per step, in the notes' notation.
    result : list of float
        The converted colour.

    Examples
    --------
    >>> from pixelpath.color.explain import explain
    >>> steps, hsv = explain([1.0, 1.0, 0.0], "rgb", "hsv")
    >>> steps[3]
    'Cmax = R, so H = 60 × ((G − B)/Δ mod 6) = 60 × ((1 − 0)/1 mod 6) = 60°'
    >>> hsv
    [60.0, 1.0, 1.0]
    """
    for model in (src, dst):
        if model not in MODELS:
            raise ValueError(f"unknown colour model {model!r}; choose from {', '.join(MODELS)}")
    values = [float(v) for v in values]
    if src == dst:
        return [f"{src.upper()} to {dst.upper()}: nothing to do"], values
    steps: list[str] = []
    rgb = values
    if src != "rgb":
        head, rgb = _to_rgb(values, src)
        steps += [f"{src.upper()} → RGB:", *head] if dst != "rgb" else head
    if dst == "rgb":
        return steps, rgb
    tail, result = _from_rgb(rgb, dst)
    steps += [f"RGB → {dst.upper()}:", *tail] if src != "rgb" else tail
    return steps, result
