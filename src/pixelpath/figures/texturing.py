"""Texturing figure: affine against perspective-correct interpolation of texture coordinates.

A checkerboard floor receding from the eye, drawn twice. On the right, as
:func:`pixelpath.render` draws it: (u, v) interpolated perspective-correctly, ``u/w``, ``v/w``
and ``1/w`` linear in screen space and divided per pixel. On the left, (u, v) interpolated
linearly in screen space (*affine*), as if every vertex had the same w: the squares no longer
shrink with distance, and each of the floor's two triangles bends the rows of squares its own
way, so the rows break along the diagonal between them. That is the classic picture of why
the division by w matters (and what early game consoles, which skipped it, looked like).

The affine half is computed here with NumPy from the renderer's own screen triangles (the
front end's set-up records hold the screen-space weights' planes); the product's kernels have
no affine mode.

Examples
--------
>>> from pixelpath.figures.texturing import perspective_figure
>>> perspective_figure(width=64, height=48).height  # 48 rows under the captions
86
"""

from __future__ import annotations

import numpy as np
from PIL import Image

from pixelpath.figures._canvas import paste_row

__all__ = ["affine_rgb", "checkerboard", "perspective_figure", "receding_floor"]

CAPTIONS = ("affine: u, v linear on screen", "perspective-correct: u/w, v/w, 1/w")
# The squares' colours (sRGB-encoded, as 8-bit pictures are).
LIGHT, DARK = (236, 232, 220), (46, 84, 150)


def checkerboard(squares: int = 8) -> np.ndarray:
    """Return a ``squares × squares`` checkerboard texture, one texel per square.

    Examples
    --------
    >>> from pixelpath.figures.texturing import checkerboard
    >>> board = checkerboard(4)
    >>> board.shape, board.dtype.name, bool((board[0, 0] != board[0, 1]).any())
    ((4, 4, 3), 'uint8', True)
    """
    if not isinstance(squares, int) or squares < 2:
        raise ValueError(f"squares must be an int >= 2, got {squares!r}")
    dark = np.indices((squares, squares)).sum(axis=0) % 2 == 1
    return np.where(dark[..., None], np.array(DARK, np.uint8), np.array(LIGHT, np.uint8))


def receding_floor(width: int = 240, height: int = 180, squares: int = 8):
    """Return a scene of a square checkerboard floor, 6 x 12 units, running away from the eye.

    The floor is one quad (two triangles) lit by ambient light only, with ``ka = 1``: every
    pixel shows its texel's colour exactly, in both halves of :func:`perspective_figure`.
    Nearest filtering keeps the squares' edges sharp.

    Examples
    --------
    >>> from pixelpath.figures.texturing import receding_floor
    >>> scene = receding_floor(64, 48)
    >>> scene.objects[0].material.texture_filter, scene.camera.width
    ('nearest', 64)
    """
    from pixelpath.scene import Camera, Material, Mesh, Scene

    material = Material(texture=checkerboard(squares), texture_filter="nearest", ka=1.0, kd=0.0,
                        ks=0.0)
    floor = Mesh([[-3, 0, 0], [3, 0, 0], [3, 0, -12], [-3, 0, -12]], [[0, 1, 2, 3]], material,
                 uv=[[0, 0], [1, 0], [1, 1], [0, 1]], name="floor")
    camera = Camera(eye=(0, 2, 3.2), target=(0, 0, -3), fov=50, width=width, height=height)
    return Scene(camera, [floor], [], ambient=1.0, background=(1, 1, 1), encoding="srgb")


def affine_rgb(scene) -> np.ndarray:
    """Render ``scene``'s textured surfaces with texture coordinates interpolated affinely.

    The front end of the raster pipeline gives the screen triangles; at each pixel centre the
    screen-space barycentric weights ``s0, s1, s2`` (linear in x and y, no division by w) mix
    the vertices' (u, v), and the texture's base level is read at the nearest texel (with
    wrap ``repeat``). Meant for :func:`receding_floor`-like scenes: one unlit (``ka = 1``,
    ``ambient = 1``), nearest-filtered texture, drawn without a depth test in triangle order.

    Returns
    -------
    (H, W, 3) float64
        Linear colour, the scene's background where nothing is drawn.

    Examples
    --------
    >>> from pixelpath.figures.texturing import affine_rgb, receding_floor
    >>> affine_rgb(receding_floor(64, 48)).shape
    (48, 64, 3)
    """
    from pixelpath.contract import RenderOptions, View
    from pixelpath.hsr import pipeline
    from pixelpath.raster import _setup_kernels

    view = View.whole(scene.camera)
    prepared = pipeline.prepare(scene, view, RenderOptions())
    ids = pipeline.paint(prepared, view, np.arange(len(prepared.triangles))).triangle_id.copy()
    rgb = np.empty((*ids.shape, 3))
    rgb[:] = scene.background
    rows, cols = np.nonzero(ids >= 0)
    triangles = ids[rows, cols]
    setup = prepared.setup[triangles]
    x, y = cols + 0.5, rows + 0.5
    s1 = setup[:, _setup_kernels.S1_PLANE] * x + setup[:, _setup_kernels.S1_PLANE + 1] * y
    s1 += setup[:, _setup_kernels.S1_PLANE + 2]
    s2 = setup[:, _setup_kernels.S2_PLANE] * x + setup[:, _setup_kernels.S2_PLANE + 1] * y
    s2 += setup[:, _setup_kernels.S2_PLANE + 2]
    weights = np.stack([1.0 - s1 - s2, s1, s2], axis=1)
    uv = np.einsum("nk,nkc->nc", weights, prepared.uv[prepared.triangles[triangles]])
    objects = prepared.info[triangles, 0]
    for obj in np.unique(objects).tolist():
        mine = objects == obj
        texels = scene.objects[obj].material.texture.linear(0)
        height, width = texels.shape[:2]
        col = np.floor(uv[mine, 0] * width).astype(np.intp) % width
        row = np.floor((1.0 - uv[mine, 1]) * height).astype(np.intp) % height
        rgb[rows[mine], cols[mine]] = texels[row, col, :3]
    return rgb


def perspective_figure(scene=None, width: int = 240, height: int = 180) -> Image.Image:
    """Draw a receding checkerboard with affine and with perspective-correct texturing.

    Parameters
    ----------
    scene : Scene, optional
        What to draw (see :func:`affine_rgb` for what suits it); by default
        :func:`receding_floor` of ``width × height`` pixels.
    width, height : int
        The size of each half when ``scene`` is not given.

    Returns
    -------
    PIL.Image.Image
        The affine half on the left, the perspective-correct one (:func:`pixelpath.render`)
        on the right, each captioned.

    Examples
    --------
    >>> from pixelpath.figures.texturing import perspective_figure
    >>> perspective_figure(width=96, height=72).save("texturing.png")
    """
    from pixelpath.image import Image as Picture
    from pixelpath.renderer import render

    scene = receding_floor(width, height) if scene is None else scene
    correct = render(scene, method="zbuffer", shading="flat")
    affine = Picture(affine_rgb(scene), encoding=correct.encoding)
    halves = [Image.fromarray(picture.to_uint8()) for picture in (affine, correct)]
    return paste_row(halves, CAPTIONS)
