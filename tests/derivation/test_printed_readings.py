"""The readings of the printed formulas that the errata rest on, against a mechanical parse of the printed LaTeX.

Where a claim's printed form is a glyph swap of the transcription, the check ties it to the LaTeX
(`derivation.transcription`).  The readings behind the strongest statements, the mathematical erratum (10),
the remark and the glyph record whose correction is typed, were typed by hand and tied to the LaTeX only by
the letters they use: a reading δR/(1 + R²/k²) of (10) gave the same erratum (a trust audit).  Here SymPy's own
LaTeX parser (its Lark grammar, a reader independent of ours) reads the printed LaTeX, and the reading must be
the same expression.  The parser reads too little of the paper for every claim (primes, juxtaposed Greek
letters); these are the readings nothing else checks.
"""

import re
import warnings

import pytest
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.parsing.latex import parse_latex

from derivation import checks
from paper import verification


def parsed(tex: str) -> sp.Expr:
    """``tex`` read by SymPy's Lark LaTeX parser, its symbols named as ours (V_{0} -> V_0).  Where the grammar is
    ambiguous (fg(…) as a product or a call), the one reading without an unknown function, which must be unique."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the parser's own deprecation warnings
        result = parse_latex(tex, backend="lark")
    if not isinstance(result, sp.Basic):  # a lark Tree of ambiguous parses
        candidates = {c for c in result.children if isinstance(c, sp.Expr) and not c.atoms(AppliedUndef)}
        assert len(candidates) == 1, f"{tex}: read {len(candidates)} ways"
        (result,) = candidates
    return result.xreplace({s: sp.Symbol(re.sub(r"[{}]", "", s.name)) for s in result.free_symbols})


def same(expr: sp.Expr, reading: sp.Expr, claim_id: str) -> bool:
    """The two equal exactly and at the seeded points of the claim's box (by name: the parser's symbols carry no
    assumptions)."""
    by_name = {s.name: s for s in reading.free_symbols}
    expr = expr.xreplace({s: by_name.get(s.name, s) for s in expr.free_symbols})
    if expr.free_symbols - reading.free_symbols:
        return False
    return checks.exact_zero(expr - reading) and checks.agrees(checks.numeric_residual(expr, reading, "reading:" + claim_id))


CLAIMS = {c.id: c for c in verification.all_claims()}


def test_the_reading_of_eq10_the_mathematical_erratum_is_its_latex():
    claim = CLAIMS["eq10"]
    lhs, rhs = claim.printed_tex.split("=")
    (reading,) = claim.printed
    assert parsed(lhs).name == reading.lhs.name and same(parsed(rhs), reading.rhs, claim.id)
    # The audit's mutant: the same letters, another formula.
    R, delta, k = (next(s for s in reading.free_symbols if s.name == n) for n in ("R", "delta", "k"))
    assert not same(parsed(rhs), delta * R / (1 + R**2 / k**2), claim.id)


def test_the_reading_of_the_slide_time_bound_glyph_is_its_latex():
    """n8.slide_time_bound is a glyph record whose correction V₀/(fg) is typed: its reading V₀/(f/g) = V₀g/f is the
    transcription's LaTeX, not any formula in the same letters (f g/V₀ passed, the audit found)."""
    claim = CLAIMS["n8.slide_time_bound"]
    (reading,) = claim.printed
    assert same(parsed(claim.printed_tex), reading.rhs, claim.id)
    V_0, f, g = (next(s for s in reading.free_symbols if s.name == n) for n in ("V_0", "f", "g"))
    assert not same(parsed(claim.printed_tex), f * g / V_0, claim.id)


def test_the_reading_of_the_remark_is_its_latex():
    """n8.V_rate_bound, the remark (a strict < that is a ≤): the relation and its bound as printed."""
    claim = CLAIMS["n8.V_rate_bound"]
    (reading,) = claim.printed
    lhs, rhs = claim.printed_tex.rstrip(",. ").split("<")
    assert isinstance(reading, sp.StrictLessThan) and lhs.strip() == "V'" and reading.lhs.name == "V'"
    assert same(parsed(rhs), reading.rhs, claim.id)
    assert not same(parsed(rhs), -reading.rhs, claim.id)
