"""Warnock's area subdivision: classification on hand cases, its report, exact agreement."""

from __future__ import annotations

import numpy as np
import pytest
from agreement import KINDS, scene_of
from hypothesis import given, settings
from hypothesis import strategies as st
from screen_triangles import set_up, view_of, zbuffer

import pixelpath as pp
from pixelpath.hsr import warnock
from pixelpath.hsr._kernels import warnock as kernels
from pixelpath.hsr.warnock import DECISIONS, LEVEL_COLUMNS

# Row j of a 16 x 16 image: A covers columns [0, 15 - j) (rows 0..14), B covers [0, 7 - j)
# (rows 0..6), i.e. pixel (i, j) with i + j < 7; BACKDROP covers every pixel.
A = [(0, 0, 0.5), (16, 0, 0.5), (0, 16, 0.5)]
B = [(0, 0, 1.0), (8, 0, 1.0), (0, 8, 1.0)]
BACKDROP = [(-20, -20, 0.5), (60, -20, 0.5), (-20, 60, 0.5)]


def classify(triangle, area):
    """Class of a screen triangle against area (x0, y0, x1, y1) of a 16 x 16 image."""
    view = view_of()
    prepared = set_up([triangle], view)
    boxes = np.zeros((1, 4), dtype=np.intp)
    kernels.coverage_boxes(prepared.setup, prepared.rows, 0, 16, boxes, 0, 1)
    x0, y0, x1, y1 = area
    return kernels.classify(prepared.setup[0], boxes[0], np.array([y0, y1, x0, x1]))


@pytest.mark.parametrize(
    ("area", "expected"),
    [
        ((0, 0, 8, 4), kernels.SURROUNDING),  # row 3 covers [0, 12): all four rows are full
        ((8, 0, 16, 4), kernels.INTERSECTING),  # row 0 covers [8, 15) of [8, 16)
        ((0, 0, 16, 16), kernels.CONTAINED),  # the whole image holds every covered pixel
        ((0, 0, 15, 15), kernels.CONTAINED),  # the tightest: columns and rows 0..14
        ((0, 0, 14, 15), kernels.INTERSECTING),  # row 0 reaches column 14
        ((10, 10, 16, 16), kernels.DISJOINT),  # inside the bounding box, but below the edge
        ((0, 15, 16, 16), kernels.DISJOINT),  # row 15 is empty: x < 0.5 has no centre
        ((7, 7, 8, 8), kernels.SURROUNDING),  # pixel (7, 7): row 7 covers [0, 8)
        ((8, 7, 9, 8), kernels.DISJOINT),  # pixel (8, 7): just right of row 7's span
    ],
)
def test_classification_of_a_triangle_against_areas(area, expected):
    assert classify(A, area) == expected


def test_classification_follows_the_fill_rule_on_shared_edges():
    # Two triangles sharing the diagonal of a square: each pixel centre belongs to exactly
    # one, so a one-pixel area is surrounded by one and disjoint from the other.
    lower = [(0, 0, 1.0), (16, 16, 1.0), (0, 16, 1.0)]
    upper = [(0, 0, 1.0), (16, 0, 1.0), (16, 16, 1.0)]
    for i in range(16):
        for j in (i, 15 - i):
            kinds = {classify(lower, (i, j, i + 1, j + 1)), classify(upper, (i, j, i + 1, j + 1))}
            assert kinds == {kernels.SURROUNDING, kernels.DISJOINT}


def subdivide(triangles, size=(16, 16), region=None):
    """Run the subdivision on screen triangles; return ids, 1/w, counts, maps, reference."""
    view = view_of(size, region)
    prepared = set_up(triangles, view)
    visibility, (counts, _), maps = warnock._subdivide(prepared, view, explain=True)
    reference = zbuffer(prepared, view)
    return (visibility.triangle_id.copy(), visibility.inv_depth.copy(), counts, maps, reference)


def test_levels_of_a_near_triangle_over_a_backdrop():
    ids, _, counts, maps, reference = subdivide([BACKDROP, B])
    expected = np.array([[1 if i + j < 7 else 0 for i in range(16)] for j in range(16)])
    assert np.array_equal(ids, expected)
    assert np.array_equal(ids, reference.triangle_id)
    # Derived by hand: level 0 (16x16): B in front of the surrounding backdrop: subdivided.
    # Level 1 (8x8): three quarters have the backdrop alone; the top-left is subdivided.
    # Level 2 (4x4): B surrounds [0, 4)^2 and is in front; [4, 8)^2 has the backdrop alone;
    # the other two are cut by B's edge. Level 3 (2x2): in each of those, B surrounds one
    # quarter, misses one, and the edge cuts two. Level 4: of each cut 2x2 area, one pixel
    # has both triangles (i + j = 6), three the backdrop alone.
    columns = ("areas", "empty", "single polygon", "surrounding polygon in front", "subdivided",
               "pixel level", "polygons tested")
    assert LEVEL_COLUMNS == columns
    assert counts.tolist() == [
        [1, 0, 0, 0, 1, 0, 2],
        [4, 0, 3, 0, 1, 0, 8],
        [4, 0, 1, 1, 2, 0, 8],
        [8, 0, 2, 2, 4, 0, 16],
        [16, 0, 12, 0, 0, 4, 32],
    ]
    level, decision, areas = maps
    # Every area examined, level by level: the first is the whole 16x16 image, cut in four.
    assert len(areas) == 1 + 4 + 4 + 8 + 16
    assert areas[0].tolist() == [0, DECISIONS.index("subdivided"), 0, 16, 0, 16]
    assert areas[1:5, 2:].tolist() == [[0, 8, 0, 8], [0, 8, 8, 16], [8, 16, 0, 8], [8, 16, 8, 16]]
    assert level[0, 0] == 2 and decision[0, 0] == DECISIONS.index("surrounding polygon in front")
    assert level[15, 15] == 1 and decision[15, 15] == DECISIONS.index("single polygon")
    assert (decision == DECISIONS.index("pixel level")).sum() == 4
    assert not (decision == DECISIONS.index("subdivided")).any()


def test_empty_and_single_polygon_areas_are_decided_at_once():
    _, _, counts, _, _ = subdivide([])
    assert counts.tolist() == [[1, 1, 0, 0, 0, 0, 0]]
    ids, _, counts, _, reference = subdivide([A])
    assert counts.tolist() == [[1, 0, 1, 0, 0, 0, 1]]
    assert np.array_equal(ids, reference.triangle_id)


def test_odd_and_thin_regions_are_cut_into_two_or_four():
    ids, inv_depth, counts, maps, reference = subdivide([A, B, BACKDROP], size=(13, 5))
    assert np.array_equal(ids, reference.triangle_id)
    assert np.array_equal(inv_depth, reference.inv_depth)
    # Areas 13 x 5 -> 7 x 3 -> 4 x 2 -> 2 x 1 -> 1 x 1: at most five levels, and every pixel
    # is decided (the maps start at -1) at a level that exists, never as "subdivided".
    level, decision, _ = maps
    assert len(counts) <= 5
    assert (level >= 0).all() and (level < len(counts)).all()
    assert (decision >= 0).all() and not (decision == DECISIONS.index("subdivided")).any()


def test_depth_ties_go_to_the_lower_triangle_like_the_zbuffer():
    twin = [(1, 1, 0.5), (14, 3, 0.5), (5, 15, 0.5)]
    other = [(0, 0, 0.5), (16, 0, 0.5), (8, 12, 0.5)]
    ids, _, counts, _, reference = subdivide([other, twin, twin])
    assert np.array_equal(ids, reference.triangle_id)
    assert 2 not in ids
    # Exact ties are never "clearly" in front: those areas go down to pixels.
    assert counts[:, LEVEL_COLUMNS.index("pixel level")].sum() > 0


vertex = st.tuples(
    st.floats(-6, 38, allow_nan=False), st.floats(-6, 30, allow_nan=False), st.floats(0.05, 2.0)
)
triangle_soup = st.lists(st.tuples(vertex, vertex, vertex), min_size=1, max_size=8)


@settings(max_examples=60, deadline=None)
@given(triangle_soup, st.integers(0, 31), st.integers(0, 23))
def test_random_triangles_give_the_zbuffers_visibility(triangles, x0, y0):
    ids, inv_depth, counts, maps, reference = subdivide(triangles, size=(32, 24))
    assert np.array_equal(ids, reference.triangle_id)
    assert np.array_equal(inv_depth, reference.inv_depth)
    # Every area is decided one way or subdivided; the pixel-level areas are single pixels.
    assert np.array_equal(counts[:, 0], counts[:, 1:6].sum(axis=1))
    pixel_level = counts[:, LEVEL_COLUMNS.index("pixel level")].sum()
    assert pixel_level == (maps[1] == DECISIONS.index("pixel level")).sum()
    region = (x0, y0, min(x0 + 9, 32), min(y0 + 7, 24))
    tile = subdivide(triangles, size=(32, 24), region=region)[0]
    assert np.array_equal(tile, ids[region[1] : region[3], region[0] : region[2]])


def test_report_through_render():
    camera = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=60, width=40, height=30)
    wall = pp.Mesh([[-3, -3, -2], [3, -3, -2], [3, 3, -2], [-3, 3, -2]], [[0, 1, 2, 3]])
    scene = pp.Scene(camera, objects=[wall, pp.Box((-0.5, -0.5, -0.5), (0.5, 0.5, 0.5))],
                     lights=[pp.PointLight((2, 3, 5))])
    image, report = pp.render(scene, "warnock", explain=True)
    levels = report.arrays["levels"]
    assert levels.shape[1] == len(LEVEL_COLUMNS)
    assert report.summary["levels"] == len(levels)
    assert report.summary["areas examined"] == levels[:, 0].sum()
    assert report.summary["polygons tested"] == levels[:, -1].sum()
    assert levels[0, 0] == 1  # the whole image is the first area
    # An area is subdivided into 2 or 4: the next level has between 2 and 4 times as many.
    subdivided = levels[:-1, LEVEL_COLUMNS.index("subdivided")]
    assert np.all(2 * subdivided <= levels[1:, 0]) and np.all(levels[1:, 0] <= 4 * subdivided)
    assert report.arrays["level"].shape == (30, 40)
    table = report.tables[0]
    assert len(table.rows) == len(levels) + 1 and table.rows[0][1] == "40x30"
    assert np.array_equal(image.object_id, pp.render(scene).object_id)


@pytest.mark.parametrize("kind", KINDS)
def test_equal_to_the_zbuffer_pixel_for_pixel(kind):
    scene = scene_of(kind, seed=5)
    image = pp.render(scene, "warnock", "gouraud")
    reference = pp.render(scene, "zbuffer", "gouraud")
    assert np.array_equal(image.object_id, reference.object_id)
    assert np.array_equal(image.depth, reference.depth)
    assert np.array_equal(np.asarray(image), np.asarray(reference))
