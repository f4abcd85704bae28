"""The hidden-surface exercises: reproducible, varied, self-consistent, and right.

Every answer is recomputed here another way: dot products written out for back faces,
barycentric depths pixel by pixel and the renderer's own object ids (an orthographic camera
looking down the depth axis) for the screen topics, rays from the eye for the BSP and octree
orders, sampled visibility for the painter's order.
"""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest
import shapely

import pixelpath as pp
from pixelpath import exercises
from pixelpath.exercises.hidden_order import build_bsp

HIDDEN = ("back-face", "z-buffer", "scan-line", "painter", "bsp", "warnock", "octree")

# A required field of each topic and a wrong value for it.
WRONG = {
    "back-face": ("visible", lambda v: v[:-1] if len(v) > 1 else [*v, "Z"]),
    "z-buffer": ("z1", lambda v: v + 0.5),
    "scan-line": ("spans", lambda v: ["." if s != "." else "A" for s in v]),
    "painter": ("order", lambda v: v[::-1]),
    "bsp": ("order", lambda v: v[::-1]),
    "warnock": ("subdivided", lambda v: v[:-1]),
    "octree": ("order", lambda v: v[::-1]),
}


def test_the_topics_are_registered_in_the_notes_order():
    topics = [t for t in exercises.TOPICS if t in HIDDEN]
    assert topics == list(HIDDEN)


@pytest.mark.parametrize("topic", HIDDEN)
def test_same_seed_same_exercise(topic):
    first, second = exercises.make(topic, seed=11), exercises.make(topic, seed=11)
    assert first.params == second.params
    assert first.answer == second.answer
    assert first.question == second.question
    assert f"({topic}-11.png)" in first.question
    json.dumps(first.params)
    json.dumps(first.answer)


@pytest.mark.parametrize("topic", HIDDEN)
def test_different_seeds_differ(topic):
    params = {json.dumps(exercises.make(topic, seed=s).params) for s in range(12)}
    assert len(params) >= 11


@pytest.mark.parametrize("topic", HIDDEN)
@pytest.mark.parametrize("difficulty", ["easy", "standard", "edge"])
def test_own_answer_is_correct_and_a_wrong_one_is_caught(topic, difficulty):
    for seed in range(4):
        ex = exercises.make(topic, seed=seed, difficulty=difficulty)
        assert ex.check(ex.answer).correct
        name, spoil = WRONG[topic]
        wrong = {**ex.answer, name: spoil(ex.answer[name])}
        result = ex.check(wrong)
        assert not result.correct
        assert result.first_wrong == name
        assert name in result.feedback


@pytest.mark.parametrize("topic", [t for t in HIDDEN if t != "octree"])
def test_a_wrong_intermediate_value_is_the_first_wrong(topic):
    ex = exercises.make(topic, seed=3)
    optional = [f for f in ex.fields if not f.required]
    required = {f.name: ex.answer[f.name] for f in ex.fields if f.required}
    field = optional[0]
    value = ex.answer[field.name]
    spoiled = (value + 1 if field.kind == "number"
               else ["ZZ", *list(value)[1:]] if isinstance(value, list) else "ZZ")
    result = ex.check({**required, field.name: spoiled})
    assert result.first_wrong == field.name
    assert ex.check(required).correct


@pytest.mark.parametrize("topic", HIDDEN)
def test_figures_draw_with_and_without_the_answer(topic):
    ex = exercises.make(topic, seed=2)
    question, solved = ex.figure(), ex.figure(solution=True)
    assert question.size == solved.size
    assert question.tobytes() != solved.tobytes()
    assert ex.figure_png().startswith(b"\x89PNG")


# ------------------------------------------------------------------ back faces

def _cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


@pytest.mark.parametrize("difficulty", ["easy", "standard"])
@pytest.mark.parametrize("seed", range(10))
def test_back_faces_by_explicit_dot_products(seed, difficulty):
    ex = exercises.make("back-face", seed=seed, difficulty=difficulty)
    vertices, faces = ex.params["vertices"], ex.params["faces"]
    visible = set()
    for face, names in faces.items():
        p1, p2, p3 = (vertices[n] for n in names[:3])
        normal = _cross([b - a for a, b in zip(p1, p2, strict=True)],
                       [c - a for a, c in zip(p1, p3, strict=True)])
        if "direction" in ex.params:
            view = ex.params["direction"]
        else:
            view = [p - e for p, e in zip(p1, ex.params["eye"], strict=True)]
        dot = sum(n * v for n, v in zip(normal, view, strict=True))
        assert ex.answer[f"NV_{face}"] == pytest.approx(dot)
        if dot < 0:
            visible.add(face)
    assert set(ex.answer["visible"]) == visible
    assert 0 < len(visible) < len(faces)


def test_back_face_normals_point_out_of_the_solid():
    for seed in range(20):
        ex = exercises.make("back-face", seed=seed)
        vertices = ex.params["vertices"]
        centre = np.mean(list(vertices.values()), axis=0)
        for names in ex.params["faces"].values():
            p1, p2, p3 = (np.array(vertices[n], dtype=float) for n in names[:3])
            assert np.dot(np.cross(p2 - p1, p3 - p1), p1 - centre) > 0


# ------------------------------------------------------------------ screens

def _barycentric_depth(vertices, x, y):
    """Depth at (x, y) inside a convex polygon, by a fan triangle's barycentric weights."""
    v = np.array(vertices, dtype=float)
    for k in range(1, len(v) - 1):
        a, b, c = v[0], v[k], v[k + 1]
        m = np.array([[b[0] - a[0], c[0] - a[0]], [b[1] - a[1], c[1] - a[1]]])
        s, t = np.linalg.solve(m, [x - a[0], y - a[1]])
        if s >= -1e-12 and t >= -1e-12 and s + t <= 1 + 1e-12:
            return a[2] + s * (b[2] - a[2]) + t * (c[2] - a[2])
    return None


def brute_force(params):
    """The frame buffer (rows from the top) and depths, by shapely coverage and barycentrics."""
    shapes = {n: shapely.Polygon([v[:2] for v in vs]) for n, vs in params["polygons"].items()}
    rows, depths = [], []
    for j in range(params["height"] - 1, -1, -1):
        row, zs = "", []
        for i in range(params["width"]):
            point = shapely.Point(i + 0.5, j + 0.5)
            best, best_z = ".", np.inf
            for name, shape in shapes.items():
                if shape.contains(point):
                    z = _barycentric_depth(params["polygons"][name], i + 0.5, j + 0.5)
                    if z < best_z:
                        best, best_z = name, z
            row += best
            zs.append(best_z)
        rows.append(row)
        depths.append(zs)
    return rows, depths


def rendered(params, method):
    """The renderer's object ids as rows of letters, seen down the depth axis."""
    width, height = params["width"], params["height"]
    names = list(params["polygons"])
    meshes = [pp.Mesh([(x, y, -z) for x, y, z in vs], [list(range(len(vs)))])
              for vs in params["polygons"].values()]
    camera = pp.Camera(eye=(width / 2, height / 2, 50.0), target=(width / 2, height / 2, 0.0),
                       width=width, height=height, projection="orthographic",
                       view_height=float(height))
    scene = pp.Scene(camera, objects=meshes, lights=[pp.PointLight((0, 0, 60))])
    ids = pp.render(scene, method=method, backface_cull=False).object_id
    return ["".join(names[k] if k >= 0 else "." for k in row) for row in ids]


@pytest.mark.parametrize("seed", range(8))
def test_zbuffer_by_brute_force_and_the_renderer(seed):
    ex = exercises.make("z-buffer", seed=seed)
    rows, depths = brute_force(ex.params)
    assert ex.answer["frame"] == rows
    assert rendered(ex.params, "zbuffer") == rows
    height = ex.params["height"]
    for number, (i, j) in enumerate(ex.params["pixels"], start=1):
        assert ex.answer[f"z{number}"] == pytest.approx(depths[height - 1 - j][i])
    for name, vs in ex.params["polygons"].items():
        # z = a + b x + c y through the vertices: b is the step along a scan line.
        v = np.array(vs, dtype=float)
        (_, b, _), *_ = np.linalg.lstsq(np.c_[np.ones(len(v)), v[:, :2]], v[:, 2], rcond=None)
        assert ex.answer[f"dz_{name}"] == pytest.approx(b)


@pytest.mark.parametrize("seed", range(8))
def test_scanline_by_shapely_and_the_renderer(seed):
    ex = exercises.make("scan-line", seed=seed)
    params, j = ex.params, ex.params["row"]
    y = j + 0.5
    line = shapely.LineString([(-1, y), (params["width"] + 1, y)])
    xs = []
    for vs in params["polygons"].values():
        hit = shapely.Polygon([v[:2] for v in vs]).exterior.intersection(line)
        if not hit.is_empty:
            xs.extend(point.x for point in getattr(hit, "geoms", [hit]))
    assert ex.answer["x"] == pytest.approx(sorted(xs))
    row = brute_force(params)[0][params["height"] - 1 - j]
    assert ex.answer["pixels"] == [row]
    assert rendered(params, "scanline")[params["height"] - 1 - j] == row
    # Each span's polygon is the one seen at the pixels inside it.
    for (left, right), seen in zip(itertools.pairwise(ex.answer["x"]), ex.answer["spans"],
                                  strict=True):
        inside = [row[i] for i in range(params["width"]) if left < i + 0.5 < right]
        assert all(p == seen for p in inside)
    assert [name[0] for name in ex.answer["ael"]] == [
        n for x in ex.answer["x"] for n, vs in params["polygons"].items()
        if shapely.Polygon([v[:2] for v in vs]).exterior.distance(shapely.Point(x, y)) < 1e-9]


def _area_of(name, width, height):
    x0, x1, y0, y1 = 0, width, 0, height
    for digit in name[1:]:
        xm, ym = (x0 + x1) // 2, (y0 + y1) // 2
        x0, x1 = (x0, xm) if digit in "13" else (xm, x1)
        y0, y1 = (ym, y1) if digit in "12" else (y0, ym)
    return x0, x1, y0, y1


def _boxes(params):
    return {n: (min(v[0] for v in vs), max(v[0] for v in vs), min(v[1] for v in vs),
                max(v[1] for v in vs), vs[0][2]) for n, vs in params["polygons"].items()}


@pytest.mark.parametrize("seed", range(8))
def test_warnock_subdivision_obeys_the_rules_and_renders_right(seed):
    ex = exercises.make("warnock", seed=seed)
    params = ex.params
    rows = brute_force(params)[0]
    assert ex.answer["frame"] == rows
    assert rendered(params, "warnock") == rows
    boxes = _boxes(params)
    for quadrant in ("R1", "R2", "R3", "R4"):
        x0, x1, y0, y1 = _area_of(quadrant, params["width"], params["height"])
        expected = []
        for a, b, c, d, _ in boxes.values():
            if a >= x1 or b <= x0 or c >= y1 or d <= y0:
                expected.append("D")
            elif a <= x0 and b >= x1 and c <= y0 and d >= y1:
                expected.append("S")
            elif a >= x0 and b <= x1 and c >= y0 and d <= y1:
                expected.append("C")
            else:
                expected.append("I")
        assert ex.answer[quadrant] == expected
    subdivided = set(ex.answer["subdivided"])
    assert "R" in subdivided
    leaves = 0
    for name in subdivided:
        for child in (name + d for d in "1234"):
            if child in subdivided:
                continue
            leaves += 1
            x0, x1, y0, y1 = _area_of(child, params["width"], params["height"])
            reaching = [n for n, (a, b, c, d, _) in boxes.items()
                        if a < x1 and b > x0 and c < y1 and d > y0]
            surrounding = [n for n in reaching if boxes[n][0] <= x0 and boxes[n][1] >= x1
                           and boxes[n][2] <= y0 and boxes[n][3] >= y1]
            nearest = min(reaching, key=lambda n: boxes[n][4], default=None)
            decided = len(reaching) <= 1 or nearest in surrounding or x1 - x0 == 1
            assert decided, child
        # a subdivided area was not decidable
        x0, x1, y0, y1 = _area_of(name, params["width"], params["height"])
        reaching = [n for n, (a, b, c, d, _) in boxes.items()
                    if a < x1 and b > x0 and c < y1 and d > y0]
        assert len(reaching) >= 2
    counts = sum(ex.answer[k] for k in ("empty", "single", "front", "pixel"))
    assert counts == leaves


# ------------------------------------------------------------------ orders

def _painted(params, order, samples=41):
    """Paint in order at sample points; return the disagreements with the nearest polygon."""
    wrong = 0
    for x, y in itertools.product(np.linspace(0.05, 9.95, samples), repeat=2):
        depths = {n: _barycentric_depth(vs, x, y) for n, vs in params["polygons"].items()}
        depths = {n: z for n, z in depths.items() if z is not None}
        if not depths:
            continue
        painted = [n for n in order if n in depths][-1]
        nearest = min(depths, key=depths.get)
        wrong += depths[painted] > depths[nearest] + 1e-9
    return wrong


@pytest.mark.parametrize("seed", range(8))
def test_painter_order_shows_the_nearest_everywhere(seed):
    ex = exercises.make("painter", seed=seed)
    assert sorted(ex.answer["order"]) == sorted(ex.params["polygons"])
    assert _painted(ex.params, ex.answer["order"]) == 0
    farthest = {n: max(v[2] for v in vs) for n, vs in ex.params["polygons"].items()}
    assert [farthest[n] for n in ex.answer["sorted"]] == sorted(farthest.values(), reverse=True)


def test_painter_orders_are_not_all_the_sorted_list():
    # Some exercises need a swap: the drawing order differs from the depth sort.
    swapped = [s for s in range(40)
               if (ex := exercises.make("painter", seed=s)).answer["order"] != ex.answer["sorted"]]
    assert swapped


def _segments_of(node):
    if node is None:
        return {}
    pieces = {node.name: (np.array(node.start, dtype=float), np.array(node.end, dtype=float))}
    return {**pieces, **_segments_of(node.front), **_segments_of(node.back)}


def _hit(eye, direction, start, end):
    """Distance along the ray to a segment, or None."""
    edge = end - start
    m = np.array([[direction[0], -edge[0]], [direction[1], -edge[1]]])
    if abs(np.linalg.det(m)) < 1e-12:
        return None
    t, u = np.linalg.solve(m, start - eye)
    return t if t > 0 and 0 <= u <= 1 else None


@pytest.mark.parametrize("seed", range(10))
def test_bsp_order_is_back_to_front_along_every_ray(seed):
    ex = exercises.make("bsp", seed=seed)
    pieces = _segments_of(build_bsp(ex.params["walls"]))
    order = ex.answer["order"]
    assert sorted(order) == sorted(pieces)
    # The pieces put back together are the walls.
    for name, (start, end) in ex.params["walls"].items():
        length = sum(np.linalg.norm(b - a) for n, (a, b) in pieces.items() if n[0] == name)
        assert length == pytest.approx(np.linalg.norm(np.subtract(end, start)))
    eye = np.array(ex.params["eye"], dtype=float)
    rank = {name: k for k, name in enumerate(order)}
    for angle in np.linspace(0, 2 * np.pi, 720, endpoint=False):
        direction = np.array([np.cos(angle), np.sin(angle)])
        hits = sorted((t, n) for n, (a, b) in pieces.items()
                      if (t := _hit(eye, direction, a, b)) is not None)
        ranks = [rank[n] for _, n in hits]
        assert ranks == sorted(ranks, reverse=True), (angle, hits)


def test_bsp_tree_preorder_is_a_whole_binary_tree():
    for seed in range(20):
        tree = exercises.make("bsp", seed=seed).answer["tree"]
        names = [t for t in tree if t != "-"]
        assert tree.count("-") == len(names) + 1
        assert len(set(names)) == len(names)


def _leaf_of(point, subdivided):
    name, corner, side = "R", np.zeros(3), 8.0
    while name in subdivided:
        side /= 2
        bits = [int(point[k] >= corner[k] + side) for k in range(3)]
        corner = corner + np.array(bits) * side
        name += str(bits[0] + 2 * bits[1] + 4 * bits[2])
    return corner, side


@pytest.mark.parametrize("seed", range(10))
def test_octree_order_is_front_to_back_along_every_ray(seed):
    ex = exercises.make("octree", seed=seed)
    points, eye = ex.params["points"], np.array(ex.params["eye"], dtype=float)
    subdivided = set(ex.answer["subdivided"])
    order = ex.answer["order"]
    assert sorted(order) == sorted(points)
    # Each point sits alone in its leaf, and every subdivided cell held two or more.
    leaves = {n: _leaf_of(p, subdivided) for n, p in points.items()}
    assert len({(tuple(c), s) for c, s in leaves.values()}) == len(points)
    # The octants: grouped by how many splitting planes separate them from the eye's own.
    eye_octant = sum(1 << k for k in range(3) if eye[k] >= 4)
    octants = [int(k) for k in ex.answer["octants"]]
    assert sorted(octants) == list(range(8))
    crossed = [bin(k ^ eye_octant).count("1") for k in octants]
    assert crossed == sorted(crossed)
    # Along any ray from the eye, leaves are met in the traversal's order.
    rank = {n: order.index(n) for n in points}
    rng = np.random.default_rng(seed)
    for target in rng.uniform(0, 8, size=(300, 3)):
        direction = target - eye
        met = []
        for name, (corner, side) in leaves.items():
            low = (corner - eye) / direction
            high = (corner + side - eye) / direction
            near = np.max(np.minimum(low, high))
            far = np.min(np.maximum(low, high))
            if near < far:
                met.append((near, name))
        ranks = [rank[n] for _, n in sorted(met)]
        assert ranks == sorted(ranks)


# ------------------------------------------------------------------ non-degeneracy

def _fair(topic, ex):
    answer, params = ex.answer, ex.params
    if topic == "back-face":
        dots = [v for k, v in answer.items() if k.startswith("NV_")]
        return all(d != 0 for d in dots) and 0 < len(answer["visible"]) < len(dots)
    if topic in ("z-buffer", "warnock"):
        return len(set("".join(answer["frame"])) - {"."}) == len(params["polygons"])
    if topic == "scan-line":
        return len(answer["x"]) == len(set(answer["x"])) >= 4
    if topic == "painter":
        return any(k.startswith("test_") for k in answer)
    if topic == "bsp":
        return len(answer["order"]) >= 3
    # An easy octree may stop at the first level.
    return len(answer["subdivided"]) >= (1 if ex.difficulty == "easy" else 2)


def _stress(topic, seeds, difficulty="standard"):
    for seed in seeds:
        ex = exercises.make(topic, seed=seed, difficulty=difficulty)
        assert ex.check(ex.answer).correct, seed
        # Edge cases may be degenerate on purpose (a face seen edge-on, a tie in depth).
        assert difficulty == "edge" or _fair(topic, ex), seed


@pytest.mark.parametrize("difficulty", exercises.DIFFICULTIES)
@pytest.mark.parametrize("topic", HIDDEN)
def test_stress_a_hundred_seeds(topic, difficulty):
    _stress(topic, range(50 if topic == "painter" else 100), difficulty)


@pytest.mark.slow
@pytest.mark.parametrize("topic", HIDDEN)
def test_stress_two_thousand_seeds(topic):
    _stress(topic, range(2000))
