"""One claim in the appendix: its statement, the printed form, the derived form and the verdict.

A referee compares a claim as printed (quoted from the transcription of
Appell 1911) with what the package derives, and reads what was checked.  So
each claim is stacked, not tabulated (table columns break in two-column
journals):

    claim id — statement
    Printed (transcription): the quoted LaTeX (a sentence of the paper as a quotation)
    Corrected: for an erratum, the printed form put right (a glyph replaced, or the SymPy correction)
    Derived: the derived form in the paper's arrangement (`paper.display`), an inequality as one
    Verdict: in words, with what was checked as the record says it (exact, proved, n digits at m points …)

Only the paper's own numbered equations (the claims eq1 … eq14) carry the
paper's numbers, each once; every other display is unnumbered.  A display
too long for a column even when broken is not shrunk: the block says so and
points to the supplement (`paper.supplement`), which holds every form in full.
"""

from __future__ import annotations

import re

import sympy as sp

from derivation import checks, transcription, translation
from derivation.claim import ERRATUM_CLASSES, Claim, NumericCheck, Verdict, evaluated
from paper import display
from paper.errata import checked
from paper.latex_text import identifier, plain_text, tex_text

SUPPLEMENT = "supplement.json"
RELATION = {"<": "<", "<=": r"\leq", ">": ">", ">=": r"\geq", "!=": r"\neq", "==": "="}


def tag_of(claim_id: str) -> str | None:
    """The paper's equation number, for the claims that are the paper's numbered equations."""
    match = re.fullmatch(r"eq(\d+)", claim_id)
    return match.group(1) if match else None


def label_of(claim_id: str) -> str:
    return "appell:claim:" + re.sub(r"[^A-Za-z0-9.:-]", "-", claim_id)


# ---------------------------------------------------------------------------------------------
# Displays.


def _environment(lines: list[str], tag: str | None) -> str:
    """Lines (``&`` before the first relation of each) as one display; tagged with the paper's number
    and labelled when ``tag`` is given."""
    if tag is not None:
        body = lines[0].replace("&", "") if len(lines) == 1 else r"\begin{aligned}" + r" \\ ".join(lines) + r"\end{aligned}"
        return rf"\begin{{equation*}}{body}\appelltag{{{tag}}}\label{{appell:eq:{tag}}}\end{{equation*}}"
    if len(lines) == 1:
        return rf"\begin{{equation*}}{lines[0].replace('&', '')}\end{{equation*}}"
    return r"\begin{align*}" + " \\\\\n".join(lines) + r"\end{align*}"


def _packed(rows: list[list[str]], budget: float) -> list[str] | None:
    """Each row laid out; short one-line rows side by side (u = ξ' − qR, v = η' + pR) while they fit."""
    lines: list[str] = []
    open_line = None  # the last line, if it holds only whole one-line rows
    for pieces in rows:
        laid = display.layout(pieces, budget)
        if laid.lines is None:
            return None
        if len(laid.lines) == 1 and open_line is not None:
            joined = open_line + r",\quad " + laid.lines[0].replace("&", "")
            if display.tex_width(joined) <= budget:
                lines[-1] = open_line = joined
                continue
        lines += laid.lines
        open_line = laid.lines[0] if len(laid.lines) == 1 else None
    return lines


def forms_display(rows: list[list[str]], tag: str | None = None) -> str | None:
    """A display of the rows (each a list of break points, `display.relation_pieces`), laid out for a narrow
    column and for a one-column page (`fitted`); None when one cannot be broken to fit a narrow column."""
    narrow = _laid(rows, tag, display.COLUMN)
    return None if narrow is None else fitted(_laid(rows, tag, display.ONE_COLUMN), narrow)


def _laid(rows: list[list[str]], tag: str | None, column: float) -> str | None:
    lines = _packed(rows, column - (display.TAG_ROOM if tag else 0.0))
    return None if lines is None else _environment(lines, tag)


WIDE_OR_NARROW = r"\appellwideornarrow{"  # appell-appendix.sty's: \appellwideornarrow{wide}{narrow}


def fitted(wide: str | None, narrow: str) -> str:
    """One display, or both layouts where they differ: ``\\appellwideornarrow{wide}{narrow}``, which the style
    file resolves by the width of the line it stands on (a two-column journal's column takes the narrow one)."""
    return narrow if wide is None or wide == narrow else f"{WIDE_OR_NARROW}{wide}}}{{{narrow}}}"


def one_layout(text: str, wide: bool) -> str:
    """The LaTeX as a line of one width reads it: each ``\\appellwideornarrow{wide}{narrow}`` its wide display
    or its narrow one."""
    out, start = [], 0
    while (at := text.find(WIDE_OR_NARROW, start)) >= 0:
        first_end = _group_end(text, at + len(WIDE_OR_NARROW) - 1)
        second_end = _group_end(text, first_end + 1)
        chosen = text[at + len(WIDE_OR_NARROW) : first_end] if wide else text[first_end + 2 : second_end]
        out += [text[start:at], chosen]
        start = second_end + 1
    return "".join(out) + text[start:]


def _group_end(text: str, at: int) -> int:
    """Where the brace group opening at ``at`` closes (escaped braces, \\{ and \\}, are no group's)."""
    if text[at] != "{":
        raise ValueError(f"no brace group at {at}: {text[at:at + 40]!r}")
    depth, i = 0, at
    while i < len(text):
        if text[i] == "\\":
            i += 2
            continue
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return i
        i += 1
    raise ValueError(f"an unclosed brace group at {at}: {text[at:at + 40]!r}")


def _trailing(tex: str) -> str:
    """The formula without the sentence's punctuation after it (but \\right. closes a brace)."""
    tex = tex.strip()
    while tex and tex[-1] in ".,;" and not tex.endswith(r"\right."):
        tex = tex[:-1].rstrip()
    return tex


def printed_rows(tex: str, mode: str = "sums") -> list[list[str]]:
    """The rows of a printed (or corrected) formula, each cut at its top-level signs for breaking:
    the environment (cases, aligned, a brace) taken off, rows at ``\\\\``, side-by-side equations at
    ``&``-columns and ``\\quad``.  ``mode`` says where else a row may break (see `_cut`)."""
    tex = _trailing(tex)
    tex = re.sub(r"\\left\\\{|\\right\.|\\begin\{\w+\}|\\end\{\w+\}", " ", tex)
    rows = []
    for row in re.split(r"\\\\", tex):
        for part in re.split(r"\\quad|(?<!\\)&(?!\s*[=<>]|\s*\\[lg]eq)", row):
            part = _trailing(part).replace("&", "")
            if part:
                rows.append(_cut(part, mode))
    return rows


def _cut(tex: str, mode: str = "sums") -> list[str]:
    """A formula cut before each top-level +, − or relation, ``&`` put before its first relation.  Never
    inside braces or a \\left…\\right pair; ``mode`` "sums": nor inside plain brackets; "products": also
    before a \\left-bracketed factor (the next line starts with ×); "brackets": inside plain brackets too
    (m[V² + …] may break inside its [ ], which are no \\left…\\right pair)."""
    opening, closing = ("{", "}") if mode == "brackets" else ("{([", "})]")
    pieces, current, depth, i = [], "", 0, 0
    first_relation = True
    while i < len(tex):
        ch = tex[i]
        if tex.startswith(r"\left", i) or (ch in opening and not tex[:i].endswith(("\\left", "\\"))):
            depth += 1
        elif tex.startswith(r"\right", i) or (ch in closing and not tex[:i].endswith(("\\right", "\\"))):
            depth -= 1
        relation = re.match(r"=|<|>|\\leq|\\geq", tex[i:])
        factor = mode == "products" and tex.startswith(r"\left", i) and not first_relation
        if depth == 1 and factor and current.strip() and not re.search(r"[-+=(\[{^_]\s*$", current):
            pieces.append(current.strip())
            current = r"\times "
        elif depth == 0 and (ch in "+-" or relation) and current.strip() and not re.search(r"[=(\[{^_]\s*$|\\left[\(\[]\s*$|\\times\s*$", current):
            pieces.append(current.strip())
            current = ""
            if relation and first_relation:
                current = "&"
                first_relation = False
        current += ch
        i += 1
    pieces.append(current.strip())
    if first_relation:  # no relation: nothing to align on
        return pieces
    return _merged_lhs(pieces)


def _merged_lhs(pieces: list[str]) -> list[str]:
    """The left side is not a break point: it joins the relation and first term that follow it."""
    for k, piece in enumerate(pieces):
        if piece.startswith("&"):
            head = " ".join(pieces[:k]) + " " + piece
            return [head.strip()] + pieces[k + 1 :]
    return pieces


def printed_display(tex: str) -> str:
    """A printed formula as a display: as transcribed where it fits, else its rows broken at their
    top-level signs, for a narrow column and for a one-column page (`fitted`); the glyphs are the
    transcription's, only the line breaks are ours."""
    body = _trailing(tex)
    width = display.tex_width(body)
    if "&" in body and r"\begin" not in body:
        body = r"\begin{aligned}" + body + r"\end{aligned}"
    whole = rf"\begin{{equation*}}{body}\end{{equation*}}"
    if width <= display.COLUMN:
        return whole
    for mode in ("sums", "products", "brackets"):
        rows = printed_rows(tex, mode)
        narrow = _laid(rows, None, display.COLUMN)
        if narrow is not None:  # on a page's line: whole if it fits, else broken there too
            return fitted(whole if width <= display.ONE_COLUMN else _laid(rows, None, display.ONE_COLUMN), narrow)
    raise ValueError(f"a printed form too wide for a column even broken: {tex[:80]}")


def _sentence(tex: str) -> str:
    """Words as text (no maths guessed in French), $…$ as they are, a display $$…$$ set in the line."""
    parts = re.split(r"(\$\$[^$]*\$\$|\$[^$]*\$)", tex)
    return "".join(f"${part[2:-2]}$" if part.startswith("$$") else part if part.startswith("$") else plain_text(part)
                   for part in parts).strip()


def quotation(tex: str) -> str:
    """A sentence of the paper, verbatim, and under it our English translation in italics (`derivation.translation`;
    a display of it, $$…$$, set in the line: (9) after the sentence that states it)."""
    english = translation.english(tex)
    under = rf"\par\textit{{{_sentence(english)}}}" if english else ""
    return rf"\begin{{quote}}``{_sentence(tex)}''{under}\end{{quote}}"


def printed_block(tex: str) -> str:
    """A quote as the paper sets it: a sentence, or a formula within one ($…$, n°8's $\\hat{c} < fR$), in quotation
    marks; a display as a display."""
    return quotation(tex) if "$" in tex or transcription.is_prose(tex) else printed_display(tex)


# ---------------------------------------------------------------------------------------------
# A claim.


def arrangement(claim: Claim) -> display.Arrangement | None:
    """The order to show the claim's forms in: the printed LaTeX's (glyphs put right for an artefact)."""
    tex = claim.corrected_tex if claim.erratum is not None and claim.erratum.kind == "ocr" else claim.printed_tex
    return display.Arrangement.of(tex)


def derived_trees(claim: Claim) -> list[sp.Basic]:
    """The derived rows as shown: the claim's display, or the derived forms arranged."""
    if claim.display is not None:
        return list(claim.display)
    arr = arrangement(claim)
    return [display.arrange(form, arr) for form in claim.derived]


def _stated(claim: Claim) -> list[sp.Basic]:
    return claim.printed if claim.erratum is None else claim.corrected


def derived_rows(claim: Claim) -> list[list[str]]:
    """Break points of each derived row; an inequality's row ends with its relation to the bound
    (lhs = value ≤ bound), as the claim states it; so does a claim beyond the paper whose stated side is short
    (Δ = … = 0, 𝓕(1 − z)|ₐ↔꜀ = … = −𝓕(z)): its stated form is shown nowhere else (a referee)."""
    trees = derived_trees(claim)
    rows = [display.relation_pieces(tree) for tree in trees]
    if claim.is_inequality:
        arr = arrangement(claim)
        for pieces, relation in zip(rows, _stated(claim), strict=True):
            bound = display.display_tex(display.arrange(relation.rhs, arr))
            pieces.append(f"{RELATION[relation.rel_op]} {bound}")
    elif claim.printed_tex is None:
        for pieces, tree, stated in zip(rows, trees, claim.printed, strict=True):
            if sp.count_ops(stated.rhs) <= STATED_OPS and sp.expand(evaluated(tree.rhs) - stated.rhs) != 0:
                pieces.append(f"= {display.display_tex(stated.rhs)}")
    return rows


STATED_OPS = 2  # a stated side this short (0, 1, −𝓕(z)) closes the derived row it is compared with, unless the
# row already shows it (V + ΩR against ΩR + V)


def where_rows(claim: Claim) -> list[list[str]]:
    """The named parts of a display ("where L = …"), in the order the claim gives them."""
    return [display.relation_pieces(sp.Eq(name, value, evaluate=False)) for name, value in claim.display_where.items()]


def _label(text: str) -> str:
    return rf"\appelllabel{{{text}}}"


def claim_block(claim: Claim | NumericCheck, verdict: Verdict) -> str:
    """The LaTeX of one claim: heading, statement, printed, corrected, derived, verdict."""
    lines = [rf"\appellclaim{{{identifier(claim.id)}}}\label{{{label_of(claim.id)}}}{tex_text(claim.statement)}"]
    if claim.printed_tex:
        lines += [_label("Printed (transcription):"), printed_block(claim.printed_tex)]
    elif claim.context:
        lines += [_label("Beyond the paper; its context in the paper:"), quotation(claim.context)]
    elif not isinstance(claim, NumericCheck):
        lines.append(_label("Beyond the paper: no printed form."))
    if isinstance(claim, NumericCheck):
        lines.append(verdict_text(claim, verdict))
        return "\n".join(lines) + "\n"
    derived = [] if claim.glyph_only else _derived_block(claim, verdict)
    if claim.erratum is not None:
        lines += [_label(f"Corrected ({ERRATUM_CLASSES[claim.erratum.kind]}):"), corrected_block(claim)]
    elif read_in_words(claim):
        reading = reading_block(claim)
        if derived == [_label("Derived:"), reading]:
            # the reading is the derived form, to the letter: shown once (11 claims showed the same display twice,
            # a referee), the verdict saying both were compared
            lines += [_label("Read as, and derived:"), reading]
            derived = []
        else:
            lines += [_label("Read as:"), reading]
    lines += derived
    lines.append(verdict_text(claim, verdict))
    return "\n".join(lines) + "\n"


def read_in_words(claim: Claim) -> bool:
    """An identity the paper states in words (a quoted sentence): its reading in symbols, the form the derived one
    is compared with, is shown under the quotation.  (An inequality's derived display ends with the relation read.)"""
    return (bool(claim.printed_tex) and transcription.is_prose(claim.printed_tex) and not claim.glyph_only
            and claim.erratum is None and not claim.is_inequality)


def reading_block(claim: Claim) -> str:
    """The claim's reading of a quoted sentence, as the check compares it (`Claim.printed`), or as the claim
    shows it (`Claim.reading`, checked equal to it)."""
    rows = [display.relation_pieces(form) for form in (claim.printed if claim.reading is None else claim.reading)]
    shown = forms_display(rows)
    return shown if shown is not None else _too_long(claim, "reading")


def corrected_block(claim: Claim) -> str:
    """The printed form put right: the printed LaTeX with the glyph replaced (an artefact), or the
    SymPy correction in the paper's arrangement (an erratum, a remark)."""
    if claim.erratum.kind == "ocr":
        return printed_block(claim.corrected_tex)
    arr = arrangement(claim)
    rows = [display.relation_pieces(display.arrange(form, arr)) for form in claim.corrected]
    shown = forms_display(rows)
    return shown if shown is not None else _too_long(claim, "corrected")


def _derived_block(claim: Claim, verdict: Verdict) -> list[str]:
    try:
        rows = derived_rows(claim)
    except Exception:  # the derivation raised: the verdict says why
        return [_label("Derived:") + " none (the derivation raised)."]
    # Appell's number tags the derived form of his equation; not the derived meaning of a sentence that states it
    # (a referee: "(9)" stood on max Ω' > 0, which is not Appell's (9), δ < fR).
    tag = None if transcription.is_prose(claim.printed_tex or "") else tag_of(claim.id)
    shown = forms_display(rows, tag)
    out = [_label("Derived:"), shown if shown is not None else _too_long(claim, "derived")]
    if claim.display_where:
        where = forms_display(where_rows(claim))
        out += [_label("where"), where if where is not None else _too_long(claim, "the parts named in its display")]
    return out


def _too_long(claim, what: str) -> str:
    return (
        rf"\emph{{The {what} form is too long to print in a column; it is in the supplement "
        rf"\texttt{{{SUPPLEMENT}}} under \texttt{{{identifier(claim.id)}}}, as SymPy \texttt{{srepr}} and LaTeX.}}"
    )


# ---------------------------------------------------------------------------------------------
# Verdicts in words.


# The numeric check every identity and inequality gets, in the record's words (derivation.claim): all the digits
# asked at all the points.  Said once in the methods paragraph, not on 122 verdicts (a referee); a verdict names its
# numeric check only where it is another (one point, fewer digits) or the verdict failed.
USUAL_NUMERIC = (f"{checks.DIGITS:.0f} digits at {checks.NUMERIC_POINTS} points",
                 f"sign at {checks.NUMERIC_POINTS} points, {checks.DIGITS} digits")


def _numeric(verdict: Verdict) -> str:
    return "" if verdict.numeric in USUAL_NUMERIC else f"; {tex_text(verdict.numeric)}"


# What a check of a premise shows: that the derivation takes it as printed, not that it follows.
PREMISE = {
    "law": "a law the model takes from the paper, so that the check shows only that the derivation uses it as printed",
    "definition": "a definition, so that the check shows only that the derivation defines it as printed",
}


def verdict_text(claim, verdict: Verdict) -> str:
    """What the check found, in the record's own terms (exact, proved, sampled, n digits at m points),
    which the methods paragraph defines."""
    status = {"confirmed": "confirmed", "erratum": "printed differently", "failed": "failed"}[verdict.status]
    if verdict.status == "erratum" and claim.erratum is not None and claim.erratum.kind == "ocr":
        status = "transcription differs"  # a glyph of our OCR copy, not the paper's mistake (a referee)
    if verdict.status == "failed":
        body = f"{tex_text(verdict.symbolic)}; {tex_text(verdict.numeric)}" + (f" --- {tex_text(verdict.note)}" if verdict.note else "")
    elif verdict.symbolic == "numeric only":
        body = f"numeric only, {tex_text(verdict.numeric)}"
    elif verdict.symbolic == "glyph only":
        body = f"glyph only ({tex_text(claim.erratum.reason)}): the meant form is typed, not derived"
    elif claim.is_inequality:
        how = "proved" if verdict.symbolic == "proved" else tex_text(verdict.symbolic)
        body = f"{how}{_numeric(verdict)}"
        if claim.erratum is not None:
            body += "; the printed relation fails at a witness"
    else:
        against = ("stated" if claim.printed_tex is None else "corrected" if claim.erratum is not None
                   else "reading" if read_in_words(claim) else "printed")
        body = f"derived = {against}, {tex_text(verdict.symbolic)}{_numeric(verdict)}"
        if claim.erratum is not None:
            body += "; the printed form differs"
    if getattr(claim, "premise", None) and verdict.status == "confirmed":  # the derivation's input, not a result
        body += "; " + PREMISE[claim.premise]
    return rf"{_label('Verdict:')} \emph{{{status}}}: {body}."


def glyph_items(entries: list[tuple[Claim, Verdict]]) -> list[str]:
    """The transcription artefacts, one item per misreading (ζ read for ξ) with every place it occurs, each linked
    to its claim, which shows the printed and corrected forms (one line a claim repeated ζ read for ξ four times, a
    referee).  The misreading is the reason's first clause; places are grouped by the glyphs put right."""
    groups: dict[tuple, list[tuple[Claim, Verdict]]] = {}
    for claim, verdict in entries:
        glyphs = tuple(sorted(f"{k}->{v}" for k, v in {**claim.erratum.glyphs, **claim.erratum.tex}.items()))
        groups.setdefault(glyphs, []).append((claim, verdict))
    items = []
    for places in groups.values():
        what = re.split(r"[:;]", places[0][0].erratum.reason)[0].strip()
        listed = ", ".join(
            rf"\appellref{{{label_of(c.id)}}}{{\texttt{{{identifier(c.id)}}}}} ({tex_text(c.where)}{tex_text(checked(v.status))})"
            for c, v in places
        )
        items.append(rf"\item {tex_text(what)}: {listed}.")
    return items


def erratum_item(claim: Claim, verdict: Verdict) -> str:
    """One erratum of the paper for the errata list: where, class, reason, and the printed and corrected displays
    (the transcription's are `glyph_items`)."""
    head = (
        rf"\item \appellref{{{label_of(claim.id)}}}{{\texttt{{{identifier(claim.id)}}}}} ({tex_text(claim.where)}; "
        rf"{ERRATUM_CLASSES[claim.erratum.kind]}{tex_text(checked(verdict.status))}): {tex_text(claim.erratum.reason.rstrip('.'))}."
    )
    return "\n".join([head, _label("Printed:"), printed_block(claim.printed_tex), _label("Corrected:"), corrected_block(claim)])

