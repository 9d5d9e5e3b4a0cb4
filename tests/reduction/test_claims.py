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
from reduction.variables import DOMAIN, a, b, c, x


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
    assert n10_special_case.constant_of(sp.sin(theta) ** 2 + sp.cos(theta) ** 2 - 1, theta) == 0
    with pytest.raises(ValueError, match="does not reduce to 0"):
        n10_special_case.constant_of(sp.sin(theta), theta)


def test_a_wrong_closed_form_fails_at_once(monkeypatch):
    """A wrong K (h for 2h) left an unevaluated integral that ran past pytest's 900 s: it fails now, in seconds."""
    from reduction.variables import h

    right = n10_special_case.special_case()
    wrong_K = right["K"].subs(h, 2 * h)
    X, rate = n10_special_case.X, right["dx/dtheta"].subs(x, n10_special_case.X)
    wrong = {**right, "dK/dtheta": sp.diff(wrong_K.subs(x, X), theta) + sp.diff(wrong_K.subs(x, X), X) * rate}
    monkeypatch.setattr(n10_special_case, "special_case", lambda: wrong)
    (closed_form,) = [c for c in n10_special_case.claims() if c.id == "n10.closed_form"]
    verdict = closed_form.check()
    assert verdict.status == "failed" and "does not reduce to 0" in verdict.note, verdict


def test_W_is_the_numerator_of_J_prime():
    """M09: W, which inv.J_never_constant solves, was typed and tied to J by nothing."""
    W = invariants.classes()["W"].as_expr()
    dJ = sp.diff(invariants.J_CLOSED, invariants.S)
    assert checks.exact_zero(dJ - 729 * invariants.N_POLY**2 * W / ((a - c) ** 2 * invariants.L_POLY**6))


def test_J_never_constant_rests_on_a_positive_leading_coefficient(monkeypatch):
    """inv.J_never_constant was a count of SymPy's solve (no proof: solve need not find every solution): it is the
    sign of W's leading coefficient now, which a W whose leading coefficient can vanish or go negative fails."""
    S = invariants.S
    with pytest.raises(ValueError, match="not positive"):
        invariants._positive_leading_coefficient(sp.Poly((a - c) * S**3 + S, S))
    with pytest.raises(ValueError, match="degree 0"):
        invariants._positive_leading_coefficient(sp.Poly(b, S))
    right = invariants.classes()
    monkeypatch.setattr(invariants, "classes", lambda: {**right, "W": sp.Poly(-b * S**3 + a, S)})
    (claim,) = [c for c in invariants.claims() if c.id == "inv.J_never_constant"]
    assert claim.check().status == "failed"


def test_J_never_constant_needs_N_not_identically_zero(monkeypatch):
    """𝓝 ≡ 0 would make J ≡ 0, a constant (a referee: the claim argued from W alone); 𝓝 comes from s₅'s
    definition, and an 𝓝 whose leading coefficient can vanish or is positive fails the claim."""
    S = invariants.S
    assert checks.exact_zero(invariants.N_from_definition().as_expr() - invariants.N_POLY)
    with pytest.raises(ValueError, match="negative"):
        invariants._negative_leading_coefficient(sp.Poly((a - c) * S**3 + S, S))
    with pytest.raises(ValueError, match="negative"):
        invariants._negative_leading_coefficient(sp.Poly(-b, S))
    monkeypatch.setattr(invariants, "N_from_definition", lambda: sp.Poly(63 * b**3 * (a + c) * S**3, S))
    (claim,) = [c for c in invariants.claims() if c.id == "inv.J_never_constant"]
    assert claim.check().status == "failed"


def test_the_excess_over_9_of_the_special_case_is_its_value(monkeypatch):
    """M11: n10.violates_9 checked the sign only; a mutation audit: `appell verify` confirmed ratio² − 1/2 for
    ratio² − 1.  Its display pins the value k²/R²: a wrong excess fails the claim itself."""
    assert checks.exact_zero(n10_special_case.physical_meaning()["squared excess"] - k**2 / R**2)
    (claim,) = [c for c in n10_special_case.claims() if c.id == "n10.violates_9"]
    assert claim.check().status == "confirmed"
    right = n10_special_case.physical_meaning()
    monkeypatch.setattr(n10_special_case, "physical_meaning", lambda: {**right, "squared excess": right["squared excess"] + sp.Rational(1, 2)})
    (claim,) = [c for c in n10_special_case.claims() if c.id == "n10.violates_9"]
    assert claim.check().status == "failed"


def test_the_printed_exponents_of_P_can_fail(monkeypatch):
    """normal.exponents prints e₁, e₂, e₃ typed (a referee: checked but never printed): a wrong one fails."""
    from reduction import normal_form

    right = normal_form.exponents_shown()
    monkeypatch.setattr(normal_form, "exponents_shown", lambda: {**right, normal_form.e_3: 2 * right[normal_form.e_3]})
    (exponents,) = [c for c in normal_form.claims() if c.id == "normal.exponents"]
    assert exponents.check().status == "failed"


@pytest.mark.slow
def test_the_printed_closed_form_of_tau_can_fail(monkeypatch):
    """normal.tau_F1 prints τ through F₁ with its parameters named: a wrong parameter (β₂ = 1 − 2e₃) fails."""
    from reduction import normal_form

    right = normal_form._tau_where()
    monkeypatch.setattr(normal_form, "_tau_where", lambda: {**right, normal_form.beta_2: 1 - 2 * normal_form.e_3})
    (tau,) = [c for c in normal_form.claims() if c.id == "normal.tau_F1"]
    assert tau.check().status == "failed"
