"""The benchmark's pieces: scoring, the accuracy of each method (never its speed), and the report."""

import math

import pytest

from numerics import bench, bench_set, reference_motion, scipy_baseline


@pytest.fixture(scope="module")
def references():
    return bench_set.scenes(), bench_set.references()


def test_the_set_is_fixed_and_seeded():
    a, b = bench_set.scenes(), bench_set.scenes()
    assert list(a) == list(b) and len(a) == 30
    assert all(bench_set.key(a[n], 40) == bench_set.key(b[n], 40) for n in a)


def test_scoring_a_perfect_answer_is_zero(references):
    scenes, refs = references
    name = "hard: sample"
    ref = refs[name]
    f = bench._f
    errs = bench.errors(scenes[name], ref, f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], f(ref["t_roll_end"]), [f(x) for x in ref["rest"]])
    assert max(errs) < 1e-15
    moved = bench.errors(scenes[name], ref, f(ref["t_slide_end"]), [f(x) for x in ref["omega_end"]], 0, [f(ref["rest"][0]) + 1e-3, f(ref["rest"][1])])
    assert moved[0] == pytest.approx(1e-3 / (math.hypot(*[f(x) for x in ref["rest"]]) + scenes[name].params.R), rel=1e-6)


@pytest.mark.skipif(not scipy_baseline.available(), reason="scipy is the optional bench extra")
@pytest.mark.parametrize("method", ["DOP853", "LSODA"])
def test_scipy_baseline_accuracy(references, method):
    scenes, refs = references
    for name in ("hard: sample", "random 03", "shot: draw (3 m/s, back spin 150 rad/s)"):
        r = scipy_baseline.solve(scenes[name], method, 1e-10)
        errs = bench.errors(scenes[name], refs[name], r["t_slide_end"], r["omega_end"], r["t_roll_end"], r["rest"])
        assert errs[0] <= 1e-7, name


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
        bench.Row("batch", "tol 1e-09", 2e-5, 5e-10, 5e-10, 1e-11, 1e-11, 30),
        bench.Row("scipy DOP853", "rtol 1e-10", 2e-2, 4e-10, 4e-10, 1e-9, 1e-9, 30),
    ]
    report = bench.Report(rows=rows, scaling=[(1, 1e-2), (10_000, 2e-5)], machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": True})
    text = "\n".join(bench.goals(report))
    assert "50,000 scenes/s" in text and "not met (4.0× short)" in text
    assert "1,000× faster" in text and "goal 100×: met" in text
    assert "| batch | tol 1e-09 |" in bench.as_text(report)
