"""A cue stroke as a player describes it, turned into the ball's state just after the strike.

The model is the instantaneous point-contact strike of Dr. Dave Alciatore's
technical proof A-30 ("The effect of cue tip offset, cue weight, and cue speed on
cue ball speed and spin", https://billiards.colostate.edu/technical_proofs/new/TP_A-30.pdf),
as pooltool codes it (``pooltool/physics/resolve/stick_ball/instantaneous_point``,
function ``cue_strike``, with the offsets of ``InstantaneousPoint.solve``; the
formulas below were checked against that code, transcribed in the tests):

* the tip meets the ball at one point Q and the impulse J acts along the cue
  (the tip does not slip on the ball), for an instant;
* the tip–ball collision is elastic (pooltool's factor 2 = 1 + e, e = 1): energy
  and momentum balance give the ball's speed along the cue

      v = 2 V0 / (1 + m/M + s² R²/k²),   s² = a² + b²,

  s R being the distance from the ball's centre to the cue's axis, and the
  rotation ω = J (Q × d)/(m k²) = (v R/k²) [a (cos θ ζ̂ + sin θ d̂) + b l̂],
  with d̂ = (cos φ, sin φ, 0) the direction of the shot and l̂ = (−sin φ, cos φ, 0)
  its left.  A-30 and pooltool take a solid ball, k² = 2R²/5; here the ball's
  own k is used, its moment of inertia m k² (the same formulas for k² = 2R²/5);
* the cloth takes the vertical component −v sin θ of an elevated cue's
  impulse: the ball does not leave the table, and its horizontal velocity is
  v cos θ along d̂.  This is pooltool's choice (its "3D FIXME": the vertical
  component is dropped); the cloth's friction during the strike is neglected.

Inputs, as in pooltool's ``Cue``: V0 the cue's speed (m/s), φ its direction in
degrees counter-clockwise from +ξ, θ its elevation in degrees, a and b the
offsets of the cue's axis from the ball's centre, fractions of R measured
across the cue as the player sees the tip on the ball: a > 0 right of centre
(side spin), b > 0 above centre (follow; b < 0 draw).  **pooltool's a has the
opposite sign** (its ``Cue.a = +1`` is the leftmost side of the ball), so
pooltool's (a, b) is (−a, b) here.  A hit right of centre drives the ball's
right side forward: r > 0, counter-clockwise seen from above.  M and m are the
masses of the cue and the ball (kg).  No squirt: pooltool then turns the
velocity by a deflection angle from the cue's end mass (A-31), not modelled here.

Refused (a `SceneError` naming the field): V0, M, m <= 0; θ outside
[0°, 90°); a² + b² >= 1, where the cue's axis misses the ball or only grazes it
(A-30 needs the tip on the ball).  No miscue limit is applied: Dr. Dave's
"How High or Low Should You Hit the Cue Ball?" puts it at about half the radius
from centre (a² + b² ≈ 0.25); beyond it the tip slips and the impulse no longer
acts along the cue: A-30 no longer holds there.  Any
non-finite number is refused too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from numerics.validation import SceneError, real

REQUIRED = ("V0", "phi", "M", "m")
OPTIONAL = ("theta", "a", "b", "xi", "eta")  # 0 when left out: a level centre-ball hit from the origin

__all__ = ["Cue", "strike"]


def _shown(x: float) -> str:
    text = repr(x)
    return text[:-2] if text.endswith(".0") else text


@dataclass(frozen=True)
class Cue:
    """A cue stroke (A-30): V0 (m/s), φ and θ (degrees), a and b (fractions of R), M and m (kg), the ball at (ξ, η)."""

    V0: float
    phi: float
    M: float
    m: float
    theta: float = 0.0
    a: float = 0.0
    b: float = 0.0
    xi: float = 0.0
    eta: float = 0.0

    def __post_init__(self):
        for name in REQUIRED + OPTIONAL:
            object.__setattr__(self, name, real(getattr(self, name), f"cue.{name}"))
        for name in ("V0", "M", "m"):
            if not getattr(self, name) > 0:
                raise SceneError(f"cue.{name}", f"must be > 0, got {_shown(getattr(self, name))}")
        if not 0 <= self.theta < 90:
            raise SceneError("cue.theta", f"must be >= 0 and < 90 (degrees of elevation), got {_shown(self.theta)}")
        if not (abs(self.a) < 1 and abs(self.b) < 1 and self.a**2 + self.b**2 < 1):  # no square of 1e200 (overflow)
            raise SceneError(
                "cue.a, cue.b", f"a² + b² must be < 1 (the cue's axis must meet the ball), got a = {_shown(self.a)}, "
                f"b = {_shown(self.b)}",
            )


def strike(cue: Cue, R: float, k: float) -> tuple[float, float, float, float, float]:
    """The ball's (ξ', η', p, q, r) just after ``cue`` strikes it (A-30), for a ball of radius R and radius of gyration k."""
    phi, theta = math.radians(cue.phi), math.radians(cue.theta)
    # Energy and momentum balance of the elastic strike: the ball's speed along the cue, its vertical part
    # then taken by the cloth.
    v = 2 * cue.V0 / (1 + cue.m / cue.M + (cue.a**2 + cue.b**2) * R**2 / k**2)
    speed = v * math.cos(theta)
    # The angular impulse about the centre, (v R/k²)(a (cos θ ζ̂ + sin θ d̂) + b l̂): b about the left of the shot
    # (follow or draw), a about the vertical (side) and, for an elevated cue, about the line of the shot (massé).
    spin = v * R / k**2
    along, left = cue.a * math.sin(theta), cue.b
    cos_phi, sin_phi = math.cos(phi), math.sin(phi)
    return (
        speed * cos_phi,
        speed * sin_phi,
        spin * (along * cos_phi - left * sin_phi),
        spin * (along * sin_phi + left * cos_phi),
        spin * cue.a * math.cos(theta),
    )
