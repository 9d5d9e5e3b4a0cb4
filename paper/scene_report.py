"""The readable summary `appell simulate` prints for one scene."""

from __future__ import annotations

from numerics.simulate import Motion


def _time(t) -> str:
    return "never" if t is None else f"{t:.9g} s"


def as_text(motion: Motion, times=()) -> str:
    P, s = motion.scene.params, motion.scene.state
    lines = [
        f"model {motion.scene.model}: f = {P.f:g}, delta = {P.delta:g} m, epsilon = {P.epsilon:g} m, "
        f"R = {P.R:g} m, k = {P.k:g} m, g = {P.g:g} m/s^2",
        f"start: xi = {s.xi:g}, eta = {s.eta:g} m; vxi = {s.vxi:g}, veta = {s.veta:g} m/s; "
        f"p = {s.p:g}, q = {s.q:g}, r = {s.r:g} rad/s",
        "",
        "phases:",
    ]
    for ph in motion.phases:
        end = "" if ph.phase == "rest" else f" to {_time(ph.t_end)}"
        error = f"  (est. rel. error {ph.error:.1e})" if ph.error else ""
        lines.append(f"  {ph.phase:<9} from {ph.t_start:.9g} s{end}: {ph.model}{error}")
    lines += [
        "",
        f"sliding ends   {_time(motion.t_slide_end)}",
        f"rolling ends   {_time(motion.t_roll_end)}",
        f"pivoting ends  {_time(motion.t_pivot_end)}",
        "rest point     " + ("none (rolls for ever: delta = 0)" if motion.rest is None
                            else f"xi = {motion.rest[0]:.10g} m, eta = {motion.rest[1]:.10g} m"),
        f"estimated relative error of the rest point: {motion.error:.1e} (tolerance asked {motion.tol:g})",
    ]
    if times:
        lines += ["", f"{'t (s)':>10} {'phase':<8} {'xi':>12} {'eta':>12} {'vxi':>11} {'veta':>11} {'p':>11} {'q':>11} {'r':>11}"]
        for t in times:
            b = motion.state_at(t)
            lines.append(
                f"{b.t:>10.6g} {b.phase:<8} {b.xi:>12.8g} {b.eta:>12.8g} {b.vxi:>11.6g} {b.veta:>11.6g} "
                f"{b.p:>11.6g} {b.q:>11.6g} {b.r:>11.6g}"
            )
    return "\n".join(lines)
