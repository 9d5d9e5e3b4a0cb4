"""Figures for the paper, deterministic (vector PDF, headless, no timestamps): same data, same bytes."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# No creation date, a fixed font set: regenerated PDFs are byte-identical.
METADATA = {"CreationDate": None, "Producer": "appell", "Creator": "appell"}
plt.rcParams.update({"pdf.fonttype": 42, "font.family": "DejaVu Sans", "svg.hashsalt": "appell", "font.size": 9})

FIGURES = Path(__file__).resolve().parent / "figures"
DATA = Path(__file__).resolve().parent / "data"


def _save(fig, path: Path) -> Path:
    """Lay out, write without a date (byte-identical), release."""
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, metadata=METADATA)
    plt.close(fig)
    return path


def work_precision(bench: dict, path: Path | None = None) -> Path:
    """Log error against log time per scene, one line per method, from `appell bench --json`'s data."""
    path = path or FIGURES / "work_precision.pdf"
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    methods: dict[str, list] = {}
    for row in bench["rows"]:
        methods.setdefault(row["method"], []).append(row)
    markers = "osD^v<>p*h"
    for i, (method, rows) in enumerate(methods.items()):
        rows = sorted(rows, key=lambda r: r["seconds_per_scene"])
        xs = [r["seconds_per_scene"] for r in rows]
        ys = [max(r["rest_error"], 1e-17) for r in rows]
        ax.loglog(xs, ys, marker=markers[i % len(markers)], label=method, linewidth=1)
    ax.axhline(1e-9, color="grey", linewidth=0.6, linestyle="--")
    ax.text(ax.get_xlim()[0] * 1.5, 1.5e-9, "1e-9", color="grey", fontsize=7)
    ax.set_xlabel("wall time per scene (s)")
    ax.set_ylabel("max relative error of the rest point")
    ax.set_title("Work against precision on the benchmark scenes")
    ax.grid(True, which="major", linewidth=0.3)
    ax.legend(fontsize=7, loc="best")
    return _save(fig, path)


def shots(path: Path | None = None) -> Path:
    """The centre's path for the pool shots of `classical_vs_appell`, Appell's model beside the classical one."""
    import numpy as np

    from numerics import classical_vs_appell
    from numerics.scene import Scene
    from numerics.simulate import simulate

    path = path or FIGURES / "shots.pdf"
    names = list(classical_vs_appell.SHOTS)
    fig, axes = plt.subplots(1, len(names), figsize=(7.2, 3.2))
    for ax, name in zip(axes, names):
        for model, style in (("appell", "-"), ("classical", "--")):
            m = simulate(Scene(classical_vs_appell.POOL, classical_vs_appell.SHOTS[name], (), model))
            ts = np.linspace(0, m.t_roll_end, 400)
            pts = np.array([[b.xi, b.eta] for b in map(m.state_at, ts)])
            # Drawn with ξ upwards (the shot's direction) and η to the left, as seen by the player.
            ax.plot(-pts[:, 1], pts[:, 0], style, linewidth=1, label=model)
            end = m.state_at(m.t_slide_end)
            ax.plot(-end.eta, end.xi, "o", markersize=3, color=ax.lines[-1].get_color())
        # Straight shots stay on η = 0: give the axis a width of its own (a tenth of the run).
        lo, hi = ax.get_xlim()
        y_lo, y_hi = ax.get_ylim()
        half = max((hi - lo) / 2, (y_hi - y_lo) / 20)
        middle = (hi + lo) / 2 if hi - lo > 1e-9 * (y_hi - y_lo) else 0.0
        ax.set_xlim(middle - half, middle + half)
        ax.ticklabel_format(useOffset=False)
        ax.set_title(name.split(" (")[0], fontsize=8)
        ax.set_xlabel("−η (m)", fontsize=7)
        ax.tick_params(labelsize=6)
    axes[0].set_ylabel("ξ (m)", fontsize=7)
    axes[0].legend(fontsize=6, loc="lower left")
    fig.suptitle("Centre's path until rest (dot: end of sliding)", fontsize=9)
    return _save(fig, path)


def phases_in_time(path: Path | None = None) -> Path:
    """V, Ω and θ = β − α against time through sliding and rolling, for the sample scene."""
    import math

    import numpy as np

    from numerics import equations, hard_cases
    from numerics.simulate import simulate

    path = path or FIGURES / "phases.pdf"
    scene = hard_cases.hard_cases()["sample"]
    m = simulate(scene)
    P = scene.params
    ts = np.linspace(0, m.t_roll_end * 1.05, 600)
    Vs, Omegas, thetas = [], [], []
    for t in ts:
        b = m.state_at(t)
        u, v = equations.slip_velocity(P, b.vxi, b.veta, b.p, b.q)
        Vs.append(math.hypot(u, v) if b.phase == "sliding" else 0.0)
        Omegas.append(math.hypot(b.p, b.q))
        theta = math.atan2(b.q, b.p) - math.atan2(v, u)
        thetas.append(math.atan2(math.sin(theta), math.cos(theta)) if b.phase == "sliding" else math.nan)
    fig, axes = plt.subplots(3, 1, figsize=(6.0, 5.0), sharex=True)
    for ax, ys, label in zip(axes, (Vs, Omegas, thetas), ("V (m/s)", "Ω (rad/s)", "θ = β − α (rad)")):
        ax.plot(ts, ys, linewidth=1)
        ax.set_ylabel(label)
        for t_mark in (m.t_slide_end, m.t_roll_end):
            ax.axvline(t_mark, color="grey", linewidth=0.5, linestyle=":")
        ax.grid(True, linewidth=0.3)
    axes[2].axhline(math.pi / 2, color="grey", linewidth=0.5, linestyle="--")
    axes[2].set_xscale("symlog", linthresh=1.0)
    axes[2].set_xlabel("t (s) (linear to 1 s, then logarithmic)")
    axes[0].set_title("The sample scene: sliding, then rolling until rest (dotted lines)")
    return _save(fig, path)


def end_of_sliding(path: Path | None = None) -> Path:
    """π/2 − θ against V near the end of sliding: the power law V^κ of n°8."""
    import math

    import numpy as np
    import sympy as sp

    from derivation import n8_general
    from numerics import equations, hard_cases, sliding
    from numerics.equations import PARAMS

    path = path or FIGURES / "end_of_sliding.pdf"
    fig, ax = plt.subplots(figsize=(5.0, 3.6))
    kappa = sp.lambdify(PARAMS, n8_general.relations()["kappa"])
    for name in ("sample", "delta close to fR", "huge spin, small speed"):
        scene = hard_cases.hard_cases()[name]
        P, s = scene.params, scene.state
        u, v = equations.slip_velocity(P, s.vxi, s.veta, s.p, s.q)
        sl = sliding.slide(P, math.hypot(u, v), math.atan2(v, u), s.p, s.q, tol=1e-12, end_fraction=1e-12)
        Vs, psis = [], []
        for sigma, y in sl.nodes:
            psi = math.pi / 2 - (math.atan2(y[3], y[2]) - y[1])
            psi = math.atan2(math.sin(psi), math.cos(psi))
            if psi > 0:
                Vs.append(math.exp(-sigma))
                psis.append(psi)
        k = kappa(*P.values())
        line = ax.loglog(Vs, psis, "o", markersize=2.5, label=f"{name} (κ = {k:.3f})")
        V_line = np.array([min(Vs), max(Vs)])
        ax.loglog(V_line, psis[-1] * (V_line / Vs[-1]) ** k, "-", linewidth=0.7, color=line[0].get_color())
    ax.set_xlabel("slip speed V (m/s)")
    ax.set_ylabel("π/2 − θ (rad)")
    ax.set_title("End of sliding: π/2 − θ ∝ V^κ (lines: slope κ of n°8)", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="major", linewidth=0.3)
    return _save(fig, path)
