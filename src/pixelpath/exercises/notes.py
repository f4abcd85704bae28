"""The notes' own worked examples, as exercises with the errata applied (SPEC section 9).

Each entry gives the values the notes give. Where the notes print a wrong number, the
exercise's answer is the right one and :attr:`~pixelpath.exercises.Exercise.errata` keeps
the printed value, so a student who copied it is told which step of the notes is wrong.
"""

from __future__ import annotations

from pixelpath.exercises.exercise import Exercise
from pixelpath.exercises.topics import TOPIC_REGISTRY, exercise_for

# (topic, the notes' given values, the values the notes print wrongly)
NOTES_EXAMPLES: tuple[tuple[str, dict, dict], ...] = (
    # Sutherland-Hodgman, example 7. The notes list the result the other way round, which
    # the marking accepts: a polygon may start anywhere and run either way.
    ("sutherland-hodgman", {"window": [2, 2, 8, 6], "polygon": [[1, 1], [9, 1], [9, 7], [1, 7]]},
     {}),
    # Basic illumination example 7 and Phong shading example 9: (0.866)^20 is 0.0563.
    ("phong-intensity", {"ka": 0.2, "kd": 0.6, "ks": 0.5, "n": 20, "Ia": 0.2, "IL": 1.0,
                         "n_dot_l": 0.707, "r_dot_v": 0.866},
     {"specular": "0.00585", "I": "0.47005"}),
    # Diffuse reflection example 8: 42 cd.
    ("diffuse", {"kd": 0.7, "IL": 120.0, "theta": 60}, {}),
    # Specular reflection example 8: 0.8 × 100 × 0.0563 = 4.50 cd.
    ("specular", {"ks": 0.8, "IL": 100.0, "n": 20, "alpha": 30},
     {"cos_alpha_n": "0.015", "Is": "1.2"}),
    # Gouraud shading example 7 (I1 = 0.9 top, I2 = 0.2 left, I3 = 0.6 right; the edge V1-V2
    # at t = 0.5 gives 0.55). The notes give no coordinates; these put the scan line y = 4
    # half-way down both edges and the pixel x = 4 half-way along the span.
    ("gouraud", {"vertices": [[4, 8], [0, 0], [8, 0]], "intensities": [0.9, 0.2, 0.6],
                 "scan_line": 4, "x": 4}, {}),
    # YIQ example table, the row for yellow.
    ("rgb-yiq", {"rgb": [1.0, 1.0, 0.0]}, {}),
    # CMY example table: blue is C + M.
    ("rgb-cmy", {"rgb": [0.0, 0.0, 1.0]}, {}),
    # HSV example table: H = 300°, S = V = 1 is bright magenta.
    ("hsv-rgb", {"hsv": [300, 1.0, 1.0]}, {}),
)


def notes_exercises() -> list[Exercise]:
    """Return the notes' worked examples as exercises (``seed`` None, difficulty ``"notes"``).

    Examples
    --------
    >>> from pixelpath.exercises.notes import notes_exercises
    >>> specular = next(e for e in notes_exercises() if e.topic == "specular")
    >>> round(specular.answer["Is"], 1), specular.errata["Is"]
    (4.5, '1.2')
    """
    return [exercise_for(TOPIC_REGISTRY[topic], params, None, "notes", errata)
            for topic, params, errata in NOTES_EXAMPLES]
