"""The claims added for n°10's recovery of x and y and n°11's φ(θ): each turns red when wrong
(that they are confirmed is `test_claims.test_claim`)."""

import dataclasses

import sympy as sp

from derivation import n5_hypothesis
from reduction import n10_special_case, n11_abel
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


def test_phi_monotone_fails_when_rolling_friction_outweighs_sliding():
    # Rδ > f(R² + k²) makes a < b: then sin θ − a/b changes sign on the motion's range.
    claim = _claim(n11_abel, "n11.phi_monotone")
    beyond = dataclasses.replace(claim, hypothesis=n5_hypothesis.BEYOND_ROLLING, domain={**claim.domain, **n5_hypothesis.PAST_ROLLING})
    assert beyond.check().status == "failed"


def test_phi_monotone_fails_for_another_change_of_variable(monkeypatch):
    a, b = sp.symbols("a b", positive=True)
    theta = sp.Symbol("theta", real=True)
    monkeypatch.setattr(n11_abel, "DPHI_DTHETA", sp.tan(theta) + a / (b * sp.cos(theta)))
    n11_abel.phi_of_theta.cache_clear()
    try:
        assert _claim(n11_abel, "n11.phi_monotone").check().status == "failed"
    finally:
        monkeypatch.undo()
        n11_abel.phi_of_theta.cache_clear()


def test_J_invariance_numeric_fails_when_J_changes(monkeypatch):
    """inv.general_numeric compares J before and after a transformation: fed an equation that is no transform of
    the first (its f0 plus 1), it must fail (comparing J with itself was confirmed at 40 digits: a mutation audit)."""
    import dataclasses

    from reduction import invariants

    real = invariants.random_invariance_check()
    wrong = {**real, "after": dataclasses.replace(real["before"], f0=real["before"].f0 + 1)}
    monkeypatch.setattr(invariants, "random_invariance_check", lambda: wrong)
    digits, _ = invariants.J_invariance_numeric()
    assert digits < 3
    monkeypatch.setattr(invariants, "random_invariance_check", lambda: real)
    assert invariants.J_invariance_numeric()[0] >= 30


def test_tau_mpmath_fails_when_its_quadrature_diverges(monkeypatch):
    """A rate that cannot be integrated from −π/2 made the error NaN, which max() dropped: the claim passed at its
    full 40 digits with P's exponents swapped (a mutation audit).  A NaN is now the worst error."""
    import sympy as sp

    from derivation.symbols import theta
    from reduction import normal_form

    real = normal_form.transformation()
    diverging = {**real, "dtau/dtheta": real["dtau/dtheta"] / (1 + sp.sin(theta)) ** 2}
    monkeypatch.setattr(normal_form, "transformation", lambda: diverging)
    assert not normal_form.tau_mpmath_check()[0] >= 30


def test_tau_integrand_fails_for_a_wrong_constant_of_the_f1_form(monkeypatch):
    """The logarithmic derivative drops any constant factor: the claim's log of the ratio at s = 0 must catch a
    constant of τ's F₁ form off by 2, by its sign, or by a power of a + c + 2b."""
    from reduction import normal_form
    from reduction.variables import a, b, c

    real = normal_form.tau_rates_in_s()
    claim = _claim(normal_form, "normal.tau_integrand")
    assert claim.check().status == "confirmed"
    for wrong in (2, -1, (a + c + 2 * b) ** sp.Rational(1, 100)):
        monkeypatch.setattr(normal_form, "tau_rates_in_s", lambda wrong=wrong: {**real, "F1": wrong * real["F1"]})
        assert _claim(normal_form, "normal.tau_integrand").check().status == "failed", wrong


def test_mirror_fails_when_its_stated_sides_are_defined_wrong():
    """inv.mirror states −𝓕(z) and J(a, b, c) by name, their definitions put in: a sign lost fails it."""
    from reduction import invariants
    from reduction.n11_abel import abel_in_theta
    from reduction.variables import z

    claim = _claim(invariants, "inv.mirror")
    named = claim.definitions()
    F, J = list(named)
    for wrong in ({F: -abel_in_theta().rhs(z), J: named[J]}, {F: named[F], J: -named[J]}):
        assert dataclasses.replace(claim, definitions=lambda wrong=wrong: wrong).check().status == "failed"


def test_general_invariance_fails_for_another_weight_or_a_coefficient_that_is_no_invariant(monkeypatch):
    """inv.general holds for any equation and any change (the jet of each function its own symbols): a weight of
    another power fails it, and so does f₀, which a change does not multiply by a power of P/τ′."""
    from reduction import invariants

    claim = _claim(invariants, "inv.general")
    w = invariants.invariance_ratios()["weight"]
    rows = list(claim.printed)
    assert rows[0].rhs == w**3  # the rows: the two ratios, then s₃ and s₅ defined
    wrong = [sp.Eq(rows[0].lhs, w**2)] + rows[1:]
    assert dataclasses.replace(claim, printed=wrong, display=None).check().status == "failed"
    real = invariants.invariance_ratios()
    f3, f2, f1, f0, P, Q, tau_rate = invariants.GENERAL.values()
    before = invariants.Abel(f3, f2, f1, f0, x=invariants.RANDOM_X)
    after = before.transformed(P, Q, tau_rate)
    f0_ratio = invariants.jet(after.f0) / invariants.jet(before.f0)
    monkeypatch.setattr(invariants, "invariance_ratios", lambda: {**real, "s3": f0_ratio})
    assert _claim(invariants, "inv.general").check().status == "failed"


def test_the_definitions_of_s3_and_s5_shown_are_the_code_s(monkeypatch):
    """inv.general shows s₃ and s₅ typed in the classical order (a referee: the appendix used them undefined); a
    sign or a factor typed wrong fails the claim."""
    from reduction import invariants

    real = invariants.invariants_shown()
    f1, f2, f3 = (invariants.JET[name] for name in ("f1", "f2", "f3"))
    for name, wrong in (("s3", real["s3"] + 2 * f1 * f2 * f3 / 3), ("s5", real["s5"] + f2**2 * invariants.JET["s3"])):
        monkeypatch.setattr(invariants, "invariants_shown", lambda name=name, wrong=wrong: {**real, name: wrong})
        assert _claim(invariants, "inv.general").check().status == "failed", name
