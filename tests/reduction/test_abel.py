"""The general Abel-equation code, on equations other than Appell's."""

import pytest
import sympy as sp

from derivation import checks
from reduction.abel import Abel
from reduction.invariants import random_invariance_check

x = sp.Symbol("x", positive=True)


def test_normal_form_invariants_are_I_and_its_derivative():
    # y' = y³ + I(x): s₃ = I, s₅ = I', J = I'³/I⁵.
    I = x**2 + 1
    eq = Abel(sp.Integer(1), sp.Integer(0), sp.Integer(0), I, x=x)
    assert checks.exact_zero(eq.s3() - I)
    assert checks.exact_zero(eq.s5() - sp.diff(I, x))
    assert checks.exact_zero(eq.J() - sp.diff(I, x) ** 3 / I**5)


def test_the_scale_invariant_class_has_constant_J():
    # y' = y³ + x^(-3/2) is invariant under x → κ²x, y → y/κ: J = (−3/2)³ = −27/8.
    eq = Abel(sp.Integer(1), sp.Integer(0), sp.Integer(0), x ** sp.Rational(-3, 2), x=x)
    assert sp.simplify(eq.J()) == sp.Rational(-27, 8)


def test_a_separable_equation_with_symmetric_roots_has_s3_zero():
    # y' = g(x) y(y − 1)(2y − 1): roots equally spaced, no constant term once depressed.
    g = sp.exp(x) + x
    eq = Abel(2 * g, -3 * g, g, sp.Integer(0), x=x)
    assert checks.exact_zero(eq.s3())


def test_the_normal_form_transformation_reaches_u3_plus_I():
    # f₁ − f₂²/(3f₃) = 1 here, so P = eˣ.
    eq = Abel(sp.Integer(1), 3 * x, 3 * x**2 + 1, x**3, x=x)
    assert checks.exact_zero(eq.normal_form_log_scale_rate() - 1)
    P = sp.exp(x)
    normal = eq.normal_form(P)
    assert [sp.simplify(f) for f in normal.coefficients[:3]] == [1, 0, 0]
    assert checks.exact_zero(normal.f0 - eq.invariant_I(P))


@pytest.mark.slow
def test_weights_under_random_transformations():
    for seed in (1, 2):  # inv.general_numeric takes seed 1911; inv.general, any equation
        inv = random_invariance_check(seed)
        before, after, w = inv["before"], inv["after"], inv["weight"]
        assert checks.exact_zero(after.s3() - w**3 * before.s3())
        assert checks.exact_zero(after.s5() - w**5 * before.s5())


def test_a_coefficient_alone_is_not_invariant():
    # The check above can fail: f₀ is not multiplied by a power of P/T'.
    inv = random_invariance_check(1)
    before, after, w = inv["before"], inv["after"], inv["weight"]
    assert not checks.exact_zero(after.f0 - w**3 * before.f0)
