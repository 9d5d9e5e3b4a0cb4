"""The verification record: every module's claims listed and checked, whatever one module does."""

import sympy as sp

from derivation import n3_classical, n4_ideal
from derivation.claim import Claim
from derivation.symbols import V, d
from paper import verification


def test_a_module_whose_claims_cannot_be_listed_fails_alone(monkeypatch):
    def unlistable():
        raise RuntimeError("n°4 could not be listed")

    n4_ids = {c.id for c in n4_ideal.claims()}
    monkeypatch.setattr(n4_ideal, "claims", unlistable)
    claims = verification.all_claims()
    ids = [c.id for c in claims]
    (stand_in,) = [c for c in claims if c.id == "derivation.n4_ideal"]
    verdict = stand_in.check()
    assert (verdict.status, verdict.note) == ("failed", "RuntimeError: n°4 could not be listed")
    assert not n4_ids & set(ids)
    assert all(c.id in ids for c in n3_classical.claims())


def test_the_table_says_why_a_claim_failed():
    def underivable():
        raise ArithmeticError("(7)-(8) do not have the structure of (12)")

    claim = Claim("broken", "n°9", "A claim whose derivation raises.", None, sp.Eq(d(V), 0), underivable)
    table = verification.as_table(verification.check_all([claim]))
    assert "derivation raised" in table and "not run" in table
    assert "broken: ArithmeticError: (7)-(8) do not have the structure of (12)" in table
    assert table.endswith(
        "1 claims: 0 confirmed, 0 printed differently (0 mathematical errata, 0 remarks, 0 transcription artefacts), "
        "1 failed; 0 of them glyph records (the meant form typed, not derived)"
    )
