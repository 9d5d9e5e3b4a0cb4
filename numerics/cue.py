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

Many strokes at once: `strikes(R, k, V0=..., phi=..., M=..., m=..., ...)` takes
each field as a number or a 1-D array (broadcast together as NumPy does) and
returns the (n, 7) states (ξ, η, ξ', η', p, q, r) that
`numerics.batch.simulate_many` takes, a row per stroke, each `strike`'s result
to the bit (one function computes both).  The same rules, in the same order:
a broken one names the field and, in an array, its first row breaking it
("cue.V0[3]: must be > 0, got -1").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from numerics.validation import SceneError, real

REQUIRED = ("V0", "phi", "M", "m")
OPTIONAL = ("theta", "a", "b", "xi", "eta")  # 0 when left out: a level centre-ball hit from the origin

__all__ = ["Cue", "strike", "strikes"]


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
        _check_rules(vars(self))


def _meets_ball(a, b):
    """a² + b² < 1, on floats or arrays: |a| and |b| clipped at 1 first (the same verdict), so that 1e200 is
    refused by this rule rather than squared to ∞."""
    a, b = np.minimum(abs(a), 1.0), np.minimum(abs(b), 1.0)
    return a * a + b * b < 1


def _ratio_held(M, m):
    """m/M within float64: beyond, 1 + m/M is ∞ and the strike's speed exactly 0 (m = 1e308 on a 0.5 kg cue left
    the ball dead still, exit 0: an audit)."""
    with np.errstate(over="ignore"):
        return np.isfinite(m / M)


# The rules of a stroke whose fields are finite numbers, in the order they are checked: the fields each reads,
# the rule (on floats or arrays alike), what it says when broken.
RULES = (
    (("V0",), lambda V0: V0 > 0, "must be > 0, got {}"),
    (("M",), lambda M: M > 0, "must be > 0, got {}"),
    (("m",), lambda m: m > 0, "must be > 0, got {}"),
    (("M", "m"), _ratio_held, "the ball would be m/M times as heavy as the cue, beyond float64 (no stroke could move it), "
     "got M = {}, m = {}"),
    (("theta",), lambda theta: (0 <= theta) & (theta < 90), "must be >= 0 and < 90 (degrees of elevation), got {}"),
    (("a", "b"), _meets_ball, "a² + b² must be < 1 (the cue's axis must meet the ball), got a = {}, b = {}"),
)


def _check_rules(fields: dict) -> None:
    """Refuse the first rule of `RULES` a stroke of ``fields`` (finite floats, or 1-D arrays of them) breaks: a
    SceneError naming its fields and, in an array, the first row that breaks it (cue.V0[3])."""
    for names, rule, says in RULES:
        values = [fields[name] for name in names]
        kept = rule(*values)
        if kept is True or kept is np.True_:  # (one stroke that keeps it: no array work, Scene.from_cue's case)
            continue
        broken = np.flatnonzero(np.logical_not(kept))
        if broken.size:
            found = [_row(f"cue.{name}", value, int(broken[0])) for name, value in zip(names, values)]
            raise SceneError(", ".join(field for field, _ in found), says.format(*(_shown(x) for _, x in found)))


def _row(field: str, values, i: int) -> tuple[str, float]:
    """Row i's name and value in a field given as a number (every row's: no index) or an array (one of length 1
    is every row's too: its [0])."""
    if np.ndim(values) == 0:
        return field, float(values)
    i = i if len(values) > 1 else 0
    return f"{field}[{i}]", float(values[i])


def _numbers(values, field: str):
    """A field of `strikes`: a number as `real` takes it, or a 1-D array of them whose row i is refused as
    `real` refuses a number, named field[i] ("cue.V0[3]: must be finite, got nan").  What gives NumPy its array
    (a pandas Series, an xarray DataArray: ``__array__``) is read as that array."""
    if hasattr(values, "__array__") and not isinstance(values, np.ndarray):
        values = np.asarray(values)
    if not isinstance(values, (list, tuple, np.ndarray)):
        return real(values, field)
    if isinstance(values, np.ma.MaskedArray):  # np.asarray would take a masked value as given
        masked = np.flatnonzero(np.ma.getmaskarray(values))
        if masked.size:
            raise SceneError(f"{field}[{masked[0]}]", "must be a number, got a masked value")
        values = values.data
    if isinstance(values, np.ndarray) or set(map(type, values)) <= {float, int}:  # (a bool is neither): read in C
        array = np.asarray(values)
    else:  # other objects kept as they are: np.asarray would read [True, 0.5] as [1.0, 0.5], and "2" as text
        array = np.array(values, dtype=object)
    if array.ndim == 0:
        return real(array[()], field)
    if array.ndim != 1:
        raise SceneError(field, f"must be a number or a 1-D array, got an array of shape {array.shape}")
    if array.dtype.kind in "iu" or (array.dtype.kind == "f" and array.dtype.itemsize <= 8):  # float64 holds them
        numbers = array.astype(float)
        bad = np.flatnonzero(~np.isfinite(numbers))
        if bad.size:
            real(numbers[bad[0]], f"{field}[{bad[0]}]")  # refuses it, with the words it has for a number
        return numbers
    return np.array([real(x, f"{field}[{i}]") for i, x in enumerate(array)], dtype=float)  # objects, text, bool…


def _strike(R, k, V0, phi, M, m, theta, a, b):
    """(ξ', η', p, q, r) of A-30's strike, on floats or arrays alike: NumPy's radians, cos and sin, and products
    where a square is meant (Python's x**2 is libm's pow, NumPy's a product), so that a row of `strikes` is what
    `strike` gives, to the bit."""
    # φ reduced to a turn first (fmod is exact): radians(1e300) lost the angle, and a shot went 131° astray.
    phi, theta = np.radians(np.fmod(phi, 360.0)), np.radians(theta)
    cos_phi, sin_phi, cos_theta = np.cos(phi), np.sin(phi), np.cos(theta)
    # Energy and momentum balance of the elastic strike: the ball's speed along the cue, its vertical part
    # then taken by the cloth.
    v = 2 * V0 / (1 + m / M + (a * a + b * b) * (R * R) / (k * k))
    speed = v * cos_theta
    # The angular impulse about the centre, (v R/k²)(a (cos θ ζ̂ + sin θ d̂) + b l̂): b about the left of the shot
    # (follow or draw), a about the vertical (side) and, for an elevated cue, about the line of the shot (massé).
    spin = v * R / (k * k)
    along, left = a * np.sin(theta), b
    return (
        speed * cos_phi,
        speed * sin_phi,
        spin * (along * cos_phi - left * sin_phi),
        spin * (along * sin_phi + left * cos_phi),
        spin * a * cos_theta,
    )


def _finite(V0, velocities) -> None:
    """Refuse a stroke whose result float64 cannot hold (V0 = 1e307: the spin v R/k² overflowed, and inf × 0 gave
    NaN), naming cue.V0 and, in an array, its first such row."""
    held = True
    for v in velocities:  # numbers and arrays broadcast (no strokes: arrays of length 0)
        held = held & np.isfinite(v)
    if np.all(held):
        return
    row = int(np.flatnonzero(np.logical_not(np.atleast_1d(held)))[0])
    field, value = _row("cue.V0", V0, row)
    raise SceneError(field, f"too fast for this ball: the speed and spin it gives (V0 R/k²) overflow float64, got {_shown(value)}")


def _ball(R, k) -> tuple[float, float]:
    """R and k by a ball's rules (`numerics.scene.Coefficients`: > 0, within float64's range, k <= R √(2/3)),
    named as `strikes` takes them."""
    from numerics.scene import Coefficients  # (scene imports this module)

    try:
        ball = Coefficients(f=0.0, delta=0.0, epsilon=0.0, R=R, k=k)
    except SceneError as error:
        raise SceneError(error.field.removeprefix("params."), error.rule) from None
    return ball.R, ball.k


def strike(cue: Cue, R: float, k: float) -> tuple[float, float, float, float, float]:
    """The ball's (ξ', η', p, q, r) just after ``cue`` strikes it (A-30), for a ball of radius R and radius of gyration k."""
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused below, by name, not warned of
        velocities = _strike(R, k, cue.V0, cue.phi, cue.M, cue.m, cue.theta, cue.a, cue.b)
    _finite(cue.V0, velocities)
    return tuple(map(float, velocities))


def strikes(R, k, *, V0, phi, M, m, theta=0.0, a=0.0, b=0.0, xi=0.0, eta=0.0) -> np.ndarray:
    """The (n, 7) float64 states (ξ, η, ξ', η', p, q, r) just after n cue strokes, ready for
    `numerics.batch.simulate_many`: row i is ``(xi, eta, *strike(Cue(...row i...), R, k))`` to the bit.

    Each field (`Cue`'s, in its units) is a number or a 1-D array; the arrays have one length n, or
    length 1, and a number stands for every row (NumPy's broadcasting); numbers only (or arrays of length 1) make one row.  R and k
    are the ball's (a `Params`' R and k).  Refused, as one `SceneError`: a field that is not numbers or not
    1-D, an array of another length (named), and `Cue`'s rules, checked in its order, each naming the field
    and its first row that breaks it ("cue.V0[3]: must be > 0, got -1").
    """
    R, k = _ball(R, k)  # k = 1e-200 divided by zero, and k = 1 m on a 28 mm ball passed
    given = {"V0": V0, "phi": phi, "M": M, "m": m, "theta": theta, "a": a, "b": b, "xi": xi, "eta": eta}
    fields = {name: _numbers(value, f"cue.{name}") for name, value in given.items()}
    n, first = 1, None
    for name, values in fields.items():
        if np.ndim(values) == 1 and len(values) != 1:
            if first is None:
                n, first = len(values), name
            elif len(values) != n:
                raise SceneError(
                    f"cue.{name}", f"must have {n} rows as cue.{first} has (or 1, or be a number), got {len(values)}",
                )
    _check_rules(fields)
    states = np.empty((n, 7))
    states[:, 0], states[:, 1] = fields["xi"], fields["eta"]
    stroke = [fields[name] for name in ("V0", "phi", "M", "m", "theta", "a", "b")]
    with np.errstate(over="ignore", invalid="ignore"):
        velocities = _strike(R, k, *stroke)
    _finite(fields["V0"], velocities)
    for column, values in enumerate(velocities, 2):
        states[:, column] = values
    return states
