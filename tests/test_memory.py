"""Scratch buffers: on whole huge pages from half a MiB up, aligned; smaller ones as NumPy's."""

from __future__ import annotations

import mmap

import numpy as np
import pytest

from pixelpath._memory import HUGE_FROM, HUGE_PAGE, fresh

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
@pytest.mark.parametrize("nbytes", [HUGE_FROM, HUGE_PAGE - 8, 3 * HUGE_PAGE + 8])
def test_a_buffer_starts_on_a_huge_page_and_its_mapping_reaches_a_whole_span(nbytes):
    array = fresh((nbytes // 8,), np.float64)
    assert array.shape == (nbytes // 8,) and array.dtype == np.float64
    assert array.flags.c_contiguous and array.flags.writeable
    assert array.ctypes.data % HUGE_PAGE == 0
    end = array.ctypes.data + array.nbytes
    assert _mapping_end(array) >= -(-end // HUGE_PAGE) * HUGE_PAGE


def test_a_small_buffer_is_numpys():
    array = fresh((HUGE_FROM // 4 - 1,), np.float32)
    assert array.base is None


def test_buffers_do_not_share_memory():
    a, b = fresh((400, 640), np.float64), fresh((400, 640), np.int32)
    a[...] = 1.0
    b[...] = 2
    assert not np.shares_memory(a, b) and np.all(a == 1.0) and np.all(b == 2)


def test_a_refused_mapping_falls_back_to_numpy(monkeypatch):
    def refuse(*args, **kwargs):
        raise OSError(12, "Cannot allocate memory")

    monkeypatch.setattr(mmap, "mmap", refuse)
    array = fresh((1024, 1024), np.float32)
    assert array.shape == (1024, 1024) and array.base is None
