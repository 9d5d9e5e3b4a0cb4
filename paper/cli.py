"""The `appell` command (also `python -m paper`).

Exit status: 0 when the job succeeded, 1 when a check failed, 2 for bad
input (always one line on stderr, never a traceback).
"""

from __future__ import annotations

import argparse
import errno
import json
import os
import re
import signal
import sys
import threading
import warnings
from typing import Sequence

EXIT_FAILED = 1
EXIT_USAGE = 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as a shell reports a program Ctrl-C stopped
EXIT_TERMINATED = 143  # 128 + SIGTERM
NO_PDFLATEX = "--pdf: pdflatex not found (Debian: texlive-latex-base texlive-latex-recommended texlive-fonts-recommended texlive-publishers; make tex)"


class UsageError(Exception):
    """Bad input: reported as one line, exit status 2."""


class _Once(argparse.Action):
    """argparse's ``store``, refusing an option given a second time: ``--csv a.csv --csv b.csv`` wrote b.csv alone
    and said nothing of a.csv (an audit).  Until it is given, the option holds its default, this very object."""

    def __call__(self, parser, namespace, values, option_string=None):
        first = getattr(namespace, self.dest, self.default)
        if first is not self.default:
            parser.error(f"{option_string}: given twice ({first}, then {values}); give it once")
        setattr(namespace, self.dest, values)


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # "--tol -1e-10" is a negative number to check (tol: must be positive), not an unknown option: Python 3.13's
        # rule (3.11's takes -1 and -.5 only; no option of appell's starts with a dash and a digit).
        self._negative_number_matcher = re.compile(r"^-\.?\d")

    def add_argument(self, *args, **kwargs):
        """An option taking one value is given at most once (`_Once`); the others as argparse has them."""
        if args and args[0].startswith("-") and "action" not in kwargs and kwargs.get("nargs") is None:
            kwargs["action"] = _Once
        return super().add_argument(*args, **kwargs)

    def error(self, message: str):  # argparse would print the usage block too
        raise UsageError(f"{message} (see '{self.prog} --help')")


def _verify(args) -> int:
    from paper import verification

    claims = None
    if args.claims:  # only these, each explained under the table; the record is kept for a whole run only
        # each once: `verify eq10 eq10` checked it twice and counted two errata (an audit)
        claims, unknown = verification.named(list(dict.fromkeys(args.claims)))
        if unknown:
            raise UsageError(f"no claim {', '.join(unknown)}: the ids are those `appell verify` lists (eq10, n8.V_rate_bound, ...)")
    results = verification.verify(claims, quiet=args.quiet)
    if args.json:
        print(json.dumps(verification.as_json(results), indent=2, ensure_ascii=False))
    else:
        print(verification.as_table(results))
        if claims is not None:
            print("\n" + "\n\n".join(verification.explained(c, v) for c, v in results))
    return EXIT_FAILED if any(v.status == "failed" for _, v in results) else 0


def _errata(args) -> int:
    from paper import errata, verification

    entries = verification.recorded(args.quiet)["errata"]
    if args.json:
        print(json.dumps({"errata": entries}, indent=2, ensure_ascii=False))
    else:
        print(errata.as_text(entries))
    return EXIT_FAILED if any(e["status"] == "failed" for e in entries) else 0


def _reduce(args) -> int:
    from paper import record, reduction_report, verification

    kept = verification.recorded(args.quiet)
    if "reduce" not in kept:  # the reduction's results, derived once and kept with the record
        kept = {**kept, "reduce": reduction_report.summary()}
        record.save(kept)
    steps = reduction_report.steps(kept["verify"]["claims"])
    results = kept["reduce"]
    if args.json:
        rows = [{"id": step_id, "step": text, **row} for step_id, text, row in steps]
        print(json.dumps({"steps": rows, **results}, indent=2, ensure_ascii=False))
    else:
        print(reduction_report.as_text(steps, results))
    failed = any(row["status"] == "failed" for _, _, row in steps) or "error" in results
    return EXIT_FAILED if failed else 0


def _params_only_for_tables(args) -> None:
    """--params gives the shared params of states in .npz/.csv; a JSON scene carries its own (simulate and plot)."""
    from numerics.scene import shown_name

    if args.scene != "-" and not os.path.lexists(args.scene):
        return  # reading it says it is missing (this said --params was wrong: an audit)
    if args.params is not None and not str(args.scene).lower().endswith((".csv", ".npz")):
        raise UsageError(f"--params: only for states in .npz/.csv; the scenes of {shown_name(args.scene)} carry their own params")


def _simulate(args) -> int:
    from numerics import scene_files, validation
    from numerics.simulate import jit_default, simulate
    from paper import scene_report

    jit_default()  # APPELL_JIT=2 passed for one scene, which the command line runs as it chooses, and failed for a list
    validation.tolerance(args.tol, "--tol")
    if args.workers is not None:
        validation.workers(args.workers, "--workers")
    _params_only_for_tables(args)
    scene_report.check_tables(args)  # before any work: --csv/--npz must be new files
    read = _read_scenes(args)
    if isinstance(read, scene_files.SceneSet):
        return scene_report.run_many(args, read)
    if args.skip_bad:
        raise UsageError("--skip-bad: only for many scenes (a JSON list, .npz or .csv)")
    at = scene_report.times_asked(args, len(read.times))
    scene_report.check_at(read.params, read.arrays()[1], at)
    # One scene: interpreted, no compilation to wait for, unless many states are asked: in a slide near δ = fR an
    # interpreted state cost milliseconds, and --samples 99990 ran 12 minutes (an audit); compiled, under a second.
    asked = len(read.times) + len(at) + (args.samples + 1 if args.samples is not None else 0)
    motion = simulate(read, tol=args.tol, jit=asked > STATES_INTERPRETED)
    times = scene_report.report_times(motion, read.times, at, args.samples)
    scene_report.write_tables(args, scene_report.motion_table(motion))
    if args.json:
        print(json.dumps(motion.as_dict(times), indent=2, ensure_ascii=False))
    else:
        print(scene_report.as_text(motion, times))
    return 0


# Beyond these, the command line runs the compiled engine (compiled once per copy, then loaded in about a second):
# the states of one scene it reports, the scenes of a picture.
STATES_INTERPRETED = 1000
SCENES_INTERPRETED = 10


def _read_scenes(args):
    """The scene file(s) of ``simulate`` or ``plot``, a count of the scenes checked on stderr for a long list."""
    from numerics import scene_files
    from paper.progress import Progress

    bar = Progress(0, "scenes read", getattr(args, "quiet", False))
    try:
        return scene_files.read(args.scene, args.params, args.model, progress=bar.update)
    finally:
        bar.close()


def _plot(args) -> int:
    """`appell plot`: the picture of one scene (`Motion.plot`) or the paths of many (`numerics.plot.draw_scenes`).

    Without -o the picture goes to <scene's name>.png in the current folder.  Like every file appell writes,
    it must be new: an existing file is refused before any work (one line, exit status 2), never replaced.
    """
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")  # a file, never a window
    from numerics import plot, scene_files, validation
    from numerics.scene import Scene, State
    from numerics.simulate import jit_default, simulate
    from paper import output

    jit_default()  # refused whatever the scenes, as for simulate
    validation.tolerance(args.tol, "--tol")
    _params_only_for_tables(args)
    asked = args.output is not None
    if asked and not args.output.strip():  # Path("") is ".", which the message named (an audit)
        raise UsageError("-o: an empty file name (the picture's file: -o shot.png, .pdf or .svg)")
    if not asked and args.scene == "-":  # its name would be "-.png"
        raise UsageError("plot: the scene comes from standard input: name the picture with -o FILE")
    target = Path(args.output) if asked else Path(Path(args.scene).stem + ".png")
    flag = "-o" if asked else "plot: (no -o)"
    output.check_new_file(target, flag)  # before any work (a folder named as such, before its missing suffix)
    try:
        kind = plot.suffix_format(target)
    except ValueError as error:
        raise UsageError(f"-o: {error}") from None
    read = _read_scenes(args)
    name = Path(args.scene).name
    if isinstance(read, scene_files.SceneSet):
        if read.errors:
            index, error = read.errors[0]
            first = error.within(f"scene [{index}]") if isinstance(error, validation.SceneError) else error
            more = len(read.errors) - 1
            raise validation.SceneError(first.field, first.rule + (f" (and {more} more bad scene{'s' * (more > 1)})" if more else ""))
        drawn = min(len(read.index), plot.MAX_SCENES)
        if drawn < read.total:
            print(f"appell: plot: drawing the first {drawn} of {read.total} scenes", file=sys.stderr)
        motions = []
        for k in range(drawn):
            params = read.params_of(k)
            scene = Scene(params, State(*read.states[k]), (), read.models[k])
            try:
                # a few scenes interpreted, nothing to compile; more compiled (100 near δ = fR took 3.5 minutes)
                motions.append(simulate(scene, tol=args.tol, jit=drawn > SCENES_INTERPRETED))
            except validation.ComputationError as error:  # "scene.slide: ..." of the list's scene [i]
                where = str(error).removeprefix("scene")
                raise type(error)(f"scene [{int(read.index[k])}]{where}") from None
        labels = [f"scene [{int(i)}]" for i in read.index[:drawn]]
        fig = plot.draw_scenes(motions, labels=labels)
    else:
        motion = simulate(read, tol=args.tol, jit=False)
        fig = motion.plot(title=plot.default_title(motion) if args.scene == "-" else f"{name}: {plot.default_title(motion)}")
    data = plot.render(fig, kind)
    matplotlib.pyplot.close(fig)
    output.write_new_file(target, data, flag)  # exclusive: a file that appeared meanwhile is not overwritten
    print(f"wrote {target}")
    return 0


def _bench(args) -> int:
    from numerics import bench
    from paper import figures, output, record
    from paper.progress import Notes

    if args.saved:  # the saved run, as it was measured: what the README's figures of speed come from
        if args.quick or args.no_save:
            raise UsageError("--saved prints the saved run and measures nothing: --quick and --no-save do not apply")
        saved = figures.DATA / "bench.json"
        remedy = "'appell bench' measures one (or restore the committed file)"
        data = output.read_data(saved, remedy, {"rows": list, "scaling": list, "mpmath_digits": list,
                                                "calibration": list, "slowest_alone": list, "machine": dict})
        try:
            report = bench.from_json(data)
        except (KeyError, TypeError) as error:  # a row or a size not as `bench.as_json` writes it
            raise output.DataError(f"{saved}: not the JSON appell writes ({error!r}): {remedy}") from None
    else:
        report = bench.run(quick=args.quick, progress=Notes(args.quiet))
        report.machine["source"] = record.source_key()  # which source these times are of (`record.measured_from`)
        data = bench.as_json(report)
    if not args.saved and not args.quick and not args.no_save:
        output.replace_file(figures.DATA / "bench.json", json.dumps(data, indent=1, ensure_ascii=False) + "\n")
        figures.work_precision(data)
    if args.json:
        print(json.dumps(data["rows"], indent=2, ensure_ascii=False))
    else:
        print(bench.as_text(report))
    said = record.measured_from(data["machine"].get("source"), record.source_key())
    if said != "from this source":  # on stderr, as a note: the run's figures are as they were measured
        print(f"appell bench: the saved run was measured {said}; 'appell bench' measures this one", file=sys.stderr)
    return 0


def _accuracy(args) -> int:
    from numerics import hard_cases, validation

    from paper.progress import Progress

    validation.tolerance(args.tol, "--tol")
    bar = Progress(len(hard_cases.hard_cases()), "hard cases against the mpmath reference", args.quiet)
    try:
        rows = hard_cases.accuracy(tol=args.tol, progress=bar.update)
    finally:
        bar.close()
    if args.json:
        print(json.dumps({"tol": args.tol, "cases": rows}, indent=2, ensure_ascii=False))
    else:
        print(hard_cases.accuracy_text(rows, args.tol))
    return 0 if hard_cases.kept(rows, args.tol) else EXIT_FAILED


def _paper(args) -> int:
    from pathlib import Path

    from paper import appendix, output, verification
    from paper.progress import Notes

    notes = Notes(args.quiet)
    # What can be refused is refused before the minutes of work: the flags, the destination, TeX.
    if args.out is not None and not args.out.strip():  # "" read as no --out wrote into the package's own paper/
        raise UsageError("--out: an empty path; give the folder to write into")
    if args.check and args.pdf and not args.out:
        raise UsageError("--check --pdf: give --out DIR to compile the regenerated copy in")
    if (args.check or not args.out) and not (appendix.PAPER / output.MANIFEST).exists():
        # An installed copy (pip install ., not -e): its paper/ is the package's modules, with no appendix in it
        # (--check compares with it, --out or not: every file would be 'stale').
        raise UsageError(f"{appendix.PAPER}: an installed copy of appell holds no appendix to "
                         f"{'check' if args.check else 'write over'}; 'appell paper --out DIR' writes one into a folder of yours")
    if args.pdf:
        _tex_available()
    destination = Path(args.out) if args.out else (None if args.check else appendix.PAPER)
    if destination is not None:
        output.check_destination(destination)  # before the record is checked: that may take a minute
        if args.pdf:  # nor will pdflatex overwrite a main.pdf of the user's
            output.check_products(destination, appendix.pdf_products())
    results = verification.results_from(verification.recorded(args.quiet))
    if args.check:
        # Regenerate elsewhere (a temporary folder, or --out) and compare with paper/ byte for byte.
        out = Path(args.out) if args.out else None
        changed = appendix.stale(appendix.PAPER, out, results, progress=notes)
        if changed:
            print("paper/ is stale (run 'appell paper' and commit): " + ", ".join(changed), file=sys.stderr)
            return EXIT_FAILED
        print("paper/ is up to date")
        if not args.pdf:
            return 0
    else:
        out = Path(args.out) if args.out else appendix.PAPER
        written = appendix.generate(out, results, progress=notes)
        print(f"wrote {len(written)} files under {out}: main.tex (standalone), appendix.tex and appell-appendix.sty "
              "(for a host document), hosts/, generated/ (with supplement.json), figures/")
    if args.pdf:
        compiled = appendix.compile_pdf(out, notes)
        if compiled is None:
            raise UsageError(NO_PDFLATEX)
        problems = [f"{document}: {problem}" for document, result in compiled.items() for problem in result["problems"]]
        if problems:
            print("\n".join(problems), file=sys.stderr)
            return EXIT_FAILED
        documents = ", ".join(f"{document} ({result['pages']} pages)" for document, result in compiled.items())
        print(f"compiled {out / 'main.pdf'} and the host documents in {out / 'hosts'}: {documents}")
    return 0


def _tex_available() -> None:
    """--pdf needs pdflatex and the host documents' classes: say which Debian packages are missing."""
    import shutil

    from paper import latex_hosts

    if shutil.which("pdflatex") is None:
        raise UsageError(NO_PDFLATEX)
    missing = latex_hosts.missing_classes()
    if missing:
        raise UsageError(f"--pdf: the host documents need Debian's {', '.join(missing)} (make tex installs it)")


def _costs(args) -> int:
    from paper import costs, verification
    from paper.progress import Notes

    # Refused before the minutes of measuring: what the measured commands would fail on.
    verification.jobs()
    _tex_available()
    data = costs.measure(progress=Notes(args.quiet))
    if not args.no_save:
        costs.save(data)
    print(json.dumps(data, indent=2, ensure_ascii=False) if args.json else costs.as_text(data))
    return 0


def _compare(args) -> int:
    from dataclasses import asdict

    from numerics import classical_vs_appell

    rows = classical_vs_appell.compare()
    if args.json:
        print(json.dumps({"params": asdict(classical_vs_appell.POOL), "shots": [asdict(r) for r in rows]}, indent=2, ensure_ascii=False))
    else:
        print(classical_vs_appell.as_text(rows))
    return 0


# Each subcommand: (one line on what it does, an example).  Shown by `appell COMMAND --help` and in
# `appell --help`'s list.
COMMANDS = {
    "verify": ("check every claim of the paper, exactly and at 30 digits; exit 1 if any fails", "appell verify --json > record.json"),
    "errata": ("list where the printed paper does not follow, printed beside corrected (from the kept record)", "appell errata"),
    "reduce": ("the reduction of the slide to the Abel equation, its normal form and invariants", "appell reduce --json"),
    "simulate": ("the motion of one ball from a scene file, phase by phase; or of many (a JSON list, .npz, .csv)",
                 "appell simulate numerics/scenes/sample.json --at 0.2 0.4"),
    "plot": ("draw a scene's motion (its path and phases; V, Ω and r against time), or many scenes' paths, to .png/.pdf/.svg",
             "appell plot numerics/scenes/sample.json -o sample.png"),
    "accuracy": ("the simulator against the mpmath reference on every hard case; exit 1 where an error exceeds --tol",
                 "appell accuracy --tol 1e-9"),
    "bench": ("speed against error of every method on the benchmark scenes (writes paper/data/bench.json)", "appell bench --quick"),
    "paper": ("generate the LaTeX appendix, figures and tables in paper/ (or --out DIR)", "appell paper --check"),
    "costs": ("time reproducing the appendix (verify, paper, paper --pdf), for its methods paragraph", "appell costs --no-save"),
    "compare": ("Appell's model beside the classical one on realistic pool shots", "appell compare --json"),
}


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("appell")
    except PackageNotFoundError:  # run from a checkout without installing
        return "unknown (not installed)"


def _command(sub, name: str, run, quiet: str | None = None):
    """A subcommand with its one-line description and example (`COMMANDS`), and ``--quiet`` when it reports progress."""
    text, example = COMMANDS[name]
    parser = sub.add_parser(name, help=text, description=text[0].upper() + text[1:] + ".",
                            epilog=f"example:\n  {example}", formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.set_defaults(run=run)
    if quiet:
        parser.add_argument("--quiet", action="store_true", help=quiet)
    return parser


def build_parser() -> argparse.ArgumentParser:
    from numerics.validation import DEFAULT_TOL

    parser = _Parser(
        prog="appell",
        description="Machine-checked companion to P. Appell, 'Sur le mouvement d'une bille de billard "
        "avec frottement de roulement' (1911).",
        epilog="example:\n  appell verify\n  appell simulate numerics/scenes/sample.json\n\n"
        "'appell COMMAND --help' describes each command.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"appell {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    progress = "no progress on stderr (shown only when stderr is a terminal)"
    verify = _command(sub, "verify", _verify, progress)
    verify.add_argument("claims", nargs="*", metavar="CLAIM",
                        help="check only these claims (ids as the table lists them: eq10 n8.V_rate_bound), each "
                             "explained under the table: printed, corrected, derived, verdict")
    verify.add_argument("--json", action="store_true", help="print the record as JSON")
    errata = _command(sub, "errata", _errata, "no progress or notes on stderr")
    errata.add_argument("--json", action="store_true", help="print the errata as JSON")
    reduce = _command(sub, "reduce", _reduce, "no progress or notes on stderr")
    reduce.add_argument("--json", action="store_true", help="print the steps and results as JSON")
    simulate = _command(sub, "simulate", _simulate, progress + "; many scenes only")
    simulate.add_argument(
        "scene", help="scene file (JSON: params, a state or a cue block, optional t and model), or many scenes: a JSON list, "
        "or states in .npz/.csv with --params (see README); - reads JSON from standard input",
    )
    simulate.add_argument("--params", help="JSON file of the shared params, for .npz/.csv states")
    simulate.add_argument("--workers", type=int, default=None, help="threads for many scenes (default: one per core)")
    # extend: --at 0.2 --at 0.3 asks both (the second dropped the first, unsaid: an audit)
    simulate.add_argument("--at", type=float, nargs="+", action="extend", metavar="T", help="also report the state at these times (s)")
    simulate.add_argument("--samples", type=int, metavar="N", help="also report N + 1 states evenly spaced until rest (for plots)")
    simulate.add_argument("--tol", type=float, default=DEFAULT_TOL, help=f"relative tolerance of numerical phases (default {DEFAULT_TOL:g})")
    simulate.add_argument("--model", choices=("appell", "classical"), help="override the scene's model")
    simulate.add_argument(
        "--skip-bad", action="store_true",
        help="many scenes: simulate the good ones and list the bad ones (by default a bad scene stops the run)",
    )
    simulate.add_argument("--json", action="store_true", help="print the motion as JSON")
    simulate.add_argument("--csv", metavar="FILE", help="also write one row per scene (phase ends, rest point, estimate) as CSV")
    simulate.add_argument("--npz", metavar="FILE", help="also write the same columns as arrays in a NumPy .npz")
    plot = _command(sub, "plot", _plot)
    plot.add_argument("scene", help="scene file (JSON: params, a state or a cue block), or many scenes: a JSON list, or states "
                      "in .npz/.csv with --params; - reads JSON from standard input (then name the picture with -o)")
    plot.add_argument(
        "-o", "--output", metavar="FILE",
        help="the picture, .png, .pdf or .svg (a new file: an existing one is refused); default: the scene's name .png in the current "
        "folder, never over an existing file",
    )
    plot.add_argument("--params", help="JSON file of the shared params, for .npz/.csv states")
    plot.add_argument("--tol", type=float, default=DEFAULT_TOL, help=f"relative tolerance of numerical phases (default {DEFAULT_TOL:g})")
    plot.add_argument("--model", choices=("appell", "classical"), help="override the scene's model")
    accuracy = _command(sub, "accuracy", _accuracy, progress)
    accuracy.add_argument("--tol", type=float, default=DEFAULT_TOL, help=f"the simulator's tolerance (default {DEFAULT_TOL:g})")
    accuracy.add_argument("--json", action="store_true", help="print the errors as JSON")
    bench = _command(sub, "bench", _bench, progress)
    bench.add_argument("--quick", action="store_true", help="a reduced set, not saved (its compile and references included on a first run)")
    bench.add_argument("--json", action="store_true", help="print the rows as JSON")
    bench.add_argument("--no-save", action="store_true", help="do not write paper/data/bench.json and the figure")
    bench.add_argument("--saved", action="store_true",
                       help="print the saved run (paper/data/bench.json) and measure nothing: the README's figures")
    paper = _command(sub, "paper", _paper, progress)
    paper.add_argument("--out", help="write into this folder instead of paper/ (new, empty, or a previous output)")
    paper.add_argument("--pdf", action="store_true", help="also compile main.tex with pdflatex (fails on any LaTeX error)")
    paper.add_argument("--check", action="store_true", help="exit 1, naming the files, if paper/ is stale")
    costs = _command(sub, "costs", _costs, progress)
    costs.add_argument("--json", action="store_true", help="print the measurements as JSON")
    costs.add_argument("--no-save", action="store_true", help="do not write paper/data/costs.json")
    compare = _command(sub, "compare", _compare)
    compare.add_argument("--json", action="store_true", help="print the comparison as JSON")
    return parser


class Terminated(BaseException):
    """SIGTERM (a kill, `timeout`, a cancelled CI job), raised where the program is so that it unwinds as for
    Ctrl-C: a temporary folder goes with it (`appell paper --out` left its staging folder, which then made the
    next run refuse the destination).  Not an Exception: nothing that catches those may swallow it."""


def _terminated(signum, frame):
    raise Terminated


def main(argv: Sequence[str] | None = None) -> int:
    from numerics.validation import ComputationError, SceneError
    from paper.output import DataError, DestinationError, SettingError

    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, _terminated)
    else:  # a signal handler can only be set from the main thread (a caller's own)
        previous = None
    shown = warnings.showwarning
    warnings.showwarning = _warning_line
    try:
        if sys.stdout is None:  # started with it closed (appell ... >&-): Python's print drops every line
            raise OSError(errno.EBADF, "it is closed")
        args, unknown = build_parser().parse_known_args(argv)
        if unknown:  # the top parser would send to 'appell --help': the command's own help names its options
            raise UsageError(f"unrecognized arguments: {' '.join(unknown)} (see 'appell {args.command} --help')")
        status = args.run(args)
        sys.stdout.flush()  # a full disk or a closed pipe shows here, not at exit
        return status
    except Terminated:
        print("appell: terminated", file=sys.stderr)
        return EXIT_TERMINATED
    except (UsageError, SceneError, DestinationError, DataError, SettingError) as error:
        return _fail(error, EXIT_USAGE)
    except ComputationError as error:
        return _fail(error, EXIT_FAILED)
    except MemoryError as error:  # a million scenes under `ulimit -v`: NumPy's allocation failed (an audit)
        return _fail(f"out of memory ({error or 'an allocation failed'}): give fewer scenes or states at once", EXIT_FAILED)
    except RuntimeError as error:
        if "can't start new thread" not in str(error):  # the same limit met by the batch's threads
            raise
        return _fail(f"out of memory (cannot start a thread: {error}): give fewer scenes or states at once, or set "
                     "--workers 1", EXIT_FAILED)
    except KeyboardInterrupt:  # Ctrl-C: one line, and the shell's status for SIGINT, not a traceback
        print("appell: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:  # output piped into head, say: nothing more to say
        _discard_stdout()
        return 0
    except OSError as error:  # writing the output failed (/dev/full, a closed terminal, a closed descriptor)
        if sys.stdout is not None:
            _discard_stdout()
        where = error.filename or "standard output"
        return _fail(f"cannot write to {where} ({error.strerror or error})", EXIT_USAGE)
    finally:
        warnings.showwarning = shown
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _warning_line(message, category, filename, lineno, file=None, line=None) -> None:
    """A warning (the tolerance may be missed: `numerics.validation.ToleranceWarning`) as one line on stderr,
    not Python's two with a source line."""
    print(f"appell: warning: {_one_line(message)}", file=sys.stderr)


def _one_line(message) -> str:
    # One line whatever the user typed: a newline or an escape in a file name or an id is shown, not obeyed.
    return "".join(ch if ch.isprintable() else repr(ch)[1:-1] for ch in str(message))


def _fail(error, status: int) -> int:
    print(f"appell: error: {_one_line(error)}", file=sys.stderr)
    return status


def _discard_stdout() -> None:
    """Point stdout at /dev/null: what is still buffered must not fail again when Python exits."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # stdout without a file descriptor (a test's capture)
        pass


if __name__ == "__main__":  # `python -m paper.cli`, as `python -m paper`
    raise SystemExit(main())
