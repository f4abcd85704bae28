"""Compiled texture lookups and the surface colour they give, shared by rasterizer and tracer.

A scene's textures are packed by :func:`pixelpath.scene.texture.surface_tables` into one
:class:`SurfaceTables` record:

* ``texels`` (N,) uint32: every mip level of every texture, rows of texels one after the
  other, one word a texel whose bytes, lowest first, are its red, green, blue (sRGB-encoded)
  and alpha (linear): one load a texel where four bytes cost three or four;
* ``levels`` (K, 3) intp: first texel, width and height of each level;
* ``textures`` (M, 4) intp: first level, number of levels, filter and wrap of each texture;
* ``objects`` (O, 3) intp: per scene object, its texture (-1 for none, or when it has no
  texture coordinates), whether it has vertex colours, and its emission texture (-1 for
  none, or when it has no texture coordinates or emits nothing);
* ``decode`` (256,) float64: the linear value of each 8-bit sRGB code;
* ``alpha`` (O, 2) float64: per scene object, the material's ``alpha`` and the cutoff of its
  alpha test, 0 for none (an opaque material, or one whose alpha never falls below its
  cutoff: :func:`pixelpath.scene.texture.surface_tables` leaves those untested).

Texel (col, row) of a level w × h has its centre at ``u = (col + 0.5) / w``,
``v = 1 - (row + 0.5) / h`` (v up, row 0 at the top of the picture). ``footprint`` is the
length, in base-level texels, that one pixel covers; trilinear filtering picks the two levels
around ``log2(footprint)`` and blends them (the classic mip-map level of detail).

The alpha test (:func:`cut_away`) reads the texture at the base level whatever the footprint
(:func:`surface_alpha`): a hole's outline stays where the texels put it at any distance,
rather than closing up as coarser levels average alpha away, and the rasterizer and the ray
tracer, which measure footprints differently, cut the same holes.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from pixelpath._jit import inlined, njit

NEAREST, BILINEAR, TRILINEAR = 0, 1, 2
REPEAT, CLAMP, MIRROR = 0, 1, 2
# Columns of SurfaceTables.objects.
TEXTURE, HAS_COLORS, GLOW = 0, 1, 2
# Columns of SurfaceTables.alpha.
BASE_ALPHA, CUTOFF = 0, 1


class SurfaceTables(NamedTuple):
    """What the kernels read to colour a surface point (see the module docstring)."""

    texels: np.ndarray
    levels: np.ndarray
    textures: np.ndarray
    objects: np.ndarray
    decode: np.ndarray
    alpha: np.ndarray


@njit(refcount=False, from_python=False)
def wrapped(index, size, wrap):
    """Return texel ``index`` of a row or column of ``size`` texels under the wrap mode."""
    if wrap == CLAMP:
        return min(max(index, 0), size - 1)
    if wrap == MIRROR:
        period = index % (2 * size)
        return period if period < size else 2 * size - 1 - period
    return index % size


@njit(refcount=False, from_python=False)
def _texel(tables, index):
    """Linear (r, g, b, a) of texel ``index`` of ``tables.texels``.

    Every array is indexed in full (``texels[k]``, not a row view): a view per texel would
    cost a reference count update on the shared table, per lookup.
    """
    word = tables.texels[index]
    decode = tables.decode
    return (decode[word & 255], decode[(word >> 8) & 255], decode[(word >> 16) & 255],
            (word >> 24) / 255.0)


# This helper, the bilinear lookup's below, sample_level and base_color are compiled once and
# inlined by LLVM into every caller (forceinline, see pixelpath._jit): left calls, they cost
# a textured frame speed; copied by Numba, they were typed again in every shading pass and
# alpha test.
@inlined(from_python=True)
def _neighbours(x, size, wrap):
    """Return the texels (i0, i1) on either side of texel coordinate x, and x's fraction past i0.

    ``repeat``, by far the commonest, wraps in floating point: an integer modulo (Python's,
    for negative indices) per texel was most of a bilinear lookup's time. A side that is a
    power of two (every level of a power-of-two picture) wraps with a mask instead, which
    gives the same texels: there the float quotient by ``size`` is exact, so the float
    wrap is the true modulo, as the mask is (two's complement), and a NaN or huge ``x``, whose
    integer part is the same out-of-range value either way, lands on texel 0 both ways. It
    saves the division and second rounding that were a third of a lookup's time.
    """
    floor_x = math.floor(x)
    fraction = x - floor_x
    if wrap == REPEAT and (size & (size - 1)) == 0:
        mask = size - 1
        i0 = np.intp(floor_x) & mask
        return i0, (i0 + 1) & mask, fraction
    if wrap == REPEAT:
        # Clamped as well: far from 0 the float quotient may round across a period's edge.
        i0 = min(max(np.intp(floor_x - size * math.floor(floor_x / size)), 0), size - 1)
        return i0, (i0 + 1 if i0 + 1 < size else np.intp(0)), fraction
    i = np.intp(floor_x)
    return wrapped(i, size, wrap), wrapped(i + 1, size, wrap), fraction


@inlined
def _bilinear(tables, level, wrap, u, v):
    """Bilinear blend of the four texels around (u, v) on one level."""
    start, width, height = tables.levels[level, 0], tables.levels[level, 1], tables.levels[level, 2]
    i00, i10, i01, i11, fx, fy = bilinear_taps(start, width, height, wrap, u, v)
    return blend_taps(tables, i00, i10, i01, i11, fx, fy)


@inlined
def bilinear_taps(start, width, height, wrap, u, v):
    """Return the four texels a bilinear lookup of (u, v) blends on a level, and the fractions.

    The level's texels start at ``start`` in ``tables.texels``, ``width`` × ``height`` of them.
    Returns ``(i00, i10, i01, i11, fx, fy)``: the texels' indices (left and right column, upper
    and lower row) and how far (u, v) lies past the left column and the upper row, which
    :func:`blend_taps` turns into the colour.
    """
    c0, c1, fx = _neighbours(u * width - 0.5, width, wrap)
    r0, r1, fy = _neighbours((1.0 - v) * height - 0.5, height, wrap)
    upper, lower = start + r0 * width, start + r1 * width
    return upper + c0, upper + c1, lower + c0, lower + c1, fx, fy


@inlined
def blend_taps(tables, i00, i10, i01, i11, fx, fy):
    """Linear (r, g, b, a) of the bilinear blend of the texels :func:`bilinear_taps` found."""
    a = _texel(tables, i00)
    b = _texel(tables, i10)
    c = _texel(tables, i01)
    d = _texel(tables, i11)
    w00, w10, w01, w11 = (1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy
    return (
        w00 * a[0] + w10 * b[0] + w01 * c[0] + w11 * d[0],
        w00 * a[1] + w10 * b[1] + w01 * c[1] + w11 * d[1],
        w00 * a[2] + w10 * b[2] + w01 * c[2] + w11 * d[2],
        w00 * a[3] + w10 * b[3] + w01 * c[3] + w11 * d[3],
    )


@njit(inline="always")
def texel_footprint(tables, texture, dudx, dvdx, dudy, dvdy):
    """Length, in base-level texels of ``texture``, that one pixel covers.

    (dudx, dvdx) and (dudy, dvdy) are how far (u, v) moves over one pixel across and down the
    image; the longer of the two steps, in texels, is the footprint.
    """
    return math.sqrt(footprint_squared(tables, texture, dudx, dvdx, dudy, dvdy))


@njit(inline="always")
def footprint_squared(tables, texture, dudx, dvdx, dudy, dvdy):
    """Return the square of :func:`texel_footprint`, for :func:`mip_level_squared`."""
    width, height = base_size(tables, texture)
    return footprint_squared_in(width, height, dudx, dvdx, dudy, dvdy)


@njit(inline="always")
def base_size(tables, texture):
    """Return the width and height of ``texture``'s base level, in texels (as floats)."""
    base = tables.textures[texture, 0]
    return float(tables.levels[base, 1]), float(tables.levels[base, 2])


@njit(inline="always")
def footprint_squared_in(width, height, dudx, dvdx, dudy, dvdy):
    """:func:`footprint_squared` of a texture whose base level is ``width`` x ``height``."""
    across = (dudx * width) ** 2 + (dvdx * height) ** 2
    down = (dudy * width) ** 2 + (dvdy * height) ** 2
    return max(across, down)


@njit(inline="always")
def mip_level(tables, texture, footprint):
    """Return (level, blend): the mip level a lookup reads (0 the base) and the next one's weight.

    ``nearest`` and ``bilinear`` read the base level. ``trilinear`` reads the two levels
    around ``log2(footprint)``, the finer one with weight ``1 - blend`` and the next with
    ``blend``; a blend of 0 reads one level only (the base level when a pixel covers at most
    one texel, the last, 1 x 1, level when it covers the whole texture).
    """
    count = tables.textures[texture, 1]
    # "not >" rather than "<=": a NaN footprint reads the base level.
    if tables.textures[texture, 2] != TRILINEAR or not footprint > 1.0 or count == 1:
        return np.intp(0), 0.0
    lod = min(math.log2(footprint), count - 1.0)
    level = np.intp(lod)
    return level, lod - level


@njit(inline="always")
def mip_level_squared(tables, texture, squared):
    """:func:`mip_level` of the footprint whose square is ``squared``.

    A square of at most 1 is a footprint of at most 1, which reads the base level: only the
    pixels that cover more than a texel pay for the square root (and the logarithm). Where a
    texture is magnified, as on most of the Duck's pixels at 1024², that is few of them.
    """
    if not squared > 1.0:  # a NaN too: mip_level reads the base level for a NaN footprint
        return np.intp(0), 0.0
    return mip_level(tables, texture, math.sqrt(squared))


# A kernel of its own, not inlined by Numba into its callers (the ray tracer's surface colour,
# every alpha test): copied into each, with the lookups it inlines, it made the z-buffer's
# kernels take 35 s of CPU to compile instead of 31 and the ray tracer's 70 s instead of 48
# (one caller, the alpha test, 13 s alone). A textured hit of the ray tracer pays a call for it
# (2-3 % of a textured frame). The rasterizer's lookups, where a call per pixel cost half a
# textured frame, use sample_level and mip_level, which are inlined into them. The lookups
# allocate nothing and only read the tables they are given: compiled without reference
# counting, which would update the shared tables' counts atomically per pixel.
@njit(refcount=False)
def sample(tables, texture, u, v, footprint):
    """Linear (r, g, b, a) of ``texture`` at (u, v), filtered for a pixel of ``footprint`` texels.

    ``nearest`` takes the texel under (u, v) on the base level; ``bilinear`` blends the four
    around it on the level :func:`mip_level` chooses, and ``trilinear`` blends two such
    lookups on consecutive levels when the pixel falls between them.
    """
    level, blend = mip_level(tables, texture, footprint)
    return sample_level(tables, texture, u, v, level, blend)


@inlined
def sample_level(tables, texture, u, v, level, blend):
    """:func:`sample` once :func:`mip_level` has chosen the ``level`` and ``blend``."""
    first, wrap = tables.textures[texture, 0], tables.textures[texture, 3]
    if tables.textures[texture, 2] == NEAREST:
        width, height = tables.levels[first, 1], tables.levels[first, 2]
        col = _neighbours(u * width, width, wrap)[0]
        row = _neighbours((1.0 - v) * height, height, wrap)[0]
        return _texel(tables, tables.levels[first, 0] + row * width + col)
    a = _bilinear(tables, first + level, wrap, u, v)
    if blend == 0.0:
        return a
    b = _bilinear(tables, first + level + 1, wrap, u, v)
    keep = 1.0 - blend
    return (
        keep * a[0] + blend * b[0],
        keep * a[1] + blend * b[1],
        keep * a[2] + blend * b[2],
        keep * a[3] + blend * b[3],
    )


@njit(inline="always")
def colored(tables, obj):
    """Whether object ``obj`` has a surface colour that varies (a texture or vertex colours)."""
    return tables.objects[obj, TEXTURE] >= 0 or tables.objects[obj, HAS_COLORS] != 0


@inlined
def base_color(tables, materials, obj, colors, a, b, c, w0, w1, w2):
    """:func:`surface_color` before the texture: the material's colour × the vertex colours.

    Multiplied by :func:`sample` at the texture coordinates, channel by channel, it gives
    :func:`surface_color`'s values bit for bit (the same products in the same order).
    """
    r, g, bl = materials[obj, 0], materials[obj, 1], materials[obj, 2]
    alpha = tables.alpha[obj, BASE_ALPHA]
    if tables.objects[obj, HAS_COLORS]:
        r *= w0 * colors[a, 0] + w1 * colors[b, 0] + w2 * colors[c, 0]
        g *= w0 * colors[a, 1] + w1 * colors[b, 1] + w2 * colors[c, 1]
        bl *= w0 * colors[a, 2] + w1 * colors[b, 2] + w2 * colors[c, 2]
        alpha *= w0 * colors[a, 3] + w1 * colors[b, 3] + w2 * colors[c, 3]
    return r, g, bl, alpha


@njit(inline="always")
def surface_color(tables, materials, obj, uv, colors, a, b, c, w0, w1, w2, dudx, dvdx, dudy,
                  dvdy):
    """Surface colour (r, g, b, alpha) at barycentric weights (w0, w1, w2) of vertices a, b, c.

    The colour of ``materials[obj]`` × the interpolated vertex colour × the texture at the
    interpolated texture coordinates (the alpha likewise, from the material's ``alpha``).
    (dudx, dvdx) and (dudy, dvdy) are how far (u, v) moves over one pixel across and down the
    image: the longer, in texels, is the footprint that sets the mip level.
    """
    r, g, bl, alpha = base_color(tables, materials, obj, colors, a, b, c, w0, w1, w2)
    texture = tables.objects[obj, TEXTURE]
    if texture >= 0:
        tr, tg, tb, ta = sample_at(tables, texture, uv, a, b, c, w0, w1, w2, dudx, dvdx, dudy,
                                   dvdy)
        r *= tr
        g *= tg
        bl *= tb
        alpha *= ta
    return r, g, bl, alpha


@njit(inline="always")
def sample_at(tables, texture, uv, a, b, c, w0, w1, w2, dudx, dvdx, dudy, dvdy):
    """``texture`` (r, g, b, alpha) at the texture coordinates of weights (w0, w1, w2) of a, b, c.

    Filtered for the footprint that (dudx, dvdx) and (dudy, dvdy) span (:func:`texel_footprint`).
    """
    u, v = texture_coordinates(uv, a, b, c, w0, w1, w2)
    return sample(tables, texture, u, v, texel_footprint(tables, texture, dudx, dvdx, dudy, dvdy))


@njit(inline="always")
def texture_coordinates(uv, a, b, c, w0, w1, w2):
    """(u, v) interpolated at barycentric weights (w0, w1, w2) of vertices a, b, c."""
    return (w0 * uv[a, 0] + w1 * uv[b, 0] + w2 * uv[c, 0],
            w0 * uv[a, 1] + w1 * uv[b, 1] + w2 * uv[c, 1])


@njit(inline="always")
def surface_alpha(tables, obj, uv, colors, a, b, c, w0, w1, w2):
    """Alpha of object ``obj``'s surface at barycentric weights (w0, w1, w2) of vertices a, b, c.

    The material's ``alpha`` × the interpolated vertex colours' alpha × the texture's alpha
    at the interpolated texture coordinates, read on the base level (a footprint of 0: the
    nearest texel, or a bilinear blend of four), as the alpha test reads it.
    """
    alpha = tables.alpha[obj, BASE_ALPHA]
    if tables.objects[obj, HAS_COLORS]:
        alpha *= w0 * colors[a, 3] + w1 * colors[b, 3] + w2 * colors[c, 3]
    texture = tables.objects[obj, TEXTURE]
    if texture >= 0:
        u, v = texture_coordinates(uv, a, b, c, w0, w1, w2)
        alpha *= sample(tables, texture, u, v, 0.0)[3]
    return alpha


@njit(inline="always")
def cut_away(tables, obj, uv, colors, a, b, c, w0, w1, w2):
    """Whether the alpha test cuts object ``obj``'s surface away at weights (w0, w1, w2).

    True where :func:`surface_alpha` is below the object's cutoff (never for an object
    that is not alpha-tested: its cutoff is 0).
    """
    return surface_alpha(tables, obj, uv, colors, a, b, c, w0, w1, w2) < tables.alpha[obj, CUTOFF]


def tiny_tables() -> SurfaceTables:
    """Return a 2 x 2 texture with two levels on object 0, for the kernels' warm-ups.

    Object 0 is alpha-tested (cutoff 0.5), so warm-ups that draw it compile the alpha test,
    and its emission texture is the same picture.
    """
    from pixelpath.scene.texture import decode_table

    texels = np.full(5, 0xFFFFFFFF, dtype=np.uint32)
    texels.flags.writeable = False  # as surface_tables packs them
    return SurfaceTables(
        texels,
        np.array([[0, 2, 2], [4, 1, 1]], dtype=np.intp),
        np.array([[0, 2, TRILINEAR, REPEAT]], dtype=np.intp),
        np.array([[0, 1, 0]], dtype=np.intp),
        decode_table(),  # the real (read-only) table: Numba types read-only arrays apart
        np.array([[1.0, 0.5]]),
    )
