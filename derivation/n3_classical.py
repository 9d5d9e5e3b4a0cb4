"""n°3: the classical case δ = 0 (no rolling friction), in closed form.

With δ = 0, (7) gives α' = 0: the slip keeps its direction, taken as O-ξ
(α = 0).  V then decreases linearly, p is constant, q grows linearly, and
the centre has a constant acceleration: a parabola, until V = 0.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler, polar
from derivation.claim import Claim, Erratum
from derivation.symbols import (
    V_0,
    Omega,
    Omega_0,
    R,
    V,
    accent,
    alpha,
    beta,
    beta_0,
    d,
    delta,
    eta,
    f,
    f_1,
    g,
    k,
    label,
    p,
    q,
    t,
    u,
    v,
    xi,
    zeta,
)

CLASSICAL = {delta: 0}
ALONG_XI = {alpha: 0}  # "on peut toujours prendre pour direction Oξ"
ZETA_FOR_XI = Erratum("ocr", "ζ read for ξ: ζ' is the vertical velocity, zero here", glyphs={zeta: xi})


@lru_cache(maxsize=None)
def motion() -> dict[str, sp.Expr]:
    """V, p, q, ξ', η' as functions of t while sliding, for δ = 0 and α = 0."""
    rates = polar.rates()
    acc = newton_euler.accelerations()
    V_rate = rates[d(V)].subs(CLASSICAL)
    p_of_t = Omega_0 * sp.cos(beta_0) + sp.integrate(acc[d(p)].subs(CLASSICAL).subs(ALONG_XI), (t, 0, t))
    q_of_t = Omega_0 * sp.sin(beta_0) + sp.integrate(acc[d(q)].subs(CLASSICAL).subs(ALONG_XI), (t, 0, t))
    V_of_t = V_0 + sp.integrate(V_rate, (t, 0, t))
    # α = 0: u = V, v = 0 (eq. (1)).
    centre = newton_euler.centre_velocity()
    slip = {u: V_of_t, v: 0, p: p_of_t, q: q_of_t}
    xi_dot, eta_dot = (sp.expand(centre[x].subs(slip)) for x in (d(xi), d(eta)))
    return {
        "alpha'": rates[d(alpha)].subs(CLASSICAL),
        "V'": V_rate,
        "V": V_of_t,
        "p": p_of_t,
        "q": q_of_t,
        "xi'": xi_dot,
        "eta'": eta_dot,
        "xi''": sp.diff(xi_dot, t),
        "eta''": sp.diff(eta_dot, t),
        "t_slide": sp.solve(V_of_t, t)[0],
    }


@lru_cache(maxsize=None)
def after_slide() -> dict[str, sp.Expr]:
    """n°3's "puis reste nulle": rolling without sliding when δ = 0, as n°7 writes it (V ≡ 0, f₁ for f).

    (7) with V ≡ 0 asks V' = 0 and Vα' = 0; without the rolling couple the second holds for every θ
    and the first gives the friction of repose f₁.  With it, (7) and (8) give the rates that follow.
    """
    sl, ro = polar.sliding(), polar.rolling()
    at_rest = {f: f_1}  # the friction of repose, f₁ ≤ f (n°7)
    (f_1_value,) = sp.solve(sl["V'"].subs(at_rest).subs(CLASSICAL), f_1)
    rolling = {**CLASSICAL, f_1: f_1_value}
    return {
        "f_1": f_1_value,
        "V'": sl["V'"].subs(at_rest).subs(rolling),
        "V alpha'": sl["V alpha'"].subs(at_rest).subs(rolling),
        "Omega'": ro["Omega'"].subs(at_rest).subs(rolling),
        "Omega beta'": ro["Omega beta'"].subs(at_rest).subs(rolling),
    }


def claims() -> list[Claim]:
    t_slide = label("t at which V = 0", r"t_{V=0}")
    return [
        Claim(
            "n3.alpha",
            "n°3",
            "Without rolling friction the slip keeps its direction.",
            r"\alpha' = 0",
            sp.Eq(d(alpha), 0),
            lambda: sp.Eq(d(alpha), motion()["alpha'"]),
        ),
        Claim(
            "n3.V",
            "n°3",
            "The sliding speed decreases linearly.",
            r"V - V_0 = -fgt \left( 1 + \frac{R^2}{k^2} \right)",
            sp.Eq(V - V_0, -f * g * t * (1 + R**2 / k**2)),
            lambda: sp.Eq(V - V_0, motion()["V"] - V_0),
            display=lambda: sp.Eq(V - V_0, -f * g * t * (1 + R**2 / k**2)),
        ),
        Claim(
            "n3.slide_ends",
            "n°3",
            "V vanishes after a finite time, V_0 k²/(fg(R²+k²)).",
            r"elle s'annule au bout d'un temps fini, puis reste nulle",
            sp.Gt(t_slide, 0),
            lambda: sp.Eq(t_slide, motion()["t_slide"]),
            # The value is ours, not the paper's: the display pins it (a sign alone let any positive time pass).
            display=lambda: sp.Eq(t_slide, V_0 * k**2 / (f * g * (R**2 + k**2))),
        ),
        Claim(
            "n3.stays_zero",
            "n°3",
            "Once V = 0 it stays 0: rolling without sliding needs, with δ = 0, the friction of repose f₁ = 0 "
            "(≤ f, whatever θ); then V' = Vα' = 0, so V ≡ 0, and Ω' = Ωβ' = 0: the ball rolls on for ever with "
            "the Ω it had.",
            r"puis reste nulle",
            [
                sp.Eq(f_1, 0),
                sp.Eq(d(V), 0),
                sp.Eq(V * d(alpha), 0),
                sp.Eq(d(Omega), 0),
                sp.Eq(Omega * d(beta), 0),
            ],
            lambda: [
                sp.Eq(f_1, after_slide()["f_1"]),
                sp.Eq(d(V), after_slide()["V'"]),
                sp.Eq(V * d(alpha), after_slide()["V alpha'"]),
                sp.Eq(d(Omega), after_slide()["Omega'"]),
                sp.Eq(Omega * d(beta), after_slide()["Omega beta'"]),
            ],
        ),
        Claim(
            "n3.p",
            "n°3",
            "With Oξ along the slip (α ≡ 0: n°3's axes, the slip keeping its direction), the component p of the "
            "rotation keeps its initial value.",
            r"p = \Omega \cos \beta = \Omega_0 \cos \beta_0",
            sp.Eq(p, Omega_0 * sp.cos(beta_0)),
            lambda: sp.Eq(p, motion()["p"]),
        ),
        Claim(
            "n3.q",
            "n°3",
            "With Oξ along the slip (α ≡ 0, n°3's axes), the component q grows linearly.",
            r"q = \Omega \sin \beta = \frac{fR}{k^2} gt + \Omega_0 \sin \beta_0",
            sp.Eq(q, f * R / k**2 * g * t + Omega_0 * sp.sin(beta_0)),
            lambda: sp.Eq(q, motion()["q"]),
        ),
        Claim(
            "n3.centre_from_slip",
            "n°3",
            "The centre's velocity from (2).",
            r"\zeta' &= u + qR, & \eta' &= v - pR",
            [sp.Eq(d(zeta), u + q * R), sp.Eq(d(eta), v - p * R)],
            lambda: [sp.Eq(x, newton_euler.centre_velocity()[x]) for x in (d(xi), d(eta))],
            erratum=ZETA_FOR_XI,
        ),
        Claim(
            "n3.centre_velocity",
            "n°3",
            "The centre's velocity while sliding, Oξ along the slip (α ≡ 0, n°3's axes).",
            r"\zeta' &= V_0 + R\Omega_0 \sin \beta_0 - fgt, \\ \eta' &= -R\Omega_0 \cos \beta_0",
            [
                sp.Eq(d(zeta), V_0 + R * Omega_0 * sp.sin(beta_0) - f * g * t),
                sp.Eq(d(eta), -R * Omega_0 * sp.cos(beta_0)),
            ],
            lambda: [sp.Eq(d(xi), motion()["xi'"]), sp.Eq(d(eta), motion()["eta'"])],
            erratum=ZETA_FOR_XI,
        ),
        Claim(
            "n3.parabola",
            "n°3",
            "The centre has the constant acceleration fg opposite the slip (along −Oξ, n°3's axes): a parabola (a line "
            "if η' = 0).",
            r"le mouvement parabolique du centre",
            [sp.Eq(d(xi, 2), -f * g), sp.Eq(d(eta, 2), 0)],
            lambda: [sp.Eq(d(xi, 2), motion()["xi''"]), sp.Eq(d(eta, 2), motion()["eta''"])],
        ),
    ]
