"""Figure captions state what the drawing code draws, read from the same objects."""

import json
import math

import pytest

from numerics import classical_vs_appell
from numerics import trajectory_checks as tc
from paper import figures

KEY = "0123456789abcdef0123"  # a source key: the figure's times are said to be of it, or of an earlier one


@pytest.fixture
def drawn(monkeypatch):
    """The figures a test draws, as matplotlib objects (not saved)."""
    figures_drawn = []
    monkeypatch.setattr(figures, "_save", lambda fig, path: figures_drawn.append(fig))
    return figures_drawn


def test_captions_state_the_parameters_of_what_is_drawn():
    caption = figures.shots_caption()
    P = classical_vs_appell.POOL
    assert f"f = {P.f:g}" in caption and f"δ = {P.delta * 1e3:.4g} mm" in caption and "R = 28.575 mm" in caption
    assert "Solid (Appell)" in caption and "dashed (classical)" in caption and "no cushions" in caption  # every legend entry
    # The starts, listed in the text before the figure (in the caption, a 12 pt page's figure overflowed it): the shot
    # as struck beside its slip (a referee read "draw: V₀ = 7.29 m/s", the slip, as the shot's speed).
    starts = dict(figures.shots_starts())
    assert list(starts) == list(classical_vs_appell.SHOTS) and all(s.startswith("slip V₀ =") for s in starts.values())
    assert "slip V₀" not in caption and "listed in the text" in caption
    end = figures.end_of_sliding_caption()
    assert f"{tc.SLIDE_DIGITS} digits" in end and f"10^-{tc.END_DECADES}" in end and "listed in the text" in end
    listed = dict(figures.end_of_sliding_starts())
    # κ to 3 digits: the rounded k listed gives a reader 0.05263 for our 0.05262 (a referee)
    assert listed["δ = 0.3 fR"].endswith("κ = 0.273") and listed["pool ball"].endswith("κ = 0.0526")
    assert "R = 28.575 mm" in listed["pool ball"]
    assert [k for k in listed if k.startswith("shot")] == [f"shot {i + 1}" for i in range(len(tc.SHOTS))]
    assert all(listed[f"shot {i + 1}"].endswith("(both balls)") for i in range(len(tc.SHOTS)))
    (scene, listed_scene), = figures.phases_scene()
    assert scene == "sample scene" and "V₀ =" in listed_scene and "Ω₀ =" in listed_scene and "f = 0.2" in listed_scene
    assert "V₀ =" not in figures.phases_caption() and "listed in the text" in figures.phases_caption()
    for caption in (figures.shots_caption(), figures.phases_caption(), end):  # the longest was 912 characters
        assert len(caption) < 520, len(caption)


def test_a_figure_s_starts_are_listed_in_the_text_before_it():
    from paper import appendix

    for name, entries in (("shots", figures.shots_starts()), ("end_of_sliding", figures.end_of_sliding_starts()),
                          ("phases", figures.phases_scene())):
        text = appendix.figure(name)
        listed, drawn_at = text.index(r"\begin{appellnotation}"), text.index(r"\begin{figure}")
        assert listed < drawn_at and text.count(r"\item[") == len(entries)
        assert rf"Figure~\ref{{appell:fig:{name}}}" in text[:listed]


def test_a_start_gives_the_directions_that_rebuild_it():
    """A referee could not rebuild the massé start from "slip 3.93 m/s, spin 130 rad/s across": the directions α₀ and
    β₀ (n°2: u = V cos α, p = Ω cos β) go with the magnitudes, and a start at rest in spin has none."""
    P = classical_vs_appell.POOL
    masse = next(state for name, state in classical_vs_appell.SHOTS.items() if name.startswith("massé"))
    text = figures.start_text(P, masse)
    assert text == "slip V₀ = 3.93 m/s at α₀ = −60.6°, spin Ω₀ = 130 rad/s at β₀ = −157°, r₀ = 20 rad/s"
    # the figures rebuild (p, q) = Ω₀(cos β₀, sin β₀) and the slip (ξ' − qR, η' + pR) = V₀(cos α₀, sin α₀) to 3 digits
    Omega, beta, V, alpha = 130, math.radians(-157), 3.93, math.radians(-60.6)
    assert math.isclose(Omega * math.cos(beta), masse.p, rel_tol=5e-3) and math.isclose(Omega * math.sin(beta), masse.q, rel_tol=2e-2)
    assert math.isclose(masse.vxi - masse.q * P.R, V * math.cos(alpha), rel_tol=5e-3)
    assert figures.start_text(P, classical_vs_appell.SHOTS["straight (centre ball, 1.5 m/s)"]).endswith("spin Ω₀ = 0 rad/s, r₀ = 0 rad/s")


def test_every_benchmark_method_is_explained_in_the_text_beside_a_short_caption():
    bench = json.loads((figures.DATA / "bench.json").read_text())
    caption = figures.work_precision_caption(bench, KEY)
    methods = dict(figures.work_precision_methods(bench))
    drawn = [row for row in bench["rows"] if row["method"] not in figures.PER_STATE]
    assert drawn and {row["method"] for row in drawn} == set(methods) and all(methods.values())
    assert "described in the text" in caption and len(caption) < 900  # fifteen lines overfilled a two-column page
    # The batch's timed scenes read off its row (50,000 copies of the curved ones; its errors over every scene).
    assert "timed on 50,000 scenes cycling through the 33 curved ones, scored on every scene" in methods["batch"]
    # A row timed per state is not drawn, and the text says so with its figures, in one sentence.
    per_state = figures.per_state_text(bench)
    assert per_state.count("Not drawn, as they are timed per state: ") == 1
    for row in bench["rows"]:
        if row["method"] in figures.PER_STATE:
            assert f"{figures.PER_STATE[row['method']]}, {row['seconds_per_scene'] * 1e6:.2g} microseconds" in per_state
            assert figures._power_of_ten(row['max_rel_error']) in per_state
    # The scenes each method is scored on, read off the rows (the caption said 43 for mpmath's 3), and the errors
    # a log axis cannot show said to be drawn at the floor.
    for n in {row["scenes"] for row in bench["rows"] if row["method"] not in figures.PER_STATE} - {bench["machine"]["scenes"]}:
        assert f" on {n} of them (" in caption
    assert "mpmath on 3 of them" in caption and "mpmath: exact" in caption
    fewer = {**bench, "rows": [{**row, "scenes": 7} if row["method"] == "classical model" else row for row in bench["rows"]]}
    assert "classical model on 7 of them" in figures.work_precision_caption(fewer, KEY)
    bench["rows"].append({**bench["rows"][0], "method": "a new solver"})
    try:
        figures.work_precision_caption(bench, KEY)
    except KeyError as error:
        assert "a new solver" in str(error)
    else:
        raise AssertionError("a method without a description passed")


def test_the_caption_says_which_source_the_times_were_measured_from():
    """A timing measured on another source than the appendix's is said to be so (a trust audit: bench.json kept
    times measured nineteen commits before, shown as this source's)."""
    bench = json.loads((figures.DATA / "bench.json").read_text())
    machine = bench["machine"]
    here = {**machine, "cpu": "AMD EPYC", "source": KEY}  # the saved run's processor is whichever host ran it
    assert "(AMD EPYC) from this source," in figures.work_precision_caption({**bench, "machine": here}, KEY)
    earlier = figures.work_precision_caption({**bench, "machine": {**machine, "source": "f" * 20}}, KEY)
    assert "from an earlier source than this appendix's," in earlier and "this source" not in earlier
    unrecorded = {key: value for key, value in machine.items() if key != "source"}
    assert "from a source not recorded," in figures.work_precision_caption({**bench, "machine": unrecorded}, KEY)


def test_the_readme_picture_is_what_appell_plot_draws(tmp_path, capsys):
    """paper/figures/sample_motion.png (written by `appell paper`, shown in the README) is, byte for byte, what
    `appell plot numerics/scenes/sample.json` draws: the same Motion.plot, whatever rcParams paper.figures set."""
    from pathlib import Path

    from paper.cli import main

    committed = figures.FIGURES / "sample_motion.png"
    assert f"]({committed.relative_to(figures.FIGURES.parent.parent)})" in (Path(figures.FIGURES.parent.parent) / "README.md").read_text()
    assert main(["plot", str(figures.SAMPLE), "-o", str(tmp_path / "sample.png")]) == 0
    assert (tmp_path / "sample.png").read_bytes() == committed.read_bytes()


@pytest.mark.slow  # the figure's 20-digit slides
def test_the_end_of_sliding_lines_stay_in_the_data_and_the_legend_below_the_axes(drawn):
    """A fitted line drawn to a δ = 0.3fR slide's first point rose off the plot, and the legend covered a pool ball's
    line (a referee)."""
    figures.end_of_sliding()
    (ax,) = drawn[0].axes
    points = [line for line in ax.lines if line.get_linestyle() == "None"]
    fits = [line for line in ax.lines if line.get_linestyle() == "-"]
    assert len(points) == len(fits) == 6
    for dots, fit in zip(points, fits, strict=True):
        assert max(fit.get_ydata()) <= max(dots.get_ydata()) + 1e-9
    drawn[0].canvas.draw()
    legend = ax.get_legend().get_window_extent()
    assert legend.y1 < ax.get_window_extent().y0  # under the axes, clear of every line


def test_the_phases_figure_starts_at_t_0(drawn):
    figures.phases_in_time()
    axes = drawn[0].axes
    assert all(ax.get_xlim()[0] == 0.0 for ax in axes)  # symlog's margin drew an empty band before t = 0
    # Each phase's end marked, the pivot's too (the sample pivots past its slide), and θ = π/2 clear of the frame.
    from numerics.hard_cases import hard_cases
    from numerics.simulate import simulate

    m = simulate(hard_cases()["sample"])
    ends = {m.t_slide_end, m.t_roll_end, m.t_pivot_end}
    for ax in axes:
        assert {line.get_xdata()[0] for line in ax.lines if line.get_linestyle() in (":", "-.")} == ends
    assert axes[2].get_ylim()[1] > math.pi / 2 + 0.1
    assert "dash-dot: the end of pivoting" in figures.phases_caption() and "κ = 0.053" in figures.phases_caption()


def test_a_curved_shot_is_drawn_to_scale_and_no_label_is_smaller_than_6_5_pt(drawn):
    """The massé's 13 cm forward were stretched to look as long as its 5 m sideways, and tick labels of 5.5 pt came
    out near 5 pt in a column of two (a referee)."""
    figures.shots()
    figures.work_precision(json.loads((figures.DATA / "bench.json").read_text()))
    shots, work = drawn
    panels = {ax.get_title(): ax for ax in shots.axes if ax.get_title()}
    assert panels["massé"].get_aspect() == 1.0 and panels["straight"].get_aspect() == "auto"
    assert "curved paths to scale" in figures.shots_caption()
    for fig in drawn:
        fig.canvas.draw()
        for ax in fig.axes:
            texts = ax.get_xticklabels() + ax.get_yticklabels() + ([*ax.get_legend().get_texts()] if ax.get_legend() else [])
            assert all(t.get_fontsize() >= 6.5 for t in texts if t.get_text()), ax.get_title()


def test_a_figure_replaces_a_link_at_its_path_and_never_writes_through_it(tmp_path):
    """`appell bench` wrote paper/figures/work_precision.pdf through a link into the link's target (an audit)."""
    import matplotlib.pyplot as plt

    target = tmp_path / "users.pdf"
    target.write_text("the user's own file")
    (tmp_path / "work_precision.pdf").symlink_to(target)
    fig, _ = plt.subplots()
    path = figures._save(fig, tmp_path / "work_precision.pdf")
    assert target.read_text() == "the user's own file"
    assert not path.is_symlink() and path.read_bytes().startswith(b"%PDF")


def test_the_text_names_the_versions_the_run_timed_or_says_it_did_not_record_them():
    bench = json.loads((figures.DATA / "bench.json").read_text())
    machine = {key: value for key, value in bench["machine"].items() if key != "versions"}
    recorded = {**bench, "machine": {**machine, "versions": {"numba": "0.68.1", "heyoka": "7.13.2"}}}
    assert figures.versions_sentence(recorded) == "Timed with numba 0.68.1, heyoka 7.13.2."
    assert "did not record the versions" in figures.versions_sentence({**bench, "machine": machine})


def test_the_work_precision_legend_is_inside_the_figure(monkeypatch, tmp_path):
    """Its third column ran past the right edge ('classical mode'): every legend entry is drawn inside the page."""
    bench = json.loads((figures.DATA / "bench.json").read_text())
    drawn = []
    save = figures._save

    def keep(fig, path):
        fig.tight_layout()
        fig.canvas.draw()
        legend = fig.axes[0].get_legend()
        drawn.append((legend.get_window_extent(), fig.bbox))
        return save(fig, path)

    monkeypatch.setattr(figures, "_save", keep)
    figures.work_precision(bench, tmp_path / "wp.pdf")
    (legend, page), = drawn
    assert page.x0 <= legend.x0 and legend.x1 <= page.x1 and page.y0 <= legend.y0, (legend, page)
