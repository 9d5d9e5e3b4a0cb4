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


from numerics import cartesian_reference, equations, reference_motion
from numerics.route_checks import agreement, as_dict, scenes

METHOD_CASES = ("sample", "delta close to fR", "huge spin, small speed", "draw, little side spin")


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
            gbs, t_gbs = _timed(reference_motion.reference, scene, digits=digits, method="gbs")
            tay, t_tay = _timed(reference_motion.reference, scene, digits=digits, method="taylor")
            yield {"case": name, "digits": digits, "gbs_s": t_gbs, "taylor_s": t_tay, **agreement(as_dict(tay), as_dict(gbs), digits)}


def routes(digits: int, names=None):
    for name, scene in scenes().items():
        if names and name not in names:
            continue
        cart, t_cart = _timed(cartesian_reference.reference, scene, digits=digits)
        sigma, t_sigma = _timed(reference_motion.reference, scene, digits=digits, method="taylor")
        yield {"case": name, "digits": digits, "cartesian_s": t_cart, "sigma_taylor_s": t_sigma, "cartesian_steps": cart.stats.steps,
               **agreement(as_dict(cart), as_dict(sigma), digits)}


def main(argv=None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    print(json.dumps({"generation_s": warm_up()}), flush=True)
    digits = [int(x) for x in argv[1].split(",")]
    rows = methods(digits) if argv[0] == "methods" else (row for d in digits for row in routes(d))
    for row in rows:
        print(json.dumps(row, ensure_ascii=False), flush=True)


if __name__ == "__main__":
    main()
