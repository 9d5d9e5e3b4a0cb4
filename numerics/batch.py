"""`simulate_many`: many scenes at once, each with its own parameters and model — the phase engine on a batch.

The same engine as `simulate` (`numerics.engine`, compiled by numba in
`numerics.compiled`): each scene is classified, its closed forms evaluated,
its curved slide integrated by DOP853 in σ = −ln V; chunks of scenes are
spread over threads, each a compiled loop that releases the GIL (no Python
per scene, no process pool).  The rows of the input are checked first (`bad_rows`): every
bad one is named, and nothing is computed unless ``skip_bad``.
"""

from __future__ import annotations

import itertools
import math
import operator
import os
import warnings
from concurrent.futures import ThreadPoolExecutor, as_completed
from functools import lru_cache

import numpy as np

from numerics import engine, lanes, validation
from numerics.engine import CLASSICAL, DRAW, DRAW_REVERSED, FOLLOW, MODEL_NAMES, NONE, NUMERICAL  # noqa: F401
from numerics.scene import ENGINE_PARAMS, STATE_FIELDS, Coefficients, Params, Scene, parse, parse_params, unrepresentable
from numerics.simulate import Motion, _solve, engine_for, problem
from numerics.validation import ComputationError, SceneError

CHUNK = 65536  # scenes per compiled call at most: progress is reported, and Ctrl-C answered, between chunks
SERIAL_BELOW = 128  # fewer scenes run in the calling thread alone: waking a thread costs ~50 µs (128: as fast either way)


def _columns(*columns):
    """Row columns as an index: a slice when they are adjacent (its copy costs a quarter of a gather's)."""
    return slice(columns[0], columns[-1] + 1) if columns == tuple(range(columns[0], columns[-1] + 1)) else list(columns)


def _copy(*columns):
    """A reader of these columns of a result's rows: a copy (the rows stay what `motion` checks), C-contiguous;
    of one column, a 1-D array."""
    index = columns[0] if len(columns) == 1 else _columns(*columns)
    return lambda result: result.rows[:, index].copy()


class _Field:
    """A field of `BatchResult`, read from its engine rows when first asked and kept (as an instance attribute,
    which the next access finds first); ``refused`` in a refused scene's entries.  Read when asked: building
    every field for every call cost 4 µs, a twentieth of a call of ten curved slides."""

    def __init__(self, read, refused=np.nan):
        self.read, self.refused = read, refused

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, result, owner=None):
        if result is None:
            return self
        value = self.read(result)
        if result.errors:  # exactly the refused rows: one refused before solving is NaN already, one whose
            value[~result.ok] = self.refused  # computation failed is not
        result.__dict__[self.name] = value
        return value


class BatchResult:
    """Per scene (arrays of length n).  Times that never come are ∞ (δ = 0: no end of rolling; ε = 0: no
    end of the pivot), a rest point that never comes NaN; a refused scene (``ok`` False, its reason in
    ``errors``) is NaN everywhere and model -1.  The arrays are read from ``rows``, the engine's rows
    (engine.OUT_*), when first asked."""

    t_slide_end = _Field(_copy(engine.OUT_T_SLIDE))
    t_roll_end = _Field(_copy(engine.OUT_T_ROLL))
    t_pivot_end = _Field(_copy(engine.OUT_T_PIVOT))
    rest = _Field(_copy(engine.OUT_REST_XI, engine.OUT_REST_ETA))  # (n, 2): ξ, η at rest
    # (n, 4): ξ, η, p, q when the slip vanishes
    slide_end = _Field(_copy(engine.OUT_END_XI, engine.OUT_END_ETA, engine.OUT_END_P, engine.OUT_END_Q))
    # An estimate (not a bound) of the rest point's relative error, as Motion.error (closed forms: their rounding);
    # NaN where no rest point comes (δ = 0), as the rest point.
    error = _Field(lambda result: np.where(np.isinf(result.rows[:, engine.OUT_T_ROLL]), np.nan, result.rows[:, engine.OUT_ERROR]))
    # Index into MODEL_NAMES (-1: refused; fmax turns a row refused before solving, NaN, into -1).
    model = _Field(lambda result: np.fmax(result.rows[:, engine.OUT_MODEL], -1).astype(int), refused=-1)

    def __init__(self, rows: np.ndarray, ok: np.ndarray, errors: dict, tol: float | None = None):
        self.rows = rows  # the engine's rows: what the fields, `stats` and `motion` read
        self.ok = ok
        self.errors = errors  # index -> why a scene was refused: SceneError or ComputationError
        self.tol = tol  # the tolerance the rows were computed with (`motion` takes it from here)

    @property
    def stats(self) -> dict:
        """Steps accepted and rejected over the rows solved, and how many slides were numerical: counted when
        asked (counting them for every call cost a fifth of a small batch's time in Python)."""
        rows = self.rows
        return {
            "steps": _count(rows[:, engine.OUT_STEPS]), "rejected": _count(rows[:, engine.OUT_REJECTED]),
            "numerical": int(np.count_nonzero(rows[:, engine.OUT_MODEL] == NUMERICAL)),
        }

    def __repr__(self) -> str:
        return f"BatchResult({len(self.rows)} scenes, {len(self.errors)} refused)"


class BadScenesError(SceneError):
    """Some scenes of a batch broke a rule: ``errors`` lists every one (index, SceneError)."""

    def __init__(self, errors: list):
        index, first = errors[0]
        more = f" (and {len(errors) - 1} more bad scenes)" if len(errors) > 1 else ""
        super().__init__(first.within(f"scene [{index}]").field, first.rule + more)
        self.errors = errors


def state_array(states, where: str = "states") -> np.ndarray:
    """An (n, 7) float64 array of states (ξ, η, ξ', η', p, q, r), n >= 1 (7 numbers: one row), or SceneError; rows
    are not yet checked."""
    if isinstance(states, np.ma.MaskedArray):  # np.asarray would take the masked values as given
        if np.ma.getmaskarray(states).any():
            raise SceneError(where, "must be numbers, got a masked array with masked values (give only the rows to simulate)")
        states = states.data
    if isinstance(states, (list, tuple)):  # np.asarray would read [True, 0.5] as [1.0, 0.5]: booleans are no numbers
        try:
            cells = np.asarray(states, dtype=object)
        except ValueError:  # ragged rows: said below
            cells = np.empty(0, dtype=object)
        bad = next((x for x in cells.flat if isinstance(x, (bool, np.bool_))), None)
        if bad is not None:
            raise SceneError(where, f"must be numbers, got {validation.describe(bad)}")
    try:
        array = np.asarray(states)
    except (TypeError, ValueError):  # ragged rows
        raise SceneError(where, "must be an array (n, 7) of numbers, rows of equal length") from None
    if array.dtype.kind == "c":
        raise SceneError(where, f"must be real numbers, got {array.dtype} values")
    if array.dtype.kind in "bmMUSV":  # booleans, times, text, records: not numbers (as in a scene file)
        raise SceneError(where, f"must be numbers, got {array.dtype} values")
    if array.dtype.kind == "O":  # Python objects: numbers only, as in a scene file (astype would read "2" as 2.0)
        bad = next((x for x in array.flat if not validation.is_real(x)), None)
        if bad is not None:
            raise SceneError(where, f"must be numbers, got {validation.describe(bad)}")
    if array.ndim != 2:  # (np.atleast_2d made () and (7,) one row: (1, 1) was named for a scalar, an audit)
        if array.ndim == 1 and len(array) == len(STATE_FIELDS):
            array = array[np.newaxis]  # one state
        else:
            shown = "None" if states is None else str(array.shape)
            raise SceneError(where, f"must have shape (n, 7) ({', '.join(STATE_FIELDS)}), got {shown}")
    if array.dtype != np.float64:  # (np.errstate costs 2 µs: not on the common case, a float64 array)
        given = array
        try:
            with np.errstate(over="raise"):  # a longdouble beyond float64 would become ∞ with a warning
                array = array.astype(float)
        except (TypeError, ValueError):
            raise SceneError(where, f"must be numbers, got {array.dtype} values") from None
        except (FloatingPointError, OverflowError):  # a longdouble, or a Python integer like 10**400
            raise SceneError(where, "must be within float64's range, got larger values") from None
        lost = np.argwhere((array == 0) & (given != 0))  # a longdouble 1e-4000 read as 0: a moving ball set still
        if len(lost):
            i, j = lost[0]
            raise SceneError(f"{where} [{i}].{STATE_FIELDS[j]}", "must be 0 or at least 4.9e-324 in size (float64's "
                             f"smallest), got {validation.describe(given[i, j])}")
    if array.shape[1] != len(STATE_FIELDS):
        raise SceneError(where, f"must have shape (n, 7) ({', '.join(STATE_FIELDS)}), got {array.shape}")
    if len(array) == 0:
        raise SceneError(where, "no scenes")
    return array


def params_table(params, n: int, refused: list | None = None) -> np.ndarray:
    """(n, 6) rows (f, R, k, δ, ε, g): one `Params` (or dict) for every scene, or a sequence of them, one each.

    A bad entry of a sequence raises, naming its scene; given a list ``refused``, it is appended there instead
    ((index, SceneError) as `bad_rows` gives them) and its row holds a placeholder ball's values (`PLACEHOLDER`:
    the row is not solved)."""
    if isinstance(params, (Coefficients, dict)):
        one = params if isinstance(params, Params) else _as_params(params, "params")
        table = np.empty((n, len(ENGINE_PARAMS)))
        table[:] = one.values()  # np.tile's rows, at a quarter of its cost
        return table
    if isinstance(params, (str, bytes)) or not hasattr(params, "__len__"):
        raise SceneError("params", f"must be a Params, a dict as in a scene file, or one per scene, got {validation.describe(params)}")
    if len(params) != n:
        raise SceneError("params", f"must be one for every scene ({n}), got {len(params)}")
    if isinstance(params, (list, tuple)) and set(map(type, params)) == {Params}:
        # The common case, a list of Params: their fields (floats, as values() gives them) read in C, no Python per
        # scene; anything else (dicts, subclasses, wrong kinds) below, each named.
        values = itertools.chain.from_iterable(map(_PARAM_VALUES, params))
        return np.fromiter(values, float, n * len(ENGINE_PARAMS)).reshape(n, len(ENGINE_PARAMS))
    return np.array([_entry(lambda: _as_params(p, "params").values(), i, refused, PLACEHOLDER.values())
                     for i, p in enumerate(params)])


def _entry(read, i: int, refused: list | None, placeholder):
    """``read()`` for scene ``i`` of a sequence: its SceneError raised naming the scene, or (given ``refused``)
    kept there and ``placeholder`` returned."""
    try:
        return read()
    except SceneError as error:
        if refused is None:
            raise error.within(f"scene [{i}]") from None
        refused.append((i, error))
        return placeholder


_PARAM_VALUES = operator.attrgetter(*ENGINE_PARAMS)  # a Params' fields as `Coefficients.values` gives them
PLACEHOLDER = Params(f=1.0, delta=0.0, epsilon=0.0, R=1.0)  # a refused entry's row: any valid ball (it is not solved)


def _as_params(p, where: str) -> Params:
    if isinstance(p, Params):
        return p
    if isinstance(p, dict):
        try:
            return parse_params(p)
        except SceneError as error:
            raise SceneError(where + error.field[len("params"):], error.rule) from None
    raise SceneError(where, f"must be a Params or a dict as in a scene file, got {validation.describe(p)}")


def classical_flags(model, n: int, refused: list | None = None) -> np.ndarray:
    """One model for every scene ("appell" or "classical"), or a sequence of them: True where classical.  A bad
    entry of a sequence raises naming its scene, or with a list ``refused`` is kept there (as `params_table`)."""
    if isinstance(model, str):
        return (np.ones if validation.model(model) == "classical" else np.zeros)(n, dtype=bool)  # np.full's, in half the time
    if not hasattr(model, "__len__") or len(model) != n:
        raise SceneError("model", f"must be appell, classical, or one for every scene ({n}), got {validation.describe(model)}")
    if isinstance(model, (list, tuple)) and set(map(type, model)) == {str} and set(model) <= set(validation.MODELS):
        return np.fromiter(map("classical".__eq__, model), bool, n)  # every one a model's name: compared in C
    return np.array([_entry(lambda: validation.model(m, "model") == "classical", i, refused, False)
                     for i, m in enumerate(model)], dtype=bool)


def bad_rows(params, states: np.ndarray, run=engine) -> list[tuple[int, SceneError]]:
    """Every row that breaks a rule of a state (finite; a motion representable in float64), with its reason
    (the field within the scene: ``error.within(f"scene [{i}]")`` names it in a list).  ``params``: one
    `Params` for every row, or the (n, 6) table; ``run``: the engine that bounds the scales."""
    errors = []
    if not isinstance(params, Coefficients) and run.all_within(params, states, validation.SCALE_LIMIT):
        return errors  # the common case, one compiled pass (a quarter of the checks below)
    finite = np.isfinite(states)
    if np.count_nonzero(finite) == finite.size:  # all finite (half the cost of .all())
        reasons = unrepresentable(params, states, run=run)
        if not any(reasons):  # the common case, in C
            return errors
        return [(int(i), validation.scale_error(*reason)) for i, reason in enumerate(reasons) if reason]
    reasons = unrepresentable(params, np.where(finite, states, 0.0), run=run)
    for i in range(len(states)):
        if not finite[i].all():
            j = int(np.argmin(finite[i]))
            errors.append((i, SceneError(f"state.{STATE_FIELDS[j]}", f"must be finite, got {states[i, j]}")))
        elif reasons[i]:
            errors.append((i, validation.scale_error(*reasons[i])))
    return errors


def _threads(workers) -> int:
    """Threads for a batch: ``workers`` (an integer >= 1, at most the cores this process may use), or all."""
    most = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return most if workers is None else min(validation.workers(workers), most)


def threads_for(total: int, workers=None, interpreted: bool = False) -> int:
    """The threads a batch of ``total`` scenes runs on: one below SERIAL_BELOW scenes or with the interpreted engine
    (it holds the GIL), else ``workers``' count (`_threads`; counted only then: a system call)."""
    return 1 if total < SERIAL_BELOW or interpreted else _threads(workers)


@lru_cache(maxsize=None)
def _pool(threads: int) -> ThreadPoolExecutor:
    """One pool per thread count, kept for the process: starting threads costs more than a small batch."""
    return ThreadPoolExecutor(threads, thread_name_prefix="appell-batch")


def _engine_array(array: np.ndarray) -> np.ndarray:
    """``array`` as the compiled engine takes it, C-contiguous, aligned and writable, copied only when not: numba
    types an array by its layout and flags too, and another type would compile another copy of the engine."""
    flags = array.flags
    return array if flags.c_contiguous and flags.aligned and flags.writeable else np.array(array, order="C")


def lanes_solver(run):
    """``solve_many`` of the engine ``run`` (`engine_for`): the interpreted lanes, or their compiled copy."""
    return lanes.solve_many if run is engine else run.solve_many


def _run_chunks(run, table, states, classical, tol, rows, index, workers, chunk, progress):
    """The lanes' ``solve_many`` on ``index`` (the good rows; None: every row) in pieces: serially below SERIAL_BELOW
    scenes or with one thread (``workers`` as `simulate_many`'s), else over a pool of threads.  With every row, a
    piece is a slice: views of the inputs, its rows written in place (no copies)."""
    solve_many = lanes_solver(run)

    def piece(part):
        if isinstance(part, slice):
            solve_many(table[part], states[part], classical[part], tol, rows[part])
            return part.stop - part.start
        out = np.empty((len(part), engine.N_OUT))
        solve_many(table[part], states[part], classical[part], tol, out)
        rows[part] = out
        return len(part)

    total = len(rows) if index is None else len(index)
    threads = threads_for(total, workers, interpreted=run is engine)
    serial = threads == 1
    if serial and index is None and total <= chunk:  # the common small batch: one call on the whole arrays
        solve_many(table, states, classical, tol, rows)
        if progress:
            progress(total, total)
        return
    # Four pieces a thread balance the scenes' costs; below four blocks of lanes a piece, one piece a thread (a
    # piece ends when its slowest scene does, its other lanes idle: small pieces waste them).
    few = total < 4 * threads * 4 * lanes.LANES
    size = chunk if serial else min(chunk, -(-total // (threads if few else 4 * threads)))
    if index is None:
        parts = [slice(start, min(start + size, total)) for start in range(0, total, size)]
    else:
        parts = [index[start : start + size] for start in range(0, total, size)]
    done = 0
    if serial:
        for part in parts:
            done += piece(part)
            if progress:
                progress(done, total)
        return
    # The first piece runs here while a pool thread wakes for the next (waking one costs ~50 µs here).
    futures = [_pool(threads).submit(piece, part) for part in parts[1:]]
    try:
        done += piece(parts[0])
        if progress:
            progress(done, total)
        for future in as_completed(futures):
            done += future.result()
            if progress:
                progress(done, total)
    finally:
        for future in futures:  # Ctrl-C or an error: drop the pieces not started
            future.cancel()


def simulate_many(
    params, states, model="appell", tol: float = validation.DEFAULT_TOL, workers: int | None = None,
    chunk: int = CHUNK, progress=None, skip_bad: bool = False, jit=None,
) -> BatchResult:
    """Every scene of ``states`` (array (n, 7): ξ, η, ξ', η', p, q, r; one
    state of 7 numbers is a batch of one).

    ``params``: one `Params` (or dict) for every scene, or one per scene;
    ``model``: "appell", "classical", or one per scene.  ``tol``: the rest
    point's relative error asked of the numerical slide (measured: `appell
    bench`).  ``workers``: threads (default every core); ``progress(done,
    total)`` after each chunk of ``chunk`` scenes; ``jit=False`` runs the
    interpreted engine (one core, milliseconds a scene).

    Bad rows (non-finite, or a motion too large or a speed too small for float64; a bad entry in a list of
    params or models) raise
    `BadScenesError` listing every one; with ``skip_bad`` they are left out
    (``ok`` False, NaN, their reason in ``errors``) and the others computed.
    A scene whose result comes out non-finite is a `ComputationError` naming
    it (with ``skip_bad``: refused like a bad row).
    """
    tol = validation.tolerance(tol)
    if not isinstance(skip_bad, (bool, np.bool_)):  # "no" would be true
        raise SceneError("skip_bad", f"must be True or False, got {validation.describe(skip_bad)}")
    chunk = validation.workers(chunk, "chunk")
    states = _engine_array(state_array(states))
    n = len(states)
    refused = []  # per-scene entries that are no Params or model: refused like a bad state (an audit: they raised)
    table = params_table(params, n, refused)
    classical = classical_flags(model, n, refused)
    run = engine_for(jit)
    errors = bad_rows(table, states, run)
    if refused:  # a scene's first reason, its params or model before its state
        first = dict(reversed(refused))
        errors = sorted({**dict(errors), **first}.items())
    if errors and not skip_bad:
        raise BadScenesError(errors)
    if workers is not None:
        validation.workers(workers)
    if progress is not None and not callable(progress):  # found only after the first chunk, its work lost
        raise SceneError("progress", f"must be a function progress(done, total) or None, got {validation.describe(progress)}")
    good = np.empty(n, dtype=bool)
    good.fill(True)  # np.ones, at a third of its cost
    if errors:  # some rows refused: the others gathered, solved, scattered back; a refused row stays NaN
        good[[i for i, _ in errors]] = False
        rows = np.full((n, engine.N_OUT), np.nan)
        _run_chunks(run, table, states, classical, tol, rows, np.flatnonzero(good), workers, chunk, progress)
    else:  # every row solved in place: np.empty as the pieces' own buffers were (the engine fills a row whole)
        rows = np.empty((n, engine.N_OUT))
        _run_chunks(run, table, states, classical, tol, rows, None, workers, chunk, progress)
    result = BatchResult(rows, good, dict(errors), tol)
    status = rows[:, engine.OUT_STATUS]
    if np.count_nonzero(status):  # OK is 0: every row OK, the common case, costs this one pass
        trouble = status != engine.OK
        if errors:
            trouble &= good  # a refused row's NaN status is no trouble of its own
        for i in np.flatnonzero(trouble):
            found = problem(rows[i])
            if not skip_bad:
                raise (validation.WorkLimitError if rows[i, engine.OUT_STATUS] == engine.WORK_LIMIT else ComputationError)(
                    f"scene [{i}].{found}")
            result.errors[int(i)] = ComputationError(found)
            result.ok[i] = False
    if np.count_nonzero(rows[:, engine.OUT_ERROR] > validation.TOL_WARNING * tol):  # (NaN, a refused row: False)
        _warn_beyond(result, tol)
    return result  # errors: exactly the rows refused (their fields NaN, model -1)


def _warn_beyond(result: BatchResult, tol: float) -> None:
    """One `validation.ToleranceWarning` for the scenes whose estimate says the tolerance may be missed."""
    beyond = np.flatnonzero(result.error > validation.TOL_WARNING * tol)
    worst = int(beyond[np.argmax(result.error[beyond])])
    listed = ", ".join(f"[{i}]" for i in beyond[:5]) + (", ..." if len(beyond) > 5 else "")
    message = validation.beyond_tolerance(float(result.error[worst]), tol)
    warnings.warn(validation.ToleranceWarning(f"{len(beyond)} scene{'s' if len(beyond) > 1 else ''} ({listed}) above "
                                              f"{validation.TOL_WARNING:g}× the tolerance asked; the worst, scene "
                                              f"[{worst}]: {message}"), stacklevel=3)


def _count(column: np.ndarray) -> int:
    """The sum of a column of counts, a refused row's NaN left out: np.nansum's value (whole numbers, exact in any
    order) at a fifth of its cost when there is no NaN."""
    total = column.sum()
    return int(np.nansum(column) if math.isnan(total) else total)


def scene_states(scenes) -> tuple[list, np.ndarray, list]:
    """(params, states array, models) of a list of `Scene`s, one of each per scene."""
    if not isinstance(scenes, (list, tuple)):  # a generator would be spent by the first pass
        raise SceneError("scenes", f"must be a list of Scenes, got {validation.describe(scenes)}")
    if len(scenes) == 0:
        raise SceneError("scenes", "no scenes")
    bad = next((i for i, s in enumerate(scenes) if not isinstance(s, Scene)), None)
    if bad is not None:
        raise SceneError(f"scenes [{bad}]", f"must be a Scene (from a dict: parse), got {validation.describe(scenes[bad])}")
    return [s.params for s in scenes], np.array([s.state.row() for s in scenes], dtype=float), [s.model for s in scenes]


def motion(result: BatchResult, scenes, i: int, tol: float | None = None, jit=None):
    """The `Motion` of scene ``i`` of a batch (its states at any time computed on demand): ``scenes`` the `Scene`s
    (or dicts) whose rows the batch was given (`scene_states`), ``tol`` and ``jit`` as the batch was given them
    (``tol``: the batch's own, kept in ``result.tol``, unless given).  The scene is solved again with its steps
    kept (the same engine: the same bits as its row) and refused when that is not its row: a Motion of another
    scene or tolerance would read the steps of one motion for the times of another."""
    if tol is None and result.tol is None:
        raise SceneError("tol", "must be the tolerance the batch was computed with (this result does not keep it)")
    tol = validation.tolerance(result.tol if tol is None else tol)
    if isinstance(i, bool) or not isinstance(i, (int, np.integer)) or not 0 <= i < len(result.rows):
        raise SceneError("i", f"must be the index of a row of the batch (0 to {len(result.rows) - 1}), got "
                              f"{validation.describe(i)}")
    if not hasattr(scenes, "__len__") or len(scenes) != len(result.rows):
        raise SceneError("scenes", f"must be the {len(result.rows)} scenes the batch was given, got "
                                   f"{len(scenes) if hasattr(scenes, '__len__') else validation.describe(scenes)}")
    if not result.ok[i]:
        raise SceneError(f"scene [{i}]", f"was refused by the batch ({result.errors.get(int(i))}): it has no motion")
    if not isinstance(scenes[i], (Scene, dict)):  # e.g. the batch's states array: a row has no params or model
        raise SceneError(f"scenes [{i}]", "must be a Scene or a dict as in a scene file (the scenes whose rows the "
                                          f"batch was given: `scene_states`), got {validation.describe(scenes[i])}")
    scene = parse(scenes[i])
    out, dense = _solve(scene, tol, engine_for(jit), dense=True)
    same = [j for j in range(engine.N_OUT) if j != engine.OUT_DENSE]  # the row kept no steps
    if not np.array_equal(out[same], result.rows[i, same], equal_nan=True):
        raise SceneError(f"scene [{i}]", "is not the scene, or tol not the tolerance, this row of the batch was computed with")
    return Motion(scene, tol, out, dense, jit)
