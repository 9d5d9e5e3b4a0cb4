"""What `appell simulate` prints and writes: one scene's summary, many scenes' text, JSON and tables."""

from __future__ import annotations

import math
import sys
import warnings

import numpy as np

from numerics import engine, validation
from numerics.scene import shown_name
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
        # A user audit read 1.8e-10 against 1e-10 as a tolerance missed: the estimate is pessimistic by design.
        # (No rest point, no estimate of one: an audit read 0.0e+00 under "rest point none".)
        "estimated relative error of the rest point: " + (f"none (no rest point; tolerance asked {motion.tol:g})" if motion.rest is None else
        f"{motion.error:.1e} (tolerance asked {motion.tol:g}; " + ("may be missed: the warning on stderr)"
        if validation.beyond_tolerance(motion.error, motion.tol) else "the estimate errs on the safe side: README, 'Error estimates')")),
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


def times_asked(args, own: int, scenes: int = 1) -> list[float]:
    """--at's times, checked, before any work: each >= 0 and far inside float64 (a scene's own t is bounded by its
    motion too), and, with the scenes' own times (``own`` in all) and --samples' N + 1 a scene, at most
    `MAX_TIMES` states in all: --at and --samples add to every one of the ``scenes``."""
    from numerics.scene import MAX_TIMES
    from numerics.validation import SCALE_LIMIT, SceneError

    at = [float(t) for t in args.at or []]
    for t in at:
        if not (t >= 0 and t < SCALE_LIMIT):
            raise SceneError("--at", f"times must be >= 0 and below {SCALE_LIMIT:g} s, got {t}")
    room = MAX_TIMES - own - scenes * len(at)
    if room < 0:
        raise SceneError("--at", f"at most {MAX_TIMES:,} times with the scene's, got {MAX_TIMES - room:,}")
    samples = getattr(args, "samples", None)
    if samples is not None and not 1 <= samples < room // scenes:
        many = f", N + 1 for each of {scenes:,} scenes" if scenes > 1 else ""
        raise SceneError("--samples", f"must be >= 1 and < {room // scenes:,} (at most {MAX_TIMES:,} states in all: the "
                         f"scenes' own times, --at's{many}), got {samples}")
    return at


def check_at(params, states, at: list, index=None) -> None:
    """--at's latest time within reach of each scene's motion (float64 holds its state then), checked before any
    work with the bound a scene's own t meets (`scene.unrepresentable`; a review: --at 9e99 with δ = 0 printed a
    state 1e101 m away).  ``params``: one `Params` or the batch's table; ``index``: each scene's place in its
    list, named in the error."""
    from numerics.scene import unrepresentable
    from numerics.validation import SceneError, scale_error

    if not at:
        return
    for k, reason in enumerate(unrepresentable(params, states, max(at))):
        if reason:
            where = "" if index is None else f"scene [{int(index[k])}]: "
            raise SceneError("--at", where + scale_error(*reason).rule)


def report_times(motion: Motion, own, at: list, samples: int | None) -> list[float]:
    """The times a scene's states are reported at: its own ``t`` as given, or, with --at or --samples (N + 1 from 0
    to rest), all of them in time order (the samples came after the others, unsorted: a user audit)."""
    if not at and samples is None:
        return list(own)
    times = list(own) + list(at)
    if samples is not None:
        times += [b.t for b in motion.samples(samples)]
    return sorted(times)


PROGRESS_FROM = 10_000  # scenes: fewer take well under a second, no bar
PROGRESS_EVERY = 1_000  # scenes written as JSON between two updates of the bar
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
    (exit 2) before work, and a scene whose computation fails (`ComputationError`)
    exits 1 after it; with ``--skip-bad`` the good ones are simulated and the
    bad or failed ones listed (in the JSON output as {"error": ...} in their place).
    ``--json`` prints one object per scene in input order, with the keys of a
    single scene's (phases, times, rest, error estimate, states at its ``t``).
    """
    import json
    import time

    from numerics import batch
    from numerics.scene import Scene, State
    from numerics.simulate import Motion, record
    from numerics.validation import ComputationError, SceneError, in_scene
    from paper.progress import Progress

    samples = getattr(args, "samples", None)
    if (args.at or samples is not None) and not args.json:
        raise SceneError("--at/--samples", "many scenes report their states with --json only (one object a scene)")
    total = scenes.total  # (every scene's t together is bounded where the list is read: `scene_files`)
    own = sum(len(t) for t in scenes.times)
    at = times_asked(args, own, max(len(scenes.index), 1))
    if at and len(scenes.index):  # (no good scene: its errors follow)
        check_at(batch.params_table(scenes.params, len(scenes.index)), scenes.states, at, scenes.index)
    errors = list(scenes.errors)
    if len(errors) == 1 and not args.skip_bad:
        index, error = errors[0]
        raise error.within(f"scene [{index}]")
    if errors and not args.skip_bad:
        _report_bad(errors, "error")
        raise SceneError(shown_name(args.scene), f"{len(errors)} bad scenes of {total} (listed above; --skip-bad runs the good ones)")
    # A bar only where it helps: a terminal, not --quiet, and enough scenes to take a while.
    bar = Progress(len(scenes.index), "scenes", args.quiet or len(scenes.index) < PROGRESS_FROM)

    rows: list = [None] * total  # for --json: each scene's object, encoded, in input order
    for i, error in errors:
        rows[i] = json.dumps({"error": in_scene(i, error)}, ensure_ascii=False)
    load = 0.0
    if len(scenes.index):  # the compiled engine loads (or, the first time ever, compiles) at its first call: timed apart
        first = scenes.params_of(0)
        start = time.perf_counter()
        with warnings.catch_warnings():  # the batch below warns of it, once
            warnings.simplefilter("ignore", validation.ToleranceWarning)
            batch.simulate_many(first, scenes.states[:1], scenes.models[:1], args.tol, workers=1, skip_bad=True)
        load = time.perf_counter() - start
    start = time.perf_counter()
    result = None
    try:
        if len(scenes.index):
            result = batch.simulate_many(scenes.params, scenes.states, scenes.models, args.tol, workers=args.workers,
                                         progress=bar.update, skip_bad=True)
    finally:
        bar.close()
    elapsed = max(time.perf_counter() - start, 1e-9)
    failed = [(int(i), result.errors[k]) for k, i in enumerate(scenes.index) if not result.ok[k]]
    if failed and not args.skip_bad:  # as for one scene: a computation that failed exits 1, and nothing is printed
        if len(failed) == 1:
            raise type(failed[0][1])(in_scene(*failed[0]))
        _report_bad(failed, "error")
        raise ComputationError(f"{len(failed)} scenes of {total} could not be computed (listed above; --skip-bad "
                               "prints the others)")
    errors += failed  # with --skip-bad: listed with the bad ones
    if errors:
        _report_bad(sorted(errors, key=lambda ie: ie[0]), "skipped")
    # The table and the text are read from the engine's rows; a record (a dict of ~2 kB) per scene is built only
    # for --json, and the states at a scene's times only there: 10⁶ records took 25 s and 1.9 GB, to print ten.
    values = np.full((total, len(TABLE_SOURCE)), np.nan)
    ok = np.zeros(total, dtype=bool)
    if result is not None:
        values[scenes.index] = result.rows[:, TABLE_SOURCE]
        ok[scenes.index] = result.ok
    columns = table(values, ok, {i: in_scene(i, error) for i, error in errors})
    write_tables(args, columns)
    if args.json:
        # One scene a line, encoded as it is built: json's indented output is written by its pure-Python encoder,
        # 100,000 scenes in 12 s without a word (an audit); the compact one is C, and line tools read it.
        bar = Progress(total, "scenes written as JSON", args.quiet or total < PROGRESS_FROM)
        try:
            for k, i in enumerate(scenes.index):
                i = int(i)
                if not result.ok[k]:
                    row = {"error": in_scene(i, result.errors[k])}
                elif scenes.times[k] or at or samples is not None:  # states: this scene's own motion (dense output)
                    scene = Scene(scenes.params_of(k), State(*scenes.states[k]), scenes.times[k], scenes.models[k])
                    motion = Motion(scene, args.tol, result.rows[k])
                    row = motion.as_dict(report_times(motion, scene.times, at, samples))
                else:
                    row = {**record(result.rows[k], scenes.models[k], args.tol, scenes.params_of(k), scenes.states[k]),
                           "states": []}
                rows[i] = json.dumps(row, ensure_ascii=False)
                if k % PROGRESS_EVERY == 0:
                    bar.update(k)
        finally:
            bar.close()
        # Written only once every scene is encoded: a scene whose states fail exits 1 with nothing printed.
        sys.stdout.write("[\n" if rows else "[")
        for j, text in enumerate(rows):
            sys.stdout.write(",\n" + text if j else text)
        sys.stdout.write("\n]\n" if rows else "]\n")
        return _none_computed(total, errors) if not ok.any() else 0
    threads = batch.threads_for(len(scenes.index), args.workers)  # what the batch ran on (one for a few scenes)
    rate = f"{np.count_nonzero(ok) / elapsed:,.0f} scenes/s, {threads} thread{'s' if threads != 1 else ''}"
    loading = "loading the compiled engine" if batch.engine_for(None) is not engine else "the interpreted engine's first scene"
    text = many_text(columns, f"in {elapsed:.3g} s ({rate}; + {load:.2g} s {loading}), tol {args.tol:g}",
                     len(errors), args.tol)
    if own:  # not in the summary nor the table (one row a scene): said, not dropped in silence (a user audit)
        text += f"\nthe scenes' own times ({own:,} in all): their states are printed with --json"
    print(text)
    return _none_computed(total, errors) if not ok.any() else 0


def _none_computed(total: int, errors: list) -> int:
    """--skip-bad when every scene was bad or failed: the listing is printed, but a script must not read success
    from the exit status (it was 0, an audit found): 2 when every one was bad input, as a bad scene alone is
    (it was 1, a CLI audit), else 1 (a computation failed)."""
    from numerics.validation import SceneError

    if all(isinstance(error, SceneError) for _, error in errors):
        print(f"appell: error: none of the {total} scenes is valid (listed above)", file=sys.stderr)
        return 2
    print(f"appell: none of the {total} scenes could be computed (listed above)", file=sys.stderr)
    return 1


SHOWN_SCENES = 10  # scenes listed one per line in the text output; every one is in --json, --csv, --npz


def many_text(columns: dict, how: str, skipped: int = 0, tol: float | None = None) -> str:
    """The text `appell simulate` prints for many scenes (their `table` columns): the first scenes' ends and rest
    points, then the ranges and the models over all of them."""
    import collections

    ok = columns["ok"].astype(bool)
    done = np.count_nonzero(ok)
    lines = [f"{done} scene{'' if done == 1 else 's'} {how}" + (f"; {skipped} bad scene{'' if skipped == 1 else 's'} skipped"
                                                                   if skipped else ""), ""]
    lines.append(f"{'scene':>7}  {'sliding ends (s)':>16}  {'rolling ends (s)':>16}  {'rest xi (m)':>13}  {'rest eta (m)':>13}  "
                 f"{'est. error':>10}  sliding model")
    for i in range(min(len(ok), SHOWN_SCENES)):
        if not ok[i]:
            lines.append(f"{i:>7}  {columns['error'][i]}")
            continue
        roll = "never" if math.isinf(columns["t_roll_end"][i]) else f"{columns['t_roll_end'][i]:.9g}"
        rest = ("-", "-") if math.isnan(columns["rest_xi"][i]) else (f"{columns['rest_xi'][i]:.9g}", f"{columns['rest_eta'][i]:.9g}")
        estimate = "-" if math.isnan(columns["error_estimate"][i]) else f"{columns['error_estimate'][i]:.1e}"
        lines.append(f"{i:>7}  {columns['t_slide_end'][i]:>16.9g}  {roll:>16}  {rest[0]:>13}  {rest[1]:>13}  "
                     f"{estimate:>10}  {columns['sliding_model'][i].split(',')[0]}")
    if len(ok) > SHOWN_SCENES:
        lines.append(f"{'...':>7}  ({len(ok) - SHOWN_SCENES} more: --json, --csv FILE or --npz FILE gives every scene)")
    if ok.any():
        slide, roll = columns["t_slide_end"][ok], columns["t_roll_end"][ok]
        rolls = roll[np.isfinite(roll)]
        lines += ["", f"sliding ends between {slide.min():.6g} s and {slide.max():.6g} s"]
        if len(rolls):
            lines.append(f"rolling ends between {rolls.min():.6g} s and {rolls.max():.6g} s"
                         + (f" ({len(roll) - len(rolls)} roll for ever: delta = 0)" if len(rolls) < len(roll) else ""))
        counts = collections.Counter(model for model, good in zip(columns["sliding_model"], ok) if good)
        lines += ["", "sliding model:"] + [f"  {n:>8}  {name}" for name, n in counts.most_common()]
        resting = ok & ~np.isnan(columns["rest_xi"])  # a scene that rolls for ever has no rest point to estimate
        worst = columns["error_estimate"][resting].max() if resting.any() else None
        lines.append("no scene comes to rest (delta = 0): no rest point's error to estimate" if worst is None else
                     f"largest estimated relative error of a rest point: {worst:.1e} "
                     + ("(the tolerance may be missed: the warning on stderr)" if tol and validation.beyond_tolerance(worst, tol)
                        else "(on the safe side: README, 'Error estimates')"))
    return "\n".join(lines)


# The columns of --csv and --npz, one row per scene in input order.  A time that never comes (δ = 0: rolling;
# ε = 0: the pivot) is inf; a rest point that never comes, or a refused scene's numbers, an empty CSV cell (NaN in
# .npz); a refused scene has ok = 0 and its reason in "error".
TABLE = ("scene", "ok", "t_slide_end", "t_roll_end", "t_pivot_end", "rest_xi", "rest_eta", "error_estimate",
         "sliding_model", "error")
# Where the numbers come from: these columns of the engine's rows (numerics.engine.OUT_*), in this order.
TABLE_SOURCE = [engine.OUT_T_SLIDE, engine.OUT_T_ROLL, engine.OUT_T_PIVOT, engine.OUT_REST_XI, engine.OUT_REST_ETA,
                engine.OUT_ERROR, engine.OUT_MODEL]


def table(values: np.ndarray, ok: np.ndarray, errors: dict) -> dict:
    """The columns of `TABLE` (arrays of numbers, lists of text) from ``values``, the `TABLE_SOURCE` columns of every
    scene's engine row; ``ok`` which scenes were computed, ``errors`` index -> the one line saying why one was not."""
    values = np.where(ok[:, None], values, np.nan)
    t_slide, t_roll, t_pivot, rest_xi, rest_eta, error, model = values.T
    never = ~np.isfinite(t_roll)  # no rest point: it rolls for ever (δ = 0), as the JSON's "rest": null
    return {
        "scene": np.arange(len(values)), "ok": ok.astype(np.int64),
        "t_slide_end": t_slide,
        "t_roll_end": np.where(ok & never, math.inf, t_roll),
        "t_pivot_end": np.where(ok & ~np.isfinite(t_pivot), math.inf, t_pivot),
        "rest_xi": np.where(never, np.nan, rest_xi), "rest_eta": np.where(never, np.nan, rest_eta),
        "error_estimate": np.where(never, np.nan, error),  # no rest point, no estimate of its error (as the JSON's null)
        "sliding_model": [engine.MODEL_NAMES[int(m)] if good else "" for m, good in zip(model, ok)],
        "error": [errors.get(i, "") for i in range(len(values))],
    }


def csv_bytes(columns: dict) -> bytes:
    import csv
    import io

    def cell(x):
        if isinstance(x, float):
            return "" if math.isnan(x) else repr(x)  # repr: every digit of the float, inf as "inf"
        return x

    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow(TABLE)
    # tolist: Python numbers (a NumPy float's repr is "np.float64(…)"); the text columns are lists already.
    writer.writerows(zip(*(map(cell, columns[name].tolist() if isinstance(columns[name], np.ndarray) else columns[name])
                           for name in TABLE)))
    return text.getvalue().encode("utf-8")


def npz_bytes(columns: dict) -> bytes:
    import io

    out = io.BytesIO()
    arrays = {name: np.asarray(values, dtype=str if name in ("sliding_model", "error") else
                               (np.int64 if name in ("scene", "ok") else np.float64)) for name, values in columns.items()}
    np.savez(out, **arrays)
    return out.getvalue()


def check_tables(args) -> None:
    """Refuse ``--csv``/``--npz`` files that exist, or whose folder does not, before any work."""
    from pathlib import Path

    from paper.output import DestinationError, check_new_file

    for flag, path in (("--csv", args.csv), ("--npz", args.npz)):
        if path is None:
            continue
        if path == "-":  # as a scene, "-" is standard input; here it made a file named "-" (an audit)
            raise DestinationError(f"{flag} -: give a file name (the table goes to a file, not standard output)")
        check_new_file(path, flag)
        suffix = "." + flag[2:]  # read back by its suffix: CSV text in x.npz was unreadable
        if not path.lower().endswith(suffix):
            raise DestinationError(f"{flag} {path}: give a name ending in {suffix} (the file is read back by its suffix)")
    if args.csv is not None and args.npz is not None and Path(args.csv).resolve() == Path(args.npz).resolve():
        raise DestinationError(f"--csv, --npz: give two different files, not {args.csv} twice")


def motion_table(motion: Motion) -> dict:
    """`table`'s columns for one scene's motion."""
    return table(motion.row[None, TABLE_SOURCE], np.ones(1, dtype=bool), {})


def write_tables(args, columns: dict) -> None:
    """Write `table`'s ``columns`` to ``--csv``/``--npz`` when asked."""
    from paper.output import write_new_file

    if args.csv is None and args.npz is None:
        return
    if args.csv is not None:
        write_new_file(args.csv, csv_bytes(columns), "--csv")
    if args.npz is not None:
        write_new_file(args.npz, npz_bytes(columns), "--npz")
