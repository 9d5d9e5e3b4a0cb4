"""Every claim of n°9–n°11 and beyond runs as a test of its own."""

from functools import lru_cache

import pytest
import sympy as sp
from expectations import expected_symbolic

import reduction
from derivation import checks
from derivation.domain import sample_point, seeded_rng
from derivation.symbols import R, k, theta
from reduction import invariants, n10_special_case
from reduction.variables import DOMAIN, a, b, c


@lru_cache(maxsize=None)
def _claims():
    return {c.id: c for c in reduction.claims()}


@pytest.mark.slow
@pytest.mark.parametrize("claim_id", list(_claims()))
def test_claim(claim_id):
    verdict = _claims()[claim_id].check()
    assert verdict.status == "confirmed", verdict
    assert verdict.symbolic == expected_symbolic(_claims()[claim_id]), verdict  # proved stays proved


def test_every_numbered_equation_of_n9_to_n11_has_a_claim():
    wheres = " ".join(c.where for c in _claims().values())
    for number in (12, 13, 14):
        assert f"eq. ({number})" in wheres
    assert {"n°10", "n°11"} <= {c.where.split(" ")[0].rstrip(",") for c in _claims().values()}


# A mutation audit of reduction/ (each test below fails on the mutant it names, passes here).


def test_the_reduction_box_keeps_a_above_b_above_c():
    """M85: the points drawn past a > b > c passed every claim."""
    rng = seeded_rng("coverage-abc")
    points = [sample_point({a, b, c}, rng, DOMAIN) for _ in range(200)]
    assert all(p[a] > p[b] > p[c] > 0 for p in points) and min(p[a] / p[b] for p in points) < 1.2


def test_a_rate_that_is_not_zero_has_no_constant_of_zero():
    """M08: `constant_of` returning 0 left n10.integral and n10.closed_form unable to fail."""
    assert n10_special_case.constant_of(sp.sin(theta), theta) != 0


def test_W_is_the_numerator_of_J_prime():
    """M09: W, which inv.J_never_constant solves, was typed and tied to J by nothing."""
    W = invariants.classes()["W"].as_expr()
    dJ = sp.diff(invariants.J_CLOSED, invariants.S)
    assert checks.exact_zero(dJ - 729 * invariants.N_POLY**2 * W / ((a - c) ** 2 * invariants.L_POLY**6))


def test_the_excess_over_9_of_the_special_case_is_its_value():
    """M11: n10.violates_9 checks the sign only."""
    assert checks.exact_zero(n10_special_case.physical_meaning()["squared excess"] - k**2 / R**2)
