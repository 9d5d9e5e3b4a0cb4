"""The `appell` command (also `python -m paper`).

Exit status: 0 when the job succeeded, 1 when a check failed, 2 for bad
input (always one line on stderr, never a traceback).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import Sequence

EXIT_FAILED = 1
EXIT_USAGE = 2


class UsageError(Exception):
    """Bad input: reported as one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # argparse would print the usage block too
        raise UsageError(f"{message} (see '{self.prog} --help')")


def _verify(args) -> int:
    from paper import verification

    results = verification.verify(quiet=args.quiet)
    if args.json:
        print(json.dumps(verification.as_json(results), indent=2, ensure_ascii=False))
    else:
        print(verification.as_table(results))
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


def _simulate(args) -> int:
    from numerics import scene_files, validation
    from numerics.simulate import simulate
    from paper import scene_report

    validation.tolerance(args.tol, "--tol")
    if args.workers is not None:
        validation.workers(args.workers, "--workers")
    if args.params is not None and not str(args.scene).endswith((".csv", ".npz")):
        raise UsageError(f"--params: only for states in .npz/.csv; the scenes of {args.scene} carry their own params")
    read = scene_files.read(args.scene, args.params, args.model)
    if isinstance(read, scene_files.SceneSet):
        return scene_report.run_many(args, read)
    if args.skip_bad:
        raise UsageError("--skip-bad: only for many scenes (a JSON list, .npz or .csv)")
    times = list(read.times)
    for t in args.at or []:
        if not (t >= 0 and t < float("inf")):
            raise UsageError(f"--at: times must be finite and >= 0, got {t}")
        times.append(t)
    if args.samples is not None and args.samples < 1:
        raise UsageError(f"--samples: must be >= 1, got {args.samples}")
    motion = simulate(read, tol=args.tol, jit=False)  # one scene: interpreted, no compilation to wait for
    if args.samples is not None:
        times += [b.t for b in motion.samples(args.samples)]
    if args.json:
        print(json.dumps(motion.as_dict(times), indent=2, ensure_ascii=False))
    else:
        print(scene_report.as_text(motion, times))
    return 0


def _bench(args) -> int:
    from numerics import bench
    from paper import figures

    report = bench.run(quick=args.quick, progress=lambda line: print(line, file=sys.stderr, flush=True))
    data = bench.as_json(report)
    if not args.quick and not args.no_save:
        figures.DATA.mkdir(parents=True, exist_ok=True)
        (figures.DATA / "bench.json").write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
        figures.work_precision(data)
    if args.json:
        print(json.dumps(data["rows"], indent=2, ensure_ascii=False))
    else:
        print(bench.as_text(report))
    return 0


def _accuracy(args) -> int:
    from numerics import hard_cases, validation

    validation.tolerance(args.tol, "--tol")
    rows = hard_cases.accuracy(tol=args.tol)
    if args.json:
        print(json.dumps({"tol": args.tol, "cases": rows}, indent=2, ensure_ascii=False))
    else:
        print(hard_cases.accuracy_text(rows, args.tol))
    worst = max((r["rest error"] for r in rows if r["rest error"] is not None), default=0.0)
    return EXIT_FAILED if worst > 1e-9 else 0


def _paper(args) -> int:
    from pathlib import Path

    from paper import appendix

    if args.check:
        # Regenerate elsewhere (a temporary folder, or --out) and compare with paper/ byte for byte.
        out = Path(args.out) if args.out else None
        changed = appendix.stale(appendix.PAPER, out)
        if changed:
            print("paper/ is stale (run 'appell paper' and commit): " + ", ".join(changed), file=sys.stderr)
            return EXIT_FAILED
        print("paper/ is up to date")
        if not args.pdf:
            return 0
        if out is None:
            raise UsageError("--check --pdf: give --out DIR to compile the regenerated copy in")
    else:
        out = Path(args.out) if args.out else appendix.PAPER
        written = appendix.generate(out)
        print(f"wrote {len(written)} files under {out}: main.tex (standalone), appendix.tex and appell-appendix.sty "
              "(for a host document), hosts/, generated/ (with supplement.json), figures/")
    if args.pdf:
        from paper import latex_hosts

        missing = latex_hosts.missing_classes()
        if missing:
            raise UsageError(f"--pdf: the host documents need Debian's {', '.join(missing)} (make tex installs it)")
        compiled = appendix.compile_pdf(out)
        if compiled is None:
            raise UsageError("--pdf: pdflatex not found (Debian: texlive-latex-base texlive-latex-recommended texlive-fonts-recommended texlive-publishers; make tex)")
        problems = [f"{document}: {problem}" for document, result in compiled.items() for problem in result["problems"]]
        if problems:
            print("\n".join(problems), file=sys.stderr)
            return EXIT_FAILED
        documents = ", ".join(f"{document} ({result['pages']} pages)" for document, result in compiled.items())
        print(f"compiled {out / 'main.pdf'} and the host documents in {out / 'hosts'}: {documents}")
    return 0


def _costs(args) -> int:
    from paper import costs

    data = costs.measure(progress=None if args.quiet else lambda line: print(line, file=sys.stderr, flush=True))
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


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="appell",
        description="Machine-checked companion to P. Appell, 'Sur le mouvement d'une bille de billard "
        "avec frottement de roulement' (1911).",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    verify = sub.add_parser("verify", help="check every claim of the paper; exit 1 if any fails")
    verify.add_argument("--json", action="store_true", help="print the record as JSON")
    verify.add_argument("--quiet", action="store_true", help="no progress on stderr")
    verify.set_defaults(run=_verify)
    errata = sub.add_parser("errata", help="list where the printed paper does not follow (from the kept record)")
    errata.add_argument("--json", action="store_true", help="print the errata as JSON")
    errata.add_argument("--quiet", action="store_true", help="no progress or notes on stderr")
    errata.set_defaults(run=_errata)
    reduce = sub.add_parser("reduce", help="the reduction to the Abel equation, its normal form and invariants")
    reduce.add_argument("--json", action="store_true", help="print the steps and results as JSON")
    reduce.add_argument("--quiet", action="store_true", help="no progress or notes on stderr")
    reduce.set_defaults(run=_reduce)
    simulate = sub.add_parser("simulate", help="the motion of one ball from a scene file (JSON), phase by phase")
    simulate.add_argument(
        "scene", help="scene file (JSON: params, state, optional t and model), or many scenes: a JSON list, "
        "or states in .npz/.csv with --params (see README)",
    )
    simulate.add_argument("--params", help="JSON file of the shared params, for .npz/.csv states")
    simulate.add_argument("--workers", type=int, default=None, help="processes for many scenes (default: one per core)")
    simulate.add_argument("--at", type=float, nargs="+", metavar="T", help="also report the state at these times (s)")
    simulate.add_argument("--samples", type=int, metavar="N", help="also report N + 1 states evenly spaced until rest (for plots)")
    simulate.add_argument("--tol", type=float, default=1e-10, help="relative tolerance of numerical phases (default 1e-10)")
    simulate.add_argument("--model", choices=("appell", "classical"), help="override the scene's model")
    simulate.add_argument(
        "--skip-bad", action="store_true",
        help="many scenes: simulate the good ones and list the bad ones (by default a bad scene stops the run)",
    )
    simulate.add_argument("--json", action="store_true", help="print the motion as JSON")
    simulate.set_defaults(run=_simulate)
    accuracy = sub.add_parser("accuracy", help="the simulator against the mpmath reference on every hard case")
    accuracy.add_argument("--tol", type=float, default=1e-10, help="the simulator's tolerance (default 1e-10)")
    accuracy.add_argument("--json", action="store_true", help="print the errors as JSON")
    accuracy.set_defaults(run=_accuracy)
    bench = sub.add_parser("bench", help="speed against error of every method on the benchmark scenes")
    bench.add_argument("--quick", action="store_true", help="a reduced set, under a minute (not saved)")
    bench.add_argument("--json", action="store_true", help="print the rows as JSON")
    bench.add_argument("--no-save", action="store_true", help="do not write paper/data/bench.json and the figure")
    bench.set_defaults(run=_bench)
    paper = sub.add_parser("paper", help="generate the LaTeX appendix, figures and tables in paper/")
    paper.add_argument("--out", help="write into this folder instead of paper/")
    paper.add_argument("--pdf", action="store_true", help="also compile main.tex with pdflatex (fails on any LaTeX error)")
    paper.add_argument("--check", action="store_true", help="exit 1, naming the files, if paper/ is stale")
    paper.set_defaults(run=_paper)
    costs = sub.add_parser("costs", help="time reproducing the appendix (verify, paper, paper --pdf); saved for its methods")
    costs.add_argument("--json", action="store_true", help="print the measurements as JSON")
    costs.add_argument("--no-save", action="store_true", help="do not write paper/data/costs.json")
    costs.add_argument("--quiet", action="store_true", help="no progress on stderr")
    costs.set_defaults(run=_costs)
    compare = sub.add_parser("compare", help="Appell's model beside the classical one on realistic pool shots")
    compare.add_argument("--json", action="store_true", help="print the comparison as JSON")
    compare.set_defaults(run=_compare)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    from numerics.validation import ComputationError, SceneError
    from paper.output import DestinationError

    try:
        args = build_parser().parse_args(argv)
        status = args.run(args)
        sys.stdout.flush()  # a full disk or a closed pipe shows here, not at exit
        return status
    except (UsageError, SceneError, DestinationError) as error:
        return _fail(error, EXIT_USAGE)
    except ComputationError as error:
        return _fail(error, EXIT_FAILED)
    except BrokenPipeError:  # output piped into head, say: nothing more to say
        _discard_stdout()
        return 0
    except OSError as error:  # writing the output failed (/dev/full, a closed terminal)
        _discard_stdout()
        where = error.filename or "standard output"
        return _fail(f"cannot write to {where} ({error.strerror or error})", EXIT_USAGE)


def _fail(error, status: int) -> int:
    print(f"appell: error: {error}", file=sys.stderr)
    return status


def _discard_stdout() -> None:
    """Point stdout at /dev/null: what is still buffered must not fail again when Python exits."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # stdout without a file descriptor (a test's capture)
        pass
