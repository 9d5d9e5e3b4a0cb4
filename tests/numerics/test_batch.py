"""The batch path against the 40-digit mpmath reference of the benchmark scenes (cached in paper/data)."""

import dataclasses
import math

import numpy as np
import pytest

from numerics import batch, bench, bench_set, classical_vs_appell
from numerics.simulate import simulate


@pytest.fixture(scope="module")
def references():
    return bench_set.scenes(), bench_set.references()


@pytest.mark.parametrize("tol", [1e-10, 1e-12])
def test_every_bench_scene_to_1e9_on_the_rest_point(references, tol):
    scenes, refs = references
    errs = bench.batch_errors(scenes, refs, tol)
    assert len(errs) == len(scenes)
    assert max(e[0] for e in errs) <= 1e-9  # rest point
    assert max(e[1] for e in errs) <= 1e-9  # end of sliding
    assert max(e[2] for e in errs) <= 1e-9  # Ω at the end of sliding


def test_error_estimate_bounds_the_actual_error(references):
    scenes, refs = references
    for (params, model), names in bench._groups(scenes).items():
        _, states, _ = batch.scene_states([scenes[n] for n in names])
        r = batch.simulate_many(params, states, model, 1e-8)
        for i, n in enumerate(names):
            if np.isfinite(r.rest[i, 0]):
                actual = bench.errors(scenes[n], refs[n], r.t_slide_end[i], r.slide_end[i, 2:], r.t_roll_end[i], r.rest[i])[0]
                assert actual <= r.error[i] + 1e-13, n


def test_same_models_and_answers_as_simulate():
    scenes = bench_set.scenes()
    for name in ("hard: centre hit", "hard: straight draw", "hard: rolls for ever (delta = 0)", "shot: massé (0.5 m/s, spin 130 rad/s across)"):
        s = scenes[name]
        params, states, model = batch.scene_states([s])
        r = batch.simulate_many(params, states, model, 1e-10)
        m = simulate(s, 1e-10)
        assert r.t_slide_end[0] == pytest.approx(m.t_slide_end, rel=1e-9)
        if m.rest is None:
            assert np.isnan(r.rest[0]).all() and np.isnan(r.t_roll_end[0])
        else:
            travel = math.hypot(m.rest[0] - s.state.xi, m.rest[1] - s.state.eta) + s.params.R
            assert math.hypot(r.rest[0, 0] - m.rest[0], r.rest[0, 1] - m.rest[1]) / travel <= 1e-9


def test_classical_model_is_n3_then_n7():
    states = bench.timing_states(50)
    P = classical_vs_appell.POOL
    r = batch.simulate_many(P, states, "classical")
    assert (r.model == batch.CLASSICAL).all() and (r.error == 0).all()
    from numerics.scene import Scene, State

    for i in (0, 7, 33):
        m = simulate(Scene(P, State(*states[i]), (), "classical"))
        assert r.rest[i] == pytest.approx(m.rest, rel=1e-12)


def test_chunks_and_workers_change_nothing():
    states = bench.timing_states(300)
    P = classical_vs_appell.POOL
    one = batch.simulate_many(P, states, tol=1e-9)
    many = batch.simulate_many(P, states, tol=1e-9, workers=2, chunk=64)
    # Lanes are independent; only the summation order inside NumPy's dot products may differ.
    assert np.array_equal(one.model, many.model)
    assert many.rest == pytest.approx(one.rest, rel=1e-12)


def test_mirror_symmetry_in_batch():
    states = bench.timing_states(40)
    mirrored = states * np.array([1, -1, 1, -1, -1, 1, -1])
    P = classical_vs_appell.POOL
    a, b = batch.simulate_many(P, states, tol=1e-11), batch.simulate_many(P, mirrored, tol=1e-11)
    assert b.rest[:, 0] == pytest.approx(a.rest[:, 0], rel=1e-9)
    assert b.rest[:, 1] == pytest.approx(-a.rest[:, 1], rel=1e-9, abs=1e-12)


def test_slide_ends_before_the_bound_of_n8():
    states = bench.timing_states(200)
    P = classical_vs_appell.POOL
    r = batch.simulate_many(P, states, tol=1e-9)
    from numerics import equations

    V0 = np.array([math.hypot(*equations.slip_velocity(P, *s[2:6])) for s in states])
    assert np.all(r.t_slide_end < V0 / (P.f * P.g))


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"states": np.zeros((3, 6))}, "shape"),
        ({"states": np.full((2, 7), np.nan)}, "finite"),
        ({"model": "magic"}, "model"),
        ({"tol": 1.0}, "tol"),
    ],
)
def test_bad_input(kwargs, message):
    args = {"params": classical_vs_appell.POOL, "states": np.zeros((2, 7)), **kwargs}
    with pytest.raises(ValueError, match=message):
        batch.simulate_many(**args)


def test_scenes_of_a_batch_share_params():
    scenes = list(bench_set.scenes().values())
    with pytest.raises(ValueError, match="same"):
        batch.scene_states([scenes[0], dataclasses.replace(scenes[1], params=dataclasses.replace(scenes[1].params, f=0.3))])
    assert math.isfinite(batch.simulate_many(classical_vs_appell.POOL, np.zeros((1, 7))).rest[0, 0])
