"""Beyond n°11: Appell's Abel equation brought to the normal form du/dτ = u³ + I(τ).

"On la ramènera aisément à la forme normale" — done here, explicitly.  With
s = sin θ and the equation b cos θ dz/dθ = z(z − 1)((2bs − a − c)z − (bs − c)):

* z = P u + Q with Q = −A₂/(3A₃) and P = (1 + s)^e₁ (1 − s)^e₂ (a + c − 2bs)^e₃,
  the exponents from a partial-fraction integration;
* dτ = A₃P² dθ, which integrates to Appell's own hypergeometric function F₁
  (Appell 1880): τ = K w^γ F₁(γ; β₁, β₂; γ + 1; w, μw)/γ with
  w = (1 + sin θ)/2, μ = 4b/(a + c + 2b), γ = 2e₁, β₁ = 1 − 2e₂, β₂ = −1 − 2e₃,
  τ = 0 at θ = −π/2 (γ, β₁, β₂ for F₁'s α, β, β': α and β are the paper's angles);
* I = s₃/(A₃P)³.
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import sympy as sp

from derivation.checks import worst_of
from derivation.claim import NumericCheck, evaluated, put_in
from derivation.symbols import label, theta
from reduction.n11_abel import abel_in_theta
from reduction.variables import a, b, c, claim

S = sp.Symbol("s", real=True)  # sin θ
w = sp.Symbol("w", positive=True)  # (1 + sin θ)/2
s = sp.sin(theta)
P_ANY = sp.Function("P", positive=True)(theta)  # the scale of the normal form, kept unknown


def _in_s(expr: sp.Expr) -> sp.Expr:
    """A function of θ, odd in cos θ, times dθ, as a function of s = sin θ times ds."""
    per_ds = sp.cancel(expr / sp.cos(theta)).subs(sp.cos(theta) ** 2, 1 - s**2)
    return sp.factor(sp.cancel(per_ds.subs(s, S)))


@lru_cache(maxsize=None)
def exponents() -> dict[str, sp.Expr]:
    """e₁, e₂, e₃ of P, from ∫(A₁ − A₂²/(3A₃)) dθ by partial fractions in s.

    Each partial fraction is k/L(s) with L linear, integrating to (k/L') log L;
    the exponent of a factor is read off with the sign that makes it positive
    on |s| < 1 (1 − s rather than s − 1, a + c − 2bs rather than 2bs − a − c).
    """
    abel = abel_in_theta()
    integrand = _in_s(abel.normal_form_log_scale_rate())
    factors = {"e1": S + 1, "e2": 1 - S, "e3": a + c - 2 * b * S}
    found = {}
    for term in sp.Add.make_args(sp.apart(integrand, S)):
        (linear,) = [f for f, _ in sp.factor_list(sp.denom(term))[1] if f.has(S)]
        name = next(n for n, L in factors.items() if sp.simplify(linear / L).is_number)
        L = factors[name]
        found[name] = sp.factor(sp.cancel(term * L) / sp.diff(L, S))
    if sp.cancel(sum(found[n] * sp.diff(L, S) / L for n, L in factors.items()) - integrand) != 0:
        raise ArithmeticError("partial fractions do not add up")
    return found


@lru_cache(maxsize=None)
def transformation() -> dict[str, sp.Expr]:
    """P, Q, dτ/dθ and I for Appell's equation."""
    abel = abel_in_theta()
    e = exponents()
    # |s − 1| = 1 − s and |2bs − a − c| = a + c − 2bs for |s| < 1, a + c > 2b.
    P = (1 + s) ** e["e1"] * (1 - s) ** e["e2"] * (a + c - 2 * b * s) ** e["e3"]
    return {
        "P": P,
        "Q": sp.factor(abel.normal_form_shift()),
        "dtau/dtheta": abel.f3 * P**2,
        "I": abel.invariant_I(P),
        "normal": abel.normal_form(P),
    }


@lru_cache(maxsize=None)
def tau_as_appell_f1() -> dict[str, sp.Expr]:
    """τ(θ) through F₁, with the parameters of the Euler integral."""
    e = exponents()
    gamma = 2 * e["e1"]
    beta1, beta2 = 1 - 2 * e["e2"], -1 - 2 * e["e3"]
    mu = 4 * b / (a + c + 2 * b)
    K = -2 / b * 2 ** (2 * e["e1"] + 2 * e["e2"] - 2) * (a + c + 2 * b) ** (2 * e["e3"] + 1)
    tau = K * w**gamma * sp.appellf1(gamma, beta1, beta2, gamma + 1, w, mu * w) / gamma
    return {"gamma": gamma, "beta1": beta1, "beta2": beta2, "mu": mu, "K": K, "tau": tau}


def f1_derivative_identity() -> sp.Expr:
    """d/dw[w^γ F₁(γ; β₁, β₂; γ+1; w, μw)/γ] = w^(γ−1)(1 − w)^(−β₁)(1 − μw)^(−β₂), term by term.

    Differentiating the double series Σ (γ)ₘ₊ₙ(β₁)ₘ(β₂)ₙ/((γ+1)ₘ₊ₙ m! n!) w^(γ+m+n) μⁿ/γ
    multiplies each term by (γ + m + n); the identity holds iff
    (γ)ₘ₊ₙ (γ + m + n)/(γ + 1)ₘ₊ₙ = γ for all m, n: returned as an expression to vanish.
    """
    g, m, n = sp.symbols("gamma m n", positive=True)
    return sp.rf(g, m + n) * (g + m + n) / sp.rf(g + 1, m + n) - g


def tau_mpmath_check(digits: int = 30) -> tuple[float, int]:
    """Digits of agreement between the F₁ closed form and a quadrature of dτ/dθ, and the number of (a, b, c, θ)
    cases compared."""
    tr, f1 = transformation(), tau_as_appell_f1()
    params = [{a: mpmath.mpf(3), b: mpmath.mpf(1), c: mpmath.mpf("0.4")}, {a: mpmath.mpf(7), b: mpmath.mpf(2), c: mpmath.mpf("0.9")}]
    worst, cases = mpmath.mpf(0), 0
    with mpmath.workdps(digits + 10):
        for point in params:
            rate = sp.lambdify(theta, tr["dtau/dtheta"].subs(point), "mpmath")
            closed = sp.lambdify(w, f1["tau"].subs(point), "mpmath")
            for th in (mpmath.mpf("-0.7"), mpmath.mpf("0.3"), mpmath.mpf("1.2")):
                quadrature = mpmath.quad(rate, [-mpmath.pi / 2, 0, th])
                value = closed((1 + mpmath.sin(th)) / 2)
                worst = worst_of(worst, abs(value - quadrature) / abs(quadrature))
                cases += 1
    return (float(min(digits + 10, -mpmath.log10(worst))) if worst else float(digits + 10)), cases


# What must vanish, term (m, n) of F₁'s double series, for the F₁ form of τ to differentiate to its integrand.
SERIES_IDENTITY = label("the (m, n) term of the F₁ series identity, zero for every m and n", r"\Delta_{m,n}")


def _display_A3() -> sp.Expr:
    """The Abel coefficient of z³ in θ, as the appendix writes it."""
    with sp.evaluate(False):
        return -(a + c - 2 * b * s) / (b * sp.cos(theta))


def log_derivative(expr: sp.Expr, var: sp.Symbol) -> sp.Expr:
    """d ln|expr|/d var of a product of powers: rational, so exactly comparable.

    The bases are positive on the domain (|sin θ| < 1, a + c > 2b), which is
    what expanding the logarithm needs; a constant factor, sign included,
    drops out (`expanded_log` at one point pins it).
    """
    return sp.cancel(sp.diff(sp.expand_log(sp.log(expr), force=True), var))


def expanded_log(expr: sp.Expr) -> sp.Expr:
    """ln(expr) of a product of powers, as a sum of exponents times logarithms of factored bases: two such
    products are equal iff the difference of their expanded logs cancels (a sign: ln(−1) = iπ, left over).
    The bases (2, b, a + c, a + c + 2b at s = 0) are positive on the domain, as expanding needs."""
    expr = sp.factor(sp.powsimp(expr, force=True))  # a sum of like powers, (a + c)^x a + (a + c)^x c, made one
    expr = expr.replace(lambda e: e.is_Pow, lambda e: sp.factor(e.base) ** e.exp)
    return sp.expand(sp.expand_log(sp.log(expr), force=True))


# The ratio of dτ/ds to the F₁ form's rate, γC_τ/2 times F₁'s integrand: ln 𝓡(0) = 0 when C_τ, γ and the signs agree.
LOG_RATIO = label("ln of the ratio 𝓡 of dτ/ds to γC_τ/2 times F₁'s integrand, at s = 0", r"\ln\mathcal{R}(0)")


@lru_cache(maxsize=None)
def normal_form_any_P() -> list[sp.Expr]:
    """The coefficients of the normal form for any P with P'/P = A₁ − A₂²/(3A₃)."""
    abel = abel_in_theta()
    on_P = {sp.Derivative(P_ANY, theta): abel.normal_form_log_scale_rate() * P_ANY}
    return [coef.subs(on_P) for coef in abel.normal_form(P_ANY).coefficients]


@lru_cache(maxsize=None)
def tau_rates_in_s() -> dict[str, sp.Expr]:
    """dτ/ds = A₃P²/cos θ, in s = sin θ; and the integrand of the F₁ form (dw/ds = 1/2)."""
    tr, f1 = transformation(), tau_as_appell_f1()
    tau_rate_s = sp.cancel((tr["dtau/dtheta"] / sp.cos(theta)).subs(sp.cos(theta) ** 2, 1 - s**2)).subs(s, S)
    f1_rate_s = (f1["K"] * w ** (f1["gamma"] - 1) * (1 - w) ** (-f1["beta1"]) * (1 - f1["mu"] * w) ** (-f1["beta2"]) / 2).subs(
        w, (1 + S) / 2
    )
    return {"tau": tau_rate_s, "F1": f1_rate_s}


e_1, e_2, e_3 = (label(f"e{sub}, the exponent of {base} in P", f"e_{i}")
                 for i, sub, base in ((1, "₁", "1 + sin θ"), (2, "₂", "1 − sin θ"), (3, "₃", "a + c − 2b sin θ")))
tau_ = label("τ, the variable of the normal form", r"\tau")
# F₁'s parameters and τ's constant, named in the display of τ (`_tau_where` defines them).
C_tau, gamma_, beta_1, beta_2, mu_ = sp.symbols("C_tau gamma beta_1 beta_2 mu", real=True)


def exponents_shown() -> dict[sp.Symbol, sp.Expr]:
    """e₁, e₂, e₃ as the appendix prints them, typed (unevaluated, in the order shown): normal.exponents checks
    them against the partial fractions of `exponents`."""
    with sp.evaluate(False):
        return {
            e_1: (a**2 + 3 * a * b + a * c + 3 * b**2 + 3 * b * c + c**2) / (6 * b * (a + 2 * b + c)),
            e_2: -(a**2 - 3 * a * b + a * c + 3 * b**2 - 3 * b * c + c**2) / (6 * b * (a - 2 * b + c)),
            e_3: (a - c) ** 2 / (6 * (a - 2 * b + c) * (a + 2 * b + c)),
        }


def _tau_where() -> dict[sp.Symbol, sp.Expr]:
    """The parts named in τ's display, built unevaluated in the order to show; a part may name another (e₁ in γ)."""
    with sp.evaluate(False):
        return {
            C_tau: -(2 ** (2 * e_1 + 2 * e_2 - 1)) * (a + c + 2 * b) ** (2 * e_3 + 1) / (b * gamma_),
            gamma_: 2 * e_1, beta_1: 1 - 2 * e_2, beta_2: -1 - 2 * e_3, mu_: 4 * b / (a + c + 2 * b),
            **exponents_shown(),
        }


def _display_tau() -> sp.Expr:
    """τ = C_τ w^γ F₁(γ; β₁, β₂; γ + 1; w, μw), its parameters named (`_tau_where`)."""
    return C_tau * w**gamma_ * sp.appellf1(gamma_, beta_1, beta_2, gamma_ + 1, w, mu_ * w)


def _typed_tau() -> sp.Expr:
    """The printed closed form of τ with every named part put in, evaluated: the form the check compares."""
    return put_in(_display_tau(), _tau_where())


def claims():
    from reduction.invariants import display_s3

    dlogP = label("d ln P/dθ", r"\frac{d\ln P}{d\theta}")
    coefficients = [label(f"coefficient of u^{i} in the normal form", rf"\hat A_{i}") for i in (3, 2, 1, 0)]
    s3, a3 = sp.Symbol("s_3", real=True), sp.Symbol("A_3", real=True)  # named in the display of I
    dlog_tau = label("d/ds ln|dτ/ds|", r"\frac{d}{ds}\ln\left|\frac{d\tau}{ds}\right|")
    half = {theta: (-sp.pi / 2, sp.pi / 2)}
    return [
        claim(
            "normal.P",
            "beyond n°11: normal form",
            "P = (1 + sin θ)^e₁ (1 − sin θ)^e₂ (a + c − 2b sin θ)^e₃ satisfies d ln P/dθ = A₁ − A₂²/(3A₃), "
            "with the Abel coefficients A₃, A₂, A₁ of n11.abel_theta.",
            None,
            lambda: sp.Eq(dlogP, abel_in_theta().normal_form_log_scale_rate()),
            lambda: sp.Eq(dlogP, log_derivative(transformation()["P"], theta)),
            display=lambda: sp.Eq(
                dlogP,
                (a**2 + a * c + c**2 - 3 * b * (a + c) * s + 3 * b**2 * s**2) / (3 * b * sp.cos(theta) * (a + c - 2 * b * s)),
            ),
            domain=half,
        ),
        claim(
            "normal.exponents",
            "beyond n°11: normal form",
            "The exponents of P, from the partial fractions of A₁ − A₂²/(3A₃) in s = sin θ.",
            None,
            lambda: [sp.Eq(e, evaluated(value)) for e, value in exponents_shown().items()],
            lambda: [sp.Eq(e, exponents()[name]) for e, name in ((e_1, "e1"), (e_2, "e2"), (e_3, "e3"))],
            display=lambda: [sp.Eq(e, value) for e, value in exponents_shown().items()],
        ),
        claim(
            "normal.form",
            "beyond n°11: normal form",
            "z = P u + Q with Q = −A₂/(3A₃), and dτ = A₃P² dθ, turn Appell's equation into du/dτ = u³ + I, "
            "I = s₃/(A₃P)³.",
            None,
            lambda: [
                sp.Eq(coefficients[0], 1),
                sp.Eq(coefficients[1], 0),
                sp.Eq(coefficients[2], 0),
                sp.Eq(coefficients[3], abel_in_theta().s3() / (abel_in_theta().f3 * P_ANY) ** 3),
            ],
            lambda: [sp.Eq(lab, coef) for lab, coef in zip(coefficients, normal_form_any_P(), strict=True)],
            display=lambda: [
                sp.Eq(coefficients[0], 1),
                sp.Eq(coefficients[1], 0),
                sp.Eq(coefficients[2], 0),
                sp.Eq(coefficients[3], s3 / (a3 * P_ANY) ** 3),
            ],
            display_where={s3: display_s3(), a3: _display_A3()},
            domain={**half, sp.Symbol("P", positive=True): (0.1, 10)},
        ),
        claim(
            "normal.tau_F1",
            "beyond n°11: normal form",
            "τ in closed form, τ = 0 at θ = −π/2, through Appell's F₁ in w = (1 + sin θ)/2: the form typeset here, "
            "checked against the one the package computes (that τ is this form: normal.tau_series, normal.tau_integrand, normal.tau_mpmath).  "
            "γ, β₁, β₂ stand for the α, β, β′ of F₁(α; β, β′; γ; x, y): α and β are the paper's angles.  "
            "Hypotheses: |θ| < π/2, so that 0 < w < 1, and a + c > 2b (b² < ac, n9.ratio), so that 0 < μ < 1: "
            "the double series converges; and γ = 2e₁ > 0 (e₁'s numerator and denominator are positive), so that "
            "w^γ and τ vanish at w = 0.",
            None,
            lambda: sp.Eq(tau_, _typed_tau()),
            lambda: sp.Eq(tau_, tau_as_appell_f1()["tau"]),
            display=lambda: sp.Eq(tau_, _display_tau()),
            display_where=_tau_where(),
            domain={a: (2 * b, 5 * b), w: (0.05, 0.45)},  # a + c > 2b (b² < ac always): μw < 1; w < 1/2: F₁ fast
        ),
        claim(
            "normal.tau_series",
            "beyond n°11: normal form",
            "The F₁ form of τ differentiates to its integrand: for 0 < w < 1 and 0 < μ < 1, "
            "d/dw[w^γ F₁(γ; β₁, β₂; γ + 1; w, μw)] = γw^(γ−1)(1 − w)^(−β₁)(1 − μw)^(−β₂).  Term by term: the "
            "term (m, n) of the double series of w^γ F₁, differentiated, is γw^(γ−1) times the term (m, n) of the "
            "binomial series of (1 − w)^(−β₁)(1 − μw)^(−β₂) exactly when the Pochhammer identity shown holds, "
            "which it does for every m and n.",
            None,
            sp.Eq(SERIES_IDENTITY, 0),
            lambda: sp.Eq(SERIES_IDENTITY, f1_derivative_identity()),
            display=lambda: sp.Eq(SERIES_IDENTITY, f1_derivative_identity()),  # built unevaluated: in its order
            domain={sp.Symbol(n, positive=True): (0.1, 20) for n in ("gamma", "m", "n")},
        ),
        claim(
            "normal.tau_integrand",
            "beyond n°11: normal form",
            "dτ/ds = A₃P²/(cos θ) is, in w = (1 + s)/2, γC_τ/2 times the Euler integrand "
            "w^(γ−1)(1 − w)^(−β₁)(1 − μw)^(−β₂) of F₁, with the parameters and the constant of normal.tau_F1: "
            "the logarithmic derivatives of the two, in s, both reduce to the one shown, and their ratio 𝓡(s) "
            "is 1 at s = 0 (the constant, sign included, exactly: both are negative, A₃ < 0 where cos θ > 0 as a + c > 2b, and "
            "C_τ < 0; a sign apart would leave ln(−1) = iπ in ln 𝓡 at s = 0; normal.tau_mpmath checks it by "
            "quadrature too).",
            None,
            lambda: [sp.Eq(dlog_tau, log_derivative(tau_rates_in_s()["F1"], S)), sp.Eq(LOG_RATIO, 0)],
            lambda: [sp.Eq(dlog_tau, log_derivative(tau_rates_in_s()["tau"], S)),
                     sp.Eq(LOG_RATIO, expanded_log(tau_rates_in_s()["tau"].subs(S, 0))
                           - expanded_log(tau_rates_in_s()["F1"].subs(S, 0)))],
            display=lambda: [
                sp.Eq(dlog_tau, 2 * (a**2 + a * c + c**2 - 3 * b**2) / (3 * b * (1 - S**2) * (a + c - 2 * b * S))),
                sp.Eq(LOG_RATIO, 0),
            ],
            domain={S: (-1, 1)},
        ),
        NumericCheck(
            "normal.tau_mpmath",
            "beyond n°11: normal form",
            "τ(θ) from Appell's F₁ (mpmath.appellf1) against a tanh-sinh quadrature of A₃P² dθ from −π/2, "
            "two parameter sets, three angles each.",
            None,
            tau_mpmath_check,
            required_digits=30,
        ),
    ]
