"""`appell paper`: the LaTeX appendix, assembled from generated fragments (showyourwork's pattern).

Every equation comes from a claim's SymPy object through the one printer of
`derivation.notation`; text comes from the claims' statements; the tables
from the verification record; the figures from `paper.figures`.  Nothing is
typed twice, and the output is deterministic: `--check` regenerates into a
temporary folder and compares bytes.

Layout of ``paper/`` (all generated, all committed):

    main.tex             a standalone article: \\input{appendix.tex}
    appendix.tex         the appendix another paper can \\input (set \\appellroot to this folder)
    generated/*.tex      one fragment per section, the errata and the verification tables
    figures/*.pdf        the figures
"""

from __future__ import annotations

import filecmp
import re
import shutil
import tempfile
from pathlib import Path

from derivation.claim import ERRATUM_CLASSES, Claim, NumericCheck, Verdict, errata_summary
from derivation import transcription
from derivation.notation import latex

PAPER = Path(__file__).resolve().parent

# The sections of the paper (n°1 is the introduction), then what goes beyond it.
TITLES = {
    "n°2": "The equations of motion",
    "n°3": "No rolling friction: the classical motion",
    "n°4": "No sliding friction",
    "n°5": "The hypothesis $\\delta < fR$ (9): what needs it, what survives without it",
    "n°6": "The rotation that vanishes comes back",
    "n°7": "Pure rolling",
    "n°8": "The general case: the slide ends, the integral (11), the energy",
    "n°9": "The reduced system (12)--(14)",
    "n°10": "The special case $a = c$",
    "n°11": "The Abel equation",
}
BEYOND = "beyond"  # claims whose where starts so: each "beyond …: topic" is a subsection

# Unicode in statements, as LaTeX (pdflatex reads bytes): an unknown character is an error, not a blank.
TEXT_MAP = {
    "α": r"$\alpha$", "β": r"$\beta$", "γ": r"$\gamma$", "δ": r"$\delta$", "ε": r"$\varepsilon$", "ζ": r"$\zeta$",
    "η": r"$\eta$", "θ": r"$\theta$", "κ": r"$\kappa$", "λ": r"$\lambda$", "μ": r"$\mu$", "ξ": r"$\xi$",
    "π": r"$\pi$", "ρ": r"$\rho$", "σ": r"$\sigma$", "τ": r"$\tau$", "φ": r"$\varphi$", "ψ": r"$\psi$",
    "ω": r"$\omega$", "Ω": r"$\Omega$", "Δ": r"$\Delta$", "Φ": r"$\Phi$", "ĉ": r"\^{c}", "∂": r"$\partial$",
    "≤": r"$\leq$", "≥": r"$\geq$", "≠": r"$\neq$", "≈": r"$\approx$", "≡": r"$\equiv$", "∝": r"$\propto$",
    "→": r"$\to$", "↦": r"$\mapsto$", "±": r"$\pm$", "∓": r"$\mp$", "∞": r"$\infty$", "√": r"$\surd$",
    "∫": r"$\int$", "·": r"$\cdot$\allowbreak{}", "×": r"$\times$", "−": "$-$", "–": "--", "—": "---", "’": "'", "‘": "`",
    "“": "``", "”": "''", "…": r"\dots{}", "°": r"\textsuperscript{o}", "²": r"$^2$", "³": r"$^3$", "⁵": r"$^5$",
    "₀": r"$_0$", "₁": r"$_1$", "₂": r"$_2$", "₃": r"$_3$", "₅": r"$_5$", "ᵏ": r"$^k$", "′": "'", "é": r"\'e",
    "è": r"\`e", "à": r"\`a", "ç": r"\c{c}", "ê": r"\^e", "ô": r"\^o", "î": r"\^{\i}", "ù": r"\`u", "É": r"\'E",
    "ĳ": "ij", "∈": r"$\in$", "∉": r"$\notin$", "⊂": r"$\subset$", "∀": r"$\forall$", "∃": r"$\exists$",
    "ℓ": r"$\ell$", "½": r"$\frac12$", "∑": r"$\sum$", "∏": r"$\prod$", "⁻": r"$^-$", "¹": r"$^1$", "⁴": r"$^4$", "ν": r"$\nu$",
}
SPECIAL = {"<": "$<$", ">": "$>$", "|": "$|$", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}",
           "^": r"\textasciicircum{}", "\\": r"\textbackslash{}"}


def tex_text(text: str) -> str:
    """Plain text (statements, reasons) as LaTeX source for pdflatex."""
    out = []
    for ch in text:
        if ch in SPECIAL:
            out.append(SPECIAL[ch])
        elif ord(ch) < 128:
            out.append(ch)
        elif ch in TEXT_MAP:
            out.append(TEXT_MAP[ch])
        elif ch == "\u0307" and out and out[-1].startswith("$"):  # combining dot above: ξ̇
            out[-1] = "$\\dot{" + out[-1][1:-1] + "}$"
        else:
            raise ValueError(f"no LaTeX for {ch!r} (U+{ord(ch):04X}) in: {text}")
    return "".join(out).replace("$$", "")  # adjacent math pieces merge


def section_of(where: str) -> str:
    """The paper's section a claim belongs to ("n°7"), or its part beyond the paper ("beyond n°8: straight shots")."""
    if where.startswith("beyond"):
        return where
    match = re.match(r"n°(\d+)", where)
    return f"n°{match.group(1)}" if match else BEYOND


def _tag(where: str) -> str | None:
    match = re.search(r"eq\. \((\d+)\)", where)
    return match.group(1) if match else None


def _display(body: str, tag: str | None) -> str:
    """A displayed equation that shrinks to the line width rather than overflow the margin."""
    tag_tex = f"\\tag{{{tag}}}" if tag else ""
    return (
        "\\begin{equation*}" + tag_tex + "\n"
        "\\appellfit{$\\displaystyle " + body + "$}\n"
        "\\end{equation*}\n"
    )


LONG = 2500  # characters of LaTeX beyond which an equation is not worth printing (nor can TeX box it)


def _form_tex(form) -> str:
    """An equation's LaTeX, or for a huge one its left side and the size of the right."""
    import sympy as sp

    body = latex(form)
    if len(body) <= LONG or not isinstance(form, sp.Eq):
        return body
    size = sp.count_ops(form.rhs)
    return latex(form.lhs) + r" = \text{(an expression of " + str(size) + r" operations: too long to print)}"


SPLIT = 400  # characters of LaTeX beyond which an equation's two sides get a line each


def _display_form(form, tag: str | None) -> str:
    """A derived form displayed; a long equation as its left side, then '= right side', each fitted."""
    import sympy as sp

    body = _form_tex(form)
    if len(body) <= SPLIT or not isinstance(form, sp.Eq) or len(body) > LONG:
        return _display(body, tag)
    return _display(latex(form.lhs) + " = {}", tag) + _display("{} = " + latex(form.rhs), None)


def _prose(tex: str) -> str:
    """A sentence of the paper: its words as text, its $…$ formulas as they are."""
    parts = re.split(r"(\$[^$]*\$)", tex)
    return "".join(part if part.startswith("$") else tex_text(" ".join(part.split(" "))) for part in parts)


def _claim_block(claim, verdict: Verdict) -> str:
    lines = [f"\\paragraph{{{_breakable(claim.id)}}} {tex_text(claim.statement)}"]
    tag = _tag(claim.where)
    if isinstance(claim, NumericCheck):
        if claim.printed_tex and transcription.is_prose(claim.printed_tex):
            lines.append(f"\\begin{{quote}}``{_prose(claim.printed_tex)}''\\end{{quote}}")
        elif claim.printed_tex:
            lines.append(_display(claim.printed_tex.rstrip(". ").rstrip(","), tag))
        lines.append(f"\\emph{{Checked numerically: {tex_text(verdict.numeric)}; {verdict.status}.}}")
        return "\n".join(lines) + "\n"
    try:
        derived = claim.derived
    except Exception:  # its check failed with the reason; there is no derived form to show
        error = verdict.note.partition(":")[0]
        lines.append(f"\\emph{{Not derived: the derivation raised {tex_text(error)}; {verdict.status}.}}")
        return "\n".join(lines) + "\n"
    for k, form in enumerate(derived):
        lines.append(_display_form(form, tag if k == 0 else None))
    if claim.erratum is not None:
        lines.append(f"\\emph{{The printed form differs ({ERRATUM_CLASSES[claim.erratum.kind]}): see the errata table.}}")
    return "\n".join(lines) + "\n"


def section_fragments(results: list[tuple[Claim, Verdict]]) -> dict[str, str]:
    """File name -> LaTeX, one fragment per section in the order of the paper."""
    groups: dict[str, list] = {}
    for claim, verdict in results:
        groups.setdefault(section_of(claim.where), []).append((claim, verdict))
    order = [key for key in TITLES if key in groups]
    # Beyond the paper: by the section each part goes beyond (then in the order of the claims).
    beyond = [key for key in groups if key not in order]
    order += sorted(beyond, key=lambda key: int(m.group(1)) if (m := re.search(r"n°(\d+)", key)) else 99)
    out = {}
    for key in order:
        if key in TITLES:
            name, heading = key.replace("n°", "n"), f"{tex_text(key)} --- {TITLES[key]}"
        else:
            name = re.sub(r"[^a-z0-9]+", "_", key.replace("n°", "n").lower()).strip("_")
            heading = tex_text(key[0].upper() + key[1:])
        head = f"\\subsection{{{heading}}}\n\\label{{sec:{name}}}\n\n"
        out[f"{name}.tex"] = head + "\n".join(_claim_block(c, v) for c, v in groups[key])
    return out


def _math_cell(tex: str) -> str:
    """Printed TeX for a table cell: alignment marks need an aligned environment of their own."""
    tex = tex.strip().rstrip(".").rstrip(",")
    if "$" in tex:  # printed as text with inline maths: a text cell
        return "\\raggedright " + tex
    if "&" in tex and "\\begin{" not in tex:
        tex = "\\begin{aligned}" + tex + "\\end{aligned}"
    return "\\appellfitcol{" + tex + "}"


def _breakable(text: str) -> str:
    """An identifier that may break after its dots and underscores (narrow table columns)."""
    return tex_text(text).replace(".", ".\\allowbreak{}").replace("\\_", "\\_\\allowbreak{}")


def errata_table(results: list[tuple[Claim, Verdict]]) -> str:
    from paper import errata

    rows = []
    for e in errata.errata(results):
        rows.append(
            f"{_breakable(e['id'])} & {tex_text(e['where'])} & {_math_cell(e['printed'])} & "
            f"{_math_cell(e['corrected'])} & {tex_text(e['class'])}: {tex_text(e['reason'])} \\\\"
        )
    return (
        "\\begin{longtable}{@{}>{\\raggedright}p{0.12\\linewidth}>{\\raggedright}p{0.1\\linewidth}p{0.23\\linewidth}p{0.23\\linewidth}>{\\raggedright\\arraybackslash}p{0.2\\linewidth}@{}}\n"
        "\\caption{Errata: the printed form (as transcribed) beside the derived one.}\\label{tab:errata}\\\\\n"
        "\\toprule claim & where & printed & derived & class and reason \\\\ \\midrule\\endhead\n"
        + "\n".join(rows) + "\n\\bottomrule\n\\end{longtable}\n"
    )


def verification_table(results: list[tuple[Claim, Verdict]]) -> str:
    rows = [
        f"{_breakable(v.id)} & {tex_text(v.where)} & {tex_text(v.symbolic)} & {tex_text(v.numeric)} & {v.status} \\\\"
        for _, v in results
    ]
    counts = {s: sum(v.status == s for _, v in results) for s in ("confirmed", "erratum", "failed")}
    kinds = [c.erratum.kind for c, v in results if c.erratum is not None and v.status == "erratum"]
    return (
        "\\begin{longtable}{@{}>{\\raggedright}p{0.22\\linewidth}>{\\raggedright}p{0.2\\linewidth}>{\\raggedright}p{0.1\\linewidth}>{\\raggedright}p{0.27\\linewidth}>{\\raggedright\\arraybackslash}p{0.1\\linewidth}@{}}\n"
        f"\\caption{{Verification record: {len(results)} claims, {counts['confirmed']} confirmed, "
        f"{counts['erratum']} printed differently ({errata_summary(kinds)}), {counts['failed']} failed.}}\\label{{tab:verification}}\\\\\n"
        "\\toprule claim & where & symbolic & numeric & status \\\\ \\midrule\\endhead\n"
        + "\n".join(rows) + "\n\\bottomrule\n\\end{longtable}\n"
    )


PREAMBLE = r"""% Generated by `appell paper`; do not edit.
\documentclass[11pt,a4paper]{article}
\usepackage[margin=2.2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage{longtable,booktabs,array}
\usepackage[hidelinks]{hyperref}
\newcommand{\appellroot}{.}
"""

MACROS = r"""% Displayed maths never wider than the line (or a table column): shrunk, never cut.
\providecommand{\appellroot}{.}
\providecommand{\appellfit}[1]{\sbox0{#1}\ifdim\wd0>\linewidth\resizebox{\linewidth}{!}{\usebox0}\else\usebox0\fi}
\providecommand{\appellfitcol}[1]{\sbox0{$\displaystyle #1$}\ifdim\wd0>\linewidth\resizebox{\linewidth}{!}{\usebox0}\else\usebox0\fi}
"""


def appendix_tex(sections: list[str]) -> str:
    parts = [
        "% Generated by `appell paper`; do not edit. Needs amsmath, graphicx, longtable, booktabs.",
        MACROS,
        "\\begingroup\\emergencystretch=3em % long identifiers and formulas in running text",
        "\\section{A machine-checked companion to Appell (1911)}\\label{sec:appell}",
        "Every equation below was generated from the SymPy object that the package \\texttt{appell} derives "
        "from Newton--Euler and checks against the printed paper (exactly and at 30 digits); equation numbers "
        "are the paper's. Section~\\ref{sec:errata} lists where the printed paper does not follow, "
        "Section~\\ref{sec:verification} how each claim was checked.",
    ]
    parts += [f"\\input{{\\appellroot/generated/{name}}}" for name in sections]
    parts += [
        "\\subsection{Figures}\\label{sec:figures}",
        _figure("shots", "The centre's path for five pool shots under Appell's model (solid) and the classical "
                "model without rolling couple while sliding (dashed); \\texttt{appell compare}."),
        _figure("phases", "Slip speed $V$, rotation $\\Omega$ and $\\theta = \\beta - \\alpha$ through sliding and "
                "rolling for the sample scene; \\texttt{appell simulate}."),
        _figure("end_of_sliding", "Near the end of sliding $\\pi/2 - \\theta \\propto V^\\kappa$ (n\\textsuperscript{o}8)."),
        _figure("work_precision", "Work against precision on the benchmark scenes; \\texttt{appell bench}."),
        "\\subsection{Errata}\\label{sec:errata}",
        "\\input{\\appellroot/generated/errata}",
        "\\subsection{Verification record}\\label{sec:verification}",
        "\\input{\\appellroot/generated/verification}",
        "\\endgroup",
    ]
    return "\n\n".join(parts) + "\n"


def _figure(name: str, caption: str) -> str:
    return (
        "\\begin{figure}[htbp]\\centering\n"
        f"\\includegraphics[width=\\linewidth]{{\\appellroot/figures/{name}.pdf}}\n"
        f"\\caption{{{caption}}}\\label{{fig:{name}}}\n\\end{{figure}}"
    )


MAIN = PREAMBLE + r"""
\title{Appell (1911), \emph{Sur le mouvement d'une bille de billard avec frottement de roulement}:\\
a machine-checked companion}
\author{generated by \texttt{appell paper}}
\date{}
\begin{document}
\maketitle
\input{appendix.tex}
\end{document}
"""


def generate(out: Path, results: list[tuple[Claim, Verdict]] | None = None, figures: bool = True) -> list[Path]:
    """Write every file of the appendix under ``out`` (only ever replacing appell's own files,
    `paper.output`); return them."""
    import json

    from paper import figures as figs
    from paper import output, verification

    output.check_destination(out)  # before minutes of work
    if results is None:  # the kept record when it matches the source: the checks are the same
        results = verification.results_from(verification.recorded())
    sections = section_fragments(results)
    files = {f"generated/{name}": text for name, text in sections.items()}
    files["generated/errata.tex"] = errata_table(results)
    files["generated/verification.tex"] = verification_table(results)
    files["appendix.tex"] = appendix_tex([name[:-4] for name in sections])
    files["main.tex"] = MAIN

    def draw(staging: Path) -> None:
        (staging / "figures").mkdir(parents=True, exist_ok=True)
        figs.shots(staging / "figures" / "shots.pdf")
        figs.phases_in_time(staging / "figures" / "phases.pdf")
        figs.end_of_sliding(staging / "figures" / "end_of_sliding.pdf")
        bench = json.loads((figs.DATA / "bench.json").read_text())
        figs.work_precision(bench, staging / "figures" / "work_precision.pdf")

    return output.write(Path(out), files, draw if figures else None)


def stale(paper_dir: Path = PAPER, out: Path | None = None, results=None, figures: bool = True) -> list[str]:
    """The files of ``paper_dir`` that regeneration (into ``out``, or a temporary folder) would change or add."""
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(out) if out is not None else Path(tmp)
        fresh = generate(target, results, figures)
        changed = []
        for path in fresh:
            rel = path.relative_to(target)
            committed = paper_dir / rel
            if not committed.exists() or not filecmp.cmp(path, committed, shallow=False):
                changed.append(str(rel))
        produced = {str(p.relative_to(target)) for p in fresh}
        for folder, pattern in (("generated", "*.tex"), ("figures", "*.pdf")):
            if folder == "figures" and not figures:
                continue
            for path in sorted((paper_dir / folder).glob(pattern)):
                rel = str(path.relative_to(paper_dir))
                if rel not in produced:
                    changed.append(rel + " (no longer generated)")
        return changed


def compile_pdf(folder: Path) -> list[str] | None:
    """pdflatex main.tex twice in ``folder``: the problems found (errors, undefined references,
    overfull lines), [] when clean, None when pdflatex is missing."""
    import subprocess

    if shutil.which("pdflatex") is None:
        return None
    for _ in range(2):  # the second run settles references and longtables
        run = subprocess.run(
            ["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "main.tex"],
            cwd=folder, capture_output=True, text=True, check=False,
        )
        if run.returncode != 0:
            return [line for line in run.stdout.splitlines() if line.startswith(("!", "l."))] or [run.stdout[-2000:]]
    log = (Path(folder) / "main.log").read_text(errors="replace")
    return [
        line for line in log.splitlines()
        if "undefined" in line.lower() or line.startswith("Overfull") or "Rerun to get" in line
    ]
