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
