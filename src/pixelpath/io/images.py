"""Image files through Pillow, written atomically (temporary file, then rename)."""

from __future__ import annotations

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

    Examples
    --------
    >>> from pixelpath.io.images import to_uint8
    >>> to_uint8([0.0, 0.2158, 1.0], "srgb").tolist(), to_uint8([0.5]).tolist()
    ([0, 128, 255], [128])
    """
    if gamma == "srgb" and isinstance(rgb, np.ndarray) and rgb.dtype == np.float32:
        return _srgb_codes(rgb)
    values = np.clip(np.asarray(rgb, dtype=np.float64), 0.0, 1.0)
    if gamma == "srgb":
        from pixelpath.scene.texture import linear_to_srgb

        values = linear_to_srgb(values)
    elif gamma is not None and gamma != "linear":
        if isinstance(gamma, str) or not gamma > 0:
            raise ValueError(f"gamma must be a positive number, 'srgb' or 'linear', got {gamma!r}")
        values = values ** (1.0 / gamma)
    return np.rint(values * 255.0).astype(np.uint8)


# sRGB-encoding a float32 picture to 8 bits looks each value up in a table instead of raising
# it to the power 1/2.4 (20 ms a megapixel instead of 50): the float32 values of [0, 1], as
# integers, fall into buckets of 2**_BUCKET_BITS consecutive floats; each bucket holds at most
# one step of the code (the steps lie 2.4e-4 or more apart, the buckets span at most 2.4e-4:
# checked when the table is built), so a value's code is its bucket's first code, plus one
# from the step on. The steps are found by bisection on the very computation of to_uint8's
# general path, so both give the same bytes.
_BUCKET_BITS = 12
_SRGB_TABLE: tuple[np.ndarray, np.ndarray] | None = None


def _srgb_codes(rgb: np.ndarray) -> np.ndarray:
    """Return ``to_uint8(rgb, "srgb")`` for a float32 array, through the step table."""
    global _SRGB_TABLE
    if _SRGB_TABLE is None:
        _SRGB_TABLE = _srgb_table()
    first_code, step = _SRGB_TABLE
    values = np.clip(rgb, np.float32(0.0), np.float32(1.0))
    bucket = values.view(np.int32) >> _BUCKET_BITS
    # mode="clip": -0.0 (negative as an integer) takes bucket 0, a NaN (past 1.0) the last
    return np.take(first_code, bucket, mode="clip") + (
        values >= np.take(step, bucket, mode="clip")
    )


def _srgb_table() -> tuple[np.ndarray, np.ndarray]:
    """Return (each bucket's first code, the value where its code steps up, or 2.0)."""
    from pixelpath.scene.texture import linear_to_srgb

    def code(bits: np.ndarray) -> np.ndarray:  # the general path of to_uint8, on float32 bits
        values = bits.astype(np.uint32).view(np.float32).astype(np.float64)
        return np.rint(linear_to_srgb(values) * 255.0).astype(np.int64)

    one = int(np.float32(1.0).view(np.uint32))
    buckets = (one >> _BUCKET_BITS) + 1
    first_code = code(np.arange(buckets, dtype=np.int64) << _BUCKET_BITS).astype(np.uint8)
    # bisect on the bits for the first float of each code 1..255
    wanted = np.arange(1, 256)
    low, high = np.zeros(255, np.int64), np.full(255, one, np.int64)
    while (high - low > 0).any():
        middle = (low + high) // 2
        reached = code(middle) >= wanted
        high, low = np.where(reached, middle, high), np.where(reached, low, middle + 1)
    step = np.full(buckets, 2.0, np.float32)
    inside = (high & ((1 << _BUCKET_BITS) - 1)) != 0  # a step at a bucket's start is its code
    where = high[inside] >> _BUCKET_BITS
    if len(np.unique(where)) != len(where):
        raise AssertionError("two sRGB code steps share a bucket: use smaller buckets")
    step[where] = high[inside].astype(np.uint32).view(np.float32)
    return first_code, step


def write_image(
    path: str | os.PathLike,
    rgb: np.ndarray,
    *,
    gamma: float | str | None = None,
    alpha: np.ndarray | None = None,
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

    Examples
    --------
    >>> import numpy as np, tempfile, os
    >>> from pixelpath.io import write_image
    >>> write_image(os.path.join(tempfile.mkdtemp(), "grey.png"), np.full((2, 2, 3), 0.5))
    """
    path = Path(path)
    if not path.parent.is_dir():
        raise FileNotFoundError(f"output directory does not exist: {path.parent}")
    write_bytes(path, encode_image(rgb, path.suffix, gamma=gamma, alpha=alpha))


def image_format(suffix: str) -> str:
    """Return Pillow's format name for a file extension such as ``".png"``; ValueError if none.

    Examples
    --------
    >>> from pixelpath.io.images import image_format
    >>> image_format(".PNG")
    'PNG'
    """
    from PIL import Image as PILImage

    fmt = PILImage.registered_extensions().get(suffix.lower())
    if fmt is None:
        raise ValueError(f"unknown image extension {suffix!r}; use .png, .jpg, ...")
    return fmt


def encode_image(
    rgb: np.ndarray,
    suffix: str,
    *,
    gamma: float | str | None = None,
    alpha: np.ndarray | None = None,
) -> bytes:
    """Return the bytes of the image file ``write_image`` writes for extension ``suffix``.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath.io.images import encode_image
    >>> encode_image(np.zeros((1, 1, 3)), ".png")[1:4]
    b'PNG'
    """
    from PIL import Image as PILImage

    rgb = np.asarray(rgb)
    if rgb.ndim != 3 or rgb.shape[-1] != 3:
        raise ValueError(f"rgb must have shape (H, W, 3), got {rgb.shape}")
    fmt = image_format(suffix)
    pixels = to_uint8(rgb, gamma)
    if alpha is not None:
        alpha = np.asarray(alpha)
        if alpha.shape != rgb.shape[:2]:
            raise ValueError(
                f"alpha must have shape {rgb.shape[:2]} like the image, got {alpha.shape}"
            )
        if fmt not in ("PNG", "TIFF", "WEBP"):
            raise ValueError(f"{suffix} files have no alpha channel; write .png for RGBA")
        pixels = np.dstack([pixels, to_uint8(alpha)])
    buffer = io.BytesIO()
    PILImage.fromarray(pixels).save(buffer, format=fmt)
    return buffer.getvalue()


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
