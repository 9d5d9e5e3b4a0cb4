"""Beyond the paper: straight shots, where β − α = ±π/2 stays fixed, in closed form.

θ' = (Rg/k²)(f/Ω + δ/V) cos θ vanishes at θ = ±π/2, so a shot whose spin is
square to its slip keeps it so (n°8).  The spin moves the contact point by
RΩ, against the slip at θ = +π/2 and along it at θ = −π/2.  With θ = +π/2
(less top spin than rolling: the centre-ball hit of n°6, where Ω leaves zero
along β = α + π/2, a follow short of rolling, a draw whose back spin has
reversed) V and Ω are linear in t; with θ = −π/2 (a draw's back spin, or a
follow with more top spin than rolling, whose slip points backward) both
decrease, and if Ω reaches zero first, it comes back along β = α + π/2 (n°6)
and the shot continues with θ = +π/2.  The slip direction α is fixed
throughout, and the centre moves along it at V + RΩ (θ = +π/2) or V − RΩ
(θ = −π/2).  (An audit: these were called follow and draw, and a follow
with more top spin than rolling is θ = −π/2.)
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler, polar
from derivation.claim import Claim
from derivation.symbols import Omega, Omega_0, R, V, V_0, alpha, beta, d, delta, eta, f, g, k, label, p, q, t, theta, u, v, xi

PLUS, MINUS = sp.pi / 2, -sp.pi / 2  # θ, the spin against / along the slip at the contact


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
        (name, side): label(f"{name} at θ = {side}π/2", rf"\left.{tex}\right|_{{\theta = {side}\pi/2}}")
        for name, tex in (
            ("centre speed along the slip", r"\dot{\mathbf{G}} \cdot \mathbf{e}_\alpha"),
            ("centre speed across the slip", r"\dot{\mathbf{G}} \cdot \mathbf{e}_\alpha^\perp"),
        )
        for side in ("+", "-")
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
                for side, shot in (("+", straight(PLUS)), ("-", straight(MINUS)))
                for name in ("theta", "alpha", "beta")
            ],
        ),
        Claim(
            "straight.theta_plus",
            "beyond n°8: straight shots",
            "θ = π/2, the spin moving the contact point against the slip (less top spin than rolling: a centre-ball "
            "hit, a follow short of rolling, a draw whose back spin has reversed): V and Ω linear, the slide ends at "
            "V₀/(fg(1 + R²/k²) − Rδg/k²).",
            None,
            [sp.Eq(V, V_0 - (f * one_plus - R * delta / k**2) * g * t), sp.Eq(Omega, Omega_0 + (f * R - delta) * g / k**2 * t)],
            lambda: [sp.Eq(V, straight(PLUS)["V"]), sp.Eq(Omega, straight(PLUS)["Omega"])],
            display=lambda: [
                sp.Eq(V, V_0 - (f * g * (1 + R**2 / k**2) - (R * delta / k**2) * g) * t),
                sp.Eq(Omega, Omega_0 + ((f * R - delta) / k**2) * g * t),
            ],
        ),
        Claim(
            "straight.theta_minus",
            "beyond n°8: straight shots",
            "θ = −π/2, the spin moving the contact point along the slip (back spin, as in a draw, or a follow with "
            "more top spin than rolling, whose slip points backward): V and Ω both decrease linearly; if Ω reaches 0 "
            "first it returns along β = α + π/2 and the law of θ = π/2 takes over.",
            None,
            [sp.Eq(V, V_0 - (f * one_plus + R * delta / k**2) * g * t), sp.Eq(Omega, Omega_0 - (f * R + delta) * g / k**2 * t)],
            lambda: [sp.Eq(V, straight(MINUS)["V"]), sp.Eq(Omega, straight(MINUS)["Omega"])],
            display=lambda: [
                sp.Eq(V, V_0 - (f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g) * t),
                sp.Eq(Omega, Omega_0 - ((f * R + delta) / k**2) * g * t),
            ],
        ),
        Claim(
            "straight.centre",
            "beyond n°8: straight shots",
            "The centre moves along the slip's direction e_α, nothing across it (e_α^⊥, e_α turned by +π/2): at "
            "V + RΩ for θ = π/2, at V − RΩ for θ = −π/2 (negative, against the slip, for a follow with more top spin "
            "than rolling).",
            None,
            [
                sp.Eq(lab["centre speed along the slip", "+"], V + R * Omega),
                sp.Eq(lab["centre speed across the slip", "+"], 0),
                sp.Eq(lab["centre speed along the slip", "-"], V - R * Omega),
                sp.Eq(lab["centre speed across the slip", "-"], 0),
            ],
            lambda: [
                sp.Eq(lab["centre speed along the slip", "+"], straight(PLUS)["centre speed"]),
                sp.Eq(lab["centre speed across the slip", "+"], straight(PLUS)["centre sideways"]),
                sp.Eq(lab["centre speed along the slip", "-"], straight(MINUS)["centre speed"]),
                sp.Eq(lab["centre speed across the slip", "-"], straight(MINUS)["centre sideways"]),
            ],
        ),
    ]
