"""The depth-buffer (z-buffer) method, an image-space method (SPEC §9 errata).

For every pixel keep the nearest surface seen so far: a new sample replaces the stored one when
it is nearer (the notes' "Z_new < Z_buffer → update") and, for an alpha-tested material, when
its alpha test keeps it (a sample cut away replaces nothing). Here the buffer holds 1/w, w
being the distance along the viewing axis, because 1/w is affine in screen space (exactly
interpolated) and larger means nearer; ``Image.depth`` reports w itself. Ties keep the earlier
triangle, so the picture does not depend on the order of threads.

The front end and the shading pass are the shared ones of :mod:`pixelpath.hsr.pipeline`. The
z-buffer runs them band by band: each band of 32 rows is scan-converted with the depth test
and shaded at once, while its buffers are still in the processor's cache.

Memory: 12 bytes per pixel of one band for each thread's buffers (1/w and triangle) besides
the image, whatever the scene (of the whole region with ``explain``, whose report reads them);
time grows with the pixels the triangles cover (their *depth complexity*).
"""

from __future__ import annotations

import numpy as np

from pixelpath._threads import in_runs
from pixelpath.contract import Frame, RenderOptions, View
from pixelpath.hsr import pipeline
from pixelpath.scene import Scene

__all__ = ["STEPS", "render_frame"]

STEPS = pipeline.FRONT_STEPS + pipeline.SHADE_SLICES


def render_frame(scene: Scene, view: View, options: RenderOptions) -> Frame:
    """Render ``view`` of ``scene`` with the z-buffer method.

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
        With ``options.explain``, its report counts the depth tests; ``report.arrays["depth
        tests"]`` holds, per pixel of the region, how many triangles were tested there (its
        depth complexity).

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, PointLight, Scene
    >>> from pixelpath.contract import RenderOptions, View
    >>> from pixelpath.hsr.zbuffer import render_frame
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0), width=32, height=24),
    ...               objects=[Box((-1, -1, -1), (1, 1, 1))], lights=[PointLight((5, 5, 5))])
    >>> frame = render_frame(scene, View.whole(scene.camera), RenderOptions())
    >>> frame.rgb.shape, int(frame.object_id[12, 16])
    ((24, 32, 3), 0)
    """
    from pixelpath.raster import _kernels, _scan_kernels

    prepared = pipeline.prepare(scene, view, options)
    # The region's visibility is kept only for the report; otherwise each thread reuses one
    # band's buffers, which stay in cache.
    visibility = pipeline.visibility_buffers(view) if options.explain else None
    offsets, items = pipeline.binned(prepared, view)
    out = pipeline.output_buffers(view)
    surfaces = pipeline.surfaces(prepared, scene, view)
    cutouts = colour_tables = None  # a plain scene: the passes compiled without lookups
    if _kernels.looks_up(surfaces):
        cutouts, colour_tables = pipeline.cutouts(prepared), surfaces.tables
    _, order = pipeline.bands(view)
    runs = pipeline.slices(view)
    def render_run(run: np.ndarray) -> None:
        buffers = visibility or pipeline.band_buffers(view.width)
        _kernels.render_bands(
            run, prepared.setup, prepared.rows, offsets, items, _scan_kernels.BAND_ROWS, view.x0,
            view.y0, *buffers, cutouts, surfaces, colour_tables,
            pipeline.shading_batch(view.width), out,
        )

    for start, stop in runs:
        in_runs(render_run, order[start:stop])
        options.progress(pipeline.SHADE_SLICES // len(runs))
    report = None
    if options.explain:
        report = pipeline.with_texture_lookups(
            _report(prepared, view, visibility), prepared, scene, view, visibility
        )
    return Frame(out.rgb, out.depth, out.object_id, prepared.stats, report, out.normal)


def _report(prepared: pipeline.Prepared, view: View, visibility: pipeline.Visibility):
    """Count the depth tests: every pixel each triangle covers is one comparison."""
    from pixelpath.raster import _scan_kernels
    from pixelpath.raster.transform import depth_key_name
    from pixelpath.report import Report

    tests = np.zeros((view.height, view.width), dtype=np.int32)
    _scan_kernels.count_coverage(prepared.setup, prepared.rows, view.x0, view.y0, tests)
    drawn = int(np.count_nonzero(visibility.triangle_id >= 0))
    total = int(tests.sum())
    return Report(
        method="zbuffer",
        summary={
            **prepared.stats,
            "depth tests (pixels covered by some triangle)": total,
            "pixels drawn": drawn,
            "samples hidden by a nearer one": total - drawn,
            "largest depth complexity": int(tests.max(initial=0)),
        },
        notes=(
            "image space: every pixel of every triangle is compared with the buffer's "
            f"{depth_key_name(view.camera)} and replaces it when nearer",
        ),
        arrays={"depth tests": tests},
    )
