"""n°7: once the slip is zero it stays zero; pure rolling, uniformly retarded.

With V ≡ 0 the friction is a force of "repose", f₁ m g with f₁ ≤ f, in
an unknown direction α.  Both components of (7) must vanish, f replaced by
f₁: θ = π/2 and f₁ = δR/(R² + k²) (the printed (10) inverts a fraction).
Then (8) gives β' = 0 and Ω' = −δg/(R² + k²), and the centre moves in a
straight line perpendicular to Ω, uniformly retarded.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import newton_euler, polar
from derivation.claim import Claim, Erratum
from derivation.symbols import (
    Omega,
    Omega_0,
    R,
    accent,
    alpha,
    beta,
    d,
    delta,
    eta,
    f,
    f_1,
    g,
    k,
    label,
    ocr_rho,
    p,
    q,
    t,
    theta,
    u,
    v,
    xi,
)

AT_REST = {f: f_1}  # the friction of repose, f₁ ≤ f
RIGHT_ANGLE = {theta: sp.pi / 2}


@lru_cache(maxsize=None)
def motion() -> dict[str, object]:
    """The conditions of pure rolling, f₁, and the motion that follows."""
    sl, ro = polar.sliding(), polar.rolling()
    # V ≡ 0: both V' and V α' vanish; divide by the factors −Rδg/k² and g.
    first = sp.simplify(sl["V alpha'"] * k**2 / (-R * delta * g))
    second = sp.expand(sl["V'"].subs(AT_REST) / g)
    roots = sorted(sp.solveset(first, theta, sp.Interval.Ropen(0, 2 * sp.pi)), key=float)
    f_1_value = sp.solve(second.subs(RIGHT_ANGLE), f_1)[0]
    # (8) with f₁ for f, at θ = π/2.
    Omega_rate_f1 = ro["Omega'"].subs(AT_REST).subs(RIGHT_ANGLE)
    Omega_rate = sp.simplify(Omega_rate_f1.subs(f_1, f_1_value))
    centre = newton_euler.centre_velocity()
    # Ω of constant direction β: p = Ω cos β, q = Ω sin β (eq. (3)).
    spin = {p: Omega * sp.cos(beta), q: Omega * sp.sin(beta), u: 0, v: 0}
    velocity = sp.Matrix([centre[d(xi)], centre[d(eta)]]).subs(spin)
    acceleration = sp.diff(velocity, t).subs({d(beta): 0, d(Omega): Omega_rate})
    return {
        "first": first,
        "second": second,
        "roots": roots,
        "second at roots": [second.subs(theta, x) for x in roots],
        "f_1": f_1_value,
        "beta'": sp.simplify(ro["Omega beta'"].subs(AT_REST).subs(RIGHT_ANGLE) / Omega),
        "Omega' (f_1)": Omega_rate_f1,
        "Omega'": Omega_rate,
        "t_1": sp.solve(Omega_0 + Omega_rate * t, t)[0],
        "centre": {x: centre[x].subs({u: 0, v: 0}) for x in (d(xi), d(eta))},
        "velocity": velocity,
        "acceleration": acceleration,
    }


def claims() -> list[Claim]:
    in_ab = {theta: beta - alpha}
    along = label("centre velocity · (cos β, sin β)", r"\dot{\mathbf{G}} \cdot \mathbf{e}_\beta")
    retard = label("centre velocity · acceleration", r"\dot{\mathbf{G}} \cdot \ddot{\mathbf{G}}")
    second_at = label("second condition at θ = 3π/2", r"\left. -f_1 \left(1 + \frac{R^2}{k^2}\right) + \frac{R\delta}{k^2} \sin\theta \right|_{\theta = 3\pi/2}")
    t_1 = sp.Symbol("t_1", positive=True)
    along_xi = {beta: 0}  # "On peut supposer β = 0"
    return [
        Claim(
            "n7.conditions",
            "n°7",
            "Rolling without sliding (V ≡ 0) requires both components of (7) to vanish, f replaced by f₁.",
            r"\begin{aligned} \cos(\beta - \alpha) &= 0, \\ -f_1 \left(1 + \frac{R^2}{k^2}\right) + \frac{R\delta}{k^2} \sin(\beta - \alpha) &= 0. \end{aligned}",
            [
                sp.Eq(sp.cos(beta - alpha), 0),
                sp.Eq(-f_1 * (1 + R**2 / k**2) + R * delta / k**2 * sp.sin(beta - alpha), 0),
            ],
            lambda: [sp.Eq(motion()["first"].subs(in_ab), 0), sp.Eq(motion()["second"].subs(in_ab), 0)],
        ),
        Claim(
            "n7.right_angle",
            "n°7",
            "At θ = 3π/2 the second condition is a sum of negative terms: θ = π/2.",
            r"Il faut prendre encore $(\beta - \alpha) = \frac{\pi}{2}$ pour que la seconde équation puisse être satisfaite",
            sp.Lt(second_at, 0),
            lambda: sp.Eq(second_at, motion()["second at roots"][1]),
        ),
        Claim(
            "eq10",
            "n°7, eq. (10)",
            "The friction force needed to roll without sliding.",
            r"f_1 = \frac{\delta}{R} \frac{1}{1 + \frac{R^2}{k^2}}",
            sp.Eq(f_1, delta / R / (1 + R**2 / k**2)),
            lambda: sp.Eq(f_1, motion()["f_1"]),
            erratum=Erratum(
                "mathematical",
                "the fraction in the denominator is inverted: the second condition at θ = π/2 gives "
                "f₁(1 + R²/k²) = Rδ/k², i.e. f₁ = (δ/R)/(1 + k²/R²) = δR/(R² + k²).  The printed value would "
                "make Ω' = −(δ − f₁R)g/k² equal to −δR²g/(k²(R² + k²)), not the −δg/(R² + k²) the paper prints "
                "next; the paper's later results use the correct value.  An inverted fraction is no glyph confusion.",
                corrected=sp.Eq(f_1, delta / R / (1 + k**2 / R**2)),
                summary="the fraction in the denominator of f₁ is inverted (the paper's later results use the right value)",
            ),
        ),
        Claim(
            "n7.f1_below_f",
            "n°7, after eq. (10)",
            "f₁ < f, so the friction of repose can hold the ball in pure rolling.",
            r"valeur de $f_1$ qui est bien inférieure à $f$",
            sp.Lt(f_1, f),
            lambda: sp.Eq(f_1, motion()["f_1"]),
        ),
        Claim(
            "n7.beta",
            "n°7",
            "The rotation keeps its direction.",
            r"Les équations (8) montrent alors que $\beta' = 0$",
            sp.Eq(d(beta), 0),
            lambda: sp.Eq(d(beta), motion()["beta'"]),
        ),
        Claim(
            "n7.Omega_rate_f1",
            "n°7",
            "(8) at θ = π/2 with f₁ for f.",
            r"\Omega' = - \frac{\delta - f_1 R}{k^2} g",
            sp.Eq(d(Omega), -(delta - f_1 * R) / k**2 * g),
            lambda: sp.Eq(d(Omega), motion()["Omega' (f_1)"]),
            display=lambda: sp.Eq(accent(Omega), -((delta - f_1 * R) / k**2) * g),
        ),
        Claim(
            "n7.Omega_rate",
            "n°7",
            "The rolling deceleration, with f₁ from (10) corrected.",
            r"\Omega' = - \frac{\delta g}{R^2 + k^2}",
            sp.Eq(d(Omega), -delta * g / (R**2 + k**2)),
            lambda: sp.Eq(d(Omega), motion()["Omega'"]),
        ),
        Claim(
            "n7.stop_time",
            "n°7",
            "Ω reaches zero at t₁ (time counted from the start of pure rolling).",
            r"t_1 = \Omega_0 \frac{R^2 + k^2}{\delta g}",
            sp.Eq(t_1, Omega_0 * (R**2 + k**2) / (delta * g)),
            lambda: sp.Eq(t_1, motion()["t_1"]),
        ),
        Claim(
            "n7.centre_velocity",
            "n°7",
            "The centre's velocity from (2) with u = v = 0.",
            r"\xi' = qR, \quad \eta' = -pR",
            [sp.Eq(d(xi), q * R), sp.Eq(d(eta), -p * R)],
            lambda: [sp.Eq(x, value) for x, value in motion()["centre"].items()],
        ),
        Claim(
            "n7.perpendicular",
            "n°7",
            "The centre moves perpendicular to Ω: its velocity has no component along the direction β of Ω (its "
            "speed's decrease is n7.retarded).",
            r"le centre est animé d'un mouvement rectiligne perpendiculaire à la direction de la rotation instantanée, uniformément retardé",
            [sp.Eq(along, 0)],
            lambda: [sp.Eq(along, motion()["velocity"].dot(sp.Matrix([sp.cos(beta), sp.sin(beta)])))],
        ),
        Claim(
            "n7.retarded",
            "n°7",
            "Retarded: velocity · acceleration = R²ΩΩ' < 0; uniformly, the acceleration being the constant of "
            "n7.centre_acceleration.",
            r"uniformément retardé",
            sp.Lt(retard, 0),
            lambda: sp.Eq(retard, sp.simplify(motion()["velocity"].dot(motion()["acceleration"]))),
        ),
        Claim(
            "n7.centre_acceleration",
            "n°7",
            "The centre's acceleration, with β = 0 (p = Ω, q = 0).",
            r"\eta'' = -R\rho' = -R\Omega' = + \frac{\delta R}{R^2 + k^2} g",
            [
                sp.Eq(d(eta, 2), -R * sp.diff(ocr_rho, t)),
                sp.Eq(d(eta, 2), -R * d(Omega)),
                sp.Eq(d(eta, 2), delta * R / (R**2 + k**2) * g),
            ],
            lambda: [
                sp.Eq(d(eta, 2), sp.diff(motion()["centre"][d(eta)], t)),
                sp.Eq(d(eta, 2), sp.diff(motion()["velocity"][1].subs(along_xi), t)),
                sp.Eq(d(eta, 2), motion()["acceleration"][1].subs(along_xi)),
            ],
            erratum=Erratum("ocr", "ρ read for p", glyphs={ocr_rho: p}),
        ),
    ]
