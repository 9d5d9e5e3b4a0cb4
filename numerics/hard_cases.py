"""The shots that are hard for a simulator, as scenes: the test set of the numerics issue.

Each is a realistic pool ball (R = 28.575 mm, a 57.15 mm ball; f = 0.2,
δ = 0.4 mm, ε = 0.3 mm; solid, k² = 2R²/5) unless the case is about the
parameters.  `WHY` says what makes each one hard; the appendix's Methods
list them with it, since its claims are measured "on every hard case".
``q < 0`` is draw (back spin) for a ball moving along +ξ: rolling is
ξ' = qR (eq. (2) with u = 0).
"""

from __future__ import annotations

import math

from numerics.scene import Scene, parse
from numerics.validation import DEFAULT_TOL

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
        # Ω passes within 0.08 rad/s of zero while the slip is 0.93 m/s (tests/numerics/test_hard_cases.py).
        "draw, little side spin": _scene({"vxi": 2.0, "p": 0.3, "q": -100.0}, times=(0.2,)),
        # The same shot exactly straight: Ω passes through zero (closed form, two stretches).
        "straight draw": _scene({"vxi": 2.0, "q": -100.0}, times=(0.2,)),
        "delta close to fR": _scene({"vxi": 1.5, "p": 20.0, "q": 30.0}, delta=0.99 * fR),
        "delta tiny": _scene({"vxi": 1.5, "p": 20.0, "q": 30.0}, delta=1e-9),
        # A draw 10⁻⁵ rad off the straight line on that cloth: Ω passes within 5·10⁻⁴ rad/s of zero, turning by π,
        # and the roll that follows (764 km) magnifies any error in the direction it leaves the pass with (a step
        # could straddle the pass: the rest point 42× tol off at 1e-10 before `engine.turn_norm`).
        "draw near the straight line, delta tiny": _scene({"vxi": 2.0, "p": 1e-3, "q": -100.0}, delta=1e-9),
        # A massé: 400 rad/s of spin, 5 cm/s of speed.
        "huge spin, small speed": _scene({"vxi": 0.05, "p": 300.0, "q": -250.0}),
        "pivoting, r0 != 0": _scene({"vxi": 1.0, "veta": 0.5, "p": 5.0, "q": 10.0, "r": 40.0}),
        "pivoting for ever (epsilon = 0)": _scene({"vxi": 1.0, "p": 5.0, "q": 10.0, "r": 40.0}, epsilon=0.0),
        "at rest": _scene({}),
        "spinning in place": _scene({"p": 20.0, "q": 5.0}),
        "pure rolling start": _scene({"vxi": 1.2, "veta": -0.5, "p": 0.5 / R_BALL, "q": 1.2 / R_BALL}),
        "rolls for ever (delta = 0)": _scene({"vxi": 1.0, "p": 3.0, "q": -30.0}, delta=0.0),
    }


# What makes each case hard, as the appendix says it (tests/numerics/test_hard_cases.py measures each statement).
WHY = {
    "sample": "the command line's sample shot: sliding, rolling and pivoting at once, the pivot outlasting the slide",
    "centre hit": "Ω₀ = 0: the spin leaves zero along β = α + π/2 (n°6)",
    "draw, little side spin": "Ω passes within 0.1 rad/s of zero while the ball still slips at 0.9 m/s: θ turns fast",
    "straight draw": "the same draw exactly straight: Ω passes through zero, where its direction jumps by π",
    "delta close to fR": "δ = 0.99 fR, at the edge of hypothesis (9), δ < fR",
    "delta tiny": "δ = 10^-6 mm: the roll that follows covers over a thousand kilometres, magnifying any error in "
    "where the slide ends",
    "draw near the straight line, delta tiny": "the straight draw with its spin turned by 10^-5 rad and δ = 10^-6 mm: "
    "Ω passes within 0.01 rad/s of zero, turning by nearly π, and the roll of over a hundred kilometres that follows "
    "magnifies any error in the direction it leaves the pass with",
    "huge spin, small speed": "a massé: Ω₀ over 300 rad/s with the centre at 0.05 m/s",
    "pivoting, r0 != 0": "r₀ = 40 rad/s: the pivot ends seconds after the slide, inside the roll",
    "pivoting for ever (epsilon = 0)": "ε = 0: the pivot never ends",
    "at rest": "nothing moves: every phase has length 0",
    "spinning in place": "a spin with the centre at rest: the contact slips and the ball moves off",
    "pure rolling start": "rolling from the start (V₀ = 0, n°7): no slide at all",
    "rolls for ever (delta = 0)": "δ = 0: the roll never ends (no rest point)",
}


def accuracy(tol: float = DEFAULT_TOL, digits: int = 15, progress=None) -> list[dict]:
    """Each hard case simulated at ``tol`` against the mpmath reference at ``digits``: the actual errors.
    ``progress(done, total)`` is called after each case.

    Rest point: distance to the reference's over its distance from the start + R;
    times: relative to the reference's (the slide's end relative to the whole motion's length).
    """
    import mpmath

    from numerics import reference_motion
    from numerics.simulate import simulate

    rows, cases = [], hard_cases()
    for name, scene in cases.items():
        motion = simulate(scene, tol)
        ref = reference_motion.reference(scene, digits=digits)
        row = {"case": name, "slide model": motion.phases[0].model if motion.phases[0].phase == "sliding" else "none"}
        # Relative to the reference's motion, as `bench.errors` scores (the simulator's own moved with its error).
        span = max(float(ref.t_roll_end) if ref.t_roll_end is not None else 0.0, float(ref.t_slide_end), 1e-3)
        row["t_slide_end error"] = abs(motion.t_slide_end - float(ref.t_slide_end)) / span
        row["missing"] = None
        if motion.rest is None or ref.rest is None:
            row["t_roll_end error"] = row["rest error"] = None
            if (motion.rest is None) != (ref.rest is None):  # one rests, the other rolls for ever: a failure, not n/a
                row["missing"] = ("the simulator rolls for ever, the reference rests" if motion.rest is None
                                  else "the simulator rests, the reference rolls for ever")
        else:
            start = scene.state
            travel = float(mpmath.hypot(ref.rest[0] - start.xi, ref.rest[1] - start.eta)) + scene.params.R
            row["t_roll_end error"] = abs(motion.t_roll_end - float(ref.t_roll_end)) / max(float(ref.t_roll_end), 1e-300)
            row["rest error"] = float(math.hypot(motion.rest[0] - ref.rest[0], motion.rest[1] - ref.rest[1])) / travel
        row["estimate"] = motion.error
        rows.append(row)
        if progress:
            progress(len(rows), len(cases))
    return rows


def accuracy_text(rows: list[dict], tol: float) -> str:
    def fmt(x, r):
        return ("missing" if r["missing"] else "n/a") if x is None else f"{x:.1e}"

    lines = [
        f"appell simulate (tol {tol:g}) against the mpmath reference (no closed form, 15 digits):",
        "",
        "| case | sliding model | rest point error | t_slide_end error | t_roll_end error | estimate |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['case']} | {r['slide model'].split(',')[0]} | {fmt(r['rest error'], r)} | {fmt(r['t_slide_end error'], r)} "
            f"| {fmt(r['t_roll_end error'], r)} | {fmt(r['estimate'], r)} |"
        )
    lines.append(f"\nworst error {worst_error(rows):.1e}, rest point or time (tolerance asked {tol:g}); "
                 + (f"an estimate below its error: {', '.join(under)}" if (under := underestimated(rows))
                    else "every estimate above its error"))
    lines += [f"{r['case']}: {r['missing']}" for r in rows if r["missing"]]
    return "\n".join(lines)


ERRORS = ("rest error", "t_slide_end error", "t_roll_end error")


def worst_error(rows: list[dict]) -> float:
    """The largest error of any case: its rest point or either end time (all judged against the tolerance)."""
    return max((r[key] for r in rows for key in ERRORS if r[key] is not None), default=0.0)


def underestimated(rows: list[dict]) -> list[str]:
    """The cases whose error estimate is below their rest point's error (an estimate, not a bound: a failure of
    `appell accuracy` all the same)."""
    return [r["case"] for r in rows if r["rest error"] is not None and r["estimate"] < r["rest error"]]


def kept(rows: list[dict], tol: float) -> bool:
    """`appell accuracy`'s verdict: every error (rest point, end of sliding, end of rolling) within the tolerance
    asked, every estimate above its error, and no case where one of the simulator and the reference rests and the
    other rolls for ever (an audit: the times were printed and not judged, a missing rest point passed)."""
    return worst_error(rows) <= tol and not underestimated(rows) and not any(r["missing"] for r in rows)
