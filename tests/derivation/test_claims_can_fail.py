"""The claims added for what the paper states without a claim so far: each turns red when its
derivation or its printed form is wrong (that they are confirmed is `test_claims.test_claim`)."""

import dataclasses
import sys

import pytest
import sympy as sp

import derivation
import numerics
import reduction
from derivation import n2_motion, n3_classical, n4_ideal, n8_general, newton_euler
from derivation.symbols import Omega, Omega_0, R, V, alpha, beta, delta, delta_1, d, f, f_1, g, k, m, p, q, u, v


def _claim(module, claim_id):
    return next(c for c in module.claims() if c.id == claim_id)


def _clear_caches():
    """Every lru_cache of the package's own modules: all of them are downstream of the loads, or may be."""
    for package in (derivation, reduction, numerics):
        package.sections()
    for name, module in list(sys.modules.items()):
        if name.partition(".")[0] in ("derivation", "reduction", "numerics"):
            for value in vars(module).values():
                if hasattr(value, "cache_clear") and getattr(value, "__module__", None) == name:
                    value.cache_clear()


@pytest.fixture
def wrong_load(monkeypatch):
    """Replace a load of `newton_euler` (its name) by ``mutation(true load)`` for one test; every derived result
    is redone."""

    def install(name, mutation):
        true_load = getattr(newton_euler, name)
        monkeypatch.setattr(newton_euler, name, lambda: mutation(true_load()))
        _clear_caches()

    yield install
    monkeypatch.undo()
    _clear_caches()


@pytest.fixture
def wrong_couple(wrong_load):
    """Replace the rolling couple by ``mutation(true couple)``."""
    return lambda mutation: wrong_load("rolling_couple", mutation)


def _swapped(load):
    """A load with its horizontal components exchanged: it no longer opposes its vector ((cos α, sin α), (cos β, sin β))."""
    return sp.Matrix([load[1], load[0], 0])


@pytest.fixture
def swapped_couple(wrong_couple):
    """The rolling couple's components exchanged: it no longer opposes Ω (cos β, sin β)."""
    wrong_couple(_swapped)


# (1) and (3) alike: the slip (u, v) and the rotation (p, q) are their size along the unit vector that their load,
# the sliding friction and the rolling couple, opposes.  claim -> (the load, the two components, the size, the angle).
DIRECTIONS = {"eq1": ("sliding_force", u, v, V, alpha), "eq3": ("rolling_couple", p, q, Omega, beta)}


@pytest.mark.parametrize("claim_id", DIRECTIONS)
def test_a_direction_equation_is_confirmed(claim_id):
    assert _claim(n2_motion, claim_id).check().status == "confirmed"


@pytest.mark.parametrize("claim_id", DIRECTIONS)
def test_a_direction_equation_fails_when_its_load_opposes_another_vector(wrong_load, claim_id):
    wrong_load(DIRECTIONS[claim_id][0], _swapped)
    verdict = _claim(n2_motion, claim_id).check()
    assert verdict.status == "failed" and verdict.symbolic == "not reduced to 0"


@pytest.mark.parametrize("claim_id", DIRECTIONS)
def test_a_direction_equation_fails_when_its_components_are_exchanged(claim_id):
    claim = _claim(n2_motion, claim_id)
    _, first, second, size, angle = DIRECTIONS[claim_id]
    exchanged = [sp.Eq(first, size * sp.sin(angle)), sp.Eq(second, size * sp.cos(angle)), *claim.printed[2:]]
    assert dataclasses.replace(claim, printed=exchanged).check().status == "failed"


def test_eq3_rates_fail_when_differentiated_wrongly():
    claim = _claim(n2_motion, "n2.eq3_rates")
    assert claim.check().status == "confirmed"
    # β' forgotten: p' = Ω' cos β, q' = Ω' sin β.
    wrong = [sp.Eq(d(p), d(Omega) * sp.cos(beta)), sp.Eq(d(q), d(Omega) * sp.sin(beta))]
    assert dataclasses.replace(claim, printed=wrong).check().status == "failed"


def test_n3_stays_zero_fails_when_a_couple_acts_without_rolling_friction(wrong_couple):
    # A couple that does not vanish with δ: after the slide, rolling would need a friction f₁ ≠ 0.
    wrong_couple(lambda H: H + R / 10 * m * g * sp.Matrix([-sp.cos(beta), -sp.sin(beta), 0]))
    assert _claim(n3_classical, "n3.stays_zero").check().status == "failed"


def test_n3_stays_zero_fails_with_another_friction():
    claim = _claim(n3_classical, "n3.stays_zero")
    wrong = [sp.Eq(f_1, f), *claim.printed[1:]]
    assert dataclasses.replace(claim, printed=wrong).check().status == "failed"


def test_n4_stop_time_fails_with_a_doubled_couple(wrong_couple):
    wrong_couple(lambda H: 2 * H)
    assert _claim(n4_ideal, "n4.stop_time").check().status == "failed"


def test_n4_stop_time_fails_with_n7s_time():
    claim = _claim(n4_ideal, "n4.stop_time")
    (printed,) = claim.printed
    wrong = sp.Eq(printed.lhs, (R**2 + k**2) * Omega_0 / (delta * g))
    assert dataclasses.replace(claim, printed=wrong).check().status == "failed"


def test_spin_leaves_zero_fails_without_9():
    from derivation import n5_hypothesis

    claim = _claim(n8_general, "n8.spin_leaves_zero")
    verdict = dataclasses.replace(claim, hypothesis=n5_hypothesis.BEYOND_9, domain=n5_hypothesis.PAST_9).check()
    assert verdict.status == "failed", verdict


def test_spin_leaves_zero_fails_at_another_angle():
    """A mutation audit: Ω' evaluated at θ = −π/3 instead of −π/2 kept both signs, and the claim stayed confirmed;
    its display pins the values the statement gives."""
    from derivation import polar
    from derivation.symbols import theta

    claim = _claim(n8_general, "n8.spin_leaves_zero")
    rate = polar.rates()[d(Omega)]
    wrong = [sp.Eq(row.lhs, rate.subs(theta, side)) for row, side in zip(claim.derived, (sp.pi / 2, -sp.pi / 3))]
    assert claim.check().status == "confirmed"
    assert dataclasses.replace(claim, derived=wrong).check().status == "failed"


@pytest.mark.parametrize("claim_id", ["n8.spin_rate", "n8.spin_rate_bounds", "n8.spin_zero_straight_only"])
def test_spin_near_zero_claims_fail_with_a_doubled_couple(wrong_couple, claim_id):
    wrong_couple(lambda H: 2 * H)
    assert _claim(n8_general, claim_id).check().status == "failed"


def test_spin_rate_fails_when_the_couple_opposes_another_vector(swapped_couple):
    assert _claim(n8_general, "n8.spin_rate").check().status == "failed"


def test_final_rest_fails_with_a_doubled_pivot_couple(monkeypatch):
    true_equations = newton_euler.equations_of_motion

    def doubled_pivot():
        eqs = dict(true_equations())
        spin = eqs["rotation"][2]
        eqs["rotation"] = eqs["rotation"][:2] + [sp.Eq(spin.lhs, 2 * spin.rhs)]
        return eqs

    monkeypatch.setattr(newton_euler, "equations_of_motion", doubled_pivot)
    _clear_caches()
    try:
        assert _claim(n8_general, "n8.final_rest").check().status == "failed"
    finally:
        monkeypatch.undo()
        _clear_caches()


def test_final_rest_fails_with_a_couple_of_repose():
    claim = _claim(n8_general, "n8.final_rest")
    wrong = [claim.printed[0], sp.Eq(delta_1, delta), *claim.printed[2:]]
    assert dataclasses.replace(claim, printed=wrong).check().status == "failed"
