"""The strongest peer, heyoka (Taylor's method compiled by LLVM), on the same generated system (optional extra).

heyoka integrates the slide in σ = −ln V in the engine's variables
(t, cos α, sin α, p, q, ξ, η), its right-hand side built from the SymPy
rates the kernels are generated from (`codegen.kernels`, through
``heyoka.from_sympy``), then the same end of slide and closed forms as the
engine finish the motion (compiled, as the engine's).  One integrator is
compiled per mode and reused with each scene's state and parameters:
``solve`` runs scenes one by one (scalar mode), ``solve_batch`` SIMD-wide
groups of them (heyoka's batch mode).  Only curved slides are run here.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from numerics import engine
from numerics.scene import Scene


def available() -> bool:
    try:
        import heyoka  # noqa: F401
    except ImportError:
        return False
    return True


@lru_cache(maxsize=None)
def system() -> list:
    """The slide in σ as heyoka expressions: variables (t, cos α, sin α, p, q, ξ, η), parameters (f, R, k, δ, g)."""
    import heyoka as hy

    from numerics import codegen

    rates = codegen.kernels()[0]  # slide_rates: V', V α', p', q', ξ', η'
    t, ca, sa, p, q, xi, eta = hy.make_vars("t", "ca", "sa", "p", "q", "xi", "eta")
    f, R, k, delta, g = (hy.par[i] for i in range(5))
    V = hy.exp(-hy.time)
    norm = hy.sqrt(ca * ca + sa * sa)
    c, s = ca / norm, sa / norm
    spin = hy.sqrt(p * p + q * q)
    V_, ca_, sa_, p_, q_, cb_, sb_, f_, R_, k_, delta_, _, g_ = rates.args
    names = {V_: V, ca_: c, sa_: s, p_: p, q_: q, cb_: p / spin, sb_: q / spin, f_: f, R_: R, k_: k, delta_: delta, g_: g}
    dV, V_dalpha, dp, dq, dxi, deta = (hy.from_sympy(e, names) for e in rates.outputs)
    per_sigma, dalpha = -V / dV, -V_dalpha / dV
    return [(t, per_sigma), (ca, -s * dalpha), (sa, c * dalpha), (p, per_sigma * dp), (q, per_sigma * dq),
            (xi, per_sigma * dxi), (eta, per_sigma * deta)]


@lru_cache(maxsize=None)
def _integrator(tol: float, batch: int = 0):
    import heyoka as hy

    if batch:
        return hy.taylor_adaptive_batch(system(), np.zeros((7, batch)), pars=np.ones((5, batch)), tol=tol)
    return hy.taylor_adaptive(system(), [0.0] * 7, pars=[1.0] * 5, tol=tol)


def _start(scene: Scene, tol: float):
    params, state = scene.arrays()
    model, V0, ca, sa, _, _ = engine.classify(params, state, False, tol)
    if model != engine.NUMERICAL:
        raise ValueError(f"the heyoka baseline runs curved slides only, got {engine.MODEL_NAMES[model]}")
    return params, [0.0, ca, sa, state[4], state[5], state[0], state[1]], V0


def _finish(params, y, sigma, finish) -> dict:
    first_order_end, roll = finish
    dt, p, q, xi, eta = first_order_end(np.asarray(y, dtype=float), sigma, params)
    t_roll, rest_xi, rest_eta = roll(y[0] + dt, xi, eta, p, q, params)
    return {"t_slide_end": y[0] + dt, "omega_end": (p, q), "t_roll_end": t_roll, "rest": (rest_xi, rest_eta)}


def _finishers():
    try:
        from numerics import compiled
    except ImportError:
        return engine.first_order_end, engine.roll
    return compiled.first_order_end, compiled.roll


def solve(scene: Scene, tol: float = 1e-12) -> dict:
    """One scene, heyoka's scalar mode: integrated to V = V₀·tol·1e-3 in σ, finished as the engine does."""
    params, y0, V0 = _start(scene, tol)
    ta = _integrator(tol)
    sigma_end = -math.log(V0 * tol * engine.END_FRACTION)
    ta.state[:], ta.time, ta.pars[:] = y0, -math.log(V0), [params[0], params[1], params[2], params[3], params[5]]
    ta.propagate_until(sigma_end)
    return _finish(params, ta.state.copy(), sigma_end, _finishers())


def solve_batch(scenes: list[Scene], tol: float = 1e-12) -> list[dict]:
    """Scenes in groups of heyoka's SIMD width (its batch mode), each lane its own state and parameters."""
    import heyoka as hy

    width = hy.recommended_simd_size()
    ta, finish, out = _integrator(tol, width), _finishers(), []
    for start in range(0, len(scenes), width):
        group = [_start(s, tol) for s in scenes[start : start + width]]
        group += [group[-1]] * (width - len(group))  # pad the last group with copies
        ta.state[:] = np.array([y0 for _, y0, _ in group]).T
        ta.set_time(np.array([-math.log(V0) for _, _, V0 in group]))
        ta.pars[:] = np.array([[p[0], p[1], p[2], p[3], p[5]] for p, _, _ in group]).T
        ends = np.array([-math.log(V0 * tol * engine.END_FRACTION) for _, _, V0 in group])
        ta.propagate_until(ends)
        for lane, (params, _, _) in enumerate(group[: min(width, len(scenes) - start)]):
            out.append(_finish(params, ta.state[:, lane].copy(), ends[lane], finish))
    return out
