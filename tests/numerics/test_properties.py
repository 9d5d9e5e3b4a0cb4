"""Property-based tests (Hypothesis) over the parser and the API: for any input, either a result that passes
the invariants of the motion or a `SceneError`, within a time limit — never another exception, a hang or a NaN."""

import math

import numpy as np
import pytest
from hypothesis import event, given
from hypothesis import strategies as st
from strategies import SETTINGS, anything, physical_params, state_value, states, time_limit

from numerics import batch, lanes
from numerics.scene import PARAM_FIELDS, STATE_FIELDS, parse
from numerics.simulate import simulate
from numerics.validation import SceneError

def mangled(part: dict):
    """A dict with some values replaced by anything, some keys dropped, some added."""
    return st.fixed_dictionaries({}).flatmap(
        lambda _: st.tuples(
            st.dictionaries(st.sampled_from(sorted(part)), anything, max_size=2),
            st.sets(st.sampled_from(sorted(part)), max_size=1),
            st.dictionaries(st.text(max_size=3), anything, max_size=1),
        ).map(lambda t: {**{k: v for k, v in part.items() if k not in t[1]}, **t[0], **t[2]})
    )


def energy(b, k):
    """Kinetic energy per unit mass: ½(ξ'² + η'²) + ½k²(p² + q² + r²)."""
    return 0.5 * (b.vxi**2 + b.veta**2) + 0.5 * k**2 * (b.p**2 + b.q**2 + b.r**2)


def assert_invariants(motion):
    """Finite, ordered phase times, energy that never increases."""
    assert math.isfinite(motion.t_slide_end) and motion.t_slide_end >= 0
    if motion.t_roll_end is not None:
        assert math.isfinite(motion.t_roll_end) and motion.t_roll_end >= motion.t_slide_end
        assert all(math.isfinite(x) for x in motion.rest)
    if motion.t_pivot_end is not None:
        assert math.isfinite(motion.t_pivot_end) and motion.t_pivot_end >= 0
    if motion.rest is None:  # no rest point, no estimate of its error
        assert motion.error is None
    else:
        assert math.isfinite(motion.error) and motion.error >= 0
    samples = motion.samples(12)
    k = motion.scene.params.k
    for a, b in zip(samples, samples[1:]):
        assert all(math.isfinite(x) for x in vars(b).values() if isinstance(x, float))
        assert energy(b, k) <= energy(a, k) * (1 + 1e-9) + 1e-300


@SETTINGS
@given(params=physical_params(), state=states(), times=st.lists(st.floats(0, 30), max_size=2))
def test_physical_scenes_either_pass_the_invariants_or_are_refused(params, state, times):
    with time_limit():
        try:
            motion = simulate({"params": params, "state": state, "t": times})
        except SceneError as error:
            assert "\n" not in str(error)
            event(f"refused: {error.rule.split(' would')[0][:40]}")
            return
        event(f"simulated: {motion.phases[0].model.split(',')[0][:30]}")
        assert_invariants(motion)
        for t in times:
            assert all(math.isfinite(x) for x in vars(motion.state_at(t)).values() if isinstance(x, float))


@SETTINGS
@given(
    params=physical_params().flatmap(mangled), state=states().flatmap(mangled),
    extra=st.dictionaries(st.sampled_from(["t", "model", "colour", 7]), anything, max_size=2),
)
def test_the_parser_answers_any_scene_with_a_scene_or_one_line(params, state, extra):
    data = {"params": params, "state": state, **extra}
    with time_limit():
        try:
            scene = parse(data)
        except SceneError as error:
            assert "\n" not in str(error) and str(error).split(":")[0]
            event("refused")
            return
        event("parsed")
    assert set(PARAM_FIELDS) <= set(vars(scene.params)) and all(math.isfinite(getattr(scene.state, n)) for n in STATE_FIELDS)


@SETTINGS
@given(
    params=physical_params(),
    rows=st.lists(st.lists(state_value(50.0, (0.0, 1e300, -1e150, math.nan, math.inf)), min_size=7, max_size=7),
                  min_size=1, max_size=6),
    skip=st.booleans(),
)
def test_the_batch_answers_any_rows_with_results_or_the_bad_rows_named(params, rows, skip):
    states_ = np.array(rows)
    with time_limit():
        try:
            result = batch.simulate_many(params, states_, tol=1e-8, skip_bad=skip)
        except batch.BadScenesError as error:
            assert not skip and error.errors and all(0 <= i < len(rows) for i, _ in error.errors)
            event("refused")
            return
        event(f"computed, {int(result.ok.sum())} of {len(rows)} rows")
    for i in range(len(rows)):
        if not result.ok[i]:
            assert skip and i in result.errors
            continue
        assert np.isfinite(result.t_slide_end[i]) and result.t_slide_end[i] >= 0
        if params["delta"] > 0:
            assert result.t_roll_end[i] >= result.t_slide_end[i] and np.isfinite(result.rest[i]).all()
        assert np.isfinite(result.error[i]) == np.isfinite(result.rest[i]).all()  # NaN exactly where no rest point


@pytest.mark.parametrize("rows", [np.zeros((1, 7)), [[0, 0, 1, 0, 0, 0, 0]] * 3])
def test_the_batch_of_trivial_scenes(rows):
    result = batch.simulate_many({"f": 0.2, "delta": 0.0004, "epsilon": 0.0, "R": 0.028575}, rows)
    assert result.ok.all() and np.isfinite(result.rest).all()


@SETTINGS
@given(scenes=st.lists(st.tuples(physical_params(), states()), min_size=1, max_size=4),
       order=st.randoms(use_true_random=False))
def test_a_batch_in_lanes_gives_each_scene_what_simulate_gives(scenes, order):
    """64 rows (the lanes, `numerics.lanes`, take 32 curved slides or more), the drawn scenes repeated in a random
    order: each row's answer is, bit for bit, `simulate`'s for its scene — or both refuse it."""
    rows = [scenes[i % len(scenes)] for i in range(64)]
    order.shuffle(rows)
    params = [p for p, _ in rows]
    states_ = np.array([[s[name] for name in STATE_FIELDS] for _, s in rows])
    with time_limit():
        result = batch.simulate_many(params, states_, tol=1e-8, skip_bad=True)
        for i, (p, s) in enumerate(rows):
            try:
                motion = simulate({"params": p, "state": s}, tol=1e-8)
            except (SceneError, ArithmeticError):
                assert not result.ok[i]
                continue
            assert result.ok[i] and result.t_slide_end[i] == motion.t_slide_end
            rest = (math.nan, math.nan) if motion.rest is None else motion.rest
            error = math.nan if motion.error is None else motion.error
            assert np.array_equal(result.rest[i], rest, equal_nan=True) and np.array_equal(result.error[i], error, equal_nan=True)
    event("in lanes" if np.sum(result.model == batch.NUMERICAL) >= lanes.LANES else "one by one")
