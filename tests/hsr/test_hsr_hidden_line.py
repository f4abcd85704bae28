"""The line styles: wireframe (every polygon edge) and hidden-line (the edges seen)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from agreement import scene_of
from skimage.measure import label

import pixelpath as pp
from pixelpath.hsr.hidden_line import polygon_edges
from pixelpath.raster import world_to_clip
from pixelpath.raster.lines import draw_lines
from pixelpath.raster.tessellate import scene_geometry
from pixelpath.renderer import View

# Hidden-line drawings must come out alike whichever implemented method filled the surface.
DRAWING_METHODS = ["zbuffer", "scanline", "warnock", "octree"]

ORANGE = pp.Material(color=(1.0, 0.5, 0.25))


def cube_scene(size=(120, 90), **camera):
    options = {"eye": (3, 2, 4), "target": (0, 0, 0), "fov": 40} | camera
    cam = pp.Camera(width=size[0], height=size[1], **options)
    return pp.Scene(cam, objects=[pp.Box((-1, -1, -1), (1, 1, 1), ORANGE)],
                    lights=[pp.PointLight((5, 5, 5))], background=(0.1, 0.2, 0.3))


def test_polygon_edges_are_the_polygons_own_edges_once_each():
    scene = cube_scene()
    starts, ends, owners = polygon_edges(scene, scene_geometry(scene))
    # 12 edges (not the 18 of the 12 triangles), each of length 2 along one axis.
    assert len(owners) == 12 and (owners == 0).all()
    assert np.allclose(np.linalg.norm(ends - starts, axis=1), 2.0)
    assert (np.count_nonzero(ends - starts, axis=1) == 1).all()
    pairs = {tuple(sorted(map(tuple, pair))) for pair in zip(starts, ends, strict=True)}
    assert len(pairs) == 12


def test_polygon_edges_keep_an_edge_shared_by_two_objects_once_per_object():
    square = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
    objects = [pp.Mesh(square, [[0, 1, 2, 3]]), pp.Mesh(square, [[0, 1, 2], [0, 2, 3]])]
    scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0)), objects=objects)
    _, _, owners = polygon_edges(scene, scene_geometry(scene))
    # The quad has 4 edges; the two triangles share their diagonal: 5.
    assert np.bincount(owners).tolist() == [4, 5]


def test_wireframe_draws_every_edge_in_the_object_colour_over_the_background():
    scene = cube_scene()
    image = pp.render(scene, style="wireframe")
    view = View.whole(scene.camera)
    starts, ends, owners = polygon_edges(scene, scene_geometry(scene))
    expected = draw_lines(starts, ends, owners, view).owner
    assert np.array_equal(image.object_id, expected)
    rgb = np.asarray(image)
    drawn = image.object_id == 0
    assert np.array_equal(rgb[drawn], np.tile(np.float32([1.0, 0.5, 0.25]), (drawn.sum(), 1)))
    assert np.array_equal(rgb[~drawn], np.tile(np.float32([0.1, 0.2, 0.3]), ((~drawn).sum(), 1)))
    assert np.isinf(image.depth[~drawn]).all() and np.isfinite(image.depth[drawn]).all()
    # Back-face elimination is a hidden-surface method: the wireframe shows the back edges.
    culled = pp.render(scene, style="wireframe", backface_cull=True)
    assert np.array_equal(culled.object_id, pp.render(scene, style="wireframe",
                                                     backface_cull=False).object_id)


def edge_pixels(scene, start, end):
    lines = draw_lines([start], [end], [0], View.whole(scene.camera))
    return lines.owner == 0


def near(mask):
    """Pixels within one pixel (8-neighbourhood) of the mask's."""
    padded = np.pad(mask, 1)
    grown = np.zeros_like(mask)
    for dy, dx in itertools.product((0, 1, 2), repeat=2):
        grown |= padded[dy : dy + mask.shape[0], dx : dx + mask.shape[1]]
    return grown


@pytest.mark.parametrize("backface_cull", [True, False])
@pytest.mark.parametrize("method", DRAWING_METHODS)
def test_the_cube_loses_exactly_the_three_edges_of_its_far_corner(method, backface_cull):
    # Seen from (3, 2, 4) the faces +x, +y, +z are visible; the three edges meeting at the far
    # corner (-1, -1, -1) lie between two back faces, behind the front ones.
    scene = cube_scene()
    image = pp.render(scene, method, style="hidden-line", backface_cull=backface_cull)
    drawn = image.object_id == 0
    corners = np.array(list(itertools.product((-1.0, 1.0), repeat=3)))
    visible = np.zeros_like(drawn)
    hidden = []
    for a, b in itertools.combinations(corners, 2):
        if np.count_nonzero(a != b) != 1:
            continue  # not an edge
        pixels = edge_pixels(scene, a, b)
        if (a == -1).all() or (b == -1).all():
            hidden.append(pixels)
        else:
            assert drawn[pixels].all(), (a, b)  # every pixel of a visible edge survives
            visible |= pixels
    assert len(hidden) == 3
    # Where a hidden edge reaches the outline, its depth meets the front surface's, within
    # the tolerance: its last two pixels may stay.
    close = near(near(visible))
    for pixels in hidden:
        away = pixels & ~close
        assert away.sum() > 15 and not drawn[away].any()
    assert not (drawn & ~close).any()  # nothing else drawn


def masked_expectation(wire, filled):
    """Which wireframe pixels must stay, which must go, judged independently of the code.

    A line pixel in front of the filled render's surface at its pixel (or over the background)
    stays. One behind every surface sample within a pixel of it, by more than twice their depth
    range (plus 0.1 %), goes: a line pixel's centre is at most a pixel off the line, so no
    surface that close in front of the line could be under it. In between, either is right.
    """
    depth = filled.depth.astype(np.float64)
    padded = np.pad(depth, 1, mode="edge")
    height, width = depth.shape
    around = [padded[dy : dy + height, dx : dx + width] for dy in range(3) for dx in range(3)]
    high, low = np.max(around, axis=0), np.min(around, axis=0)
    line = wire.object_id >= 0
    line_depth = wire.depth.astype(np.float64)
    keep = line & (line_depth <= depth)
    with np.errstate(invalid="ignore"):  # inf - inf around empty pixels: never dropped
        drop = line & (line_depth > high + 2 * (high - low) + 1e-3 * high)
    return keep, drop


@pytest.mark.parametrize("method", DRAWING_METHODS)
@pytest.mark.parametrize("kind", ["separate", "interpenetrating", "near", "floor"])
def test_hidden_line_is_the_wireframe_masked_by_the_filled_render(kind, method):
    scene = scene_of(kind, seed=5)
    wire = pp.render(scene, style="wireframe")
    filled = pp.render(scene, method, backface_cull=False)
    lines = pp.render(scene, method, style="hidden-line", backface_cull=False)
    drawn = lines.object_id >= 0
    # Each kept pixel is the wireframe's pixel, unchanged.
    assert np.array_equal(lines.object_id[drawn], wire.object_id[drawn])
    assert np.array_equal(lines.depth[drawn], wire.depth[drawn])
    assert np.array_equal(np.asarray(lines)[drawn], np.asarray(wire)[drawn])
    keep, drop = masked_expectation(wire, filled)
    assert drawn[keep].all()
    assert not drawn[drop].any()
    # Lines on the surface are within the tolerance (either is right there): the rule still
    # decides well over half the pixels, and drops many.
    lines_drawn = (wire.object_id >= 0).sum()
    assert drop.sum() > 0.04 * lines_drawn and keep.sum() + drop.sum() > 0.6 * lines_drawn


# Not "near": where the near plane cuts a closed mesh open, the wireframe's back edges seen
# through the cut are in front of what the culled render shows, yet no candidates.
@pytest.mark.parametrize("kind", ["separate", "interpenetrating"])
def test_with_back_faces_culled_only_front_polygons_edges_are_drawn(kind):
    scene = scene_of(kind, seed=6)
    wire = pp.render(scene, style="wireframe")
    filled = pp.render(scene)
    lines = pp.render(scene, style="hidden-line")
    drawn = lines.object_id >= 0
    assert (wire.object_id[drawn] >= 0).all()
    keep, drop = masked_expectation(wire, filled)
    assert not drawn[drop].any()
    # Edges between two back faces are not candidates: some pixels in front of the surface
    # (over the background, at silhouettes) may go, but nearly all those to keep stay.
    assert drawn[keep].mean() > 0.97


def test_a_culled_face_draws_no_outline():
    # One triangle turning its back to the camera: culled, it is no surface and no lines.
    triangle = pp.Mesh([[0, 0, 0], [0, 1, 0], [1, 0, 0]], [[0, 1, 2]], ORANGE)  # normal -z
    scene = pp.Scene(pp.Camera(eye=(0.3, 0.3, 4), target=(0.3, 0.3, 0), width=40, height=30),
                     objects=[triangle])
    assert (pp.render(scene, style="hidden-line").object_id == -1).all()
    both_sides = pp.render(scene, style="hidden-line", backface_cull=False)
    wire = pp.render(scene, style="wireframe")
    assert (wire.object_id == 0).sum() > 20
    assert np.array_equal(both_sides.object_id, wire.object_id)


def test_a_plane_has_no_edges_but_hides_the_edges_below_it():
    # A cube sunk halfway into the floor, seen from above: its bottom edges are under the plane.
    floor = pp.Plane((0, 0, 0), (0, 1, 0), pp.Material(color=(0.5, 0.5, 0.5)))
    cube = pp.Box((-1, -1, -1), (1, 1, 1), ORANGE)
    cam = pp.Camera(eye=(2.5, 4, 3.5), target=(0, 0, 0), fov=45, width=120, height=90)
    scene = pp.Scene(cam, objects=[floor, cube], lights=[pp.PointLight((3, 6, 3))])
    wire = pp.render(scene, style="wireframe")
    lines = pp.render(scene, style="hidden-line")
    assert not (wire.object_id == 0).any() and not (lines.object_id == 0).any()
    bottom = np.zeros((90, 120), dtype=bool)
    above = np.zeros((90, 120), dtype=bool)  # the top edges, the vertical edges above y = 0
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    for (xa, za), (xb, zb) in itertools.pairwise([*corners, corners[0]]):
        bottom |= edge_pixels(scene, np.array([xa, -1.0, za]), np.array([xb, -1.0, zb]))
        above |= edge_pixels(scene, np.array([xa, 1.0, za]), np.array([xb, 1.0, zb]))
        above |= edge_pixels(scene, np.array([xa, 0.0, za]), np.array([xa, 1.0, za]))
    assert (wire.object_id[bottom] == 1).mean() > 0.9  # the wireframe shows them
    under = bottom & ~near(near(above))
    assert under.sum() > 20 and not (lines.object_id[under] == 1).any()


def test_edges_are_connected_one_pixel_wide_lines():
    triangle = pp.Mesh([[-1.3, -0.8, 0], [1.1, -0.5, 0], [0.2, 1.2, 0]], [[0, 1, 2]], ORANGE)
    scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=90, height=70),
                     objects=[triangle])
    for style in ("wireframe", "hidden-line"):
        drawn = pp.render(scene, style=style).object_id == 0
        assert label(drawn, connectivity=2).max() == 1  # one 8-connected outline, no gaps
        # The lowest edge runs mostly along x: one pixel per column where it is alone.
        bottom = edge_pixels(scene, np.array([-1.3, -0.8, 0]), np.array([1.1, -0.5, 0]))
        columns = np.flatnonzero(bottom.any(axis=0))
        assert (bottom.sum(axis=0)[columns] == 1).all()
        assert drawn[bottom].all()


def test_edges_crossing_the_near_plane_are_clipped():
    # The camera inside a long box: its four edges along z run from behind the eye to far in
    # front, crossing the near plane (w = 1) inside the view; the four edges of the face behind
    # the eye are wholly behind it.
    box = pp.Box((-0.5, -0.3, -5), (0.5, 0.3, 1), ORANGE)
    cam = pp.Camera(eye=(0, 0, 0), target=(0, 0, -1), fov=70, near=1.0, width=80, height=60)
    image = pp.render(pp.Scene(cam, objects=[box]), style="wireframe")
    assert image.stats["edges outside the frustum"] == 4
    assert image.stats["edges cut by the frustum"] == 4
    drawn = image.object_id == 0
    assert image.depth[drawn].min() == pytest.approx(1.0, rel=1e-3)
    # Each cut edge starts at its point on the near plane, (±0.5, ±0.3, -1).
    for x, y in itertools.product((-0.5, 0.5), (-0.3, 0.3)):
        clip = world_to_clip(np.array([[x, y, -1.0]]), cam)[0]
        column = int((clip[0] / clip[3] + 1) / 2 * cam.width)
        row = int((1 - clip[1] / clip[3]) / 2 * cam.height)
        assert drawn[row, column] and image.depth[row, column] < 1.1


def test_explain_adds_the_line_counts_to_the_methods_report():
    scene = cube_scene()
    _, report = pp.render(scene, "octree", style="hidden-line", explain=True)
    assert report.method == "octree, hidden-line"
    assert report.summary["nodes visited"] >= 1 and report.summary["edges"] == 9
    _, report = pp.render(scene, style="wireframe", explain=True)
    assert report.method == "wireframe" and report.summary["edges"] == 12


# The z-buffer's cases run in every pass; the other methods' (3.5-5 s each in plain Python)
# in the main pass only: the pass without the JIT draws their hidden lines in
# test_hidden_line_is_the_wireframe_masked_by_the_filled_render.
@pytest.mark.parametrize(
    ("method", "style"),
    [("zbuffer", "wireframe"),
     *(pytest.param(m, "hidden-line", marks=[] if m == "zbuffer" else pytest.mark.slow)
       for m in DRAWING_METHODS)],
)
def test_tiles_of_a_line_drawing_equal_the_whole_drawing(method, style):
    for kind in ("floor", "near"):
        scene = scene_of(kind, seed=4)
        whole = pp.render(scene, method, style=style, ssaa=2)
        width, height = scene.camera.width, scene.camera.height
        for x0, x1 in itertools.pairwise((0, 37, width)):
            for y0, y1 in itertools.pairwise((0, 20, 51, height)):
                tile = pp.render(scene, method, style=style, ssaa=2, region=(x0, y0, x1, y1))
                assert np.array_equal(np.asarray(tile), np.asarray(whole)[y0:y1, x0:x1])
                assert np.array_equal(tile.depth, whole.depth[y0:y1, x0:x1])
                assert np.array_equal(tile.object_id, whole.object_id[y0:y1, x0:x1])


def test_progress_counts_the_methods_steps_for_every_style():
    from pixelpath.renderer import render_steps

    for style in ("wireframe", "hidden-line"):
        steps = []
        pp.render(cube_scene(size=(16, 12)), "octree", style=style, progress=steps.append)
        assert sum(steps) == render_steps("octree")


def test_an_unknown_style_names_the_choices():
    with pytest.raises(ValueError, match="style must be one of filled, wireframe, hidden-line"):
        pp.render(cube_scene(), style="outline")
