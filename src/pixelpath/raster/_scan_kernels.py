"""Compiled scan conversion: bands of rows, depth-tested or painted, coverage, the alpha test.

Step 3 of the pipeline :mod:`pixelpath.raster._kernels` outlines: ``bin_triangles`` sorts the
set-up triangles into bands of ``BAND_ROWS`` rows; ``rasterize_bands`` scan-converts them with
the depth test (the z-buffer's visibility, kept as 1/w and a triangle index per pixel),
``paint_bands`` paints them in a given order (the painter's and the BSP methods), and
``count_coverage`` counts the triangles covering each pixel. ``cut_away_at`` is the alpha test
of a sample (``Cutouts``) and ``interpolate_values`` interpolates vertex values over what was
drawn.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._setup_kernels import (
    KEY_PLANE,
    perspective_weights,
    scanline_span,
)
from pixelpath.scene._texture_kernels import cut_away, tiny_tables

BAND_ROWS = 32


class Cutouts(NamedTuple):
    """What the alpha test of the visibility pass reads about the drawn triangles.

    Only triangles with ``masked`` set are tested (their object's material has an alpha
    cutoff its alpha can fall below: ``SurfaceTables.alpha``); the other arrays are the
    shading pass's own (see :class:`pixelpath.raster._kernels.Surfaces`).
    """

    masked: np.ndarray  # (T,) bool: the triangle's surface may be cut away
    setup: np.ndarray  # (T, SETUP_FIELDS) set-up records
    triangles: np.ndarray  # (T, 3) vertex indices
    info: np.ndarray  # (T, 2) object index, flip flag
    uv: np.ndarray  # (V, 2) texture coordinates; (0, 2) when nothing is textured
    vertex_colors: np.ndarray  # (V, 4) vertex colours; (0, 4) when no object has them
    tables: object  # SurfaceTables: textures, alpha and cutoff of each object


@njit
def bin_triangles(rows, n_bands, band_rows, row_first):
    """Return the triangles of each band of rows as CSR: offsets (n_bands + 1,), items.

    Band b holds the image rows ``row_first + b * band_rows`` onwards; items keep the order of
    ``rows`` within each band.
    """
    counts = np.zeros(n_bands + 1, dtype=np.intp)
    for t in range(rows.shape[0]):
        if rows[t, 0] < rows[t, 1]:
            first = (rows[t, 0] - row_first) // band_rows
            last = (rows[t, 1] - 1 - row_first) // band_rows
            for band in range(first, last + 1):
                counts[band + 1] += 1
    for band in range(n_bands):
        counts[band + 1] += counts[band]
    items = np.empty(counts[n_bands], dtype=np.intp)
    fill = np.empty(n_bands, dtype=np.intp)
    for band in range(n_bands):
        fill[band] = counts[band]
    for t in range(rows.shape[0]):
        if rows[t, 0] < rows[t, 1]:
            first = (rows[t, 0] - row_first) // band_rows
            last = (rows[t, 1] - 1 - row_first) // band_rows
            for band in range(first, last + 1):
                items[fill[band]] = t
                fill[band] += 1
    return counts, items


@njit(inline="always")
def _band_rows(band, band_rows, y0, height):
    """Image rows [first, stop) of band ``band`` of a region starting at row y0, height rows."""
    first = y0 + band * band_rows
    return first, min(first + band_rows, y0 + height)


@njit(from_python=False)
def _clear_band(first, stop, y0, inv_depth, triangle_id):
    """Mark rows [first, stop) of the region as empty: 1/w = 0 (infinitely far), no triangle."""
    for j in range(first - y0, stop - y0):
        for i in range(inv_depth.shape[1]):
            inv_depth[j, i] = 0.0
            triangle_id[j, i] = -1


@njit(from_python=False)
def _rasterize_band(setup, rows, offsets, items, band, band_first, band_stop, x0, top, inv_depth,
                    triangle_id, cutouts):
    """Clear band ``band`` (image rows [band_first, band_stop)), then depth-test its pixels.

    The nearest 1/w wins. The buffers (h, w) cover image columns [x0, x0 + w) and rows
    [top, top + h): the whole region's (``top`` its first row), or the band's alone (``top``
    is ``band_first``). Pixel centres are computed in image coordinates, so a region gets
    exactly the pixels of the whole image. Alpha-tested triangles (``cutouts.masked``) go
    through :func:`_draw_masked`; ``cutouts`` None (a scene without them) leaves the alpha
    test out of the compiled code.
    """
    width = inv_depth.shape[1]
    _clear_band(band_first, band_stop, top, inv_depth, triangle_id)
    for k in range(offsets[band], offsets[band + 1]):
        t = items[k]
        if cutouts is not None:  # a branch Numba prunes, with the alpha test, for None
            if cutouts.masked[t]:
                _draw_masked(t, max(rows[t, 0], band_first), min(rows[t, 1], band_stop), x0,
                             top, inv_depth, triangle_id, cutouts, True)
                continue
        record = setup[t]
        pa, pb, pc = record[KEY_PLANE], record[KEY_PLANE + 1], record[KEY_PLANE + 2]
        for j in range(max(rows[t, 0], band_first), min(rows[t, 1], band_stop)):
            y = j + 0.5
            first, stop = scanline_span(record, y, x0, x0 + width)
            row_value = pb * y + pc
            for i in range(first, stop):
                inv_w = pa * (i + 0.5) + row_value
                if inv_w > inv_depth[j - top, i - x0]:
                    inv_depth[j - top, i - x0] = inv_w
                    triangle_id[j - top, i - x0] = t


@njit(from_python=False)
def _draw_masked(t, row_first, row_stop, x0, y0, inv_depth, triangle_id, cutouts, depth_test):
    """Draw alpha-tested triangle t on image rows [row_first, row_stop), skipping its holes.

    As the z-buffer's loop (``depth_test``: a sample must be nearer than what is there) or the
    painter's (it paints over), but only where the alpha test does not cut the sample away
    (:func:`cut_away_at`): what lies behind shows through.
    """
    width = inv_depth.shape[1]
    record = cutouts.setup[t]
    pa, pb, pc = record[KEY_PLANE], record[KEY_PLANE + 1], record[KEY_PLANE + 2]
    for j in range(row_first, row_stop):
        y = j + 0.5
        first, stop = scanline_span(record, y, x0, x0 + width)
        row_value = pb * y + pc
        for i in range(first, stop):
            inv_w = pa * (i + 0.5) + row_value
            nearer = not depth_test or inv_w > inv_depth[j - y0, i - x0]
            if nearer and not cut_away_at(cutouts, t, i + 0.5, y):
                inv_depth[j - y0, i - x0] = inv_w
                triangle_id[j - y0, i - x0] = t


@njit
def rasterize_bands(bands, setup, rows, offsets, items, band_rows, x0, y0, inv_depth,
                    triangle_id, cutouts):
    """Depth-test the triangles' pixels in the listed bands, keeping the nearest (largest 1/w).

    Each band first clears its rows of ``inv_depth`` (h, w) to 0 (infinitely far) and of
    ``triangle_id`` (h, w) to -1 (nothing), so the buffers may hold anything on entry.
    ``cutouts`` (:class:`Cutouts`) says which triangles are alpha-tested, and how.
    """
    for k in range(bands.shape[0]):
        band = bands[k]
        first, stop = _band_rows(band, band_rows, y0, inv_depth.shape[0])
        _rasterize_band(
            setup, rows, offsets, items, band, first, stop, x0, y0, inv_depth, triangle_id, cutouts
        )


# Inlined by Numba into its one caller, the loop over bands (see pixelpath._jit).
@njit(inline="always")
def _paint_band(setup, rows, offsets, items, order, band, band_rows, x0, y0, inv_depth,
                triangle_id, cutouts):
    """Clear one band, then draw ``order``'s triangles over each other, later ones on top.

    No depth test: the painter's and BSP methods list the triangles back to front. The 1/w of
    the triangle drawn last is kept, so the visible surface's depth is known. An alpha-tested
    triangle paints only the pixels its alpha test keeps (:func:`_draw_masked`).
    """
    height, width = inv_depth.shape
    band_first, band_stop = _band_rows(band, band_rows, y0, height)
    _clear_band(band_first, band_stop, y0, inv_depth, triangle_id)
    masked = cutouts.masked
    for k in range(offsets[band], offsets[band + 1]):
        t = order[items[k]]
        if masked[t]:
            _draw_masked(t, max(rows[t, 0], band_first), min(rows[t, 1], band_stop), x0, y0,
                         inv_depth, triangle_id, cutouts, False)
            continue
        record = setup[t]
        pa, pb, pc = record[KEY_PLANE], record[KEY_PLANE + 1], record[KEY_PLANE + 2]
        for j in range(max(rows[t, 0], band_first), min(rows[t, 1], band_stop)):
            y = j + 0.5
            first, stop = scanline_span(record, y, x0, x0 + width)
            row_value = pb * y + pc
            for i in range(first, stop):
                inv_depth[j - y0, i - x0] = pa * (i + 0.5) + row_value
                triangle_id[j - y0, i - x0] = t


@njit
def paint_bands(bands, setup, rows, offsets, items, order, band_rows, x0, y0, inv_depth,
                triangle_id, cutouts):
    """Draw the triangles ``order[items[...]]`` of each listed band in list order (painter's).

    ``offsets``/``items`` bin the positions of ``order`` (not triangle indices) per band;
    ``cutouts`` (:class:`Cutouts`) says which triangles are alpha-tested.
    """
    for k in range(bands.shape[0]):
        band = bands[k]
        _paint_band(
            setup, rows, offsets, items, order, band, band_rows, x0, y0, inv_depth, triangle_id,
            cutouts,
        )


@njit
def count_coverage(setup, rows, x0, y0, counts):
    """Add 1 to counts (h, w) for every pixel each triangle draws (fill-rule and overdraw)."""
    width = counts.shape[1]
    for t in range(rows.shape[0]):
        for j in range(rows[t, 0], rows[t, 1]):
            first, stop = scanline_span(setup[t], j + 0.5, x0, x0 + width)
            for i in range(first, stop):
                counts[j - y0, i - x0] += 1


@njit(refcount=False, from_python=False)
def cut_away_at(cutouts, t, x, y):
    """Whether triangle t's surface is cut away by its alpha test at pixel centre (x, y).

    The alpha is taken at the perspective-correct weights the shading pass uses there
    (:func:`pixelpath.scene._texture_kernels.cut_away`). Ask only for triangles with
    ``cutouts.masked`` set; compiled without reference counting, like the lookups.
    """
    b0, b1, b2 = perspective_weights(cutouts.setup, t, x, y)
    triangles = cutouts.triangles
    return cut_away(cutouts.tables, cutouts.info[t, 0], cutouts.uv, cutouts.vertex_colors,
                    triangles[t, 0], triangles[t, 1], triangles[t, 2], b0, b1, b2)


@njit
def interpolate_values(first, stop, setup, triangles, values, triangle_id, out):
    """Interpolate per-vertex values (V, C) over the drawn pixels of rows [first, stop)."""
    width = triangle_id.shape[1]
    for j in range(first, stop):
        for i in range(width):
            t = triangle_id[j, i]
            if t < 0:
                continue
            b0, b1, b2 = perspective_weights(setup, t, i + 0.5, j + 0.5)
            a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
            for channel in range(values.shape[1]):
                out[j, i, channel] = (
                    b0 * values[a, channel] + b1 * values[b, channel] + b2 * values[c, channel]
                )


def opaque_cutouts(setup, triangles):
    """Return a :class:`Cutouts` that tests no triangle: for triangles with no material.

    Typed as a render's, so the kernels are compiled once for both.
    """
    from pixelpath.scene.texture import surface_tables

    count = triangles.shape[0]
    return Cutouts(
        np.zeros(count, dtype=np.bool_), setup, triangles, np.zeros((count, 2), dtype=np.intp),
        np.empty((0, 2)), np.empty((0, 4)), surface_tables([]),
    )


def tiny_cutouts(setup, triangles):
    """Return a :class:`Cutouts` for warm-ups: every triangle alpha-tested, typed as in renders.

    ``triangles`` are indices into three vertices with texture coordinates and colours.
    """
    return Cutouts(
        np.ones(triangles.shape[0], dtype=np.bool_), setup, triangles,
        np.zeros((triangles.shape[0], 2), dtype=np.intp), np.zeros((3, 2)), np.ones((3, 4)),
        tiny_tables(),
    )
