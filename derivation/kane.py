"""n°2, second route: Kane's method (sympy.physics.mechanics) to (4)–(8).

Independent of `newton_euler` in everything but the physics: the ball is a
`RigidBody`, the contact velocity comes from `Point.v2pt_theory`, the
equations from `KanesMethod`, and the loads are written from their laws,
not from the paper's components: sliding friction −fmg v_A/|v_A|, rolling
couple −δmg Ω_h/|Ω_h| with Ω_h the horizontal part of ω, pivot couple
−εmg sign(r).  The polar rates then come from V V' = u u' + v v' and
V² α' = u v' − v u', with no trigonometric solving.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
import sympy.physics.mechanics as me

from derivation.newton_euler import sign_r
from derivation.polar import in_theta
from derivation.symbols import Omega, R, V, alpha, beta, d, delta, epsilon, eta, f, g, k, m, p, q, r, t, xi

# Generalised speeds: the velocity of G and the rotation, in the fixed frame.
xi_k, eta_k = me.dynamicsymbols("xi eta", real=True)
u_xi, u_eta, p_k, q_k, r_k = me.dynamicsymbols("u_xi u_eta p q r", real=True)


@lru_cache(maxsize=None)
def kanes_equations() -> dict[sp.Expr, sp.Expr]:
    """ξ'', η'', p', q', r' from Kane's equations, in the speeds (u_ξ, u_η, p, q, r)."""
    N = me.ReferenceFrame("N")
    ball_frame = me.ReferenceFrame("B")
    ball_frame.set_ang_vel(N, p_k * N.x + q_k * N.y + r_k * N.z)
    origin = me.Point("O")
    origin.set_vel(N, 0)
    G = origin.locatenew("G", xi_k * N.x + eta_k * N.y + R * N.z)
    G.set_vel(N, u_xi * N.x + u_eta * N.y)
    A = G.locatenew("A", -R * N.z)
    A.v2pt_theory(G, N, ball_frame)

    v_A = A.vel(N)
    speed = sp.sqrt(v_A.dot(N.x) ** 2 + v_A.dot(N.y) ** 2)
    omega_h = p_k * N.x + q_k * N.y
    spin = sp.sqrt(p_k**2 + q_k**2)
    loads = [
        (A, -f * m * g * v_A / speed),  # sliding friction opposes the slip
        (A, m * g * N.z),  # normal reaction
        (G, -m * g * N.z),  # weight
        (ball_frame, -delta * m * g * omega_h / spin - sign_r * epsilon * m * g * N.z),
    ]
    ball = me.RigidBody("ball", G, ball_frame, m, (me.inertia(N, m * k**2, m * k**2, m * k**2), G))
    kane = me.KanesMethod(
        N,
        q_ind=[xi_k, eta_k],
        u_ind=[u_xi, u_eta, p_k, q_k, r_k],
        kd_eqs=[xi_k.diff(t) - u_xi, eta_k.diff(t) - u_eta],
    )
    kane.kanes_equations([ball], loads)
    rhs = kane.rhs()
    # Keyed like newton_euler.accelerations(), so the two routes compare entry by entry.
    return dict(zip([d(xi, 2), d(eta, 2), d(p), d(q), d(r)], rhs[2:]))


def _to_polar(expr: sp.Expr) -> sp.Expr:
    """Write the speeds through V, α, Ω, β (eqs. (1)–(3)), then through θ."""
    polar = {
        u_xi: V * sp.cos(alpha) + R * Omega * sp.sin(beta),
        u_eta: V * sp.sin(alpha) - R * Omega * sp.cos(beta),
        p_k: Omega * sp.cos(beta),
        q_k: Omega * sp.sin(beta),
    }
    return sp.simplify(sp.trigsimp(expr.subs(polar)))


@lru_cache(maxsize=None)
def equations_4_5() -> dict[sp.Symbol, sp.Expr]:
    """(4)–(5) by Kane's method, in the polar variables."""
    return {name: _to_polar(rhs) for name, rhs in kanes_equations().items()}


@lru_cache(maxsize=None)
def equations_7_8() -> dict[str, sp.Expr]:
    """(7)–(8) by the second route: V', Vα', Ω', Ωβ' as functions of θ."""
    acc = kanes_equations()
    u = u_xi - R * q_k  # eq. (2) from v2pt_theory, checked in the tests
    v = u_eta + R * p_k
    dp, dq = acc[d(p)], acc[d(q)]
    du = acc[d(xi, 2)] - R * dq
    dv = acc[d(eta, 2)] + R * dp
    slip_sq = u**2 + v**2
    spin_sq = p_k**2 + q_k**2
    rates = {
        "V'": (u * du + v * dv) / sp.sqrt(slip_sq),
        "V alpha'": (u * dv - v * du) / sp.sqrt(slip_sq),
        "Omega'": (p_k * dp + q_k * dq) / sp.sqrt(spin_sq),
        "Omega beta'": (p_k * dq - q_k * dp) / sp.sqrt(spin_sq),
    }
    return {name: in_theta(_to_polar(rate)) for name, rate in rates.items()}
