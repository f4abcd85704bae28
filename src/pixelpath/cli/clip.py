"""``pixelpath clip``: clip a polygon against a window and show the work."""

from __future__ import annotations

import argparse

from pixelpath.cli._common import CommandError, add_command, console, error_console

METHODS = ("sutherland-hodgman", "weiler-atherton")


def register(subparsers) -> None:
    """Add the ``clip`` subcommand."""
    parser = add_command(
        subparsers,
        "clip",
        summary="clip a polygon against a window (Sutherland-Hodgman or Weiler-Atherton)",
        description=(
            "Clip a polygon against a rectangle or a polygon window. Sutherland-Hodgman "
            "(the default) follows the notes: boundaries Left, Right, Bottom, Top, S starting "
            "as the last vertex; --trace prints the table of every stage. Weiler-Atherton "
            "takes concave windows and returns the separate pieces. Write --window=... when "
            "the window starts with a minus sign."
        ),
        examples=[
            'pixelpath clip "1,1 9,1 9,7 1,7" --window 2,2,8,6 --trace',
            'pixelpath clip "1,1 9,1 9,7 1,7" --window 2,2,8,6 --plot stages.png',
            'pixelpath clip "0,0 6,0 6,6 0,6 0,4 4,4 4,2 0,2" --window=-1,-1,3,7 '
            "--method weiler-atherton",
            'pixelpath clip "1,1 9,1 9,7 1,7" --window 2,2,8,6 --animate steps.gif',
        ],
        run=run,
    )
    parser.add_argument("subject", help='the polygon\'s vertices "x,y x,y x,y ..." in order')
    parser.add_argument(
        "--window",
        required=True,
        help='a rectangle "xmin,ymin,xmax,ymax" or a polygon "x,y x,y x,y ..."',
    )
    parser.add_argument("--method", choices=METHODS, default=METHODS[0])
    parser.add_argument(
        "--trace", action="store_true", help="print each stage's table (Sutherland-Hodgman)"
    )
    parser.add_argument(
        "--plot",
        metavar="PNG",
        help="draw each stage (Sutherland-Hodgman) or both methods' results (Weiler-Atherton)",
    )
    parser.add_argument(
        "--animate",
        metavar="GIF",
        help="write an animated GIF: one frame per (S, E) step (Sutherland-Hodgman) or per "
        "piece of boundary walked (Weiler-Atherton)",
    )


def run(args: argparse.Namespace) -> int:
    """Clip, print the result (and trace), draw the picture if asked."""
    from pixelpath.clip import sutherland_hodgman, weiler_atherton, zero_width_bridges

    subject = parse_points(args.subject, "subject")
    window = parse_window(args.window)
    out = console()
    if args.method == "weiler-atherton":
        if args.trace:
            raise CommandError("--trace shows Sutherland-Hodgman's stages; drop --method")
        pieces, walk = weiler_atherton(subject, window, trace=True)
        for k, piece in enumerate(pieces, start=1):
            out.print(f"piece {k}: {_format(piece)}")
        if not pieces:
            out.print("nothing is left: the polygons do not overlap")
        _plot(args.plot, "plot_bridges", subject, window)
        _animate(args.animate, walk)
        return 0
    result, trace = sutherland_hodgman(subject, window, trace=True)
    if args.trace:
        out.print(str(trace))
    else:
        out.print(f"clipped polygon: {_format(result)}" if len(result) else "nothing is left")
    if len(result) and len(zero_width_bridges(result, window)):
        error_console().print(
            "note: the result runs along the window boundary and back (zero-width bridges "
            "joining pieces of a concave subject); --method weiler-atherton gives the pieces"
        )
    _plot(args.plot, "plot_trace", trace)
    _animate(args.animate, trace)
    return 0


def parse_points(text: str, name: str) -> list[tuple[float, float]]:
    """Parse ``"x,y x,y ..."`` into a list of points."""
    points = []
    for token in text.replace(";", " ").split():
        parts = token.split(",")
        if len(parts) != 2:
            raise CommandError(f"{name}: expected x,y pairs separated by spaces, got {token!r}")
        try:
            points.append((float(parts[0]), float(parts[1])))
        except ValueError:
            raise CommandError(f"{name}: {token!r} is not a pair of numbers") from None
    return points


def parse_window(text: str):
    """Parse ``"xmin,ymin,xmax,ymax"`` into a Rect, anything else into a polygon."""
    from pixelpath.clip import Rect

    tokens = text.split()
    if len(tokens) == 1 and tokens[0].count(",") == 3:
        try:
            bounds = [float(v) for v in tokens[0].split(",")]
        except ValueError:
            raise CommandError(f"window: {text!r} is not four numbers") from None
        return Rect(*bounds)
    return parse_points(text, "window")


def _plot(path: str | None, function: str, *args) -> None:
    if not path:
        return
    from pixelpath.clip import plot

    try:
        written = getattr(plot, function)(*args, path)
    except ImportError as exc:  # matplotlib missing
        raise CommandError(str(exc)) from None
    error_console().print(f"wrote {written}")


def _animate(path: str | None, trace) -> None:
    if not path:
        return
    try:
        written = trace.animate(path)
    except (ValueError, FileNotFoundError) as exc:  # not a .gif, or no such folder
        raise CommandError(str(exc)) from None
    error_console().print(f"wrote {written}")


def _format(points) -> str:
    return " -> ".join(f"({x:g}, {y:g})" for x, y in points)
