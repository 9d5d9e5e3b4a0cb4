"""The supplement: every claim's forms whole, as srepr a reader can evaluate back, and as LaTeX."""

import json

import pytest
import sympy as sp

from paper import supplement, verification


@pytest.mark.slow  # every claim's forms, written and parsed back
def test_the_supplement_holds_the_forms_in_full_and_reads_back():
    claims = [c for c in verification.all_claims() if c.id in ("eq7", "inv.s3", "n8.end_exponent_mpmath")]
    results = verification.check_all(claims)
    text = supplement.supplement_json(results)
    assert text == supplement.supplement_json(results)  # byte-identical
    data = json.loads(text)
    by_id = {entry["id"]: entry for entry in data["claims"]}
    assert set(by_id) == {"eq7", "inv.s3", "n8.end_exponent_mpmath"}
    s3 = by_id["inv.s3"]
    derived = sp.sympify(eval(s3["derived"][0]["srepr"], vars(sp)))  # noqa: S307 - our own file, SymPy names
    shown = eval(s3["display"][0]["srepr"], vars(sp))  # noqa: S307
    assert sp.simplify((derived.rhs - shown.rhs).doit()) == 0
    assert by_id["eq7"]["status"] == "confirmed" and "printed_tex" in by_id["eq7"]
    assert "derived" not in by_id["n8.end_exponent_mpmath"]  # measured, not derived: no forms
