"""The simulator's pictures (`numerics.plot`, `Motion.plot`): what is drawn is the motion, read back from the artists."""

import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib import pyplot as plt  # noqa: E402

from numerics import hard_cases, plot  # noqa: E402
from numerics.scene import load  # noqa: E402
from numerics.simulate import simulate  # noqa: E402
from numerics.validation import SceneError  # noqa: E402

CASES = hard_cases.hard_cases()


@pytest.fixture(scope="module")
def sample():
    return simulate(load("numerics/scenes/sample.json"), jit=False)


@pytest.fixture(scope="module")
def figure(sample):
    fig = sample.plot()
    yield fig
    plt.close(fig)


def _by_gid(fig, gid):
    found = [line for ax in fig.axes for line in ax.lines if line.get_gid() == gid]
    assert len(found) == 1, (gid, len(found))
    return found[0]


def _axes(fig, label):
    (ax,) = [ax for ax in fig.axes if ax.get_label() == label]
    return ax


def test_the_path_has_a_line_per_phase_and_the_marks(sample, figure):
    slide, roll = _by_gid(figure, "path:sliding"), _by_gid(figure, "path:rolling")
    assert slide.axes is roll.axes is _axes(figure, "path")
    assert slide.get_color() != roll.get_color()
    end = sample.state_at(sample.t_slide_end)
    # The slide's line ends where the rolling line begins: at the end of sliding, which is marked there.
    assert (slide.get_xdata()[-1], slide.get_ydata()[-1]) == pytest.approx((end.xi, end.eta), abs=1e-12)
    assert (roll.get_xdata()[0], roll.get_ydata()[0]) == pytest.approx((end.xi, end.eta), abs=1e-12)
    marked = _by_gid(figure, "end of sliding")
    assert (marked.get_xdata()[0], marked.get_ydata()[0]) == pytest.approx((end.xi, end.eta))
    rest = _by_gid(figure, "rest point")
    assert (rest.get_xdata()[0], rest.get_ydata()[0]) == sample.rest
    assert (roll.get_xdata()[-1], roll.get_ydata()[-1]) == pytest.approx(sample.rest, rel=1e-12, abs=0)
    labels = _axes(figure, "path").get_legend_handles_labels()[1]
    assert any(label.startswith("sliding") for label in labels) and "end of sliding" in labels
    assert any(label.startswith("rest point") for label in labels)


def test_the_slide_is_sampled_densest_where_it_ends(sample, figure):
    t = plot.times(sample)
    t1 = sample.t_slide_end
    last_tenth, first_tenth = np.sum((t > 0.9 * t1) & (t <= t1)), np.sum(t < 0.1 * t1)
    assert last_tenth > 3 * first_tenth and len(_by_gid(figure, "path:sliding").get_xdata()) > 300
    assert t1 in t and sample.t_roll_end in t and sample.t_pivot_end in t


def test_the_time_panels_show_V_Omega_r_until_rest(sample, figure):
    V, Omega, r = (_by_gid(figure, f"curve:{name}") for name in ("V", "Omega", "r"))
    t = V.get_xdata()
    assert t[0] == 0 and t[-1] >= sample.t_roll_end and np.array_equal(t, Omega.get_xdata())
    states = sample.states(t)
    assert Omega.get_ydata() == pytest.approx(np.hypot(states.p, states.q), rel=1e-14, abs=0)
    assert r.get_ydata() == pytest.approx(states.r, abs=1e-14)
    s0 = sample.scene.state
    R = sample.scene.params.R
    assert V.get_ydata()[0] == pytest.approx(np.hypot(s0.vxi - s0.q * R, s0.veta + s0.p * R))
    # The slip ends at the end of sliding (n°8), and stays 0 while the ball rolls (n°7).
    at_end = V.get_ydata()[np.flatnonzero(t == sample.t_slide_end)[0]]
    assert at_end < 1e-8 * V.get_ydata()[0]
    assert np.all(V.get_ydata()[t > sample.t_slide_end] < 1e-8)
    assert r.get_ydata()[t >= sample.t_pivot_end] == pytest.approx(0, abs=1e-12)  # eq. (5): the pivot stops
    for name in ("V", "Omega", "r"):
        ax = _axes(figure, name)
        assert "rad/s" in ax.get_ylabel() or "m/s" in ax.get_ylabel()
        marks = {line.get_gid(): line.get_xdata()[0] for line in ax.lines if (line.get_gid() or "").startswith("mark:")}
        assert marks == {"mark:end of sliding": sample.t_slide_end, "mark:rest (end of rolling)": sample.t_roll_end,
                         "mark:end of pivoting (eq. (5))": sample.t_pivot_end}
    assert _axes(figure, "r").get_xlabel().startswith("t (s)")
    assert _axes(figure, "path").get_xlabel() == "ξ (m)" and _axes(figure, "path").get_ylabel() == "η (m)"
    assert "δ = 0.4 mm" in figure._suptitle.get_text()


def test_an_axes_given_gets_the_path_only(sample):
    fig, ax = plt.subplots()
    try:
        assert sample.plot(ax) is fig
        assert fig.axes == [ax]
        assert {line.get_gid() for line in ax.lines} == {"path:sliding", "path:rolling", "start", "end of sliding", "rest point"}
    finally:
        plt.close(fig)


@pytest.mark.parametrize("name", ["at rest", "pure rolling start", "rolls for ever (delta = 0)", "pivoting for ever (epsilon = 0)"])
def test_motions_without_some_phase_draw_what_they_have(name):
    m = simulate(CASES[name], jit=False)
    fig = m.plot()
    try:
        gids = {line.get_gid() for ax in fig.axes for line in ax.lines}
        assert ("path:sliding" in gids) == (m.t_slide_end > 0)
        assert ("rest point" in gids) == (m.rest is not None)
        t = _by_gid(fig, "curve:V").get_xdata()
        assert t[-1] >= (m.t_roll_end if m.t_roll_end is not None else 2 * m.t_slide_end + 1)
        assert np.all(np.isfinite(_by_gid(fig, "curve:Omega").get_ydata()))
    finally:
        plt.close(fig)


def test_many_scenes_give_one_path_and_one_rest_point_each():
    names = ["sample", "centre hit", "straight draw", "rolls for ever (delta = 0)"]
    motions = [simulate(CASES[n], jit=False) for n in names]
    fig = plot.draw_scenes(motions, labels=names)
    try:
        (ax,) = fig.axes
        paths = [line for line in ax.lines if line.get_gid().startswith("path:")]
        assert len(paths) == len(names)
        rests = [line for line in ax.lines if line.get_gid().startswith("rest point:")]
        assert len(rests) == 3  # δ = 0 never rests
        for line, m in zip(paths, motions):
            if m.rest is not None:
                assert (line.get_xdata()[-1], line.get_ydata()[-1]) == pytest.approx(m.rest, rel=1e-12, abs=0)
        assert ax.get_legend_handles_labels()[1] == names
        # every dot and cross above every path (a later path from a shared start hid a short slide's dot: an audit)
        marks = [line for line in ax.lines if not line.get_gid().startswith("path:")]
        assert len(marks) == len(rests) + sum(m.t_slide_end > 0 for m in motions)
        assert min(line.get_zorder() for line in marks) > max(line.get_zorder() for line in paths)
    finally:
        plt.close(fig)
    with pytest.raises(SceneError, match="^motions: must be 1 to 100 Motions in one picture, got 101$"):
        plot.draw_scenes([motions[0]] * (plot.MAX_SCENES + 1))


@pytest.mark.parametrize("call, message", [
    # zip would draw the first scene only, and say nothing
    (lambda m: plot.draw_scenes([m, m, m], labels=["only one"]), "labels: must be one for each of the 3 scenes"),
    (lambda m: plot.draw_scenes([m], labels="one"), "labels: must be one for each of the 1 scenes"),
    (lambda m: plot.draw_scenes([]), "motions: must be 1 to 100 Motions in one picture, got 0"),
    (lambda m: plot.draw_scenes(m), "motions: must be a list of Motions"),
    (lambda m: plot.draw_scenes([m, m.scene]), r"motions \[1\]: must be a Motion \(simulate\(scene\)\), got Scene"),
    (lambda m: plot.draw_scenes([m], ax=5), "ax: must be a matplotlib Axes or None, got 5"),
    (lambda m: plot.draw(m.scene), r"motion: must be a Motion \(simulate\(scene\)\)"),
    (lambda m: m.plot(ax="left"), "ax: must be a matplotlib Axes or None, got 'left'"),
])
def test_a_picture_of_what_is_not_a_motion_is_refused_naming_it(sample, call, message):
    figures = plt.get_fignums()
    with pytest.raises(SceneError, match=message):
        call(sample)
    assert plt.get_fignums() == figures  # refused before any figure is made


def test_save_closes_the_figure_it_writes(sample, tmp_path):
    fig = sample.plot()
    assert plt.fignum_exists(fig.number)
    plot.save(fig, tmp_path / "shot.png")
    assert not plt.fignum_exists(fig.number) and (tmp_path / "shot.png").read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("fig", ["fig", None, 3])
def test_save_names_a_figure_that_is_not_one(fig, tmp_path):
    """A user audit: save("fig", ...) raised AttributeError deep in render, naming no argument; nothing is written."""
    with pytest.raises(SceneError, match=r"^fig: must be a matplotlib Figure"):
        plot.save(fig, tmp_path / "shot.png")
    assert not (tmp_path / "shot.png").exists()


@pytest.mark.parametrize("kind, magic", [("png", b"\x89PNG\r\n\x1a\n"), ("pdf", b"%PDF-"), ("svg", b"<?xml")])
def test_the_same_figure_gives_the_same_bytes(sample, kind, magic):
    first, second = (plot.render(sample.plot(), kind) for _ in range(2))
    plt.close("all")
    assert first.startswith(magic) and first == second
    assert b"Matplotlib v" not in first  # no version string, no date


def test_a_suffix_names_the_format():
    assert plot.suffix_format("a/b.PNG") == "png"
    with pytest.raises(ValueError, match="'.gif'"):
        plot.suffix_format("b.gif")


def test_simulating_and_the_cli_parser_import_no_matplotlib():
    """The simulator and the command line start without matplotlib: only a picture loads it."""
    code = (
        "import sys\n"
        "from numerics.scene import load\n"
        "from numerics.simulate import simulate\n"
        "from paper.cli import main\n"
        "simulate(load('numerics/scenes/sample.json'), jit=False).state_at(0.1)\n"
        "main(['simulate', 'numerics/scenes/sample.json'])\n"
        "print([n for n in sys.modules if n.split('.')[0] == 'matplotlib'], file=sys.stderr)\n"
        "sys.exit(1 if 'matplotlib' in sys.modules else 0)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_the_callers_rcparams_do_not_change_the_picture(sample):
    """Ticks are made when the figure is drawn: under the style of `numerics.plot`, not the caller's settings."""
    plain = plot.render(sample.plot(), "png")
    with matplotlib.rc_context({"font.size": 5, "xtick.labelsize": 4, "ytick.labelsize": 14}):
        styled = plot.render(sample.plot(), "png")
    plt.close("all")
    assert plain == styled


@pytest.mark.parametrize("name", ["at rest", "spinning in place"])
def test_a_ball_that_never_moves_draws_without_a_warning(name, caplog):
    """Its path is a point in a square box: the box, not the limits, keeps it square (matplotlib logged "Ignoring
    fixed y limits ..." on stderr when asked to adjust limits it had been given)."""
    _draws_without_a_warning(simulate(CASES[name], jit=False), caplog)


def _draws_without_a_warning(motion, caplog):
    """Its picture, drawn, logs nothing and warns nothing (a warning is an error here)."""
    import io
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig = motion.plot()
        try:
            with caplog.at_level("WARNING"):
                fig.savefig(io.BytesIO(), format="png")
            assert caplog.records == []
        finally:
            plt.close(fig)


def test_a_ball_far_from_the_origin_draws_without_a_warning(caplog):
    """At ξ = 1e99 m its path is one float64 wide: limits a twentieth of its length wide came out equal, and
    matplotlib warned (singular limits) on stderr (an audit); it now keeps its own margin."""
    from numerics.scene import Params, Scene, State

    scene = Scene(Params(f=0.2, delta=4e-4, epsilon=3e-4, R=0.028575), State(1e99, 0.0, 2.0, 0.0, 10.0, -40.0, 5.0))
    _draws_without_a_warning(simulate(scene, jit=False), caplog)


def test_the_path_legend_covers_no_point_of_the_path():
    """A user audit: in the README's own example (a straight roll to the upper right) matplotlib's "best" put the
    legend over the rest point.  Its box now keeps clear of every point drawn, the markers included."""
    from numerics.scene import Params, Scene

    cloth = Params.from_pool(u_s=0.2, u_r=0.01, u_sp=0.0127, R=0.028575)
    shot = Scene.from_cue(cloth, V0=2.0, phi=30, theta=5, a=0.2, b=-0.3, M=0.567, m=0.170)  # the README's
    fig = simulate(shot, jit=False).plot()
    ax = fig.axes[0]
    fig.canvas.draw()
    margin = 8 / 72 * fig.dpi / 2  # half the widest marker (the rest point's X, 8 pt): its glyph, not only its centre
    box = ax.get_legend().get_window_extent().padded(margin)
    drawn = np.vstack([line.get_xydata() for line in ax.get_lines()])
    assert len(drawn) > 100 and not box.count_contains(ax.transData.transform(drawn))
    plt.close(fig)
