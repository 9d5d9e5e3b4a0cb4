"""The simulator's own pictures: the path of the centre with its phases, and V, Ω, r against time.

`draw(motion)` (also `Motion.plot`) draws one scene: on the left the path of
the centre in the (ξ, η) plane, the sliding and the pure rolling (n°7) in
their own colours, the start, the end of sliding and the rest point marked;
on the right, stacked and sharing the time axis, the slip speed
V = |(ξ' − qR, η' + pR)| (n°2: the velocity of the contact point), the
horizontal rotation Ω = √(p² + q²) and the pivot spin r (eq. (5)), with the
sliding shaded and the ends of the phases marked.  `draw_scenes(motions)`
draws many scenes' paths and rest points in one plane.

Both return the `matplotlib.figure.Figure` (``ax.figure`` when an axes is
given): ``motion.plot().savefig("shot.png")``.  `save` writes a figure by its
suffix (png, pdf, svg) with fixed metadata, so that the same motion gives the
same bytes.

Matplotlib is imported here only: `numerics.simulate` and the command line
import this module when a picture is asked for, never before (their start
stays as fast as without it).
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import matplotlib.axes
import matplotlib.figure
import numpy as np
from matplotlib import pyplot as plt

from numerics import validation
from numerics.validation import SceneError

# Colours told apart in colour-blind palettes (tab:orange / tab:blue), and the phases' names as in `simulate.PHASES`.
SLIDING, ROLLING, REST, PIVOT = "tab:orange", "tab:blue", "black", "tab:green"
# Drawn under these settings whatever the caller's rcParams (the figure of `appell paper` sets a smaller font).
STYLE = {"font.family": "DejaVu Sans", "font.size": 9, "axes.titlesize": 9, "legend.fontsize": 8, "lines.linewidth": 1.4}
FORMATS = ("png", "pdf", "svg")
# No dates, no version strings: the same figure gives the same bytes (matplotlib pinned).
METADATA = {
    "png": {"Software": "appell"},
    "pdf": {"CreationDate": None, "Producer": "appell", "Creator": "appell"},
    "svg": {"Date": None, "Creator": "appell"},
}
DPI = 120
MAX_SCENES = 100  # `draw_scenes` draws at most this many paths (the command line says so when it drops some)
# Markers above every path: in `draw_scenes` a later scene's path from a shared start hid the end-of-sliding dots
# of short slides drawn before it (matplotlib draws artists of one zorder in the order added; lines are at 2).
MARKER_ZORDER = 3


def times(motion, n_slide: int = 400, n_after: int = 400) -> np.ndarray:
    """A time grid for the pictures, from 0 to a little after rest.

    Denser inside the slide and most of all towards its end, where the path curves: there the direction of
    the slip turns as V^(κ−1) (n°8).  The ends of the phases are points of the grid, so that the curves reach
    them exactly.  A ball that rolls for ever (δ = 0) is drawn to 2 t_slide_end + 1 s, as `Motion.samples`.
    """
    t1 = motion.t_slide_end
    end = _end(motion)
    grid = [np.linspace(t1, end, n_after)]
    if t1 > 0:
        approach = t1 * (1 - np.geomspace(1e-7, 1, n_slide // 2))  # clustered at t1 from below
        grid += [np.linspace(0, t1, n_slide - n_slide // 2), approach]
    grid.append([t for t in (motion.t_roll_end, motion.t_pivot_end) if t is not None and t <= end])
    return np.unique(np.clip(np.concatenate([np.asarray(g, dtype=float) for g in grid]), 0, end))


def _end(motion) -> float:
    """The last time drawn: rest (or the end of the pivot, when later), then 5 % more to show the ball still."""
    rest = motion.t_roll_end if motion.t_roll_end is not None else 2 * motion.t_slide_end + 1.0
    end = max(rest, motion.t_pivot_end or 0.0, motion.t_slide_end)
    return 1.05 * end if end > 0 else 1.0


def slip_speed(motion, states) -> np.ndarray:
    """V = |(ξ' − qR, η' + pR)|, the speed of the contact point (n°2's u, v); 0 from the end of sliding on."""
    R = motion.scene.params.R
    return np.hypot(states.vxi - states.q * R, states.veta + states.p * R)


def rotation(states) -> np.ndarray:
    """Ω = √(p² + q²), the horizontal rotation (n°2)."""
    return np.hypot(states.p, states.q)


def _check_motion(motion, where: str) -> None:
    from numerics.simulate import Motion  # (the module that imports this one when a picture is asked for)

    if not isinstance(motion, Motion):
        raise SceneError(where, f"must be a Motion (simulate(scene)), got {validation.describe(motion)}")


def _check_axes(ax) -> None:
    if ax is not None and not isinstance(ax, matplotlib.axes.Axes):
        raise SceneError("ax", f"must be a matplotlib Axes or None, got {validation.describe(ax)}")


def draw(motion, ax=None, title: str | None = None):
    """The picture of one scene (see the module); returns the Figure.

    With ``ax``, only the path is drawn, into it (the caller's layout), and ``ax.figure`` returned.  Without,
    a new figure (pyplot's, so that ``plt.show()`` shows it; `save` closes it, else ``plt.close(fig)``) holds the
    path and the three time panels; ``title`` replaces the default one, which states the model and the parameters.
    Anything else than a `Motion` and an Axes (or None) is a SceneError naming it.
    """
    _check_motion(motion, "motion")
    _check_axes(ax)
    with matplotlib.rc_context(STYLE):
        ts = times(motion)
        states = motion.states(ts)
        if ax is not None:
            _draw_path(ax, motion, states)
            return ax.figure
        fig = plt.figure(figsize=(10, 5.2))
        grid = fig.add_gridspec(3, 2, width_ratios=(1.25, 1), hspace=0.12, wspace=0.28)
        path_ax = fig.add_subplot(grid[:, 0], label="path")
        _draw_path(path_ax, motion, states)
        panels = [fig.add_subplot(grid[0, 1], label="V")]
        panels += [fig.add_subplot(grid[i, 1], sharex=panels[0], label=name) for i, name in ((1, "Omega"), (2, "r"))]
        _draw_in_time(panels, motion, states)
        fig.suptitle(title if title is not None else default_title(motion))
        fig.subplots_adjust(left=0.07, right=0.98, bottom=0.1, top=0.9)
        return fig


MODELS = {"appell": "Appell's model", "classical": "the classical model (no rolling couple while sliding, n°3)"}


def default_title(motion) -> str:
    P = motion.scene.params
    return (
        f"A shot under {MODELS[motion.scene.model]}: f = {P.f:g}, "
        f"δ = {P.delta * 1e3:.3g} mm, ε = {P.epsilon * 1e3:.3g} mm, R = {P.R * 1e3:.4g} mm, k = {P.k * 1e3:.4g} mm"
    )


def _draw_path(ax, motion, states) -> None:
    """The centre's path in (ξ, η), one line per phase; the start, the end of sliding and the rest point."""
    t1, t2 = motion.t_slide_end, motion.t_roll_end
    t = states.t
    if t1 > 0:
        slide = t <= t1
        ax.plot(states.xi[slide], states.eta[slide], color=SLIDING, label=f"sliding (0 – {t1:.3g} s)", gid="path:sliding")
    rolls = (t >= t1) & (t <= (t2 if t2 is not None else np.inf))
    if t2 is None or t2 > t1:
        until = "for ever: δ = 0" if t2 is None else f"{t1:.3g} – {t2:.3g} s"
        ax.plot(states.xi[rolls], states.eta[rolls], color=ROLLING, label=f"pure rolling, n°7 ({until})", gid="path:rolling")
    start = motion.scene.state
    ax.plot([start.xi], [start.eta], "o", color="grey", markersize=5, label="start", gid="start")
    if t1 > 0:
        end = motion.state_at(t1)
        ax.plot([end.xi], [end.eta], "o", markerfacecolor="white", markeredgecolor=SLIDING, markeredgewidth=1.6,
                markersize=7, label="end of sliding", gid="end of sliding")
    if motion.rest is not None:
        ax.plot(*([c] for c in motion.rest), "X", color=REST, markersize=8, label=f"rest point ({t2:.3g} s)", gid="rest point")
    _label_plane(ax)
    ax.set_title("Path of the centre" + _frame_path(ax))
    ax.grid(True, linewidth=0.3)
    _legend_clear_of_path(ax, states.xi, states.eta)


CORNERS = ("upper left", "upper right", "lower left", "lower right")


def _legend_clear_of_path(ax, xs, ys) -> None:
    """The legend in the corner where its box stays farthest from every point of the path (in the axes' units,
    once its equal scales are applied): matplotlib's "best" counts the vertices a legend would cover, and in the
    README's own example it covered the rest point at the end of a straight roll (a user audit)."""
    legend = ax.legend(loc=CORNERS[0])
    ax.apply_aspect()
    to_axes = ax.transAxes.inverted()
    box = legend.get_window_extent().transformed(to_axes)  # (the figure's own renderer, any backend)
    w, h = box.width, box.height
    points = to_axes.transform(ax.transData.transform(np.column_stack([xs, ys])))

    def clearance(corner: str) -> float:  # the path's least distance to the legend's box in that corner
        x0 = 0.0 if corner.endswith("left") else 1.0 - w
        y0 = 1.0 - h if corner.startswith("upper") else 0.0
        dx = np.maximum(np.maximum(x0 - points[:, 0], points[:, 0] - (x0 + w)), 0.0)
        dy = np.maximum(np.maximum(y0 - points[:, 1], points[:, 1] - (y0 + h)), 0.0)
        return float(np.min(np.hypot(dx, dy)))

    legend.set_loc(max(CORNERS, key=clearance))  # the first of equals: the same picture every time


def _label_plane(ax) -> None:
    ax.set_xlabel("ξ (m)")
    ax.set_ylabel("η (m)")
    _fix_ticks(ax)


def _fix_ticks(ax) -> None:
    """Tick labels at the style's size: matplotlib makes ticks when it draws, under the rcParams of that moment."""
    ax.tick_params(labelsize=STYLE["font.size"])


def _frame_path(ax) -> str:
    """Equal scales when the path is about as wide as long; else each axis its own scale, the narrower given at
    least a twentieth of the longer so that a straight shot is a line, not magnified rounding.  Returns what the
    title should add ("" or " (ξ and η to different scales)")."""
    (x0, x1), (y0, y1) = ax.dataLim.intervalx, ax.dataLim.intervaly
    longest = max(x1 - x0, y1 - y0) or 0.1  # a ball that never moves: 5 mm around it
    spans = []
    for (lo, hi), set_lim in (((x0, x1), ax.set_xlim), ((y0, y1), ax.set_ylim)):
        low, high = (lo + hi) / 2 - longest / 40, (lo + hi) / 2 + longest / 40
        if hi - lo < longest / 20 and low < high:  # (equal far from the origin, 1e99 m: matplotlib's own margin)
            set_lim(low, high)
        spans.append(max(hi - lo, longest / 20))
    if max(x1 - x0, y1 - y0) == 0:  # its square box is set: the box keeps it square (its limits, fixed, cannot move)
        ax.set_aspect("equal", adjustable="box")
        return ""
    if min(spans) > longest / 4:
        ax.set_aspect("equal", adjustable="datalim")
        return ""
    return " (ξ and η to different scales)"


def _draw_in_time(panels, motion, states) -> None:
    """V, Ω and r against t; the slide shaded, the ends of sliding, of rolling (rest) and of the pivot marked."""
    t = states.t
    curves = (
        (slip_speed(motion, states), "V (m/s)", "slip speed V", "V"),
        (rotation(states), "Ω (rad/s)", "rotation Ω", "Omega"),
        (states.r, "r (rad/s)", "pivot spin r", "r"),
    )
    ends = [(motion.t_slide_end, SLIDING, "--", "end of sliding"), (motion.t_roll_end, REST, ":", "rest (end of rolling)"),
            (motion.t_pivot_end, PIVOT, "-.", "end of pivoting (eq. (5))")]
    ends = [e for e in ends if e[0] is not None and e[0] > 0]
    for ax, (ys, unit, name, gid) in zip(panels, curves):
        if motion.t_slide_end > 0:
            ax.axvspan(0, motion.t_slide_end, color=SLIDING, alpha=0.12, linewidth=0, label="sliding")
        ax.plot(t, ys, color="black" if gid != "r" else PIVOT, label=name, gid=f"curve:{gid}")
        for when, colour, style, label in ends:
            ax.axvline(when, color=colour, linestyle=style, linewidth=1, label=label, gid=f"mark:{label}")
        ax.set_ylabel(unit)
        _fix_ticks(ax)
        ax.grid(True, linewidth=0.3)
    panels[0].legend(loc="upper right", ncol=2)
    for ax in panels[:-1]:
        ax.tick_params(labelbottom=False)
    # Rolling lasts tens of slides: past the slide and the pivot, time runs logarithmically so that both show.
    last = t[-1]
    short = max(motion.t_slide_end, motion.t_pivot_end or 0.0)
    if short > 0 and last > 5 * short:
        linear = 10.0 ** math.ceil(math.log10(short))
        for ax in panels:
            ax.set_xscale("symlog", linthresh=linear, linscale=1.5)
        panels[-1].set_xlabel(f"t (s), linear to {linear:g} s, then logarithmic")
    else:
        panels[-1].set_xlabel("t (s)")
    panels[-1].set_xlim(0, last)


def draw_scenes(motions, ax=None, labels=None, title: str | None = None):
    """Many scenes' paths in one (ξ, η) plane, each with its end of sliding (a dot) and its rest point (a cross
    of its colour); returns the Figure.  ``labels`` names the scenes in the legend (default "scene [i]"),
    shown when there are at most ten, one for each scene.  One to `MAX_SCENES` are drawn: anything else, a
    label list of another length, or anything not a `Motion`, is a SceneError naming it."""
    if isinstance(motions, (str, bytes)) or not hasattr(motions, "__iter__"):
        raise SceneError("motions", f"must be a list of Motions, got {validation.describe(motions)}")
    motions = list(motions)
    if not 1 <= len(motions) <= MAX_SCENES:
        raise SceneError("motions", f"must be 1 to {MAX_SCENES} Motions in one picture, got {len(motions)}")
    for i, motion in enumerate(motions):
        _check_motion(motion, f"motions [{i}]")
    _check_axes(ax)
    if labels is None:
        labels = [f"scene [{i}]" for i in range(len(motions))]
    elif isinstance(labels, (str, bytes)) or not hasattr(labels, "__len__") or len(labels) != len(motions):
        # zip would drop the scenes past the last label, silently
        raise SceneError("labels", f"must be one for each of the {len(motions)} scenes, got {validation.describe(labels)}")
    with matplotlib.rc_context(STYLE):
        fig = ax.figure if ax is not None else plt.figure(figsize=(8, 6))
        ax = ax if ax is not None else fig.add_subplot(label="paths")
        for i, (motion, label) in enumerate(zip(motions, labels)):
            states = motion.states(times(motion, 200, 100))
            colour = f"C{i % 10}"
            ax.plot(states.xi, states.eta, color=colour, label=label, gid=f"path:{i}")
            if motion.t_slide_end > 0:
                end = motion.state_at(motion.t_slide_end)
                ax.plot([end.xi], [end.eta], "o", color=colour, markersize=4, markeredgecolor="white",
                        markeredgewidth=0.6, zorder=MARKER_ZORDER, gid=f"end of sliding:{i}")
            if motion.rest is not None:
                ax.plot(*([c] for c in motion.rest), "X", color=colour, markersize=7, zorder=MARKER_ZORDER,
                        gid=f"rest point:{i}")
        _label_plane(ax)
        scales = _frame_path(ax)
        shots = f"{len(motions)} shot{'s' if len(motions) != 1 else ''}"
        ax.set_title(title if title is not None else f"{shots}: the centre's path{scales}\n(dot: end of sliding; cross: rest point)")
        ax.grid(True, linewidth=0.3)
        if len(motions) <= 10:
            ax.legend(loc="best")
        return fig


def render(fig, kind: str) -> bytes:
    """``fig`` as a png, pdf or svg file's bytes, with fixed metadata: the same figure, the same bytes."""
    import io

    buffer = io.BytesIO()
    with matplotlib.rc_context({**STYLE, "svg.hashsalt": "appell"}):
        fig.savefig(buffer, format=kind, dpi=DPI, metadata=METADATA[kind])
    return buffer.getvalue()


def save(fig, path, close: bool = True) -> Path:
    """Write ``fig`` in the format of ``path``'s suffix (png, pdf or svg; else a ValueError), as `render`, and close
    it (pyplot keeps every figure it made until then).  A file already at ``path`` is written over, as
    ``savefig`` does: the caller names it (`appell plot` refuses a name that exists)."""
    if not isinstance(fig, matplotlib.figure.Figure):  # else an AttributeError deep in render, naming no argument
        raise SceneError("fig", f"must be a matplotlib Figure (draw(motion) or draw_scenes(motions)), got {validation.describe(fig)}")
    path = Path(path)
    data = render(fig, suffix_format(path))
    path.write_bytes(data)
    if close:
        plt.close(fig)
    return path


def suffix_format(path) -> str:
    """The format a file name asks for: png, pdf or svg (a ValueError naming the suffix otherwise)."""
    kind = Path(path).suffix.lower().lstrip(".")
    if kind not in FORMATS:
        raise ValueError(f"{path}: unknown picture format {Path(path).suffix or '(no suffix)'!r}: give .png, .pdf or .svg")
    return kind
