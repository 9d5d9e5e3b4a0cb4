"""n°10: the special case a = c, integrable in closed form — and why it is not the billiard's.

With a = c, (12) gives y − x = A; (14) separates and
x(x + A) = C / (cos θ tan^h(θ/2 + π/4)), h = a/b.  Physically a = c means
δ = f√(R² + k²), i.e. δ/(fR) = √(1 + k²/R²) > 1: it contradicts (9).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import checks
from derivation.symbols import R, delta, f, k, label, t, theta
from reduction import n9_reduced_system
from reduction.variables import A, C, a, b, c, claim, h, x, y

SPECIAL = {c: a}
X = sp.Symbol("x", positive=True)  # x as a function of θ, sampled as a number


@lru_cache(maxsize=None)
def special_case() -> dict[str, sp.Expr]:
    red = n9_reduced_system.reduced_rates()
    on_integral = {y: x + A}
    dx_dtheta = red["dx/dtheta"].subs(SPECIAL).subs(on_integral).subs(a, h * b)
    # The printed closed form, solved for its constant: K(x, θ) = C.
    K = x * (x + A) * sp.cos(theta) * sp.tan(theta / 2 + sp.pi / 4) ** h
    return {
        "d(y - x)/dt": (red["y'"] - red["x'"]).subs(SPECIAL),
        "dx/dtheta": dx_dtheta,
        "separated": sp.simplify((2 * x + A) / (x * (x + A)) * dx_dtheta),
        "K": K,
        "dK/dtheta": sp.diff(K.subs(x, X), theta) + sp.diff(K.subs(x, X), X) * dx_dtheta.subs(x, X),
    }


@lru_cache(maxsize=None)
def recovery() -> dict[str, sp.Expr]:
    """x and y from y − x = A and xy = x(x + A), the closed form solved for it (n°10's last sentence).

    Both are positive in the motion (x = fV, y = δΩ), so xy > 0: the two roots have x + y = ±√(A² + 4xy),
    and only the one with x + y > 0 can be the motion.
    """
    product = sp.cancel(C * x * (x + A) / special_case()["K"])  # xy = C/(cos θ tan^h(θ/2 + π/4))
    xy = sp.Symbol("xy", positive=True)
    roots = sp.solve([y - x - A, x * y - xy], [x, y], dict=True)
    (motion,) = [root for root in roots if (root[x] + root[y]).is_positive]
    (other,) = [root for root in roots if root is not motion]
    return {
        "xy": product,
        "x": motion[x].subs(xy, product),
        "y": motion[y].subs(xy, product),
        "x1 x2": sp.expand(motion[x] * other[x]).subs(xy, product),
        "y1 y2": sp.expand(motion[y] * other[y]).subs(xy, product),
    }


@lru_cache(maxsize=None)
def physical_meaning() -> dict[str, sp.Expr]:
    """a = c in the ball's parameters."""
    values = n9_reduced_system.constants()
    (delta_special,) = sp.solve(sp.Eq(values[a], values[c]), delta)
    ratio = sp.simplify(delta_special / (f * R))
    return {"delta": delta_special, "delta/(fR)": ratio, "squared excess": sp.simplify(ratio**2 - 1)}


def constant_of(rate: sp.Expr, var: sp.Symbol) -> sp.Expr:
    """∫ rate d(var) from 0: exactly 0 when the rate is identically zero (proved), else ValueError, which
    fails the claim at once.  (Left as an unevaluated integral, a wrong K ran the checks' quadrature past
    900 s: a mutation audit.)"""
    if checks.exact_zero(rate):
        return sp.Integer(0)
    raise ValueError(f"the rate in {var} of what should be constant does not reduce to 0")


def claims():
    separated = label("(2x + A)/(x(x + A)) dx/dθ", r"\frac{2x + A}{x(x + A)} \frac{dx}{d\theta}")
    ratio = label("δ/(fR) when a = c", r"\left.\frac{\delta}{fR}\right|_{a = c}")
    excess = label("(δ/(fR))² − 1 when a = c", r"\left.\frac{\delta^2}{f^2R^2}\right|_{a = c} - 1")
    closed = C / (sp.cos(theta) * sp.tan(theta / 2 + sp.pi / 4) ** h)  # xy, the printed closed form
    root_products = [label("x₁x₂, the product of the two roots' x", r"x_1 x_2"), label("y₁y₂, the product of the two roots' y", r"y_1 y_2")]
    # On the motion's side, |θ| < π/2 (θ' ∝ cos θ keeps it there): cos θ > 0 and tan(θ/2 + π/4) > 0.
    tan_h = sp.tan(theta / 2 + sp.pi / 4) ** h  # written so in the displays (SymPy prints tan^(−h) upstairs)
    positive_side = {sp.cos(theta): sp.Symbol("c_theta", positive=True), sp.tan(theta / 2 + sp.pi / 4): sp.Symbol("t_theta", positive=True)}

    def recovered():  # x and y with tan^h downstairs, as the paper writes the closed form
        return [
            sp.Eq(x, (sp.sqrt(A**2 + 4 * C / (sp.cos(theta) * tan_h)) - A) / 2),
            sp.Eq(y, (sp.sqrt(A**2 + 4 * C / (sp.cos(theta) * tan_h)) + A) / 2),
        ]

    return [
        claim(
            "n10.integral",
            "n°10",
            "With a = c, y − x is constant: its rate from (12) vanishes, so y − x keeps its value A.",
            r"y - x = A,",
            sp.Eq(y - x, A),
            lambda: sp.Eq(y - x, A + constant_of(special_case()["d(y - x)/dt"], t)),
        ),
        claim(
            "n10.separated",
            "n°10",
            "(14) with y = x + A separates.",
            r"\frac{2x + A}{x(x + A)} dx = \left( \operatorname{tang} \theta - \frac{h}{\cos \theta} \right) d\theta,",
            sp.Eq(separated, sp.tan(theta) - h / sp.cos(theta)),
            lambda: sp.Eq(separated, special_case()["separated"]),
        ),
        claim(
            "n10.closed_form",
            "n°10",
            "The closed form, checked by differentiation: Φ = x(x + A) cos θ tan^h(θ/2 + π/4) has dΦ/dθ ≡ 0 "
            "along (14), so Φ keeps its value C.",
            r"x(x + A) = \frac{C}{\cos \theta \left[ \tan \left( \frac{\theta}{2} + \frac{\pi}{4} \right) \right]^h}.",
            sp.Eq(X * (X + A), C / (sp.cos(theta) * sp.tan(theta / 2 + sp.pi / 4) ** h)),
            lambda: sp.Eq(
                X * (X + A),
                (C + constant_of(special_case()["dK/dtheta"], theta)) / (sp.cos(theta) * sp.tan(theta / 2 + sp.pi / 4) ** h),
            ),
            display=lambda: sp.Eq(X * (X + A), C / (sp.cos(theta) * tan_h)),
            domain={theta: (-sp.pi / 2, sp.pi / 2)},
        ),
        claim(
            "n10.recovery",
            "n°10",
            "x and y from y − x = A and xy = C/(cos θ tan^h(θ/2 + π/4)): the roots of a quadratic, the one with "
            "x + y = √(A² + 4xy) > 0.",
            r"et l'on peut calculer $x$ et $y$ en fonction de $\theta$",
            [sp.Eq(x, (sp.sqrt(A**2 + 4 * closed) - A) / 2), sp.Eq(y, (sp.sqrt(A**2 + 4 * closed) + A) / 2)],
            lambda: [sp.Eq(x, recovery()["x"]), sp.Eq(y, recovery()["y"])],
            display=recovered,
            reading=recovered,
            domain={theta: (-sp.pi / 2, sp.pi / 2)},
        ),
        claim(
            "n10.recovery_unique",
            "n°10",
            "The recovery is unique: the two roots' x multiply to −xy < 0, and so do their y, so exactly one root has "
            "x = fV > 0 and exactly one has y = δΩ > 0 — the same one, x + y > 0.",
            r"On a ainsi $y - x$ et $yx$",
            [sp.Lt(lhs, 0) for lhs in root_products],
            lambda: [sp.Eq(lhs, recovery()[key]) for lhs, key in zip(root_products, ("x1 x2", "y1 y2"), strict=True)],
            display=lambda: [sp.Eq(lhs, -C / (sp.cos(theta) * tan_h)) for lhs in root_products],
            domain={theta: (-sp.pi / 2, sp.pi / 2)},
            hypothesis=positive_side,
        ),
        claim(
            "n10.physical",
            "n°10 (beyond the paper)",
            "a = c means δ = f√(R² + k²): δ/(fR) = √(1 + k²/R²) (√(7/5) ≈ 1.18 for a solid ball).",
            r"si $a = c$",
            sp.Eq(ratio, sp.sqrt(1 + k**2 / R**2)),
            lambda: sp.Eq(ratio, physical_meaning()["delta/(fR)"]),
        ),
        claim(
            "n10.violates_9",
            "n°10 (beyond the paper)",
            "So a = c needs δ > fR: it contradicts (9); Appell's ‘point de vue purement analytique’.",
            r"En se plaçant au point de vue purement analytique, on a une intégration immédiate, si $a = c$",
            sp.Gt(excess, 0),
            lambda: sp.Eq(excess, physical_meaning()["squared excess"]),
            hypothesis={},
            display=lambda: sp.Eq(excess, k**2 / R**2),  # its value, pinned (the sign alone held with − 1/2 for − 1)
        ),
    ]

