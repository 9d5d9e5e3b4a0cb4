"""Every claim of n°9–n°11 and beyond runs as a test of its own."""

from functools import lru_cache

import pytest
from expectations import expected_symbolic

import reduction


@lru_cache(maxsize=None)
def _claims():
    return {c.id: c for c in reduction.claims()}


@pytest.mark.slow
@pytest.mark.parametrize("claim_id", list(_claims()))
def test_claim(claim_id):
    verdict = _claims()[claim_id].check()
    assert verdict.status == "confirmed", verdict
    assert verdict.symbolic == expected_symbolic(_claims()[claim_id]), verdict  # proved stays proved


def test_every_numbered_equation_of_n9_to_n11_has_a_claim():
    wheres = " ".join(c.where for c in _claims().values())
    for number in (12, 13, 14):
        assert f"eq. ({number})" in wheres
    assert {"n°10", "n°11"} <= {c.where.split(" ")[0].rstrip(",") for c in _claims().values()}
