"""A quad with holes cut by its texture's alpha, and where its holes are, by hand.

The picture is 2 x 2: an opaque red texel and a transparent one on the top row, a transparent
one and an opaque green one below. Where a pixel sees it is computed here with independent
NumPy geometry (the pixel centre's ray met with the quad's plane, the texel under that point
looked up by hand), never by the renderer.
"""

from __future__ import annotations

import numpy as np

import pixelpath as pp
from camera_rays import view_rays

SQUARE = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]  # counter-clockwise seen from +z
SQUARE_UV = [[0, 0], [1, 0], [1, 1], [0, 1]]  # (0, 0) at the bottom-left
# Rows top to bottom: opaque red, transparent; transparent, opaque green (the transparent
# texels are white: they must not be drawn).
HOLES = np.array(
    [[[255, 0, 0, 255], [255, 255, 255, 0]], [[255, 255, 255, 0], [0, 255, 0, 255]]], np.uint8
)
OPAQUE = HOLES[..., 3] == 255  # (row, column) of the texels that stay
RED, GREEN, BLUE = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)
SIZE, FOV = 32, 60.0


def unlit(**options) -> pp.Material:
    """A white material lit by the ambient term alone (ka Ia = 1): the pixel is its colour."""
    return pp.Material(color=(1, 1, 1), ka=1.0, kd=0.0, ks=0.0, **options)


def holed_quad(z=0.0, **options) -> pp.Mesh:
    """The square [-1, 1]^2 at height z facing +z, u along +x and v along +y, with HOLES."""
    material = unlit(texture=HOLES, texture_filter="nearest", alpha_cutoff=0.5, **options)
    return pp.Mesh(np.add(SQUARE, (0.0, 0.0, z)), [[0, 1, 2, 3]], material, uv=SQUARE_UV)


def wall(z=-1.0, color=BLUE, normal_z=1.0, half=3.0) -> pp.Mesh:
    """An unlit square of side 2 * half at height z, facing +z (or -z)."""
    corners = [[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]]
    faces = [[0, 1, 2, 3]] if normal_z > 0 else [[3, 2, 1, 0]]
    return pp.Mesh(corners, faces, pp.Material(color=color, ka=1.0, kd=0.0, ks=0.0))


def camera(eye=(0, 0, 3), target=(0, 0, 0)) -> pp.Camera:
    return pp.Camera(eye=eye, target=target, fov=FOV, width=SIZE, height=SIZE)


def facing_scene(objects, eye=(0, 0, 3), target=(0, 0, 0)) -> pp.Scene:
    return pp.Scene(camera(eye, target), objects=objects, lights=[pp.PointLight((0, 0, 5))],
                    ambient=1.0)


def texel_under(x: np.ndarray, y: np.ndarray):
    """Where the square [-1, 1]^2 is met at (x, y): inside, clearly inside a texel, the texel."""
    inside = (np.abs(x) < 1) & (np.abs(y) < 1)
    u, v = (x + 1) / 2, (y + 1) / 2
    column = np.clip(np.floor(u * 2), 0, 1).astype(int)
    row = np.clip(np.floor((1 - v) * 2), 0, 1).astype(int)
    # away from the texel borders (x or y near 0) and the quad's edges (near +-1)
    clear = (np.minimum(np.abs(x), np.abs(y)) > 0.08) & (np.abs(np.abs(x) - 1) > 0.08) & (
        np.abs(np.abs(y) - 1) > 0.08
    )
    return inside, clear, row, column


def expected_holes(distance: float):
    """Per pixel of the camera at (0, 0, 3) looking down -z, the quad seen ``distance`` ahead.

    Returns whether the quad is drawn there (not cut away), which pixels are clear of texel
    borders and edges, and the colour of its texel.
    """
    rays = view_rays(camera())
    inside, clear, row, column = texel_under(distance * rays[..., 0], distance * rays[..., 1])
    kept = inside & OPAQUE[row, column]
    colour = np.where((row == 0)[..., None], RED, GREEN)
    return kept, clear, colour
