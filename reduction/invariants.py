"""Beyond n°11: the invariants s₃, s₅, J of Appell's Abel equation, and what they say.

With s = sin θ, L = (2a + c)(a + 2c) + 9b² − 9b(a + c)s and N a cubic in s,

    s₃ = (a − c) L / (27 b³ cos³θ),   s₅ = (a − c) N / (27 b⁵ cos⁵θ),
    J = s₅³/s₃⁵ = 729 N³ / ((a − c)² L⁵).

* s₃ ≡ 0 exactly when a = c: Appell's special case n°10 is the class s₃ ≡ 0
  (normal form du/dτ = u³, separable).
* J is constant for no positive a, b, c: the billiard (a > b > c > 0, by (9))
  is never in the constant-invariant integrable classes.
* As δ → 0 (b/a = ν, c/a = ν²(R² + k²)/R²), J → 729/4, the invariant of the
  separable z' = z³ − z² of the classical case, with
  J = 729/4 + (19683/16) ν² (3 sin²θ − 2) + O(ν³): rolling friction leaves the
  integrable class at second order in ν = Rδ/(f(R² + k²)) (ν, not ε: ε is the pivot's).
"""

from __future__ import annotations

import random
from functools import lru_cache

import mpmath
import sympy as sp

from derivation.checks import worst_of
from derivation.claim import NumericCheck
from derivation.symbols import label, theta
from reduction.abel import Abel
from reduction.n11_abel import abel_in_theta
from reduction.variables import a, b, c, claim, phi, z

S = sp.Symbol("s", real=True)  # sin θ
nu, rho = sp.symbols("nu rho", positive=True)  # b/a, and R²/(R² + k²) = b²/(ac)

def display_L() -> sp.Expr:
    """L = (2a + c)(a + 2c) + 9b² − 9b(a + c)s, written unevaluated for the appendix."""
    with sp.evaluate(False):
        return (2 * a + c) * (a + 2 * c) + 9 * b**2 - 9 * b * (a + c) * S


def display_N() -> sp.Expr:
    """N, the cubic in s of s₅, by descending powers of s, written unevaluated for the appendix."""
    with sp.evaluate(False):
        return (
            -63 * b**3 * (a + c) * S**3
            + 9 * b**2 * (4 * a**2 + 9 * a * c + 4 * c**2 + 9 * b**2) * S**2
            - 3 * b * (a + c) * (5 * a**2 + 8 * a * c + 5 * c**2 - 3 * b**2) * S
            + (2 * a + c) * (a + 2 * c) * (a**2 + a * c + c**2)
            + 3 * b**2 * (2 * a**2 - a * c + 2 * c**2)
            - 54 * b**4
        )


# The same polynomials evaluated: written once, in the order the appendix shows them.
L_POLY = display_L().doit()
N_POLY = display_N().doit()
IN_THETA = {S: sp.sin(theta)}
S3 = ((a - c) * L_POLY / (27 * b**3 * sp.cos(theta) ** 3)).subs(IN_THETA)
S5 = ((a - c) * N_POLY / (27 * b**5 * sp.cos(theta) ** 5)).subs(IN_THETA)
J_CLOSED = 729 * N_POLY**3 / ((a - c) ** 2 * L_POLY**5)  # in s = sin θ
J_CLASSICAL = sp.Rational(729, 4)
# The variable of the general Abel equation of inv.general and of the random one (`random_invariance_check`): χ, a
# letter the paper does not use (x = fV).
RANDOM_X = sp.Symbol("chi", real=True)
# L and N as the appendix names them in the displays of s₅ and J (`display_where`): 𝓛 and 𝓝, since L and N
# are the rolling couple's components in n°2.
L_NAME = label("𝓛, the factor of s₃ linear in s = sin θ", r"\mathcal{L}")
N_NAME = label("𝓝, the factor of s₅ cubic in s = sin θ", r"\mathcal{N}")


def display_s3() -> sp.Expr:
    """s₃ factored so that the case a = c shows: (a − c)(9b² − 9b(a + c) sin θ + (a + 2c)(2a + c))/(27b³cos³θ)."""
    with sp.evaluate(False):
        return (a - c) * (9 * b**2 - 9 * b * (a + c) * sp.sin(theta) + (a + 2 * c) * (2 * a + c)) / (
            27 * b**3 * sp.cos(theta) ** 3
        )


def display_J() -> sp.Expr:
    """J = 729 N³/((a − c)² L⁵), with L and N named."""
    with sp.evaluate(False):
        return 729 * N_NAME**3 / ((a - c) ** 2 * L_NAME**5)


def _polynomial_in_s(expr: sp.Expr) -> sp.Poly:
    """A polynomial in sin θ (cos θ only in even powers), as a Poly in s."""
    expr = sp.expand(sp.expand_trig(expr)).subs(sp.cos(theta) ** 2, 1 - sp.sin(theta) ** 2)
    return sp.Poly(sp.expand(expr).subs(sp.sin(theta), S), S)


def _positive_solutions(equations: list[sp.Expr]) -> list[dict]:
    """Solutions (a, b, c) of polynomial equations that admit a, b, c > 0."""
    generic = [sp.Symbol(n) for n in "abc"]
    eqs = [e.subs(dict(zip((a, b, c), generic))) for e in equations]
    found = []
    for sol in sp.solve(eqs, generic, dict=True):
        free = set(generic) - set(sol)
        # Try positive values of the free symbols: a solution is kept if the others come out positive.
        rng = random.Random(0)
        for _ in range(20):
            point = {g_: sp.Rational(rng.randint(1, 50), rng.randint(1, 50)) for g_ in free}
            values = {g_: sp.sympify(sol.get(g_, g_)).subs(point) for g_ in generic}
            if all(v.is_positive for v in values.values()):
                found.append({k.name: v for k, v in sol.items()})  # names: the solve ran on plain symbols
                break
    return found


def _a_minus_c(solution: dict) -> sp.Expr:
    generic = {n: sp.Symbol(n) for n in "abc"}
    return sp.simplify((generic["a"] - generic["c"]).subs({generic[k]: v for k, v in solution.items()}))


@lru_cache(maxsize=None)
def classes() -> dict[str, object]:
    """The (a, b, c) > 0 for which s₃ ≡ 0 or J is constant."""
    abel = abel_in_theta()
    s3_zero = _positive_solutions(_polynomial_in_s(abel.s3() * sp.cos(theta) ** 3).coeffs())
    # J' ∝ N²(3N'L − 5NL') / L⁶; N ≢ 0 (its s³ coefficient is −63b³(a + c): inv.J_never_constant
    # checks it), so J is constant iff 3N'L − 5NL' vanishes identically in s.
    W = sp.Poly(sp.expand(3 * sp.diff(N_POLY, S) * L_POLY - 5 * N_POLY * sp.diff(L_POLY, S)), S)
    return {"s3 zero": s3_zero, "J constant": _positive_solutions(W.coeffs()), "W": W}


def N_from_definition() -> sp.Poly:
    """𝓝 from s₅ of n°11's Abel equation, by its definition s₅ = (a − c)𝓝/(27b⁵cos⁵θ) (not from `display_N`)."""
    return _polynomial_in_s(sp.cancel(abel_in_theta().s5() * 27 * b**5 * sp.cos(theta) ** 5 / (a - c)))


def _negative_leading_coefficient(N: sp.Poly) -> sp.Expr:
    """𝓝's leading coefficient in s, which must be negative for every a, b, c > 0: then 𝓝 ≢ 0, and J, which
    𝓝 ≡ 0 would make 0, is not constant that way.  A coefficient not so is refused."""
    lead = sp.factor(N.LC())
    if N.degree() < 1 or (-lead).is_positive is not True:
        raise ValueError(f"𝓝 = {N.as_expr()} has no leading term negative for every a, b, c > 0")
    return lead


def _positive_leading_coefficient(W: sp.Poly) -> sp.Expr:
    """W's leading coefficient in s, which must be positive for every a, b, c > 0 (SymPy's assumptions on the
    positive symbols decide it): then W ≢ 0 and J is never constant.  A coefficient not so is refused."""
    if W.degree() < 1:
        raise ValueError(f"3N'L - 5NL' is of degree {W.degree()} in s: no leading term to argue from")
    lead = sp.factor(W.LC())
    if lead.is_positive is not True:
        raise ValueError(f"the leading coefficient {lead} of 3N'L - 5NL' is not positive for every a, b, c > 0")
    return lead


@lru_cache(maxsize=None)
def J_from_definition() -> sp.Expr:
    """J = s₅³/s₃⁵ with s₃, s₅ of Appell's Abel equation (`Abel.s3`, `Abel.s5`), as a rational function of s."""
    abel = abel_in_theta()
    s3 = _polynomial_in_s(abel.s3() * sp.cos(theta) ** 3).as_expr()
    s5 = _polynomial_in_s(abel.s5() * sp.cos(theta) ** 5).as_expr()
    return s5**3 / s3**5


@lru_cache(maxsize=None)
def small_delta() -> list[sp.Expr]:
    """Coefficients of ν⁰, ν¹, ν² in J, with b = νa, c = ν²a/ρ."""
    scaled = J_CLOSED.subs({b: nu * a, c: nu**2 * a / rho}, simultaneous=True)
    series = sp.series(scaled, nu, 0, 3).removeO()
    return [sp.factor(series.coeff(nu, n)) for n in range(3)]


def random_invariance_check(seed: int = 1911) -> dict[str, sp.Expr]:
    """s₃, s₅, J of a random Abel equation before and after a random transformation.

    Coefficients and P, Q, dτ/dt are random polynomials in x (integer
    coefficients, seeded), so every identity is rational and checked exactly.
    """
    rng = random.Random(seed)
    x = RANDOM_X

    def poly(degree: int, positive: bool = False) -> sp.Expr:
        terms = sum(rng.randint(-5, 5) * x**n for n in range(degree + 1))
        return terms + (1 + x**2) ** degree if positive else terms + 1

    before = Abel(poly(1, True), poly(1), poly(1), poly(2), x=x)
    P, Q, T_rate = poly(1, True), poly(1), poly(1, True)
    after = before.transformed(P, Q, T_rate)
    return {"before": before, "after": after, "weight": P / T_rate, "x": x}


# Any Abel equation and any change of it: f₃, f₂, f₁, f₀, P, Q and τ′ unknown functions of χ.
GENERAL = {name: sp.Function(name)(RANDOM_X) for name in ("f3", "f2", "f1", "f0", "P", "Q", "tau'")}
JET_TEX = {"f3": "f_3", "f2": "f_2", "f1": "f_1", "f0": "f_0", "P": "P", "Q": "Q", "tau'": "tau'",  # names of symbols
           "s3": "s_3"}
# s₃ as a function of χ, unexpanded: s₅ is defined from s₃ and its derivative, as inv.general shows it.
S3_OF_CHI = sp.Function("s3")(RANDOM_X)


def jet(expr: sp.Expr) -> sp.Expr:
    """``expr`` with each unknown function of χ and each of its derivatives made a symbol of its own (f₃, f₃′, f₃″,
    …): an identity for all functions is then an identity of rational functions in these symbols, which SymPy
    decides and the numeric check samples (at a point, a function's value and derivatives are independent)."""
    names = {derivative: jet_symbol(derivative.expr.func.__name__, derivative.derivative_count)
             for derivative in expr.atoms(sp.Derivative)}
    names.update({function: jet_symbol(name) for name, function in {**GENERAL, "s3": S3_OF_CHI}.items()})
    return expr.subs(names)  # sp.subs puts in the derivatives before the functions they are of


def jet_symbol(name: str, order: int = 0) -> sp.Symbol:
    """The symbol of the ``order``-th derivative of the function ``name`` at a point: f_3, f_3', f_3'', …"""
    return sp.Symbol(JET_TEX[name] + "'" * order, real=True)


JET = {name: jet_symbol(name) for name in JET_TEX}
# The sampling box of every symbol of the jet (s₅ takes derivatives up to the third); P and τ′ away from 0, as an
# invertible change needs.
JET_BOX = {jet_symbol(name, order): (0.5, 2) if order == 0 and name in ("P", "tau'") else (-2, 2)
           for name in JET_TEX for order in range(4)}


def invariants_defined() -> dict[str, sp.Expr]:
    """s₃ and s₅ of any Abel equation as `Abel.s3`, `Abel.s5` compute them (s₅ from s₃ and s₃′), in jet symbols."""
    f3, f2, f1, f0 = (GENERAL[name] for name in ("f3", "f2", "f1", "f0"))
    general = Abel(f3, f2, f1, f0, x=RANDOM_X)
    return {"s3": jet(general.s3()), "s5": jet(general.s5(S3_OF_CHI))}


def invariants_shown() -> dict[str, sp.Expr]:
    """The same, typed in the classical order (inv.general shows them; the check ties them to the code)."""
    f3, f2, f1, f0, s3 = (JET[name] for name in ("f3", "f2", "f1", "f0", "s3"))
    d_f3, d_f2, d_s3 = (jet_symbol(name, 1) for name in ("f3", "f2", "s3"))
    with sp.evaluate(False):
        return {
            "s3": f0 * f3**2 - f1 * f2 * f3 / 3 + 2 * f2**3 / 27 + (f3 * d_f2 - f2 * d_f3) / 3,
            "s5": f3 * d_s3 - 3 * s3 * (d_f3 + f1 * f3 - f2**2 / 3),
        }


@lru_cache(maxsize=None)
def invariance_ratios() -> dict[str, sp.Expr]:
    """s̃₃/s₃ and s̃₅/s₅ for any Abel equation under any change z = P u + Q, dτ = τ′ dχ, as quotients in the jet
    symbols (left whole: the exact check cancels them, the numeric check evaluates them), and the weight P/τ′."""
    f3, f2, f1, f0, P, Q, tau_rate = GENERAL.values()
    before = Abel(f3, f2, f1, f0, x=RANDOM_X)
    after = before.transformed(P, Q, tau_rate)
    return {
        "s3": jet(after.s3()) / jet(before.s3()),
        "s5": jet(after.s5()) / jet(before.s5()),
        "weight": JET["P"] / JET["tau'"],
    }


def J_invariance_numeric(digits: int = 30) -> tuple[float, int]:
    """J before and after the random transformation, at 30 digits, at seeded points."""
    inv = random_invariance_check()
    x = inv["x"]
    J_before = sp.lambdify(x, inv["before"].J(), "mpmath")
    J_after = sp.lambdify(x, inv["after"].J(), "mpmath")
    points = [mpmath.mpf(n) / 7 for n in (-9, -4, 1, 3, 8, 13)]
    worst = mpmath.mpf(0)
    with mpmath.workdps(digits + 10):
        for point in points:
            before, after = J_before(point), J_after(point)
            worst = worst_of(worst, abs(after - before) / abs(before))
    return (float(min(digits + 10, -mpmath.log10(worst))) if worst else float(digits + 10)), len(points)


MIRROR = "the Abel right-hand side at 1 − z, a and c exchanged"


def claims():
    from reduction.n11_abel import display_abel_theta

    N_in_s = {N_NAME: display_N(), S: sp.sin(theta)}  # s₅'s display uses 𝓝, not 𝓛
    lab = {name: label(name, tex) for name, tex in (
        ("s3", r"s_3"), ("s5", r"s_5"), ("J", r"J"),
        ("s3 ≡ 0 classes", r"\#\,\mathrm{families}\{(a,b,c) > 0 : s_3 \equiv 0\}"),
        ("a − c on it", r"\left.(a - c)^2\right|_{s_3 \equiv 0}"),
        ("sin θ coefficient", r"[\sin\theta]\, s_3 \cos^3\theta"),
        ("leading coefficient in s of W = 3𝓛 d𝓝/ds − 5𝓝 d𝓛/ds", r"[s^3]\, W"),
        ("leading coefficient in s of 𝓝", r"[s^3]\, \mathcal{N}"),
        # no "families" in its name: beside [s³]W aligned, it overfilled an 11 pt column by 15 pt
        ("J constant classes", r"\#\{(a,b,c) > 0 : dJ/ds \equiv 0\}"),
        ("J of z' = z³ − z²", r"J_{\delta = 0}"),
        ("J0", r"J_0"), ("J1", r"J_1"), ("J2", r"J_2"),  # named in the statement of inv.small_delta
        ("the Abel right-hand side at 1 − z, a and c exchanged", r"\mathcal{F}(1 - z)\big|_{a \leftrightarrow c}"),
        ("J with a and c exchanged", r"J(c, b, a)"), ("J as given", r"J(a, b, c)"),
        ("the Abel right-hand side", r"\mathcal{F}(z)"),  # the stated sides of inv.mirror, defined there
        ("s3 ratio", r"\tilde s_3 / s_3"), ("s5 ratio", r"\tilde s_5 / s_5"),
    )}
    mirrored = {a: c, c: a}
    return [
        claim(
            "inv.general",
            "beyond n°11: invariants",
            "The classical invariants, rederived.  For any Abel equation dz/dχ = f₃z³ + f₂z² + f₁z + f₀ (f₃, f₂, "
            "f₁, f₀ any functions of χ, a prime d/dχ), s₃ and s₅ are defined by the last two rows.  Under any "
            "change z = P u + Q, dτ = τ′ dχ with P, τ′ ≠ 0 (P, Q, τ′ any functions of χ), s₃ and s₅ are multiplied "
            "by (P/τ′)³ and (P/τ′)⁵, so that J = s₅³/s₃⁵, defined where s₃ ≠ 0, is unchanged (checked on its own, "
            "numerically, in inv.general_numeric).  At a point, the values of the functions and of their "
            "derivatives (f₃, f₃′, f₃′′, …) can be any numbers: the identity is one between rational functions of them.",
            None,
            # The ratios first, the definitions after: in this order the one-column layout pairs the ratios and
            # gives each definition its line (the other way, s₅'s shared one with s̃₃/s₃).
            lambda: [
                sp.Eq(lab["s3 ratio"], invariance_ratios()["weight"] ** 3),
                sp.Eq(lab["s5 ratio"], invariance_ratios()["weight"] ** 5),
                sp.Eq(lab["s3"], invariants_shown()["s3"]),
                sp.Eq(lab["s5"], invariants_shown()["s5"]),
            ],
            lambda: [
                sp.Eq(lab["s3 ratio"], invariance_ratios()["s3"]),
                sp.Eq(lab["s5 ratio"], invariance_ratios()["s5"]),
                sp.Eq(lab["s3"], invariants_defined()["s3"]),
                sp.Eq(lab["s5"], invariants_defined()["s5"]),
            ],
            display=lambda: [sp.Eq(lab["s3 ratio"], (JET["P"] / JET["tau'"]) ** 3),
                             sp.Eq(lab["s5 ratio"], (JET["P"] / JET["tau'"]) ** 5),
                             sp.Eq(lab["s3"], invariants_shown()["s3"]),
                             sp.Eq(lab["s5"], invariants_shown()["s5"])],
            domain=JET_BOX,
        ),
        NumericCheck(
            "inv.general_numeric",
            "beyond n°11: invariants",
            "J of the random Abel equation and of its transform, evaluated at six points with 40 working digits: "
            "equal to 30 digits at least.",
            None,
            J_invariance_numeric,
            required_digits=30,
        ),
        claim(
            "inv.s3",
            "beyond n°11: invariants",
            "s₃ of Appell's equation.",
            None,
            sp.Eq(lab["s3"], S3),
            lambda: sp.Eq(lab["s3"], abel_in_theta().s3()),
            display=lambda: sp.Eq(lab["s3"], display_s3()),
        ),
        claim(
            "inv.s5",
            "beyond n°11: invariants",
            "s₅ of Appell's equation.",
            None,
            sp.Eq(lab["s5"], S5),
            lambda: sp.Eq(lab["s5"], abel_in_theta().s5()),
            display=lambda: sp.Eq(lab["s5"], (a - c) * N_NAME / (27 * b**5 * sp.cos(theta) ** 5)),
            display_where=N_in_s,
        ),
        claim(
            "inv.J",
            "beyond n°11: invariants",
            "The absolute invariant J = s₅³/s₃⁵ = 729 𝓝³/((a − c)² 𝓛⁵), a rational function of s = sin θ.",
            None,
            sp.Eq(lab["J"], J_CLOSED),
            # From the definition: s₃, s₅ by the invariant formulas from the Abel coefficients of n°11,
            # not from the closed forms above; cos θ cancels between s₅³ and s₃⁵ (s₃ cos³θ and s₅ cos⁵θ
            # are polynomials in s = sin θ).
            lambda: sp.Eq(lab["J"], J_from_definition()),
            display=lambda: sp.Eq(lab["J"], display_J()),
            display_where={L_NAME: display_L(), N_NAME: display_N()},
        ),
        claim(
            "inv.s3_zero",
            "beyond n°11: invariants",
            "s₃ ≡ 0 for positive a, b, c only when a = c: the special case n°10 (normal form du/dτ = u³).  The "
            "coefficient of sin θ in s₃ cos³θ (a polynomial of degree 1 in sin θ) is −(a − c)(a + c)/(3b²), zero for "
            "a, c > 0 only when a = c, where s₃ ≡ 0 (inv.s3).  Counted in families, as SymPy's solve of the "
            "coefficients returns them, the same: one family of positive solutions (a = c, any b > 0).",
            None,
            [
                sp.Eq(lab["sin θ coefficient"], -(a - c) * (a + c) / (3 * b**2)),
                sp.Eq(lab["s3 ≡ 0 classes"], 1), sp.Eq(lab["a − c on it"], 0),
            ],
            lambda: [
                sp.Eq(lab["sin θ coefficient"], _polynomial_in_s(abel_in_theta().s3() * sp.cos(theta) ** 3).coeff_monomial(S)),
                sp.Eq(lab["s3 ≡ 0 classes"], len(classes()["s3 zero"])),
                sp.Eq(lab["a − c on it"], sum(_a_minus_c(sol) ** 2 for sol in classes()["s3 zero"])),
            ],
        ),
        claim(
            "inv.J_never_constant",
            "beyond n°11: invariants",
            "J is constant for no a, b, c > 0 with a ≠ c (a = c is n°10's case, where s₃ ≡ 0 and J is not "
            "defined: inv.s3_zero): dJ/ds = 729𝓝²W/((a − c)²𝓛⁶) in s = sin θ, where W = 3𝓛 d𝓝/ds − 5𝓝 d𝓛/ds is a "
            "cubic in s, so that dJ/ds ≡ 0 needs 𝓝 ≡ 0 or W ≡ 0.  Neither: 𝓝 (from s₅'s definition) has the leading "
            "coefficient [s³]𝓝 = −63b³(a + c), negative, and W the leading coefficient [s³]W = 2268b⁴(a + c)², "
            "positive, for a, b, c > 0.  So the billiard, a > b > c > 0, is not in the constant-invariant "
            "integrable classes.  (SymPy's solve of the coefficients of W, a cross-check and no proof, finds no family "
            "with a, b, c > 0 either.)",
            None,
            [sp.Eq(lab["leading coefficient in s of 𝓝"], -63 * b**3 * (a + c)),
             sp.Eq(lab["leading coefficient in s of W = 3𝓛 d𝓝/ds − 5𝓝 d𝓛/ds"], 2268 * b**4 * (a + c) ** 2), sp.Eq(lab["J constant classes"], 0)],
            lambda: [sp.Eq(lab["leading coefficient in s of 𝓝"], _negative_leading_coefficient(N_from_definition())),
                     sp.Eq(lab["leading coefficient in s of W = 3𝓛 d𝓝/ds − 5𝓝 d𝓛/ds"], _positive_leading_coefficient(classes()["W"])),
                     sp.Eq(lab["J constant classes"], len(classes()["J constant"]))],
        ),
        claim(
            "inv.classical",
            "beyond n°11: invariants",
            "For δ = 0, λ = 0 and z' = z³ − z² is separable, with J = 729/4: a limit (at δ = 0 itself z ≡ 0 and φ is "
            "not defined), J₀ of inv.small_delta.",
            None,
            sp.Eq(lab["J of z' = z³ − z²"], J_CLASSICAL),
            lambda: sp.Eq(lab["J of z' = z³ − z²"], Abel(sp.Integer(1), sp.Integer(-1), sp.Integer(0), sp.Integer(0), x=phi).J()),
        ),
        claim(
            "inv.small_delta",
            "beyond n°11: invariants",
            "With ν = b/a = Rδ/(f(R² + k²)) and c/a = ν²(R² + k²)/R²: J = J₀ + J₁ν + J₂ν² + O(ν³) = 729/4 + "
            "(19683/16) ν² (3 sin²θ − 2) + O(ν³); "
            "rolling friction moves J off the classical constant at second order.",
            None,
            [sp.Eq(lab["J0"], J_CLASSICAL), sp.Eq(lab["J1"], 0), sp.Eq(lab["J2"], sp.Rational(19683, 16) * (3 * S**2 - 2))],
            lambda: [sp.Eq(lab[name], coef) for name, coef in zip(("J0", "J1", "J2"), small_delta(), strict=True)],
            domain={nu: (0, 0.5), rho: (0.6, 1), S: (-1, 1)},
        ),
        claim(
            "inv.mirror",
            "beyond n°11: invariants",
            "The sliding/rolling symmetry of n°2 in the Abel equation dz/dθ = 𝓕(z): since 𝓕(1 − z)|a↔c = −𝓕(z), "
            "1 − z solves the same equation with a ↔ c: d(1 − z)/dθ = 𝓕(1 − z)|a↔c.  The exchange "
            "takes the equation outside the billiard's range a > b > c > 0 (it maps the family of equations, not "
            "one ball, to itself).  "
            "J(c, b, a) = J(a, b, c) follows at sight, 𝓝, 𝓛 and (a − c)² being unchanged by a ↔ c.",
            None,
            # stated as −𝓕(z) and J(a, b, c), their definitions put in: the derived rows end "= −𝓕(z)", "= J(a, b, c)"
            [sp.Eq(lab[MIRROR], -lab["the Abel right-hand side"]), sp.Eq(lab["J with a and c exchanged"], lab["J as given"])],
            lambda: [
                sp.Eq(lab[MIRROR], abel_in_theta().rhs(1 - z).subs(mirrored, simultaneous=True)),
                sp.Eq(lab["J with a and c exchanged"], J_CLOSED.subs(mirrored, simultaneous=True)),
            ],
            display=lambda: [sp.Eq(lab[MIRROR], -display_abel_theta()), sp.Eq(lab["J with a and c exchanged"], display_J())],
            display_where={L_NAME: display_L(), N_NAME: display_N()},
            definitions=lambda: {lab["the Abel right-hand side"]: abel_in_theta().rhs(z), lab["J as given"]: J_CLOSED},
            domain={S: (-1, 1)},
        ),
    ]
