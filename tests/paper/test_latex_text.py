"""Prose as LaTeX: the maths in a statement comes out as maths, its words as text."""

import pytest

from paper.latex_text import code_text, pdf_text, plain_text, tex_text


def test_maths_in_prose_is_set_as_maths():
    assert tex_text("With r_0 > 0 the pivoting decreases") == r"With $r_{0} > 0$ the pivoting decreases"
    assert tex_text("π/2 − θ ∝ V^κ") == r"$\pi / 2 - \theta \propto V^{\kappa}$"
    assert tex_text("down to V = 10^-200 V₀.") == r"down to $V = 10^{-200} V_{0}$."
    assert tex_text("√(R²+k²)") == r"$\sqrt{R^{2} + k^{2}}$"
    assert tex_text("3 sin²θ − 2") == r"$3 \sin^{2} \theta - 2$"
    assert tex_text("V₀ = 4 m/s") == r"$V_{0} = 4 \,\mathrm{m/s}$"


def test_a_number_in_e_notation_is_a_power_of_ten_and_a_command_stays_as_typed():
    """3.7e-02 was set as $3.7 e - 02$ (e a variable) and `appell paper --pdf` as $- - p d f$ (a referee's read)."""
    assert tex_text("margin 3.7e-02 (computed to 1e-30)") == r"margin $3.7\times10^{-2}$ (computed to $10^{-30}$)"
    assert tex_text("at tol 1e-9 on one thread") == r"at tol $10^{-9}$ on one thread"
    assert tex_text("1.5e+3 and 2e5") == r"$1.5\times10^{3}$ and $2\times10^{5}$"
    assert code_text("appell paper --pdf & 100%") == r"appell paper --pdf \& 100\%"


def test_words_stay_text_the_article_a_included():
    assert tex_text("For a random Abel equation, a = c.") == r"For a random Abel equation, $a = c$."
    assert tex_text("A draw just off the line, at the contact A moves") == r"A draw just off the line, at the contact $A$ moves"
    assert tex_text("a glyph record") == "a glyph record"  # y counts as a vowel in glyph, not in xy
    assert tex_text("xy") == "$x y$"
    assert tex_text("i.e. n°7's (9)") == r"i.e. n\textsuperscript{o}7's (9)"
    # a degree is a degree sign, not n°'s superscript o (a referee read "α₀ = 5.19º")
    assert tex_text("α₀ = 5.19°, n°8") == r"$\alpha_{0} = 5.19$\ensuremath{^\circ}, n\textsuperscript{o}8"
    assert tex_text("sliding/rolling and 17-point") == "sliding/rolling and 17-point"


def test_identifiers_are_typewriter_and_breakable():
    assert tex_text("see n8.V_decreases") == r"see \texttt{n8.\allowbreak{}V\appellus\allowbreak{}decreases}"
    assert code_text("APPELL_CACHE=x appell") == r"APPELL\appellus{}CACHE=x appell"


def test_an_aside_in_brackets_is_its_own_maths():
    assert tex_text("β = 0 (p = Ω, q = 0)") == r"$\beta = 0$ $( p = \Omega , q = 0 )$"
    assert tex_text("(harmless: V' < −fg)") == r"(harmless: $V' < - f g$)"


def test_a_character_without_latex_is_an_error_not_a_blank():
    with pytest.raises(ValueError, match="U\\+2603"):
        tex_text("snow ☃")
    # A subscript on a bracket, as n2.symmetry once wrote "(8)₁": the bare ₁ passed into the LaTeX and stopped
    # pdflatex at the compile; it is set as a subscript, and what no rule sets (a capital À) is an error here.
    assert tex_text("(x + y)₁") == "$( x + y )$$_{1}$"
    with pytest.raises(ValueError, match="U\\+00C0"):
        tex_text("VÀ")


def test_a_french_sentence_is_text_and_a_bookmark_is_ascii():
    assert plain_text("il y a différents cas") == r"il y a diff\'erents cas"
    assert pdf_text("n°5 — The hypothesis δ < fR (9)") == "no5 - The hypothesis delta < fR (9)"


def test_a_processor_is_named_without_its_marks():
    """The saved bench ran on "Intel(R) Xeon(R) Processor", which the caption set as Intel$( R )$ Xeon$( R )$."""
    from paper.latex_text import processor

    assert processor("Intel(R) Xeon(R) Processor") == "Intel Xeon"
    assert processor("Intel(R) Core(TM) i7-8700 CPU @ 3.20GHz") == "Intel Core i7-8700"
    assert processor("AMD EPYC 7B13 64-Core Processor") == "AMD EPYC 7B13"
    assert processor("AMD EPYC") == "AMD EPYC" and processor("") == "unknown"
    assert "$" not in tex_text(processor("Intel(R) Xeon(R) Processor"))
