"""The mpmath reference integrator, on problems with known solutions."""

import mpmath
import pytest

from numerics.reference import solve


@pytest.mark.parametrize("digits", [15, 30, 50])
def test_exponential_to_the_asked_digits(digits):
    (y,), stats = solve(lambda t, y: [y[0]], 0, [1], [mpmath.mpf(2)], digits)
    with mpmath.workdps(digits + 10):
        assert abs(y[0] - mpmath.e**2) / mpmath.e**2 < mpmath.mpf(10) ** (-digits)
    # Extrapolation reaches 50 digits of e² in a handful of large steps (measured: 4, 7, 7, none rejected):
    # a broken step-size control or error estimate shows as many more.
    assert stats.steps <= 10 and stats.rejected <= 1


def test_oscillator_lands_on_every_requested_time():
    times = [mpmath.mpf(k) / 3 for k in range(1, 10)]
    states, _ = solve(lambda t, y: [y[1], -y[0]], 0, [0, 1], times, 30)
    with mpmath.workdps(40):
        for t, (s, c) in zip(times, states):
            assert abs(s - mpmath.sin(t)) < mpmath.mpf(10) ** -30
            assert abs(c - mpmath.cos(t)) < mpmath.mpf(10) ** -30


def test_a_time_dependent_right_hand_side():
    # y' = cos t → sin t: checks that the stages use the right times.
    (y,), _ = solve(lambda t, y: [mpmath.cos(t)], 0, [0], [mpmath.mpf(3)], 30)
    with mpmath.workdps(40):
        assert abs(y[0] - mpmath.sin(3)) < mpmath.mpf(10) ** -30


def test_the_reference_integrator_holds_every_component_to_the_tolerance():
    """GBS's error test reads every component (a mutation reading only the first passed every test): a
    first component that is exact from the first column must not accept the step for the others."""
    states, _ = solve(lambda t, y: [0 * y[0], y[1]], 0, [mpmath.mpf(1), mpmath.mpf(1)], [2], digits=30)
    with mpmath.workdps(40):
        assert abs(states[0][1] - mpmath.e**2) < mpmath.mpf(10) ** -29 * mpmath.e**2
