"""The tie between a claim's quoted LaTeX and its SymPy reading: a glyph put right in one only turns it red."""

import dataclasses

import sympy as sp

import derivation
from derivation import n8_general, symbols, transcription
from derivation.notation import latex
from derivation.symbols import OCR_GLYPH_TEX, delta, f, g, m, ocr_partial, snapshot


def _claim(claim_id):
    return next(c for c in n8_general.claims() if c.id == claim_id)


def test_glyphs_are_the_letters_of_a_formula():
    assert transcription.glyphs(r"fV' - \delta\Omega' = -f^2g\left(1 + \frac{R^2}{k^2}\right)") == {
        "f", "V", "delta", "Omega", "g", "R", "k"}
    assert transcription.glyphs(r"\frac{\partial^2}{k^2}") == {"partial", "k"}
    assert transcription.glyphs(r"u = \dot{\xi}' - qR") == {"u", "dotxi", "q", "R"}
    assert transcription.glyphs(r"\frac{dx}{dt} = -a") == {"x", "a"}  # Leibniz in t is the paper's prime
    assert transcription.glyphs(r"mk^2 r' = \pm \varepsilon mg") == {"m", "k", "r", "s", "epsilon", "g"}


def test_a_reading_that_puts_a_glyph_right_is_caught():
    eq11 = _claim("eq11")
    # The SymPy reading typed with δ where the transcription has ∂: the erratum would be hidden.
    tidy = [e.xreplace({ocr_partial: delta}) for e in eq11.printed]
    verdict = dataclasses.replace(eq11, printed=tidy, erratum=None).check()
    assert verdict.status == "failed" and verdict.symbolic == "transcription"
    assert verdict.note.endswith("(in the transcription only: partial)")
    assert eq11.check().status == "erratum"


def test_a_quote_not_in_the_transcription_is_caught():
    claim = _claim("n8.V_decreases")
    verdict = dataclasses.replace(claim, printed_tex=r"V' < -fg + 1;").check()
    assert verdict.status == "failed" and "not quoted verbatim" in verdict.note


def test_a_corrected_latex_that_does_not_name_the_corrected_form_is_caught():
    claim = _claim("n8.slide_time_bound")
    assert claim.corrected_tex == r"\frac{V_0}{fg}"  # the printed LaTeX with f/g put right, nothing else
    wrong = dataclasses.replace(claim.erratum, tex={"f/g": "fk"})
    verdict = dataclasses.replace(claim, erratum=wrong).check()
    assert verdict.status == "failed" and "corrected LaTeX" in verdict.note


def test_a_glyph_record_says_so():
    verdict = _claim("n8.hypothesis").check()
    assert (verdict.status, verdict.symbolic) == ("erratum", "glyph only")
    assert _claim("eq11").check().symbolic == "exact"


def test_prose_is_not_read_as_a_formula():
    assert transcription.is_prose(r"le pivotement est nul : il reste ensuite nul")
    assert transcription.is_prose(r"si $a = c$")
    assert not transcription.is_prose(r"y - x = A,")
    assert transcription.mismatch(r"si $a = c$", [sp.Eq(sp.Symbol("q"), 0)]) is None


def test_a_system_in_an_environment_is_a_formula_and_its_letters_are_tied():
    from derivation import n2_motion

    # \begin{cases} and \operatorname{tang} are structure: the tie must not take them for French words.
    assert not transcription.is_prose(n2_motion.TEX_7)
    assert not transcription.is_prose(r"\frac{dx}{d\theta} = \operatorname{tang} \theta")
    assert transcription.glyphs(r"\operatorname{tang} \theta") == {"theta"}
    eq7 = next(c for c in n2_motion.claims() if c.id == "eq7")
    wrong_letter = [e.xreplace({delta: sp.Symbol("k", positive=True)}) for e in eq7.printed]
    verdict = dataclasses.replace(eq7, printed=wrong_letter).check()
    assert verdict.status == "failed" and verdict.symbolic == "transcription"


# A mutation audit of derivation/ (each test below fails on the mutant it names, passes here).


def test_a_letter_of_the_reading_alone_is_caught():
    """M06: the tie between a quote and its reading was tested one way (a letter of the quote alone)."""
    assert transcription.mismatch(r"V' = -fg", [sp.Eq(sp.Symbol("V'", real=True), -f * g * m)]) == "in the SymPy reading only: m"


def test_a_formula_quote_is_not_prose():
    """M07: a looser prose rule read five formula quotes as prose, which switches their letter tie off."""
    for tex in (r"X = -fmg \cos \alpha, \quad Y = -fmg \sin \alpha, \quad Z = 0",
                r"dT = -mf g V dt - m \delta g \Omega dt \pm \varepsilon mgr dt,"):
        assert not transcription.is_prose(tex)


def test_no_misread_glyph_reads_as_the_letter_it_stands_for():
    """M55, M57: a glyph normalised into its letter (ζ into ξ) would hide the erratum; only ∂ was tested."""
    pairs = {(w, meant) for c in derivation.claims() if c.erratum is not None for w, meant in c.erratum.glyphs.items()}
    assert pairs
    for wrong, meant in pairs:
        assert transcription.glyphs(OCR_GLYPH_TEX[wrong]) != transcription.glyphs(latex(snapshot(meant))), wrong


def test_a_quote_that_is_one_formula_in_dollars_is_tied():
    """Mutation audit: n°8's quote $\\hat{c} < fR$ was read as prose, so its tie never ran and a reading
    with δ already put right for the OCR's ĉ passed."""
    assert not transcription.is_prose(r"$\hat{c} < fR$")
    assert transcription.is_prose(r"si $a = c$")
    hypothesis = _claim("n8.hypothesis")
    assert transcription.check(hypothesis) is None
    tidy = [e.xreplace({symbols.ocr_hat_c: delta}) for e in hypothesis.printed]
    assert "in the transcription only: hatc" in transcription.check(dataclasses.replace(hypothesis, printed=tidy))


def test_a_context_is_quoted_verbatim_and_only_for_a_claim_of_ours():
    """n°5's sentences are the context of claims of ours (Appell names the cases beyond (9) and leaves them): a context
    must stand in the transcription like any quote, and a claim the paper states quotes it as printed instead."""
    from derivation import n5_hypothesis

    claim = next(c for c in n5_hypothesis.claims() if c.id == "n5.rolling_survives")
    assert claim.printed_tex is None and transcription.check(claim) is None
    assert "context is not quoted verbatim" in transcription.check(dataclasses.replace(claim, context="il y a des cas"))
    both = dataclasses.replace(claim, printed_tex=claim.context)
    assert "has no context" in transcription.check(both)
