"""The verification record: every module's claims listed and checked, whatever one module does."""

import pytest
import sympy as sp

from derivation import n3_classical, n4_ideal
from derivation.claim import Claim, Verdict
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
        "1 failed; 0 of them glyph records (the meant form typed, not derived)\n\n" + verification.LEGEND
    )


def test_the_table_shows_each_erratum_by_its_class():
    """Every difference showed as "erratum", the 13 glyphs of the OCR copy too (a user's audit): the class now."""
    claims = {c.id: c for c in verification.all_claims()}  # listed: nothing derived
    expected = {"eq10": "mathematical erratum", "n8.V_rate_bound": "remark", "eq2": "transcription artefact"}
    results = [(claims[i], Verdict(i, claims[i].where, "erratum", "exact", "30 digits at 5 points")) for i in expected]
    results.append((claims["eq1"], Verdict("eq1", claims["eq1"].where, "confirmed", "exact", "30 digits at 5 points")))
    rows = verification.as_table(results).splitlines()[2:6]
    assert [row.split("  ")[0] for row in rows] == [*expected, "eq1"]
    assert [row.rstrip().rsplit("  ", 1)[-1].strip() for row in rows] == [*expected.values(), "confirmed"]
    for word in ("exact", "proved", "sampled", "glyph only", "numeric", "confirmed", "transcription artefact"):
        assert word in verification.LEGEND


def test_the_digits_numeric_checks_must_reach_are_the_pinned_ones():
    """Each numeric-only claim's required digits, as pinned (listing the claims derives nothing)."""
    from derivation.claim import NumericCheck
    from expectations import REQUIRED_DIGITS

    found = {c.id: c.required_digits for c in verification.all_claims()
             if isinstance(c, NumericCheck) and c.required_digits is not None}
    assert found == REQUIRED_DIGITS


def test_every_claim_a_statement_names_is_a_claim():
    """Methods: "where a statement argues around it, its other steps are the claims it names" — so each name must
    be a claim (n8.theta_right_angle names n8.theta_rate and n8.end_exponent_mpmath)."""
    import re

    claims = verification.all_claims()
    ids = {claim.id for claim in claims}
    prefixes = {i.split(".")[0] for i in ids}
    named = {(claim.id, name) for claim in claims
             for name in re.findall(r"\b([a-z][a-z0-9_]*\.[A-Za-z0-9_-]*[A-Za-z0-9])", claim.statement)
             if name.split(".")[0] in prefixes}
    assert len(named) > 10
    assert sorted(pair for pair in named if pair[1] not in ids) == []


def test_an_erratum_whose_check_failed_is_counted_as_failed_not_by_its_class():
    claims = {c.id: c for c in verification.all_claims()}  # listed: nothing derived
    results = [(claims["eq2"], Verdict("eq2", claims["eq2"].where, "failed", "exact", "")),
               (claims["eq10"], Verdict("eq10", claims["eq10"].where, "erratum", "exact", ""))]
    summary = verification.as_json(results)["summary"]
    assert summary["errata by class"] == {"mathematical": 1, "remark": 0, "ocr": 0}
    assert (summary["erratum"], summary["failed"]) == (1, 1)


def test_a_kept_record_of_other_claims_is_not_answered_from(monkeypatch):
    """`recorded` checks again when the kept record lists other claims than `all_claims` (a mutation audit:
    dropping the comparison of ids passed)."""
    from paper import record

    kept = {"verify": {"claims": [{"id": "eq10"}]}, "errata": []}
    monkeypatch.setattr(record, "load", lambda: kept)
    monkeypatch.setattr(verification, "verify", lambda quiet=False: [])
    assert verification.recorded(quiet=True) == verification.record_of([])


@pytest.mark.parametrize("quiet", [False, True])
def test_checking_every_claim_first_is_said_even_when_piped(monkeypatch, capsys, quiet):
    """With no record, `appell errata` (or reduce, paper) piped printed nothing for a minute or two, the
    progress counter being for terminals only: one line says why the wait (not with --quiet)."""
    from paper import record

    monkeypatch.setattr(record, "load", lambda: None)
    monkeypatch.setattr(verification, "verify", lambda quiet=False: [])
    assert verification.recorded(quiet=quiet) == verification.record_of([])
    err = capsys.readouterr().err
    assert err == "" if quiet else ("checking every claim first" in err and len(err.splitlines()) == 1)
