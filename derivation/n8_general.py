"""n°8: the general case, V₀ > 0 and Ω₀ > 0 — what (7)–(8) say without integrating them.

The slip ends in finite time (V' < −fg); fV − δΩ decreases linearly (the
integral (11)); the kinetic energy decreases at the rate of the friction
work; |ΩV cos θ| decreases; and θ = β − α turns towards π/2, which it
reaches exactly when V does, with π/2 − θ ∝ V^κ.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import checks, n7_pure_rolling, newton_euler, polar
from derivation.claim import Claim, Erratum
from derivation.newton_euler import L, M, N, X, Y, sign_r
from derivation.symbols import (
    V_0,
    Omega,
    Omega_0,
    R,
    V,
    accent,
    alpha,
    beta,
    d,
    delta,
    delta_1,
    epsilon,
    eta,
    f,
    f_1,
    g,
    k,
    label,
    m,
    ocr_hat_c,
    ocr_partial,
    ocr_U,
    p,
    q,
    r,
    snapshot,
    t,
    theta,
    u,
    v,
    xi,
    zeta,
)

ONE_PLUS = 1 + R**2 / k**2
PARTIAL_FOR_DELTA = Erratum("ocr", "∂ read for δ", glyphs={ocr_partial: delta})
TWO_T = label("2T, twice the kinetic energy", "2T")  # our name: the paper writes the bracket alone
# θ acute: cos θ > 0, as a positive symbol for the sign proofs.
cos_theta_positive = sp.Symbol("c_theta", positive=True)
PRODUCT_RATE = label("d/dt[ΩV cos(β − α)]", r"\frac{d}{dt}\left[\Omega V \cos(\beta - \alpha)\right]")


# Displays (`Claim.display`): derived forms as the paper arranges them, built unevaluated.
def display_V_rate() -> sp.Eq:
    """(7)'s V' in θ: −fg(1 + R²/k²) + (Rδ/k²) g sin θ."""
    return sp.Eq(accent(V), -f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g * sp.sin(theta))


def display_integral_rate() -> sp.Eq:
    """fV' − δΩ' = −f²g(1 + R²/k²) + (δ²/k²) g, as n°8 prints it."""
    return sp.Eq(f * accent(V) - delta * accent(Omega), -f**2 * g * (1 + R**2 / k**2) + (delta**2 / k**2) * g)


def display_theta_coefficient() -> sp.Expr:
    """The coefficient of cos θ in θ' = β' − α': (Rg/k²)(f/Ω + δ/V)."""
    return (R * g / k**2) * (f / Omega + delta / V)


@lru_cache(maxsize=None)
def relations() -> dict[str, sp.Expr]:
    """The relations of n°8, each obtained from (7), (8), (5)."""
    rates = polar.rates()
    V_rate, Omega_rate = rates[d(V)], rates[d(Omega)]
    theta_rate = polar.theta_rate()
    integral_rate = sp.expand(f * V_rate - delta * Omega_rate)

    # Kinetic energy (Koenig): translation of G plus rotation about G.
    centre = newton_euler.centre_velocity()
    polar_state = {
        u: V * sp.cos(alpha),
        v: V * sp.sin(alpha),
        p: Omega * sp.cos(beta),
        q: Omega * sp.sin(beta),
    }
    xi_dot, eta_dot = (centre[x].subs(polar_state) for x in (d(xi), d(eta)))
    two_T_def = m * (d(xi) ** 2 + d(eta) ** 2 + k**2 * (p**2 + q**2 + r**2))
    two_T = polar.in_theta(m * (xi_dot**2 + eta_dot**2) + m * k**2 * (Omega**2 + r**2))

    # dT/dt along the motion: differentiate, then put in (7), (8), (5).
    T_t = (m * (xi_dot**2 + eta_dot**2) + m * k**2 * (Omega**2 + r**2)) / 2
    r_rate = newton_euler.accelerations()[d(r)]
    along_motion = {d(V): V_rate, d(Omega): Omega_rate, d(alpha): rates[d(alpha)], d(beta): rates[d(beta)], d(r): r_rate}
    T_rate = polar.in_theta(sp.diff(T_t, t).subs(along_motion))

    # Second route: the power of the loads (the normal reaction works not, w = 0).
    v_A = sp.Matrix([V * sp.cos(alpha), V * sp.sin(alpha), 0])
    omega = sp.Matrix([Omega * sp.cos(beta), Omega * sp.sin(beta), r])
    pivot = sp.Matrix([0, 0, -sign_r * epsilon * m * g])
    power = sp.simplify(
        newton_euler.sliding_force().dot(v_A) + (newton_euler.rolling_couple() + pivot).dot(omega)
    )

    # Pure rolling (n°7): V = 0, θ = π/2, Ω' = −δg/(R² + k²).
    rolling = n7_pure_rolling.motion()
    T_rate_rolling = sp.simplify(sp.diff(T_t.subs(V, 0), t).subs({d(Omega): rolling["Omega'"], d(r): r_rate}))

    product = Omega * V * sp.cos(theta)
    product_rate = sp.factor(
        (Omega_rate * V + Omega * V_rate) * sp.cos(theta) - Omega * V * sp.sin(theta) * theta_rate
    )

    # Near the end of sliding, ψ = π/2 − θ → 0 and V → 0: the exponent of ψ ∝ V^κ.
    psi = sp.Symbol("psi", positive=True)
    log_slope = snapshot((-V * theta_rate / (psi * V_rate)).subs(theta, sp.pi / 2 - psi))
    kappa = sp.simplify(sp.limit(sp.limit(log_slope, snapshot(V), 0), psi, 0))
    return {
        "V'": V_rate,
        "Omega'": Omega_rate,
        "theta'": theta_rate,
        "fV' - delta Omega'": integral_rate,
        "fV - delta Omega": f * V_0 - delta * Omega_0 + sp.integrate(integral_rate, (t, 0, t)),
        "t bound": sp.solve(V_0 - f * g * t, t)[0],
        "2T def": two_T_def,
        "2T": sp.expand(two_T),
        "T'": T_rate,
        "power": power,
        "T' rolling": T_rate_rolling,
        "d/dt[Omega V cos]": product_rate,
        "coefficient": sp.expand(sp.cancel(product_rate / product)),
        "alpha' beta'": sp.factor(rates[d(alpha)] * rates[d(beta)]),
        "kappa": kappa,
    }


@lru_cache(maxsize=None)
def spin_near_zero() -> dict[str, object]:
    """n°8's "si Ω s'annule avant V": the rotation's rate in Cartesian (p, q), bounded where (8) is singular.

    (8) divides by Ω: at Ω = 0 the angle β, and with it the direction of the rolling couple, is
    undefined.  In (p, q) the rate is the sliding friction's term, fixed by α, minus the couple's
    δg/k² along e_β: bounded, its size between (fR − δ)g/k² and (fR + δ)g/k².  The only direction
    Ω can leave zero along is one where this rate is radial and outward, θ = π/2 (n°6's rule); and
    ln|tan(θ/2 + π/4)| grows at the rate (Rg/k²)(f/Ω + δ/V), which forbids reaching Ω = 0 unless θ ≡ −π/2.
    """
    acc = newton_euler.accelerations()
    rates = polar.rates()
    spin_rate = [acc[d(p)], acc[d(q)]]
    return {
        "p', q'": spin_rate,
        "|p', q'|^2": polar.in_theta(spin_rate[0] ** 2 + spin_rate[1] ** 2),
        "Omega' at theta": [rates[d(Omega)].subs(theta, side) for side in (sp.pi / 2, -sp.pi / 2)],
        "d/dt ln tan": sp.simplify(polar.theta_rate() * sp.diff(sp.log(sp.tan(theta / 2 + sp.pi / 4)), theta)),
    }


@lru_cache(maxsize=None)
def rest() -> dict[str, object]:
    """The final rest: V ≡ 0 and Ω ≡ 0, so ξ'' = η'' = p' = q' = 0; what (4) and (5) ask of the loads then.

    The loads are those of repose, unknown a priori (n°6, n°7): a force F = (X, Y, 0) of magnitude
    f₁mg and a horizontal couple H = (L, M, 0) of magnitude δ₁mg.
    """
    eqs = newton_euler.equations_of_motion()
    still = {d(xi, 2): 0, d(eta, 2): 0, d(p): 0, d(q): 0}
    (loads,) = sp.solve([e.subs(still) for e in eqs["translation"] + eqs["rotation"][:2]], [X, Y, L, M], dict=True)
    weight = eqs["n"]  # n = mg
    centre = newton_euler.centre_velocity()
    at_rest = {u: 0, v: 0, p: 0, q: 0}
    # The couple of repose is horizontal (N = 0), as the rolling couple it stands for.
    (r_rate,) = sp.solve(eqs["rotation"][2].subs(N, 0), d(r))
    return {
        "f_1": sp.sqrt(loads[X] ** 2 + loads[Y] ** 2) / weight,
        "delta_1": sp.sqrt(loads[L] ** 2 + loads[M] ** 2) / weight,
        "xi'": centre[d(xi)].subs(at_rest),
        "eta'": centre[d(eta)].subs(at_rest),
        "r'": r_rate,
    }


def claims() -> list[Claim]:
    in_ab = {theta: beta - alpha}
    V_rate = d(V)
    bound = label("time bound on the slide", r"t_{\max}")
    rate_11 = f * d(V) - delta * d(Omega)
    T_rate = label("dT/dt", r"\frac{dT}{dt}")
    # The terms in r of the energy relation, one from each side: d/dt(½mk²r²) on the left, ∓εmgr on the right.
    r_terms = label("d/dt(½mk²r²) less the pivot term", r"\frac{d}{dt}\left(\tfrac12 m k^2 r^2\right) + s_r \varepsilon m g r")
    T_rest = label("d/dt(T − ½mk²r²)", r"\frac{d}{dt}\left(T - \tfrac12 m k^2 r^2\right)")

    def pivot_power():  # d/dt(½mk²r²) by (5); called by the checks only (listing the claims derives nothing)
        return sp.diff(m * k**2 * r**2 / 2, t).subs(d(r), newton_euler.accelerations()[d(r)])

    def rolling_energy_rate():  # −mgδΩ, the factor mg first as in n8.energy_decreases' −mg(fV + δΩ)
        return sp.Eq(T_rest, sp.Mul(-m * g, delta * Omega))

    coeff = label("the coefficient of ΩV cos(β − α) in its own rate", r"\kappa_{\Omega V}")
    sign_product = d(alpha) * d(beta)
    theta_coeff = label("coefficient of cos(β − α) in β' − α'", r"\kappa_\theta")
    theta_rate = label("θ', the rate of θ = β − α while θ is acute", r"\theta'")
    kappa = label("κ, with π/2 − θ ∝ V^κ as V → 0", r"\kappa")
    hyp = label("hypothesis of n°8", r"\delta - fR")
    reason = label("bound invoked for θ", r"V - (V_0 - fgt)")
    leave = [
        label("Ω' at θ = π/2", r"\left. \Omega' \right|_{\theta = \pi/2}"),
        label("Ω' at θ = −π/2", r"\left. \Omega' \right|_{\theta = -\pi/2}"),
    ]
    spin_rate_2 = label("|(p', q')|²", r"p'^2 + q'^2")
    log_tan_rate = label("d/dt ln|tan(θ/2 + π/4)|", r"\frac{d}{dt} \ln\left|\tan\left(\frac{\theta}{2} + \frac{\pi}{4}\right)\right|")
    return [
        Claim(
            "n8.V_rate_bound",
            "n°8",
            "From (7) and sin(β − α) ≤ 1.  Equality holds at θ = π/2, so the printed strict ‘<’ is ‘≤’ "
            "(harmless: the next bound V' < −fg is strict under (9)).",
            r"V' < -fg \left( 1 + \frac{R^2}{k^2} \right) + \frac{R\delta}{k^2} g,",
            sp.Lt(V_rate, -f * g * ONE_PLUS + R * delta / k**2 * g),
            lambda: sp.Eq(V_rate, relations()["V'"]),
            display=display_V_rate,
            erratum=Erratum(
                "remark",
                "sin(β − α) ≤ 1 gives V' ≤ −fg(1 + R²/k²) + Rδg/k², with equality when β − α = π/2 (a straight "
                "shot slipping forward with less top spin than rolling keeps it there: a centre-ball hit, a draw "
                "once its back spin has reversed); the strict ‘<’ does not follow.",
                corrected=sp.Le(V_rate, -f * g * ONE_PLUS + R * delta / k**2 * g),
                witness={theta: sp.pi / 2},
                summary="the bound on V' is printed strict though β − α = π/2 reaches it (‘<’ for ‘≤’; harmless, the next bound V' < −fg being strict)",
            ),
            bounded={sp.sin(theta): (-1, 1)},
        ),
        Claim(
            "n8.V_decreases",
            "n°8",
            "V' < −fg under δ < fR (9): V decreases and V − V₀ < −fgt.",
            r"V' < -fg;",
            sp.Lt(V_rate, -f * g),
            lambda: sp.Eq(V_rate, relations()["V'"]),
            display=display_V_rate,
            bounded={sp.sin(theta): (-1, 1)},
        ),
        Claim(
            "n8.slide_time_bound",
            "n°8",
            "V vanishes before the root of V₀ − fgt (a glyph record: the meant V₀/(fg) is typed; that the "
            "slide ends before it follows from V − V₀ < −fgt, n8.V_decreases, and is measured by n8.slide_time_mpmath).",
            r"\frac{V_0}{f/g}",
            sp.Eq(bound, V_0 / (f / g)),
            lambda: sp.Eq(bound, relations()["t bound"]),
            erratum=Erratum(
                "ocr",
                "fg read as f/g: the bound is the root V₀/(fg) of V₀ − fgt, and f/g is not even a time",
                corrected=sp.Eq(bound, V_0 / (f * g)),
                tex={"f/g": "fg"},
            ),
            glyph_only=True,
        ),
        Claim(
            "n8.integral_rate",
            "n°8",
            "Eliminating sin(β − α) between the first equations of (7) and (8).",
            r"fV' - \delta\Omega' = -f^2g\left(1 + \frac{R^2}{k^2}\right) + \frac{\partial^2}{k^2}g,",
            sp.Eq(f * d(V) - delta * d(Omega), -(f**2) * g * ONE_PLUS + ocr_partial**2 / k**2 * g),
            lambda: sp.Eq(f * d(V) - delta * d(Omega), relations()["fV' - delta Omega'"]),
            display=display_integral_rate,
            erratum=PARTIAL_FOR_DELTA,
        ),
        Claim(
            "n8.integral_rate_negative",
            "n°8",
            "The right-hand side is negative because δ < fR (the OCR prints the hypothesis as ĉ < fR).",
            r"où le second membre est négatif à cause de l'hypothèse $\hat{c} < fR$",
            sp.Lt(rate_11, 0),
            lambda: sp.Eq(rate_11, relations()["fV' - delta Omega'"]),
            display=display_integral_rate,
        ),
        Claim(
            "n8.hypothesis",
            "n°8",
            "The hypothesis invoked is (9), δ < fR (a glyph record: the meant δ < fR is typed, not derived).",
            r"$\hat{c} < fR$",
            sp.Eq(hyp, ocr_hat_c - f * R),
            lambda: sp.Eq(hyp, delta - f * R),
            erratum=Erratum("ocr", "ĉ read for δ", glyphs={ocr_hat_c: delta}),
            glyph_only=True,
        ),
        Claim(
            "eq11",
            "n°8, eq. (11)",
            "The integral: fV − δΩ decreases linearly while V and Ω are both nonzero.",
            r"fV - \delta\Omega = fV_0 - \delta\Omega_0 - \left[ f^2\left(1 + \frac{R^2}{k^2}\right) - \frac{\partial^2}{k^2} \right] g t.",
            sp.Eq(f * V - delta * Omega, f * V_0 - delta * Omega_0 - (f**2 * ONE_PLUS - ocr_partial**2 / k**2) * g * t),
            lambda: sp.Eq(f * V - delta * Omega, relations()["fV - delta Omega"]),
            display=lambda: sp.Eq(
                f * V - delta * Omega,
                f * V_0 - delta * Omega_0 - (f**2 * (1 + R**2 / k**2) - delta**2 / k**2) * g * t,
            ),
            erratum=PARTIAL_FOR_DELTA,
        ),
        Claim(
            "n8.kinetic_energy_def",
            "n°8",
            "Twice the kinetic energy: translation of G plus rotation about G (Koenig).",
            r"m[\zeta'^2 + \eta'^2 + k^2(p^2 + q^2 + r^2)]",
            sp.Eq(TWO_T, m * (d(zeta) ** 2 + d(eta) ** 2 + k**2 * (p**2 + q**2 + r**2))),
            lambda: sp.Eq(TWO_T, relations()["2T def"]),
            erratum=Erratum("ocr", "ζ read for ξ", glyphs={zeta: xi}),
        ),
        Claim(
            "n8.kinetic_energy",
            "n°8",
            "Twice the kinetic energy in the polar variables.",
            r"2T = m[V^2 + R^2\Omega^2 + 2R\Omega V \sin(\beta - \alpha) + k^2(\Omega^2 + r^2)].",
            sp.Eq(
                TWO_T,
                m * (V**2 + R**2 * Omega**2 + 2 * R * Omega * V * sp.sin(beta - alpha) + k**2 * (Omega**2 + r**2)),
            ),
            lambda: sp.Eq(TWO_T, relations()["2T"].subs(in_ab)),
            display=lambda: sp.Eq(
                TWO_T,
                m * (V**2 + R**2 * Omega**2 + 2 * R * Omega * V * sp.sin(beta - alpha) + k**2 * (Omega**2 + r**2)),
            ),
        ),
        Claim(
            "n8.energy_rate",
            "n°8",
            "dT/dt along (7), (8), (5): the work of sliding friction, rolling and pivot couples "
            "(± is −s_r, s_r the sign of r).",
            r"dT = -mf g V dt - m \delta g \Omega dt \pm \varepsilon mgr dt,",
            sp.Eq(T_rate, -m * f * g * V - m * delta * g * Omega - sign_r * epsilon * m * g * r),
            lambda: sp.Eq(T_rate, relations()["T'"]),
        ),
        Claim(
            "n8.energy_power",
            "n°8",
            "Second route to dT/dt: the power of the loads, F·v_A + (H + K)·ω, of the sliding friction F on the "
            "velocity v_A of the ball's material point at the contact A, and of the rolling couple H and the pivot "
            "couple K on the rotation ω.",
            r"dT = -mf g V dt - m \delta g \Omega dt \pm \varepsilon mgr dt,",
            sp.Eq(T_rate, -m * f * g * V - m * delta * g * Omega - sign_r * epsilon * m * g * r),
            lambda: sp.Eq(T_rate, relations()["power"]),
        ),
        Claim(
            "n8.energy_r_terms",
            "n°8",
            "The terms in r cancel: by (5), the pivot term is d/dt(½mk²r²).",
            r"Dans cette relation les termes en $r$ se détruisent",
            sp.Eq(r_terms, 0),
            lambda: sp.Eq(r_terms, sp.expand(pivot_power()) + sign_r * epsilon * m * g * r),
        ),
        Claim(
            "n8.energy_decreases",
            "n°8",
            "What is left once the terms in r cancel (n8.energy_r_terms) is negative: d/dt(T − ½mk²r²) = "
            "−mg(fV + δΩ) < 0.  With the pivot's d/dt(½mk²r²) = −εmg|r| ≤ 0, the energy T itself decreases while "
            "the ball slides.",
            r"Le second membre est essentiellement négatif",
            sp.Lt(T_rest, 0),
            lambda: sp.Eq(T_rest, sp.expand(relations()["T'"] - pivot_power())),
            display=lambda: sp.Eq(T_rest, sp.Mul(-m * g, f * V + delta * Omega, evaluate=False)),
        ),
        Claim(
            "n8.energy_all_phases",
            "n°8",
            "In pure rolling too (n°7: V = 0, θ = π/2): the same relation with V = 0, d/dt(T − ½mk²r²) = −mgδΩ.",
            r"et cela dans toutes les phases du mouvement",
            sp.Eq(T_rest, -m * g * delta * Omega),
            lambda: sp.Eq(T_rest, sp.expand(relations()["T' rolling"] - pivot_power())),
            display=rolling_energy_rate,
            reading=rolling_energy_rate,
        ),
        Claim(
            "n8.product_rate",
            "n°8",
            "The relation for d/dt[ΩV cos(β − α)].",
            r"\frac{d}{dt} [\Omega V \cos(\beta - \alpha)] = \Omega V \cos(\beta - \alpha) \left[ -\frac{f g \left(1 + \frac{R^2}{k^2}\right)}{V} - \frac{\partial g}{\Omega k^2} \right].",
            sp.Eq(
                PRODUCT_RATE,
                Omega * V * sp.cos(beta - alpha) * (-f * g * ONE_PLUS / V - ocr_partial * g / (Omega * k**2)),
            ),
            lambda: sp.Eq(PRODUCT_RATE, relations()["d/dt[Omega V cos]"].subs(in_ab)),
            display=lambda: sp.Eq(
                PRODUCT_RATE,
                Omega * V * sp.cos(beta - alpha) * (-f * g * (1 + R**2 / k**2) / V - delta * g / (Omega * k**2)),
            ),
            erratum=PARTIAL_FOR_DELTA,
        ),
        Claim(
            "n8.product_decreases",
            "n°8",
            "The coefficient is negative: |ΩV cos(β − α)| decreases.",
            r"Le coefficient du second membre est essentiellement négatif",
            sp.Lt(coeff, 0),
            lambda: sp.Eq(coeff, relations()["coefficient"]),
            display=lambda: sp.Eq(coeff, -f * g * (1 + R**2 / k**2) / V - delta * g / (Omega * k**2)),
        ),
        Claim(
            "n8.opposite_turns",
            "n°8",
            "β' and α' have opposite signs (α'β' ≤ 0, zero only when cos θ = 0).",
            r"en remarquant que $\beta'$ et $\alpha'$ sont de signes contraires",
            sp.Le(sign_product, 0),
            lambda: sp.Eq(sign_product, relations()["alpha' beta'"]),
        ),
        Claim(
            "n8.theta_rate",
            "n°8",
            "The rate of θ = β − α.",
            r"\beta' - \alpha' = \frac{Rg}{k^2} \left( \frac{f}{\Omega} + \frac{\delta}{V} \right) \cos(\beta - \alpha),",
            sp.Eq(d(beta) - d(alpha), R * g / k**2 * (f / Omega + delta / V) * sp.cos(beta - alpha)),
            lambda: sp.Eq(d(beta) - d(alpha), sp.simplify(polar.rates()[d(beta)] - polar.rates()[d(alpha)]).subs(in_ab)),
            display=lambda: sp.Eq(accent(beta) - accent(alpha), display_theta_coefficient() * sp.cos(beta - alpha)),
        ),
        Claim(
            "n8.theta_coefficient",
            "n°8",
            "The coefficient of cos(β − α) is positive.",
            r"où le coefficient de $\cos(\beta - \alpha)$ est positif",
            sp.Gt(theta_coeff, 0),
            lambda: sp.Eq(theta_coeff, sp.cancel(relations()["theta'"] / sp.cos(theta))),
            display=lambda: sp.Eq(theta_coeff, display_theta_coefficient()),
        ),
        Claim(
            "n8.theta_increases",
            "n°8",
            "If θ is positive and acute, it increases.",
            r"si l'angle $\beta - \alpha$ est d'abord positif et aigu, il augmente constamment",
            sp.Gt(theta_rate, 0),
            lambda: sp.Eq(theta_rate, relations()["theta'"]),
            display=lambda: sp.Eq(theta_rate, display_theta_coefficient() * sp.cos(theta)),
            domain={theta: (0, sp.pi / 2)},
            hypothesis={**checks.HYPOTHESIS_9, sp.cos(theta): cos_theta_positive},
        ),
        Claim(
            "n8.theta_right_angle",
            "n°8",
            "θ = π/2 solves θ' = 0 (θ' is cos θ times a coefficient, n8.theta_rate), so θ reaches π/2 only as "
            "V → 0: near the end of sliding π/2 − θ ∝ V^κ (measured by n8.end_exponent_mpmath) with "
            "κ = Rδ/(f(R²+k²) − Rδ) = b/(a − b) > 0, the verdict below.  ‘Becomes right in a finite time’ holds in "
            "this sense: at the end of sliding.  Not before: ln|tan(θ/2 + π/4)| changes at the rate "
            "(Rg/k²)(f/Ω + δ/V) (n8.spin_zero_straight_only, checked), finite while V and Ω are positive, so "
            "tan(θ/2 + π/4) stays finite and θ ≠ π/2 over any time in which V and Ω stay away from 0 (that a finite "
            "rate integrates to a finite change is calculus, not machine-checked); Ω reaches 0 before V only on "
            "the straight draw (the same claim).",
            r"devient droit en un temps fini",
            sp.Gt(kappa, 0),
            lambda: sp.Eq(kappa, relations()["kappa"]),
            display=lambda: sp.Eq(kappa, R * delta / (f * (R**2 + k**2) - R * delta)),
        ),
        Claim(
            "n8.spin_leaves_zero",
            "n°8",
            "Where Ω reaches 0 before V it leaves 0 at once: from Ω = 0 the rotation can only leave along a "
            "direction β where its rate is radial (Ωβ' = fRg cos θ/k² = 0, θ = ±π/2) and outward; Ω' = "
            "(fR − δ)g/k² > 0 at θ = π/2 by (9), −(fR + δ)g/k² < 0 at θ = −π/2: it leaves along β = α + π/2 (n°6).",
            r"immédiatement après $\Omega$ cesse d'être nul, d'après le cas particulier du n° 6",
            [sp.Gt(leave[0], 0), sp.Lt(leave[1], 0)],
            lambda: [sp.Eq(x, value) for x, value in zip(leave, spin_near_zero()["Omega' at theta"], strict=True)],
            # The values the statement gives, pinned (a mutation audit: the signs alone held with −π/2 made −π/3).
            display=lambda: [sp.Eq(leave[0], (f * R - delta) * g / k**2), sp.Eq(leave[1], -(f * R + delta) * g / k**2)],
        ),
        Claim(
            "n8.spin_rate",
            "beyond n°8: Ω reaching zero before V",
            "(8) is singular at Ω = 0 only through the angle β: in Cartesian (p, q) the rotation's rate (4) is the "
            "sliding friction's (fRg/k²) e_{α+π/2}, fixed while V > 0, minus the rolling couple's (δg/k²) e_β, "
            "whose direction jumps by π where Ω passes through zero.",
            None,
            [
                sp.Eq(d(p), f * R * g / k**2 * sp.cos(alpha + sp.pi / 2) - delta * g / k**2 * sp.cos(beta)),
                sp.Eq(d(q), f * R * g / k**2 * sp.sin(alpha + sp.pi / 2) - delta * g / k**2 * sp.sin(beta)),
            ],
            lambda: [sp.Eq(x, value) for x, value in zip((d(p), d(q)), spin_near_zero()["p', q'"], strict=True)],
        ),
        Claim(
            "n8.spin_rate_bounds",
            "beyond n°8: Ω reaching zero before V",
            "The rotation's rate stays between (fR − δ)g/k² and (fR + δ)g/k² in size, whatever θ: bounded "
            "(so |Ω'| ≤ (fR + δ)g/k² even where β is undefined) and, under (9), never zero.",
            None,
            [sp.Le(spin_rate_2, ((f * R + delta) * g / k**2) ** 2), sp.Ge(spin_rate_2, ((f * R - delta) * g / k**2) ** 2)],
            lambda: [sp.Eq(spin_rate_2, spin_near_zero()["|p', q'|^2"])] * 2,
            bounded={sp.sin(theta): (-1, 1)},
        ),
        Claim(
            "n8.spin_zero_straight_only",
            "beyond n°8: Ω reaching zero before V",
            "ln|tan(θ/2 + π/4)| grows at the rate (Rg/k²)(f/Ω + δ/V) > 0.  If Ω reached 0 at t* with V > 0, "
            "Ω ≤ (fR + δ)g(t* − t)/k² (n8.spin_rate_bounds) would make ∫dt/Ω, hence |tan(θ/2 + π/4)|, unbounded: "
            "θ → π/2, where Ω' → (fR − δ)g/k² > 0 (n8.spin_leaves_zero), a contradiction.  So Ω reaches 0 before V "
            "only on the straight draw θ ≡ −π/2 (tan(θ/2 + π/4) ≡ 0); a curved slide can only pass near it "
            "(measured by n8.spin_near_zero_mpmath).  The verdict below is the rate's; that ∫dt/(t* − t) diverges "
            "is calculus, not machine-checked.",
            None,
            sp.Eq(log_tan_rate, R * g / k**2 * (f / Omega + delta / V)),
            lambda: sp.Eq(log_tan_rate, spin_near_zero()["d/dt ln tan"]),
            display=lambda: sp.Eq(log_tan_rate, display_theta_coefficient()),
            domain={theta: (-sp.pi / 2, sp.pi / 2)},
        ),
        Claim(
            "n8.final_rest",
            "n°8",
            "Once V = 0 and Ω = 0 the centre stays at rest (the ball may still pivot): with ξ'' = η'' = p' = q' = 0, (4) leaves no friction "
            "force and no rolling couple — the loads of repose f₁ = 0 ≤ f and δ₁ = 0 ≤ δ, admissible — and by (2) "
            "the centre does not move.  Only the pivot r goes on, by (5), on its own.",
            r"jusqu'au moment où la bille s'arrête",
            [
                sp.Eq(f_1, 0),
                sp.Eq(delta_1, 0),
                sp.Eq(d(xi), 0),
                sp.Eq(d(eta), 0),
                sp.Eq(d(r), -sign_r * epsilon * g / k**2),
            ],
            lambda: [
                sp.Eq(f_1, rest()["f_1"]),
                sp.Eq(delta_1, rest()["delta_1"]),
                sp.Eq(d(xi), rest()["xi'"]),
                sp.Eq(d(eta), rest()["eta'"]),
                sp.Eq(d(r), rest()["r'"]),
            ],
        ),
        Claim(
            "n8.theta_reason",
            "n°8",
            "The bound invoked is V < V₀ − fgt, from V' < −fg (n8.V_decreases; a glyph record: the meant "
            "V < V₀ − fgt is typed, not derived).",
            r"parce que $U < V_0 - fgt$",
            sp.Eq(reason, ocr_U - (V_0 - f * g * t)),
            lambda: sp.Eq(reason, V - (V_0 - f * g * t)),
            erratum=Erratum("ocr", "U read for V", glyphs={ocr_U: V}),
            glyph_only=True,
        ),
    ]
