"""The curved sliding phase (δ > 0, spin not square to the slip), integrated numerically.

The whole slide is integrated in σ = −ln V (see `equations.sliding_in_log_slip`),
from V₀ down to V₀·ε with ε far below the tolerance; the rest of the slide,
a time V/|V'| ≈ ε V₀/(a − b) f, is added to first order.  Near the end
π/2 − θ ∝ V^κ (n°8, claim n8.theta_right_angle) and β converges like V, so
the slip's final direction is α_end = β_end − π/2, not the slowly
converging α itself.

The same code runs in floats (the simulator) and in mpmath (the reference).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import math

import mpmath

from numerics import equations, taylor
from numerics.scene import Coefficients
from numerics.reference import Stats, integrate
from numerics.validation import WorkLimitError

MAX_RESTARTS = 1000
SPIN_FLOOR = 1e-3  # below this fraction of its scale, Ω's error is measured against the floor

T, ALPHA, P, Q, XI, ETA = range(6)  # the state in σ
TAYLOR_ESCAPE = 0.05  # the GBS stretch in σ off Ω = 0 before Taylor steps (method "taylor")


@dataclass
class SlideEnd:
    """The state when the slip vanishes."""

    t: object
    alpha: object  # the slip's limiting direction, β − π/2
    p: object
    q: object
    xi: object
    eta: object


@dataclass
class Slide:
    """A solved sliding phase: its end, the states at requested times, the nodes to restart from."""

    params: Coefficients
    end: SlideEnd
    states: dict = field(default_factory=dict)  # t -> [V, α, p, q, ξ, η]
    nodes: list = field(default_factory=list)  # (σ, [t, α, p, q, ξ, η])
    stats: Stats = field(default_factory=Stats)
    num: object = float
    tol: object = 1e-12
    scale: list | None = None  # per component of [t, α, p, q, ξ, η], what its error is measured against


def _fn(num):
    return mpmath if num is not float else math


def _spin_direction(y, fn):
    """The unit vector of (p, q), or of α + π/2 where Ω = 0 (n°6)."""
    spin = fn.sqrt(y[P] ** 2 + y[Q] ** 2)
    if spin == 0:
        return -fn.sin(y[ALPHA]), fn.cos(y[ALPHA])
    return y[P] / spin, y[Q] / spin


def slide(
    params: Coefficients,
    V0,
    alpha0,
    p0,
    q0,
    xi0=0,
    eta0=0,
    t0=0,
    tol=1e-12,
    num=float,
    times=(),
    end_fraction=None,
    through_zero=False,
    method="gbs",
) -> Slide:
    """Integrate the slide from slip speed V0 (> 0) until V = 0.

    ``times`` (absolute, ≥ t0) get their states recorded; ``end_fraction``
    (default tol/100) is where the integration hands over to the first-order end.
    ``through_zero`` watches for Ω passing through zero (a straight draw, which
    the simulator otherwise takes in closed form).  ``method``: "gbs"
    (`reference.integrate`) or, in mpmath only, "taylor" (`taylor.integrate`
    on the generated coefficients of the same rates); where Ω = 0 exactly the
    Taylor recurrences cannot start (the direction is 0/0, n°6 fixes it), so a
    short GBS stretch (``TAYLOR_ESCAPE`` in σ) leaves zero first.
    """
    fn = _fn(num)
    end_fraction = num(tol) / 100 if end_fraction is None else num(end_fraction)
    V0 = num(V0)
    sigma, sigma_end = -fn.log(V0), -fn.log(V0 * end_fraction)
    y = [num(t0), num(alpha0), num(p0), num(q0), num(xi0), num(eta0)]
    # Errors against the slide's own sizes: its duration (at most V₀/(fg), n°8) and the distance it
    # covers for t and the centre, 1 rad for the angle, and for the spin (which may pass near zero,
    # where its direction turns fast) 1 rad/s or a small fraction of its scale Ω₀ + V₀/R if larger.
    duration = V0 / (num(params.f) * num(params.g))
    spin = max(num(1), SPIN_FLOOR * (fn.sqrt(y[P] ** 2 + y[Q] ** 2) + V0 / num(params.R)))
    result = Slide(params, None, num=num, tol=tol, scale=[duration + 1, 1, spin, spin, V0 * duration + 1, V0 * duration + 1])
    pending = sorted(num(t) for t in times)
    spin_scale = max(fn.sqrt(y[P] ** 2 + y[Q] ** 2), num(1))
    # Each pass ends at a requested time, at Ω through zero or turned 60° (a handful), or at the end.
    if method == "taylor":
        jet = equations.log_slip_taylor().bind(params.values(num))
    for _ in range(len(pending) + MAX_RESTARTS):
        while pending and pending[0] <= y[T]:  # reached already (the start, or a time asked twice): no event fires
            result.states[pending.pop(0)] = [fn.exp(-sigma)] + y[1:]
        events = []
        if through_zero:
            # Watch Ω's component along its direction at (re)start: it changes sign where Ω
            # passes through zero (then Ω comes back along β = α + π/2, n°6), and the rhs is
            # continued smoothly across so that the crossing can be located.  A second event
            # restarts when Ω has turned 60° away, so that the continuation is only ever used
            # near a crossing.
            ref = _spin_direction(y, fn)
            rhs = equations.sliding_in_log_slip(params, num, orientation=ref)
            along = lambda s_, y_, ref=ref: y_[P] * ref[0] + y_[Q] * ref[1]  # noqa: E731
            turned = lambda s_, y_, along=along: along(s_, y_) - fn.sqrt(y_[P] ** 2 + y_[Q] ** 2) / 2  # noqa: E731
            events = [along, turned]
        else:
            rhs = equations.sliding_in_log_slip(params, num)
        if pending:
            events.append(lambda s_, y_, target=pending[0]: y_[T] - target)
        on_step = lambda s_, y_: result.nodes.append((s_, list(y_)))  # noqa: E731
        if method == "taylor" and (y[P] != 0 or y[Q] != 0):
            outcome = taylor.integrate(jet, sigma, y, sigma_end, tol, events=events, num=num, stats=result.stats, on_step=on_step)
        else:
            stop = sigma_end if method != "taylor" else min(sigma_end, sigma + TAYLOR_ESCAPE)
            outcome = integrate(
                rhs, sigma, y, stop, tol, events=events, num=num, stats=result.stats, scale=result.scale, on_step=on_step,
            )
        sigma, y = outcome.t, outcome.y
        if outcome.event is None and sigma < sigma_end:
            continue  # off Ω = 0: Taylor from here
        if outcome.event is None:
            break
        if through_zero and outcome.event in (0, 1):
            if fn.sqrt(y[P] ** 2 + y[Q] ** 2) <= 1000 * tol * spin_scale:
                y[P], y[Q] = num(0), num(0)  # through zero: n°6 takes over
            continue
        target = pending.pop(0)
        result.states[target] = [fn.exp(-sigma)] + y[1:]
    else:
        raise WorkLimitError(f"slide: not ended after {len(result.states) + MAX_RESTARTS} restarts (Ω through zero)")
    # The last stretch, V from V₀ε to 0, to first order in t.
    dt, p_end, q_end, xi_end, eta_end = first_order_end(params, y[T], [fn.exp(-sigma)] + y[1:], num)
    result.end = SlideEnd(y[T] + dt, fn.atan2(q_end, p_end) - fn.pi / 2, p_end, q_end, xi_end, eta_end)
    for target in pending:  # within the last stretch (or after it: the rolling's), to first order as the end is
        if target <= result.end.t:
            w = (target - y[T]) / dt
            result.states[target] = [fn.exp(-sigma) * (1 - w), y[ALPHA], y[P] + w * (p_end - y[P]), y[Q] + w * (q_end - y[Q]),
                                     y[XI] + w * (xi_end - y[XI]), y[ETA] + w * (eta_end - y[ETA])]
    return result


def first_order_end(params: Coefficients, t, state: list, num=float) -> tuple:
    """The last stretch of a slide, from a small slip to V = 0, to first order in t.

    ``state`` is [V, α, p, q, ξ, η] at time t; returns (dt, p, q, ξ, η) when
    the slip vanishes.  The slip's own direction is left to the caller: it
    converges too slowly (as V^κ), its limit is β − π/2 (n°8).
    """
    rates = equations.sliding(params, num)(t, state)
    dt = state[0] / -rates[0]
    return (dt,) + tuple(state[i] + rates[i] * dt for i in (2, 3, 4, 5))


def state_at(s: Slide, t) -> list:
    """[V, α, p, q, ξ, η] at time t within the slide, restarting from the nearest node."""
    num = s.num
    t = num(t)
    if t in s.states:
        return s.states[t]
    fn = _fn(num)
    before = [node for node in s.nodes if node[1][T] <= t]
    if not before:
        raise ValueError(f"t = {t} is before the slide")
    sigma, y = before[-1]
    if y[T] == t:
        return [fn.exp(-sigma)] + y[1:]
    rhs = equations.sliding_in_log_slip(s.params, num)
    last_sigma = s.nodes[-1][0]
    outcome = integrate(rhs, sigma, y, last_sigma + 1, s.tol, events=[lambda z, y_: y_[T] - t], num=num, scale=s.scale)
    if outcome.event is None:
        raise ValueError(f"t = {t} is after the slide")
    return [fn.exp(-outcome.t)] + outcome.y[1:]
