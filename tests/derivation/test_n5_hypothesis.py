"""n°5, eq. (9): each result is proved on the side of its boundary it claims, and fails on the other.

A claim that a result survives without (9) fails when its hypothesis is moved past the boundary;
a claim that a result needs (9) fails when (9) is put back.  So every boundary is exact."""

import dataclasses

import pytest
import sympy as sp

from derivation import checks, n5_hypothesis as n5
from derivation.domain import PHYSICAL
from derivation.symbols import delta, delta_1, f, R

CLAIMS = {c.id: c for c in n5.claims()}
PAPER_BOX = {delta: PHYSICAL["delta"]}  # (9)'s own box, 0 < δ < fR

# Claim id -> (hypothesis, sampling box) on the other side of its boundary.
OTHER_SIDE = {
    "eq9": (n5.BEYOND_9, n5.PAST_9),
    "n5.spin_up_needs_9": (checks.HYPOTHESIS_9, PAPER_BOX),
    "n5.rolling_survives": (n5.BEYOND_ROLLING, n5.PAST_ROLLING),
    "n5.rolling_fails_beyond": (n5.WITHIN_ROLLING_STRICT, n5.UP_TO_ROLLING),
    "n5.slip_ends_survives": (n5.BEYOND_ROLLING, n5.PAST_ROLLING),
    "n5.slip_bound_needs_9": (checks.HYPOTHESIS_9, PAPER_BOX),
    "n5.no_rolling_admissible": (checks.HYPOTHESIS_9, PAPER_BOX),
    "n5.integral_rate_survives": ({delta: n5.SQRT_BOUND * (1 + n5.s1)}, {delta: (n5.SQRT_BOUND, 2 * n5.SQRT_BOUND)}),
}


@pytest.mark.parametrize("claim_id", list(CLAIMS))
def test_confirmed_and_proved(claim_id):
    verdict = CLAIMS[claim_id].check()
    assert verdict.status == "confirmed", verdict
    assert verdict.symbolic in ("proved", "exact"), verdict


@pytest.mark.parametrize("claim_id", list(OTHER_SIDE))
def test_fails_on_the_other_side_of_its_boundary(claim_id):
    hypothesis, box = OTHER_SIDE[claim_id]
    verdict = dataclasses.replace(CLAIMS[claim_id], hypothesis=hypothesis, domain=box).check()
    assert verdict.status == "failed", verdict
    # Not proved, and contradicted by the samples: the other side really is a counterexample.
    assert verdict.symbolic == "violated on sample" and verdict.numeric == "sign violated", verdict


def test_every_inequality_of_n5_has_its_other_side():
    assert {c.id for c in CLAIMS.values() if c.is_inequality} == set(OTHER_SIDE)


def test_sliding_without_rolling_fails_with_another_couple_of_repose():
    claim = CLAIMS["n5.no_rolling_needs_9"]
    wrong = [claim.printed[0], sp.Eq(delta_1, f * R / 2), claim.printed[2]]
    assert dataclasses.replace(claim, printed=wrong).check().status == "failed"


def test_every_claim_quotes_n5_as_its_context():
    """Appell names the cases beyond (9) and leaves them (a referee: his sentences were shown as "Printed" for claims
    he did not make): what n°5 says beyond (9) is ours, the sentence its context; only eq9 quotes (9) itself."""
    for claim in CLAIMS.values():
        assert claim.where == "n°5, eq. (9)"
        if claim.id == "eq9":
            assert claim.printed_tex == n5.HYPOTHESIS_9_PRINTED and claim.context is None
        else:
            assert claim.printed_tex is None and claim.context in (n5.CASES, n5.REAL_CASE, n5.ADMIT, n5.SIMPLIFIES)
