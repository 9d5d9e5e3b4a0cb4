"""The `appell` command: exit codes, JSON shape, and one clear line for bad input."""

import json
import subprocess
import sys

import pytest

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


def test_verify_table(capsys):
    assert main(["verify"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].split() == ["id", "where", "symbolic", "numeric", "status"]
    assert "eq10" in out and "0 failed" in out


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
