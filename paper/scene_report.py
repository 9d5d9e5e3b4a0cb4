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


SHOWN_ERRORS = 20  # bad scenes listed one per line on stderr; the rest are counted


def _report_bad(errors: list, verb: str) -> None:
    import sys

    from numerics.validation import in_scene

    for index, error in errors[:SHOWN_ERRORS]:
        print(f"appell: {verb}: {in_scene(index, error)}", file=sys.stderr)
    if len(errors) > SHOWN_ERRORS:
        print(f"appell: {verb}: ... and {len(errors) - SHOWN_ERRORS} more bad scenes (--json --skip-bad lists every one)",
              file=sys.stderr)


def run_many(args, scenes) -> int:
    """`appell simulate` on many scenes (a `scene_files.SceneSet`): the batch path, a progress bar on long runs.

    Every bad scene is named, by index; by default any bad scene stops the run
    (exit 2) before work, with ``--skip-bad`` the good ones are simulated and
    the bad ones listed (in the JSON output as {"error": ...} in their place).
    """
    import json
    import os
    import sys
    import time

    import numpy as np

    from numerics import batch
    from numerics.validation import SceneError, in_scene

    if args.at or getattr(args, "samples", None):
        raise SceneError("--at/--samples", "states at given times are for single scenes; the batch path reports phases and rest")
    total = scenes.total
    errors = list(scenes.errors)
    if len(errors) == 1 and not args.skip_bad:
        index, error = errors[0]
        raise error.within(f"scene [{index}]")
    if errors and not args.skip_bad:
        _report_bad(errors, "error")
        raise SceneError(str(args.scene), f"{len(errors)} bad scenes of {total} (listed above; --skip-bad runs the good ones)")
    workers = args.workers or len(os.sched_getaffinity(0))
    show = total >= 50_000 and sys.stderr.isatty() or total >= 200_000
    done_before = [0]

    def progress(done, _):
        if show:
            n = done_before[0] + done
            bar = "#" * int(40 * n / total)
            print(f"\r[{bar:<40}] {n}/{total} scenes", end="", file=sys.stderr, flush=True)

    rows: list = [None] * total
    for i, error in errors:
        rows[i] = {"error": in_scene(i, error)}
    start = time.perf_counter()
    batch.warm_up()  # compile the right-hand sides from the derivation once, before forking
    setup = time.perf_counter() - start
    start = time.perf_counter()
    for group in scenes.groups:
        r = batch.simulate_many(group.params, group.states, group.model, args.tol, workers=workers, progress=progress,
                                skip_bad=args.skip_bad)
        done_before[0] += len(group.states)
        for k, i in enumerate(group.index):
            if not r.ok[k]:
                rows[i] = {"error": in_scene(int(i), r.errors[k])}
                errors.append((int(i), r.errors[k]))
                continue
            rest = r.rest[k]
            rows[i] = {
                "model": batch.MODEL_NAMES[r.model[k]],
                "t_slide_end": float(r.t_slide_end[k]),
                "t_roll_end": None if np.isnan(r.t_roll_end[k]) else float(r.t_roll_end[k]),
                "t_pivot_end": None if np.isnan(r.t_pivot_end[k]) else float(r.t_pivot_end[k]),
                "rest": None if np.isnan(rest[0]) else {"xi": float(rest[0]), "eta": float(rest[1])},
                "error_estimate": float(r.error[k]),
            }
    elapsed = max(time.perf_counter() - start, 1e-9)
    if show:
        print(file=sys.stderr)
    if errors:
        _report_bad(sorted(errors, key=lambda ie: ie[0]), "skipped")
    if args.json:
        print(json.dumps(rows, indent=1, ensure_ascii=False))
        return 0
    done = [row for row in rows if "error" not in row]
    counts: dict = {}
    for row in done:
        counts[row["model"]] = counts.get(row["model"], 0) + 1
    worst = max((row["error_estimate"] for row in done), default=0.0)
    lines = [
        f"{len(done)} scenes in {elapsed:.3g} s ({len(done) / elapsed:,.0f} scenes/s, {workers} processes), tol {args.tol:g}"
        f" (+ {setup:.2g} s compiling the equations from the derivation)"
        + (f"; {len(errors)} bad scenes skipped" if errors else "")
    ]
    lines += [f"  {n:>8}  {name}" for name, n in sorted(counts.items(), key=lambda kv: -kv[1])]
    lines.append(
        f"largest upper estimate of a rest point's relative error: {worst:.1e} (the error of the run at "
        f"{batch.COARSE:g}× the tolerance)"
    )
    print("\n".join(lines))
    return 0
