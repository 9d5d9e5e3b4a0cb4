"""Figures for the paper, deterministic (vector PDF, headless, no timestamps): same data, same bytes.

Each figure has a caption function beside its drawing function that reads the
same objects (the parameters, the initial states, the data), so a caption
states what was drawn and cannot fall behind it.  Captions are Unicode prose,
set by `paper.latex_text`.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from numerics.files import replace_file  # noqa: E402

# No creation date, a fixed font set: regenerated PDFs are byte-identical.
METADATA = {"CreationDate": None, "Producer": "appell", "Creator": "appell"}
plt.rcParams.update({"pdf.fonttype": 42, "font.family": "DejaVu Sans", "svg.hashsalt": "appell", "font.size": 7.5})
# Drawn at the width they are printed at (3.6 in, a column; 7 in across the page), so that 7.5 pt stays 6-8 pt.

FIGURES = Path(__file__).resolve().parent / "figures"
DATA = Path(__file__).resolve().parent / "data"


def params_text(P) -> str:
    """The ball and cloth of a scene, as a caption states them."""
    return (
        f"f = {P.f:g}, δ = {P.delta * 1e3:.4g} mm, ε = {P.epsilon * 1e3:.4g} mm, R = {P.R * 1e3:.5g} mm, "
        f"k = {P.k * 1e3:.4g} mm, g = {P.g:g} m/s²"
    )


def start_text(P, state) -> str:
    """An initial state as V₀, Ω₀ (the slip and the horizontal spin, not the centre's speed) with their directions
    α₀ and β₀ (n°2: u = V cos α, p = Ω cos β; a referee could not rebuild the massé start from its magnitudes), and r₀."""
    from numerics import equations

    u, v = equations.slip_velocity(P, state.vxi, state.veta, state.p, state.q)
    V, Omega = math.hypot(u, v), math.hypot(state.p, state.q)
    slip = f"slip V₀ = {V:.3g} m/s" + (f" at α₀ = {_degrees(v, u)}" if V else "")
    spin = f"spin Ω₀ = {Omega:.3g} rad/s" + (f" at β₀ = {_degrees(state.q, state.p)}" if Omega else "")
    return f"{slip}, {spin}, r₀ = {state.r:g} rad/s"


def _degrees(y: float, x: float) -> str:
    return f"{math.degrees(math.atan2(y, x)):.3g}°".replace("-", "−")


def _save(fig, path: Path) -> Path:
    """Lay out, write without a date (byte-identical) and whole (`numerics.files.replace_file`: a link at ``path`` is
    replaced, not written through, as savefig did), release."""
    fig.tight_layout()
    drawn = io.BytesIO()
    fig.savefig(drawn, format=path.suffix[1:], metadata=METADATA)
    plt.close(fig)
    replace_file(path, drawn.getvalue())
    return path


def work_precision(bench: dict, path: Path | None = None) -> Path:
    """Log error against log time per scene, one line per method, from `appell bench --json`'s data."""
    path = path or FIGURES / "work_precision.pdf"
    fig, ax = plt.subplots(figsize=(3.6, 3.7))
    methods: dict[str, list] = {}
    for row in bench["rows"]:
        if row["method"] not in PER_STATE:  # time per state, not per scene: another axis
            methods.setdefault(row["method"], []).append(row)
    markers = "osD^v<>p*h"
    for i, (method, rows) in enumerate(methods.items()):
        rows = sorted(rows, key=lambda r: r["seconds_per_scene"])
        xs = [r["seconds_per_scene"] for r in rows]
        ys = [max(r["rest_error"], FLOOR) for r in rows]  # a log axis has no 0: the caption says which
        ax.loglog(xs, ys, marker=markers[i % len(markers)], label=method, linewidth=1)
    ax.axhline(1e-9, color="grey", linewidth=0.6, linestyle="--")
    # At the right, clear of the batch's points; written as the caption writes it.
    ax.text(ax.get_xlim()[1] / 1.5, 1.5e-9, r"$10^{-9}$", color="grey", fontsize=7, ha="right")
    ax.set_xlabel("wall time per scene (s)")
    ax.set_ylabel("max relative error of the rest point")
    ax.set_title("Work against precision, benchmark scenes")
    ax.grid(True, which="major", linewidth=0.3)
    # Under the axes: inside, the legend hid scipy's points (a referee); every corner of the plot holds some.
    # Compact columns: at matplotlib's spacing the third column ran past the figure's right edge ("classical mode").
    ax.legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.17), ncol=3, frameon=False,
              columnspacing=0.8, handlelength=1.6, handletextpad=0.4)
    return _save(fig, path)


# Errors below this are drawn at it (a log axis shows no 0); the caption names the methods it lifts.
FLOOR = 1e-17

# What each method of `appell bench` is, for the text beside the figure ([key]: a citation, `paper.bibliography`).
BENCH_METHODS = {
    "batch": "the batch path, the engine compiled by numba [lam2015] (Dormand–Prince 8(5,3) [hairer1993] in σ = −ln V, "
             "32 scenes side by side in vector lanes), in threads; timed on {timed}, scored on every scene",
    "batch, 1 thread": "the same at tol 1e-9 on one thread, as heyoka's batch mode is timed",
    "simulate": "the same engine compiled, one scene per call",
    "simulate, interpreted": "the same engine not compiled (what the command line runs for one scene)",
    "heyoka": "heyoka's Taylor integrator [biscani2021] (compiled just in time), one scene per call",
    "heyoka batch": "heyoka's batch mode (SIMD-wide groups of scenes), one thread",
    "scipy DOP853": "scipy's integrator DOP853 [scipy2020] (one scene per call)",
    "scipy LSODA": "scipy's integrator LSODA [petzold1983] (one scene per call)",
    "mpmath": "the mpmath reference motion at 15, 30 and 50 digits",
    "classical model": "the closed forms of the classical model, whose error is the model's",
}
# Rows timed per state rather than per scene: in the caption, not on the figure's axes.
PER_STATE = {"states (dense output)": "states inside a slide from the dense output",
             "states in stiff steps": "states inside the stiff steps of a slide near δ = fR, integrated to in substeps"}


# Each figure's short caption, for a host's list of figures (the long one holds every parameter of the scenes).
SHORT_CAPTIONS = {
    "shots": "The centre's path of the pool shots in Appell's and the classical model",
    "phases": "V, Ω and θ through sliding, rolling and rest (the sample scene)",
    "end_of_sliding": "The end of sliding: π/2 − θ against V",
    "work_precision": "Work against precision of the simulators",
}


def work_precision_caption(bench: dict, source: str) -> str:
    """The figure's caption: what is plotted and on which scenes; the methods are described in the text
    (`work_precision_methods`: as a caption, fifteen lines overfilled a two-column page), and which source the
    times are of against ``source``, this appendix's (`paper.record.measured_from`)."""
    from paper.latex_text import processor
    from paper.record import measured_from

    methods = _methods(bench)  # every method described, before anything is written
    machine = bench["machine"]
    # Which methods are scored on fewer scenes, read off the rows (the curved slides; mpmath's few, for its cost).
    fewer: dict[int, list[str]] = {}
    for method in methods:
        counts = {row["scenes"] for row in bench["rows"] if row["method"] == method}
        if counts != {machine["scenes"]}:
            fewer.setdefault(max(counts), []).append(method)
    why = {machine["curved scenes (timed)"]: "those whose slide is curved, the slides they integrate"}
    scored = "".join(f"; {_listed(names)} on {n} of them ({why.get(n, 'for its cost')})" for n, names in fewer.items())
    lifted = [m for m in methods if any(r["rest_error"] < FLOOR for r in bench["rows"] if r["method"] == m)]
    floor = (f" Errors below 10^{round(math.log10(FLOOR))} ({_listed(lifted)}: exact to the double-precision rounding "
             f"of the comparison) are drawn at 10^{round(math.log10(FLOOR))}." if lifted else "")
    return (
        f"Work against precision: the largest relative error of the rest point against the wall "
        f"time per scene on {machine['cores']} cores ({processor(machine['cpu'])}) {measured_from(machine.get('source'), source, code=None)}, "
        f"one point per setting, over "
        f"{machine['scenes']} fixed scenes (the pool shots, the hard cases and seeded random shots, against their "
        f"40-digit mpmath reference){scored}; each method is described in the text. "
        f"Dashed line: the relative error 10^-9 asked of the batch path.{floor}"
    )


def work_precision_methods(bench: dict) -> list[tuple[str, str]]:
    """(method, what it is) for each method of the work-precision figure, for a list beside it (one sentence of
    them all ran on, a referee).  The batch's timed scenes are read off its row."""
    note = next(row["note"] for row in bench["rows"] if row["method"] == "batch")
    timed = f"{int(note.split()[0]):,} scenes cycling through the {bench['machine']['curved scenes (timed)']} curved ones"
    return [(m, BENCH_METHODS[m].format(timed=timed)) for m in _methods(bench)]


def versions_sentence(bench: dict) -> str:
    """Which numba (our engine's compiler), scipy and heyoka the run timed: times depend on them."""
    from numerics.bench import versions_text

    versions = versions_text(bench["machine"])
    return (f"Timed with {versions}." if versions
            else "The run did not record the versions of numba, scipy and heyoka it timed.")


def per_state_text(bench: dict) -> str:
    """The rows timed per state, which the figure does not draw."""
    per_state = [
        f"{PER_STATE[row['method']]}, {row['seconds_per_scene'] * 1e6:.2g} microseconds per state within "
        f"{_power_of_ten(row['max_rel_error'])} of the 20-digit states" for row in bench["rows"] if row["method"] in PER_STATE
    ]
    return f"Not drawn, as they are timed per state: {'; '.join(per_state)}." if per_state else ""


def _methods(bench: dict) -> list[str]:
    """The methods drawn, in the order of the rows; a KeyError names one without a description."""
    methods = [m for m in dict.fromkeys(row["method"] for row in bench["rows"]) if m not in PER_STATE]
    unknown = [m for m in methods if m not in BENCH_METHODS]
    if unknown:
        raise KeyError(f"bench method {unknown[0]!r} has no description for the caption")
    return methods


def _listed(names: list[str]) -> str:
    """a, b and c."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def _power_of_ten(x: float) -> str:
    """1.2·10^-10: a number the caption's maths sets as such (1.2e-10 would read as a product)."""
    mantissa, exponent = f"{x:.1e}".split("e")
    return f"{mantissa}·10^{int(exponent)}"


def shots(path: Path | None = None) -> Path:
    """The centre's path for the pool shots of `classical_vs_appell`, Appell's model beside the classical one."""
    import numpy as np

    from numerics import classical_vs_appell
    from numerics.scene import Scene
    from numerics.simulate import simulate

    path = path or FIGURES / "shots.pdf"
    names = list(classical_vs_appell.SHOTS)
    # Two rows of three, the sixth cell the legend: a column's width, in one or two columns alike.
    fig, grid = plt.subplots(2, 3, figsize=(3.6, 4.4))
    axes, legend_cell = grid.flat[: len(names)], grid.flat[len(names)]
    for ax, name in zip(axes, names):
        for model, style in (("appell", "-"), ("classical", "--")):
            m = simulate(Scene(classical_vs_appell.POOL, classical_vs_appell.SHOTS[name], (), model))
            ts = np.linspace(0, m.t_roll_end, 400)
            pts = np.array([[b.xi, b.eta] for b in map(m.state_at, ts)])
            # Drawn with ξ upwards (the shot's direction) and η to the left, as seen by the player.
            ax.plot(-pts[:, 1], pts[:, 0], style, linewidth=1, label=MODEL_LABELS[model])
            end = m.state_at(m.t_slide_end)
            ax.plot(-end.eta, end.xi, "o", markersize=3, color=ax.lines[-1].get_color())
        # Straight shots stay on η = 0: give the axis a width of its own (a tenth of the run).  A curved one is drawn
        # to scale: stretched, the massé's 13 cm forward looked as long as its 5 m sideways (a referee).
        lo, hi = ax.get_xlim()
        y_lo, y_hi = ax.get_ylim()
        if hi - lo > 1e-9 * (y_hi - y_lo):
            ax.set_aspect("equal", adjustable="datalim")
        else:
            half = (y_hi - y_lo) / 20
            ax.set_xlim(-half, half)
        ax.ticklabel_format(useOffset=False)
        ax.set_title(name.split(" (")[0], fontsize=7.5)
        ax.set_xlabel("−η (m)", fontsize=7)
        ax.tick_params(labelsize=6.5)  # 5.5 pt was about 5 pt in a column of two (a referee)
        ax.locator_params(axis="x", nbins=3)
    for ax in grid[:, 0]:
        ax.set_ylabel("ξ (m)", fontsize=7)
    legend_cell.axis("off")
    legend_cell.legend(*axes[0].get_legend_handles_labels(), fontsize=6.5, loc="center")
    fig.suptitle("Centre's path until rest (dot: end of sliding)", fontsize=7.5)
    return _save(fig, path)


MODEL_LABELS = {"appell": "Appell", "classical": "classical"}


def shots_caption() -> str:
    from numerics import classical_vs_appell

    return (
        f"The centre's path until rest of the pool shots ({params_text(classical_vs_appell.POOL)}) on an unbounded "
        f"cloth (no cushions), struck along ξ, drawn upwards with η to the left: curved paths to scale, straight ones "
        f"with a −η axis a tenth of the ξ axis. Solid (Appell): the rolling couple δmg acts while the ball slides; "
        f"dashed (classical): it does not (n°3); both roll alike once sliding ends; dot: the end of sliding. The "
        f"starts are listed in the text."
    )


def shots_starts() -> list[tuple[str, str]]:
    """Each shot of the figure and its start, listed in the text before it (in the caption, with the rest, a 12 pt
    page's figure overflowed it: an audit of hosts)."""
    from numerics import classical_vs_appell

    # The shot as struck (its name: the centre's speed and spin), then the paper's variables: the slip V₀ differs
    # from the centre's speed (a referee read "draw: V₀ = 7.29 m/s" as the shot's speed).
    return [(name, start_text(classical_vs_appell.POOL, state)) for name, state in classical_vs_appell.SHOTS.items()]


def phases_in_time(path: Path | None = None) -> Path:
    """V, Ω and θ = β − α against time through sliding and rolling, for the sample scene."""
    import numpy as np

    from numerics import equations, hard_cases
    from numerics.simulate import simulate

    path = path or FIGURES / "phases.pdf"
    scene = hard_cases.hard_cases()["sample"]
    m = simulate(scene)
    P = scene.params
    # As many samples in the slide (half a second) as in the roll (ten seconds): 600 evenly spread gave the slide 24,
    # and Ω's minimum kinks.
    ts = np.concatenate([np.linspace(0, m.t_slide_end, 400, endpoint=False), np.linspace(m.t_slide_end, m.t_roll_end * 1.05, 400)])
    Vs, Omegas, thetas = [], [], []
    for t in ts:
        b = m.state_at(t)
        u, v = equations.slip_velocity(P, b.vxi, b.veta, b.p, b.q)
        Vs.append(math.hypot(u, v) if b.phase == "sliding" else 0.0)
        Omegas.append(math.hypot(b.p, b.q))
        theta = math.atan2(b.q, b.p) - math.atan2(v, u)
        thetas.append(math.atan2(math.sin(theta), math.cos(theta)) if b.phase == "sliding" else math.nan)
    fig, axes = plt.subplots(3, 1, figsize=(3.6, 3.6), sharex=True)
    for ax, ys, label in zip(axes, (Vs, Omegas, thetas), ("V (m/s)", "Ω (rad/s)", "θ = β − α (rad)")):
        ax.plot(ts, ys, linewidth=1)
        ax.set_ylabel(label)
        for t_mark in (m.t_slide_end, m.t_roll_end):
            ax.axvline(t_mark, color="grey", linewidth=0.5, linestyle=":")
        ax.axvline(m.t_pivot_end, color="grey", linewidth=0.5, linestyle="-.")  # the sample pivots past its slide
        ax.grid(True, linewidth=0.3)
    axes[2].axhline(math.pi / 2, color="grey", linewidth=0.5, linestyle="--")
    axes[2].set_ylim(top=math.pi / 2 + 0.3)  # the dashed θ = π/2 clear of the frame
    axes[2].set_xscale("symlog", linthresh=1.0)
    axes[2].set_xlim(left=0.0)  # no negative times: symlog's margin drew an empty band before t = 0
    axes[2].set_xlabel("t (s) (linear to 1 s, then logarithmic)")
    axes[0].set_title("Sample scene (vertical lines: the phases end)")
    return _save(fig, path)


def phases_caption() -> str:
    from numerics import hard_cases

    scene = hard_cases.hard_cases()["sample"]
    return (
        "The slip speed V, the horizontal rotation Ω and θ = β − α against time for the sample scene (listed in "
        "the text), through sliding, pure rolling and rest. Dotted: the ends of sliding and of rolling; dash-dot: "
        "the end of pivoting; dashed: θ = π/2, which θ reaches at the end of sliding, as V → 0, π/2 − θ "
        f"shrinking like V^κ (κ = {_kappa(scene.params):.2g} here; n8.end_exponent_mpmath): so slowly that at the "
        "last time plotted before the end the curve is still short of the line."
    )


def phases_scene() -> list[tuple[str, str]]:
    """The ball and the start of the phases figure, listed in the text before it, as `shots_starts` (in its caption,
    they made it the longest, 900 characters, a referee)."""
    from numerics import hard_cases

    scene = hard_cases.hard_cases()["sample"]
    # sample.json alone: the whole path, one unbreakable word, stretched a two-column caption (a referee).
    return [("sample scene", f"{params_text(scene.params)}; {start_text(scene.params, scene.state)} (the "
                             "package's example shot, sample.json)")]


def end_of_sliding(path: Path | None = None) -> Path:
    """π/2 − θ against V at the end of sliding: the power law V^κ (ours; n°8 says θ becomes right in a finite
    time), on the 20-digit slides that the claim n8.end_exponent_mpmath measures it on, down to V = 10⁻²⁰⁰ V₀
    (log10 of both, which float64 holds)."""
    import mpmath
    import numpy as np

    from numerics import trajectory_checks as tc

    path = path or FIGURES / "end_of_sliding.pdf"
    fig, ax = plt.subplots(figsize=(3.6, 3.4))
    markers = "os^"
    for P, name, color in _end_sets():
        k = _kappa(P)
        for i, start in enumerate(tc.SHOTS):
            xs, ys = _log_slide(tc.reference_slide(P, start), mpmath)
            ax.plot(xs, ys, markers[i], markersize=2.2, color=color, label=f"{name}, shot {i + 1}")
            # From the last point up to where the line leaves the data's range (the start of a δ = 0.3fR slide is
            # far from the power law: a line to its first point rose off the plot).
            x_line = np.array([min(xs), min(max(xs), xs[-1] + (max(ys) - ys[-1]) / k)])
            ax.plot(x_line, ys[-1] + k * (x_line - xs[-1]), "-", linewidth=0.6, color=color)
    ax.set_xlabel(r"$\log_{10} V$ ($V$ in m/s)")
    ax.set_ylabel(r"$\log_{10}(\pi/2 - \theta)$")
    ax.set_title(r"End of sliding: $\pi/2 - \theta \propto V^{\kappa}$ (lines: slope $\kappa$)", fontsize=7.5)
    # Under the axes, as in the work-precision figure: inside, it covered a pool ball's line.
    ax.legend(fontsize=5.5, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, frameon=False)
    ax.grid(True, which="major", linewidth=0.3)
    return _save(fig, path)


def end_of_sliding_caption() -> str:
    from numerics import trajectory_checks as tc

    return (
        f"The end of sliding: log₁₀(π/2 − θ) against log₁₀ V on the slides of n8.end_exponent_mpmath, integrated in "
        f"σ = −ln V at {tc.SLIDE_DIGITS} digits down to V = 10^-{tc.END_DECADES} V₀, at the integration's steps "
        f"(markers) where π/2 − θ > 10^{round(math.log10(PSI_FLOOR))} (below it, the integration's own error in θ "
        f"dominates); lines of slope κ = Rδ/(f(R² + k²) − Rδ) through each slide's last step (the lines are ours: "
        f"n°8 says only that θ becomes a right angle in a finite time). The balls and the starts are listed in the text."
    )


def end_of_sliding_starts() -> list[tuple[str, str]]:
    """The balls (with their κ) and the starts of the figure's slides, listed in the text before it, as
    `shots_starts`."""
    from numerics import trajectory_checks as tc
    from numerics.scene import State

    # κ to 3 digits: from the rounded k listed (18.07 mm), a reader gets 0.05263, not our 0.05262 (a referee)
    sets = [(name, f"{params_text(P)}, κ = {_kappa(P):.3g}") for P, name, _ in _end_sets()]
    # The slip and the spin depend on R alone, which the balls share: one start serves both (a referee read "for
    # the pool ball" as leaving the other's start unsaid).
    starts = [{start_text(P, State(*start)) for P, _, _ in _end_sets()} for start in tc.SHOTS]
    if any(len(one) != 1 for one in starts):
        raise ValueError("the balls of the end-of-sliding figure start differently: list each ball's starts")
    return sets + [(f"shot {i + 1}", f"{one.pop()} (both balls)") for i, one in enumerate(starts)]


PSI_FLOOR = 1e-10


def _kappa(P) -> float:
    import sympy as sp

    from derivation import n8_general
    from numerics.equations import PARAMS

    return float(sp.lambdify(PARAMS, n8_general.relations()["kappa"])(*P.values()))


def _log_slide(slide, mpmath) -> tuple[list[float], list[float]]:
    """log₁₀ V and log₁₀(π/2 − θ) at a slide's nodes, in mpmath at the claim's working precision (V reaches
    10⁻²⁰⁰ V₀, π/2 − θ far below float64's resolution of π/2).  Nodes where π/2 − θ < `PSI_FLOOR` are left
    out: there the slide's own error in θ (the steps add up over hundreds of decades of V) begins to show."""
    from numerics import trajectory_checks as tc

    xs, ys = [], []
    with mpmath.workdps(tc.DIGITS + 10):
        floor = mpmath.mpf(PSI_FLOOR)
        for sigma, y in slide.nodes:
            psi = mpmath.pi / 2 - (mpmath.atan2(y[3], y[2]) - y[1])
            psi = mpmath.atan2(mpmath.sin(psi), mpmath.cos(psi))
            if psi > floor:
                xs.append(float(-sigma / mpmath.log(10)))
                ys.append(float(mpmath.log10(psi)))
    return xs, ys


def _end_sets():
    from numerics import trajectory_checks as tc

    return ((tc.POOL, "pool ball", "C0"), (tc.HEAVY, "δ = 0.3 fR", "C3"))


SAMPLE = Path(__file__).resolve().parent.parent / "numerics" / "scenes" / "sample.json"


def sample_motion(path: Path | None = None) -> Path:
    """The README's picture: `Motion.plot` of numerics/scenes/sample.json, as `appell plot` draws it (the same
    simulation, interpreted, and the same title: the same bytes), a PNG without a date or version."""
    from numerics import plot
    from numerics.scene import load
    from numerics.simulate import simulate

    path = path or FIGURES / "sample_motion.png"
    motion = simulate(load(SAMPLE), jit=False)
    path.parent.mkdir(parents=True, exist_ok=True)
    return plot.save(motion.plot(title=f"{SAMPLE.name}: {plot.default_title(motion)}"), path)
