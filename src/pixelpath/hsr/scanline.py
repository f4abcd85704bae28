"""The polygon scan-line method, an image-space method (SPEC §9 errata).

The image is processed one scan line (row of pixel centres) at a time, with the notes' data
structures:

* an **edge table**: every non-horizontal edge of every triangle, bucketed by the first scan line
  it crosses;
* an **active edge list** (AEL): the edges crossing the current scan line, sorted by x. Going
  down one line, edges whose lower end was passed leave, the line's bucket enters and the
  others move by their slope; the order barely changes (edge coherence), so re-sorting is
  cheap;
* per line, the crossings are walked left to right, each switching its polygon "in" or "out",
  which cuts the line into **spans** covered by a fixed set of polygons. A span covered by one
  polygon is drawn with no depth computed. Over a span covered by several, 1/w of each is
  linear, so the polygon nearest at both ends of the span is nearest all along it; when the
  ends disagree the polygons interpenetrate there, and the span is split where the two planes
  cross and each part is decided the same way. A span covered by an alpha-tested polygon
  (``Material.alpha_cutoff``) is decided pixel by pixel, since its holes are where its
  texture says, not where its edges are.

Crossings follow the same top-left fill rule as the z-buffer's scan converter, and depth ties
go to the lower triangle like the z-buffer's, so the two methods agree pixel for pixel (also on
meshes: no cracks, no pixel drawn twice). Bands of 32 lines are scanned in parallel, each
building its own active edge list at its first line.

Cost: per line, the active edges (sorting them is nearly linear thanks to coherence) plus the
spans; depth is only evaluated at span ends, so a large polygon in front costs nothing per
pixel beyond writing it. Memory: the edge table of one band per thread, plus the visibility
buffers the shading pass reads.

Examples
--------
>>> import pixelpath as pp
>>> scene = pp.Scene(pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=40, height=30),
...                  objects=[pp.Sphere((0, 0, 0), 1.0)], lights=[pp.PointLight((3, 3, 3))])
>>> image, report = pp.render(scene, method="scanline", explain=True)
>>> int(image.object_id[15, 20]), report.arrays["spans"].shape
(0, (30,))
"""

from __future__ import annotations

import math

import numpy as np

from pixelpath._threads import in_runs
from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Scene

__all__ = ["LINE_COUNTS", "STEPS", "render_frame"]

STEPS = pipeline.FRONT_STEPS + 1 + pipeline.SHADE_SLICES
# The per-line table prints about this many lines (every k-th); the report's arrays hold all.
PRINTED_LINES = 24

# What the report counts on each scan line (the keys of ``Report.arrays`` besides "row").
LINE_COUNTS = (
    "active edges",
    "edges entering",
    "edges leaving",
    "sort moves",
    "crossings",
    "spans",
    "spans without depth",
    "spans compared by depth",
    "span splits",
    "pixels compared one by one",
)
# The printed table's columns (short headers, so that it fits a terminal) and their counts;
# the AEL's entering, leaving and sort moves are in the summary and the arrays.
TABLE_COLUMNS = {
    "edges": "active edges",
    "crossings": "crossings",
    "spans": "spans",
    "one polygon": "spans without depth",
    "by depth": "spans compared by depth",
    "splits": "span splits",
    "pixel tests": "pixels compared one by one",
}


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Render ``view`` of ``scene`` with the scan-line method.

    Parameters
    ----------
    scene : Scene
        What to draw.
    view : View
        Camera and region to render.
    options : RenderOptions
        Shading, culling, Blinn-Phong, progress, explain.

    Returns
    -------
    Frame
        With ``options.explain``, its report counts per scan line (``LINE_COUNTS``): the table
        prints every k-th line and the totals; ``report.arrays`` holds every line's counts as
        arrays indexed by the region's rows (``report.arrays["row"]`` gives the image row).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.scanline import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    prepared = pipeline.prepare(scene, view, options)
    visibility, counts = _scan(prepared, view)
    options.progress(1)
    report = _report(prepared, view, visibility, counts) if options.explain else None
    return pipeline.shade(prepared, scene, view, visibility, options, report)


def _scan(prepared: pipeline.Prepared, view: View) -> tuple[pipeline.Visibility, np.ndarray]:
    """Decide visibility over the region; return it and the counts per scan line (h, 10)."""
    from pixelpath.hsr._kernels import scanline as kernels
    from pixelpath.raster import _scan_kernels

    visibility = pipeline.visibility_buffers(view)
    offsets, items = pipeline.binned(prepared, view)
    _, order = pipeline.bands(view)
    counts = np.zeros((view.height, len(LINE_COUNTS)), dtype=np.intp)
    cutouts = pipeline.cutouts(prepared)

    def scan(run: np.ndarray) -> None:
        kernels.scan_bands(
            run, prepared.setup, prepared.rows, offsets, items, _scan_kernels.BAND_ROWS, view.x0,
            view.y0, *visibility, counts, cutouts,
        )

    in_runs(scan, order)
    return visibility, counts


def _report(prepared: pipeline.Prepared, view: View, visibility: pipeline.Visibility,
            counts: np.ndarray):
    """Totals, a table of every k-th scan line, and every line's counts as arrays."""
    from pixelpath.raster.transform import depth_key_name
    from pixelpath.report import Report, Table

    key = depth_key_name(view.camera)
    totals = counts.sum(axis=0)
    image_rows = np.arange(view.y0, view.y0 + view.height)
    step = max(1, math.ceil(view.height / PRINTED_LINES))
    shown = range(0, view.height, step)
    columns = [LINE_COUNTS.index(name) for name in TABLE_COLUMNS.values()]
    table = Table(
        f"scan lines (one in {step} of {view.height}, then the totals)",
        ("row", *TABLE_COLUMNS),
        [(int(image_rows[r]), *(int(counts[r, c]) for c in columns)) for r in shown]
        + [("total", *(int(totals[c]) for c in columns))],
    )
    summary = {
        **prepared.stats,
        "scan lines": view.height,
        "largest active edge list": int(counts[:, 0].max(initial=0)),
        **{name: int(total) for name, total in zip(LINE_COUNTS[1:], totals[1:], strict=True)},
        "pixels drawn": int(np.count_nonzero(visibility.triangle_id >= 0)),
    }
    arrays = {"row": image_rows}
    arrays.update({name: counts[:, k].copy() for k, name in enumerate(LINE_COUNTS)})
    return Report(
        method="scanline",
        summary=summary,
        tables=(table,),
        notes=(
            "image space: per scan line the active edge list is sorted by x and walked left to "
            "right; a span covered by one polygon needs no depth, one covered by several is "
            f"decided by {key} at its two ends and split where two polygons' planes cross",
            "per line: edges = active edges, one polygon = spans decided without depth, by "
            f"depth = spans compared by {key}, splits = spans split where planes cross, pixel "
            "tests = one-pixel pieces decided by the z-buffer's test",
            "edges entering counts each band's edge table: an edge crossing a band border "
            "enters again at the band's first line (bands of 32 lines run in parallel)",
            *(("alpha-tested polygons (alpha_cutoff) have holes their edges do not show: "
               "a span one of them covers is decided pixel by pixel (counted in pixel tests)",)
              if pipeline.cutouts(prepared).masked.any() else ()),
        ),
        arrays=arrays,
    )

