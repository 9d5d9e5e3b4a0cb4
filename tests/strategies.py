"""Hypothesis strategies and a time limit shared by the property-based tests (on the path: pyproject's pythonpath)."""

import contextlib
import math
import signal

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

SECONDS_PER_CASE = 30  # far above any real scene (milliseconds), far below a hang
SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)


@contextlib.contextmanager
def time_limit(seconds=SECONDS_PER_CASE):
    def expired(signum, frame):
        raise TimeoutError(f"no answer in {seconds} s: a hang")

    previous = signal.signal(signal.SIGALRM, expired)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


anything = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(min_value=-(10**400), max_value=10**400),
    st.booleans(), st.none(), st.text(max_size=4), st.decimals(allow_nan=True), st.fractions(),
    st.lists(st.floats(), max_size=2), st.complex_numbers(max_magnitude=10),
)


@st.composite
def physical_params(draw):
    R = draw(st.floats(1e-3, 1.0))
    f = draw(st.floats(1e-3, 1.0))
    return {
        "f": f, "R": R, "k": R * draw(st.floats(0.1, math.sqrt(2 / 3))), "g": draw(st.floats(0.1, 100.0)),
        "delta": f * R * draw(st.sampled_from([0.0, 1e-9, 0.3, 0.9, 0.999])),
        "epsilon": draw(st.sampled_from([0.0, 1e-6, 3e-4, 1e-2])),
    }


def state_value(scale, extremes=(0.0, 1e-12, -1e-9, 1e8, -1e120, 1e300)):
    """Mostly a realistic value, one time in ten an extreme one."""
    return st.integers(0, 9).flatmap(lambda i: st.sampled_from(extremes) if i == 0 else st.floats(-scale, scale))


@st.composite
def states(draw):
    return {
        "xi": draw(state_value(10.0)), "eta": draw(state_value(10.0)), "vxi": draw(state_value(20.0)),
        "veta": draw(state_value(20.0)), "p": draw(state_value(500.0)), "q": draw(state_value(500.0)),
        "r": draw(state_value(500.0)),
    }
