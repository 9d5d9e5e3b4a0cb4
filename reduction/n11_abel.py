"""n°11: the reduction of (14) to the Abel equation z' = z³ − z² + λz(1 − z)².

Appell's steps, each derived: the new variable dφ = (tan θ − a/(b cos θ)) dθ
turns (14) into x' = xy/(x + y), y' = λ xy/(x + y); eliminating y gives
x²x'' = x'³ + λx'(x − x')²; and x = exp ∫ z dφ gives the Abel equation.
Beyond the paper: λ = (b sin θ − c)/(b sin θ − a), z = y/(x + y) ∈ (0, 1),
and the right-hand side factors as z(z − 1)((1 + λ)z − λ).  Written in θ,
the equation is the `Abel` object the invariants are computed from.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation.symbols import R, accent, delta, f, k, label, theta
from reduction import n9_reduced_system
from reduction.abel import Abel
from reduction.variables import a, b, c, claim, lam, phi, x, y, z

# Functions of φ; their accents are d/dφ, as in n°11.
X = sp.Function("x", positive=True)(phi)
Y = sp.Function("y", positive=True)(phi)
Lam = sp.Function("lambda", real=True)(phi)
Z = sp.Function("z", positive=True)(phi)

# The paper's definition of φ (n°11) and the λ that (14) then implies.
DPHI_DTHETA = sp.tan(theta) - a / (b * sp.cos(theta))
LAMBDA_FROM_14 = (sp.tan(theta) - c / (b * sp.cos(theta))) / DPHI_DTHETA
s = sp.sin(theta)


def _tidy(expr: sp.Expr) -> sp.Expr:
    """Sines and cosines of θ only, factored."""
    return sp.factor(sp.cancel(sp.simplify(expr).subs(sp.tan(theta), s / sp.cos(theta))))


@lru_cache(maxsize=None)
def chain() -> dict[str, sp.Expr]:
    """Every step of n°11, derived."""
    red = n9_reduced_system.reduced_rates()
    x_rate = _tidy(red["dx/dtheta"] / DPHI_DTHETA)
    y_rate = _tidy(red["dy/dtheta"] / DPHI_DTHETA)
    lam_value = _tidy(y_rate / x_rate)

    # Eliminate y: solve x' = xy/(x + y) for y, then ask y' = λ x'.
    x_prime = sp.Symbol("x'", real=True)
    (y_of_x,) = sp.solve(sp.Eq(x_prime, x * y / (x + y)), y)
    y_phi = y_of_x.subs({x_prime: sp.diff(X, phi), x: X})
    (x_second,) = sp.solve(sp.Eq(sp.diff(y_phi, phi), Lam * sp.diff(X, phi)), sp.diff(X, phi, 2))

    # x = exp ∫ z dφ in x² x'' = x'³ + λ x'(x − x')².
    X_of_z = sp.exp(sp.Integral(Z, phi))
    second_order = X**2 * sp.diff(X, phi, 2) - sp.diff(X, phi) ** 3 - Lam * sp.diff(X, phi) * (X - sp.diff(X, phi)) ** 2
    in_z = sp.expand(second_order.subs(X, X_of_z).doit() / X_of_z**3)
    (z_rate,) = sp.solve(in_z, sp.diff(Z, phi))
    return {
        "x'": x_rate,
        "y'": y_rate,
        "lambda": lam_value,
        "y": y_of_x,
        "x''": x_second,
        "z'": sp.expand(z_rate),
        "z": _tidy(x_rate / x),
    }


@lru_cache(maxsize=None)
def abel_in_theta() -> Abel:
    """Appell's Abel equation with θ as the variable: dz/dθ = (dz/dφ)(dφ/dθ)."""
    rate = chain()["z'"].subs(Lam, chain()["lambda"]).subs(Z, z) * DPHI_DTHETA
    poly = sp.Poly(sp.expand(sp.simplify(rate)), z)
    f3, f2, f1, f0 = (_tidy(poly.coeff_monomial(z**n)) for n in (3, 2, 1, 0))
    return Abel(f3, f2, f1, f0, x=theta)


@lru_cache(maxsize=None)
def phi_of_theta() -> sp.Expr:
    """cos θ dφ/dθ with the a, b read off (7)–(8): its sign decides whether φ(θ) can be inverted."""
    values = n9_reduced_system.constants()
    return _tidy(sp.cos(theta) * DPHI_DTHETA.subs(values))


def display_lambda() -> sp.Expr:
    """λ as the appendix writes it: (b sin θ − c)/(b sin θ − a)."""
    return (b * s - c) / (b * s - a)


def display_abel_theta() -> sp.Expr:
    """The Abel equation's right-hand side in θ, factored: z(z − 1)((2b sin θ − a − c)z − (b sin θ − c))/(b cos θ)."""
    return z * (z - 1) * ((2 * b * s - a - c) * z - (b * s - c)) / (b * sp.cos(theta))


def claims():
    ratio = label("y'/x'", r"\frac{y'}{x'}")
    phi_rate = label("cos θ dφ/dθ", r"\cos\theta \frac{d\varphi}{d\theta}")
    dz_dtheta = label("dz/dθ", r"\frac{dz}{d\theta}")
    return [
        claim(
            "n11.system",
            "n°11",
            "With dφ = (tan θ − a/(b cos θ)) dθ, (14) becomes x' = xy/(x + y), y' = λ xy/(x + y), "
            "λ the ratio of the brackets of (14).",
            r"x' = \frac{xy}{x+y}, \quad y' = \frac{xy}{x+y} \lambda,",
            [sp.Eq(sp.diff(X, phi), x * y / (x + y)), sp.Eq(sp.diff(Y, phi), x * y / (x + y) * lam)],
            lambda: [sp.Eq(sp.diff(X, phi), chain()["x'"]), sp.Eq(sp.diff(Y, phi), chain()["y'"])],
            display=lambda: [
                sp.Eq(accent(X), x * y / (x + y)),
                sp.Eq(accent(Y), (x * y / (x + y)) * display_lambda()),
            ],
            definitions={lam: LAMBDA_FROM_14},
        ),
        claim(
            "n11.phi_monotone",
            "n°11",
            "λ is a function of φ because φ(θ) is invertible on the θ the motion covers: cos θ dφ/dθ = sin θ − a/b < 0 "
            "(a > b, i.e. Rδ < f(R² + k²), implied by (9)), and cos θ keeps its sign along the motion (θ' ∝ cos θ, "
            "n8.theta_rate: θ never crosses ±π/2), so dφ/dθ keeps the sign of −cos θ.",
            r"où $\lambda$ peut être considéré comme une fonction connue de $\varphi$",
            sp.Lt(phi_rate, 0),
            lambda: sp.Eq(phi_rate, phi_of_theta()),
            display=lambda: sp.Eq(phi_rate, s - f * (R**2 + k**2) / (R * delta)),
            bounded={sp.sin(theta): (-1, 1)},
        ),
        claim(
            "n11.lambda",
            "n°11 (beyond the paper)",
            "λ in closed form.",
            None,
            sp.Eq(lam, (b * s - c) / (b * s - a)),
            lambda: sp.Eq(lam, chain()["lambda"]),
            display=lambda: sp.Eq(lam, display_lambda()),
        ),
        claim(
            "n11.elimination",
            "n°11",
            "y' = λ x', and y from x' = xy/(x + y).",
            r"y' = \lambda x', \quad y = \frac{xx'}{x - x'}.",
            [sp.Eq(ratio, lam), sp.Eq(y, X * sp.diff(X, phi) / (X - sp.diff(X, phi)))],
            lambda: [sp.Eq(ratio, chain()["y'"] / chain()["x'"]), sp.Eq(y, chain()["y"])],
            display=lambda: [sp.Eq(ratio, display_lambda()), sp.Eq(y, x * accent(X) / (x - accent(X)))],
            definitions={lam: LAMBDA_FROM_14},
        ),
        claim(
            "n11.second_order",
            "n°11",
            "Eliminating y: the second-order equation for x(φ).",
            r"x^2 x'' = x'^3 + \lambda x' (x - x')^2.",
            sp.Eq(X**2 * sp.diff(X, phi, 2), sp.diff(X, phi) ** 3 + Lam * sp.diff(X, phi) * (X - sp.diff(X, phi)) ** 2),
            lambda: sp.Eq(X**2 * sp.diff(X, phi, 2), X**2 * chain()["x''"]),
            display=lambda: sp.Eq(x**2 * accent(X, 2), accent(X) ** 3 + lam * accent(X) * (x - accent(X)) ** 2),
        ),
        claim(
            "n11.abel",
            "n°11",
            "With x = exp ∫ z dφ: the Abel equation of the first kind.",
            r"z' = z^3 - z^2 + \lambda z(1 - z)^2.",
            sp.Eq(sp.diff(Z, phi), Z**3 - Z**2 + Lam * Z * (1 - Z) ** 2),
            lambda: sp.Eq(sp.diff(Z, phi), chain()["z'"]),
            display=lambda: sp.Eq(accent(Z), z**3 - z**2 + lam * z * (1 - z) ** 2),
        ),
        claim(  # "in (0, 1) while the ball slides and rolls" was wrong for rolling, where z = 1 (a referee)
            "n11.z",
            "n°11 (beyond the paper)",
            "z = x'/x = y/(x + y) = δΩ/(fV + δΩ): in (0, 1) while the ball slides with Ω > 0 (x, y > 0), "
            "z = 0 where Ω = 0 and z = 1 in pure rolling (V = 0).",
            None,
            sp.Eq(z, y / (x + y)),
            lambda: sp.Eq(z, chain()["z"]),
        ),
        claim(
            "n11.factored",
            "n°11 (beyond the paper)",
            "The right-hand side factors: z = 0 (Ω = 0) and z = 1 (V = 0) are solutions; the third root "
            "λ/(1 + λ) = (b sin θ − c)/(2b sin θ − a − c) is a nullcline, not a solution.",
            None,
            sp.Eq(sp.diff(Z, phi), Z * (Z - 1) * ((1 + Lam) * Z - Lam)),
            lambda: sp.Eq(sp.diff(Z, phi), sp.factor(chain()["z'"])),
            display=lambda: sp.Eq(accent(Z), z * (z - 1) * ((1 + lam) * z - lam)),
        ),
        claim(
            "n11.abel_theta",
            "n°11 (beyond the paper)",
            "The Abel equation with θ as the variable, dz/dθ = A₃z³ + A₂z² + A₁z + A₀ (A₀ = 0), factored: "
            "b cos θ dz/dθ = z(z − 1)((2b sin θ − a − c) z − (b sin θ − c)).",
            None,
            sp.Eq(dz_dtheta, z * (z - 1) * ((2 * b * s - a - c) * z - (b * s - c)) / (b * sp.cos(theta))),
            lambda: sp.Eq(dz_dtheta, abel_in_theta().rhs(z)),
            display=lambda: sp.Eq(dz_dtheta, display_abel_theta()),
        ),
    ]
