"""The methods paragraph: what produced the appendix, what each verdict means, how to reproduce it.

Everything is read from where it is defined: the versions from the installed
packages (pinned in pyproject.toml), the source from `paper.record.source_key`
(not a git commit, which would make paper/ stale at every commit), the
sampling box and the seeds from `derivation.domain`, the precision from
`derivation.checks`, and the cost of each command from paper/data/costs.json,
which `appell costs` measures and writes — never a number typed here, and
never a time measured while `appell paper` runs (regeneration is
byte-identical).
"""

from __future__ import annotations

import json
import sys
from importlib import metadata
from pathlib import Path

import sympy as sp

from derivation import checks, domain
from paper.bibliography import cite
from paper.latex_text import code_text, identifier, processor, tex_text

COSTS = Path(__file__).resolve().parent / "data" / "costs.json"
PINNED = ("sympy", "mpmath", "numpy", "matplotlib")
NAMES = {"sympy": "SymPy", "mpmath": "mpmath", "numpy": "NumPy", "matplotlib": "Matplotlib"}
# The claims that derive the equations of motion a second time, by Kane's method.
KANE_ROUTE = ("route2.eq4-5", "route2.eq7", "route2.eq8")
# Each pinned package's reference, cited beside its version (a package the appendix uses is cited, a referee).
REFERENCE = {"SymPy": "sympy2017", "mpmath": "mpmath", "NumPy": "numpy2020", "Matplotlib": "matplotlib2007"}
# The box's symbols shown, in the paper's order (the others are derivatives and components, any moderate value).
BOX = ("R", "k", "m", "g", "f", "delta", "epsilon", "V", "Omega", "alpha", "beta", "theta", "t", "r")
UNITS = {"R": r"\,\mathrm{m}", "m": r"\,\mathrm{kg}", "g": r"\,\mathrm{m/s^2}", "V": r"\,\mathrm{m/s}",
         "Omega": r"\,\mathrm{rad/s}", "r": r"\,\mathrm{rad/s}", "t": r"\,\mathrm{s}", "epsilon": r"\,\mathrm{m}"}


def versions() -> dict[str, str]:
    """Python (major.minor: what pyproject requires) and the pinned packages, as installed."""
    out = {"Python": f"{sys.version_info.major}.{sys.version_info.minor}"}
    out.update({NAMES[name]: metadata.version(name) for name in PINNED})
    out["appell"] = metadata.version("appell")
    return out


def costs() -> dict | None:
    """The measured cost of each command (`appell costs`), or None when it was never measured."""
    try:
        return json.loads(COSTS.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def _bound_tex(bound) -> str:
    from paper.display import Arrangement, arrange, display_tex

    value = sp.sympify(bound)
    if value.is_number:
        return f"{float(value):g}" if not value.has(sp.pi) else display_tex(arrange(value, None))
    return display_tex(arrange(value, Arrangement.of(r"\delta < fR")))  # as the paper writes (9): fR, not R f


def box_tex() -> str:
    """The sampling box of the paper's symbols, as intervals."""
    from derivation.notation import latex

    items = []
    for name in BOX:
        lo, hi = domain.PHYSICAL[name]
        symbol = latex(sp.Symbol(name))
        items.append(f"${symbol} \\in ({_bound_tex(lo)}, {_bound_tex(hi)}){UNITS.get(name, '')}$")
    return ", ".join(items)


def _code(text: str) -> str:
    return f"\\texttt{{{text}}}"


def _cost_sentence(measured: dict | None, record_key: str) -> str:
    from paper.record import measured_from

    if not measured:
        return r"Their cost has not been measured here (\texttt{appell costs} measures it)."
    machine = measured["machine"]
    parts = [f"\\texttt{{{code_text(row['command'])}}} {row['seconds']:.0f}\\,s" for row in measured["commands"]]
    return (
        f"Measured by \\texttt{{appell costs}} on a {machine['cores']}-core {tex_text(processor(machine['cpu']))} machine "
        f"{measured_from(machine.get('source'), record_key, _code)} (wall time): " + "; ".join(parts) + "."
    )


def methods_tex(heading, record_key: str) -> str:
    """The methods subsection, under ``heading`` (a function of the title and the label's name)."""
    v = versions()
    software = ", ".join(f"{name} {version}" + (f" {cite(REFERENCE[name])}" if name in REFERENCE else "")
                         for name, version in v.items() if name != "appell")
    paragraphs = [
        heading("Methods", "methods"),
        (
            f"Every claim below is checked by the Python package \\texttt{{appell}} {v['appell']} with {software} "
            f"(the packages pinned exactly, so that the digits and the LaTeX are reproducible). "
            f"The appendix was generated from the source whose key is \\texttt{{{record_key}}}: a hash of every source "
            "file of \\texttt{derivation/}, \\texttt{reduction/} and \\texttt{numerics/} and of the transcription of the "
            "paper, which identifies the source (any other source gives another key); the verification record of "
            "\\texttt{appell verify} is kept under this key combined with the versions above."
        ),
        (
            "Each equation is derived with SymPy from Newton--Euler's equations, the equations of motion (4), (5), (7) "
            f"and (8) a second time by Kane's method {cite('kane1985')} (the claims {_claims(*KANE_ROUTE)}). "
            "A sentence of the paper is quoted verbatim from the transcription, its glyphs included, with our "
            "English translation under it in italics."
        ),
        (  # a paragraph each: what a verdict compares; inequalities; the numeric claims (together, one was a page)
            "Each verdict says what was compared with what: \\emph{derived = printed} (or \\emph{corrected}, the "
            "erratum's form), the paper's formula; \\emph{derived = reading}, where the paper says it in words, the "
            "claim's reading of the quoted sentence, shown under it (once, as \\emph{Read as, and derived}, where the "
            "derived form is the same display); \\emph{derived = stated}, beyond the paper, the "
            "form the claim's statement gives. \\emph{Exact}: SymPy reduces the difference of the two to 0; "
            f"\\emph{{$n$ digits at $m$ points}}, the relative difference evaluated at {checks.DIGITS} significant digits "
            f"({checks.DIGITS + 10} working digits) at {checks.NUMERIC_POINTS} seeded random points of the box below "
            "(at 1 point where the two have no variable), "
            f"the worst point's digits reported (agreement means a relative difference below "
            f"$10^{{{round(float(sp.log(checks.NUMERIC_TOLERANCE, 10)))}}}$); an identity counts only when both hold. "
            f"A verdict names its numeric check only where it is not all {checks.DIGITS} digits at all "
            f"{checks.NUMERIC_POINTS} points (\\emph{{exact}} alone: both). "
            "A verdict covers the formula shown under \\emph{Derived}; where a statement argues around it, its other "
            "steps are the claims it names, each with its own verdict."
        ),
        (
            "An inequality is \\emph{proved} when it is affine in its bounded quantities ($\\sin\\theta\\in[-1,1]$, \\dots; "
            "each interval checked to hold over the sampling box, so that the proof's box is not too small) "
            "and SymPy's assumptions decide its sign at every vertex with $\\delta = fR/(1+\\psi)$, $\\psi > 0$ "
            "(hypothesis (9); a claim about another range of $\\delta$, such as $\\delta \\geq fR$, is proved under "
            "that range, which its statement names); "
            f"else it is \\emph{{sampled}} on {checks.DENSE_SAMPLES:,} seeded points, which is not a proof (not for a "
            "strict inequality, $<$ or $>$: sampling cannot tell $<$ from $\\leq$, so an unproved strict one fails); "
            f"\\emph{{sign at $m$ points, $n$ digits}}: its sign checked at the {checks.NUMERIC_POINTS} points as well, at "
            f"{checks.DIGITS} digits (named in a verdict only where it is not so: \\emph{{proved}} alone means both). An erratum's printed relation \\emph{{fails at a witness}}: a point of the box where it is false."
        ),
        (
            "\\emph{Numeric only} claims are measured along trajectories integrated in mpmath at 20 to 50 digits "
            f"(Gragg--Bulirsch--Stoer extrapolation {cite('hairer1993')}, and a Taylor-series integrator of the "
            f"package's own, its coefficients by automatic differentiation as in {cite('jorba2005')}), the measured "
            "value quoted: \\emph{$n$ digits ($\\geq d$ asked), $c$ cases}, the "
            "worst agreement over the $c$ cases (points along the trajectories, steps or slides, as the claim's "
            "statement says) and the agreement the claim requires. Only the $d$ digits asked are claimed: the "
            "agreement measured may exceed the digits the trajectory is integrated to (its error often falls below the "
            "tolerance asked, and a difference of exactly 0 is reported as the working precision, 10 digits beyond "
            "them), and is no bound on the error. A \\emph{glyph only} "
            "record shows that replacing the "
            "transcription's misread glyph gives the form the paper means, which is typed, not derived."
        ),
        (
            "The points are drawn strictly inside the box (2\\,\\% to 98\\,\\% of each interval), by a generator seeded "
            "with the first 8 bytes of the SHA-256 of the claim's identifier, so that every run and every machine "
            f"draws the same points: {box_tex()}; the reduction's constants are drawn with $a > b > c > 0$. "
            "A claim may narrow the box "
            "($\\theta$ acute, \\dots)."
        ),
        _hard_cases_tex(),
        (
            "To reproduce: \\texttt{make run} (or \\texttt{appell verify}, then \\texttt{appell paper}); "
            "\\texttt{appell paper --check --pdf --out build/paper} regenerates this appendix, compares it byte by byte "
            "with the committed one and compiles it alone and in the host documents; \\texttt{make test} runs the "
            f"test suite as well. {_cost_sentence(costs(), record_key)}"
        ),
    ]
    return "\n\n".join(paragraphs) + "\n"


def _hard_cases_tex() -> str:
    """The hard cases that claims and `appell accuracy` are measured on, each with its start and what makes it hard
    (`numerics.hard_cases.WHY`): "on every hard case" named shots a reader could not see (a referee)."""
    from numerics.hard_cases import WHY, hard_cases
    from paper.figures import params_text, start_text

    cases = hard_cases()
    usual = cases["sample"].params
    items = "\n".join(
        f"\\item[\\texttt{{{code_text(name)}}}] {tex_text(start_text(scene.params, scene.state) + '; ' + WHY[name])}."
        for name, scene in cases.items()
    )
    return (
        f"The \\emph{{hard cases}} that numeric claims and the simulator's accuracy (\\texttt{{appell accuracy}}) are "
        f"measured on are {len(cases)} shots from the origin, each a pool ball on cloth "
        f"({tex_text(params_text(usual))}) unless its entry says otherwise; each entry gives its start "
        "and what makes it hard for a simulator:\n"
        f"\\begin{{appellnotation}}\n{items}\n\\end{{appellnotation}}"
    )


def _claims(*ids: str) -> str:
    """Claim identifiers as every other page sets them (typewriter, copying as typed): a, b and c."""
    names = [f"\\texttt{{{identifier(i)}}}" for i in ids]
    return f"{', '.join(names[:-1])} and {names[-1]}" if len(names) > 1 else names[0]
