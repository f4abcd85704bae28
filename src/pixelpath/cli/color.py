"""``pixelpath color``: convert one colour (with the notes' steps) or a whole image file."""

from __future__ import annotations

import argparse
import re
from pathlib import Path
from typing import Any

from pixelpath.cli._common import CommandError, add_command, console

EXAMPLES = [
    "pixelpath color 255,255,0 --to hsv,yiq,cmy,cmyk",
    "pixelpath color '#ffff00' --to hsv --explain",
    "pixelpath color 0.2,0.4,0.6 --to hsl,ycbcr",
    "pixelpath color 200,0.5,0.8 --from hsv --to rgb --explain",
    "pixelpath color photo.png --to hsv -o photo_hsv.npy",
    "pixelpath color photo_hsv.npy --from hsv --to rgb -o roundtrip.png",
]

_COMPONENTS = {
    "rgb": ("R", "G", "B"),
    "hsv": ("H°", "S", "V"),
    "hsl": ("H°", "S", "L"),
    "cmy": ("C", "M", "Y"),
    "cmyk": ("C", "M", "Y", "K"),
    "yiq": ("Y", "I", "Q"),
    "ycbcr": ("Y", "Cb", "Cr"),
}
_HEX = re.compile(r"#?([0-9a-fA-F]{6}|[0-9a-fA-F]{3})")


def register(subparsers: Any) -> None:
    """Add the ``color`` subcommand."""
    parser = add_command(
        subparsers,
        "color",
        summary="convert a colour or an image between RGB, HSV, HSL, CMY, CMYK, YIQ and YCbCr",
        description=(
            "Convert one colour and print a table, or convert a whole image file. A colour is "
            "'255,255,0' (integers: 8-bit RGB), '#ffff00', or floats '1,1,0.0' (RGB in [0, 1]); "
            "with --from, the numbers are in that model's units (hue in degrees). A file (PNG, "
            "JPEG, ... or .npy) is converted whole to one model and written with -o: .npy for any "
            "model, an image format for RGB."
        ),
        examples=EXAMPLES,
        run=run,
    )
    parser.add_argument("value", help="a colour (255,255,0 | #ffff00 | 1,1,0.0) or a file")
    parser.add_argument("--from", dest="src", default="rgb", help="model of the input (rgb)")
    parser.add_argument(
        "--to", default="hsv,hsl,cmy,cmyk,yiq,ycbcr", help="models to convert to, comma-separated"
    )
    parser.add_argument("--explain", action="store_true", help="print each step as the notes do")
    parser.add_argument("-o", "--output", help="output file when converting an image")


def _models(text: str, flag: str) -> list[str]:
    from pixelpath.color import MODELS

    names = [name.strip().lower() for name in text.split(",") if name.strip()]
    for name in names:
        if name not in MODELS:
            raise CommandError(f"{flag}: unknown model {name!r}; choose from {', '.join(MODELS)}")
    if not names:
        raise CommandError(f"{flag}: give at least one model")
    return names


def parse_colour(text: str, model: str) -> tuple[list[float], str]:
    """Parse a colour argument; return its components as floats and how they were read."""
    match = _HEX.fullmatch(text.strip())
    if match and (text.startswith("#") or not text.replace(",", "").isdigit()):
        if model != "rgb":
            raise CommandError(f"hex colours are RGB; drop --from {model}")
        digits = match.group(1)
        if len(digits) == 3:
            digits = "".join(d * 2 for d in digits)
        return [int(digits[k : k + 2], 16) / 255.0 for k in (0, 2, 4)], "hex, 8-bit"
    parts = [part.strip() for part in text.split(",")]
    try:
        numbers = [float(part) for part in parts]
    except ValueError:
        raise CommandError(
            f"cannot read {text!r} as a colour: give numbers separated by commas "
            "(255,255,0 or 1,1,0.0), a hex colour (#ffff00), or an existing file"
        ) from None
    if model == "rgb" and all(re.fullmatch(r"[+-]?\d+", part) for part in parts):
        if any(not 0 <= v <= 255 for v in numbers):
            raise CommandError(f"8-bit RGB values must lie in 0..255, got {text}")
        return [v / 255.0 for v in numbers], "8-bit"
    return numbers, "floats"


def run(args: argparse.Namespace) -> int:
    """Convert a colour or a file."""
    src = _models(args.src, "--from")[0]
    targets = _models(args.to, "--to")
    path = Path(args.value)
    if path.suffix and path.exists():
        return _convert_file(path, src, targets, args.output)
    if args.output:
        raise CommandError(f"-o is for converting files, and {args.value!r} is not a file")
    values, how = parse_colour(args.value, src)
    _print_table(values, src, how, targets, args.explain)
    return 0


def _print_table(values: list[float], src: str, how: str, targets: list[str], explain: bool):
    from rich.table import Table

    from pixelpath.color import MODELS, convert
    from pixelpath.color.explain import explain as explain_steps
    from pixelpath.color.explain import fmt

    if len(values) != MODELS[src]:
        raise CommandError(f"{src.upper()} has {MODELS[src]} components, got {len(values)}")
    out = console()
    table = Table(title=f"{src.upper()} {', '.join(fmt(v) for v in values)} (read as {how})")
    table.add_column("model")
    table.add_column("components")
    table.add_column("values", justify="right")
    for model in targets:
        result = convert(values, src, model).tolist()
        shown = ", ".join(fmt(v) for v in result)
        if model == "rgb":
            shown += f"  (8-bit {', '.join(str(round(v * 255)) for v in result)})"
        table.add_row(model.upper(), ", ".join(_COMPONENTS[model]), shown)
    out.print(table)
    if explain:
        for model in targets:
            steps, _ = explain_steps(values, src, model)
            out.print(f"\n[bold]{src.upper()} → {model.upper()}[/bold]")
            for step in steps:
                out.print(f"  {step}", markup=False)


def _convert_file(path: Path, src: str, targets: list[str], output: str | None) -> int:
    import numpy as np

    from pixelpath.color import convert
    from pixelpath.io import read_image, write_image

    if len(targets) != 1:
        raise CommandError("a file converts to one model: give a single --to")
    if not output:
        raise CommandError("give the output file with -o (.npy, or .png for RGB)")
    if path.suffix.lower() == ".npy":
        data = np.load(path, allow_pickle=False)
    elif src == "rgb":
        data = read_image(path)
    else:
        raise CommandError(f"image files hold RGB; {src.upper()} data must come as .npy")
    result = convert(data, src, targets[0])
    destination = Path(output)
    if destination.suffix.lower() == ".npy":
        np.save(destination, result)
    elif targets[0] == "rgb":
        write_image(destination, result)
    else:
        raise CommandError(
            f"{targets[0].upper()} values do not fit an image file; write .npy instead"
        )
    console().print(f"wrote {destination} ({targets[0].upper()}, shape {result.shape})")
    return 0
