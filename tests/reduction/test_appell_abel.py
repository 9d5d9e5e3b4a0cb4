"""Appell's Abel equation: its special cases and its symmetry."""

import sympy as sp

from derivation import checks
from derivation.symbols import theta
from reduction import invariants, n11_abel, normal_form
from reduction.variables import a, b, c, z


def test_the_special_case_a_equals_c_is_separable():
    abel = n11_abel.abel_in_theta()
    rhs = sp.factor(abel.rhs(z).subs(c, a))
    # z(z − 1)(2z − 1) times a function of θ alone.
    assert checks.exact_zero(sp.cancel(rhs / (z * (z - 1) * (2 * z - 1))).diff(z))
    assert checks.exact_zero(abel.s3().subs(c, a))


def test_s3_vanishes_only_on_a_equals_c():
    assert invariants.classes()["s3 zero"] == [{"a": sp.Symbol("c")}]
    assert invariants.classes()["J constant"] == []


def test_exponents_of_P_are_positive_where_tau_needs_it():
    # α = 2e₁ > 0 makes τ finite at θ = −π/2.
    e1 = normal_form.exponents()["e1"]
    assert (e1.subs({a: 3, b: 1, c: sp.Rational(1, 3)}) > 0) is sp.true


def test_J_tends_to_the_classical_value_as_delta_vanishes():
    J = invariants.J_CLOSED.subs({invariants.S: sp.Rational(1, 3), a: 1, c: sp.Rational(1, 10**12)})
    assert abs(float(J.subs(b, sp.Rational(1, 10**6))) - 729 / 4) < 1e-6


def test_theta_form_keeps_the_particular_solutions_z0_and_z1():
    abel = n11_abel.abel_in_theta()
    assert abel.rhs(0) == 0 and sp.simplify(abel.rhs(1)) == 0
    assert abel.x == theta
