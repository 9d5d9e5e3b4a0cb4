"""A scene: one ball, its parameters, its initial state (SI units, the paper's names).

    {"params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575, "k": 0.018072, "g": 9.81},
     "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0},
     "t": [0.1, 0.5], "model": "appell"}

``k`` defaults to √(2/5) R (solid ball), ``g`` to 9.81, ``t`` to none,
``model`` to "appell" ("classical": no rolling couple while sliding).
Instead of ``state``, a ``cue`` block gives the ball just after a cue stroke
(`Scene.from_cue`, `numerics.cue`: A-30's strike):

    "cue": {"V0": 2.0, "phi": 30, "theta": 5, "a": 0.2, "b": -0.3, "M": 0.567, "m": 0.170}

(optional ``theta``, ``a``, ``b``, ``xi``, ``eta``, 0 by default).  `Params.from_pool`
takes the coefficients of pool simulators (u_s, u_r, u_sp) instead of f, δ, ε.

`Params`, `State` and `Scene` check themselves when built, from JSON
(`parse`, `load`) or directly in Python, with the rules of
`numerics.validation`: a broken rule is a `SceneError`, one line naming the
field.  What a ball and a cloth must be:

* R, k, g > 0 and f, δ, ε >= 0, all finite;
* k <= R √(2/3): a thin spherical shell has the largest radius of gyration a
  ball of radius R can have (k² = 2R²/3);
* δ < fR, eq. (9) (the simulator's `Params`; it implies f > 0): the paper's
  whole analysis of the billiard assumes it, and without it the slip need not
  end (n°8).  `Coefficients` drops this one rule, for the checks of n°4
  (f = 0) that study the equations outside the billiard;
* the motion's times and lengths far inside float64 (`validation.representable`).
"""

from __future__ import annotations

import itertools
import json
import math
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import ClassVar, NamedTuple

import numpy as np

from numerics import cue as cue_strike
from numerics import engine, validation
from numerics.validation import MODELS, SceneError, describe, real

PARAM_FIELDS = ("f", "delta", "epsilon", "R", "k", "g")
ENGINE_PARAMS = ("f", "R", "k", "delta", "epsilon", "g")  # the order of a row of parameters in the engine (`values`)
STATE_FIELDS = ("xi", "eta", "vxi", "veta", "p", "q", "r")
SHELL = math.sqrt(2 / 3)  # k / R of a thin spherical shell, the largest of any ball
MAX_FILE_BYTES = 512 * 2**20  # a scene file larger than this is refused, not read (/dev/zero, a wrong file)
# A JSON file is read into Python objects, about 40 times its size: 200,000 scenes (32 MB) took 18 s and 0.6 GB,
# and 512 MiB would take minutes and gigabytes (an audit).  More scenes go in .npz or .csv, read as arrays.
MAX_JSON_BYTES = 64 * 2**20
MAX_TIMES = 100_000  # times one scene reports at most (its t, --at, --samples): 10⁶ states took 49 s and 2.7 GB as JSON

__all__ = [
    "Coefficients", "Params", "PoolCoefficients", "State", "Scene", "SceneError", "parse", "parse_params", "load",
    "with_model", "MODELS",
]


@dataclass(frozen=True)
class Coefficients:
    """A ball on a cloth where the equations of n°2 hold: the paper's f, δ, ε, R, k, g (SI units).

    ``k`` defaults to a solid ball's √(2/5) R.  Only the rules of any ball
    and cloth are checked (see the module's docstring); `Params` adds eq. (9).
    """

    f: float
    delta: float
    epsilon: float
    R: float
    k: float | None = None
    g: float = 9.81
    ZERO_F: ClassVar[bool] = True  # a cloth without sliding friction is a cloth; not a ball the paper studies (Params)

    def __post_init__(self):
        for name in ("f", "delta", "epsilon", "R", "g"):
            object.__setattr__(self, name, real(getattr(self, name), f"params.{name}"))
        k = math.sqrt(2 / 5) * self.R if self.k is None else real(self.k, "params.k")
        object.__setattr__(self, "k", k)
        for name, ok, rule in (
            ("R", self.R > 0, "> 0"),
            ("k", self.k > 0, "> 0"),
            ("g", self.g > 0, "> 0"),
            ("delta", self.delta >= 0, ">= 0"),
            ("epsilon", self.epsilon >= 0, ">= 0"),
            ("f", self.f >= 0, ">= 0"),
        ):
            if not ok:
                raise SceneError(f"params.{name}", f"must be {rule}, got {getattr(self, name)}")
        for name in ("f", "delta", "epsilon", "R", "k", "g"):
            value = getattr(self, name)
            if value != 0 and not 1 / validation.SCALE_LIMIT < value < validation.SCALE_LIMIT:
                # "0 or" only where 0 is allowed: R, k, g (and a Params' f) must be > 0 (a user audit)
                zero = "0 or " if name in ("delta", "epsilon") or (name == "f" and self.ZERO_F) else ""
                raise SceneError(
                    f"params.{name}", f"must be {zero}between {1 / validation.SCALE_LIMIT:g} and "
                    f"{validation.SCALE_LIMIT:g}, both excluded (float64 must hold its squares and products), got {value}",
                )
        if self.k > SHELL * self.R * (1 + 1e-12):  # rounding of k = R √(2/3) itself is allowed
            raise SceneError(
                "params.k", f"must be <= R √(2/3) = {SHELL * self.R:.6g} (a thin shell: no ball of radius R has a "
                f"larger radius of gyration), got {self.k}",
            )

    def values(self, num=float) -> tuple:
        return tuple(num(getattr(self, name)) for name in ENGINE_PARAMS)


class PoolCoefficients(NamedTuple):
    """The coefficients of pool simulators (pooltool's ``BallParams``): sliding u_s, rolling u_r, spinning u_sp."""

    u_s: float
    u_r: float
    u_sp: float


@dataclass(frozen=True)
class Params(Coefficients):
    """A billiard ball as the paper studies it: `Coefficients` with δ < fR (eq. (9)), what the simulator needs."""

    ZERO_F: ClassVar[bool] = False

    def __post_init__(self):
        super().__post_init__()
        if self.f <= 0:
            raise SceneError("params.f", f"must be > 0, got {self.f}")
        if not self.delta < self.f * self.R:
            raise SceneError(
                "params.delta", f"must be < f R (eq. (9), the paper's whole analysis assumes it), "
                f"got delta = {self.delta} >= f R = {self.f * self.R}",
            )

    @classmethod
    def from_pool(cls, u_s, u_r, u_sp, R, k=None, g=9.81) -> Params:
        """The paper's f, δ, ε from the coefficients of pool simulators (pooltool's ``BallParams``).

        Those simulators give rates, the paper lengths of couples; the map keeps
        what a player sees:

        * f = u_s: both are the Coulomb coefficient of the sliding contact point (n°2);
        * δ = u_r (R² + k²)/R: pooltool's rolling ball decelerates at u_r g, and the
          paper's rolling couple δmg decelerates a pure roll at Rδg/(R² + k²) (n°7);
        * ε = u_sp R: pooltool's spin about the vertical decays at 5 u_sp g/(2R)
          (``evolve_perpendicular_spin_component``), the deceleration of a couple
          u_sp R m g on a solid ball (k² = 2R²/5); the paper's pivot couple εmg gives
          r' = −εg/k² (eq. (5)), so ε = u_sp R, and for another k the couple is kept:
          r' = −u_sp R g/k².  pooltool's u_sp is its property ``BallParams.u_sp``
          = ``u_sp_proportionality * R``, not ``u_sp_proportionality`` (its
          defaults: u_s = 0.2, u_r = 0.01, u_sp_proportionality = 4/9, R = 0.028575 m).

        eq. (9), δ < fR, reads u_r < u_s R²/(R² + k²) (5/7 u_s for a solid ball);
        a cloth that breaks it is refused, naming u_r.
        """
        ball = Coefficients(f=0.0, delta=0.0, epsilon=0.0, R=R, k=k, g=g)  # checks R, k, g and defaults k
        u_s, u_r, u_sp = (real(x, name) for x, name in ((u_s, "u_s"), (u_r, "u_r"), (u_sp, "u_sp")))
        for name, value, ok, rule in (("u_s", u_s, u_s > 0, "> 0"), ("u_r", u_r, u_r >= 0, ">= 0"), ("u_sp", u_sp, u_sp >= 0, ">= 0")):
            if not ok:
                raise SceneError(name, f"must be {rule}, got {value}")
        share = ball.R**2 / (ball.R**2 + ball.k**2)  # δ/(fR) = (u_r/u_s)/share
        if not u_r < u_s * share:
            raise SceneError(
                "u_r", f"must be < u_s R²/(R² + k²) = {u_s * share:.6g} (delta < f R, eq. (9): the rolling friction "
                f"must be weaker than the sliding one), got {u_r}",
            )
        mapped = {"delta": ("u_r", u_r, "u_r (R² + k²)/R", u_r / share * ball.R),
                  "epsilon": ("u_sp", u_sp, "u_sp R", u_sp * ball.R)}
        for name, (pool_name, value, formula, result) in mapped.items():
            if value != 0 and result == 0:  # underflowed: a cloth with rolling friction would have none, silently
                raise SceneError(pool_name, f"too small: {name} = {formula} underflows to 0 in float64, got {value}")
        try:
            return cls(f=u_s, delta=mapped["delta"][3], epsilon=mapped["epsilon"][3], R=ball.R, k=ball.k, g=ball.g)
        except SceneError as error:  # the rule broken by δ or ε is the user's u_r or u_sp
            if error.field[len("params."):] not in mapped:
                raise
            pool_name, value, formula, result = mapped[error.field[len("params."):]]
            raise SceneError(pool_name, f"gives {error.field[len('params.'):]} = {formula} = {result:g}, which {error.rule}") from None

    def pool(self) -> PoolCoefficients:
        """The inverse of `from_pool`: (u_s, u_r, u_sp) = (f, δR/(R² + k²), ε/R)."""
        return PoolCoefficients(self.f, self.delta * self.R / (self.R**2 + self.k**2), self.epsilon / self.R)


@dataclass(frozen=True)
class State:
    """The ball at t = 0: centre (ξ, η), its velocity (ξ', η'), the rotation (p, q, r)."""

    xi: float
    eta: float
    vxi: float
    veta: float
    p: float
    q: float
    r: float

    def __post_init__(self):
        for name in STATE_FIELDS:
            object.__setattr__(self, name, real(getattr(self, name), f"state.{name}"))

    def row(self) -> list[float]:
        return [getattr(self, name) for name in STATE_FIELDS]


@dataclass(frozen=True)
class Scene:
    """One ball: its `Params`, its initial `State`, the times to report, the model ("appell" or "classical")."""

    params: Params
    state: State
    times: tuple = field(default_factory=tuple)
    model: str = "appell"

    def __post_init__(self):
        if not isinstance(self.params, Params):
            raise SceneError("scene.params", f"must be a Params (numerics.scene.Params; from a dict: parse), got {describe(self.params)}")
        if not isinstance(self.state, State):
            raise SceneError("scene.state", f"must be a State (numerics.scene.State; from a dict: parse), got {describe(self.state)}")
        if isinstance(self.times, (str, bytes, dict, set, frozenset)) or not hasattr(self.times, "__iter__"):
            raise SceneError("t", f"must be a list of times (s; a list, its order kept), got {describe(self.times)}")
        times = tuple(real(x, f"t[{i}]") for i, x in enumerate(itertools.islice(self.times, MAX_TIMES + 1)))
        if len(times) > MAX_TIMES:  # (an endless iterator is cut here, not followed)
            raise SceneError("t", f"at most {MAX_TIMES:,} times (a state reported at each), got more")
        for i, x in enumerate(times):
            if x < 0:
                raise SceneError(f"t[{i}]", f"must be >= 0, got {x}")
        object.__setattr__(self, "times", times)
        validation.model(self.model)
        reason = unrepresentable(self.params, np.array([self.state.row()]), max(times, default=0.0))[0]
        if reason:  # named t when the motion itself is fine and only a time asked is too far
            alone = times and not unrepresentable(self.params, np.array([self.state.row()]), 0.0)[0]
            field, name, value = reason
            raise validation.scale_error("t" if alone else field, name, value)
        # What the engine reads, made once (a scene is immutable): (f, R, k, δ, ε, g) and (ξ, η, ξ', η', p, q, r).
        object.__setattr__(self, "_arrays", (np.array(self.params.values()), np.array(self.state.row())))

    @classmethod
    def from_cue(cls, params: Params, *, V0, phi, M, m, theta=0.0, a=0.0, b=0.0, xi=0.0, eta=0.0,
                 times=(), model: str = "appell") -> Scene:
        """The ball just after a cue stroke (`numerics.cue`: Alciatore's A-30, pooltool's strike), on ``params``' cloth.

        V0 the cue's speed (m/s), φ its direction (degrees counter-clockwise from +ξ),
        θ its elevation (degrees, 0 <= θ < 90), a and b the tip's offsets across the
        cue as fractions of R (a > 0 right of centre seen from behind the cue, the
        opposite of pooltool's a; b > 0 above centre), M and m the cue's and the ball's
        masses (kg), (ξ, η) the ball's position.  The ball's own R and k are used; the
        cloth takes the vertical part of an elevated cue's impulse.  The same as the
        ``"cue"`` block of a scene file.  Many strokes at once, as the states array
        `numerics.batch.simulate_many` takes: `numerics.cue.strikes`.
        """
        if not isinstance(params, Params):
            raise SceneError("scene.params", f"must be a Params (numerics.scene.Params), got {describe(params)}")
        stroke = cue_strike.Cue(V0=V0, phi=phi, M=M, m=m, theta=theta, a=a, b=b, xi=xi, eta=eta)
        vxi, veta, p, q, r = cue_strike.strike(stroke, params.R, params.k)
        try:
            return cls(params, State(stroke.xi, stroke.eta, vxi, veta, p, q, r), times, model)
        except SceneError as error:  # a state the stroke made: the user gave the cue, so the cue is named
            if not error.field.startswith("state."):
                raise
            if set(error.field.split(", ")) <= {"state.xi", "state.eta"}:  # the position, given as the cue's
                raise type(error)(error.field.replace("state.", "cue."), error.rule) from None
            ratio = stroke.m / stroke.M
            blamed = f"cue.M, cue.m: a ball {ratio:.3g} times as heavy as the cue" if ratio > 1 else "cue.V0"
            raise type(error)(blamed, f"the stroke leaves the ball at {math.hypot(vxi, veta):.3g} m/s, and {error.rule}") from None

    def arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """The parameters (f, R, k, δ, ε, g) and the state (ξ, η, ξ', η', p, q, r) as float64 arrays."""
        return self._arrays


# The names of `engine.motion_scales`'s columns, in its order (engine.SPEED, …, engine.INVERSE_SPEED).
SCALE_NAMES = (
    "speed (|ξ'| + |η'| + R(|p| + |q|))", "spin |r|", "sliding time bound V₀/(fg)", "rolling time bound Ω(R² + k²)/(δg)",
    "pivot time bound k²|r|/(εg)", "duration (with the times asked)", "distance bound",
    "sliding deceleration bound g(f(1 + R²/k²) + δR/k²)", "inverse speed 1/(|ξ'| + |η'| + R(|p| + |q|)) (a speed not 0 but tiny)",
)


def blamed_field(scale: int, value: float, params: np.ndarray, state: np.ndarray, horizon: float = 0.0) -> str:
    """The field(s) of a scene that make scale ``scale`` (an index into `SCALE_NAMES`) reach ``value``: the largest
    term of a sum; for a bound proportional to the speed (or to |r|), the speed when at 1 m/s it would be fine,
    else the coefficients.  Errors named the scene alone (a user audit: which number to fix?).
    ``params`` is an engine row (f, R, k, δ, ε, g), ``state`` (ξ, η, ξ', η', p, q, r)."""
    limit = validation.SCALE_LIMIT
    R = params[1]
    with np.errstate(all="ignore"):
        terms = np.abs([state[2], state[3], R * state[4], R * state[5]])
    speed_value = float(terms.sum())
    largest = int(np.argmax(terms))
    speed = "state." + ("vxi", "veta", "p", "q")[largest]
    if largest >= 2 and R > abs(state[2 + largest]):  # R p with R the larger factor: the ball's size (R = 1e99)
        speed = "params.R"

    def per_unit(of: float, name: str, coefficients: str) -> str:  # the bound is ∝ ``of``: blame it or the rest
        return name if of > 1 and value / of < limit else coefficients

    if scale == engine.DISTANCE:  # the start's own size, or how far the ball goes
        far = int(np.argmax(np.abs(state[:2])))
        return f"state.{STATE_FIELDS[far]}" if abs(state[far]) >= limit / 4 else per_unit(speed_value, speed, "params")
    if scale == engine.DURATION and horizon >= limit / 4:
        return "t"
    return {
        engine.SPEED: speed, engine.SPIN: "state.r",
        engine.SLIDE_TIME: per_unit(speed_value, speed, "params.f, params.g"),
        engine.ROLL_TIME: per_unit(speed_value, speed, "params.delta, params.R, params.k, params.g"),
        engine.PIVOT_TIME: per_unit(abs(state[6]), "state.r", "params.epsilon, params.k, params.g"),
        engine.DURATION: per_unit(speed_value, speed, "params.f, params.delta, params.R, params.k, params.g"),
        engine.DECELERATION: "params.f, params.R, params.k, params.g",
        engine.INVERSE_SPEED: "state.vxi, state.veta, state.p, state.q",
    }[scale]


def unrepresentable(params, states: np.ndarray, horizon: float = 0.0, run=engine) -> list:
    """Per row of ``states``: None when its motion's scales are far inside float64, else (field, scale, value), the
    field to blame (`blamed_field`) and the first scale (in `SCALE_NAMES`' order) not below
    `validation.SCALE_LIMIT`: the arguments of `validation.scale_error`.

    ``params``: one `Params` for every row, or an array of rows (f, R, k, δ, ε, g).  The bounds are
    `engine.motion_scales` (n°3, n°7, eq. (5)); ``run`` is the engine that computes them (the compiled one
    for a batch: no Python per row).
    """
    states = np.ascontiguousarray(np.atleast_2d(np.asarray(states, dtype=float)))
    table = np.array(params.values(), dtype=float) if isinstance(params, Coefficients) else np.asarray(params, dtype=float)
    shape = (len(states), len(ENGINE_PARAMS))
    if table.shape == shape and table.flags.c_contiguous:  # a batch's table: read-only, as np.broadcast_to would
        table = table.view()  # give it (the type the compiled code is built for), at a tenth of the cost
        table.flags.writeable = False
    else:
        table = np.ascontiguousarray(np.broadcast_to(table, shape))
    scales = np.empty((len(states), engine.SCALES))
    if run is engine:
        with np.errstate(all="ignore"):  # interpreted on NumPy scalars: overflow is ∞, as compiled
            run.motion_scales(table, states, float(horizon), scales)
    else:  # compiled: NumPy's error state plays no part (setting it costs a fifth of the whole check)
        run.motion_scales(table, states, float(horizon), scales)
    below = scales < validation.SCALE_LIMIT  # not NaN nor ∞ either
    reasons: list = [None] * len(states)
    if np.count_nonzero(below) == below.size:  # the common case: every row far inside float64
        return reasons
    bad = ~below
    for i in np.flatnonzero(bad.any(axis=1)):
        j = int(np.argmax(bad[i]))
        value = float(scales[i, j])
        reasons[i] = (blamed_field(j, value, table[i], states[i], float(horizon)), SCALE_NAMES[j], value)
    return reasons


def parse_params(data) -> Params:
    """`Params` from a decoded JSON object (f, delta, epsilon, R; optional k, g)."""
    return Params(**validation.fields(data, "params", ("f", "delta", "epsilon", "R"), ("k", "g")))


def parse(data) -> Scene:
    """A Scene from decoded JSON, or SceneError."""
    if isinstance(data, Scene):
        return data
    if not isinstance(data, dict):
        raise SceneError("scene", f"must be a JSON object, got {describe(data)}")
    unknown = sorted((name for name in data if name not in ("params", "state", "cue", "t", "model")), key=str)
    if unknown:
        raise SceneError(validation.key_name("scene", unknown[0]), "unknown field (allowed: params, state or cue, t, model)")
    if "params" not in data:
        raise SceneError("scene.params", "missing")
    if "state" not in data and "cue" not in data:
        raise SceneError("scene.state", "missing (or a cue block instead: the ball just after a cue stroke)")
    if "state" in data and "cue" in data:
        raise SceneError("scene.cue", "give a state or a cue block, not both")
    params = parse_params(data["params"])
    times = data.get("t", [])
    if not isinstance(times, list):
        raise SceneError("t", f"must be a list of times, got {describe(times)}")
    model = data.get("model", "appell")
    if "cue" in data:
        stroke = validation.fields(data["cue"], "cue", cue_strike.REQUIRED, cue_strike.OPTIONAL)
        return Scene.from_cue(params, **stroke, times=tuple(times), model=model)
    state = State(**validation.fields(data["state"], "state", STATE_FIELDS))
    return Scene(params, state, tuple(times), model)


def with_model(scene: Scene, model: str) -> Scene:
    return Scene(scene.params, scene.state, scene.times, validation.model(model))


def shown_name(path) -> str:
    """A scene file's name in a message: ``-`` is standard input."""
    return "standard input" if path == "-" else str(path)


def read_text(path, where: str | None = None, limit: int | None = None) -> str:
    """A UTF-8 text file, at most ``limit`` bytes (`MAX_FILE_BYTES` unless given), or SceneError naming the file."""
    limit = MAX_FILE_BYTES if limit is None else limit
    if not isinstance(path, (str, Path)):
        raise SceneError("path", f"must be a file name (str or Path), got {describe(path)}")
    if path == "-":  # standard input, as Unix tools read it: `... | appell simulate -`
        where = shown_name(path) if where in (None, "-") else where
        if sys.stdin is None:  # started with standard input closed (<&-)
            raise SceneError(where, "cannot read (standard input is closed)")
        try:
            raw = sys.stdin.buffer.read(limit + 1)
        except (OSError, ValueError, AttributeError) as error:  # closed, or no byte stream
            raise SceneError(where, f"cannot read ({getattr(error, 'strerror', None) or error})") from None
        return _decoded(raw, where, limit)
    where = where or str(path)
    csv = str(path).lower().endswith(".csv")
    try:
        # Opened without waiting: a named pipe no one writes to would block open() for ever; read then (blocking
        # again) it gives what a writer sends, or nothing at once when there is none.
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        os.set_blocking(fd, True)
        with os.fdopen(fd, "rb") as handle:
            raw = handle.read(limit + 1)
    except OSError as error:
        raise SceneError(where, f"cannot read ({error.strerror or error})") from None
    return _decoded(raw, where, limit, csv)


def _decoded(raw: bytes, where: str, limit: int, csv: bool = False) -> str:
    if len(raw) > limit:  # a CSV was told to use .csv (an audit)
        advice = "too many states for CSV text: save them as .npz" if csv else "not a scene file (many scenes: use .npz or .csv)"
        raise SceneError(where, f"larger than {limit // 2**20} MiB: {advice}")
    try:
        return raw.decode("utf-8-sig")  # a byte-order mark, as some editors write, is not part of the text
    except UnicodeDecodeError as error:
        raise SceneError(where, f"not UTF-8 text (byte {error.start}): not a JSON or CSV file") from None


def read_json(path, where: str | None = None):
    """Decoded JSON of a file (``"-"``: standard input), or SceneError naming the file: never a traceback."""
    where = where or shown_name(path)
    text = read_text(path, where, MAX_JSON_BYTES)
    if not text.strip():  # (json says "Expecting value at line 1": an empty file, or a named pipe no one writes to)
        raise SceneError(where, "empty: no JSON in it")
    try:
        return json.loads(text, object_pairs_hook=_unique_keys, parse_float=validation.decimal_beyond_float,
                          parse_int=validation.int_beyond_str_limit)
    except DuplicateKeyError as error:
        raise SceneError(where, f"the key {error.args[0]!r} is given twice in one object (which one is meant?)") from None
    except json.JSONDecodeError as error:
        raise SceneError(where, f"not valid JSON ({error.msg} at line {error.lineno})") from None
    except RecursionError:
        raise SceneError(where, "not a scene: JSON nested too deeply") from None
    except ValueError as error:  # e.g. an integer of more than 4300 digits
        raise SceneError(where, f"not valid JSON ({error})") from None


class DuplicateKeyError(ValueError):
    """A JSON object that gives one key twice (json would keep the last silently)."""


def _unique_keys(pairs: list) -> dict:
    out = {}
    for key, value in pairs:
        if key in out:
            raise DuplicateKeyError(key)
        out[key] = value
    return out


def load(path) -> Scene:
    """Read and check a scene file."""
    return parse(read_json(path))
