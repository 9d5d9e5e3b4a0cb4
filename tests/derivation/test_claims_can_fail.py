"""The claims added for what the paper states without a claim so far: each turns red when its
derivation or its printed form is wrong (that they are confirmed is `test_claims.test_claim`)."""

import dataclasses

import pytest
import sympy as sp

from derivation import n2_motion, newton_euler, polar
from derivation.symbols import Omega, beta, p, q


def _claim(module, claim_id):
    return next(c for c in module.claims() if c.id == claim_id)


def _clear(*caches):
    for cache in caches:
        cache.cache_clear()


@pytest.fixture
def swapped_couple(monkeypatch):
    """The rolling couple's components exchanged: it no longer opposes Ω (cos β, sin β)."""
    true_couple = newton_euler.rolling_couple
    monkeypatch.setattr(newton_euler, "rolling_couple", lambda: sp.Matrix([true_couple()[1], true_couple()[0], 0]))
    caches = (n2_motion.horizontal_rotation, newton_euler.accelerations, newton_euler.contact_acceleration, polar.sliding, polar.rolling)
    _clear(*caches)
    yield
    monkeypatch.undo()
    _clear(*caches)


def test_eq3_is_confirmed():
    assert _claim(n2_motion, "eq3").check().status == "confirmed"


def test_eq3_fails_when_the_couple_opposes_another_vector(swapped_couple):
    verdict = _claim(n2_motion, "eq3").check()
    assert verdict.status == "failed" and verdict.symbolic == "not reduced to 0"


def test_eq3_fails_when_p_and_q_are_exchanged():
    claim = _claim(n2_motion, "eq3")
    exchanged = [sp.Eq(p, Omega * sp.sin(beta)), sp.Eq(q, Omega * sp.cos(beta)), *claim.printed[2:]]
    assert dataclasses.replace(claim, printed=exchanged).check().status == "failed"
