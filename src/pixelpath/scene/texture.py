"""Image textures: the picture, its mip-map pyramid and the sampling choices of a material.

Conventions (SPEC, ``pp.Mesh`` and ``pp.Material``):

- Texture coordinates (u, v) run with u to the right and v **up**: (0, 0) is the bottom-left
  corner of the image and (1, 1) its top-right (OBJ's and trimesh's convention; glTF's flipped
  v is converted when a model file is loaded). Texel (col, row) has its centre at
  ``u = (col + 0.5) / W``, ``v = 1 − (row + 0.5) / H``.
- Colour: 8-bit pictures (image files, PIL images, uint8 arrays) are sRGB-encoded, as glTF
  says base-colour textures are, and are decoded to linear light before they modulate the
  surface; float arrays are taken as linear. ``srgb=`` overrides either guess.
- Storage: every level is kept as 8-bit RGBA, colour sRGB-encoded (enough precision for
  colour, four bytes a texel) and alpha linear; the kernels decode colour through a 256-entry
  table. The pyramid is built in linear light: each level averages 2 × 2 texels of the one
  above (an odd side repeats its last row or column), down to 1 × 1.
- Size: a side over :data:`MAX_SIDE` texels is reduced (by a whole factor, with a warning)
  before anything else: a 12k × 12k picture is kept at 6k × 6k, a quarter of the memory.
  Pillow refuses pictures of more than about 179 million pixels (16k × 16k is past that), its
  guard against decompression bombs: a ValueError naming the picture.
- Decoding: a file, a PIL image or an array is read at once. :meth:`Texture.deferred` (what
  the model-file loader uses) decodes a PIL image when the texture is first used, as PIL and
  trimesh open pictures lazily, so loading a model costs little more than trimesh's own
  loading; pixels that cannot be decoded (a truncated PNG or JPEG) raise the ValueError
  naming the picture then.
"""

from __future__ import annotations

import functools
import os
import sys
import warnings
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["FILTERS", "MAX_SIDE", "WRAPS", "Texture", "linear_to_srgb", "srgb_to_linear"]

FILTERS = ("nearest", "bilinear", "trilinear")
WRAPS = ("repeat", "clamp", "mirror")
MAX_SIDE = 8192


def srgb_to_linear(values: Any) -> np.ndarray:
    """Decode sRGB-encoded values in [0, 1] to linear light (the IEC 61966-2-1 curve).

    Examples
    --------
    >>> from pixelpath.scene.texture import srgb_to_linear
    >>> srgb_to_linear([0.0, 0.5, 1.0]).round(4).tolist()
    [0.0, 0.214, 1.0]
    """
    x = np.asarray(values, dtype=np.float64)
    return np.where(x <= 0.04045, x / 12.92, ((x + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(values: Any) -> np.ndarray:
    """Encode linear values in [0, 1] with the sRGB curve (the inverse of :func:`srgb_to_linear`).

    Examples
    --------
    >>> from pixelpath.scene.texture import linear_to_srgb
    >>> linear_to_srgb([0.0, 0.214, 1.0]).round(3).tolist()
    [0.0, 0.5, 1.0]
    """
    x = np.clip(np.asarray(values, dtype=np.float64), 0.0, 1.0)
    # np.where(x <= 0.0031308, x * 12.92, 1.055 * x ** (1 / 2.4) - 0.055), the same
    # operations with fewer temporary arrays
    encoded = np.power(x, 1.0 / 2.4, out=np.empty_like(x))
    encoded *= 1.055
    encoded -= 0.055
    dark = x <= 0.0031308
    encoded[dark] = x[dark] * 12.92
    return encoded


class Texture:
    """A picture to map onto surfaces, with its mip-map pyramid.

    Parameters
    ----------
    image : path, PIL.Image.Image or (H, W, 3|4) array_like
        The picture, row 0 at the top. Greyscale and palette images are expanded to RGB;
        a missing alpha channel is opaque.
    srgb : bool, optional
        Whether the values are sRGB-encoded. Default: True for 8-bit data (files, PIL
        images, uint8 arrays), False for float arrays (linear, in [0, 1]).
    name : str, optional
        A label for messages; a file's name by default.

    Raises
    ------
    FileNotFoundError
        A path that does not exist.
    ValueError
        An unreadable or empty picture, a wrong shape, non-finite or out-of-range values; the
        message names the file.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import Texture
    >>> checker = Texture(np.array([[[255, 0, 0], [0, 0, 255]]], dtype=np.uint8))
    >>> checker.width, checker.height, len(checker.levels)
    (2, 1, 2)
    >>> checker.linear()[0, 1].tolist()  # blue, opaque
    [0.0, 0.0, 1.0, 1.0]
    """

    __hash__ = None  # textures compare by value

    def __init__(self, image: Any, *, srgb: bool | None = None, name: str | None = None) -> None:
        if name is not None and not isinstance(name, str):
            raise TypeError(f"name must be a str, got {type(name).__name__}")
        if srgb is not None and not isinstance(srgb, bool):
            raise TypeError(f"srgb must be a bool or None, got {type(srgb).__name__}")
        label = name
        if isinstance(image, str | os.PathLike):
            path = Path(image)
            label = label or path.name
            rgba, eight_bit = _read_file(path)
        elif _is_pil_image(image):
            rgba, eight_bit = _from_pil(image, label or "texture")
        else:
            rgba, eight_bit = _from_array(image)
        self.name = label
        self.srgb = eight_bit if srgb is None else srgb
        self._pending: tuple[Any, str, bool] | None = None
        self.__dict__["_base"] = _frozen(_encoded_base(rgba, self.srgb))

    @classmethod
    def deferred(cls, image: Any, *, name: str, opaque: bool = False) -> Texture:
        """Make a texture of a PIL image that is decoded when the texture is first used.

        The image must stay readable until then (not closed). Undecodable pixels raise the
        ValueError, naming ``name``, at that first use. ``opaque`` ignores the picture's
        alpha channel (a glTF material whose alpha mode is OPAQUE).

        Examples
        --------
        >>> import io
        >>> from PIL import Image
        >>> from pixelpath.scene import Texture
        >>> buffer = io.BytesIO()
        >>> Image.new("RGB", (4, 2), (255, 0, 0)).save(buffer, format="PNG")
        >>> texture = Texture.deferred(Image.open(buffer), name="red.png")
        >>> texture.width, texture.height
        (4, 2)
        """
        if not _is_pil_image(image):
            raise TypeError(f"{name}: a deferred texture needs a PIL image, got "
                            f"{type(image).__name__}")
        texture = cls.__new__(cls)
        texture.name = name
        texture.srgb = image.mode not in _WIDE_MODES
        texture._pending = (image, name, opaque)
        return texture

    @functools.cached_property
    def _base(self) -> np.ndarray:
        """The base level, decoded from the deferred PIL image at first use."""
        image, label, opaque = self._pending
        rgba, _ = _from_pil(image, label, opaque)
        self._pending = None
        return _frozen(_encoded_base(rgba, self.srgb))

    @property
    def width(self) -> int:
        """Width of the base level in texels."""
        return self._base.shape[1]

    @property
    def height(self) -> int:
        """Height of the base level in texels."""
        return self._base.shape[0]

    @functools.cached_property
    def levels(self) -> tuple[np.ndarray, ...]:
        """The mip-map pyramid: (h, w, 4) uint8 levels (sRGB colour, linear alpha), base first."""
        levels = [self._base]
        # Colour and alpha averaged apart, each array contiguous: an (h, w, 4) array's
        # colour is a strided view, slower to add to. The base is decoded block by block.
        colour, alpha = self._base, self._base
        decode_colour, decode_alpha = _decoded_colour, _decoded_alpha
        while colour.shape[0] > 1 or colour.shape[1] > 1:
            colour, alpha = _half(colour, decode_colour), _half(alpha, decode_alpha)
            decode_colour = decode_alpha = None
            levels.append(_frozen(_encoded(colour, alpha)))
        return tuple(levels)

    def linear(self, level: int = 0) -> np.ndarray:
        """Return a level as (h, w, 4) float64 linear RGBA in [0, 1].

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath.scene import Texture
        >>> Texture(np.full((4, 4, 3), 0.25)).linear(2).shape
        (1, 1, 4)
        """
        return _decoded(self.levels[level])

    @functools.cached_property
    def _packed(self) -> tuple[np.ndarray, list[tuple[int, int, int]]]:
        """Every level as the kernels read it, packed once: (texels, levels).

        ``texels`` (N,) uint32, read-only: the levels' texels one after the other, one word
        each (:func:`_words`); ``levels``: each level's first texel, width and height.
        :func:`surface_tables` hands it to the kernels as it is when a scene has one texture
        (no copy per scene or camera position), and joins these otherwise. Where the words
        hold the bytes in the levels' order (a little-endian machine), :attr:`levels` become
        views of them, so the texture keeps its texels once.
        """
        rows = []
        start = 0
        for level in self.levels:
            rows.append((start, level.shape[1], level.shape[0]))
            start += level.shape[0] * level.shape[1]
        words = np.empty(start, dtype=np.uint32)
        for (first, width, height), level in zip(rows, self.levels, strict=True):
            words[first:first + width * height] = _words(level)
        _frozen(words)
        if sys.byteorder == "little":
            views = tuple(
                _frozen(words[first:first + width * height].view(np.uint8)
                        .reshape(height, width, 4))
                for first, width, height in rows
            )
            self.__dict__["levels"] = views
            self.__dict__["_base"] = views[0]
        return words, rows

    def __getstate__(self) -> dict[str, Any]:
        state = dict(self.__dict__)
        state.pop("_packed", None)  # packed again where it is next used
        return state

    @functools.cached_property
    def lowest_alpha(self) -> float:
        """The smallest alpha of the base level's texels, in [0, 1] (1 for an opaque picture).

        No filtered lookup can go below it: the alpha test skips a material whose alpha
        never falls under its cutoff.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath.scene import Texture
        >>> Texture(np.array([[[0, 0, 0, 255], [0, 0, 0, 51]]], dtype=np.uint8)).lowest_alpha
        0.2
        """
        return int(self._base[..., 3].min()) / 255.0

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Texture):
            return NotImplemented
        return self is other or np.array_equal(self._base, other._base)

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return f"<Texture{label}: {self.width}x{self.height}>"


# PIL modes of more than 8 bits a channel: linear, not sRGB.
_WIDE_MODES = ("I;16", "I;16B", "I;16L", "I", "F")


def wide_grey(image: Any) -> np.ndarray | None:
    """Return a PIL picture of more than 8 bits a channel as (H, W) fractions; None otherwise.

    Such pictures (16-bit integers or floats) have one channel, taken as grey and as linear.

    Examples
    --------
    >>> import numpy as np, PIL.Image
    >>> from pixelpath.scene.texture import wide_grey
    >>> wide_grey(PIL.Image.fromarray(np.array([[0, 65535]], dtype=np.uint16))).tolist()
    [[0.0, 1.0]]
    """
    if image.mode not in _WIDE_MODES:
        return None
    return np.asarray(image, dtype=np.float64) / (65535.0 if image.mode != "F" else 1.0)


def _frozen(array: np.ndarray) -> np.ndarray:
    array.flags.writeable = False
    return array


def _words(level: np.ndarray) -> np.ndarray:
    """(h, w, 4) uint8 RGBA as (h w,) uint32, bytes r, g, b, a from the lowest up."""
    level = np.ascontiguousarray(level, dtype=np.uint8).reshape(-1, 4)
    if sys.byteorder == "little":
        return level.view(np.uint32).reshape(-1)
    channels = level.astype(np.uint32)
    return channels[:, 0] | channels[:, 1] << 8 | channels[:, 2] << 16 | channels[:, 3] << 24


def _is_pil_image(value: Any) -> bool:
    module = type(value).__module__
    return module.startswith("PIL.") and hasattr(value, "convert")


def _read_file(path: Path) -> tuple[np.ndarray, bool]:
    from PIL import Image as PILImage
    from PIL import UnidentifiedImageError

    if not path.is_file():
        raise FileNotFoundError(f"texture file not found: {path}")
    try:
        with warnings.catch_warnings():
            # Past Pillow's warning (about 89 million pixels) a picture is decoded and reduced
            # to MAX_SIDE, as a model file's is; past its error (twice that) it is refused.
            warnings.simplefilter("ignore", PILImage.DecompressionBombWarning)
            with PILImage.open(path) as img:
                return _from_pil(img, str(path))
    except (UnidentifiedImageError, OSError, SyntaxError, PILImage.DecompressionBombError) as exc:
        raise ValueError(f"{path}: not a readable image ({exc})") from None


def _from_pil(img: Any, label: str, opaque: bool = False) -> tuple[np.ndarray, bool]:
    """Return (H, W, 4) pixels of a PIL image, reduced to MAX_SIDE, and whether 8-bit."""
    from PIL import Image as PILImage

    try:
        return _decoded_pil(img, label, opaque)
    except (OSError, ValueError, SyntaxError, PILImage.DecompressionBombError) as exc:
        # Truncated or corrupt data is only found when the pixels are decoded.
        raise ValueError(f"{label}: not a readable image ({exc})") from None


def _decoded_pil(img: Any, label: str, opaque: bool) -> tuple[np.ndarray, bool]:
    reduction = -(-max(img.size) // MAX_SIDE)
    if reduction > 1:
        warnings.warn(
            f"{label}: a {img.size[0]}x{img.size[1]} texture is larger than {MAX_SIDE} texels "
            f"on a side; reduced {reduction} times", UserWarning, stacklevel=5,
        )
        img = img.reduce(reduction)
    grey = wide_grey(img)
    if grey is not None:
        return _from_array(np.repeat(grey[..., None], 3, axis=2))[0], False
    # Pillow adds (or drops) the alpha faster than NumPy does.
    return _from_array(np.asarray(img.convert("RGB" if opaque else "RGBA")))[0], True


def _from_array(image: Any) -> tuple[np.ndarray, bool]:
    """Return (H, W, 4) RGBA in [0, 1] (float64) or uint8, and whether the data is 8-bit."""
    array = np.asarray(image)
    if array.ndim != 3 or array.shape[2] not in (3, 4) or 0 in array.shape[:2]:
        raise ValueError(f"texture must have shape (H, W, 3) or (H, W, 4), got {array.shape}")
    if max(array.shape[:2]) > MAX_SIDE:
        step = -(-max(array.shape[:2]) // MAX_SIDE)
        warnings.warn(
            f"a {array.shape[1]}x{array.shape[0]} texture is larger than {MAX_SIDE} texels "
            f"on a side; every {step}th texel kept", UserWarning, stacklevel=4,
        )
        array = array[::step, ::step]
    if array.dtype == np.uint8:
        if array.shape[2] == 3:
            array = np.concatenate([array, np.full((*array.shape[:2], 1), 255, np.uint8)], 2)
        return array, True
    if array.dtype == np.bool_ or not np.issubdtype(array.dtype, np.number):
        raise TypeError(f"texture must hold numbers, got dtype {array.dtype}")
    values = array.astype(np.float64) / (65535.0 if array.dtype == np.uint16 else 1.0)
    if not np.all(np.isfinite(values)):
        raise ValueError("texture must be finite (no NaN or inf)")
    if values.min() < 0.0 or values.max() > 1.0:
        raise ValueError(
            f"texture values must lie in [0, 1] (or be uint8/uint16), got "
            f"{values.min():g}..{values.max():g}"
        )
    if values.shape[2] == 3:
        values = np.concatenate([values, np.ones((*values.shape[:2], 1))], axis=2)
    return values, False


def _encoded_base(rgba: np.ndarray, srgb: bool) -> np.ndarray:
    """Return the base level as uint8 RGBA with sRGB-encoded colour."""
    if rgba.dtype == np.uint8:
        if srgb:
            return np.ascontiguousarray(rgba)
        rgba = rgba.astype(np.float64) / 255.0
    elif srgb:
        return np.ascontiguousarray(np.rint(rgba * 255.0).astype(np.uint8))
    return _encoded(rgba[..., :3], rgba[..., 3])


@functools.cache
def decode_table() -> np.ndarray:
    """(256,) float64: linear value of each 8-bit sRGB code (what the kernels look up)."""
    table = srgb_to_linear(np.arange(256) / 255.0)
    table.flags.writeable = False
    return table


def _decoded(level: np.ndarray) -> np.ndarray:
    out = np.empty(level.shape)
    out[..., :3] = _decoded_colour(level)
    out[..., 3] = _decoded_alpha(level)
    return out


def _decoded_colour(level: np.ndarray) -> np.ndarray:
    """(h, w, 3) linear colour of an 8-bit (h, w, 4) level."""
    return decode_table()[level[..., :3]]


def _decoded_alpha(level: np.ndarray) -> np.ndarray:
    """(h, w) alpha of an 8-bit (h, w, 4) level, in [0, 1]."""
    return level[..., 3] / 255.0


def _encoded(colour: np.ndarray, alpha: np.ndarray) -> np.ndarray:
    """Return linear (h, w, 3) ``colour`` and (h, w) ``alpha`` as an 8-bit sRGB (h, w, 4) level."""
    out = np.empty((*alpha.shape, 4), dtype=np.uint8)
    encoded = linear_to_srgb(colour)
    encoded *= 255.0
    out[..., :3] = np.rint(encoded, out=encoded)
    out[..., 3] = np.rint(np.clip(alpha, 0.0, 1.0) * 255.0)
    return out


def _half(values: np.ndarray, decode: Any = None) -> np.ndarray:
    """Average 2 × 2 blocks (an odd side repeats its last row or column first).

    ``values`` are linear, or codes that ``decode`` turns into linear values: each quarter of
    the blocks is decoded in turn, so a big base level is never held decoded whole (128 MB
    for a 2048² picture, whose first touch alone cost a tenth of a second).
    """
    height, width = values.shape[:2]
    if height > 1 and height % 2:
        values = np.concatenate([values, values[-1:]], axis=0)
    if width > 1 and width % 2:
        values = np.concatenate([values, values[:, -1:]], axis=1)
    rows = 2 if values.shape[0] > 1 else 1
    cols = 2 if values.shape[1] > 1 else 1
    # The block's texels added in the order NumPy's mean over a (h, 2, w, 2) view adds them,
    # so the levels keep their bits; four times faster on a 2048² picture (43 ms, was 163).
    total = None
    for row in range(rows):
        for col in range(cols):
            quarter = values[row::rows, col::cols]
            linear = quarter if decode is None else decode(quarter)
            if total is None:
                total = linear.copy() if decode is None else linear
            else:
                total += linear
    total /= rows * cols
    return total


def surface_tables(objects: Any):
    """Pack the textures, vertex colours and texture coordinates of scene objects for kernels.

    Parameters
    ----------
    objects : sequence of scene objects
        Their ``material.texture`` and ``emission_texture`` and, for meshes, ``colors`` and
        ``uv``. A texture shows only on meshes with texture coordinates (``uv``); elsewhere
        it is left out, as is the emission texture of a material that emits nothing.

    Returns
    -------
    SurfaceTables
        See :mod:`pixelpath.scene._texture_kernels`; a texture's levels are packed once,
        and kept on the texture, however many objects and scenes use it. An object's alpha
        cutoff is kept only where its alpha can fall below it (the material's ``alpha`` × the
        lowest vertex-colour alpha × the texture's :attr:`Texture.lowest_alpha`): an
        alpha-tested material whose texture and colours are opaque costs no test.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import Material, Mesh
    >>> quad = Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]],
    ...             Material(texture=np.ones((4, 4, 3))), uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> tables = surface_tables([quad])
    >>> tables.levels.tolist(), tables.objects.tolist(), tables.alpha.tolist()
    ([[0, 4, 4], [16, 2, 2], [20, 1, 1]], [[0, 0, -1]], [[1.0, 0.0]])
    """
    from pixelpath.scene import _texture_kernels as tk

    samplers: dict[tuple[int, str, str], int] = {}
    level_ranges: dict[int, tuple[int, int]] = {}
    sampler_rows: list[list[int]] = []
    level_rows: list[list[int]] = []
    pixels: list[np.ndarray] = []
    object_rows = []
    alpha_rows = []

    def sampler(texture: Texture | None, material: Any) -> int:
        """Return the row of ``texture`` read with ``material``'s filter and wrap (-1: none)."""
        if texture is None:
            return -1
        if id(texture) not in level_ranges:
            texels, levels = texture._packed
            texel_count = sum(len(block) for block in pixels)
            level_ranges[id(texture)] = (len(level_rows), len(levels))
            level_rows.extend([texel_count + first, width, height]
                              for first, width, height in levels)
            pixels.append(texels)
        key = (id(texture), material.texture_filter, material.texture_wrap)
        if key not in samplers:
            samplers[key] = len(sampler_rows)
            sampler_rows.append([
                *level_ranges[id(texture)], FILTERS.index(material.texture_filter),
                WRAPS.index(material.texture_wrap),
            ])
        return samplers[key]

    for obj in objects:
        material = obj.material
        texture, glow, colors = _shown(obj)
        object_rows.append([sampler(texture, material), colors is not None,
                            sampler(glow, material)])
        alpha_rows.append([material.alpha, _cutoff(material, texture, colors)])
    if len(pixels) == 1:
        texels = pixels[0]  # the texture's own packed levels: no copy
    else:
        texels = _frozen(np.concatenate(pixels) if pixels else np.zeros(0, dtype=np.uint32))
    return tk.SurfaceTables(
        texels,
        np.array(level_rows, dtype=np.intp).reshape(-1, 3),
        np.array(sampler_rows, dtype=np.intp).reshape(-1, 4),
        np.array(object_rows, dtype=np.intp).reshape(-1, 3),
        decode_table(),
        np.array(alpha_rows, dtype=np.float64).reshape(-1, 2),
    )


def needs_lookups(objects: Any) -> bool:
    """Whether the kernels look any of the scene objects' surfaces up point by point.

    Those objects are the ones :func:`surface_tables` gives a texture, an emission texture,
    vertex colours or an alpha test: meshes with vertex colours, meshes with texture
    coordinates whose material has a texture, or an emission texture and light to emit, and
    objects whose alpha can fall below their material's ``alpha_cutoff`` (primitives have
    no texture coordinates or vertex colours). A render of objects without any compiles and
    runs its passes without those lookups (:func:`pixelpath.raster._kernels.looks_up`).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.scene import Material, Mesh, Sphere
    >>> quad = Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]],
    ...             Material(texture=np.ones((4, 4, 3))), uv=[[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> ball = Sphere((0, 0, 0), 1.0)
    >>> needs_lookups([ball]), needs_lookups([ball, quad])
    (False, True)
    """
    return any(_looked_up(obj) for obj in objects)


def _shown(obj: Any) -> tuple[Texture | None, Texture | None, np.ndarray | None]:
    """Return the texture, emission texture and vertex colours the kernels read for ``obj``.

    A texture shows only with texture coordinates (``uv``), an emission texture only where
    the material emits: None where nothing is read.
    """
    material, uv = obj.material, getattr(obj, "uv", None)
    colors = getattr(obj, "colors", None)
    if uv is None:
        return None, None, colors
    return material.texture, material.emission_texture if material.emits else None, colors


def _looked_up(obj: Any) -> bool:
    texture, glow, colors = _shown(obj)
    return (texture is not None or glow is not None or colors is not None
            or _cutoff(obj.material, texture, colors) > 0.0)


def _cutoff(material: Any, texture: Texture | None, colors: np.ndarray | None) -> float:
    """Return the cutoff the kernels test an object's alpha against: 0 where it cannot cut."""
    cutoff = material.alpha_cutoff
    if cutoff is None:
        return 0.0
    lowest = material.alpha
    if texture is not None:
        lowest *= texture.lowest_alpha
    if colors is not None and len(colors):
        lowest *= float(colors[:, 3].min())
    return cutoff if lowest < cutoff else 0.0
