"""The command line explains itself: --version, a description and an example in every --help, progress on a
terminal only, and many-scene results as text (ends and rest points), CSV and NPZ."""

import csv
import io
import json
import math

import numpy as np
import pytest

from paper import cli, progress
from paper.cli import main

SCENE = {
    "params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575, "k": 0.018072, "g": 9.81},
    "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0},
}


def test_version(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    out = capsys.readouterr().out.strip()
    assert out.startswith("appell ") and out.split()[1][0].isdigit()


@pytest.mark.parametrize("module", ["paper", "paper.cli"])
def test_the_command_runs_as_a_module_both_ways(module):
    """`python -m paper.cli` ran the module and did nothing, with status 0 (an audit): it is the command too."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", module, "--version"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.startswith("appell "), done


@pytest.mark.parametrize("command", sorted(cli.COMMANDS))
def test_every_command_has_a_description_and_a_runnable_example(command, capsys):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = capsys.readouterr().out
    description, example = cli.COMMANDS[command]
    assert description[1:] in text and f"example:\n  {example}" in text
    # The example parses: the command it names and flags it uses exist (argparse would exit 2 otherwise).
    words = example.split(">")[0].split()
    assert words[:2] == ["appell", command]
    assert cli.build_parser().parse_args(words[1:]).command == command


def test_every_subcommand_is_described():
    parser = cli.build_parser()
    subparsers = next(a for a in parser._actions if a.dest == "command")
    assert set(subparsers.choices) == set(cli.COMMANDS)


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_only_on_a_terminal_and_not_quiet():
    for stream, quiet, shown in ((_Terminal(), False, True), (_Terminal(), True, False), (io.StringIO(), False, False)):
        bar, notes = progress.Progress(3, "cases", quiet, stream), progress.Notes(quiet, stream)
        bar.update(2)
        notes("figures")
        bar.close()
        text = stream.getvalue()
        assert ("2/3 cases" in text and "figures" in text) == shown and (text == "") == (not shown)


def test_accuracy_shows_progress_on_a_terminal_and_keeps_stdout_clean(monkeypatch, capsys):
    from numerics import hard_cases

    cases = hard_cases.hard_cases()
    monkeypatch.setattr(hard_cases, "hard_cases", lambda: {k: cases[k] for k in ("centre hit", "at rest")})
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["accuracy", "--json"]) == 0
    assert "2/2 hard cases" in terminal.getvalue()
    json.loads(capsys.readouterr().out)  # stdout holds the result only
    quiet = _Terminal()
    monkeypatch.setattr("sys.stderr", quiet)
    assert main(["accuracy", "--json", "--quiet"]) == 0
    assert quiet.getvalue() == ""


def _many(tmp_path, n=12):
    rng = np.random.default_rng(7)
    scenes = []
    for i in range(n):
        state = {**SCENE["state"], "vxi": float(rng.uniform(0.5, 3)), "q": float(rng.uniform(-100, 100))}
        scenes.append({"params": dict(SCENE["params"]), "state": state})
    scenes[3]["params"]["delta"] = 0.0  # rolls for ever: no rest point
    path = tmp_path / "many.json"
    path.write_text(json.dumps(scenes))
    return str(path)


def test_many_scenes_text_lists_ends_and_rest_points(tmp_path, capsys):
    path = _many(tmp_path)
    assert main(["simulate", path, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert main(["simulate", path]) == 0
    text = capsys.readouterr().out
    lines = text.splitlines()
    first = next(line for line in lines if line.strip().startswith("0 "))
    assert f"{rows[0]['t_slide_end']:.9g}" in first and f"{rows[0]['rest']['xi']:.9g}" in first
    never = next(line for line in lines if line.strip().startswith("3 "))
    assert "never" in never and never.split()[1:6] == [never.split()[1], "never", "-", "-", "-"]  # est. error: none, not nan
    assert f"({len(rows) - 10} more" in text
    slides = [r["t_slide_end"] for r in rows]
    assert f"sliding ends between {min(slides):.6g} s and {max(slides):.6g} s" in text
    assert "1 roll for ever" in text


def test_many_scenes_csv_and_npz_hold_every_scene(tmp_path, capsys):
    path = _many(tmp_path)
    assert main(["simulate", path, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    out_csv, out_npz = tmp_path / "out.csv", tmp_path / "out.npz"
    assert main(["simulate", path, "--csv", str(out_csv), "--npz", str(out_npz)]) == 0
    table = list(csv.DictReader(out_csv.open()))
    arrays = np.load(out_npz)
    assert len(table) == len(rows) == len(arrays["scene"])
    for i, row in enumerate(rows):
        assert float(table[i]["t_slide_end"]) == row["t_slide_end"] == arrays["t_slide_end"][i]  # every digit
        if row["rest"] is None:  # no rest point, no estimate of its error (a 0.0 read as exact: a user audit)
            assert table[i]["rest_xi"] == "" and np.isnan(arrays["rest_xi"][i])
            assert table[i]["t_roll_end"] == "inf" and np.isinf(arrays["t_roll_end"][i])
            assert row["error_estimate"] is None and table[i]["error_estimate"] == "" and np.isnan(arrays["error_estimate"][i])
            continue
        else:
            assert float(table[i]["rest_xi"]) == row["rest"]["xi"] == arrays["rest_xi"][i]
            assert float(table[i]["rest_eta"]) == row["rest"]["eta"] == arrays["rest_eta"][i]
            assert float(table[i]["t_roll_end"]) == row["t_roll_end"] == arrays["t_roll_end"][i]
        pivot = math.inf if row["t_pivot_end"] is None else row["t_pivot_end"]
        assert float(table[i]["t_pivot_end"]) == pivot == arrays["t_pivot_end"][i]
        assert float(table[i]["error_estimate"]) == row["error_estimate"] == arrays["error_estimate"][i]
        assert table[i]["sliding_model"] == arrays["sliding_model"][i] == row["phases"][0]["model"]


def test_one_scene_writes_a_one_row_table(tmp_path, capsys):
    scene = tmp_path / "one.json"
    scene.write_text(json.dumps(SCENE))
    assert main(["simulate", str(scene), "--csv", str(tmp_path / "one.csv")]) == 0
    (row,) = list(csv.DictReader((tmp_path / "one.csv").open()))
    assert row["ok"] == "1" and float(row["rest_xi"]) == pytest.approx(6.8825833, rel=1e-7, abs=0)


def test_tables_never_overwrite_and_are_refused_before_work(tmp_path, capsys, monkeypatch):
    path = _many(tmp_path)
    existing = tmp_path / "mine.csv"
    existing.write_text("my data\n")
    from numerics import batch

    monkeypatch.setattr(batch, "simulate_many", lambda *a, **k: pytest.fail("work before refusing the output"))
    for args in (["--csv", str(existing)], ["--npz", str(existing)], ["--csv", str(tmp_path / "no" / "x.csv")],
                 ["--csv", str(tmp_path / "a.csv"), "--npz", str(tmp_path / "a.csv")]):
        assert main(["simulate", path, *args]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and err.startswith("appell: error: --")
    assert existing.read_text() == "my data\n"


def test_paper_refuses_bad_flags_before_any_work(monkeypatch, capsys, tmp_path):
    from paper import verification

    monkeypatch.setattr(verification, "recorded", lambda *a, **k: pytest.fail("claims checked before refusing"))
    assert main(["paper", "--check", "--pdf"]) == 2
    assert "--check --pdf: give --out DIR" in capsys.readouterr().err
    monkeypatch.setattr("shutil.which", lambda name: None)  # no pdflatex
    assert main(["paper", "--pdf", "--out", str(tmp_path / "new")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "pdflatex not found" in err


def test_csv_states_by_header_name_in_any_order(tmp_path, capsys):
    params = tmp_path / "params.json"
    params.write_text(json.dumps(SCENE["params"]))
    rows = [[0, 0, 2.0, 0.0, 10.0, -40.0, 5.0], [0.5, -0.2, 1.0, 0.5, 0.0, 30.0, -3.0]]
    names = ["xi", "eta", "vxi", "veta", "p", "q", "r"]
    order = [6, 2, 0, 5, 3, 1, 4]  # r, vxi, xi, q, veta, eta, p
    (tmp_path / "ordered.csv").write_text(",".join(names) + "\n" + "\n".join(",".join(map(str, r)) for r in rows) + "\n")
    (tmp_path / "shuffled.csv").write_text(",".join(names[j] for j in order) + "\n"
                                           + "\n".join(",".join(str(r[j]) for j in order) for r in rows) + "\n")
    results = []
    for name in ("ordered.csv", "shuffled.csv"):
        assert main(["simulate", str(tmp_path / name), "--params", str(params), "--json"]) == 0
        results.append(json.loads(capsys.readouterr().out))
    assert results[0] == results[1] and results[0][1]["rest"]["xi"] != results[0][0]["rest"]["xi"]


def test_many_scenes_and_bench_show_progress_on_a_terminal_only(tmp_path, monkeypatch, capsys):
    from numerics import bench
    from paper import scene_report

    monkeypatch.setattr(scene_report, "PROGRESS_FROM", 1)  # the bar shows from 10,000 scenes; here from one
    path = _many(tmp_path, n=5)
    for quiet, shown in (([], True), (["--quiet"], False)):
        terminal = _Terminal()
        monkeypatch.setattr("sys.stderr", terminal)
        assert main(["simulate", path, *quiet]) == 0
        assert ("5/5 scenes" in terminal.getvalue()) == shown
        assert "5/5" not in capsys.readouterr().out  # never on stdout

    for quiet, shown in (([], True), (["--quiet"], False)):  # writing the JSON of many scenes took 12 s unannounced
        terminal = _Terminal()
        monkeypatch.setattr("sys.stderr", terminal)
        monkeypatch.setattr(scene_report, "PROGRESS_EVERY", 2)
        assert main(["simulate", path, "--json", *quiet]) == 0
        assert ("4/5 scenes written as JSON" in terminal.getvalue()) == shown
        out = capsys.readouterr().out
        assert "scenes written" not in out and len(json.loads(out)) == 5
        assert out.splitlines()[1:-1] == [json.dumps(row, ensure_ascii=False) + "," * (k < 4)  # one scene a line
                                           for k, row in enumerate(json.loads(out))]

    report = bench.Report(rows=[bench.Row("batch", "tol 1e-09", 2e-5, 5e-10, 5e-10, 1e-11, 1e-11, 30)],
                          scaling=[(10, 1e-3)], machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": True})

    def run(quick, progress):
        progress("scipy solve_ivp DOP853")
        return report

    monkeypatch.setattr(bench, "run", run)
    for quiet, shown in (([], True), (["--quiet"], False)):
        terminal = _Terminal()
        monkeypatch.setattr("sys.stderr", terminal)
        assert main(["bench", "--quick", *quiet]) == 0
        assert ("scipy solve_ivp DOP853" in terminal.getvalue()) == shown
    piped = io.StringIO()
    monkeypatch.setattr("sys.stderr", piped)
    assert main(["bench", "--quick"]) == 0 and piped.getvalue() == ""


def test_a_list_in_text_computes_no_states_and_its_states_are_bounded_together(tmp_path, capsys, monkeypatch):
    """The text and the tables are read from the engine's rows: the states at each scene's t are only computed for
    --json (a list of 60 scenes × 10⁵ times took 2.2 GB and minutes, to print none of them); and a list asks at
    most MAX_TIMES states in all, refused where it is read (checking 500 × 10⁵ times took 83 s, for text that
    prints none: two adversarial audits)."""
    from numerics import simulate

    path = tmp_path / "timed.json"
    path.write_text(json.dumps([{**SCENE, "t": [0.1, 0.2]}, SCENE]))

    def no_states(self, t):
        raise AssertionError("a state was computed")
    monkeypatch.setattr(simulate.Motion, "state_at", no_states)
    assert main(["simulate", str(path)]) == 0
    assert "2 scenes in" in capsys.readouterr().out
    many = tmp_path / "many.json"
    many.write_text(json.dumps([{**SCENE, "t": [0.5] * 60_000}] * 2))
    for argv in (["simulate", str(many), "--json"], ["simulate", str(many)]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith("appell: error: t: at most 100,000 times in a list of scenes") and err.count("\n") == 1


def test_model_flag_applies_to_every_scene_of_a_list(tmp_path, capsys):
    path = tmp_path / "two.json"
    path.write_text(json.dumps([SCENE, SCENE]))
    assert main(["simulate", str(path), "--json", "--model", "classical"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [row["model"] for row in rows] == ["classical", "classical"]
    assert all(row["phases"][0]["model"] == "closed form n°3 (no rolling couple)" for row in rows)


def test_skip_bad_keeps_each_row_in_its_place_when_the_first_is_bad(tmp_path, capsys):
    """A .csv whose first row is bad: its error first, then the good rows, each its own scene (a mutation that
    indexed the good rows 0, 1, … shifted them and lost the error)."""
    params = tmp_path / "p.json"
    params.write_text(json.dumps(SCENE["params"]))
    rows = [[0, 0, "nan", 0, 0, 0, 0], list(SCENE["state"].values()), [0, 0, 1, 0, 0, 0, 0]]
    states = tmp_path / "s.csv"
    states.write_text("xi,eta,vxi,veta,p,q,r\n" + "\n".join(",".join(map(str, r)) for r in rows) + "\n")
    assert main(["simulate", str(states), "--params", str(params), "--skip-bad", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert len(out) == 3 and out[0]["error"].startswith("scene [0].state.vxi")
    alone = []
    for row in rows[1:]:
        scene = tmp_path / "one.json"
        scene.write_text(json.dumps({"params": SCENE["params"], "state": dict(zip(SCENE["state"], row))}))
        assert main(["simulate", str(scene), "--json"]) == 0
        alone.append(json.loads(capsys.readouterr().out)["rest"])
    assert out[1]["rest"] == pytest.approx(alone[0], rel=1e-9, abs=0)
    assert out[2]["rest"] == pytest.approx(alone[1], rel=1e-9, abs=1e-12)  # η at rest ~1e-20: a straight shot


def test_reading_a_long_list_of_scenes_shows_its_count_on_a_terminal(monkeypatch, tmp_path, capsys):
    """100,000 scenes of a JSON list took 10 s to check before any output, silent (a user audit): the count of
    scenes read shows on a terminal, every `scene_files.READ_EVERY`, and stdout is the result alone."""
    from numerics import scene_files

    scene = {"params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575},
             "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0}}
    path = tmp_path / "many.json"
    path.write_text(json.dumps([scene] * 25))
    monkeypatch.setattr(scene_files, "READ_EVERY", 10)
    calls = []
    assert scene_files.read(path, progress=lambda done, total: calls.append((done, total))).total == 25
    assert calls == [(10, 25), (20, 25)]
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["simulate", str(path)]) == 0
    assert "20/25 scenes read" in terminal.getvalue() and "scenes read" not in capsys.readouterr().out


def test_output_names_that_cannot_be_what_they_ask_are_refused_before_any_work(tmp_path, capsys, monkeypatch):
    """A CLI audit: `--csv -` wrote a file named "-", `--csv x.npz` wrote CSV text into x.npz (unreadable as a
    .npz), `plot -o FOLDER` said "unknown picture format", and a missing scene file with --params blamed
    --params.  Each is one line naming the flag (or the file), exit 2, nothing written."""
    from pathlib import Path

    monkeypatch.chdir(tmp_path)
    sample = str(Path(__file__).resolve().parents[2] / "numerics" / "scenes" / "sample.json")
    (tmp_path / "folder").mkdir()
    cases = {
        ("simulate", sample, "--csv", "-"): "appell: error: --csv -: give a file name",
        ("simulate", sample, "--csv", ""): "appell: error: --csv: an empty file name",  # was "--csv .: names a folder"
        ("simulate", sample, "--csv", "x.npz"): "appell: error: --csv x.npz: give a name ending in .csv",
        ("simulate", sample, "--npz", "x.csv"): "appell: error: --npz x.csv: give a name ending in .npz",
        ("plot", sample, "-o", "folder"): "appell: error: -o folder: names a folder; give a file name",
        ("simulate", "missing.json", "--params", "params.json"): "appell: error: missing.json: cannot read",
    }
    for argv, said in cases.items():
        assert main(list(argv)) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith(said) and err.count("\n") == 1, (argv, err)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder"]
    assert main(["simulate", sample, "--csv", "t.CSV", "--npz", "t.NPZ"]) == 0  # the suffix in any case
    assert (tmp_path / "t.CSV").is_file() and (tmp_path / "t.NPZ").is_file()


def test_a_list_warns_once_of_a_tolerance_likely_missed(tmp_path, capsys):
    """A list with a scene whose estimate is far above tol (k = 0.002 R, 10⁸ m from the origin: float64's
    rounding): one warning line (the engine's warm-up call on the first scene does not warn again), and the summary
    does not call the estimate safe."""
    stiff = {"params": {"f": 0.2, "delta": 1e-12, "epsilon": 0.0003, "R": 0.028575, "k": 5.715e-5},
             "state": {"xi": 1e8, "eta": 0, "vxi": 0, "veta": 1e-6, "p": 0, "q": 50, "r": 0}}
    plain = {"params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575},
             "state": {"xi": 0, "eta": 0, "vxi": 1, "veta": 0, "p": 0, "q": 50, "r": 0}}
    path = tmp_path / "two.json"
    path.write_text(json.dumps([stiff, plain]))
    assert main(["simulate", str(path)]) == 0
    out, err = capsys.readouterr()
    assert err.count("appell: warning:") == 1 and "1 scene ([0]) above 1000× the tolerance asked" in err
    assert "largest estimated relative error of a rest point: 9.2e-06 (the tolerance may be missed" in out
    path.write_text(json.dumps([plain, plain]))
    assert main(["simulate", str(path)]) == 0
    out, err = capsys.readouterr()
    assert "warning" not in err and "(on the safe side: README, 'Error estimates')" in out
