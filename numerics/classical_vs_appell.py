"""Appell's model beside the classical one, on realistic pool shots.

The classical model (common billiards simulators): no rolling couple while
the ball slides (n°3), then rolling that slows at a constant rate.  Appell's
model keeps the rolling couple during the slide as well (δ > 0 in eqs. (4)).
Both share every parameter, so the difference is that couple alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from numerics.scene import Params
from numerics.scene import Scene, State
from numerics.simulate import simulate
from numerics.validation import DEFAULT_TOL

R_BALL = 0.028575  # a 57.15 mm pool ball
# f = 0.2 (sliding on cloth); δ = 0.4 mm gives the rolling deceleration δgR/(R² + k²) ≈ 0.1 m/s²
# of a cloth of rolling resistance 0.01; ε = 0.3 mm.
POOL = Params(f=0.2, delta=0.0004, epsilon=0.0003, R=R_BALL, k=R_BALL * math.sqrt(0.4))

# ξ' > 0 is the shot's direction; q > 0 is top spin (rolling is ξ' = qR), q < 0 back spin,
# p ≠ 0 a spin about the line of the shot (an elevated cue: massé).
SHOTS = {
    "straight (centre ball, 1.5 m/s)": State(0, 0, 1.5, 0, 0, 0, 0),
    "stun (centre ball, 4 m/s)": State(0, 0, 4.0, 0, 0, 0, 0),
    "draw (3 m/s, back spin 150 rad/s)": State(0, 0, 3.0, 0, 0, -150.0, 0),
    "follow (3 m/s, top spin 150 rad/s)": State(0, 0, 3.0, 0, 0, 150.0, 0),
    "massé (0.5 m/s, spin 130 rad/s across)": State(0, 0, 0.5, 0, -120.0, -50.0, 20.0),
}


@dataclass(frozen=True)
class Row:
    shot: str
    t_slide_appell: float
    t_slide_classical: float
    rest_appell: tuple
    rest_classical: tuple
    rest_apart: float | None  # distance between the two rest points, m (None: δ = 0, no rest)
    turn_apart: float  # difference of the rolling directions after the slide, degrees
    error: float | None  # the larger of the two runs' estimated relative errors (None: no rest point, δ = 0)


def _rolling_direction(motion) -> float:
    end = motion.state_at(motion.t_slide_end)
    return math.degrees(math.atan2(end.veta, end.vxi))


def compare(tol: float = DEFAULT_TOL, params: Params = POOL) -> list[Row]:
    rows = []
    for name, state in SHOTS.items():
        a = simulate(Scene(params, state, (), "appell"), tol)
        c = simulate(Scene(params, state, (), "classical"), tol)
        turn = (_rolling_direction(a) - _rolling_direction(c) + 180) % 360 - 180
        rows.append(
            Row(
                name, a.t_slide_end, c.t_slide_end, a.rest, c.rest,
                None if a.rest is None else math.hypot(a.rest[0] - c.rest[0], a.rest[1] - c.rest[1]),
                turn, max((e for e in (a.error, c.error) if e is not None), default=None),
            )
        )
    return rows


def as_text(rows: list[Row], params: Params = POOL) -> str:
    head = (
        f"Pool ball R = {params.R * 1000:g} mm, f = {params.f:g}, delta = {params.delta * 1000:g} mm, "
        f"epsilon = {params.epsilon * 1000:g} mm; Appell (rolling couple while sliding) vs classical (none).\n\n"
        "| shot | sliding time Appell (s) | classical (s) | change | rest point Appell (m) | classical (m) "
        "| rest points apart (mm) | rolling direction apart (deg) |\n"
        "|---|---|---|---|---|---|---|---|"
    )
    lines = [head]
    z = lambda x: round(x, 4) + 0.0  # noqa: E731  (no "-0.0000")
    for r in rows:
        change = (r.t_slide_appell - r.t_slide_classical) / r.t_slide_classical if r.t_slide_classical else 0.0
        lines.append(
            f"| {r.shot} | {r.t_slide_appell:.4f} | {r.t_slide_classical:.4f} | {100 * change:+.2f} % "
            f"| ({z(r.rest_appell[0]):.4f}, {z(r.rest_appell[1]):.4f}) | ({z(r.rest_classical[0]):.4f}, {z(r.rest_classical[1]):.4f}) "
            f"| {1000 * r.rest_apart:.1f} | {z(round(r.turn_apart, 3)):+.3f} |"
        )
    worst = max((r.error for r in rows if r.error is not None), default=0.0)
    lines.append(f"\nEvery figure to an estimated relative error below {max(worst, 1e-15):.0e} (appell simulate's estimate).")
    return "\n".join(lines)
