"""The work of one task: pure, picklable functions of (scene, frame, options).

They are module-level functions of plain arguments, so any process that has pixelpath can run
them (Dask pickles them by reference) and the same arguments always give the same result: a
frame rendered on a worker is the frame rendered here, to the byte.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from pixelpath.image import Image
from pixelpath.scene import Scene

if TYPE_CHECKING:
    from pixelpath.frames.views import ViewJob


def render_frame(
    scene: Scene,
    frame: int,
    options: dict[str, Any],
    region: tuple[int, int, int, int] | None = None,
) -> Image:
    """Render ``frame`` of ``scene`` (or the ``region`` of it) with ``render``'s ``options``.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.frames import render_frame
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6))
    >>> render_frame(scene, 0, {"shading": "flat"}, region=(0, 0, 4, 6)).shape
    (6, 4, 3)
    """
    from pixelpath.renderer import render

    return render(scene.at_frame(frame), region=region, **options)


def frame_file(
    scene: Scene,
    frame: int,
    options: dict[str, Any],
    suffix: str,
    gamma: float | None,
    png_level: int | None = None,
) -> bytes:
    """Return the bytes of ``frame``'s image file (format by ``suffix``, e.g. ``".png"``).

    ``png_level`` is a PNG's zlib compression level (0-9), as in
    :func:`pixelpath.io.images.encode_image`; by default 6, as ``Image.save``.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.frames import frame_file
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6))
    >>> frame_file(scene, 0, {}, ".png", None, png_level=1)[1:4]
    b'PNG'
    """
    return encode(render_frame(scene, frame, options), suffix, gamma, png_level=png_level)


def in_turn(function: Callable, scene: Scene, calls: Sequence[tuple]) -> list:
    """Return ``[function(scene, *call) for call in calls]``: several frames as one task.

    A cluster's scheduler spends a few milliseconds of CPU on every task, whatever it does; a
    task of several frames pays that once for all of them.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.frames.work import in_turn, render_frame
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6))
    >>> [image.shape for image in in_turn(render_frame, scene, [(0, {}), (1, {})])]
    [(6, 8, 3), (6, 8, 3)]
    """
    return [function(scene, *call) for call in calls]


def warm_up(options: dict[str, Any]) -> None:
    """Render a tiny scene of every kind of object with ``options``, compiling what they need.

    The kernels that encode files' pixels (:func:`pixelpath.io.images.to_uint8`) too.

    Numba compiles a kernel for the types of its arguments, not their values, so this compiles
    (or loads from the disk cache) every kernel that frames rendered with ``options`` call.

    Examples
    --------
    >>> from pixelpath.frames.work import warm_up
    >>> warm_up({"shading": "gouraud"})
    """
    from pixelpath.io.images import to_uint8
    from pixelpath.renderer import render
    from pixelpath.scene import Box, Camera, DirectionalLight, Plane, PointLight, Sphere
    from pixelpath.scene.procedural import icosphere

    scene = Scene(
        Camera(eye=(0, 1, 4), target=(0, 0, 0), width=8, height=6),
        [
            Plane((0, -1, 0), (0, 1, 0)),
            Sphere((-1, 0, 0), 0.5),
            Box((0, -0.5, -0.5), (1, 0.5, 0.5)),
            icosphere(subdivisions=0, radius=0.3, center=(0, 1, 0)),
        ],
        [PointLight((2, 3, 4)), DirectionalLight((-1, -1, -1))],
    )
    render(scene, **options)
    to_uint8(np.zeros((1, 1, 3), np.float32))  # and the 8-bit encoding of the files
    to_uint8(np.zeros((1, 1, 3), np.float32), "srgb")


def view_files(job: ViewJob, index: int) -> None:
    """Render view ``index`` of a dataset of views and write its files.

    Examples
    --------
    >>> import os, tempfile
    >>> import pixelpath as pp
    >>> from pixelpath.frames.views import plan_views
    >>> from pixelpath.frames.work import view_files
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6),
    ...                  [pp.Sphere((0, 0, 0), 1.0)])
    >>> plan = plan_views(scene, 3, tempfile.mkdtemp(), "mask")
    >>> view_files(plan.job, 2)
    >>> sorted(os.listdir(os.path.join(plan.job.output.folder, "masks")))
    ['view_0002.png']
    """
    job.output.write(index, job.render(index))


def encode(
    image: Image,
    suffix: str,
    gamma: float | str | None,
    alpha: bool = False,
    png_level: int | None = None,
) -> bytes:
    """Return ``image`` encoded as ``Image.save(path, gamma, alpha)`` would write it.

    ``png_level`` (0-9) is a PNG's zlib compression level, as in
    :func:`pixelpath.io.images.encode_image`; by default 6, as ``Image.save``.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.frames.work import encode
    >>> encode(Image(np.zeros((2, 2, 3))), ".png", None, png_level=1)[1:4]
    b'PNG'
    """
    from pixelpath.io.images import encode_image

    if not alpha:
        return picture_encoder(image, suffix, gamma, png_level)()
    return encode_image(
        image.foreground(),
        suffix,
        gamma=image.encoding if gamma is None else gamma,
        alpha=image.alpha,
        png_level=png_level,
    )


def picture_encoder(
    image: Image, suffix: str, gamma: float | str | None, png_level: int | None = None
) -> Callable[[], bytes]:
    """Return a call that encodes ``image``'s picture as :func:`encode` does (no alpha).

    The call holds the picture's pixels only, not the image's other buffers (depth, ...):
    what a frame waiting for a writer thread keeps in memory.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.frames.work import picture_encoder
    >>> picture_encoder(Image(np.zeros((2, 2, 3))), ".png", None)()[1:4]
    b'PNG'
    """
    from pixelpath.io.images import encode_image

    gamma = image.encoding if gamma is None else gamma
    return functools.partial(encode_image, image.rgb, suffix, gamma=gamma, png_level=png_level)


def stitch(tiles: Sequence[Image], regions: Sequence[tuple[int, int, int, int]]) -> Image:
    """Return the image the ``tiles`` (rendered over ``regions``) cover, buffers included.

    The stitched image has no ``stats``: counts of separate tiles do not add up to a frame's.

    Examples
    --------
    >>> import numpy as np
    >>> from pixelpath import Image
    >>> from pixelpath.frames.work import stitch
    >>> left, right = Image(np.zeros((2, 1, 3))), Image(np.ones((2, 2, 3)))
    >>> np.asarray(stitch([left, right], [(0, 0, 1, 2), (1, 0, 3, 2)]))[:, :, 0].tolist()
    [[0.0, 1.0, 1.0], [0.0, 1.0, 1.0]]
    """
    width = max(region[2] for region in regions)
    height = max(region[3] for region in regions)
    rgb = np.empty((height, width, 3), np.float32)
    depth = np.empty((height, width), np.float32)
    object_id = np.empty((height, width), np.int32)
    alpha = np.empty((height, width), np.float32)
    normal = np.empty((height, width, 3), np.float32)
    for tile, (x0, y0, x1, y1) in zip(tiles, regions, strict=True):
        rgb[y0:y1, x0:x1] = tile.rgb
        depth[y0:y1, x0:x1] = tile.depth
        object_id[y0:y1, x0:x1] = tile.object_id
        alpha[y0:y1, x0:x1] = tile.alpha
        normal[y0:y1, x0:x1] = tile.normal
    first = tiles[0]
    return Image(
        rgb,
        depth,
        object_id,
        alpha=alpha,
        normal=normal,
        background=first._background,
        encoding=first.encoding,
    )
