"""What a user would otherwise write: eqs. (4)–(6) integrated in t by SciPy's `solve_ivp` (optional extra).

The slide is integrated in t, in the simulator's variables (the slip V and
its direction α, the rotation p, q — so Ω may pass near zero — and the
centre ξ, η), with the same generated right-hand sides (`kernels.slide_rates`),
until the slip falls below rtol·V₀ (a terminal event: V ≥ 0 has no sign
change to locate at V = 0); then the rest of the motion uses the same
end of slide and closed forms as the engine — so the comparison is of the
sliding phase alone.  Only curved slides are run here (the others are
closed forms for every method).
"""

from __future__ import annotations

import math

import numpy as np

from numerics import engine
from numerics.kernels import slide_rates
from numerics.scene import Scene


def _rates_in_t(params):
    f, R, k, delta, epsilon, g = params

    def rhs(t, y):
        V, alpha, p, q = y[0], y[1], y[2], y[3]
        ca, sa = math.cos(alpha), math.sin(alpha)
        cb, sb = engine.unit_rotation(ca, sa, p, q)
        dV, V_dalpha, dp, dq, dxi, deta = slide_rates(V, ca, sa, p, q, cb, sb, f, R, k, delta, epsilon, g)
        return [dV, V_dalpha / V, dp, dq, dxi, deta]

    return rhs


def solve(scene: Scene, method: str = "DOP853", rtol: float = 1e-10) -> dict:
    """t_slide_end, Ω at the end (p, q), t_roll_end and rest point of a curved slide (model appell)."""
    from scipy.integrate import solve_ivp

    params, state = scene.arrays()
    model, V0, ca, sa, _, _ = engine.classify(params, state, False, rtol)
    if model != engine.NUMERICAL:
        raise ValueError(f"the scipy baseline runs curved slides only, got {engine.MODEL_NAMES[model]}")
    f, R, g = params[0], params[1], params[5]
    slip = lambda t, y: y[0] - rtol * V0  # noqa: E731
    slip.terminal, slip.direction = True, -1
    bound = V0 / (f * g)  # n°8: the slide ends before this
    atol = rtol * np.array([V0, 1.0, V0 / R, V0 / R, V0 * bound, V0 * bound])
    y0 = [V0, math.atan2(sa, ca), state[4], state[5], state[0], state[1]]
    sol = solve_ivp(_rates_in_t(tuple(params)), (0.0, bound), y0, method=method, rtol=rtol, atol=atol, events=slip)
    if sol.status != 1:
        raise ArithmeticError(f"{method}: the slide did not end before V0/(fg): {sol.message}")
    t1, (V, alpha, p, q, xi, eta) = float(sol.t_events[0][0]), sol.y_events[0][0]
    # The rest of the slip, V = rtol·V₀ to 0, to first order (as the engine does).
    dt, p, q, xi, eta = engine.first_order_end(np.array([t1, math.cos(alpha), math.sin(alpha), p, q, xi, eta]), -math.log(V), params)
    t_roll, rest_xi, rest_eta = engine.roll(t1 + dt, xi, eta, p, q, params)
    return {"t_slide_end": t1 + dt, "omega_end": (p, q), "t_roll_end": t_roll, "rest": (rest_xi, rest_eta)}


def available() -> bool:
    try:
        import scipy.integrate  # noqa: F401
    except ImportError:
        return False
    return True
