"""The readable summary `appell simulate` prints for one scene."""

from __future__ import annotations

from numerics.simulate import Motion


def _time(t) -> str:
    return "never" if t is None else f"{t:.9g} s"


def as_text(motion: Motion, times=()) -> str:
    P, s = motion.scene.params, motion.scene.state
    lines = [
        f"model {motion.scene.model}: f = {P.f:g}, delta = {P.delta:g} m, epsilon = {P.epsilon:g} m, "
        f"R = {P.R:g} m, k = {P.k:g} m, g = {P.g:g} m/s^2",
        f"start: xi = {s.xi:g}, eta = {s.eta:g} m; vxi = {s.vxi:g}, veta = {s.veta:g} m/s; "
        f"p = {s.p:g}, q = {s.q:g}, r = {s.r:g} rad/s",
        "",
        "phases:",
    ]
    for ph in motion.phases:
        end = "" if ph.phase == "rest" else f" to {_time(ph.t_end)}"
        error = f"  (est. rel. error {ph.error:.1e})" if ph.error else ""
        lines.append(f"  {ph.phase:<9} from {ph.t_start:.9g} s{end}: {ph.model}{error}")
    lines += [
        "",
        f"sliding ends   {_time(motion.t_slide_end)}",
        f"rolling ends   {_time(motion.t_roll_end)}",
        f"pivoting ends  {_time(motion.t_pivot_end)}",
        "rest point     " + ("none (rolls for ever: delta = 0)" if motion.rest is None
                            else f"xi = {motion.rest[0]:.10g} m, eta = {motion.rest[1]:.10g} m"),
        f"estimated relative error of the rest point: {motion.error:.1e} (tolerance asked {motion.tol:g})",
    ]
    if times:
        lines += ["", f"{'t (s)':>10} {'phase':<8} {'xi':>12} {'eta':>12} {'vxi':>11} {'veta':>11} {'p':>11} {'q':>11} {'r':>11}"]
        for t in times:
            b = motion.state_at(t)
            lines.append(
                f"{b.t:>10.6g} {b.phase:<8} {b.xi:>12.8g} {b.eta:>12.8g} {b.vxi:>11.6g} {b.veta:>11.6g} "
                f"{b.p:>11.6g} {b.q:>11.6g} {b.r:>11.6g}"
            )
    return "\n".join(lines)


def _params_from(path, UsageError):
    import json

    from numerics.scene import SceneError, parse

    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
    except OSError as error:
        raise UsageError(f"{path}: cannot read ({error.strerror})") from None
    except json.JSONDecodeError as error:
        raise UsageError(f"{path}: not valid JSON ({error.msg} at line {error.lineno})") from None
    zero = {name: 0.0 for name in STATE_COLUMNS}
    try:
        return parse({"params": data, "state": zero}).params
    except SceneError as error:
        raise UsageError(str(error)) from None


STATE_COLUMNS = ("xi", "eta", "vxi", "veta", "p", "q", "r")


def load_many(args, UsageError):
    """[(params, states array, model, indices into the input)] from a JSON list, .npz or .csv."""
    import json

    import numpy as np

    from numerics.scene import SceneError, parse

    path = str(args.scene)
    model = args.model or "appell"
    if path.endswith((".npz", ".csv")):
        if args.params is None:
            raise UsageError(f"{path}: states without params: give --params PARAMS.json")
        params = _params_from(args.params, UsageError)
        try:
            if path.endswith(".npz"):
                with np.load(path) as data:
                    if "states" not in data:
                        raise UsageError(f"{path}: no array 'states' (n rows of {', '.join(STATE_COLUMNS)})")
                    states = np.asarray(data["states"], dtype=float)
            else:
                with open(path, encoding="utf-8") as handle:
                    header = handle.readline().strip().split(",")
                if [h.strip() for h in header] != list(STATE_COLUMNS):
                    raise UsageError(f"{path}: the first line must be the header {','.join(STATE_COLUMNS)}")
                states = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        except (OSError, ValueError) as error:
            raise UsageError(f"{path}: cannot read states ({error})") from None
        if states.ndim != 2 or states.shape[1] != 7:
            raise UsageError(f"{path}: states must have 7 columns ({', '.join(STATE_COLUMNS)}), got shape {states.shape}")
        bad = np.argwhere(~np.isfinite(states))
        if len(bad):
            i, j = bad[0]
            raise UsageError(f"{path}: row {i}, {STATE_COLUMNS[j]}: must be finite, got {states[i, j]}")
        return [(params, states, model, np.arange(len(states)))], len(states)
    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
    except json.JSONDecodeError as error:
        raise UsageError(f"{path}: not valid JSON ({error.msg} at line {error.lineno})") from None
    groups: dict = {}
    for i, item in enumerate(data):
        try:
            scene = parse(item)
        except SceneError as error:
            raise UsageError(f"scene [{i}]: {error}") from None
        if scene.times:
            raise UsageError(f"scene [{i}].t: states at given times are for single scenes (the batch path reports phases and rest)")
        m = args.model or scene.model
        row = [getattr(scene.state, name) for name in STATE_COLUMNS]
        groups.setdefault((scene.params, m), []).append((i, row))
    return [(p, np.array([r for _, r in rows]), m, np.array([i for i, _ in rows])) for (p, m), rows in groups.items()], len(data)


def run_many(args, UsageError) -> int:
    """`appell simulate` on many scenes: the batch path, a progress bar on long runs."""
    import json
    import os
    import sys
    import time

    import numpy as np

    from numerics import batch

    if not batch.TOL_RANGE[0] <= args.tol <= batch.TOL_RANGE[1]:
        raise UsageError(f"--tol: must be between {batch.TOL_RANGE[0]:g} and {batch.TOL_RANGE[1]:g}, got {args.tol:g}")
    if args.at or getattr(args, "samples", None):
        raise UsageError("--at/--samples: states at given times are for single scenes; the batch path reports phases and rest")
    groups, total = load_many(args, UsageError)
    if total == 0:
        raise UsageError(f"{args.scene}: no scenes")
    workers = args.workers or len(os.sched_getaffinity(0))
    if workers < 1:
        raise UsageError(f"--workers: must be >= 1, got {workers}")
    show = total >= 50_000 and sys.stderr.isatty() or total >= 200_000
    done_before = [0]

    def progress(done, _):
        if show:
            n = done_before[0] + done
            bar = "#" * int(40 * n / total)
            print(f"\r[{bar:<40}] {n}/{total} scenes", end="", file=sys.stderr, flush=True)

    rows: list = [None] * total
    start = time.perf_counter()
    batch.warm_up()  # compile the right-hand sides from the derivation once, before forking
    setup = time.perf_counter() - start
    start = time.perf_counter()
    for params, states, model, index in groups:
        r = batch.simulate_many(params, states, model, args.tol, workers=workers, progress=progress)
        done_before[0] += len(states)
        for k, i in enumerate(index):
            rest = r.rest[k]
            rows[i] = {
                "model": batch.MODEL_NAMES[r.model[k]],
                "t_slide_end": float(r.t_slide_end[k]),
                "t_roll_end": None if np.isnan(r.t_roll_end[k]) else float(r.t_roll_end[k]),
                "t_pivot_end": None if np.isnan(r.t_pivot_end[k]) else float(r.t_pivot_end[k]),
                "rest": None if np.isnan(rest[0]) else {"xi": float(rest[0]), "eta": float(rest[1])},
                "error_estimate": float(r.error[k]),
            }
    elapsed = time.perf_counter() - start
    if show:
        print(file=sys.stderr)
    if args.json:
        print(json.dumps(rows, indent=1, ensure_ascii=False))
        return 0
    counts: dict = {}
    for row in rows:
        counts[row["model"]] = counts.get(row["model"], 0) + 1
    worst = max(row["error_estimate"] for row in rows)
    lines = [
        f"{total} scenes in {elapsed:.3g} s ({total / elapsed:,.0f} scenes/s, {workers} processes), tol {args.tol:g}"
        f" (+ {setup:.2g} s compiling the equations from the derivation)"
    ]
    lines += [f"  {n:>8}  {name}" for name, n in sorted(counts.items(), key=lambda kv: -kv[1])]
    lines.append(
        f"largest upper estimate of a rest point's relative error: {worst:.1e} (the error of the run at "
        f"{batch.COARSE:g}× the tolerance)"
    )
    print("\n".join(lines))
    return 0
