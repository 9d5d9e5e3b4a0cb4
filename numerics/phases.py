"""The closed-form phases of a shot, compiled from the derivation (no formula retyped).

Each model gives, for a time τ since the phase began, the state in the
frame of the slip (α = 0 along O-ξ, as n°3 and n°7 choose their axes);
`simulate` rotates frames.  Models:

* ``classical_slide`` — n°3, δ = 0 (also the classical model's slide);
* ``straight_slide`` — θ = ±π/2 (derivation.straight_shot);
* ``rolling`` — n°7, pure rolling, β fixed;
* ``pivot`` — eq. (5), r(t).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from derivation import n3_classical, n7_pure_rolling, newton_euler, straight_shot
from derivation.symbols import Omega, Omega_0, V, V_0, beta, beta_0, r_0, t
from numerics.equations import PARAMS
from numerics.scene import Coefficients

tau = t  # time since the start of the phase


@dataclass(frozen=True)
class Local:
    """A state in the slip frame: slip speed V, rotation (p, q), centre (ξ, η) and its velocity."""

    V: object
    p: object
    q: object
    xi: object
    eta: object
    vxi: object
    veta: object


def _modules(num) -> str:
    return "math" if num is float else "mpmath"


def _centre_path(vxi: sp.Expr, veta: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    return sp.integrate(vxi, (t, 0, tau)), sp.integrate(veta, (t, 0, tau))


@lru_cache(maxsize=None)
def classical_forms() -> tuple:
    """n°3 in the slip frame: (args, [V, p, q, ξ, η, ξ', η'] at τ, end args, [duration])."""
    sol = n3_classical.motion()
    vxi, veta = sol["xi'"], sol["eta'"]
    xi_, eta_ = _centre_path(vxi, veta)
    args = (tau, V_0, Omega_0, beta_0) + PARAMS
    return args, [sol["V"], sol["p"], sol["q"], xi_, eta_, vxi, veta], args[1:], [sol["t_slide"]]


@lru_cache(maxsize=None)
def _classical(modules: str):
    args, exprs, end_args, (end,) = classical_forms()
    return sp.lambdify(args, exprs, modules), sp.lambdify(end_args, end, modules)


def classical_slide(params: Coefficients, V0, Omega0, beta0, num=float):
    """n°3 from V0 along O-ξ and the rotation Ω0 at β0: (duration, τ ↦ Local)."""
    fn, end = _classical(_modules(num))
    P = params.values(num)
    return end(V0, Omega0, beta0, *P), lambda s: Local(*fn(s, V0, Omega0, beta0, *P))


@lru_cache(maxsize=None)
def straight_forms(side_key: str) -> tuple:
    """θ = +π/2 ("follow") or −π/2 ("draw"): (args, [V, p, q, ξ, η, ξ', η'] at τ, end args, [slip end, spin end])."""
    side = straight_shot.PLUS if side_key == "follow" else straight_shot.MINUS
    sol = straight_shot.straight(side)
    # Slip along O-ξ, the rotation at β = θ = side: p = Ω cos θ, q = Ω sin θ.
    speed = sol["centre speed"].subs({V: sol["V"], Omega: sol["Omega"]})
    xi_, _ = _centre_path(speed, sp.Integer(0))
    exprs = [sol["V"], sol["Omega"] * sp.cos(side), sol["Omega"] * sp.sin(side), xi_, sp.Integer(0), speed, sp.Integer(0)]
    args = (tau, V_0, Omega_0) + PARAMS
    return args, exprs, args[1:], [sp.solve(sol["V"], t)[0], sp.solve(sol["Omega"], t)[0]]


@lru_cache(maxsize=None)
def _straight(side_key: str, modules: str):
    args, exprs, end_args, ends = straight_forms(side_key)
    return sp.lambdify(args, exprs, modules), sp.lambdify(end_args, ends, modules)


def straight_slide(params: Coefficients, side: str, V0, Omega0, num=float):
    """θ = +π/2 ("follow") or −π/2 ("draw") from V0, Ω0: (slip end, spin end, τ ↦ Local)."""
    fn, ends = _straight(side, _modules(num))
    P = params.values(num)
    slip_end, spin_end = ends(V0, Omega0, *P)
    return slip_end, spin_end, lambda s: Local(*fn(s, V0, Omega0, *P))


@lru_cache(maxsize=None)
def rolling_forms() -> tuple:
    """n°7 from the rotation Ω₀ at β₀: (args, [V, p, q, ξ, η, ξ', η'] at τ, end args, [duration])."""
    sol = n7_pure_rolling.motion()
    spin = Omega_0 + sol["Omega'"] * t
    along_xi = {beta: beta_0, Omega: spin}
    vxi, veta = (sol["velocity"][i].subs(along_xi) for i in (0, 1))
    xi_, eta_ = _centre_path(vxi, veta)
    exprs = [sp.Integer(0), spin * sp.cos(beta_0), spin * sp.sin(beta_0), xi_, eta_, vxi, veta]
    args = (tau, Omega_0, beta_0) + PARAMS
    return args, exprs, args[1:], [sol["t_1"]]


@lru_cache(maxsize=None)
def _rolling(modules: str):
    args, exprs, end_args, (end,) = rolling_forms()
    return sp.lambdify(args, exprs, modules), sp.lambdify(end_args, end, modules)


def rolling(params: Coefficients, Omega0, beta0, num=float):
    """n°7 from the rotation Ω0 at β0: (duration or None when δ = 0, τ ↦ Local)."""
    fn, end = _rolling(_modules(num))
    P = params.values(num)
    duration = None if params.delta == 0 else end(Omega0, beta0, *P)
    return duration, lambda s: Local(*fn(s, Omega0, beta0, *P))


@lru_cache(maxsize=None)
def pivot_forms() -> tuple:
    """Eq. (5) from r₀ > 0: (args, [r] at τ, end args, [duration])."""
    sol = newton_euler.pivot_solution()
    return (tau, r_0) + PARAMS, [sol["r(t)"]], (r_0,) + PARAMS, [sol["t_1"]]


@lru_cache(maxsize=None)
def _pivot(modules: str):
    args, (r_of_t,), end_args, (end,) = pivot_forms()
    return sp.lambdify(args, r_of_t, modules), sp.lambdify(end_args, end, modules)


def pivot(params: Coefficients, r0, num=float):
    """Eq. (5): (duration or None when ε = 0 and r0 ≠ 0, τ ↦ r)."""
    if r0 == 0:
        return num(0), lambda s: num(0)
    fn, end = _pivot(_modules(num))
    P = params.values(num)
    sign = 1 if r0 > 0 else -1  # eq. (5) is odd in r
    if params.epsilon == 0:
        return None, lambda s: r0
    duration = end(sign * r0, *P)
    # Exactly 0 from t₁ on (the formula rounds to ±1 ulp there).
    return duration, lambda s: sign * fn(s, sign * r0, *P) if s < duration else num(0)

