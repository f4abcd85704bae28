"""Compiled raster kernels: screen mapping, triangle set-up, scan conversion, deferred shading.

The pipeline these kernels implement (driven by :mod:`pixelpath.hsr.zbuffer`):

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
without alpha tests.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from pixelpath._jit import njit
from pixelpath.clip._kernels import PLANE, clip_stage
from pixelpath.lighting._kernels import shade_planar, shade_point
from pixelpath.scene._texture_kernels import (
    TEXTURE,
    cut_away,
    mip_level,
    surface_color,
    texel_footprint,
    tiny_tables,
)

FLAT = 0
GOURAUD = 1
PHONG = 2

# Column layout of the per-triangle set-up record (float64).
SORTED_XY = 0  # x0, y0, x1, y1, x2, y2 sorted by y: the triangle's edge table
S1_PLANE = 6  # screen weight of vertex 1: s1 = a x + b y + c
S2_PLANE = 9  # screen weight of vertex 2
KEY_PLANE = 12  # depth key (1/w in perspective; larger is nearer) = a x + b y + c
VERTEX_INVW = 15  # 1/w at vertices 0, 1, 2 (in the triangle's own order; 1 when orthographic)
SLOPES = 18  # dx/dy of the sorted edges (v0, v2), (v0, v1), (v1, v2); 0 for a horizontal one
SETUP_FIELDS = 21

# The Gouraud vertex colours hold the light from the front (normal as given), then from the
# back (normal reversed, for two-sided faces seen from behind): 3 columns each, the intensity;
# 6 each when the scene has coloured surfaces (textures or vertex colours), which keep the
# light split in two, what their surface colour multiplies (ambient and diffuse) and what it
# does not (the highlight). Flat colours are laid out as one such half.

BAND_ROWS = 32
# Phong pixels gathered per call of the planar shading kernel: a whole row of a 1024-wide frame.
# Fewer, longer calls were measured faster than work arrays small enough for the L1 cache
# (batches of 128 and 256 pixels).
SHADE_BATCH = 1024

# Frustum triangle classes.
OUTSIDE = 0  # every vertex outside one frustum plane: dropped
INSIDE = 1  # in front of the near plane, behind the far plane, inside the guard band: drawn as is
CROSSING = 2  # clipped against the six planes

# The six frustum planes in clip space as boundary rows of the clipping kernel:
# [PLANE, c0, c1, c2, c3], the half-space c · (x, y, z, w) >= 0.
FRUSTUM_PLANES = np.array(
    [
        [PLANE, 0.0, 0.0, 1.0, 1.0],  # near: z >= -w
        [PLANE, 0.0, 0.0, -1.0, 1.0],  # far: z <= w
        [PLANE, 1.0, 0.0, 0.0, 1.0],  # left: x >= -w
        [PLANE, -1.0, 0.0, 0.0, 1.0],  # right: x <= w
        [PLANE, 0.0, 1.0, 0.0, 1.0],  # bottom: y >= -w
        [PLANE, 0.0, -1.0, 0.0, 1.0],  # top: y <= w
    ]
)
# Triangles within GUARD_BAND times the view's half-width are rasterized without x/y clipping
# (the scan converter clamps spans to the image); only larger ones are clipped exactly.
GUARD_BAND = 8.0
# Room for a triangle clipped by the six planes. In exact arithmetic it stays convex and gains
# at most one vertex per plane (9); rounding on nearly degenerate input could break convexity,
# so the buffers follow the general bound of a stage, n + n // 2 vertices: 3, 4, 6, 9, 13, 19,
# 28.
MAX_CLIPPED = 28


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
    lights: np.ndarray  # (L, 7) packed lights
    ambient: np.ndarray  # (3,) ambient intensity
    eye: np.ndarray  # (4,) the camera's homogeneous viewpoint (eye, 1) or (-d, 0)
    background: np.ndarray  # (3,) colour where nothing is drawn
    mode: int  # FLAT, GOURAUD or PHONG
    blinn: bool  # Blinn-Phong highlights
    orthographic: bool  # the depth key is affine in depth (else 1/w)
    near: float  # the camera's near and far distances (an orthographic key's depth)
    far: float


class Cutouts(NamedTuple):
    """What the alpha test of the visibility pass reads about the drawn triangles.

    Only triangles with ``masked`` set are tested (their object's material has an alpha
    cutoff its alpha can fall below: ``SurfaceTables.alpha``); the other arrays are the
    shading pass's own (see :class:`Surfaces`).
    """

    masked: np.ndarray  # (T,) bool: the triangle's surface may be cut away
    setup: np.ndarray  # (T, SETUP_FIELDS) set-up records
    triangles: np.ndarray  # (T, 3) vertex indices
    info: np.ndarray  # (T, 2) object index, flip flag
    uv: np.ndarray  # (V, 2) texture coordinates; (0, 2) when nothing is textured
    vertex_colors: np.ndarray  # (V, 4) vertex colours; (0, 4) when no object has them
    tables: object  # SurfaceTables: textures, alpha and cutoff of each object


class Buffers(NamedTuple):
    """The output buffers of a frame (or of a region of one)."""

    rgb: np.ndarray  # (h, w, 3) float32 clamped intensities
    depth: np.ndarray  # (h, w) float32 view-axis depth, inf where nothing is drawn
    object_id: np.ndarray  # (h, w) int32 object index, -1 where nothing is drawn
    normal: np.ndarray  # (h, w, 3) float32 unit shading normal, 0 where nothing is drawn


@njit(inline="always")
def faces_away(normal, point, eye):
    """Return the object-space back-face test N · (w P − E) >= 0 (V from the eye inwards).

    ``eye`` (4,) is homogeneous (``Camera.viewpoint``): (eye, 1) gives N · (P − eye), and the
    orthographic viewer at infinity, (−d, 0), gives N · d with d the viewing direction.
    """
    return (
        normal[0] * (eye[3] * point[0] - eye[0])
        + normal[1] * (eye[3] * point[1] - eye[1])
        + normal[2] * (eye[3] * point[2] - eye[2])
        >= 0.0
    )


@njit
def front_facing_many(normals, points, eye, out):
    """Write whether each face (F,) turns towards the eye (not :func:`faces_away`)."""
    for f in range(normals.shape[0]):
        out[f] = not faces_away(normals[f], points[f], eye)


@njit(inline="always")
def _outcode(x, y, z, w):
    """Return bit p set when the vertex is outside FRUSTUM_PLANES[p]."""
    code = 0
    if z < -w:
        code |= 1
    if z > w:
        code |= 2
    if x < -w:
        code |= 4
    if x > w:
        code |= 8
    if y < -w:
        code |= 16
    if y > w:
        code |= 32
    return code


@njit
def classify_triangles(clip, triangles, keep, status):
    """Sort each kept triangle (T,) into OUTSIDE, INSIDE or CROSSING the view frustum."""
    for t in range(triangles.shape[0]):
        status[t] = OUTSIDE
        if not keep[t]:
            continue
        outside_all = 63
        needs_clip = False
        for corner in range(3):
            v = triangles[t, corner]
            x, y, z, w = clip[v, 0], clip[v, 1], clip[v, 2], clip[v, 3]
            outside_all &= _outcode(x, y, z, w)
            band = GUARD_BAND * w
            if z < -w or z > w or abs(x) > band or abs(y) > band:
                needs_clip = True
        if outside_all == 0:
            status[t] = CROSSING if needs_clip else INSIDE


@njit
def clip_triangles(attributes, triangles, crossing):
    """Clip the listed triangles against the frustum with Sutherland-Hodgman.

    Returns the new vertices (N, k) (indices continue after ``attributes``), their fan
    triangles (M, 3) and, per new triangle, the index of the triangle it came from.
    """
    k = attributes.shape[1]
    offset = attributes.shape[0]
    # Sized for the usual case (a convex piece of at most 9 vertices), grown when exceeded.
    vertices = np.empty((crossing.shape[0] * 9, k))
    new_triangles = np.empty((crossing.shape[0] * 7, 3), dtype=np.intp)
    source = np.empty(crossing.shape[0] * 7, dtype=np.intp)
    polygon = np.empty((MAX_CLIPPED + 1, k))
    scratch = np.empty((MAX_CLIPPED + 1, k))
    untraced = np.empty((0, 2))  # no room to record crossings: the stages keep no trace
    n_vertices = 0
    n_triangles = 0
    for t in crossing:
        for corner in range(3):
            _copy_row(attributes, triangles[t, corner], polygon, corner)
        n = triangles.shape[1]  # 3, typed int64 rather than literal (one clip_stage build)
        src, dst = polygon, scratch
        for p in range(6):
            n = clip_stage(src, n, FRUSTUM_PLANES[p], dst, untraced)
            src, dst = dst, src
        if n < 3:
            continue
        if n_vertices + n > vertices.shape[0]:
            vertices = _grown_rows(vertices, n_vertices + n)
        if n_triangles + n - 2 > source.shape[0]:
            new_triangles = _grown_rows(new_triangles, n_triangles + n - 2)
            source = _grown(source, n_triangles + n - 2)
        for corner in range(n):
            _copy_row(src, corner, vertices, n_vertices + corner)
        for fan in range(1, n - 1):
            new_triangles[n_triangles, 0] = offset + n_vertices
            new_triangles[n_triangles, 1] = offset + n_vertices + fan
            new_triangles[n_triangles, 2] = offset + n_vertices + fan + 1
            source[n_triangles] = t
            n_triangles += 1
        n_vertices += n
    return vertices[:n_vertices], new_triangles[:n_triangles], source[:n_triangles]


# Element-by-element copies: slice assignment would make Numba compile its shape-mismatch error
# messages (string formatting), seconds of first-run compile time for code that never runs.
@njit(inline="always")
def _copy_row(source, source_row, target, target_row):
    for column in range(source.shape[1]):
        target[target_row, column] = source[source_row, column]


@njit
def _grown_rows(array, needed):
    """Return a copy of the 2-D ``array`` with room for at least ``needed`` rows (doubling)."""
    bigger = np.empty((max(needed, 2 * array.shape[0]), array.shape[1]), dtype=array.dtype)
    for row in range(array.shape[0]):
        _copy_row(array, row, bigger, row)
    return bigger


@njit
def _grown(array, needed):
    """Return a copy of the 1-D ``array`` with room for at least ``needed`` items (doubling)."""
    bigger = np.empty(max(needed, 2 * array.shape[0]), dtype=array.dtype)
    for k in range(array.shape[0]):
        bigger[k] = array[k]
    return bigger


# Cutting a triangle by a plane (the painter's and BSP methods' polygon splitting).
@njit
def cut_triangle(vertices, count, corners, distances, eps, pieces, cut_edges, cut_params):
    """Cut a triangle by a plane into pieces that each lie on one side of it.

    Parameters
    ----------
    vertices : (V, k) float64
        Per-vertex rows (a position and any attributes, all interpolated linearly along a cut
        edge); rows ``[0, count)`` are in use. Grown (doubled) when full: keep the returned one.
    corners : (3,) intp
        The triangle's vertex indices.
    distances : (3,) float64
        Signed distances of its corners to the plane; within ``eps`` a corner lies on it.
    pieces : (3, 4) intp, out
        Per piece: its three vertex indices (in the triangle's winding) and its side, +1 where
        the distances are positive, -1 where negative.
    cut_edges : (2, 2) intp, out; cut_params : (2,) float64, out
        Per new vertex: the edge it cuts (lower vertex index first) and its parameter along it.

    Returns
    -------
    (vertices, count, n_pieces)
        ``n_pieces`` is 0 when the triangle does not straddle the plane (nothing is written),
        else 2 (a corner on the plane: one new vertex) or 3 (two new vertices).
    """
    s0, s1, s2 = _side(distances[0], eps), _side(distances[1], eps), _side(distances[2], eps)
    if max(s0, s1, s2) < 1 or min(s0, s1, s2) > -1:
        return vertices, count, 0
    if count + 2 > vertices.shape[0]:
        vertices = _grown_rows(vertices, count + 2)
    # The corner on the plane, or else the corner alone on its side, comes first.
    if s0 * s1 * s2 == 0:
        lone = 0 if s0 == 0 else (1 if s1 == 0 else 2)
    else:
        lone = 0 if s1 == s2 else (1 if s0 == s2 else 2)
    a, b, c = corners[lone], corners[(lone + 1) % 3], corners[(lone + 2) % 3]
    da, db, dc = distances[lone], distances[(lone + 1) % 3], distances[(lone + 2) % 3]
    side_a, side_b = _side(da, eps), _side(db, eps)
    if side_a == 0:
        m = _cut_edge(vertices, count, b, db, c, dc, cut_edges, cut_params, 0)
        _store_piece(pieces, 0, a, b, m, side_b)
        _store_piece(pieces, 1, a, m, c, -side_b)
        return vertices, count + 1, 2
    m_ab = _cut_edge(vertices, count, a, da, b, db, cut_edges, cut_params, 0)
    m_ca = _cut_edge(vertices, count + 1, c, dc, a, da, cut_edges, cut_params, 1)
    _store_piece(pieces, 0, a, m_ab, m_ca, side_a)
    _store_piece(pieces, 1, m_ab, b, c, side_b)
    _store_piece(pieces, 2, m_ab, c, m_ca, side_b)
    return vertices, count + 2, 3


@njit(inline="always")
def _cut_edge(vertices, row, i, di, j, dj, cut_edges, cut_params, slot):
    """Write at ``row`` the point where edge (i, j) meets the plane; return ``row``.

    Always interpolated from the lower vertex index, so an edge shared by two triangles gets
    the same bits from both.
    """
    if j < i:
        i, di, j, dj = j, dj, i, di
    s = di / (di - dj)
    for column in range(vertices.shape[1]):
        start = vertices[i, column]
        vertices[row, column] = start + s * (vertices[j, column] - start)
    cut_edges[slot, 0] = i
    cut_edges[slot, 1] = j
    cut_params[slot] = s
    return row


@njit(inline="always")
def _side(distance, eps):
    """+1, -1 or 0 (on the plane, within eps)."""
    if distance > eps:
        return 1
    if distance < -eps:
        return -1
    return 0


@njit(inline="always")
def _store_piece(pieces, slot, a, b, c, side):
    pieces[slot, 0] = a
    pieces[slot, 1] = b
    pieces[slot, 2] = c
    pieces[slot, 3] = side


@njit(error_model="numpy")
def clip_to_screen(clip, width, height, orthographic, screen):
    """Write (x_screen, y_screen, key) of each clip-space vertex (V, 4) into screen (V, 3).

    A vertex in the eye's plane (w = 0, such as the point of a plane's grid under an eye
    looking along the plane) maps to infinity, not an error: only vertices of triangles that
    were dropped or clipped can lie there, and those are never drawn.
    """
    for v in range(clip.shape[0]):
        screen_point(clip, v, width, height, orthographic, screen, v)


@njit(inline="always")
def screen_point(clip, row, width, height, orthographic, screen, screen_row):
    """Divide and map one clip-space vertex: ``screen[screen_row] = (x, y, key)``.

    The one formula of the viewport and of the depth key, shared by :func:`clip_to_screen`
    and by the methods that make vertices of their own (the painter's splits), so equal inputs
    give equal bits.
    """
    inv_w = 1.0 / clip[row, 3]
    screen[screen_row, 0] = (clip[row, 0] * inv_w + 1.0) * 0.5 * width
    screen[screen_row, 1] = (1.0 - clip[row, 1] * inv_w) * 0.5 * height
    key = ORTHO_KEY_AT_NDC_0 - 0.5 * clip[row, 2] * inv_w if orthographic else inv_w
    screen[screen_row, 2] = key


# The orthographic depth key is ORTHO_KEY_AT_NDC_0 - z_ndc / 2: 2 on the near plane
# (z_ndc = -1) and 1 on the far one, positive everywhere in the view volume, so "nothing drawn"
# stays key 0 as in perspective. It spends the doubles' resolution evenly over [near, far].
ORTHO_KEY_AT_NDC_0 = 1.5


@njit(inline="always")
def key_depth(key, orthographic, near, far):
    """Return the view-axis depth of a depth key (``inf`` for 0: nothing drawn).

    Conditional expressions on cheap values, not branches: the shading pass's row loop,
    which turns every pixel's key into its depth, stays vectorizable.
    """
    affine = 0.5 * ((far - near) * (2.0 * (ORTHO_KEY_AT_NDC_0 - key)) + (far + near))
    return (affine if orthographic else 1.0 / key) if key > 0.0 else np.inf


@njit(inline="always")
def _plane(xa, ya, va, xb, yb, vb, xc, yc, vc, inv_area2):
    """Coefficients (a, b, c) of the affine function through three screen points' values."""
    a = ((vb - va) * (yc - ya) - (vc - va) * (yb - ya)) * inv_area2
    b = ((vc - va) * (xb - xa) - (vb - va) * (xc - xa)) * inv_area2
    return a, b, va - a * xa - b * ya


@njit(inline="always")
def _store3(record, start, values):
    record[start] = values[0]
    record[start + 1] = values[1]
    record[start + 2] = values[2]


@njit(inline="always")
def _above(xa, ya, xb, yb):
    """Whether point a comes before point b in scan order (smaller y, then smaller x)."""
    return ya < yb or (ya == yb and xa < xb)


# A triangle thinner than this (twice its area, in square pixels) draws nothing, and an edge
# rising less than MIN_EDGE_RISE pixels counts as horizontal: their plane coefficients and
# slopes would overflow (a warning without the JIT, inf and NaN spans with it), for shapes that
# could hold a pixel centre only by exact coincidence. Every method shares this set-up, so they
# all agree on such triangles.
MIN_AREA2 = 1e-200
MIN_EDGE_RISE = 1e-200


@njit
def setup_triangles(screen, triangles, orthographic, row_first, row_stop, setup, rows):
    """Fill the set-up record (T, SETUP_FIELDS) and the covered rows [first, stop) (T, 2).

    Rows are image rows, clipped to the rendered region's rows [row_first, row_stop).
    ``screen`` (V, 3) holds (x, y, depth key); perspective keys are the vertices' 1/w, the
    weights of perspective-correct interpolation, while orthographic vertices all weigh 1.

    Serial on purpose: it costs well under a millisecond for 70k triangles, less than waking
    the worker threads for a parallel loop (only ``render_bands`` is worth that).
    """
    for t in range(triangles.shape[0]):
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        xa, ya, wa = screen[a, 0], screen[a, 1], screen[a, 2]
        xb, yb, wb = screen[b, 0], screen[b, 1], screen[b, 2]
        xc, yc, wc = screen[c, 0], screen[c, 1], screen[c, 2]
        area2 = (xb - xa) * (yc - ya) - (xc - xa) * (yb - ya)
        rows[t, 0] = 0
        rows[t, 1] = 0
        # Degenerate, non-finite, or too thin for its planes (MIN_AREA2): no pixel.
        if not (math.isfinite(area2) and abs(area2) >= MIN_AREA2):
            continue
        inv = 1.0 / area2
        record = setup[t]
        _store3(record, S1_PLANE, _plane(xa, ya, 0.0, xb, yb, 1.0, xc, yc, 0.0, inv))
        _store3(record, S2_PLANE, _plane(xa, ya, 0.0, xb, yb, 0.0, xc, yc, 1.0, inv))
        _store3(record, KEY_PLANE, _plane(xa, ya, wa, xb, yb, wb, xc, yc, wc, inv))
        _store3(record, VERTEX_INVW, (1.0, 1.0, 1.0) if orthographic else (wa, wb, wc))
        # Edge table: vertices sorted by y, ties by x, so every edge runs from its upper end.
        if _above(xb, yb, xa, ya):
            xa, ya, xb, yb = xb, yb, xa, ya
        if _above(xc, yc, xb, yb):
            xb, yb, xc, yc = xc, yc, xb, yb
            if _above(xb, yb, xa, ya):
                xa, ya, xb, yb = xb, yb, xa, ya
        _store3(record, SORTED_XY, (xa, ya, xb))
        _store3(record, SORTED_XY + 3, (yb, xc, yc))
        long_edge = _slope(xa, ya, xc, yc)
        _store3(record, SLOPES, (long_edge, _slope(xa, ya, xb, yb), _slope(xb, yb, xc, yc)))
        # Rows whose centre j + 0.5 lies in [y_top, y_bottom).
        first = max(math.ceil(ya - 0.5), float(row_first))
        stop = min(math.ceil(yc - 0.5), float(row_stop))
        if first < stop:
            rows[t, 0] = int(first)
            rows[t, 1] = int(stop)


@njit(inline="always")
def _slope(x_top, y_top, x_bottom, y_bottom):
    """Return dx/dy of an edge from its upper end to its lower end (0 when horizontal)."""
    if y_bottom - y_top < MIN_EDGE_RISE:
        return 0.0
    return (x_bottom - x_top) / (y_bottom - y_top)


@njit(inline="always")
def scanline_span(record, y, col_first, col_stop):
    """Pixel columns [first, stop) drawn by a set-up triangle on the scan line at height y.

    The active edge list on scan line y is the long edge (v0, v2) and whichever of (v0, v1),
    (v1, v2) spans y; a horizontal edge is never active. Columns are clipped to the rendered
    region's [col_first, col_stop).
    """
    x0, y0 = record[SORTED_XY], record[SORTED_XY + 1]
    x_long = x0 + (y - y0) * record[SLOPES]
    if y < record[SORTED_XY + 3]:
        x_short = x0 + (y - y0) * record[SLOPES + 1]
    else:
        x1, y1 = record[SORTED_XY + 2], record[SORTED_XY + 3]
        x_short = x1 + (y - y1) * record[SLOPES + 2]
    x_left = min(x_long, x_short)
    x_right = max(x_long, x_short)
    first = max(math.ceil(x_left - 0.5), float(col_first))
    stop = min(math.ceil(x_right - 0.5), float(col_stop))
    return int(first), int(stop)


# How much nearer (larger 1/w) one surface must be than another, relative to the size of the
# terms its value is computed from, before a method decides a whole span or area from its ends
# or corners (scan-line, Warnock). Rounding moves a computed 1/w by a few units in the last place
# of those terms (about 1e-16 of them); with a margin far above that, the surface found nearer
# at the ends is nearer, as the z-buffer computes it, at every pixel between them. Closer calls
# are settled pixel by pixel with the z-buffer's own test (:func:`wins_depth_test`).
NEARER_MARGIN = 1e-12


@njit(inline="always")
def clearly_nearer(value, other, scale):
    """Whether 1/w ``value`` beats ``other`` by more than rounding of terms of size ``scale``."""
    return value - other > NEARER_MARGIN * scale


@njit(inline="always")
def wins_depth_test(value, t, best_value, best_t):
    """Return whether triangle t, at 1/w ``value``, replaces the best: the z-buffer's test.

    Larger 1/w is nearer; a tie goes to the lower triangle index (the z-buffer visits triangles
    in ascending order and replaces only on strictly nearer). Start from (0.0, -1): nothing at
    1/w <= 0 is drawn, as in the z-buffer, whose buffer starts at 0.
    """
    return value > best_value or (value == best_value and t < best_t)


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


@njit
def _clear_band(first, stop, y0, inv_depth, triangle_id):
    """Mark rows [first, stop) of the region as empty: 1/w = 0 (infinitely far), no triangle."""
    for j in range(first - y0, stop - y0):
        for i in range(inv_depth.shape[1]):
            inv_depth[j, i] = 0.0
            triangle_id[j, i] = -1


@njit
def _rasterize_band(setup, rows, offsets, items, band, band_rows, x0, y0, inv_depth, triangle_id,
                    cutouts):
    """Clear one band of rows, then depth-test its triangles' pixels (nearest 1/w wins).

    The buffers (h, w) cover image columns [x0, x0 + w) and rows [y0, y0 + h); pixel centres
    are computed in image coordinates, so a region gets exactly the pixels of the whole image.
    Alpha-tested triangles (``cutouts.masked``) go through :func:`_draw_masked`.
    """
    height, width = inv_depth.shape
    band_first, band_stop = _band_rows(band, band_rows, y0, height)
    _clear_band(band_first, band_stop, y0, inv_depth, triangle_id)
    masked = cutouts.masked
    for k in range(offsets[band], offsets[band + 1]):
        t = items[k]
        if masked[t]:
            _draw_masked(t, max(rows[t, 0], band_first), min(rows[t, 1], band_stop), x0, y0,
                         inv_depth, triangle_id, cutouts, True)
            continue
        record = setup[t]
        pa, pb, pc = record[KEY_PLANE], record[KEY_PLANE + 1], record[KEY_PLANE + 2]
        for j in range(max(rows[t, 0], band_first), min(rows[t, 1], band_stop)):
            y = j + 0.5
            first, stop = scanline_span(record, y, x0, x0 + width)
            row_value = pb * y + pc
            for i in range(first, stop):
                inv_w = pa * (i + 0.5) + row_value
                if inv_w > inv_depth[j - y0, i - x0]:
                    inv_depth[j - y0, i - x0] = inv_w
                    triangle_id[j - y0, i - x0] = t


@njit
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
        _rasterize_band(
            setup, rows, offsets, items, band, band_rows, x0, y0, inv_depth, triangle_id,
            cutouts,
        )


@njit
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


@njit(inline="always")
def perspective_weights(record, x, y):
    """Perspective-correct barycentric weights (b0, b1, b2) of a set-up triangle at (x, y)."""
    s1 = record[S1_PLANE] * x + record[S1_PLANE + 1] * y + record[S1_PLANE + 2]
    s2 = record[S2_PLANE] * x + record[S2_PLANE + 1] * y + record[S2_PLANE + 2]
    t0 = (1.0 - s1 - s2) * record[VERTEX_INVW]
    t1 = s1 * record[VERTEX_INVW + 1]
    t2 = s2 * record[VERTEX_INVW + 2]
    scale = 1.0 / (t0 + t1 + t2)
    return t0 * scale, t1 * scale, t2 * scale


@njit(refcount=False)
def cut_away_at(cutouts, t, x, y):
    """Whether triangle t's surface is cut away by its alpha test at pixel centre (x, y).

    The alpha is taken at the perspective-correct weights the shading pass uses there
    (:func:`pixelpath.scene._texture_kernels.cut_away`). Ask only for triangles with
    ``cutouts.masked`` set; compiled without reference counting, like the lookups.
    """
    terms = _perspective_terms(cutouts.setup, t, x, y)
    triangles = cutouts.triangles
    return cut_away(cutouts.tables, cutouts.info[t, 0], cutouts.uv, cutouts.vertex_colors,
                    triangles[t, 0], triangles[t, 1], triangles[t, 2], terms[0], terms[1],
                    terms[2])


@njit
def interpolate_values(first, stop, setup, triangles, values, triangle_id, out):
    """Interpolate per-vertex values (V, C) over the drawn pixels of rows [first, stop)."""
    width = triangle_id.shape[1]
    for j in range(first, stop):
        for i in range(width):
            t = triangle_id[j, i]
            if t < 0:
                continue
            b0, b1, b2 = perspective_weights(setup[t], i + 0.5, j + 0.5)
            a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
            for channel in range(values.shape[1]):
                out[j, i, channel] = (
                    b0 * values[a, channel] + b1 * values[b, channel] + b2 * values[c, channel]
                )


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


@njit(inline="always")
def _mix(values, a, b, c, w0, w1, w2, column):
    """Weighted sum of one column of per-vertex values over a triangle's vertices a, b, c."""
    return w0 * values[a, column] + w1 * values[b, column] + w2 * values[c, column]


@njit(inline="always")
def _clamp01(value):
    return min(max(value, 0.0), 1.0)


@njit
def _new_batch(width):
    return PhongBatch(
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((3, SHADE_BATCH)),
        np.empty((5, SHADE_BATCH)),
        np.empty(SHADE_BATCH),
        np.empty(SHADE_BATCH, dtype=np.intp),
        np.empty((width, 3)),
    )


@njit
def render_bands(bands, setup, rows, offsets, items, band_rows, x0, y0, inv_depth, triangle_id,
                 cutouts, surfaces, out):
    """Rasterize the listed bands of rows with the depth test, then shade them (the z-buffer).

    One pass per band: its depth and triangle buffers are still in cache when it is shaded.
    Serial, and called on runs of the band list from several threads at once (it releases
    the GIL): a ``parallel=True`` loop cost seconds more to compile on a first run.
    """
    height = inv_depth.shape[0]
    for k in range(bands.shape[0]):
        band = bands[k]
        _rasterize_band(
            setup, rows, offsets, items, band, band_rows, x0, y0, inv_depth, triangle_id,
            cutouts,
        )
        batch = _new_batch(inv_depth.shape[1])
        first, stop = _band_rows(band, band_rows, y0, height)
        for j in range(first, stop):
            _shade_row(j, x0, y0, triangle_id, inv_depth, surfaces, out, batch)


@njit
def shade_bands(bands, band_rows, x0, y0, inv_depth, triangle_id, surfaces, out):
    """Shade the listed bands from visibility buffers a hidden-surface method filled.

    ``inv_depth`` (h, w) holds 1/w of the visible surface (0 where nothing is drawn) and
    ``triangle_id`` (h, w) its triangle (-1 there), for the region whose top-left pixel is
    (x0, y0). Writes clamped RGB (h, w, 3) (``surfaces.background`` where nothing was drawn),
    the view-axis depth (h, w) (``inf`` there) and the object id (h, w) (-1 there) into
    ``out``.
    """
    height = inv_depth.shape[0]
    for k in range(bands.shape[0]):
        batch = _new_batch(inv_depth.shape[1])
        first, stop = _band_rows(bands[k], band_rows, y0, height)
        for j in range(first, stop):
            _shade_row(j, x0, y0, triangle_id, inv_depth, surfaces, out, batch)


@njit
def _shade_row(j, x0, y0, triangle_id, inv_depth, surfaces, out, batch):
    """Fill image row j of the output buffers from the triangle seen at each of its pixels.

    This is the one shading pass of every raster method. Phong pixels are gathered
    (interpolated point and unit normal, planar, and the object colour) into ``batch`` and
    shaded together by :func:`_shade_batch` when it is full, when the object changes, and at
    the end of the row. A coloured surface (texture or vertex colours) has its colour looked
    up at every pixel, whatever the shading mode: flat and Gouraud shading are about where the
    light is computed, and its ambient and diffuse parts are then tinted by the colour there.
    """
    s = surfaces
    row = j - y0
    rgb = out.rgb[row]
    normal = out.normal[row]
    count = np.intp(0)  # not a literal 0: that would compile a second _shade_batch
    batch_object = -1
    line_triangle = -1
    line = (0.0,) * 14
    y = j + 0.5
    _fill_row(inv_depth[row], s.background, rgb, out.depth[row], out.object_id[row], normal,
              s.orthographic, s.near, s.far)
    ids = triangle_id[row]
    half = s.colors.shape[1] // 2  # Gouraud: the columns of the light from the front
    if s.uv.shape[0] > 0 or s.vertex_colors.shape[0] > 0:
        _row_surface_colors(j, x0, ids, s.info, s.setup, s.triangles, s.uv, s.vertex_colors,
                            s.tables, s.materials, s.coloured, batch.row_colors)
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
                    rgb[i, channel] = _clamp01(value)
                continue
            b0, b1, b2 = perspective_weights(s.setup[t], x, y)
            a, b, c = s.triangles[t, 0], s.triangles[t, 1], s.triangles[t, 2]
            _store_normal(normal, i, s.normals, a, b, c, b0, b1, b2, s.info[t, 1])
            first = half if s.info[t, 1] else 0
            for channel in range(3):
                value = _mix(s.colors, a, b, c, b0, b1, b2, first + channel) * tint[channel]
                if coloured:
                    value += _mix(s.colors, a, b, c, b0, b1, b2, first + 3 + channel)
                rgb[i, channel] = _clamp01(value)
            continue
        if count == SHADE_BATCH or (count > 0 and obj != batch_object):
            _shade_batch(count, batch, s.materials[batch_object], s, rgb, normal)
            count = np.intp(0)
        batch_object = obj
        if t != line_triangle:
            line_triangle = t
            sign = -1.0 if s.info[t, 1] else 1.0
            line = _scanline_surface(s.setup[t], y, s.triangles[t], s.positions, s.normals, sign)
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
        _shade_batch(count, batch, s.materials[batch_object], s, rgb, normal)


@njit(inline="always")
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


@njit(inline="always")
def _perspective_terms(setup, t, x, y):
    """Weights and screen gradients of triangle t at pixel centre (x, y).

    Returns the perspective-correct weights ``b_k = t_k / D`` (``t_k = s_k / w_k``, D their
    sum, the interpolated 1/w), ``1 / D``, then ``d t_k / dx`` and ``d t_k / dy`` (constants:
    the ``t_k`` are affine in screen space): 10 numbers.
    """
    w0, w1, w2 = setup[t, VERTEX_INVW], setup[t, VERTEX_INVW + 1], setup[t, VERTEX_INVW + 2]
    # s1 = x1 x + y1 y + c1 and s2 = x2 x + y2 y + c2: the screen weights' planes.
    x1, y1, c1 = setup[t, S1_PLANE], setup[t, S1_PLANE + 1], setup[t, S1_PLANE + 2]
    x2, y2, c2 = setup[t, S2_PLANE], setup[t, S2_PLANE + 1], setup[t, S2_PLANE + 2]
    s1 = x1 * x + y1 * y + c1
    s2 = x2 * x + y2 * y + c2
    t0, t1, t2 = (1.0 - s1 - s2) * w0, s1 * w1, s2 * w2
    inv = 1.0 / (t0 + t1 + t2)
    return (
        t0 * inv, t1 * inv, t2 * inv, inv,
        -(x1 + x2) * w0, x1 * w1, x2 * w2,
        -(y1 + y2) * w0, y1 * w1, y2 * w2,
    )


@njit(inline="always")
def texture_coordinates(terms, uv, a, b, c):
    """Return (u, v, du/dx, dv/dx, du/dy, dv/dy) of a triangle (vertices a, b, c) at a pixel.

    ``terms`` are the triangle's :func:`_perspective_terms` at the pixel's centre.

    The texture coordinates are interpolated perspective-correctly and differentiated along
    the image's rows and columns, which gives how far they move over one pixel (the
    footprint that chooses the mip level): for ``u = sum t_k u_k / D`` with affine ``t_k``,
    ``du/dx = (sum t_k,x u_k - u sum t_k,x) / D``. Shared by the shading pass and the
    explain report's count of mip levels, so both see the same footprint.
    """
    b0, b1, b2, inv, gx0, gx1, gx2, gy0, gy1, gy2 = terms
    u = _mix(uv, a, b, c, b0, b1, b2, 0)
    v = _mix(uv, a, b, c, b0, b1, b2, 1)
    gx, gy = gx0 + gx1 + gx2, gy0 + gy1 + gy2
    dudx = (_mix(uv, a, b, c, gx0, gx1, gx2, 0) - u * gx) * inv
    dvdx = (_mix(uv, a, b, c, gx0, gx1, gx2, 1) - v * gx) * inv
    dudy = (_mix(uv, a, b, c, gy0, gy1, gy2, 0) - u * gy) * inv
    dvdy = (_mix(uv, a, b, c, gy0, gy1, gy2, 1) - v * gy) * inv
    return u, v, dudx, dvdx, dudy, dvdy


@njit(refcount=False)
def _row_surface_colors(j, x0, ids, info, setup, triangles, uv, vertex_colors, tables,
                        materials, coloured, out):
    """Write the surface colour (r, g, b) of row j's pixels that show a coloured object.

    One call per row, compiled without reference counting: the lookups' arrays are handed
    on per pixel without the atomic count updates a counted kernel makes at each call.
    """
    y = j + 0.5
    for i in range(ids.shape[0]):
        t = ids[i]
        if t < 0 or not coloured[info[t, 0]]:
            continue
        x = (x0 + i) + 0.5
        terms = _perspective_terms(setup, t, x, y)
        b0, b1, b2 = terms[0], terms[1], terms[2]
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        dudx = dvdx = dudy = dvdy = 0.0
        if uv.shape[0] > 0:
            _, _, dudx, dvdx, dudy, dvdy = texture_coordinates(terms, uv, a, b, c)
        r, g, bl, _ = surface_color(tables, materials, info[t, 0], uv, vertex_colors, a, b, c,
                                    b0, b1, b2, dudx, dvdx, dudy, dvdy)
        out[i, 0] = r
        out[i, 1] = g
        out[i, 2] = bl


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
            terms = _perspective_terms(s.setup, t, x, y)
            _, _, dudx, dvdx, dudy, dvdy = texture_coordinates(terms, s.uv, a, b, c)
            footprint = texel_footprint(s.tables, k, dudx, dvdx, dudy, dvdy)
            texture[row, i] = k
            level[row, i], blend[row, i] = mip_level(s.tables, k, footprint)


@njit(inline="always")
def _scanline_surface(record, y, corners, positions, normals, sign):
    """Surface point and normal of a set-up triangle along scan line y, as functions of x.

    The perspective weights are ``b_k = t_k / sum t`` with ``t_k = s_k / w_k`` affine in x on
    the line, so an interpolated attribute is (u x + v) / (d x + e). Returns (d, e), then
    (u, v) for the point's x, y, z and for the normal's (times ``sign``), 14 numbers. The
    normal's denominator (the interpolated 1/w > 0) is left out: normalizing removes it.
    """
    r1 = record[S1_PLANE + 1] * y + record[S1_PLANE + 2]
    r2 = record[S2_PLANE + 1] * y + record[S2_PLANE + 2]
    w0, w1, w2 = record[VERTEX_INVW], record[VERTEX_INVW + 1], record[VERTEX_INVW + 2]
    slope0 = -w0 * (record[S1_PLANE] + record[S2_PLANE])
    slope1 = w1 * record[S1_PLANE]
    slope2 = w2 * record[S2_PLANE]
    base0 = w0 * (1.0 - r1 - r2)
    base1 = w1 * r1
    base2 = w2 * r2
    a, b, c = corners[0], corners[1], corners[2]
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


@njit(error_model="numpy")
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


@njit(error_model="numpy")
def _shade_batch(count, batch, material, surfaces, rgb_row, normal_row):
    """Shade the gathered pixels of one row (one object's); write their colours and normals.

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
        count, batch.points, batch.normals, batch.albedo, surfaces.eye, material,
        surfaces.lights, surfaces.ambient, surfaces.blinn, batch.shaded, batch.scratch,
    )
    for q in range(count):
        i = batch.columns[q]
        for channel in range(3):
            rgb_row[i, channel] = _clamp01(batch.shaded[channel, q])
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


def overlapping_pair():
    """Return the set-up records and rows of two triangles crossing each other on an 8x8 image.

    For the warm-ups of the methods that decide visibility from set-up triangles (scan-line,
    Warnock): real values, so their warm-ups run the kernels' main paths, not only compile them.
    """
    screen = np.array(
        [[1.0, 1.0, 0.5], [7.0, 2.0, 0.5], [3.0, 7.0, 0.5], [0.5, 4.0, 0.2], [7.5, 5.0, 0.9],
         [6.0, 0.5, 0.2]]
    )
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    setup = np.zeros((2, SETUP_FIELDS))
    rows = np.zeros((2, 2), dtype=np.intp)
    setup_triangles(screen, triangles, False, 0, 8, setup, rows)
    return setup, rows


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
        np.ones((3, 4)), tiny_tables(), np.ones(1, dtype=np.bool_), materials, lights, ambient,
        np.array([0.0, 0.0, 5.0, 1.0]), np.zeros(3), PHONG, False, False, 0.1, 10.0,
    )
    out = Buffers(
        np.zeros((8, 8, 3), dtype=np.float32),
        np.empty((8, 8), dtype=np.float32),
        np.empty((8, 8), dtype=np.int32),
        np.empty((8, 8, 3), dtype=np.float32),
    )
    bands = np.zeros(1, dtype=np.intp)
    return bands, setup, rows, offsets, items, inv_depth, triangle_id, surfaces, out


def warm_back() -> None:
    """Compile the z-buffer's fused pass: depth test and shading, band by band."""
    bands, setup, rows, offsets, items, inv_depth, triangle_id, surfaces, out = (
        _tiny_shading_pass()
    )
    render_bands(bands, setup, rows, offsets, items, BAND_ROWS, 0, 0, inv_depth, triangle_id,
                 tiny_cutouts(setup, surfaces.triangles), surfaces, out)


def warm_shade() -> None:
    """Compile the shading pass the other methods run on the visibility they decided.

    And the count of texture lookups every raster method's explain report makes.
    """
    bands, _, _, _, _, inv_depth, triangle_id, surfaces, out = _tiny_shading_pass()
    shade_bands(bands, BAND_ROWS, 0, 0, inv_depth, triangle_id, surfaces, out)
    lookups = np.empty(triangle_id.shape, dtype=np.int32)
    texture_lookups(0, 0, triangle_id, surfaces, lookups, lookups.copy(), np.empty(inv_depth.shape))


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
