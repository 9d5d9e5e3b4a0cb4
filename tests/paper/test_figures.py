"""Figure captions state what the drawing code draws, read from the same objects."""

import json

from numerics import classical_vs_appell
from numerics import trajectory_checks as tc
from paper import figures


def test_captions_state_the_parameters_of_what_is_drawn():
    caption = figures.shots_caption()
    P = classical_vs_appell.POOL
    assert f"f = {P.f:g}" in caption and f"δ = {P.delta * 1e3:.4g} mm" in caption and "R = 28.575 mm" in caption
    assert "Solid (Appell)" in caption and "dashed (classical)" in caption  # every legend entry defined
    assert all(name.split(" (")[0] in caption for name in classical_vs_appell.SHOTS)
    end = figures.end_of_sliding_caption()
    assert f"{tc.SLIDE_DIGITS} digits" in end and f"10^-{tc.END_DECADES}" in end and "κ = 0.2727" in end
    assert "V₀ =" in figures.phases_caption() and "Ω₀ =" in figures.phases_caption()


def test_every_benchmark_method_is_explained_in_the_caption():
    bench = json.loads((figures.DATA / "bench.json").read_text())
    caption = figures.work_precision_caption(bench)
    drawn = [row for row in bench["rows"] if row["method"] not in figures.PER_STATE]
    assert drawn and all(f"{row['method']}:" in caption for row in drawn)
    # A row timed per state is not drawn, and the caption says so with its figures, in one sentence.
    assert caption.count("Not drawn: ") == 1
    for row in bench["rows"]:
        if row["method"] in figures.PER_STATE:
            assert f"{figures.PER_STATE[row['method']]}, {row['seconds_per_scene'] * 1e6:.2g} microseconds" in caption
            assert figures._power_of_ten(row['max_rel_error']) in caption
    bench["rows"].append({**bench["rows"][0], "method": "a new solver"})
    try:
        figures.work_precision_caption(bench)
    except KeyError as error:
        assert "a new solver" in str(error)
    else:
        raise AssertionError("a method without a description passed")


def test_the_readme_picture_is_what_appell_plot_draws(tmp_path, capsys):
    """paper/figures/sample_motion.png (written by `appell paper`, shown in the README) is, byte for byte, what
    `appell plot numerics/scenes/sample.json` draws: the same Motion.plot, whatever rcParams paper.figures set."""
    from pathlib import Path

    from paper.cli import main

    committed = figures.FIGURES / "sample_motion.png"
    assert f"]({committed.relative_to(figures.FIGURES.parent.parent)})" in (Path(figures.FIGURES.parent.parent) / "README.md").read_text()
    assert main(["plot", str(figures.SAMPLE), "-o", str(tmp_path / "sample.png")]) == 0
    assert (tmp_path / "sample.png").read_bytes() == committed.read_bytes()
