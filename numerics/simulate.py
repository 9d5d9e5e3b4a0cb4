"""`simulate(scene)`: the whole motion of one ball, phase by phase — the phase engine on a batch of one.

The phases and their models are `numerics.engine`'s (n°3 or the straight
shots in closed form, the curved slide by DOP853 in σ = −ln V, n°7's pure
rolling, eq. (5)'s pivot); this module is the API over one solved scene: the
phase times, the rest point, the state at any time (`Motion.state_at`, and
`Motion.states` on an array of times, from the slide's 7th-order dense output (substeps in a stiff step)
and the closed forms), and the error estimate.

The engine runs compiled by numba (`numerics.compiled`) unless ``jit=False``
or ``APPELL_JIT=0`` (read when this module is imported): compiled, one scene takes tens of microseconds after a
first call that loads the compiled code (or, the first time ever, compiles
it); interpreted, it takes tens of milliseconds but starts at once, which is
what the command line does for a single scene.
"""

from __future__ import annotations

import math
import os
import warnings
from dataclasses import dataclass

import numpy as np

from numerics import engine, validation
from numerics.scene import MAX_TIMES, PARAM_FIELDS, STATE_FIELDS, Scene, parse
from numerics.validation import ComputationError, SceneError

DENSE_ROWS = 256  # steps of a slide kept for its dense output (a slide takes tens to a few hundred)
PHASES = ("sliding", "rolling", "rest")


_COMPILED = []  # the compiled engine, once imported
# jit=None means compiled, unless APPELL_JIT=0: read once, when this module is imported (looking it up at every
# call cost 1.3–1.7 µs, a tenth of a compiled scene's time).
# Any other value ("no", "false") is refused at the first call that reads it, naming the variable: read as "not 0",
# "no" meant compiled, silently (an audit).
JIT = {"0": False, "1": True}.get(os.environ.get("APPELL_JIT", "1").strip())


def jit_default() -> bool:
    """What ``jit=None`` means: APPELL_JIT's 0 or 1 (default 1); another value is refused, naming it."""
    if JIT is None:
        raise SceneError("APPELL_JIT", f"must be 0 (the interpreted engine) or 1 (compiled), got {os.environ.get('APPELL_JIT')!r}")
    return JIT


def engine_for(jit):
    """The compiled engine when asked (``jit`` None: as APPELL_JIT says, and numba is there), else the
    interpreted one."""
    if not (jit is None or isinstance(jit, (bool, np.bool_))):  # "no" would be true
        raise SceneError("jit", f"must be True, False or None, got {validation.describe(jit)}")
    if jit is None:
        jit = jit_default()
    if not jit:
        return engine
    if not _COMPILED:
        try:
            from numerics import compiled
        except ImportError:  # numba missing: the same code, interpreted
            return engine
        _COMPILED.append(compiled)
    return _COMPILED[0]


@dataclass(frozen=True)
class PhaseRecord:
    phase: str  # sliding, rolling, rest, pivoting
    t_start: float
    t_end: float | None  # None: never ends
    model: str
    # The estimated relative error of the rest point, on the sliding phase (closed forms: their rounding,
    # `engine.closed_estimate`; None: no rest point); the phases after it None: the rest point's estimate is the
    # slide's, carried through the rolling (an audit read their 0.0 as exact).
    error: float | None


@dataclass(frozen=True)
class BallState:
    t: float
    phase: str
    xi: float
    eta: float
    vxi: float
    veta: float
    p: float
    q: float
    r: float


@dataclass(frozen=True)
class States:
    """States at an array of times (`Motion.states`): one array per quantity, ``phase`` an index into PHASES."""

    t: np.ndarray
    phase: np.ndarray
    xi: np.ndarray
    eta: np.ndarray
    vxi: np.ndarray
    veta: np.ndarray
    p: np.ndarray
    q: np.ndarray
    r: np.ndarray


def _finite_or_none(x: float) -> float | None:
    return None if math.isinf(x) else float(x)


def _estimate(out: np.ndarray) -> float | None:
    """The rest point's estimated relative error; None when there is no rest point (δ = 0: the engine's 0.0 was
    read as an exact answer, a user audit), in the API, the JSON and the phases alike."""
    return None if math.isinf(out[engine.OUT_T_ROLL]) else float(out[engine.OUT_ERROR])


class Motion:
    """The solved motion of one scene (from `simulate`, or a row of `simulate_many`)."""

    def __init__(self, scene: Scene, tol: float, out: np.ndarray, dense: np.ndarray | None = None, jit=None):
        self.scene, self.tol, self._out, self._dense, self._jit = scene, tol, out, dense, jit

    @property
    def row(self) -> np.ndarray:
        """The engine's row of this scene (columns `engine.OUT_*`), a copy: what every field here is read from."""
        return self._out.copy()

    @property
    def model(self) -> str:
        """How the ball slides: a closed form, or numerical (`engine.MODEL_NAMES`)."""
        return engine.MODEL_NAMES[int(self._out[engine.OUT_MODEL])]

    @property
    def t_slide_end(self) -> float:
        return float(self._out[engine.OUT_T_SLIDE])

    @property
    def t_roll_end(self) -> float | None:
        """None: rolls for ever (δ = 0)."""
        return _finite_or_none(self._out[engine.OUT_T_ROLL])

    @property
    def t_pivot_end(self) -> float | None:
        """None: pivots for ever (ε = 0, r ≠ 0)."""
        return _finite_or_none(self._out[engine.OUT_T_PIVOT])

    @property
    def rest(self) -> tuple | None:
        if self.t_roll_end is None:
            return None
        return float(self._out[engine.OUT_REST_XI]), float(self._out[engine.OUT_REST_ETA])

    @property
    def error(self) -> float | None:
        """An estimate (not a bound) of the rest point's relative error: DOP853's local estimates summed, times 2
        (README, "Error estimates"); for closed forms, their rounding (`engine.closed_estimate`); None without a
        rest point (δ = 0)."""
        return _estimate(self._out)

    @property
    def phases(self) -> list[PhaseRecord]:
        return phase_records(self._out)

    def _dense_output(self) -> np.ndarray:
        """The numerical slide's steps and their interpolants, computed the first time a state inside the slide
        is asked (the same slide again, keeping its steps; other phases need none)."""
        if self._dense is None:
            self._dense = _solve(self.scene, self.tol, engine_for(self._jit), dense=True)[1]
        return self._dense

    def states(self, times) -> States:
        """The state at every time of ``times`` (an array, each ≥ 0, finite): one compiled loop, no Python per time."""
        if isinstance(times, np.ma.MaskedArray):  # np.asarray would take the masked times as given
            if np.ma.getmaskarray(times).any():
                raise SceneError("t", "must be times, got a masked array with masked values (give only the times wanted)")
            times = times.data
        try:
            ts = np.atleast_1d(np.asarray(times))
            if ts.dtype.kind in "bcmMUSV":  # booleans, complex numbers, dates, text, records: not times
                raise TypeError
            ts = ts.astype(float)
        except (TypeError, ValueError):  # and a set, ragged lists, objects that are not numbers
            raise SceneError("t", f"must be an array of times (real numbers), got {validation.describe(times)}") from None
        if ts.ndim != 1 or ts.size == 0:
            raise SceneError("t", f"must be a 1-D array of at least one time, got shape {ts.shape}")
        if not np.all(np.isfinite(ts)) or np.any(ts < 0):
            bad = ts[~(np.isfinite(ts) & (ts >= 0))][0]
            raise SceneError("t", f"must be finite and >= 0, got {bad}")
        if ts.max() >= validation.SCALE_LIMIT:  # as for the times of a scene: far inside float64
            raise validation.UnrepresentableError("t", f"the state at t = {ts.max():g} s is not representable in float64")
        result = np.empty((len(ts), 8))
        in_slide = self._out[engine.OUT_MODEL] == engine.NUMERICAL and ts.min() <= self.t_slide_end
        dense = self._dense_output() if in_slide else NO_DENSE
        params, state = self.scene.arrays()
        engine_for(self._jit).states_at(ts, params, state, self._out, dense, result)
        finite = np.isfinite(result).all(axis=1)
        if not finite.all():
            bad = ts[np.argmin(finite)]
            raise validation.UnrepresentableError("t", f"the state at t = {bad:g} s is not representable in float64")
        return States(ts, result[:, 0].astype(int), *(result[:, j] for j in range(1, 8)))

    def state_at(self, t: float) -> BallState:
        t = validation.real(t, "t")
        if t < 0:
            raise SceneError("t", f"must be >= 0, got {t}")
        s = self.states([t])
        return BallState(t, PHASES[s.phase[0]], *(float(getattr(s, n)[0]) for n in ("xi", "eta", "vxi", "veta", "p", "q", "r")))

    def samples(self, n: int = 200) -> list[BallState]:
        """n + 1 states evenly spaced from 0 to rest (to 2 t_slide_end + 1 s when the ball never rests): for plots."""
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n < MAX_TIMES:
            raise SceneError("samples", f"must be an integer >= 1 and < {MAX_TIMES:,}, got {validation.describe(n)}")
        end = self.t_roll_end if self.t_roll_end is not None else 2 * self.t_slide_end + 1.0
        end = max(end, self.t_pivot_end or 0.0)
        s = self.states(np.linspace(0.0, end, int(n) + 1))  # the last exactly at the end (end·n/n need not be end)
        return [BallState(float(t), PHASES[k], *map(float, row)) for t, k, *row in
                zip(s.t, s.phase, s.xi, s.eta, s.vxi, s.veta, s.p, s.q, s.r)]

    def plot(self, ax=None, title: str | None = None):
        """The picture of the motion (`numerics.plot.draw`): the centre's path with its phases coloured — the
        slide, n°7's pure rolling — the end of sliding and the rest point marked, beside V, Ω and the pivot spin
        r of eq. (5) against time.  Returns the matplotlib Figure (``motion.plot().savefig("shot.png")``); with
        ``ax``, only the path is drawn, into ``ax``, and ``ax.figure`` is returned."""
        from numerics import plot  # matplotlib only when a picture is asked for

        return plot.draw(self, ax, title)

    def as_dict(self, times=None) -> dict:
        """The record `appell simulate --json` prints for a scene: its states at the scene's own times
        (``scene.times``, its ``t`` list), or at ``times`` when given (a sequence)."""
        times = self.scene.times if times is None else times
        if isinstance(times, (str, bytes)) or not hasattr(times, "__iter__"):
            raise SceneError("t", f"must be a list of times, got {validation.describe(times)}")
        scene = self.scene
        return {**record(self._out, scene.model, self.tol, scene.params, scene.arrays()[1]),
                "states": [vars(self.state_at(t)) for t in times]}


def phase_records(out: np.ndarray) -> list[PhaseRecord]:
    """The phases of a solved scene, from its row of the engine."""
    t1, t2, t3 = float(out[engine.OUT_T_SLIDE]), _finite_or_none(out[engine.OUT_T_ROLL]), _finite_or_none(out[engine.OUT_T_PIVOT])
    model = int(out[engine.OUT_MODEL])
    records = []
    if model != engine.NONE:
        records.append(PhaseRecord("sliding", 0.0, t1, engine.MODEL_NAMES[model], _estimate(out)))
    if math.hypot(out[engine.OUT_END_P], out[engine.OUT_END_Q]) > 0:
        records.append(PhaseRecord("rolling", t1, t2, "closed form n°7 (pure rolling)", None))
    if t2 is not None:
        records.append(PhaseRecord("rest", t2, None, "rest", None))
    records.append(PhaseRecord("pivoting", 0.0, t3, "closed form eq. (5)", None))
    return records


def record(out: np.ndarray, model: str, tol: float, params, start) -> dict:
    """A solved scene as `appell simulate --json` prints it (without states): with its params and its start
    (ξ, η, ξ', η', p, q, r; a cue's stroke turned into the state it gives), so that a record is a scene again."""
    t_roll = _finite_or_none(out[engine.OUT_T_ROLL])
    return {
        "model": model,
        "tol": tol,
        "params": {name: float(getattr(params, name)) for name in PARAM_FIELDS},
        "start": {name: float(x) for name, x in zip(STATE_FIELDS, start, strict=True)},
        "phases": [vars(p) for p in phase_records(out)],
        "t_slide_end": float(out[engine.OUT_T_SLIDE]),
        "t_roll_end": t_roll,
        "t_pivot_end": _finite_or_none(out[engine.OUT_T_PIVOT]),
        "rest": None if t_roll is None else {"xi": float(out[engine.OUT_REST_XI]), "eta": float(out[engine.OUT_REST_ETA])},
        "error_estimate": _estimate(out),
    }


def problem(out: np.ndarray) -> str | None:
    """What is wrong with a solved row ("slide: not done after … steps", "rest: came out non-finite …"), or None."""
    status = out[engine.OUT_STATUS]
    if status == engine.WORK_LIMIT:
        return f"slide: not done after {engine.MAX_STEPS} steps"
    if status == engine.NON_FINITE:
        index = engine.first_non_finite(out)
        return f"{engine.OUT_NAMES.get(index, 'slide')}: came out non-finite in float64"
    return None


def check_result(out: np.ndarray, where: str = "scene") -> None:
    """A solved row's trouble as an error naming the scene and the quantity: never a NaN as an answer."""
    found = problem(out)
    if found is None:
        return
    error = validation.WorkLimitError if out[engine.OUT_STATUS] == engine.WORK_LIMIT else ComputationError
    raise error(f"{where}.{found}")


NO_DENSE = np.empty((0, engine.DENSE_WIDTH))


def _solve(scene: Scene, tol: float, run, dense: bool) -> tuple[np.ndarray, np.ndarray]:
    """(the result row, the slide's dense rows) of one scene; the rows are kept only when asked."""
    params, state = scene.arrays()
    out, rows = np.empty(engine.N_OUT), DENSE_ROWS if dense else 0
    while True:
        buffer = np.empty((rows, engine.DENSE_WIDTH)) if rows else NO_DENSE
        run.solve(params, state, scene.model == "classical", tol, out, buffer)
        if not dense or out[engine.OUT_DENSE] < rows or rows >= engine.MAX_STEPS:
            break
        rows *= 8  # a slide of more steps than kept: again, with room for all of them
    return out, buffer[: int(out[engine.OUT_DENSE])].copy() if dense else NO_DENSE


def simulate(scene: Scene | dict, tol: float = validation.DEFAULT_TOL, jit=None) -> Motion:
    """The whole motion of ``scene`` (a `Scene`, or a dict as in a scene file) until rest; the rest point
    within ``tol`` relative to its distance from the start, plus R (the numerical slide's tolerance; so is every
    state asked), as far as float64 resolves it: far from the origin the coordinates' rounding (an ulp of their
    size a step) can exceed a fine ``tol``, and ``Motion.error``, which includes it, says so (README, "Error
    estimates"); an estimate above `validation.TOL_WARNING` × tol warns (`validation.ToleranceWarning`).

    Bad input is a `SceneError` naming the field; a result that comes out non-finite is a
    `ComputationError` naming the quantity, never returned.
    """
    if not isinstance(scene, (Scene, dict)):
        raise SceneError("scene", f"must be a Scene or a dict as in a scene file, got {validation.describe(scene)}")
    scene = parse(scene)
    tol = validation.tolerance(tol)
    out, _ = _solve(scene, tol, engine_for(jit), dense=False)
    check_result(out)
    motion = Motion(scene, tol, out, None, jit)
    beyond = validation.beyond_tolerance(motion.error, tol)
    if beyond:  # the result stands, with what it is worth said (README, "Error estimates")
        warnings.warn(validation.ToleranceWarning(beyond), stacklevel=2)
    return motion
