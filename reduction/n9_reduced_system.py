"""n°9: (7)–(8) in the variables x = fV, y = δΩ, θ = β − α — eqs. (12), (13), (14).

The constants a, b, c are not typed: they are read off the derived
equations (the constant term and the coefficient of sin θ in x' and y'),
and a claim compares them with the paper's definitions.  From there on the
reduction works with (12) in a, b, c.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import checks, polar
from derivation.claim import Claim
from derivation.symbols import Omega, R, V, accent, alpha, beta, d, delta, f, g, k, label, t, theta
from reduction.variables import a, b, c, claim, x, x_0, y, y_0

PRINTED_DEFINITIONS = {a: f**2 * (1 + R**2 / k**2) * g, b: f * R * delta / k**2 * g, c: delta**2 / k**2 * g}
IN_X_Y = {V: x / f, Omega: y / delta}
s = sp.sin(theta)


@lru_cache(maxsize=None)
def physical_rates() -> dict[str, sp.Expr]:
    """x', xα', y', yβ', θ' from (7)–(8), still in f, R, k, δ, g."""
    sl, ro = polar.sliding(), polar.rolling()
    rates = polar.rates()
    return {
        "x'": sp.expand(f * rates[d(V)]),
        "x alpha'": sp.expand(f * sl["V alpha'"]),
        "y'": sp.expand(delta * rates[d(Omega)]),
        "y beta'": sp.expand(delta * ro["Omega beta'"]),
        "alpha'": sp.expand(rates[d(alpha)].subs(IN_X_Y)),
        "beta'": sp.expand(rates[d(beta)].subs(IN_X_Y)),
        "theta'": sp.simplify(polar.theta_rate().subs(IN_X_Y)),
    }


@lru_cache(maxsize=None)
def constants() -> dict[sp.Symbol, sp.Expr]:
    """a, b, c read off x' = −a + b sin θ and y' = b sin θ − c."""
    rate = physical_rates()
    values = {
        a: -rate["x'"].subs(s, 0),
        b: rate["x'"].coeff(s),
        c: -rate["y'"].subs(s, 0),
    }
    # The same b multiplies sin θ in y' and cos θ in x α', y β': a check, not an assumption.
    for other in (rate["y'"].coeff(s), -rate["x alpha'"].coeff(sp.cos(theta)), rate["y beta'"].coeff(sp.cos(theta))):
        if not checks.exact_zero(other - values[b]):
            raise ArithmeticError("(7)-(8) do not have the structure of (12)")
    return values


def in_abc(expr: sp.Expr) -> sp.Expr:
    """A rate of (7)–(8) in x, y, θ rewritten with the constants a, b, c, not typed but read off.

    Each term is (coefficient in f, R, k, δ, g) × (a monomial in sin θ, cos θ, x, y); every
    coefficient must be exactly one of ±a, ±b, ±c as `constants` derived them — else the
    equations do not have the structure of (12), and this raises.
    """
    values = constants()
    by_monomial: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        coefficient, monomial = term.as_independent(theta, x, y, as_Add=False)
        by_monomial[monomial] = by_monomial.get(monomial, 0) + coefficient
    out = sp.Integer(0)
    for monomial, coefficient in by_monomial.items():
        for sym, value in values.items():
            sign = next((sg for sg in (1, -1) if checks.exact_zero(coefficient - sg * value)), None)
            if sign is not None:
                out += sign * sym * monomial
                break
        else:
            raise ArithmeticError(f"{coefficient} (of {monomial}) is none of ±a, ±b, ±c: not the structure of (12)")
    return out


@lru_cache(maxsize=None)
def reduced_rates() -> dict[str, sp.Expr]:
    """(12) and θ' in x, y, θ and the symbols a, b, c, read off the derived (7)–(8) by `in_abc`."""
    rate = physical_rates()
    abc = {
        "x'": in_abc(rate["x'"]),
        "x alpha'": in_abc(rate["x alpha'"]),
        "y'": in_abc(rate["y'"]),
        "y beta'": in_abc(rate["y beta'"]),
        "alpha'": in_abc(rate["alpha'"]),
        "beta'": in_abc(rate["beta'"]),
    }
    abc["theta'"] = sp.expand(abc["beta'"] - abc["alpha'"])
    abc["dx/dtheta"] = sp.factor(abc["x'"] / abc["theta'"])
    abc["dy/dtheta"] = sp.factor(abc["y'"] / abc["theta'"])
    return abc


def claims() -> list[Claim]:
    printed = PRINTED_DEFINITIONS
    gaps = [label("a − b", "a - b"), label("b − c", "b - c"), label("c", "c")]
    dx_dtheta = label("dx/dθ", r"\frac{dx}{d\theta}")
    dy_dtheta = label("dy/dθ", r"\frac{dy}{d\theta}")
    ratio = label("b²/(ac)", r"\frac{b^2}{ac}")
    tan, sec = sp.tan(theta), 1 / sp.cos(theta)
    d_alpha, d_t = label("dα", r"d\alpha"), label("dt", "dt")  # the paper's differentials: dα = α' dt
    return [
        claim(
            "n9.constants",
            "n°9",
            "a, b, c, read off the derived x' and y', are the paper's.",
            r"a = f^2 \left( 1 + \frac{R^2}{k^2} \right) g, \quad b = f \frac{R\delta}{k^2} g, \quad c = \frac{\delta^2}{k^2} g;",
            [sp.Eq(sym, printed[sym]) for sym in (a, b, c)],
            lambda: [sp.Eq(sym, constants()[sym]) for sym in (a, b, c)],
            display=lambda: [
                sp.Eq(a, f**2 * (1 + R**2 / k**2) * g),
                sp.Eq(b, f * (R * delta / k**2) * g),
                sp.Eq(c, (delta**2 / k**2) * g),
            ],
        ),
        claim(
            "n9.order",
            "n°9",
            "a > b > c > 0 because δ < fR.",
            r"a > b > c,",
            [sp.Gt(gap, 0) for gap in gaps],
            lambda: [
                sp.Eq(gaps[0], constants()[a] - constants()[b]),
                sp.Eq(gaps[1], constants()[b] - constants()[c]),
                sp.Eq(gaps[2], constants()[c]),
            ],
        ),
        claim(
            "n9.ratio",
            "n°9 (beyond the paper)",
            "b² = ac R²/(R² + k²): the three constants are tied, b² < ac, and 3/5 ≤ b²/(ac) for a ball of "
            "concentric layers (k² ≤ 2R²/3).",
            None,
            sp.Eq(ratio, R**2 / (R**2 + k**2)),
            lambda: sp.Eq(ratio, sp.simplify(constants()[b] ** 2 / (constants()[a] * constants()[c]))),
        ),
        claim(
            "eq12",
            "n°9, eq. (12)",
            "(7)–(8) in x = fV, y = δΩ, θ = β − α.",
            r"\frac{dx}{dt} &= -a + b \sin \theta, \\ x \frac{d\alpha}{dt} &= -b \cos \theta, \\ \frac{dy}{dt} &= b \sin \theta - c, \\ y \frac{d\beta}{dt} &= b \cos \theta,",
            [
                sp.Eq(d(x), -a + b * s),
                sp.Eq(x * d(alpha), -b * sp.cos(theta)),
                sp.Eq(d(y), b * s - c),
                sp.Eq(y * d(beta), b * sp.cos(theta)),
            ],
            lambda: [
                sp.Eq(d(x), reduced_rates()["x'"]),
                sp.Eq(x * d(alpha), x * reduced_rates()["alpha'"]),
                sp.Eq(d(y), reduced_rates()["y'"]),
                sp.Eq(y * d(beta), y * reduced_rates()["beta'"]),
            ],
        ),
        claim(
            "eq13",
            "n°9, eq. (13)",
            "Every ratio of (13) equals dt; in particular θ' = b(1/x + 1/y) cos θ.",
            r"\frac{dx}{-a + b \sin \theta} = \frac{dy}{b \sin \theta - c} = \frac{d\beta}{\frac{b}{y} \cos \theta} = \frac{-d\alpha}{\frac{b}{x} \cos \theta} = \frac{d\theta}{b \left( \frac{1}{x} + \frac{1}{y} \right) \cos \theta} = dt;",
            [
                sp.Eq(d(x), -a + b * s),
                sp.Eq(d(y), b * s - c),
                sp.Eq(d(beta), b / y * sp.cos(theta)),
                sp.Eq(-d(alpha), b / x * sp.cos(theta)),
                sp.Eq(label("dθ/dt", r"\frac{d\theta}{dt}"), b * (1 / x + 1 / y) * sp.cos(theta)),
            ],
            lambda: [
                sp.Eq(d(x), reduced_rates()["x'"]),
                sp.Eq(d(y), reduced_rates()["y'"]),
                sp.Eq(d(beta), reduced_rates()["beta'"]),
                sp.Eq(-d(alpha), -reduced_rates()["alpha'"]),
                sp.Eq(label("dθ/dt", r"\frac{d\theta}{dt}"), reduced_rates()["theta'"]),
            ],
        ),
        claim(
            "eq14",
            "n°9, eq. (14)",
            "x and y as functions of θ: the first two ratios of (13) against the fifth.",
            r"\begin{cases} \frac{dx}{d\theta} = \frac{xy}{x+y} \left( \operatorname{tang} \theta - \frac{a}{b \cos \theta} \right), \\ \frac{dy}{d\theta} = \frac{xy}{x+y} \left( \operatorname{tang} \theta - \frac{c}{b \cos \theta} \right), \end{cases}",
            [
                sp.Eq(dx_dtheta, x * y / (x + y) * (tan - a / b * sec)),
                sp.Eq(dy_dtheta, x * y / (x + y) * (tan - c / b * sec)),
            ],
            lambda: [sp.Eq(dx_dtheta, reduced_rates()["dx/dtheta"]), sp.Eq(dy_dtheta, reduced_rates()["dy/dtheta"])],
            display=lambda: [
                sp.Eq(dx_dtheta, (x * y / (x + y)) * (tan - a / (b * sp.cos(theta)))),
                sp.Eq(dy_dtheta, (x * y / (x + y)) * (tan - c / (b * sp.cos(theta)))),
            ],
        ),
        claim(
            "n9.time",
            "n°9",
            "y − x is linear in t, which gives θ as a function of t.",
            r"y - x = (a - c)t + y_0 - x_0;",
            [sp.Eq(d(y) - d(x), a - c), sp.Eq(y - x, (a - c) * t + y_0 - x_0)],
            lambda: [
                sp.Eq(d(y) - d(x), reduced_rates()["y'"] - reduced_rates()["x'"]),
                sp.Eq(y - x, y_0 - x_0 + sp.integrate(reduced_rates()["y'"] - reduced_rates()["x'"], (t, 0, t))),
            ],
            display=lambda: [sp.Eq(accent(y) - accent(x), a - c), sp.Eq(y - x, (a - c) * t + y_0 - x_0)],
        ),
        claim(
            "n9.alpha",
            "n°9",
            "α by a quadrature.",
            r"d\alpha = - \frac{b \cos \theta}{x} dt,",
            sp.Eq(d_alpha, -b * sp.cos(theta) / x * d_t),
            lambda: sp.Eq(d_alpha, reduced_rates()["alpha'"] * d_t),
            display=lambda: sp.Eq(d_alpha, -(b * sp.cos(theta) / x) * d_t),
        ),
    ]

