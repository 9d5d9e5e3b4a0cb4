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
    ``--json`` prints one object per scene in input order, with the keys of a
    single scene's (phases, times, rest, error estimate, states at its ``t``).
    """
    import json
    import os
    import sys
    import time

    from numerics import batch
    from numerics.scene import Scene, State
    from numerics.simulate import Motion, record
    from numerics.validation import SceneError, in_scene

    if args.at or getattr(args, "samples", None):
        raise SceneError("--at/--samples", "for a single scene; in a list, each scene gives its own times (its t)")
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

    def progress(done, _):
        if show:
            bar = "#" * int(40 * done / max(len(scenes.index), 1))
            print(f"\r[{bar:<40}] {done}/{len(scenes.index)} scenes", end="", file=sys.stderr, flush=True)

    rows: list = [None] * total
    for i, error in errors:
        rows[i] = {"error": in_scene(i, error)}
    start = time.perf_counter()
    result = None
    if len(scenes.index):
        result = batch.simulate_many(scenes.params, scenes.states, scenes.models, args.tol, workers=workers,
                                     progress=progress, skip_bad=True)
    elapsed = max(time.perf_counter() - start, 1e-9)
    if show:
        print(file=sys.stderr)
    for k, i in enumerate(scenes.index):
        i = int(i)
        if not result.ok[k]:
            rows[i] = {"error": in_scene(i, result.errors[k])}
            errors.append((i, result.errors[k]))
        elif scenes.times[k]:  # states at its times: this scene's own motion (its slide's dense output)
            params = scenes.params[k] if isinstance(scenes.params, list) else scenes.params
            scene = Scene(params, State(*scenes.states[k]), scenes.times[k], scenes.models[k])
            rows[i] = Motion(scene, args.tol, result.rows[k]).as_dict(scene.times)
        else:
            rows[i] = {**record(result.rows[k], scenes.models[k], args.tol), "states": []}
    if errors:
        _report_bad(sorted(errors, key=lambda ie: ie[0]), "skipped")
    if args.json:
        print(json.dumps(rows, indent=1, ensure_ascii=False))
        return 0
    done = [row for row in rows if "error" not in row]
    counts: dict = {}
    for row in done:
        name = row["phases"][0]["model"] if row["phases"][0]["phase"] == "sliding" else "none (no slip at the start)"
        counts[name] = counts.get(name, 0) + 1
    worst = max((row["error_estimate"] for row in done), default=0.0)
    lines = [
        f"{len(done)} scenes in {elapsed:.3g} s ({len(done) / elapsed:,.0f} scenes/s, {workers} threads), tol {args.tol:g}"
        + (f"; {len(errors)} bad scenes skipped" if errors else "")
    ]
    lines += [f"  {n:>8}  {name}" for name, n in sorted(counts.items(), key=lambda kv: -kv[1])]
    lines.append(f"largest upper estimate of a rest point's relative error: {worst:.1e}")
    print("\n".join(lines))
    return 0
