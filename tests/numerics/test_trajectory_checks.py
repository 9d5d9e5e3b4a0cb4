"""The trajectory cross-checks have teeth: what they compare differs when the physics differs.

(Each check itself runs, and must be confirmed, in `appell verify`: tests/paper/test_cli.py.)
"""

import mpmath
import pytest

from numerics import phases, trajectory_checks as tc


def test_rolling_couple_is_visible_against_n3():
    # With δ > 0 the integrated motion must depart from n°3's closed form (which has δ = 0)
    # by far more than the 28 digits the δ = 0 check asks for.
    P, start = tc.POOL, tc.SHOTS[0]
    with mpmath.workdps(tc.DIGITS + 10):
        times, states = tc.cartesian_run(P, start)
        V0, alpha0 = tc._slip(P, [mpmath.mpf(x) for x in start])
        Omega0, beta0 = mpmath.hypot(start[4], start[5]), mpmath.atan2(start[5], start[4])
        _, local = phases.classical_slide(P, V0, Omega0, beta0 - alpha0, num=mpmath.mpf)
        exact = tc._world(local(times[-1]), alpha0, 0, 0)
        assert tc._worst_state_error(exact, states[-1][:6], tc._scale(P, start)) > 1e-4


@pytest.mark.slow
def test_times_stay_inside_the_slide():
    for P in (tc.POOL, tc.HEAVY):
        for start in tc.SHOTS:
            times, _ = tc.cartesian_run(P, start)
            assert times[-1] < tc.reference_slide(P, start).end.t


def test_digits_of_an_exact_agreement_are_capped():
    assert tc._digits(mpmath.mpf(0)) == tc.DIGITS + 10
    assert round(tc._digits(mpmath.mpf("1e-12"))) == 12


# Each check turns red when what it compares is off by 1e-20 (a mutation audit: comparing the closed form with
# itself, n°7's friction with itself, the drop's sign, the pivot's stopping time or β, each left its claim confirmed).
def _off(monkeypatch, name, change):
    """``tc.<name>``'s run with ``change`` applied to each of its states."""
    real = getattr(tc, name)

    def run(P, start, *args):
        first, states = real(P, start, *args)
        return first, [change(list(s)) for s in states]

    monkeypatch.setattr(tc, name, run)


def _scaled(s, i, factor):
    return s[:i] + [s[i] * factor] + s[i + 1:]


def test_n3_sees_the_integrated_states(monkeypatch):
    _off(monkeypatch, "cartesian_run", lambda s: _scaled(s, 2, 1 + mpmath.mpf("1e-20")))
    assert tc.n3_closed_form()[0] < 25


def test_cartesian_against_reduced_sees_beta(monkeypatch):
    _off(monkeypatch, "reduced_run", lambda s: s[:3] + [s[3] + mpmath.mpf("1e-20")] + s[4:])
    assert tc.cartesian_matches_reduced()[0] < 25


def test_an_increasing_product_is_caught(monkeypatch):
    real = tc.cartesian_run

    def reversed_in_time(P, start):
        first, states = real(P, start)
        return first, states[::-1]

    monkeypatch.setattr(tc, "cartesian_run", reversed_in_time)
    assert not tc.product_decreases()[0].holds()


def test_the_pivot_check_sees_its_stopping_time(monkeypatch):
    real = phases.pivot

    def later(P, r0, num):
        t1, r_of = real(P, r0, num=num)
        return t1 * (1 + mpmath.mpf("1e-20")), r_of

    monkeypatch.setattr(phases, "pivot", later)
    assert tc.pivot_closed_form()[0] < 25


def test_n7_sees_the_friction_f1(monkeypatch):
    import sympy as sp

    from derivation import n7_pure_rolling

    true = n7_pure_rolling.motion()
    monkeypatch.setattr(n7_pure_rolling, "motion", lambda: {**true, "f_1": true["f_1"] * (1 + sp.Rational(1, 10**20))})
    assert tc.n7_closed_form()[0] < 25
