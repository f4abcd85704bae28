"""New big buffers: huge-page spans inside them, aligned; small buffers as they come."""

from __future__ import annotations

import mmap

import numpy as np
import pytest

from pixelpath._memory import HUGE_PAGE, WHOLE_PAGES_FROM, fresh

needs_madvise = pytest.mark.skipif(
    not hasattr(mmap, "MADV_HUGEPAGE"),
    reason="no madvise(MADV_HUGEPAGE) here (not Linux): fresh() allocates as NumPy does",
)


def _mapping_end(array: np.ndarray) -> int:
    block = array
    while isinstance(block.base, np.ndarray):
        block = block.base
    return block.ctypes.data + block.nbytes


@needs_madvise
@pytest.mark.parametrize("shape", [(400, 640, 3), (HUGE_PAGE // 4,), (1024, 1024)])
def test_a_big_buffer_starts_on_a_huge_page(shape):
    array = fresh(shape, np.float32)
    assert array.shape == shape and array.dtype == np.float32 and array.flags.c_contiguous
    assert array.flags.writeable and array.ctypes.data % HUGE_PAGE == 0


@needs_madvise
@pytest.mark.parametrize("nbytes", [WHOLE_PAGES_FROM, HUGE_PAGE - 8, 3 * HUGE_PAGE + 8])
def test_whole_pages_reach_past_the_buffers_end_to_a_whole_span(nbytes):
    array = fresh((nbytes // 8,), np.float64, whole_pages=True)
    assert array.ctypes.data % HUGE_PAGE == 0
    end = array.ctypes.data + array.nbytes
    assert _mapping_end(array) >= -(-end // HUGE_PAGE) * HUGE_PAGE


@pytest.mark.parametrize("whole_pages", [False, True])
def test_a_small_buffer_is_allocated_as_it_comes(whole_pages):
    limit = WHOLE_PAGES_FROM if whole_pages else HUGE_PAGE
    array = fresh((limit // 4 - 1,), np.float32, whole_pages=whole_pages)
    assert array.base is None


def test_buffers_do_not_share_memory():
    a, b = fresh((512, 512), np.float64), fresh((512, 512), np.float64)
    a[...] = 1.0
    b[...] = 2.0
    assert not np.shares_memory(a, b) and np.all(a == 1.0) and np.all(b == 2.0)


def test_a_refused_mapping_falls_back_to_numpy(monkeypatch):
    def refuse(*args, **kwargs):
        raise OSError(12, "Cannot allocate memory")

    monkeypatch.setattr(mmap, "mmap", refuse)
    array = fresh((1024, 1024), np.float32)
    assert array.shape == (1024, 1024) and array.base is None
