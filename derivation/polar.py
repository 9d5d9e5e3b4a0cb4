"""n°2, eqs. (7)–(8): the motion in the polar variables V, α (sliding) and Ω, β (rolling).

(7) comes from (6) by writing u = V cos α, v = V sin α and solving the two
differentiated equations for V' and α'; (8) comes the same way from the
rotational equations (4) with p = Ω cos β, q = Ω sin β (eq. (3)).
Every right-hand side is finally written with θ = β − α (n°9), the only
angle the magnitudes depend on.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler
from derivation.symbols import Omega, V, alpha, beta, d, p, q, t, theta


def in_theta(expr: sp.Expr) -> sp.Expr:
    """Write sines and cosines of α and β through θ = β − α where they combine."""
    expanded = sp.expand(sp.expand_trig(expr))
    in_beta = expanded.subs(beta, theta + alpha)
    return sp.simplify(sp.expand(sp.expand_trig(in_beta)))


def _polar_rates(x_dot, y_dot, radius, angle):
    """Solve d/dt(ρ cos φ) = x', d/dt(ρ sin φ) = y' for ρ' and ρφ'."""
    eqs = [
        sp.Eq(sp.diff(radius * sp.cos(angle), t), x_dot),
        sp.Eq(sp.diff(radius * sp.sin(angle), t), y_dot),
    ]
    sol = sp.solve(eqs, [d(radius), d(angle)], dict=True)[0]
    return {"rate": sp.simplify(sol[d(radius)]), "turn": sp.simplify(radius * sol[d(angle)]), "equations": eqs}


@lru_cache(maxsize=None)
def sliding() -> dict[str, object]:
    """Eq. (7): V' and V α' from (6)."""
    acc = newton_euler.contact_acceleration()
    rates = _polar_rates(acc["u' (6)"], acc["v' (6)"], V, alpha)
    return {
        "equations": rates["equations"],
        "V'": in_theta(rates["rate"]),
        "V alpha'": in_theta(rates["turn"]),
    }


@lru_cache(maxsize=None)
def rolling() -> dict[str, object]:
    """Eq. (8): Ω' and Ω β' from the rotational equations (4)."""
    acc = newton_euler.accelerations()
    rates = _polar_rates(acc[d(p)], acc[d(q)], Omega, beta)
    return {
        "equations": rates["equations"],
        "Omega'": in_theta(rates["rate"]),
        "Omega beta'": in_theta(rates["turn"]),
    }


def rates() -> dict[sp.Expr, sp.Expr]:
    """V', α', Ω', β' as functions of (V, Ω, θ): the right-hand side of (7)–(8)."""
    s, r = sliding(), rolling()
    return {
        d(V): s["V'"],
        d(alpha): sp.cancel(s["V alpha'"] / V),
        d(Omega): r["Omega'"],
        d(beta): sp.cancel(r["Omega beta'"] / Omega),
    }


def theta_rate() -> sp.Expr:
    """θ' = β' − α' (n°8, last relation)."""
    rate = rates()
    return sp.simplify(rate[d(beta)] - rate[d(alpha)])
