"""The claim machinery, shown wrong claims: it must fail them."""

import dataclasses

import mpmath
import pytest
import sympy as sp

from derivation import n2_motion, n6_rolling_returns, n7_pure_rolling, n8_general
from derivation.claim import Claim, Erratum, Margin, NumericCheck
from derivation.symbols import R, V, alpha, beta, d, delta, delta_1, f, g, k, snapshot, theta


def _claim(module, claim_id) -> Claim:
    return next(c for c in module.claims() if c.id == claim_id)


def test_a_wrong_printed_form_fails():
    eq7 = _claim(n2_motion, "eq7")
    wrong = [sp.Eq(d(V), -f * g + R * delta / k**2 * g * sp.sin(beta - alpha)), eq7.printed[1]]
    assert dataclasses.replace(eq7, printed=wrong).check().status == "failed"


def test_an_error_far_below_float_precision_fails():
    eq7 = _claim(n2_motion, "eq7")
    nudged = [sp.Eq(e.lhs, e.rhs * (1 + sp.Float("1e-22", 40))) for e in eq7.printed]
    assert dataclasses.replace(eq7, printed=nudged).check().status == "failed"


def test_an_identity_that_agrees_in_numbers_only_fails():
    """Exact *and* numeric: a difference below the numeric tolerance (1e-28 relative) that SymPy does not
    reduce to 0 fails the claim (a mutation of ``exact and agrees`` into ``or`` passed every test)."""
    eq7 = _claim(n2_motion, "eq7")
    nudged = [sp.Eq(e.lhs, e.rhs * (1 + sp.Rational(1, 10**28))) for e in eq7.printed]
    verdict = dataclasses.replace(eq7, printed=nudged).check()
    assert verdict.status == "failed" and verdict.symbolic == "not reduced to 0" and verdict.digits >= 25


@pytest.mark.parametrize("claim_id, module, atom, narrowed", [
    ("n8.V_decreases", n8_general, sp.sin(theta), (-1, 0)),
    ("n6.impossible", n6_rolling_returns, delta_1, (0, 0)),
])
def test_a_proof_over_a_narrower_box_than_the_domain_fails(claim_id, module, atom, narrowed):
    """``bounded`` intervals are the proof's premise: narrowed (sin θ in [−1, 0], δ₁ in [0, 0]), the proof ran over
    too small a box and still said "proved" (a mutation audit)."""
    claim = _claim(module, claim_id)
    assert claim.check().symbolic == "proved" and atom in claim.bounded
    verdict = dataclasses.replace(claim, bounded={**claim.bounded, atom: narrowed}).check()
    assert verdict.status == "failed" and f"{atom} leaves its interval {narrowed}" in verdict.note


def test_an_erratum_whose_printed_form_agrees_fails():
    eq7 = _claim(n2_motion, "eq7")
    bogus = Erratum("mathematical", "no error", corrected=eq7.printed)
    verdict = dataclasses.replace(eq7, erratum=bogus).check()
    assert verdict.status == "failed" and "agrees" in verdict.note


def test_a_transcription_artefact_must_put_a_glyph_right():
    """eq. (10)'s inverted fraction reclassed as a glyph of the OCR copy passed its check (a mutation audit):
    an artefact names the glyphs it replaces, and its corrected LaTeX is not the printed one."""
    eq10 = _claim(n7_pure_rolling, "eq10")
    verdict = dataclasses.replace(eq10, erratum=dataclasses.replace(eq10.erratum, kind="ocr")).check()
    assert verdict.status == "failed" and "names the glyphs it puts right" in verdict.note
    eq11 = _claim(n8_general, "eq11")
    absent = Erratum("ocr", "a glyph the quote does not hold", glyphs={sp.Symbol("partial", positive=True): delta})
    verdict = dataclasses.replace(eq11, printed_tex=eq11.corrected_tex, erratum=absent).check()
    assert verdict.status == "failed" and "corrected LaTeX must differ from the printed" in verdict.note


def test_an_erratum_with_a_wrong_correction_fails():
    eq10 = _claim(n7_pure_rolling, "eq10")
    (printed,) = eq10.printed
    wrong = Erratum("mathematical", "wrong fix", corrected=sp.Eq(printed.lhs, delta / R))
    assert dataclasses.replace(eq10, erratum=wrong).check().status == "failed"


def test_a_glyph_map_that_does_not_fix_the_printed_form_fails():
    eq11 = _claim(n8_general, "eq11")
    # Mapping ∂ to R is a substitution, but not the right one.
    wrong = Erratum("ocr", "∂ for R", glyphs={sp.Symbol("partial", positive=True): R})
    assert dataclasses.replace(eq11, erratum=wrong).check().status == "failed"


def test_a_false_inequality_fails():
    claim = _claim(n8_general, "n8.V_decreases")
    (printed,) = claim.printed
    assert dataclasses.replace(claim, printed=sp.Gt(printed.lhs, 0)).check().status == "failed"


def test_a_strict_inequality_that_is_only_sampled_fails():
    """A mutation audit: n8.opposite_turns' α'β' ≤ 0 made < 0 stayed confirmed ("sampled"), false where cos θ = 0;
    the ≤ the paper means stays confirmed, proved."""
    claim = _claim(n8_general, "n8.opposite_turns")
    (printed,) = claim.printed
    verdict = dataclasses.replace(claim, printed=sp.Lt(printed.lhs, printed.rhs)).check()
    assert verdict.status == "failed" and verdict.symbolic.startswith("strict, not proved")
    assert claim.check().status == "confirmed" and claim.check().symbolic == "proved"


def test_an_inequality_erratum_needs_its_witness_to_refute_the_printed_relation():
    claim = _claim(n8_general, "n8.V_rate_bound")
    wrong_witness = dataclasses.replace(claim.erratum, witness={theta: 0})
    verdict = dataclasses.replace(claim, erratum=wrong_witness).check()
    assert verdict.status == "failed"


def test_derived_values_must_answer_the_printed_left_hand_side():
    claim = _claim(n8_general, "n8.V_decreases")
    verdict = dataclasses.replace(claim, derived=sp.Eq(sp.Symbol("other"), 0)).check()
    assert verdict.status == "failed" and verdict.note.startswith("ValueError") and "left-hand sides" in verdict.note


def test_a_derivation_that_raises_fails_its_claim_with_the_reason():
    def derivation():
        raise ArithmeticError("(7)-(8) do not have\nthe structure of (12)" + ", and more" * 40)

    claim = Claim("broken", "n°9", "A claim whose derivation raises.", None, sp.Eq(d(V), 0), derivation)
    verdict = claim.check()
    assert (verdict.status, verdict.symbolic, verdict.numeric) == ("failed", "derivation raised", "not run")
    assert verdict.note.startswith("ArithmeticError: (7)-(8) do not have the structure of (12), and more")
    assert "\n" not in verdict.note and len(verdict.note) <= 200
    with pytest.raises(ArithmeticError):  # read directly, the forms raise as the derivation did
        claim.derived


def test_a_numeric_check_that_raises_fails_with_the_reason():
    check = NumericCheck("broken", "n°9", "A check whose integration raises.", None, lambda: 1 / 0, required_digits=28)
    verdict = check.check()
    assert (verdict.status, verdict.symbolic, verdict.note) == ("failed", "derivation raised", "ZeroDivisionError: division by zero")
    # mpmath raises some errors without a message: the type alone, no dangling colon.
    mute = dataclasses.replace(check, run=lambda: mpmath.mpf(1) / 0).check()
    assert mute.note == "ZeroDivisionError"


def test_a_derivation_runs_when_its_forms_are_first_read_and_once():
    runs = []

    def derivation():
        runs.append(1)
        return sp.Eq(d(V), 0)

    claim = Claim("once", "n°2", "A claim counting its derivations.", None, sp.Eq(d(V), 0), derivation)
    assert runs == []
    assert claim.derived == claim.derived == [sp.Eq(snapshot(d(V)), 0)]
    assert runs == [1]


def test_a_numeric_check_below_its_digits_fails():
    check = NumericCheck("x", "n°8", "a trajectory check", None, lambda: (24.0, 3), required_digits=25)
    verdict = check.check()
    assert verdict.status == "failed" and verdict.numeric == "24 digits (≥ 25 asked), 3 cases"
    assert dataclasses.replace(check, run=lambda: (25.0, 3)).check().status == "confirmed"


def test_a_measured_margin_must_be_far_above_the_computation_error():
    check = NumericCheck("x", "n°8", "a quantity keeps its sign", None, lambda: (Margin(1e-18, 1e-20), 40))
    verdict = check.check()
    assert verdict.status == "failed" and verdict.numeric == "smallest margin 1.0e-18 over 40 samples (computed to 1e-20)"
    assert dataclasses.replace(check, run=lambda: (Margin(1e-3, 1e-20), 40)).check().status == "confirmed"
    assert dataclasses.replace(check, run=lambda: (Margin(-1e-3, 1e-20), 40)).check().status == "failed"


def test_a_display_must_be_the_derived_form():
    from derivation.symbols import accent

    eq7 = _claim(n2_motion, "eq7")
    assert eq7.display is not None and eq7.check().status == "confirmed"

    def wrong():  # sin(α − β) where the derived form has sin(β − α): a display that shows another equation
        return [
            sp.Eq(accent(V), -f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g * sp.sin(alpha - beta)),
            sp.Eq(V * accent(alpha), -(R * delta / k**2) * g * sp.cos(beta - alpha)),
        ]

    verdict = dataclasses.replace(eq7, display=wrong).check()
    assert (verdict.status, verdict.symbolic) == ("failed", "display") and "differs from the derived form" in verdict.note
    one_row = dataclasses.replace(eq7, display=lambda: wrong()[1:]).check()
    assert one_row.status == "failed" and "1 rows" in one_row.note


def test_a_reading_shown_must_be_the_reading_checked():
    """`Claim.reading` shows a sentence's reading in the order to read (ρ × (8)₁ for n2.symmetry); it is checked
    equal to ``printed``, so a reading that shows another equation, or another number of rows, fails the claim."""
    symmetry = _claim(n2_motion, "n2.symmetry")
    assert symmetry.reading is not None and symmetry.check().status == "confirmed"
    shown = symmetry.reading
    swapped = dataclasses.replace(symmetry, reading=[sp.Eq(shown[0].lhs, shown[1].rhs), sp.Eq(shown[1].lhs, shown[0].rhs), *shown[2:]])
    verdict = swapped.check()
    assert (verdict.status, verdict.symbolic) == ("failed", "display") and "differs from the reading checked" in verdict.note
    assert "3 rows" in dataclasses.replace(symmetry, reading=shown[1:]).check().note
    # ρ is the display's named part, put in before the comparison: another value for it fails.
    assert dataclasses.replace(symmetry, display_where={n2_motion.RHO: R}).check().status == "failed"
    # A reading is for a sentence the paper states: a claim of ours (no printed form) cannot show one.
    ours = dataclasses.replace(symmetry, printed_tex=None, display=None, reading=shown)
    assert "only for an identity the paper states" in ours.check().note


def test_a_display_keeps_the_order_it_is_written_in_and_its_named_parts_are_put_in():
    from reduction import invariants

    s5 = next(c for c in invariants.claims() if c.id == "inv.s5")
    (row,) = s5.display
    assert invariants.N_NAME in row.free_symbols  # shown as (a − c)𝓝/(27b⁵cos⁵θ), 𝓝 written out after it
    wrong = dataclasses.replace(s5, display_where={**s5.display_where, invariants.N_NAME: invariants.display_L()})
    assert wrong.check().status == "failed"


def test_a_transcription_artefact_is_corrected_by_its_glyphs_alone():
    """M75 (a mutation audit): a typed `corrected=` let a sign difference pass as "ρ read for p".  A typed
    correction is a glyph record's only (its meant form typed, with its LaTeX map)."""
    import derivation

    for c in derivation.claims():
        if c.erratum is not None and c.erratum.kind == "ocr" and c.erratum.corrected is not None:
            assert c.glyph_only and c.erratum.tex, c.id
