"""Colour-model exercises: convert one colour, step by step (the notes' colour chapters).

The worked solution is :func:`pixelpath.color.explain.explain`, the same steps that
``pixelpath color --explain`` prints, one line per step.
"""

from __future__ import annotations

import random

from pixelpath.exercises.exercise import Field, Step
from pixelpath.exercises.topics import Solved, register

_MARKING = "Each value is accepted within ±0.01 (two decimals)"


def _conversion(src: str, dst: str, fields: tuple[tuple[str, str, int], ...],
                titles: tuple[str, ...]):
    """Make the solve function of one conversion: fields are (name, label, step line)."""

    def solve(params: dict) -> Solved:
        from pixelpath.color.explain import explain

        given = params[src]
        lines, result = explain(given, src, dst)
        lines = [line for line in lines if not line.endswith(":")]
        if len(lines) != len(titles):
            raise AssertionError(f"{src}->{dst}: {len(lines)} steps for {len(titles)} titles")
        values = dict(zip(_result_names(dst), result, strict=True))
        steps = tuple(Step(title, (line,)) for title, line in zip(titles, lines, strict=True))
        return Solved(
            question=_question(src, dst, given),
            answer={name: values[name] for name, _, _ in fields},
            fields=tuple(Field(name, label, step + 1, tolerance=1.0 if name == "h" else 0.01)
                         for name, label, step in fields),
            steps=steps,
            marking=_MARKING + ("; hue within ±1° (whole degrees)." if dst == "hsv" else "."),
        )

    return solve


def _result_names(model: str) -> tuple[str, ...]:
    return {"hsv": ("h", "s", "v"), "rgb": ("r", "g", "b"), "cmy": ("c", "m", "y"),
            "cmyk": ("c", "m", "y", "k"), "yiq": ("y", "i", "q")}[model]


def _question(src: str, dst: str, given: list) -> str:
    names = ", ".join(src.upper())
    values = ", ".join(f"{v:g}°" if src == "hsv" and k == 0 else f"{v:g}"
                       for k, v in enumerate(given))
    units = {"hsv": "Give H in degrees and S, V in [0, 1].",
             "rgb": "Give R, G, B in [0, 1].",
             "cmy": "Give C, M, Y in [0, 1].",
             "cmyk": "Give C, M, Y, K in [0, 1].",
             "yiq": "Use the notes' matrix; give Y, I, Q to two decimals."}[dst]
    scale = " (each in [0, 1])" if src == "rgb" else ""
    return (f"Convert the {src.upper()} colour ({names}) = ({values}){scale} to the "
            f"{dst.upper()} model. {units}")


def _channel(rng: random.Random, difficulty: str) -> float:
    step = 0.1 if difficulty == "easy" else 0.05
    return round(rng.randint(0, round(1 / step)) * step, 2)


def pick_rgb(rng: random.Random, difficulty: str) -> dict:
    """Pick an RGB colour in steps of 0.05 (0.1 when easy); never a grey unless ``edge``."""
    while True:
        rgb = [_channel(rng, difficulty) for _ in range(3)]
        if difficulty == "edge" and rng.random() < 0.3:
            grey = _channel(rng, difficulty)
            return {"rgb": [grey, grey, grey]}
        if max(rgb) - min(rgb) >= 0.1:
            return {"rgb": rgb}


def pick_hsv(rng: random.Random, difficulty: str) -> dict:
    """Pick an HSV colour: H in steps of 5° (30° when easy), S > 0 unless ``edge``."""
    hue_step = 30 if difficulty == "easy" else 5
    hue = rng.randint(0, 360 // hue_step - 1) * hue_step
    low = 0 if difficulty == "edge" else 0.2
    while True:
        s, v = _channel(rng, difficulty), _channel(rng, difficulty)
        if s >= low and v >= low:
            return {"hsv": [hue, s, v]}


_RGB_HSV = (("Cmax", "Cmin", "Δ = Cmax − Cmin", "hue H", "value V", "saturation S"),
            (("h", "the hue H in degrees", 3), ("s", "the saturation S", 5),
             ("v", "the value V", 4)))
_HSV_RGB = ("chroma C = V × S", "X", "m = V − C", "the sector of H", "add m")

register("rgb-hsv", "RGB to HSV", "Colour models: HSV", pick_rgb,
         _conversion("rgb", "hsv", _RGB_HSV[1], _RGB_HSV[0]))
register("hsv-rgb", "HSV to RGB", "Colour models: HSV", pick_hsv,
         _conversion("hsv", "rgb", (("r", "red R", 4), ("g", "green G", 4),
                                    ("b", "blue B", 4)), _HSV_RGB))
register("rgb-cmy", "RGB to CMY", "Colour models: CMY", pick_rgb,
         _conversion("rgb", "cmy", (("c", "cyan C", 0), ("m", "magenta M", 0),
                                    ("y", "yellow Y", 0)), ("subtract from 1",)))
register("hsv-cmy", "HSV to CMY", "Colour models: HSV and CMY", pick_hsv,
         _conversion("hsv", "cmy", (("c", "cyan C", 5), ("m", "magenta M", 5),
                                    ("y", "yellow Y", 5)), (*_HSV_RGB, "subtract from 1")))
register("rgb-cmyk", "RGB to CMYK", "Colour models: CMY", pick_rgb,
         _conversion("rgb", "cmyk", (("k", "black K", 1), ("c", "cyan C′", 2),
                                     ("m", "magenta M′", 2), ("y", "yellow Y′", 2)),
                     ("subtract from 1", "black K = min(C, M, Y)", "C′, M′, Y′")))
register("rgb-yiq", "RGB to YIQ", "Colour models: YIQ", pick_rgb,
         _conversion("rgb", "yiq", (("y", "luma Y", 0), ("i", "in-phase I", 1),
                                    ("q", "quadrature Q", 2)), ("Y row", "I row", "Q row")))
