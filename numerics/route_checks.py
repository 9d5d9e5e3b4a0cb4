"""Two independent mpmath routes to one motion: the Cartesian equations (4)–(6) in t, and the slide in σ = −ln V.

`cartesian_reference` integrates eqs. (4)–(6) in (ξ, η, ξ', η', p, q, r) with
its own end of slide (an event on the slip, then a local expansion);
`reference_motion` integrates the slide in σ = −ln V and finishes it to first
order.  The Cartesian route takes the rolling and the pivot in closed form (n°7,
eq. (5)), the σ route integrates them.  They share only the equations of
motion, so their agreement on every hard case and every pool shot checks each
route, and the simulator's references with them.
"""

from __future__ import annotations

import mpmath

from derivation.claim import NumericCheck
from numerics import cartesian_reference, classical_vs_appell, hard_cases, reference_motion
from numerics.scene import Scene

ROUTE_DIGITS = 30
REQUIRED_DIGITS = 25


def scenes() -> dict[str, Scene]:
    """Every hard case and every pool shot."""
    out = {f"hard: {k}": v for k, v in hard_cases.hard_cases().items()}
    out.update({f"shot: {k}": Scene(classical_vs_appell.POOL, s, ()) for k, s in classical_vs_appell.SHOTS.items()})
    return out


def _digits(diff, scale) -> float:
    """Digits of agreement: -log10(diff / scale), one decimal (equal: 99)."""
    return 99.0 if diff == 0 else round(float(-mpmath.log10(diff / scale)), 1)


def _compared(a, b, digits_of) -> float | None:
    """``digits_of(a, b)``, or None when neither route has the quantity, 0 when only one has it (a route that
    misses one disagrees, it is not skipped)."""
    if a is None or b is None:
        return None if a is None and b is None else 0.0
    return digits_of(a, b)


def _vector_digits(a, b) -> float:
    """Digits of agreement of two vectors, by the norm of the difference relative to the larger."""
    a, b = list(a), list(b)
    return _digits(mpmath.norm([x - y for x, y in zip(a, b)]), max(mpmath.norm(a), mpmath.norm(b)))


def agreement(a: dict, b: dict, digits: int) -> dict:
    """Digits of agreement of two motions (dicts t_slide_end, t_roll_end, t_pivot_end, rest, omega_end): times
    relative to the motion's duration (the rolling's end, else the slide's; the pivot's if longer), vectors
    relative to the larger (`_vector_digits`).  A quantity one motion has and the other not (a rest point
    against rolling for ever) is 0 digits; one that neither has (no slide, or no end) is left out."""
    with mpmath.workdps(digits + 10):
        ends = [x for x in (b["t_roll_end"], a["t_roll_end"]) if x]
        slides = [x for x in (b["t_slide_end"], a["t_slide_end"]) if x is not None]
        span = ends[0] if ends else max(slides + [mpmath.mpf("1e-3")])
        # The pivot may outlast the rolling: a time is compared relative to the span or itself, the larger.
        found = {key: _compared(a[key], b[key], lambda x, y: _digits(abs(x - y), max(span, abs(y))))
                 for key in ("t_slide_end", "t_roll_end", "t_pivot_end")}
        found |= {key: _compared(a[key], b[key], _vector_digits) for key in ("rest", "omega_end")}
        return {key: value for key, value in found.items() if value is not None}


def as_dict(ref) -> dict:
    """What the two routes are compared on."""
    if isinstance(ref, cartesian_reference.CartesianMotion):
        end = ref.slide_end
        omega = None if end is None else (end["p"], end["q"])
    else:
        omega = None if ref.slide_end is None else (ref.slide_end.p, ref.slide_end.q)
    return {"t_slide_end": ref.t_slide_end, "t_roll_end": ref.t_roll_end, "t_pivot_end": ref.t_pivot_end,
            "rest": ref.rest, "omega_end": omega}


def routes_agree(digits: int = ROUTE_DIGITS) -> tuple[float, int]:
    """The smallest agreement, in digits, of the two routes over every scene and quantity."""
    worst = float("inf")
    all_scenes = scenes()
    for scene in all_scenes.values():
        cart = cartesian_reference.reference(scene, digits=digits)
        sigma = reference_motion.reference(scene, digits=digits, method="taylor")
        worst = min([worst, *agreement(as_dict(cart), as_dict(sigma), digits).values()])  # (None left out there)
    if worst == float("inf"):  # nothing compared on any scene: no agreement shown (an audit: it read 40 digits)
        return 0.0, len(all_scenes)
    return min(worst, float(digits + 10)), len(all_scenes)


def claims() -> list[NumericCheck]:
    return [
        NumericCheck(
            "cartesian_route.agrees_mpmath",
            "n°2, eqs. (4)–(6)",
            f"Two routes agree on the end of sliding, Ω there, the end of rolling, the rest point and the end of the "
            f"pivot: eqs. (4)–(6) integrated in t in Cartesian variables (with its own end of slide), then rolling and "
            f"the pivot in closed form (n°7, eq. (5)); and the slide integrated in σ = −ln V, then rolling and the "
            f"pivot integrated.  Compared at {ROUTE_DIGITS}-digit work on every hard case and every pool shot.",
            None,
            routes_agree,
            required_digits=REQUIRED_DIGITS,
        )
    ]
