"""Pictures of the hidden-surface methods at work, drawn from their explain reports.

Every picture is drawn from what the method itself recorded while rendering
(``pixelpath.render(..., explain=True)`` returns it as ``report.arrays``, with the rendered
image attached); nothing here decides visibility again.

* the z-buffer filling the image band by band: colour buffer, depth buffer and how many
  triangles were depth-tested at each pixel (:func:`zbuffer_frames`);
* the scan-line method going down the image, with the active edges and the spans compared by
  depth on each line (:func:`scanline_frames`);
* Warnock's subdivision, one frame per level, every area coloured by how it was decided
  (:func:`warnock_frames`, :func:`warnock_figure`);
* the painter's order, one polygon (or group) per frame, pieces made by splitting marked
  (:func:`order_frames`);
* the BSP tree as a diagram beside the drawing order (:func:`bsp_figure`, :func:`bsp_frames`);
* the octree's cells, coloured by what the front-to-back traversal did with them
  (:func:`octree_figure`).

Each frame is a :class:`~pixelpath.figures._canvas.Board`: a title, panels of the image's size
(scaled up by ``picture_scale``, nearest neighbour, so every pixel of the image is a square
block) and a column of numbers on the right.

Examples
--------
>>> import pixelpath as pp
>>> from pixelpath.figures.hidden_surfaces import warnock_frames
>>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
>>> image, report = pp.render(scene, method="warnock", explain=True)
>>> len(warnock_frames(image, report)) == len(report.arrays["levels"])
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from PIL import Image

from pixelpath.figures._canvas import COLOURS, Board, PixelPanel

__all__ = [
    "DECISION_COLOURS",
    "OBJECT_COLOURS",
    "OUTCOME_COLOURS",
    "bsp_figure",
    "bsp_frames",
    "depth_grey",
    "octree_figure",
    "octree_frames",
    "order_figure",
    "order_frames",
    "scanline_figure",
    "scanline_frames",
    "warnock_figure",
    "warnock_frames",
    "zbuffer_frames",
]

ORDER_FRAMES = 40  # the painter's and BSP animations show at most this many frames
FILL_FRAMES = 30  # the scan-line animation shows at most this many groups of lines
OUTLINED = 300  # drawing orders with more triangles are drawn without their edges
DIAGRAM_NODES = 24  # the BSP diagram shows the levels of the tree that fit this many nodes
STEP_MS, LAST_MS = 400, 2500

# The colour of each of Warnock's decisions (the codes of pixelpath.hsr.warnock.DECISIONS);
# subdivided areas are outlined in the boundary colour where they are cut.
DECISION_COLOURS = ("empty area", "single area", "in front area", "boundary", "pixel area")
OBJECT_COLOURS = tuple(f"object {k}" for k in range(1, 7))


def depth_grey(depth: np.ndarray) -> np.ndarray:
    """Return (H, W) uint8 greys of a depth buffer: near light, far dark, nothing black.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.figures.hidden_surfaces import depth_grey
    >>> depth_grey(np.array([[1.0, 2.0, np.inf]])).tolist()
    [[255, 55, 0]]
    """
    depth = np.asarray(depth, dtype=np.float64)
    drawn = np.isfinite(depth)
    grey = np.zeros(depth.shape, dtype=np.uint8)
    if drawn.any():
        near, far = depth[drawn].min(), depth[drawn].max()
        scale = (far - near) or 1.0
        grey[drawn] = np.rint(255 - 200 * (depth[drawn] - near) / scale).astype(np.uint8)
    return grey


def _checked(image: Any, report: Any, keys: Sequence[str]) -> np.ndarray:
    """Return the image as (H, W, 3) uint8, after checking the report has what is drawn."""
    if report is None or not hasattr(report, "arrays"):
        raise ValueError("the figure is drawn from the method's report: get it from "
                         "pixelpath.render(scene, method=..., explain=True)")
    if image is None:
        raise ValueError(
            f"the {report.method} report has no image to draw on: get both from "
            "pixelpath.render(scene, method=..., explain=True) without supersampling (ssaa=1)"
        )
    missing = [key for key in keys if key not in report.arrays]
    if missing:
        raise ValueError(f"the {report.method} report lacks {', '.join(missing)}: it did not "
                         "come from pixelpath.render(..., explain=True)")
    rgb = image.to_uint8()
    for key in keys:
        shape = np.shape(report.arrays[key])
        if key in ("level", "decision", "depth tests") and shape != rgb.shape[:2]:
            raise ValueError(
                f"the {report.method} report's {key!r} map is {shape}, the image "
                f"{rgb.shape[:2]}: figures need the filled style and ssaa=1"
            )
    return rgb


def _palette(names: Sequence[str]) -> np.ndarray:
    return np.array([COLOURS[name] for name in names], dtype=np.uint8)


def _white(shape: tuple[int, int]) -> np.ndarray:
    return np.full((*shape, 3), 255, dtype=np.uint8)


# The z-buffer and the scan-line method: filling the image.


def zbuffer_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return the z-buffer filling the image, one frame per band of rows it renders.

    Panels: the colour buffer and the depth buffer filled down to the band, and how many
    triangles were depth-tested at each pixel (its depth complexity,
    ``report.arrays["depth tests"]``).

    Returns
    -------
    list of PIL.Image.Image
        ``ceil(height / BAND_ROWS)`` frames.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import zbuffer_frames
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=40),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> len(zbuffer_frames(*pp.render(scene, explain=True)))  # bands of 32 rows
    2
    """
    from pixelpath.raster._scan_kernels import BAND_ROWS

    rgb = _checked(image, report, ["depth tests"])
    tests = np.asarray(report.arrays["depth tests"])
    height = rgb.shape[0]
    depth = np.repeat(depth_grey(image.depth)[..., None], 3, axis=2)
    complexity = _complexity(tests)
    drawn = np.asarray(image.object_id) >= 0
    bands = math.ceil(height / BAND_ROWS)
    frames = []
    for band in range(bands):
        first, stop = band * BAND_ROWS, min((band + 1) * BAND_ROWS, height)
        board = Board(
            rgb.shape[:2], ["colour buffer", "depth buffer (near is light)", "depth tests"],
            f"The z-buffer: band {band + 1} of {bands}, rows {first}-{stop - 1}",
            "each triangle over the band is scan-converted; a sample replaces the stored one "
            "when it is nearer",
        )
        for k, picture in enumerate((rgb, depth, complexity)):
            shown = _white(rgb.shape[:2])
            shown[:stop] = picture[:stop]
            board.paste(k, shown)
            board.sketch.draw.rectangle(board.panels[k].box(first, stop, 0, rgb.shape[1]),
                                        outline=COLOURS["boundary"], width=2)
        band_tests = int(tests[first:stop].sum())
        band_drawn = int(drawn[first:stop].sum())
        board.line(f"rows {first}-{stop - 1}:")
        board.line(f"depth tests {band_tests}")
        board.line(f"pixels drawn {band_drawn}")
        board.line(f"samples hidden {band_tests - band_drawn}")
        board.skip()
        board.line(f"largest depth complexity {int(tests.max(initial=0))}", colour="muted")
        frames.append(board.image)
    return frames


def _complexity(tests: np.ndarray) -> np.ndarray:
    """Depth tests per pixel as colours: white for none, deepening purple for more."""
    tests = np.asarray(tests, dtype=np.float64)
    share = tests / max(tests.max(initial=0.0), 1.0)
    purple = np.array(COLOURS["edge"], dtype=np.float64)
    rgb = 255.0 - share[..., None] * (255.0 - purple)
    return np.rint(rgb).astype(np.uint8)


def scanline_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return the scan-line method going down the image, one frame per group of lines.

    Panels: the image filled down to the current lines (outlined), and per line the active
    edge list's length and the spans that needed a depth comparison, as bars
    (``report.arrays``).

    Returns
    -------
    list of PIL.Image.Image
        ``ceil(height / lines)`` frames, ``lines = ceil(height / FILL_FRAMES)``.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import scanline_frames
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=24, height=20),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> len(scanline_frames(*pp.render(scene, method="scanline", explain=True)))
    20
    """
    rgb = _checked(image, report, SCAN_KEYS)
    return [_scanline_frame(rgb, report, first, stop) for first, stop in _line_groups(rgb)]


def scanline_figure(image: Any, report: Any) -> Image.Image:
    """Return the scan-line method's last frame: the whole image and every line's counts.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import scanline_figure
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=24, height=20),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> scanline_figure(*pp.render(scene, method="scanline", explain=True)).mode
    'RGB'
    """
    rgb = _checked(image, report, SCAN_KEYS)
    return _scanline_frame(rgb, report, *_line_groups(rgb)[-1])


def _line_groups(rgb: np.ndarray) -> list[tuple[int, int]]:
    """(first, stop) rows of each scan-line frame: at most FILL_FRAMES groups of lines."""
    height = rgb.shape[0]
    lines = math.ceil(height / FILL_FRAMES)
    return [(first, min(first + lines, height)) for first in range(0, height, lines)]


SCAN_KEYS = ("active edges", "spans", "spans compared by depth", "span splits")


def _scanline_frame(rgb: np.ndarray, report: Any, first: int, stop: int) -> Image.Image:
    """Draw the frame of scan lines [first, stop): the image and the bars down to ``stop``."""
    active, spans, by_depth, splits = (np.asarray(report.arrays[key]) for key in SCAN_KEYS)
    height, width = rgb.shape[:2]
    longest = max(int(active.max(initial=0)), int(spans.max(initial=0)), 1)
    board = Board(
        (height, width),
        ["image", "active edges (purple), spans (green), by depth (red)"],
        f"The scan-line method: lines {first}-{stop - 1} of {height}",
        "per line: the active edge list sorted by x, walked left to right into spans",
    )
    shown = _white((height, width))
    shown[:stop] = rgb[:stop]
    board.paste(0, shown)
    bars = board.panels[1]
    series = ((active, _light(COLOURS["edge"])), (spans, COLOURS["output"]),
              (by_depth, COLOURS["emitted"]))
    for j in range(stop):
        for counts, fill in series:
            if counts[j]:
                _bar(board, bars, j, counts[j] / longest, fill)
    for panel in board.panels:
        board.sketch.draw.rectangle(panel.box(first, stop, 0, width),
                                    outline=COLOURS["boundary"], width=2)
    board.line(f"lines {first}-{stop - 1}:")
    board.line(f"active edges {int(active[first:stop].max(initial=0))} at most")
    board.line(f"spans {int(spans[first:stop].sum())}", swatch="output")
    board.line(f"by depth {int(by_depth[first:stop].sum())}", swatch="emitted")
    board.line(f"splits {int(splits[first:stop].sum())}")
    board.skip()
    board.line(f"longest active edge list {int(active.max(initial=0))}", colour="muted")
    return board.image


def _bar(board: Board, panel: PixelPanel, row: int, share: float,
         fill: tuple[int, int, int]) -> None:
    """Draw a bar across an image row of a panel, ``share`` of the panel's width long."""
    left, top, right, bottom = panel.box(row, row + 1, 0, panel.width)
    end = left + max(1, round(share * (right - left)))
    board.sketch.draw.rectangle([left, top, end, bottom], fill=fill)


def _light(colour: tuple[int, int, int]) -> tuple[int, int, int]:
    return tuple((c + 255) // 2 for c in colour)


# Warnock's area subdivision.


def warnock_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return Warnock's subdivision level by level, one frame per level.

    Left: the image where it has been decided so far (the rest faint). Right: every area
    decided so far filled with the colour of how it was decided (:data:`DECISION_COLOURS`),
    its outline drawn, and the areas of this level that are cut in four outlined in orange
    with their cut lines.

    Returns
    -------
    list of PIL.Image.Image
        One frame per level (``len(report.arrays["levels"])``).

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import warnock_frames
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> image, report = pp.render(scene, method="warnock", explain=True)
    >>> len(warnock_frames(image, report)) == report.summary["levels"]
    True
    """
    rgb = _checked(image, report, WARNOCK_KEYS)
    levels = len(report.arrays["levels"])
    return [_warnock_frame(rgb, report, level) for level in range(levels)]


def warnock_figure(image: Any, report: Any) -> Image.Image:
    """Return the finished subdivision: the last frame of :func:`warnock_frames`.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import warnock_figure
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((3, 3, 3))])
    >>> warnock_figure(*pp.render(scene, method="warnock", explain=True)).mode
    'RGB'
    """
    rgb = _checked(image, report, WARNOCK_KEYS)
    return _warnock_frame(rgb, report, len(report.arrays["levels"]) - 1)


def _warnock_frame(rgb: np.ndarray, report: Any, level: int) -> Image.Image:
    from pixelpath.hsr.warnock import DECISIONS

    level_map = np.asarray(report.arrays["level"])
    decision_map = np.asarray(report.arrays["decision"])
    areas = np.asarray(report.arrays["areas"])
    counts = np.asarray(report.arrays["levels"])
    levels = len(counts)
    decided = (level_map >= 0) & (level_map <= level)
    board = Board(
        rgb.shape[:2], ["decided so far", "areas, by how they were decided"],
        f"Warnock's area subdivision: level {level + 1} of {levels}",
        f"{int(counts[level, 0])} areas examined at this level; the undecided ones are cut "
        "in four",
    )
    faint = np.full_like(rgb, COLOURS["faint"])
    board.paste(0, np.where(decided[..., None], rgb, faint))
    colours = _palette(DECISION_COLOURS)
    board.paste(1, np.where(decided[..., None], colours[np.maximum(decision_map, 0)],
                            faint))
    panel = board.panels[1]
    for row_level, decision, y0, y1, x0, x1 in areas[areas[:, 0] <= level]:
        if decision == 3 and row_level == level:
            board.sketch.draw.rectangle(panel.box(y0, y1, x0, x1),
                                        outline=COLOURS["boundary"], width=2)
            _cut_lines(board, panel, y0, y1, x0, x1)
        elif decision != 3 and min(x1 - x0, y1 - y0) * board.scale >= 8:
            board.sketch.draw.rectangle(panel.box(y0, y1, x0, x1), outline=COLOURS["area edge"])
    columns = dict(zip(("areas", *DECISIONS), counts[level, :-1], strict=True))
    board.line(f"level {level + 1}: {int(columns['areas'])} areas")
    for code, name in enumerate(DECISIONS):
        label = "cut in four" if name == "subdivided" else name
        board.line(f"{label}: {int(columns[name])}", swatch=DECISION_COLOURS[code])
    board.line(f"polygons classified: {int(counts[level, -1])}")
    board.skip()
    totals = counts.sum(axis=0)
    board.line(f"all levels: {int(totals[0])} areas", colour="muted")
    return board.image


def _cut_lines(board: Board, panel: PixelPanel, y0: int, y1: int, x0: int, x1: int) -> None:
    """Draw where a subdivided area is cut (the first half takes the odd pixel)."""
    x_mid = x0 + (x1 - x0 + 1) // 2 if x1 - x0 > 1 else x1
    y_mid = y0 + (y1 - y0 + 1) // 2 if y1 - y0 > 1 else y1
    left, top, right, bottom = panel.box(y0, y1, x0, x1)
    if x_mid < x1:
        x = panel.left + panel.scale * x_mid
        board.sketch.draw.line([(x, top), (x, bottom)], fill=COLOURS["boundary"])
    if y_mid < y1:
        y = panel.top + panel.scale * y_mid
        board.sketch.draw.line([(left, y), (right, y)], fill=COLOURS["boundary"])


# The painter's and the BSP tree's drawing order.


def order_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return the drawing order of the painter's (or BSP) method, polygon by polygon.

    Frame ``k`` shows the first ``k`` polygons painted (or ``k`` groups of them when there are
    more than :data:`ORDER_FRAMES`), each filled with its object's colour
    (:data:`OBJECT_COLOURS`), the ones of this frame outlined in red and pieces made by
    splitting outlined in magenta; beside it the rendered image with the same polygons
    outlined.

    Returns
    -------
    list of PIL.Image.Image
        ``ceil(n / group)`` frames for ``n`` polygons painted, ``group = ceil(n /
        ORDER_FRAMES)``.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import order_frames
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> len(order_frames(*pp.render(scene, method="painter", explain=True)))  # 3 faces
    6
    """
    rgb = _checked(image, report, ORDER_KEYS)
    order = np.asarray(report.arrays["order"])
    return [_order_board(rgb, report, order, first, stop).image
            for first, stop in _order_groups(np.arange(1, len(order) + 1))]


def order_figure(image: Any, report: Any) -> Image.Image:
    """Return every polygon painted, the pieces made by splitting outlined in magenta.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import order_figure
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> order_figure(*pp.render(scene, method="painter", explain=True)).mode
    'RGB'
    """
    rgb = _checked(image, report, ORDER_KEYS)
    order = np.asarray(report.arrays["order"])
    return _order_board(rgb, report, order, len(order) - 1, len(order)).image


ORDER_KEYS = ("order", "triangles", "object", "split")
WARNOCK_KEYS = ("levels", "level", "decision", "areas")
OCTREE_KEYS = ("cell footprint", "cell level", "cell is leaf", "cell outcome")
BSP_KEYS = (*ORDER_KEYS, "node", "children", "eye in front")


def _order_groups(ends: np.ndarray) -> list[tuple[int, int]]:
    """(first, stop) in the drawing order of each frame, at most ORDER_FRAMES of them.

    ``ends`` lists where each step of the drawing ends (a polygon, or a BSP node's polygons);
    a frame holds ``ceil(len(ends) / ORDER_FRAMES)`` steps, the last frame the last ones.
    """
    group = max(1, math.ceil(len(ends) / ORDER_FRAMES))
    spans = []
    for k in range(group - 1, len(ends) + group - 1, group):
        k = min(k, len(ends) - 1)
        spans.append((int(ends[k - group]) if k >= group else 0, int(ends[k])))
    return spans


def _order_board(rgb: np.ndarray, report: Any, order: np.ndarray, first: int, stop: int,
                 diagram: bool = False) -> Board:
    """Draw polygons [0, stop) of the order, those from ``first`` on outlined in red."""
    name = "The BSP tree" if report.method == "bsp" else "The painter's algorithm"
    first = max(first, 0)
    what = (f"polygon {stop} of {len(order)}" if stop - first == 1
            else f"polygons {first + 1}-{stop} of {len(order)}")
    captions = ["painted so far, back to front", "the image"]
    if diagram:
        captions = ["the tree (numbers: drawing order)", *captions]
    board = Board(rgb.shape[:2], captions, f"{name}: {what}",
                   "no depth test: each polygon is painted over the ones before it")
    painted, view = board.canvas()
    picture, _ = board.canvas(rgb)
    triangles = np.asarray(report.arrays["triangles"])
    objects = np.asarray(report.arrays["object"])
    split = np.asarray(report.arrays["split"])
    edges = len(order) <= OUTLINED
    for t in order[:stop]:
        colour = OBJECT_COLOURS[int(objects[t]) % len(OBJECT_COLOURS)]
        painted.draw.polygon(view.xy(triangles[t]), fill=COLOURS[colour],
                             outline=COLOURS["area edge"] if edges else None)
    for t in order[:stop]:
        if split[t] and edges:
            painted.outline(view, triangles[t], "contact", width=2)
    for t in order[first:stop]:
        for sketch in (painted, picture):
            sketch.outline(view, triangles[t], "emitted", width=2)
    board.place(len(captions) - 2, painted.image)
    board.place(len(captions) - 1, picture.image)
    current = order[stop - 1]
    board.line(f"{what}:")
    board.line(f"object {int(objects[current])}",
               swatch=OBJECT_COLOURS[int(objects[current]) % len(OBJECT_COLOURS)])
    if split[current]:
        board.line("a piece made by splitting", colour="contact")
    board.skip()
    board.line(f"pieces made by splitting: {int(split[order].sum())}", swatch="contact")
    for key in ("comparisons", "moves (Q painted before P)", "splits", "nodes",
                "triangles split", "depth"):
        if key in report.summary:
            board.line(f"{key}: {report.summary[key]}", colour="muted")
    return board


def bsp_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return the BSP tree's drawing order node by node, the tree diagram beside it.

    Frame ``k`` shows the polygons of the first ``k`` nodes painted (or ``k`` groups of nodes
    when more than :data:`ORDER_FRAMES` nodes paint something), the current node ringed in
    red in the diagram.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import bsp_frames
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> len(bsp_frames(*pp.render(scene, method="bsp", explain=True)))  # 3 faces, 3 nodes
    3
    """
    rgb = _checked(image, report, BSP_KEYS)
    order = np.asarray(report.arrays["order"])
    nodes = np.asarray(report.arrays["node"])[order]
    # Where each node's polygons end in the order (a node's polygons are painted together).
    ends = np.flatnonzero(np.r_[nodes[1:] != nodes[:-1], True]) + 1
    return [_bsp_board(rgb, report, order, first, stop).image
            for first, stop in _order_groups(ends)]


def bsp_figure(image: Any, report: Any) -> Image.Image:
    """Return the BSP tree as a diagram beside the finished drawing order.

    Each node of the diagram is numbered by when its polygons are painted (1 first, "-" for
    a node with nothing in view); the edge to the child on the far side of the node's plane
    from the eye, which is drawn first, is orange.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import bsp_figure
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> bsp_figure(*pp.render(scene, method="bsp", explain=True)).mode
    'RGB'
    """
    rgb = _checked(image, report, BSP_KEYS)
    order = np.asarray(report.arrays["order"])
    return _bsp_board(rgb, report, order, max(len(order) - 1, 0), len(order)).image


def _bsp_board(rgb: np.ndarray, report: Any, order: np.ndarray, first: int,
               stop: int) -> Board:
    board = _order_board(rgb, report, order, first, stop, diagram=True)
    nodes = np.asarray(report.arrays["node"])
    current = set(nodes[order[first:stop]].tolist())
    _diagram(board, board.panels[0], report, order, current)
    return board


def _diagram(board: Board, panel: PixelPanel, report: Any, order: np.ndarray,
             current: set[int]) -> None:
    """Draw the top levels of the tree: node numbers by drawing order, far sides in orange."""
    children = np.asarray(report.arrays["children"])
    front = np.asarray(report.arrays["eye in front"])
    nodes = np.asarray(report.arrays["node"])[order]
    rank = {}
    for node in nodes.tolist():
        rank.setdefault(node, len(rank) + 1)
    if len(children) == 0:
        return
    root = int(np.setdiff1d(np.arange(len(children)), children[children >= 0])[0])
    depth, spots = _layout(children, root)
    size = (panel.width * panel.scale, panel.height * panel.scale)
    board.sketch.draw.rectangle([panel.left, panel.top, panel.left + size[0] - 1,
                                 panel.top + size[1] - 1], outline=COLOURS["faint"])
    columns = max(spots.values()) + 1
    step_y = (size[1] - 24) / max(depth, 1)

    def centre(node: int, level: int) -> tuple[float, float]:
        return (panel.left + (spots[node] + 0.5) * size[0] / columns,
                panel.top + 12 + level * step_y)

    levels = {root: 0}
    stack = [root]
    while stack:
        node = stack.pop()
        x, y = centre(node, levels[node])
        far = 0 if front[node] else 1  # the child drawn first: behind the plane if eye in front
        for side in (0, 1):
            child = int(children[node, side])
            if child < 0:
                continue
            if child not in spots:
                board.sketch.text(x - 4 + (12 if side else -12), y + 10, "...", colour="muted")
                continue
            levels[child] = levels[node] + 1
            cx, cy = centre(child, levels[child])
            colour = "boundary" if side == far else "muted"
            board.sketch.draw.line([(x, y), (cx, cy)], fill=COLOURS[colour], width=2)
            stack.append(child)
    radius = max(4, min(10, int(size[0] / columns / 2) - 1, int(step_y / 2) - 1))
    for node, level in levels.items():
        x, y = centre(node, level)
        ring = COLOURS["emitted"] if node in current else COLOURS["area edge"]
        board.sketch.draw.ellipse([x - radius, y - radius, x + radius, y + radius],
                                  fill=COLOURS["background"], outline=ring,
                                  width=3 if node in current else 1)
        label = str(rank.get(node, "-"))
        width = board.sketch.draw.textlength(label)
        if width < 2 * radius + 6:
            board.sketch.text(x - width / 2, y - 6, label, size=11)
    board.line("orange edge: the far side of the", colour="muted")
    board.line("node's plane, drawn first", colour="muted")


def _layout(children: np.ndarray, root: int) -> tuple[int, dict[int, int]]:
    """Levels shown and the column of each shown node (in-order: back child left).

    Shows the deepest top part of the tree with at most DIAGRAM_NODES nodes.
    """
    levels = [[root]]
    while True:
        below = [int(c) for node in levels[-1] for c in children[node] if c >= 0]
        if not below or sum(map(len, levels)) + len(below) > DIAGRAM_NODES:
            break
        levels.append(below)
    shown = {node for level in levels for node in level}
    spots: dict[int, int] = {}
    stack: list[tuple[int, bool]] = [(root, False)]
    while stack:  # in-order: back subtree, node, front subtree
        node, visited = stack.pop()
        if visited:
            spots[node] = len(spots)
            continue
        back, front = (int(c) for c in children[node])
        if front in shown:
            stack.append((front, False))
        stack.append((node, True))
        if back in shown:
            stack.append((back, False))
    return len(levels) - 1, spots


# The octree's cells.

# The colour of each outcome of pixelpath.hsr.octree.OUTCOMES (None: not drawn).
OUTCOME_COLOURS = (None, "muted", "boundary", "subject", "output")


def octree_frames(image: Any, report: Any) -> list[Image.Image]:
    """Return the octree's cells level by level: what the front-to-back traversal did.

    Frame ``k`` outlines the screen footprint of every cell of level ``k`` in the colour of
    what the traversal did with it (:data:`OUTCOME_COLOURS`): leaves drawn, inner cells
    entered, cells skipped because their pixels were all decided, cells culled.

    Returns
    -------
    list of PIL.Image.Image
        One frame per level of the tree (``report.summary["tree depth"] + 1``).

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import octree_frames
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> len(octree_frames(*pp.render(scene, method="octree", explain=True)))  # one leaf
    1
    """
    rgb = _checked(image, report, OCTREE_KEYS)
    levels = np.asarray(report.arrays["cell level"])
    depth = int(levels.max(initial=0))
    return [_octree_board(rgb, report, levels == level, f"level {level} of {depth}")
            for level in range(depth + 1)]


def octree_figure(image: Any, report: Any) -> Image.Image:
    """Return every cell the traversal reached, leaves and skipped cells of all levels.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.figures.hidden_surfaces import octree_figure
    >>> scene = pp.Scene(pp.Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))], [pp.PointLight((5, 5, 5))])
    >>> octree_figure(*pp.render(scene, method="octree", explain=True)).mode
    'RGB'
    """
    rgb = _checked(image, report, OCTREE_KEYS)
    outcome = np.asarray(report.arrays["cell outcome"])
    shown = np.asarray(report.arrays["cell is leaf"]) | (outcome == 2)
    return _octree_board(rgb, report, shown, "all levels")


def _octree_board(rgb: np.ndarray, report: Any, shown: np.ndarray, what: str) -> Image.Image:
    from pixelpath.hsr.octree import OUTCOMES

    footprints = np.asarray(report.arrays["cell footprint"])
    outcome = np.asarray(report.arrays["cell outcome"])
    board = Board(rgb.shape[:2], ["the image", "cells' screen footprints"],
                   f"The octree, front to back: {what}",
                   "a cell whose pixels are all decided is skipped with everything behind it")
    board.paste(0, rgb)
    cells, view = board.canvas(rgb // 4 + 191)
    width = 2 if np.count_nonzero(shown) <= 100 else 1
    # Culled first, drawn leaves last: what was drawn stays on top.
    for code in (1, 2, 3, 4):
        for node in np.flatnonzero(shown & (outcome == code)):
            x0, x1, y0, y1 = footprints[node]
            (left, top), (right, bottom) = view.xy(np.array([[x0, y0], [x1, y1]]))
            cells.draw.rectangle([left, top, max(left, right - 1), max(top, bottom - 1)],
                                 outline=COLOURS[OUTCOME_COLOURS[code]], width=width)
    board.place(1, cells.image)
    for code in (4, 3, 2, 1):
        count = int(np.count_nonzero(shown & (outcome == code)))
        board.line(f"{OUTCOMES[code]}: {count}", swatch=OUTCOME_COLOURS[code])
    board.skip()
    for key in ("nodes built", "tree depth", "pixels decided early"):
        if key in report.summary:
            board.line(f"{key}: {report.summary[key]}", colour="muted")
    return board.image
