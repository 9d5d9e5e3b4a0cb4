"""The README's command outputs come from real runs: `python -m paper.readme --check` runs every
``$ appell ...`` example of README.md and compares what it prints with what the README shows.

An example is an indented block line ``$ appell COMMAND ...`` followed by the output shown (up to the
next ``$`` line or the end of the block), or a comment ``<!-- $ appell COMMAND -->`` followed by the lines
it prints as they stand in the README (a Markdown table, rendered as a table), up to a blank line.  The shown lines must appear in the real output (stdout,
then stderr), in order and verbatim; a line ``...`` stands for any number of lines left out.  Only
wall-clock figures (`TIMED`) and figures at float64's rounding level (`ROUNDING`: an error of 1e-16 on
one processor is 4e-16 on another, with or without fused multiply-adds) are masked: every other digit is
compared.  An example that shows no
output is only parsed (its command and flags must exist).  `make test` runs the check, so the README
cannot drift from the code.

The README's Python examples (``>>>`` lines) are run by `doctest` in a temporary folder (a picture they
save is written there, not into the checkout) and must print what the README shows.

``appell verify`` is answered from the kept verification record (`paper.verification.recorded`, the
same table `appell verify` prints) rather than by checking every claim once more.

The numbers of tests the README gives for ``make check`` and ``make test`` are what pytest collects
(`suite_counts`): a test added or removed shows there too.  Its page counts of ``main.pdf`` and the host
documents are what pdflatex wrote in build/paper (`page_problems`), when `make test` compiled them there.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from paper import latex_hosts

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
# Figures that depend on the machine and the moment, not on the code: masked on both sides.
TIMED = (
    re.compile(r"in [0-9.e+-]+ s \([0-9,]+ scenes/s, \d+ threads?"),
    re.compile(r"\+ [0-9.e+-]+ s loading"),
)
# An error below 1e-14 (or exactly 0) is rounding, not a result: which rounding depends on the processor.
ROUNDING = re.compile(r"(?<![\w.])(?:0\.0e\+00|\d\.\de-(?:1[5-9]|[2-9]\d))(?![\w.])")
COMMENT = re.compile(r"^<!-- \$ (appell .*) -->$")
# How the README gives the suite's size: the fast subset, then the whole suite.
TEST_COUNTS = {"check": re.compile(r"`make check` runs ([0-9,]+) tests"),
               "test": re.compile(r"`make test` from a fresh clone runs ([0-9,]+) tests")}
SKIPPED = "..."
# The pages of main.pdf and of each host document, as the README gives them, in this order of pdflatex's logs.
PAGES = re.compile(r"`main\.pdf` is (\d+) pages .*?takes (\d+) pages\s+\(article, one column\), (\d+) \(article, two "
                   r"columns\), (\d+) \(amsart\), (\d+) \(revtex4-2 reprint\), (\d+) \(article, the class's\s+defaults\),\s+"
                   r"(\d+) \(IEEEtran\),\s+(\d+) \(mnras\),\s+(\d+) \(book,\s+the\s+appendix\s+a\s+chapter\),\s+"
                   r"(\d+) \(article,\s+two\s+columns\s+at\s+11\s+pt\)\s+and\s+(\d+) \(amsart\s+at\s+12\s+pt\)", re.DOTALL)
PAGE_LOGS = ("main.log",) + tuple(f"hosts/{name}.log" for name in latex_hosts.HOSTS)  # in the README's order
COMPILED = ROOT / "build" / "paper"  # where `make test` compiles the appendix (appell paper --check --pdf --out)


@dataclass(frozen=True)
class Example:
    line: int  # of the command in README.md, from 1
    command: str  # as typed after "$ ", without a trailing comment
    shown: tuple[str, ...]  # the output lines shown, indentation removed


def examples(text: str) -> list[Example]:
    """Every ``$ appell`` example of a README's indented blocks, with the output shown after it."""
    found, current, lines = [], None, text.splitlines()
    for number, line in enumerate(lines, 1):
        marked = COMMENT.match(line)
        if marked:  # the lines below, to a blank one, as the README shows them
            if current:
                found.append(current)
            shown = []
            for below in lines[number:]:
                if not below.strip():
                    break
                shown.append(below.rstrip())
            found.append(Example(number, marked.group(1).strip(), (SKIPPED, *shown)))  # an excerpt: from anywhere
            current = None
            continue
        indented = line.startswith("    ")
        body = line[4:] if indented else None
        if indented and body.startswith("$ "):
            if current:
                found.append(current)
            command = body[2:].split("  #")[0].strip()
            current = Example(number, command, ()) if command.startswith("appell ") else None
        elif current and (indented or (line == "" and _continues(lines, number))):
            current = Example(current.line, current.command, current.shown + (body.rstrip() if indented else "",))
        elif current:
            found.append(current)
            current = None
    if current:
        found.append(current)
    return [Example(e.line, e.command, _trim(e.shown)) for e in found]


def _continues(lines: list[str], number: int) -> bool:
    """A blank line inside a block: the block goes on after it."""
    return number < len(lines) and lines[number].startswith("    ")


def _trim(shown: tuple[str, ...]) -> tuple[str, ...]:
    while shown and shown[-1] == "":
        shown = shown[:-1]
    return shown


def masked(line: str) -> str:
    for pattern in TIMED:
        line = pattern.sub("<timed>", line)
    return ROUNDING.sub("<rounding>", line)


def mismatch(shown: tuple[str, ...], actual: str) -> str | None:
    """None when every shown line appears in ``actual`` in order (``...`` skipping any lines), else the first
    shown line that does not, with the real line that stands in its place."""
    real = [masked(line.rstrip()) for line in actual.splitlines()]
    at, free = 0, False  # free: a "..." allows lines to be skipped before the next shown one
    for line in shown:
        if line.strip() == SKIPPED:
            free = True
            continue
        want = masked(line)
        if free:
            while at < len(real) and real[at] != want:
                at += 1
        if at >= len(real) or real[at] != want:
            near = real[at] if at < len(real) else "(the output ended)"
            return f"shown {line!r}, printed {near!r}"
        at, free = at + 1, False
    return None


def run(command: str) -> str:
    """What ``command`` prints (stdout, then stderr), run from the checkout as a user would."""
    words = shlex.split(command)[1:]
    if words == ["verify"]:
        from paper import verification

        return verification.as_table(verification.results_from(verification.recorded(quiet=True)))
    done = subprocess.run([sys.executable, "-m", "paper", *words], cwd=ROOT, capture_output=True, text=True,
                          env={**os.environ, "COLUMNS": "100"}, check=False, timeout=600)
    return done.stdout + done.stderr


def check(readme: Path = README) -> list[str]:
    """Every example of ``readme`` whose shown output the real one does not contain, one line each."""
    from paper.cli import build_parser

    problems = []
    for example in examples(readme.read_text(encoding="utf-8")):
        words = shlex.split(example.command)[1:]
        try:
            build_parser().parse_args(words)
        except (SystemExit, Exception) as error:  # noqa: BLE001 - any refusal of the command line is the finding
            problems.append(f"{readme.name}:{example.line}: {example.command}: does not parse ({error})")
            continue
        if not example.shown:
            continue
        found = mismatch(example.shown, run(example.command))
        if found:
            problems.append(f"{readme.name}:{example.line}: {example.command}: {found}")
    return problems


def python_examples(readme: Path = README) -> list[str]:
    """The README's ``>>>`` examples run by doctest, in a temporary folder: one line per failure."""
    import doctest
    import io
    import tempfile

    text = readme.read_text(encoding="utf-8")
    test = doctest.DocTestParser().get_doctest(text, {}, readme.name, str(readme), 0)
    report = io.StringIO()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as folder:
        os.chdir(folder)
        try:
            runner.run(test, out=report.write)
        finally:
            os.chdir(here)
    problems = []
    for block in report.getvalue().split("*" * 70):
        found = re.search(r'line (\d+).*?\nFailed example:\n\s*(.*?)\n', block, re.S)
        if found:
            problems.append(f"{readme.name}:{int(found.group(1))}: >>> {found.group(2).strip()}: "
                            + " ".join(block.split("\n", 4)[-1].split())[:300])
    if runner.failures and not problems:  # a report this function could not read: say so, never pass
        problems.append(f"{readme.name}: {runner.failures} Python examples failed")
    return problems


def collected(summary: str) -> dict[str, int]:
    """The numbers of tests of ``make check`` and ``make test`` from the last line of ``pytest --collect-only -q
    -m "not slow"`` ("627/793 tests collected (166 deselected) in 5.9s", or "793 tests collected" when none is slow)."""
    found = re.search(r"(?:(\d+)/)?(\d+) tests? collected", summary)
    if found is None:
        raise ValueError(f"no count of tests collected in {summary.strip()[-200:]!r}")
    whole = int(found.group(2))
    return {"check": int(found.group(1) or whole), "test": whole}


def count_problems(text: str, counts: dict[str, int]) -> list[str]:
    """Each count of tests ``text`` gives (``make check``, ``make test``) that is not ``counts``, or that it lacks."""
    problems = []
    for target, pattern in TEST_COUNTS.items():
        given = pattern.search(text)
        if given is None:
            problems.append(f"README.md: does not say how many tests `make {target}` runs ({pattern.pattern!r})")
        elif int(given.group(1).replace(",", "")) != counts[target]:
            line = text.count("\n", 0, given.start()) + 1
            problems.append(f"README.md:{line}: `make {target}` runs {given.group(1)} tests, says the README; "
                            f"pytest collects {counts[target]}")
    return problems


def suite_counts(readme: Path = README) -> list[str]:
    """The README's numbers of tests against what pytest collects now (about 7 s: every test module is imported)."""
    done = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-m", "not slow"], cwd=ROOT,
                          capture_output=True, text=True, check=False, timeout=600)
    if done.returncode != 0:
        return [f"pytest --collect-only failed (exit {done.returncode}): {(done.stdout + done.stderr).strip()[-300:]}"]
    return count_problems(readme.read_text(encoding="utf-8"), collected(done.stdout))


def page_problems(text: str, folder: Path = COMPILED) -> list[str] | None:
    """The README's page counts against pdflatex's logs in ``folder`` ("Output written on main.pdf (39 pages"),
    or None when nothing was compiled there (`make test` compiles it just before this check)."""
    if not (folder / PAGE_LOGS[0]).is_file():
        return None
    given = PAGES.search(text)
    if given is None:
        return [f"README.md: does not give the page counts ({PAGES.pattern[:40]!r}...)"]
    problems = []
    for log, shown in zip(PAGE_LOGS, given.groups()):
        if not (folder / log).is_file():
            problems.append(f"README.md: {Path(log).stem} was not compiled in {folder} (no {log}): its pages unchecked")
            continue
        pages = latex_hosts.pages((folder / log).read_text(encoding="latin-1"))
        if pages != int(shown):
            problems.append(f"README.md: {Path(log).stem} is {shown} pages, says the README; pdflatex wrote {'no' if pages is None else pages} "
                            f"({folder / log})")
    return problems


COSTS = re.compile(r"Measured \(`appell costs`, (\d+) cores, ([^)]*)\): `appell verify` ([\d.]+) s,\s+`appell paper` "
                   r"([\d.]+) s, `appell paper --pdf` ([\d.]+) s\.")
VERIFY_WALL = re.compile(r"checks the \d+ claims in\s+(\d+) s wall")


def cost_problems(text: str, costs: Path | None = None) -> list[str]:
    """The README's costs (its "Measured (`appell costs`, ...)" sentence and `appell verify`'s wall time in the
    opening) against paper/data/costs.json, which `appell costs` writes: prose restating a file drifts silently."""
    import json

    from paper import methods
    from paper.latex_text import processor

    saved = json.loads((costs or methods.COSTS).read_text(encoding="utf-8"))
    seconds = {c["command"]: c["seconds"] for c in saved["commands"]}
    machine = saved["machine"]
    expected = (str(machine["cores"]), processor(machine["cpu"]),
                *(f"{seconds[c]:.1f}" for c in ("appell verify", "appell paper", "appell paper --pdf")))
    problems = []
    given = COSTS.search(text)
    if given is None:
        problems.append(f"README.md: does not give the costs ({COSTS.pattern[:40]!r}...)")
    elif given.groups() != expected:
        problems.append(f"README.md: the costs read {', '.join(given.groups())}; paper/data/costs.json has {', '.join(expected)}")
    wall = VERIFY_WALL.search(text)
    if wall is None or int(wall.group(1)) != round(seconds["appell verify"]):
        problems.append(f"README.md: `appell verify` checks the claims in {wall.group(1) if wall else '(not found)'} s "
                        f"wall, says the README; paper/data/costs.json has {seconds['appell verify']} s")
    return problems


def main(argv=None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if args != ["--check"]:
        print("usage: python -m paper.readme --check", file=sys.stderr)
        return 2
    pages = page_problems(README.read_text(encoding="utf-8"))
    problems = check() + python_examples() + suite_counts() + cost_problems(README.read_text(encoding="utf-8")) + (pages or [])
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"{len(problems)} README examples differ from what the commands print (run them and paste)", file=sys.stderr)
        return 1
    print(f"README.md: every example's output is what the command prints ({len(examples(README.read_text()))} command "
          "examples, the Python examples run by doctest, the numbers of tests, the costs"
          + (", and the page counts of build/paper)" if pages is not None else "; page counts not checked: nothing compiled in build/paper)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
