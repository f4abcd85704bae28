"""The explain report's texture lookups: mip levels per pixel, filters, texels read."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import pixelpath as pp

RASTER_METHODS = ("zbuffer", "scanline", "painter", "bsp", "warnock", "octree")


def _checker(size: int = 256, squares: int = 8) -> np.ndarray:
    cells = np.indices((size, size)).sum(axis=0) // (size // squares) % 2
    return np.repeat(cells[..., None], 3, axis=2).astype(np.float64)


def _floor_scene(texture_filter: str = "trilinear") -> pp.Scene:
    """A long textured floor seen from just above it: near rows at the bottom, far ones up."""
    material = pp.Material(texture=_checker(), texture_filter=texture_filter)
    floor = pp.Mesh([[-4, 0, -20], [4, 0, -20], [4, 0, 2], [-4, 0, 2]], [[3, 2, 1, 0]],
                    material, uv=[[0, 1], [1, 1], [1, 0], [0, 0]])
    camera = pp.Camera(eye=(0, 1, 3), target=(0, 0.5, -5), width=96, height=72)
    return pp.Scene(camera, [floor], [pp.PointLight((0, 3, 3))])


def _table(report, title):
    return next(table for table in report.tables if table.title == title)


@pytest.mark.parametrize("method", RASTER_METHODS)
def test_a_receding_floor_reads_coarser_levels_further_away(method):
    image, report = pp.render(_floor_scene(), method, explain=True)
    levels = report.arrays["texture level"]
    textured = levels >= 0
    assert report.summary["textured pixels"] == int(textured.sum()) > 0
    assert np.array_equal(textured, image.object_id == 0)
    rows = _table(report, "mip levels").rows
    assert len({row[1] for row in rows}) >= 3
    assert sum(row[3] for row in rows) == report.summary["textured pixels"]
    # Each row of the picture further up (further away) reads levels no finer than below it.
    per_row = [levels[j][textured[j]].mean() for j in range(levels.shape[0]) if textured[j].any()]
    assert per_row[0] > per_row[-1]
    assert all(upper >= lower for upper, lower in itertools.pairwise(per_row))
    assert (levels[textured][-1], per_row[-1]) == (0, 0.0)  # the nearest row: the base level


def test_every_method_reports_the_same_lookups():
    reports = [pp.render(_floor_scene(), method, explain=True)[1] for method in RASTER_METHODS]
    for report in reports[1:]:
        assert np.array_equal(report.arrays["texture level"], reports[0].arrays["texture level"])
        assert report.tables[-2:] == reports[0].tables[-2:]


def test_texels_read_follow_the_filter():
    counts = {}
    for name in ("nearest", "bilinear", "trilinear"):
        _, report = pp.render(_floor_scene(name), explain=True)
        counts[name] = report.summary["texels read"], report.summary["textured pixels"]
        row = _table(report, "textures").rows[0]
        assert (row[1], row[2], row[3]) == ("256×256", name, "repeat")
        assert row[5] == report.summary["texels read"]
    pixels = counts["nearest"][1]
    assert counts["nearest"][0] == pixels
    assert counts["bilinear"][0] == 4 * pixels
    assert 4 * pixels < counts["trilinear"][0] < 8 * pixels
    _, report = pp.render(_floor_scene("bilinear"), explain=True)
    assert {row[1] for row in _table(report, "mip levels").rows} == {0}


def test_one_texel_per_pixel_reads_the_base_level_only():
    size = 64
    fov = 40.0
    distance = 3.0
    half = distance * math.tan(math.radians(fov / 2))  # the quad fills the view exactly
    quad = pp.Mesh([[-half, -half, 0], [half, -half, 0], [half, half, 0], [-half, half, 0]],
                   [[0, 1, 2, 3]], pp.Material(texture=_checker(size, 4)),
                   uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    camera = pp.Camera(eye=(0, 0, distance), target=(0, 0, 0), fov=fov, width=size, height=size)
    _, report = pp.render(pp.Scene(camera, [quad], [pp.PointLight((0, 0, 5))]), explain=True)
    assert report.summary["textured pixels"] == size * size
    rows = _table(report, "mip levels").rows
    assert [row[1:4] for row in rows] == [(0, f"{size}×{size}", size * size)]


def test_untextured_scenes_report_nothing_about_textures():
    scene = _floor_scene()
    plain = pp.Scene(scene.camera, [pp.Sphere((0, 0.5, -2), 0.5)], scene.lights)
    for method in ("zbuffer", "painter"):
        _, report = pp.render(plain, method, explain=True)
        assert "textured pixels" not in report.summary
        assert not any("texture" in key for key in report.arrays)
        assert not any(table.title in ("textures", "mip levels") for table in report.tables)
        assert not any("mip level" in note for note in report.notes)


def test_the_shading_pass_reads_the_levels_the_report_counts():
    """The floor's colour, nearest row against far row, blurs where the report says it should."""
    image, report = pp.render(_floor_scene(), explain=True)
    levels = report.arrays["texture level"]
    coarse = levels >= 4
    assert coarse.any()
    grey = np.asarray(image).mean(axis=2)
    # Coarse levels average the checker's squares: the pixels there lie far from black and
    # white, unlike those read on the base level.
    fine = levels == 0
    assert np.std(grey[coarse]) < np.std(grey[fine])
