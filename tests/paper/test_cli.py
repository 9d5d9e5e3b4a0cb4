"""The `appell` command: exit codes, JSON shape, and one clear line for bad input."""

import json
import subprocess
import sys

import pytest
import sympy as sp

from paper.cli import main


@pytest.fixture(scope="module")
def verify_record():
    out = subprocess.run(
        [sys.executable, "-m", "paper", "verify", "--json"], capture_output=True, text=True, check=False
    )
    return out


def test_verify_json_has_every_claim_and_exits_0(verify_record):
    assert verify_record.returncode == 0, verify_record.stderr
    record = json.loads(verify_record.stdout)
    assert record["summary"]["failed"] == 0
    ids = [row["id"] for row in record["claims"]]
    assert len(ids) == len(set(ids)) == record["summary"]["total"]
    for row in record["claims"]:
        assert {"id", "where", "status", "symbolic", "numeric"} <= row.keys()
        assert row["status"] in {"confirmed", "erratum", "failed"}


def test_verify_table(capsys, monkeypatch):
    from derivation import n7_pure_rolling
    from paper import verification

    monkeypatch.setattr(verification, "all_claims", n7_pure_rolling.claims)
    assert main(["verify"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].split() == ["id", "where", "symbolic", "numeric", "status"]
    assert "eq10" in out and "2 errata" in out and "0 failed" in out


def test_verify_exits_1_when_a_claim_fails(capsys, monkeypatch):
    import dataclasses

    import sympy as sp

    from derivation import n7_pure_rolling
    from paper import verification

    def broken():
        claims = n7_pure_rolling.claims()
        eq = claims[0]
        return [dataclasses.replace(eq, printed=[sp.Eq(e.lhs, e.rhs + 1) for e in eq.printed])]

    monkeypatch.setattr(verification, "all_claims", broken)
    assert main(["verify"]) == 1
    assert "1 failed" in capsys.readouterr().out


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
    assert all(step["status"] == "confirmed" for step in record["steps"])


def test_errata_json(capsys):
    assert main(["errata", "--json"]) == 0
    errata = json.loads(capsys.readouterr().out)["errata"]
    by_id = {e["id"]: e for e in errata}
    assert by_id["eq10"]["kind"] == "mathematical"
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
