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


@pytest.mark.slow  # derives the forms of half the claims
def test_every_symbol_of_the_appendix_is_defined():
    from paper import appendix, verification

    chosen = [c for c in verification.all_claims() if c.id.startswith(("eq", "n2.", "inv.", "normal."))]
    results = [(c, None) for c in chosen]
    assert notation_table.undefined(appendix.displayed_symbols(results)) == []
