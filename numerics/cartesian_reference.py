"""A second mpmath route for a scene: the Cartesian equations (4)–(6) in t, with their own end of sliding.

The reference (`reference_motion`) integrates the slide in σ = −ln V, where
everything is smooth up to V = 0.  This route does not: it integrates
(ξ, η, ξ', η', p, q, r) in t with the Taylor integrator (`numerics.taylor`,
the recurrences generated from `newton_euler.accelerations` with the slip
(u, v) of eq. (2) and cos α = u/V, sin α = v/V, cos β = p/Ω, sin β = q/Ω),
up to the time the slip speed has fallen to about V₁ = V₀·``end_fraction``
(an event on the slip's component along its recent direction).  There the solution is not analytic in t: the slip
turns as V^κ, κ = Rδ/(f(R² + k²) − Rδ), so the last stretch is a local
expansion of its own (`tail`): first order in V, exact in the turning of the
slip.  Its neglected terms are O(V₁²) (the drift of β and Ω over a time
V₁/(a − c)), hence the default V₁/V₀ = 10^−(digits/2 + 2).

Then pure rolling until Ω = 0 and the pivot until r = 0 in closed form
(`roll`, `pivot`: n°7's Ω' = −δg/(R² + k²) along a fixed direction, the
centre at ξ' = Rq, η' = −Rp by eq. (2) with no slip; eq. (5)'s r' = −εg/k²),
where the reference integrates the constrained rolling and the pivot: the two
routes share no code after the equations of motion.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from functools import lru_cache

import mpmath
import sympy as sp

from derivation import newton_euler
from derivation.newton_euler import sign_r
from derivation.symbols import alpha, beta, d, eta, p, q, r, xi
from numerics import equations, taylor
from numerics.equations import PARAMS
from numerics.scene import Coefficients
from numerics.reference import Stats
from numerics.reference import integrate as gbs_integrate
from numerics.scene import Scene

XI, ETA, XID, ETAD, P, Q, RR = range(7)
ESCAPE = mpmath.mpf("0.05")  # the GBS stretch off Ω = 0, as a fraction of the time left to slide
_state = sp.symbols("xi_c eta_c xid_c etad_c p_c q_c r_c", real=True)
_theta = sp.Symbol("theta_c", real=True)


@lru_cache(maxsize=None)
def rates() -> tuple:
    """(state, d/dt of [ξ, η, ξ', η', p, q, r]) in SymPy: eqs. (4)–(5), the slip from eq. (2)."""
    xs, es, xd, ed, ps, qs, rs = _state
    acc = newton_euler.accelerations()
    on_state = {d(xi): xd, d(eta): ed, p: ps, q: qs, r: rs}
    u_, v_, _ = (c.subs(on_state) for c in newton_euler.kinematics()["v_A"])
    slip, spin = sp.sqrt(u_**2 + v_**2), sp.sqrt(ps**2 + qs**2)
    unit = {sp.cos(alpha): u_ / slip, sp.sin(alpha): v_ / slip, sp.cos(beta): ps / spin, sp.sin(beta): qs / spin}
    rhs = [xd, ed] + [acc[n].subs(unit).subs(on_state) for n in (d(xi, 2), d(eta, 2), d(p), d(q), d(r))]
    return _state, rhs


@lru_cache(maxsize=None)
def jets() -> taylor.Generated:
    state, rhs = rates()
    return taylor.generate(rhs, state, PARAMS + (sign_r,), name="cartesian_coefficients")


@lru_cache(maxsize=None)
def tail_coefficients() -> dict:
    """The slide's rates near its end, read off (4)–(6) as functions of θ = β − α.

    V' = −a + c sin θ and V α' = −c cos θ with constants a, c (checked here,
    not assumed); p' and q' are linear in (cos α, sin α) with coefficients in
    β: returned as SymPy expressions in (cos β, sin β) and PARAMS.
    """
    ca, sa = sp.symbols("cos_alpha_c sin_alpha_c", real=True)
    contact = newton_euler.contact_acceleration()
    acc = newton_euler.accelerations()
    on = {sp.cos(alpha): ca, sp.sin(alpha): sa, **equations.ON_UNIT}
    du, dv = (sp.expand(contact[k]).subs(on) for k in ("u' (6)", "v' (6)"))
    V_rate, turn = ca * du + sa * dv, ca * dv - sa * du  # V' and V α' from (u, v) = V (cos α, sin α)
    # cos α = cos(β − θ), sin α = sin(β − θ): in θ alone once (cos β, sin β) is a unit vector.
    cb, sb = equations.cb, equations.sb
    in_theta = {ca: cb * sp.cos(_theta) + sb * sp.sin(_theta), sa: sb * sp.cos(_theta) - cb * sp.sin(_theta)}

    def plain(e):
        e = sp.expand(e.subs(in_theta)).subs(sb**2, 1 - cb**2)
        return sp.simplify(sp.expand(e))

    V_rate, turn = plain(V_rate), plain(turn)
    a = -V_rate.subs(_theta, 0)
    c = sp.simplify(V_rate.subs(_theta, sp.pi / 2) + a)
    assert sp.simplify(V_rate - (-a + c * sp.sin(_theta))) == 0, V_rate
    assert sp.simplify(turn + c * sp.cos(_theta)) == 0, turn
    out = {"a": a, "c": c}
    for name, key in (("p'", d(p)), ("q'", d(q))):
        e = sp.expand(acc[key].subs(on))
        lin = {"cos": e.coeff(ca), "sin": e.coeff(sa)}
        rest = sp.expand(e - lin["cos"] * ca - lin["sin"] * sa)
        assert not ({ca, sa} & (rest.free_symbols | lin["cos"].free_symbols | lin["sin"].free_symbols))
        out[name] = (rest, lin["cos"], lin["sin"])
    return out


@lru_cache(maxsize=None)
def _tail_compiled():
    tc = tail_coefficients()
    args = (equations.cb, equations.sb) + PARAMS
    compile_ = lambda e: sp.lambdify(args, e, "mpmath")  # noqa: E731
    return {k: (tuple(map(compile_, v)) if isinstance(v, tuple) else compile_(v)) for k, v in tc.items()}


def tail(params: Coefficients, y: list, num=mpmath.mpf) -> tuple:
    """The end of the slide from a small slip: (Δt, p, q, ξ, η, r rate × Δt) when V reaches 0.

    β frozen (its drift over the tail is O(V₁)), the slip angle φ = α − β + π/2
    obeys V φ' = −c sin φ and V' = −a + c cos φ exactly, so with μ = ln tan(φ/2)
    V = K e^{(a/c)μ} cosh μ and dt = −V dμ/c: the integrals of 1, cos φ and
    sin φ over the rest of the slide are elementary,
        Δt  = V₁/2 · [(1 − cos φ₁)/(a + c) + (1 + cos φ₁)/(a − c)],
        ∫cos φ dt = V₁/2 · [(1 + cos φ₁)/(a − c) − (1 − cos φ₁)/(a + c)],
        ∫sin φ dt = V₁ sin φ₁ / a,
    and p', q' (linear in cos α, sin α, α = β − π/2 + φ) integrate term by term.
    Errors O(V₁²).
    """
    fns = _tail_compiled()
    P_ = params.values(num)
    u_, v_ = equations.slip_velocity(params, y[XID], y[ETAD], y[P], y[Q], num)
    V1 = mpmath.sqrt(u_**2 + v_**2)
    spin = mpmath.sqrt(y[P] ** 2 + y[Q] ** 2)
    cb, sb = y[P] / spin, y[Q] / spin
    ca, sa = u_ / V1, v_ / V1
    # φ = α − β + π/2: cos φ = sin(β − α), sin φ = cos(β − α).
    cos_phi, sin_phi = sb * ca - cb * sa, cb * ca + sb * sa
    a, c = fns["a"](cb, sb, *P_), fns["c"](cb, sb, *P_)
    dt = V1 / 2 * ((1 - cos_phi) / (a + c) + (1 + cos_phi) / (a - c))
    int_cos_phi = V1 / 2 * ((1 + cos_phi) / (a - c) - (1 - cos_phi) / (a + c))
    int_sin_phi = V1 * sin_phi / a
    # cos α = sin(β + φ), sin α = −cos(β + φ).
    int_cos_a = sb * int_cos_phi + cb * int_sin_phi
    int_sin_a = -cb * int_cos_phi + sb * int_sin_phi
    ends = []
    for name, start in (("p'", y[P]), ("q'", y[Q])):
        rest, k_cos, k_sin = fns[name]
        ends.append(start + rest(cb, sb, *P_) * dt + k_cos(cb, sb, *P_) * int_cos_a + k_sin(cb, sb, *P_) * int_sin_a)
    # The centre moves at ξ', η' (changing by O(V₁) over the tail): O(V₁²) dropped.
    return dt, ends[0], ends[1], y[XI] + y[XID] * dt, y[ETA] + y[ETAD] * dt


@dataclass
class CartesianMotion:
    digits: int
    t_slide_end: object
    slide_end: dict | None  # p, q, xi, eta, alpha (β − π/2) at the end of the slide
    t_roll_end: object | None
    rest: tuple | None
    t_pivot_end: object | None
    stats: Stats = field(default_factory=Stats)
    end_fraction: object = None


def _escape_rhs(params: Coefficients, s_r, orientation):
    """d/dt of the state for GBS where Ω = 0: the direction Ω leaves zero along (n°6), else (p, q)/Ω."""
    acc, slip = equations._compiled_cartesian("mpmath")
    P_ = params.values(mpmath.mpf)

    def rhs(t, y):
        u_, v_ = slip(y[XID], y[ETAD], y[P], y[Q], *P_)
        V_ = mpmath.sqrt(u_**2 + v_**2)
        cb, sb = equations._unit_rotation(mpmath.atan2(v_, u_), y[P], y[Q], mpmath.mpf, orientation)
        return [y[XID], y[ETAD]] + list(acc(u_ / V_, v_ / V_, cb, sb, s_r, *P_))

    return rhs


def slide(params: Coefficients, y0: list, tol, end_fraction, stats: Stats):
    """The Cartesian slide from the state y0 (V > 0): (t at V₁, state there)."""
    num = mpmath.mpf
    slip = lambda y: equations.slip_velocity(params, y[XID], y[ETAD], y[P], y[Q], num)  # noqa: E731
    u_, v_ = slip(y0)
    V1 = mpmath.sqrt(u_**2 + v_**2) * end_fraction
    gen = jets()
    t, y = num(0), list(y0)
    spin_scale = max(mpmath.sqrt(y[P] ** 2 + y[Q] ** 2), num(1))

    def s_r(y):
        return (y[RR] > 0) - (y[RR] < 0)

    while True:
        sign = s_r(y)
        jet = gen.bind(params.values(num) + (num(sign),))
        # The slip's component along its direction at (re)start, not |V|: u² + v² − V₁² has a
        # double root where the slip passes straight through zero (a straight shot), which a
        # step can jump over; the component changes sign.  A restart when the slip has turned
        # 60° keeps the component within [V/2, V], so the hand-over is at V₁ ≤ V ≤ 2V₁.
        V_ = mpmath.sqrt(u_**2 + v_**2)
        slip_ref = (u_ / V_, v_ / V_)
        ahead = lambda t_, y_: sum(a * b for a, b in zip(slip(y_), slip_ref))  # noqa: E731
        slow = lambda t_, y_: ahead(t_, y_) - V1  # noqa: E731
        slip_turned = lambda t_, y_: ahead(t_, y_) - mpmath.sqrt(sum(x**2 for x in slip(y_))) / 2  # noqa: E731
        spin = mpmath.sqrt(y[P] ** 2 + y[Q] ** 2)
        ref = (y[P] / spin, y[Q] / spin) if spin else (-slip_ref[1], slip_ref[0])  # n°6: β = α + π/2
        along = lambda t_, y_: y_[P] * ref[0] + y_[Q] * ref[1]  # noqa: E731
        turned = lambda t_, y_: along(t_, y_) - mpmath.sqrt(y_[P] ** 2 + y_[Q] ** 2) / 2  # noqa: E731
        events = [slow, along, turned, slip_turned] + ([lambda t_, y_: y_[RR]] if sign else [])
        if spin:
            out = taylor.integrate(jet, t, y, mpmath.inf, tol, events=events, stats=stats)
        else:
            # (p, q)/Ω is 0/0: a short GBS stretch with n°6's direction, then Taylor again.
            u_, v_ = slip(y)
            t_left = mpmath.sqrt(u_**2 + v_**2) / (params.f * params.g)
            out = gbs_integrate(_escape_rhs(params, sign, ref), t, y, t + ESCAPE * t_left, tol, events=events, num=num, stats=stats)
        t, y = out.t, out.y
        if out.event == 0:
            return t, y
        if out.event in (1, 2) and mpmath.sqrt(y[P] ** 2 + y[Q] ** 2) <= 1000 * tol * spin_scale:
            y[P], y[Q] = num(0), num(0)  # through zero along a line: n°6 from here
        if out.event == 4:
            y[RR] = num(0)  # the pivot has stopped: r' = 0 from here (eq. (5))
        u_, v_ = slip(y)


def reference(scene: Scene, digits: int = 30, end_fraction=None) -> CartesianMotion:
    """The scene by the Cartesian route, at about ``digits`` digits (``end_fraction``: V₁/V₀)."""
    num = mpmath.mpf
    with mpmath.workdps(digits + 10):
        tol = num(10) ** (-digits - 2)
        end_fraction = num(10) ** (-(digits // 2) - 2) if end_fraction is None else num(end_fraction)
        P_, s = scene.params, scene.state
        P_slide = dataclasses.replace(P_, delta=0.0) if scene.model == "classical" else P_
        y = [num(x) for x in (s.xi, s.eta, s.vxi, s.veta, s.p, s.q, s.r)]
        u_, v_ = equations.slip_velocity(P_, y[XID], y[ETAD], y[P], y[Q], num)
        out = CartesianMotion(digits, num(0), None, None, None, None, end_fraction=end_fraction)
        start, t_roll = [y[XI], y[ETA], y[P], y[Q]], num(0)
        if u_ or v_:
            t1, y1 = slide(P_slide, y, tol, end_fraction, out.stats)
            dt, p_end, q_end, xi_end, eta_end = tail(P_slide, y1, num)
            out.t_slide_end = t1 + dt
            alpha_end = mpmath.atan2(q_end, p_end) - mpmath.pi / 2
            out.slide_end = {"p": p_end, "q": q_end, "xi": xi_end, "eta": eta_end, "alpha": alpha_end}
            start, t_roll = [xi_end, eta_end, p_end, q_end], out.t_slide_end
        out.t_roll_end, out.rest = roll(P_, start, t_roll)
        out.t_pivot_end = pivot(P_, num(s.r))
        return out


def roll(params: Coefficients, start, t0):
    """Pure rolling from ``start`` = [ξ, η, p, q] at ``t0`` until Ω = 0, in closed form: (end time, rest point).

    n°7: Ω decreases at δg/(R² + k²), its direction fixed; the centre moves at (ξ', η') = R(q, −p) (eq. (2), no
    slip), so it travels R Ω₁² (R² + k²)/(2δg) along (q, −p)/Ω₁.  With δ = 0 it rolls for ever: (None, None)."""
    num = mpmath.mpf
    xi_, eta_, p_, q_ = start
    spin = mpmath.sqrt(p_**2 + q_**2)
    if spin == 0:
        return t0, (xi_, eta_)
    if params.delta == 0:
        return None, None
    R, k, g, delta = num(params.R), num(params.k), num(params.g), num(params.delta)
    duration = spin * (R**2 + k**2) / (delta * g)
    reach = R * duration / 2  # R ∫Ω dt over the roll, per unit of Ω₁ (Ω falls linearly to 0)
    return t0 + duration, (xi_ + reach * q_, eta_ - reach * p_)


def pivot(params: Coefficients, r0):
    """The end of the pivot in closed form, eq. (5): r' = −εg sgn(r)/k², so |r₀| k²/(εg); None if ε = 0 (r ≠ 0)."""
    num = mpmath.mpf
    if r0 == 0:
        return num(0)
    if params.epsilon == 0:
        return None
    return abs(r0) * num(params.k) ** 2 / (num(params.epsilon) * num(params.g))
