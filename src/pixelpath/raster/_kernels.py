"""Compiled raster shading, the z-buffer's fused pass, and the warm-ups of the raster kernels.

The pipeline the raster kernels implement (driven by :mod:`pixelpath.hsr.zbuffer`): steps 1
and 2 are :mod:`pixelpath.raster._setup_kernels`', step 3 :mod:`pixelpath.raster._scan_kernels`'
and step 4, with the shading pass the other methods run (``shade_bands``), this module's.

1. ``clip_to_screen``: perspective divide and viewport. Pixel (i, j) has its centre at
   (i + 0.5, j + 0.5); row 0 is the top, so ``y_screen = (1 - y_ndc) * H / 2``. The third
   screen coordinate is the *depth key*: affine in screen space, positive in the view volume
   and larger where nearer. For a perspective camera it is 1/w (w = the view-axis depth); for
   an orthographic one, whose clip w is 1, it is ``(3 - z_ndc) / 2``, in [1, 2] from the far
   plane to the near one (:func:`key_depth` turns it back into a depth). Every method orders
   surfaces by the key alone, so both projections share one code path.
2. ``setup_triangles``: per triangle, its vertices sorted by y (the *edge table*: the edges
   sorted by their upper end), the affine planes of the screen-space barycentric weights and of
   the depth key, the vertices' 1/w (all 1 when orthographic: attributes are then interpolated
   affinely) and the rows it covers. Zero-area and non-finite triangles cover no row.
3. ``rasterize_bands``: scan conversion with an *active edge list*. On scan line y (a row of
   pixel centres) the active edges are the two edges whose half-open y-range [top, bottom)
   contains y; their x at y bounds the span, and pixels with ``x_left <= x_centre < x_right``
   are drawn. This is the top-left fill rule: a pixel centre on an edge shared by two triangles
   belongs to exactly one of them (the one the edge bounds on the left; for a horizontal edge,
   the one below it), so adjacent triangles leave no cracks and draw no pixel twice. The x of
   an edge is always computed from its upper end to its lower end, so both triangles sharing it
   get bit-identical spans. The image is cut into bands of rows run in parallel; each band
   visits its triangles in ascending order and keeps a sample only when it is strictly nearer,
   so ties go to the lower triangle index whatever the thread count (deterministic output).
4. ``render_bands``: the same, then, while the band is still in cache, shading once per visible
   pixel (deferred): the depth test stored only (key, triangle) per pixel; shading uses the
   perspective-correct barycentric weights ``b_i = (s_i / w_i) / sum_k (s_k / w_k)`` of the
   screen weights ``s_i``. Phong shading gathers a row's interpolated points and normals into
   planar batches (one object's pixels each) and shades a batch at once with the lighting
   stage's vectorized ``shade_planar``.

Alpha-tested materials (``Material.alpha_cutoff``) cut holes where visibility is decided: a
method asks :func:`cut_away_at` about each sample of an alpha-tested triangle (``Cutouts``)
before it lets the sample hide what lies behind, so the sample behind shows through, and the
shading pass never sees the cut one. The question is asked per triangle first
(``Cutouts.masked``): the loops over the samples of other triangles are the ones they were
without alpha tests. A scene without alpha tests, textures or vertex colours hands the
z-buffer's pass no cutouts and the passes no colour tables (:func:`looks_up`), and those
versions of the kernels are compiled without the tests and lookups.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from pixelpath._jit import compile_for, inlined, njit
from pixelpath.lighting._kernels import shade_planar, shade_point
from pixelpath.raster._scan_kernels import (
    BAND_ROWS,
    _band_rows,
    _rasterize_band,
    bin_triangles,
    count_coverage,
    interpolate_values,
    paint_bands,
    rasterize_bands,
    tiny_cutouts,
)
from pixelpath.raster._setup_kernels import (
    S1_PLANE,
    S2_PLANE,
    SETUP_FIELDS,
    VERTEX_INVW,
    classify_triangles,
    clip_to_screen,
    clip_triangles,
    front_facing_many,
    key_depth,
    perspective_weights,
    setup_triangles,
)
from pixelpath.scene._texture_kernels import (
    CUTOFF,
    GLOW,
    HAS_COLORS,
    NEAREST,
    TEXTURE,
    base_color,
    base_size,
    bilinear_taps,
    blend_taps,
    footprint_squared,
    footprint_squared_in,
    mip_level_squared,
    sample_level,
    tiny_tables,
)

FLAT = 0
GOURAUD = 1
PHONG = 2

# The Gouraud vertex colours hold the light from the front (normal as given), then from the
# back (normal reversed, for two-sided faces seen from behind): 3 columns each, the intensity;
# 6 each when the scene has coloured surfaces (textures or vertex colours), which keep the
# light split in two, what their surface colour multiplies (ambient and diffuse) and what it
# does not (the highlight). Flat colours are laid out as one such half.

# Phong pixels gathered per call of the planar shading kernel: a whole row of a 1024-wide frame.
# Fewer, longer calls were measured faster than work arrays small enough for the L1 cache
# (batches of 128 and 256 pixels).
SHADE_BATCH = 1024


class PhongBatch(NamedTuple):
    """Work arrays of one band's Phong pixels, planar: x, y, z (or r, g, b) in rows."""

    points: np.ndarray  # (3, SHADE_BATCH) interpolated surface points
    normals: np.ndarray  # (3, SHADE_BATCH) unit normals, turned towards the viewer
    shaded: np.ndarray  # (3, SHADE_BATCH) unclamped intensities
    albedo: np.ndarray  # (3, SHADE_BATCH) object colour C at each pixel
    scratch: np.ndarray  # (5, SHADE_BATCH) work space of shade_planar
    denominators: np.ndarray  # (SHADE_BATCH,) interpolated 1/w: points are numerators first
    columns: np.ndarray  # (SHADE_BATCH,) intp: the pixel column of each gathered pixel
    row_colors: np.ndarray  # (w, 3) surface colour of a row's pixels of coloured objects
    row_glow: np.ndarray  # (w, 3) emitted light of a row's pixels of emission-textured objects
    # A row's texture lookups, in order: the surface colours' from 0, the emission's from w.
    lookups: np.ndarray  # (3, 2w) u, v and squared footprint of each lookup
    lookup_columns: np.ndarray  # (2w,) intp: the pixel column of each lookup
    lookup_textures: np.ndarray  # (2w,) intp: the texture each lookup reads
    lookup_levels: np.ndarray  # (2w,) intp: the mip level each lookup reads first
    lookup_taps: np.ndarray  # (4, 2w) intp: the texels of a base-level lookup (-1: another kind)
    lookup_fractions: np.ndarray  # (2, 2w) the base-level lookups' blend fractions (fx, fy)


class Surfaces(NamedTuple):
    """What the shading pass reads about the drawn triangles, the materials and the lights."""

    setup: np.ndarray  # (T, SETUP_FIELDS) set-up records
    triangles: np.ndarray  # (T, 3) vertex indices
    positions: np.ndarray  # (V, 3) world positions
    normals: np.ndarray  # (V, 3) unit normals
    colors: np.ndarray  # (V, 6|12) Gouraud light, front then back; (0, 6) otherwise
    info: np.ndarray  # (T, 2) object index, flip flag (seen from behind)
    flat_colors: np.ndarray  # (T, 3|6) flat-shading light (zeros in the other modes)
    face_normals: np.ndarray  # (T, 3) unit normal of each triangle's polygon, towards the eye
    uv: np.ndarray  # (V, 2) texture coordinates; (0, 2) when nothing is textured
    vertex_colors: np.ndarray  # (V, 4) vertex colours; (0, 4) when no object has them
    tables: object  # SurfaceTables: textures and which objects have coloured surfaces
    coloured: np.ndarray  # (O,) bool: objects with a texture or vertex colours
    materials: np.ndarray  # (O, 8) packed materials
    emission: np.ndarray  # (O, 3) light each object emits; (0, 3) when none emits any
    lights: np.ndarray  # (L, 7) packed lights
    ambient: np.ndarray  # (3,) ambient intensity
    eye: np.ndarray  # (4,) the camera's homogeneous viewpoint (eye, 1) or (-d, 0)
    background: np.ndarray  # (3,) colour where nothing is drawn
    mode: int  # FLAT, GOURAUD or PHONG
    blinn: bool  # Blinn-Phong highlights
    orthographic: bool  # the depth key is affine in depth (else 1/w)
    near: float  # the camera's near and far distances (an orthographic key's depth)
    far: float


def looks_up(surfaces: Surfaces) -> bool:
    """Whether the passes look the scene's surfaces up point by point.

    True when an object has a coloured surface (``surfaces.uv`` or ``surfaces.vertex_colors``
    has rows) or an alpha test (a cutoff in ``surfaces.tables.alpha``). Otherwise the scene is
    plain, and the passes are handed no cutouts and no colour tables (None): Numba compiles
    them separately for None and prunes the alpha test and the colour lookups
    (:func:`_row_surface_colors`) from that version, so the plain scenes most renders draw
    compile none of them, 3.6 of the 10 s the z-buffer's depth test and pass took to compile
    with them (``docs/performance.md``; the groups of each version in :mod:`pixelpath._warm`).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.raster._kernels import Surfaces, looks_up
    >>> from pixelpath.scene.texture import surface_tables
    >>> plain = Surfaces(*[None] * 8, np.empty((0, 2)), np.empty((0, 4)), surface_tables([]),
    ...                  *[None] * 12)
    >>> looks_up(plain), looks_up(plain._replace(uv=np.zeros((3, 2))))
    (False, True)
    """
    return bool(surfaces.uv.shape[0] or surfaces.vertex_colors.shape[0]
                or np.any(surfaces.tables.alpha[:, CUTOFF] > 0.0))


class Buffers(NamedTuple):
    """The output buffers of a frame (or of a region of one)."""

    rgb: np.ndarray  # (h, w, 3) float32 clamped intensities
    depth: np.ndarray  # (h, w) float32 view-axis depth, inf where nothing is drawn
    object_id: np.ndarray  # (h, w) int32 object index, -1 where nothing is drawn
    normal: np.ndarray  # (h, w, 3) float32 unit shading normal, 0 where nothing is drawn


@njit
def shade_points(first, stop, points, normals, flip, owner, materials, lights, ambient, eye,
                 blinn, out):
    """Unclamped intensities at points [first, stop) with unit normals, into out (N, 3).

    Each point has its owner's material; where ``flip`` is set the normal is reversed first
    (a surface seen from behind). ``eye`` (4,) is homogeneous (the camera's viewpoint).
    """
    for p in range(first, stop):
        sign = -1.0 if flip[p] else 1.0
        shade_point(
            points[p, 0],
            points[p, 1],
            points[p, 2],
            sign * normals[p, 0],
            sign * normals[p, 1],
            sign * normals[p, 2],
            eye[0],
            eye[1],
            eye[2],
            eye[3],
            materials[owner[p]],
            lights,
            ambient,
            blinn,
            out[p],
        )


@inlined
def _mix(values, a, b, c, w0, w1, w2, column):
    """Weighted sum of one column of per-vertex values over a triangle's vertices a, b, c."""
    return w0 * values[a, column] + w1 * values[b, column] + w2 * values[c, column]


@inlined
def _clamp01(value):
    return min(max(value, 0.0), 1.0)


def new_batch(width: int) -> PhongBatch:
    """Return the work arrays of a shading pass's rows ``width`` pixels wide (:class:`PhongBatch`).

    Allocated in Python and handed to the passes, which reuse them row after row: built by a
    compiled function, they cost every cold first render a third of a second of compiling on
    its longest path (``docs/performance.md``), and a call per band.

    Examples
    --------
    >>> from pixelpath.raster._kernels import new_batch
    >>> new_batch(640).row_colors.shape
    (640, 3)
    """
    return PhongBatch(
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((5, SHADE_BATCH)),
        np.empty(SHADE_BATCH),
        np.empty(SHADE_BATCH, dtype=np.intp),
        np.empty((width, 3)),
        np.empty((width, 3)),
        np.empty((3, 2 * width)),
        np.empty(2 * width, dtype=np.intp),
        np.empty(2 * width, dtype=np.intp),
        np.empty(2 * width, dtype=np.intp),
        np.empty((4, 2 * width), dtype=np.intp),
        np.empty((2, 2 * width)),
    )


@njit
def render_bands(bands, setup, rows, offsets, items, band_rows, x0, y0, inv_depth, triangle_id,
                 cutouts, surfaces, colour_tables, batch, out):
    """Rasterize the listed bands of rows with the depth test, then shade them (the z-buffer).

    One pass per band: its depth and triangle buffers are still in cache when it is shaded.
    ``inv_depth`` and ``triangle_id`` are the region's visibility buffers (h, w), left filled
    for whatever reads them afterwards, or one band's (``band_rows``, w), which every band
    reuses: those stay in cache, and a frame's 12 bytes a pixel of them never reach memory.
    ``cutouts`` and ``colour_tables`` are None for a plain scene (:func:`looks_up`);
    ``batch`` is the calling thread's work arrays (:func:`new_batch`). Serial, and called on
    runs of the band list from several threads at once (it releases the GIL): a
    ``parallel=True`` loop cost seconds more to compile on a first run.
    """
    height = out.depth.shape[0]
    for k in range(bands.shape[0]):
        band = bands[k]
        first, stop = _band_rows(band, band_rows, y0, height)
        top = y0 if inv_depth.shape[0] == height else first  # the buffers' first image row
        _rasterize_band(
            setup, rows, offsets, items, band, first, stop, x0, top, inv_depth, triangle_id,
            cutouts,
        )
        for j in range(first, stop):
            if colour_tables is not None:  # a branch Numba prunes, with the lookups, for None
                _row_surface_colors(j, x0, triangle_id[j - top], surfaces, batch)
            _shade_row(j, x0, y0, triangle_id[j - top], inv_depth[j - top], surfaces, out, batch)


@njit
def shade_bands(bands, band_rows, x0, y0, inv_depth, triangle_id, surfaces, colour_tables, batch,
                out):
    """Shade the listed bands from visibility buffers a hidden-surface method filled.

    ``inv_depth`` (h, w) holds 1/w of the visible surface (0 where nothing is drawn) and
    ``triangle_id`` (h, w) its triangle (-1 there), for the region whose top-left pixel is
    (x0, y0). Writes clamped RGB (h, w, 3) (``surfaces.background`` where nothing was drawn),
    the view-axis depth (h, w) (``inf`` there) and the object id (h, w) (-1 there) into
    ``out``. ``colour_tables`` is ``surfaces.tables``, or None for a plain scene
    (:func:`looks_up`).
    """
    height = inv_depth.shape[0]
    for k in range(bands.shape[0]):
        first, stop = _band_rows(bands[k], band_rows, y0, height)
        for j in range(first, stop):
            if colour_tables is not None:  # as in render_bands
                _row_surface_colors(j, x0, triangle_id[j - y0], surfaces, batch)
            _shade_row(j, x0, y0, triangle_id[j - y0], inv_depth[j - y0], surfaces, out, batch)


@njit(refcount=False, from_python=False)
def _shade_row(j, x0, y0, ids, keys, surfaces, out, batch):
    """Fill image row j of the output buffers from the triangle seen at each of its pixels.

    ``ids`` and ``keys`` are the row's triangles (-1 where none) and depth keys (1/w, 0 where
    none); the output buffers cover the region whose top-left pixel is (x0, y0).

    This is the one shading pass of every raster method. Phong pixels are gathered
    (interpolated point and unit normal, planar, and the object colour) into ``batch`` and
    shaded together by :func:`_shade_batch` when it is full, when the object changes, and at
    the end of the row. A coloured surface (texture or vertex colours) has its colour looked
    up at every pixel, whatever the shading mode: flat and Gouraud shading are about where the
    light is computed, and its ambient and diffuse parts are then tinted by the colour there.
    Those colours are looked up first, into ``batch.row_colors`` (:func:`_row_surface_colors`).
    """
    s = surfaces
    row = j - y0
    rgb = out.rgb[row]
    normal = out.normal[row]
    count = 0
    batch_object = -1
    line_triangle = -1
    line = (0.0,) * 14
    y = j + 0.5
    _fill_row(keys, s.background, rgb, out.depth[row], out.object_id[row], normal,
              s.orthographic, s.near, s.far)
    half = s.colors.shape[1] // 2  # Gouraud: the columns of the light from the front
    glow = s.emission.shape[0] > 0  # some object emits light
    for i in range(ids.shape[0]):
        t = ids[i]
        if t < 0:
            continue
        obj = s.info[t, 0]
        out.object_id[row, i] = obj
        x = (x0 + i) + 0.5
        coloured = s.coloured[obj]
        if s.mode != PHONG:
            tint = (1.0, 1.0, 1.0)
            if coloured:
                tint = (batch.row_colors[i, 0], batch.row_colors[i, 1], batch.row_colors[i, 2])
            if s.mode == FLAT:
                for channel in range(3):
                    normal[i, channel] = s.face_normals[t, channel]
                    value = s.flat_colors[t, channel] * tint[channel]
                    if coloured:
                        value += s.flat_colors[t, 3 + channel]
                    if glow:
                        value += _emitted(s, batch.row_glow, obj, i, channel)
                    rgb[i, channel] = _clamp01(value)
                continue
            b0, b1, b2 = perspective_weights(s.setup, t, x, y)
            a, b, c = s.triangles[t, 0], s.triangles[t, 1], s.triangles[t, 2]
            _store_normal(normal, i, s.normals, a, b, c, b0, b1, b2, s.info[t, 1])
            first = half if s.info[t, 1] else 0
            for channel in range(3):
                value = _mix(s.colors, a, b, c, b0, b1, b2, first + channel) * tint[channel]
                if coloured:
                    value += _mix(s.colors, a, b, c, b0, b1, b2, first + 3 + channel)
                if glow:
                    value += _emitted(s, batch.row_glow, obj, i, channel)
                rgb[i, channel] = _clamp01(value)
            continue
        if count == SHADE_BATCH or (count > 0 and obj != batch_object):
            _shade_batch(count, batch, batch_object, s, rgb, normal)
            count = np.intp(0)
        batch_object = obj
        if t != line_triangle:
            line_triangle = t
            sign = -1.0 if s.info[t, 1] else 1.0
            line = _scanline_surface(s.setup, t, y, s.triangles, s.positions, s.normals, sign)
        # Numerators and denominator only; _shade_batch divides, normalizes, all at once.
        batch.denominators[count] = line[0] * x + line[1]
        batch.points[0, count] = line[2] * x + line[3]
        batch.points[1, count] = line[4] * x + line[5]
        batch.points[2, count] = line[6] * x + line[7]
        batch.normals[0, count] = line[8] * x + line[9]
        batch.normals[1, count] = line[10] * x + line[11]
        batch.normals[2, count] = line[12] * x + line[13]
        colors = batch.row_colors if coloured else s.materials
        k = i if coloured else obj
        batch.albedo[0, count] = colors[k, 0]
        batch.albedo[1, count] = colors[k, 1]
        batch.albedo[2, count] = colors[k, 2]
        batch.columns[count] = i
        count += 1
    if count > 0:
        _shade_batch(count, batch, batch_object, s, rgb, normal)


@inlined
def _emitted(surfaces, row_glow, obj, i, channel):
    """Light object ``obj`` emits at pixel i of a row: its emission, or as its texture scales it."""
    if surfaces.tables.objects[obj, GLOW] >= 0:
        return row_glow[i, channel]
    return surfaces.emission[obj, channel]


@inlined
def _store_normal(normal, i, normals, a, b, c, b0, b1, b2, flipped):
    """Write the unit interpolated vertex normal (turned to the viewer) at pixel i of a row."""
    nx = _mix(normals, a, b, c, b0, b1, b2, 0)
    ny = _mix(normals, a, b, c, b0, b1, b2, 1)
    nz = _mix(normals, a, b, c, b0, b1, b2, 2)
    length = math.sqrt(nx * nx + ny * ny + nz * nz)
    scale = (-1.0 if flipped else 1.0) / length if length > 0.0 else 0.0
    normal[i, 0] = nx * scale
    normal[i, 1] = ny * scale
    normal[i, 2] = nz * scale


# Compiled once and inlined by LLVM into its three callers (see pixelpath._jit).
@inlined
def _line_weights(setup, t, y):
    """Return the perspective weights' numerators ``t_k = s_k / w_k`` of triangle t on row y.

    Each is affine in x on the line: returns their slopes, then their values at x = 0; at x,
    ``t_k = slope_k x + base_k``, and the perspective-correct weight is ``b_k = t_k / sum t``
    (the sum is the interpolated 1/w).
    """
    r1 = setup[t, S1_PLANE + 1] * y + setup[t, S1_PLANE + 2]
    r2 = setup[t, S2_PLANE + 1] * y + setup[t, S2_PLANE + 2]
    w0, w1, w2 = setup[t, VERTEX_INVW], setup[t, VERTEX_INVW + 1], setup[t, VERTEX_INVW + 2]
    return (
        -w0 * (setup[t, S1_PLANE] + setup[t, S2_PLANE]), w1 * setup[t, S1_PLANE],
        w2 * setup[t, S2_PLANE], w0 * (1.0 - r1 - r2), w1 * r1, w2 * r2,
    )


@inlined
def _weights_at(numerators, x):
    """Perspective-correct weights (b0, b1, b2) at pixel centre x of a :func:`_line_weights`."""
    t0 = numerators[0] * x + numerators[3]
    t1 = numerators[1] * x + numerators[4]
    t2 = numerators[2] * x + numerators[5]
    inv = 1.0 / (t0 + t1 + t2)
    return t0 * inv, t1 * inv, t2 * inv


# Compiled once and inlined by LLVM into its callers (see pixelpath._jit).
@inlined
def texture_line(setup, t, y, uv, a, b, c):
    """Texture coordinates of set-up triangle t (vertices a, b, c) along scan line y.

    ``u = U / D`` with U and D affine in screen space (D the interpolated 1/w, U its sum
    weighted by the vertices' u): returns the slope along the line and the value at x = 0 of
    D, U and V, then their changes per row down the image, 9 numbers that
    :func:`texture_at` evaluates at a pixel. Computed once per run of a triangle's pixels on
    a row: the textured Duck's frame took 5 % less time than with the weights and their
    gradients worked out afresh at every pixel.
    """
    s0, s1, s2, e0, e1, e2 = _line_weights(setup, t, y)
    w0, w1, w2 = setup[t, VERTEX_INVW], setup[t, VERTEX_INVW + 1], setup[t, VERTEX_INVW + 2]
    d0 = -(setup[t, S1_PLANE + 1] + setup[t, S2_PLANE + 1]) * w0
    d1, d2 = setup[t, S1_PLANE + 1] * w1, setup[t, S2_PLANE + 1] * w2
    ua, ub, uc, va, vb, vc = uv[a, 0], uv[b, 0], uv[c, 0], uv[a, 1], uv[b, 1], uv[c, 1]
    return (
        s0 + s1 + s2, e0 + e1 + e2,
        s0 * ua + s1 * ub + s2 * uc, e0 * ua + e1 * ub + e2 * uc,
        s0 * va + s1 * vb + s2 * vc, e0 * va + e1 * vb + e2 * vc,
        d0 + d1 + d2, d0 * ua + d1 * ub + d2 * uc, d0 * va + d1 * vb + d2 * vc,
    )


@inlined
def texture_at(line, x):
    """Return (u, v, du/dx, dv/dx, du/dy, dv/dy) at pixel centre x of a :func:`texture_line`.

    The derivatives give how far (u, v) moves over one pixel, the footprint that chooses the
    mip level: for ``u = U / D``, ``du/dx = (U' - u D') / D``. The shading pass and the
    explain report's count of mip levels both take them from here, so both see the same
    footprint.
    """
    inv = 1.0 / (line[0] * x + line[1])
    u = (line[2] * x + line[3]) * inv
    v = (line[4] * x + line[5]) * inv
    return (u, v, (line[2] - u * line[0]) * inv, (line[4] - v * line[0]) * inv,
            (line[7] - u * line[6]) * inv, (line[8] - v * line[6]) * inv)


@njit(refcount=False, from_python=False)
def _row_surface_colors(j, x0, ids, surfaces, batch):
    """Write into ``batch.row_colors`` the surface colour (r, g, b) of row j's coloured pixels.

    ``ids`` are the row's triangles (-1 where none). The shading pass (:func:`_shade_row`)
    then reads the colours of the pixels of coloured objects there.

    One call per row, compiled without reference counting: the lookups' arrays are handed
    on per pixel without the atomic count updates a counted kernel makes at each call.

    Three loops: the first writes each pixel's colour before the texture
    (:func:`~pixelpath.scene._texture_kernels.base_color`) and lists its texture lookup
    (u, v, squared footprint) in ``lookups``; the second chooses their mip levels (the
    footprint's place is taken by the blend); the third makes the lookups and multiplies them
    in. The products are :func:`~pixelpath.scene._texture_kernels.surface_color`'s, with
    weights and texture coordinates taken from each triangle's lines along the row (equal up
    to rounding to those of the pixel's own perspective weights); split so, each loop's
    pixels are independent of each other, and the processor overlaps them (a fifth less time
    a textured pixel of the bunny than one loop doing it all). A row that shows an object
    whose emission texture scales its ``emission`` then gets its emitted light
    (:func:`_row_glow`).
    """
    s = surfaces
    info, setup, triangles, uv, tables = s.info, s.setup, s.triangles, s.uv, s.tables
    vertex_colors, materials, emission, coloured = (
        s.vertex_colors, s.materials, s.emission, s.coloured
    )
    out = batch.row_colors
    y = j + 0.5
    lookups, lookup_columns, lookup_textures = (
        batch.lookups, batch.lookup_columns, batch.lookup_textures
    )
    count = 0
    line_triangle = -1
    obj = texture = a = b = c = 0
    painted = glowing = False
    r = g = bl = 0.0
    numerators = (0.0,) * 6
    line = (0.0,) * 9
    size = (0.0, 0.0)
    for i in range(ids.shape[0]):
        t = ids[i]
        if t < 0:
            continue
        if t != line_triangle:
            # What the run of this triangle's pixels shares, looked up once: the compiled
            # loop reloads a table entry at every pixel, as the stores may have changed it.
            glowing = glowing or tables.objects[info[t, 0], GLOW] >= 0
            if not coloured[info[t, 0]]:
                continue
            line_triangle = t
            obj = info[t, 0]
            a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
            texture = tables.objects[obj, TEXTURE]
            painted = tables.objects[obj, HAS_COLORS] != 0
            if painted:
                numerators = _line_weights(setup, t, y)
            else:  # the material's colour alone: the same at every pixel
                r, g, bl, _ = base_color(tables, materials, obj, vertex_colors, a, b, c, 0.0,
                                         0.0, 0.0)
            if texture >= 0:
                line = texture_line(setup, t, y, uv, a, b, c)
                size = base_size(tables, texture)
        x = (x0 + i) + 0.5
        if painted:
            b0, b1, b2 = _weights_at(numerators, x)
            r, g, bl, _ = base_color(tables, materials, obj, vertex_colors, a, b, c, b0, b1, b2)
        out[i, 0] = r
        out[i, 1] = g
        out[i, 2] = bl
        if texture >= 0:
            _list_lookup(lookups, lookup_columns, lookup_textures, count, size, texture, line, x,
                         i)
            count += 1
    if count > 0:
        _apply_lookups(0, count, tables, batch, out)
    if glowing:
        _row_glow(j, x0, ids, info, setup, triangles, uv, tables, emission, batch)


@njit(refcount=False, from_python=False)
def _row_glow(j, x0, ids, info, setup, triangles, uv, tables, emission, batch):
    """Write into ``batch.row_glow`` the light row j's emission-textured pixels give off.

    The object's ``emission`` × its emission texture, looked up at the pixel's texture
    coordinates and footprint as the surface colour's texture is; the lookups are listed
    after the row's room for the surface colour's. A pass of its own, made only in rows that
    show such an object, so that the surface colours' loop stays as it was.
    """
    y = j + 0.5
    width = ids.shape[0]
    count = width
    line_triangle = -1
    obj = glow = np.intp(0)
    line = (0.0,) * 9
    size = (0.0, 0.0)
    for i in range(width):
        t = ids[i]
        if t < 0:
            continue
        if t != line_triangle:
            glow = tables.objects[info[t, 0], GLOW]
            if glow < 0:
                continue
            line_triangle = t
            obj = info[t, 0]
            line = texture_line(setup, t, y, uv, triangles[t, 0], triangles[t, 1],
                                triangles[t, 2])
            size = base_size(tables, glow)
        _list_lookup(batch.lookups, batch.lookup_columns, batch.lookup_textures, count, size,
                     glow, line, (x0 + i) + 0.5, i)
        count += 1
        for channel in range(3):
            batch.row_glow[i, channel] = emission[obj, channel]
    _apply_lookups(width, count, tables, batch, batch.row_glow)


@inlined
def _list_lookup(lookups, columns, textures, q, size, texture, line, x, i):
    """List, as lookup q of a row, ``texture`` read at pixel i (centre x) of a triangle's line.

    Its texture coordinates and squared footprint (:func:`texture_at`), its column and texture.
    ``size`` is the texture's base-level (width, height) (:func:`base_size`).
    """
    u, v, dudx, dvdx, dudy, dvdy = texture_at(line, x)
    lookups[0, q] = u
    lookups[1, q] = v
    lookups[2, q] = footprint_squared_in(size[0], size[1], dudx, dvdx, dudy, dvdy)
    columns[q] = i
    textures[q] = texture


# A kernel of its own, called once per row. When Numba still copied the lookups (sample_level)
# into their callers, a copy cost more the larger the function receiving it: into the row loop
# above, which had taken in the other helpers already, 3.9 s of the 18 s of CPU the z-buffer's
# group took to compile; into this small kernel, 0.8 s (the lookups are now compiled once and
# inlined by LLVM, see pixelpath._jit). The textured Duck's frame takes the same time. One
# general lookup only: a second, for rows that skip the base-level loop, made the group take
# 20 s to compile instead of 17.
@njit(refcount=False)
def _apply_lookups(first, stop, tables, batch, out):
    """Make the row's listed texture lookups first..stop-1; multiply their colours into ``out``.

    First the lookups' mip levels. Then, in a row whose first lookup is of the commonest kind,
    one bilinear blend on the base level of the row's texture (a magnified texture, as on most
    of the Duck's pixels), the lookups of that kind get a loop of their own that finds their
    texels, with the level's place and size read once instead of at every lookup, and a last
    loop blends them and makes the other lookups: 18 ns a lookup of that kind instead of 24 on
    one core, with the same bits. Other rows (a minified texture's, whose lookups blend two
    levels) skip the base-level loop's work, which cost them more than it saved.
    """
    lookups, levels, textures = batch.lookups, batch.lookup_levels, batch.lookup_textures
    taps, fractions = batch.lookup_taps, batch.lookup_fractions
    for q in range(first, stop):
        levels[q], lookups[2, q] = mip_level_squared(tables, textures[q], lookups[2, q])
    texture = textures[first]
    base, wrap = tables.textures[texture, 0], tables.textures[texture, 3]
    start, width, height = tables.levels[base, 0], tables.levels[base, 1], tables.levels[base, 2]
    common = (tables.textures[texture, 2] != NEAREST and levels[first] == 0
              and lookups[2, first] == 0.0)
    for q in range(first, stop):
        if common and textures[q] == texture and levels[q] == 0 and lookups[2, q] == 0.0:
            (taps[0, q], taps[1, q], taps[2, q], taps[3, q], fractions[0, q],
             fractions[1, q]) = bilinear_taps(start, width, height, wrap, lookups[0, q],
                                              lookups[1, q])
        else:
            taps[0, q] = -1  # a texel index is never negative
    for q in range(first, stop):
        if taps[0, q] >= 0:
            color = blend_taps(tables, taps[0, q], taps[1, q], taps[2, q], taps[3, q],
                               fractions[0, q], fractions[1, q])
        else:
            color = sample_level(tables, textures[q], lookups[0, q], lookups[1, q], levels[q],
                                 lookups[2, q])
        _tint(out, batch.lookup_columns[q], color)


@inlined
def _tint(out, i, color):
    """Multiply pixel i's surface colour in ``out`` by a texture lookup's (r, g, b, a)."""
    out[i, 0] *= color[0]
    out[i, 1] *= color[1]
    out[i, 2] *= color[2]


@njit
def texture_lookups(x0, y0, triangle_id, surfaces, texture, level, blend):
    """Record the texture lookup of every drawn pixel of a region, for the explain report.

    From the visibility buffer ``triangle_id`` (h, w) of the region whose top-left pixel is
    (x0, y0): writes, per pixel, the texture (row of ``surfaces.tables.textures``) read there,
    the mip level read (0 the base) and the weight of the next level (:func:`mip_level`,
    from the same footprint as the shading pass); -1, -1 and 0 where no texture is read.
    """
    s = surfaces
    for row in range(triangle_id.shape[0]):
        y = (y0 + row) + 0.5
        for i in range(triangle_id.shape[1]):
            texture[row, i], level[row, i], blend[row, i] = -1, -1, 0.0
            t = triangle_id[row, i]
            if t < 0:
                continue
            k = s.tables.objects[s.info[t, 0], TEXTURE]
            if k < 0:
                continue
            a, b, c = s.triangles[t, 0], s.triangles[t, 1], s.triangles[t, 2]
            x = (x0 + i) + 0.5
            line = texture_line(s.setup, t, y, s.uv, a, b, c)
            _, _, dudx, dvdx, dudy, dvdy = texture_at(line, x)
            squared = footprint_squared(s.tables, k, dudx, dvdx, dudy, dvdy)
            texture[row, i] = k
            level[row, i], blend[row, i] = mip_level_squared(s.tables, k, squared)


@inlined
def _scanline_surface(setup, t, y, triangles, positions, normals, sign):
    """Surface point and normal of set-up triangle t along scan line y, as functions of x.

    The perspective weights are ``b_k = t_k / sum t`` with ``t_k = s_k / w_k`` affine in x on
    the line, so an interpolated attribute is (u x + v) / (d x + e). Returns (d, e), then
    (u, v) for the point's x, y, z and for the normal's (times ``sign``), 14 numbers. The
    normal's denominator (the interpolated 1/w > 0) is left out: normalizing removes it.
    """
    slope0, slope1, slope2, base0, base1, base2 = _line_weights(setup, t, y)
    a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
    return (
        slope0 + slope1 + slope2,
        base0 + base1 + base2,
        slope0 * positions[a, 0] + slope1 * positions[b, 0] + slope2 * positions[c, 0],
        base0 * positions[a, 0] + base1 * positions[b, 0] + base2 * positions[c, 0],
        slope0 * positions[a, 1] + slope1 * positions[b, 1] + slope2 * positions[c, 1],
        base0 * positions[a, 1] + base1 * positions[b, 1] + base2 * positions[c, 1],
        slope0 * positions[a, 2] + slope1 * positions[b, 2] + slope2 * positions[c, 2],
        base0 * positions[a, 2] + base1 * positions[b, 2] + base2 * positions[c, 2],
        sign * (slope0 * normals[a, 0] + slope1 * normals[b, 0] + slope2 * normals[c, 0]),
        sign * (base0 * normals[a, 0] + base1 * normals[b, 0] + base2 * normals[c, 0]),
        sign * (slope0 * normals[a, 1] + slope1 * normals[b, 1] + slope2 * normals[c, 1]),
        sign * (base0 * normals[a, 1] + base1 * normals[b, 1] + base2 * normals[c, 1]),
        sign * (slope0 * normals[a, 2] + slope1 * normals[b, 2] + slope2 * normals[c, 2]),
        sign * (base0 * normals[a, 2] + base1 * normals[b, 2] + base2 * normals[c, 2]),
    )


@njit(error_model="numpy", refcount=False, from_python=False)
def _fill_row(inv_depth_row, background, rgb_row, depth_row, id_row, normal_row, orthographic,
              near, far):
    """Write a row as if nothing were drawn, but with every drawn pixel's depth.

    A pixel is drawn exactly where its depth key is positive (the buffer starts at 0); its
    depth is :func:`key_depth` of the key (1/(1/w) for a perspective camera). One loop
    without branches over the whole row, so LLVM vectorizes it; the drawn pixels' colour,
    object id and normal are written afterwards.
    """
    red, green, blue = background[0], background[1], background[2]
    rgb_flat = rgb_row.reshape(-1)  # r g b r g b ...: indexed 3 i + c, which vectorizes
    normal_flat = normal_row.reshape(-1)
    for i in range(inv_depth_row.shape[0]):
        depth_row[i] = key_depth(inv_depth_row[i], orthographic, near, far)
        id_row[i] = -1
        rgb_flat[3 * i] = red
        rgb_flat[3 * i + 1] = green
        rgb_flat[3 * i + 2] = blue
        normal_flat[3 * i] = 0.0
        normal_flat[3 * i + 1] = 0.0
        normal_flat[3 * i + 2] = 0.0


@njit(error_model="numpy", refcount=False, from_python=False)
def _shade_batch(count, batch, obj, surfaces, rgb_row, normal_row):
    """Shade the gathered pixels of one row (object ``obj``'s); write their colours and normals.

    First the perspective division of the points and the normalization of the normals, in a
    loop LLVM vectorizes (``error_model="numpy"``: no zero-division check; the denominator is
    the interpolated 1/w, positive on a drawn pixel, and a zero normal's length is guarded).
    """
    x, y, z = batch.points[0], batch.points[1], batch.points[2]
    nx, ny, nz = batch.normals[0], batch.normals[1], batch.normals[2]
    denominators = batch.denominators
    for q in range(count):
        inv = 1.0 / denominators[q]
        x[q] *= inv
        y[q] *= inv
        z[q] *= inv
        length = math.sqrt(nx[q] * nx[q] + ny[q] * ny[q] + nz[q] * nz[q])
        scale = 1.0 / length if length > 0.0 else 1.0
        nx[q] *= scale
        ny[q] *= scale
        nz[q] *= scale
    shade_planar(
        count, batch.points, batch.normals, batch.albedo, surfaces.eye, surfaces.materials[obj],
        surfaces.lights, surfaces.ambient, surfaces.blinn, batch.shaded, batch.scratch,
    )
    glow = surfaces.emission.shape[0] > 0
    for q in range(count):
        i = batch.columns[q]
        for channel in range(3):
            value = batch.shaded[channel, q]
            if glow:
                value += _emitted(surfaces, batch.row_glow, obj, i, channel)
            rgb_row[i, channel] = _clamp01(value)
            normal_row[i, channel] = batch.normals[channel, q]


# Warm-up in groups that compile independently (pixelpath._warm compiles groups in
# separate processes at once on a first run): each builds its inputs by hand rather than with
# another group's kernels. Values do not matter, only types: Numba compiles per type.
def _tiny_triangle():
    """One triangle's inputs: clip (3, 4), triangles (1, 3), setup, rows, bins, buffers."""
    clip = np.array([[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.0, 0.5, 0.0, 1.0]])
    triangles = np.array([[0, 1, 2]], dtype=np.intp)
    setup = np.zeros((1, SETUP_FIELDS))
    rows = np.zeros((1, 2), dtype=np.intp)
    offsets = np.array([0, 1], dtype=np.intp)
    items = np.zeros(1, dtype=np.intp)
    inv_depth = np.empty((8, 8))
    triangle_id = np.empty((8, 8), dtype=np.int32)
    return clip, triangles, setup, rows, offsets, items, inv_depth, triangle_id


def warm_front() -> None:
    """Compile the front end's kernels: cull, classify, clip, divide, set up, bin."""
    clip, triangles, setup, rows, _, _, _, _ = _tiny_triangle()
    status = np.empty(1, dtype=np.int8)
    classify_triangles(clip, triangles, np.ones(1, dtype=np.bool_), status)
    normal = np.array([[0.0, 0.0, 1.0]])
    front_facing_many(normal, np.zeros((1, 3)), np.ones(4), np.empty(1, dtype=np.bool_))
    clip_triangles(np.zeros((3, 10)), triangles, np.zeros(1, dtype=np.intp))
    screen = np.empty((3, 3))
    clip_to_screen(clip, 8, 8, False, screen)
    setup_triangles(screen, triangles, False, 0, 8, setup, rows)
    bin_triangles(rows, 1, BAND_ROWS, 0)


def _tiny_lighting():
    """Three unit normals along z, one material, one point light and the ambient light."""
    normals = np.zeros((3, 3))
    normals[:, 2] = 1.0
    materials = np.array([[1.0, 1.0, 1.0, 0.1, 0.7, 0.3, 32.0, 0.0]])
    lights = np.array([[0.0, 0.0, 0.0, 5.0, 1.0, 1.0, 1.0]])
    return normals, materials, lights, np.full(3, 0.1)


def warm_vertex_shading() -> None:
    """Compile the lighting of points that flat and Gouraud shading do before rasterizing."""
    normals, materials, lights, ambient = _tiny_lighting()
    shade_points(
        0, 3, np.zeros((3, 3)), normals, np.zeros(3, np.bool_), np.zeros(3, np.intp), materials,
        lights, ambient, np.array([0.0, 0.0, 5.0, 1.0]), False, np.empty((3, 3)),
    )


def _tiny_shading_pass():
    """Return the shading pass's inputs for the one triangle of :func:`_tiny_triangle`.

    The visibility buffers say that nothing is drawn, as before any method has run.
    """
    clip, triangles, setup, rows, offsets, items, inv_depth, triangle_id = _tiny_triangle()
    inv_depth.fill(0.0)
    triangle_id.fill(-1)
    normals, materials, lights, ambient = _tiny_lighting()
    surfaces = Surfaces(
        setup, triangles, clip[:, :3].copy(), normals, np.zeros((3, 6)),
        np.zeros((1, 2), dtype=np.intp), np.ones((1, 3)), normals[:1].copy(), np.zeros((3, 2)),
        np.ones((3, 4)), tiny_tables(), np.ones(1, dtype=np.bool_), materials,
        np.zeros((1, 3)), lights, ambient, np.array([0.0, 0.0, 5.0, 1.0]), np.zeros(3), PHONG,
        False, False, 0.1, 10.0,
    )
    out = Buffers(
        np.zeros((8, 8, 3), dtype=np.float32),
        np.empty((8, 8), dtype=np.float32),
        np.empty((8, 8), dtype=np.int32),
        np.empty((8, 8, 3), dtype=np.float32),
    )
    bands = np.zeros(1, dtype=np.intp)
    return bands, setup, rows, offsets, items, inv_depth, triangle_id, surfaces, out


def warm_rows() -> None:
    """Compile the shading of a row, which every raster method's shading pass calls.

    With the types the passes hand it: a row of each visibility buffer, int64 rows.
    """
    _, _, _, _, _, inv_depth, triangle_id, surfaces, out = _tiny_shading_pass()
    compile_for(_shade_row, np.intp(0), 0, 0, triangle_id[0], inv_depth[0], surfaces, out,
                new_batch(inv_depth.shape[1]))


def warm_colours() -> None:
    """Compile the look-up of a row's surface colours, the passes' for coloured surfaces."""
    _, _, _, _, _, inv_depth, triangle_id, surfaces, _ = _tiny_shading_pass()
    compile_for(_row_surface_colors, np.intp(0), 0, triangle_id[0], surfaces,
                new_batch(inv_depth.shape[1]))


def warm_back() -> None:
    """Compile the z-buffer's fused pass for plain scenes: depth test and shading, by bands.

    After ``rows`` (``pixelpath._warm.FOLLOWS``), whose row shading it calls. By the time the
    pass needs its depth test, the group ``depth-test``, compiled at once in another process
    (``pixelpath._warm.FEEDS``), has put that in the disk cache, and this process loads it
    instead of compiling it too.
    """
    _warm_fused_pass(with_lookups=False)


def warm_back_lookups() -> None:
    """Compile the z-buffer's fused pass with the alpha test and the colour lookups.

    As ``back``; the lookups come from the group ``colours``, the depth test from
    ``depth-test-lookups``.
    """
    _warm_fused_pass(with_lookups=True)


def _warm_fused_pass(with_lookups: bool) -> None:
    bands, setup, rows, offsets, items, inv_depth, triangle_id, surfaces, out = (
        _tiny_shading_pass()
    )
    cutouts = tiny_cutouts(setup, surfaces.triangles) if with_lookups else None
    render_bands(bands, setup, rows, offsets, items, BAND_ROWS, 0, 0, inv_depth, triangle_id,
                 cutouts, surfaces, surfaces.tables if with_lookups else None,
                 new_batch(inv_depth.shape[1]), out)


def warm_depth_test() -> None:
    """Compile the z-buffer's depth test of a band for plain scenes, as its fused pass calls it."""
    _warm_depth_test(with_lookups=False)


def warm_depth_test_lookups() -> None:
    """Compile the z-buffer's depth test of a band with the alpha test."""
    _warm_depth_test(with_lookups=True)


def _warm_depth_test(with_lookups: bool) -> None:
    bands, setup, rows, offsets, items, inv_depth, triangle_id, surfaces, _ = (
        _tiny_shading_pass()
    )
    first, stop = _band_rows(bands[0], BAND_ROWS, 0, inv_depth.shape[0])
    compile_for(_rasterize_band, setup, rows, offsets, items, bands[0], first, stop, 0, first,
                inv_depth, triangle_id,
                tiny_cutouts(setup, surfaces.triangles) if with_lookups else None)


def warm_shade() -> None:
    """Compile the shading pass the other methods run on the visibility they decided.

    For plain scenes, after ``rows`` as ``back``; and the count of texture lookups every
    raster method's explain report makes.
    """
    _, _, _, _, _, inv_depth, triangle_id, surfaces, _ = _warm_shading_pass(with_lookups=False)
    counts = np.empty(triangle_id.shape, dtype=np.int32)
    texture_lookups(0, 0, triangle_id, surfaces, counts, counts.copy(), np.empty(inv_depth.shape))


def warm_shade_lookups() -> None:
    """Compile the other methods' shading pass with the colour lookups."""
    _warm_shading_pass(with_lookups=True)


def _warm_shading_pass(with_lookups: bool) -> tuple:
    inputs = _tiny_shading_pass()
    bands, _, _, _, _, inv_depth, triangle_id, surfaces, out = inputs
    shade_bands(bands, BAND_ROWS, 0, 0, inv_depth, triangle_id, surfaces,
                surfaces.tables if with_lookups else None, new_batch(inv_depth.shape[1]), out)
    return inputs


def warm_scan() -> None:
    """Compile the other scan conversions: depth test only, painting in order, coverage."""
    _, triangles, setup, rows, offsets, items, inv_depth, triangle_id = _tiny_triangle()
    bands = np.zeros(1, dtype=np.intp)
    cutouts = tiny_cutouts(setup, triangles)
    rasterize_bands(bands, setup, rows, offsets, items, BAND_ROWS, 0, 0, inv_depth, triangle_id,
                    cutouts)
    paint_bands(bands, setup, rows, offsets, items, np.zeros(1, dtype=np.intp), BAND_ROWS, 0, 0,
                inv_depth, triangle_id, cutouts)
    count_coverage(setup, rows, 0, 0, np.zeros((8, 8), dtype=np.int32))
    interpolate_values(0, 8, setup, triangles, np.ones((3, 1)), triangle_id, np.zeros((8, 8, 1)))
