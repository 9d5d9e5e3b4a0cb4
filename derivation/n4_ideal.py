"""n°4: the ideal case f = 0 (no sliding friction), in closed form.

With f = 0, (8) gives β' = 0: the rotation keeps its direction, taken as
O-ξ (β = 0).  Ω decreases linearly; (6) gives u constant and v linear; the
terms in δ cancel in the centre's velocity, which is constant.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler, polar
from derivation.claim import Claim
from derivation.symbols import (
    V_0,
    Omega,
    Omega_0,
    R,
    alpha_0,
    beta,
    d,
    delta,
    eta,
    f,
    g,
    k,
    label,
    p,
    q,
    t,
    u,
    v,
    xi,
)

IDEAL = {f: 0}
ALONG_XI = {beta: 0}  # "en prenant Oξ parallèle à Ω"


@lru_cache(maxsize=None)
def motion() -> dict[str, sp.Expr]:
    """β, Ω, u, v, ξ', η' as functions of t, for f = 0 and β₀ = 0."""
    rates = polar.rates()
    contact = newton_euler.contact_acceleration()
    Omega_of_t = Omega_0 + sp.integrate(rates[d(Omega)].subs(IDEAL), (t, 0, t))
    u_of_t = V_0 * sp.cos(alpha_0) + sp.integrate(contact["u' (6)"].subs(IDEAL).subs(ALONG_XI), (t, 0, t))
    v_of_t = V_0 * sp.sin(alpha_0) + sp.integrate(contact["v' (6)"].subs(IDEAL).subs(ALONG_XI), (t, 0, t))
    # β = 0 in (3): p = Ω, q = 0.
    rotation = {p: Omega_of_t, q: 0, u: u_of_t, v: v_of_t}
    centre = newton_euler.centre_velocity()
    xi_dot, eta_dot = (sp.expand(centre[x].subs(rotation)) for x in (d(xi), d(eta)))
    return {
        "beta'": rates[d(beta)].subs(IDEAL),
        # β = β₀ + ∫β' dt, with β₀ = 0 by the choice of axes (Oξ along Ω).
        "beta": ALONG_XI[beta] + sp.integrate(rates[d(beta)].subs(IDEAL), (t, 0, t)),
        "Omega": Omega_of_t,
        "t_stop": sp.solve(Omega_of_t, t)[0],
        "u": u_of_t,
        "v": v_of_t,
        "xi'": xi_dot,
        "eta'": eta_dot,
    }


def claims() -> list[Claim]:
    t_stop = label("t at which Ω = 0", r"t_{\Omega=0}")
    return [
        Claim(
            "n4.beta",
            "n°4",
            "Without sliding friction the rotation keeps its direction (β' = 0), which the axes take as Oξ "
            "(β = β₀ = 0).",
            r"\beta' = 0, \quad \beta = 0",
            [sp.Eq(d(beta), 0), sp.Eq(beta, 0)],
            lambda: [sp.Eq(d(beta), motion()["beta'"]), sp.Eq(beta, motion()["beta"])],
        ),
        Claim(
            "n4.Omega",
            "n°4",
            "The rotation decreases linearly and stops in finite time.",
            r"\Omega - \Omega_0 = -\frac{\delta}{k^2} gt",
            sp.Eq(Omega - Omega_0, -delta / k**2 * g * t),
            lambda: sp.Eq(Omega - Omega_0, motion()["Omega"] - Omega_0),
        ),
        Claim(
            "n4.stop_time",
            "n°4",
            "Ω vanishes after the finite time k²Ω₀/(δg).",
            r"$\Omega$ a donc une direction fixe et s'annule au bout d'un temps fini",
            sp.Eq(t_stop, k**2 * Omega_0 / (delta * g)),
            lambda: sp.Eq(t_stop, motion()["t_stop"]),
        ),
        Claim(
            "n4.slip_u",
            "n°4",
            "(6) with f = 0, β = 0: u keeps its value.",
            r"u = V \cos \alpha = V_0 \cos \alpha_0,",
            sp.Eq(u, V_0 * sp.cos(alpha_0)),
            lambda: sp.Eq(u, motion()["u"]),
        ),
        Claim(
            "n4.slip",
            "n°4",
            "(6) with f = 0, β = 0: v changes linearly.",
            r"v = V \sin \alpha = -\frac{R\delta}{k^2} gt + V_0 \sin \alpha_0",
            sp.Eq(v, -R * delta / k**2 * g * t + V_0 * sp.sin(alpha_0)),
            lambda: sp.Eq(v, motion()["v"]),
        ),
        Claim(
            "n4.centre_velocity",
            "n°4",
            "The centre moves uniformly in a straight line (the δ terms cancel).",
            r"\begin{aligned} \xi' &= V_0 \cos \alpha_0, \\ \eta' &= V_0 \sin \alpha_0 - \Omega_0 R, \end{aligned}",
            [sp.Eq(d(xi), V_0 * sp.cos(alpha_0)), sp.Eq(d(eta), V_0 * sp.sin(alpha_0) - Omega_0 * R)],
            lambda: [sp.Eq(d(xi), motion()["xi'"]), sp.Eq(d(eta), motion()["eta'"])],
        ),
    ]
