"""Every closed form and relation of n°3–n°10 checked along trajectories integrated at high precision.

The trajectories come from the equations of motion only: eqs. (4)–(6) in
Cartesian form (`equations.cartesian`), eq. (12) in the reduced form, pure
rolling with the friction solved from the no-slip constraint, eq. (5) for
the pivot, and the slide in σ = −ln V up to V = 0 (`sliding.slide`).  The
closed forms they are compared with are compiled from derivation/ (through
`phases`); nothing is retyped.  Each check returns the decimal digits of the
worst relative disagreement and the number of cases (trajectory points).
"""

from __future__ import annotations

import math
from functools import lru_cache

import mpmath
import sympy as sp

from derivation import n4_ideal, n8_general
from derivation.checks import worst_of
from derivation.claim import Margin, NumericCheck
from derivation.newton_euler import sign_r
from derivation.symbols import Omega, Omega_0, V, V_0, alpha_0, m, r, t
from numerics import equations, phases, sliding
from numerics.equations import PARAMS
from numerics.scene import Coefficients, Params
from numerics.reference import integrate

DIGITS = 30
mpf = mpmath.mpf

# A pool ball, and the same with a large rolling coefficient (δ = 0.3 fR) so that δ matters.
POOL = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575, k=0.028575 * math.sqrt(0.4))
HEAVY = Params(f=0.2, delta=0.3 * 0.2 * 0.028575, epsilon=0.0003, R=0.028575, k=0.028575 * math.sqrt(0.4))
# Cartesian starts [ξ, η, ξ', η', p, q, r]: a curved draw with side spin, a massé, a follow with english.
SHOTS = (
    (0.0, 0.0, 2.0, 0.0, 10.0, -40.0, 5.0),
    (0.1, -0.2, 0.3, 0.4, 150.0, -90.0, -20.0),
    (0.0, 0.0, 1.5, -0.5, 30.0, 60.0, 12.0),
)


def _digits(worst) -> float:
    return float(-mpmath.log10(worst)) if worst > 0 else float(DIGITS + 10)


def _slip(P: Coefficients, state):
    u, v = equations.slip_velocity(P, state[2], state[3], state[4], state[5], mpf)
    return mpmath.sqrt(u**2 + v**2), mpmath.atan2(v, u)


def _times(t_end, n: int = 6) -> list:
    """n times spread over (0, t_end), not evenly (so no two cases share a step pattern)."""
    return [t_end * mpf(j) ** 1.5 / mpf(n + 1) ** 1.5 for j in range(1, n + 1)]


def _tol():
    return mpf(10) ** (-DIGITS - 2)


@lru_cache(maxsize=None)
def cartesian_run(P: Coefficients, start: tuple, fraction: float = 0.8) -> tuple[list, list]:
    """Eqs. (4)–(6) from ``start`` over ``fraction`` of the slide (the Cartesian form is singular at V = 0).

    |V'| ≤ g(f(1 + R²/k²) + Rδ/k²) by (7), so the slide lasts at least
    V₀ over that; the times are a fraction of it.  The starts keep r away
    from 0 (sgn r jumps there).  Returns (times, states) at DIGITS + 10 working digits.
    """
    with mpmath.workdps(DIGITS + 10):
        V0, _ = _slip(P, [mpf(x) for x in start])
        f_, g_, R_, k_, d_ = (mpf(x) for x in (P.f, P.g, P.R, P.k, P.delta))
        t_end = fraction * V0 / (g_ * (f_ * (1 + R_**2 / k_**2) + R_ * d_ / k_**2))
        times = _times(t_end)
        out = integrate(equations.cartesian(P, mpf), 0, [mpf(x) for x in start], t_end, _tol(), times=times, num=mpf)
        return times, out.states


def _world(local: phases.Local, alpha0, xi0, eta0) -> list:
    """A closed-form state in the slip frame, in the world frame: [ξ, η, ξ', η', p, q]."""
    c, s = mpmath.cos(alpha0), mpmath.sin(alpha0)
    rot = lambda x, y: (x * c - y * s, x * s + y * c)  # noqa: E731
    xi, eta = rot(local.xi, local.eta)
    return [xi0 + xi, eta0 + eta, *rot(local.vxi, local.veta), *rot(local.p, local.q)]


def _worst_state_error(exact: list, computed: list, scale: list):
    return max(abs(x - y) / s for x, y, s in zip(exact, computed, scale))


def _scale(P: Coefficients, start) -> list:
    """Per component: the size against which an error is relative (lengths by R, rates by the start's)."""
    speed = max(abs(mpf(start[2])), abs(mpf(start[3])), mpf(P.R) * abs(mpf(start[4])), mpf(P.R) * abs(mpf(start[5])))
    return [mpf(P.R), mpf(P.R), speed, speed, speed / mpf(P.R), speed / mpf(P.R)]


def n3_closed_form() -> tuple[float, int]:
    """n°3 (δ = 0): V, p, q, ξ, η, ξ', η' of the closed form against eqs. (4)–(6) integrated."""
    P = Params(POOL.f, 0.0, POOL.epsilon, POOL.R, POOL.k)
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for start in SHOTS:
            times, states = cartesian_run(P, start)
            V0, alpha0 = _slip(P, [mpf(x) for x in start])
            Omega0, beta0 = mpmath.hypot(start[4], start[5]), mpmath.atan2(start[5], start[4])
            _, local = phases.classical_slide(P, V0, Omega0, beta0 - alpha0, num=mpf)
            for tt, state in zip(times, states):
                exact = _world(local(tt), alpha0, mpf(start[0]), mpf(start[1]))
                worst = worst_of(worst, _worst_state_error(exact, state[:6], _scale(P, start)))
                cases += 1
    return _digits(worst), cases


def n4_closed_form() -> tuple[float, int]:
    """n°4 (f = 0): Ω, u, v, ξ', η' of the closed form against eqs. (4)–(6) integrated (Ω along the axis Oξ)."""
    sol = n4_ideal.motion()
    names = ("Omega", "u", "v", "xi'", "eta'")
    fn = sp.lambdify((t, V_0, alpha_0, Omega_0) + PARAMS, [sol[n] for n in names], "mpmath")
    P = Coefficients(0.0, HEAVY.delta, HEAVY.epsilon, HEAVY.R, HEAVY.k)
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for vxi, veta, Omega0 in (("1.0", "0.2", "20"), ("0.3", "-0.8", "60")):
            start = [mpf(0), mpf(0), mpf(vxi), mpf(veta), mpf(Omega0), mpf(0), mpf(3)]
            V0, alpha0 = _slip(P, start)
            t_end = mpf(Omega0) * mpf(P.k) ** 2 / (mpf(P.delta) * mpf(P.g)) / 2  # half-way to Ω = 0
            times = _times(t_end)
            states = integrate(equations.cartesian(P, mpf), 0, start, t_end, _tol(), times=times, num=mpf).states
            for tt, s in zip(times, states):
                Om, u_, v_, xd, ed = fn(tt, V0, alpha0, mpf(Omega0), *P.values(mpf))
                uc, vc = equations.slip_velocity(P, s[2], s[3], s[4], s[5], mpf)
                computed, exact = [s[4], s[5], uc, vc, s[2], s[3]], [Om, 0, u_, v_, xd, ed]
                scale = mpf(Omega0) * mpf(P.R)
                worst = worst_of(worst, max(abs(a_ - b_) for a_, b_ in zip(computed, exact)) / scale)
                cases += 1
    return _digits(worst), cases


def n7_closed_form() -> tuple[float, int]:
    """n°7: pure rolling with the friction solved from the constraint against the closed form; its f₁."""
    from derivation import n7_pure_rolling

    f1 = sp.lambdify(PARAMS, n7_pure_rolling.motion()["f_1"], "mpmath")
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for Omega0, beta0 in (("40", "0.3"), ("7", "-2.5")):
                Omega0, beta0 = mpf(Omega0), mpf(beta0)
                t_1, local = phases.rolling(P, Omega0, beta0, num=mpf)
                start = [mpf(0), mpf(0), Omega0 * mpmath.cos(beta0), Omega0 * mpmath.sin(beta0)]
                rhs, friction = equations.rolling_constrained(P, mpf)
                times = _times(t_1)
                states = integrate(rhs, 0, start, times[-1], _tol(), times=times, num=mpf).states
                for tt, s in zip(times, states):
                    ex = local(tt)
                    R_ = mpf(P.R)
                    errs = [abs(s[0] - ex.xi) / R_, abs(s[1] - ex.eta) / R_, abs(s[2] - ex.p) / Omega0, abs(s[3] - ex.q) / Omega0]
                    X, Y = friction(s)
                    f1_value = f1(*P.values(mpf))
                    errs.append(abs(mpmath.hypot(X, Y) - f1_value) / f1_value)
                    worst = worst_of(worst, *errs)
                    cases += 1
    return _digits(worst), cases


def pivot_closed_form() -> tuple[float, int]:
    """Eq. (5) integrated to its event r = 0 against r(t) and the stopping time k² r₀/(εg)."""
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for r0 in (mpf(25), mpf(-3)):
                t_1, r_of = phases.pivot(P, r0, num=mpf)
                sign = 1 if r0 > 0 else -1
                times = _times(t_1)
                out = integrate(
                    equations.pivot_rate(P, mpf, sign), 0, [r0], 2 * t_1, _tol(), times=times,
                    events=[lambda s, y: y[0]], num=mpf,
                )
                errs = [abs(state[0] - r_of(tt)) / abs(r0) for tt, state in zip(times, out.states)]
                worst = worst_of(worst, abs(out.t - t_1) / t_1, *errs)
                cases += len(errs) + 1
    return _digits(worst), cases


@lru_cache(maxsize=None)
def _relation(name: str):
    return sp.lambdify((t, V_0, Omega_0) + PARAMS, n8_general.relations()[name], "mpmath")


def _polar(P: Coefficients, state) -> tuple:
    """(V, Ω, α, β) of a Cartesian state."""
    V_, alpha_ = _slip(P, state)
    return V_, mpmath.hypot(state[4], state[5]), alpha_, mpmath.atan2(state[5], state[4])


def integral_11() -> tuple[float, int]:
    """(11): fV − δΩ is linear in t, with the slope of n°8, along eqs. (4)–(6)."""
    fn = _relation("fV - delta Omega")
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for start in SHOTS:
                times, states = cartesian_run(P, start)
                V0, Omega0, _, _ = _polar(P, [mpf(x) for x in start])
                scale = mpf(P.f) * V0 + mpf(P.delta) * Omega0
                for tt, s in zip(times, states):
                    V_, Om, _, _ = _polar(P, s)
                    value = mpf(P.f) * V_ - mpf(P.delta) * Om
                    worst = worst_of(worst, abs(value - fn(tt, V0, Omega0, *P.values(mpf))) / scale)
                    cases += 1
    return _digits(worst), cases


@lru_cache(maxsize=None)
def reduced_run(P: Coefficients, start: tuple) -> tuple[list, list]:
    """Eq. (12) in (x, y, α, β) from the Cartesian ``start``, at the times of `cartesian_run`."""
    times, _ = cartesian_run(P, start)
    with mpmath.workdps(DIGITS + 10):
        V0, Omega0, alpha0, beta0 = _polar(P, [mpf(x) for x in start])
        y0 = [mpf(P.f) * V0, mpf(P.delta) * Omega0, alpha0, beta0]
        out = integrate(equations.reduced(P, mpf), 0, y0, times[-1], _tol(), times=times, num=mpf)
        return times, out.states


def y_minus_x_linear() -> tuple[float, int]:
    """n°9: y − x = (a − c)t + const along eq. (12) integrated."""
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            a_, _, c_ = equations.constants_abc(P, mpf)
            for start in SHOTS:
                times, states = reduced_run(P, start)
                x0, y0 = _polar(P, [mpf(x) for x in start])[:2]
                x0, y0 = mpf(P.f) * x0, mpf(P.delta) * y0
                for tt, s in zip(times, states):
                    worst = worst_of(worst, abs((s[1] - s[0]) - (y0 - x0) - (a_ - c_) * tt) / (x0 + y0))
                    cases += 1
    return _digits(worst), cases


def cartesian_matches_reduced() -> tuple[float, int]:
    """Eqs. (4)–(6) and eq. (12), integrated separately from one start, agree on x = fV, y = δΩ, α, β."""
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for start in SHOTS:
                _, cart = cartesian_run(P, start)
                _, red = reduced_run(P, start)
                x0, y0 = _polar(P, [mpf(x) for x in start])[:2]
                scale = mpf(P.f) * x0 + mpf(P.delta) * y0
                for c_state, r_state in zip(cart, red):
                    V_, Om, al, be = _polar(P, c_state)
                    errs = [
                        abs(mpf(P.f) * V_ - r_state[0]) / scale,
                        abs(mpf(P.delta) * Om - r_state[1]) / scale,
                        abs(mpmath.sin(al - r_state[2])),
                        abs(mpmath.sin(be - r_state[3])),
                    ]
                    worst = worst_of(worst, *errs)
                    cases += 1
    return _digits(worst), cases


@lru_cache(maxsize=None)
def _power():
    """n°8's power of the loads per unit mass, in plain symbols (V, Ω, r, sgn r)."""
    Vs, Os, rs = sp.symbols("V Omega r", real=True)
    expr = n8_general.relations()["power"].subs({V: Vs, Omega: Os, r: rs, m: 1})
    return sp.lambdify((Vs, Os, rs, sign_r) + PARAMS, expr, "mpmath")


def energy() -> tuple[float, int]:
    """The energy equation: T(t) − T₀ (T₀ at the start) equals the work of the loads, n°8's power integrated with the motion.

    T = ½(ξ'² + η'² + k²(p² + q² + r²)) per unit mass from the Cartesian state;
    the work W is an extra state, W' = power(V, Ω, r), integrated with (4)–(6).
    Also: T never increases.
    """
    power = _power()
    worst, cases, increased = mpf(0), 0, False
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            motion = equations.cartesian(P, mpf)
            values = P.values(mpf)
            k2 = mpf(P.k) ** 2

            def rhs(tt, y, motion=motion, values=values):
                V_, Om = _polar(P, y)[:2]
                s_r = (y[6] > 0) - (y[6] < 0)
                return motion(tt, y[:7]) + [power(V_, Om, y[6], s_r, *values)]

            def kinetic(y, k2=k2):
                return (y[2] ** 2 + y[3] ** 2 + k2 * (y[4] ** 2 + y[5] ** 2 + y[6] ** 2)) / 2

            for start in SHOTS:
                times, _ = cartesian_run(P, start)
                y0 = [mpf(x) for x in start] + [mpf(0)]
                # Stop before r reaches 0: sgn r is discontinuous there.
                t_pivot = mpf(P.k) ** 2 * abs(y0[6]) / (mpf(P.epsilon) * mpf(P.g))
                times = [x for x in times if x < t_pivot]
                states = integrate(rhs, 0, y0, times[-1], _tol(), times=times, num=mpf).states
                T0, previous = kinetic(y0), kinetic(y0)
                for s in states:
                    worst = worst_of(worst, abs(kinetic(s) - T0 - s[7]) / T0)
                    increased |= kinetic(s) >= previous
                    previous = kinetic(s)
                    cases += 1
    return (0.0 if increased else _digits(worst)), cases


def product_decreases() -> tuple[Margin, int]:
    """n°8: |ΩV cos(β − α)| decreases along eqs. (4)–(6): its smallest relative drop between samples,
    against the integration's relative error 10^-DIGITS (negative if it ever increased)."""
    smallest, cases = mpf(1), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for start in SHOTS:
                times, states = cartesian_run(P, start)
                values = [abs(Om * V_ * mpmath.cos(be - al)) for V_, Om, al, be in (_polar(P, s) for s in states)]
                V0, O0, a0, b0 = _polar(P, [mpf(x) for x in start])
                values.insert(0, abs(O0 * V0 * mpmath.cos(b0 - a0)))
                for before, after in zip(values, values[1:]):
                    smallest = min(smallest, (before - after) / before)
                    cases += 1
    return Margin(float(smallest), 10.0**-DIGITS), cases


# The slide is followed down to V = 10^-200 V₀, where π/2 − θ ∝ V^κ is itself
# below 10^-10 (κ ≈ 0.05 for a pool ball): in σ = −ln V that is 460 units,
# a few dozen steps.
END_DECADES = 200
SLIDE_DIGITS = 20


@lru_cache(maxsize=None)
def reference_slide(P: Coefficients, start: tuple, digits: int = SLIDE_DIGITS):
    """The whole slide to V = 0 in σ = −ln V (mpmath), with Ω allowed through zero."""
    with mpmath.workdps(digits + 10):
        s = [mpf(x) for x in start]
        V0, alpha0 = _slip(P, s)
        return sliding.slide(
            P, V0, alpha0, s[4], s[5], s[0], s[1], tol=mpf(10) ** (-digits - 2), num=mpf,
            end_fraction=mpf(10) ** -END_DECADES, through_zero=True,
        )


def slide_time_bound() -> tuple[Margin, int]:
    """n°8: the slide ends before V₀/(fg): the smallest relative margin (t* − t_end)/t*, against the
    slide's relative error 10^-20 (`reference_slide`)."""
    bound = _relation("t bound")
    smallest, cases = mpf(1), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for start in SHOTS:
                sl = reference_slide(P, start)
                V0, _ = _slip(P, [mpf(x) for x in start])
                t_star = bound(0, V0, 0, *P.values(mpf))
                smallest = min(smallest, (t_star - sl.end.t) / t_star)
                cases += 1
    return Margin(float(smallest), 10.0**-SLIDE_DIGITS), cases


def end_exponent() -> tuple[float, int]:
    """n°8: near the end of sliding π/2 − θ ∝ V^κ; the log-slope between two late nodes against κ.

    The slope differs from κ by O((π/2 − θ)²); the nodes are the last two with
    π/2 − θ above 10^-7, where the integration's absolute error (10^-22 in θ)
    is 10^-15 of it: both effects far below the 10 digits asked (tests/expectations.py).
    """
    kappa = sp.lambdify(PARAMS, n8_general.relations()["kappa"], "mpmath")
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for start in SHOTS:
                sl = reference_slide(P, start)
                late = []
                for sigma, y in sl.nodes:
                    psi = mpmath.pi / 2 - (mpmath.atan2(y[3], y[2]) - y[1])
                    psi = mpmath.atan2(mpmath.sin(psi), mpmath.cos(psi))
                    if psi > mpf(10) ** -7:
                        late.append((sigma, psi))
                (s1, psi1), (s2, psi2) = late[-2:]
                slope = (mpmath.log(psi2) - mpmath.log(psi1)) / -(s2 - s1)  # ln V = −σ
                k_ = kappa(*P.values(mpf))
                worst = worst_of(worst, abs(slope - k_) / k_)
                cases += 1
    return _digits(worst), cases


def straight_closed_form() -> tuple[float, int]:
    """Straight shots: the closed form against the integrated slide — follow and draw from eqs. (4)–(6),
    the centre-ball hit (Ω₀ = 0) and a draw whose spin passes through zero from the slide in σ."""
    worst, cases = mpf(0), 0
    with mpmath.workdps(DIGITS + 10):
        for P in (POOL, HEAVY):
            for q0 in (20, -30, 50):  # θ = +π/2, −π/2, and −π/2 again (over-spun: the slip points back)
                start = (0.0, 0.0, 1.0, 0.0, 0.0, float(q0), 0.0)
                V0, alpha0 = _slip(P, [mpf(x) for x in start])
                theta0 = mpmath.atan2(mpmath.sin(mpmath.pi / 2 * mpmath.sign(q0) - alpha0), mpmath.cos(mpmath.pi / 2 * mpmath.sign(q0) - alpha0))
                side = "follow" if theta0 > 0 else "draw"
                _, _, local = phases.straight_slide(P, side, V0, abs(mpf(q0)), num=mpf)
                times, states = cartesian_run(P, start, 0.5)
                for tt, s in zip(times, states):
                    exact = _world(local(tt), alpha0, 0, 0)
                    worst = worst_of(worst, _worst_state_error(exact, s[:6], _scale(P, start)))
                    cases += 1
            # Whole slides to V = 0: a centre-ball hit and a straight draw that reverses its spin.
            for start in ((0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 2.0, 0.0, 0.0, -100.0, 0.0)):
                sl = reference_slide(P, start)
                V0, _ = _slip(P, [mpf(x) for x in start])
                Om0 = abs(mpf(start[5]))
                slip_end, spin_end, draw = phases.straight_slide(P, "draw", V0, Om0, num=mpf)
                if Om0 == 0 or spin_end > slip_end:  # the follow law from the start
                    t_end, _, _ = phases.straight_slide(P, "follow", V0, Om0, num=mpf)
                    end_state = phases.straight_slide(P, "follow", V0, Om0, num=mpf)[2](t_end)
                    x_end = end_state.xi
                else:  # draw until Ω = 0, then follow
                    mid = draw(spin_end)
                    rest, _, follow = phases.straight_slide(P, "follow", mid.V, 0, num=mpf)
                    t_end, x_end = spin_end + rest, mid.xi + follow(rest).xi
                worst = worst_of(worst, abs(sl.end.t - t_end) / t_end, abs(sl.end.xi - x_end) / x_end, abs(sl.end.eta) / x_end)
                cases += 1
    return min(_digits(worst), 20.0), cases


def claims() -> list[NumericCheck]:
    cart = f"eqs. (4)–(6) integrated at {DIGITS} digits"
    return [
        NumericCheck(
            "n3.closed_form_mpmath", "n°3",
            f"δ = 0: n°3's V, p, q, ξ, η, ξ', η' against {cart} (three shots, two parameter sets' worth of spin).",
            None, n3_closed_form, required_digits=28,
        ),
        NumericCheck(
            "n4.closed_form_mpmath", "n°4",
            f"f = 0: n°4's Ω, u, v, ξ', η' (Ω along the axis Oξ) against {cart}.",
            None, n4_closed_form, required_digits=28,
        ),
        NumericCheck(
            "n7.closed_form_mpmath", "n°7",
            f"Pure rolling with the friction solved from the no-slip constraint, integrated at {DIGITS} digits, "
            "against n°7's closed form; the friction needed is f₁ m g with f₁ = Rδ/(R² + k²) (corrected (10)).",
            None, n7_closed_form, required_digits=28,
        ),
        NumericCheck(
            "n2.pivot_mpmath", "n°2, eq. (5)",
            f"Eq. (5) integrated at {DIGITS} digits to its event r = 0 against r = r₀ − εgt/k² and t₁ = k²r₀/(εg).",
            None, pivot_closed_form, required_digits=28,
        ),
        NumericCheck(
            "n8.integral_11_mpmath", "n°8, eq. (11)",
            f"fV − δΩ = fV₀ − δΩ₀ − (f²(1 + R²/k²) − δ²/k²) g t along {cart} (two parameter sets, three shots).",
            None, integral_11, required_digits=28,
        ),
        NumericCheck(
            "n9.y_minus_x_mpmath", "n°9",
            f"y − x = (a − c)t + const along eq. (12) integrated at {DIGITS} digits.",
            None, y_minus_x_linear, required_digits=28,
        ),
        NumericCheck(
            "n9.cartesian_is_reduced", "n°9, eq. (12)",
            f"Eqs. (4)–(6) and eq. (12), each integrated at {DIGITS} digits from the same start, agree on "
            "x = fV, y = δΩ, α, β.",
            None, cartesian_matches_reduced, required_digits=28,
        ),
        NumericCheck(
            "n8.energy_mpmath", "n°8",
            f"T(t) − T₀ (T₀ at the start) equals the work of the loads (n°8's power −mg(fV + δΩ + ε|r|), integrated with "
            f"{cart}); T decreases between every pair of samples.",
            None, energy, required_digits=28,
        ),
        NumericCheck(
            "n8.product_decreases_mpmath", "n°8",
            f"|ΩV cos(β − α)| decreases between every pair of samples along {cart}: the smallest relative "
            "drop, far above the integration's error.",
            None, product_decreases,
        ),
        NumericCheck(
            "n8.slide_time_mpmath", "n°8",
            f"The slide, integrated to V = 0 in σ = −ln V at {SLIDE_DIGITS} digits, ends before V₀/(fg): the "
            "smallest relative margin, far above the integration's error.",
            None, slide_time_bound,
        ),
        NumericCheck(
            "n8.end_exponent_mpmath", "beyond n°8: the end of sliding",
            "Near the end of sliding, d ln(π/2 − θ)/d ln V → κ = Rδ/(f(R² + k²) − Rδ), measured on the slide "
            "integrated at 20 digits down to V = 10^-200 V₀.",
            None, end_exponent, required_digits=10,
        ),
        NumericCheck(
            "straight.closed_form_mpmath", "beyond n°8: straight shots",
            f"θ = ±π/2: the straight-shot closed form against {cart}; a centre-ball hit (Ω₀ = 0) and a straight "
            "draw whose spin passes through zero against the slide integrated to V = 0 at 20 digits.",
            None, straight_closed_form, required_digits=18,
        ),
    ]
