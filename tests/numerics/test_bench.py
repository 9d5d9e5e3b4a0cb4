"""The benchmark's pieces: scoring, the accuracy of each method (never its speed), and the report."""

import json
import math

import numpy as np
import pytest

from numerics import batch, bench, bench_set, engine, heyoka_baseline, reference_motion, scipy_baseline


@pytest.fixture(scope="module")
def references():
    return bench_set.scenes(), bench_set.references()


def test_the_set_is_fixed_and_seeded():
    a, b = bench_set.scenes(), bench_set.scenes()
    assert list(a) == list(b) and len(a) == 31 + bench_set.N_FAST
    assert sum(n.startswith("fast ") for n in a) == bench_set.N_FAST
    # the fast shots each have their own cloth: per-scene parameters are exercised by every bench run
    assert len({a[n].params for n in a if n.startswith("fast ")}) == bench_set.N_FAST
    assert all(bench_set.key(a[n], 40) == bench_set.key(b[n], 40) for n in a)


def test_scoring_a_perfect_answer_is_zero(references):
    scenes, refs = references
    name = "hard: sample"
    ref = refs[name]
    f = bench._f
    errs = bench.errors(scenes[name], ref, f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], f(ref["t_roll_end"]), [f(x) for x in ref["rest"]])
    assert max(errs) < 1e-15
    moved = bench.errors(scenes[name], ref, f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], 0, [f(ref["rest"][0]) + 1e-3, f(ref["rest"][1])])
    assert moved[0] == pytest.approx(1e-3 / (math.hypot(*[f(x) for x in ref["rest"]]) + scenes[name].params.R), rel=1e-6, abs=0)


@pytest.mark.skipif(not scipy_baseline.available(), reason="scipy is the optional bench extra")
@pytest.mark.parametrize("method", ["DOP853", "LSODA"])
def test_scipy_baseline_accuracy(references, method):
    scenes, refs = references
    curved = bench.curved(scenes)
    for name in ("hard: sample", "random 03", "fast 00"):
        assert name in curved
        r = scipy_baseline.solve(scenes[name], method, 1e-10)
        errs = bench.errors(scenes[name], refs[name], r["t_slide_end"], r["omega_end"], r["t_roll_end"], r["rest"])
        assert errs[0] <= 1e-7, name


@pytest.mark.skipif(not scipy_baseline.available(), reason="scipy is the optional bench extra")
def test_scipy_baseline_refuses_a_closed_form_scene(references):
    scenes, _ = references
    with pytest.raises(ValueError, match="curved slides only"):
        scipy_baseline.solve(scenes["hard: straight draw"], "DOP853", 1e-10)


@pytest.mark.skipif(not heyoka_baseline.available(), reason="heyoka is the optional bench extra")
def test_heyoka_baseline_accuracy_scalar_and_batch(references):
    scenes, refs = references
    names = ["hard: sample", "random 03", "fast 00", "fast 05"]
    batch_answers = heyoka_baseline.solve_batch([scenes[n] for n in names], 1e-12)
    for name, b in zip(names, batch_answers):
        r = heyoka_baseline.solve(scenes[name], 1e-12)
        for answer in (r, b):
            errs = bench.errors(scenes[name], refs[name], answer["t_slide_end"], answer["omega_end"], answer["t_roll_end"], answer["rest"])
            assert max(errs) <= 1e-9, name


@pytest.mark.slow
def test_mpmath_at_15_digits_matches_the_40_digit_reference(references):
    scenes, refs = references
    name = "hard: huge spin, small speed"
    ref = reference_motion.reference(scenes[name], digits=15)
    errs = bench.errors(scenes[name], refs[name], float(ref.t_slide_end), (float(ref.slide_end.p), float(ref.slide_end.q)),
                        float(ref.t_roll_end), (float(ref.rest[0]), float(ref.rest[1])))
    assert max(errs) <= 1e-13


def test_report_states_the_goals_honestly():
    rows = [
        bench.Row("batch", "tol 1e-09", 1e-5, 5e-10, 5e-10, 1e-11, 1e-11, 42),
        bench.Row("batch, 1 thread", "tol 1e-09", 2e-5, 5e-10, 5e-10, 1e-11, 1e-11, 42),
        bench.Row("simulate", "tol 1e-09", 4e-5, 5e-10, 5e-10, 1e-11, 1e-11, 42),
        bench.Row("scipy DOP853", "rtol 1e-10", 1e-2, 4e-10, 4e-10, 1e-9, 1e-9, 42),
        bench.Row("scipy DOP853", "rtol 1e-08", 1e-3, 4e-8, 4e-8, 1e-7, 1e-7, 42),  # faster but never within 1e-9
        bench.Row("heyoka", "tol 1e-10", 5e-5, 1e-10, 1e-10, 1e-11, 1e-11, 42),
        bench.Row("heyoka batch", "tol 1e-10", 5e-6, 1e-10, 1e-10, 1e-11, 1e-11, 42),
        bench.Row("states (dense output)", "tol 1e-09", 3e-7, 1e-10, 4e-11, 0.0, 1e-10, 12),
        bench.Row("states in stiff steps", "tol 1e-09", 6e-6, 2e-10, 4e-11, 0.0, 2e-10, 18),
    ]
    report = bench.Report(rows=rows, scaling=[(1, 1e-2), (10, 1.1e-5), (10_000, 1e-5)], floor=[(10, 8e-6)],
                          calibration=[(1e-6, 0.31, 1.86, 162), (1e-9, 0.56, 25.0, 162)],
                          machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": True})
    text = "\n".join(bench.goals(report))
    assert "one scene per call (simulate): 40 µs at tol 1e-09, 250× faster than scipy DOP853 at rtol 1e-10; goal 300×: not met" in text
    assert "batch: 10 µs at tol 1e-09, 1,000× faster than scipy DOP853 at rtol 1e-10; goal 2000×: not met" in text
    assert "against heyoka scalar (50 µs at tol 1e-10): 1.25× ahead" in text
    assert "against heyoka batch mode (5 µs at tol 1e-10): 0.50× behind" in text
    assert "against heyoka batch mode, both on one thread (5 µs at tol 1e-10): 0.25× behind" in text
    assert (f"from n = 10 up: 10 µs to 11 µs (1.10×; one thread below {batch.SERIAL_BELOW} scenes a call); "
            "n = 10 against a long batch on one thread (20 µs): 0.55×; a call of 10 is no faster than its slowest "
            "scene alone: 8 µs a scene, 0.80× the cheapest") in text
    assert "(calls of 10 on their slowest scene alone: 8 µs a scene)" in bench.as_text(report)
    assert "tolerance: worst error 0.56 × tol over 162 scenes and every tol — within; the estimate at least 1.86 × the error — above it" in text
    assert "| 1e-06 | 0.31 | 1.86 |" in bench.as_text(report)
    assert "states inside a slide: 300 ns per state, within 1.0e-10 of the reference; goal 5 µs: met" in text
    assert "states inside stiff steps (near δ = fR): 6 µs per state, within 2.0e-10 of the reference; goal 5 µs: not met" in text
    assert "| batch | tol 1e-09 |" in bench.as_text(report)
    # no scipy row within 1e-9: the goals say so rather than compare with a less accurate run
    report.rows = [r for r in rows if r.method != "scipy DOP853" or r.setting == "rtol 1e-08"]
    assert bench.goals(report) == ["  scipy DOP853: not run, or never within 1e-9 (install the bench extra)"]


def test_a_saved_report_reads_back_as_it_was_written():
    """`appell bench --saved` prints the saved run (the README's figures of speed come from it): `from_json` must give
    back every row, size, calibration and machine figure `as_json` wrote, and so the same text."""
    report = bench.Report(
        rows=[bench.Row("batch", "tol 1e-09", 2e-6, 5e-10, 5e-10, 1e-11, 2e-11, 30, "2 threads"),
              bench.Row("scipy DOP853", "rtol 1e-12", 2e-2, 3e-11, 3e-11, 1e-14, 3e-12, 33, "one scene per call")],
        scaling=[(1, 2e-5), (10, 6e-6)], digits_scaling=[(15, 0.3)], calibration=[(1e-6, 0.02, 17.9, 163)],
        floor=[(10, 3e-6)], machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": False,
                                     "cold simulate (s)": 0.2, "import numpy (s)": 0.1, "first-ever compile (s)": 38.6},
        lost={"engine_calls_of_10": 8e-6, "engine_one_call": 5e-6, "python_per_call_of_10": 1.5e-5, "median_steps": 24,
              "step_alone": 7e-7, "block_steps": {4: 3e-7, 8: 2.2e-7, 12: 2.1e-7, 32: 2e-7}},
    )
    data = json.loads(json.dumps(bench.as_json(report)))
    assert bench.from_json(data) == report
    text = bench.as_text(bench.from_json(data))
    assert text == bench.as_text(report)
    assert "calls of 10 8 µs a scene,\n    one call of 1,000 5 µs (1.60×); simulate_many adds 15 µs a call of 10;" in text
    assert "(24 steps) alone 700 ns, a lane's share in a block of w copies: 4 300 ns, 8 220 ns, 12 210 ns, 32 200 ns" in text
    del data["calls_of_ten_lost"]  # a run saved before it was measured: printed without those lines
    assert bench.from_json(data).lost == {} and "Where calls of 10 lose" not in bench.as_text(bench.from_json(data))


def test_the_saved_run_is_printed_without_measuring(monkeypatch, capsys, tmp_path):
    from paper.cli import main

    monkeypatch.setattr(bench, "run", lambda **kw: pytest.fail("--saved measured"))
    assert main(["bench", "--saved"]) == 0
    saved = json.loads((bench_set.CACHE.parent / "bench.json").read_text(encoding="utf-8"))
    assert capsys.readouterr().out.rstrip("\n") == bench.as_text(bench.from_json(saved))
    assert main(["bench", "--saved", "--quick"]) == 2
    assert "--saved prints the saved run" in capsys.readouterr().err
    from paper import figures, record

    # The saved run names the source it was measured on, and says so when that is not this source.
    monkeypatch.setattr(figures, "DATA", tmp_path)
    for source, note in ((record.source_key(), None), ("f" * 20, f"from an earlier source (key {'f' * 20})"),
                         (None, "from a source not recorded")):
        machine = {key: value for key, value in saved["machine"].items() if key != "source"}
        (tmp_path / "bench.json").write_text(json.dumps({**saved, "machine": {**machine, **({"source": source} if source else {})}}))
        assert main(["bench", "--saved"]) == 0
        out, err = capsys.readouterr()
        assert f"; source {source or 'not recorded'}" in out.splitlines()[0]
        assert err == (f"appell bench: the saved run was measured {note}; 'appell bench' measures this one\n" if note else "")
    # a saved run that is not what `appell bench` writes
    for text in ("[]", json.dumps({**saved, "rows": [{"method": "batch"}]})):
        (tmp_path / "bench.json").write_text(text)
        assert main(["bench", "--saved"]) == 2
        err = capsys.readouterr().err
        assert "bench.json: not the JSON appell writes" in err and err.count("\n") == 1


@pytest.mark.slow  # the reference states: about 10 s
def test_the_stiff_states_row_times_and_scores_states_inside_stiff_steps():
    row = bench.stiff_dense_row(repeats=1)
    assert row.method == "states in stiff steps" and row.scenes >= 3
    assert row.max_rel_error <= 1e-9  # within the tolerance, as every state is (`test_engine`)
    assert 0 < row.seconds_per_scene < 1e-3


def test_scaling_runs_the_same_mix_at_every_size_and_reports_what_it_timed(monkeypatch):
    """Every size times SCALING_SCENES scenes (the same mix) in calls of n, each call's rest points read; the
    progress line and the report give the same time per scene."""
    monkeypatch.setattr(bench, "SCALING_SCENES", 20)
    sizes, read = [], []

    class Result:  # a batch's result: its rest points read, as a user reads them (its arrays are built when read)
        @property
        def rest(self):
            read.append(len(sizes))

    def simulate_many(p, s, tol):
        sizes.append((len(p), len(s), tol))
        return Result()

    monkeypatch.setattr(bench.batch, "simulate_many", simulate_many)

    def timed(fn, repeats):
        fn()
        return 1e-3  # the calls' wall time, made up: what is divided by what is the point here

    monkeypatch.setattr(bench, "_median_time", timed)
    slides = dict(list(bench_set.scenes().items())[:3])
    said = []
    assert bench.scaling(slides, [1, 10, 40], 1, said.append) == [(1, 5e-5), (10, 5e-5), (40, 2.5e-5)]
    assert said == ["  1: 50.00 µs/scene", "  10: 50.00 µs/scene", "  40: 25.00 µs/scene"]
    assert sizes == [(1, 1, 1e-9)] * 20 + [(10, 10, 1e-9)] * 2 + [(40, 40, 1e-9)]
    assert read == list(range(1, len(sizes) + 1))


def test_the_floor_of_small_batches_is_each_calls_slowest_scene_alone(monkeypatch):
    """`bench.slowest_alone`: each scene timed alone in calls of one (its rest point read), and a call of n costing
    its slowest scene's time: made-up times of 1, 2 and 3 (scene i + 1) over calls of 2 through the cycle 1 2 3 1 2 …"""
    monkeypatch.setattr(bench, "SCALING_SCENES", 6)
    calls = []

    class Result:
        @property
        def rest(self):
            calls[-1][1] = True

    def simulate_many(p, s, tol):
        calls.append([(len(p), len(s), tol, float(s[0][2])), False])
        return Result()

    monkeypatch.setattr(bench.batch, "simulate_many", simulate_many)
    slides = dict(list(bench_set.scenes().items())[:3])
    speeds = [scene.state.vxi for scene in slides.values()]

    def timed(fn, repeats):
        fn()
        return 20.0 * (speeds.index(calls[-1][0][3]) + 1)  # twenty calls of the scene: its time is index + 1

    monkeypatch.setattr(bench, "_median_time", timed)
    # calls of 2 over (1 2)(3 1)(2 3) cost 2 + 3 + 3 for six scenes
    assert bench.slowest_alone(slides, 2, 1) == pytest.approx((2 + 3 + 3) / 6)
    assert {c[0][:3] for c in calls} == {(1, 1, 1e-9)} and all(c[1] for c in calls)


def test_where_calls_of_ten_lose_is_measured_on_what_it_names(monkeypatch):
    """`bench.calls_of_ten_lost` on fakes: the engine's ``solve_many`` in calls of ten and in one call over the same
    SCALING_SCENES scenes, `simulate_many` in calls of ten on one thread (rest points read), and blocks of w copies
    of the median slide (by its steps, accepted and rejected), each divided by what it names.  The made-up time of
    a timed function is the number of solver calls it made plus 1,000 a `simulate_many` call."""
    monkeypatch.setattr(bench, "SCALING_SCENES", 30)
    slides = dict(list(bench_set.scenes().items())[:3])
    speeds = [scene.state.vxi for scene in slides.values()]
    solved, api = [], []

    def solve_many(table, states, classical, tol, out):
        assert len(table) == len(states) == len(classical) == len(out) and tol == 1e-9
        solved.append(np.array(states))
        for i, row in enumerate(states):  # scene j (in `slides`' order): 10 (j + 1) steps accepted, 2 rejected
            out[i, engine.OUT_STEPS], out[i, engine.OUT_REJECTED] = 10 * (speeds.index(row[2]) + 1), 2

    class Result:
        @property
        def rest(self):
            api[-1][1] = True

    def simulate_many(p, s, tol, workers):
        api.append([(len(p), len(s), tol, workers), False])
        return Result()

    monkeypatch.setattr(bench.batch, "engine_for", lambda jit: "compiled")
    monkeypatch.setattr(bench.batch, "lanes_solver", lambda run: solve_many if run == "compiled" else None)
    monkeypatch.setattr(bench.batch, "simulate_many", simulate_many)

    def timed(fn, repeats):
        before = (len(solved), len(api))
        fn()
        return (len(solved) - before[0]) + 1000.0 * (len(api) - before[1])

    monkeypatch.setattr(bench, "_median_time", timed)
    lost = bench.calls_of_ten_lost(slides, 1)
    assert lost["engine_calls_of_10"] == pytest.approx(3 / 30) and lost["engine_one_call"] == pytest.approx(1 / 30)
    assert [len(s) for s in solved[:4]] == [10, 10, 10, 30]
    assert {a[0] for a in api} == {(10, 10, 1e-9, 1)} and len(api) == 3 and all(a[1] for a in api)
    assert lost["python_per_call_of_10"] == pytest.approx((3000 / 30 - 3 / 30) * 10)
    assert lost["median_steps"] == 22  # steps 12, 22, 32: the second scene's
    assert lost["step_alone"] == pytest.approx(1 / 22)
    assert lost["block_steps"] == pytest.approx({w: 1 / (w * 22) for w in bench.BLOCK_WIDTHS})
    blocks = solved[-20 * len(bench.BLOCK_WIDTHS):]
    assert [len(b) for b in blocks[::20]] == list(bench.BLOCK_WIDTHS)
    assert all(np.all(b[:, 2] == speeds[1]) for b in blocks)


def test_a_damaged_reference_cache_is_computed_again_and_written_whole(tmp_path, monkeypatch):
    """An interrupted write used to leave half a cache, and the next run raised on it (an adversarial audit)."""
    scene = bench_set.scenes()["random 00"]
    monkeypatch.setattr(bench_set, "scenes", lambda: {"random 00": scene})
    monkeypatch.setattr(bench_set, "CACHE", tmp_path / "bench_reference.json")
    bench_set.CACHE.write_text('{"0123": {"scene": ')
    refs = bench_set.references(workers=1)
    assert list(refs) == ["random 00"] and refs["random 00"]["rest"] is not None
    assert json.loads(bench_set.CACHE.read_text()) == {bench_set.key(scene, bench_set.REFERENCE_DIGITS): {"scene": "random 00", **refs["random 00"]}}
    assert [p.name for p in tmp_path.iterdir()] == ["bench_reference.json"]


def test_scoring_sees_a_wrong_end_of_sliding_and_a_wrong_spin(references):
    """bench.errors' three numbers each move with what they score (the perfect answer alone left e_t and e_Ω
    unchecked: each compared against itself, or zeroed, passed; every "end of sliding within tol" assertion
    of test_batch and the calibration read e_t)."""
    scenes, refs = references
    name = "hard: sample"
    scene, ref, f = scenes[name], refs[name], bench._f
    t1, omega, t2, rest = f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], f(ref["t_roll_end"]), [f(x) for x in ref["rest"]]
    span = max(t2, t1, 1e-3)
    s = scene.state
    spin = max(math.hypot(s.p, s.q), math.hypot(s.vxi, s.veta) / scene.params.R, 1.0)
    e = bench.errors(scene, ref, t1 + 1e-3 * span, omega, t2, rest)
    assert e[1] == pytest.approx(1e-3, rel=1e-6) and e[0] < 1e-15 and e[2] < 1e-15
    e = bench.errors(scene, ref, t1, [omega[0], omega[1] + 1e-3 * spin], t2, rest)
    assert e[2] == pytest.approx(1e-3, rel=1e-6) and e[0] < 1e-15 and e[1] < 1e-15
    e = bench.errors(scene, ref, t1, [omega[0] + 1e-3 * spin, omega[1]], t2, rest)
    assert e[2] == pytest.approx(1e-3, rel=1e-6)


def test_bench_says_it_loads_the_engine_before_it_waits(monkeypatch):
    """`appell bench --quick` was silent for 47 s on a first run (the engine compiling): a note comes first."""
    from numerics import bench

    notes = []

    class Stop(Exception):
        pass

    def first_call(*args, **kwargs):
        notes.append("simulate_many called")
        raise Stop

    monkeypatch.setattr(bench.batch, "simulate_many", first_call)
    with pytest.raises(Stop):
        bench.run(quick=True, progress=notes.append)
    assert notes[-2].startswith("loading the compiled engine") and notes[-1] == "simulate_many called"


def test_scoring_sees_a_rest_point_off_across_one_that_should_not_exist_and_measures_from_the_start(references):
    """A mutation audit: bench.errors scoring ξ alone, scoring 0 for a rest point where the reference has none, or
    measuring the travel from the origin instead of the start, each passed (every bench scene starts at the origin)."""
    import dataclasses

    scenes, refs = references
    scene, ref, f = scenes["hard: sample"], refs["hard: sample"], bench._f
    t1, omega, t2, (rx, ry) = f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], f(ref["t_roll_end"]), [f(x) for x in ref["rest"]]
    travel = math.hypot(rx, ry) + scene.params.R
    assert bench.errors(scene, ref, t1, omega, t2, [rx, ry + 1e-3])[0] == pytest.approx(1e-3 / travel, rel=1e-6)
    assert bench.errors(scene, {**ref, "rest": None}, t1, omega, None, [rx, ry])[0] == math.inf
    assert bench.errors(scene, {**ref, "rest": None}, t1, omega, None, None)[0] == 0.0
    far = dataclasses.replace(scene, state=dataclasses.replace(scene.state, xi=scene.state.xi + 100.0))
    far_ref = {**ref, "rest": [str(rx + 100.0), str(ry)]}
    assert bench.errors(far, far_ref, t1, omega, t2, [rx + 100.0, ry + 1e-3])[0] == pytest.approx(1e-3 / travel, rel=1e-6)


def test_a_run_records_the_versions_of_the_compiler_and_the_peers_it_timed():
    """Times depend on numba, scipy and heyoka as much as on the machine: the run records those installed and its
    report's first line names them (a referee asked which versions the figure timed)."""
    from importlib import metadata

    versions = bench.peer_versions()
    assert versions["numba"] == metadata.version("numba")  # a core dependency: always there
    assert set(versions) <= set(bench.PEERS)
    machine = {"cpu": "AMD EPYC", "cores": 2, "python": "3.11.7", "numpy": "2.4.6", "quick": False,
               "versions": {"numba": "0.68.1", "scipy": "1.17.1"}}
    first = bench.as_text(bench.Report(machine=machine)).splitlines()[0]
    assert first == "AMD EPYC, 2 cores; Python 3.11.7, NumPy 2.4.6, numba 0.68.1, scipy 1.17.1; source not recorded"
    assert bench.versions_text({**machine, "versions": {}}) == bench.versions_text({}) == ""
