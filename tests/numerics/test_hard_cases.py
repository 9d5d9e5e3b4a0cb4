"""The hard cases are what `WHY` says they are: the appendix lists them with it, so each statement is measured."""

import math

import mpmath
import numpy as np
import pytest

from numerics import equations, reference_motion
from numerics import hard_cases as module
from numerics.hard_cases import POOL, R_BALL, WHY, hard_cases
from numerics.simulate import simulate

CASES = hard_cases()


def _motion(name):
    return simulate(CASES[name], 1e-9)


def _slip(P, s):
    return np.hypot(*equations.slip_velocity(P, s.vxi, s.veta, s.p, s.q))


def _closest_pass(name):
    """(smallest Ω, the slip then) over the slide: a fine grid, refined around its least point."""
    motion = _motion(name)
    t = np.linspace(0.0, motion.t_slide_end, 20001)
    s = motion.states(t)
    k = int(np.argmin(np.hypot(s.p, s.q)))
    t = np.linspace(t[max(k - 2, 0)], t[min(k + 2, len(t) - 1)], 4001)
    s = motion.states(t)
    k = int(np.argmin(np.hypot(s.p, s.q)))
    return math.hypot(s.p[k], s.q[k]), _slip(CASES[name].params, s)[k], motion


def _travel(motion, scene):
    return math.hypot(motion.rest[0] - scene.state.xi, motion.rest[1] - scene.state.eta)


def test_every_case_says_what_makes_it_hard():
    assert list(WHY) == list(CASES) and all(WHY.values())
    assert POOL["R"] == R_BALL == 0.028575  # the docstring's 28.575 mm (a 57.15 mm ball)


def test_the_sample_slides_rolls_and_pivots_the_pivot_outlasting_the_slide():
    m = _motion("sample")
    assert 0 < m.t_slide_end < m.t_pivot_end < m.t_roll_end


def test_the_centre_hit_starts_without_spin_and_slips():
    s = CASES["centre hit"].state
    assert s.p == s.q == 0 and s.vxi > 0


def test_the_draw_with_little_side_spin_passes_close_to_no_spin_while_it_slips():
    least, slip, _ = _closest_pass("draw, little side spin")
    assert least < 0.1 and slip > 0.9


def test_the_straight_draw_passes_through_no_spin():
    """Straight along ξ (p = 0): q changes sign inside the slide, so β jumps by π."""
    m = _motion("straight draw")
    q = m.states(np.linspace(0.0, m.t_slide_end, 2001)).q
    assert CASES["straight draw"].state.p == 0 and q[0] < 0 < q[-1]


def test_delta_close_to_fR_is_at_the_edge_of_hypothesis_9():
    P = CASES["delta close to fR"].params
    assert P.delta == pytest.approx(0.99 * P.f * P.R, rel=1e-15, abs=0)


def test_a_tiny_delta_rolls_over_a_thousand_km_and_the_near_straight_draw_turns_by_about_pi():
    scene = CASES["delta tiny"]
    assert scene.params.delta == 1e-9 and _travel(_motion("delta tiny"), scene) > 1e6
    name = "draw near the straight line, delta tiny"
    scene = CASES[name]
    assert math.atan2(scene.state.p, -scene.state.q) == pytest.approx(1e-5, rel=1e-6, abs=0)
    least, _, m = _closest_pass(name)
    assert least < 0.01 and _travel(m, scene) > 1e5
    s = m.states([0.0, m.t_slide_end])
    turn = abs(math.remainder(math.atan2(s.q[1], s.p[1]) - math.atan2(s.q[0], s.p[0]), 2 * math.pi))
    assert turn > 0.9 * math.pi


def test_the_masse_spins_over_300_rad_s_at_5_cm_s():
    s = CASES["huge spin, small speed"].state
    assert math.hypot(s.p, s.q) > 300 and math.hypot(s.vxi, s.veta) == 0.05


def test_the_pivot_ends_seconds_after_the_slide_inside_the_roll_and_never_without_epsilon():
    m = _motion("pivoting, r0 != 0")
    assert CASES["pivoting, r0 != 0"].state.r == 40 and m.t_slide_end + 1 < m.t_pivot_end < m.t_roll_end
    assert CASES["pivoting for ever (epsilon = 0)"].params.epsilon == 0
    assert _motion("pivoting for ever (epsilon = 0)").t_pivot_end is None


def test_at_rest_every_phase_has_length_0_and_a_spin_in_place_moves_off():
    m = _motion("at rest")
    assert m.t_slide_end == m.t_roll_end == 0 and _travel(m, CASES["at rest"]) == 0
    scene = CASES["spinning in place"]
    assert scene.state.vxi == scene.state.veta == 0 and _travel(_motion("spinning in place"), scene) > 0.1


def test_pure_rolling_from_the_start_has_no_slide_and_without_delta_no_rest():
    scene = CASES["pure rolling start"]
    assert _slip(scene.params, scene.state) < 1e-15 and _motion("pure rolling start").t_slide_end == 0
    assert CASES["rolls for ever (delta = 0)"].params.delta == 0 and _motion("rolls for ever (delta = 0)").rest is None


# `appell accuracy`'s scoring and verdict: what they measure moves with the error (a mutation audit).
def _row(error, estimate, **changes):
    return {"case": "c", "slide model": "numerical", "rest error": error, "t_slide_end error": 0.0,
            "t_roll_end error": 0.0, "estimate": estimate, "missing": None, **changes}


@pytest.mark.parametrize("error, kept", [(0.9e-9, True), (1e-9, True), (1.1e-9, False), (2e-9, False)])
def test_the_verdict_is_the_tolerance_asked_to_the_digit(error, kept):
    """`kept` judging by 100 × tol passed (the CLI test's error is 180 × tol)."""
    assert module.kept([_row(error, 1e-8)], 1e-9) is kept


@pytest.mark.parametrize("time", ["t_slide_end error", "t_roll_end error"])
def test_the_verdict_judges_the_times_too(time):
    """An audit: the times were printed and not judged (a time 50% off exited 0)."""
    assert module.kept([_row(1e-12, 1e-8, **{time: 1e-9})], 1e-9)
    assert not module.kept([_row(1e-12, 1e-8, **{time: 1.1e-9})], 1e-9)
    assert not module.kept([_row(1e-12, 1e-8, **{time: 0.5})], 1e-9)


def test_a_rest_point_one_side_misses_fails_and_is_named(monkeypatch):
    """An audit: a simulator rolling for ever where the reference rests had its rest error None, and passed."""
    missing = _row(None, 1e-8, **{"t_roll_end error": None, "missing": "the simulator rolls for ever, the reference rests"})
    assert not module.kept([missing], 1e-9)
    text = module.accuracy_text([missing], 1e-9)
    assert "| missing | 0.0e+00 | missing |" in text and "c: the simulator rolls for ever, the reference rests" in text

    def rolls_for_ever(ref):
        ref.t_roll_end, ref.rest = None, None

    row, _ = _sample_scored_against(monkeypatch, rolls_for_ever)
    assert row["missing"] == "the simulator rests, the reference rolls for ever" and row["rest error"] is None


def _sample_scored_against(monkeypatch, change) -> tuple[dict, object]:
    """`accuracy`'s row for the sample against its reference as ``change(ref)`` alters it, and the true reference."""
    real = reference_motion.reference

    def changed(scene, digits=15, **kw):
        ref = real(scene, digits=digits, **kw)
        change(ref)
        return ref

    monkeypatch.setattr(module, "hard_cases", lambda: {"sample": CASES["sample"]})
    monkeypatch.setattr(reference_motion, "reference", changed)
    (row,) = module.accuracy()
    return row, real(CASES["sample"], digits=15)


def test_a_rest_point_off_across_the_shot_is_an_error(monkeypatch):
    """The sample's reference moved by 1 mm along η: its rest error must show it (scoring ξ alone passed every
    pytest test; only the README's digits saw it)."""
    sample = CASES["sample"]

    def moved(ref):
        ref.rest = (ref.rest[0], ref.rest[1] + mpmath.mpf("1e-3"))

    row, true = _sample_scored_against(monkeypatch, moved)
    rx, ry = true.rest
    travel = float(mpmath.hypot(rx, ry + mpmath.mpf("1e-3"))) + sample.params.R  # the reference's travel
    assert row["rest error"] == pytest.approx(1e-3 / travel, rel=1e-6)


def test_times_are_relative_to_the_references_motion_as_the_bench_scores_them(monkeypatch):
    """The end of sliding 1 ms off in a reference whose roll lasts twice as long: 1 ms over the reference's length
    (the simulator's own length, half of it, was the span: `bench.errors` uses the reference's)."""
    def longer(ref):
        ref.t_slide_end, ref.t_roll_end = ref.t_slide_end + mpmath.mpf("1e-3"), 2 * ref.t_roll_end

    row, true = _sample_scored_against(monkeypatch, longer)
    assert row["t_slide_end error"] == pytest.approx(1e-3 / (2 * float(true.t_roll_end)), rel=1e-6)
