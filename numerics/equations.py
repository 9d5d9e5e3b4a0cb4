"""The equations of motion as numeric right-hand sides, lambdified from derivation/ and reduction/.

Nothing here retypes a formula: each function takes the SymPy expression
the derivation holds and compiles it, for mpmath (the reference motion and
the claims' trajectory checks) or for floats.  The simulator does not use
this module at run time: `numerics.codegen` writes the same expressions
(``sliding_expressions``, ``slip_expressions``) into `numerics.kernels`.
The forms:

* ``sliding`` — the state the simulator integrates while the ball slides:
  the slip in polar form (V, α), the rotation in Cartesian form (p, q) so
  that Ω may pass near or through zero, and the centre (ξ, η).  When Ω = 0
  the rolling couple's direction is the one Ω leaves zero along, β = α + π/2
  (n°6).
* ``sliding_in_log_slip`` — the same with σ = −ln V as the variable, t a
  state: α' ∝ V^(κ−1) is singular in t at the end of sliding, d/dσ is smooth.
* ``cartesian`` — eqs. (4)–(6) in (ξ, η, ξ', η', p, q, r), and ``reduced`` —
  eq. (12) in (x, y, α, β): the paper's two forms, for the cross-checks;
* ``rolling_constrained`` — pure rolling with the friction solved from the
  no-slip constraint (not n°7's result), and ``pivot_rate`` — eq. (5).
"""

from __future__ import annotations

import math
from functools import lru_cache

import mpmath
import sympy as sp

from derivation import newton_euler, polar
from derivation.newton_euler import sign_r
from derivation.symbols import R, V, alpha, beta, d, delta, epsilon, eta, f, g, k, p, q, r, theta, u, v, xi
from reduction import n9_reduced_system
from reduction.variables import a, b, c
from reduction.variables import x as x_fn
from reduction.variables import y as y_fn

from numerics.scene import Coefficients
from numerics.validation import ComputationError


PARAMS = (f, R, k, delta, epsilon, g)
cb, sb = sp.symbols("cos_beta sin_beta", real=True)  # the unit vector of Ω = (p, q)
Vs, As, Ps, Qs = sp.symbols("V alpha p q", real=True)
ON_UNIT = {sp.cos(beta): cb, sp.sin(beta): sb}


def _modules(num):
    return "mpmath" if num is not float else "math"


@lru_cache(maxsize=None)
def sliding_expressions() -> dict[str, sp.Expr]:
    """V', Vα', p', q', ξ', η' in (V, α, p, q) and the unit vector (cos β, sin β)."""
    sl = polar.sliding()
    acc = newton_euler.accelerations()
    centre = newton_euler.centre_velocity()
    in_angles = {theta: beta - alpha}

    def plain(expr):
        expr = sp.expand(sp.expand_trig(expr.subs(in_angles))).subs(ON_UNIT)
        return expr.subs({V: Vs, alpha: As, p: Ps, q: Qs})

    slip = {u: V * sp.cos(alpha), v: V * sp.sin(alpha)}
    return {
        "V'": plain(sl["V'"]),
        "V alpha'": plain(sl["V alpha'"]),
        "p'": plain(acc[d(p)]),
        "q'": plain(acc[d(q)]),
        "xi'": plain(centre[d(xi)].subs(slip)),
        "eta'": plain(centre[d(eta)].subs(slip)),
    }


@lru_cache(maxsize=None)
def _compiled_sliding(modules: str):
    expr = sliding_expressions()
    args = (Vs, As, Ps, Qs, cb, sb) + PARAMS
    return {name: sp.lambdify(args, e, modules) for name, e in expr.items()}


def _unit_rotation(alpha_, p_, q_, num, orientation=None):
    """(cos β, sin β); at Ω = 0 the direction Ω leaves zero along, β = α + π/2 (n°6).

    With ``orientation`` (a unit vector), the unit vector is the one on its
    side: where Ω passes straight through zero along a line, this is the
    smooth continuation an integrator needs to step across the crossing and
    locate it as an event (the true direction flips there).
    """
    spin = (p_ * p_ + q_ * q_) ** num("0.5")
    if spin == 0:
        fn = mpmath if num is not float else math
        return -fn.sin(alpha_), fn.cos(alpha_)
    if orientation is not None and p_ * orientation[0] + q_ * orientation[1] < 0:
        spin = -spin
    return p_ / spin, q_ / spin


def sliding(params: Coefficients, num=float):
    """d/dt of [V, α, p, q, ξ, η] while the ball slides (V > 0)."""
    fns = _compiled_sliding(_modules(num))
    P = params.values(num)

    def rhs(t, y):
        V_, a_, p_, q_ = y[0], y[1], y[2], y[3]
        c_, s_ = _unit_rotation(a_, p_, q_, num)
        args = (V_, a_, p_, q_, c_, s_) + P
        return [
            fns["V'"](*args),
            fns["V alpha'"](*args) / V_,
            fns["p'"](*args),
            fns["q'"](*args),
            fns["xi'"](*args),
            fns["eta'"](*args),
        ]

    return rhs


def sliding_in_log_slip(params: Coefficients, num=float, orientation=None):
    """d/dσ of [t, α, p, q, ξ, η] with σ = −ln V: the whole slide, smooth up to its end.

    d/dσ = (V/|V'|) d/dt.  V' < −fg while sliding (n°8), so σ increases with t;
    V α' is bounded, so dα/dσ = V α'/|V'| stays finite where α' ∝ V^(κ−1)
    blows up at the end of sliding.
    """
    fns = _compiled_sliding(_modules(num))
    P = params.values(num)
    exp = mpmath.exp if num is not float else math.exp

    def rhs(sigma, y):
        V_ = exp(-sigma)
        a_, p_, q_ = y[1], y[2], y[3]
        c_, s_ = _unit_rotation(a_, p_, q_, num, orientation)
        args = (V_, a_, p_, q_, c_, s_) + P
        rate = fns["V'"](*args)
        if not rate < 0:  # V' < −fg(1 − δ/(fR)) under (9): never, unless (9) is broken or a value overflowed
            raise ComputationError(f"slide: the slip is not decreasing (V' = {float(rate):g} at V = {float(V_):g})")
        per_sigma = -V_ / rate
        return [
            per_sigma,
            -fns["V alpha'"](*args) / rate,
            per_sigma * fns["p'"](*args),
            per_sigma * fns["q'"](*args),
            per_sigma * fns["xi'"](*args),
            per_sigma * fns["eta'"](*args),
        ]

    return rhs


@lru_cache(maxsize=None)
def slip_expressions() -> dict:
    """(u, v) of eq. (2) in the centre's velocity (ξ', η'), p, q and R."""
    xd, ed = sp.symbols("xi_dot eta_dot", real=True)
    slip = newton_euler.kinematics()["v_A"]
    return {"args": (xd, ed, Ps, Qs, R), "u, v": [slip[i].subs({d(xi): xd, d(eta): ed, p: Ps, q: Qs}) for i in (0, 1)]}


@lru_cache(maxsize=None)
def _compiled_cartesian(modules: str):
    """Eqs. (4)–(5) with the slip and rotation directions from the Cartesian state."""
    acc = newton_euler.accelerations()
    xd, ed = sp.symbols("xi_dot eta_dot", real=True)
    ca, sa = sp.symbols("cos_alpha sin_alpha", real=True)
    on = {sp.cos(alpha): ca, sp.sin(alpha): sa, **ON_UNIT}
    names = [d(xi, 2), d(eta, 2), d(p), d(q), d(r)]
    args = (ca, sa, cb, sb, sign_r) + PARAMS
    exprs = [acc[n].subs(on) for n in names]
    slip = newton_euler.kinematics()["v_A"]
    slip_args = (xd, ed, Ps, Qs) + PARAMS
    slip_expr = [slip[i].subs({d(xi): xd, d(eta): ed, p: Ps, q: Qs}) for i in (0, 1)]
    return sp.lambdify(args, exprs, modules), sp.lambdify(slip_args, slip_expr, modules)


def cartesian(params: Coefficients, num=float):
    """d/dt of [ξ, η, ξ', η', p, q, r]: eqs. (4)–(5), slip (u, v) from eq. (2). Valid while V > 0, Ω > 0."""
    acc, slip = _compiled_cartesian(_modules(num))
    P = params.values(num)

    def rhs(t, y):
        _, _, xd, ed, p_, q_, r_ = y
        u_, v_ = slip(xd, ed, p_, q_, *P)
        V_ = (u_ * u_ + v_ * v_) ** num("0.5")
        spin = (p_ * p_ + q_ * q_) ** num("0.5")
        s_r = (r_ > 0) - (r_ < 0)
        xdd, edd, pd, qd, rd = acc(u_ / V_, v_ / V_, p_ / spin, q_ / spin, s_r, *P)
        return [xd, ed, xdd, edd, pd, qd, rd]

    return rhs


@lru_cache(maxsize=None)
def _compiled_reduced(modules: str):
    red = n9_reduced_system.reduced_rates()
    xs, ys = sp.symbols("x y", positive=True)
    on = {x_fn: xs, y_fn: ys, theta: beta - alpha}
    plain = {alpha: As, beta: sp.Symbol("beta", real=True)}
    exprs = [red["x'"], red["y'"], red["x alpha'"] / x_fn, red["y beta'"] / y_fn]
    exprs = [e.subs(on).subs(plain) for e in exprs]
    return sp.lambdify((xs, ys, As, sp.Symbol("beta", real=True), a, b, c), exprs, modules)


@lru_cache(maxsize=None)
def _compiled_constants(modules: str):
    consts = n9_reduced_system.constants()
    return sp.lambdify(PARAMS, [consts[sym] for sym in (a, b, c)], modules)


def constants_abc(params: Coefficients, num=float) -> tuple:
    """(a, b, c) of n°9 for these parameters."""
    return tuple(_compiled_constants(_modules(num))(*params.values(num)))


def reduced(params: Coefficients, num=float):
    """d/dt of [x, y, α, β]: eq. (12), with a, b, c from the derivation."""
    fn = _compiled_reduced(_modules(num))
    abc = constants_abc(params, num)
    return lambda t, y: fn(*y, *abc)


def slip_velocity(params: Coefficients, xi_dot, eta_dot, p_, q_, num=float) -> tuple:
    """(u, v) from the centre's velocity and the rotation: eq. (2)."""
    _, slip = _compiled_cartesian(_modules(num))
    return tuple(slip(xi_dot, eta_dot, p_, q_, *params.values(num)))


def centre_velocity(params: Coefficients, V_, alpha_, p_, q_, num=float) -> tuple:
    """(ξ', η') from the slip (V, α) and the rotation (p, q): eq. (2) solved for the centre."""
    fns = _compiled_sliding(_modules(num))
    args = (V_, alpha_, p_, q_, num(0), num(0)) + params.values(num)
    return fns["xi'"](*args), fns["eta'"](*args)


@lru_cache(maxsize=None)
def _rolling_expressions() -> list:
    """Pure rolling without n°7's result: p', q' and the friction (X, Y)/(mg) solved from the constraint u' = v' = 0."""
    from derivation.newton_euler import L, M, X, Y

    contact = newton_euler.contact_acceleration()
    eqs = newton_euler.equations_of_motion()
    couple = newton_euler.rolling_couple()
    on_couple = {L: couple[0], M: couple[1]}
    friction = sp.solve([contact["m u' generic"].subs(on_couple), contact["m v' generic"].subs(on_couple)], [X, Y], dict=True)[0]
    rotation = [sp.solve(e.subs(on_couple).subs(friction), d(w))[0] for e, w in zip(eqs["rotation"][:2], (p, q))]
    m_ = sp.Symbol("m", positive=True)
    return [sp.expand(e).subs(ON_UNIT) for e in rotation] + [
        sp.simplify(friction[X] / (m_ * g)).subs(ON_UNIT),
        sp.simplify(friction[Y] / (m_ * g)).subs(ON_UNIT),
    ]


@lru_cache(maxsize=None)
def _compiled_rolling(modules: str):
    return sp.lambdify((cb, sb) + PARAMS, _rolling_expressions(), modules)


def rolling_constrained(params: Coefficients, num=float, orientation=None):
    """d/dt of [ξ, η, p, q] in pure rolling, and the friction over mg needed (X, Y)/(mg).

    Returns (rhs, friction): the centre moves as ξ' = qR, η' = −pR (eq. (2), u = v = 0).
    ``orientation``: as in `_unit_rotation`, to step across Ω = 0 and locate it.
    """
    fn = _compiled_rolling(_modules(num))
    P = params.values(num)
    R_ = num(params.R)

    def unit(y):
        spin = (y[2] * y[2] + y[3] * y[3]) ** num("0.5")
        if spin == 0 and orientation is not None:
            return orientation
        if orientation is not None and y[2] * orientation[0] + y[3] * orientation[1] < 0:
            spin = -spin
        return y[2] / spin, y[3] / spin

    def rhs(t, y):
        pd, qd, _, _ = fn(*unit(y), *P)
        return [y[3] * R_, -y[2] * R_, pd, qd]

    def friction(y):
        _, _, X_, Y_ = fn(*unit(y), *P)
        return X_, Y_

    return rhs, friction


@lru_cache(maxsize=None)
def _compiled_pivot(modules: str):
    return sp.lambdify((sign_r,) + PARAMS, newton_euler.accelerations()[d(r)], modules)


def pivot_rate(params: Coefficients, num=float, sign=None):
    """d/dt of [r]: eq. (5), the couple opposing r (r' = 0 once r = 0).

    ``sign`` fixes sgn r (the sign r starts with): the smooth continuation
    past r = 0 that an integrator steps across to locate the stop.
    """
    fn = _compiled_pivot(_modules(num))
    P = params.values(num)
    if sign is not None:
        return lambda t, y: [fn(sign, *P)]
    return lambda t, y: [fn((y[0] > 0) - (y[0] < 0), *P)]


# The same expressions for the Taylor integrator (`numerics.taylor`), which generates the
# recurrences of their Taylor coefficients.  (cos β, sin β) = (p, q)/Ω with the principal
# root: its analytic continuation is what `_unit_rotation`'s ``orientation`` emulates, so a
# Taylor step crosses Ω = 0 along a line as the GBS steps do.
Sigma, Ts, Xis, Etas = sp.symbols("sigma t_ xi_ eta_", real=True)


def _unit_from_spin() -> dict:
    spin = sp.sqrt(Ps**2 + Qs**2)
    return {cb: Ps / spin, sb: Qs / spin}


@lru_cache(maxsize=None)
def log_slip_rates() -> tuple:
    """(σ, state [t, α, p, q, ξ, η], d/dσ of the state): `sliding_in_log_slip` in SymPy, V = e^(−σ)."""
    expr = sliding_expressions()
    on = {Vs: sp.exp(-Sigma), **_unit_from_spin()}
    rate = {name: e.subs(on) for name, e in expr.items()}
    per_sigma = -sp.exp(-Sigma) / rate["V'"]
    rates = [per_sigma, -rate["V alpha'"] / rate["V'"]] + [per_sigma * rate[n] for n in ("p'", "q'", "xi'", "eta'")]
    return Sigma, (Ts, As, Ps, Qs, Xis, Etas), rates


@lru_cache(maxsize=None)
def log_slip_taylor():
    """`log_slip_rates` as a generated Taylor-coefficient function (`numerics.taylor.Generated`)."""
    from numerics import taylor

    sigma, state, rates = log_slip_rates()
    return taylor.generate(rates, state, PARAMS, indep=sigma, name="log_slip_coefficients")


@lru_cache(maxsize=None)
def rolling_rates() -> tuple:
    """(state [ξ, η, p, q], d/dt of it): `rolling_constrained` in SymPy, the centre from eq. (2) with u = v = 0."""
    centre = newton_euler.centre_velocity()
    plain = {u: 0, v: 0, p: Ps, q: Qs}
    unit = _unit_from_spin()
    pd, qd = (e.subs(unit) for e in _rolling_expressions()[:2])
    return (Xis, Etas, Ps, Qs), [centre[d(xi)].subs(plain), centre[d(eta)].subs(plain), pd, qd]


@lru_cache(maxsize=None)
def rolling_taylor():
    from numerics import taylor

    state, rates = rolling_rates()
    return taylor.generate(rates, state, PARAMS, name="rolling_coefficients")
