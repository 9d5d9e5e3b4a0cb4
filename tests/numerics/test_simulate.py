"""The scene simulator against the mpmath reference (no closed form used there), on every hard case,
and the invariants a ball must respect whatever the model."""

import dataclasses
import math
import os
import random
import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest

from numerics import equations, hard_cases, reference_motion
from numerics.scene import Params, Scene, State
from numerics.simulate import simulate

ROOT = Path(__file__).resolve().parents[2]

TOL = 1e-10
REQUIRED = 1e-9  # relative error on the rest point, promised in the README
CASES = hard_cases.hard_cases()

# The model each case must use while sliding: the cheapest exact one.
SLIDE_MODEL = {
    "centre hit": "straight shot",
    "straight draw": "straight shot",
    "spinning in place": "straight shot",
    "rolls for ever (delta = 0)": "n°3",
    "at rest": None,
    "pure rolling start": None,
}


@pytest.fixture(scope="module")
def solved():
    return {}


def _solve(name, solved):
    if name not in solved:
        scene = CASES[name]
        solved[name] = simulate(scene, tol=TOL), reference_motion.reference(scene, digits=15, times=scene.times)
    return solved[name]


def _travel(motion) -> float:
    s = motion.scene.state
    end = motion.rest if motion.rest is not None else motion.state_at(motion.t_slide_end)[2:4]
    return math.hypot(end[0] - s.xi, end[1] - s.eta) + motion.scene.params.R


@pytest.mark.slow  # the mpmath reference motion of each hard case
@pytest.mark.parametrize("name", list(CASES))
def test_against_mpmath_reference(name, solved):
    motion, ref = _solve(name, solved)
    scale_t = max(motion.t_roll_end or 0.0, motion.t_slide_end, 1e-3)
    assert abs(motion.t_slide_end - float(ref.t_slide_end)) <= REQUIRED * scale_t
    if ref.t_roll_end is None:
        assert motion.t_roll_end is None and motion.rest is None
    else:
        assert motion.t_roll_end == pytest.approx(float(ref.t_roll_end), rel=REQUIRED, abs=1e-15)
        travel = _travel(motion)
        actual = math.hypot(motion.rest[0] - float(ref.rest[0]), motion.rest[1] - float(ref.rest[1])) / travel
        assert actual <= REQUIRED
        # The error estimate is honest: it bounds the actual error (closed forms: rounding only).
        assert actual <= motion.error + 1e-13
    if ref.t_pivot_end is None:
        assert motion.t_pivot_end is None
    else:
        assert motion.t_pivot_end == pytest.approx(float(ref.t_pivot_end), rel=1e-12, abs=1e-15)
    s = motion.scene.state
    spin = max(math.hypot(s.p, s.q), max(abs(s.vxi), abs(s.veta)) / motion.scene.params.R, 1.0)
    for t in motion.scene.times:
        b, (xi, eta, p, q) = motion.state_at(t), ref.states[mpmath.mpf(t)]
        assert math.hypot(b.xi - float(xi), b.eta - float(eta)) <= REQUIRED * _travel(motion)
        assert math.hypot(b.p - float(p), b.q - float(q)) <= REQUIRED * spin


@pytest.mark.parametrize("name", list(SLIDE_MODEL))
def test_cheapest_exact_model(name):
    motion = simulate(CASES[name], tol=TOL)
    slides = [p for p in motion.phases if p.phase == "sliding"]
    if SLIDE_MODEL[name] is None:
        assert slides == []
    else:
        # a closed form's estimate is its rounding (engine.closed_estimate), far below any tolerance; with no rest
        # point (δ = 0: it rolls for ever) there is none to estimate
        assert slides and all(SLIDE_MODEL[name] in p.model for p in slides)
        assert all((0 < p.error < 1e-12) if motion.rest is not None else p.error is None for p in slides)


def test_numerical_slide_only_when_curved():
    motion = simulate(CASES["sample"], tol=TOL)
    assert motion.phases[0].model.startswith("numerical") and 0 < motion.phases[0].error <= 1e-9
    assert [p.phase for p in motion.phases] == ["sliding", "rolling", "rest", "pivoting"]


@pytest.mark.slow
def test_end_of_sliding_direction_is_beta_minus_right_angle(solved):
    # At the end of sliding θ = π/2 (n°8): the rolling that follows keeps β, and the reference's
    # slip direction, followed down to V = 0, agrees with β − π/2.
    motion, ref = _solve("draw, little side spin", solved)
    end = motion.state_at(motion.t_slide_end)
    assert math.atan2(end.q, end.p) == pytest.approx(float(mpmath.atan2(ref.slide_end.q, ref.slide_end.p)), abs=1e-9)
    assert float(ref.slide_end.alpha) == pytest.approx(math.atan2(end.q, end.p) - math.pi / 2, abs=1e-9)


def _mirror(scene: Scene) -> Scene:
    """Reflection η → −η: (ξ, η, ξ', η', p, q, r) → (ξ, −η, ξ', −η', −p, q, −r) (ω is a pseudovector)."""
    s = scene.state
    return dataclasses.replace(scene, state=State(s.xi, -s.eta, s.vxi, -s.veta, -s.p, s.q, -s.r))


@pytest.mark.parametrize("name", ["sample", "draw, little side spin", "huge spin, small speed", "pivoting, r0 != 0"])
def test_mirror_symmetry(name):
    scene = CASES[name]
    a, b = simulate(scene, tol=TOL), simulate(_mirror(scene), tol=TOL)
    assert b.t_slide_end == pytest.approx(a.t_slide_end, rel=1e-12, abs=0)
    assert b.t_roll_end == pytest.approx(a.t_roll_end, rel=1e-12, abs=0)
    assert b.rest[0] == pytest.approx(a.rest[0], rel=1e-12, abs=0) and b.rest[1] == pytest.approx(-a.rest[1], rel=1e-12, abs=1e-14)
    for t in (0.05, a.t_slide_end / 2, a.t_slide_end * 2):
        x, y = a.state_at(t), b.state_at(t)
        assert (y.xi, -y.eta, y.vxi, -y.veta, -y.p, y.q, -y.r) == pytest.approx((x.xi, x.eta, x.vxi, x.veta, x.p, x.q, x.r), rel=1e-9, abs=1e-12)


def _random_scenes(n, seed=1911):
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        R_ = 0.028575
        f_ = rng.uniform(0.1, 0.4)
        params = Params(f_, rng.uniform(0, 0.9) * f_ * R_, rng.uniform(0, 1e-3), R_, R_ * math.sqrt(0.4))
        state = State(0.0, 0.0, rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-150, 150), rng.uniform(-150, 150), rng.uniform(-50, 50))
        out.append(Scene(params, state, (), rng.choice(["appell", "appell", "classical"])))
    return out


def _kinetic(b, k):
    return (b.vxi**2 + b.veta**2 + k**2 * (b.p**2 + b.q**2 + b.r**2)) / 2


@pytest.mark.parametrize("scene", _random_scenes(12), ids=lambda s: f"{s.model}-{s.state.vxi:.2f}")
def test_energy_never_increases_and_slide_ends_before_the_bound(scene):
    motion = simulate(scene, tol=TOL)
    P, s = scene.params, scene.state
    u, v = equations.slip_velocity(P, s.vxi, s.veta, s.p, s.q)
    assert motion.t_slide_end < math.hypot(u, v) / (P.f * P.g)  # n°8
    end = motion.t_roll_end if motion.t_roll_end is not None else 3 * motion.t_slide_end + 1
    times = [end * j / 200 for j in range(201)]
    energies = [_kinetic(motion.state_at(t), P.k) for t in times]
    for before, after in zip(energies, energies[1:]):
        assert after <= before * (1 + 1e-12)


@pytest.mark.slow
def test_classical_model_slides_without_rolling_couple():
    scene = dataclasses.replace(CASES["sample"], model="classical")
    motion = simulate(scene, tol=TOL)
    ref = reference_motion.reference(scene, digits=15)
    assert "n°3" in motion.phases[0].model
    assert motion.t_slide_end == pytest.approx(float(ref.t_slide_end), rel=1e-12, abs=0)
    assert motion.rest == pytest.approx((float(ref.rest[0]), float(ref.rest[1])), rel=1e-11, abs=0)


def test_state_at_is_continuous_across_phases():
    motion = simulate(CASES["sample"], tol=TOL)
    for boundary in (motion.t_slide_end, motion.t_roll_end):
        a, b = motion.state_at(boundary * (1 - 1e-12)), motion.state_at(boundary * (1 + 1e-12))
        assert (a.xi, a.eta, a.vxi, a.veta, a.p, a.q) == pytest.approx((b.xi, b.eta, b.vxi, b.veta, b.p, b.q), abs=1e-8)


def test_tolerance_outside_range_is_refused():
    with pytest.raises(ValueError, match="tol"):
        simulate(CASES["sample"], tol=1e-20)


def test_samples_for_plotting_cover_the_whole_motion():
    motion = simulate(CASES["sample"], tol=TOL)
    samples = motion.samples(50)
    assert len(samples) == 51 and samples[0].t == 0 and samples[-1].t == motion.t_roll_end
    assert {b.phase for b in samples} == {"sliding", "rolling"}
    assert (samples[-1].vxi, samples[-1].veta) == pytest.approx((0, 0), abs=1e-12)
    forever = simulate(CASES["rolls for ever (delta = 0)"], tol=TOL).samples(10)
    assert forever[-1].phase == "rolling"
    with pytest.raises(ValueError):
        motion.samples(0)
    with pytest.raises(ValueError, match="samples: must be an integer >= 1 and < 100,000"):
        motion.samples(100_000)  # each a state: a bound on work and memory
    assert len(motion.samples(np.int64(5))) == 6  # NumPy's integers are integers


def test_a_scene_reports_at_most_max_times_and_an_endless_iterator_is_cut():
    import itertools

    from numerics.scene import MAX_TIMES

    sample = CASES["sample"]
    assert len(Scene(sample.params, sample.state, [0.5] * MAX_TIMES).times) == MAX_TIMES
    for times in ([0.5] * (MAX_TIMES + 1), itertools.count()):
        with pytest.raises(ValueError, match="^t: at most 100,000 times"):
            Scene(sample.params, sample.state, times)


def test_a_vanishing_shot_is_refused_in_one_line_without_a_warning():
    """Speeds of 1e-300 once gave a NaN error norm (a RuntimeWarning, the slide's distance V₀²/(fg) underflowed);
    then they were solved, while speeds near 1e-160 (a square below float64's normal numbers) ran into the bound
    on steps.  A speed below 1e-100 (but not 0) is now refused before any work, as a parameter below 1e-100 is."""
    import warnings

    from numerics.validation import UnrepresentableError

    for speed in (1e-300, 1e-160):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with pytest.raises(UnrepresentableError, match=r"^state.vxi, state.veta, state.p, state.q: the motion's inverse speed"):
                Scene(CASES["sample"].params, State(0.0, 0.0, speed, 0.0, speed, speed, speed))
    assert simulate(Scene(CASES["sample"].params, State(0.0, 0.0, 1e-99, 0.0, 0.0, 0.0, 0.0))).t_slide_end > 0


def test_appell_jit_0_in_the_environment_runs_the_interpreted_engine():
    """APPELL_JIT=0 (read when numerics.simulate is imported) makes ``jit=None`` the interpreted engine; unset, it
    is the compiled one (numba is installed with the test extras)."""
    import subprocess
    import sys

    code = "from numerics.simulate import engine_for; print(engine_for(None).__name__, engine_for(False).__name__)"
    for value, names in (("0", "numerics.engine numerics.engine"), ("1", "numerics.compiled numerics.engine")):
        env = {**os.environ, "APPELL_JIT": value}
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT)
        assert done.returncode == 0 and done.stdout.split() == names.split(), done.stderr
    # "no" read as "not 0" meant compiled, silently (an audit): refused, naming the variable, where it is read.
    code = ("from numerics.simulate import engine_for\ntry:\n    engine_for(None)\nexcept ValueError as error:\n"
            "    print(error)\nprint(engine_for(False).__name__)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, "APPELL_JIT": "no"},
                          cwd=ROOT)
    assert done.stdout == "APPELL_JIT: must be 0 (the interpreted engine) or 1 (compiled), got 'no'\nnumerics.engine\n", done.stderr


def test_a_ball_spinning_in_place_rests_and_pivots_and_its_samples_reach_the_pivots_end():
    """No slip and no rolling: the phases are rest, then the pivot (no rolling phase of length 0), and the samples
    for a plot run to the pivot's end, where the spin stops (mutations of both went unnoticed)."""
    motion = simulate(Scene(Params(f=0.2, delta=4e-4, epsilon=3e-4, R=0.028575), State(0, 0, 0, 0, 0, 0, 30.0), ()))
    assert [ph.phase for ph in motion.phases] == ["rest", "pivoting"]
    samples = motion.samples(4)
    assert samples[0].t == 0 and samples[-1].t == motion.t_pivot_end > 3
    assert samples[0].r == 30.0 and samples[-1].r == pytest.approx(0.0, abs=1e-12)
    assert [b.t for b in samples] == sorted(b.t for b in samples) and len({b.t for b in samples}) == 5


def test_the_record_reports_the_motions_own_error_estimate():
    """`--json`'s error_estimate is `Motion.error`, not the tolerance (a mutation went unnoticed)."""
    from numerics.simulate import record

    for name in ("sample", "centre hit"):
        motion = simulate(CASES[name], TOL)
        assert motion.as_dict()["error_estimate"] == motion.error == record(
            motion.row, "appell", TOL, motion.scene.params, motion.scene.arrays()[1])["error_estimate"]
    assert simulate(CASES["sample"], TOL).error not in (0.0, TOL)


def test_a_shot_nearly_straight_takes_the_closed_form_only_where_it_is_within_tol():
    """The straight closed form is off by |θ ∓ π/2| times a lever of the shot (here a draw, lever 2): a draw
    0.9e-12 rad off straight was 1.8× tol 1e-12 off with an estimate of 0 (an audit).  Against the mpmath
    reference: within tol at every tolerance, the closed form where it is close enough."""
    from numerics import bench, bench_set

    R = 0.028575
    P = Params(f=0.2, delta=4e-4, epsilon=3e-4, R=R)
    p, q = 100.0 * math.cos(-math.pi / 2 + 0.9e-12), 100.0 * math.sin(-math.pi / 2 + 0.9e-12)
    scene = Scene(P, State(0.0, 0.0, 2.0 + R * q, -R * p, p, q, 0.0), ())
    ref = bench_set.compute(scene, 30)
    for tol, model in ((1e-13, "numerical"), (1e-12, "numerical"), (1e-10, "numerical"), (1e-9, "closed form straight")):
        motion = simulate(scene, tol)
        e_rest, e_t, _ = bench.errors(scene, ref, motion.t_slide_end, (0.0, 0.0), motion.t_roll_end, motion.rest)
        assert motion.model.startswith(model) and e_rest <= tol and e_t <= tol, (tol, motion.model, e_rest / tol)


class _Terminal:
    def __init__(self, tty: bool):
        self.tty, self.text = tty, ""

    def isatty(self):
        return self.tty

    def write(self, text):
        self.text += text

    def flush(self):
        pass


def test_the_first_compilation_of_a_copy_is_announced_on_a_terminal(tmp_path, monkeypatch):
    """A minute without a word, the first time a copy of appell runs compiled: one line, on a terminal or in a
    notebook, when nothing of this copy is compiled yet (another checkout's code in the same cache does not count:
    numba compiles again for it)."""
    from numerics import compiled

    terminal = _Terminal(True)
    assert compiled.announce_first_compile(tmp_path, terminal)
    assert terminal.text.startswith("appell: compiling the simulator's engine, once for this copy of appell")
    assert terminal.text.count("\n") == 1
    assert not compiled.announce_first_compile(tmp_path, _Terminal(False))  # a pipe, a log, a test's capture
    assert not compiled.announce_first_compile(tmp_path, None)  # no stderr at all (pythonw)
    notebook = _Terminal(False)
    monkeypatch.setitem(sys.modules, "ipykernel", object())  # a Jupyter kernel: its stderr is shown, not a terminal
    assert compiled.announce_first_compile(tmp_path, notebook) and notebook.text.startswith("appell: compiling")
    (tmp_path / "numerics_of_another_checkout").mkdir()
    (tmp_path / "numerics_of_another_checkout" / "solve-1.py311.nbi").write_bytes(b"")
    assert compiled.announce_first_compile(tmp_path, _Terminal(True))
    compiled.copy_folder(tmp_path).mkdir()
    (compiled.copy_folder(tmp_path) / "solve-1.py311.nbi").write_bytes(b"")
    silent = _Terminal(True)
    assert not compiled.announce_first_compile(tmp_path, silent) and silent.text == ""


def test_the_copy_folder_is_where_numba_keeps_this_copys_code():
    """`compiled.copy_folder` names numba's own subfolder (a private numba function, numba pinned): the engine,
    once called, has its index there."""
    from numerics import batch, bench, classical_vs_appell, compiled

    batch.simulate_many(classical_vs_appell.POOL, bench.timing_states(2), jit=True)
    assert compiled.CACHE is None and any(compiled.copy_folder(Path(compiled.numba.config.CACHE_DIR)).glob("*.nbi"))


def test_a_cache_folder_that_cannot_be_written_is_named(tmp_path):
    from numerics import compiled

    assert compiled.unusable(tmp_path / "new" / "cache") is None and (tmp_path / "new" / "cache").is_dir()
    (tmp_path / "a file").write_text("")
    assert compiled.unusable(tmp_path / "a file" / "cache") is not None


@pytest.mark.slow  # compiles the engine once, in memory: about a minute
def test_an_unusable_cache_compiles_in_memory_and_writes_nothing_into_the_package(tmp_path):
    """An audit: with $APPELL_NUMBA_CACHE unwritable, numba kept the compiled code in the package's own
    numerics/__pycache__ (55 files, keyed there by timestamps only) without a word."""
    import subprocess
    import sys

    package = Path(__file__).resolve().parents[2] / "numerics" / "__pycache__"
    before = sorted(package.glob("*.nb*")) if package.is_dir() else []
    (tmp_path / "a file").write_text("")
    env = {**os.environ, "APPELL_NUMBA_CACHE": str(tmp_path / "a file")}
    code = ("from numerics.simulate import simulate; from numerics.scene import load; "
            "print(simulate(load('numerics/scenes/sample.json'), jit=True).t_slide_end)")
    run = subprocess.run([sys.executable, "-c", code], cwd=package.parent.parent, env=env, capture_output=True,
                         text=True, timeout=600, check=False)
    assert run.returncode == 0 and float(run.stdout) > 0, run.stderr
    assert run.stderr.startswith("appell: cannot keep the compiled engine in ") and run.stderr.count("\n") == 1
    assert (sorted(package.glob("*.nb*")) if package.is_dir() else []) == before


FULL_CACHE = """
import errno, math
from numba.core import caching
def full(self, key, data):
    raise OSError(errno.ENOSPC, "No space left on device")
caching.IndexDataCacheFile.save = full  # the disk under the cache fills up as the code is saved
from numerics import compiled
print(compiled._COMPILED["slip_velocity"](1.0, 2.0, 3.0, 4.0, 0.5), compiled._COMPILED["pivot_end"](2.0, 0.2, 0.03, 0.7, 0.001, 0.002, 9.8))
import sys
sys.path.insert(0, sys.argv[1])
try:  # a user's own numba code in the same process: numba's behaviour, untouched
    import user_code
    user_code.plus(1)
except OSError:
    pass
else:
    raise SystemExit("another's save error was swallowed")
"""


def test_a_cache_folder_that_fills_up_leaves_the_code_compiled_in_memory(tmp_path):
    """A full disk under $APPELL_NUMBA_CACHE: numba's save raised, and the command line blamed standard output (an
    audit).  The engine's code stays compiled in memory for the process, said once, naming the folder."""
    import subprocess
    import sys

    env = {**os.environ, "APPELL_NUMBA_CACHE": str(tmp_path)}
    user = tmp_path / "user"
    user.mkdir()
    (user / "user_code.py").write_text("import numba\n\n@numba.njit(cache=True)\ndef plus(x):\n    return x + 1\n")
    run = subprocess.run([sys.executable, "-c", FULL_CACHE, str(user)], cwd=Path(__file__).resolve().parents[2], env=env,
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stderr.startswith(f"appell: cannot keep the compiled engine in {tmp_path}/numba-") and run.stderr.count("\n") == 1
    assert "(No space left on device;" in run.stderr
    from numerics import kernels

    assert [float(x) for x in run.stdout.replace("(", "").replace(")", "").replace(",", " ").split()] == [
        *kernels.slip_velocity(1.0, 2.0, 3.0, 4.0, 0.5), kernels.pivot_end(2.0, 0.2, 0.03, 0.7, 0.001, 0.002, 9.8)]
    assert not list(tmp_path.rglob("*.tmp.*"))  # numba's half-written file went

def _turned(state, angle):
    """The state turned by ``angle`` about the vertical: positions, velocities and (p, q) alike; r kept."""
    c, s = math.cos(angle), math.sin(angle)
    xi, eta, vxi, veta, p, q, r = state
    return (c * xi - s * eta, s * xi + c * eta, c * vxi - s * veta, s * vxi + c * veta, c * p - s * q, s * p + c * q, r)


@pytest.mark.parametrize("angle", [math.pi / 2, math.pi, 0.7])
def test_the_error_estimate_does_not_depend_on_the_heading(angle):
    """The table has no preferred direction: turning a curved shot turns its motion and leaves its error
    estimate (and its steps) as they were (a mutation audit: the estimate ignoring eta's error passed)."""
    from numerics import bench_set, engine

    scene = bench_set.calibration_scenes()["calibration 042"]  # the centre's own error dominates its estimate
    base = scene.state.row()
    a = simulate(scene, 1e-9, jit=False)
    b = simulate(Scene(scene.params, State(*_turned(base, angle)), ()), 1e-9, jit=False)
    assert a.model == b.model == engine.MODEL_NAMES[engine.NUMERICAL]
    assert b.row[engine.OUT_STEPS] == a.row[engine.OUT_STEPS]
    assert b.error == pytest.approx(a.error, rel=1e-3)


def test_a_slide_of_more_steps_than_the_dense_buffer_keeps_every_step(monkeypatch):
    """`simulate._solve` solves again with room for every step when the slide took more than DENSE_ROWS (a
    mutation dropping the retry passed: no test slide took more than 256 steps).  With a buffer of 4 rows,
    the states inside the slide are the same bits as with the default buffer."""
    from numerics import simulate as simulate_module
    from numerics.scene import load

    scene = load(Path(__file__).resolve().parents[2] / "numerics" / "scenes" / "sample.json")
    full = simulate(scene, 1e-10, jit=False)
    times = np.linspace(0.0, full.t_slide_end, 41)
    want = full.states(times)
    assert len(full._dense_output()) > 4
    monkeypatch.setattr(simulate_module, "DENSE_ROWS", 4)
    few = simulate(scene, 1e-10, jit=False)
    got = few.states(times)
    assert len(few._dense_output()) == len(full._dense_output())
    for name in ("xi", "eta", "vxi", "veta", "p", "q"):
        assert np.array_equal(getattr(got, name), getattr(want, name)), name


def test_the_times_of_a_scene_are_in_order_and_a_time_too_far_is_named():
    """An audit: a set of times (no order) was taken, and t = [1e99] was refused as "scene: the motion's
    distance bound ...", which did not say that the time was the trouble."""
    from numerics.validation import SceneError

    P, start = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=0.028575), State(0, 0, 1.0, 0, 0, 0, 0)
    with pytest.raises(SceneError, match=r"t: must be a list of times \(s; a list, its order kept\), got"):
        Scene(P, start, {0.2, 0.1})
    rolling_for_ever = Params(f=0.2, delta=0.0, epsilon=0.0003, R=0.028575)  # δ = 0: the distance grows with t
    with pytest.raises(SceneError, match=r"^t: the motion's distance bound"):
        Scene(rolling_for_ever, State(0, 0, 20.0, 0, 0, 0, 0), (1e99,))
    with pytest.raises(SceneError, match=r"^state.vxi: the motion's rolling time"):  # the motion itself: the speed
        Scene(P, State(0, 0, 1e99, 0, 0, 0, 0), ())
    with pytest.raises(SceneError, match=r"jit: must be True, False or None"):
        simulate(Scene(P, start, ()), jit="no")


def test_no_rest_point_no_error_estimate_in_every_form():
    """δ = 0: the API said 0.0 (read as an exact answer) where the JSON said null (a user audit): None in `Motion`
    and its phases, NaN in a batch, null in the record; a scene that rests keeps its estimate."""
    from numerics import batch
    from numerics.simulate import record

    never = hard_cases.hard_cases()["rolls for ever (delta = 0)"]
    rests = dataclasses.replace(never, params=dataclasses.replace(never.params, delta=0.001))
    motion = simulate(never)
    assert motion.rest is None and motion.error is None and motion.phases[0].error is None
    assert record(motion._out, never.model, motion.tol, never.params, never.state.row())["error_estimate"] is None
    p, s, m = batch.scene_states([never, rests])
    errors = batch.simulate_many(p, s, m).error
    assert np.isnan(errors[0]) and errors[1] == simulate(rests).error > 0


@pytest.mark.parametrize("distance, tol", [(1e4, 1e-13), (1e5, 1e-12)])
def test_far_from_the_origin_the_estimate_covers_the_rounding_tol_cannot(distance, tol):
    """A user audit: a start 10 km out at tol 1e-13 missed tol tenfold (float64's ulp of the coordinates, a few
    of them over 1.5 m of travel), with nothing said but the estimate.  The slide now integrates the displacement
    (`engine.slide_numerically`): the rest point is within an ulp of the coordinates of the reference; half an ulp,
    what float64 cannot resolve there, is still above tol, and the estimate stays above it and says so."""
    from numerics.scene import Params, Scene, State

    scene = Scene(Params.from_pool(0.2, 0.01, 0.0127, 0.028575), State(distance, -distance, 2.0, 0.3, 10.0, -40.0, 5.0))
    motion = simulate(scene, tol)
    ref = reference_motion.reference(scene, digits=25)
    travel = float(mpmath.hypot(ref.rest[0] - distance, ref.rest[1] + distance)) + scene.params.R
    error = math.hypot(motion.rest[0] - float(ref.rest[0]), motion.rest[1] - float(ref.rest[1])) / travel
    ulp = math.ulp(distance) / travel  # float64's spacing of the coordinates there, over the travel
    assert error <= ulp  # as near as float64 holds it
    assert tol < ulp / 2 <= motion.error  # the limit is float64's, and the estimate reports it


def test_a_closed_form_whose_slide_takes_nearly_all_the_spin_estimates_the_cancellation():
    """An audit: a ball spinning in place with k = 0.002 R and δ = 1e-13 (closed-form straight shot) rested 4.4e-11
    off with an estimate of 1.4e-14: Ω at the end of sliding, Ω₀ less nearly all of it, carries the cancellation
    into a 46-hour roll.  `engine.closed_estimate` weighs it (Ω₀/Ω₁ ≈ 2.5e5): the estimate stays above the error."""
    from numerics.scene import Params, Scene, State

    scene = Scene(Params(f=0.2, delta=1e-13, epsilon=0.0003, R=0.028575, k=5.715e-5), State(0, 0, 0, 0, 0.001, 50.0, 0))
    motion = simulate(scene, 1e-13)
    assert motion.model.startswith("closed form straight shot")
    ref = reference_motion.reference(scene, digits=25)
    travel = float(mpmath.hypot(*ref.rest)) + scene.params.R
    error = math.hypot(motion.rest[0] - float(ref.rest[0]), motion.rest[1] - float(ref.rest[1])) / travel
    assert 1e-13 < error <= motion.error


def test_an_estimate_far_above_the_tolerance_warns_once_and_the_result_stands(tmp_path, capsys):
    """An audit: k = 0.002 R missed tol 1e-10 by 360× (estimate 5.7e-6) with nothing said but the estimate, on
    stderr or in Python.  Above TOL_WARNING × tol: a ToleranceWarning (one per batch, naming the scenes), one line
    from the command line; the bench's scenes (estimates below 20× tol) do not warn.  That ball now slides again
    (`engine.RERUN_SPIN_RATIO`: 0.49× tol, estimate 31×); here it starts 10⁸ m from the origin, where float64
    cannot hold its rest point within tol (half an ulp of 10⁸ m is 1,500× tol over its 4.9 cm of travel)."""
    import json
    import warnings

    from numerics import batch, validation
    from numerics.scene import Params, Scene, State, load
    from paper.cli import main

    stiff = Scene(Params(f=0.2, delta=1e-12, epsilon=0.0003, R=0.028575, k=5.715e-5),
                  State(1e8, 0, 0, 1e-6, 0, 50.0, 0))
    sample = load("numerics/scenes/sample.json")
    with pytest.warns(validation.ToleranceWarning, match=r"^the rest point's estimated relative error .* the tolerance "
                      r"asked \(1e-10\): the tolerance may be missed") as caught:
        motion = simulate(stiff)
    assert len(caught) == 1 and motion.error > validation.TOL_WARNING * 1e-10 and motion.rest is not None
    p, s, m = batch.scene_states([sample, stiff, sample, stiff])
    with pytest.warns(validation.ToleranceWarning, match=r"^2 scenes \(\[1\], \[3\]\) above 1000× the tolerance asked; "
                      r"the worst, scene \[1\]") as caught:
        batch.simulate_many(p, s, m)
    assert len(caught) == 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        simulate(sample)
        batch.simulate_many(p[:1], s[:1], m[:1])
    path = tmp_path / "stiff.json"
    path.write_text(json.dumps({"params": {"f": 0.2, "delta": 1e-12, "epsilon": 0.0003, "R": 0.028575, "k": 5.715e-5},
                                "state": {"xi": 1e8, "eta": 0, "vxi": 0, "veta": 1e-6, "p": 0, "q": 50, "r": 0}}))
    capsys.readouterr()
    assert main(["simulate", str(path)]) == 0
    out, err = capsys.readouterr()
    assert err.startswith("appell: warning: the rest point's estimated relative error") and err.count("\n") == 1
    assert "may be missed: the warning on stderr" in out
