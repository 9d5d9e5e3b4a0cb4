"""`appell paper`: the LaTeX appendix, assembled from generated fragments (showyourwork's pattern).

Every equation comes from a claim's SymPy object (`paper.claim_blocks`,
`paper.display`); text comes from the claims' statements; the methods from the
installed versions and the measured costs (`paper.methods`); the figures and
their captions from `paper.figures`.  Nothing is typed twice, and the output is
deterministic: `--check` regenerates into a temporary folder and compares bytes.

Layout of ``paper/`` (all generated, all committed):

    main.tex                 a standalone article: \\usepackage{appell-appendix}, \\input{appendix}
    appendix.tex             the appendix a paper \\input's (with \\appellroot set to this folder)
    appell-appendix.sty      everything appendix.tex needs (`paper.latex_hosts`)
    hosts/*.tex              the appendix in host documents (`latex_hosts.HOSTS`): article (one and two columns,
                             the class's defaults, two at 11 pt), amsart (and at 12 pt), revtex4-2, IEEEtran, mnras,
                             book (the appendix a chapter)
    generated/*.tex          one fragment per section, methods, notation, errata, the record, the references
    generated/supplement.json  every claim's forms in full, SymPy srepr and LaTeX (`paper.supplement`)
    figures/*.pdf            the figures
    figures/sample_motion.png  the README's picture of a shot (`Motion.plot`, as `appell plot` draws it)

Before writing, the fragments are checked (`check_latex`): the paper's
equation numbers each at most once, every label prefixed ``appell:`` and
defined once, every reference to a label of the appendix.
"""

from __future__ import annotations

import filecmp
import re
import tempfile
from pathlib import Path

from derivation.claim import Claim, NumericCheck, Verdict, errata_summary
from paper import claim_blocks
from paper.bibliography import cite
from paper.latex_text import identifier, pdf_text, plain_text, tex_text

BENCH_REMEDY = "run 'appell bench' (or restore the committed file) to write it again"
BENCH_KEYS = {"rows": list, "machine": dict}  # what the figure and its caption read first (bench.as_json)


def saved_bench() -> dict:
    """The saved run of `appell bench` (paper/data/bench.json), which the work-precision figure, its caption and the
    text beside it read."""
    from paper import figures, output

    return output.read_data(figures.DATA / "bench.json", BENCH_REMEDY, BENCH_KEYS)

PAPER = Path(__file__).resolve().parent

# The sections of the paper (n°1 is the introduction), then what goes beyond it.
TITLES = {
    "n°2": "The equations of motion",
    "n°3": "No rolling friction: the classical motion",
    "n°4": "No sliding friction",
    "n°5": "The hypothesis δ < fR (9): what needs it, what survives without it",
    "n°6": "The rotation that vanishes comes back",
    "n°7": "Pure rolling",
    "n°8": "The general case: the slide ends, the integral (11), the energy",
    "n°9": "The reduced system (12)–(14)",
    "n°10": "The special case a = c",
    "n°11": "The Abel equation",
}
BEYOND = "beyond"  # claims whose where starts so: each "beyond …: topic" is a subsection
# A sentence opening a section, where the section uses a reference or a figure.
OPENINGS = {
    "n°2": "The equations are derived twice: by Newton–Euler, and by Kane's method [kane1985] (the claims "
           "route2.eq4-5, route2.eq7 and route2.eq8).",
    "n°11": "The Abel equation of the first kind z' = z³ − z² + λz(1 − z)² is of the type that, Appell writes, Roger "
            "Liouville studied first (his later account: [liouville1902]) and to which Appell devoted his monograph "
            "of 1889 [appell1889], whose normal form the paper refers to.",
    "beyond n°11: normal form": "τ(θ) is written through Appell's hypergeometric function F₁ of two variables "
                                "[appell1880], where cos θ > 0.",
    "beyond n°11: invariants": "The relative invariants s₃, s₅ and the absolute invariant J = s₅³/s₃⁵ of an Abel "
                               "equation [appell1889, chebterrab2000], for Appell's equation.",
    "n°8": "Figure [fig:phases] follows V, Ω and θ through sliding and rolling until rest on a sample shot.",
    "beyond n°8: the end of sliding": "Figure [fig:end_of_sliding] shows π/2 − θ ∝ V^κ on the slides the claim "
                                      "n8.end_exponent_mpmath measures it on.",
}
# The figures a section's opening refers to, placed there (spread out: floats queued together get stuck).
SECTION_FIGURES = {"n°8": "phases", "beyond n°8: the end of sliding": "end_of_sliding"}
FIGURES = ("shots", "phases", "end_of_sliding", "work_precision")  # each a column wide: no figure*, whose
# queue apart from the column floats leaves them stuck in revtex's reprint mode


def section_of(where: str) -> str:
    """The paper's section a claim belongs to ("n°7"), or its part beyond the paper ("beyond n°8: straight shots")."""
    if where.startswith("beyond"):
        return where
    match = re.match(r"n°(\d+)", where)
    return f"n°{match.group(1)}" if match else BEYOND


def heading(title: str, name: str, level: str = "subsection") -> str:
    """A heading of the appendix at the host's level (\\appellsection, \\appellsubsection), with a PDF
    bookmark in plain text and the label appell:sec:<name>.  A title with a colon gives its first part as the
    short title (the running heads of a book or thesis, where the appendix may be a chapter: the long ones
    overfilled them by up to 105 pt; the bookmark keeps the whole), and n° is \\appellno, which their capitals
    leave alone (not N^O)."""

    def tex(text):
        return tex_text(text).replace(r"n\textsuperscript{o}", r"\appellno{}")

    short = title.split(":")[0].strip()
    # The bookmark (hyperref reads the short title's PDF part) keeps the whole title: three "Beyond no8" in a row
    # could not be told apart (a referee's audit).
    optional = f"[\\texorpdfstring{{{tex(short)}}}{{{pdf_text(title)}}}]" if short != title else ""
    return (f"\\appell{level}{optional}{{\\texorpdfstring{{{tex(title)}}}{{{pdf_text(title)}}}}}"
            f"\\label{{appell:sec:{name}}}\n\n")


def _prose_with_refs(text: str) -> str:
    """A sentence with [key] citations and [fig:name] references."""
    out = []
    for i, part in enumerate(re.split(r"\[([a-z0-9_:, ]+)\]", text)):
        if i % 2 == 0:
            out.append(tex_text(part))
        elif part.startswith("fig:"):  # "Figure~\ref": the tie in place of the space, not beside it
            out[-1] = out[-1].rstrip()
            out.append(rf"~\ref{{appell:{part}}}")
        else:
            out.append(cite(*(key.strip() for key in part.split(","))))
    return "".join(out)


def _name(key: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", key.replace("n°", "n").lower()).strip("_")


def section_fragments(results: list[tuple[Claim, Verdict]]) -> dict[str, str]:
    """File name -> LaTeX, one fragment per section in the order of the paper, then beyond it."""
    groups: dict[str, list] = {}
    for claim, verdict in results:
        groups.setdefault(section_of(claim.where), []).append((claim, verdict))
    order = [key for key in TITLES if key in groups]
    beyond = [key for key in groups if key not in order]
    order += sorted(beyond, key=lambda key: int(m.group(1)) if (m := re.search(r"n°(\d+)", key)) else 99)
    out = {}
    for key in order:
        title = f"{key} — {TITLES[key]}" if key in TITLES else key[0].upper() + key[1:]
        parts = [heading(title, _name(key))]
        if key in OPENINGS:
            parts.append(_prose_with_refs(OPENINGS[key]) + "\n\n")
        if key in SECTION_FIGURES:
            parts.append(figure(SECTION_FIGURES[key]))
        parts += [claim_blocks.claim_block(c, v) for c, v in groups[key]]
        out[f"{_name(key)}.tex"] = "\n".join(parts)
    return out


def figure(name: str) -> str:
    """A figure of paper/figures with its caption, read from the code that draws it."""
    from paper import figures as figs, record

    captions = {
        "shots": figs.shots_caption,
        "phases": figs.phases_caption,
        "end_of_sliding": figs.end_of_sliding_caption,
        "work_precision": lambda: figs.work_precision_caption(saved_bench(), record.source_key()),
    }
    lists = {"shots": ("The starts of the shots of", figs.shots_starts),
             "end_of_sliding": ("The balls and the starts of the slides of", figs.end_of_sliding_starts),
             "phases": ("The scene of", figs.phases_scene)}
    listed = ""
    if name in lists:  # in the text: in the caption, a long list made the figure taller than a 12 pt page
        intro, entries = lists[name]
        items = "\n".join(rf"\item[\textit{{{tex_text(term)}}}] {tex_text(what)}." for term, what in entries())
        listed = f"{intro} Figure~\\ref{{appell:fig:{name}}}:\n\\begin{{appellnotation}}\n{items}\n\\end{{appellnotation}}\n"
    return listed + (
        "\\begin{figure}\\centering\n"  # no placement: mnras reads none, and would print "[tbp]"
        f"\\appellfigure{{\\appellroot/figures/{name}.pdf}}{{3.6in}}\n"
        f"\\caption[{tex_text(figs.SHORT_CAPTIONS[name])}]{{{tex_text(captions[name]())}}}\\label{{appell:fig:{name}}}\n"
        "\\end{figure}\n"
    )


def simulation_tex() -> str:
    """The simulator's results: the figures that are not tied to one claim."""
    text = (
        "Beyond the checks, the package simulates a shot phase by phase, each phase by closed forms where there are "
        "some (the paper's, and beyond it those of the straight shots) and by a numerical slide in σ = −ln V "
        "otherwise, and compares "
        "Appell's model with the classical one. Figure [fig:shots] shows five pool shots under both models, "
        "and Figure [fig:work_precision] the simulators' work against their precision, measured by appell bench "
        "against mpmath references [hairer1993, jorba2005]."
    )
    from paper import figures as figs

    bench = saved_bench()
    methods = "\n".join(rf"\item[\textit{{{tex_text(m)}}}] {_prose_with_refs(what)}."
                        for m, what in figs.work_precision_methods(bench))
    return (heading("Simulated shots", "simulation") + _prose_with_refs(text) + "\n\n"
            + "The methods of Figure~\\ref{appell:fig:work_precision}, each point of a method one setting of it (its "
            "tolerance \\texttt{tol}, scipy's \\texttt{rtol}, or mpmath's digits):\n"
            + f"\\begin{{appellnotation}}\n{methods}\n\\end{{appellnotation}}\n"
            + _prose_with_refs(figs.per_state_text(bench)) + " " + tex_text(figs.versions_sentence(bench)) + "\n\n"
            + "".join(figure(name) for name in ("shots", "work_precision"))
            # before the errata: they floated in between two errata (a referee)
            + "\\appellflushfloats\n")


def errata_tex(results: list[tuple[Claim, Verdict]]) -> str:
    """The errata: those of the paper first, each with its printed and corrected displays; then the transcription's
    glyphs, one line a misreading with its places (their claims show both displays: the list showed 26 displays a
    second time, and the two errata a reader looks for came among thirteen glyphs, a referee)."""
    entries = [(c, v) for c, v in results if isinstance(c, Claim) and c.erratum is not None]
    of_paper = [claim_blocks.erratum_item(c, v) for c, v in entries if c.erratum.kind != "ocr"]
    of_copy = claim_blocks.glyph_items([(c, v) for c, v in entries if c.erratum.kind == "ocr"])
    kinds = [c.erratum.kind for c, v in entries if v.status == "erratum"]
    unsettled = len(entries) - len(kinds)  # an erratum whose check failed is listed, saying so, but not counted
    text = (
        f"Where the printed paper, as transcribed, differs from the derived form: {len(kinds)} places "
        f"({errata_summary(kinds)})" + (f"; listed too, {unsettled} whose check failed" if unsettled else "") + ".\n"
    )

    def listed(items: list[str]) -> str:
        return "\\begin{appellerrata}\n" + "\n".join(items) + "\n\\end{appellerrata}\n"

    if of_paper:
        text += ("\n\\emph{Of the paper.} A mathematical erratum is a printed result that does not follow; a remark, "
                 "a slip in a detail that nothing after it uses (a strict inequality whose bound is reached). Each is corrected in SymPy and printed from it.\n"
                 + listed(of_paper))
    if of_copy:
        text += ("\n\\emph{Of the transcription.} A transcription artefact is a glyph our OCR copy shows wrong "
                 "(the reading's slip, or a misprint of that glyph in 1911: the copy cannot tell them apart, and the "
                 "meaning is not in doubt): its correction is the printed LaTeX with that glyph replaced and nothing "
                 "else, shown with the printed form under its claim. Each misreading, with the claims where it "
                 "occurs:\n" + listed(of_copy))
    return heading("Errata", "errata") + text


# What the claims beyond the paper establish, each sentence stated only when every claim it names is confirmed.
BEYOND_FINDINGS = (
    ("the reduction to the normal form that Appell announces is carried out, du/dτ = u³ + I(τ), with τ in closed "
     "form through his hypergeometric function F₁ where cos θ > 0 (the closed form is not carried to cos θ < 0, "
     "which a massé can start in)", ("normal.form", "normal.tau_F1")),
    ("the absolute invariant J of his Abel equation is constant for no billiard ball, so that the equation is in none "
     "of the integrable classes of constant invariant (which does not rule out others of non-constant invariant)",
     ("inv.J_never_constant",)),
)
# How the findings call an error of the paper, by its class.
ERROR_OF_PAPER = {"mathematical": ("mathematical erratum", "mathematical errata"),
                  "remark": ("remark, a minor slip", "remarks, minor slips")}


def _claim_link(claim_id: str) -> str:
    return rf"\appellref{{{claim_blocks.label_of(claim_id)}}}{{\texttt{{{identifier(claim_id)}}}}}"


def _status_counts(results: list[tuple[Claim, Verdict]]) -> dict[str, int]:
    """How many verdicts are confirmed, erratum and failed (the findings' and the record's counts)."""
    return {s: sum(v.status == s for _, v in results) for s in ("confirmed", "erratum", "failed")}


def _count(n: int, one: str, many: str) -> str:
    return f"{'one' if n == 1 else n} {one if n == 1 else many}"


def findings_tex(results: list[tuple[Claim, Verdict]]) -> str:
    """What the checks found, in one paragraph after the introduction: the claims by kind (as each is labelled),
    the counts, the premises among the confirmed, the paper's own errors by class (each named with its claim and
    what is wrong), the transcription's, and what the claims beyond the paper establish.  The record and the
    errata close the appendix: a referee looked for them on its first pages."""
    status = {c.id: v.status for c, v in results}
    quoted = sum(bool(c.printed_tex) for c, _ in results)  # labelled "Printed (transcription)", numeric or not
    own = sum(isinstance(c, NumericCheck) for c, _ in results if not c.printed_tex)  # no label: checks of ours
    counts = _status_counts(results)
    premises = sum(bool(getattr(c, "premise", None)) for c, v in results if v.status == "confirmed")
    differs = [c for c, v in results if c.erratum is not None and v.status == "erratum"]
    glyphs = sum(c.erratum.kind == "ocr" for c in differs)
    n_failed = counts["failed"]
    # "no check fails": an erratum's printed relation "fails at a witness", which is the paper's failure, not ours
    failed = ("no check fails" if not n_failed
              else f"{n_failed} fail{'s' if n_failed == 1 else ''} (Section~\\ref{{appell:sec:verification}})")
    text = (f"\\emph{{Findings.}} {len(results)} claims are checked: {quoted} check a formula or a sentence as the "
            f"paper prints it, {len(results) - quoted - own} go beyond it (labelled so), and {own} are numerical checks of "
            f"our own, most along high-precision integrations. {counts['confirmed']} are confirmed")
    if premises:
        text += f" ({_count(premises, 'of them a law or definition', 'of them laws and definitions')} the derivation takes as printed)"
    text += f" and {failed}. "
    for kind, (one, many) in ERROR_OF_PAPER.items():
        of_kind = [c for c in differs if c.erratum.kind == kind]
        if of_kind:
            where = "; ".join(f"in {tex_text(c.where)} ({_claim_link(c.id)}), {tex_text(c.erratum.summary)}" for c in of_kind)
            text += f"The paper has {_count(len(of_kind), one, many)}: {where}. "
    if glyphs:
        lead = "The other" if glyphs < len(differs) else ("The" if glyphs == 1 else "All")
        text += (f"{lead} {_count(glyphs, 'difference is a glyph', 'differences are glyphs')} our transcription "
                 "shows wrong (misread, or misprinted in 1911: the copy cannot tell which), "
                 f"{'its' if glyphs == 1 else 'their'} meaning not in doubt. ")
    if differs:
        text += f"Section~\\ref{{appell:sec:errata}} lists {'it' if len(differs) == 1 else 'them'} with the corrections. "
    established = [f"{tex_text(sentence)} ({', '.join(_claim_link(i) for i in ids)})"
                   for sentence, ids in BEYOND_FINDINGS if all(status.get(i) == "confirmed" for i in ids)]
    if established:
        text += "Beyond the paper, " + "; ".join(established) + "."
    return text.rstrip() + "\n"


def verification_tex(results: list[tuple[Claim, Verdict]]) -> str:
    """The record in sum: each claim's own verdict is under it; here the counts, and what failed."""
    counts = _status_counts(results)
    kinds = [c.erratum.kind for c, v in results if c.erratum is not None and v.status == "erratum"]
    how: dict[str, int] = {}
    for _, v in results:
        kind = re.sub(r" \(.*", "", v.symbolic)
        how[kind] = how.get(kind, 0) + 1
    # The findings count "numerical checks of our own" by kind of claim; here "numeric only" is a kind of check,
    # which some quoted claims get too (a referee read the two counts as disagreeing): say how they meet.
    own = sum(isinstance(c, NumericCheck) and not c.printed_tex and v.symbolic.startswith("numeric only")
              for c, v in results)
    of_own = {"numeric only": f" ({own} of them the numerical checks of our own)"} if own else {}
    how_text = ", ".join(f"{n} {plain_text(kind)}{of_own.get(kind, '') if n != own else ''}"
                         for kind, n in sorted(how.items(), key=lambda item: -item[1]))
    failed = [v for _, v in results if v.status == "failed"]
    text = (
        f"{len(results)} claims: {counts['confirmed']} confirmed, {counts['erratum']} differ from the print "
        f"({errata_summary(kinds)}), {counts['failed']} failed. How they were checked: {how_text}. "
        "\\texttt{appell verify --json} prints the record, and the supplement \\texttt{supplement.json} holds every "
        "claim's forms as SymPy expressions (\\texttt{srepr}) and LaTeX."
    )
    if failed:
        text += " Failed: " + "; ".join(f"\\texttt{{{identifier(v.id)}}} ({tex_text(v.note)})" for v in failed) + "."
    return heading("Verification record", "verification") + text + "\n"


def displayed_symbols(results: list[tuple[Claim, Verdict]]) -> list:
    """Every symbol a display of the appendix shows, in the order of the claims that first show it (the table lists
    the quantities named for a check in that order: sorted by their words, "the product of the two roots" came
    between "the pivot couple" and "the variable of the normal form"), the notation table defines them."""
    symbols: dict = {}  # an ordered set

    def show(found) -> None:
        for symbol in sorted(found, key=str):  # within one claim, a fixed order
            symbols.setdefault(symbol)

    for claim, _ in results:
        if isinstance(claim, NumericCheck):
            continue
        try:
            trees = claim_blocks.derived_trees(claim) if not claim.glyph_only else []
        except Exception:  # a claim whose derivation raised shows no form
            continue
        # A glyph-only record shows the printed LaTeX with one glyph replaced, not its SymPy form (whose label,
        # t_max, no display shows: the table listed it).
        corrected = [] if claim.glyph_only else list(claim.corrected or [])
        # The reading of a sentence, shown above the derived form (Read as).
        read = list(claim.reading or claim.printed) if claim_blocks.read_in_words(claim) else []
        for form in read + trees + corrected + list(claim.display_where):
            show(form.free_symbols)
        for value in claim.display_where.values():
            show(value.free_symbols)
        if claim.is_inequality and not claim.glyph_only:
            show(set().union(*(r.rhs.free_symbols for r in (claim.printed if claim.erratum is None else claim.corrected))))
    return list(symbols)


INTRO = (
    "This appendix re-derives and checks every claim of Appell's paper on the billiard ball with rolling friction "
    "[appell1911], as printed in our transcription of it, with the Python package appell. Each claim reads as "
    "follows: its identifier and what it states; the form printed in the paper, quoted from the transcription "
    "(glyph errors of the transcription included); for an erratum, the form put right; the form derived from "
    "first principles, written as the paper arranges it (the check proves the form shown equal to the derived "
    "one); and the verdict, with what was checked. Equation numbers (1)–(14) are the paper's, on its own "
    "numbered equations; every other display is unnumbered."
)


def appendix_tex(sections: list[str]) -> str:
    parts = [
        "% Generated by `appell paper`; do not edit.  In the host's preamble: \\usepackage{appell-appendix}",
        "% (appell-appendix.sty, beside this file), with \\appellroot set to this folder; then \\input{\\appellroot/appendix}.",
        "\\begingroup\\emergencystretch=3em\\allowdisplaybreaks[1] % long identifiers; a long display may break",
        heading("Machine-checked companion to Appell (1911)", "appell", "section").rstrip(),
        # its running head, short (in a book's capitals the title overfilled it by 5 pt): a no-op unless the host
        # says where it goes (\\chaptermark in a thesis); no optional argument here, which IEEEtran's appendix refuses
        r"\appellsectionmark{Appell (1911), machine-checked}",
        _prose_with_refs(INTRO),
        "\\input{\\appellroot/generated/findings}",
        "\\input{\\appellroot/generated/methods}",
        "\\input{\\appellroot/generated/notation}",
    ]
    parts += [f"\\input{{\\appellroot/generated/{name}}}" for name in sections]
    parts += [
        "\\input{\\appellroot/generated/simulation}",
        "\\input{\\appellroot/generated/errata}",
        "\\input{\\appellroot/generated/verification}",
        "\\input{\\appellroot/generated/references}",
        "\\endgroup",
    ]
    return "\n\n".join(parts) + "\n"


MAIN = r"""% Generated by `appell paper`; do not edit.
\documentclass[11pt,a4paper]{article}
\usepackage[margin=2.2cm]{geometry}
\usepackage{appell-appendix}
\usepackage[hidelinks]{hyperref}
\title{Appell (1911), \emph{Sur le mouvement d'une bille de billard avec frottement de roulement}:\\
a machine-checked companion}
\author{generated by \texttt{appell paper}}
\date{}
\begin{document}
\maketitle
\input{appendix}
\end{document}
"""


class GenerationError(ValueError):
    """The generated LaTeX breaks a rule of the appendix (a paper tag twice, an unprefixed label…)."""


def check_latex(files: dict[str, str]) -> None:
    """The rules the LaTeX of the appendix keeps, checked before anything is written: each of the paper's
    equation numbers at most once, every label prefixed appell: and defined once, every \\ref to one of them."""
    text = "\n".join(body for name, body in files.items() if name.endswith(".tex") and not name.startswith("hosts/"))
    for wide in (True, False):  # as a one-column page reads it, and as a narrow column does (`claim_blocks.fitted`)
        _check_labels(claim_blocks.one_layout(text, wide))


def _check_labels(text: str) -> None:
    tags = re.findall(r"\\(?:appell)?tag\{([^}]*)\}", text)  # \appelltag: Appell's numbers (appell-appendix.sty)
    repeated = sorted({t for t in tags if tags.count(t) > 1}, key=lambda t: int(t) if t.isdigit() else 0)
    if repeated:
        raise GenerationError(f"the paper's equation number(s) {', '.join(f'({t})' for t in repeated)} shown more than once")
    labels = re.findall(r"\\label\{([^}]*)\}", text)
    unprefixed = [label for label in labels if not label.startswith("appell:")]
    if unprefixed:
        raise GenerationError(f"label(s) without the appell: prefix: {', '.join(unprefixed)}")
    twice = sorted({label for label in labels if labels.count(label) > 1})
    if twice:
        raise GenerationError(f"label(s) defined more than once: {', '.join(twice)}")
    defined = set(labels)
    referred = set(re.findall(r"\\(?:ref|eqref|pageref)\{([^}]*)\}", text)) | set(re.findall(r"\\appellref\{([^}]*)\}", text))
    referred |= {f"appell:bib:{key}" for key in re.findall(r"\\appellcite\{([^}]*)\}", text)}
    missing = sorted(referred - defined)
    if missing:
        raise GenerationError(f"reference(s) to undefined label(s): {', '.join(missing)}")


def generate(out: Path, results: list[tuple[Claim, Verdict]] | None = None, figures: bool = True,
             progress=None) -> list[Path]:
    """Write every file of the appendix under ``out`` (only ever replacing appell's own files,
    `paper.output`); return them.  ``progress(line)`` names each stage as it starts."""
    from paper import bibliography, latex_hosts, methods, notation_table, output, record, supplement, verification
    from paper import figures as figs

    progress = progress or (lambda line: None)
    output.check_destination(out)  # before minutes of work
    if results is None:  # the kept record when it matches the source: the checks are the same
        results = verification.results_from(verification.recorded())
    progress("sections, claim by claim")
    sections = section_fragments(results)
    files = {f"generated/{name}": text for name, text in sections.items()}
    files["generated/findings.tex"] = findings_tex(results)
    files["generated/methods.tex"] = methods.methods_tex(heading, record.source_key())
    files["generated/notation.tex"] = notation_table.notation_tex(displayed_symbols(results), heading, cite)
    files["generated/simulation.tex"] = simulation_tex()
    files["generated/errata.tex"] = errata_tex(results)
    files["generated/verification.tex"] = verification_tex(results)
    files["generated/references.tex"] = bibliography.references_tex(heading)
    progress("methods, notation, simulation, errata, references, supplement")
    files["generated/supplement.json"] = supplement.supplement_json(results)
    files["appendix.tex"] = appendix_tex([name[:-4] for name in sections])
    files["main.tex"] = MAIN
    files.update(latex_hosts.files())
    check_latex(files)

    def draw(staging: Path) -> None:
        progress("figures")
        (staging / "figures").mkdir(parents=True, exist_ok=True)
        figs.shots(staging / "figures" / "shots.pdf")
        figs.phases_in_time(staging / "figures" / "phases.pdf")
        figs.end_of_sliding(staging / "figures" / "end_of_sliding.pdf")
        figs.work_precision(saved_bench(), staging / "figures" / "work_precision.pdf")
        figs.sample_motion(staging / "figures" / "sample_motion.png")

    return output.write(Path(out), files, draw if figures else None, products=pdf_products())


def pdf_products() -> tuple[str, ...]:
    """What pdflatex writes beside main.tex and each host document when `--pdf` compiles them."""
    from paper import latex_hosts, output

    return output.PDF_PRODUCTS + tuple(latex_hosts.products())


def stale(paper_dir: Path = PAPER, out: Path | None = None, results=None, figures: bool = True,
          progress=None) -> list[str]:
    """The files of ``paper_dir`` that regeneration (into ``out``, or a temporary folder) would change, add
    or no longer produce."""
    from paper import output

    with tempfile.TemporaryDirectory() as tmp:
        target = Path(out) if out is not None else Path(tmp)
        fresh = generate(target, results, figures, progress)
        changed = []
        for path in fresh:
            rel = path.relative_to(target)
            committed = paper_dir / rel
            if not committed.exists() or not filecmp.cmp(path, committed, shallow=False):
                changed.append(str(rel))
        produced = {str(p.relative_to(target)) for p in fresh}
        present = set(output.owned(paper_dir) or ()) | {
            str(path.relative_to(paper_dir)) for pattern in ("generated/*", "figures/*.pdf", "figures/*.png", "hosts/*.tex")
            for path in paper_dir.glob(pattern)
        }
        for rel in sorted(present - produced - set(pdf_products())):
            if (rel.startswith("figures/") and not figures) or not (paper_dir / rel).exists():
                continue
            changed.append(rel + " (no longer generated)")
        return changed


def compile_pdf(folder: Path, progress=None) -> dict[str, dict] | None:
    """Compile main.tex and every host document in ``folder``: per document, its problems (errors,
    undefined or multiply-defined labels, overfull boxes, hyperref warnings) and its page count; None
    when pdflatex is missing.  What pdflatex will write is claimed first (`output.claim_products`): a file of that
    name appell did not write is refused, not overwritten."""
    from paper import latex_hosts, output

    output.claim_products(folder, pdf_products())
    fragments = "".join(path.read_text() for path in (Path(folder) / "generated").glob("*.tex"))
    included = [name for name in FIGURES if f"figures/{name}.pdf" in fragments]  # a section may be absent
    return latex_hosts.compile_all(folder, included, progress)

