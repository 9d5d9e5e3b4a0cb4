"""The table of symbols defines every symbol a display shows."""

import pytest
import sympy as sp

from paper import notation_table


def test_a_displayed_symbol_without_a_definition_stops_the_table():
    heading = lambda title, name: f"[{title}]"  # noqa: E731
    cite = lambda key: f"[{key}]"  # noqa: E731
    tex = notation_table.notation_tex({sp.Symbol("R"), sp.Symbol("t_1"), sp.Symbol("V'")}, heading, cite)
    assert "radius of the ball" in tex and "two things" in tex  # t₁: n°2's end of pivot and n°7's end of rolling
    with pytest.raises(ValueError, match="without a definition in the notation table: zeta_9"):
        notation_table.notation_tex({sp.Symbol("zeta_9")}, heading, cite)


def test_the_quantities_named_for_a_check_come_in_the_order_the_appendix_shows_them():
    """A referee: sorted by their words, the named quantities read as unsorted ("the product of the two roots"
    between "the pivot couple" and "the variable of the normal form"); they come in the order given, the order of
    the claims that first show them (`appendix.displayed_symbols`)."""
    from derivation.symbols import label

    heading = lambda title, name: ""  # noqa: E731
    later, first = label("zz test quantity, shown first", "Z_t"), label("aa test quantity, shown second", "A_t")
    tex = notation_table.notation_tex([later, first], heading, lambda key: key)
    assert tex.index("shown first") < tex.index("shown second")
    tex = notation_table.notation_tex({later, first}, heading, lambda key: key)  # a set has no order: by name
    assert tex.index("shown second") < tex.index("shown first")


def test_the_symbols_shown_are_in_the_order_of_the_claims_that_show_them():
    from paper import appendix, verification

    claims = {c.id: c for c in verification.all_claims()}
    shown = appendix.displayed_symbols([(claims["n2.symmetry"], None), (claims["n10.recovery_unique"], None)])
    names = [s.name for s in shown]
    assert names.index("[row 1 of (7)–(8) after the symmetry map (n2.symmetry)]") < names.index("[x₁x₂, the product of the two roots' x]")
    shown = appendix.displayed_symbols([(claims["n10.recovery_unique"], None), (claims["n2.symmetry"], None)])
    names = [s.name for s in shown]
    assert names.index("[row 1 of (7)–(8) after the symmetry map (n2.symmetry)]") > names.index("[x₁x₂, the product of the two roots' x]")


@pytest.mark.slow  # derives the forms of half the claims
def test_every_symbol_of_the_appendix_is_defined():
    from paper import appendix, verification

    chosen = [c for c in verification.all_claims() if c.id.startswith(("eq", "n2.", "inv.", "normal."))]
    results = [(c, None) for c in chosen]
    assert notation_table.undefined(appendix.displayed_symbols(results)) == []


def test_every_entry_of_the_committed_table_is_used_by_the_appendix():
    """A table entry for a symbol no other part of the appendix shows (t_max, a glyph record's hidden label) sends
    a reader looking for it."""
    import re
    from pathlib import Path

    generated = Path(notation_table.__file__).resolve().parent / "generated"
    table = (generated / "notation.tex").read_text(encoding="utf-8")
    rest = "".join(p.read_text(encoding="utf-8") for p in sorted(generated.glob("*.tex")) if p.name != "notation.tex")
    squeeze = lambda tex: re.sub(r"[\s{}]|\\left|\\right", "", tex)  # noqa: E731  (spacing and grouping aside)
    rest = squeeze(rest)
    labels = re.findall(r"^\\item\[\$(.+?)\$\] ", table, flags=re.MULTILINE)
    assert len(labels) > 40
    conventions = {"X'", "X''", r"\left(x\right)_{n}"}  # the accents and the rising factorial, on other letters
    unused = [tex for label in labels for tex in label.split(r",\ ") if squeeze(tex) not in rest and tex not in conventions]
    assert unused == []
