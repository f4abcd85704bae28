"""The colour models of the notes over whole arrays, with RGB as the hub.

Every converter takes an array of colours with the components on the last axis, shape
``(..., 3)`` (``(..., 4)`` for CMYK), and returns an array of the same leading shape.

Input policy, written once in :func:`_prepare`:

* RGB input: floats are taken as they are (nominally [0, 1]); ``uint8`` is scaled by 1/255 and
  ``uint16`` by 1/65535; any other integer input (a Python list of ints included) is read as
  8-bit values and must lie in 0..255.
* Input of the other models is numbers in that model's own units (hue in degrees), so integers
  are taken at face value: ``hsv_to_rgb([120, 1, 1])`` is pure green.
* The result is ``float32`` for ``float32`` input and ``float64`` for everything else, unless
  ``dtype=`` (float32 or float64) asks for another: integer input is then converted straight
  into it (a uint8 image to float32 takes 4 bytes a component, not 8), and float input of the
  other precision is cast first. The arithmetic runs in the result's precision.
* Booleans, strings, complex and object arrays raise ``TypeError``; a wrong last axis, ragged
  input and NaN or infinite components raise ``ValueError``. The input is never modified.

Values outside the nominal ranges are converted by the same formulas (extrapolated), with one
exception: hue is always reduced modulo 360 (``hsv_to_rgb`` accepts 360 and negative hues).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from pixelpath.color import _matrices as mx

#: Model name -> number of components.
MODELS: dict[str, int] = {
    "rgb": 3,
    "hsv": 3,
    "hsl": 3,
    "cmy": 3,
    "cmyk": 4,
    "yiq": 3,
    "ycbcr": 3,
}

_IDENTITY = np.eye(3)
_ZERO = np.zeros(3)
_RUN_PIXELS = 1 << 18  # pixels a run of a threaded conversion: a 4K image is 32 runs


class _Conversion(NamedTuple):
    """One kernel call: operation name, source and target models and, if affine, M and offset."""

    op: str
    src: str
    dst: str
    matrix: np.ndarray = _IDENTITY
    offset: np.ndarray = _ZERO


def _affine(src: str, dst: str, matrix: np.ndarray, offset: np.ndarray) -> _Conversion:
    return _Conversion("AFFINE", src, dst, np.ascontiguousarray(matrix), offset)


_FROM_RGB = {
    "hsv": _Conversion("RGB_TO_HSV", "rgb", "hsv"),
    "hsl": _Conversion("RGB_TO_HSL", "rgb", "hsl"),
    "cmyk": _Conversion("RGB_TO_CMYK", "rgb", "cmyk"),
    "cmy": _affine("rgb", "cmy", mx.cmy_from_rgb, mx.cmy_offset),
    "yiq": _affine("rgb", "yiq", mx.yiq_from_rgb, _ZERO),
    "ycbcr": _affine("rgb", "ycbcr", mx.ycbcr_from_rgb, mx.ycbcr_offset),
}
_TO_RGB = {
    "hsv": _Conversion("HSV_TO_RGB", "hsv", "rgb"),
    "hsl": _Conversion("HSL_TO_RGB", "hsl", "rgb"),
    "cmyk": _Conversion("CMYK_TO_RGB", "cmyk", "rgb"),
    "cmy": _affine("cmy", "rgb", mx.cmy_from_rgb, mx.cmy_offset),
    "yiq": _affine("yiq", "rgb", mx.rgb_from_yiq, _ZERO),
    "ycbcr": _affine(
        "ycbcr", "rgb", mx.rgb_from_ycbcr, mx.inverse_offset(mx.rgb_from_ycbcr, mx.ycbcr_offset)
    ),
}

_REJECTED_KINDS = {
    "b": "booleans",
    "c": "complex numbers",
    "O": "Python objects",
    "U": "strings",
    "S": "bytes",
    "V": "structured records",
    "M": "datetimes",
    "m": "timedeltas",
}


def _requested_dtype(dtype: DTypeLike | None) -> np.dtype | None:
    """Check the ``dtype=`` argument: None, or float32 or float64 in any spelling."""
    if dtype is None:
        return None
    try:
        resolved = np.dtype(dtype)
    except TypeError:
        raise TypeError(f"dtype must be float32 or float64, got {dtype!r}") from None
    if resolved not in (np.float32, np.float64):
        raise ValueError(f"dtype must be float32 or float64, got {resolved}")
    return resolved


def _prepare(
    values: ArrayLike, name: str, model: str, dtype: DTypeLike | None
) -> tuple[np.ndarray, float, np.dtype]:
    """Validate ``values`` as colours of ``model``: return kernel-ready array, scale, result dtype.

    The array keeps the caller's data where it can (no copy for contiguous float32/float64,
    uint8 and uint16 input); the scale is applied inside the kernel, in the result's precision.
    """
    requested = _requested_dtype(dtype)
    try:
        arr = np.asarray(values)
    except ValueError as exc:  # ragged nested lists
        raise ValueError(f"{name} must be a rectangular array of colours: {exc}") from None
    if arr.dtype.kind in _REJECTED_KINDS:
        raise TypeError(
            f"{name} must hold real numbers, got {_REJECTED_KINDS[arr.dtype.kind]} "
            f"(dtype {arr.dtype})"
        )
    channels = MODELS[model]
    if arr.ndim == 0 or arr.shape[-1] != channels:
        raise ValueError(
            f"{name} must have shape (..., {channels}) for {model.upper()}, got {arr.shape}"
        )
    if not arr.dtype.isnative:
        arr = arr.astype(arr.dtype.newbyteorder("="))
    default = np.dtype(np.float32 if arr.dtype == np.float32 else np.float64)
    result = default if requested is None else requested
    scale = 1.0
    if arr.dtype.kind in "iu":
        if model != "rgb":
            arr = arr.astype(result)
        elif arr.dtype == np.uint8:
            scale = 1.0 / 255.0
        elif arr.dtype == np.uint16:
            scale = 1.0 / 65535.0
        else:
            if arr.size and (arr.min() < 0 or arr.max() > 255):
                raise ValueError(
                    f"{name} holds integers outside 0..255 (min {arr.min()}, max {arr.max()}); "
                    "integer RGB is read as 8-bit values: pass uint16 for 16-bit data or floats "
                    "in [0, 1]"
                )
            arr = arr.astype(np.uint8)
            scale = 1.0 / 255.0
    elif arr.dtype != result:
        arr = arr.astype(result)
    return np.ascontiguousarray(arr), scale, result


def _prepare_out(out: np.ndarray | None, shape: tuple[int, ...], dtype: np.dtype) -> np.ndarray:
    if out is None:
        return np.empty(shape, dtype=dtype)
    if not isinstance(out, np.ndarray):
        raise TypeError(f"out must be a numpy array, got {type(out).__name__}")
    if out.shape != shape or out.dtype != dtype or not out.flags.c_contiguous:
        raise ValueError(
            f"out must be a C-contiguous {dtype.name} array of shape {shape}, "
            f"got {out.dtype} {out.shape}"
            + ("" if out.flags.c_contiguous else " (not C-contiguous)")
        )
    if not out.flags.writeable:
        raise ValueError("out must be writeable")
    return out


def _apply(
    conversion: _Conversion,
    values: ArrayLike,
    name: str,
    out: np.ndarray | None,
    dtype: DTypeLike | None = None,
) -> NDArray[np.floating]:
    from pixelpath.color import _kernels

    src, scale, dtype = _prepare(values, name, conversion.src, dtype)
    dst_channels = MODELS[conversion.dst]
    result = _prepare_out(out, (*src.shape[:-1], dst_channels), dtype)
    # The kernels compute in the precision of scale, matrix and offset: the result's.
    args = (
        dtype.type(scale),
        getattr(_kernels, conversion.op),
        conversion.matrix.astype(dtype, copy=False),
        conversion.offset.astype(dtype, copy=False),
    )
    flat_src, flat_dst = src.reshape(-1), result.reshape(-1)
    # Non-finite input is flagged by the kernel and counted below; errstate keeps the pure-Python
    # run (NUMBA_DISABLE_JIT=1) from warning on the way, as the compiled run never does.
    with np.errstate(invalid="ignore", over="ignore"):
        if flat_src.size <= _kernels.CHUNK * src.shape[-1]:
            # One chunk's worth: waking the thread pool would cost more than the work.
            bad = _kernels.convert_span(flat_src, flat_dst, *args)
        else:
            bad = _convert_in_threads(flat_src, flat_dst, src.shape[-1], dst_channels, args)
    if bad:
        count = np.count_nonzero(~np.isfinite(src).all(axis=-1))
        raise ValueError(
            f"{name} has {count} colour(s) with NaN or infinite components; "
            "mask or replace them before converting"
        )
    return result


def _convert_in_threads(
    src: np.ndarray, dst: np.ndarray, src_channels: int, dst_channels: int, args: tuple
) -> bool:
    """Run ``convert_span`` on runs of whole pixels from several threads; whether any was bad."""
    from pixelpath._threads import in_threads, thread_count
    from pixelpath.color import _kernels

    flags = []

    def convert(start: int, stop: int) -> None:
        flags.append(_kernels.convert_span(
            src[src_channels * start : src_channels * stop],
            dst[dst_channels * start : dst_channels * stop],
            *args,
        ))

    # Every pixel costs the same, but a thread may not run at full speed the whole time (a
    # virtual machine's core, a small core of a hybrid processor): with one run per thread, a
    # 4K conversion's first call took 100 ms instead of 8 in some processes here, its one
    # slowed thread holding the call up, where runs of _RUN_PIXELS shared out as threads
    # finish let the others take the work (docs/performance.md).
    pixels = len(src) // src_channels
    in_threads(convert, pixels, runs=max(thread_count(), -(-pixels // _RUN_PIXELS)))
    return any(flags)


def _same_model(
    values: ArrayLike, model: str, out: np.ndarray | None, dtype: DTypeLike | None
) -> NDArray[np.floating]:
    src, scale, dtype = _prepare(values, "values", model, dtype)
    result = _prepare_out(out, src.shape, dtype)
    np.multiply(src, scale, out=result, casting="unsafe")
    if not np.isfinite(result).all():
        raise ValueError("values has NaN or infinite components")
    return result


def convert(
    values: ArrayLike,
    src: str = "rgb",
    dst: str = "hsv",
    *,
    dtype: DTypeLike | None = None,
    out: np.ndarray | None = None,
) -> NDArray[np.floating]:
    """Convert colours between any two models, through RGB.

    Parameters
    ----------
    values : (..., 3) or (..., 4) array_like
        Colours of model ``src`` (four components for CMYK).
    src, dst : {"rgb", "hsv", "hsl", "cmy", "cmyk", "yiq", "ycbcr"}
        Model names, lower case.
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination of the right shape and dtype, C-contiguous, to reuse a buffer.

    Returns
    -------
    ndarray
        Colours of model ``dst``, of the result dtype (see ``dtype``).

    Raises
    ------
    ValueError
        Unknown model names, a wrong last axis, non-finite components.
    TypeError
        Non-numeric input.

    Examples
    --------
    >>> from pixelpath.color import convert
    >>> convert([255, 255, 0], "rgb", "hsv").tolist()
    [60.0, 1.0, 1.0]
    >>> convert([60.0, 1.0, 0.5], "hsl", "cmyk").tolist()
    [0.0, 0.0, 1.0, 0.0]
    """
    for label, model in (("src", src), ("dst", dst)):
        if model not in MODELS:
            raise ValueError(
                f"unknown colour model {label}={model!r}; choose from {', '.join(MODELS)}"
            )
    if src == dst:
        return _same_model(values, src, out, dtype)
    if src == "rgb":
        return _apply(_FROM_RGB[dst], values, "values", out, dtype)
    if dst == "rgb":
        return _apply(_TO_RGB[src], values, "values", out, dtype)
    rgb = _apply(_TO_RGB[src], values, "values", None, dtype)
    return _apply(_FROM_RGB[dst], rgb, "values", out)


def rgb_to_hsv(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to HSV (the notes' single hexcone).

    V = Cmax, S = Δ/Cmax (0 for black), H from the notes' three hue cases, in degrees
    [0, 360); greys get H = 0 and S = 0.

    Parameters
    ----------
    rgb : (..., 3) array_like
        Floats in [0, 1], or integers (uint8, uint16, 8-bit values; see the module notes).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer (same shape as the result, C-contiguous, result dtype).

    Returns
    -------
    (..., 3) ndarray
        (H, S, V), of the result dtype (see ``dtype``).

    Examples
    --------
    >>> from pixelpath.color import rgb_to_hsv
    >>> rgb_to_hsv([255, 255, 0]).tolist()
    [60.0, 1.0, 1.0]
    >>> rgb_to_hsv([0.5, 0.5, 0.5]).tolist()
    [0.0, 0.0, 0.5]
    >>> import numpy as np
    >>> rgb_to_hsv(np.array([[255, 0, 51]], np.uint8), dtype="float32")
    array([[348.,   1.,   1.]], dtype=float32)
    """
    return _apply(_FROM_RGB["hsv"], rgb, "rgb", out, dtype)


def hsv_to_rgb(
    hsv: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert HSV to RGB with the notes' sector table.

    C = V·S, X = C·(1 − ``|(H/60) mod 2 − 1|``), m = V − C; (R', G', B') from H's 60° sector, then
    m is added. H is taken modulo 360, so 360 and negative hues wrap.

    Parameters
    ----------
    hsv : (..., 3) array_like
        (H in degrees, S in [0, 1], V in [0, 1]).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        RGB in [0, 1].

    Examples
    --------
    >>> from pixelpath.color import hsv_to_rgb
    >>> hsv_to_rgb([120, 1, 1]).tolist()
    [0.0, 1.0, 0.0]
    >>> hsv_to_rgb([-60.0, 1.0, 1.0]).tolist()
    [1.0, 0.0, 1.0]
    """
    return _apply(_TO_RGB["hsv"], hsv, "hsv", out, dtype)


def rgb_to_hsl(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to HSL (the double hexcone).

    L = (Cmax + Cmin)/2, S = Δ/(1 − ``|2L − 1|``) (0 for greys), H as for HSV.

    Parameters
    ----------
    rgb : (..., 3) array_like
        RGB colours (see the module notes for integer input).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        (H in degrees, S, L).

    Examples
    --------
    >>> from pixelpath.color import rgb_to_hsl
    >>> rgb_to_hsl([1.0, 0.0, 0.0]).tolist()
    [0.0, 1.0, 0.5]
    """
    return _apply(_FROM_RGB["hsl"], rgb, "rgb", out, dtype)


def hsl_to_rgb(
    hsl: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert HSL to RGB.

    C = (1 − ``|2L − 1|``)·S, m = L − C/2, then the same sector table as HSV.

    Parameters
    ----------
    hsl : (..., 3) array_like
        (H in degrees, S in [0, 1], L in [0, 1]).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        RGB in [0, 1].

    Examples
    --------
    >>> from pixelpath.color import hsl_to_rgb
    >>> hsl_to_rgb([240, 1, 0.5]).tolist()
    [0.0, 0.0, 1.0]
    """
    return _apply(_TO_RGB["hsl"], hsl, "hsl", out, dtype)


def rgb_to_cmy(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to CMY: the complements C = 1 − R, M = 1 − G, Y = 1 − B.

    Parameters
    ----------
    rgb : (..., 3) array_like
        RGB colours (see the module notes for integer input).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        (C, M, Y) in [0, 1]; 1 is full ink.

    Examples
    --------
    >>> from pixelpath.color import rgb_to_cmy
    >>> rgb_to_cmy([255, 255, 0]).tolist()
    [0.0, 0.0, 1.0]
    """
    return _apply(_FROM_RGB["cmy"], rgb, "rgb", out, dtype)


def cmy_to_rgb(
    cmy: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert CMY to RGB: R = 1 − C, G = 1 − M, B = 1 − Y.

    Parameters
    ----------
    cmy : (..., 3) array_like
        (C, M, Y) in [0, 1].
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        RGB in [0, 1].

    Examples
    --------
    >>> from pixelpath.color import cmy_to_rgb
    >>> cmy_to_rgb([1, 1, 0]).tolist()
    [0.0, 0.0, 1.0]
    """
    return _apply(_TO_RGB["cmy"], cmy, "cmy", out, dtype)


def rgb_to_cmyk(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to CMYK: K = min(C, M, Y) and C' = (C − K)/(1 − K), likewise M', Y'.

    Pure black gives (0, 0, 0, 1), with no division by zero.

    Parameters
    ----------
    rgb : (..., 3) array_like
        RGB colours (see the module notes for integer input).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer of shape (..., 4).

    Returns
    -------
    (..., 4) ndarray
        (C', M', Y', K) in [0, 1].

    Examples
    --------
    >>> from pixelpath.color import rgb_to_cmyk
    >>> rgb_to_cmyk([0, 0, 0]).tolist()
    [0.0, 0.0, 0.0, 1.0]
    >>> rgb_to_cmyk([1.0, 0.5, 0.0]).tolist()
    [0.0, 0.5, 1.0, 0.0]
    """
    return _apply(_FROM_RGB["cmyk"], rgb, "rgb", out, dtype)


def cmyk_to_rgb(
    cmyk: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert CMYK to RGB: R = (1 − C')(1 − K), likewise G and B.

    Parameters
    ----------
    cmyk : (..., 4) array_like
        (C', M', Y', K) in [0, 1].
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer of shape (..., 3).

    Returns
    -------
    (..., 3) ndarray
        RGB in [0, 1].

    Examples
    --------
    >>> from pixelpath.color import cmyk_to_rgb
    >>> cmyk_to_rgb([0, 0, 1, 0.5]).tolist()
    [0.5, 0.5, 0.0]
    """
    return _apply(_TO_RGB["cmyk"], cmyk, "cmyk", out, dtype)


def rgb_to_yiq(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to YIQ with the notes' NTSC matrix.

    Parameters
    ----------
    rgb : (..., 3) array_like
        RGB colours (see the module notes for integer input).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        (Y, I, Q): Y in [0, 1], I in about ±0.596, Q in about ±0.523.

    Examples
    --------
    >>> from pixelpath.color import rgb_to_yiq
    >>> [round(v, 3) for v in rgb_to_yiq([1.0, 1.0, 0.0]).tolist()]
    [0.886, 0.322, -0.312]
    """
    return _apply(_FROM_RGB["yiq"], rgb, "rgb", out, dtype)


def yiq_to_rgb(
    yiq: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert YIQ to RGB with the exact inverse of the notes' matrix.

    The notes print the inverse rounded to three decimals; the exact inverse makes round trips
    exact to float precision.

    Parameters
    ----------
    yiq : (..., 3) array_like
        (Y, I, Q).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        RGB.

    Examples
    --------
    >>> from pixelpath.color import yiq_to_rgb
    >>> yiq_to_rgb([0.299, 0.596, 0.211]).round(6) + 0.0  # + 0.0 turns -0.0 into 0.0
    array([1., 0., 0.])
    """
    return _apply(_TO_RGB["yiq"], yiq, "yiq", out, dtype)


def rgb_to_ycbcr(
    rgb: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert RGB to YCbCr, ITU-R BT.601 full range with every component in [0, 1].

    Y = 0.299 R + 0.587 G + 0.114 B, Cb = 0.5 + (B − Y)/1.772, Cr = 0.5 + (R − Y)/1.402.

    Parameters
    ----------
    rgb : (..., 3) array_like
        RGB colours (see the module notes for integer input).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        (Y, Cb, Cr).

    Examples
    --------
    >>> from pixelpath.color import rgb_to_ycbcr
    >>> [round(v, 6) for v in rgb_to_ycbcr([0.0, 0.0, 1.0]).tolist()]
    [0.114, 1.0, 0.418688]
    """
    return _apply(_FROM_RGB["ycbcr"], rgb, "rgb", out, dtype)


def ycbcr_to_rgb(
    ycbcr: ArrayLike, *, dtype: DTypeLike | None = None, out: np.ndarray | None = None
) -> NDArray[np.floating]:
    """Convert BT.601 full-range YCbCr (all in [0, 1]) to RGB.

    Parameters
    ----------
    ycbcr : (..., 3) array_like
        (Y, Cb, Cr).
    dtype : {None, "float32", "float64"}, optional
        The result's dtype: by default float32 for float32 input, else float64. Integer input
        is converted straight into it (uint8 to float32 takes half the memory of float64).
    out : ndarray, optional
        Destination buffer.

    Returns
    -------
    (..., 3) ndarray
        RGB.

    Examples
    --------
    >>> from pixelpath.color import ycbcr_to_rgb
    >>> [round(v, 6) for v in ycbcr_to_rgb([0.5, 0.5, 0.5]).tolist()]
    [0.5, 0.5, 0.5]
    """
    return _apply(_TO_RGB["ycbcr"], ycbcr, "ycbcr", out, dtype)
