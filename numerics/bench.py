"""`appell bench`: speed against error for every way this package (or a user) can solve a scene.

Every method runs on the fixed scenes of `bench_set` and is scored against
their 40-digit mpmath reference: the worst relative error over the set of the
rest point (over its distance from the start + R), of the end of sliding (over the
motion's duration) and of Ω at the end of sliding (over the shot's spin
scale).  Time is wall-clock per scene: the median of several repeats, after
a warm-up run that is not counted.
"""

from __future__ import annotations

import math
import os
import platform
import statistics
import time
from dataclasses import dataclass, field

import mpmath
import numpy as np

from numerics import batch, bench_set, classical_vs_appell, engine, reference_motion, scipy_baseline
from numerics.scene import Params, Scene, State
from numerics.simulate import simulate


@dataclass
class Row:
    method: str
    setting: str
    seconds_per_scene: float
    max_rel_error: float  # the worst of the three below
    rest_error: float
    t_slide_error: float
    omega_error: float
    scenes: int  # scored scenes
    note: str = ""


@dataclass
class Report:
    rows: list = field(default_factory=list)
    scaling: list = field(default_factory=list)  # (batch size, seconds per scene)
    digits_scaling: list = field(default_factory=list)  # (digits, seconds per scene)
    calibration: list = field(default_factory=list)  # (tol, worst error / tol, least estimate / error, scenes)
    floor: list = field(default_factory=list)  # (batch size, seconds per scene of each call's slowest scene alone)
    lost: dict = field(default_factory=dict)  # `calls_of_ten_lost`: where calls of ten lose against a long batch
    machine: dict = field(default_factory=dict)


# --- scoring ------------------------------------------------------------------------------------


def _f(x):
    return None if x is None else float(mpmath.mpf(x))


def errors(scene: Scene, ref: dict, t_slide, omega_end, t_roll, rest) -> tuple[float, float, float]:
    """(rest, t_slide_end, Ω_end) relative errors of one result against the reference."""
    s = scene.state
    span = max(_f(ref["t_roll_end"]) or 0.0, _f(ref["t_slide_end"]), 1e-3)
    e_t = abs(t_slide - _f(ref["t_slide_end"])) / span
    spin = max(math.hypot(s.p, s.q), math.hypot(s.vxi, s.veta) / scene.params.R, 1.0)
    wp, wq = (_f(x) for x in ref["omega_end"])
    e_omega = math.hypot(omega_end[0] - wp, omega_end[1] - wq) / spin
    if ref["rest"] is None:
        e_rest = 0.0 if rest is None or not np.all(np.isfinite(rest)) else math.inf
    else:
        rx, ry = (_f(x) for x in ref["rest"])
        travel = math.hypot(rx - s.xi, ry - s.eta) + scene.params.R
        e_rest = math.hypot(rest[0] - rx, rest[1] - ry) / travel if rest is not None else math.inf
    return e_rest, e_t, e_omega


def _row(method, setting, seconds, errs, note="") -> Row:
    errs = list(errs)
    worst = [max(e[i] for e in errs) for i in range(3)]
    return Row(method, setting, seconds, max(worst), *worst, len(errs), note)


SCALING_SCENES = 1_000  # a batch size n below this is timed on these many scenes, in calls of n


def _median_time(fn, repeats: int) -> float:
    fn()  # warm-up: compiles the right-hand sides, fills caches
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


# --- methods ------------------------------------------------------------------------------------


def batch_errors(scenes: dict[str, Scene], refs: dict, tol: float, model=None) -> list[tuple]:
    """The errors of every scene of ``scenes`` solved in one `simulate_many` call, each with its own params."""
    names = list(scenes)
    params, states, models = batch.scene_states([scenes[n] for n in names])
    r = batch.simulate_many(params, states, model or models, tol)
    errs = []
    for i, n in enumerate(names):
        rest = r.rest[i] if np.all(np.isfinite(r.rest[i])) else None
        t_roll = r.t_roll_end[i] if np.isfinite(r.t_roll_end[i]) else None
        errs.append(errors(scenes[n], refs[n], r.t_slide_end[i], r.slide_end[i, 2:], t_roll, rest))
    return errs


def calibration(tols) -> list[tuple]:
    """Does the tolerance mean what it says, and is the error estimate above the error?  The batch on every
    bench scene and the 120 calibration shots (`bench_set.calibration_scenes`, 20-digit references):
    per tol, the worst of the rest point's and the end of sliding's errors over tol, and the least ratio of
    the reported estimate to the rest point's error over the numerical slides."""
    scenes = {**bench_set.scenes(), **bench_set.calibration_scenes()}
    refs = {**bench_set.references(), **bench_set.references(calibration=True)}
    names = list(scenes)
    params, states, models = batch.scene_states([scenes[n] for n in names])
    out = []
    for tol in tols:
        r = batch.simulate_many(params, states, models, tol)
        worst, least = 0.0, math.inf
        for i, n in enumerate(names):
            rest = r.rest[i] if np.all(np.isfinite(r.rest[i])) else None
            t_roll = r.t_roll_end[i] if np.isfinite(r.t_roll_end[i]) else None
            e_rest, e_t, _ = errors(scenes[n], refs[n], r.t_slide_end[i], r.slide_end[i, 2:], t_roll, rest)
            worst = max(worst, e_rest / tol, e_t / tol)
            if r.model[i] == batch.NUMERICAL and rest is not None and e_rest > 0:
                least = min(least, r.error[i] / e_rest)
        out.append((tol, worst, least, len(names)))
    return out


def timing_states(n: int) -> np.ndarray:
    """n general shots (pool ball): the seeded random shots and the realistic ones, repeated."""
    pool = np.vstack([bench_set.random_states(64, seed=bench_set.SEED + 1)] +
                     [[[s.xi, s.eta, s.vxi, s.veta, s.p, s.q, s.r] for s in classical_vs_appell.SHOTS.values()]])
    return pool[np.arange(n) % len(pool)]


def curved(scenes: dict[str, Scene]) -> dict[str, Scene]:
    """The scenes whose slide is integrated (the others are closed forms for every method): what is timed."""
    return {n: s for n, s in scenes.items() if simulate(s, 1e-9).model.startswith("numerical")}


def _tiled(scenes: dict[str, Scene], n: int):
    """n scenes cycling through ``scenes``: (params list, states array), each scene with its own parameters."""
    chosen = [list(scenes.values())[i % len(scenes)] for i in range(n)]
    return [s.params for s in chosen], np.array([s.state.row() for s in chosen])


def _per_call(fn, items, repeats: int) -> float:
    """Median over ``repeats`` of the mean wall time of fn(item) over ``items`` (after one warm-up pass)."""
    return _median_time(lambda: [fn(x) for x in items], repeats) / len(items)


def _score(fn, names, scenes, refs) -> list:
    out = []
    for n in names:
        r = fn(scenes[n])
        out.append(errors(scenes[n], refs[n], r["t_slide_end"], r["omega_end"], r["t_roll_end"], r["rest"]))
    return out


def _motion_answer(m) -> dict:
    end = m.state_at(m.t_slide_end)
    return {"t_slide_end": m.t_slide_end, "omega_end": (end.p, end.q), "t_roll_end": m.t_roll_end, "rest": m.rest}


def run(quick: bool = False, progress=print) -> Report:
    from numerics import heyoka_baseline, simulate as simulate_module

    scenes, refs = bench_set.scenes(), bench_set.references(progress=lambda n: progress(f"  reference computed: {n}"))
    slides = curved(scenes)
    cores = len(os.sched_getaffinity(0))
    report = Report(machine={
        "cores": cores, "cpu": cpu_name(), "python": platform.python_version(), "numpy": np.__version__, "quick": quick,
        "scenes": len(scenes), "curved scenes (timed)": len(slides), "versions": peer_versions(),
    })
    repeats = 3 if quick else 5
    n_time = 5_000 if quick else 50_000
    params, states = _tiled(slides, n_time)
    tols = [1e-6, 1e-9, 1e-12] if quick else [1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]

    # The compiled engine loads at its first call and, on a copy's first run, compiles (a minute, silent before).
    progress("loading the compiled engine (compiling it, on this copy's first run, takes about a minute)")
    start = time.perf_counter()
    batch.simulate_many(params[:1], states[:1])
    progress(f"  loaded in {time.perf_counter() - start:.1f} s")
    progress(f"batch (compiled engine, {cores} threads)")
    for tol in tols:
        errs = batch_errors(scenes, refs, tol)
        seconds = _median_time(lambda: batch.simulate_many(params, states, tol=tol).rest, repeats) / n_time
        report.rows.append(_row("batch", f"tol {tol:.0e}", seconds, errs, f"{n_time} curved scenes, {cores} threads"))
        progress(f"  tol {tol:.0e}: {seconds * 1e6:.2f} µs/scene")
    # On one thread too, as heyoka's batch mode is timed: the comparison at equal cores.
    errs = batch_errors(scenes, refs, 1e-9)
    seconds = _median_time(lambda: batch.simulate_many(params, states, tol=1e-9, workers=1).rest, repeats) / n_time
    report.rows.append(_row("batch, 1 thread", "tol 1e-09", seconds, errs, f"{n_time} curved scenes, 1 thread"))
    progress(f"  one thread, tol 1e-09: {seconds * 1e6:.2f} µs/scene")

    progress("simulate (the public API, one scene per call)")
    for tol in ([1e-9] if quick else [1e-6, 1e-9, 1e-12]):
        errs = _score(lambda s: _motion_answer(simulate(s, tol)), scenes, scenes, refs)
        seconds = _per_call(lambda s: simulate(s, tol), list(slides.values()), repeats)
        report.rows.append(_row("simulate", f"tol {tol:.0e}", seconds, errs, "compiled, one scene per call"))
        progress(f"  tol {tol:.0e}: {seconds * 1e6:.1f} µs/scene")
    seconds = _per_call(lambda s: simulate(s, 1e-9, jit=False), list(slides.values())[:8], 1)
    errs = _score(lambda s: _motion_answer(simulate(s, 1e-9, jit=False)), slides, scenes, refs)
    report.rows.append(_row("simulate, interpreted", "tol 1e-09", seconds, errs, "jit=False: no compilation (the CLI's single scene)"))

    progress("tolerance calibration: the bench scenes and 120 more fast shots")
    report.calibration = calibration(tols)

    progress("states inside a slide (dense output), against 20-digit reference states")
    report.rows.append(dense_row(scenes, repeats))
    report.rows.append(stiff_dense_row(repeats))

    if scipy_baseline.available():
        for method in ("DOP853", "LSODA"):
            progress(f"scipy solve_ivp {method}")
            # LSODA below rtol 1e-12 creeps towards V = 0 (α' ∝ V^(κ−1) there) for minutes, using GBs.
            finest = 1e-13 if method == "DOP853" else 1e-12
            for rtol in ([1e-8, 1e-12] if quick else sorted({1e-6, 1e-8, 1e-10, 1e-12, finest}, reverse=True)):
                solve = lambda s, rtol=rtol, method=method: scipy_baseline.solve(s, method, rtol)  # noqa: E731
                errs = _score(solve, slides, scenes, refs)
                seconds = _per_call(solve, list(slides.values())[: 8 if quick else len(slides)], 1)
                report.rows.append(_row(f"scipy {method}", f"rtol {rtol:.0e}", seconds, errs, "one scene per call"))
    else:
        progress("scipy not installed (pip install '.[bench]'): its rows are skipped")

    if heyoka_baseline.available():
        progress("heyoka (Taylor, LLVM): scalar and batch mode")
        for tol in ([1e-10, 1e-14] if quick else [1e-8, 1e-10, 1e-12, 1e-14]):
            errs = _score(lambda s, tol=tol: heyoka_baseline.solve(s, tol), slides, scenes, refs)
            seconds = _per_call(lambda s, tol=tol: heyoka_baseline.solve(s, tol), list(slides.values()), repeats)
            report.rows.append(_row("heyoka", f"tol {tol:.0e}", seconds, errs, "scalar mode, one scene per call"))
            group = list(slides.values()) * (4 if quick else 20)
            seconds = _median_time(lambda tol=tol: heyoka_baseline.solve_batch(group, tol), repeats) / len(group)
            report.rows.append(_row("heyoka batch", f"tol {tol:.0e}", seconds, errs, "batch mode, SIMD-wide groups, 1 thread"))
    else:
        progress("heyoka not installed (pip install '.[bench]'): its rows are skipped")

    progress("mpmath reference (Taylor integrator)")
    subset = ["hard: sample"] if quick else ["hard: sample", "hard: draw, little side spin", "random 00"]
    for digits in ([15] if quick else [15, 30, 50]):
        errs, times = [], []
        for name in subset:
            start = time.perf_counter()
            ref = reference_motion.reference(scenes[name], digits=digits)
            times.append(time.perf_counter() - start)
            end = ref.slide_end
            errs.append(errors(
                scenes[name], refs[name], float(ref.t_slide_end), (float(end.p), float(end.q)),
                None if ref.t_roll_end is None else float(ref.t_roll_end),
                None if ref.rest is None else (float(ref.rest[0]), float(ref.rest[1])),
            ))
        note = f"{len(subset)} scenes; errors below 1e-16 are float64 rounding of the comparison"
        report.rows.append(_row("mpmath", f"{digits} digits", statistics.median(times), errs, note))
        report.digits_scaling.append((digits, statistics.median(times)))

    progress("classical model (no rolling couple while sliding), against Appell's reference")
    errs = batch_errors(scenes, refs, 1e-9, model="classical")
    seconds = _median_time(lambda: batch.simulate_many(params, states, "classical").rest, repeats) / n_time
    report.rows.append(_row("classical model", "closed forms", seconds, errs, "its error is the model's, not the arithmetic's"))

    progress("scaling with batch size")
    report.scaling += scaling(slides, [1, 10, 100, 1_000, 10_000] + ([] if quick else [100_000, 1_000_000]), repeats,
                              progress)

    report.floor.append((10, slowest_alone(slides, 10, repeats)))
    progress("where calls of 10 lose against a long batch: the engine alone, the Python layer, blocks of lanes")
    report.lost = calls_of_ten_lost(slides, repeats)
    report.machine.update(start_costs(simulate_module))
    return report


def slowest_alone(slides: dict[str, Scene], n: int, repeats: int) -> float:
    """Seconds per scene of `scaling`'s calls of n, each replaced by a call on its slowest scene alone: a floor
    for any batch that takes each scene's steps one after the other (a call ends when its slowest scene does)."""
    p_all, s_all = _tiled(slides, len(slides))
    alone = [_median_time(lambda: [batch.simulate_many(p_all[i : i + 1], s_all[i : i + 1], tol=1e-9).rest
                                   for _ in range(20)], repeats) / 20 for i in range(len(slides))]
    total = max(n, SCALING_SCENES)
    cycle = [alone[i % len(slides)] for i in range(total)]  # `_tiled`'s order
    return sum(max(cycle[a : a + n]) for a in range(0, total, n)) / total


BLOCK_WIDTHS = (4, 8, 12, 32)  # blocks of lanes timed by `calls_of_ten_lost` (a call of ten fills one of 12)


def calls_of_ten_lost(slides: dict[str, Scene], repeats: int) -> dict:
    """Where `scaling`'s calls of ten lose against one long batch, one thread, tol 1e-9, on its mix of scenes:

    - ``engine_calls_of_10``, ``engine_one_call``: seconds per scene of the compiled lanes' ``solve_many`` alone
      (no checks, no result object) in calls of ten and in one call of them all;
    - ``python_per_call_of_10``: what `simulate_many` (one thread) adds to a call of ten, in seconds;
    - ``median_steps``, ``step_alone``, ``block_steps``: the median slide's steps (accepted and rejected), the
      seconds of one of them alone, and a lane's share of one in a block of w copies of it (w: BLOCK_WIDTHS), each
      copy ending with the others: what lanes save before the tail of a call narrows its block."""
    run = batch.engine_for(None)
    solve_many = batch.lanes_solver(run)
    total, tol = SCALING_SCENES, 1e-9
    p_all, s_all = _tiled(slides, total)
    table = batch.params_table(p_all, total)
    classical = batch.classical_flags("appell", total)
    out = np.empty((total, engine.N_OUT))

    def engine_calls(n):
        for a in range(0, total, n):
            solve_many(table[a : a + n], s_all[a : a + n], classical[a : a + n], tol, out[a : a + n])

    def api_calls(n):
        for a in range(0, total, n):
            batch.simulate_many(p_all[a : a + n], s_all[a : a + n], tol=tol, workers=1).rest

    engine_10 = _median_time(lambda: engine_calls(10), repeats) / total
    engine_long = _median_time(lambda: engine_calls(total), repeats) / total
    api_10 = _median_time(lambda: api_calls(10), repeats) / total
    engine_calls(total)
    steps = out[: len(slides), engine.OUT_STEPS] + out[: len(slides), engine.OUT_REJECTED]  # `_tiled`'s first cycle
    median = int(np.argsort(steps)[len(steps) // 2])
    n_steps = int(steps[median])

    def block(w):
        rows = slice(median, median + 1)
        P, S, C = np.repeat(table[rows], w, 0), np.repeat(s_all[rows], w, 0), np.repeat(classical[rows], w, 0)
        O = np.empty((w, engine.N_OUT))
        return _median_time(lambda: [solve_many(P, S, C, tol, O) for _ in range(20)], repeats) / 20 / (w * n_steps)

    return {"engine_calls_of_10": engine_10, "engine_one_call": engine_long,
            "python_per_call_of_10": (api_10 - engine_10) * 10, "median_steps": n_steps,
            "step_alone": block(1), "block_steps": {w: block(w) for w in BLOCK_WIDTHS}}


def scaling(slides: dict[str, Scene], sizes, repeats: int, progress=print) -> list[tuple[int, float]]:
    """(n, seconds per scene) at tol 1e-9 for each batch size n: the same mix of scenes at every size, at least
    SCALING_SCENES of them, in calls of n (the first n scenes alone would be another mix).  Every batch timed here
    has its rest points read, as a user would: a `BatchResult`'s arrays are built when first read."""
    out = []
    for n in sizes:
        total = max(n, SCALING_SCENES)
        p_all, s_all = _tiled(slides, total)
        calls = [(p_all[a : a + n], s_all[a : a + n]) for a in range(0, total, n)]
        seconds = _median_time(lambda: [batch.simulate_many(p, s, tol=1e-9).rest for p, s in calls],
                               1 if total >= 100_000 else repeats)
        out.append((n, seconds / total))
        progress(f"  {n}: {seconds / total * 1e6:.2f} µs/scene")
    return out


DENSE_SCENES = ("hard: sample", "fast 03", "random 05")  # curved slides: a slow one, a fast one, a general one
DENSE_FRACTIONS = (0.013, 0.31, 0.77, 0.999)  # where in the slide the states are asked


def dense_errors(scene: Scene, motion, fractions=DENSE_FRACTIONS) -> list[tuple[float, float, float]]:
    """The states of ``motion`` at these fractions of its slide against the mpmath reference states (20 digits):
    per state (t, position error over the travel, Ω error over the spin scale), measured as the rest point is."""
    ts = [motion.t_slide_end * x for x in fractions]
    ref = reference_motion.reference(scene, digits=20, times=ts)
    got = motion.states(ts)
    s, R = scene.state, scene.params.R
    travel = math.hypot(motion.rest[0] - s.xi, motion.rest[1] - s.eta) + R
    spin = max(math.hypot(s.p, s.q), math.hypot(s.vxi, s.veta) / R, 1.0)
    out = []
    for i, t in enumerate(ts):
        xi, eta, p, q = (float(x) for x in ref.states[mpmath.mpf(t)])
        out.append((t, math.hypot(got.xi[i] - xi, got.eta[i] - eta) / travel, math.hypot(got.p[i] - p, got.q[i] - q) / spin))
    return out


def midpoints(motion) -> np.ndarray:
    """The time midway in each step of ``motion``'s numerical slide (the last ending at the end of sliding)."""
    nodes = np.append(motion._dense_output()[:, 2 + engine.T], motion.t_slide_end)
    return (nodes[:-1] + nodes[1:]) / 2


def dense_midway(scene: Scene, motion) -> list[tuple[float, float, float]]:
    """`dense_errors` midway between every two steps of ``motion``'s numerical slide, where its interpolant is
    furthest from the steps (they are what the error estimates check)."""
    return dense_errors(scene, motion, midpoints(motion) / motion.t_slide_end)


def dense_row(scenes: dict[str, Scene], repeats: int, tol: float = 1e-9) -> Row:
    """`Motion.states` inside curved slides: time per state (10,000 times in one call, the slide solved
    before) and the error of four states per scene (`dense_errors`): position over the travel (in the
    rest-point column), Ω over the spin scale (in the Ω column)."""
    errs, per_state = [], []
    for name in DENSE_SCENES:
        motion = simulate(scenes[name], tol)
        errs += [(position, 0.0, spin) for _, position, spin in dense_errors(scenes[name], motion)]
        many = np.linspace(0.0, motion.t_slide_end, 10_000)
        per_state.append(_median_time(lambda: motion.states(many), repeats) / len(many))
    return _row("states (dense output)", f"tol {tol:.0e}", max(per_state), errs,
                f"time per state, 10,000 in one call; {len(errs)} states of {len(DENSE_SCENES)} slides scored")


def near_fR(fraction: float) -> Scene:
    """An audit's shot with δ = fraction × fR (f 0.2, 2 m/s, Ω (30, −100) rad/s): near fR its slide is stiff."""
    R = 0.028575
    return Scene(Params(f=0.2, delta=fraction * 0.2 * R, epsilon=0.0003, R=R), State(0.0, 0.0, 2.0, 0.0, 30.0, -100.0, 5.0), ())


def stiff_dense_row(repeats: int, tol: float = 1e-9, fraction: float = 0.999) -> Row:
    """`Motion.states` midway inside the stiff steps of a slide near δ = fR, where they are integrated to in
    substeps (`engine.DENSE_STIFF`): time per state (10,000 in one call) and the error of each (`dense_errors`)."""
    scene = near_fR(fraction)
    motion = simulate(scene, tol)
    rows = motion._dense_output()
    stiff = np.flatnonzero(rows[:, engine.DENSE_STIFFNESS] > engine.DENSE_STIFF)
    midway = midpoints(motion)[stiff]
    errs = [(position, 0.0, spin) for _, position, spin in dense_errors(scene, motion, midway / motion.t_slide_end)]
    many = np.resize(midway, 10_000)
    seconds = _median_time(lambda: motion.states(many), repeats) / len(many)
    return _row("states in stiff steps", f"tol {tol:.0e}", seconds, errs,
                f"δ = {fraction} fR: midway in its {len(stiff)} stiff steps of {len(rows)}, integrated to in substeps")


def start_costs(simulate_module) -> dict:
    """Seconds of: `appell simulate` on the sample scene from a cold start, `python -c "import numpy"` beside it,
    and the compilation of the engine into an empty cache (a copy's first run: `compiled.copy_folder`)."""
    import subprocess
    import sys
    import tempfile
    from pathlib import Path

    sample = Path(__file__).with_name("scenes") / "sample.json"

    def wall(argv, env=None) -> float:
        start = time.perf_counter()
        subprocess.run(argv, check=True, capture_output=True, env=env)
        return time.perf_counter() - start

    cli = min(wall([sys.executable, "-m", "paper", "simulate", str(sample)]) for _ in range(3))
    numpy_import = min(wall([sys.executable, "-c", "import numpy"]) for _ in range(3))
    with tempfile.TemporaryDirectory() as empty:
        env = {**os.environ, "APPELL_CACHE": empty, "APPELL_NUMBA_CACHE": empty}  # nothing compiled yet
        code = ("from numerics.simulate import simulate; from numerics.batch import simulate_many; "
                "from numerics.scene import load; s = load(%r); simulate(s).state_at(0.01); "
                "simulate_many(s.params, [s.state.row()])" % str(sample))  # all three entry points compiled
        first_compile = wall([sys.executable, "-c", code], env)
    return {"cold simulate (s)": round(cli, 3), "import numpy (s)": round(numpy_import, 3),
            "first-ever compile (s)": round(first_compile, 1)}


PEERS = ("numba", "scipy", "heyoka")  # the compiler of our engine and the peers timed against it


def peer_versions() -> dict[str, str]:
    """The installed versions of `PEERS` (those installed): times depend on them as much as on the machine."""
    from importlib import metadata

    versions = {}
    for name in PEERS:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            pass
    return versions


def versions_text(machine: dict) -> str:
    """"numba 0.68.1, scipy 1.17.1, heyoka 7.13.2" as a run recorded them; "" for a run that did not."""
    return ", ".join(f"{name} {version}" for name, version in machine.get("versions", {}).items())


def cpu_name() -> str:
    """The processor's model name (Linux), for the record of a measurement."""
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


# --- output -------------------------------------------------------------------------------------


def as_text(report: Report) -> str:
    m = report.machine
    versions = versions_text(m)
    lines = [
        f"{m['cpu']}, {m['cores']} cores; Python {m['python']}, NumPy {m['numpy']}"
        + (f", {versions}" if versions else "") + f"; source {m.get('source', 'not recorded')}"
        + (" (--quick)" if m["quick"] else ""),
        "",
        "| method | setting | time per scene | max rel. error | rest point | end of sliding | Ω at end | note |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in report.rows:
        lines.append(
            f"| {r.method} | {r.setting} | {_duration(r.seconds_per_scene)} | {r.max_rel_error:.1e} | {r.rest_error:.1e} "
            f"| {r.t_slide_error:.1e} | {r.omega_error:.1e} | {r.note} |"
        )
    lines += ["", f"Batch size against time per scene (tol 1e-9; below {SCALING_SCENES:,} scenes, the same {SCALING_SCENES:,} "
              f"in calls of n; one thread below {batch.SERIAL_BELOW} scenes a call):", ""]
    lines += [f"  {n:>9}  {_duration(s)}  ({1 / s:,.0f} scenes/s)" for n, s in report.scaling]
    lines += [f"  (calls of {n} on their slowest scene alone: {_duration(s)} a scene)" for n, s in report.floor]
    if report.lost:
        lost = report.lost
        blocks = ", ".join(f"{w} {_duration(s)}" for w, s in lost["block_steps"].items())
        lines += [f"  Where calls of 10 lose against a long batch (one thread, the compiled lanes alone): calls of 10 "
                  f"{_duration(lost['engine_calls_of_10'])} a scene,",
                  f"    one call of {SCALING_SCENES:,} {_duration(lost['engine_one_call'])} "
                  f"({lost['engine_calls_of_10'] / lost['engine_one_call']:.2f}×); simulate_many adds "
                  f"{_duration(lost['python_per_call_of_10'])} a call of 10;",
                  f"    a step of the median slide ({lost['median_steps']} steps) alone {_duration(lost['step_alone'])}, "
                  f"a lane's share in a block of w copies: {blocks}"]
    if report.digits_scaling:
        lines += ["", "mpmath time per scene against digits:", ""]
        lines += [f"  {d:>3} digits  {_duration(s)}" for d, s in report.digits_scaling]
    if report.calibration:
        lines += ["", f"Tolerance calibration (batch, {report.calibration[0][3]} scenes: the bench's and 120 fast shots):", "",
                  "| tol | worst error / tol | least estimate / error |", "|---|---|---|"]
        lines += [f"| {tol:.0e} | {worst:.2f} | {least:.2f} |" for tol, worst, least, _ in report.calibration]
    if "cold simulate (s)" in m:
        lines += ["", f"Cold `appell simulate` of the sample scene: {m['cold simulate (s)']} s (`python -c \"import numpy\"`: "
                  f"{m['import numpy (s)']} s); the engine's compilation into an empty cache: {m['first-ever compile (s)']} s."]
    lines += ["", "Goals (each method at its fastest setting whose rest point and end of sliding are within 1e-9):", ""]
    lines += goals(report)
    return "\n".join(lines)


def _fastest_within(report: Report, method: str, limit: float = 1e-9):
    rows = [r for r in report.rows if r.method == method and r.rest_error <= limit and r.t_slide_error <= limit]
    return min(rows, key=lambda r: r.seconds_per_scene) if rows else None


def goals(report: Report) -> list[str]:
    """The goals of the numerics issue, measured: ratios to scipy's DOP853 and to heyoka, at 1e-9."""
    out = []
    scipy, single, many = (_fastest_within(report, m) for m in ("scipy DOP853", "simulate", "batch"))
    hey, hey_batch = _fastest_within(report, "heyoka"), _fastest_within(report, "heyoka batch")
    if scipy is None:
        return ["  scipy DOP853: not run, or never within 1e-9 (install the bench extra)"]
    for row, goal, what in ((single, 300, "one scene per call (simulate)"), (many, 2000, "batch")):
        if row is None:
            out.append(f"  {what}: never within 1e-9")
            continue
        ratio = scipy.seconds_per_scene / row.seconds_per_scene
        out.append(f"  {what}: {_duration(row.seconds_per_scene)} at {row.setting}, {ratio:,.0f}× faster than scipy DOP853 "
                   f"at {scipy.setting}; goal {goal}×: " + ("met" if ratio >= goal else "not met"))
    one_thread = _fastest_within(report, "batch, 1 thread")
    for row, peer, what in ((single, hey, "heyoka scalar"), (many, hey_batch, "heyoka batch mode"),
                            (one_thread, hey_batch, "heyoka batch mode, both on one thread")):
        if row is not None and peer is not None:
            ratio = peer.seconds_per_scene / row.seconds_per_scene
            out.append(f"  against {what} ({_duration(peer.seconds_per_scene)} at {peer.setting}): {ratio:.2f}× "
                       + ("ahead" if ratio > 1 else "behind"))
    if report.calibration:
        worst = max(w for _, w, _, _ in report.calibration)
        least = min(e for _, _, e, _ in report.calibration)
        out.append(f"  tolerance: worst error {worst:.2f} × tol over {report.calibration[0][3]} scenes and every tol — "
                   + ("within" if worst <= 1 else "NOT within") + f"; the estimate at least {least:.2f} × the error — "
                   + ("above it" if least >= 1 else "NOT always above it"))
    dense = next((r for r in report.rows if r.method == "states (dense output)"), None)
    if dense is not None:
        out.append(f"  states inside a slide: {_duration(dense.seconds_per_scene)} per state, within {dense.max_rel_error:.1e} "
                   "of the reference; goal 5 µs: " + ("met" if dense.seconds_per_scene <= 5e-6 else "not met"))
    stiff = next((r for r in report.rows if r.method == "states in stiff steps"), None)
    if stiff is not None:
        out.append(f"  states inside stiff steps (near δ = fR): {_duration(stiff.seconds_per_scene)} per state, within "
                   f"{stiff.max_rel_error:.1e} of the reference; goal 5 µs: " + ("met" if stiff.seconds_per_scene <= 5e-6 else "not met"))
    if report.scaling:
        flat = [s for n, s in report.scaling if n >= 10]
        line = (f"  batch cost per scene from n = 10 up: {_duration(min(flat))} to {_duration(max(flat))} "
                f"({max(flat) / min(flat):.2f}×; one thread below {batch.SERIAL_BELOW} scenes a call)")
        # Ten scenes a call run on one thread: against a long batch on one thread too, the part threads play is out.
        alone = next((r for r in report.rows if r.method == "batch, 1 thread" and r.setting == "tol 1e-09"), None)
        ten = dict(report.scaling).get(10)
        if alone is not None and ten is not None:
            line += (f"; n = 10 against a long batch on one thread ({_duration(alone.seconds_per_scene)}): "
                     f"{ten / alone.seconds_per_scene:.2f}×")
        floor = dict(report.floor).get(10)
        if floor is not None:
            line += (f"; a call of 10 is no faster than its slowest scene alone: {_duration(floor)} a scene, "
                     f"{floor / min(flat):.2f}× the cheapest")
        out.append(line)
    return out


def _duration(seconds: float) -> str:
    for unit, scale in (("s", 1), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds:.2e} s"


def from_json(data: dict) -> Report:
    """The report `as_json` wrote (`appell bench --saved` prints the saved run without measuring again)."""
    return Report(
        rows=[Row(**r) for r in data["rows"]],
        scaling=[(s["batch_size"], s["seconds_per_scene"]) for s in data["scaling"]],
        digits_scaling=[(d["digits"], d["seconds_per_scene"]) for d in data["mpmath_digits"]],
        calibration=[(c["tol"], c["worst_error_over_tol"], c["least_estimate_over_error"], c["scenes"])
                     for c in data["calibration"]],
        floor=[(s["batch_size"], s["seconds_per_scene"]) for s in data["slowest_alone"]],
        lost=_lost_from_json(data.get("calls_of_ten_lost", {})),
        machine=data["machine"],
    )


def _lost_from_json(lost: dict) -> dict:
    """`calls_of_ten_lost` as JSON wrote it (its block widths became strings); {} in a report saved before it."""
    return {**lost, "block_steps": {int(w): s for w, s in lost["block_steps"].items()}} if lost else {}


def as_json(report: Report) -> dict:
    from dataclasses import asdict

    return {
        "rows": [asdict(r) for r in report.rows],
        "scaling": [{"batch_size": n, "seconds_per_scene": s} for n, s in report.scaling],
        "slowest_alone": [{"batch_size": n, "seconds_per_scene": s} for n, s in report.floor],
        "calls_of_ten_lost": report.lost,
        "mpmath_digits": [{"digits": d, "seconds_per_scene": s} for d, s in report.digits_scaling],
        "calibration": [{"tol": t, "worst_error_over_tol": w, "least_estimate_over_error": e, "scenes": n}
                        for t, w, e, n in report.calibration],
        "machine": report.machine,
        "goals": goals(report),
    }
