"""n°2: the claims of the equations of motion (1)–(8), the pivot, and the second route.

The printed forms are our transcription of the OCR (``printed_tex`` is
quoted from it verbatim); the derived forms come from `newton_euler`,
`polar` and `kane`.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation import kane, newton_euler, polar
from derivation.claim import Claim, Erratum
from derivation.newton_euler import L, M, N, X, Y, Z, n_reaction, sign_r
from derivation.notation import latex
from derivation.symbols import (
    Omega,
    R,
    V,
    accent,
    alpha,
    beta,
    d,
    delta,
    epsilon,
    eta,
    f,
    g,
    k,
    label,
    m,
    ocr_dot_eta,
    ocr_dot_xi,
    p,
    q,
    r,
    r_0,
    t,
    theta,
    u,
    v,
    w,
    xi,
    zeta,
)

ONE_PLUS = 1 + R**2 / k**2  # the factor (1 + R²/k²) the paper keeps whole
OCR_DOTS = Erratum(
    "ocr",
    "the transcription puts a dot over ξ and η (ξ̇' for ξ'); the paper writes accents, never dots",
    glyphs={ocr_dot_xi: xi, ocr_dot_eta: eta},
)
t_1 = sp.Symbol("t_1", positive=True)
FOUR_NAMES = ("xi''", "eta''", "p'", "q'")


def _partial(name: str, var: str) -> sp.Symbol:
    """∂(name)/∂(var), a label for the decoupling claim."""
    return label(f"∂{name}/∂{var}", rf"\frac{{\partial {latex(sp.Symbol(name))}}}{{\partial {var}}}")


TEX_7 = r"\begin{cases} V' = -fg \left( 1 + \frac{R^2}{k^2} \right) + \frac{R\delta}{k^2} g \sin(\beta - \alpha), \\ V \alpha' = -\frac{R\delta}{k^2} g \cos(\beta - \alpha). \end{cases}"
TEX_8 = r"\left\{ \begin{aligned}\Omega' &= \frac{fR}{k^2} g \sin(\beta - \alpha) - \frac{\delta}{k^2} g, \\ \Omega \beta' &= \frac{fR}{k^2} g \cos(\beta - \alpha).\end{aligned}\right."


# Displays (`Claim.display`): the derived forms as the paper arranges them, built unevaluated; each
# claim's check proves its display equal to what it derives.
def display_6(lhs=None) -> list[sp.Eq]:
    """(6) as printed: u' = −fg(1 + R²/k²) cos α + (Rδ/k²) g sin β, and v'."""
    lhs = lhs or [accent(u), accent(v)]
    return [
        sp.Eq(lhs[0], -f * g * (1 + R**2 / k**2) * sp.cos(alpha) + (R * delta / k**2) * g * sp.sin(beta)),
        sp.Eq(lhs[1], -f * g * (1 + R**2 / k**2) * sp.sin(alpha) - (R * delta / k**2) * g * sp.cos(beta)),
    ]


def display_7() -> list[sp.Eq]:
    """(7) as printed, in β − α."""
    return [
        sp.Eq(accent(V), -f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g * sp.sin(beta - alpha)),
        sp.Eq(V * accent(alpha), -(R * delta / k**2) * g * sp.cos(beta - alpha)),
    ]


def display_8() -> list[sp.Eq]:
    """(8) as printed, in β − α."""
    return [
        sp.Eq(accent(Omega), (f * R / k**2) * g * sp.sin(beta - alpha) - (delta / k**2) * g),
        sp.Eq(Omega * accent(beta), (f * R / k**2) * g * sp.cos(beta - alpha)),
    ]


def printed_7() -> list[sp.Eq]:
    """(7) as printed."""
    return [
        sp.Eq(d(V), -f * g * ONE_PLUS + R * delta / k**2 * g * sp.sin(beta - alpha)),
        sp.Eq(V * d(alpha), -R * delta / k**2 * g * sp.cos(beta - alpha)),
    ]


def printed_8() -> list[sp.Eq]:
    """(8) as printed."""
    return [
        sp.Eq(d(Omega), f * R / k**2 * g * sp.sin(beta - alpha) - delta / k**2 * g),
        sp.Eq(Omega * d(beta), f * R / k**2 * g * sp.cos(beta - alpha)),
    ]


def _in_alpha_beta(expr: sp.Expr) -> sp.Expr:
    return expr.subs(theta, beta - alpha)


def symmetry_map() -> dict:
    """The exchange of sliding and rolling that leaves (7)–(8) unchanged.

    With ρ = √(R² + k²): f ↦ δ/ρ, δ ↦ fρ, V ↦ ρΩ, Ω ↦ V/ρ, α ↦ −β, β ↦ −α
    (so fV ↔ δΩ and θ is kept).  Found by asking that (a, b, c) of n°9 go to
    (c, b, a) with R and k fixed.
    """
    rho = sp.sqrt(R**2 + k**2)
    return {"params": {f: delta / rho, delta: f * rho}, "V": rho * Omega, "Omega": V / rho, "rho": rho}


@lru_cache(maxsize=None)
def symmetry() -> dict[str, list[sp.Expr]]:
    """(7)–(8) under `symmetry_map`, and what invariance expects them to become."""
    # The system (7)–(8) as residuals in the state (V, Ω, α', β', θ).
    Vp, Op, ap, bp = sp.symbols("V' Omega' alpha' beta'", real=True)
    Vs, Os = sp.symbols("V Omega", positive=True)
    sl, ro = polar.sliding(), polar.rolling()

    def system(V_, O_, Vd, Od, ad, bd, params):
        return [
            Vd - sl["V'"].subs(params, simultaneous=True),
            V_ * ad - sl["V alpha'"].subs(params, simultaneous=True),
            Od - ro["Omega'"].subs(params, simultaneous=True),
            O_ * bd - ro["Omega beta'"].subs(params, simultaneous=True),
        ]

    sym = symmetry_map()
    rho = sym["rho"]
    original = system(Vs, Os, Vp, Op, ap, bp, {})
    # Under the map: V ↦ ρΩ (so V' ↦ ρΩ'), Ω ↦ V/ρ, α' ↦ −β', β' ↦ −α'.
    mapped = system(rho * Os, Vs / rho, rho * Op, Vp / rho, -bp, -ap, sym["params"])
    # Expected: the equations of the other half, each times a constant.
    expected = [rho * original[2], -rho * original[3], original[0] / rho, -original[1] / rho]
    return {"mapped": mapped, "expected": expected}


RHO = sp.Symbol("rho", positive=True)  # √(R² + k²), named in the symmetry's display


def _symmetry_display(labels) -> list[sp.Eq]:
    """The rows (7)₁, (7)₂, (8)₁, (8)₂ as residuals with the map put in, term by term: V' ↦ ρΩ', f ↦ δ/ρ, …"""
    s_, c_ = sp.sin(theta), sp.cos(theta)
    rows = [
        RHO * accent(Omega) + (delta / RHO) * g * (1 + R**2 / k**2) - (f * RHO * R / k**2) * g * s_,
        -RHO * Omega * accent(beta) + (f * RHO * R / k**2) * g * c_,
        accent(V) / RHO - (delta * R / (RHO * k**2)) * g * s_ + (f * RHO / k**2) * g,
        -(V / RHO) * accent(alpha) - (delta * R / (RHO * k**2)) * g * c_,
    ]
    return [sp.Eq(lab, row) for lab, row in zip(labels, rows)]


def _symmetry_reading(labels) -> list[sp.Eq]:
    """Each mapped row of (7)–(8) is a multiple of another row: ρ × (8)₁, −ρ × (8)₂, (7)₁/ρ, −(7)₂/ρ."""
    s_, c_ = sp.sin(theta), sp.cos(theta)
    rows = [
        RHO * (accent(Omega) - (f * R / k**2) * g * s_ + (delta / k**2) * g),
        -RHO * (Omega * accent(beta) - (f * R / k**2) * g * c_),
        (accent(V) + f * g * (1 + R**2 / k**2) - (R * delta / k**2) * g * s_) / RHO,
        -(V * accent(alpha) + (R * delta / k**2) * g * c_) / RHO,
    ]
    return [sp.Eq(lab, row) for lab, row in zip(labels, rows)]


def _symmetry_claim() -> Claim:
    labels = [label(f"row {i + 1} of (7)–(8) after the symmetry map (n2.symmetry)", rf"S_{{{i + 1}}}") for i in range(4)]
    return Claim(
        "n2.symmetry",
        "n°2, after eq. (8)",
        "The ‘symétrie digne d'attention’ made exact: (7)–(8) are invariant under f ↦ δ/ρ, δ ↦ fρ, "
        "V ↦ ρΩ, Ω ↦ V/ρ, α ↦ −β, β ↦ −α with ρ = √(R²+k²): mapped, the two rows of (7) become those of (8) "
        "times ρ and −ρ, and the two rows of (8) those of (7) over ρ and −ρ.  The map sends δ < fR to δ > f(R²+k²)/R.",
        r"Ces quatre équations (7) et (8) présentent une symétrie digne d'attention entre le glissement et la rotation",
        lambda: [sp.Eq(lab, e) for lab, e in zip(labels, symmetry()["expected"])],
        lambda: [sp.Eq(lab, e) for lab, e in zip(labels, symmetry()["mapped"])],
        display=lambda: _symmetry_display(labels),
        reading=lambda: _symmetry_reading(labels),
        display_where={RHO: sp.sqrt(R**2 + k**2)},
    )


@lru_cache(maxsize=None)
def slip_components() -> list[sp.Expr]:
    """u and v as the derivation uses them (n°2, eq. (1)): V times the unit vector the sliding friction
    F = −fn e_V opposes, read off `newton_euler.sliding_force`."""
    n = newton_euler.equations_of_motion()["n"]
    unit = -newton_euler.sliding_force() / (f * n)
    return [sp.simplify(V * unit[i]) for i in range(2)]


@lru_cache(maxsize=None)
def horizontal_rotation() -> dict[str, list[sp.Expr]]:
    """Ω and β as the derivation uses them (n°2, eq. (3)): the rolling couple opposes Ω, and (8) differentiates (3).

    ``components``: Ω times the unit vector the rolling couple H = −δn e_Ω opposes, read off
    `newton_euler.rolling_couple`; ``rates``: the left-hand sides `polar.rolling` equates to p' and q'.
    """
    n = newton_euler.equations_of_motion()["n"]
    unit = -newton_euler.rolling_couple() / (delta * n)
    return {
        "components": [sp.simplify(Omega * unit[i]) for i in range(2)],
        "rates": [e.lhs for e in polar.rolling()["equations"]],
    }


def claims() -> list[Claim]:
    K_hold = label("the pivot couple that holds r at 0", r"|K_0|")
    four = [d(xi, 2), d(eta, 2), d(p), d(q)]

    return [
        Claim(
            "eq1",
            "n°2, eq. (1)",
            "(1) defines the slip's speed V and direction α by u = V cos α, v = V sin α (the derivation's sliding "
            "friction opposes (cos α, sin α)); what it asserts is that the material point of the ball at the "
            "contact A moves horizontally: w = 0.",
            r"u = V \cos \alpha, \quad v = V \sin \alpha, \quad w = 0",
            [sp.Eq(u, V * sp.cos(alpha)), sp.Eq(v, V * sp.sin(alpha)), sp.Eq(w, 0)],
            lambda: [
                *(sp.Eq(x, value) for x, value in zip((u, v), slip_components(), strict=True)),
                sp.Eq(w, newton_euler.kinematics()["v_A"][2]),
            ],
        ),
        Claim(
            "eq2",
            "n°2, eq. (2)",
            "Velocity of the contact point: translation of G plus the rotation ω about G.",
            r"u = \dot{\xi}' - qR, \quad v = \dot{\eta}' + pR",
            [sp.Eq(u, d(ocr_dot_xi) - q * R), sp.Eq(v, d(ocr_dot_eta) + p * R)],
            lambda: [sp.Eq(lhs, value) for lhs, value in zip((u, v), newton_euler.kinematics()["v_A"])],
            erratum=OCR_DOTS,
        ),
        Claim(
            "eq3",
            "n°2, eq. (3)",
            "Ω is the horizontal projection of ω, of angle β with Oξ: the derivation's rolling couple opposes "
            "Ω (cos β, sin β).",
            r"p = \Omega \cos \beta, \quad q = \Omega \sin \beta",
            [sp.Eq(p, Omega * sp.cos(beta)), sp.Eq(q, Omega * sp.sin(beta))],
            lambda: [sp.Eq(x, value) for x, value in zip((p, q), horizontal_rotation()["components"], strict=True)],
            premise="definition",
        ),
        Claim(
            "n2.eq3_rates",
            "n°2, eqs. (3) and (8)",
            "(8) comes from (4) by differentiating (3): the p′ and q′ that the derivation's (8) equates to (4)'s "
            "are those of p = Ω cos β, q = Ω sin β.",
            None,
            [sp.Eq(d(p), d(Omega * sp.cos(beta))), sp.Eq(d(q), d(Omega * sp.sin(beta)))],
            lambda: [sp.Eq(x, value) for x, value in zip((d(p), d(q)), horizontal_rotation()["rates"], strict=True)],
            display=lambda: [  # in the order of the product rule
                sp.Eq(accent(p), accent(Omega) * sp.cos(beta) - Omega * accent(beta) * sp.sin(beta)),
                sp.Eq(accent(q), accent(Omega) * sp.sin(beta) + Omega * accent(beta) * sp.cos(beta)),
            ],
        ),
        Claim(
            "n2.normal",
            "n°2",
            "The normal reaction balances the weight, since G stays at height R.",
            r"n = mg",
            sp.Eq(n_reaction, m * g),
            lambda: sp.Eq(n_reaction, newton_euler.equations_of_motion()["n"]),
        ),
        Claim(
            "n2.friction",
            "n°2",
            "Components of the sliding friction fmg opposite V.",
            r"X = -fmg \cos \alpha, \quad Y = -fmg \sin \alpha, \quad Z = 0",
            [sp.Eq(X, -f * m * g * sp.cos(alpha)), sp.Eq(Y, -f * m * g * sp.sin(alpha)), sp.Eq(Z, 0)],
            lambda: [sp.Eq(lhs, value) for lhs, value in zip((X, Y, Z), newton_euler.sliding_force())],
            premise="law",
        ),
        Claim(
            "n2.rolling_couple",
            "n°2",
            "Components of the rolling couple δmg opposite Ω.",
            r"L = -\delta mg \cos \beta, \quad M = -\delta mg \sin \beta, \quad N = 0",
            [sp.Eq(L, -delta * m * g * sp.cos(beta)), sp.Eq(M, -delta * m * g * sp.sin(beta)), sp.Eq(N, 0)],
            lambda: [sp.Eq(lhs, value) for lhs, value in zip((L, M, N), newton_euler.rolling_couple())],
            premise="law",
        ),
        Claim(
            "eq4",
            "n°2, eq. (4)",
            "Momentum theorem at G and angular momentum about G (isotropic ball, no gyroscopic term).",
            r"\begin{cases} m\dot{\xi}'' = X, & m\dot{\eta}'' = Y, \\ mk^2 p' = RY + L, & mk^2 q' = -RX + M, \end{cases}",
            [
                sp.Eq(m * d(ocr_dot_xi, 2), X),
                sp.Eq(m * d(ocr_dot_eta, 2), Y),
                sp.Eq(m * k**2 * d(p), R * Y + L),
                sp.Eq(m * k**2 * d(q), -R * X + M),
            ],
            lambda: newton_euler.equations_of_motion()["translation"] + newton_euler.equations_of_motion()["rotation"][:2],
            erratum=OCR_DOTS,
        ),
        Claim(
            "eq5",
            "n°2, eq. (5)",
            "The pivot couple εmg opposes r (with the sign − for r > 0).",
            r"mk^2 r' = \pm \varepsilon mg",
            sp.Eq(m * k**2 * d(r), -sign_r * epsilon * m * g),
            lambda: newton_euler.equations_of_motion()["rotation"][2].subs(N, newton_euler.rolling_couple()[2]),
        ),
        Claim(
            "n2.pivot",
            "n°2, after eq. (5)",
            "With r_0 > 0 the pivoting decreases linearly.",
            r"k^2(r - r_0) = -\varepsilon g t",
            sp.Eq(k**2 * (r - r_0), -epsilon * g * t),
            lambda: sp.Eq(k**2 * (r - r_0), k**2 * (newton_euler.pivot_solution()["r(t)"] - r_0)),
        ),
        Claim(
            "n2.pivot_time",
            "n°2, after eq. (5)",
            "The pivoting stops at t_1.",
            r"t_1 = \frac{k^2 r_0}{\varepsilon g}",
            sp.Eq(t_1, k**2 * r_0 / (epsilon * g)),
            lambda: sp.Eq(t_1, newton_euler.pivot_solution()["t_1"]),
        ),
        Claim(
            "n2.pivot_stays_zero",
            "n°2, after eq. (5)",
            "Once r = 0 it stays 0: the pivot couple needed to keep r' = 0, from the vertical component of the "
            "angular-momentum theorem (4)–(5) with the friction and rolling couple of n°2, is within the static "
            "bound εmg.",
            r"le pivotement est nul : il reste ensuite nul",
            sp.Le(K_hold, epsilon * m * g),
            lambda: sp.Eq(K_hold, sp.Abs(newton_euler.pivot_couple_at_rest())),
        ),
        Claim(
            "n2.decoupled",
            "n°2, after eq. (5)",
            "The four equations (4) involve neither r nor the sign of r: they can be studied alone.",
            r"Il suffit donc d'étudier les quatre équations (4)",
            [sp.Eq(_partial(x, y), 0) for x in FOUR_NAMES for y in ("r", "s_r")],
            lambda: [
                sp.Eq(_partial(name, y), sp.diff(newton_euler.accelerations()[x], var))
                for name, x in zip(FOUR_NAMES, four)
                for y, var in (("r", r), ("s_r", sign_r))
            ],
        ),
        Claim(
            "n2.contact_derivative",
            "n°2, before eq. (6)",
            "Differentiating (2).",
            r"u' = \zeta'' - Rq', \quad v' = \eta'' + Rp'",
            [sp.Eq(d(u), d(zeta, 2) - R * d(q)), sp.Eq(d(v), d(eta, 2) + R * d(p))],
            lambda: [
                sp.Eq(d(u), newton_euler.contact_acceleration()["u'"]),
                sp.Eq(d(v), newton_euler.contact_acceleration()["v'"]),
            ],
            erratum=Erratum("ocr", "ζ read for ξ: ζ'' is the vertical acceleration, zero here", glyphs={zeta: xi}),
        ),
        Claim(
            "n2.contact_generic",
            "n°2, before eq. (6)",
            "u', v' through the force and couple components, from (2) and (4).",
            r"\begin{aligned} mu' &= X \left( 1 + \frac{R^2}{k^2} \right) - \frac{R}{k^2} M, \\ mv' &= Y \left( 1 + \frac{R^2}{k^2} \right) + \frac{R}{k^2} L, \end{aligned}",
            [sp.Eq(m * d(u), X * ONE_PLUS - R / k**2 * M), sp.Eq(m * d(v), Y * ONE_PLUS + R / k**2 * L)],
            lambda: [
                sp.Eq(m * d(u), newton_euler.contact_acceleration()["m u' generic"]),
                sp.Eq(m * d(v), newton_euler.contact_acceleration()["m v' generic"]),
            ],
            display=lambda: [
                sp.Eq(m * accent(u), X * (1 + R**2 / k**2) - (R / k**2) * M),
                sp.Eq(m * accent(v), Y * (1 + R**2 / k**2) + (R / k**2) * L),
            ],
        ),
        Claim(
            "eq6",
            "n°2, eq. (6)",
            "Acceleration of the contact point with the forces of n°2.",
            r"\begin{cases} u' = -fg \left( 1 + \frac{R^2}{k^2} \right) \cos \alpha + \frac{R\delta}{k^2} g \sin \beta, \\ v' = -fg \left( 1 + \frac{R^2}{k^2} \right) \sin \alpha - \frac{R\delta}{k^2} g \cos \beta. \end{cases}",
            [
                sp.Eq(d(u), -f * g * ONE_PLUS * sp.cos(alpha) + R * delta / k**2 * g * sp.sin(beta)),
                sp.Eq(d(v), -f * g * ONE_PLUS * sp.sin(alpha) - R * delta / k**2 * g * sp.cos(beta)),
            ],
            lambda: [
                sp.Eq(d(u), newton_euler.contact_acceleration()["u' (6)"]),
                sp.Eq(d(v), newton_euler.contact_acceleration()["v' (6)"]),
            ],
            display=display_6,
        ),
        Claim(
            "n2.sliding_polar",
            "n°2, before eq. (7)",
            "(6) with u = V cos α, v = V sin α.",
            r"\begin{aligned} V' \cos \alpha - V \sin \alpha \alpha' &= -fg \left( 1 + \frac{R^2}{k^2} \right) \cos \alpha + \frac{R\delta}{k^2} g \sin \beta, \\ V' \sin \alpha + V \cos \alpha \alpha' &= -fg \left( 1 + \frac{R^2}{k^2} \right) \sin \alpha - \frac{R\delta}{k^2} g \cos \beta; \end{aligned}",
            [
                sp.Eq(
                    d(V) * sp.cos(alpha) - V * sp.sin(alpha) * d(alpha),
                    -f * g * ONE_PLUS * sp.cos(alpha) + R * delta / k**2 * g * sp.sin(beta),
                ),
                sp.Eq(
                    d(V) * sp.sin(alpha) + V * sp.cos(alpha) * d(alpha),
                    -f * g * ONE_PLUS * sp.sin(alpha) - R * delta / k**2 * g * sp.cos(beta),
                ),
            ],
            lambda: polar.sliding()["equations"],
            display=lambda: display_6([
                accent(V) * sp.cos(alpha) - V * sp.sin(alpha) * accent(alpha),
                accent(V) * sp.sin(alpha) + V * sp.cos(alpha) * accent(alpha),
            ]),
        ),
        Claim(
            "eq7",
            "n°2, eq. (7)",
            "The sliding speed V and its direction α.",
            TEX_7,
            printed_7(),
            lambda: [
                sp.Eq(d(V), _in_alpha_beta(polar.sliding()["V'"])),
                sp.Eq(V * d(alpha), _in_alpha_beta(polar.sliding()["V alpha'"])),
            ],
            display=display_7,
        ),
        Claim(
            "n2.rolling_polar",
            "n°2, before eq. (8)",
            "The rotational equations (4) with p = Ω cos β, q = Ω sin β.",
            r"\begin{aligned}\Omega' \cos \beta - \Omega \sin \beta \beta' &= -\frac{fR}{k^2} g \sin \alpha - \frac{\delta}{k^2} g \cos \beta, \\ \Omega' \sin \beta + \Omega \cos \beta \beta' &= +\frac{fR}{k^2} g \cos \alpha - \frac{\delta}{k^2} g \sin \beta;\end{aligned}",
            [
                sp.Eq(
                    d(Omega) * sp.cos(beta) - Omega * sp.sin(beta) * d(beta),
                    -f * R / k**2 * g * sp.sin(alpha) - delta / k**2 * g * sp.cos(beta),
                ),
                sp.Eq(
                    d(Omega) * sp.sin(beta) + Omega * sp.cos(beta) * d(beta),
                    f * R / k**2 * g * sp.cos(alpha) - delta / k**2 * g * sp.sin(beta),
                ),
            ],
            lambda: polar.rolling()["equations"],
        ),
        Claim(
            "eq8",
            "n°2, eq. (8)",
            "The horizontal rotation Ω and its direction β.",
            TEX_8,
            printed_8(),
            lambda: [
                sp.Eq(d(Omega), _in_alpha_beta(polar.rolling()["Omega'"])),
                sp.Eq(Omega * d(beta), _in_alpha_beta(polar.rolling()["Omega beta'"])),
            ],
            display=display_8,
        ),
        _symmetry_claim(),
        Claim(
            "route2.eq4-5",
            "n°2, eqs. (4)–(5)",
            "Second route: Kane's method (sympy.physics.mechanics), with the loads written from their laws, "
            "gives the same ξ'', η'', p', q', r' as Newton–Euler.",
            None,
            # Newton–Euler's values stand as the printed side: they are what the second route must give.
            lambda: [sp.Eq(x, value) for x, value in newton_euler.accelerations().items()],
            lambda: [sp.Eq(x, kane.equations_4_5()[x]) for x in newton_euler.accelerations()],
        ),
        Claim(
            "route2.eq7",
            "n°2, eq. (7)",
            "Second route: (7) from Kane's equations, through V V' = u u' + v v' and V² α' = u v' − v u'.",
            TEX_7,
            printed_7(),
            lambda: [
                sp.Eq(d(V), _in_alpha_beta(kane.equations_7_8()["V'"])),
                sp.Eq(V * d(alpha), _in_alpha_beta(kane.equations_7_8()["V alpha'"])),
            ],
            display=display_7,
        ),
        Claim(
            "route2.eq8",
            "n°2, eq. (8)",
            "Second route: (8) from Kane's equations.",
            TEX_8,
            printed_8(),
            lambda: [
                sp.Eq(d(Omega), _in_alpha_beta(kane.equations_7_8()["Omega'"])),
                sp.Eq(Omega * d(beta), _in_alpha_beta(kane.equations_7_8()["Omega beta'"])),
            ],
            display=display_8,
        ),
    ]
