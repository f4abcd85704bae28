"""Every hidden-surface method draws what the z-buffer draws, on every kind of scene.

The scenes and the check live in ``agreement.py``: object ids equal on at least 99.5 % of the
pixels, differences only on edges of the id image, colours and depths equal where the ids are.
A region of the image (a tile) must equal the same pixels of the whole image exactly.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from agreement import KINDS, check_agreement, scene_of

import pixelpath as pp

# The methods that decide visibility their own way (the z-buffer is the reference).
METHODS: list[str] = ["scanline", "painter", "bsp", "warnock", "octree"]
ALL_METHODS = ["zbuffer", *METHODS]
# Cases the no-JIT pass cannot afford (the JIT pass runs them): the BSP build in plain Python
# takes about a minute on the floor scene's 5,120-triangle sphere, and 9-10 s on the
# interpenetrating and separate scenes; the near scene's case keeps the BSP method in that pass.
SLOW_CASES = {("bsp", "floor"), ("bsp", "interpenetrating"), ("bsp", "separate")}


def cases(methods, kind):
    """(method, kind) parameters, the ones in SLOW_CASES marked slow."""
    return [
        pytest.param(method, kind, marks=[pytest.mark.slow] if (method, kind) in SLOW_CASES
                     else [])
        for method in methods
    ]


@pytest.mark.parametrize(("method", "kind"), [c for kind in KINDS for c in cases(METHODS, kind)])
def test_method_agrees_with_the_zbuffer(method, kind):
    check_agreement(scene_of(kind, seed=1), method)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("shading", ["flat", "gouraud"])
def test_method_agrees_in_every_shading_mode(method, shading):
    check_agreement(scene_of("interpenetrating", seed=2), method, shading)


@pytest.mark.parametrize("method", METHODS)
def test_method_agrees_with_back_faces_drawn(method):
    check_agreement(scene_of("near", seed=3), method, backface_cull=False)


@pytest.mark.parametrize(("method", "kind"), cases(ALL_METHODS, "floor"))
def test_tiles_equal_the_whole_image(method, kind):
    scene = scene_of(kind, seed=4)
    whole = pp.render(scene, method, ssaa=2)
    width, height = scene.camera.width, scene.camera.height
    columns, rows = (0, 37, width), (0, 20, 51, height)
    for x0, x1 in itertools.pairwise(columns):
        for y0, y1 in itertools.pairwise(rows):
            tile = pp.render(scene, method, ssaa=2, region=(x0, y0, x1, y1))
            assert np.array_equal(np.asarray(tile), np.asarray(whole)[y0:y1, x0:x1])
            assert np.array_equal(tile.depth, whole.depth[y0:y1, x0:x1])
            assert np.array_equal(tile.object_id, whole.object_id[y0:y1, x0:x1])


def test_a_region_must_lie_inside_the_image():
    scene = scene_of("floor")
    with pytest.raises(ValueError, match="region"):
        pp.render(scene, region=(0, 0, scene.camera.width + 1, 10))
    with pytest.raises(ValueError, match="region"):
        pp.render(scene, region=(5, 5, 5, 10))
    with pytest.raises(TypeError, match="region"):
        pp.render(scene, region=(0, 0, 1.5, 10))
