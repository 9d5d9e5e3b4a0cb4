"""A wrong derivation turns claims red and never crashes the checker; listing the claims derives nothing."""

import sys

import pytest

import derivation
import numerics
import reduction
from derivation import n2_motion, n3_classical, newton_euler
from paper import verification
from reduction import n9_reduced_system, n10_special_case

PACKAGES = (derivation, reduction, numerics)


def _caches() -> dict:
    """Every lru_cache of the package's own functions, by qualified name."""
    for package in PACKAGES:
        package.sections()  # imports every module with claims, and what they derive from
    names = {package.__name__ for package in PACKAGES}
    return {
        f"{value.__module__}.{value.__qualname__}": value
        for name, module in list(sys.modules.items())
        if name.partition(".")[0] in names
        for value in vars(module).values()
        if hasattr(value, "cache_clear") and value.__module__ == name
    }


def _clear_caches():
    # Every cache is downstream of (4) or may be: clearing them all misses none.
    for cache in _caches().values():
        cache.cache_clear()


@pytest.fixture
def rolling_couple_doubled(monkeypatch):
    """The issue's mutation: `rolling_couple` returns twice its value, and nothing derived before survives."""
    true_couple = newton_euler.rolling_couple
    monkeypatch.setattr(newton_euler, "rolling_couple", lambda: 2 * true_couple())
    monkeypatch.setenv("APPELL_JOBS", "1")
    _clear_caches()
    yield
    monkeypatch.undo()
    _clear_caches()  # later tests derive from the true couple again


def test_listing_the_claims_runs_no_derivation(monkeypatch):
    def underived():
        raise AssertionError("a load was derived while listing the claims")

    # The loads are the derivations not behind a cache; a call of a cached one shows in its counts.
    for load in ("sliding_force", "rolling_couple"):
        monkeypatch.setattr(newton_euler, load, underived)
    calls = {name: cache.cache_info()[:2] for name, cache in _caches().items()}
    claims = derivation.claims() + reduction.claims() + numerics.claims()
    assert {name: cache.cache_info()[:2] for name, cache in _caches().items()} == calls
    assert len(claims) == len({c.id for c in claims})


def test_a_doubled_rolling_couple_fails_claims_and_crashes_nothing(rolling_couple_doubled):
    # Enough of the record to see all three outcomes, in a fraction of its time.
    pivot = {"eq5", "n2.pivot", "n2.pivot_time", "n2.pivot_stays_zero"}
    mismatched = {"n2.rolling_couple", "eq7", "eq8"}
    claims = [c for c in n2_motion.claims() if c.id in pivot | mismatched]
    claims += n3_classical.claims() + n9_reduced_system.claims() + n10_special_case.claims()
    results = verification.check_all(claims)

    assert [c.id for c, _ in results] == [v.id for _, v in results] == [c.id for c in claims]
    status = {v.id: v for _, v in results}
    # Compared with the printed forms, the doubled couple shows.
    for claim_id in mismatched:
        assert status[claim_id].status == "failed" and status[claim_id].symbolic != "derivation raised"
    # a, b, c cannot be read off (7)-(8) any more: n°9's constants raise, and all that builds on them fails.
    raised = [v for v in status.values() if v.symbolic == "derivation raised"]
    assert {"n9.constants", "n9.order", "eq14", "n10.integral", "n10.physical"} <= {v.id for v in raised}
    for verdict in raised:
        assert verdict.status == "failed" and verdict.numeric == "not run"
        assert verdict.note.startswith("ArithmeticError: ") and "structure of (12)" in verdict.note
    # The couple does not act at δ = 0 (n°3) nor on the pivot (5): those still hold.
    for claim in n3_classical.claims():
        assert status[claim.id].status == ("confirmed" if claim.erratum is None else "erratum"), status[claim.id]
    for claim_id in pivot:
        assert status[claim_id].status == "confirmed", status[claim_id]


def test_a_vertical_rolling_couple_breaks_the_pivot_at_rest(monkeypatch):
    """n2.pivot_stays_zero is derived from (4)–(5): a couple about ζ would need a pivot couple beyond εmg."""
    import sympy as sp

    from derivation.symbols import epsilon, g, m

    true_couple = newton_euler.rolling_couple
    monkeypatch.setattr(newton_euler, "rolling_couple", lambda: true_couple() + sp.Matrix([0, 0, 2 * epsilon * m * g]))
    _clear_caches()
    try:
        claim = next(c for c in n2_motion.claims() if c.id == "n2.pivot_stays_zero")
        assert claim.check().status == "failed"
    finally:
        monkeypatch.undo()
        _clear_caches()


def test_n9_reads_alpha_off_the_derivation(monkeypatch):
    """n9.alpha compares the printed dα with α' read off (7)–(8), not with a typed form."""
    true_rates = n9_reduced_system.physical_rates.__wrapped__

    def turned_back():  # the slip turning the other way: still ±b cos θ/x, so read off, and wrong
        rates = dict(true_rates())
        rates["alpha'"] = -rates["alpha'"]
        return rates

    monkeypatch.setattr(n9_reduced_system, "physical_rates", turned_back)
    n9_reduced_system.reduced_rates.cache_clear()
    try:
        claim = next(c for c in n9_reduced_system.claims() if c.id == "n9.alpha")
        verdict = claim.check()
        # A mismatch of the forms, not a raise: the claim itself compares with the derivation.
        assert verdict.status == "failed" and verdict.symbolic == "not reduced to 0"
    finally:
        monkeypatch.undo()
        n9_reduced_system.reduced_rates.cache_clear()
