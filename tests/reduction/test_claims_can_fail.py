"""The claims added for n°10's recovery of x and y: each turns red when wrong
(that they are confirmed is `test_claims.test_claim`)."""

import dataclasses

import sympy as sp

from reduction import n10_special_case
from reduction.variables import x, y


def _claim(module, claim_id):
    return next(c for c in module.claims() if c.id == claim_id)


def test_recovery_fails_with_the_other_root():
    claim = _claim(n10_special_case, "n10.recovery")
    # The other root of the quadratic: x₂ = −y₁, y₂ = −x₁.
    other = [sp.Eq(x, -claim.printed[1].rhs), sp.Eq(y, -claim.printed[0].rhs)]
    assert dataclasses.replace(claim, printed=other).check().status == "failed"


def test_recovery_fails_when_x_and_y_are_exchanged():
    claim = _claim(n10_special_case, "n10.recovery")
    exchanged = [sp.Eq(x, claim.printed[1].rhs), sp.Eq(y, claim.printed[0].rhs)]
    assert dataclasses.replace(claim, printed=exchanged).check().status == "failed"


def test_recovery_unique_fails_for_a_closed_form_of_the_other_sign(monkeypatch):
    # Were xy negative (a closed form with −C), both roots would be positive or both negative.
    true = n10_special_case.special_case()
    monkeypatch.setattr(n10_special_case, "special_case", lambda: {**true, "K": -true["K"]})
    n10_special_case.recovery.cache_clear()
    try:
        verdict = _claim(n10_special_case, "n10.recovery_unique").check()
        assert verdict.status == "failed", verdict
    finally:
        monkeypatch.undo()
        n10_special_case.recovery.cache_clear()

