"""The lanes (`numerics.lanes`): many slides side by side take exactly the steps each takes alone."""

import platform

import numba
import numpy as np
import pytest

from numerics import bench, bench_set, classical_vs_appell, compiled, dop853_steps, engine, lane_rows, lanes

NO_DENSE = np.empty((0, engine.DENSE_WIDTH))


def _batch(n, seed=0):
    """n shots of the bench's timing set, each with its own parameters (f, δ, ε, R drawn around a pool ball)."""
    states = bench.timing_states(n)
    rng = np.random.default_rng(seed)
    params = np.tile(np.array(classical_vs_appell.POOL.values()), (n, 1))
    params[:, 0] *= rng.uniform(0.5, 1.5, n)  # f
    params[:, 3] *= rng.uniform(0.2, 2.0, n)  # δ, below fR still
    params[:, 4] *= rng.uniform(0.0, 2.0, n)  # ε
    classical = rng.random(n) < 0.1
    return np.ascontiguousarray(params), states, classical


def _one_by_one(run, params, states, classical, tol):
    out = np.empty((len(states), engine.N_OUT))
    for i in range(len(states)):
        run.solve(params[i], states[i], classical[i], tol, out[i], NO_DENSE)
    return out


@pytest.mark.parametrize("tol", [1e-6, 1e-9, 1e-12])
def test_lanes_take_the_steps_of_the_single_scene_loop(tol):
    n = 3 * lanes.LANES + 5  # lanes refill, and the last block is partly idle
    params, states, classical = _batch(n, seed=int(-np.log10(tol)))
    alone = _one_by_one(compiled, params, states, classical, tol)
    together = np.empty_like(alone)
    compiled.solve_many(params, states, classical, tol, together)
    numerical = alone[:, engine.OUT_MODEL] == engine.NUMERICAL
    assert 2 * lanes.LANES < numerical.sum() < n  # closed forms among them
    # IEEE arithmetic in both (`numerics.compiled`): the same steps, the same bits.
    assert np.array_equal(alone, together, equal_nan=True)


@pytest.mark.parametrize("n", [2, 3, lanes.VECTOR + 1, 2 * lanes.VECTOR + 1, lanes.LANES // 2, lanes.LANES + 1])
def test_small_batches_take_the_steps_of_the_single_scene_loop(n):
    """Any number of curved slides: part of a block busy, lanes closing up as slides end (a lane's every row
    moved), the last slide handed to the single-scene loop mid-slide: every row the bits of its scene alone."""
    params, states, classical = _batch(n, seed=n)
    alone = _one_by_one(compiled, params, states, classical, 1e-9)
    together = np.empty_like(alone)
    compiled.solve_many(params, states, classical, 1e-9, together)
    assert np.array_equal(alone, together, equal_nan=True)


@pytest.mark.parametrize("handoff", [0, 4])
def test_a_lane_that_runs_out_of_steps_leaves_the_others_alone(monkeypatch, handoff):
    """With a work limit between the scenes' step counts, each scene ends as it does alone (interpreted engine,
    whose limit can be lowered): the ones within it finish, the others are WORK_LIMIT, none is disturbed —
    in the lanes, or handed to the single-scene loop mid-slide with the steps they have taken (``handoff``)."""
    scenes = bench_set.scenes()
    chosen = [s for s in scenes.values() if s.model == "appell"]
    params = np.array([s.params.values() for s in chosen])
    states = np.array([s.state.row() for s in chosen])
    classical = np.zeros(len(chosen), bool)
    full = _one_by_one(compiled, params, states, classical, 1e-8)
    curved = np.flatnonzero(full[:, engine.OUT_MODEL] == engine.NUMERICAL)[:12]
    steps = full[curved, engine.OUT_STEPS] + full[curved, engine.OUT_REJECTED]
    curved = curved[np.argsort(steps, kind="stable")]  # the longest last: handed on mid-slide, they run out there
    params, states, classical, full = params[curved], states[curved], classical[curved], full[curved]
    counted = np.sort(steps)
    limit = int(counted[len(counted) // 2])
    assert counted[0] <= limit < counted[-1]
    monkeypatch.setattr(engine, "MAX_STEPS", limit)
    monkeypatch.setattr(lanes, "MAX_STEPS", limit)
    for module in (lane_rows, lanes, dop853_steps):  # a block of 4 lanes: the 12 scenes in lanes, which refill
        monkeypatch.setattr(module, "LANES", 4)
        if hasattr(module, "STAGE"):
            monkeypatch.setattr(module, "STAGE", lane_rows.N_Y * 4)
    monkeypatch.setattr(lanes, "HANDOFF", handoff)  # 4: the last four scenes go on alone, from where they are
    handed = []
    monkeypatch.setattr(lanes, "slide_on", lambda *a: handed.append(a[11]) or engine.slide_on(*a))
    alone = _one_by_one(engine, params, states, classical, 1e-8)
    together = np.empty_like(alone)
    lanes.solve_many(params, states, classical, 1e-8, together)
    status = together[:, engine.OUT_STATUS]
    assert np.array_equal(status, alone[:, engine.OUT_STATUS])
    assert (status == engine.WORK_LIMIT).any() and (status == engine.OK).any()
    assert np.array_equal(together, alone, equal_nan=True)  # step counts too: a handed scene keeps its count
    assert len(handed) == handoff and (handoff == 0 or 0 < max(handed) < limit)
    assert handoff == 0 or status[-1] == engine.WORK_LIMIT  # a handed scene that ran out of steps
    ok = status == engine.OK
    assert np.array_equal(together[ok, engine.OUT_REST_XI], full[ok, engine.OUT_REST_XI])


@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="reads x86 assembly")
def test_the_lanes_rates_loop_compiles_to_vector_instructions(monkeypatch):
    """The point of the lanes: their rate loop (`lanes._rates_from`, inlined) computes several lanes an instruction.
    Its one square root (Ω's norm, `engine.unit_rotation`) must come out packed (sqrtpd: SSE2, AVX2, AVX-512
    alike); a loop that stays scalar has only sqrtsd (AMD EPYC, AVX2, with `vector_exp.exp`'s k an integer).
    Compiled afresh here: numba shows no assembly for code it loaded from its cache."""
    monkeypatch.setattr(compiled, "CACHE", "not cached: this test reads the assembly")
    rates = compiled._compile(compiled.MODULES)["_lane_rates"]
    rates.compile((numba.float64[::1], numba.float64, numba.int64))
    assembly = rates.inspect_asm(rates.signatures[0])
    assert "sqrtpd" in assembly, "the lanes' rate loop is scalar on this machine"
