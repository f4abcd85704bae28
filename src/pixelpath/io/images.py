"""Image files through Pillow, written atomically (temporary file, then rename)."""

from __future__ import annotations

import functools
import io
import os
import tempfile
from pathlib import Path

import numpy as np


def read_image(path: str | os.PathLike) -> np.ndarray:
    """Read an image file as RGB floats in [0, 1].

    Parameters
    ----------
    path : str or path-like
        Any format Pillow reads (PNG, JPEG, TIFF, ...). Alpha is dropped; greyscale is
        repeated over three channels; 16-bit images are scaled by 1/65535.

    Returns
    -------
    (H, W, 3) float32 ndarray

    Examples
    --------
    >>> import numpy as np, tempfile, os
    >>> from pixelpath.io import read_image, write_image
    >>> path = os.path.join(tempfile.mkdtemp(), "red.png")
    >>> write_image(path, np.array([[[1.0, 0.0, 0.0]]]))
    >>> read_image(path).tolist()
    [[[1.0, 0.0, 0.0]]]
    """
    from PIL import Image as PILImage

    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"image file not found: {path}")
    with PILImage.open(path) as img:
        if img.mode in ("I;16", "I;16B", "I;16L", "I"):
            data = np.asarray(img, dtype=np.float32) / 65535.0
            return np.repeat(data[..., None], 3, axis=-1)
        return np.asarray(img.convert("RGB"), dtype=np.float32) / 255.0


def to_uint8(rgb: np.ndarray, gamma: float | str | None = None) -> np.ndarray:
    """Map floats in [0, 1] to 0..255 (clamped, rounded), optionally gamma-encoding first.

    ``gamma=2.2`` raises each value to ``1/2.2`` before quantizing (display encoding);
    ``"srgb"`` applies the sRGB curve (what model files' textures were encoded with);
    ``None`` or ``"linear"`` keeps the linear mapping of the notes (value × 255).

    A float32 array (what :class:`~pixelpath.Image` holds) goes through compiled kernels,
    about 1 ms for a 640×400 picture: the linear mapping is computed in float64 as below, any
    other encoding is looked up in a table built once from that computation
    (:func:`code_table`), so the bytes are those of the general path. Other inputs take the
    general path: ``rint(clip(value, 0, 1) ** (1/gamma) · 255)`` in float64.

    Parameters
    ----------
    rgb : array_like
        Intensities of any shape.
    gamma : float or {"srgb", "linear"}, optional
        Display encoding; default none (linear).

    Returns
    -------
    uint8 ndarray
        The codes, of the shape of ``rgb``.

    Examples
    --------
    >>> from pixelpath.io.images import to_uint8
    >>> to_uint8([0.0, 0.2158, 1.0], "srgb").tolist(), to_uint8([0.5]).tolist()
    ([0, 128, 255], [128])
    """
    gamma = _checked_gamma(gamma)
    if isinstance(rgb, np.ndarray) and rgb.dtype == np.float32:
        return _float32_codes(rgb, gamma)
    return _general_codes(np.asarray(rgb, dtype=np.float64), gamma)


def _checked_gamma(gamma: float | str | None) -> float | str | None:
    """Return ``gamma``, None for linear; ValueError for anything but a positive number."""
    if gamma is None or gamma == "linear":
        return None
    if gamma != "srgb" and (isinstance(gamma, str) or not gamma > 0):
        raise ValueError(f"gamma must be a positive number, 'srgb' or 'linear', got {gamma!r}")
    return gamma


def _general_codes(values: np.ndarray, gamma: float | str | None) -> np.ndarray:
    """Return the codes of float64 ``values`` by the general path of :func:`to_uint8`."""
    values = np.clip(values, 0.0, 1.0)
    if gamma == "srgb":
        from pixelpath.scene.texture import linear_to_srgb

        values = linear_to_srgb(values)
    elif gamma is not None:
        values = values ** (1.0 / gamma)
    with np.errstate(invalid="ignore"):  # a NaN casts to 0
        return np.rint(values * 255.0).astype(np.uint8)


def _float32_codes(rgb: np.ndarray, gamma: float | str | None) -> np.ndarray:
    """Return ``to_uint8(rgb, gamma)`` for a float32 array, through the compiled kernels."""
    from numba.core import config

    from pixelpath.io import _kernels

    table = None if gamma is None else code_table(gamma if gamma == "srgb" else float(gamma))
    if config.DISABLE_JIT or (gamma is not None and table is None):
        # NumPy is faster than the kernels as plain Python; a gamma without a table has no choice
        codes = _general_codes(rgb.astype(np.float64), gamma)
        nan = np.isnan(rgb)
        if table is not None and nan.any():  # a table gives a NaN the code its bits say
            codes[nan] = np.where(np.signbit(rgb[nan]), table[2][3], table[2][2])
        return codes
    values = np.ascontiguousarray(rgb).reshape(-1)
    out = np.empty(rgb.shape, np.uint8)
    if table is None:
        _kernels.linear_codes(values, out.reshape(-1))
    else:
        _kernels.table_codes(values.view(np.int32), *table, out.reshape(-1))
    return out


@functools.lru_cache(maxsize=8)
def code_table(gamma: float | str) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Return the step table that encodes float32 values with ``gamma`` (or None if none fits).

    The float32 values of [0, 1], as integers, fall into buckets of ``2**12`` consecutive
    floats; when each bucket holds at most one step of the code (the steps of the sRGB curve
    lie 2.4e-4 or more apart, a bucket spans at most 2.4e-4), a value's code is its bucket's
    first code, plus one from the step on. The steps are found by bisection on the general
    path's very computation, so both give the same bytes; a gamma whose steps crowd closer
    (below about 0.03) gets None, and :func:`to_uint8` takes the general path.

    Parameters
    ----------
    gamma : float or "srgb"
        The encoding.

    Returns
    -------
    (first_code, step, codes) or None
        Each bucket's first code (uint8); the bits (int32) of the float where its code steps
        up, past 1.0's where it does not; the codes of 0, 1, +NaN and -NaN (uint8).

    Examples
    --------
    >>> from pixelpath.io.images import code_table
    >>> first_code, step, codes = code_table("srgb")
    >>> len(first_code), int((step <= 0x3F800000).sum()), codes.tolist()
    (260097, 255, [0, 255, 255, 0])
    """
    from pixelpath.io._kernels import BUCKET_BITS, ONE_BITS

    def code(bits: np.ndarray) -> np.ndarray:  # the general path, on float32 bits
        values = bits.astype(np.uint32).view(np.float32).astype(np.float64)
        return _general_codes(values, gamma).astype(np.int64)

    buckets = (ONE_BITS >> BUCKET_BITS) + 1
    first_code = code(np.arange(buckets, dtype=np.int64) << BUCKET_BITS).astype(np.uint8)
    # bisect on the bits for the first float of each code 1..255
    wanted = np.arange(1, 256)
    low, high = np.zeros(255, np.int64), np.full(255, ONE_BITS, np.int64)
    while (high - low > 0).any():
        middle = (low + high) // 2
        reached = code(middle) >= wanted
        high, low = np.where(reached, middle, high), np.where(reached, low, middle + 1)
    if (code(high) != wanted).any():  # a code skipped (steps of two): no table
        return None
    step = np.full(buckets, ONE_BITS + 1, np.int32)
    inside = (high & ((1 << BUCKET_BITS) - 1)) != 0  # a step at a bucket's start is its code
    where = high[inside] >> BUCKET_BITS
    if len(np.unique(where)) != len(where):
        return None
    step[where] = high[inside]
    # What the step table gave these before it was compiled: a NaN's code came from its bits
    # (the last bucket for +NaN, the first for -NaN) with the linear mapping's 0 for both.
    zero, one = code(np.array([0, ONE_BITS]))
    nan = (first_code[-1], first_code[0]) if gamma == "srgb" else (0, 0)
    codes = np.array([zero, one, *nan], np.uint8)
    for array in (first_code, step, codes):
        array.flags.writeable = False
    return first_code, step, codes


def write_image(
    path: str | os.PathLike,
    rgb: np.ndarray,
    *,
    gamma: float | str | None = None,
    alpha: np.ndarray | None = None,
    png_level: int | None = None,
) -> None:
    """Write an ``(H, W, 3)`` float image in [0, 1] to ``path`` atomically.

    The format follows the extension (PNG, JPEG, BMP, TIFF, ...). The file is written to a
    temporary name in the same directory and renamed into place, so a crash never leaves a
    half-written image.

    Parameters
    ----------
    path : str or path-like
        Destination; its directory must exist.
    rgb : (H, W, 3) array_like
        Linear intensities; values outside [0, 1] are clamped.
    gamma : float or {"srgb", "linear"}, optional
        Display encoding (for example 2.2, or the sRGB curve); default none (linear).
    alpha : (H, W) array_like, optional
        Coverage in [0, 1], written as a fourth channel (RGBA; PNG, TIFF, WebP).
    png_level : int, optional
        zlib compression level of a PNG, 0 (none) to 9 (smallest, slowest); default Pillow's,
        6. See :func:`encode_image`.

    Examples
    --------
    >>> import numpy as np, tempfile, os
    >>> from pixelpath.io import write_image
    >>> write_image(os.path.join(tempfile.mkdtemp(), "grey.png"), np.full((2, 2, 3), 0.5))
    """
    path = Path(path)
    if not path.parent.is_dir():
        raise FileNotFoundError(f"output directory does not exist: {path.parent}")
    data = encode_image(rgb, path.suffix, gamma=gamma, alpha=alpha, png_level=png_level)
    write_bytes(path, data)


def image_format(suffix: str, *, alpha: bool = False) -> str:
    """Return Pillow's format name for a file extension such as ``".png"``; ValueError if none.

    With ``alpha=True``, a format without an alpha channel (JPEG, ...) is a ValueError too:
    callers check before the work that makes the image, not after it.

    Examples
    --------
    >>> from pixelpath.io.images import image_format
    >>> image_format(".PNG")
    'PNG'
    >>> image_format(".jpg", alpha=True)
    Traceback (most recent call last):
    ...
    ValueError: .jpg files have no alpha channel; write .png for RGBA
    """
    from PIL import Image as PILImage

    fmt = PILImage.registered_extensions().get(suffix.lower())
    if fmt is None:
        raise ValueError(f"unknown image extension {suffix!r}; use .png, .jpg, ...")
    if alpha and fmt not in ("PNG", "TIFF", "WEBP"):
        raise ValueError(f"{suffix} files have no alpha channel; write .png for RGBA")
    return fmt


def encode_image(
    rgb: np.ndarray,
    suffix: str,
    *,
    gamma: float | str | None = None,
    alpha: np.ndarray | None = None,
    png_level: int | None = None,
) -> bytes:
    """Return the bytes of the image file ``write_image`` writes for extension ``suffix``.

    Parameters
    ----------
    rgb : (H, W, 3) array_like
        Linear intensities; values outside [0, 1] are clamped.
    suffix : str
        The file's extension, which picks the format (``".png"``, ``".jpg"``, ...).
    gamma : float or {"srgb", "linear"}, optional
        Display encoding, as :func:`to_uint8`.
    alpha : (H, W) array_like, optional
        Coverage in [0, 1], written as a fourth channel.
    png_level : int, optional
        zlib compression level of a PNG (Pillow's ``compress_level``), 0 (none) to 9
        (smallest, slowest); checked but unused by other formats. Default 6, as
        ``Image.save`` writes. Level 1 encodes a 640×400 render in 7.7 ms instead of 21 ms,
        into 91 kB instead of 61.

    Returns
    -------
    bytes

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.io.images import encode_image
    >>> encode_image(np.zeros((1, 1, 3)), ".png")[1:4]
    b'PNG'
    >>> len(encode_image(np.zeros((64, 64, 3)), ".png", png_level=0)) > 64 * 64 * 3
    True
    """
    from PIL import Image as PILImage

    rgb = np.asarray(rgb)
    if rgb.ndim != 3 or rgb.shape[-1] != 3:
        raise ValueError(f"rgb must have shape (H, W, 3), got {rgb.shape}")
    fmt = image_format(suffix, alpha=alpha is not None)
    options = save_options(fmt, png_level)
    pixels = to_uint8(rgb, gamma)
    if alpha is not None:
        alpha = np.asarray(alpha)
        if alpha.shape != rgb.shape[:2]:
            raise ValueError(
                f"alpha must have shape {rgb.shape[:2]} like the image, got {alpha.shape}"
            )
        pixels = np.dstack([pixels, to_uint8(alpha)])
    buffer = io.BytesIO()
    PILImage.fromarray(pixels).save(buffer, format=fmt, **options)
    return buffer.getvalue()


def save_options(fmt: str, png_level: object) -> dict[str, int]:
    """Return Pillow's ``save`` keywords for format ``fmt`` at PNG level ``png_level``.

    The level is checked (:func:`png_level_of`) whatever the format, so a bad one is refused
    before any work; only a PNG uses it, and None leaves Pillow's default (6).

    Examples
    --------
    >>> from pixelpath.io.images import save_options
    >>> save_options("PNG", 1), save_options("JPEG", 1), save_options("PNG", None)
    ({'compress_level': 1}, {}, {})
    """
    level = None if png_level is None else png_level_of(png_level)
    return {"compress_level": level} if level is not None and fmt == "PNG" else {}


def png_level_of(level: object) -> int:
    """Return ``level`` as a PNG compression level (an int from 0 to 9), or raise ValueError.

    Examples
    --------
    >>> from pixelpath.io.images import png_level_of
    >>> png_level_of(1)
    1
    """
    if isinstance(level, bool) or not isinstance(level, int | np.integer) or not 0 <= level <= 9:
        raise ValueError(f"png_level must be an int from 0 to 9, got {level!r}")
    return int(level)


def write_bytes(path: str | os.PathLike, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically: a temporary file in the same folder, then a rename.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pixelpath.io.images import write_bytes
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "note.txt"
    >>> write_bytes(path, b"done")
    >>> path.read_bytes()
    b'done'
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        if hasattr(os, "fchmod"):  # mkstemp makes 0600; give the file the usual permissions
            os.fchmod(fd, _new_file_mode())
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _new_file_mode() -> int:
    """Return the mode a newly created file gets under the process umask (0644 under 022)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask
