"""`numerics.vector_exp.exp`: within an ulp of e^x over float64's range, saturating as the C library does."""

import math

import mpmath
import numba
import numpy as np
import pytest

from numerics import vector_exp


def _ulps(x: float) -> float:
    """|exp(x) − e^x| in units of the last place of e^x (40-digit reference)."""
    with mpmath.workdps(40):
        exact = mpmath.exp(mpmath.mpf(x))
        got = vector_exp.exp(x)
        return float(abs(mpmath.mpf(got) - exact) / mpmath.mpf(np.spacing(float(exact))))


def test_within_an_ulp_where_the_slide_evaluates_it_and_beyond():
    rng = np.random.default_rng(7)
    xs = np.concatenate([rng.uniform(-80, 10, 3000),  # −σ of a slide: V from 1e-35 to 2e4
                         rng.uniform(-745, 709, 1000),
                         [0.0, -0.0, 1e-300, -1e-300, 0.5 * math.log(2), -0.5 * math.log(2), math.log(2), 1.0]])
    worst = max(_ulps(float(x)) for x in xs)
    assert worst < 1.0


def test_subnormal_results_are_rounded_once():
    for x in (-708.5, -720.0, -740.0, -744.5):
        assert _ulps(x) < 1.0


def test_saturation_and_nan():
    assert vector_exp.exp(-746.0) == 0.0 == vector_exp.exp(-1e10) == vector_exp.exp(-math.inf)
    assert vector_exp.exp(710.0) == math.inf == vector_exp.exp(1e10) == vector_exp.exp(math.inf)
    assert vector_exp.exp(709.7) == pytest.approx(math.exp(709.7), rel=2.3e-16, abs=0)
    assert math.isnan(vector_exp.exp(math.nan))


def test_the_compiled_copy_gives_the_same_bits():
    from numerics import compiled

    exp = compiled._COMPILED["exp"]
    xs = np.random.default_rng(8).uniform(-745, 709, 2000)
    assert all(exp(float(x)) == vector_exp.exp(float(x)) for x in xs)


def test_two_to_builds_every_normal_power_of_two_from_its_bits():
    """2^j from j's exponent field, for every j `exp` asks (|j| ≤ 538) and beyond, interpreted and compiled."""
    from numerics import compiled

    two_to = compiled._COMPILED["two_to"]
    for j in range(-1022, 1024):
        assert vector_exp.two_to(float(j)) == math.ldexp(1.0, j) == two_to(float(j))


def test_the_bits_of_a_float_read_and_written_alike_interpreted_and_compiled():
    from numerics import compiled

    as_bits, as_float = compiled.COMPILED_AS["float_bits"], compiled.COMPILED_AS["bits_float"]
    float_bits = numba.njit(lambda x: as_bits(x))  # intrinsics: callable from compiled code only
    bits_float = numba.njit(lambda n: as_float(n))
    for x in (0.0, -0.0, 1.0, -2.5, 5e-324, 1.7976931348623157e308, math.inf, 2.0**52 + 1075.0):
        n = vector_exp.float_bits(x)
        assert n == int(np.float64(x).view(np.int64)) == float_bits(x)
        assert vector_exp.bits_float(n) == x == bits_float(n) and math.copysign(1.0, bits_float(n)) == math.copysign(1.0, x)
