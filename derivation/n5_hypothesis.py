"""n°5, eq. (9): the hypothesis δ < fR — which results need it, and which survive without it.

Appell restricts himself to "le cas réel du billard ordinaire", δ < fR, and
notes that pure mathematics would have other cases.  Each result of n°6–n°8
that leans on (9) is checked here on both sides of it: proved under the
weakest hypothesis it needs, and shown to fail just beyond (a proof under the
opposite hypothesis, so the boundary is exact).

* n°7's pure rolling needs only Rδ ≤ f(R² + k²) (f₁ = Rδ/(R² + k²) ≤ f),
  which allows δ up to fR(1 + k²/R²); beyond it f₁ > f and the ball cannot roll.
* n°8's "V decreases and vanishes" needs only Rδ < f(R² + k²) too;
  n°8's bound V' < −fg (and so the slide shorter than V₀/(fg)) needs (9):
  for δ ≥ fR a straight follow shot has V' ≥ −fg.
* n°6 (no sliding without rolling, hence n°8's "Ω cesse d'être nul") needs (9)
  exactly: for δ ≥ fR the couple of repose δ₁ = fR ≤ δ holds Ω ≡ 0 while the
  ball slides like a block, V' = −fg.
* the slope of (11) keeps its sign while δ < f√(R² + k²); at equality a = c,
  n°10's case (n10.violates_9).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import n6_rolling_returns, n7_pure_rolling, n8_general, polar
from derivation.claim import Claim
from derivation.symbols import Omega, R, V, d, delta, delta_1, f, f_1, g, k, label, theta

# Each side of a boundary as a substitution over a nonnegative or positive symbol, so that
# SymPy's assumptions decide a sign under it (as checks.HYPOTHESIS_9 does for δ < fR).
s0 = sp.Symbol("sigma_0", nonnegative=True)
s1 = sp.Symbol("sigma_1", positive=True)
ROLLING_BOUND = f * (R**2 + k**2) / R  # f₁ = f there: the largest δ pure rolling allows
WITHIN_ROLLING = {delta: ROLLING_BOUND / (1 + s0)}  # Rδ ≤ f(R² + k²)
WITHIN_ROLLING_STRICT = {delta: ROLLING_BOUND / (1 + s1)}  # Rδ < f(R² + k²)
BEYOND_ROLLING = {delta: ROLLING_BOUND * (1 + s1)}  # Rδ > f(R² + k²)
BEYOND_9 = {delta: f * R * (1 + s0)}  # δ ≥ fR: (9) broken
SQRT_BOUND = f * sp.sqrt(R**2 + k**2)  # a = c there (n°10)
WITHIN_SQRT = {delta: SQRT_BOUND / (1 + s1)}  # δ < f√(R² + k²)

# Sampling boxes for δ on each side (the default box is (9)'s, 0 < δ < fR).
UP_TO_ROLLING = {delta: (0, ROLLING_BOUND)}
PAST_ROLLING = {delta: (ROLLING_BOUND, 2 * ROLLING_BOUND)}
PAST_9 = {delta: (f * R, 2 * f * R)}
UP_TO_SQRT = {delta: (0, SQRT_BOUND)}

RIGHT_ANGLE = {theta: sp.pi / 2}

# The paper's sentences of n°5 (verbatim from the transcription).
CASES = r"il y aurait différents cas à distinguer suivant les grandeurs relatives des coefficients"
REAL_CASE = (
    r"Nous n'envisagerons que le cas réel du billard ordinaire, dans lequel le frottement de roulement a une "
    r"importance beaucoup plus petite que le frottement de glissement"
)
# (9) as printed: the sentence and its display (a referee's audit: eq9 said "no printed form").
HYPOTHESIS_9_PRINTED = r"Nous admettrons que le coefficient $\delta$ est assez petit pour que $$(9) \quad \delta < fR.$$"
ADMIT = r"Nous admettrons que le coefficient $\delta$ est assez petit pour que"
SIMPLIFIES = r"Dans cette hypothèse la discussion se simplifie comme il suit"


@lru_cache(maxsize=None)
def sliding_without_rolling() -> dict[str, sp.Expr]:
    """n°6's motion Ω ≡ 0 at θ = π/2: the couple of repose it needs and the slip's rate then."""
    conditions = n6_rolling_returns.conditions()
    (needed,) = sp.solve(conditions["second"].subs(RIGHT_ANGLE), delta_1)
    # (7) with δ₁ for δ (n°6: "où δ serait remplacé par δ₁").
    V_rate = polar.rates()[d(V)].subs(delta, delta_1).subs(RIGHT_ANGLE).subs(delta_1, needed)
    return {"first": conditions["first"].subs(RIGHT_ANGLE), "delta_1": needed, "V'": sp.simplify(V_rate)}


def claims() -> list[Claim]:
    slip_excess = label("V' + fg at θ = π/2", r"\left. V' + fg \right|_{\theta = \pi/2}")
    first = label("cos θ at θ = π/2", r"\left. \cos\theta \right|_{\theta = \pi/2}")
    rate_11 = f * d(V) - delta * d(Omega)
    spin_up = label("largest Ω' over θ", r"\max_\theta \Omega'")
    where = "n°5, eq. (9)"
    return [
        Claim(
            "eq9",
            where,
            "(9), δ < fR, is the condition that sliding friction can spin the ball up against the rolling couple: "
            "the largest rate of Ω that (8) allows, (fR − δ)g/k² (at θ = π/2), is positive exactly when δ < fR.  "
            "(The paper states (9) as its hypothesis; what is checked is this meaning of it.)",
            HYPOTHESIS_9_PRINTED,
            sp.Gt(spin_up, 0),
            lambda: sp.Eq(spin_up, sp.maximum(polar.rates()[d(Omega)], theta, sp.Interval(-sp.pi, sp.pi))),
            # fR − δ as the statement has it (the quoted sentence names δ first, which would put it first).
            display=lambda: sp.Eq(spin_up, (f * R - delta) * g / k**2),
        ),
        Claim(
            "n5.spin_up_needs_9",
            where,
            "… and for δ ≥ fR it is not: no direction of the rotation lets Ω grow from zero.",
            None,
            sp.Le(spin_up, 0),
            lambda: sp.Eq(spin_up, sp.maximum(polar.rates()[d(Omega)], theta, sp.Interval(-sp.pi, sp.pi))),
            domain=PAST_9,
            hypothesis=BEYOND_9,
            context=REAL_CASE,
        ),
        Claim(
            "n5.rolling_survives",
            where,
            "n°7's pure rolling does not need (9): the friction of repose f₁ = Rδ/(R² + k²) stays ≤ f whenever "
            "Rδ ≤ f(R² + k²), which allows δ up to fR(1 + k²/R²) (1.4 fR for a solid ball).",
            None,
            sp.Le(f_1, f),
            lambda: sp.Eq(f_1, n7_pure_rolling.motion()["f_1"]),
            domain=UP_TO_ROLLING,
            hypothesis=WITHIN_ROLLING,
            context=CASES,
        ),
        Claim(
            "n5.rolling_fails_beyond",
            where,
            "… and no further: for Rδ > f(R² + k²) the friction needed exceeds f (f₁ > f), so the ball cannot roll "
            "without sliding.",
            None,
            sp.Gt(f_1, f),
            lambda: sp.Eq(f_1, n7_pure_rolling.motion()["f_1"]),
            domain=PAST_ROLLING,
            hypothesis=BEYOND_ROLLING,
            context=CASES,
        ),
        Claim(
            "n5.slip_ends_survives",
            where,
            "n°8's ‘V diminue constamment’ does not need (9): V' ≤ −g(f(R² + k²) − Rδ)/k² < 0 for every θ "
            "whenever Rδ < f(R² + k²), so the slide still ends in finite time.",
            None,
            sp.Lt(d(V), 0),
            lambda: sp.Eq(d(V), n8_general.relations()["V'"]),
            display=n8_general.display_V_rate,
            bounded={sp.sin(theta): (-1, 1)},
            domain=UP_TO_ROLLING,
            hypothesis=WITHIN_ROLLING_STRICT,
            context=CASES,
        ),
        Claim(
            "n5.slip_bound_needs_9",
            where,
            "n°8's V' < −fg (and the slide shorter than V₀/(fg)) needs (9): for δ ≥ fR a straight follow shot "
            "(θ = π/2) has V' + fg = Rg(δ − fR)/k² ≥ 0.",
            None,
            sp.Ge(slip_excess, 0),
            lambda: sp.Eq(slip_excess, n8_general.relations()["V'"].subs(RIGHT_ANGLE) + f * g),
            # As the statement writes it (SymPy's order read fg + g(−fR² + Rδ − fk²)/k², a referee).
            display=lambda: sp.Eq(slip_excess, sp.Mul(R * g / k**2, delta - f * R, evaluate=False)),
            domain=PAST_9,
            hypothesis=BEYOND_9,
            context=SIMPLIFIES,
        ),
        Claim(
            "n5.no_rolling_needs_9",
            where,
            "n°6 needs (9), and exactly: sliding without rolling (Ω ≡ 0) holds at θ = π/2 with the couple of repose "
            "δ₁ = fR, and the ball then slides like a block, V' = −fg.  n°6's δ₁ ≤ δ < fR excludes it; for δ ≥ fR "
            "(n5.no_rolling_admissible) it is the motion that follows from Ω₀ = 0, the only one (n5.spin_up_needs_9).",
            None,
            [sp.Eq(first, 0), sp.Eq(delta_1, f * R), sp.Eq(d(V), -f * g)],
            lambda: [
                sp.Eq(first, sliding_without_rolling()["first"]),
                sp.Eq(delta_1, sliding_without_rolling()["delta_1"]),
                sp.Eq(d(V), sliding_without_rolling()["V'"]),
            ],
            context=ADMIT,
        ),
        Claim(
            "n5.no_rolling_admissible",
            where,
            "For δ ≥ fR the couple of repose that sliding without rolling needs, δ₁ = fR, is within its bound "
            "δ₁ ≤ δ (n°6): without (9) the rotation may stay zero while the ball slides.",
            None,
            sp.Le(delta_1, delta),
            lambda: sp.Eq(delta_1, sliding_without_rolling()["delta_1"]),
            domain=PAST_9,
            hypothesis=BEYOND_9,
            context=ADMIT,
        ),
        Claim(
            "n5.integral_rate_survives",
            where,
            "The slope of (11), fV' − δΩ' = −(f²(R² + k²) − δ²)g/k², is negative whenever δ < f√(R² + k²), "
            "weaker than (9); at δ = f√(R² + k²) it vanishes: n°10's a = c.",
            None,
            sp.Lt(rate_11, 0),
            lambda: sp.Eq(rate_11, n8_general.relations()["fV' - delta Omega'"]),
            display=n8_general.display_integral_rate,
            domain=UP_TO_SQRT,
            hypothesis=WITHIN_SQRT,
            context=CASES,
        ),
    ]
