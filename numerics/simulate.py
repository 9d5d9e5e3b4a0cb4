"""`simulate(scene)`: the whole motion of one ball, phase by phase, each with the cheapest exact model.

Phases (design notes, "model only what a scene needs"):

* sliding — n°3's closed form when δ = 0 (or for the classical model);
  the straight-shot closed form when the spin is square to the slip
  (θ = ±π/2, including a centre-ball hit, Ω₀ = 0, n°6); otherwise the
  numerical slide of `sliding` (the only integration);
* pure rolling — n°7's closed form, until Ω = 0 (never when δ = 0);
* rest;
* pivoting — eq. (5), independent of the rest.

Numerical phases are run twice, at ``tol`` and ``tol/1000``; the result is
the finer run and its error estimate the difference of the two rest points
(or slide ends), relative to the distance travelled: an upper estimate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from numerics import equations, phases, sliding, validation
from numerics.scene import Scene, parse
from numerics.validation import ComputationError, SceneError

STRAIGHT_ANGLE = 1e-12  # |θ ∓ π/2| below this is a straight shot


@dataclass(frozen=True)
class PhaseRecord:
    phase: str  # sliding, rolling, rest, pivoting
    t_start: float
    t_end: float | None  # None: never ends
    model: str
    error: float  # estimated relative error at the phase's end (0 for closed forms, to rounding)


@dataclass(frozen=True)
class BallState:
    t: float
    phase: str
    xi: float
    eta: float
    vxi: float
    veta: float
    p: float
    q: float
    r: float


def _rotate(x, y, angle):
    c, s = math.cos(angle), math.sin(angle)
    return x * c - y * s, x * s + y * c


def _wrap(angle: float) -> float:
    return math.atan2(math.sin(angle), math.cos(angle))


@dataclass
class _Stretch:
    """A phase as a function of absolute time: t ↦ (ξ, η, ξ', η', p, q)."""

    t_start: float
    t_end: float | None
    model: str
    at: object
    error: float = 0.0
    coarse_end: sliding.SlideEnd | None = None  # numerical phases: the end at the coarser tolerance


def _closed_form_stretch(t0, xi0, eta0, alpha0, duration, local, model) -> _Stretch:
    """A closed-form phase written in the slip frame (angle alpha0), placed in the world frame."""

    def at(t):
        s = local(t - t0)
        xi, eta = _rotate(s.xi, s.eta, alpha0)
        vxi, veta = _rotate(s.vxi, s.veta, alpha0)
        p, q = _rotate(s.p, s.q, alpha0)
        return xi0 + xi, eta0 + eta, vxi, veta, p, q

    return _Stretch(t0, None if duration is None else t0 + duration, model, at)


def _slide(scene: Scene, tol: float) -> list[_Stretch]:
    """The sliding stretches (none, one, or two for a draw that reverses)."""
    P, s = scene.params, scene.state
    u, v = equations.slip_velocity(P, s.vxi, s.veta, s.p, s.q)
    V0 = math.hypot(u, v)
    scale = max(abs(s.vxi), abs(s.veta), P.R * abs(s.p), P.R * abs(s.q), 1e-300)
    if V0 <= 1e-14 * scale:
        return []
    alpha0, Omega0 = math.atan2(v, u), math.hypot(s.p, s.q)
    beta0 = math.atan2(s.q, s.p)
    theta0 = _wrap(beta0 - alpha0)
    if scene.model == "classical" or P.delta == 0:
        duration, local = phases.classical_slide(P, V0, Omega0, theta0)
        return [_closed_form_stretch(0.0, s.xi, s.eta, alpha0, duration, local, "closed form n°3 (no rolling couple)")]
    if Omega0 <= 1e-14 * scale / P.R or abs(theta0 - math.pi / 2) <= STRAIGHT_ANGLE:
        slip_end, _, local = phases.straight_slide(P, "follow", V0, Omega0)
        return [_closed_form_stretch(0.0, s.xi, s.eta, alpha0, slip_end, local, "closed form straight shot, θ = π/2")]
    if abs(theta0 + math.pi / 2) <= STRAIGHT_ANGLE:
        slip_end, spin_end, local = phases.straight_slide(P, "draw", V0, Omega0)
        first = _closed_form_stretch(0.0, s.xi, s.eta, alpha0, min(slip_end, spin_end), local, "closed form straight shot, θ = −π/2")
        if slip_end <= spin_end:
            return [first]
        # Ω reaches 0 first and comes back along β = α + π/2 (n°6): the follow law.
        reversal = local(spin_end)
        end, _, follow = phases.straight_slide(P, "follow", reversal.V, 0.0)
        xi1, eta1 = _rotate(reversal.xi, reversal.eta, alpha0)
        second = _closed_form_stretch(
            spin_end, s.xi + xi1, s.eta + eta1, alpha0, end, follow, "closed form straight shot, θ = π/2 after the spin reversed"
        )
        return [first, second]
    return [_numerical_slide(scene, V0, alpha0, tol)]


def _numerical_slide(scene: Scene, V0: float, alpha0: float, tol: float) -> _Stretch:
    P, s = scene.params, scene.state
    fine = sliding.slide(P, V0, alpha0, s.p, s.q, s.xi, s.eta, tol=tol / 1000)
    coarse = sliding.slide(P, V0, alpha0, s.p, s.q, s.xi, s.eta, tol=tol)
    a, b = fine.end, coarse.end
    travel = math.hypot(a.xi - s.xi, a.eta - s.eta) + P.R
    spin = max(math.hypot(a.p, a.q), math.hypot(s.p, s.q))
    error = max(abs(a.t - b.t) / a.t, math.hypot(a.xi - b.xi, a.eta - b.eta) / travel, math.hypot(a.p - b.p, a.q - b.q) / spin)

    def at(t):
        if t >= a.t:
            return (a.xi, a.eta, *equations.centre_velocity(P, 0.0, a.alpha, a.p, a.q), a.p, a.q)
        V, alpha, p, q, xi, eta = sliding.state_at(fine, t)
        vxi, veta = equations.centre_velocity(P, V, alpha, p, q)
        return xi, eta, vxi, veta, p, q

    model = f"numerical: extrapolated midpoint in σ = −ln V, tol {tol / 1000:.0e}"
    return _Stretch(0.0, a.t, model, at, error, coarse_end=b)


@dataclass
class Motion:
    """The solved motion of one scene."""

    scene: Scene
    tol: float
    slides: list  # the sliding stretches
    rolling: _Stretch | None
    t_slide_end: float
    t_roll_end: float | None  # None: rolls for ever (δ = 0)
    t_pivot_end: float | None  # None: pivots for ever (ε = 0, r ≠ 0)
    rest: tuple | None
    error: float  # estimated relative error of the rest point (of the slide's end if it never rests)
    pivot_at: object
    phases: list

    def state_at(self, t: float) -> BallState:
        t = validation.real(t, "t")
        if t < 0:
            raise SceneError("t", f"must be >= 0, got {t}")
        try:
            state = self._state_at(t)
        except OverflowError:
            state = None
        if state is None or not all(math.isfinite(x) for x in vars(state).values() if isinstance(x, float)):
            raise validation.UnrepresentableError("t", f"the state at t = {t:g} s is not representable in float64")
        return state

    def _state_at(self, t: float) -> BallState:
        r = self.pivot_at(t)
        for stretch in self.slides:
            if t <= stretch.t_end:
                return BallState(t, "sliding", *stretch.at(max(t, stretch.t_start)), r)
        if self.rolling is not None and (self.t_roll_end is None or t <= self.t_roll_end):
            return BallState(t, "rolling", *self.rolling.at(t), r)
        xi, eta = self.rest
        return BallState(t, "rest", xi, eta, 0.0, 0.0, 0.0, 0.0, r)

    def samples(self, n: int = 200) -> list[BallState]:
        """n + 1 states evenly spaced from 0 to rest (to 2 t_slide_end + 1 s when the ball never rests): for plots."""
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise SceneError("samples", f"must be an integer >= 1, got {validation.describe(n)}")
        end = self.t_roll_end if self.t_roll_end is not None else 2 * self.t_slide_end + 1.0
        end = max(end, self.t_pivot_end or 0.0)
        return [self.state_at(end * j / n) for j in range(n + 1)]

    def as_dict(self, times=()) -> dict:
        return {
            "model": self.scene.model,
            "tol": self.tol,
            "phases": [vars(p) for p in self.phases],
            "t_slide_end": self.t_slide_end,
            "t_roll_end": self.t_roll_end,
            "t_pivot_end": self.t_pivot_end,
            "rest": None if self.rest is None else {"xi": self.rest[0], "eta": self.rest[1]},
            "error_estimate": self.error,
            "states": [vars(self.state_at(t)) for t in times],
        }


def simulate(scene: Scene | dict, tol: float = 1e-10) -> Motion:
    """The whole motion of ``scene`` (a `Scene`, or a dict as in a scene file) until rest,
    numerical phases to about ``tol`` relative.

    Bad input is a `SceneError` naming the field; a result that comes out
    non-finite is a `ComputationError` naming the quantity, never returned.
    """
    if not isinstance(scene, (Scene, dict)):
        raise SceneError("scene", f"must be a Scene or a dict as in a scene file, got {validation.describe(scene)}")
    scene = parse(scene)
    tol = validation.tolerance(tol)
    try:
        motion = _motion(scene, tol)
    except (OverflowError, ZeroDivisionError) as error:
        raise ComputationError(f"scene: the motion could not be computed in float64 ({type(error).__name__}: {error})") from None
    _check_finite(motion)
    return motion


def _check_finite(motion: Motion) -> None:
    """Every number of the result finite, or the quantity named: NaN is never an answer."""
    end = motion.slides[-1].at(motion.t_slide_end) if motion.slides else ()
    named = {
        "t_slide_end": motion.t_slide_end, **{f"state at the end of sliding[{i}]": x for i, x in enumerate(end)},
        "t_roll_end": motion.t_roll_end, **{f"rest[{i}]": x for i, x in enumerate(motion.rest or ())},
        "t_pivot_end": motion.t_pivot_end, "error_estimate": motion.error,  # last: computed from the others
    }
    for name, value in named.items():
        if value is not None and not math.isfinite(value):
            raise ComputationError(f"scene: {name} came out {value}")


def _motion(scene: Scene, tol: float) -> Motion:
    P, s = scene.params, scene.state
    slides = _slide(scene, tol)
    error = max((st.error for st in slides), default=0.0)
    t_slide = slides[-1].t_end if slides else 0.0
    xi1, eta1, _, _, p1, q1 = slides[-1].at(t_slide) if slides else (s.xi, s.eta, s.vxi, s.veta, s.p, s.q)
    rolling, t_roll, rest = None, t_slide, (xi1, eta1)
    if math.hypot(p1, q1) > 0:
        duration, local = phases.rolling(P, math.hypot(p1, q1), math.atan2(q1, p1))
        rolling = _closed_form_stretch(t_slide, xi1, eta1, 0.0, duration, local, "closed form n°7 (pure rolling)")
        t_roll = rolling.t_end
        rest = None if t_roll is None else rolling.at(t_roll)[:2]
    coarse = slides[-1].coarse_end if slides else None
    if rest is not None and coarse is not None:
        # The rest point from the coarse slide: its distance to ours estimates our error.
        c_duration, c_local = phases.rolling(P, math.hypot(coarse.p, coarse.q), math.atan2(coarse.q, coarse.p))
        c_rest = c_local(c_duration)
        travel = math.hypot(rest[0] - s.xi, rest[1] - s.eta) + P.R
        error = max(error, math.hypot(coarse.xi + c_rest.xi - rest[0], coarse.eta + c_rest.eta - rest[1]) / travel)
    t_pivot, pivot_at = phases.pivot(P, s.r)
    records = [PhaseRecord("sliding", st.t_start, st.t_end, st.model, st.error) for st in slides]
    if rolling is not None:
        records.append(PhaseRecord("rolling", t_slide, t_roll, rolling.model, 0.0))
    if t_roll is not None:
        records.append(PhaseRecord("rest", t_roll, None, "rest", 0.0))
    records.append(PhaseRecord("pivoting", 0.0, t_pivot, "closed form eq. (5)", 0.0))
    return Motion(scene, tol, slides, rolling, t_slide, t_roll, t_pivot, rest, error, pivot_at, records)
