"""The mpmath reference for a whole scene: every phase integrated, no closed form used.

The slide is `sliding.slide` in mpmath (with Ω allowed through zero); pure
rolling integrates eqs. (4) with the friction solved from the no-slip
constraint (`equations.rolling_constrained`), not n°7's result; the pivot
integrates eq. (5) to its event r = 0.  The simulator's closed forms are
tested against this.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import mpmath

from numerics import equations, sliding, taylor
from numerics.reference import Stats, integrate
from numerics.scene import Scene
from numerics.validation import WorkLimitError

MAX_DOUBLINGS = 200  # of the rolling horizon, from 1 s: far beyond any rolling time float64 can hold


@dataclass
class ReferenceMotion:
    digits: int
    t_slide_end: object
    slide_end: sliding.SlideEnd | None
    t_roll_end: object | None
    rest: tuple | None
    t_pivot_end: object | None
    states: dict = field(default_factory=dict)  # t -> (ξ, η, p, q) at requested times


def reference(scene: Scene, digits: int = 30, times=(), method: str = "taylor") -> ReferenceMotion:
    """The scene's motion at about ``digits`` digits.

    ``method``: "taylor" (`taylor.integrate` on generated coefficients; 1–4 s a
    scene at 50 digits) or "gbs" (Gragg–Bulirsch–Stoer, `reference.integrate`;
    ten to thirty times slower, kept as a second integrator to test against)
    for the slide and the rolling; the pivot (r' constant) stays GBS either way.
    """
    if method not in ("gbs", "taylor"):
        raise ValueError(f"method: 'gbs' or 'taylor', got {method!r}")
    num = mpmath.mpf
    with mpmath.workdps(digits + 10):
        tol = mpmath.mpf(10) ** (-digits - 2)
        P, s = scene.params, scene.state
        times = sorted(num(t) for t in times)
        # The classical model: no rolling couple while sliding.
        P_slide = dataclasses.replace(P, delta=0.0) if scene.model == "classical" else P
        u, v = equations.slip_velocity(P, num(s.vxi), num(s.veta), num(s.p), num(s.q), num)
        V0 = mpmath.sqrt(u**2 + v**2)
        out = ReferenceMotion(digits, num(0), None, None, None, None)
        start = [num(s.xi), num(s.eta), num(s.p), num(s.q)]
        t_roll_start = num(0)
        if V0 > 0:
            slide_times = [t for t in times]
            sl = sliding.slide(
                P_slide, V0, mpmath.atan2(v, u), num(s.p), num(s.q), num(s.xi), num(s.eta),
                tol=tol, num=num, times=slide_times, through_zero=True, method=method,
            )
            e = sl.end
            out.t_slide_end, out.slide_end = e.t, e
            for t, state in sl.states.items():
                if t <= e.t:
                    out.states[t] = (state[4], state[5], state[2], state[3])
            start, t_roll_start = [e.xi, e.eta, e.p, e.q], e.t
        out.t_roll_end, out.rest = _roll(P, start, t_roll_start, tol, [t for t in times if t > t_roll_start], out, method)
        out.t_pivot_end = _pivot(P, num(s.r), tol)
        return out


def _roll(P, start, t0, tol, times, out, method="gbs"):
    """Pure rolling from ``start`` = [ξ, η, p, q] until Ω = 0: (end time, rest point)."""
    spin = mpmath.sqrt(start[2] ** 2 + start[3] ** 2)
    if spin == 0:
        return t0, (start[0], start[1])
    if P.delta == 0:
        return None, None
    direction = (start[2] / spin, start[3] / spin)
    if method == "taylor":
        # The principal root's continuation carries the direction across Ω = 0 (`equations.rolling_rates`).
        rhs, run = equations.rolling_taylor().bind(P.values(mpmath.mpf)), taylor.integrate
    else:
        (rhs, _), run = equations.rolling_constrained(P, mpmath.mpf, orientation=direction), integrate
    stop = lambda t, y: y[2] * direction[0] + y[3] * direction[1]  # noqa: E731  Ω along its start direction
    horizon = t0 + 1
    y, t = start, t0
    stats = Stats()  # one count for the whole roll (the Taylor integrator's step limit reads it)
    for _ in range(MAX_DOUBLINGS):  # the rolling time is not assumed: extend the horizon until Ω reaches 0
        outcome = run(rhs, t, y, horizon, tol, times=[x for x in times if t < x <= horizon], events=[stop], num=mpmath.mpf, stats=stats)
        for x, state in zip([x for x in times if t < x <= horizon], outcome.states):
            out.states[x] = tuple(state)
        if outcome.event is not None:
            return outcome.t, (outcome.y[0], outcome.y[1])
        t, y, horizon = outcome.t, outcome.y, t0 + 2 * (horizon - t0)
    raise WorkLimitError(f"reference: pure rolling has not stopped after {horizon - t0} s ({MAX_DOUBLINGS} doublings)")


def _pivot(P, r0, tol):
    if r0 == 0:
        return mpmath.mpf(0)
    if P.epsilon == 0:
        return None
    sign = 1 if r0 > 0 else -1
    outcome = integrate(equations.pivot_rate(P, mpmath.mpf, sign), 0, [r0], 10**6, tol, events=[lambda t, y: y[0]], num=mpmath.mpf)
    return outcome.t
