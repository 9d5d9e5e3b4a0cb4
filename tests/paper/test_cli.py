"""The `appell` command: exit codes, JSON shape, and one clear line for bad input."""

import json
import subprocess
import sys

import pytest
import sympy as sp

from numerics.validation import SceneError
from paper.cli import main


@pytest.fixture(scope="module")
def verify_record():
    out = subprocess.run(
        [sys.executable, "-m", "paper", "verify", "--json"], capture_output=True, text=True, check=False
    )
    return out


@pytest.mark.slow  # every claim, through the command line
def test_verify_json_has_every_claim_and_exits_0(verify_record):
    assert verify_record.returncode == 0, verify_record.stderr
    record = json.loads(verify_record.stdout)
    assert record["summary"]["failed"] == 0
    ids = [row["id"] for row in record["claims"]]
    assert len(ids) == len(set(ids)) == record["summary"]["total"]
    assert record["summary"]["errata by class"] == {"mathematical": 1, "remark": 1, "ocr": 13}
    assert {row["class"] for row in record["claims"]} == {None, "mathematical erratum", "remark", "transcription artefact"}
    for row in record["claims"]:
        assert {"id", "where", "status", "symbolic", "numeric", "class"} <= row.keys()
        assert row["status"] in {"confirmed", "erratum", "failed"}


def test_verify_table(capsys, monkeypatch, tmp_path):
    from derivation import n7_pure_rolling
    from paper import verification

    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))  # a record of these claims only: not the session's
    monkeypatch.setattr(verification, "all_claims", n7_pure_rolling.claims)
    assert main(["verify"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].split() == ["id", "where", "symbolic", "numeric", "status"]
    assert "eq10" in out and "2 printed differently (1 mathematical erratum, 0 remarks, 1 transcription artefact)" in out
    assert "0 failed" in out


def test_verify_exits_1_when_a_claim_fails(capsys, monkeypatch, tmp_path):
    import dataclasses

    import sympy as sp

    from derivation import n7_pure_rolling
    from paper import verification

    def broken():
        claims = n7_pure_rolling.claims()
        eq = claims[0]
        return [dataclasses.replace(eq, printed=[sp.Eq(e.lhs, e.rhs + 1) for e in eq.printed])]

    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    monkeypatch.setattr(verification, "all_claims", broken)
    assert main(["verify"]) == 1
    assert "1 failed" in capsys.readouterr().out


@pytest.mark.slow
def test_verify_named_claims_explains_each_and_keeps_no_record(capsys, monkeypatch):
    """A teacher checks one claim and reads it explained (the command took no ids: an argparse error)."""
    from paper import record

    monkeypatch.setattr(record, "save", lambda kept: pytest.fail("a partial run kept as the record"))
    assert main(["verify", "--quiet", "eq10", "eq1"]) == 0
    out = capsys.readouterr().out
    table, _, explained = out.partition("\neq10 — n°7, eq. (10): ")
    assert table.splitlines()[2].startswith("eq10 ") and table.splitlines()[3].startswith("eq1 ")  # the order asked
    assert "2 claims: 1 confirmed, 1 printed differently (1 mathematical erratum" in table
    assert "  corrected: f_{1} = " in explained and "  derived:   Eq(f_1, R*delta/(R**2 + k**2))" in explained
    assert "  verdict:   mathematical erratum — symbolic: exact" in explained and "\neq1 — n°2, eq. (1): " in explained
    assert main(["verify", "eq10", "eq99"]) == 2
    assert capsys.readouterr().err == ("appell: error: no claim eq99: the ids are those `appell verify` lists "
                                       "(eq10, n8.V_rate_bound, ...)\n")


@pytest.mark.slow  # it checks every claim first (make check keeps no record): a minute of the fast subset's two
def test_reduce_json_gives_parseable_invariants():
    out = subprocess.run(
        [sys.executable, "-m", "paper", "reduce", "--json"], capture_output=True, text=True, check=False
    )
    assert out.returncode == 0, out.stderr
    record = json.loads(out.stdout)
    a, b, c, theta = sp.symbols("a b c theta")
    names = {"a": a, "b": b, "c": c, "theta": theta}
    for key in ("s3", "s5", "J"):
        assert sp.sympify(record[key], locals=names).free_symbols == {a, b, c, theta}
    f = [sp.sympify(record["abel"][n], locals=names) for n in ("f3", "f2", "f1", "f0")]
    assert f[3] == 0
    from paper.reduction_report import STEPS

    assert [step["id"] for step in record["steps"]] == [step_id for step_id, _ in STEPS]  # every step, none dropped
    assert all(step["status"] == "confirmed" for step in record["steps"])


def test_errata_json(capsys, monkeypatch, tmp_path):
    from derivation import n7_pure_rolling
    from paper import verification

    # n°7's claims hold a mathematical erratum and a transcription artefact: enough for the shape.
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    monkeypatch.setattr(verification, "all_claims", n7_pure_rolling.claims)
    assert main(["errata", "--json"]) == 0
    errata = json.loads(capsys.readouterr().out)["errata"]
    by_id = {e["id"]: e for e in errata}
    assert set(by_id) == {"eq10", "n7.centre_acceleration"}
    assert by_id["eq10"]["kind"] == "mathematical" and by_id["eq10"]["class"] == "mathematical erratum"
    assert by_id["n7.centre_acceleration"]["class"] == "transcription artefact"
    assert "\\frac{R^2}{k^2}" in by_id["eq10"]["printed"]
    assert by_id["eq10"]["corrected"].startswith("f_{1} =")
    for e in errata:
        assert {"id", "where", "kind", "printed", "corrected", "reason"} <= e.keys()
        assert e["status"] == "erratum"


@pytest.mark.parametrize(
    "argv",
    [[], ["nonsense"], ["verify", "--bogus"], ["errata", "extra"]],
)
def test_bad_invocation_is_one_line_and_status_2(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("appell: error:")


def test_python_dash_m_reports_usage_errors_the_same_way():
    out = subprocess.run([sys.executable, "-m", "paper", "--nope"], capture_output=True, text=True)
    assert out.returncode == 2
    assert out.stderr.count("\n") == 1 and "Traceback" not in out.stderr


SCENE = {
    "params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575, "k": 0.018072, "g": 9.81},
    "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0},
    "t": [0.1, 0.5],
}


def _scene_file(tmp_path, data=SCENE, name="scene.json"):
    path = tmp_path / name
    path.write_text(data if isinstance(data, str) else json.dumps(data))
    return str(path)


def test_simulate_json_has_the_promised_keys(tmp_path, capsys):
    assert main(["simulate", _scene_file(tmp_path), "--json", "--at", "20"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert {"phases", "t_slide_end", "t_roll_end", "t_pivot_end", "rest", "states"} <= out.keys()
    assert [p["phase"] for p in out["phases"]] == ["sliding", "rolling", "rest", "pivoting"]
    for phase in out["phases"]:
        assert {"phase", "t_start", "t_end", "model"} <= phase.keys()
    assert [s["t"] for s in out["states"]] == [0.1, 0.5, 20]
    assert [s["phase"] for s in out["states"]] == ["sliding", "rolling", "rest"]
    for state in out["states"]:
        assert {"t", "phase", "xi", "eta", "vxi", "veta", "p", "q", "r"} <= state.keys()
    assert out["states"][2]["xi"] == out["rest"]["xi"]


def test_motion_as_dict_is_what_simulate_json_prints(tmp_path, capsys):
    """`Motion.as_dict()` says it is the record `--json` prints: with the scene's own times (it gave none)."""
    from numerics.scene import load
    from numerics.simulate import simulate

    path = _scene_file(tmp_path)
    assert main(["simulate", path, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    record = simulate(load(path), jit=False).as_dict()
    assert len(record["states"]) == 2 and json.loads(json.dumps(record)) == printed
    with pytest.raises(SceneError, match=r"^t: must be a list of times, got 0.5$"):
        simulate(load(path), jit=False).as_dict(0.5)


def test_simulate_summary_and_model_override(tmp_path, capsys):
    assert main(["simulate", _scene_file(tmp_path), "--model", "classical"]) == 0
    text = capsys.readouterr().out
    assert "model classical" in text and "closed form n°3" in text and "rest point" in text


def test_simulate_never_stops_rolling_when_delta_is_zero(tmp_path, capsys):
    data = json.loads(json.dumps(SCENE))
    data["params"]["delta"] = 0
    assert main(["simulate", _scene_file(tmp_path, data), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["t_roll_end"] is None and out["rest"] is None


@pytest.mark.parametrize(
    "content, extra, message",
    [
        ('{"params": ', [], "not valid JSON"),
        (json.dumps({**SCENE, "params": {**SCENE["params"], "R": 0}}), [], "params.R: must be > 0"),
        (json.dumps({**SCENE, "params": {**SCENE["params"], "delta": 0.01}}), [], "params.delta: must be < f R"),
        (json.dumps(SCENE).replace("2.0", "NaN"), [], "state.vxi: must be finite"),
        (json.dumps(SCENE), ["--tol", "1"], "--tol"),
        (json.dumps(SCENE), ["--at", "-1"], "--at"),
        (json.dumps(SCENE), ["--at", "nan"], "--at"),
        (json.dumps(SCENE), ["--model", "magic"], "invalid choice"),
    ],
)
def test_simulate_bad_input_is_one_line_and_status_2(tmp_path, capsys, content, extra, message):
    assert main(["simulate", _scene_file(tmp_path, content), *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err


def test_simulate_missing_file(tmp_path, capsys):
    assert main(["simulate", str(tmp_path / "none.json")]) == 2
    assert "cannot read" in capsys.readouterr().err


def test_accuracy_and_compare_commands(monkeypatch, capsys):
    from numerics import hard_cases

    cases = hard_cases.hard_cases()
    monkeypatch.setattr(hard_cases, "hard_cases", lambda: {k: cases[k] for k in ("centre hit", "at rest")})
    assert main(["accuracy", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["cases"]
    assert [r["case"] for r in rows] == ["centre hit", "at rest"]
    assert rows[0]["rest error"] < 1e-9 and "straight shot" in rows[0]["slide model"]
    assert main(["compare"]) == 0
    assert "massé" in capsys.readouterr().out


def test_accuracy_judges_by_the_tolerance_asked_and_the_estimates(monkeypatch, capsys):
    """A user audit: `appell accuracy --tol 1e-5` exited 1 on errors of 1.8e-7, judged against a fixed 1e-9.  The
    verdict is the tolerance asked, and every estimate above its error."""
    from numerics import hard_cases

    def rows(error, estimate):
        return lambda tol, progress=None: [{"case": "c", "slide model": "numerical", "rest error": error,
                                             "t_slide_end error": 0.0, "t_roll_end error": 0.0, "estimate": estimate,
                                             "missing": None}]

    monkeypatch.setattr(hard_cases, "accuracy", rows(1.8e-7, 2e-6))
    assert main(["accuracy", "--tol", "1e-5", "--quiet"]) == 0
    assert "rest point or time (tolerance asked 1e-05); every estimate above its error" in capsys.readouterr().out
    assert main(["accuracy", "--tol", "1e-9", "--quiet"]) == 1
    monkeypatch.setattr(hard_cases, "accuracy", rows(1e-12, 1e-13))  # within tol, the estimate below the error
    assert main(["accuracy", "--quiet"]) == 1
    assert "an estimate below its error: c" in capsys.readouterr().out


def test_simulate_many_scenes_json_list_npz_and_csv(tmp_path, capsys):
    import numpy as np

    single = {k: v for k, v in SCENE.items() if k != "t"}
    scenes = [single, {**single, "state": {**single["state"], "p": 0.0, "q": 0.0}}, {**single, "model": "classical"}]
    scenes[1] = {**scenes[1], "t": [0.05, 3.0], "params": {**scenes[1]["params"], "f": 0.3}}  # its own params and times
    assert main(["simulate", _scene_file(tmp_path, scenes, "many.json"), "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["phases"][0]["model"].split(":")[0] for r in rows] == [
        "numerical", "closed form straight shot, θ = π/2", "closed form n°3 (no rolling couple)"]
    assert [r["model"] for r in rows] == ["appell", "appell", "classical"]
    for row in rows:  # the keys of a single scene's record
        assert {"phases", "t_slide_end", "t_roll_end", "t_pivot_end", "rest", "error_estimate", "states"} <= row.keys()
    single = scenes[1]
    assert main(["simulate", _scene_file(tmp_path, single, "one.json"), "--json"]) == 0
    # The list runs compiled (fused multiply-adds), the single scene interpreted: the same states to rounding.
    alone = json.loads(capsys.readouterr().out)["states"]
    assert len(rows[1]["states"]) == len(alone) == 2
    for a, b in zip(rows[1]["states"], alone):
        assert a.pop("phase") == b.pop("phase") and a == pytest.approx(b, rel=1e-12, abs=1e-15)
    params = _scene_file(tmp_path, SCENE["params"], "params.json")
    states = np.array([[0, 0, 2.0, 0.0, 10.0, -40.0, 5.0], [0, 0, 1.0, 0.5, 0.0, 0.0, 0.0]])
    np.savez(tmp_path / "s.npz", states=states)
    np.savetxt(tmp_path / "s.csv", states, delimiter=",", header="xi,eta,vxi,veta,p,q,r", comments="")
    for name in ("s.npz", "s.csv"):
        assert main(["simulate", str(tmp_path / name), "--params", params, "--json"]) == 0
        got = json.loads(capsys.readouterr().out)
        assert got[0]["rest"]["xi"] == pytest.approx(rows[0]["rest"]["xi"], rel=1e-9, abs=0)
    assert main(["simulate", str(tmp_path / "s.npz"), "--params", params]) == 0
    assert "2 scenes in" in capsys.readouterr().out


@pytest.mark.parametrize("n, workers, threads", [(2, [], "1 thread;"), (128, ["--workers", "2"], "2 threads;"),
                                                 (128, ["--workers", "1"], "1 thread;")])
def test_simulate_many_says_the_threads_it_ran_on(tmp_path, capsys, monkeypatch, n, workers, threads):
    """A list below SERIAL_BELOW scenes runs in the calling thread: the line said "2 threads" for it."""
    import numpy as np

    from numerics import batch

    monkeypatch.setattr(batch, "_threads", lambda w: 2 if w is None else w)  # as on a machine of two cores
    params = _scene_file(tmp_path, SCENE["params"], "params.json")
    np.savez(tmp_path / "s.npz", states=np.tile([0, 0, 2.0, 0.0, 10.0, -40.0, 5.0], (n, 1)))
    assert main(["simulate", str(tmp_path / "s.npz"), "--params", params, *workers]) == 0
    assert threads in capsys.readouterr().out.splitlines()[0]


@pytest.mark.parametrize(
    "files, extra, message",
    [
        ({"s.csv": "a,b\n1,2\n"}, ["--params", "P"], "the first line must name the columns"),
        ({"s.csv": "xi,eta,vxi,veta,p,q,r\n0,0,1,0,0,0,nan\n"}, ["--params", "P"], "scene [0].state.r: must be finite"),
        ({"s.csv": "xi,eta,vxi,veta,p,q,r\n0,0,1,0,0,0,0\n"}, [], "--params"),
        ({"many.json": json.dumps([{"params": SCENE["params"]}])}, [], "scene [0].state: missing"),
        ({"many.json": json.dumps([{k: v for k, v in SCENE.items() if k != "t"}])}, ["--at", "1"], "--at"),
        ({"many.json": "[]"}, [], "no scenes"),
    ],
)
def test_simulate_many_bad_input(tmp_path, capsys, files, extra, message):
    params = _scene_file(tmp_path, SCENE["params"], "params.json")
    for name, text in files.items():
        path = _scene_file(tmp_path, text, name)
    extra = [params if x == "P" else x for x in extra]
    assert main(["simulate", path, *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err


def test_bench_prints_the_table_and_json(monkeypatch, capsys):
    from numerics import bench

    report = bench.Report(
        rows=[bench.Row("batch", "tol 1e-09", 2e-5, 5e-10, 5e-10, 1e-11, 1e-11, 30)],
        scaling=[(10, 1e-3)], machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": True},
    )
    monkeypatch.setattr(bench, "run", lambda quick, progress: report)
    assert main(["bench", "--quick", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert {"method", "setting", "seconds_per_scene", "max_rel_error"} <= rows[0].keys()
    assert main(["bench", "--quick"]) == 0
    text = capsys.readouterr().out
    assert "| batch | tol 1e-09 |" in text and "Batch size against time per scene" in text


def test_simulate_samples_for_plotting(tmp_path, capsys):
    assert main(["simulate", _scene_file(tmp_path), "--json", "--samples", "20"]) == 0
    states = json.loads(capsys.readouterr().out)["states"]
    times = [s["t"] for s in states]
    assert len(states) == 2 + 21 and times[0] == 0.0 and {0.1, 0.5} <= set(times)
    assert times == sorted(times)  # the samples came after the scene's own t, unsorted (a user audit)
    assert main(["simulate", _scene_file(tmp_path), "--samples", "0"]) == 2


def test_simulate_many_reports_states_at_at_and_samples_with_json(tmp_path, capsys):
    """--at and --samples were refused for a list: with --json each scene reports its own t, --at's and its N + 1
    samples, in time order, the same states as the scene run alone; without --json they are refused (one object a
    scene holds them), and a list's own t, which only --json prints, is said, not dropped."""
    single = {k: v for k, v in SCENE.items() if k != "t"}
    scenes = [{**single, "t": [0.3]}, {**single, "state": {**single["state"], "p": 0.0, "q": 0.0}}]
    path = _scene_file(tmp_path, scenes, "many.json")
    assert main(["simulate", path, "--json", "--at", "2", "0.05", "--samples", "4"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [len(r["states"]) for r in rows] == [1 + 2 + 5, 2 + 5]
    for row in rows:
        times = [s["t"] for s in row["states"]]
        assert times == sorted(times) and {0.05, 2.0} <= set(times) and times[0] == 0.0
    assert main(["simulate", _scene_file(tmp_path, scenes[0], "one.json"), "--json", "--at", "2", "0.05", "--samples", "4"]) == 0
    alone = json.loads(capsys.readouterr().out)
    for a, b in zip(rows[0]["states"], alone["states"], strict=True):
        assert a.pop("phase") == b.pop("phase") and a == pytest.approx(b, rel=1e-12, abs=1e-15)
    assert main(["simulate", path, "--at", "2"]) == 2
    assert "--json only" in capsys.readouterr().err
    assert main(["simulate", path, "--json", "--samples", str(50_000)]) == 2  # 2 × 50,001 states: over MAX_TIMES
    assert "for each of 2 scenes" in capsys.readouterr().err
    assert main(["simulate", path]) == 0
    assert "the scenes' own times (1 in all): their states are printed with --json" in capsys.readouterr().out


def test_simulate_json_gives_each_scene_its_params_and_start(tmp_path, capsys):
    """--json lacked the params and the start: a cue scene's start (the stroke turned into a state) was nowhere."""
    from numerics.scene import Params, Scene

    cue = {"V0": 2.0, "phi": 30, "theta": 5, "a": 0.2, "b": -0.3, "M": 0.567, "m": 0.170}
    scene = {"params": SCENE["params"], "cue": cue}
    assert main(["simulate", _scene_file(tmp_path, scene, "cue.json"), "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    params = Params(**SCENE["params"])
    expected = Scene.from_cue(params, **cue).state
    assert printed["start"] == {name: getattr(expected, name) for name in printed["start"]} and len(printed["start"]) == 7
    assert printed["params"] == {name: getattr(params, name) for name in ("f", "delta", "epsilon", "R", "k", "g")}
    assert main(["simulate", _scene_file(tmp_path, [scene, scene], "cues.json"), "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["start"] for r in rows] == [printed["start"]] * 2 and rows[0]["params"] == printed["params"]


MAGIC = {"png": b"\x89PNG\r\n\x1a\n", "pdf": b"%PDF-", "svg": b"<?xml"}


@pytest.mark.parametrize("kind", ["png", "pdf", "svg"])
def test_plot_writes_the_format_of_the_suffix(tmp_path, capsys, kind):
    out = tmp_path / f"shot.{kind}"
    assert main(["plot", _scene_file(tmp_path), "-o", str(out), "--tol", "1e-8"]) == 0
    assert capsys.readouterr().out.strip() == f"wrote {out}"
    data = out.read_bytes()
    assert len(data) > 10_000 and data.startswith(MAGIC[kind])
    if kind == "svg":  # the artists of `Motion.plot` went into it, by their ids
        text = data.decode()
        assert all(f'id="{gid}"' in text for gid in ("path:sliding", "path:rolling", "end of sliding", "rest point"))


def test_plot_a_list_of_scenes_draws_a_path_each_and_caps_a_huge_list(tmp_path, capsys, monkeypatch):
    import numpy as np

    from numerics import plot

    single = {k: v for k, v in SCENE.items() if k != "t"}
    scenes = [single, {**single, "state": {**single["state"], "q": 40.0}}, {**single, "model": "classical"}]
    out = tmp_path / "many.svg"
    assert main(["plot", _scene_file(tmp_path, scenes, "many.json"), "-o", str(out)]) == 0
    text = out.read_text()
    assert [f'id="path:{i}"' in text for i in range(4)] == [True, True, True, False]
    assert text.count('id="rest point:') == 3 and "scene [2]" in text
    monkeypatch.setattr(plot, "MAX_SCENES", 2)
    params = _scene_file(tmp_path, SCENE["params"], "params.json")
    np.savez(tmp_path / "s.npz", states=np.array([[0, 0, 2.0, 0.0, 10.0, -40.0, 5.0]] * 5))
    capsys.readouterr()
    capped = tmp_path / "capped.svg"
    assert main(["plot", str(tmp_path / "s.npz"), "--params", params, "-o", str(capped)]) == 0
    assert capsys.readouterr().err == "appell: plot: drawing the first 2 of 5 scenes\n"
    assert capped.read_text().count('id="path:') == 2


def test_plot_never_overwrites_a_file(tmp_path, capsys, monkeypatch):
    scene = _scene_file(tmp_path, SCENE, "shot.json")
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    assert main(["plot", scene]) == 0  # the default: the scene's name, .png, in the current folder
    assert (work / "shot.png").read_bytes().startswith(MAGIC["png"])
    (work / "shot.png").write_text("the user's own file")
    capsys.readouterr()
    for extra in ([], ["-o", "shot.png"]):  # named or not, an existing file is the user's: refused
        assert main(["plot", scene, *extra]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "shot.png: exists" in err
        assert (work / "shot.png").read_text() == "the user's own file"
    assert main(["plot", scene, "-o", "other.svg"]) == 0
    assert sorted(p.name for p in work.iterdir()) == ["other.svg", "shot.png"]  # no temporary file left beside it


@pytest.mark.parametrize(
    "content, extra, message",
    [
        (json.dumps(SCENE), ["-o", "shot.gif"], "unknown picture format '.gif'"),
        (json.dumps(SCENE), ["-o", "shot"], "unknown picture format '(no suffix)'"),
        (json.dumps({**SCENE, "params": {**SCENE["params"], "delta": 0.01}}), ["-o", "x.png"], "params.delta: must be < f R"),
        (json.dumps([SCENE, {**SCENE, "state": {}}, {}]), ["-o", "x.png"], "scene [1].state"),
        ('{"params": ', ["-o", "x.png"], "not valid JSON"),
        (json.dumps(SCENE), ["-o", "x.png", "--tol", "1"], "--tol"),
        (json.dumps(SCENE), ["-o", "x.png", "--params", "p.json"], "--params"),
    ],
)
def test_plot_bad_input_is_one_line_and_status_2(tmp_path, capsys, monkeypatch, content, extra, message):
    scene = _scene_file(tmp_path, content)
    monkeypatch.chdir(tmp_path)
    assert main(["plot", scene, *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.json"]  # nothing written


def test_plot_help_has_an_example(capsys):
    with pytest.raises(SystemExit):
        main(["plot", "--help"])
    assert "example:\n  appell plot numerics/scenes/sample.json -o sample.png" in capsys.readouterr().out


def test_a_list_whose_scene_fails_to_compute_exits_1_unless_skip_bad(tmp_path, capsys, monkeypatch):
    """A scene of a list whose computation fails (here its slide's bound on work, lowered) exits 1 naming it, as
    one scene does; with --skip-bad the others are printed and it is listed in its place."""
    from numerics import engine, lanes, simulate as simulate_module

    monkeypatch.setattr(simulate_module, "JIT", False)  # the interpreted engine (APPELL_JIT=0): it reads the lowered bound
    for module in (engine, lanes):
        monkeypatch.setattr(module, "MAX_STEPS", 3)
    single = {k: v for k, v in SCENE.items() if k != "t"}
    straight = {**single, "state": {**single["state"], "p": 0.0, "q": 0.0}}  # closed form: no steps
    one = _scene_file(tmp_path, [straight, single], "one.json")
    assert main(["simulate", one]) == 1
    assert capsys.readouterr().err.strip() == "appell: error: scene [1].slide: not done after 3 steps"
    two = _scene_file(tmp_path, [single, straight, single], "two.json")
    assert main(["simulate", two, "--json"]) == 1
    captured = capsys.readouterr()
    assert captured.out == "" and "scene [0].slide" in captured.err and "scene [2].slide" in captured.err
    assert "appell: error: 2 scenes of 3 could not be computed" in captured.err
    assert main(["simulate", two, "--json", "--skip-bad"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [("error" in row) for row in rows] == [True, False, True]


def test_plot_of_a_list_names_the_scene_whose_computation_fails(tmp_path, capsys, monkeypatch):
    from numerics import engine

    monkeypatch.setattr(engine, "MAX_STEPS", 3)  # plot runs the interpreted engine, which reads it
    single = {k: v for k, v in SCENE.items() if k != "t"}
    straight = {**single, "state": {**single["state"], "p": 0.0, "q": 0.0}}
    path = _scene_file(tmp_path, [straight, single], "list.json")
    assert main(["plot", path, "-o", str(tmp_path / "paths.png")]) == 1
    assert capsys.readouterr().err.strip() == "appell: error: scene [1].slide: not done after 3 steps"
    assert not (tmp_path / "paths.png").exists()


def test_at_beyond_the_reach_of_the_motion_is_refused_as_a_scene_t_is(tmp_path, capsys):
    """A review: with δ = 0 (the ball rolls for ever) --at 9e99 printed a state 1e101 m away, exit 0, where the scene's
    own t = [9e99] is refused: --at is held to the same bound, for one scene and in a list (naming the scene)."""
    rolling = {**SCENE, "params": {**SCENE["params"], "delta": 0.0}, "t": []}
    assert main(["simulate", _scene_file(tmp_path, rolling, "roll.json"), "--json", "--at", "9e99"]) == 2
    assert "--at: the motion's distance bound" in capsys.readouterr().err
    fast = {**rolling, "state": {**SCENE["state"], "vxi": 20.0}}  # 3e98 s is within reach of SCENE, not of it
    assert main(["simulate", _scene_file(tmp_path, [SCENE, fast], "rolls.json"), "--json", "--at", "3e98"]) == 2
    assert "--at: scene [1]: the motion's distance bound" in capsys.readouterr().err
    assert main(["simulate", _scene_file(tmp_path, rolling, "near.json"), "--json", "--at", "100"]) == 0
    capsys.readouterr()
    # A ball that comes to rest (δ > 0) moves no further: --at 9e99 is its rest point (an audit: it was refused
    # for a distance bound of 1.5e100, speed times the time asked).
    assert main(["simulate", _scene_file(tmp_path, SCENE, "rests.json"), "--json", "--at", "9e99"]) == 0
    late = json.loads(capsys.readouterr().out)["states"][-1]
    assert late["t"] == 9e99 and late["phase"] == "rest" and late["vxi"] == 0 and abs(late["xi"]) < 100
    broken = {**SCENE, "params": {**SCENE["params"], "delta": 0.01}}  # δ ≥ fR: no good scene left to hold to --at
    assert main(["simulate", _scene_file(tmp_path, [broken], "broken.json"), "--json", "--at", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "scene [0].params.delta: must be < f R" in err  # a traceback, before


def test_no_rest_point_has_no_estimate_of_one(tmp_path, capsys):
    """An audit: with δ = 0 the text printed "estimated relative error of the rest point: 0.0e+00" under "rest point
    none", and a list of such scenes a largest estimate of 0 for rest points none of them has."""
    rolling = {**SCENE, "params": {**SCENE["params"], "delta": 0.0}, "t": []}
    assert main(["simulate", _scene_file(tmp_path, rolling, "roll.json")]) == 0
    assert "estimated relative error of the rest point: none (no rest point; tolerance asked 1e-10)" in capsys.readouterr().out
    assert main(["simulate", _scene_file(tmp_path, rolling, "roll.json"), "--json"]) == 0
    # An audit: the closed-form phases after the slide said error 0.0, read as exact; the slide's null stood alone.
    assert [p["error"] for p in json.loads(capsys.readouterr().out)["phases"]] == [None, None, None]
    assert main(["simulate", _scene_file(tmp_path, [rolling, rolling], "rolls.json")]) == 0
    out = capsys.readouterr().out
    assert "no scene comes to rest" in out and "largest estimated" not in out
    assert main(["simulate", _scene_file(tmp_path, [rolling, SCENE], "mixed.json")]) == 0
    assert "largest estimated relative error of a rest point: " in capsys.readouterr().out


def test_at_given_twice_asks_both_times_and_an_empty_picture_name_is_refused(tmp_path, capsys):
    """An audit: --at 0.2 --at 0.3 dropped 0.2 unsaid, and plot -o "" named the folder "." as the bad picture."""
    path = _scene_file(tmp_path, {**SCENE, "t": []}, "s.json")
    assert main(["simulate", path, "--json", "--at", "0.2", "--at", "0.3", "0.4"]) == 0
    assert [state["t"] for state in json.loads(capsys.readouterr().out)["states"]] == [0.2, 0.3, 0.4]
    assert main(["plot", path, "-o", ""]) == 2
    assert capsys.readouterr().err == "appell: error: -o: an empty file name (the picture's file: -o shot.png, .pdf or .svg)\n"


def test_many_states_or_scenes_run_the_compiled_engine(tmp_path, capsys, monkeypatch):
    """An audit: near δ = fR an interpreted state cost milliseconds: --samples 99990 ran 12 minutes, a picture of 100
    such scenes 3.5.  Beyond STATES_INTERPRETED states of one scene, or SCENES_INTERPRETED scenes of a picture, the
    command line runs the compiled engine; below, the interpreted one (nothing to compile)."""
    from numerics import simulate as simulate_module
    from paper import cli

    engines = []
    real_simulate = simulate_module.simulate

    def recording(scene, tol=None, jit=None, **kw):
        engines.append(jit)
        return real_simulate(scene, tol=tol, jit=False, **kw)  # the answer itself: not what is tested here
    monkeypatch.setattr(simulate_module, "simulate", recording)
    path = _scene_file(tmp_path, {**SCENE, "t": []}, "s.json")
    for samples, jit in ((cli.STATES_INTERPRETED - 1, False), (cli.STATES_INTERPRETED, True)):  # N + 1 states
        assert main(["simulate", path, "--json", "--samples", str(samples)]) == 0
        assert engines.pop() is jit
    capsys.readouterr()
    for n, jit in ((cli.SCENES_INTERPRETED, False), (cli.SCENES_INTERPRETED + 1, True)):
        assert main(["plot", _scene_file(tmp_path, [SCENE] * n, f"l{n}.json"), "-o", str(tmp_path / f"l{n}.png")]) == 0
        assert engines[-n:] == [jit] * n


@pytest.mark.parametrize("twice, said", [
    (["--csv", "a.csv", "--csv", "b.csv"], "--csv: given twice (a.csv, then b.csv)"),
    (["--tol", "1e-9", "--tol", "1e-9"], "--tol: given twice (1e-09, then 1e-09)"),  # the same value too: a slip
    (["--model", "appell", "--model", "classical"], "--model: given twice (appell, then classical)"),
])
def test_an_option_of_one_value_given_twice_is_refused_before_any_work(tmp_path, capsys, monkeypatch, twice, said):
    """An audit: --csv a.csv --csv b.csv wrote b.csv alone, unsaid.  Every option of one value (not --at, which
    extends) is refused a second time: one line, status 2, no file written."""
    monkeypatch.chdir(tmp_path)
    path = _scene_file(tmp_path, SCENE, "s.json")
    assert main(["simulate", path, *twice]) == 2
    err = capsys.readouterr().err
    assert err == f"appell: error: {said}; give it once (see 'appell simulate --help')\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.json"]
    assert main(["plot", path, "-o", "a.png", "--output", "b.png"]) == 2
    assert "-o/--output" not in (err := capsys.readouterr().err) and "--output: given twice (a.png, then b.png)" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.json"]
    assert main(["paper", "--out", "x", "--out", "y"]) == 2 and "--out: given twice (x, then y)" in capsys.readouterr().err


def test_a_claim_named_twice_is_checked_once(capsys):
    """An audit: `appell verify eq10 eq10` checked eq10 twice and counted two mathematical errata."""
    assert main(["verify", "eq10", "eq10", "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["summary"]["total"] == 1 and [c["id"] for c in record["claims"]] == ["eq10"]
