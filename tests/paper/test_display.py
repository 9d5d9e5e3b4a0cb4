"""The derived forms in the paper's arrangement: only the order changes, never the form; and lines that fit."""

import sympy as sp

from derivation import n2_motion
from derivation.claim import evaluated
from derivation.symbols import R, V, accent, alpha, beta, delta, f, g, k, m, snapshot
from paper import display


def _claim(claim_id):
    return next(c for c in n2_motion.claims() if c.id == claim_id)


def test_the_angle_difference_is_written_as_the_paper_writes_it():
    eq7 = _claim("eq7")
    arrangement = display.Arrangement.of(eq7.printed_tex)
    assert ("\\beta", "\\alpha") in arrangement.differences
    shown = [display.display_tex(display.arrange(form, arrangement)) for form in eq7.derived]
    assert all(r"\sin(\beta - \alpha)" in s or r"\cos(\beta - \alpha)" in s for s in shown)
    assert not any(r"\alpha - \beta" in s for s in shown)
    # SymPy alone writes sin(α − β): the arrangement, not luck, turns it round (with the sign).
    assert r"\alpha - \beta" in display.display_tex(display.arrange(eq7.derived[0], None))


def test_terms_and_factors_follow_the_printed_latex_and_numbers_come_first():
    arrangement = display.Arrangement.of(r"n = mg")
    assert display.display_tex(display.arrange(sp.Eq(sp.Symbol("n"), g * m), arrangement)) == "n = m g"
    assert display.display_tex(display.arrange(sp.Eq(sp.Symbol("n"), g * m), None)) == "n = g m"  # SymPy's order
    arrangement = display.Arrangement.of(r"m\eta'' = Y, \\ mk^2 p' = RY + L")  # R before Y, though Y comes first
    X, Y, L = sp.symbols("X Y L")
    assert display.display_tex(display.arrange(R * Y + L, arrangement)) == "R Y + L"
    v = sp.Symbol("V")
    assert display.display_tex(display.arrange(2 * R * f * v, display.Arrangement.of("f V R"))) == "2 f V R"


def test_an_arranged_form_is_the_derived_form():
    # Arranging reorders and turns differences round; evaluated again, it is the very same SymPy object.
    for claim_id in ("eq6", "eq7", "eq8", "n2.contact_generic", "eq4", "n2.sliding_polar"):
        claim = _claim(claim_id)
        arrangement = display.Arrangement.of(claim.printed_tex)
        for form in claim.derived:
            assert evaluated(display.arrange(form, arrangement)) == form, claim_id


def test_a_display_prints_in_the_order_it_was_built():
    with sp.evaluate(False):
        tree = snapshot(-f * g * (1 + R**2 / k**2) + (R * delta / k**2) * g * sp.sin(beta - alpha))
    assert display.display_tex(sp.Eq(accent(V), tree, evaluate=False)) == (
        r"V' = - f g \left(1 + \frac{R^{2}}{k^{2}}\right) + \frac{R \delta}{k^{2}} g \sin(\beta - \alpha)"
    )


def test_a_long_sum_is_broken_into_lines_that_fit_and_an_unbreakable_one_is_refused():
    terms = [f"+ \\frac{{a_{{{i}}} b^{{2}}}}{{c^{{3}}}} \\sin \\theta" for i in range(12)]
    laid = display.layout([r"J &= x"] + terms)
    assert laid.lines is not None and len(laid.lines) > 1
    assert all(display.tex_width(line.replace("&", "")) <= display.COLUMN for line in laid.lines)
    assert all(line.startswith(r"&\quad") for line in laid.lines[1:])
    assert display.layout([r"J &= " + " ".join(t[2:] for t in terms)]).lines is None


def test_a_product_with_a_long_sum_opens_round_it():
    a, b, c, s = sp.symbols("a b c s")
    with sp.evaluate(False):
        long = (a - c) * (9 * b**2 - 9 * b * (a + c) * s + (a + 2 * c) * (2 * a + c) + 7 * a * b * c * s**3) / (27 * b**3)
    pieces = display.relation_pieces(sp.Eq(sp.Symbol("s_3"), long, evaluate=False))
    assert len(pieces) > 1 and r"\Bigl(" in pieces[0] and pieces[-1].endswith(r"\Bigr)")
    assert pieces[0].startswith(r"s_{3} &= \frac{a - c}{27 b^{3}}")


def test_widths_grow_with_what_is_written():
    assert display.tex_width("m") > display.tex_width("l")
    assert display.tex_width(r"\frac{R^{2}}{k^{2}}") < display.tex_width("R^{2} k^{2}")
    assert display.tex_width(r"\left(\frac{a}{b}\right)") > display.tex_width(r"\left(ab\right)")
