"""The two routes to the equations of motion, and physics the paper leaves implicit."""

import sympy as sp

from derivation import checks, kane, n7_pure_rolling, newton_euler, polar
from derivation.symbols import R, alpha, d, delta, g, k, theta


def test_newton_euler_and_kane_give_the_same_accelerations():
    first, second = newton_euler.accelerations(), kane.equations_4_5()
    assert set(first) == set(second)
    for x in first:
        assert checks.exact_zero(first[x] - second[x]), x


def test_rates_depend_on_the_angles_only_through_theta():
    from derivation.symbols import beta

    for expr in polar.rates().values():
        assert not expr.has(alpha) and not expr.has(beta) and theta in expr.free_symbols


def test_straight_shot_keeps_theta_at_right_angles():
    # θ = ±π/2 is invariant: θ' vanishes there (the straight shots of the numerics).
    for value in (sp.pi / 2, -sp.pi / 2):
        assert polar.theta_rate().subs(theta, value) == 0


def test_no_rolling_friction_means_no_turning_of_the_slip():
    assert polar.rates()[d(alpha)].subs(delta, 0) == 0


def test_solid_ball_rolling_deceleration_is_five_sevenths():
    # Design notes: δRg/(R² + k²) = (5/7)(δ/R) g for k² = 2R²/5.
    eta_acc = -R * n7_pure_rolling.motion()["Omega'"]
    solid = eta_acc.subs(k, sp.sqrt(sp.Rational(2, 5)) * R)
    assert sp.simplify(solid - sp.Rational(5, 7) * delta / R * g) == 0
