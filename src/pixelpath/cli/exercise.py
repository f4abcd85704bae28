"""``pixelpath exercise``: the notes' exam questions, seeded, with worked solutions and marking.

Print an exercise (and its solution), mark an answer typed on the command line, write its
figure, or export many seeds as a worksheet, a Moodle quiz or PrairieLearn questions.
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path
from typing import Any

from pixelpath.cli._common import CommandError, add_command, console

EXAMPLES = [
    "pixelpath exercise --list",
    "pixelpath exercise rgb-hsv --seed 3",
    "pixelpath exercise rgb-hsv --seed 3 --solution",
    "pixelpath exercise rgb-hsv --seed 3 --check 'h=43; s=0.35; v=1'",
    "pixelpath exercise sutherland-hodgman --seed 1 --figure clip.png",
    "pixelpath exercise rgb-hsv --export sheet --count 10",
    "pixelpath exercise phong-intensity --export quiz --format moodle --count 20",
]

# A ';' starts the next answer only before 'name=': polygons use ';' between their pieces.
_ANSWER_SEPARATOR = re.compile(r";\s*(?=[A-Za-z_]\w*\s*=)")


def register(subparsers: Any) -> None:
    """Add the ``exercise`` subcommand."""
    parser = add_command(
        subparsers,
        "exercise",
        summary="exam questions of the notes: seeded, with worked solutions, marking and exports",
        description=(
            "Print an exercise of TOPIC drawn from --seed (the same seed gives the same numbers "
            "everywhere), with --solution its worked solution; --check marks your answer "
            "(exit status 0 when right, 1 when wrong); --export writes seeds SEED to "
            "SEED+COUNT-1 as a worksheet and answer key (markdown, html), a Moodle XML quiz or "
            "PrairieLearn questions. --list shows the topics."
        ),
        examples=EXAMPLES,
        run=run,
    )
    parser.add_argument("topic", nargs="?", metavar="TOPIC", help="the exercise's topic")
    parser.add_argument("--list", action="store_true", help="list the topics and exit")
    parser.add_argument("--seed", type=int, default=0, help="the exercise's seed (default 0)")
    parser.add_argument("--difficulty", default="standard",
                        help="easy, standard (default) or edge (degenerate cases too)")
    parser.add_argument("--solution", action="store_true",
                        help="print the worked solution (and write the solved figure)")
    parser.add_argument("--check", metavar="ANSWER",
                        help="mark an answer: 'name=value; name=value' (see the question's "
                             "fields); exit status 1 when wrong")
    parser.add_argument("--figure", metavar="PATH", help="write the figure as PNG")
    export = parser.add_argument_group("export")
    export.add_argument("--export", metavar="DIR", help="write the exercises into DIR")
    export.add_argument("--format", default="markdown",
                        help="markdown (default), html, moodle or prairielearn")
    export.add_argument("--count", type=int, default=1,
                        help="with --export: how many seeds, from --seed on (default 1)")


def show_markdown(text: str) -> None:
    """Print Markdown formatted on a terminal, as plain text when piped.

    Examples
    --------
    >>> show_markdown("**I** = 0.4923")
    **I** = 0.4923
    """
    out = console()
    if out.is_terminal:
        from rich.markdown import Markdown

        out.print(Markdown(text))
    else:
        print(text)


def parse_answers(text: str) -> dict[str, str]:
    """Read ``'I=0.49; n_dot_l=0.7'`` into ``{"I": "0.49", "n_dot_l": "0.7"}``.

    Examples
    --------
    >>> parse_answers("P=(0, 0) (1, 0) (0, 1); (2, 2) (3, 2) (2, 3); t = none")
    {'P': '(0, 0) (1, 0) (0, 1); (2, 2) (3, 2) (2, 3)', 't': 'none'}
    """
    answers = {}
    for part in _ANSWER_SEPARATOR.split(text.strip().rstrip(";")):
        name, equals, value = part.partition("=")
        if not equals or not name.strip():
            raise CommandError(f"--check wants 'name=value; name=value', got {part!r}")
        answers[name.strip()] = value.strip()
    return answers


def _list_topics() -> int:
    from pixelpath import exercises

    width = max(map(len, exercises.TOPICS))
    for topic in exercises.TOPICS:
        print(f"{topic:<{width}}  {exercises.topic_title(topic)}")
    return 0


def _export(args: argparse.Namespace) -> int:
    from pixelpath import exercises

    items = [exercises.make(args.topic, seed, args.difficulty)
             for seed in range(args.seed, args.seed + args.count)]
    written = exercises.export(items, args.export, format=args.format)
    files = f"{len(written)} file" + ("s" if len(written) != 1 else "")
    print(f"wrote {files} ({args.format}, seeds {args.seed} to {args.seed + args.count - 1}) "
          f"to {args.export}")
    return 0


def _write_figure(exercise: Any, path: str, solution: bool) -> None:
    from pixelpath.io.images import write_bytes

    png = exercise.figure_png(solution=solution)
    if png is None:
        raise CommandError(f"{exercise.topic!r} exercises have no figure")
    if Path(path).suffix.lower() != ".png":
        raise CommandError(f"--figure writes PNG; give a .png path, got {path!r}")
    if not Path(path).parent.is_dir():
        raise FileNotFoundError(f"output directory does not exist: {Path(path).parent}")
    write_bytes(path, png)
    print(f"wrote {path}")


def _print_marking(result: Any) -> None:
    if result.correct:
        print("correct")
    else:
        print(f"wrong: the first wrong value is {result.first_wrong}")
    for name, right in result.marks.items():
        print(f"  {name}: {'right' if right else 'wrong'}")
    print(result.feedback)


def run(args: argparse.Namespace) -> int:
    """Print, mark or export exercises."""
    if args.list:
        return _list_topics()
    if args.topic is None:
        raise CommandError("give a TOPIC (pixelpath exercise --list shows them)")
    if args.count < 1:
        raise CommandError(f"--count must be at least 1, got {args.count}")
    if args.export is not None:
        return _export(args)
    if args.count != 1:
        raise CommandError("--count needs --export (it exports that many seeds)")
    from pixelpath import exercises

    exercise = exercises.make(args.topic, args.seed, args.difficulty)
    if args.figure is not None:
        _write_figure(exercise, args.figure, args.solution)
    if args.check is not None:
        result = exercise.check(parse_answers(args.check))
        _print_marking(result)
        if args.solution:
            show_markdown(exercise.solution)
        return 0 if result.correct else 1
    text = f"# {exercise.title} ({exercise.name})\n\n{exercise.question}"
    if args.solution:
        text += f"\n\n## Worked solution\n\n{exercise.solution}\n\n*Marking:* {exercise.marking}"
    show_markdown(text)
    return 0
