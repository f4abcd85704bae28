"""New big buffers: aligned to huge pages from half a MiB up, plain below."""

from __future__ import annotations

import numpy as np
import pytest

from pixelpath._memory import ALIGNED_FROM, HUGE_PAGE, fresh


@pytest.mark.parametrize("shape", [(400, 640, 3), (ALIGNED_FROM // 4,), (1024, 1024)])
def test_a_big_buffer_starts_on_a_huge_page_inside_whole_huge_pages(shape):
    array = fresh(shape, np.float32)
    assert array.shape == shape and array.dtype == np.float32 and array.flags.c_contiguous
    assert array.flags.writeable and array.ctypes.data % HUGE_PAGE == 0
    block = array.base
    while block.base is not None:
        block = block.base
    end = array.ctypes.data + array.nbytes
    assert block.nbytes % HUGE_PAGE == 0
    assert block.ctypes.data + block.nbytes >= -(-end // HUGE_PAGE) * HUGE_PAGE


def test_a_small_buffer_is_allocated_as_it_comes():
    array = fresh((ALIGNED_FROM // 4 - 1,), np.float32)
    assert array.base is None and array.nbytes < ALIGNED_FROM


def test_buffers_do_not_share_memory():
    a, b = fresh((512, 512), np.float64), fresh((512, 512), np.float64)
    a[...] = 1.0
    b[...] = 2.0
    assert not np.shares_memory(a, b) and np.all(a == 1.0)
