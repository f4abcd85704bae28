"""Shading figures: flat, Gouraud and Phong side by side, and the highlight against n.

Both are rendered by :func:`pixelpath.render` (the z-buffer pipeline) and laid out with Pillow.
The highlight strip prints beside each sphere the numbers of the notes' specular table,
computed with :func:`pixelpath.lighting.phong_terms`: ``(R·V)^n`` at 30° and 60°, and the
half-width of the highlight, the angle at which it falls to half its peak,
``arccos(0.5^(1/n))``.

Examples
--------
>>> from pixelpath.figures.shading import highlight_numbers
>>> round(highlight_numbers(20)["30°"], 4)  # the notes print 0.0117 (SPEC §9)
0.0563
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from PIL import Image

from pixelpath.figures._canvas import LINE_HEIGHT, Sketch, paste_row

__all__ = ["coarse_ball", "highlight_numbers", "highlight_strip", "shading_comparison"]

SHADINGS = ("flat", "gouraud", "phong")
NOTES_EXPONENTS = (1, 5, 20, 100)
TABLE_ANGLES = (30.0, 60.0)


def coarse_ball(width: int = 220, height: int = 220, subdivisions: int = 2):
    """Return a scene of one shiny icosphere of 320 faces (by default) under one light.

    Few faces make the three shadings differ visibly: flat shows the facets, Gouraud
    smears the highlight over the triangles around it, Phong keeps it round.

    Examples
    --------
    >>> from pixelpath.figures.shading import coarse_ball
    >>> scene = coarse_ball()
    >>> scene.objects[0].face_count
    320
    """
    from pixelpath.scene import Camera, Material, PointLight, Scene, icosphere

    material = Material(color=(0.85, 0.35, 0.2), ka=0.3, kd=0.7, ks=0.6, shininess=40)
    return Scene(
        camera=Camera(eye=(0, 0, 4.2), target=(0, 0, 0), fov=34, width=width, height=height),
        objects=[icosphere(subdivisions, material=material)],
        lights=[PointLight(position=(2.5, 3.0, 5.0))],
        ambient=0.25,
        background=(1.0, 1.0, 1.0),
    )


def shading_comparison(scene=None, shadings: Sequence[str] = SHADINGS,
                       method: str = "zbuffer") -> Image.Image:
    """Render one scene in several shadings and place the pictures side by side.

    Parameters
    ----------
    scene : Scene, optional
        What to draw; by default :func:`coarse_ball`.
    shadings : sequence of {"flat", "gouraud", "phong"}
        The panels, in order.
    method : str
        The hidden-surface method (see :func:`pixelpath.render`).

    Returns
    -------
    PIL.Image.Image
        The panels with their names above them.

    Examples
    --------
    >>> from pixelpath.figures.shading import coarse_ball, shading_comparison
    >>> shading_comparison(coarse_ball(64, 48)).height  # 48 rows under the captions
    86
    """
    from pixelpath.renderer import render

    scene = coarse_ball() if scene is None else scene
    pictures = [
        Image.fromarray(render(scene, method=method, shading=shading).to_uint8())
        for shading in shadings
    ]
    return paste_row(pictures, [f"{shading} shading" for shading in shadings])


def highlight_numbers(shininess: float, angles: Sequence[float] = TABLE_ANGLES) -> dict[str, float]:
    """Return ``(R·V)^n`` at each angle α (degrees) and the highlight's half-width.

    The values are the specular term ``ks IL (R·V)^n`` with ``ks IL = 1``, from
    :func:`pixelpath.lighting.phong_terms`.

    Parameters
    ----------
    shininess : float
        The exponent n, > 0.
    angles : sequence of float
        Angles α between R and V, in degrees.

    Returns
    -------
    dict
        ``"30°": value, ...`` and ``"half-width": angle in degrees``.

    Examples
    --------
    >>> from pixelpath.figures.shading import highlight_numbers
    >>> numbers = highlight_numbers(1, angles=(60,))
    >>> round(numbers["60°"], 6), round(numbers["half-width"], 6)
    (0.5, 60.0)
    """
    from pixelpath.lighting import phong_terms

    if not shininess > 0:
        raise ValueError(f"shininess must be > 0 for a highlight to have a width, got {shininess}")
    cosines = np.cos(np.radians(np.asarray(angles, dtype=np.float64)))
    terms = phong_terms(ka=0, kd=0, ks=1, shininess=shininess, ambient=0, light=1,
                        n_dot_l=1, r_dot_v=cosines)
    numbers = {f"{angle:g}°": float(value) for angle, value in
               zip(angles, np.atleast_1d(terms.specular), strict=True)}
    numbers["half-width"] = math.degrees(math.acos(0.5 ** (1.0 / shininess)))
    return numbers


def highlight_strip(exponents: Sequence[float] = NOTES_EXPONENTS, size: int = 160) -> Image.Image:
    """Render a sphere for each shininess n, with the notes' specular numbers under it.

    Parameters
    ----------
    exponents : sequence of float
        The exponents n, each > 0 (default: 1, 5, 20, 100).
    size : int
        Each sphere's picture is ``size × size`` pixels.

    Returns
    -------
    PIL.Image.Image

    Examples
    --------
    >>> from pixelpath.figures.shading import highlight_strip
    >>> highlight_strip((5, 50), size=48).height  # 48 rows and 3 lines of numbers
    143
    """
    from pixelpath.renderer import render
    from pixelpath.scene import Camera, Material, PointLight, Scene, Sphere

    camera = Camera(eye=(0, 0, 4.2), target=(0, 0, 0), fov=34, width=size, height=size)
    pictures, captions = [], []
    for n in exponents:
        material = Material(color=(0.3, 0.45, 0.8), ka=0.3, kd=0.6, ks=0.7, shininess=n)
        scene = Scene(camera, objects=[Sphere((0, 0, 0), 1.0, material=material)],
                      lights=[PointLight(position=(2.0, 2.5, 5.0))], ambient=0.25,
                      background=(1.0, 1.0, 1.0))
        ball = Image.fromarray(render(scene, shading="phong").to_uint8())
        pictures.append(_with_numbers(ball, highlight_numbers(n)))
        captions.append(f"n = {n:g}")
    return paste_row(pictures, captions)


def _with_numbers(ball: Image.Image, numbers: dict[str, float]) -> Image.Image:
    lines = [f"(R·V)^n at {key}: {_number(value)}" for key, value in numbers.items()
             if key != "half-width"]
    lines.append(f"half-width: {numbers['half-width']:.1f}°")
    sketch = Sketch(max(ball.width, 150), ball.height + 6 + LINE_HEIGHT * len(lines))
    sketch.image.paste(ball, (0, 0))
    for k, line in enumerate(lines):
        sketch.text(0, ball.height + 6 + k * LINE_HEIGHT, line)
    return sketch.image


def _number(value: float) -> str:
    return f"{value:.4f}" if value >= 1e-3 else f"{value:.2g}"
