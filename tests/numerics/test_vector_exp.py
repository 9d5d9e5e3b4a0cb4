"""`numerics.vector_exp.exp`: within an ulp of e^x over float64's range, saturating as the C library does."""

import math

import mpmath
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
