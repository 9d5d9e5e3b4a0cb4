"""High-precision cross-checks of the closed forms, and the scene simulator.

Cross-checks: `reference` is the mpmath Gragg–Bulirsch–Stoer integrator;
`trajectory_checks` checks n°3–n°9 and the straight shots, and
`reduction_checks` n°10 and n°11, along integrated trajectories;
`spin_near_zero` follows a curved slide whose Ω passes within 10⁻⁹ rad/s of zero;
`route_checks`: the Cartesian route (`cartesian_reference`, eqs. (4)–(6) in t)
and the σ route (`reference_motion`) agree; `taylor` is the Taylor-series
integrator both use.

Simulator: `scene` reads a shot, `simulate` solves it phase by phase with
the closed forms of `phases` and the numerical slide of `sliding`;
`reference_motion` is the same motion in mpmath with no closed form, to test
it against.  `equations` compiles every right-hand side from derivation/.
"""

from __future__ import annotations


def sections() -> tuple:
    """The modules with numeric cross-checks, in order."""
    from numerics import reduction_checks, route_checks, spin_near_zero, trajectory_checks

    return (trajectory_checks, route_checks, spin_near_zero, reduction_checks)


def claims() -> list:
    """Every numeric cross-check, as claims for `appell verify`."""
    return [claim for section in sections() for claim in section.claims()]
