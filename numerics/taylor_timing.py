"""Wall time and agreement of the three mpmath routes, one scene at a time in this process.

    python -m numerics.taylor_timing methods 15,30,50      # GBS reference vs Taylor reference
    python -m numerics.taylor_timing routes 30             # Cartesian route vs σ route (Taylor)

Agreement is in decimal digits: times relative to the motion's duration
(the rolling's end, else the slide's), vectors (rest point, Ω at the end of
the slide) by the norm of the difference over the norm.  The generated
Taylor code is built once before the clock starts (its cost is printed).
"""

from __future__ import annotations

import json
import sys
import time

import mpmath

from numerics import cartesian_reference, classical_vs_appell, equations, hard_cases, reference_motion
from numerics.scene import Scene

METHOD_CASES = ("sample", "delta close to fR", "huge spin, small speed", "draw, little side spin")


def scenes() -> dict[str, Scene]:
    out = {f"hard: {k}": v for k, v in hard_cases.hard_cases().items()}
    out.update({f"shot: {k}": Scene(classical_vs_appell.POOL, s, ()) for k, s in classical_vs_appell.SHOTS.items()})
    return out


def _digits(a: list, b: list) -> float | None:
    if any(x is None for x in a + b):
        return None
    diff, size = mpmath.norm([x - y for x, y in zip(a, b)]), mpmath.norm(b)
    if diff == 0:
        return 99.0
    return round(float(-mpmath.log10(diff / size)), 1) if size else None


def agreement(a, b, digits: int) -> dict:
    """Digits of agreement of two motions given as dicts t_slide_end, t_roll_end, rest, omega_end."""
    with mpmath.workdps(digits + 10):
        span = b["t_roll_end"] or max(b["t_slide_end"], mpmath.mpf("1e-3"))
        out = {}
        for key in ("t_slide_end", "t_roll_end"):
            if b[key] is not None and a[key] is not None:
                diff = abs(a[key] - b[key])
                out[key] = 99.0 if diff == 0 else round(float(-mpmath.log10(diff / span)), 1)
        for key in ("rest", "omega_end"):
            if b[key] is not None:
                out[key] = _digits(list(a[key]), list(b[key]))
        return out


def _as_dict(ref) -> dict:
    if isinstance(ref, cartesian_reference.CartesianMotion):
        end = ref.slide_end
        omega = None if end is None else (end["p"], end["q"])
    else:
        omega = None if ref.slide_end is None else (ref.slide_end.p, ref.slide_end.q)
    return {"t_slide_end": ref.t_slide_end, "t_roll_end": ref.t_roll_end, "rest": ref.rest, "omega_end": omega}


def _timed(fn, *args, **kw):
    t0 = time.perf_counter()
    out = fn(*args, **kw)
    return out, round(time.perf_counter() - t0, 2)


def warm_up() -> float:
    t0 = time.perf_counter()
    equations.log_slip_taylor()
    equations.rolling_taylor()
    cartesian_reference.jets()
    cartesian_reference.tail_coefficients()
    return round(time.perf_counter() - t0, 2)


def methods(digits_list, names=METHOD_CASES):
    all_scenes = scenes()
    for name in names:
        scene = all_scenes[f"hard: {name}"] if f"hard: {name}" in all_scenes else all_scenes[name]
        for digits in digits_list:
            gbs, t_gbs = _timed(reference_motion.reference, scene, digits=digits)
            tay, t_tay = _timed(reference_motion.reference, scene, digits=digits, method="taylor")
            yield {"case": name, "digits": digits, "gbs_s": t_gbs, "taylor_s": t_tay, **agreement(_as_dict(tay), _as_dict(gbs), digits)}


def routes(digits: int, names=None):
    for name, scene in scenes().items():
        if names and name not in names:
            continue
        cart, t_cart = _timed(cartesian_reference.reference, scene, digits=digits)
        sigma, t_sigma = _timed(reference_motion.reference, scene, digits=digits, method="taylor")
        yield {"case": name, "digits": digits, "cartesian_s": t_cart, "sigma_taylor_s": t_sigma, "cartesian_steps": cart.stats.steps,
               **agreement(_as_dict(cart), _as_dict(sigma), digits)}


def main(argv=None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    print(json.dumps({"generation_s": warm_up()}), flush=True)
    digits = [int(x) for x in argv[1].split(",")]
    rows = methods(digits) if argv[0] == "methods" else (row for d in digits for row in routes(d))
    for row in rows:
        print(json.dumps(row, ensure_ascii=False), flush=True)


if __name__ == "__main__":
    main()
