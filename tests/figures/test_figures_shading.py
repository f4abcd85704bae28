"""Shading figures: three shadings side by side; the highlight strip and its numbers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pixelpath.figures.shading import highlight_numbers, highlight_strip, shading_comparison
from pixelpath.report import Report


@pytest.mark.parametrize("n", [1, 5, 20, 100])
def test_highlight_numbers_are_the_cosine_powers(n):
    numbers = highlight_numbers(n)
    assert numbers["30°"] == pytest.approx(math.cos(math.radians(30)) ** n)
    assert numbers["60°"] == pytest.approx(0.5**n)


def test_highlight_strip_has_one_panel_per_exponent():
    one = highlight_strip((20,), size=48)
    two = np.asarray(highlight_strip((1, 100), size=48)).astype(int)
    assert two.shape[1] > 2 * 48 and two.shape[1] > one.width
    half = two.shape[1] // 2
    assert np.abs(two[:48, :48] - two[:48, half:half + 48]).sum() > 0  # n changes the sphere


def test_shading_comparison_differs_between_flat_and_phong():
    image = np.asarray(shading_comparison()).astype(int)
    third = image.shape[1] // 3
    assert image.shape[1] >= 3 * 200
    assert np.abs(image[:, :third] - image[:, third:2 * third]).sum() > 0


def test_report_renders_as_html_with_escaped_values():
    report = Report("zbuffer", summary={"<b>": "1 < 2"})
    html = report._repr_html_()
    assert "&lt;b&gt;" in html and "1 &lt; 2" in html
