"""The rendered image: linear RGB in [0, 1] with its depth, object-id, alpha and normal buffers."""

from __future__ import annotations

import io
import os
import types
from collections.abc import Mapping

import numpy as np

__all__ = ["Image"]


class Image:
    """A rendered picture and its per-pixel buffers.

    ``np.asarray(image)`` is the ``(H, W, 3)`` float32 RGB array (linear intensities in [0, 1],
    row 0 at the top). Images are read-only: the buffers are never modified after rendering.

    Parameters
    ----------
    rgb : (H, W, 3) array_like
        Intensities; stored as float32 clamped to [0, 1].
    depth : (H, W) array_like, optional
        Distance along the camera's viewing axis (smaller is nearer), ``inf`` where nothing was
        drawn. Default: all ``inf``.
    object_id : (H, W) int array_like, optional
        Index into ``scene.objects`` of the object seen at each pixel, -1 for the background.
        Default: all -1.
    stats : mapping of str to int, optional
        Counts the renderer reports about its work (for the z-buffer: triangles culled,
        clipped, scan-converted); empty by default.
    alpha : (H, W) array_like, optional
        Coverage in [0, 1]: 1 where a surface was drawn, 0 where the background shows,
        fractional on edges with supersampling. Default: 1 where ``object_id >= 0``.
    normal : (H, W, 3) array_like, optional
        Unit world-space shading normal of the visible surface (turned towards the viewer),
        0 where nothing was drawn. Default: all 0.
    background : (3,) array_like, optional
        The colour the picture shows where nothing was drawn (default black); saving with
        ``alpha=True`` takes it out of the edge pixels again.
    encoding : {"linear", "srgb"}
        How :meth:`save` and :meth:`to_uint8` encode intensities when no ``gamma`` is given
        (the scene's ``encoding``; see :class:`~pixelpath.scene.Scene`).

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> img = Image(np.full((2, 3, 3), 0.5))
    >>> np.asarray(img).shape, img.depth.dtype.name, int(img.object_id[0, 0])
    ((2, 3, 3), 'float32', -1)
    >>> img.to_uint8()[0, 0].tolist()
    [128, 128, 128]
    """

    def __init__(
        self,
        rgb: np.ndarray,
        depth: np.ndarray | None = None,
        object_id: np.ndarray | None = None,
        stats: Mapping[str, int] | None = None,
        *,
        alpha: np.ndarray | None = None,
        normal: np.ndarray | None = None,
        background: np.ndarray | None = None,
        encoding: str = "linear",
    ) -> None:
        rgb = np.asarray(rgb)
        if rgb.ndim != 3 or rgb.shape[2] != 3 or rgb.shape[0] == 0 or rgb.shape[1] == 0:
            raise ValueError(f"rgb must have shape (H, W, 3) with H, W >= 1, got {rgb.shape}")
        if not np.all(np.isfinite(rgb)):
            raise ValueError("rgb must be finite (no NaN or inf intensities)")
        size = rgb.shape[:2]
        self._rgb = _frozen(np.clip(rgb.astype(np.float32), 0.0, 1.0))
        self._depth = _frozen(_buffer(depth, size, np.float32, np.inf, "depth"))
        self._object_id = _frozen(_buffer(object_id, size, np.int32, -1, "object_id"))
        self._stats = types.MappingProxyType(dict(stats or {}))
        if alpha is None:
            alpha = self._object_id >= 0
        self._alpha = _frozen(np.clip(_buffer(alpha, size, np.float32, 0.0, "alpha"), 0.0, 1.0))
        self._normal = _frozen(_buffer(normal, (*size, 3), np.float32, 0.0, "normal"))
        self._set_output(background, encoding)

    def _set_output(self, background: np.ndarray | None, encoding: str) -> None:
        from pixelpath.scene.scene import ENCODINGS

        if encoding not in ENCODINGS:
            raise ValueError(f"encoding must be one of {', '.join(ENCODINGS)}; got {encoding!r}")
        self._encoding = encoding
        self._background = np.zeros(3) if background is None else np.asarray(background, float)

    @classmethod
    def _from_buffers(
        cls,
        rgb: np.ndarray,
        depth: np.ndarray,
        object_id: np.ndarray,
        stats: Mapping[str, int],
        normal: np.ndarray | None,
        background: np.ndarray,
        encoding: str,
    ) -> Image:
        """Wrap a renderer's own buffers without copying (already clamped float32, int32)."""
        image = cls.__new__(cls)
        image._rgb, image._depth, image._object_id = (_frozen(a) for a in (rgb, depth, object_id))
        image._stats = types.MappingProxyType(dict(stats))
        image._alpha = None  # coverage of one sample per pixel: made from object_id when asked
        if normal is None:
            normal = np.zeros((*depth.shape, 3), np.float32)
        image._normal = _frozen(normal)
        image._set_output(background, encoding)
        return image

    @property
    def rgb(self) -> np.ndarray:
        """(H, W, 3) float32 linear intensities in [0, 1] (read-only)."""
        return self._rgb

    @property
    def depth(self) -> np.ndarray:
        """(H, W) float32 view-axis distance; ``inf`` where nothing was drawn (read-only)."""
        return self._depth

    @property
    def object_id(self) -> np.ndarray:
        """(H, W) int32 index of the object seen at each pixel; -1 for background (read-only)."""
        return self._object_id

    @property
    def alpha(self) -> np.ndarray:
        """(H, W) float32 coverage: 1 where a surface was drawn, 0 on the background (read-only).

        Fractional on silhouette edges when rendered with ``ssaa``: the share of the pixel's
        samples that hit a surface.
        """
        if self._alpha is None:
            self._alpha = _frozen((self._object_id >= 0).astype(np.float32))
        return self._alpha

    @property
    def normal(self) -> np.ndarray:
        """(H, W, 3) float32 unit world-space shading normal, 0 where nothing was drawn.

        The normal the illumination model used at the pixel (interpolated for Gouraud and
        Phong shading, the polygon's for flat), turned towards the viewer (read-only).
        """
        return self._normal

    @property
    def encoding(self) -> str:
        """``"linear"`` or ``"srgb"``: how :meth:`save` encodes when given no ``gamma``."""
        return self._encoding

    @property
    def stats(self) -> Mapping[str, int]:
        """What the renderer counted while drawing this image (read-only; may be empty)."""
        return self._stats

    @property
    def width(self) -> int:
        """Width in pixels."""
        return self._rgb.shape[1]

    @property
    def height(self) -> int:
        """Height in pixels."""
        return self._rgb.shape[0]

    @property
    def shape(self) -> tuple[int, int, int]:
        """``(H, W, 3)``, as for the array."""
        return self._rgb.shape

    def __array__(self, dtype=None, copy=None) -> np.ndarray:
        if dtype is not None and np.dtype(dtype) != self._rgb.dtype:
            if copy is False:
                raise ValueError(f"converting the float32 image to {np.dtype(dtype)} needs a copy")
            return self._rgb.astype(dtype)
        return self._rgb.copy() if copy else self._rgb

    def __repr__(self) -> str:
        drawn = int(np.count_nonzero(self._object_id >= 0))
        return f"<Image {self.width}x{self.height}, {drawn} pixels drawn>"

    def to_uint8(self, gamma: float | str | None = None) -> np.ndarray:
        """Return the ``(H, W, 3)`` uint8 picture: value × 255, rounded (``gamma`` encodes first).

        ``gamma`` is a number, ``"srgb"`` or ``"linear"``; by default the image's
        :attr:`encoding`.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath import Image
        >>> Image(np.ones((1, 1, 3))).to_uint8().tolist()
        [[[255, 255, 255]]]
        """
        from pixelpath.io.images import to_uint8

        return to_uint8(self._rgb, self._encoding if gamma is None else gamma)

    def save(
        self, path: str | os.PathLike, gamma: float | str | None = None, alpha: bool = False
    ) -> None:
        """Write the picture to ``path`` atomically; the format follows the extension.

        Parameters
        ----------
        path : str or path-like
            Destination (``.png``, ``.jpg``, ...); its directory must exist.
        gamma : float or {"srgb", "linear"}, optional
            Display encoding: a gamma such as 2.2, the sRGB curve, or linear as in the notes;
            default: the image's :attr:`encoding` (linear unless the scene says otherwise).
        alpha : bool
            Write RGBA (PNG, TIFF, WebP) with :attr:`alpha` as the fourth channel; the colour
            of edge pixels is then the surface's alone (the background taken out), so the
            picture composites cleanly over anything.

        Examples
        --------
        >>> import numpy as np, os, tempfile
        >>> from pixelpath import Image
        >>> Image(np.zeros((2, 2, 3))).save(os.path.join(tempfile.mkdtemp(), "black.png"))
        """
        from pixelpath.io.images import write_image

        gamma = self._encoding if gamma is None else gamma
        if not alpha:
            write_image(path, self._rgb, gamma=gamma)
            return
        write_image(path, self.foreground(), gamma=gamma, alpha=self.alpha)

    def foreground(self) -> np.ndarray:
        """Return the (H, W, 3) colour of the surfaces alone, without the background.

        Where a pixel is partly covered (``0 < alpha < 1``) its colour is ``alpha · surface +
        (1 − alpha) · background``; this solves for the surface. 0 where nothing was drawn.

        Examples
        --------
        >>> import numpy as np
        >>> from pixelpath import Image
        >>> edge = Image(np.full((1, 1, 3), 0.6), alpha=np.full((1, 1), 0.5),
        ...              background=(0.2, 0.2, 0.2))
        >>> edge.foreground().round(6).tolist()
        [[[1.0, 1.0, 1.0]]]
        """
        coverage = self.alpha[..., None].astype(np.float64)
        behind = (1.0 - coverage) * self._background
        surface = np.divide(self._rgb - behind, coverage, out=np.zeros(self._rgb.shape),
                            where=coverage > 0.0)
        return np.clip(surface, 0.0, 1.0).astype(np.float32)

    def _repr_png_(self) -> bytes:
        """PNG bytes, for Jupyter's rich display."""
        from PIL import Image as PILImage

        buffer = io.BytesIO()
        PILImage.fromarray(self.to_uint8()).save(buffer, format="PNG")
        return buffer.getvalue()


def _buffer(values, size: tuple[int, ...], dtype: type, fill: float, name: str) -> np.ndarray:
    """Return a buffer of ``size`` and ``dtype``: ``values`` checked for shape, or ``fill``."""
    if values is None:
        return np.full(size, fill, dtype=dtype)
    array = np.asarray(values)
    if array.shape != size:
        raise ValueError(f"{name} must have shape {size} like the image, got {array.shape}")
    return array.astype(dtype)


def _frozen(array: np.ndarray) -> np.ndarray:
    array = np.ascontiguousarray(array)
    array.flags.writeable = False
    return array
