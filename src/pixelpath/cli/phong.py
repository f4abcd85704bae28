"""``pixelpath phong``: the exam-style illumination calculator of the notes.

Three ways to give the geometry:

* cosines: ``--ndotl`` and ``--rdotv``, as in the notes' worked example;
* vectors: ``--normal``, ``--to-light``, ``--to-eye`` (normalized, then N.L, R and R.V derived);
* points: ``--normal``, ``--surface``, ``--light``, ``--eye`` (L and V derived first).

Intensities and coefficients take one number or ``r,g,b`` for per-channel values.
"""

from __future__ import annotations

import argparse
from typing import Any

from pixelpath.cli._common import CommandError, add_command, console

EXAMPLES = [
    "pixelpath phong --ka 0.2 --kd 0.6 --ks 0.5 -n 20 --ia 0.2 --il 1 --ndotl 0.707 --rdotv 0.866",
    "pixelpath phong --normal 0,0,1 --to-light 1,1,1 --to-eye 0,1,1 --explain",
    "pixelpath phong --normal 0,1,0 --surface 0,0,0 --light 2,4,1 --eye=-3,5,2 --il 1,0.8,0.8",
    "pixelpath phong --normal 0,0,1 --to-light 0,1,1 --to-eye 0,0,1 --model blinn",
]


def register(subparsers: Any) -> None:
    """Add the ``phong`` subcommand."""
    parser = add_command(
        subparsers,
        "phong",
        summary="compute ambient, diffuse and specular intensity step by step (Phong model)",
        description=(
            "Evaluate I = ka Ia + kd IL max(0, N.L) + ks IL max(0, R.V)^n and print each term, "
            "the total and the total clamped to [0, 1]. Give the cosines (--ndotl, --rdotv), "
            "or the vectors N, L, V, or the surface, light and eye points. Defaults for the "
            "coefficients are the notes' worked example. Values beginning with '-' need '=' "
            "(--eye=-3,5,2)."
        ),
        examples=EXAMPLES,
        run=run,
    )
    material = parser.add_argument_group("material and light (a number, or r,g,b)")
    material.add_argument("--ka", default="0.2", help="ambient coefficient (default 0.2)")
    material.add_argument("--kd", default="0.6", help="diffuse coefficient (default 0.6)")
    material.add_argument("--ks", default="0.5", help="specular coefficient (default 0.5)")
    material.add_argument("-n", "--shininess", default="20", help="specular exponent (default 20)")
    material.add_argument("--ia", default="0.2", help="ambient light intensity Ia (default 0.2)")
    material.add_argument("--il", default="1", help="light source intensity IL (default 1)")
    cosines = parser.add_argument_group("geometry as cosines")
    cosines.add_argument("--ndotl", type=float, help="N.L = cos(theta)")
    cosines.add_argument("--rdotv", type=float, help="R.V = cos(alpha)")
    vectors = parser.add_argument_group("geometry as vectors or points (x,y,z)")
    vectors.add_argument("--normal", help="surface normal N")
    vectors.add_argument("--to-light", help="vector L from the surface point to the light")
    vectors.add_argument("--to-eye", help="vector V from the surface point to the eye")
    vectors.add_argument("--surface", help="the surface point P")
    vectors.add_argument("--light", help="the light position")
    vectors.add_argument("--eye", help="the eye position")
    vectors.add_argument(
        "--model",
        choices=("phong", "blinn"),
        default="phong",
        help="specular cosine: R.V (phong, default) or N.H with H = (L+V)/|L+V| (blinn)",
    )
    parser.add_argument("--explain", action="store_true", help="print each step in words")


def _numbers(text: str, name: str) -> tuple[float, ...]:
    try:
        return tuple(float(part) for part in text.split(","))
    except ValueError as exc:
        raise ValueError(f"{name} must be numbers separated by commas, got {text!r}") from exc


def _number(text: str, name: str) -> float:
    values = _numbers(text, name)
    if len(values) != 1:
        raise ValueError(f"{name} must be one number, got {text!r}")
    return values[0]


def _channels(text: str, name: str) -> float | tuple[float, ...]:
    values = _numbers(text, name)
    if len(values) not in (1, 3):
        raise ValueError(f"{name} must be one number or r,g,b, got {text!r}")
    return values[0] if len(values) == 1 else values


def _vector(text: str, name: str) -> tuple[float, ...]:
    values = _numbers(text, name)
    if len(values) != 3:
        raise ValueError(f"{name} must be x,y,z, got {text!r}")
    return values


def fmt(value: Any) -> str:
    """Format a number (or r,g,b) the way the notes write them: up to 4 decimals."""
    import numpy as np

    array = np.asarray(value, dtype=float)
    if array.ndim:
        return "(" + ", ".join(fmt(v) for v in array) + ")"
    x = float(array)
    if x == 0:
        return "0"
    if abs(x) < 5e-4:
        return f"{x:.3g}"
    return f"{x:.4f}".rstrip("0").rstrip(".")


def _geometry(args: argparse.Namespace) -> Any:
    """Return the PhongGeometry of vector or point mode, or None in cosine mode."""
    from pixelpath.lighting import phong_geometry

    vectors = (args.to_light, args.to_eye)
    points = (args.surface, args.light, args.eye)
    given = [x is not None for x in (*vectors, *points, args.normal)]
    cosines = args.ndotl is not None or args.rdotv is not None
    if not any(given):
        if args.ndotl is None or args.rdotv is None:
            raise CommandError(
                "give --ndotl and --rdotv, or --normal with --to-light and --to-eye, "
                "or --normal with --surface, --light and --eye"
            )
        if args.model == "blinn":
            raise CommandError("--model blinn needs vectors or points (N.H is derived from them)")
        return None
    if cosines:
        raise CommandError("give either the cosines (--ndotl, --rdotv) or vectors/points, not both")
    if args.normal is None:
        raise CommandError("--normal is required with vectors or points")
    normal = _vector(args.normal, "--normal")
    if all(v is not None for v in vectors) and all(p is None for p in points):
        return phong_geometry(normal, _vector(args.to_light, "--to-light"),
                              _vector(args.to_eye, "--to-eye"))
    if all(p is not None for p in points) and all(v is None for v in vectors):
        return phong_geometry(normal, surface=_vector(args.surface, "--surface"),
                              light=_vector(args.light, "--light"), eye=_vector(args.eye, "--eye"))
    raise CommandError(
        "give --to-light and --to-eye (vectors), or --surface, --light and --eye (points)"
    )


def _explain_geometry(out: Any, args: argparse.Namespace, g: Any) -> None:
    """Print steps 1-6 of the notes' 'Steps to compute Phong intensity'."""
    if args.surface is not None:
        out.print(f"surface point P = {fmt(_vector(args.surface, '--surface'))}")
    out.print(f"1. Find surface normal N at point P (unit): N = {fmt(g.normal)}")
    source = "light − P, normalized" if args.surface is not None else "normalized"
    out.print(f"2. Compute vector L from P to light source ({source}): L = {fmt(g.to_light)}")
    source = "eye − P, normalized" if args.surface is not None else "normalized"
    out.print(f"3. Compute viewing vector V from P to viewer ({source}): V = {fmt(g.to_eye)}")
    out.print(
        f"4. Compute reflection vector R = 2(N·L)N − L = 2 × {fmt(g.n_dot_l)} × {fmt(g.normal)}"
        f" − {fmt(g.to_light)} = {fmt(g.reflected)}"
    )
    out.print(f"5. Compute θ_i = cos⁻¹(N·L) = cos⁻¹({fmt(g.n_dot_l)}) = {g.theta:.2f}°")
    out.print(f"6. Compute α = cos⁻¹(R·V) = cos⁻¹({fmt(g.r_dot_v)}) = {g.alpha:.2f}°")
    if args.model == "blinn":
        out.print(f"   Blinn-Phong: H = (L + V)/|L + V| = {fmt(g.halfway)}, N·H = {fmt(g.n_dot_h)}")


def _explain_cosines(out: Any, n_dot_l: float, r_dot_v: float) -> None:
    """Print the given cosines with their angles (steps 5 and 6 of the notes, read backwards)."""
    import math

    for label, symbol, cosine in (("N·L", "θ_i", n_dot_l), ("R·V", "α", r_dot_v)):
        if -1 <= cosine <= 1:
            angle = math.degrees(math.acos(cosine))
            out.print(f"Given {label} = cos {symbol} = {fmt(cosine)}, so {symbol} = {angle:.2f}°")


def _geometry_table(g: Any, model: str) -> Any:
    from rich.table import Table

    table = Table(title="Geometry (unit vectors)")
    table.add_column("quantity")
    table.add_column("formula", no_wrap=True)
    table.add_column("value", justify="right", no_wrap=True)
    table.add_row("N", "surface normal", fmt(g.normal))
    table.add_row("L", "towards the light", fmt(g.to_light))
    table.add_row("V", "towards the eye", fmt(g.to_eye))
    table.add_row("N·L", "cos θ", fmt(g.n_dot_l))
    table.add_row("R", "2(N·L)N − L", fmt(g.reflected))
    table.add_row("R·V", "cos α", fmt(g.r_dot_v))
    if model == "blinn":
        table.add_row("H", "(L + V)/|L + V|", fmt(g.halfway))
        table.add_row("N·H", "Blinn-Phong cosine", fmt(g.n_dot_h))
    return table


def _specular_note(n_dot_l: float, cosine: float, name: str) -> str:
    if n_dot_l <= 0:
        return " (N·L ≤ 0: the light is behind the surface)"
    if cosine <= 0:
        return f" ({name} ≤ 0: the viewer is on the other side)"
    return ""


def _terms_table(args: argparse.Namespace, coefficients: dict, terms: Any, n_dot_l: float,
                 cosine: float, name: str) -> Any:
    from rich.table import Table

    ka, kd, ks, n, ia, il = (coefficients[k] for k in ("ka", "kd", "ks", "shininess", "ia", "il"))
    power = fmt(max(cosine, 0.0) ** n) if n_dot_l > 0 and cosine > 0 else "0"
    table = Table(title="Phong illumination" + (" (Blinn-Phong)" if name == "N·H" else ""))
    table.add_column("term")
    table.add_column("formula", no_wrap=True)
    table.add_column("substitution")
    table.add_column("value", justify="right", no_wrap=True)
    table.add_row("I_a", "k_a I_a", f"{fmt(ka)} × {fmt(ia)}", fmt(terms.ambient))
    table.add_row("I_d", "k_d I_L max(0, N·L)", f"{fmt(kd)} × {fmt(il)} × {fmt(max(n_dot_l, 0))}",
                  fmt(terms.diffuse))
    table.add_row(
        "I_s",
        f"k_s I_L max(0, {name})^n",
        f"{fmt(ks)} × {fmt(il)} × {fmt(cosine)}^{fmt(n)} = {fmt(ks)} × {fmt(il)} × {power}"
        + _specular_note(n_dot_l, cosine, name),
        fmt(terms.specular),
    )
    table.add_row(
        "I",
        "I_a + I_d + I_s",
        f"{fmt(terms.ambient)} + {fmt(terms.diffuse)} + {fmt(terms.specular)}",
        fmt(terms.total),
    )
    table.add_row("I (display)", "clamped to [0, 1]", "", fmt(terms.clamped))
    return table


def run(args: argparse.Namespace) -> int:
    """Compute and print the breakdown."""
    from pixelpath.lighting import phong_terms

    coefficients = {
        "ka": _channels(args.ka, "--ka"),
        "kd": _channels(args.kd, "--kd"),
        "ks": _channels(args.ks, "--ks"),
        "shininess": _number(args.shininess, "--shininess"),
        "ia": _channels(args.ia, "--ia"),
        "il": _channels(args.il, "--il"),
    }
    geometry = _geometry(args)
    out = console()
    if geometry is None:
        n_dot_l, cosine, name = args.ndotl, args.rdotv, "R·V"
        if args.explain:
            _explain_cosines(out, n_dot_l, cosine)
    else:
        blinn = args.model == "blinn"
        n_dot_l = geometry.n_dot_l
        cosine, name = (geometry.n_dot_h, "N·H") if blinn else (geometry.r_dot_v, "R·V")
        if args.explain:
            _explain_geometry(out, args, geometry)
        out.print(_geometry_table(geometry, args.model))
    terms = phong_terms(
        ka=coefficients["ka"],
        kd=coefficients["kd"],
        ks=coefficients["ks"],
        shininess=coefficients["shininess"],
        ambient=coefficients["ia"],
        light=coefficients["il"],
        n_dot_l=n_dot_l,
        r_dot_v=cosine,
    )
    if args.explain:
        out.print("7. Compute I_a, I_d, I_s:")
    out.print(_terms_table(args, coefficients, terms, n_dot_l, cosine, name))
    if args.explain:
        out.print(f"8. Compute total intensity I = {fmt(terms.total)}"
                  f" (displayed, clamped to [0, 1]: {fmt(terms.clamped)})")
    return 0
