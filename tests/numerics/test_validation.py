"""The one validation path: every entry refuses the same values with the same one line, and no loop runs unbounded."""

import math
import re
import warnings
from decimal import Decimal
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from numerics import batch, reference, validation
from numerics.scene import Coefficients, Params, Scene, State, parse
from numerics.simulate import simulate
from numerics.validation import ComputationError, SceneError, UnrepresentableError, WorkLimitError

POOL = dict(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575)
SHOT = dict(xi=0.0, eta=0.0, vxi=2.0, veta=0.0, p=10.0, q=-40.0, r=5.0)


@pytest.mark.parametrize(
    "value, expected",
    [(3, 3.0), (np.int64(3), 3.0), (np.float32(0.5), 0.5), (Decimal("0.25"), 0.25), (Fraction(1, 4), 0.25),
     (mpmath.mpf("0.125"), 0.125), (-0.0, 0.0)],
)
def test_real_accepts_every_kind_of_real_number(value, expected):
    assert validation.real(value, "x") == expected


@pytest.mark.parametrize(
    "value, rule",
    [(True, "must be a number"), (np.bool_(True), "must be a number"), ("1.5", "must be a number"),
     (None, "must be a number"), ([1.0], "must be a number"), (1j, "must be a real number"),
     (np.complex128(1), "must be a real number"), (float("nan"), "must be finite"), (-math.inf, "must be finite"),
     (np.float32("nan"), "must be finite"), (Decimal("NaN"), "must be finite"), (Decimal("Infinity"), "must be finite"),
     (10**400, "float64's range"), (Decimal("1e400"), "float64's range"), (Fraction(10**400, 3), "float64's range"),
     (Decimal("1e-400"), "must be 0 or at least 4.9e-324"), (Fraction(1, 10**400), "must be 0 or at least 4.9e-324")],
)
def test_real_refuses_with_one_line_naming_the_field(value, rule):
    with pytest.raises(SceneError) as error:
        validation.real(value, "state.p")
    assert str(error.value).startswith("state.p: ") and rule in str(error.value) and "\n" not in str(error.value)


def test_a_json_literal_beyond_float64_is_kept_for_real_to_refuse():
    """json.loads read 1e-400 as 0 and 1e400 as ∞: `decimal_beyond_float` keeps such a literal as a Decimal, and
    reads every other as float() does."""
    assert validation.decimal_beyond_float("1e-400") == Decimal("1e-400")
    assert validation.decimal_beyond_float("-1.5E+400") == Decimal("-1.5e400")
    for literal in ("0e-400", "-0.0", "2.5", "1e-320", "1.7e308"):
        number = validation.decimal_beyond_float(literal)
        assert type(number) is float and number == float(literal)


def test_tolerance_workers_and_model_rules():
    assert validation.tolerance(1e-9) == 1e-9
    for bad in (0, -1, 1, float("nan"), "1e-9", None):
        with pytest.raises(SceneError, match="^--tol: must"):
            validation.tolerance(bad, "--tol")
    assert validation.workers(np.int64(2)) == 2
    for bad in (0, -1, 1.5, True, "2"):
        with pytest.raises(SceneError, match="^workers: must be an integer >= 1"):
            validation.workers(bad)
    with pytest.raises(SceneError, match="^model: must be one of appell, classical"):
        validation.model("pooltool")


@pytest.mark.parametrize(
    "change, field, rule",
    [
        (dict(delta=0.01), "params.delta", "< f R"),
        (dict(f=float("nan")), "params.f", "finite"),
        (dict(f=0.0, delta=0.0), "params.f", "> 0"),
        (dict(R=-1.0), "params.R", "> 0"),
        (dict(g=float("nan")), "params.g", "finite"),
        (dict(g=0.0), "params.g", "> 0"),
        (dict(k=0.0), "params.k", "> 0"),
        (dict(k=0.028575), "params.k", "R √(2/3)"),
        (dict(epsilon=-1e-4), "params.epsilon", ">= 0"),
        (dict(R=1e300), "params.R", "between 1e-100 and 1e+100, both excluded"),
        (dict(f=1e100), "params.f", "between 1e-100 and 1e+100, both excluded"),  # (an audit: said as in range)
        (dict(f=1e-300), "params.f", "between 1e-100 and 1e+100"),
        (dict(g=1e-300), "params.g", "between 1e-100 and 1e+100"),
    ],
)
def test_params_check_themselves_when_built(change, field, rule):
    with pytest.raises(SceneError) as error:
        Params(**{**POOL, **change})
    assert error.value.field == field and rule in error.value.rule


def test_params_defaults_and_the_looser_coefficients():
    assert Params(**POOL).k == pytest.approx(math.sqrt(0.4) * POOL["R"], rel=1e-15, abs=0)
    shell = Params(**{**POOL, "k": POOL["R"] * math.sqrt(2 / 3)})  # the largest k, exactly at the bound
    assert shell.k > 0
    assert Coefficients(**{**POOL, "f": 0.0}).f == 0.0  # n°4: no sliding friction, outside (9)
    with pytest.raises(SceneError, match="params.delta"):
        Params(**{**POOL, "f": 0.001})


def test_scene_checks_its_parts_and_its_magnitudes():
    params, state = Params(**POOL), State(**SHOT)
    with pytest.raises(SceneError, match="^model: "):
        Scene(params, state, (), "bogus")
    with pytest.raises(SceneError, match=r"^scene.params: must be a Params"):
        Scene(dict(POOL), state)
    with pytest.raises(SceneError, match=r"^t\[1\]: must be >= 0"):
        Scene(params, state, (0.1, -1.0))
    with pytest.raises(SceneError, match="^state.p: must be finite"):
        State(**{**SHOT, "p": float("nan")})
    for change in (dict(vxi=1e300), dict(p=1e200), dict(r=1e150), dict(xi=1e300), dict(eta=-1e300)):
        (field,) = change  # the error names the number to fix (it named the scene: a user audit)
        with pytest.raises(UnrepresentableError, match=rf"^state.{field}: the motion's .* cannot be represented"):
            Scene(params, State(**{**SHOT, **change}))
    with pytest.raises(UnrepresentableError, match="duration"):
        Scene(params, state, (1e300,))


def test_simulate_takes_a_dict_and_refuses_anything_else():
    assert simulate({"params": POOL, "state": SHOT}).t_slide_end > 0
    for bad in ([1], "scene.json", None):
        with pytest.raises(SceneError, match="^scene: must be a Scene or a dict"):
            simulate(bad)
    with pytest.raises(SceneError, match="^tol: must be a number"):
        simulate({"params": POOL, "state": SHOT}, tol="1e-9")


def test_a_state_beyond_float64_is_refused_not_returned_as_inf():
    motion = simulate({"params": {**POOL, "delta": 0.0}, "state": SHOT})  # rolls for ever
    assert math.isfinite(motion.state_at(100.0).xi)
    with pytest.raises(UnrepresentableError, match="^t: the state at t = 1e\\+300 s"):
        motion.state_at(1e300)


@pytest.mark.parametrize("jit", [False, True])
def test_simulate_never_returns_a_nan(monkeypatch, jit):
    from numerics import engine

    # A rolling phase that comes out NaN (interpreted: the engine's own function; compiled: its result row).
    if jit:
        real_solve = simulate.__globals__["engine_for"](True).solve

        def solve(params, state, classical, tol, out, dense):
            real_solve(params, state, classical, tol, out, dense)
            out[engine.OUT_T_ROLL] = math.nan
            out[engine.OUT_STATUS] = engine.NON_FINITE if engine.first_non_finite(out) >= 0 else engine.OK

        monkeypatch.setattr(simulate.__globals__["engine_for"](True), "solve", solve)
    else:
        monkeypatch.setattr(engine, "roll", lambda *args: (math.nan, math.nan, math.nan))
    with pytest.raises(ComputationError, match=r"^scene.t_roll_end: came out non-finite"):
        simulate({"params": POOL, "state": SHOT}, jit=jit)


def test_batch_names_every_bad_row_and_can_skip_them():
    params = Params(**POOL)
    states = np.array([list(SHOT.values()), [0, 0, 1e300, 0, 0, 0, 0], [0, 0, 1, np.nan, 0, 0, 0], [0, 0, 1, 0, 0, 0, 0]], dtype=float)
    with pytest.raises(batch.BadScenesError) as error:
        batch.simulate_many(params, states)
    assert [i for i, _ in error.value.errors] == [1, 2]
    assert str(error.value).startswith("scene [1].state.vxi: the motion's speed") and "(and 1 more bad scenes)" in str(error.value)
    result = batch.simulate_many(params, states, skip_bad=True)
    assert result.ok.tolist() == [True, False, False, True]
    assert validation.in_scene(2, result.errors[2]) == "scene [2].state.veta: must be finite, got nan"
    assert np.isnan(result.rest[1]).all() and result.model[1] == -1
    assert np.isfinite(result.rest[[0, 3]]).all()
    alone = batch.simulate_many(params, states[[0]])
    assert alone.rest[0] == pytest.approx(result.rest[0], rel=1e-12, abs=0)


def test_batch_api_refuses_wrong_kinds():
    params = Params(**POOL)
    with pytest.raises(SceneError, match="^states: must be real numbers, got complex128"):
        batch.simulate_many(params, np.ones((1, 7)) * 1j)
    with pytest.raises(SceneError, match="^states: no scenes"):
        batch.simulate_many(params, np.zeros((0, 7)))
    with pytest.raises(SceneError, match="^states: must be an array .n, 7. of numbers, rows of equal length"):
        batch.simulate_many(params, [[1, 2], [1]])
    with pytest.raises(SceneError, match=r"^states: must have shape \(n, 7\)"):
        batch.simulate_many(params, np.zeros((2, 6)))
    with pytest.raises(SceneError, match=r"^scene \[0\].params: must be a Params or a dict"):
        batch.simulate_many([0.2], np.zeros((1, 7)))
    with pytest.raises(SceneError, match="^params: must be a Params, a dict as in a scene file, or one per scene"):
        batch.simulate_many(0.2, np.zeros((1, 7)))
    assert batch.simulate_many(dict(POOL), [list(SHOT.values())]).t_slide_end[0] > 0
    with pytest.raises(SceneError, match="^scenes: no scenes"):
        batch.scene_states([])



def test_batch_api_refuses_what_would_pass_as_numbers():
    """Found by an adversarial audit: an object array took the text "2" as 2.0, a masked array its masked values,
    a longdouble beyond float64 became ∞ with a numpy warning; and `Motion.states` took masked times."""
    params = Params(**POOL)
    row = list(SHOT.values())
    with pytest.raises(SceneError, match="^states: must be numbers, got '2'"):
        batch.simulate_many(params, np.array([row[:2] + ["2"] + row[3:]], dtype=object))
    with pytest.raises(SceneError, match="^states: must be numbers, got True"):
        batch.simulate_many(params, np.array([row[:6] + [True]], dtype=object))
    assert batch.simulate_many(params, np.array([row], dtype=object)).rest[0] == pytest.approx(
        batch.simulate_many(params, np.array([row])).rest[0], rel=0, abs=0)
    with pytest.raises(SceneError, match="^states: must be numbers, got a masked array with masked values"):
        batch.simulate_many(params, np.ma.masked_array([row], mask=[[0, 0, 1, 0, 0, 0, 0]]))
    plain = batch.simulate_many(params, np.array([row])).rest
    assert np.array_equal(batch.simulate_many(params, np.ma.masked_array([row])).rest, plain)  # nothing masked: its data
    # Any real number a scene file takes (Decimal, Fraction), as the rest of the API does; 10**400 is out of range.
    exact = np.array([[Decimal(str(x)) for x in row[:6]] + [Fraction(row[6])]], dtype=object)
    assert np.array_equal(batch.simulate_many(params, exact).rest, plain)
    with pytest.raises(SceneError, match="^states: must be within float64's range"):
        batch.simulate_many(params, np.array([row[:2] + [10**400] + row[3:]], dtype=object))
    huge = np.array([row], dtype=np.longdouble)
    huge[0, 2] = np.longdouble(10) ** 400
    if np.isfinite(huge[0, 2]):  # a longdouble wider than float64 (x86); elsewhere it is float64 and ∞ already
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with pytest.raises(SceneError, match="^states: must be within float64's range"):
                batch.simulate_many(params, huge)
    motion = simulate(Scene(params, State(*row), ()))
    with pytest.raises(SceneError, match="^t: must be times, got a masked array with masked values"):
        motion.states(np.ma.masked_array([0.1, 0.2], mask=[0, 1]))
    assert np.array_equal(motion.states(np.ma.masked_array([0.1, 0.2])).xi, motion.states([0.1, 0.2]).xi)


def test_batch_names_a_scene_whose_result_is_not_finite(monkeypatch):
    from numerics import engine

    monkeypatch.setattr(engine, "roll", lambda *args: (math.nan, math.nan, math.nan))
    with pytest.raises(ComputationError, match=r"^scene \[0\].t_roll_end: came out non-finite") as raised:
        batch.simulate_many(Params(**POOL), [list(SHOT.values())], jit=False)
    assert not isinstance(raised.value, WorkLimitError)  # a non-finite result is not a bound on work
    result = batch.simulate_many(Params(**POOL), [list(SHOT.values())], skip_bad=True, jit=False)
    assert not result.ok[0] and "t_roll_end" in str(result.errors[0])
    # Its row holds what was computed (a finite slide); every field of a refused scene reads NaN, its model -1.
    assert np.isfinite(result.rows[0, engine.OUT_T_SLIDE]) and result.rows[0, engine.OUT_MODEL] >= 0
    for name in ("t_slide_end", "t_roll_end", "t_pivot_end", "rest", "slide_end", "error"):
        assert np.isnan(getattr(result, name)[0]).all(), name
    assert result.model[0] == -1


def test_the_slide_stops_at_once_on_a_non_finite_rate_instead_of_looping(monkeypatch):
    from numerics import engine

    monkeypatch.setattr(engine, "rates_in_sigma", lambda sigma, y, p: (math.nan,) * 7)
    P, S = np.array(Params(**POOL).values()), np.array(list(SHOT.values()))
    out = np.empty(engine.N_OUT)
    engine.solve(P, S, False, 1e-9, out, np.empty((0, engine.DENSE_WIDTH)))
    assert out[engine.OUT_STATUS] == engine.NON_FINITE
    assert out[engine.OUT_STEPS] == out[engine.OUT_REJECTED] == 0  # stopped at once, not shrinking its step until the bound


def test_the_slide_has_a_bound_on_work(monkeypatch):
    from numerics import engine

    monkeypatch.setattr(engine, "MAX_STEPS", 3)
    with pytest.raises(WorkLimitError, match=r"^scene.slide: not done after 3 steps"):
        simulate({"params": POOL, "state": SHOT}, jit=False)


def test_gbs_has_a_bound_on_work_and_stops_on_nan(monkeypatch):
    monkeypatch.setattr(reference, "MAX_STEPS", 5)
    with pytest.raises(WorkLimitError, match="not done after 5 steps"):
        reference.integrate(lambda t, y: [y[0]], 0.0, [1.0], 100.0, 1e-12, first_step=1e-3)
    monkeypatch.setattr(reference, "MAX_STEPS", 10_000)
    with pytest.raises(ComputationError, match="non-finite"):
        reference.integrate(lambda t, y: [math.nan], 0.0, [1.0], 1.0, 1e-12)


def test_parse_accepts_numpy_and_decimal_values_and_sorts_mixed_unknown_keys():
    scene = parse({"params": {k: np.float32(v) for k, v in POOL.items()},
                   "state": {k: np.int64(1) if k == "vxi" else Decimal(0) for k in SHOT}})
    assert scene.state.vxi == 1.0
    with pytest.raises(SceneError, match=r"^scene\[1\]: unknown field"):
        parse({"params": POOL, "state": SHOT, 1: 2, "x": 3})


@pytest.mark.parametrize("bad", [None, (3, 4, np.nan), (0, 2, np.inf), (5, 4, 1e99), (7, 6, 1e200)])
def test_a_batch_of_fine_rows_is_passed_in_one_pass_and_only_then(bad):
    """`engine.all_within`, the fast path of `batch.bad_rows`: True exactly when no row is refused by the
    full check (a non-finite state, or a scale not below the limit: p = 1e99 rad/s, the distance bound;
    r = 1e200, the spin and the pivot's duration), compiled and interpreted alike."""
    compiled = pytest.importorskip("numerics.compiled")
    from numerics import batch, engine
    from numerics.scene import Params

    P = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575)
    rows = np.random.default_rng(5).uniform(-50, 50, size=(8, 7))
    if bad:
        rows[bad[0], bad[1]] = bad[2]
    table = np.tile(np.array(P.values()), (len(rows), 1))
    refused = batch.bad_rows(P, rows)  # the full check (a Params: no fast path)
    assert [i for i, _ in refused] == ([] if bad is None else [bad[0]])
    for run in (engine, compiled):
        assert run.all_within(table, rows, batch.validation.SCALE_LIMIT) == (bad is None)
        assert [i for i, _ in batch.bad_rows(table, rows, run)] == ([] if bad is None else [bad[0]])


def test_the_scale_bounds_decide_alike_compiled_and_interpreted():
    """The batch bounds its rows with the compiled `engine.motion_scales`, a scene with the interpreted one:
    on rows from 1e-300 to 1e300 both refuse the same rows for the same scale (values to rounding), and
    the bounds are the formulas of n°3, n°7 and eq. (5)."""
    compiled = pytest.importorskip("numerics.compiled")
    from numerics.scene import Params, unrepresentable

    P = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575)
    rng = np.random.default_rng(3)
    rows = 10.0 ** rng.uniform(-300, 300, size=(4000, 7)) * rng.choice([-1, 1], size=(4000, 7))
    rows[:1000] = rng.uniform(-50, 50, size=(1000, 7))  # ordinary shots: none refused
    table = np.tile(np.array(P.values()), (len(rows), 1))
    a, b = unrepresentable(table, rows), unrepresentable(table, rows, run=compiled)
    assert all(x is None for x in a[:1000]) and sum(x is not None for x in a) > 2000
    for x, y in zip(a, b):
        assert (x is None) == (y is None) and (x is None or (x[:2] == y[:2] and x[2] == pytest.approx(y[2], rel=1e-14, abs=0)))
    # One ordinary row against the formulas: V₀/(fg) for the slide, Ω(R² + k²)/(δg) for rolling, k²|r|/(εg).
    from numerics import engine

    state = np.array([[0.0, 0.0, 2.0, 0.0, 10.0, -40.0, 5.0]])
    scales = np.empty((1, engine.SCALES))
    engine.motion_scales(table[:1], state, 0.0, scales)
    speed = 2.0 + P.R * 50.0
    assert scales[0, 0] == pytest.approx(speed) and scales[0, 2] == pytest.approx(speed / (P.f * P.g))
    spin = speed / P.R * (1 + P.R**2 / P.k**2)
    assert scales[0, 3] == pytest.approx(spin * (P.R**2 + P.k**2) / (P.delta * P.g))
    assert scales[0, 4] == pytest.approx(5.0 * P.k**2 / (P.epsilon * P.g))


def test_the_batch_check_gives_the_compiled_bounds_a_read_only_view_and_the_same_reasons():
    """A batch's (n, 6) table goes to the compiled bounds as a read-only view, as np.broadcast_to gave it (the type
    they are compiled for), the caller's table left writable; the reasons those of one Params broadcast, with the
    interpreted and the compiled engine; a batch of good rows none."""
    compiled = pytest.importorskip("numerics.compiled")
    from numerics.scene import unrepresentable

    P = Params(**POOL)
    rows = np.array([list(SHOT.values()), [0, 0, 1e300, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0, 1e120], [0, 0, 1, 0, 0, 0, 0]])
    table = np.tile(np.array(P.values()), (len(rows), 1))
    seen = []

    class Recording:
        def motion_scales(self, params, states, horizon, out):
            seen.append(params.flags.writeable)
            compiled.motion_scales(params, states, horizon, out)

    found = unrepresentable(table, rows, run=Recording())
    assert seen == [False] and table.flags.writeable
    assert found == unrepresentable(P, rows) == unrepresentable(table, rows) == unrepresentable(P, rows, run=compiled)
    assert [x is None for x in found] == [True, False, False, True] and found[2][1] == "spin |r|"
    assert unrepresentable(table[[0, 3]], rows[[0, 3]], run=compiled) == [None, None]


def test_coefficients_whose_products_overflow_are_refused_before_any_work():
    """f = R = g = 1e99, each within [1e-100, 1e100]: the slide's deceleration g(f(1 + R²/k²) + δR/k²) is 3.5e198,
    and the formulas' products overflowed into a finite, wrong motion (the slide ending at 0 s).  Refused, naming it."""
    with pytest.raises(ValueError, match=r"^params.f, params.R, params.k, params.g: the motion's sliding deceleration bound .* would be 3.52e\+198"):
        Scene(Params(f=1e99, delta=0.0, epsilon=0.0, R=1e99, k=6.3e98, g=1e99), State(0, 0, 0, 0, 1.0, 2.0, 3.0))
    Scene(Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575), State(0, 0, 2.0, 0, 10.0, -40.0, 5.0))  # a shot


@pytest.mark.parametrize("jit", [False, None])
def test_a_speed_too_small_for_float64_squares_is_refused_not_left_at_the_step_bound(jit):
    """A mutation audit found valid-looking slides at ~1e-160 m/s (a square below float64's normal numbers) that
    ran into MAX_STEPS: a speed below 1/SCALE_LIMIT (but not 0) is refused before any work, as one too large."""
    params = Params(**POOL)
    tiny = [(0, 0, 1e-160, 0, 1e-160, 1e-160, 0), (0, 0, 1e-158, 0, 1e-168, 1e-168, 0), (0, 0, 1e-160, 0, 1e-161, 0, 0),
            (0, 0, 2e-155, 0, 5e-164, 0, 0), (0, 0, 1e-101, 0, 0, 0, 0)]
    for row in tiny:
        with pytest.raises(UnrepresentableError, match=r"inverse speed .* would be .*, not below 1e\+100"):
            Scene(params, State(*row), ())
    result = batch.simulate_many(params, np.array(tiny + [(0, 0, 1e-99, 0, 0, 0, 0), (0, 0, 0, 0, 0, 0, 30)]), skip_bad=True, jit=jit)
    assert result.ok.tolist() == [False] * len(tiny) + [True, True]
    assert all(isinstance(result.errors[i], UnrepresentableError) for i in range(len(tiny)))
    assert simulate(Scene(params, State(0, 0, 1e-99, 0, 0, 0, 0), ()), jit=jit).t_slide_end > 0


def test_a_batch_scene_at_the_bound_on_steps_is_a_work_limit_error(monkeypatch):
    """As `simulate`'s: the batch names the scene and the bound, as a WorkLimitError (a mutation swapping it for a
    plain ComputationError went unnoticed)."""
    from numerics import engine

    monkeypatch.setattr(engine, "MAX_STEPS", 3)
    with pytest.raises(WorkLimitError, match=r"^scene \[0\].slide: not done after 3 steps"):
        batch.simulate_many(Params(**POOL), [list(SHOT.values())], jit=False)


@pytest.mark.parametrize("params, state, field", [
    ({}, dict(vxi=1e300), "state.vxi"),
    ({}, dict(q=-1e200), "state.q"),
    ({}, dict(r=1e150), "state.r"),
    ({}, dict(xi=1e300), "state.xi"),
    ({}, dict(vxi=1e99), "state.vxi"),  # the speed is fine, the times and distance it gives are not
    (dict(delta=2e-100, g=1e-3), {}, "params.delta, params.R, params.k, params.g"),  # each coefficient within [1e-100, 1e100]
    (dict(epsilon=2e-100, delta=0.0, g=1e-5), {}, "params.epsilon, params.k, params.g"),
    (dict(R=1e99, k=1e98, delta=0.0, epsilon=0.0), {}, "params.R"),  # R p, R the larger factor (a review)
    (dict(f=2e-100, delta=0.0, g=1e-3), {}, "params.f, params.g"),
])
def test_a_motion_too_large_names_the_field_to_fix(params, state, field):
    """An error for a motion beyond float64 named the scene alone ("scene: the motion's speed ..."): it names the
    field now, the largest term of a sum, or the coefficients of a bound that a plain speed would keep in range."""
    P = Params(**{**POOL, **params})
    with pytest.raises(UnrepresentableError, match=rf"^{re.escape(field)}: the motion's"):
        Scene(P, State(**{**SHOT, **state}))


def test_a_field_list_inside_a_list_of_scenes_names_each_field_there():
    """A review: "scene [1].params.delta, params.g" put only the first field under its scene."""
    error = SceneError("params.delta, params.g", "a rule").within("scene [1]")
    assert error.field == "scene [1].params.delta, scene [1].params.g"
    assert SceneError("scene.cue", "a rule").within("scene [2]").field == "scene [2].cue"


def test_every_column_of_the_scale_bounds_has_its_name():
    """unrepresentable reads SCALE_NAMES[j] for engine.motion_scales' column j: one name a column, no more."""
    from numerics import engine, scene

    assert len(scene.SCALE_NAMES) == engine.SCALES == engine.INVERSE_SPEED + 1


def test_a_tolerance_below_the_range_is_refused_as_a_float_too():
    """`tolerance`'s fast path for floats keeps both ends of TOL_RANGE (a mutation audit: its lower end 1000× lower
    passed; every float tested below the range was 0 or negative)."""
    assert validation.tolerance(1e-13) == 1e-13
    for bad in (9e-14, 1e-14, 1e-16):
        with pytest.raises(SceneError, match="^tol: must be between 1e-13 and 1e-05"):
            validation.tolerance(bad)


def test_an_estimate_is_beyond_the_tolerance_above_tol_warning_times_it():
    from numerics import validation

    tol = 1e-10
    assert validation.beyond_tolerance(None, tol) is None  # no rest point, no estimate
    assert validation.beyond_tolerance(validation.TOL_WARNING * tol, tol) is None
    said = validation.beyond_tolerance(2 * validation.TOL_WARNING * tol, tol)
    assert said.startswith("the rest point's estimated relative error 2.0e-07 is 2,000× the tolerance asked (1e-10)")
    assert "5.6e+95×" in validation.beyond_tolerance(5.6e85, tol)  # not 96 digits (a ball 1e99 m from the origin)
