"""What a user would otherwise write: eqs. (4)–(6) integrated in t by SciPy's `solve_ivp` (optional extra).

The slide is integrated in t, in the same variables as the simulator's
(`equations.sliding`: the slip V, α, the rotation p, q — so Ω may pass
through zero — and the centre ξ, η), until the slip falls below rtol·V₀ (a
terminal event: V ≥ 0 has no sign change to locate at V = 0), then the
rest of the motion uses the same closed forms as `simulate` — so the
comparison is of the sliding phase alone.
"""

from __future__ import annotations

import math

import numpy as np

from numerics import equations, phases, sliding
from numerics.scene import Scene


def solve(scene: Scene, method: str = "DOP853", rtol: float = 1e-10) -> dict:
    """t_slide_end, Ω at the end (p, q), t_roll_end and rest point of ``scene`` (model appell)."""
    from scipy.integrate import solve_ivp

    P, s = scene.params, scene.state
    u, v = equations.slip_velocity(P, s.vxi, s.veta, s.p, s.q)
    V0 = math.hypot(u, v)
    scale = max(abs(s.vxi), abs(s.veta), P.R * abs(s.p), P.R * abs(s.q), 1e-300)
    y = [V0, math.atan2(v, u), s.p, s.q, s.xi, s.eta]
    t_end = 0.0
    if V0 > 1e-14 * scale:
        rhs = equations.sliding(P)
        slip = lambda t, y: y[0] - rtol * V0  # noqa: E731
        slip.terminal, slip.direction = True, -1
        bound = V0 / (P.f * P.g)  # n°8: the slide ends before this
        atol = rtol * np.array([V0, 1.0, V0 / P.R, V0 / P.R, V0 * bound, V0 * bound])
        sol = solve_ivp(lambda t, y: rhs(t, [float(x) for x in y]), (0.0, bound), y, method=method, rtol=rtol, atol=atol, events=slip)
        if sol.status != 1:
            raise ArithmeticError(f"{method}: the slide did not end before V0/(fg): {sol.message}")
        t_end, y = float(sol.t_events[0][0]), list(sol.y_events[0][0])
        # The rest of the slip, V = rtol·V₀ to 0, to first order (as the simulator does).
        dt, *end = sliding.first_order_end(P, t_end, [float(x) for x in y])
        t_end, y = t_end + dt, [0.0, y[1]] + end
    else:
        y = [0.0, 0.0, s.p, s.q, s.xi, s.eta]
    p_end, q_end = y[2], y[3]
    spin = math.hypot(p_end, q_end)
    duration, local = phases.rolling(P, spin, math.atan2(q_end, p_end))
    if duration is None:
        return {"t_slide_end": t_end, "omega_end": (p_end, q_end), "t_roll_end": None, "rest": None}
    end = local(duration)
    return {
        "t_slide_end": t_end, "omega_end": (p_end, q_end), "t_roll_end": t_end + duration,
        "rest": (y[4] + end.xi, y[5] + end.eta),
    }


def available() -> bool:
    try:
        import scipy.integrate  # noqa: F401
    except ImportError:
        return False
    return True

