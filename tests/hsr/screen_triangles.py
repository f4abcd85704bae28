"""Triangles given directly in screen space, set up as the front end would, for hand cases.

A vertex is (x, y, 1/w) in pixels (pixel (i, j) has its centre at (i + 0.5, j + 0.5)), so a
test can place edges and depths exactly where its hand derivation needs them, then run a
method's kernels and the z-buffer's on the same set-up records.
"""

from __future__ import annotations

import types

import numpy as np

from pixelpath.hsr import pipeline
from pixelpath.raster import _scan_kernels, _setup_kernels
from pixelpath.renderer import View
from pixelpath.scene import Camera, Sphere
from pixelpath.scene.texture import surface_tables


def view_of(size=(16, 16), region=None) -> View:
    """A View of a ``size`` (width, height) image, or of its ``region`` (x0, y0, x1, y1)."""
    camera = Camera(eye=(0, 0, 5), target=(0, 0, 0), width=size[0], height=size[1])
    if region is None:
        return View.whole(camera)
    x0, y0, x1, y1 = region
    return View(camera, x0, y0, x1 - x0, y1 - y0)


def set_up(triangles, view: View):
    """Set up screen triangles [[(x, y, 1/w)] * 3, ...] for the view's region.

    Returns an object with ``setup`` and ``rows`` (clipped to the region's rows), as
    :class:`pixelpath.hsr.pipeline.Prepared` has them, and what the alpha test reads (all the
    triangles belong to one opaque object: none is alpha-tested).
    """
    screen = np.asarray(triangles, dtype=np.float64).reshape(-1, 3)
    indices = np.arange(len(screen), dtype=np.intp).reshape(-1, 3)
    setup = np.zeros((len(indices), _setup_kernels.SETUP_FIELDS))
    rows = np.zeros((len(indices), 2), dtype=np.intp)
    _setup_kernels.setup_triangles(screen, indices, False, view.y0, view.y0 + view.height, setup,
                                   rows)
    return types.SimpleNamespace(
        setup=setup, rows=rows, triangles=indices, info=np.zeros((len(indices), 2), np.intp),
        uv=np.empty((0, 2)), vertex_colors=np.empty((0, 4)),
        geometry=types.SimpleNamespace(surfaces=surface_tables([Sphere((0, 0, 0), 1.0)])),
    )


def zbuffer(prepared, view: View) -> pipeline.Visibility:
    """The z-buffer's (1/w, triangle) buffers for the view's region: the reference."""
    offsets, items = pipeline.binned(prepared, view)
    inv_depth = np.empty((view.height, view.width))
    triangle_id = np.empty((view.height, view.width), dtype=np.int32)
    _scan_kernels.rasterize_bands(np.arange(len(offsets) - 1), prepared.setup, prepared.rows,
                                  offsets, items, _scan_kernels.BAND_ROWS, view.x0, view.y0,
                                  inv_depth, triangle_id, pipeline.cutouts(prepared))
    return pipeline.Visibility(inv_depth, triangle_id)
