"""Warnock's area subdivision, an image-space method (SPEC §9 errata).

Start with the whole image as one area. Classify every polygon against the area:

* **surrounding**: it covers the whole area;
* **intersecting**: it covers part of the area and reaches outside it;
* **contained**: it lies entirely inside the area;
* **disjoint**: it does not reach the area.

Then decide the area at once if one of the rules applies:

1. no polygon reaches it: it shows the background;
2. exactly one polygon reaches it (contained, intersecting or surrounding): draw that polygon,
   clipped to the area;
3. a surrounding polygon is in front of every other polygon over the whole area: fill the area
   with it. Depths are planes (1/w is affine in screen space), so comparing them at the area's
   four corner pixel centres decides the whole area;

otherwise cut the area into four and repeat, down to single pixels, where the polygon nearest
at the pixel centre wins. Each area is only handed the polygons that reached its parent.

A polygon of an alpha-tested material (``Material.alpha_cutoff``) has holes its outline does
not show: it never counts as the surrounding polygon in front (rule 3), and rules 2 and 4 draw
it only where its alpha test keeps it.

"Covers" means exactly what the scan converter draws (the top-left fill rule on pixel centres),
and depth ties go to the lower triangle, as in the z-buffer, so the two agree pixel for pixel;
rule 3 only fires when the surrounding polygon is nearer by more than rounding could explain,
so near ties go on down to pixels. The subdivision runs level by level (breadth first): all
areas of a level are decided in parallel, and the report counts what happened per level.

Cost: large uniform regions (background, a polygon in front of everything behind it) are
decided in a few large areas; every visible edge must be followed down to pixel size, so the
work grows with the length of the visible edges times the polygons near them. Memory: the
areas of one level and their candidate lists.

Examples
--------
>>> import pixelpath as pp
>>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=40, height=30),
...                  objects=[pp.Sphere((0, 0, 0), 1.0)], lights=[pp.PointLight((3, 3, 3))])
>>> image, report = pp.render(scene, method="warnock", explain=True)
>>> int(image.object_id[15, 20]), report.arrays["level"].shape
(0, (30, 40))
"""

from __future__ import annotations

import functools

import numpy as np

from pixelpath._threads import in_threads
from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Scene

__all__ = ["DECISIONS", "LEVEL_COLUMNS", "STEPS", "render_frame"]

STEPS = pipeline.FRONT_STEPS + 1 + pipeline.SHADE_SLICES
# How an area can be decided; the codes 0..4 of ``report.arrays["decision"]``.
DECISIONS = (
    "empty",
    "single polygon",
    "surrounding polygon in front",
    "subdivided",
    "pixel level",
)
# Columns of the per-level counts (``report.arrays["levels"]``), and their short headers in
# the printed table.
LEVEL_COLUMNS = ("areas", *DECISIONS, "polygons tested")
TABLE_COLUMNS = ("areas", "empty", "single", "in front", "subdivided", "pixels", "tested")


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Render ``view`` of ``scene`` with Warnock's area subdivision.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera and region to render; the region is the first area.
    options : RenderOptions
        Shading, culling, Blinn-Phong, progress, explain.

    Returns
    -------
    Frame
        With ``options.explain``, its report has a row per level: the areas examined, how many
        were decided each way (``DECISIONS``) and the polygons classified. ``report.arrays``
        holds the same per level (key ``"levels"``, one row per level, ``LEVEL_COLUMNS``), and,
        per pixel of the region, the level at which it was decided (``"level"``) and how
        (``"decision"``, an index into ``DECISIONS``), and every area examined (``"areas"``,
        rows of level, decision, first and stop row, first and stop column, in pixels of the
        region).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.warnock import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    prepared = pipeline.prepare(scene, view, options)
    visibility, levels, maps = _subdivide(prepared, view, options.explain)
    options.progress(1)
    report = _report(prepared, visibility, levels, maps) if options.explain else None
    return pipeline.shade(prepared, scene, view, visibility, options, report)


def _subdivide(prepared: pipeline.Prepared, view: View, explain: bool):
    """Decide the region area by area, level by level.

    Returns the visibility, the per-level counts ((levels, len(LEVEL_COLUMNS)) ints) with the
    largest area (width, height) of each level, and, when explaining, maps of each pixel's
    level and decision (else None).
    """
    from pixelpath.hsr._kernels import warnock as kernels

    visibility = pipeline.visibility_buffers(view)
    boxes = np.empty((len(prepared.rows), 4), dtype=np.intp)
    in_threads(
        functools.partial(kernels.coverage_boxes, prepared.setup, prepared.rows, view.x0,
                          view.x0 + view.width, boxes),
        len(boxes),
    )
    candidates = np.flatnonzero(boxes[:, kernels.ROW_FIRST] < boxes[:, kernels.ROW_STOP])
    candidates = candidates.astype(np.intp)
    areas = np.array([[view.y0, view.y0 + view.height, view.x0, view.x0 + view.width]],
                     dtype=np.intp)
    offsets = np.array([0, len(candidates)], dtype=np.intp)
    shape = (view.height, view.width)
    maps = (np.full(shape, -1, np.int8), np.full(shape, -1, np.int8)) if explain else None
    counts, sizes, examined = [], [], []
    cutouts = pipeline.cutouts(prepared)
    while len(areas):
        kept = np.empty(len(candidates), dtype=np.bool_)
        decisions = np.empty(len(areas), dtype=np.int8)
        decide = functools.partial(
            kernels.decide_level, areas, offsets, candidates, prepared.setup, boxes, view.x0,
            view.y0, *visibility, cutouts, kept, decisions,
        )
        in_threads(decide, len(areas))
        tally = np.bincount(decisions, minlength=len(DECISIONS))
        counts.append((len(areas), *tally.tolist(), len(candidates)))
        sizes.append((int((areas[:, 3] - areas[:, 2]).max()),
                      int((areas[:, 1] - areas[:, 0]).max())))
        if maps is not None:
            kernels.mark_areas(areas, decisions, len(counts) - 1, view.x0, view.y0, *maps)
            examined.append(_area_rows(areas, decisions, len(counts) - 1, view))
        areas, offsets, candidates = kernels.subdivide(areas, offsets, candidates, kept,
                                                       decisions)
    counts = np.array(counts, dtype=np.intp).reshape(-1, len(LEVEL_COLUMNS))
    if maps is not None:
        maps = (*maps, np.concatenate(examined) if examined else np.empty((0, 6), np.intp))
    return visibility, (counts, sizes), maps


def _area_rows(areas: np.ndarray, decisions: np.ndarray, level: int, view: View) -> np.ndarray:
    """Rows (level, decision, first row, stop row, first column, stop column) of one level.

    Rows and columns count from the region's top-left pixel.
    """
    rows = np.empty((len(areas), 6), dtype=np.intp)
    rows[:, 0] = level
    rows[:, 1] = decisions
    rows[:, 2:4] = areas[:, 0:2] - view.y0
    rows[:, 4:6] = areas[:, 2:4] - view.x0
    return rows


def _report(prepared: pipeline.Prepared, visibility: pipeline.Visibility, levels, maps):
    """Totals, the table of levels, and the per-level and per-pixel arrays."""
    from pixelpath.report import Report, Table

    counts, sizes = levels
    totals = counts.sum(axis=0)
    rows = [
        (level, f"{width}x{height}", *(int(v) for v in counts[level]))
        for level, (width, height) in enumerate(sizes)
    ]
    table = Table(
        "subdivision levels (largest area of each level; areas decided each way)",
        ("level", "area size", *TABLE_COLUMNS),
        [*rows, ("total", "", *(int(v) for v in totals))],
    )
    summary = {
        **prepared.stats,
        "levels": len(counts),
        **{
            ("areas examined" if name == "areas" else name): int(total)
            for name, total in zip(LEVEL_COLUMNS, totals, strict=True)
        },
        "pixels drawn": int(np.count_nonzero(visibility.triangle_id >= 0)),
    }
    return Report(
        method="warnock",
        summary=summary,
        tables=(table,),
        notes=(
            "image space: an area is decided whole when no polygon reaches it, when one does, "
            "or when a polygon surrounding it is nearer than all others at its four corners; "
            "otherwise it is cut in four, down to pixels",
            "per level: areas examined; decided empty, by a single polygon, by a surrounding "
            "polygon in front, subdivided, or at pixel level; polygons classified (tested)",
            *(("alpha-tested polygons (alpha_cutoff) have holes their outline does not show: "
               "they are never the surrounding polygon in front, and are drawn only where "
               "their alpha test keeps each pixel",)
              if pipeline.cutouts(prepared).masked.any() else ()),
        ),
        arrays={"levels": counts, "level": maps[0], "decision": maps[1], "areas": maps[2]},
    )
