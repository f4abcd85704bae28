"""A pixel's ray tree drawn over the scene: what ``pixelpath ray --explain`` prints, as a picture.

Two panels, each the scene rendered (z-buffer) with the rays projected over it by the same
camera: the scene's own camera, where the eye ray is seen end-on at the pixel (ringed), and an
overview camera from the side, where the eye ray runs from the eye to its hit. Each kind of ray
has its colour (:data:`RAY_COLOURS`): eye (primary), shadow rays to the lights (grey and
dashed when blocked), reflected and refracted rays; hit points are dots. Rays that hit nothing
are drawn as long as the scene is wide.

The rays are those of :func:`pixelpath.raytrace.ray_tree`, the very ones the renderer traced
for the pixel.

Examples
--------
>>> import pixelpath as pp
>>> from pixelpath.raytrace import ray_tree
>>> from pixelpath.figures.ray_tree import ray_tree_figure
>>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30),
...                  [pp.Sphere((0, 0, 0), 1)], lights=[pp.PointLight((2, 3, 4))])
>>> ray_tree_figure(ray_tree(scene, (20, 15))).mode
'RGB'
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
from PIL import Image

from pixelpath.figures._canvas import COLOURS, Board, Sketch
from pixelpath.scene import Camera, PointLight

__all__ = ["RAY_COLOURS", "overview_camera", "ray_tree_figure"]

RAY_COLOURS = {
    "primary": "primary ray",
    "shadow": "shadow ray",
    "reflected": "reflected ray",
    "refracted": "refracted ray",
}
PANEL = 320  # the longest side of each panel's rendering


def ray_tree_figure(tree: Any, overview: Camera | None = None) -> Image.Image:
    """Return the ray tree of one pixel drawn over the scene, seen by its camera and from aside.

    Parameters
    ----------
    tree : RayTree
        From :func:`pixelpath.raytrace.ray_tree` (or ``pixelpath ray``).
    overview : Camera, optional
        The second panel's camera; by default :func:`overview_camera`. Its size is the
        panel's size.

    Returns
    -------
    PIL.Image.Image
        A board of two panels (a :class:`~pixelpath.figures._canvas.Board`): panel ``k``
        starts at ``(MARGIN + k * (width + GAP), HEADER)``.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.raytrace import ray_tree
    >>> from pixelpath.figures.ray_tree import ray_tree_figure
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30),
    ...                  [pp.Sphere((0, 0, 0), 1)], lights=[pp.PointLight((2, 3, 4))])
    >>> side = pp.Camera(eye=(10, 0, 0), target=(0, 0, 0), fov=90, width=120, height=90)
    >>> ray_tree_figure(ray_tree(scene, (20, 15)), overview=side).size
    (932, 314)
    """
    from pixelpath.raytrace.explain import RayTree

    if not isinstance(tree, RayTree):
        raise TypeError(f"tree must be a RayTree (see pixelpath.raytrace.ray_tree), got "
                        f"{type(tree).__name__}")
    scene = tree.scene
    main = _panel_camera(scene.camera)
    if overview is None:
        overview = overview_camera(tree, main.width, main.height)
    elif not isinstance(overview, Camera):
        raise TypeError(f"overview must be a pixelpath Camera, got {type(overview).__name__}")
    elif (overview.width, overview.height) != (main.width, main.height):
        overview = overview.with_size(main.width, main.height)
    x, y = tree.pixel
    board = Board(
        (main.height, main.width), ["seen by the scene's camera", "seen from aside"],
        f"The ray tree of pixel ({x}, {y}): {tree.rays} rays traced",
        "each ray from its origin to its hit; shadow rays from each hit to the lights",
    )
    for k, camera in enumerate((main, overview)):
        sketch, _ = board.canvas(_backdrop(scene, camera))
        _draw_tree(sketch, camera, tree)
        if k == 0:
            scale = main.width / scene.camera.width
            cx, cy = (x + 0.5) * scale, (y + 0.5) * scale
            sketch.draw.ellipse([cx - 7, cy - 7, cx + 7, cy + 7],
                                outline=COLOURS["primary ray"], width=2)
        else:
            _mark(sketch, camera, np.asarray(scene.camera.eye), "primary ray", "eye")
        board.place(k, sketch.image)
    for kind, colour in RAY_COLOURS.items():
        board.line(f"{kind} ray", swatch=colour)
    board.line("blocked shadow ray", swatch="blocked ray")
    board.skip()
    board.line("rgb " + ", ".join(f"{c:.3g}" for c in tree.rgb))
    seen = f"object {tree.object}" if tree.object >= 0 else "the background"
    board.line(f"sees {seen}")
    return board.image


def overview_camera(tree: Any, width: int = 240, height: int = 180) -> Camera:
    """Return a camera looking from the side at the eye and every point of the ray tree.

    It looks across the scene camera's viewing direction, horizontally, from far enough that
    the eye and the hit points all fit in its 50° view (shadow rays may leave it).

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.raytrace import ray_tree
    >>> from pixelpath.figures.ray_tree import overview_camera
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=9, height=9),
    ...                  [pp.Sphere((0, 0, 0), 1)], lights=[pp.PointLight((0, 0, 5))])
    >>> camera = overview_camera(ray_tree(scene, (4, 4)))
    >>> bool(abs(camera.eye[2] - camera.target[2]) < 1e-9)  # looking along the x axis
    True
    """
    scene = tree.scene
    points = [np.asarray(scene.camera.eye, dtype=np.float64)]
    points += [node.point for root in tree.roots for node in root.walk() if node.hit]
    points = np.array(points)
    centre = (points.min(axis=0) + points.max(axis=0)) / 2
    radius = max(float(np.linalg.norm(points - centre, axis=1).max()), 1e-3)
    forward = np.asarray(scene.camera.target, dtype=np.float64) - scene.camera.eye
    up = np.asarray(scene.camera.up, dtype=np.float64)
    side = np.cross(forward, up)
    if np.linalg.norm(side) < 1e-12:
        side = np.cross(forward, [1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    fov = 50.0
    distance = 1.15 * radius / np.sin(np.radians(fov / 2)) * max(1.0, height / width)
    return Camera(eye=centre + distance * side, target=centre, up=up, fov=fov, width=width,
                  height=height)


def _panel_camera(camera: Camera) -> Camera:
    """Return the scene's camera at the panel's size (the same view, fewer pixels)."""
    scale = PANEL / max(camera.width, camera.height)
    return camera.with_size(max(1, round(camera.width * scale)),
                            max(1, round(camera.height * scale)))


def _backdrop(scene: Any, camera: Camera) -> np.ndarray:
    """Return the scene rendered by ``camera`` (z-buffer, Phong), as uint8 RGB."""
    from pixelpath.renderer import render

    return render(dataclasses.replace(scene, camera=camera)).to_uint8()


def _draw_tree(sketch: Sketch, camera: Camera, tree: Any) -> None:
    reach = _reach(tree)
    lights = tree.scene.lights
    for root in tree.roots:
        for node in root.walk():
            end = node.point if node.hit else node.origin + reach * _unit(node.direction)
            if node.hit:
                for test in node.lights:
                    if not test.tested:
                        continue
                    light = lights[test.light]
                    target = (np.asarray(light.position) if isinstance(light, PointLight)
                              else node.point + reach * test.to_light)
                    blocked = test.let_through == 0.0
                    _segment(sketch, camera, node.point, target,
                             "blocked ray" if blocked else "shadow ray", dashed=blocked)
            _segment(sketch, camera, node.origin, end, RAY_COLOURS[node.kind], width=3)
    for root in tree.roots:
        for node in root.walk():
            if node.hit:
                _mark(sketch, camera, node.point, RAY_COLOURS[node.kind])


def _reach(tree: Any) -> float:
    """How far a ray that hits nothing is drawn: the size of the scene's hit points and eye."""
    points = [np.asarray(tree.scene.camera.eye, dtype=np.float64)]
    points += [node.point for root in tree.roots for node in root.walk() if node.hit]
    points = np.array(points)
    return max(float(np.ptp(points, axis=0).max()), 2.0)


def _unit(vector: np.ndarray) -> np.ndarray:
    length = np.linalg.norm(vector)
    return vector / length if length > 0 else vector


def _project(camera: Camera, a: np.ndarray, b: np.ndarray):
    """Return a segment's ends in pixels, cut where it passes behind the near plane."""
    from pixelpath.raster import _setup_kernels
    from pixelpath.raster.transform import world_to_clip

    clip = world_to_clip(np.array([a, b], dtype=np.float64), camera)
    near = camera.near
    wa, wb = clip[0, 3], clip[1, 3]
    if wa < near and wb < near:
        return None
    if wa < near or wb < near:
        t = (near - wa) / (wb - wa)
        cut = clip[0] + t * (clip[1] - clip[0])
        clip[0 if wa < near else 1] = cut
    screen = np.empty((2, 3))
    _setup_kernels.clip_to_screen(np.ascontiguousarray(clip), camera.width, camera.height,
                                  camera.orthographic, screen)
    return screen[:, :2]


def _segment(sketch: Sketch, camera: Camera, a: np.ndarray, b: np.ndarray, colour: str,
             width: int = 2, dashed: bool = False) -> None:
    ends = _project(camera, a, b)
    if ends is None:
        return
    (x0, y0), (x1, y1) = ends
    if not dashed:
        sketch.draw.line([(x0, y0), (x1, y1)], fill=COLOURS[colour], width=width)
        return
    length = max(float(np.hypot(x1 - x0, y1 - y0)), 1e-9)
    for start in np.arange(0.0, length, 10.0):
        t0, t1 = start / length, min(start + 6.0, length) / length
        sketch.draw.line([(x0 + t0 * (x1 - x0), y0 + t0 * (y1 - y0)),
                          (x0 + t1 * (x1 - x0), y0 + t1 * (y1 - y0))],
                         fill=COLOURS[colour], width=width)


def _mark(sketch: Sketch, camera: Camera, point: np.ndarray, colour: str,
          label: str | None = None) -> None:
    ends = _project(camera, point, point)
    if ends is None:
        return
    x, y = ends[0]
    sketch.draw.ellipse([x - 4, y - 4, x + 4, y + 4], fill=COLOURS[colour],
                        outline=COLOURS["background"])
    if label:
        sketch.text(x + 6, y - 16, label, colour=colour, background="background")
