"""Gragg–Bulirsch–Stoer extrapolation, for mpmath numbers (the reference) or floats.

For the smooth stretches of the billiard ball's motion, extrapolation of
the modified midpoint rule reaches 30–50 digits with a handful of large
steps, much faster than mpmath's Taylor `odefun` on these right-hand sides.
A step is accepted when the last two diagonal entries of the extrapolation
table agree to the tolerance, so each step carries its own error estimate.

`integrate` adds what the phases of the motion need: landing exactly on
requested times, and event location (a sign change of an event function,
located by the Illinois method on the length of the last step, each trial
being a full extrapolated step).

Reference: Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.9 (ODEX).
The arithmetic is whatever ``num`` makes of a number: ``float`` or
``mpmath.mpf`` (then call inside ``mpmath.workdps``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

import mpmath

from numerics.validation import ComputationError, WorkLimitError

RHS = Callable[[object, list], list]
Event = Callable[[object, list], object]

MAX_COLUMNS = 18  # up to order 36
# A bound on the work of one integration (a slide takes tens to hundreds of steps at 50 digits).
MAX_STEPS = 10_000


@dataclass
class Stats:
    steps: int = 0
    rejected: int = 0
    evaluations: int = 0


@dataclass
class Outcome:
    """Where an integration stopped: at ``t_end`` (event None) or at an event."""

    t: object
    y: list
    event: int | None
    states: list = field(default_factory=list)  # at the requested times, in order
    stats: Stats = field(default_factory=Stats)


def _finite(values) -> bool:
    """No NaN or ∞ among floats or mpmath numbers (NaN ≠ NaN)."""
    return all(v == v and abs(v) != mpmath.inf for v in values)


def _axpy(a, x: list, y: list) -> list:
    return [a * xi + yi for xi, yi in zip(x, y)]


def _midpoint(rhs: RHS, t, y: list, H, n: int, f0: list, stats: Stats) -> list:
    """Gragg's modified midpoint rule with n substeps, smoothed at the end."""
    h = H / n
    z_prev, z = y, _axpy(h, f0, y)
    for i in range(1, n):
        z_prev, z = z, _axpy(2 * h, rhs(t + i * h, z), z_prev)
    f_end = rhs(t + H, z)
    stats.evaluations += n
    return [(zi + zpi + h * fi) / 2 for zi, zpi, fi in zip(z, z_prev, f_end)]


def step(rhs: RHS, t, y: list, H, tol, stats: Stats, num=float, scale=None) -> tuple[list | None, object, int]:
    """One extrapolated step of size H: (new state or None if rejected, error ratio, columns used).

    A component's error is measured against ``scale`` + |its value| (scale 1 by default): a
    component that starts at 0 but grows to the size of its scale (a position) is then not held
    to an absolute tolerance that rounding alone breaks."""
    scale = scale or [1] * len(y)
    f0 = rhs(t, y)
    stats.evaluations += 1
    table: list[list] = []
    err = float("inf")
    for j in range(MAX_COLUMNS):
        n_j = 2 * (j + 1)
        row = [_midpoint(rhs, t, y, H, n_j, f0, stats)]
        for k in range(1, j + 1):
            ratio = (num(n_j) / (2 * (j - k + 1))) ** 2 - 1
            row.append([r + (r - p) / ratio for r, p in zip(row[k - 1], table[j - 1][k - 1])])
        table.append(row)
        if j >= 2:
            err = max(abs(a - b) / (tol * (s + abs(a))) for a, b, s in zip(row[j], row[j - 1], scale))
            if err <= 1:
                return row[j], err, j
    return None, err, MAX_COLUMNS


def _next_step(h, H, err, cols, num):
    """Grow or shrink by the error of the converged column (order 2*cols + 1)."""
    factor = num("0.9") * (1 / max(err, num("1e-6"))) ** (num(1) / (2 * cols + 1))
    if cols < 8:
        factor *= num("1.5")  # converging early: try bigger steps
    proposed = h * min(num(4), max(num("0.2"), factor))
    return max(H, proposed) if h < H else proposed  # a step cut short to land is no evidence


def advance(rhs: RHS, t, y: list, h, tol, stats: Stats, num=float, scale=None) -> list:
    """The state at t + h, by as many steps as needed (no events)."""
    outcome = integrate(rhs, t, y, t + h, tol, num=num, first_step=h, stats=stats, scale=scale)
    return outcome.y


def _locate(rhs, event: Event, t, y, h, g0, g1, tol, stats, num, scale):
    """Illinois on the step length: the root of event(t + s, y(t + s)) for s in (0, h]."""
    lo, hi, g_lo, g_hi = num(0), h, g0, g1
    side = 0
    s, y_s = hi, None
    for _ in range(200):
        s = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        if not lo < s < hi:
            s = (lo + hi) / 2
        y_s = advance(rhs, t, y, s, tol, stats, num, scale)
        g_s = event(t + s, y_s)
        if g_s == 0 or hi - lo <= tol * (1 + abs(t + s)):
            break
        if (g_s > 0) == (g_hi > 0):
            hi, g_hi = s, g_s
            if side == 1:
                g_lo /= 2
            side = 1
        else:
            lo, g_lo = s, g_s
            if side == -1:
                g_hi /= 2
            side = -1
    return s, y_s


def integrate(
    rhs: RHS,
    t0,
    y0: Sequence,
    t_end,
    tol,
    times: Sequence = (),
    events: Sequence[Event] = (),
    num=float,
    first_step=None,
    stats: Stats | None = None,
    scale: Sequence | None = None,
    on_step: Callable[[object, list], None] | None = None,
) -> Outcome:
    """Integrate from t0 towards t_end; stop at the first sign change of an event function.

    ``times`` (increasing, within [t0, t_end]) are landed on exactly and their
    states returned; an event stops the integration at its root, located to
    about ``tol`` relative in t.  ``on_step`` sees every accepted (t, y),
    starting with (t0, y0): the nodes a caller can restart from.  ``scale``:
    per component, the size its error is measured against (see `step`).
    """
    stats = Stats() if stats is None else stats
    t, y = num(t0), [num(v) for v in y0]
    t_end = num(t_end)
    pending = [num(x) for x in times]
    states = []
    while pending and pending[0] <= t:
        states.append(list(y))
        pending.pop(0)
    g_prev = [g(t, y) for g in events]
    if on_step is not None:
        on_step(t, y)
    H = num(first_step) if first_step is not None else (t_end - t) / 8
    taken = 0
    while t < t_end:
        taken += 1
        if taken > MAX_STEPS:
            raise WorkLimitError(f"integration not done after {MAX_STEPS} steps, at t = {float(t):g} of {float(t_end):g}")
        target = min(t_end, pending[0]) if pending else t_end
        h = min(H, target - t)
        new, err, cols = step(rhs, t, y, h, tol, stats, num, scale)
        if not _finite(new if new is not None else [err]) or not h > 0:
            raise ComputationError(f"integration: the state became non-finite (or the step vanished) at t = {float(t):g}")
        if new is None:
            stats.rejected += 1
            H = h / 4
            continue
        g_new = [g(t + h, new) for g in events]
        crossed = [i for i, (a, b) in enumerate(zip(g_prev, g_new)) if (a > 0 >= b) or (a < 0 <= b)]
        if crossed:
            roots = [(_locate(rhs, events[i], t, y, h, g_prev[i], g_new[i], tol, stats, num, scale), i) for i in crossed]
            (s, y_s), i = min(roots, key=lambda r: r[0][0])
            return Outcome(t + s, y_s, i, states, stats)
        stats.steps += 1
        t, y, g_prev = t + h, new, g_new
        if pending and t >= pending[0]:
            t = pending.pop(0)  # land exactly
            states.append(list(y))
        if on_step is not None:
            on_step(t, y)
        H = _next_step(h, H, err, cols, num)
    return Outcome(t, y, None, states, stats)


def solve(rhs: RHS, t0, y0: Sequence, times: Sequence, digits: int = 30, first_step=None) -> tuple[list, Stats]:
    """The state at each of ``times`` (increasing, ≥ t0), about ``digits`` digits, in mpmath.

    Work is done at ``digits + 10`` decimal digits.
    """
    with mpmath.workdps(digits + 10):
        tol = mpmath.mpf(10) ** (-digits - 2)
        outcome = integrate(rhs, t0, y0, max(times), tol, times=times, num=mpmath.mpf, first_step=first_step)
        return outcome.states, outcome.stats
