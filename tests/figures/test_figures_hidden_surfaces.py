"""The hidden-surface figures: frame counts, and frames that show what they claim.

The scenes are hand-made so that what each frame must show is known without running the
methods: a camera at (0, 0, 5) looking at the origin with a 90° field of view maps a point
(x, y, z) to pixel ((x / (5 - z) + 1) · W / 2, (1 - y / (5 - z)) · H / 2) of a square image.
"""

from __future__ import annotations

import numpy as np
import pytest
from gif_frames import gif_frames
from PIL import Image

import pixelpath as pp
from pixelpath.figures import DRAWN_METHODS
from pixelpath.figures._canvas import COLOURS, GAP, HEADER, MARGIN, picture_scale
from pixelpath.figures.hidden_surfaces import (
    OBJECT_COLOURS,
    bsp_frames,
    octree_frames,
    order_frames,
    scanline_frames,
    warnock_frames,
    zbuffer_frames,
)
from pixelpath.figures.methods import METHOD_ANIMATIONS, METHOD_FIGURES, method_figure
from pixelpath.report import Report

SIZE = 16
LIGHT = pp.PointLight((0, 0, 10))


def _camera(size: int = SIZE) -> pp.Camera:
    return pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=size, height=size)


def _world(px: float, py: float, z: float, size: int = SIZE) -> tuple[float, float, float]:
    """The point at depth z that the camera above maps to pixel position (px, py)."""
    distance = 5.0 - z
    return ((2 * px / size - 1) * distance, (1 - 2 * py / size) * distance, z)


def _triangle(corners, z: float, size: int = SIZE) -> pp.Mesh:
    """A triangle at depth z with the given pixel corners, listed as in TOP_LEFT (that order
    faces the eye)."""
    return pp.Mesh([_world(px, py, z, size) for px, py in corners], [[0, 1, 2]])


def _panel_pixel(figure: Image.Image | np.ndarray, panel: int, x: float, y: float,
                 size: int = SIZE) -> tuple[int, ...]:
    """The colour a board shows at the centre of image pixel (x, y) of panel ``panel``."""
    scale = picture_scale(size, size)
    left = MARGIN + panel * (size * scale + GAP)
    array = np.asarray(figure)
    return tuple(int(v) for v in array[HEADER + int((y + 0.5) * scale),
                                       left + int((x + 0.5) * scale)])


# Two triangles in opposite quarters of a 16 x 16 image: top-left and bottom-right.
TOP_LEFT = [(1, 1), (1, 6), (6, 1)]
BOTTOM_RIGHT = [(9, 9), (9, 15), (15, 9)]


def _quarters_scene() -> pp.Scene:
    objects = [_triangle(TOP_LEFT, 0.0), _triangle(BOTTOM_RIGHT, 0.0)]
    return pp.Scene(_camera(), objects, [LIGHT])


def test_warnock_frames_one_per_level_coloured_by_decision(tmp_path):
    # By hand: the 16 x 16 image holds both triangles: cut in four. Of the 8 x 8 quarters,
    # the top-left and bottom-right hold one triangle each ("single polygon"), the other two
    # none ("empty"). Two levels.
    image, report = pp.render(_quarters_scene(), method="warnock", explain=True)
    frames = gif_frames(report.animate(tmp_path / "levels.gif"))
    assert len(frames) == 2
    first, last = frames
    # Level 1: nothing decided yet; the whole image is outlined where it is cut.
    assert _panel_pixel(first, 1, 12, 3) == COLOURS["faint"]
    assert _panel_pixel(first, 0, 3, 3) == COLOURS["faint"]
    scale = picture_scale(SIZE, SIZE)
    cut_x = MARGIN + (SIZE * scale + GAP) + 8 * scale
    assert tuple(first[HEADER + 5 * scale, cut_x]) == COLOURS["boundary"]
    # Level 2: every pixel of the empty quarters carries the "empty" colour; the others the
    # "single polygon" colour, whether the triangle covers the pixel or not.
    for x, y in [(12, 3), (9, 0), (15, 7), (3, 12), (0, 15)]:
        assert _panel_pixel(last, 1, x, y) == COLOURS["empty area"], (x, y)
    for x, y in [(2, 2), (7, 7), (10, 10), (15, 15)]:
        assert _panel_pixel(last, 1, x, y) == COLOURS["single area"], (x, y)
    # The left panel shows the image where it has been decided (exactly before the GIF's
    # palette rounds it).
    drawn = warnock_frames(image, report)[-1]
    assert _panel_pixel(drawn, 0, 2, 2) == tuple(image.to_uint8()[2, 2])


def test_warnock_and_scanline_figures_are_their_last_frames():
    for method, frames_of in (("warnock", warnock_frames), ("scanline", scanline_frames)):
        image, report = pp.render(_quarters_scene(), method=method, explain=True)
        assert np.array_equal(np.asarray(report.figure()),
                              np.asarray(frames_of(image, report)[-1]))


def test_method_figure_is_none_for_a_line_styles_report():
    # The playground asks for the figure of any method and style: a line style's report
    # (its edges) has none of the method's data, so only the z-buffer's depth figure remains.
    scene = _quarters_scene()
    for method in ("warnock", "painter", "zbuffer"):
        image, report = pp.render(scene, method=method, style="hidden-line", explain=True)
        figure = method_figure(method, image, report)
        assert (figure is None) == (method != "zbuffer")


# Three triangles side by side on a 32 x 32 image, at depths far, middle and near: the
# painter's algorithm sorts them by farthest depth and paints them far to near.
WIDE = 32
DEPTHS = (-3.0, -1.5, 0.0)
CENTRES = ((6, 16), (16, 16), (26, 16))


def _row_scene() -> pp.Scene:
    objects = []
    for (cx, cy), z in zip(CENTRES, DEPTHS, strict=True):
        corners = [(cx - 4, cy - 4), (cx - 4, cy + 4), (cx + 4, cy - 4)]
        objects.append(_triangle(corners, z, WIDE))
    return pp.Scene(_camera(WIDE), objects, [LIGHT])


def _inside(k: int) -> tuple[float, float]:
    """A pixel well inside triangle k (near its right-angle corner)."""
    cx, cy = CENTRES[k]
    return cx - 2, cy - 2


@pytest.mark.parametrize("method, frames_of", [("painter", order_frames), ("bsp", bsp_frames)])
def test_the_nth_order_frame_shows_exactly_the_first_n_polygons(method, frames_of):
    image, report = pp.render(_row_scene(), method=method, explain=True)
    frames = frames_of(image, report)
    assert len(frames) == 3
    panel = 1 if method == "bsp" else 0  # the BSP board has the tree diagram first
    for n, frame in enumerate(frames, start=1):
        for k in range(3):
            x, y = _inside(k)
            expected = COLOURS[OBJECT_COLOURS[k]] if k < n else COLOURS["background"]
            assert _panel_pixel(frame, panel, x, y, WIDE) == expected, (n, k)


def test_painter_marks_the_pieces_of_a_split():
    # Two triangles that cut through each other (one leans back, the other forward): neither
    # may be painted first whole, so one is split by the other's plane.
    lean = [(-2, -1, -1), (2, -1, 1), (0, 2, 0)]
    other = [(-2, -1, 1), (2, -1, -1), (0, 2.2, 0)]
    scene = pp.Scene(_camera(WIDE), [pp.Mesh(lean, [[0, 1, 2]]), pp.Mesh(other, [[0, 1, 2]])],
                     [LIGHT])
    _, report = pp.render(scene, method="painter", explain=True, backface_cull=False)
    assert report.summary["splits"] >= 1
    split = report.arrays["split"][report.arrays["order"]]
    assert split.any()
    last = np.asarray(report.figure())
    assert np.all(last == COLOURS["contact"], axis=-1).any()


def test_zbuffer_frames_fill_band_by_band():
    # 40 rows are two bands of 32: the first frame shows rows 0-31, the second all.
    scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=40, height=40),
                     [pp.Sphere((0, 0, 0), 1.5)], [LIGHT])
    image, report = pp.render(scene, explain=True)
    frames = zbuffer_frames(image, report)
    assert len(frames) == 2
    rgb = image.to_uint8()
    x = 20
    assert _panel_pixel(frames[0], 0, x, 20, 40) == tuple(rgb[20, x])
    assert _panel_pixel(frames[0], 0, x, 36, 40) == COLOURS["background"]
    assert _panel_pixel(frames[1], 0, x, 36, 40) == tuple(rgb[36, x])


def test_scanline_frames_one_per_line_with_bars_on_covered_lines():
    # 16 lines: one frame each. The top-left triangle covers rows 1-5 (two active edges
    # there); rows 7 and 8 cross no triangle: no bar.
    image, report = pp.render(_quarters_scene(), method="scanline", explain=True)
    frames = scanline_frames(image, report)
    assert len(frames) == SIZE
    last = frames[-1]
    assert _panel_pixel(last, 1, 0, 3) != COLOURS["background"]
    assert _panel_pixel(last, 1, 0, 7) == COLOURS["background"]
    assert _panel_pixel(last, 1, 0, 8) == COLOURS["background"]
    # Frame k has drawn the bars of lines 0..k only.
    assert _panel_pixel(frames[2], 1, 0, 3) == COLOURS["background"]
    assert _panel_pixel(frames[3], 1, 0, 3) != COLOURS["background"]


def test_octree_single_leaf_is_drawn():
    # Two triangles are far fewer than a leaf holds: the root is the only cell, a leaf drawn.
    image, report = pp.render(_quarters_scene(), method="octree", explain=True)
    assert report.arrays["cell outcome"].tolist() == [4]
    frames = octree_frames(image, report)
    assert len(frames) == 1
    assert np.all(np.asarray(frames[0]) == COLOURS["output"], axis=-1).any()


def test_recording_the_octree_cells_changes_nothing_drawn():
    scene = pp.Scene(pp.Camera(eye=(3, 4, 5), target=(0, 0, 0), width=48, height=40),
                     [pp.Sphere((0, 0, 0), 1.0), pp.Box((-2, -2, -2), (-1, -1, -1))], [LIGHT])
    plain = pp.render(scene, method="octree")
    explained, report = pp.render(scene, method="octree", explain=True)
    assert np.array_equal(np.asarray(plain), np.asarray(explained))
    outcome = report.arrays["cell outcome"]
    assert outcome.shape == report.arrays["cell level"].shape
    assert (outcome[report.arrays["cell is leaf"]] == 4).any()


def test_every_drawn_method_has_a_figure_and_an_animation():
    assert set(METHOD_FIGURES) == set(DRAWN_METHODS) == set(METHOD_ANIMATIONS)
    scene = _quarters_scene()
    for method in DRAWN_METHODS:
        _, report = pp.render(scene, method=method, explain=True)
        assert report.figure().mode == "RGB"
        assert len(report.frames()) >= 1
        assert report._repr_png_().startswith(b"\x89PNG")


def test_figures_refuse_clearly_what_they_cannot_draw():
    with pytest.raises(ValueError, match="no image"):
        Report("warnock", {}).figure()
    _, supersampled = pp.render(_quarters_scene(), method="warnock", explain=True, ssaa=2)
    with pytest.raises(ValueError, match="ssaa"):
        supersampled.figure()
    _, traced = pp.render(_quarters_scene(), method="raytrace", explain=True)
    with pytest.raises(ValueError, match="'raytrace' has no animation"):
        traced.frames()
    assert traced._repr_png_() is None
