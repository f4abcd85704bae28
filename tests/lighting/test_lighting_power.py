"""The specular power: repeated squaring for whole exponents, pow otherwise."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.lighting._kernels import power


@settings(max_examples=200, deadline=None)
@given(st.floats(0.0, 1.0), st.integers(0, 4096))
def test_whole_exponents_match_pow(base, exponent):
    assert power(base, float(exponent)) == pytest.approx(base**exponent, rel=1e-12, abs=1e-300)


@pytest.mark.parametrize(("base", "exponent"), [(0.866, 20.5), (0.5, 0.25), (0.9, 5000.0)])
def test_other_exponents_use_pow(base, exponent):
    assert power(base, exponent) == math.pow(base, exponent)


def test_notes_value():
    # SPEC errata: 0.866^20 = 0.0563 (the notes print 0.0117).
    assert power(0.866, 20.0) == pytest.approx(0.0563, abs=5e-5)
