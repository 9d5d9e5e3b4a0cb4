"""The claim: one checkable statement of the paper (design notes, "one source of truth").

A claim holds where the statement stands in the paper, the form *as printed*
(``printed_tex`` is quoted verbatim from the OCR transcription, ``printed`` is
our SymPy reading of it, glyph errors included), the form *derived* from
first principles, and the relation between them.  ``appell verify``,
``appell errata`` and the LaTeX appendix all read claims; nothing is typed twice.

An erratum is never asserted: the check proves that the printed form differs
from the derived one (a 30-digit residual far above rounding) and that the
corrected form equals it (exactly and numerically).  An OCR erratum with
``glyphs`` is corrected by the glyph substitution alone, which is what makes
"glyph confusion" a verified class rather than an opinion.

A derived form is given as a zero-argument callable, run only when the claim
is checked: listing the claims runs no derivation, and a derivation that
raises fails its own claim (with the reason) instead of the whole record.
"""

from __future__ import annotations

import dataclasses

from dataclasses import dataclass, field
from typing import Callable, Literal, Mapping

import sympy as sp

from derivation import checks, transcription
from derivation.domain import Bounds
from derivation.notation import latex
from derivation.symbols import OCR_GLYPH_TEX, snapshot, snapshot_symbol

Status = Literal["confirmed", "erratum", "failed"]


Form = sp.Basic | list  # an Eq or relational, or a list of them (a system)
Derivation = Callable[[], Form]  # run on first use, see Lazy
REASON_LENGTH = 200  # characters of an exception's message kept in a verdict


def _as_list(form: Form) -> list[sp.Basic]:
    return list(form) if isinstance(form, (list, tuple)) else [form]


class Lazy:
    """A claim's field given as forms, or as a `Derivation` of them; read as the snapshotted list.

    The derivation runs on the first read and its forms are kept; if it raises, the read
    raises (every time), and `Claim.check` turns that into a failed verdict.  An ``unevaluated``
    field (a display) is built and snapshotted without evaluation, so that it keeps the order
    it was written in; an ``optional`` one defaults to None.
    """

    def __init__(self, unevaluated: bool = False, optional: bool = False):
        self.unevaluated, self.optional = unevaluated, optional

    def __set_name__(self, owner, name: str):
        self.name, self.given = name, "_given_" + name

    def __get__(self, claim, owner=None):
        if claim is None:
            if self.optional:
                return None
            raise AttributeError(self.name)  # no class default: the dataclass field stays required
        state = claim.__dict__  # a frozen dataclass: the cache goes in behind its back
        if self.name not in state:
            given = state[self.given]
            if given is None:
                return None
            with sp.evaluate(not self.unevaluated):
                form = given if isinstance(given, (sp.Basic, list, tuple)) else given()
                state[self.name] = [snapshot(e) for e in _as_list(form)]
        return state[self.name]

    def __set__(self, claim, value: Form | Derivation):
        claim.__dict__[self.given] = value
        claim.__dict__.pop(self.name, None)


# The classes of a difference between the printed and the derived form, and how reports name them.
ERRATUM_CLASSES = {
    "mathematical": "mathematical erratum",  # a result of the paper that does not follow (eq. (10))
    "remark": "remark",  # a slip nothing after it uses (a strict "<" whose bound is reached)
    "ocr": "transcription artefact",  # a glyph the OCR transcription confused (∂ or ĉ for δ, ζ for ξ)
}


def errata_summary(kinds: list[str]) -> str:
    """"1 mathematical erratum, 1 remark, 13 transcription artefacts" for a list of erratum kinds."""
    parts = []
    for kind, name in ERRATUM_CLASSES.items():
        n = kinds.count(kind)
        plural = name if n == 1 else name.replace("erratum", "errata").replace("artefact", "artefacts").replace("remark", "remarks")
        parts.append(f"{n} {plural}")
    return ", ".join(parts)


@dataclass(frozen=True)
class Erratum:
    """How the printed form is wrong, and its correction.

    kind: "mathematical" for a result of the printed paper that does not
    follow, "remark" for a slip in a detail that nothing after it uses, "ocr"
    for a glyph confusion of the transcription (∂ or ĉ for δ, ζ for ξ, ρ for
    p, f/g for fg): a glyph our copy shows wrong (the reading's slip, or a misprint of that glyph, which the
    copy cannot tell apart; the meaning is not in doubt).
    """

    kind: Literal["ocr", "mathematical", "remark"]
    reason: str
    glyphs: Mapping[sp.Basic, sp.Basic] = field(default_factory=dict)
    # Misread marks that are no letter (f/g for fg): printed LaTeX -> meant, for the corrected LaTeX.
    tex: Mapping[str, str] = field(default_factory=dict)
    corrected: Form | None = None
    # For an error of the paper (not "ocr"): what is wrong, in a clause, for the appendix's findings.
    summary: str = ""
    # For an inequality: a point where the printed relation fails (exactly).
    witness: Mapping[sp.Basic, sp.Expr] = field(default_factory=dict)

    def corrected_form(self, printed: sp.Basic) -> sp.Basic:
        """The printed form with the glyphs put right."""
        return printed.xreplace(self._glyph_map())

    def _glyph_map(self) -> dict[sp.Basic, sp.Basic]:
        # A misread function letter is misread in its derivatives too (ζ'' for ξ'').
        glyphs = {}
        for wrong, meant in self.glyphs.items():
            if isinstance(wrong, sp.Symbol):
                glyphs[wrong] = meant
            else:
                glyphs.update({snapshot_symbol(wrong, n): snapshot_symbol(meant, n) for n in range(3)})
        return glyphs


@dataclass(frozen=True)
class Verdict:
    id: str
    where: str
    status: Status
    symbolic: str  # "exact", "proved", "sampled", or what failed
    numeric: str  # e.g. "30 digits at 5 points"
    digits: float | None = None
    note: str = ""


def raised(id: str, where: str, error: Exception) -> Verdict:
    """The verdict of a claim whose derivation or check raised: failed, with the reason on one line."""
    message = " ".join(str(error).split())
    reason = f"{type(error).__name__}: {message}" if message else type(error).__name__
    if len(reason) > REASON_LENGTH:
        reason = reason[: REASON_LENGTH - 1] + "…"
    return Verdict(id, where, "failed", "derivation raised", "not run", note=reason)


def put_in(expr: sp.Basic, where: Mapping[sp.Symbol, sp.Expr]) -> sp.Basic:
    """``expr`` with the named parts ``where`` put in, evaluated; a named part may name another (N in s, s = sin θ)."""
    for _ in range(len(where)):
        expr = expr.xreplace(where)
    return evaluated(expr)


def evaluated(expr: sp.Basic) -> sp.Basic:
    """An unevaluated tree (a display) rebuilt with SymPy's evaluation, bottom up."""
    if not expr.args or isinstance(expr, sp.Number):
        return expr
    return expr.func(*[evaluated(a) for a in expr.args])


def residuals(form: Form) -> sp.Matrix:
    """An equation ``lhs = rhs`` (or a system) as the column of ``lhs - rhs``."""
    return sp.Matrix([e.lhs - e.rhs for e in _as_list(form)])


@dataclass(frozen=True)
class Claim:
    """One statement of the paper.

    An identity: ``printed`` and ``derived`` are equations (or lists of them)
    written with the same left-hand sides, the paper's; the claim holds when
    their residuals ``lhs - rhs`` agree, so a glyph error on either side shows.
    An inequality: ``printed`` is a relational ``lhs < rhs`` (or a list) and
    ``derived`` the equations ``lhs = value`` the derivation gives; the claim
    is ``value < rhs`` under the paper's hypotheses.

    ``printed`` and ``derived`` may each be given as a `Derivation` (`Lazy`);
    ``domain`` overrides the sampling box for this claim (theta acute, ...);
    ``bounded`` lists the atoms an inequality proof may take to their bounds.
    """

    id: str
    where: str
    statement: str
    printed_tex: str | None  # None: a cross-check of ours, not a statement of the paper
    printed: Form | Derivation = Lazy()
    derived: Form | Derivation = Lazy()
    erratum: Erratum | None = None
    domain: Mapping[sp.Symbol, Bounds] = field(default_factory=dict)
    bounded: Mapping[sp.Basic, tuple[sp.Expr, sp.Expr]] = field(default_factory=dict)
    hypothesis: Mapping[sp.Symbol, sp.Expr] = field(default_factory=lambda: checks.HYPOTHESIS_9)
    # The size the numeric residual is measured against (an expression in the claim's symbols);
    # None: relative to the larger of the two sides at each point.
    scale: sp.Expr | None = None
    # A record of a transcription glyph only: the meant form is typed, not derived, so the check
    # shows that the glyph substitution gives it and nothing more (counted apart, never "exact").
    glyph_only: bool = False
    # Symbols the printed form uses as the paper does and defines elsewhere or implicitly (n°11's λ):
    # their definitions are put in before the printed form is compared with the derived one (given as a function
    # of none, they are derived on first use, as the forms are: inv.mirror's 𝓕(z)).
    definitions: Mapping[sp.Symbol, sp.Expr] | Callable[[], Mapping[sp.Symbol, sp.Expr]] = field(default_factory=dict)
    # How the appendix shows the derived form where the arrangement read off the printed LaTeX
    # (`paper.display`) is not the paper's: the same rows, built unevaluated in the order to show
    # (s₃ factored so that a = c shows).  The check proves it equal to the derived form, exactly and
    # at 30 digits, so a wrong display fails the claim.  None: the derived form, arranged.
    display: Form | Derivation | None = Lazy(unevaluated=True, optional=True)
    # The same for the reading of a sentence (``printed`` when the paper states it in words), where SymPy's
    # order is not the one to read (ρ × (8)₁, −mgδΩ): built unevaluated, and checked equal to ``printed``,
    # exactly and at 30 digits, so a wrong reading shown fails the claim.  None: ``printed``, as SymPy orders it.
    reading: Form | Derivation | None = Lazy(unevaluated=True, optional=True)
    # A sentence of the paper that a claim of ours (printed_tex None: beyond the paper) comments, quoted verbatim
    # and shown as its context, not as what the paper states (n°5's cases, which Appell names and leaves).
    context: str | None = None
    # Symbols the display (and the reading shown) names for sub-expressions (the polynomials L and N of J),
    # shown after it ("where L = …") and put in before the comparison.
    display_where: Mapping[sp.Symbol, sp.Expr] = field(default_factory=dict)
    # A law or definition the derivation takes from the paper as its input (the friction laws, Ω's definition):
    # its check shows the derivation uses it as printed, not that it follows from anything, and the appendix says
    # so in its verdict and counts it apart (a referee: counted among the confirmed results, it made them circular).
    premise: Literal["law", "definition"] | None = None

    def _check_consistent(self):
        """An inequality's forms fit together, and a transcription artefact is one (it puts glyphs right, and its
        corrected LaTeX is not the printed): checked with the forms, so on checking."""
        if self.erratum is not None and self.erratum.kind == "ocr":  # an inverted fraction called a glyph passed
            if not (self.erratum.glyphs or self.erratum.tex):
                raise ValueError(f"{self.id}: a transcription artefact names the glyphs it puts right (glyphs or tex)")
            if self.printed_tex is not None and self.corrected_tex == self.printed_tex:
                raise ValueError(f"{self.id}: a transcription artefact's corrected LaTeX must differ from the printed")
        if self.is_inequality:
            if self.erratum is not None and not (self.erratum.corrected is not None and self.erratum.witness):
                raise ValueError(f"{self.id}: an inequality erratum needs a corrected relation and a witness")
            if [e.lhs for e in self.printed] != [e.lhs for e in self.derived]:
                raise ValueError(f"{self.id}: derived values must be given for the printed left-hand sides")

    @property
    def corrected_tex(self) -> str | None:
        """LaTeX of the correction.  A transcription artefact is the printed LaTeX with each
        misread glyph replaced by what is meant, and nothing else; a mathematical erratum
        or a remark is printed from its SymPy form."""
        if self.erratum is None:
            return None
        if self.erratum.kind == "ocr" and self.printed_tex is not None:
            tex = self.printed_tex
            for wrong, meant in self.erratum.glyphs.items():
                tex = tex.replace(OCR_GLYPH_TEX[wrong], latex(snapshot(meant)))
            for wrong, meant in self.erratum.tex.items():
                tex = tex.replace(wrong, meant)
            return tex
        return latex(self.corrected)

    @property
    def is_inequality(self) -> bool:
        return not isinstance(self.printed[0], sp.Equality)

    @property
    def corrected(self) -> list[sp.Basic] | None:
        if self.erratum is None:
            return None
        if self.erratum.corrected is not None:
            return [snapshot(e) for e in _as_list(self.erratum.corrected)]
        return [self.erratum.corrected_form(e) for e in self.printed]

    def check(self) -> Verdict:
        """The verdict; never raises, so that one wrong derivation fails its claims and no others."""
        try:
            self._check_consistent()
            problem = transcription.check(self)
            if problem:
                return self._verdict("failed", "transcription", "not run", note=problem)
            verdict = self._check_inequality() if self.is_inequality else self._check_identity()
            if verdict.status != "failed":
                problem = self._display_problem() or self._reading_problem()
                if problem:
                    return self._verdict("failed", "display", verdict.numeric, note=problem)
        except Exception as error:
            return raised(self.id, self.where, error)
        return dataclasses.replace(verdict, symbolic="glyph only") if self.glyph_only else verdict

    def _verdict(self, status: Status, symbolic: str, numeric: str, digits=None, note="") -> Verdict:
        return Verdict(self.id, self.where, status, symbolic, numeric, digits, note)

    def _stated(self, forms: list[sp.Basic]) -> list[sp.Basic]:
        """Printed (or corrected) forms with the paper's definitions put in."""
        definitions = self.definitions() if callable(self.definitions) else self.definitions
        return [e.subs(definitions) for e in forms] if definitions else forms

    def _check_identity(self) -> Verdict:
        derived = residuals(self.derived)
        target = residuals(self._stated(self.printed if self.erratum is None else self.corrected))
        exact = checks.exact_zero(derived - target)
        num = checks.numeric_residual(derived, target, self.id, self.domain, scale=self.scale)
        numeric = f"{num.digits:.0f} digits at {num.points} point{'s' if num.points > 1 else ''}"
        symbolic = "exact" if exact else "not reduced to 0"
        ok = exact and checks.agrees(num)
        if self.erratum is None:
            return self._verdict("confirmed" if ok else "failed", symbolic, numeric, num.digits)
        # An erratum stands only if the printed form really differs.
        differs = checks.numeric_residual(derived, residuals(self._stated(self.printed)), "printed:" + self.id, self.domain, scale=self.scale)
        if not checks.is_strictly_nonzero_somewhere(differs):
            return self._verdict("failed", symbolic, numeric, num.digits, "recorded as erratum but printed form agrees")
        return self._verdict("erratum" if ok else "failed", symbolic, numeric, num.digits)

    def _check_inequality(self) -> Verdict:
        outside = checks.outside_bounds(self.bounded, self.id, self.domain)
        if outside is not None:  # the proof would run over too small a box: a claim that says too little
            raise ValueError(f"{outside} leaves its interval {self.bounded[outside]} in the claim's domain")
        unmet = checks.unmet_hypothesis(self.hypothesis, self.id, self.domain)
        if unmet is not None:  # the proof would assume a sign the atom does not keep
            raise ValueError(f"{unmet} leaves the sign the hypothesis gives it in the claim's domain")
        stated = self._stated(self.printed if self.erratum is None else self.corrected)
        holds, symbolic, numeric = self._inequalities_hold(stated)
        if self.erratum is None:
            return self._verdict("confirmed" if holds else "failed", symbolic, numeric)
        # An inequality erratum stands only if the printed relation fails at the witness.
        if not self._printed_fails_at_witness():
            return self._verdict("failed", symbolic, numeric, note="printed relation not refuted at the witness")
        return self._verdict("erratum" if holds else "failed", symbolic, numeric)

    def _inequalities_hold(self, relationals: list[sp.Basic]) -> tuple[bool, str, str]:
        """Each row ``value rel bound``: proved, else densely sampled; and signed at 30 digits.  A strict row
        (< or >) must be proved: random points never land where the two sides meet, so sampling cannot tell < from
        ≤ (a mutation audit: n8.opposite_turns' ≤ made < stayed confirmed, sampled, where α'β' = 0 at cos θ = 0)."""
        proved, sampled, strict_unproved, numeric_ok = True, True, False, True
        for i, (der, rel) in enumerate(zip(self.derived, relationals, strict=True)):
            gap = der.rhs - rel.rhs
            key = f"{self.id}[{i}]"
            if not checks.prove_sign(gap, rel.rel_op, self.bounded, self.hypothesis):
                proved = False
                strict_unproved = strict_unproved or rel.rel_op in ("<", ">")
                sampled = sampled and checks.dense_sign(gap, rel.rel_op, key, self.domain)
            numeric_ok = numeric_ok and checks.numeric_sign(gap, rel.rel_op, key, self.domain)
        if proved:
            symbolic = "proved"
        elif sampled and strict_unproved:
            symbolic = f"strict, not proved (sampled at {checks.DENSE_SAMPLES} points: sampling cannot tell < from ≤)"
            sampled = False
        elif sampled:
            symbolic = f"sampled ({checks.DENSE_SAMPLES} points)"
        else:
            symbolic = "violated on sample"
        numeric = f"sign at {checks.NUMERIC_POINTS} points, {checks.DIGITS} digits" if numeric_ok else "sign violated"
        return numeric_ok and (proved or sampled), symbolic, numeric

    def _display_problem(self) -> str | None:
        """What is wrong with the display (None: none given, or it is the derived form, exactly and at 30 digits)."""
        if self.display is None:
            return None
        return self._shown_differs("display", self.display, self.derived, "the derived form")

    def _reading_problem(self) -> str | None:
        """What is wrong with the reading shown (None: none given, or it is ``printed``, exactly and at 30 digits)."""
        if self.reading is None:
            return None
        if self.printed_tex is None or self.is_inequality:
            return "a reading is shown only for an identity the paper states"
        return self._shown_differs("reading", self.reading, self.printed, "the reading checked")

    def _shown_differs(self, name: str, trees: list[sp.Basic], forms: list[sp.Basic], what: str) -> str | None:
        """What is wrong with ``trees`` (a display or a reading, unevaluated), their named parts put in and
        evaluated, against ``forms`` (None: equal, exactly and at 30 digits)."""
        shown = [put_in(e, self.display_where) for e in trees]
        if len(shown) != len(forms):
            return f"the {name} has {len(shown)} rows, {what} {len(forms)}"
        expected, displayed = residuals(forms), residuals(shown)
        # Numerically first: a display that differs is told in a second, where SymPy's simplify of the nonzero
        # difference ran past 12 minutes (a test's wrong 𝓝, its time depending on SymPy's cache).  Both must hold.
        num = checks.numeric_residual(expected, displayed, f"{name}:" + self.id, self.domain, scale=self.scale)
        if not checks.agrees(num):
            return f"the {name} differs from {what} (numerically: {num.digits:.0f} digits)"
        if not checks.exact_zero(expected - displayed):
            return f"the {name} differs from {what} (not reduced to 0; {num.digits:.0f} digits)"
        return None

    def _printed_fails_at_witness(self) -> bool:
        witness = {snapshot(a): b for a, b in self.erratum.witness.items()}
        return any(
            checks.prove_sign((der.rhs - rel.rhs).subs(witness), NEGATION[rel.rel_op], self.bounded, self.hypothesis)
            for der, rel in zip(self.derived, self.printed)
        )


NEGATION = {"<": ">=", "<=": ">", ">": "<=", ">=": "<"}



@dataclass(frozen=True)
class Margin:
    """What a numeric check of an inequality measured: the smallest relative margin by which the
    quantity kept its sign over ``cases`` samples, and the relative error of the computation it
    comes from.  The inequality stands when every margin is far (10⁵×) above that error."""

    smallest: float
    error: float

    def holds(self) -> bool:
        return self.smallest > 1e5 * self.error

    def describe(self, cases: int) -> str:
        return f"smallest margin {self.smallest:.1e} over {cases} samples (computed to {self.error:.0e})"


@dataclass(frozen=True)
class NumericCheck:
    """A statement checked along computed trajectories, where no exact test applies.

    ``run`` integrates (mpmath, 20–50 digits) and returns what it measured
    and the number of cases (trajectories, points): for an equality, the
    decimal digits of agreement reached, which must be ``>= required_digits``;
    for an inequality, a `Margin`.  Nothing is reported that was not measured.
    """

    id: str
    where: str
    statement: str
    printed_tex: str | None
    run: Callable[[], tuple[float | Margin, int]]
    required_digits: float | None = None
    erratum: None = None
    context: None = None  # as a Claim's (none here): the report reads both kinds alike

    def check(self) -> Verdict:
        from derivation import seed

        if self.printed_tex is not None and not seed.quotes(self.printed_tex):
            return Verdict(self.id, self.where, "failed", "transcription", "not run",
                           note="the printed LaTeX is not quoted verbatim from the transcription")
        try:
            measured, cases = self.run()
        except Exception as error:  # as for a claim: this check fails, the others still run
            return raised(self.id, self.where, error)
        if isinstance(measured, Margin):
            status: Status = "confirmed" if measured.holds() else "failed"
            return Verdict(self.id, self.where, status, "numeric only", measured.describe(cases))
        status = "confirmed" if measured >= self.required_digits else "failed"
        numeric = f"{measured:.0f} digits (≥ {self.required_digits:g} asked), {cases} cases"
        return Verdict(self.id, self.where, status, "numeric only", numeric, measured)
