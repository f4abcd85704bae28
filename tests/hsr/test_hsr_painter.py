"""The painter's algorithm: each of the notes' tests on hand pairs, moves, splits, the report.

The eye is at (0, 0, 5) looking down -z, so a point's depth (w, the distance along the view
axis) is 5 - z. P is the triangle sorted as farther (the larger farthest depth); each case
says why the tests before the one expected fail.
"""

from __future__ import annotations

import numpy as np
import pytest
from agreement import check_agreement, scene_of

import pixelpath as pp
from pixelpath.hsr import painter
from pixelpath.hsr.painter import TESTS, Comparison, compare

CAMERA = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=64, height=64)

# The steep plane z + 1.5 y + 0.5 = 0 (depths 4..7) and a triangle behind it (depths 6..7).
STEEP = [(-1, -1, 1), (1, -1, 1), (0, 1, -2)]
BEHIND_STEEP = [(-1, -1, -1), (1, -1, -1), (0, 0, -2)]
# The flat triangle z = -1 (depth 6) and the plane z = 2 y - 1 crossing it (depths 5..7).
FLAT = [(-1, -1, -1), (1, -1, -1), (0, 1, -1)]
CROSSING = [(-1, -0.5, -2), (1, -0.5, -2), (0, 0.5, 0)]


@pytest.mark.parametrize(
    ("p", "q", "test"),
    [
        # 1: Q's farthest depth 5 is nearer than P's nearest 9.
        ([(-1, -1, -4), (1, -1, -4), (0, 1, -4)], [(-1, -1, 0), (1, -1, 0), (0, 1, 0)], 1),
        # 2: depths 6..6.2 and 5.9..6.1 overlap; P lies at x < -1, Q at x > 1 (on screen too).
        ([(-3, -1, -1), (-1, -1, -1), (-2, 1, -1.2)], [(1, -1, -1.1), (3, -1, -1.1),
                                                        (2, 1, -0.9)], 2),
        # 3: the same depths; x overlaps, but P lies at y > 1 and Q at y < -1.
        ([(-1, 1, -1), (1, 1, -1), (0, 3, -1.2)], [(-1, -3, -1.1), (1, -3, -1.1),
                                                    (0, -1, -0.9)], 3),
        # 4: P (depths 6..7) against the steep Q (4..7): P's corners give z + 1.5 y + 0.5 =
        # -2, -2, -1.5, all on the side away from the eye (which gives 5.5).
        (BEHIND_STEEP, STEEP, 4),
        # 5: P is the plane z - 0.75 y + 1.5 = 0 (depths 5..8; its corner (0, 2, 0) is on the
        # eye's side of Q's plane z = -1, so test 4 fails); Q (depth 6) gives 0.875 and 0.125,
        # on the eye's side (6.5) of P's plane.
        ([(-2, -2, -3), (2, -2, -3), (0, 2, 0)], [(-0.5, -0.5, -1), (0.5, -0.5, -1),
                                                  (0, 0.5, -1)], 5),
        # 6: P on the plane z = x - 1 (depths 5..6.9), Q on z = -x (4..6): P's corner (1, 1, 0)
        # is on the eye's side of Q's plane (test 4 fails), Q's corner (1, -1, -1) is behind
        # P's (test 5 fails); but P lies at x + y >= 0.1 and Q at x + y <= 0: no overlap.
        ([(1, 1, 0), (-0.9, 1, -1.9), (1, -0.9, 0)], [(-1, -1, 1), (1, -1, -1), (-1, 1, 1)], 6),
    ],
    ids=["depth", "x", "y", "P-behind-Q", "Q-in-front-of-P", "projections"],
)
def test_each_test_settles_its_hand_pair(p, q, test):
    assert compare(p, q, CAMERA) == Comparison(test, "P first")


def test_q_behind_p_plane_moves_before_p():
    # The steep triangle is farther (depth 7 at its top) but BEHIND_STEEP lies behind its
    # plane: every test fails, and the reversed test shows Q cannot hide P.
    assert compare(STEEP, BEHIND_STEEP, CAMERA) == Comparison(0, "Q first")


def test_interpenetrating_pair_must_be_split():
    # FLAT's corners give z - 2 y + 1 = 2, 2, -2 against CROSSING's plane, and CROSSING's
    # give -1, -1, 1 against z = -1: each straddles the other's plane, no order is right.
    assert compare(CROSSING, FLAT, CAMERA) == Comparison(0, "split")


@pytest.mark.parametrize(
    ("p", "q", "error", "match"),
    [
        ([(0, 0, 0)] * 2, FLAT, ValueError, "p must have shape"),
        (FLAT, "abc", TypeError, "q must be three 3-D points"),
        (FLAT, [(0, 0, 0), (1, 0, 0), (2, 0, 0)], ValueError, "q must be a triangle"),
        (FLAT, [(0, 0, 9), (1, 0, 9), (0, 1, 9)], ValueError, "in front of the eye"),
        (FLAT, [(0, 0, np.nan), (1, 0, 0), (0, 1, 0)], ValueError, "q must be finite"),
    ],
)
def test_compare_rejects_bad_input(p, q, error, match):
    with pytest.raises(error, match=match):
        compare(p, q, CAMERA)


def test_compare_needs_a_camera():
    with pytest.raises(TypeError, match="camera"):
        compare(FLAT, STEEP, "eye")


def explain(*triangles):
    """Render triangles (meshes 0, 1, ...) with the painter; return the image and summary."""
    objects = [pp.Mesh(t, [[0, 1, 2]]) for t in triangles]
    scene = pp.Scene(CAMERA, objects=objects, lights=[pp.PointLight((0, 0, 6))])
    image, report = pp.render(scene, "painter", explain=True, backface_cull=False)
    reference = pp.render(scene, "zbuffer", backface_cull=False)
    assert report.method == "painter"
    return image, reference, report.summary


def test_report_of_a_pair_in_depth_order():
    # Sorted [far, near]: the far one meets the near one, which test 1 settles, and is
    # painted; then the near one, alone.
    far = [(-1, -1, -4), (1, -1, -4), (0, 1, -4)]
    image, reference, summary = explain([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], far)
    assert summary["triangles sorted"] == 2
    assert summary["comparisons"] == 1
    assert summary["moves (Q painted before P)"] == 0
    assert summary["splits"] == 0
    assert summary["triangles painted"] == 2
    assert np.array_equal(image.object_id, reference.object_id)
    assert image.object_id[32, 32] == 0


def test_report_of_a_move():
    # Sorted [steep, behind]: steep vs behind fails every test, behind moves before it (one
    # comparison, one move); then behind vs steep is settled by test 4 (a second comparison)
    # and behind is painted, then steep.
    image, reference, summary = explain(STEEP, BEHIND_STEEP)
    assert summary["comparisons"] == 2
    assert summary["moves (Q painted before P)"] == 1
    assert summary["cycles found"] == 0
    assert summary["splits"] == 0
    assert summary["triangles painted"] == 2
    assert np.array_equal(image.object_id, reference.object_id)


def test_report_of_a_split():
    # CROSSING is farther (depth 7); FLAT straddles its plane and is cut by it. No corner of
    # FLAT lies on the plane, so the cut makes three pieces: the corner (0, 1, -1) alone
    # behind the plane, and the other two corners' side in two triangles.
    image, reference, summary = explain(FLAT, CROSSING)
    assert summary["splits"] == 1
    assert summary["pieces made by splitting"] == 3
    assert summary["cycles found"] == 0
    assert summary["triangles painted"] == 4
    assert np.array_equal(image.object_id, reference.object_id)


def test_cyclic_overlap_is_broken_by_a_split():
    # Three long triangles each over the next admit no depth order: one must be split.
    scene = scene_of("cyclic", seed=5)
    _, report = pp.render(scene, "painter", explain=True)
    assert report.summary["splits"] >= 1
    check_agreement(scene, "painter")


def test_a_polygon_moved_twice_closes_a_cycle():
    # Among the interpenetrating meshes' faces some overlaps form cycles: a polygon already
    # moved before the head must move again; the sort splits a member of the cycle instead.
    scene = scene_of("interpenetrating", seed=1)
    _, report = pp.render(scene, "painter", explain=True)
    assert report.summary["cycles found"] >= 1
    check_agreement(scene, "painter")


def test_report_table_counts_every_comparison():
    _, report = pp.render(scene_of("interpenetrating", seed=6), "painter", explain=True)
    (table,) = report.tables
    settled = sum(row[2] for row in table.rows[: len(TESTS)])
    summary = report.summary
    assert summary["splits"] > 0
    # Every comparison is settled by a test, moves Q, or asks for a split (a pair cut more
    # than once is compared again with each piece).
    assert settled + summary["moves (Q painted before P)"] + summary["splits"] + summary.get(
        "pairs left in sorted order (no plane cuts them)", 0
    ) + summary.get("pairs left in sorted order (polygon limit reached)", 0) == summary[
        "comparisons"]


def crossing_soup(count: int = 60, seed: int = 0) -> pp.Scene:
    """``count`` large random triangles crossing each other, each an object of its own colour:
    the 60 of seed 0 need about 1,950 pieces, more than the 8 n + 1024 the sort once allowed."""
    rng = np.random.default_rng(seed)
    corners = rng.uniform(-1, 1, (count, 1, 3)) + rng.normal(0, 0.8, (count, 3, 3))
    objects = [pp.Mesh(triangle, [[0, 1, 2]], pp.Material(color=rng.uniform(0.2, 1, 3),
                                                          double_sided=True))
               for triangle in corners]
    camera = pp.Camera(eye=(0, 0, 6), target=(0, 0, 0), width=96, height=72)
    return pp.Scene(camera, objects, [pp.PointLight((3, 3, 6))])


def test_a_soup_of_crossing_triangles_is_split_until_exact():
    scene = crossing_soup()
    _, report = pp.render(scene, "painter", explain=True)
    assert report.summary["pieces made by splitting"] > 8 * 60 + 1024
    assert "pairs left in sorted order (polygon limit reached)" not in report.summary
    check_agreement(scene, "painter")


def test_the_split_limit_warns_and_is_reported(monkeypatch):
    """With room for 60 + 100 polygons the same soup cannot be split enough: the sort says so."""
    monkeypatch.setattr(painter, "MAX_GROWTH", 1)
    monkeypatch.setattr(painter, "SPLIT_FLOOR", 100)
    with pytest.warns(painter.SplitLimitWarning, match=r"stopped splitting at 160 polygons"):
        _, report = pp.render(crossing_soup(), "painter", explain=True)
    assert report.summary["pairs left in sorted order (polygon limit reached)"] > 0
    assert report.summary["pieces made by splitting"] <= 100
