"""The playground's JSON API through Starlette's test client: answers and refusals."""

from __future__ import annotations

import base64
import io
import threading

import numpy as np
import pytest

pytest.importorskip("starlette", reason="the playground needs the web extra (starlette)")

from PIL import Image
from practice_answers import typed_answer
from starlette.testclient import TestClient

from pixelpath import exercises
from pixelpath.exercises import Field, Step
from pixelpath.exercises.topics import TOPIC_REGISTRY, Solved, Topic
from pixelpath.web import Limits, api, create_app, practice
from pixelpath.web.app import PAGES

NOTCHED = [[0, 0], [6, 0], [6, 6], [0, 6], [0, 4], [4, 4], [4, 2], [0, 2]]
PATH_LIKE_SCENES = ["../../etc/passwd", "/etc/passwd", "showcase.toml", "data/scenes/showcase",
                    "..", "", "showcase/../showcase", "C:\\Windows\\win.ini"]


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app(), base_url="http://127.0.0.1") as test_client:
        yield test_client


def decode_png(url: str) -> np.ndarray:
    prefix = "data:image/png;base64,"
    assert url.startswith(prefix)
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(url[len(prefix):]))))


def refused(response, status: int = 400) -> str:
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/json"
    message = response.json()["error"]
    assert "Traceback" not in message
    return message


# ----- pages and safety -----------------------------------------------------------------------


@pytest.mark.parametrize("path", ["/", *PAGES])
def test_pages_are_served_with_a_strict_content_security_policy(client, path):
    response = client.get(path)
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    policy = response.headers["content-security-policy"]
    assert "default-src 'self'" in policy and "script-src 'self'" in policy
    assert "http://" not in response.text.replace("http://www.w3.org", "")
    assert "https://" not in response.text


def test_every_script_and_style_a_page_names_is_shipped(client):
    for path in ["/", *PAGES]:
        html = client.get(path).text
        for asset in ("/static/common.js", "/static/style.css"):
            assert asset in html
    for name in ("clipping", "illumination", "hidden-surfaces", "ray-tracing", "colour",
                 "practice"):
        response = client.get(f"/static/{name}.js")
        assert response.status_code == 200 and "use strict" in response.text


def test_unknown_paths_get_a_json_404(client):
    message = refused(client.get("/no/such/page"), 404)
    assert message == "Not Found"
    refused(client.get("/static/../../pyproject.toml"), 404)
    refused(client.get("/api/nope"), 404)


def test_a_request_for_another_host_is_refused(client):
    # DNS rebinding: a page of another site that resolves its name to 127.0.0.1.
    response = client.get("/api/scenes", headers={"host": "evil.example"})
    assert response.status_code == 400


def test_scenes_lists_only_the_bundled_scenes_and_the_limits(client):
    answer = client.get("/api/scenes").json()
    assert answer["scenes"] == ["facets", "shininess", "showcase"]
    assert answer["methods"][0] == "zbuffer" and "raytrace" in answer["methods"]
    assert answer["limits"]["max_side"] == 1024


@pytest.mark.parametrize(
    ("body", "status", "message"),
    [
        (b'{"values": [NaN, 0, 0]}', 400, "NaN"),
        (b'{"values": [Infinity, 0, 0]}', 400, "Infinity"),
        (b'{"values": [-Infinity, 0, 0]}', 400, "-Infinity"),
        (b'{"values": [1e400, 0, 0]}', 400, "must be finite"),
        (b'{"values": [1, 0, 0]', 400, "not valid JSON"),
        (b'[1, 0, 0]', 400, "must be a JSON object"),
        (b'"rgb"', 400, "must be a JSON object"),
        (b"\xff\xfe", 400, "not valid JSON"),
        (b'{"pad": "' + b"x" * 70_000 + b'"}', 413, "larger than"),
        (b"[" * 100_000, 413, "larger than"),
    ],
)
def test_malformed_bodies_are_refused_with_a_message(client, body, status, message):
    response = client.post("/api/colour", content=body,
                           headers={"content-type": "application/json"})
    assert message in refused(response, status)


def test_a_fault_of_the_app_is_a_json_500_without_a_traceback(monkeypatch):
    def broken(data, limits):
        raise RuntimeError("secret internals")

    monkeypatch.setitem(api.ENDPOINTS, "colour", broken)
    with TestClient(create_app(), base_url="http://127.0.0.1",
                    raise_server_exceptions=False) as test_client:
        response = test_client.post("/api/colour", json={})
    message = refused(response, 500)
    assert "secret internals" not in response.text
    assert "bug" in message


def test_a_computation_past_the_time_limit_gets_a_503(monkeypatch):
    release = threading.Event()

    def slow(data, limits):
        release.wait(60)  # longer than the limit below, until the test lets it go
        return {}

    monkeypatch.setitem(api.ENDPOINTS, "colour", slow)
    try:
        with TestClient(create_app(Limits(render_seconds=0.2)),
                        base_url="http://127.0.0.1") as test_client:
            message = refused(test_client.post("/api/colour", json={}), 503)
    finally:
        release.set()
    assert "longer than the playground's limit of 0.2 s" in message


def test_api_answers_only_its_methods(client):
    assert client.get("/api/colour").status_code == 405
    assert client.post("/api/scenes").status_code == 405


# ----- clipping ---------------------------------------------------------------------------------


def test_clip_the_notes_example(client):
    answer = client.post("/api/clip", json={"subject": [[1, 1], [9, 1], [9, 7], [1, 7]],
                                            "window": [2, 2, 8, 6]}).json()
    sh = answer["sutherland_hodgman"]
    # SPEC §9: traced as the algorithm runs, the notes' example ends (2,6) (2,2) (8,2) (8,6).
    assert sh["result"] == [[2, 6], [2, 2], [8, 2], [8, 6]]
    assert [stage["boundary"] for stage in sh["stages"]] == ["left", "right", "bottom", "top"]
    first = sh["stages"][0]["steps"][1]  # S = (1, 1) outside the left edge, E = (9, 1) inside
    assert first["case"] == "out -> in" and first["emitted"] == [[2, 1], [9, 1]]
    assert sh["bridges"] == []
    assert "Clip against the left boundary" in sh["text"]
    assert answer["weiler_atherton"]["pieces"] == [[[2, 2], [8, 2], [8, 6], [2, 6]]]


def test_clip_a_concave_subject_shows_the_bridge_and_the_two_pieces(client):
    answer = client.post("/api/clip", json={"subject": NOTCHED, "window": [-1, -1, 3, 7]}).json()
    assert answer["sutherland_hodgman"]["bridges"] == [[[3, 2], [3, 4]]]
    wa = answer["weiler_atherton"]
    assert wa["pieces"] == [[[0, 0], [3, 0], [3, 2], [0, 2]], [[0, 4], [3, 4], [3, 6], [0, 6]]]
    assert {step["loop"] for step in wa["steps"]} == {0, 1}
    assert len(wa["contacts"]) == 4


def test_clip_a_concave_window_is_for_weiler_atherton_only(client):
    window = [[0, 0], [10, 0], [10, 10], [5, 5], [0, 10]]
    answer = client.post("/api/clip", json={"subject": [[1, 1], [9, 1], [9, 9], [1, 9]],
                                            "window": window}).json()
    assert "convex" in answer["sutherland_hodgman"]["error"]
    assert len(answer["weiler_atherton"]["pieces"]) == 1


def test_clip_a_self_intersecting_subject_is_for_sutherland_hodgman_only(client):
    bow_tie = [[0, 0], [4, 4], [4, 0], [0, 4]]
    answer = client.post("/api/clip", json={"subject": bow_tie, "window": [1, 1, 3, 3]}).json()
    assert "error" in answer["weiler_atherton"]
    assert len(answer["sutherland_hodgman"]["result"]) >= 3


@pytest.mark.parametrize(
    ("subject", "message"),
    [
        (None, "subject must be a list of [x, y] points"),
        ("0,0 1,0 0,1", "subject must be a list of [x, y] points"),
        ([[0, 0], [1, 0]], "3 to 64 vertices"),
        ([[0, 0]] * 65, "3 to 64 vertices"),
        ([[0, 0], [1, 0], [0, 1, 2]], "subject[2] must be a point [x, y]"),
        ([[0, 0], [1, 0], 7], "subject[2] must be a point [x, y]"),
        ([[0, 0], [1, "a"], [0, 1]], "subject[1] must be a number"),
        ([[0, 0], [1, True], [0, 1]], "subject[1] must be a number"),
        ([[0, 0], [1e300, 0], [0, 1]], "subject[1] must lie in"),
        ([[0, 0], [0, 0], [0, 0]], "distinct"),
    ],
)
def test_clip_refuses_malformed_polygons(client, subject, message):
    response = client.post("/api/clip", json={"subject": subject, "window": [0, 0, 1, 1]})
    assert message in refused(response)


@pytest.mark.parametrize("window", [[2, 2, 2, 6], [0, 0, 1], "rect", [[0, 0], [1, 1]], None])
def test_clip_refuses_malformed_windows(client, window):
    refused(client.post("/api/clip", json={"subject": NOTCHED, "window": window}))


# ----- illumination -----------------------------------------------------------------------------


def test_illumination_renders_the_three_shadings_at_the_asked_size(client):
    answer = client.post("/api/illumination", json={"width": 24, "height": 16}).json()
    pictures = {name: decode_png(url) for name, url in answer["images"].items()}
    assert sorted(pictures) == ["flat", "gouraud", "phong"]
    for picture in pictures.values():
        assert picture.shape == (16, 24, 3)
        assert picture[8, 12].sum() > picture[0, 0].sum()  # the ball is lit, the corner is not
    assert not np.array_equal(pictures["flat"], pictures["phong"])


def test_illumination_point_is_the_notes_sum_at_the_centre():
    # Light and eye on the axis through the centre pixel: N·L = R·V = 1, so
    # I = ka Ia + kd IL + ks IL = 0.2·0.2 + 0.6 + 0.5.
    answer = api.illumination_point(
        {"width": 9, "height": 9, "pixel": [4, 4], "light": [0, 0, 5]}, Limits())
    assert answer["n_dot_l"] == pytest.approx(1.0)
    assert answer["r_dot_v"] == pytest.approx(1.0)
    assert answer["terms"]["ambient"] == pytest.approx(0.04)
    assert answer["terms"]["total"] == pytest.approx(1.14)
    assert answer["terms"]["clamped"] == 1.0


def test_illumination_point_agrees_with_the_ray_tracers_local_light(client):
    import pixelpath as pp
    from pixelpath.raytrace import ray_tree

    inputs = {"ka": 0.3, "kd": 0.5, "ks": 0.7, "n": 12, "ia": 0.4, "il": 0.9,
              "light": [-3, 2, 4], "color": [0.2, 0.6, 0.9], "width": 40, "height": 30,
              "pixel": [17, 12]}
    answer = client.post("/api/illumination/point", json=inputs).json()
    material = pp.Material(color=inputs["color"], ka=0.3, kd=0.5, ks=0.7, shininess=12)
    scene = pp.Scene(pp.Camera(eye=(0, 0, 4.2), target=(0, 0, 0), fov=34, width=40, height=30),
                     [pp.Sphere((0, 0, 0), 1.0, material)],
                     [pp.PointLight((-3, 2, 4), intensity=0.9)], ambient=0.4)
    local = ray_tree(scene, (17, 12), max_depth=0).root.local
    np.testing.assert_allclose(answer["rgb"], np.clip(local, 0, 1), atol=1e-12)


def test_illumination_point_off_the_ball_is_a_miss(client):
    answer = client.post("/api/illumination/point", json={"pixel": [0, 0]}).json()
    assert answer == {"hit": False, "pixel": [0, 0]}


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"width": 4096}, "width must lie in 1..1024"),
        ({"height": 0}, "height must lie in 1..1024"),
        ({"width": 32.5}, "width must be an integer"),
        ({"ka": 2}, "ka must lie in [0, 1]"),
        ({"n": -1}, "n must lie in"),
        ({"il": "bright"}, "il must be a number"),
        ({"light": [0, 0]}, "light must be a list of 3 numbers"),
        ({"light": [0, 0, 1e9]}, "light must lie in"),
        ({"color": "red"}, "color must be a list of 3 numbers"),
    ],
)
def test_illumination_refuses_bad_inputs(client, change, message):
    assert message in refused(client.post("/api/illumination", json=change))


@pytest.mark.parametrize("pixel", [None, [1], [-1, 0], [1.5, 2], ["a", 2], [0, 200]])
def test_illumination_point_refuses_bad_pixels(client, pixel):
    response = client.post("/api/illumination/point", json={"pixel": pixel, "width": 64,
                                                             "height": 64})
    assert "pixel" in refused(response)


# ----- hidden surfaces and ray tracing ----------------------------------------------------------


def test_hidden_surfaces_answers_image_report_and_figure(client):
    answer = client.post("/api/hidden-surfaces", json={
        "scene": "shininess", "method": "zbuffer", "width": 40, "height": 18}).json()
    assert decode_png(answer["image"]).shape == (18, 40, 3)
    report = answer["report"]
    assert report["method"] == "zbuffer"
    summary = dict(report["summary"])
    assert summary["pixels drawn"] <= 40 * 18
    assert decode_png(answer["figure"]).shape[1] > 40  # the z-buffer's figure: image and depth


def test_hidden_surfaces_methods_agree_on_a_scene(client):
    pictures = {}
    for method in ("zbuffer", "scanline"):
        answer = client.post("/api/hidden-surfaces", json={
            "scene": "shininess", "method": method, "width": 40, "height": 18}).json()
        pictures[method] = decode_png(answer["image"]).astype(int)
        assert answer["report"]["method"] == method
    differ = np.abs(pictures["zbuffer"] - pictures["scanline"]).max(axis=2) > 8
    assert differ.mean() < 0.05  # silhouette pixels at most


def test_orbit_keeps_the_distance_and_turns_about_the_target():
    import pixelpath as pp

    camera = pp.Camera(eye=(0, 3, 4), target=(0, 1, 0))
    assert api.orbit(camera, 0, 0).eye == pytest.approx([0, 3, 4])
    turned = api.orbit(camera, 90, 0)
    assert turned.eye == pytest.approx([4, 3, 0])
    assert api.orbit(camera, 360, 0).eye == pytest.approx([0, 3, 4])
    top = api.orbit(camera, 0, 180)  # stops short of the pole
    offset = top.eye - top.target
    assert np.linalg.norm(offset) == pytest.approx(np.linalg.norm([0, 2, 4]))
    assert np.degrees(np.arcsin(offset[1] / np.linalg.norm(offset))) == pytest.approx(85)


@pytest.mark.parametrize("scene", PATH_LIKE_SCENES)
def test_scenes_are_bundled_names_never_paths(client, scene):
    message = refused(client.post("/api/hidden-surfaces", json={"scene": scene}), 404)
    assert "unknown scene" in message and "showcase" in message


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"method": "radiosity"}, "unknown method 'radiosity'"),
        ({"method": ["zbuffer"]}, "unknown method"),
        ({"shading": "toon"}, "unknown shading"),
        ({"style": "sketch"}, "unknown style"),
        ({"width": 2000}, "width must lie in 1..1024"),
        ({"azimuth": "left"}, "azimuth must be a number"),
        ({"elevation": 1000}, "elevation must lie in"),
        ({"scene": 3}, "unknown scene 3"),
    ],
)
def test_hidden_surfaces_refuses_bad_inputs(client, change, message):
    response = client.post("/api/hidden-surfaces", json={"scene": "shininess", **change})
    assert message in refused(response, 404 if "scene" in change else 400)


def test_ray_tree_of_a_pixel(client):
    answer = client.post("/api/ray-tree", json={
        "scene": "shininess", "width": 64, "height": 28, "pixel": [32, 14]}).json()
    tree = answer["tree"]
    assert tree["kind"] == "primary" and tree["hit"]
    assert answer["rays"] >= 1 and not answer["truncated"]
    primary = answer["segments"][0]
    assert primary["kind"] == "primary"
    # Seen from the camera, the eye ray is a point: the centre of the pixel it goes through.
    np.testing.assert_allclose(primary["image"], [[32.5, 14.5], [32.5, 14.5]], atol=1e-6)
    assert {segment["kind"] for segment in answer["segments"]} >= {"primary", "shadow"}
    assert answer["text"].startswith("pixel (32, 14) of 64×28")


def test_ray_tree_colour_is_the_ray_traced_pixel(client):
    view = {"scene": "shininess", "width": 48, "height": 21}
    image = decode_png(client.post("/api/hidden-surfaces",
                                   json={**view, "method": "raytrace"}).json()["image"])
    for pixel in ([24, 10], [5, 18], [40, 3]):
        answer = client.post("/api/ray-tree", json={**view, "pixel": pixel}).json()
        expected = image[pixel[1], pixel[0]].astype(float)
        assert np.abs(np.asarray(answer["rgb"]) * 255 - expected).max() <= 1


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"pixel": [64, 0]}, "pixel x must lie in 0..63"),
        ({"pixel": [0, -1]}, "pixel y must lie in"),
        ({"pixel": "32,14"}, "pixel must be [x, y]"),
        ({"max_depth": 9}, "max_depth must lie in 0..8"),
        ({"max_depth": 2.0}, "max_depth must be an integer"),
    ],
)
def test_ray_tree_refuses_bad_inputs(client, change, message):
    body = {"scene": "shininess", "width": 64, "height": 28, "pixel": [3, 3], **change}
    assert message in refused(client.post("/api/ray-tree", json=body))


def test_ray_tree_refuses_path_like_scenes(client):
    response = client.post("/api/ray-tree", json={"scene": "../../etc/passwd", "pixel": [0, 0]})
    refused(response, 404)


def test_project_segment_cuts_the_part_behind_the_camera():
    import pixelpath as pp

    camera = pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=100, height=100)
    # From a point in front of the camera to one behind it: only the front part is drawn,
    # which ends on the near plane, far outside the picture.
    start, end = api.project_segment(camera, (0, 0, 0), (0, 5, 10))
    assert start == pytest.approx([50, 50])
    assert end[0] == pytest.approx(50) and end[1] < -1000


# ----- colour -----------------------------------------------------------------------------------


def test_colour_shows_every_model_with_its_steps(client):
    answer = client.post("/api/colour", json={"model": "rgb", "values": [1, 1, 0]}).json()
    models = answer["models"]
    assert list(models) == ["rgb", "hsv", "hsl", "cmy", "cmyk", "yiq", "ycbcr"]
    assert models["hsv"]["values"] == [60, 1, 1]
    assert models["hsl"]["values"] == [60, 1, 0.5]
    assert models["cmyk"]["values"] == [0, 0, 1, 0]
    assert models["ycbcr"]["values"][0] == pytest.approx(0.886)
    assert any("Cmax" in step for step in models["hsv"]["steps"])
    assert answer["hex"] == "#ffff00"


def test_colour_from_another_model(client):
    answer = client.post("/api/colour", json={"model": "cmyk", "values": [0, 1, 1, 0.5]}).json()
    assert answer["rgb"] == pytest.approx([0.5, 0, 0])
    assert answer["hex"] == "#800000"
    assert answer["to_rgb"]


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ({"model": "lab", "values": [1, 1, 1]}, "unknown model 'lab'"),
        ({"model": "cmyk", "values": [0, 0, 0]}, "values must be a list of 4 numbers"),
        ({"model": "rgb", "values": [2, 0, 0]}, "rgb component 1 must lie in [0, 1]"),
        ({"model": "hsv", "values": [-10, 1, 1]}, "hsv component 1 must lie in [0, 360]"),
        ({"model": "hsv", "values": [400, 1, 1]}, "values must lie in [-360, 360]"),
        ({"model": "rgb", "values": [None, 0, 0]}, "values must be a number"),
    ],
)
def test_colour_refuses_bad_inputs(client, body, message):
    assert message in refused(client.post("/api/colour", json=body))


# ----- practice -------------------------------------------------------------------------------

SHOWN_KEYS = {"topic", "seed", "difficulty", "title", "question", "figure", "marking", "fields"}


def test_exercise_topics_lists_every_topic_with_its_title(client):
    listing = client.get("/api/exercise-topics").json()
    assert [topic["name"] for topic in listing["topics"]] == list(exercises.TOPICS)
    assert all(topic["title"] == exercises.topic_title(topic["name"])
               for topic in listing["topics"])
    assert listing["difficulties"] == list(exercises.DIFFICULTIES)


@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_an_exercise_shows_its_question_and_fields_but_not_its_answer(client, topic):
    exercise = exercises.make(topic, 7, "edge")
    shown = client.post("/api/exercise", json={"topic": topic, "seed": 7,
                                               "difficulty": "edge"}).json()
    assert set(shown) == SHOWN_KEYS
    assert (shown["topic"], shown["seed"], shown["difficulty"]) == (topic, 7, "edge")
    assert shown["question"].startswith("<") and "Step 1" not in shown["question"]
    assert shown["fields"] == [
        {"name": f.name, "label": f.label, "kind": f.kind, "required": f.required,
         "step": f.step} for f in exercise.fields]
    assert (shown["figure"] is None) == (exercise.figure_png() is None)


def test_an_exercise_without_a_seed_gets_one_that_makes_it_again(client):
    shown = client.post("/api/exercise", json={"topic": "rgb-hsv"}).json()
    assert 0 <= shown["seed"] < practice.RANDOM_SEEDS
    again = client.post("/api/exercise", json={"topic": "rgb-hsv", "seed": shown["seed"]})
    assert again.json() == shown


@pytest.mark.parametrize("difficulty", ["standard", "edge"])
@pytest.mark.parametrize("topic", exercises.TOPICS)
def test_the_right_answer_typed_is_marked_correct_and_the_solution_follows(client, topic,
                                                                           difficulty):
    exercise = exercises.make(topic, 5, difficulty)
    marked = client.post("/api/exercise/check", json={
        "topic": topic, "seed": 5, "difficulty": difficulty,
        "values": typed_answer(exercise)}).json()
    assert marked["correct"] is True and marked["first_wrong"] is None
    assert marked["marks"] == {field.name: True for field in exercise.fields}
    assert marked["feedback"] == "Correct."
    assert "<strong>Step 1." in marked["solution"] and "<table>" in marked["solution"]
    assert (marked["solved_figure"] is None) == (exercise.figure_png(solution=True) is None)


def test_a_wrong_value_is_the_first_wrong_with_feedback_naming_it(client):
    exercise = exercises.make("rgb-hsv", 1)
    values = {**typed_answer(exercise), "s": "0.35"}
    marked = client.post("/api/exercise/check", json={
        "topic": "rgb-hsv", "seed": 1, "difficulty": "standard", "values": values}).json()
    assert marked["correct"] is False and marked["first_wrong"] == "s"
    assert marked["marks"] == {"h": True, "v": True, "s": False}
    assert marked["feedback"].startswith("s is not right: look at step 6")


def test_a_required_value_left_out_is_missing(client):
    marked = client.post("/api/exercise/check", json={
        "topic": "rgb-hsv", "seed": 1, "values": {"s": "0.9375"}}).json()
    assert marked["first_wrong"] == "h" and "missing" in marked["feedback"]
    assert marked["marks"] == {"h": False, "v": False, "s": True}


def test_a_figure_is_shown_inline_where_the_question_puts_it(client, monkeypatch):
    def draw(solution):
        return Image.new("RGB", (4, 3), "red" if solution else "white")

    def solve(params):
        return Solved(question="Clip the polygon ![the polygon](FIGURE); see [it](FIGURE).",
                      answer={"n": 3}, fields=(Field("n", "the vertices", 1),),
                      steps=(Step("count", ("n = 3",)),), marking="exact", draw=draw)

    topic = Topic("figure-test", "A figure", "test", lambda rng, difficulty: {}, solve)
    monkeypatch.setitem(TOPIC_REGISTRY, topic.name, topic)
    monkeypatch.setattr(exercises, "TOPICS", (*exercises.TOPICS, topic.name))
    shown = client.post("/api/exercise", json={"topic": topic.name, "seed": 2}).json()
    assert decode_png(shown["figure"]).shape == (3, 4, 3)
    assert f'<img src="{shown["figure"]}" alt="the polygon" class="figure" />' in shown["question"]
    assert '<a href="#figure-box">it</a>' in shown["question"]
    marked = client.post("/api/exercise/check", json={"topic": topic.name, "seed": 2,
                                                      "values": {"n": "3"}}).json()
    assert decode_png(marked["solved_figure"])[0, 0].tolist() == [255, 0, 0]


def test_markdown_passes_no_html_or_inline_style_to_the_page():
    html = practice.markdown_html("<script>alert(1)</script>\n\n| a | b |\n|:-:|--:|\n| 1 | 2 |")
    assert "<script>" not in html and "&lt;script&gt;" in html
    assert "style=" not in html
    assert html.count('class="align-center"') == 2 and html.count('class="align-right"') == 2


@pytest.mark.parametrize(
    ("path", "body", "message"),
    [
        ("exercise", {"topic": "warnock-magic"}, "unknown topic 'warnock-magic'; choose from"),
        ("exercise", {}, "unknown topic ''; choose from"),
        ("exercise", {"topic": "rgb-hsv", "difficulty": "hard"}, "unknown difficulty 'hard'"),
        ("exercise", {"topic": "rgb-hsv", "seed": -1}, "seed must lie in 0..4294967295, got -1"),
        ("exercise", {"topic": "rgb-hsv", "seed": 2**40}, "seed must lie in 0..4294967295"),
        ("exercise", {"topic": "rgb-hsv", "seed": "12a"}, "seed must be an integer, got '12a'"),
        ("exercise", {"topic": "rgb-hsv", "seed": 1.5}, "seed must be an integer, got 1.5"),
        ("exercise/check", {"topic": "rgb-hsv", "values": {}}, "seed is required"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": {"h": "abc"}},
         "cannot read h = 'abc': expected a number"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": {"hue": "72"}},
         "unknown answer field(s) 'hue' for 'rgb-hsv'; its fields are h, s, v"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": ["72"]},
         "values must be an object of field names to typed values, got list"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": {"h": [72]}},
         "the value of 'h' must be typed text or a finite number, got [72]"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": {"h": True}},
         "the value of 'h' must be typed text or a finite number, got True"),
        ("exercise/check", {"topic": "rgb-hsv", "seed": 1, "values": {"h": "7" * 2001}},
         "the value of 'h' holds 2001 characters, more than the 2000 allowed"),
    ],
)
def test_practice_refuses_bad_inputs_with_a_message(client, path, body, message):
    assert message in refused(client.post(f"/api/{path}", json=body))


def test_exercise_topics_is_a_listing_not_a_computation(client):
    assert client.post("/api/exercise-topics").status_code == 405
    assert client.get("/api/exercise").status_code == 405
