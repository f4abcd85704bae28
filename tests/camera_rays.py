"""The rays of a perspective camera's pixel centres, computed independently of pixelpath."""

from __future__ import annotations

import math

import numpy as np

import pixelpath as pp


def view_rays(camera: pp.Camera) -> np.ndarray:
    """(H, W, 3) rays through the pixel centres, scaled so that their dot with forward is 1.

    A point at view-axis depth d along a pixel's ray is ``eye + d * ray``.
    """
    eye, target = np.asarray(camera.eye, float), np.asarray(camera.target, float)
    w = (eye - target) / np.linalg.norm(eye - target)
    u = np.cross([0.0, 1.0, 0.0], w)
    u /= np.linalg.norm(u)
    v = np.cross(w, u)
    half = math.tan(math.radians(camera.fov) / 2)
    cols, rows = np.meshgrid(np.arange(camera.width) + 0.5, np.arange(camera.height) + 0.5)
    x = (2 * cols / camera.width - 1) * half * camera.width / camera.height
    y = (1 - 2 * rows / camera.height) * half
    return x[..., None] * u + y[..., None] * v - w
