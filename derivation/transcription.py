"""The tie between a claim's printed LaTeX (quoted from the transcription) and our SymPy reading of it.

A claim's printed form is typed twice: as LaTeX quoted verbatim from the OCR
transcription (what the reader compares with the paper) and as a SymPy
reading (what the checks use).  If the reading put right a glyph the LaTeX
has wrong (δ typed where the transcription has ∂), the erratum would be
hidden.  So for every printed form that is an equation (not French prose),
the two must name the same letters: the glyphs of the LaTeX (Greek letters,
Latin letters, the OCR's ∂, ĉ, ξ̇) are compared with those of the SymPy form
printed in the paper's notation.  Structure (fractions, brackets, sin, cos)
is ignored; only which letters occur is compared, which is what a glyph
confusion changes.
"""

from __future__ import annotations

import re

import sympy as sp

# LaTeX commands that are structure or functions, not letters of the paper.
STRUCTURE = {
    "frac", "left", "right", "quad", "qquad", "cdot", "mathbf", "leq", "geq", "sqrt", "text", "dfrac", "tfrac",
    "mathrm", "operatorname", "ldots", "dots", "infty", "cos", "sin", "tan", "log", "ln", "exp", "limits",
    "pi",  # π is a number, not a letter of the paper
}
# The same letter written two ways; ± and ∓ in the paper are the sign of r (the symbol s_r).
SAME = {"varepsilon": "epsilon", "pm": "s", "mp": "s", "varphi": "phi"}
PROSE = re.compile(r"[a-zA-Zéèàêôçù]{4,}")
# Environments and operator names are structure, not words: \begin{cases}, \operatorname{tang}.
NAMED_GROUP = re.compile(r"\\(begin|end|operatorname)\{\w+\}")


def glyphs(tex: str) -> set[str]:
    """The letters a LaTeX formula names: command names of Greek letters and glyphs, single Latin letters.

    Leibniz's dX/dt is the paper's X' (its accent is the derivative in t), dt and d alone are
    differentials, never quantities of the paper.
    """
    tex = re.sub(r"\\frac\{d\s*(\\?[a-zA-Z]+)\}\{d\s*t\}", r" \1 ", tex)
    tex = re.sub(r"(?<![a-zA-Z\\])d\s*t(?![a-zA-Z])", " ", tex)  # the differential dt of the paper's dX = … dt
    tex = re.sub(r"\\(dot|hat)\{\\?([a-zA-Z]+)\}", lambda m: f" \\{m.group(1)}{m.group(2)} ", tex)  # ξ̇, ĉ: one glyph
    tex = NAMED_GROUP.sub(" ", tex)
    found = set()
    for command, letter in re.findall(r"\\([a-zA-Z]+)|([a-zA-Z])", tex):
        if command and command not in STRUCTURE:
            found.add(SAME.get(command, command))
        elif letter and letter != "d":
            found.add(letter)
    return found


def is_prose(tex: str) -> bool:
    """Whether the printed text is a sentence of the paper (its formulas in $…$), not a formula.

    A quote that is one formula in $…$ and nothing else (n°8's $\\hat{c} < fR$) is a formula: its
    letters are tied like any other's.  Any word beside a $…$ (si $a = c$) makes it a sentence.
    """
    outside = NAMED_GROUP.sub(" ", re.sub(r"\$[^$]*\$", " ", tex))
    words = re.sub(r"\\[a-zA-Z]+", " ", outside)
    if "$" in tex:
        return bool(re.search(r"[a-zA-Zéèàêôçù]", words))
    return bool(PROSE.search(words))


def mismatch(tex: str, forms: list) -> str | None:
    """None when the LaTeX ``tex`` and the SymPy ``forms`` name the same letters (or ``tex`` is prose),
    else what differs.

    A label (our name for a quantity, such as t_max) may or may not appear in the LaTeX; every other
    symbol of the forms must, and every letter of the LaTeX must be one of the forms' symbols or labels.
    """
    from derivation.notation import latex
    from derivation.symbols import LABEL_TEX

    if is_prose(tex):
        return None
    tex = tex.replace("$", " ")
    symbols = set().union(*(sp.sympify(f).free_symbols for f in forms))
    named = set().union(set(), *(glyphs(latex(x)) for x in symbols if x.name not in LABEL_TEX))
    labels = set().union(set(), *(glyphs(LABEL_TEX[x.name]) for x in symbols if x.name in LABEL_TEX))
    in_tex = glyphs(tex)
    parts = []
    if in_tex - named - labels:
        parts.append(f"in the transcription only: {', '.join(sorted(in_tex - named - labels))}")
    if named - in_tex:
        parts.append(f"in the SymPy reading only: {', '.join(sorted(named - in_tex))}")
    return "; ".join(parts) or None


def check(claim) -> str | None:
    """What is wrong between a claim and the transcription (None: nothing).

    The printed LaTeX must stand verbatim in the transcription; its letters must be those of the
    printed SymPy form; for a transcription artefact, the corrected LaTeX's letters those of the
    corrected form.
    """
    from derivation import seed

    if claim.context is not None and not seed.quotes(claim.context):
        return "the context is not quoted verbatim from the transcription"
    if claim.context is not None and claim.printed_tex is not None:
        return "a claim the paper states has no context: the printed form is its quote"
    if claim.printed_tex is None:
        return None
    if not seed.quotes(claim.printed_tex):
        return "the printed LaTeX is not quoted verbatim from the transcription"
    problem = mismatch(claim.printed_tex, claim.printed)
    if problem:
        return f"printed LaTeX and SymPy reading differ ({problem})"
    if claim.erratum is not None and claim.erratum.kind == "ocr":
        problem = mismatch(claim.corrected_tex, claim.corrected)
        if problem:
            return f"corrected LaTeX and corrected form differ ({problem})"
    return None
