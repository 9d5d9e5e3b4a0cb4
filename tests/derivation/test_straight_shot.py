"""derivation.straight_shot: which shots are θ = +π/2 and which −π/2, read off the derivation's own eq. (2).

A referee's audit: the claims called θ = π/2 "follow" and θ = −π/2 "draw", and the appendix's own follow shot
(3 m/s, top spin 150 rad/s, more than rolling) is θ = −π/2.  The statements now name the classes by the spin
against or along the slip; these tests hold them to the kinematics.
"""

import math

import pytest
import sympy as sp

from derivation import newton_euler, straight_shot
from derivation.symbols import Omega, R, V, d, eta, p, q, u, v, xi

BALL = 0.028575  # m, a pool ball's radius


def _theta(centre_speed: float, top_spin: float) -> float:
    """θ = β − α of a ball moving along +ξ at ``centre_speed`` with spin q = ``top_spin`` (p = 0), from the
    derivation's centre velocity (eq. (2) solved for ξ', η'), inverted for the slip (u, v)."""
    centre = newton_euler.centre_velocity()
    at = {p: 0, q: top_spin, R: BALL}
    slip = sp.solve([sp.Eq(centre[d(xi)].subs(at), centre_speed), sp.Eq(centre[d(eta)].subs(at), 0)], [u, v], dict=True)[0]
    alpha = math.atan2(float(slip[v]), float(slip[u]))
    beta = math.atan2(top_spin, 0.0)  # Ω = (p, q) = (0, q)
    return math.remainder(beta - alpha, 2 * math.pi)


@pytest.mark.parametrize("top_spin, side", [
    (50.0, +1),    # top spin below rolling (3 / R = 105 rad/s): the slip points forward, θ = +π/2
    (150.0, -1),   # a follow with more top spin than rolling: the slip points backward, θ = −π/2
    (-150.0, -1),  # a draw: back spin, θ = −π/2
])
def test_each_straight_shot_is_on_the_side_its_statement_names(top_spin, side):
    assert _theta(3.0, top_spin) == pytest.approx(side * math.pi / 2, rel=0, abs=1e-12)
    plus, minus = (c for c in straight_shot.claims() if c.id in ("straight.theta_plus", "straight.theta_minus"))
    if side < 0 and top_spin > 0:
        assert "follow with more top spin than rolling" in minus.statement
    if side > 0:
        assert "less top spin than rolling" in plus.statement


def test_the_centre_speed_along_the_slip_is_v_minus_r_omega_for_theta_minus():
    """The overspun follow: Ġ·e_α = V − RΩ is negative (the centre moves against the slip), |it| the shot's speed."""
    speed, spin = 3.0, 150.0
    slip_speed = abs(speed - spin * BALL)
    along = straight_shot.straight(straight_shot.MINUS)["centre speed"]
    value = float(along.subs({V: slip_speed, Omega: spin, R: BALL}))
    assert value == pytest.approx(-speed, rel=1e-12, abs=0)
