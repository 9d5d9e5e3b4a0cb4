"""The batch path against the 40-digit mpmath reference of the benchmark scenes (cached in paper/data)."""

import math

import numpy as np
import pytest

from numerics import batch, bench, bench_set, classical_vs_appell, kernels, validation
from numerics.scene import Params, Scene, State
from numerics.simulate import simulate
from numerics.validation import SceneError


@pytest.fixture(scope="module")
def references():
    return bench_set.scenes(), bench_set.references()


@pytest.mark.parametrize("tol", [1e-6, 1e-9, 1e-10, 1e-12])
def test_the_rest_point_is_within_the_tolerance_asked_on_every_bench_scene(references, tol):
    """The tolerance means what it says, the fast high-spin shots on random cloths included."""
    scenes, refs = references
    errs = bench.batch_errors(scenes, refs, tol)
    assert len(errs) == len(scenes) >= 40
    assert max(e[0] for e in errs) <= tol  # rest point
    assert max(e[1] for e in errs) <= tol  # end of sliding


@pytest.mark.parametrize("tol", [1e-6, 1e-8, 1e-10, 1e-12])
def test_tolerance_and_estimate_hold_on_120_more_fast_shots(tol):
    """The shots TOL_SAFETY and ESTIMATE_MARGIN were measured on (20-digit references, cached in paper/data):
    every rest point within tol, every estimate well above the actual error.  The estimate's margin is pinned
    (at least 12.5× the error measured, `appell bench --saved`): `least >= 1` alone let ESTIMATE_MARGIN 2 -> 1
    pass (8.96×), and a calibration that compared no estimate at all (least = ∞), a mutation audit found."""
    ((_, worst, least, n),) = bench.calibration([tol])
    assert n == 43 + 120
    assert worst <= 1.0
    assert 10.0 <= least < math.inf


# Shots near δ = fR that missed a coarser tolerance than TOL_RANGE allows (an adversarial audit: 80,000 random shots
# at 1e-4 to 1e-3), each with the tol it missed and by how much against its 20-digit reference: the coarsest
# tolerance accepted must hold on them, so TOL_RANGE cannot be widened to any of those tols unnoticed.
MISSED_COARSER = [
    (Params(f=0.08852773435596215, delta=0.0025271503292123966, epsilon=3e-4, R=0.028575),  # 0.999 fR: 2.8× at 3e-4
     State(0.0, 0.0, -0.5850060926823343, -2.6698825487001008, 215.14820783732262, 377.8515417358285, -23.4011076938079)),
    (Params(f=0.07858887598540286, delta=0.002223220359970058, epsilon=0.0, R=0.028575),  # 0.99 fR: 1.016× at 1e-3
     State(0.0, 0.0, 1.593930390692397, 1.5648654392465335, -391.5103912670028, -191.5946822344673, 25.89691588896021)),
    (Params(f=0.11186680484766473, delta=0.99 * 0.11186680484766473 * 0.028575, epsilon=3e-4, R=0.028575),  # 1.47× at 1e-4
     State(0.0, 0.0, 0.9347012543881614, 0.986362424894361, -357.18662911569777, -117.68193057476788, -94.44436324487569)),
]


@pytest.mark.parametrize("index", range(len(MISSED_COARSER)))
def test_the_coarsest_tolerance_accepted_holds_where_coarser_ones_missed(index):
    scene = Scene(*MISSED_COARSER[index], ())
    ref = bench_set.compute(scene, 20)
    tol = validation.TOL_RANGE[1]
    params, states, models = batch.scene_states([scene])
    r = batch.simulate_many(params, states, models, tol)
    e_rest, e_t, _ = bench.errors(scene, ref, r.t_slide_end[0], r.slide_end[0, 2:], r.t_roll_end[0], r.rest[0])
    assert e_rest <= tol and e_t <= tol
    assert r.error[0] >= e_rest


def test_the_coarsest_tolerance_accepted_holds_on_random_shots_near_fR():
    """Seeded random shots from 0.99 to 0.9999 fR (stiff: DOP853 takes few long steps at a coarse tolerance) at
    the coarsest tol accepted, against the same shots at tol 1e-13 (whose error is 1e-8 of this one's)."""
    rng = np.random.default_rng(2026)
    R, n, tol = 0.028575, 500, validation.TOL_RANGE[1]
    for f in (0.08, 0.2, 0.45):
        for fraction in (0.99, 0.999, 0.9999):
            P = Params(f=f, delta=fraction * f * R, epsilon=3e-4, R=R)
            speed, angle = rng.uniform(0.1, 10, n), rng.uniform(0, 2 * np.pi, n)
            states = np.column_stack([np.zeros(n), np.zeros(n), speed * np.cos(angle), speed * np.sin(angle),
                                      rng.uniform(-400, 400, (n, 2)), rng.uniform(-100, 100, n)])
            # skip_bad: at 1e-13 a slide at 0.9999 fR may need more than MAX_STEPS (WorkLimitError, documented).
            fine = batch.simulate_many(P, states, tol=1e-13, skip_bad=True)
            coarse = batch.simulate_many(P, states, tol=tol)
            assert np.count_nonzero(fine.ok) >= 0.9 * n
            travel = np.hypot(*(fine.rest - states[:, :2]).T) + R
            error = (np.hypot(*(coarse.rest - fine.rest).T) / travel)[fine.ok]
            assert np.all(error <= tol), (f, fraction, error.max() / tol)


def test_the_error_estimate_is_above_the_actual_error(references):
    scenes, refs = references
    names = list(scenes)
    params, states, models = batch.scene_states([scenes[n] for n in names])
    for tol in (1e-6, 1e-9):
        r = batch.simulate_many(params, states, models, tol)
        checked = 0
        for i, n in enumerate(names):
            if np.isfinite(r.rest[i, 0]) and r.model[i] == batch.NUMERICAL:
                rest, t_roll = r.rest[i], r.t_roll_end[i]
                actual = bench.errors(scenes[n], refs[n], r.t_slide_end[i], r.slide_end[i, 2:], t_roll, rest)[0]
                assert actual <= r.error[i], n
                checked += 1
        assert checked >= 30  # the curved slides of the bench set (33): a filter that dropped them would pass (an audit)


def test_same_models_and_answers_as_simulate():
    scenes = bench_set.scenes()
    names = ["hard: centre hit", "hard: straight draw", "hard: rolls for ever (delta = 0)", "shot: massé (0.5 m/s, spin 130 rad/s across)", "fast 03"]
    params, states, models = batch.scene_states([scenes[n] for n in names])
    r = batch.simulate_many(params, states, models, 1e-10)
    for i, name in enumerate(names):
        m = simulate(scenes[name], 1e-10)
        assert r.t_slide_end[i] == m.t_slide_end and batch.MODEL_NAMES[r.model[i]] == m.model
        if m.rest is None:
            assert np.isnan(r.rest[i]).all() and np.isinf(r.t_roll_end[i])
        else:
            assert tuple(r.rest[i]) == m.rest  # one engine: the same numbers


def test_a_slide_run_again_in_a_batch_is_the_one_simulate_runs():
    """A ball that comes back near its start slides again at a tighter tolerance (`engine.finish`); in a batch, after
    the lanes, alone: the same bits as `simulate`, among scenes that run once (lanes and the single-scene loop)."""
    from numerics import engine

    P = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575)
    back = [0.0, 0.0, 1.5, 0.0, 0.5, -3.476818473218177 * 1.5 / P.R, 0.0]  # tests/numerics/test_engine.py's
    on = [0.0, 0.0, 2.0, 0.3, 10.0, -40.0, 5.0]
    states = [on, back, on, back, on]
    r = batch.simulate_many(P, states, tol=1e-9)
    assert r.rows[:, engine.OUT_RUNS].tolist() == [1, 2, 1, 2, 1]
    for i, state in enumerate(states):
        m = simulate(Scene(P, State(*state), ()), 1e-9)
        same = [j for j in range(engine.N_OUT) if j != engine.OUT_DENSE]
        assert np.array_equal(r.rows[i, same], m._out[same]), i


def test_each_scene_its_own_params_and_model():
    pool, heavy = classical_vs_appell.POOL, Params(f=0.15, delta=0.001, epsilon=0.0, R=0.028575)
    state = [0, 0, 2.0, 0.3, 10.0, -40.0, 5.0]
    r = batch.simulate_many([pool, heavy, pool], [state] * 3, ["appell", "appell", "classical"], 1e-10)
    for i, (params, model) in enumerate([(pool, "appell"), (heavy, "appell"), (pool, "classical")]):
        assert r.rest[i, 0] == simulate(Scene(params, State(*state), (), model), 1e-10).rest[0]
    assert r.model.tolist() == [batch.NUMERICAL, batch.NUMERICAL, batch.CLASSICAL]
    assert np.isinf(r.t_pivot_end[1])  # ε = 0: pivots for ever


def test_classical_model_is_n3_then_n7():
    states = bench.timing_states(50)
    P = classical_vs_appell.POOL
    r = batch.simulate_many(P, states, "classical")
    assert (r.model == batch.CLASSICAL).all() and ((0 < r.error) & (r.error < 1e-13)).all()  # their rounding
    for i in (0, 7, 33):
        m = simulate(Scene(P, State(*states[i]), (), "classical"))
        assert tuple(r.rest[i]) == m.rest


def test_chunks_and_threads_change_nothing():
    states = bench.timing_states(300)
    P = classical_vs_appell.POOL
    one = batch.simulate_many(P, states, tol=1e-9, workers=1)
    many = batch.simulate_many(P, states, tol=1e-9, workers=2, chunk=64)
    assert np.array_equal(one.model, many.model) and np.array_equal(one.rest, many.rest)  # each scene on its own


def test_the_interpreted_engine_gives_the_same_numbers():
    states = bench.timing_states(6)
    P = classical_vs_appell.POOL
    compiled, interpreted = batch.simulate_many(P, states, tol=1e-9), batch.simulate_many(P, states, tol=1e-9, jit=False)
    assert np.allclose(compiled.rest, interpreted.rest, rtol=1e-13, atol=0)


def test_mirror_symmetry_in_batch():
    states = bench.timing_states(40)
    mirrored = states * np.array([1, -1, 1, -1, -1, 1, -1])
    P = classical_vs_appell.POOL
    a, b = batch.simulate_many(P, states, tol=1e-11), batch.simulate_many(P, mirrored, tol=1e-11)
    assert b.rest[:, 0] == pytest.approx(a.rest[:, 0], rel=1e-9, abs=0)
    assert b.rest[:, 1] == pytest.approx(-a.rest[:, 1], rel=1e-9, abs=1e-12)


def test_slide_ends_before_the_bound_of_n8():
    states = bench.timing_states(200)
    P = classical_vs_appell.POOL
    r = batch.simulate_many(P, states, tol=1e-9)
    V0 = np.array([math.hypot(*kernels.slip_velocity(*s[2:6], P.R)) for s in states])
    assert np.all(r.t_slide_end < V0 / (P.f * P.g))


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"states": np.zeros((3, 6))}, "shape"),
        ({"states": np.full((2, 7), np.nan)}, "finite"),
        ({"model": "magic"}, "model"),
        ({"model": ["appell"]}, "one for every scene"),
        ({"params": [classical_vs_appell.POOL]}, "one for every scene"),
        ({"tol": 1.0}, "tol"),
        # From an audit: booleans in a list were read as 1 (ξ = 1 m), and flags took any non-empty string as true.
        ({"states": [[True, 0.5, 2, 0, 10, -40, 5]]}, r"states: must be numbers, got True"),
        ({"states": [(0.0, 0.5, 2, 0, 10, -40, np.True_)]}, r"states: must be numbers, got"),
        ({"jit": "no"}, r"jit: must be True, False or None, got 'no'"),
        ({"skip_bad": "no"}, r"skip_bad: must be True or False, got 'no'"),
    ],
)
def test_bad_input(kwargs, message):
    args = {"params": classical_vs_appell.POOL, "states": np.zeros((2, 7)), **kwargs}
    with pytest.raises(ValueError, match=message):
        batch.simulate_many(**args)


def _same_results(a, b):
    """Two BatchResults alike bit for bit (NaN where NaN), the engine's rows included."""
    for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "model", "error", "ok", "rows"):
        x, y = getattr(a, name), getattr(b, name)
        assert x.dtype == y.dtype and x.shape == y.shape and np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), name
    assert a.stats == b.stats


@pytest.mark.parametrize("workers, chunk", [(1, batch.CHUNK), (1, 64), (2, 64)])
def test_good_rows_solved_in_place_as_when_gathered_around_a_refused_one(workers, chunk):
    """Every row good: the batch runs on slices of its inputs, writing its rows in place; a refused row makes it
    gather the others, solve them and scatter them back.  The same numbers either way, serial or in threads."""
    states = bench.timing_states(300)
    P = classical_vs_appell.POOL
    calls = []
    in_place = batch.simulate_many(P, states, workers=workers, chunk=chunk, progress=lambda *a: calls.append(a))
    assert calls[-1] == (300, 300) and all(done <= 300 for done, _ in calls)
    with_bad = np.insert(states, 137, [0, 0, np.nan, 0, 0, 0, 0], axis=0)
    calls = []
    gathered = batch.simulate_many(P, with_bad, workers=workers, chunk=chunk, skip_bad=True, progress=lambda *a: calls.append(a))
    assert calls[-1] == (300, 300) and all(done <= 300 for done, _ in calls)  # the good rows' count: a bar that ends
    assert gathered.ok.tolist() == [i != 137 for i in range(301)] and np.isnan(gathered.rows[137]).all()
    keep = np.arange(301) != 137
    for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "model", "error", "rows"):
        assert np.array_equal(getattr(in_place, name), getattr(gathered, name)[keep], equal_nan=True), name
    assert in_place.stats == gathered.stats and not in_place.errors


def test_one_state_of_seven_numbers_is_a_batch_of_one():
    """The README and the docstring say so: a state of 7 numbers, as an array or a list, gives the numbers of the
    (1, 7) batch; 8 numbers are refused, named by the shape they have."""
    P = classical_vs_appell.POOL
    state = bench.timing_states(3)[2]
    one = batch.simulate_many(P, state[np.newaxis])
    _same_results(batch.simulate_many(P, state), one)
    _same_results(batch.simulate_many(P, state.tolist()), one)
    assert len(one.rest) == 1
    with pytest.raises(SceneError, match=r"states: must have shape \(n, 7\).*got \(8,\)"):
        batch.simulate_many(P, np.append(state, 0.0))


def test_any_layout_of_the_states_gives_the_same_numbers_and_no_new_compile():
    """States strided, Fortran-ordered, read-only or of another dtype: the numbers of a plain array, and the
    compiled code called with the one type it was built for (numba would compile another copy for another)."""
    compiled = pytest.importorskip("numerics.compiled")
    P = classical_vs_appell.POOL
    states = bench.timing_states(20)
    plain = batch.simulate_many(P, states)
    known = (len(compiled.solve_many.signatures), len(compiled.motion_scales.signatures))
    wide = np.zeros((40, 9))
    wide[::2, 1:8] = states
    frozen = states.copy()
    frozen.flags.writeable = False
    for odd in (np.asfortranarray(states), wide[::2, 1:8], frozen, states.astype(">f8"), states.tolist()):
        _same_results(batch.simulate_many(P, odd), plain)
    assert (len(compiled.solve_many.signatures), len(compiled.motion_scales.signatures)) == known
    assert not frozen.flags.writeable and np.array_equal(frozen, states)  # the caller's array untouched


def test_the_result_arrays_and_stats_are_those_of_nansum_and_gathers():
    """`BatchResult` reads adjacent columns by slices and sums the counts without np.nansum when no row is NaN:
    the arrays and totals of the plain gathers and np.nansum, with refused (NaN) rows and without."""
    from numerics import engine

    rows = batch.simulate_many(classical_vs_appell.POOL, bench.timing_states(30), tol=1e-8).rows.copy()
    assert rows[:, engine.OUT_STEPS].sum() > 0
    for refused in ([], [0, 7, 29]):
        rows[refused] = np.nan
        ok = ~np.isnan(rows[:, 0])
        r = batch.BatchResult(rows, ok, {})
        assert np.array_equal(r.rest, rows[:, [engine.OUT_REST_XI, engine.OUT_REST_ETA]], equal_nan=True)
        assert r.rest.flags.c_contiguous and r.slide_end.flags.c_contiguous
        end = rows[:, [engine.OUT_END_XI, engine.OUT_END_ETA, engine.OUT_END_P, engine.OUT_END_Q]]
        assert np.array_equal(r.slide_end, end, equal_nan=True)
        assert r.stats == {
            "steps": int(np.nansum(rows[:, engine.OUT_STEPS])), "rejected": int(np.nansum(rows[:, engine.OUT_REJECTED])),
            "numerical": int(np.sum(r.model == batch.NUMERICAL)),
        }
        model = rows[:, engine.OUT_MODEL]
        assert r.model.dtype == int and np.array_equal(r.model, np.where(np.isnan(model), -1, model).astype(int))
        assert r.model[refused].tolist() == [-1] * len(refused) and (r.model[ok] >= 0).all()
    assert batch._columns(3, 4) == slice(3, 5) and batch._columns(3, 5) == [3, 5]  # a gather when not adjacent


def test_a_list_of_params_gives_the_table_of_the_general_path():
    """A list (or tuple) of Params is read without Python per scene; one Params filled in without np.tile.  The
    same table as each scene's `values()` (which dicts, subclasses and other sequences still go through), the
    same batch, and a wrong kind among them still named."""
    from numerics.scene import Coefficients

    class Mine(Params):
        pass

    pool, heavy = classical_vs_appell.POOL, Params(f=0.15, delta=0.001, epsilon=0.0, R=0.028575, k=0.0181, g=9.8)
    params = [pool, heavy, heavy, pool, heavy]
    general = np.array([p.values() for p in params])
    for fast in (params, tuple(params)):
        table = batch.params_table(fast, 5)
        assert table.dtype == float and table.flags.c_contiguous and table.flags.writeable
        assert np.array_equal(table, general)
    as_dicts = [pool, {"f": 0.15, "delta": 0.001, "epsilon": 0.0, "R": 0.028575, "k": 0.0181, "g": 9.8}, heavy, pool,
                Mine(**vars(heavy))]
    assert np.array_equal(batch.params_table(as_dicts, 5), general)
    assert np.array_equal(batch.params_table(np.array(params, dtype=object), 5), general)
    one = batch.params_table(heavy, 5)
    assert one.flags.c_contiguous and np.array_equal(one, np.tile(np.array(heavy.values()), (5, 1)))
    states = bench.timing_states(5)
    _same_results(batch.simulate_many(params, states), batch.simulate_many(as_dicts, states))
    with pytest.raises(SceneError, match=r"^scene \[1\].params: must be a Params or a dict"):
        batch.params_table([pool, Coefficients(**vars(heavy)), pool], 3)


def test_a_list_of_model_names_gives_the_flags_of_the_general_path():
    """A list of model names is compared in C; anything else goes scene by scene, the first bad one named."""

    class Name(str):
        pass

    models = ["appell", "classical", "classical", "appell"]
    general = np.array([m == "classical" for m in models])
    for fast in (models, tuple(models), [Name(m) for m in models], np.array(models)):
        flags = batch.classical_flags(fast, 4)
        assert flags.dtype == bool and flags.flags.c_contiguous and np.array_equal(flags, general)
    assert batch.classical_flags(["classical"], 1).tolist() == [True]
    for bad, index in ((["appell", "classical", "Appell", "appell"], 2), (["appell", 3, "x", "classical"], 1),
                       (["appell", "appell", ["classical"], "x"], 2)):
        with pytest.raises(SceneError, match=rf"^scene \[{index}\].model: must be one of appell, classical"):
            batch.classical_flags(bad, 4)


@pytest.mark.parametrize("n", [1, batch.SERIAL_BELOW])
@pytest.mark.parametrize("field, bad", [("workers", 0), ("workers", -1), ("workers", 1.5), ("workers", True), ("chunk", 0)])
def test_workers_and_chunk_are_checked_at_every_size(n, field, bad):
    """A bad thread count or chunk size is refused by name whether or not the batch is large enough for threads
    (a small batch never counts its threads)."""
    states = bench.timing_states(n)
    with pytest.raises(SceneError, match=rf"^{field}: must be an integer >= 1"):
        batch.simulate_many(classical_vs_appell.POOL, states, **{field: bad})


@pytest.mark.parametrize("bad", [5, "bar", [print]])
def test_a_progress_that_cannot_be_called_is_refused_before_any_work(bad, monkeypatch):
    """It was called only after the first chunk: a TypeError that threw the chunk's work away."""
    monkeypatch.setattr(batch, "_run_chunks", lambda *args: pytest.fail("solved before progress was checked"))
    with pytest.raises(SceneError, match=r"^progress: must be a function progress\(done, total\) or None, got "):
        batch.simulate_many(classical_vs_appell.POOL, bench.timing_states(3), progress=bad)


def test_motion_of_a_row_is_its_scene_and_refuses_another():
    """`batch.motion`: a row's Motion, its states those `simulate` gives; another scene, another tolerance, an
    index out of range or a refused row is a SceneError (it once returned states read from the wrong steps)."""
    from numerics import hard_cases
    from numerics.simulate import simulate

    cases = hard_cases.hard_cases()
    scenes = [cases["sample"], cases["draw, little side spin"], cases["centre hit"]]
    params, states, models = batch.scene_states(scenes)
    result = batch.simulate_many(params, states, models, 1e-9)
    for i, scene in enumerate(scenes):
        alone = simulate(scene, 1e-9).states([0.01, 0.1, 2.0])
        rows = batch.motion(result, scenes, i, 1e-9).states([0.01, 0.1, 2.0])
        assert all(np.array_equal(getattr(rows, f), getattr(alone, f)) for f in ("t", "phase", "xi", "eta", "p", "q", "r"))
    with pytest.raises(ValueError, match=r"^scene \[0\]: is not the scene, or tol not the tolerance"):
        batch.motion(result, scenes, 0, 1e-6)
    with pytest.raises(ValueError, match=r"^scene \[0\]: is not the scene"):
        batch.motion(result, scenes[::-1], 0, 1e-9)
    states[2, 0] = np.nan
    refused = batch.simulate_many(params, states, models, 1e-9, skip_bad=True)
    with pytest.raises(ValueError, match=r"^scene \[2\]: was refused by the batch"):
        batch.motion(refused, scenes, 2, 1e-9)
    for i in (3, -1, True, 1.0):
        with pytest.raises(ValueError, match=r"^i: must be the index of a row"):
            batch.motion(result, scenes, i, 1e-9)
    with pytest.raises(ValueError, match="tol"):
        batch.motion(result, scenes, 0, float("nan"))
    with pytest.raises(ValueError, match=r"^scenes: must be the 3 scenes the batch was given, got 2"):
        batch.motion(result, scenes[:2], 2, 1e-9)  # an IndexError before (an adversarial audit)
    # The batch's own tolerance when none is given (a user's audit: the result did not keep it); the states array
    # the batch was given, in place of its scenes, named as such (it was "scene: must be a JSON object").
    own = batch.motion(result, scenes, 1)
    assert result.tol == own.tol == 1e-9 and own.t_slide_end == result.t_slide_end[1]
    with pytest.raises(SceneError, match=r"^scenes \[1\]: must be a Scene or a dict as in a scene file \(the scenes "):
        batch.motion(result, states, 1)
    with pytest.raises(SceneError, match=r"^tol: must be the tolerance the batch was computed with"):
        batch.motion(batch.BatchResult(result.rows, result.ok, {}), scenes, 1)


@pytest.mark.slow  # 100,000 draws, three times
def test_the_estimate_holds_on_near_straight_draws():
    """Seeded draws with pool parameters whose side spin is 10⁻⁹ to 10⁻¹ of the back spin: Ω passes close to zero,
    often closer than 10⁻³ of its scale.  Against the same draws at tol 1e-13, every error estimate at tol 1e-9 and
    1e-10 is above the error (with Ω's floor at 10⁻³ of its scale, 9 fell below it at 1e-9: `engine.SPIN_FLOOR`)."""
    rng = np.random.default_rng(5)
    n = 100_000
    states = np.zeros((n, 7))
    states[:, 2] = np.exp(rng.uniform(np.log(0.05), np.log(5), n))
    states[:, 5] = -np.exp(rng.uniform(np.log(1), np.log(300), n))
    states[:, 4] = states[:, 5] * np.exp(rng.uniform(np.log(1e-9), np.log(1e-1), n)) * rng.choice([-1, 1], n)
    states[:, 6] = rng.uniform(-50, 50, n)
    P = classical_vs_appell.POOL
    fine = batch.simulate_many(P, states, tol=1e-13)
    travel = np.hypot(fine.rest[:, 0], fine.rest[:, 1]) + P.R
    for tol in (1e-9, 1e-10):
        r = batch.simulate_many(P, states, tol=tol)
        error = np.hypot(*(r.rest - fine.rest).T) / travel
        assert np.count_nonzero(r.error < error) == 0, tol


def test_scene_states_names_what_is_not_a_scene():
    """`scene_states([None])` raised an AttributeError, a generator a TypeError (an audit)."""
    with pytest.raises(SceneError, match=r"scenes \[1\]: must be a Scene"):
        batch.scene_states([Scene(classical_vs_appell.POOL, State(0, 0, 1, 0, 0, 0, 0), ()), None])
    with pytest.raises(SceneError, match="scenes: must be a list of Scenes"):
        batch.scene_states(s for s in [])


def test_a_bad_per_scene_params_or_model_is_refused_like_a_bad_state():
    """A user audit: a bad entry in a list of params or models raised a plain SceneError naming only the first,
    with nothing computed, where the docstring and the CLI's --skip-bad list every bad scene and run the others."""
    pool = classical_vs_appell.POOL
    breaks_9 = {"f": 0.2, "delta": 0.01, "epsilon": 0.0, "R": 0.028575}  # δ ≥ fR
    states = bench.timing_states(3)
    with pytest.raises(batch.BadScenesError, match=r"^scene \[1\].params.delta: must be < f R.*\(and 1 more bad scenes\)") as caught:
        batch.simulate_many([pool, breaks_9, breaks_9], states)
    assert [i for i, _ in caught.value.errors] == [1, 2]
    result = batch.simulate_many([pool, breaks_9, breaks_9], states, skip_bad=True)
    assert result.ok.tolist() == [True, False, False] and sorted(result.errors) == [1, 2]
    assert np.isnan(result.rest[1:]).all()
    np.testing.assert_array_equal(result.rest[0], batch.simulate_many(pool, states[:1]).rest[0])
    result = batch.simulate_many(pool, states, model=["appell", "Classical", "classical"], skip_bad=True)
    assert result.ok.tolist() == [True, False, True] and result.errors[1].field == "model"
    np.testing.assert_array_equal(result.rest[2], batch.simulate_many(pool, states[2:], model="classical").rest[0])
    bad_state = states.copy()
    bad_state[1, 0] = np.nan  # scene 1 bad twice: its params named, once
    with pytest.raises(batch.BadScenesError) as caught:
        batch.simulate_many([pool, breaks_9, pool], bad_state)
    assert [(i, e.field) for i, e in caught.value.errors] == [(1, "params.delta")]
