"""Recycled output buffers: memory comes back only when no array uses it."""

from __future__ import annotations

import mmap

import numpy as np
import pytest

import pixelpath as pp
from pixelpath._memory import HUGE_FROM, HUGE_PAGE
from pixelpath.raster import _pool


def test_memory_in_use_is_never_handed_out_again():
    first = _pool.empty((64, 64), np.float32)
    view = first[3:, ::2]  # a view keeps the buffer in use after the array is gone
    del first
    second = _pool.empty((64, 64), np.float32)
    assert not np.shares_memory(second, view)


def test_memory_is_reused_once_every_view_is_gone():
    first = _pool.empty((64, 32), np.int32)
    address = first.__array_interface__["data"][0]
    view = first.T
    del first, view
    again = _pool.empty((64, 32), np.int32)
    assert again.__array_interface__["data"][0] == address


def test_images_held_by_the_caller_keep_their_own_pixels():
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=24, height=16)
    red = pp.Scene(camera, objects=[pp.Sphere((0, 0, 0), 1.0, pp.Material(color=(1, 0, 0)))],
                   lights=[pp.PointLight((2, 2, 4))])
    blue = pp.Scene(camera, objects=[pp.Sphere((0, 0, 0), 1.0, pp.Material(color=(0, 0, 1)))],
                    lights=[pp.PointLight((2, 2, 4))])
    kept = pp.render(red)
    pixels = np.asarray(kept).copy()
    for _ in range(3):
        other = pp.render(blue)
        assert not np.shares_memory(np.asarray(other), np.asarray(kept))
        del other
    assert np.array_equal(np.asarray(kept), pixels)


def test_every_pixel_of_a_recycled_buffer_is_rewritten():
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=40, height=70)
    busy = pp.Scene(camera, objects=[pp.Plane((0, 0, 0), (0, 0, 1))], background=(1, 1, 1))
    for _ in range(2):
        pp.render(busy)  # fills buffers, which go back to the pool
    empty = pp.render(pp.Scene(camera, background=(0.25, 0.5, 0.75)))
    assert np.all(np.asarray(empty) == np.float32([0.25, 0.5, 0.75]))
    assert np.all(np.isinf(empty.depth)) and np.all(empty.object_id == -1)


def test_an_image_kept_in_part_keeps_its_pixels():
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=24, height=16)
    scene = pp.Scene(camera, objects=[pp.Sphere((0, 0, 0), 1.0)], lights=[pp.PointLight((2, 2, 4))])
    for method in ("zbuffer", "raytrace"):
        normal = pp.render(scene, method).normal
        kept = normal.copy()
        for _ in range(3):
            pp.render(pp.Scene(camera, background=(1, 1, 1)), method)
        assert np.array_equal(normal, kept) and np.any(kept != 0)


@pytest.mark.skipif(not hasattr(mmap, "MADV_HUGEPAGE"),
                    reason="no madvise(MADV_HUGEPAGE) here (not Linux): every block is NumPy's")
def test_the_first_blocks_of_a_size_are_on_huge_pages_and_later_ones_numpys(monkeypatch):
    monkeypatch.setattr(_pool, "_made", {})  # as in a fresh process
    monkeypatch.setattr(_pool, "_spares", {})
    shape = (HUGE_FROM // 4 + 3,)
    blocks = [_pool.empty(shape, np.float32) for _ in range(_pool.HUGE_BLOCKS_PER_SIZE + 1)]
    on_huge_pages = [b.ctypes.data % HUGE_PAGE == 0 for b in blocks]
    assert on_huge_pages == [True] * _pool.HUGE_BLOCKS_PER_SIZE + [False]
