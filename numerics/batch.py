"""`simulate_many`: many scenes at once in float64, vectorised over scenes (no Python loop per scene).

The same phases and models as `simulate` (design notes, "model only what a
scene needs"), on arrays:

* sliding — n°3's closed form (δ = 0 or the classical model), the straight
  shots' closed form (θ = ±π/2, Ω₀ = 0, a draw whose spin reverses), and
  for the curved slide with δ > 0 Dormand–Prince 8(5,3) (`dop853`) in
  σ = −ln V, where the whole slide is smooth, each scene with its own steps;
  the slide is followed to V = V₀·tol/100 and finished to first order, the
  slip leaving along β − π/2 (n°8's end of sliding);
* pure rolling — n°7's closed form; pivoting — eq. (5).

The error estimate of a numerically slid scene is the distance between its
rest point and that of a second run at 100× the tolerance, over the distance
travelled: the coarse run's error, so an upper estimate of ours (typically
much too large: at tol 1e-10 the largest estimate over a million random
shots was 2.7e-8, while the actual errors on the benchmark scenes stay below 1e-10).
"""

from __future__ import annotations

import multiprocessing
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from numerics import dop853, equations, phases, validation
from numerics.sliding import SPIN_FLOOR
from numerics.scene import STATE_FIELDS, Params, parse_params, unrepresentable
from numerics.validation import ComputationError, SceneError

# How each scene slides (the `model` array).
NONE, CLASSICAL, FOLLOW, DRAW, DRAW_REVERSED, NUMERICAL = range(6)
MODEL_NAMES = (
    "none (no slip at the start)",
    "closed form n°3 (no rolling couple)",
    "closed form straight shot, θ = π/2",
    "closed form straight shot, θ = −π/2",
    "closed form straight shot, θ = −π/2 then π/2 after the spin reversed",
    "numerical: DOP853 in σ = −ln V",
)
STRAIGHT_ANGLE = 1e-12  # as in `simulate`
CHUNK = 16384  # scenes per array: measured fastest here (8192 and 32768 are slower)
COARSE = 100.0  # the error-estimate run's tolerance, relative to the asked one


@dataclass
class BatchResult:
    """Per scene (arrays of length n); NaN where something never happens (δ = 0: no rest; ε = 0: pivots
    for ever) and in every field of a scene that was refused (``ok`` False, its reason in ``errors``)."""

    t_slide_end: np.ndarray
    t_roll_end: np.ndarray
    t_pivot_end: np.ndarray
    rest: np.ndarray  # (n, 2): ξ, η at rest
    slide_end: np.ndarray  # (n, 4): ξ, η, p, q when the slip vanishes
    model: np.ndarray  # index into MODEL_NAMES (-1: refused)
    error: np.ndarray  # estimated relative error of the rest point (0: closed forms, to rounding)
    stats: dict = field(default_factory=dict)
    ok: np.ndarray | None = None  # False where the scene was refused (with skip_bad)
    errors: dict = field(default_factory=dict)  # index -> why a scene was refused: SceneError or ComputationError


class BadScenesError(SceneError):
    """Some scenes of a batch broke a rule: ``errors`` lists every one (index, SceneError)."""

    def __init__(self, errors: list):
        index, first = errors[0]
        more = f" (and {len(errors) - 1} more bad scenes)" if len(errors) > 1 else ""
        super().__init__(first.within(f"scene [{index}]").field, first.rule + more)
        self.errors = errors


@lru_cache(maxsize=None)
def _numpy_forms():
    """The closed forms of `phases`, compiled for NumPy arrays."""
    return {
        "classical": phases._classical("numpy"),
        "follow": phases._straight("follow", "numpy"),
        "draw": phases._straight("draw", "numpy"),
        "rolling": phases._rolling("numpy"),
        "pivot": phases._pivot("numpy"),
        "slip": equations._compiled_cartesian("numpy")[1],
    }


def warm_up() -> None:
    """Compile every right-hand side and closed form (a few seconds, once per process)."""
    _numpy_forms()
    equations.compiled_log_slip_arrays()
    equations.compiled_sliding_arrays()


def _rotate(x, y, c, s):
    return x * c - y * s, x * s + y * c


def _wrap(angle):
    return np.arctan2(np.sin(angle), np.cos(angle))


def _unit(alpha, p, q):
    """(cos β, sin β); where Ω = 0 the direction it leaves zero along, α + π/2 (n°6)."""
    spin = np.hypot(p, q)
    zero = spin == 0
    safe = np.where(zero, 1.0, spin)
    return np.where(zero, -np.sin(alpha), p / safe), np.where(zero, np.cos(alpha), q / safe)


def _slide_numerical(P: Params, V0, alpha0, p0, q0, xi0, eta0, tol, stats):
    """The curved slide of every lane, to V = 0: (t, ξ, η, p, q) at its end."""
    rates = equations.compiled_log_slip_arrays()
    values = P.values(float)

    def rhs(sigma, y, lanes):
        return np.array(rates(np.exp(-sigma), y[1], y[2], y[3], *values))

    end_fraction = tol / 100
    sigma0, sigma_end = -np.log(V0), -np.log(V0 * end_fraction)
    y0 = np.array([np.zeros_like(V0), alpha0, p0, q0, xi0, eta0])
    t_scale = V0 / (P.f * P.g)
    spin_scale = np.hypot(p0, q0) + V0 / P.R
    base = np.array([t_scale, np.ones_like(V0), spin_scale, spin_scale, V0 * t_scale, V0 * t_scale])

    def scale(y_old, y_new, lanes):
        # Ω relative to itself when it is small: where it passes near zero its direction, and so the
        # rolling couple's, turns fast; measuring p, q against their start size would step over that.
        sc = base[:, lanes].copy()
        spin = np.minimum(np.hypot(y_old[2], y_old[3]), np.hypot(y_new[2], y_new[3]))
        sc[2] = sc[3] = np.maximum(spin, SPIN_FLOOR * base[2, lanes])
        return sc

    y = dop853.integrate(rhs, sigma0, y0, sigma_end, np.full_like(V0, 0.5), scale, tol, stats)
    # The last stretch, V from V₀·tol/100 to 0, to first order in t (as `sliding.slide`).
    V_end = V0 * end_fraction
    cb, sb = _unit(y[1], y[2], y[3])
    dV, _, dp, dq, dxi, deta = equations.compiled_sliding_arrays()(V_end, y[1], y[2], y[3], cb, sb, *values)
    dt = V_end / -dV
    return y[0] + dt, y[4] + dxi * dt, y[5] + deta * dt, y[2] + dp * dt, y[3] + dq * dt


def _roll(P: Params, t0, xi, eta, p, q):
    """n°7 from the end of sliding: (t_roll_end, rest ξ, rest η); NaN when δ = 0."""
    fn, end = _numpy_forms()["rolling"]
    values = P.values(float)
    spin, beta = np.hypot(p, q), np.arctan2(q, p)
    if P.delta == 0:
        nan = np.full_like(spin, np.nan)
        still = spin == 0
        return np.where(still, t0, nan), np.where(still, xi, nan), np.where(still, eta, nan)
    duration = np.asarray(end(spin, beta, *values), dtype=float) * np.ones_like(spin)
    local = fn(duration, spin, beta, *values)
    return t0 + duration, xi + local[3], eta + local[4]


def state_array(states, where: str = "states") -> np.ndarray:
    """An (n, 7) float64 array of states (ξ, η, ξ', η', p, q, r), n >= 1, or SceneError; rows are not yet checked."""
    try:
        array = np.asarray(states)
    except (TypeError, ValueError):  # ragged rows
        raise SceneError(where, "must be an array (n, 7) of numbers, rows of equal length") from None
    if array.dtype.kind == "c":
        raise SceneError(where, f"must be real numbers, got {array.dtype} values")
    if array.dtype.kind not in "biuf":
        try:
            array = array.astype(float)
        except (TypeError, ValueError):
            raise SceneError(where, f"must be numbers, got {array.dtype} values") from None
    array = np.atleast_2d(array).astype(float, copy=False)
    if array.ndim != 2 or array.shape[1] != len(STATE_FIELDS):
        raise SceneError(where, f"must have shape (n, 7) ({', '.join(STATE_FIELDS)}), got {array.shape}")
    if len(array) == 0:
        raise SceneError(where, "no scenes")
    return array


def bad_rows(params: Params, states: np.ndarray) -> list[tuple[int, SceneError]]:
    """Every row that breaks a rule of a state (finite; a motion representable in float64), with its reason
    (the field within the scene: ``error.within(f"scene [{i}]")`` names it in a list)."""
    errors = []
    finite = np.isfinite(states)
    reasons = unrepresentable(params, np.where(finite, states, 0.0))
    for i in range(len(states)):
        if not finite[i].all():
            j = int(np.argmin(finite[i]))
            errors.append((i, SceneError(f"state.{STATE_FIELDS[j]}", f"must be finite, got {states[i, j]}")))
        elif reasons[i]:
            errors.append((i, validation.scale_error("scene", *reasons[i])))
    return errors


def simulate_many(
    params: Params | dict, states, model: str = "appell", tol: float = 1e-9, workers: int = 1,
    chunk: int = CHUNK, progress=None, skip_bad: bool = False,
) -> BatchResult:
    """Every scene of ``states`` (array (n, 7): ξ, η, ξ', η', p, q, r) with the shared ``params``.

    ``tol`` is the relative tolerance of the numerical slide (DOP853); the
    rest point comes out about that accurate (measured: `appell bench`).
    Scenes go in chunks of ``chunk`` (arrays that stay in cache), over
    ``workers`` forked processes; ``progress(done, total)`` after each chunk.

    Bad rows (non-finite, or a motion too large for float64) raise
    `BadScenesError` listing every one; with ``skip_bad`` they are left out
    instead (``ok`` False, NaN, their reason in ``errors``) and the others
    computed.  A scene whose result comes out non-finite is a
    `ComputationError` naming it (with ``skip_bad``: refused like a bad row).
    """
    if not isinstance(params, Params):
        if not isinstance(params, dict):
            raise SceneError("params", f"must be a Params or a dict as in a scene file, got {validation.describe(params)}")
        params = parse_params(params)
    model = validation.model(model)
    tol = validation.tolerance(tol)
    workers = validation.workers(workers)
    chunk = validation.workers(chunk, "chunk")
    states = state_array(states)
    errors = bad_rows(params, states)
    if errors and not skip_bad:
        raise BadScenesError(errors)
    good = np.ones(len(states), dtype=bool)
    good[[i for i, _ in errors]] = False
    result = _simulate_good(params, states[good], model, tol, workers, chunk, progress)
    result = _spread(result, good, len(states))
    result.errors = dict(errors)
    for i, quantity in _first_non_finite(result, params, states).items():
        if not skip_bad:
            raise ComputationError(f"scene [{i}].{quantity}: came out non-finite in float64")
        result.errors[i] = ComputationError(f"{quantity}: came out non-finite in float64")
        result.ok[i] = False
        for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "error"):
            getattr(result, name)[i] = np.nan
        result.model[i] = -1
    return result


def _first_non_finite(result: BatchResult, params: Params, states: np.ndarray) -> dict:
    """index -> the first quantity of a computed scene that is non-finite where the motion has a value."""
    spin_end = np.hypot(result.slide_end[:, 2], result.slide_end[:, 3])
    found: dict = {}
    expected = {
        "t_slide_end": (result.t_slide_end, True),
        "slide_end": (result.slide_end, True),
        "t_roll_end": (result.t_roll_end, params.delta > 0 or None),
        "rest": (result.rest, params.delta > 0 or None),
        "t_pivot_end": (result.t_pivot_end, (params.epsilon > 0) | (states[:, 6] == 0)),
        "error_estimate": (result.error, True),  # last: it is computed from the others
    }
    for name, (values, needed) in expected.items():
        if needed is None:  # δ = 0: rests only when Ω is already 0 at the end of sliding
            needed = spin_end == 0
        values = values.reshape(len(values), -1)
        bad = result.ok & np.asarray(needed) & ~np.isfinite(values).all(axis=1)
        for i in np.flatnonzero(bad):
            found.setdefault(int(i), name)
    return found


def _spread(result: BatchResult, good: np.ndarray, n: int) -> BatchResult:
    """The results of the good rows placed among n rows, NaN (model -1) in the others."""
    if good.all():
        result.ok = good
        return result
    out = {}
    for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "error", "model"):
        values = getattr(result, name)
        full = np.full((n,) + values.shape[1:], -1 if name == "model" else np.nan, dtype=values.dtype)
        full[good] = values
        out[name] = full
    return BatchResult(**out, stats=result.stats, ok=good.copy())


def _simulate_good(params, states, model, tol, workers, chunk, progress) -> BatchResult:
    if len(states) == 0:
        empty = np.zeros(0)
        return BatchResult(empty, empty, empty, np.zeros((0, 2)), np.zeros((0, 4)), np.zeros(0, dtype=int), empty,
                           {"steps": 0, "rejected": 0, "evaluations": 0})
    pieces = [states[i : i + chunk] for i in range(0, len(states), chunk)]
    results = []
    if workers > 1 and len(pieces) > 1:
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            jobs = [(params, piece, model, tol) for piece in pieces]
            for result in pool.imap(_chunk_job, jobs):
                results.append(result)
                if progress:
                    progress(sum(len(r.t_slide_end) for r in results), len(states))
    else:
        for piece in pieces:
            results.append(_simulate_chunk(params, piece, model, tol))
            if progress:
                progress(sum(len(r.t_slide_end) for r in results), len(states))
    return _concatenate(results)


def _chunk_job(job):
    return _simulate_chunk(*job)


def _simulate_chunk(params: Params, states: np.ndarray, model: str, tol: float) -> BatchResult:
    """`simulate_many` on one chunk of scenes; a lane that overflows ends NaN, named afterwards, not warned about."""
    with np.errstate(all="ignore"):
        return _chunk(params, states, model, tol)


def _concatenate(results: list[BatchResult]) -> BatchResult:
    if len(results) == 1:
        return results[0]
    stats = {k: sum(r.stats[k] for r in results) for k in results[0].stats}
    arrays = {
        name: np.concatenate([getattr(r, name) for r in results])
        for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "model", "error")
    }
    return BatchResult(**arrays, stats=stats)


def _chunk(params: Params, states: np.ndarray, model: str, tol: float) -> BatchResult:
    """`simulate_many` on one chunk of scenes (all the array work)."""
    stats = {"steps": 0, "rejected": 0, "evaluations": 0}
    forms = _numpy_forms()
    values = params.values(float)
    xi0, eta0, vxi, veta, p0, q0, r0 = states.T
    n = len(states)
    u, v = (np.asarray(a, dtype=float) * np.ones(n) for a in forms["slip"](vxi, veta, p0, q0, *values))
    V0, alpha0 = np.hypot(u, v), np.arctan2(v, u)
    Omega0, beta0 = np.hypot(p0, q0), np.arctan2(q0, p0)
    theta0 = _wrap(beta0 - alpha0)
    scale = np.maximum.reduce([abs(vxi), abs(veta), params.R * abs(p0), params.R * abs(q0), np.full(n, 1e-300)])

    kind = np.full(n, NUMERICAL)
    kind[abs(theta0 + np.pi / 2) <= STRAIGHT_ANGLE] = DRAW
    kind[(Omega0 <= 1e-14 * scale / params.R) | (abs(theta0 - np.pi / 2) <= STRAIGHT_ANGLE)] = FOLLOW
    if model == "classical" or params.delta == 0:
        kind[:] = CLASSICAL
    kind[V0 <= 1e-14 * scale] = NONE

    t1 = np.zeros(n)
    xi1, eta1, p1, q1 = xi0.copy(), eta0.copy(), p0.copy(), q0.copy()
    error = np.zeros(n)
    ca, sa = np.cos(alpha0), np.sin(alpha0)

    def place(idx, duration, local, offset=(0.0, 0.0)):
        """Closed-form end of slide, slip frame → world."""
        dx, dy = _rotate(local[3], local[4], ca[idx], sa[idx])
        t1[idx] = duration
        xi1[idx], eta1[idx] = xi0[idx] + offset[0] + dx, eta0[idx] + offset[1] + dy
        p1[idx], q1[idx] = _rotate(local[1], local[2], ca[idx], sa[idx])

    idx = np.flatnonzero(kind == CLASSICAL)
    if idx.size:
        fn, end = forms["classical"]
        args = (V0[idx], Omega0[idx], theta0[idx]) + values
        duration = end(*args) * np.ones(idx.size)
        place(idx, duration, fn(duration, *args))
    idx = np.flatnonzero(kind == FOLLOW)
    if idx.size:
        fn, ends = forms["follow"]
        args = (V0[idx], Omega0[idx]) + values
        duration = ends(*args)[0] * np.ones(idx.size)
        place(idx, duration, fn(duration, *args))
    idx = np.flatnonzero(kind == DRAW)
    if idx.size:
        fn, ends = forms["draw"]
        args = (V0[idx], Omega0[idx]) + values
        slip_end, spin_end = (np.asarray(e) * np.ones(idx.size) for e in ends(*args))
        plain = slip_end <= spin_end
        if plain.any():
            j = idx[plain]
            place(j, slip_end[plain], [np.asarray(x)[plain] if np.ndim(x) else x for x in fn(slip_end, *args)])
        if (~plain).any():
            # Ω reaches 0 first and comes back along β = α + π/2 (n°6): the follow law from there.
            j, sub = idx[~plain], ~plain
            mid = [np.asarray(x) * np.ones(idx.size) for x in fn(spin_end, *args)]
            f_fn, f_ends = forms["follow"]
            f_args = (mid[0][sub], np.zeros(j.size)) + values
            rest_of_slide = f_ends(*f_args)[0] * np.ones(j.size)
            offset = _rotate(mid[3][sub], mid[4][sub], ca[j], sa[j])
            place(j, spin_end[sub] + rest_of_slide, f_fn(rest_of_slide, *f_args), offset)
            kind[j] = DRAW_REVERSED
    idx = np.flatnonzero(kind == NUMERICAL)
    if idx.size:
        args = (V0[idx], alpha0[idx], p0[idx], q0[idx], xi0[idx], eta0[idx])
        fine = _slide_numerical(params, *args, tol, stats)
        coarse = _slide_numerical(params, *args, tol * COARSE, {"steps": 0, "rejected": 0, "evaluations": 0})
        t1[idx], xi1[idx], eta1[idx], p1[idx], q1[idx] = fine
        _, rest_x, rest_y = _roll(params, *fine)
        _, c_x, c_y = _roll(params, *coarse)
        if params.delta > 0:
            travel = np.hypot(rest_x - xi0[idx], rest_y - eta0[idx]) + params.R
            error[idx] = np.hypot(rest_x - c_x, rest_y - c_y) / travel

    t2, rest_xi, rest_eta = _roll(params, t1, xi1, eta1, p1, q1)
    if params.epsilon > 0:
        pivot_end = np.where(r0 == 0, 0.0, forms["pivot"][1](abs(r0), *values))
    else:
        pivot_end = np.where(r0 == 0, 0.0, np.nan)
    return BatchResult(
        t_slide_end=t1, t_roll_end=t2, t_pivot_end=np.asarray(pivot_end, dtype=float),
        rest=np.column_stack([rest_xi, rest_eta]), slide_end=np.column_stack([xi1, eta1, p1, q1]),
        model=kind, error=error, stats=stats,
    )


def scene_states(scenes) -> tuple[Params, np.ndarray, str]:
    """(shared params, states array, model) of a list of `Scene`s that share params and model."""
    if len(scenes) == 0:
        raise SceneError("scenes", "no scenes")
    first = scenes[0]
    for i, s in enumerate(scenes):
        if s.params != first.params or s.model != first.model:
            raise SceneError(f"scene [{i}]", "params and model must be the same for every scene of a batch")
    return first.params, np.array([s.state.row() for s in scenes], dtype=float), first.model

