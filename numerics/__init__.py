"""High-precision cross-checks of the closed forms, and (later) the scene simulator.

`reference` is the mpmath Gragg–Bulirsch–Stoer integrator; `reduction_checks`
checks n°10 and n°11 along integrated trajectories.
"""

from __future__ import annotations


def claims() -> list:
    """Every numeric cross-check, as claims for `appell verify`."""
    from numerics import reduction_checks

    return reduction_checks.claims()
