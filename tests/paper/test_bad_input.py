"""Hostile but fair input through the command line: one line and exit status 2, never a traceback or a hang."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from paper.cli import main

PARAMS = {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575}
SCENE = {"params": PARAMS, "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0}}


def _with(part, name, value):
    data = json.loads(json.dumps(SCENE))
    data[part][name] = value
    return data


def _write(folder, name, content):
    path = folder / name
    if isinstance(content, bytes):
        path.write_bytes(content)
    elif isinstance(content, str):
        path.write_text(content)
    else:
        path.write_text(json.dumps(content))
    return str(path)


def _literal(part, name, literal: str) -> str:
    """SCENE's JSON with ``literal`` written as the number of part.name (1e-400, which no float holds)."""
    return json.dumps(_with(part, name, "LITERAL")).replace('"LITERAL"', literal)


def _npz(folder, name, **arrays):
    path = folder / name
    with open(path, "wb") as handle:
        np.savez(handle, **arrays)
    return str(path)


def _npy_named_npz(folder, name):
    path = folder / name
    with open(path, "wb") as handle:
        np.save(handle, np.zeros((2, 7)))
    return str(path)


# (files to write, argv with {name} for their paths, a fragment of the one line expected)
CASES = {
    "vxi 1e300": ({"s.json": _with("state", "vxi", 1e300)}, ["simulate", "{s.json}"], "cannot be represented in float64"),
    "p 1e300": ({"s.json": _with("state", "p", 1e300)}, ["simulate", "{s.json}"], "cannot be represented in float64"),
    "R 1e300": ({"s.json": _with("params", "R", 1e300)}, ["simulate", "{s.json}"], "params.R: must be between"),
    "g 1e-300": ({"s.json": _with("params", "g", 1e-300)}, ["simulate", "{s.json}"], "params.g: must be between"),
    "f 1e-300": ({"s.json": _with("params", "f", 1e-300)}, ["simulate", "{s.json}"], "params.f: must be between"),
    "integer 10^400": ({"s.json": json.dumps(SCENE).replace('"vxi": 2.0', '"vxi": 1' + "0" * 400)},
                       ["simulate", "{s.json}"], "state.vxi: must be within float64's range"),
    # Literals beyond float64 (an audit: 1e-400 was read as 0 and the ball lay still, 1e400 as ∞ "must be finite").
    "vxi 1e-400": ({"s.json": _literal("state", "vxi", "1e-400")}, ["simulate", "{s.json}"],
                   "state.vxi: must be 0 or at least 4.9e-324 in size (float64's smallest), got 1E-400"),
    "delta 1e-400": ({"s.json": _literal("params", "delta", "1e-400")}, ["simulate", "{s.json}"],
                     "params.delta: must be 0 or at least 4.9e-324"),
    "p 1e400": ({"s.json": _literal("state", "p", "1e400")}, ["simulate", "{s.json}"],
                "state.p: must be within float64's range (|x| < 1.8e308), got 1E+400"),
    "integer of 5000 digits": ({"s.json": _literal("state", "vxi", "9" * 5000)}, ["simulate", "{s.json}"],
                               "state.vxi: must be within float64's range (|x| < 1.8e308), got 99999"),
    "csv 1e-400": ({"s.csv": "xi,eta,vxi,veta,p,q,r\n0,0,1e-400,0,0,0,0\n", "p.json": json.dumps(SCENE["params"])},
                   ["simulate", "{s.csv}", "--params", "{p.json}"], "scene [0].state.vxi: must be 0 or at least 4.9e-324"),
    "duplicate key": ({"s.json": json.dumps(SCENE).replace('"vxi": 2.0', '"vxi": 2.0, "vxi": 3.0')}, ["simulate", "{s.json}"],
                      "s.json: the key 'vxi' is given twice in one object"),
    "binary scene": ({"s.json": bytes(range(256)) * 8}, ["simulate", "{s.json}"], "not UTF-8 text"),
    "binary params": ({"s.csv": "xi,eta,vxi,veta,p,q,r\n0,0,1,0,0,0,0\n", "p.json": bytes(range(256))},
                      ["simulate", "{s.csv}", "--params", "{p.json}"], "p.json: not UTF-8 text"),
    "deeply nested": ({"s.json": "[" * 100_000 + "]" * 100_000}, ["simulate", "{s.json}"], "nested too deeply"),
    "npy under npz": ({"s.npz": "npy", "p.json": PARAMS}, ["simulate", "{s.npz}", "--params", "{p.json}"], "not a .npz archive"),
    "complex npz": ({"s.npz": np.ones((2, 7)) * (1 + 1j), "p.json": PARAMS}, ["simulate", "{s.npz}", "--params", "{p.json}"],
                    "states: must be real numbers, got complex128"),
    "boolean npz": ({"s.npz": np.ones((2, 7), dtype=bool), "p.json": PARAMS}, ["simulate", "{s.npz}", "--params", "{p.json}"],
                    "states: must be numbers, got bool values"),
    "text npz": ({"s.npz": np.full((2, 7), "1.5"), "p.json": PARAMS}, ["simulate", "{s.npz}", "--params", "{p.json}"],
                 "states: must be numbers, got <U3 values"),
    "list with binary after 4 kB": ({"s.json": ("[" + json.dumps(SCENE) + "," + " " * 4100).encode() + b"\xff\xfe"},
                                    ["simulate", "{s.json}"], "not UTF-8 text"),
    "header-only csv": ({"s.csv": "xi,eta,vxi,veta,p,q,r\n", "p.json": PARAMS}, ["simulate", "{s.csv}", "--params", "{p.json}"],
                        "no scenes"),
    "params with a single scene": ({"s.json": SCENE, "p.json": PARAMS}, ["simulate", "{s.json}", "--params", "{p.json}"],
                                   "--params: only for states in .npz/.csv"),
    "samples 10^5": ({"s.json": SCENE}, ["simulate", "{s.json}", "--samples", "100000"], "--samples: must be >= 1 and < 100,000"),
    "t 10^5 + 1 times": ({"s.json": {**SCENE, "t": [0.5] * 100_001}}, ["simulate", "{s.json}"], "t: at most 100,000 times"),
    "workers 0": ({"s.json": [SCENE, SCENE]}, ["simulate", "{s.json}", "--workers", "0"], "--workers: must be an integer >= 1"),
    "workers -1": ({"s.json": SCENE}, ["simulate", "{s.json}", "--workers", "-1"], "--workers: must be an integer >= 1"),
    "accuracy tol 0": ({}, ["accuracy", "--tol", "0"], "--tol: must be between"),
    "accuracy tol nan": ({}, ["accuracy", "--tol", "nan"], "--tol: must be finite"),
    "accuracy tol -1": ({}, ["accuracy", "--tol", "-1"], "--tol: must be between"),
    "k beyond a shell": ({"s.json": _with("params", "k", 0.028575)}, ["simulate", "{s.json}"], "params.k: must be <= R √(2/3)"),
    "unknown keys of mixed types": ({"s.json": '{"params": {}, "state": {}, "1": 2, "x": 3}'}, ["simulate", "{s.json}"],
                                    "scene['1']: unknown field"),
    "paper --out a file": ({"f.txt": "mine"}, ["paper", "--out", "{f.txt}"], "is a file, not a folder"),
    "paper --out /proc": ({}, ["paper", "--out", "/proc/nope"], "/proc/nope: cannot create the folder"),
    "skip-bad with one scene": ({"s.json": SCENE}, ["simulate", "{s.json}", "--skip-bad"], "--skip-bad: only for many scenes"),
    # Found by an adversarial audit: csv's own error, a tolerance shown rounded into the range, --at named t.
    "csv cell beyond csv's field limit": ({"s.csv": "xi,eta,vxi,veta,p,q,r\n" + "0" * 140_000 + ",0,1,0,0,0,0\n", "p.json": PARAMS},
                                          ["simulate", "{s.csv}", "--params", "{p.json}"], "s.csv: not a CSV table (field larger"),
    "tol just above the range": ({"s.json": SCENE}, ["simulate", "{s.json}", "--tol", "1.0000001e-05"],
                                 "--tol: must be between 1e-13 and 1e-05, got 1.0000001e-05"),
    "tol 1e-4": ({"s.json": SCENE}, ["simulate", "{s.json}", "--tol", "1e-4"], "--tol: must be between 1e-13 and 1e-05"),
    "at 1e300": ({"s.json": SCENE}, ["simulate", "{s.json}", "--at", "1e300"], "--at: times must be >= 0 and below 1e+100 s"),
    # A negative number in exponent form is a number to check, not an unknown option ("expected one argument").
    "tol -1e-10": ({"s.json": SCENE}, ["simulate", "{s.json}", "--tol", "-1e-10"], "--tol: must be between 1e-13 and 1e-05, got -1e-10"),
    "at -1e-3": ({"s.json": SCENE}, ["simulate", "{s.json}", "--at", "-1e-3"], "--at: times must be >= 0"),
    # An audit: exponents past Decimal's own were a traceback; a longdouble below float64 read as 0 (a ball set still);
    # a scalar .npz named shape (1, 1).
    "vxi 1e(10^18)": ({"s.json": _literal("state", "vxi", "1e1000000000000000000")}, ["simulate", "{s.json}"],
                      "state.vxi: must be within float64's range (|x| < 1.8e308), got 1e1000000000000000000"),
    "R 1e-(10^20)": ({"s.json": _literal("params", "R", "1e-99999999999999999999")}, ["simulate", "{s.json}"],
                     "params.R: must be 0 or at least 4.9e-324 in size (float64's smallest), got 1e-99999999999999999999"),
    "csv 1e(10^18)": ({"s.csv": "xi,eta,vxi,veta,p,q,r\n1e1000000000000000000,0,2,0,10,-40,5\n", "p.json": PARAMS},
                      ["simulate", "{s.csv}", "--params", "{p.json}"], "scene [0].state.xi: must be within float64's range"),
    "longdouble npz below float64": ({"s.npz": np.array([[0, 0, np.longdouble("1e-4000"), 0, 0, 0, 0], [0, 0, 2, 0, 0, 0, 0]],
                                                        dtype=np.longdouble), "p.json": PARAMS},
                                     ["simulate", "{s.npz}", "--params", "{p.json}"],
                                     "states [0].vxi: must be 0 or at least 4.9e-324 in size (float64's smallest)"),
    "scalar npz": ({"s.npz": np.float64(3), "p.json": PARAMS}, ["simulate", "{s.npz}", "--params", "{p.json}"],
                   "states: must have shape (n, 7) (xi, eta, vxi, veta, p, q, r), got ()"),
    # A user audit: a misspelt option of a command sent to the top help, which does not list the command's options.
    "misspelt option": ({"s.json": SCENE}, ["simulate", "{s.json}", "--jsn"], "--jsn (see 'appell simulate --help')"),
}


def _materialise(tmp_path, files, argv):
    """Write the files, and put their paths in place of {name} in argv."""
    paths = {}
    for name, content in files.items():
        if name.endswith(".npz"):
            paths[name] = _npy_named_npz(tmp_path, name) if isinstance(content, str) else _npz(tmp_path, name, states=content)
        else:
            paths[name] = _write(tmp_path, name, content)
    for name, path in paths.items():
        argv = [arg.replace("{" + name + "}", path) for arg in argv]
    return argv


@pytest.mark.parametrize("case", CASES)
def test_each_hostile_case_is_one_line_and_status_2(case, tmp_path, capsys):
    files, argv, fragment = CASES[case]
    assert main(_materialise(tmp_path, files, argv)) == 2
    captured = capsys.readouterr()
    assert captured.err.count("\n") == 1 and captured.err.startswith("appell: error: "), captured.err
    assert fragment in captured.err


def test_a_list_after_5_kB_of_whitespace_is_a_list(tmp_path, capsys):
    path = _write(tmp_path, "s.json", " " * 5000 + json.dumps([SCENE]))
    assert main(["simulate", path, "--json"]) == 0
    assert len(json.loads(capsys.readouterr().out)) == 1


def test_every_bad_scene_of_a_list_is_named_and_skip_bad_runs_the_others(tmp_path, capsys):
    bad_p = _with("state", "p", "x")
    huge = _with("state", "vxi", 1e300)
    path = _write(tmp_path, "s.json", [SCENE, bad_p, SCENE, huge])
    assert main(["simulate", path]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err[0] == "appell: error: scene [1].state.p: must be a number, got 'x'"
    assert err[1].startswith("appell: error: scene [3].state.vxi: the motion's speed")
    assert "2 bad scenes of 4" in err[2] and len(err) == 3
    assert main(["simulate", path, "--skip-bad", "--json"]) == 0
    captured = capsys.readouterr()
    rows = json.loads(captured.out)
    assert rows[1] == {"error": "scene [1].state.p: must be a number, got 'x'"} and "error" in rows[3]
    assert rows[0]["rest"] == rows[2]["rest"] and rows[0]["rest"] is not None
    assert captured.err.count("appell: skipped: scene [") == 2


def test_skip_bad_with_no_good_scene_exits_2(tmp_path, capsys):
    """--skip-bad --json exited 0 when every scene was bad (an audit), then 1 (a CLI audit: bad input is 2, as a
    bad scene alone): the list is printed, the status says so."""
    path = _write(tmp_path, "s.json", [_with("state", "p", "x"), _with("state", "vxi", 1e300)])
    for argv in (["simulate", path, "--skip-bad", "--json"], ["simulate", path, "--skip-bad"]):
        assert main(argv) == 2
        captured = capsys.readouterr()
        assert captured.err.endswith("appell: error: none of the 2 scenes is valid (listed above)\n")
    assert all("error" in row for row in json.loads(main(["simulate", path, "--skip-bad", "--json"]) and capsys.readouterr().out))


def test_csv_columns_by_header_name_and_bad_rows_by_index(tmp_path, capsys):
    params = _write(tmp_path, "p.json", PARAMS)
    shuffled = _write(tmp_path, "a.csv", "r,q,p,veta,vxi,eta,xi\n5,-40,10,0,2,0,0\n")
    ordered = _write(tmp_path, "b.csv", "xi,eta,vxi,veta,p,q,r\n0,0,2,0,10,-40,5\n")
    outs = []
    for path in (shuffled, ordered):
        assert main(["simulate", path, "--params", params, "--json"]) == 0
        outs.append(json.loads(capsys.readouterr().out))
    assert outs[0] == outs[1]
    bad = _write(tmp_path, "c.csv", "xi,eta,vxi,veta,p,q,r\n0,0,2,0,10,-40,5\n0,0,x,0,0,0,0\n0,0,1,0,0,0\n0,0,nan,0,0,0,0\n")
    assert main(["simulate", bad, "--params", params]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err[:3] == [
        "appell: error: scene [1].state.vxi: must be a number, got 'x'",
        "appell: error: scene [2]: must have 7 values, got 6",
        "appell: error: scene [3].state.vxi: must be finite, got nan",
    ]


def test_output_that_cannot_be_written_is_one_line(tmp_path):
    path = _write(tmp_path, "s.json", SCENE)
    with open("/dev/full", "w") as full:
        out = subprocess.run([sys.executable, "-m", "paper", "simulate", path], stdout=full, stderr=subprocess.PIPE,
                             text=True, timeout=120)
    assert out.returncode == 2
    assert out.stderr == "appell: error: cannot write to standard output (No space left on device)\n"


def test_a_closed_standard_output_is_one_line(tmp_path):
    """Started with stdout closed (appell simulate ... >&-), the command printed into nothing and ended in a
    traceback at its flush (an audit)."""
    path = _write(tmp_path, "s.json", SCENE)
    out = subprocess.run([sys.executable, "-m", "paper", "simulate", path], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True, timeout=120, preexec_fn=lambda: os.close(1))
    assert out.returncode == 2
    assert out.stderr == "appell: error: cannot write to standard output (it is closed)\n"


def test_an_endless_input_is_refused_by_size(tmp_path, capsys, monkeypatch):
    from numerics import scene

    monkeypatch.setattr(scene, "MAX_JSON_BYTES", 1000)  # a JSON scene file's bound (below the tables')
    assert main(["simulate", "/dev/zero"]) == 2
    assert "larger than" in capsys.readouterr().err
    monkeypatch.setattr(scene, "MAX_FILE_BYTES", 1000)  # a table's: a CSV was told to use .npz or .csv (an audit)
    table = tmp_path / "big.csv"
    table.write_text("xi,eta,vxi,veta,p,q,r\n" + "0,0,1,0,0,0,0\n" * 100)
    assert main(["simulate", str(table), "--params", _write(tmp_path, "p.json", PARAMS)]) == 2
    assert "larger than 0 MiB: too many states for CSV text: save them as .npz" in capsys.readouterr().err


def test_a_json_list_is_bounded_below_the_tables_and_its_times_together(tmp_path, capsys, monkeypatch):
    """An audit: a 100 MB JSON list of 500 scenes with 100,000 times each took 83 s and 2.4 GB, for times only
    --json reports; 512 MiB of JSON would take minutes and gigabytes.  A JSON file is at most 64 MiB, and a
    list's times together at most 100,000, refused before any scene is checked."""
    from numerics import scene

    assert scene.MAX_JSON_BYTES == 64 * 2**20 < scene.MAX_FILE_BYTES
    many = [{**SCENE, "t": [0.1] * 60_000}, {**SCENE, "t": [0.2] * 60_000}]
    assert main(["simulate", _write(tmp_path, "many.json", many)]) == 2
    assert capsys.readouterr().err == ("appell: error: t: at most 100,000 times in a list of scenes (every scene's t "
                                       "together), got 120,000; Motion.states in Python takes any number\n")
    monkeypatch.setattr(scene, "MAX_JSON_BYTES", 1000)
    assert main(["simulate", _write(tmp_path, "big.json", [SCENE] * 20)]) == 2
    assert capsys.readouterr().err.endswith("larger than 0 MiB: not a scene file (many scenes: use .npz or .csv)\n")


def test_a_csv_cell_is_a_number_as_a_table_writes_it(tmp_path, capsys):
    """float() reads "1_0" and other scripts' digits ("١٠") as 10 (an audit): refused, by row and column."""
    params = _write(tmp_path, "p.json", PARAMS)
    rows = _write(tmp_path, "a.csv", "xi,eta,vxi,veta,p,q,r\n0,0,1_0,0,10,-40,5\n0,0,2,0,١٠,-40,5\n0,0,2,0,10,-40,5\n")
    assert main(["simulate", rows, "--params", params]) == 2
    err = capsys.readouterr().err
    assert "scene [0].state.vxi: must be a number, got '1_0'" in err and "scene [1].state.p: must be a number" in err


def test_a_npz_whose_header_declares_more_than_memory_is_one_line(tmp_path, capsys):
    """A crafted states.npy header (10¹¹ rows, no data): refused in one line, not a MemoryError traceback."""
    import io
    import zipfile

    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": "<f8", "fortran_order": False, "shape": (10**11, 7)})
    path = tmp_path / "s.npz"
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("states.npy", header.getvalue())
    params = _write(tmp_path, "p.json", PARAMS)
    assert main(["simulate", str(path), "--params", params]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "s.npz: states: larger than this machine's memory" in err, err


def test_a_byte_order_mark_and_upper_case_suffixes_are_read(tmp_path, capsys):
    """A scene file some editors start with a UTF-8 byte-order mark, and STATES.CSV / STATES.NPZ, read as any."""
    assert main(["simulate", _write(tmp_path, "s.json", b"\xef\xbb\xbf" + json.dumps(SCENE).encode())]) == 0
    params = _write(tmp_path, "p.json", PARAMS)
    assert main(["simulate", _write(tmp_path, "S.CSV", "xi,eta,vxi,veta,p,q,r\n0,0,2,0,10,-40,5\n"), "--params", params]) == 0
    assert main(["simulate", _npz(tmp_path, "S.NPZ", states=np.array([[0, 0, 2.0, 0, 10, -40, 5]])), "--params", params]) == 0
    capsys.readouterr()


def test_a_named_pipe_no_one_writes_to_is_refused_not_waited_on(tmp_path):
    """open() of a FIFO waits for a writer for ever: the scene is opened without waiting, and read as empty (said
    so: it was "not valid JSON (Expecting value at line 1)")."""
    import os

    fifo = tmp_path / "scene.json"
    os.mkfifo(fifo)
    done = subprocess.run([sys.executable, "-m", "paper", "simulate", str(fifo)], capture_output=True, text=True,
                          timeout=60, check=False)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "scene.json: empty: no JSON in it" in done.stderr


def test_a_scene_piped_into_dev_stdin_is_read():
    done = subprocess.run([sys.executable, "-m", "paper", "simulate", "/dev/stdin", "--json"], input=json.dumps(SCENE),
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0 and json.loads(done.stdout)["rest"] is not None, done.stderr


def _stdin(monkeypatch, text: str) -> None:
    import io

    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(text.encode())))


def test_a_dash_reads_a_scene_or_a_list_from_standard_input(monkeypatch, capsys, tmp_path):
    """`appell simulate -` (as Unix tools read it) said '-: cannot read (No such file or directory)'."""
    _stdin(monkeypatch, json.dumps(SCENE))
    assert main(["simulate", "-", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["rest"] is not None
    _stdin(monkeypatch, json.dumps([SCENE, SCENE]))
    assert main(["simulate", "-", "--json"]) == 0
    assert len(json.loads(capsys.readouterr().out)) == 2
    _stdin(monkeypatch, "{")
    assert main(["simulate", "-"]) == 2
    assert capsys.readouterr().err.startswith("appell: error: standard input: not valid JSON")
    _stdin(monkeypatch, json.dumps([{"params": {}}, {"params": {}}]))
    assert main(["simulate", "-"]) == 2
    assert capsys.readouterr().err.splitlines()[-1].startswith("appell: error: standard input: 2 bad scenes of 2")
    monkeypatch.setattr(sys, "stdin", None)  # started with standard input closed (<&-)
    assert main(["simulate", "-"]) == 2
    assert capsys.readouterr().err == "appell: error: standard input: cannot read (standard input is closed)\n"
    # a picture needs a name: "-.png" was written
    monkeypatch.chdir(tmp_path)
    _stdin(monkeypatch, json.dumps(SCENE))
    assert main(["plot", "-"]) == 2
    assert "name the picture with -o FILE" in capsys.readouterr().err and list(tmp_path.iterdir()) == []
    _stdin(monkeypatch, json.dumps(SCENE))
    from numerics.simulate import Motion

    titles = []
    plot = Motion.plot
    monkeypatch.setattr(Motion, "plot", lambda self, ax=None, title=None: titles.append(title) or plot(self, ax, title))
    assert main(["plot", "-", "-o", "shot.png"]) == 0
    assert (tmp_path / "shot.png").stat().st_size > 0
    assert titles and not titles[0].startswith(("-", "standard input"))  # no file name to give


def test_a_csv_with_old_mac_line_ends_reads_as_with_newlines(tmp_path, capsys):
    rows = ["xi,eta,vxi,veta,p,q,r", "0,0,2,0,10,-40,5", "0,0,1,0.5,0,0,0"]
    outputs = []
    for name, end in (("lf.csv", "\n"), ("cr.csv", "\r"), ("crlf.csv", "\r\n")):
        path = _write(tmp_path, name, end.join(rows) + end)
        assert main(["simulate", path, "--params", _write(tmp_path, "p.json", PARAMS), "--json"]) == 0
        outputs.append(json.loads(capsys.readouterr().out))
    assert outputs[0] == outputs[1] == outputs[2] and len(outputs[0]) == 2


def test_ctrl_c_is_one_line_and_status_130(tmp_path, capsys, monkeypatch):
    import numerics.simulate

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(numerics.simulate, "simulate", interrupted)
    assert main(["simulate", _write(tmp_path, "s.json", SCENE)]) == 130
    assert capsys.readouterr().err == "appell: interrupted\n"


def test_appell_jit_other_than_0_or_1_is_refused_whatever_the_scenes(tmp_path, capsys, monkeypatch):
    """APPELL_JIT=2 ran one scene (the command line chooses its engine) and failed a list (a user audit)."""
    import numerics.simulate

    monkeypatch.setattr(numerics.simulate, "JIT", None)  # as read from APPELL_JIT=2 when the module was imported
    monkeypatch.setenv("APPELL_JIT", "2")
    for argv in (["simulate", _write(tmp_path, "s.json", SCENE)], ["plot", _write(tmp_path, "p.json", SCENE), "-o",
                                                                     str(tmp_path / "p.png")]):
        assert main(argv) == 2
        assert capsys.readouterr().err == "appell: error: APPELL_JIT: must be 0 (the interpreted engine) or 1 (compiled), got '2'\n"
    assert not (tmp_path / "p.png").exists()


@pytest.mark.parametrize("error, said", [
    (MemoryError("Unable to allocate 191. MiB for an array with shape (1000000, 25) and data type float64"),
     "appell: error: out of memory (Unable to allocate 191. MiB for an array with shape (1000000, 25) and data type "
     "float64): give fewer scenes or states at once\n"),
    (RuntimeError("can't start new thread"),
     "appell: error: out of memory (cannot start a thread: can't start new thread): give fewer scenes or states at once, "
     "or set --workers 1\n"),
])
def test_running_out_of_memory_is_one_line(tmp_path, capsys, monkeypatch, error, said):
    """Under `ulimit -v`, a million scenes ended in NumPy's allocation traceback, or the batch's thread start's (an
    audit)."""
    import numerics.simulate

    def short_of_memory(*args, **kwargs):
        raise error
    monkeypatch.setattr(numerics.simulate, "simulate", short_of_memory)
    assert main(["simulate", _write(tmp_path, "s.json", SCENE)]) == 1
    assert capsys.readouterr().err == said


@pytest.mark.slow  # eight seconds of `appell verify` before the interrupt
def test_ctrl_c_during_verify_is_one_line_from_the_parent_and_none_from_its_workers(tmp_path):
    """The forked workers took SIGINT too and each printed a traceback ("Process ForkPoolWorker-2: ...": a review);
    they ignore it now, and the parent answers in one line."""
    import os
    import signal
    import time

    env = {**os.environ, "APPELL_CACHE": str(tmp_path), "APPELL_JOBS": "2"}
    run = subprocess.Popen([sys.executable, "-m", "paper", "verify"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           text=True, start_new_session=True, env=env)
    time.sleep(8)  # the claims are being checked in the two workers
    os.killpg(run.pid, signal.SIGINT)  # as a terminal's Ctrl-C: the whole process group
    _, err = run.communicate(timeout=120)
    assert run.returncode == 130 and err == "appell: interrupted\n", err


def test_a_newline_in_what_the_user_typed_keeps_the_error_on_one_line(capsys):
    """An audit: `appell verify $'eq1\\nfake'` and a scene file named with a newline wrote two lines of error."""
    assert main(["verify", "eq1\nfake"]) == 2
    assert capsys.readouterr().err == "appell: error: no claim eq1\\nfake: the ids are those `appell verify` lists (eq10, n8.V_rate_bound, ...)\n"
    assert main(["simulate", "no\nsuch\x1b[31m.json"]) == 2
    assert capsys.readouterr().err == "appell: error: no\\nsuch\\x1b[31m.json: cannot read (No such file or directory)\n"


def test_an_npz_that_is_no_regular_file_or_is_corrupt_is_one_line(tmp_path, capsys):
    """An audit: a FIFO named .npz hung np.load for ever; a corrupt compressed archive ended in a zlib traceback."""
    params = _write(tmp_path, "p.json", SCENE["params"])
    fifo = tmp_path / "states.npz"
    os.mkfifo(fifo)
    assert main(["simulate", str(fifo), "--params", params]) == 2
    assert "not a regular file" in capsys.readouterr().err
    archive = tmp_path / "c.npz"
    np.savez_compressed(archive, states=np.random.default_rng(1).normal(size=(2000, 7)))
    data = bytearray(archive.read_bytes())
    data[2000:2060] = bytes(b ^ 0xFF for b in data[2000:2060])  # inside the compressed array
    archive.write_bytes(bytes(data))
    assert main(["simulate", str(archive), "--params", params]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"appell: error: {archive}: states: cannot be read (") and err.count("\n") == 1


def test_none_computed_is_1_when_a_computation_failed(capsys):
    from numerics.validation import ComputationError, SceneError
    from paper import scene_report

    assert scene_report._none_computed(2, [(0, SceneError("state.p", "bad")), (1, ComputationError("t"))]) == 1
    assert capsys.readouterr().err == "appell: none of the 2 scenes could be computed (listed above)\n"
    assert scene_report._none_computed(1, [(0, SceneError("state.p", "bad"))]) == 2
