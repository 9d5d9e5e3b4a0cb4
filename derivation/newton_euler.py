"""n°2: the equations of motion from Newton–Euler, first route.

A ball of radius R, mass m and moment of inertia m k² about every diameter
(concentric homogeneous layers) touches the cloth at A.  Forces and couples
are exactly those of n°2: the sliding friction F (fmg, opposite V) and the
normal reaction n at A, gravity at G, the rolling couple H (δmg, opposite
the horizontal rotation Ω) and the pivot couple K (εmg, opposite r).

Everything below is obtained, not retyped: kinematics gives (1)–(2), the
momentum and angular-momentum theorems give (4)–(5), and (6) follows by
differentiating (2).  (7)–(8) live in `polar`.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derivation.symbols import Omega, R, V, alpha, beta, d, delta, epsilon, eta, f, g, k, m, p, q, r, r_0, t, u, v, xi

e_z = sp.Matrix([0, 0, 1])

# Generic force and couple components, as the paper names them (n°2):
# F = (X, Y, Z) at A, rolling couple H = (L, M, N).
X, Y, Z, L, M, N = sp.symbols("X Y Z L M N", real=True)
n_reaction = sp.Symbol("n", real=True)
# sign(r): the pivot couple opposes r, eq. (5).
sign_r = sp.Symbol("s_r", real=True)


@lru_cache(maxsize=None)
def kinematics() -> dict[str, sp.Matrix]:
    """Velocity of the material point of the ball at the contact A, eqs. (1)–(2)."""
    omega = sp.Matrix([p, q, r])
    # G stays at height zeta = R: its velocity is horizontal.
    v_G = sp.Matrix([d(xi), d(eta), d(R)])
    GA = sp.Matrix([0, 0, -R])
    # Rigid body: v_A = v_G + omega x GA.
    v_A = v_G + omega.cross(GA)
    return {"omega": omega, "v_G": v_G, "GA": GA, "v_A": v_A}


def sliding_force() -> sp.Matrix:
    """F = (X, Y, Z): magnitude f n, opposite the slip V = (V cos α, V sin α, 0) of eq. (1)."""
    slip = sp.Matrix([V * sp.cos(alpha), V * sp.sin(alpha), 0])
    n = equations_of_motion()["n"]
    return sp.simplify(-f * n * slip / sp.sqrt(slip.dot(slip)))


def rolling_couple() -> sp.Matrix:
    """H = (L, M, N): magnitude δ n, opposite Ω = (Ω cos β, Ω sin β, 0) of eq. (3)."""
    spin = sp.Matrix([Omega * sp.cos(beta), Omega * sp.sin(beta), 0])
    n = equations_of_motion()["n"]
    return sp.simplify(-delta * n * spin / sp.sqrt(spin.dot(spin)))


@lru_cache(maxsize=None)
def equations_of_motion() -> dict[str, object]:
    """Newton–Euler with generic F = (X, Y, Z), H = (L, M, N), eqs. (4)–(5).

    Returns the equations as the paper writes them (left: m ξ'', m η'',
    m k² p', m k² q', m k² r') and the normal reaction n.
    """
    kin = kinematics()
    F = sp.Matrix([X, Y, Z])
    H = sp.Matrix([L, M, N])
    normal = n_reaction * e_z
    weight = -m * g * e_z
    # Momentum theorem at G: m a_G = F + n + weight.
    a_G = sp.diff(kin["v_G"], t)
    total_force = F + normal + weight
    # The vertical component, with Z = 0 (F is horizontal), gives n.
    n_value = sp.solve(sp.Eq(m * a_G[2], total_force[2]).subs(Z, 0), n_reaction)[0]
    # Angular momentum about G: for an isotropic ball it is m k² omega, so
    # d/dt (m k² omega) = GA x (F + n) + H + K (no gyroscopic term).
    pivot = -sign_r * epsilon * n_value * e_z
    torque = kin["GA"].cross(F + normal) + H + pivot
    angular = m * k**2 * sp.diff(kin["omega"], t)
    return {
        "n": n_value,
        "translation": [sp.Eq(m * a_G[i], total_force[i]) for i in range(2)],
        "rotation": [sp.Eq(angular[i], torque[i]) for i in range(3)],
    }


@lru_cache(maxsize=None)
def accelerations() -> dict[sp.Expr, sp.Expr]:
    """ξ'', η'', p', q', r' with n°2's forces put in: the right-hand side of (4)–(5)."""
    eqs = equations_of_motion()
    F, H = sliding_force(), rolling_couple()
    values = {X: F[0], Y: F[1], Z: F[2], L: H[0], M: H[1], N: H[2]}
    unknowns = [d(xi, 2), d(eta, 2), d(p), d(q), d(r)]
    system = [e.subs(values) for e in eqs["translation"] + eqs["rotation"]]
    solution = sp.solve(system, unknowns, dict=True)[0]
    return {x: sp.expand(solution[x]) for x in unknowns}


@lru_cache(maxsize=None)
def contact_acceleration() -> dict[str, sp.Expr]:
    """u', v' by differentiating (2): the generic form before (6), and (6) itself."""
    v_A = kinematics()["v_A"]
    eqs = equations_of_motion()
    generic = sp.solve(
        eqs["translation"] + eqs["rotation"][:2], [d(xi, 2), d(eta, 2), d(p), d(q)], dict=True
    )[0]
    du, dv = sp.diff(v_A[0], t), sp.diff(v_A[1], t)
    acc = accelerations()
    return {
        "u'": du,
        "v'": dv,
        "m u' generic": sp.expand(m * du.subs(generic)),
        "m v' generic": sp.expand(m * dv.subs(generic)),
        "u' (6)": sp.expand(du.subs(acc)),
        "v' (6)": sp.expand(dv.subs(acc)),
    }


@lru_cache(maxsize=None)
def pivot_solution() -> dict[str, sp.Expr]:
    """Eq. (5) with r_0 > 0: r decreases linearly and stops at t_1 = k² r_0 / (ε g)."""
    r_dot = accelerations()[d(r)].subs(sign_r, 1)
    r_of_t = r_0 + sp.integrate(r_dot, (t, 0, t))
    return {"r(t)": r_of_t, "t_1": sp.solve(r_of_t, t)[0], "r'": r_dot}


@lru_cache(maxsize=None)
def pivot_couple_at_rest() -> sp.Expr:
    """The pivot couple K₀ (about ζ) that keeps r' = 0 once r = 0: the vertical angular-momentum equation
    with the couple left unknown, n°2's sliding friction and rolling couple put in."""
    K0 = sp.Symbol("K_0", real=True)
    vertical = equations_of_motion()["rotation"][2]
    n = equations_of_motion()["n"]
    F, H = sliding_force(), rolling_couple()
    # The law of the pivot couple is set aside (−s_r ε n is replaced by the unknown K₀): at rest it is
    # whatever holds r = 0, within |K₀| ≤ ε n.
    at_rest = vertical.subs(sign_r, -K0 / (epsilon * n)).subs({X: F[0], Y: F[1], Z: F[2], L: H[0], M: H[1], N: H[2]})
    return sp.solve(at_rest.subs(d(r), 0), K0)[0]


@lru_cache(maxsize=None)
def centre_velocity() -> dict[sp.Expr, sp.Expr]:
    """ξ', η' from (2): the centre's velocity through the slip (u, v) and the rotation."""
    v_A = kinematics()["v_A"]
    return sp.solve([sp.Eq(v_A[0], u), sp.Eq(v_A[1], v)], [d(xi), d(eta)], dict=True)[0]
