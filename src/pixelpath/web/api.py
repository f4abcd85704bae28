"""The playground's JSON API: validate a request, call the library, answer with plain data.

Each endpoint is a function ``(data, limits) -> dict`` that runs in a worker thread (see
:mod:`pixelpath.web.app`): ``data`` is the request's JSON object, checked field by field with
:mod:`pixelpath.web._limits` before the library sees it; the answer holds only JSON values
(non-finite numbers become ``null``) and images as ``data:image/png`` URLs.

Examples
--------
>>> from pixelpath.web.api import colour
>>> from pixelpath.web import Limits
>>> colour({"model": "rgb", "values": [1, 1, 0]}, Limits())["models"]["hsv"]["values"]
[60.0, 1.0, 1.0]
"""

from __future__ import annotations

import base64
import dataclasses
import functools
import io
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from pixelpath.web import practice
from pixelpath.web._limits import (
    BadRequest,
    Limits,
    choice,
    image_size,
    integer,
    number,
    points,
    vector,
)

__all__ = [
    "ENDPOINTS",
    "LISTINGS",
    "clip",
    "colour",
    "hidden_surfaces",
    "illumination",
    "illumination_point",
    "ray_tree",
    "scenes",
]

SHADINGS = ("flat", "gouraud", "phong")
LIGHT_BOUND = 50.0  # light positions on the illumination page, world units
MAX_RAY_DEPTH = 8  # a ray tree holds at most 2^(depth+1) - 1 rays
MAX_ELEVATION = 85.0  # orbiting stops short of the poles, where "up" would be the view axis


def scenes(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Return the names the other endpoints accept: bundled scenes, methods, shadings, models.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import scenes
    >>> "showcase" in scenes({}, Limits())["scenes"]
    True
    """
    from pixelpath.color import MODELS
    from pixelpath.renderer import METHOD_NAMES, STYLES
    from pixelpath.scene import bundled_scenes

    return {
        "scenes": list(bundled_scenes()),
        "methods": list(METHOD_NAMES),
        "shadings": list(SHADINGS),
        "styles": list(STYLES),
        "models": list(MODELS),
        "limits": dataclasses.asdict(limits),
    }


# ---------------------------------------------------------------------------------------------
# Clipping


def clip(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Clip ``subject`` against ``window`` with Sutherland-Hodgman and Weiler-Atherton.

    ``window`` is ``[xmin, ymin, xmax, ymax]`` (the notes' rectangle) or a polygon. Each
    algorithm's part holds its result and its trace, or ``error`` when that algorithm cannot
    take the input (a concave window for Sutherland-Hodgman, a self-intersecting subject for
    Weiler-Atherton); when neither can, the request fails.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import clip
    >>> answer = clip({"subject": [[1, 1], [9, 1], [9, 7], [1, 7]], "window": [2, 2, 8, 6]},
    ...               Limits())
    >>> answer["sutherland_hodgman"]["result"]
    [[2.0, 6.0], [2.0, 2.0], [8.0, 2.0], [8.0, 6.0]]
    >>> len(answer["weiler_atherton"]["pieces"])
    1
    """
    subject = points(data, "subject", limits)
    window = _window(data, limits)
    parts = {
        "sutherland_hodgman": _answer_or_error(_sutherland_hodgman, subject, window),
        "weiler_atherton": _answer_or_error(_weiler_atherton, subject, window),
    }
    errors = [part["error"] for part in parts.values() if "error" in part]
    if len(errors) == len(parts):
        raise BadRequest(errors[0])
    return parts


def _window(data: dict[str, Any], limits: Limits) -> Any:
    from pixelpath.clip import Rect

    window = data.get("window")
    if isinstance(window, list) and len(window) == 4 and not any(
            isinstance(v, list) for v in window):
        bounds = [number({"window": v}, "window", 0.0, -1e6, 1e6) for v in window]
        return Rect(*bounds)
    return points(data, "window", limits)


def _answer_or_error(algorithm: Callable[..., dict], *args: Any) -> dict[str, Any]:
    try:
        return algorithm(*args)
    except (ValueError, TypeError) as exc:
        return {"error": str(exc)}


def _sutherland_hodgman(subject: list, window: Any) -> dict[str, Any]:
    from pixelpath.clip import sutherland_hodgman, zero_width_bridges

    result, trace = sutherland_hodgman(subject, window, trace=True)
    bridges = zero_width_bridges(result, window) if len(result) else np.empty((0, 2, 2))
    stages = [
        {
            "boundary": stage.boundary,
            "input": stage.input.tolist(),
            "output": stage.output.tolist(),
            "steps": [
                {
                    "s": step.s.tolist(),
                    "e": step.e.tolist(),
                    "s_inside": step.s_inside,
                    "e_inside": step.e_inside,
                    "case": step.case,
                    "emitted": step.emitted.tolist(),
                }
                for step in stage.steps
            ],
        }
        for stage in trace.stages
    ]
    return {
        "result": result.tolist(),
        "stages": stages,
        "bridges": bridges.tolist(),
        "window": trace.window.vertices.tolist(),
        "text": str(trace),
    }


def _weiler_atherton(subject: list, window: Any) -> dict[str, Any]:
    from pixelpath.clip import weiler_atherton

    pieces, walk = weiler_atherton(subject, window, trace=True)
    return {
        "pieces": [piece.tolist() for piece in pieces],
        "contacts": walk.contacts.tolist(),
        "steps": [
            {"loop": s.loop, "start": s.start.tolist(), "end": s.end.tolist(),
             "along": s.along, "switch": s.switch}
            for s in walk.steps
        ],
        "text": str(walk),
    }


# ---------------------------------------------------------------------------------------------
# Illumination


@dataclasses.dataclass(frozen=True)
class _PhongInputs:
    ka: float
    kd: float
    ks: float
    n: float
    ia: float
    il: float
    light: tuple[float, ...]
    color: tuple[float, ...]


def _phong_inputs(data: dict[str, Any]) -> _PhongInputs:
    return _PhongInputs(
        ka=number(data, "ka", 0.2, 0.0, 1.0),
        kd=number(data, "kd", 0.6, 0.0, 1.0),
        ks=number(data, "ks", 0.5, 0.0, 1.0),
        n=number(data, "n", 20.0, 0.0, 1000.0),
        ia=number(data, "ia", 0.2, 0.0, 2.0),
        il=number(data, "il", 1.0, 0.0, 2.0),
        light=vector(data, "light", (2.5, 3.0, 5.0), 3, LIGHT_BOUND),
        color=tuple(min(max(c, 0.0), 1.0) for c in vector(data, "color", (0.85, 0.35, 0.2),
                                                         3, 1.0)),
    )


def _ball_scene(inputs: _PhongInputs, width: int, height: int, *, exact: bool) -> Any:
    """Return the illumination page's ball: an icosphere of 320 faces, or the exact sphere."""
    from pixelpath.scene import Camera, Material, PointLight, Scene, Sphere, icosphere

    material = Material(color=inputs.color, ka=inputs.ka, kd=inputs.kd, ks=inputs.ks,
                        shininess=inputs.n)
    ball = Sphere((0, 0, 0), 1.0, material=material) if exact else icosphere(2, material=material)
    return Scene(
        camera=Camera(eye=(0, 0, 4.2), target=(0, 0, 0), fov=34, width=width, height=height),
        objects=[ball],
        lights=[PointLight(position=inputs.light, intensity=inputs.il)],
        ambient=inputs.ia,
        background=(0.1, 0.1, 0.12),
    )


def illumination(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Render the ball in flat, Gouraud and Phong shading with the request's Phong inputs.

    Inputs: ``ka``, ``kd``, ``ks`` in [0, 1], ``n`` in [0, 1000], ``ia``, ``il`` in [0, 2],
    ``light`` (x, y, z) and the ball's ``color``; ``width``, ``height`` of each picture.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import illumination
    >>> answer = illumination({"width": 16, "height": 16, "n": 5}, Limits())
    >>> sorted(answer["images"]), answer["images"]["phong"][:22]
    (['flat', 'gouraud', 'phong'], 'data:image/png;base64,')
    """
    from pixelpath.renderer import render

    inputs = _phong_inputs(data)
    width, height = image_size(data, limits)
    scene = _ball_scene(inputs, width, height, exact=False)
    images = {shading: png_url(render(scene, shading=shading).to_uint8()) for shading in SHADINGS}
    return {"images": images, "width": width, "height": height}


def illumination_point(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Return the ambient, diffuse and specular terms where pixel ``pixel`` meets the sphere.

    The point and normal are those of the exact sphere (which Phong shading of the ball
    approximates); the terms come from :func:`pixelpath.lighting.phong_terms`, the notes'
    ``I = ka Ia + kd IL (N·L) + ks IL (R·V)^n``, and ``rgb`` is the displayed colour (the
    ball's colour tints the ambient and diffuse terms).

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import illumination_point
    >>> answer = illumination_point({"width": 9, "height": 9, "pixel": [4, 4],
    ...                              "light": [0, 0, 5]}, Limits())
    >>> answer["hit"], round(answer["n_dot_l"], 6), round(answer["terms"]["total"], 6)
    (True, 1.0, 1.14)
    """
    from pixelpath.lighting import phong_geometry, phong_terms
    from pixelpath.raytrace import ray_tree

    inputs = _phong_inputs(data)
    width, height = image_size(data, limits)
    pixel = _pixel(data, width, height)
    scene = _ball_scene(inputs, width, height, exact=True)
    root = ray_tree(scene, pixel, max_depth=0).root
    if not root.hit:
        return {"hit": False, "pixel": list(pixel)}
    geometry = phong_geometry(root.normal, surface=root.point, light=inputs.light,
                              eye=scene.camera.eye)
    terms = phong_terms(ka=inputs.ka, kd=inputs.kd, ks=inputs.ks, shininess=inputs.n,
                        ambient=inputs.ia, light=inputs.il, n_dot_l=geometry.n_dot_l,
                        r_dot_v=geometry.r_dot_v)
    color = np.asarray(inputs.color)
    rgb = (terms.ambient + terms.diffuse) * color + terms.specular
    return jsonable({
        "hit": True,
        "pixel": list(pixel),
        "point": root.point,
        "normal": root.normal,
        "to_light": geometry.to_light,
        "to_eye": geometry.to_eye,
        "reflected": geometry.reflected,
        "n_dot_l": geometry.n_dot_l,
        "r_dot_v": geometry.r_dot_v,
        "terms": {"ambient": terms.ambient, "diffuse": terms.diffuse,
                  "specular": terms.specular, "total": terms.total, "clamped": terms.clamped},
        "color": color,
        "rgb": np.clip(rgb, 0.0, 1.0),
    })


def _pixel(data: dict[str, Any], width: int, height: int) -> tuple[int, int]:
    pixel = data.get("pixel")
    if not isinstance(pixel, list) or len(pixel) != 2:
        raise BadRequest(f"pixel must be [x, y], got {pixel!r}"[:120])
    x = integer({"pixel x": pixel[0]}, "pixel x", 0, 0, width - 1)
    y = integer({"pixel y": pixel[1]}, "pixel y", 0, 0, height - 1)
    return x, y


# ---------------------------------------------------------------------------------------------
# Hidden surfaces and ray tracing


@functools.lru_cache(maxsize=8)
def _load_bundled(name: str) -> Any:
    from pixelpath.scene import bundled_scene, load_scene

    return load_scene(bundled_scene(name))


def _scene(data: dict[str, Any], limits: Limits) -> Any:
    """Return the bundled scene the request names, seen from its orbiting camera at its size.

    Only the names of the bundled scenes are accepted: the name is looked up, never used
    as a path.
    """
    from pixelpath.scene import bundled_scenes

    name = data.get("scene", "showcase")
    names = list(bundled_scenes())
    if not isinstance(name, str) or name not in names:
        shown = name[:80] if isinstance(name, str) else name
        raise BadRequest(f"unknown scene {shown!r}; choose from {', '.join(names)}", status=404)
    scene = _load_bundled(name)
    width, height = image_size(data, limits)
    azimuth = number(data, "azimuth", 0.0, -360.0, 360.0)
    elevation = number(data, "elevation", 0.0, -180.0, 180.0)
    camera = orbit(scene.camera, azimuth, elevation).with_size(width, height)
    return dataclasses.replace(scene, camera=camera)


def orbit(camera: Any, azimuth: float, elevation: float) -> Any:
    """Return ``camera`` turned about its target by ``azimuth`` and ``elevation`` degrees.

    The azimuth turns about the world's y axis; the elevation is added to the camera's own
    and kept within ±85° so that the up vector never lies along the view.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.web.api import orbit
    >>> orbit(Camera(eye=(0, 0, 5), target=(0, 0, 0)), 90, 0).eye.round(9).tolist()
    [5.0, 0.0, 0.0]
    """
    offset = camera.eye - camera.target
    distance = float(np.linalg.norm(offset))
    base_azimuth = math.atan2(offset[0], offset[2])
    base_elevation = math.asin(max(-1.0, min(1.0, offset[1] / distance)))
    turn = base_azimuth + math.radians(azimuth)
    lift = max(-MAX_ELEVATION, min(MAX_ELEVATION, math.degrees(base_elevation) + elevation))
    lift = math.radians(lift)
    direction = (math.cos(lift) * math.sin(turn), math.sin(lift), math.cos(lift) * math.cos(turn))
    eye = camera.target + distance * np.asarray(direction)
    return dataclasses.replace(camera, eye=eye, up=(0.0, 1.0, 0.0))


def hidden_surfaces(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Render a bundled scene with one method; return the image, the report and the figure.

    Inputs: ``scene`` (a bundled scene's name), ``method``, ``shading``, ``style``,
    ``azimuth`` and ``elevation`` (degrees the camera orbits its target), ``width``,
    ``height``.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import hidden_surfaces
    >>> answer = hidden_surfaces({"scene": "facets", "width": 32, "height": 20}, Limits())
    >>> answer["report"]["method"], answer["figure"][:22]
    ('zbuffer', 'data:image/png;base64,')
    """
    from pixelpath.figures.methods import method_figure
    from pixelpath.renderer import METHOD_NAMES, STYLES, render

    method = choice(data, "method", "zbuffer", METHOD_NAMES)
    shading = choice(data, "shading", "phong", SHADINGS)
    style = choice(data, "style", "filled", STYLES)
    scene = _scene(data, limits)
    image, report = render(scene, method=method, shading=shading, style=style, explain=True)
    figure = method_figure(method, image, report)
    return jsonable({
        "image": png_url(image.to_uint8()),
        "width": image.width,
        "height": image.height,
        "report": {
            "method": report.method,
            "summary": [[key, value] for key, value in report.summary.items()],
            "notes": list(report.notes),
            "tables": [{"title": t.title, "columns": list(t.columns),
                        "rows": [list(row) for row in t.rows]} for t in report.tables],
        },
        "figure": None if figure is None else png_url(np.asarray(figure.convert("RGB"))),
        "stats": dict(image.stats),
    })


def ray_tree(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Trace one pixel of a bundled scene; return its tree of rays and their image positions.

    Inputs: those of :func:`hidden_surfaces` (scene, orbit, size) and ``pixel`` [x, y],
    ``max_depth`` (0..8). ``segments`` are the rays projected into the image (pixel
    coordinates, the part in front of the camera) for drawing over it.

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import ray_tree
    >>> answer = ray_tree({"scene": "showcase", "width": 64, "height": 40,
    ...                    "pixel": [32, 20]}, Limits())
    >>> answer["tree"]["kind"], answer["rays"] >= 1
    ('primary', True)
    """
    from pixelpath.raytrace import ray_tree as trace_pixel

    scene = _scene(data, limits)
    pixel = _pixel(data, scene.camera.width, scene.camera.height)
    max_depth = integer(data, "max_depth", 5, 0, MAX_RAY_DEPTH)
    tree = trace_pixel(scene, pixel, max_depth=max_depth)
    reach = 2.0 * float(np.linalg.norm(np.ptp(_finite_bounds(scene), axis=0))) + 1.0
    segments = []
    for node in tree.root.walk():
        end = node.point if node.hit else node.origin + reach * _unit(node.direction)
        segments.append({"kind": node.kind, "depth": node.depth, "from": node.origin, "to": end})
        for test in node.lights if node.hit else ():
            segments.append({"kind": "shadow", "depth": node.depth, "blocked": test.let_through < 1,
                             "from": node.point, "to": _light_end(scene, test, node.point, reach)})
    for segment in segments:
        segment["image"] = project_segment(scene.camera, segment["from"], segment["to"])
    return jsonable({
        "pixel": list(tree.pixel),
        "rgb": tree.rgb,
        "depth": tree.depth,
        "object": tree.object,
        "rays": tree.rays,
        "truncated": tree.truncated,
        "tree": _node(tree.root),
        "segments": segments,
        "text": str(tree),
    })


def _finite_bounds(scene: Any) -> np.ndarray:
    bounds = np.asarray(scene.bounds(), dtype=np.float64)
    points_ = np.vstack([np.where(np.isfinite(bounds), bounds, 0.0), scene.camera.eye])
    return points_


def _unit(vector_: np.ndarray) -> np.ndarray:
    length = float(np.linalg.norm(vector_))
    return vector_ / length if length > 0 else vector_


def _light_end(scene: Any, test: Any, point: np.ndarray, reach: float) -> np.ndarray:
    light = scene.lights[test.light]
    position = getattr(light, "position", None)
    return np.asarray(position) if position is not None else point + reach * test.to_light


def _node(node: Any) -> dict[str, Any]:
    children = {kind: _node(child) for kind, child in
                (("reflected", node.reflected), ("refracted", node.refracted)) if child is not None}
    return {
        "kind": node.kind,
        "depth": node.depth,
        "weight": node.weight,
        "origin": node.origin,
        "direction": node.direction,
        "hit": node.hit,
        "t": node.t,
        "object": node.object,
        "point": node.point,
        "normal": node.normal,
        "local": node.local,
        "ambient": node.ambient,
        "lights": [
            {"light": test.light, "n_dot_l": test.n_dot_l, "tested": test.tested,
             "let_through": test.let_through, "blocker": test.blocker,
             "diffuse": test.diffuse, "specular": test.specular}
            for test in node.lights
        ],
        "quadratic": None if node.quadratic is None else dataclasses.asdict(node.quadratic),
        "kr": node.kr,
        "kt": node.kt,
        "total_internal_reflection": node.total_internal_reflection,
        "color": node.color,
        **children,
    }


def project_segment(camera: Any, start: Any, end: Any) -> list[list[float]] | None:
    """Return a 3-D segment's part in front of the camera in pixel coordinates, or None.

    Pixel coordinates run from the image's top-left corner: pixel (i, j) covers
    ``[i, i + 1] × [j, j + 1]``.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.web.api import project_segment
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), fov=90, width=100, height=100)
    >>> [[round(c, 9) + 0.0 for c in p] for p in project_segment(camera, (0, 0, 0), (5, 5, 0))]
    [[50.0, 50.0], [100.0, 0.0]]
    >>> project_segment(camera, (0, 0, 6), (0, 1, 7)) is None  # behind the camera
    True
    """
    view = camera.view_matrix()
    ends = [view[:3, :3] @ np.asarray(p, dtype=np.float64) + view[:3, 3] for p in (start, end)]
    near = -camera.near
    a, b = ends
    if a[2] > near and b[2] > near:
        return None
    if a[2] > near or b[2] > near:  # cut the part behind the near plane
        t = (near - a[2]) / (b[2] - a[2])
        cut = a + t * (b - a)
        a, b = (cut, b) if a[2] > near else (a, cut)
    projection = camera.projection_matrix()
    pixels = []
    for p in (a, b):
        clip_ = projection @ np.append(p, 1.0)
        ndc = clip_[:2] / clip_[3]
        pixels.append([float((ndc[0] + 1) / 2 * camera.width),
                       float((1 - ndc[1]) / 2 * camera.height)])
    return pixels


# ---------------------------------------------------------------------------------------------
# Colour


def colour(data: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """Convert one colour into every model, with the notes' steps for each conversion.

    Inputs: ``model`` (one of :data:`pixelpath.color.MODELS`) and ``values`` in that model:
    hue in [0, 360] degrees, YIQ's I in ±0.6 and Q in ±0.53, every other component in [0, 1].

    Examples
    --------
    >>> from pixelpath.web import Limits
    >>> from pixelpath.web.api import colour
    >>> answer = colour({"model": "hsv", "values": [120, 1, 1]}, Limits())
    >>> answer["rgb"], answer["hex"]
    ([0.0, 1.0, 0.0], '#00ff00')
    """
    from pixelpath.color import MODELS, convert
    from pixelpath.color.explain import explain

    model = choice(data, "model", "rgb", tuple(MODELS))
    values = vector(data, "values", (1.0, 1.0, 0.0), MODELS[model], 360.0)
    for k, (value, (low, high)) in enumerate(zip(values, _ranges(model, MODELS[model]),
                                                 strict=True)):
        if not low <= value <= high:
            raise BadRequest(f"{model} component {k + 1} must lie in [{low:g}, {high:g}], "
                             f"got {value:g}")
    rgb = [float(c) for c in convert(np.asarray(values), src=model, dst="rgb")]
    to_rgb, _ = explain(values, model, "rgb")
    models = {}
    for name in MODELS:
        steps, result = explain(rgb, "rgb", name)
        models[name] = {"values": result, "steps": steps}
    hex_code = "#" + "".join(f"{round(min(max(c, 0.0), 1.0) * 255):02x}" for c in rgb)
    return jsonable({"model": model, "values": list(values), "rgb": rgb, "hex": hex_code,
                     "to_rgb": to_rgb, "models": models})


def _ranges(model: str, count: int) -> list[tuple[float, float]]:
    """Return the range of each component of ``model``: hue in degrees, YIQ's I and Q signed."""
    if model in ("hsv", "hsl"):
        return [(0.0, 360.0), (0.0, 1.0), (0.0, 1.0)]
    if model == "yiq":
        return [(0.0, 1.0), (-0.6, 0.6), (-0.53, 0.53)]
    return [(0.0, 1.0)] * count


# ---------------------------------------------------------------------------------------------
# Answers


def png_url(pixels: np.ndarray) -> str:
    """Return an (H, W, 3) uint8 array as a ``data:image/png;base64,...`` URL.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.web.api import png_url
    >>> png_url(np.zeros((2, 2, 3), dtype=np.uint8))[:30]  # the PNG signature, in base64
    'data:image/png;base64,iVBORw0K'
    """
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(pixels, dtype=np.uint8)).save(buffer, format="PNG")
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")


def jsonable(value: Any) -> Any:
    """Return ``value`` with arrays as lists, NumPy scalars as Python ones, non-finite as None.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.web.api import jsonable
    >>> jsonable({"t": np.float32(2.5), "hits": np.array([1.0, np.inf])})
    {'t': 2.5, 'hits': [1.0, None]}
    """
    if isinstance(value, dict):
        return {str(key): jsonable(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [jsonable(item) for item in value]
    if isinstance(value, np.ndarray):
        return jsonable(value.tolist())
    if isinstance(value, np.generic):
        return jsonable(value.item())
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


Handler = Callable[[dict[str, Any], Limits], dict[str, Any]]

# Endpoint name (the path under /api/) -> handler, answering POST requests.
ENDPOINTS: dict[str, Handler] = {
    "clip": clip,
    "illumination": illumination,
    "illumination/point": illumination_point,
    "hidden-surfaces": hidden_surfaces,
    "ray-tree": ray_tree,
    "colour": colour,
    "exercise": practice.make_exercise,
    "exercise/check": practice.check_exercise,
}

# The names the pages fill their choices from, answering GET requests (no body).
LISTINGS: dict[str, Handler] = {
    "scenes": scenes,
    "exercise-topics": practice.exercise_topics,
}
