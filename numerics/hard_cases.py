"""The shots that are hard for a simulator, as scenes: the test set of the numerics issue.

Each is a realistic pool ball (R = 57.15 mm, f = 0.2, solid, k² = 2R²/5)
unless the case is about the parameters.  ``q < 0`` is draw (back spin) for
a ball moving along +ξ: rolling is ξ' = qR (eq. (2) with u = 0).
"""

from __future__ import annotations

import math

from numerics.scene import Scene, parse

R_BALL = 0.028575
POOL = {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": R_BALL}


def _scene(state: dict, times=(), **params) -> Scene:
    full = {"xi": 0.0, "eta": 0.0, "vxi": 0.0, "veta": 0.0, "p": 0.0, "q": 0.0, "r": 0.0, **state}
    return parse({"params": {**POOL, **params}, "state": full, "t": list(times)})


def hard_cases() -> dict[str, Scene]:
    """Name -> scene, one per hard case of the issue (and the sample scene)."""
    fR = POOL["f"] * R_BALL
    return {
        "sample": _scene({"vxi": 2.0, "p": 10.0, "q": -40.0, "r": 5.0}, times=(0.1, 0.5)),
        # n°6: Ω₀ = 0, Ω leaves zero along β = α + π/2.
        "centre hit": _scene({"vxi": 2.0}, times=(0.1,)),
        # Ω passes within 0.3 rad/s of zero while the slip is 4 m/s.
        "draw, little side spin": _scene({"vxi": 2.0, "p": 0.3, "q": -100.0}, times=(0.2,)),
        # The same shot exactly straight: Ω passes through zero (closed form, two stretches).
        "straight draw": _scene({"vxi": 2.0, "q": -100.0}, times=(0.2,)),
        "delta close to fR": _scene({"vxi": 1.5, "p": 20.0, "q": 30.0}, delta=0.99 * fR),
        "delta tiny": _scene({"vxi": 1.5, "p": 20.0, "q": 30.0}, delta=1e-9),
        # A massé: 400 rad/s of spin, 5 cm/s of speed.
        "huge spin, small speed": _scene({"vxi": 0.05, "p": 300.0, "q": -250.0}),
        "pivoting, r0 != 0": _scene({"vxi": 1.0, "veta": 0.5, "p": 5.0, "q": 10.0, "r": 40.0}),
        "pivoting for ever (epsilon = 0)": _scene({"vxi": 1.0, "p": 5.0, "q": 10.0, "r": 40.0}, epsilon=0.0),
        "at rest": _scene({}),
        "spinning in place": _scene({"p": 20.0, "q": 5.0}),
        "pure rolling start": _scene({"vxi": 1.2, "veta": -0.5, "p": 0.5 / R_BALL, "q": 1.2 / R_BALL}),
        "rolls for ever (delta = 0)": _scene({"vxi": 1.0, "p": 3.0, "q": -30.0}, delta=0.0),
    }


def angle(a: float, b: float) -> float:
    """|a − b| on the circle."""
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))
