"""Beyond the paper: straight shots, where β − α = ±π/2 stays fixed, in closed form.

θ' = (Rg/k²)(f/Ω + δ/V) cos θ vanishes at θ = ±π/2, so a shot whose spin is
square to its slip keeps it so (n°8).  With θ = +π/2 (follow, stun, and the
centre-ball hit of n°6, where Ω leaves zero along β = α + π/2) V and Ω are
linear in t; with θ = −π/2 (draw) both decrease, and if Ω reaches zero
first, it comes back along β = α + π/2 (n°6) and the shot continues with
θ = +π/2.  The slip direction α is fixed throughout, and the centre moves
along it with speed V ± RΩ.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler, polar
from derivation.claim import Claim
from derivation.symbols import Omega, Omega_0, R, V, V_0, alpha, beta, d, delta, eta, f, g, k, label, p, q, t, theta, u, v, xi

FOLLOW, DRAW = sp.pi / 2, -sp.pi / 2


@lru_cache(maxsize=None)
def straight(side: sp.Expr) -> dict[str, sp.Expr]:
    """θ ≡ side (±π/2): the rates, V(t), Ω(t), and the centre's speed along the slip."""
    rates = polar.rates()
    at = {theta: side}
    V_rate, Omega_rate = rates[d(V)].subs(at), rates[d(Omega)].subs(at)
    centre = newton_euler.centre_velocity()
    # Spin square to the slip: β = α + θ.
    along = {u: V * sp.cos(alpha), v: V * sp.sin(alpha), p: Omega * sp.cos(alpha + side), q: Omega * sp.sin(alpha + side)}
    velocity = sp.Matrix([centre[d(xi)], centre[d(eta)]]).subs(along)
    return {
        "theta'": sp.simplify(polar.theta_rate().subs(at)),
        "alpha'": rates[d(alpha)].subs(at),
        "beta'": rates[d(beta)].subs(at),
        "V'": V_rate,
        "Omega'": Omega_rate,
        "V": V_0 + V_rate * t,
        "Omega": Omega_0 + Omega_rate * t,
        "centre speed": sp.simplify(velocity.dot(sp.Matrix([sp.cos(alpha), sp.sin(alpha)]))),
        "centre sideways": sp.simplify(velocity.dot(sp.Matrix([-sp.sin(alpha), sp.cos(alpha)]))),
    }


def rate_label(name: str, side: str) -> sp.Symbol:
    """The label of θ', α' or β' on the straight shot θ = ±π/2."""
    return label(f"{name}' at θ = {side}π/2", rf"\left.\{name}'\right|_{{\theta = {side}\pi/2}}")


def claims() -> list[Claim]:
    lab = {
        name: label(name, tex)
        for name, tex in (
            ("centre speed along the slip", r"\dot{\mathbf{G}} \cdot \mathbf{e}_\alpha"),
            ("centre speed across the slip", r"\dot{\mathbf{G}} \cdot \mathbf{e}_\alpha^\perp"),
        )
    }
    one_plus = 1 + R**2 / k**2
    return [
        Claim(
            "straight.invariant",
            "beyond n°8: straight shots",
            "θ = ±π/2 is invariant: θ' = 0 there, and α' = β' = 0 (the slip and the spin keep their directions).",
            None,
            [sp.Eq(rate_label(name, side), 0) for side in ("+", "-") for name in ("theta", "alpha", "beta")],
            lambda: [
                sp.Eq(rate_label(name, side), shot[f"{name}'"])
                for side, shot in (("+", straight(FOLLOW)), ("-", straight(DRAW)))
                for name in ("theta", "alpha", "beta")
            ],
        ),
        Claim(
            "straight.follow",
            "beyond n°8: straight shots",
            "θ = π/2 (follow, stun, centre-ball hit): V and Ω linear, the slide ends at V₀/(fg(1 + R²/k²) − Rδg/k²).",
            None,
            [sp.Eq(V, V_0 - (f * one_plus - R * delta / k**2) * g * t), sp.Eq(Omega, Omega_0 + (f * R - delta) * g / k**2 * t)],
            lambda: [sp.Eq(V, straight(FOLLOW)["V"]), sp.Eq(Omega, straight(FOLLOW)["Omega"])],
            display=lambda: [
                sp.Eq(V, V_0 - (f * g * (1 + R**2 / k**2) - (R * delta / k**2) * g) * t),
                sp.Eq(Omega, Omega_0 + ((f * R - delta) / k**2) * g * t),
            ],
        ),
        Claim(
            "straight.draw",
            "beyond n°8: straight shots",
            "θ = −π/2 (draw): V and Ω both decrease linearly; if Ω reaches 0 first it returns along β = α + π/2 "
            "and the follow law takes over.",
            None,
            [sp.Eq(V, V_0 - (f * one_plus + R * delta / k**2) * g * t), sp.Eq(Omega, Omega_0 - (f * R + delta) * g / k**2 * t)],
            lambda: [sp.Eq(V, straight(DRAW)["V"]), sp.Eq(Omega, straight(DRAW)["Omega"])],
            display=lambda: [
                sp.Eq(V, V_0 - (f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g) * t),
                sp.Eq(Omega, Omega_0 - ((f * R + delta) / k**2) * g * t),
            ],
        ),
        Claim(
            "straight.centre",
            "beyond n°8: straight shots",
            "The centre moves along the slip direction with speed V + RΩ (follow) or V − RΩ (draw), nothing across.",
            None,
            [
                sp.Eq(lab["centre speed along the slip"], V + R * Omega),
                sp.Eq(lab["centre speed across the slip"], 0),
                sp.Eq(lab["centre speed along the slip"], V - R * Omega),
                sp.Eq(lab["centre speed across the slip"], 0),
            ],
            lambda: [
                sp.Eq(lab["centre speed along the slip"], straight(FOLLOW)["centre speed"]),
                sp.Eq(lab["centre speed across the slip"], straight(FOLLOW)["centre sideways"]),
                sp.Eq(lab["centre speed along the slip"], straight(DRAW)["centre speed"]),
                sp.Eq(lab["centre speed across the slip"], straight(DRAW)["centre sideways"]),
            ],
        ),
    ]
