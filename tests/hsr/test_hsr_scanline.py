"""The scan-line method: spans on hand cases, its report, and pixel-exact agreement."""

from __future__ import annotations

import math

import numpy as np
import pytest
from agreement import KINDS, scene_of
from hypothesis import example, given, settings
from hypothesis import strategies as st
from screen_triangles import set_up, view_of, zbuffer

import pixelpath as pp
from pixelpath.hsr import scanline
from pixelpath.hsr.scanline import LINE_COUNTS

# Far (1/w = 0.5) triangle A covers columns [0, 15 - j) of row j; near (1/w = 1) triangle B
# covers [4, 13 - j) on rows 2..9 (the top-left rule on pixel centres j + 0.5).
FAR = [(0, 0, 0.5), (16, 0, 0.5), (0, 16, 0.5)]
NEAR = [(4, 2, 1.0), (12, 2, 1.0), (4, 10, 1.0)]
# Interpenetrating: 1/w of A falls with x (0.66 - 0.02 x), of B rises (0.42 + 0.01 x); they
# cross at x = 8. B covers [j, 16) of row j.
FALLING = [(0, 0, 0.66), (16, 0, 0.34), (0, 16, 0.66)]
RISING = [(0, 0, 0.42), (16, 0, 0.58), (16, 16, 0.58)]


def scan(triangles, size=(16, 16), region=None):
    """Run the scan-line kernels on screen triangles; return ids, 1/w, counts by name."""
    view = view_of(size, region)
    prepared = set_up(triangles, view)
    visibility, counts = scanline._scan(prepared, view)
    reference = zbuffer(prepared, view)
    named = {name: counts[:, k].copy() for k, name in enumerate(LINE_COUNTS)}
    return visibility.triangle_id.copy(), visibility.inv_depth.copy(), named, reference


def expected_ids(covers):
    """Ids (16, 16) from a function (i, j) -> triangle seen there, -1 for none."""
    return np.array([[covers(i, j) for i in range(16)] for j in range(16)], dtype=np.int32)


def test_near_triangle_over_far_one():
    ids, _, counts, reference = scan([FAR, NEAR])

    def seen(i, j):
        if 2 <= j <= 9 and 4 <= i < 13 - j:
            return 1
        return 0 if i < 15 - j else -1

    assert np.array_equal(ids, expected_ids(seen))
    assert np.array_equal(ids, reference.triangle_id)
    # Row 4: crossings A 0, B 4, B 9, A 11: spans [0, 4) A alone, [4, 9) A and B (B nearer at
    # both ends: no split), [9, 11) A alone; [11, 16) is background.
    row = {name: int(counts[name][4]) for name in LINE_COUNTS}
    assert row == {
        "active edges": 4, "edges entering": 0, "edges leaving": 0, "sort moves": 0,
        "crossings": 4, "spans": 3, "spans without depth": 2, "spans compared by depth": 1,
        "span splits": 0, "pixels compared one by one": 0,
    }
    # B's two edges enter on row 2 and leave on row 10; A's enter on row 0. On row 9 B's span
    # is empty (both its crossings at column 4), so A's two pieces are separate spans.
    assert counts["edges entering"].tolist() == [2, 0, 2] + [0] * 13
    assert counts["edges leaving"].tolist() == [0] * 10 + [2] + [0] * 5
    assert counts["spans"].tolist() == [1, 1] + [3] * 7 + [2] + [1] * 5 + [0]
    assert counts["spans compared by depth"].sum() == 7
    assert counts["spans without depth"].sum() == 23
    assert counts["span splits"].sum() == 0


def test_interpenetrating_span_splits_where_the_planes_cross():
    ids, inv_depth, counts, reference = scan([FALLING, RISING])

    def seen(i, j):
        in_a, in_b = i < 15 - j, i >= j
        if in_a and in_b:
            return 0 if i + 0.5 < 8 else 1
        return 0 if in_a else 1 if in_b else -1

    assert np.array_equal(ids, expected_ids(seen))
    assert np.array_equal(ids, reference.triangle_id)
    assert np.array_equal(inv_depth, reference.inv_depth)
    # Row 2: A covers [0, 13), B [2, 16): [0, 2) A alone, [2, 13) both, split once at
    # column 8 (A nearer left of x = 8), [13, 16) B alone.
    assert ids[2].tolist() == [0] * 8 + [1] * 8
    assert counts["spans"][2] == 3
    assert counts["spans compared by depth"][2] == 1
    assert counts["span splits"][2] == 1
    # A span of both triangles straddling x = 8 is split once; one lying on one side is not.
    overlap = [(j, 15 - j) for j in range(16)]
    straddles = [int(first < 8 < stop) for first, stop in overlap]
    assert counts["span splits"].tolist() == straddles


def test_depth_ties_go_to_the_lower_triangle_like_the_zbuffer():
    # The same triangle twice, and a coplanar one overlapping it: every tie at every pixel.
    twin = [(1, 1, 0.5), (14, 3, 0.5), (5, 15, 0.5)]
    other = [(0, 0, 0.5), (16, 0, 0.5), (8, 12, 0.5)]
    ids, _, counts, reference = scan([other, twin, twin])
    assert np.array_equal(ids, reference.triangle_id)
    assert 2 not in ids
    # Exact ties are never "clearly" nearer: those spans are decided pixel by pixel.
    assert counts["pixels compared one by one"].sum() > 0


def test_spans_reaching_outside_the_image_are_clipped():
    big = [(-40, -3, 0.2), (70, 2, 0.3), (5, 60, 0.4)]
    ids, _, counts, reference = scan([big, NEAR])
    assert np.array_equal(ids, reference.triangle_id)
    # Crossings outside the image's columns are not counted.
    assert counts["crossings"].max() <= 2 + 2


@pytest.mark.parametrize("region", [(0, 0, 16, 16), (3, 2, 11, 15), (7, 0, 8, 16)])
def test_a_region_equals_the_same_pixels_of_the_whole_image(region):
    whole, whole_depth, _, _ = scan([FALLING, RISING, NEAR])
    ids, inv_depth, _, _ = scan([FALLING, RISING, NEAR], region=region)
    x0, y0, x1, y1 = region
    assert np.array_equal(ids, whole[y0:y1, x0:x1])
    assert np.array_equal(inv_depth, whole_depth[y0:y1, x0:x1])


vertex = st.tuples(
    st.floats(-6, 38, allow_nan=False), st.floats(-6, 30, allow_nan=False), st.floats(0.05, 2.0)
)
triangle_soup = st.lists(st.tuples(vertex, vertex, vertex), min_size=1, max_size=8)


TINY = 2.2250738585072014e-308  # the smallest normal float64


@settings(max_examples=60, deadline=None)
@given(triangle_soup, st.integers(0, 31), st.integers(0, 23))
# Found by hypothesis: a sliver whose planes overflowed, and an edge rising by TINY whose slope
# overflowed (warnings without the JIT, inf and NaN with it). Both draw nothing now.
@example([((0, 0, 1), (0, 0, 1), (0, 0, 1)), ((0, 0, 1), (1, 0, 1), (4, TINY, 1))], 0, 0)
@example([((0, 0, 1), (0, 1, 1), (4, TINY, 1))], 0, 0)
def test_random_triangles_give_the_zbuffers_visibility(triangles, x0, y0):
    # Random 1/w per vertex: the triangles interpenetrate in every way. The scan-line method
    # must give the z-buffer's triangle and 1/w at every pixel, of the image and of a region.
    ids, inv_depth, _, reference = scan(triangles, size=(32, 24))
    assert np.array_equal(ids, reference.triangle_id)
    assert np.array_equal(inv_depth, reference.inv_depth)
    region = (x0, y0, min(x0 + 9, 32), min(y0 + 7, 24))
    tile, _, _, _ = scan(triangles, size=(32, 24), region=region)
    assert np.array_equal(tile, ids[region[1] : region[3], region[0] : region[2]])


def small_scene(objects, width=40, height=30):
    camera = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=60, width=width, height=height)
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((2, 3, 5))])


def test_report_of_one_triangle():
    triangle = pp.Mesh([[-1.5, -1, 0], [1.5, -1.2, 0], [0.2, 1.4, 0]], [[0, 1, 2]])
    image, report = pp.render(small_scene([triangle]), "scanline", explain=True)
    arrays = report.arrays
    assert list(arrays) == ["row", *LINE_COUNTS]
    assert arrays["row"].tolist() == list(range(30))
    drawn_rows = (image.object_id >= 0).any(axis=1)
    # One triangle: each line it crosses has its two edges and at most one span, of it alone.
    assert np.array_equal(arrays["spans"], drawn_rows.astype(int))
    assert np.array_equal(arrays["spans without depth"], arrays["spans"])
    assert set(arrays["active edges"].tolist()) <= {0, 2}
    assert arrays["spans compared by depth"].sum() == 0
    # Its three edges enter (two at its top vertex, one at its middle vertex) and leave (one
    # at the middle vertex, two at the bottom), all inside the image and in one band.
    assert arrays["edges entering"][arrays["edges entering"] > 0].tolist() == [2, 1]
    assert arrays["edges leaving"][arrays["edges leaving"] > 0].tolist() == [1, 2]
    assert report.summary["pixels drawn"] == int((image.object_id >= 0).sum())
    assert report.summary["spans"] == int(drawn_rows.sum())
    table = report.tables[0]
    assert table.columns == ("row", *scanline.TABLE_COLUMNS)
    assert table.rows[0][1:] == tuple(
        int(arrays[name][0]) for name in scanline.TABLE_COLUMNS.values()
    )
    assert table.rows[-1][0] == "total"
    assert len(table.rows) == len(range(0, 30, math.ceil(30 / scanline.PRINTED_LINES))) + 1
    assert "scanline" in str(report)


def test_report_of_a_box_in_front_of_a_wall():
    # The box hides part of the wall: those spans are compared by depth, without any split
    # (nothing interpenetrates), and the totals add up.
    wall = pp.Mesh([[-3, -3, -2], [3, -3, -2], [3, 3, -2], [-3, 3, -2]], [[0, 1, 2, 3]])
    box = pp.Box((-0.5, -0.5, -0.5), (0.5, 0.5, 0.5))
    image, report = pp.render(small_scene([wall, box]), "scanline", explain=True)
    arrays = report.arrays
    assert arrays["spans compared by depth"].sum() > 0
    assert arrays["span splits"].sum() == 0
    assert np.array_equal(
        arrays["spans"], arrays["spans without depth"] + arrays["spans compared by depth"]
    )
    assert report.summary["span splits"] == 0
    reference = pp.render(small_scene([wall, box]))
    assert np.array_equal(image.object_id, reference.object_id)


@pytest.mark.parametrize("kind", KINDS)
def test_equal_to_the_zbuffer_pixel_for_pixel(kind):
    # Stronger than the agreement test: the same coverage rule and tie rule make the two
    # methods' pictures identical, not only close.
    scene = scene_of(kind, seed=5)
    image = pp.render(scene, "scanline", "gouraud")
    reference = pp.render(scene, "zbuffer", "gouraud")
    assert np.array_equal(image.object_id, reference.object_id)
    assert np.array_equal(image.depth, reference.depth)
    assert np.array_equal(np.asarray(image), np.asarray(reference))
