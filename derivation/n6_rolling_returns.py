"""n°6: sliding without rolling is impossible when δ < fR.

Suppose Ω stays 0 while V ≠ 0.  The rolling couple is then a couple of
"repose", of magnitude δ₁ m g with δ₁ ≤ δ and some direction β.  Both
components of (8) must vanish, with δ replaced by δ₁; the first forces
θ = π/2 or 3π/2, and at neither can the second vanish.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import polar
from derivation.claim import Claim
from derivation.symbols import R, alpha, beta, delta, delta_1, f, g, k, label, theta

AT_REST = {delta: delta_1}  # the couple of repose, δ₁ ≤ δ


@lru_cache(maxsize=None)
def conditions() -> dict[str, object]:
    """The two conditions from (8) with Ω ≡ 0, and where the first one holds."""
    ro = polar.rolling()
    # Ω ≡ 0: both Ω' and Ω β' vanish; divide by the positive factors R f g/k², g/k².
    first = sp.simplify(ro["Omega beta'"].subs(AT_REST) * k**2 / (R * f * g))
    second = sp.expand(ro["Omega'"].subs(AT_REST) * k**2 / g)
    roots = sorted(sp.solveset(first, theta, sp.Interval.Ropen(0, 2 * sp.pi)), key=float)
    return {"first": first, "second": second, "roots": roots, "second at roots": [second.subs(theta, x) for x in roots]}


def claims() -> list[Claim]:
    in_ab = {theta: beta - alpha}
    roots = [label("θ₁, the first root of cos θ in [0, 2π)", r"\theta_1"), label("θ₂, the second root of cos θ in [0, 2π)", r"\theta_2")]
    at_root = [label("fR sin θ − δ₁ at θ = π/2", r"\left. fR \sin\theta - \delta_1 \right|_{\theta = \pi/2}"), label("fR sin θ − δ₁ at θ = 3π/2", r"\left. fR \sin\theta - \delta_1 \right|_{\theta = 3\pi/2}")]
    return [
        Claim(
            "n6.conditions",
            "n°6",
            "Sliding without rolling (Ω ≡ 0) would require both components of (8) to vanish, δ replaced by δ₁.",
            r"\begin{aligned} \cos(\beta - \alpha) &= 0, \\ fR \sin(\beta - \alpha) - \delta_1 &= 0. \end{aligned}",
            [sp.Eq(sp.cos(beta - alpha), 0), sp.Eq(f * R * sp.sin(beta - alpha) - delta_1, 0)],
            lambda: [sp.Eq(conditions()["first"].subs(in_ab), 0), sp.Eq(conditions()["second"].subs(in_ab), 0)],
        ),
        Claim(
            "n6.roots",
            "n°6",
            "The first condition leaves θ = π/2 or 3π/2.",
            r"La première donne $\beta - \alpha = \frac{\pi}{2}$ ou $\frac{3\pi}{2}$",
            [sp.Eq(roots[0], sp.pi / 2), sp.Eq(roots[1], 3 * sp.pi / 2)],
            lambda: [sp.Eq(x, value) for x, value in zip(roots, conditions()["roots"], strict=True)],
        ),
        Claim(
            "n6.impossible",
            "n°6",
            "At θ = π/2 the second condition is fR − δ₁ > 0 (δ₁ ≤ δ < fR); at 3π/2 both terms are negative: "
            "sliding without rolling is impossible.",
            r"Donc le mouvement supposé, glissement sans roulement, est impossible",
            [sp.Gt(at_root[0], 0), sp.Lt(at_root[1], 0)],
            lambda: [sp.Eq(x, value) for x, value in zip(at_root, conditions()["second at roots"], strict=True)],
            bounded={delta_1: (0, delta)},
        ),
    ]
