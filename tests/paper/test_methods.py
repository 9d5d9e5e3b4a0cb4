"""The methods paragraph reads what it states from where it is defined, and times from costs.json only."""

import json

import pytest

from paper import methods


def _heading(title, name):
    return f"[{title}]"


@pytest.fixture
def text(monkeypatch, tmp_path):
    """The methods subsection with no costs.json: nothing measured, nothing invented."""
    monkeypatch.setattr(methods, "COSTS", tmp_path / "costs.json")
    return methods.methods_tex(_heading, "0123456789abcdef0123")


def test_versions_key_box_and_meanings_are_stated(text):
    versions = methods.versions()
    for name, version in versions.items():
        assert f"{name} {version}" in text or (name == "appell" and f"appell}} {version}" in text)
    assert "0123456789abcdef0123" in text and "identifies the source" in text
    assert r"R \in (0.01, 0.1)\,\mathrm{m}" in text and "SHA-256 of the claim's identifier" in text
    for word in ("exact", "proved", "sampled", "digits at", "numeric only", "glyph only"):
        assert word in text.lower()
    assert "has not been measured" in text  # no costs.json: nothing invented
    # One paragraph each (together they ran over a page): what a verdict compares, inequalities, numeric claims.
    for opening in ("Each verdict says", "An inequality is", r"\emph{Numeric only} claims", "The points are drawn"):
        assert f"\n\n{opening}" in text, opening


def test_every_hard_case_is_listed_with_its_start_and_what_makes_it_hard(text):
    """Claims say "on every hard case": Methods names each one (a referee could not tell which shots those were)."""
    from numerics.hard_cases import WHY, hard_cases
    from paper.latex_text import code_text, tex_text

    cases = hard_cases()
    assert f"are {len(cases)} shots" in text
    for name, scene in cases.items():
        assert f"\\item[\\texttt{{{code_text(name)}}}]" in text and tex_text(WHY[name]) in text
    assert r"$r_{0} = 40 \,\mathrm{rad/s}$: the pivot ends" in text  # the start, then the reason


def test_each_pinned_package_is_cited_beside_its_version(text):
    for name, version in methods.versions().items():
        if name not in ("Python", "appell"):
            assert f"{name} {version} \\appellcite{{{methods.REFERENCE[name]}}}" in text


def test_costs_come_from_the_file_appell_costs_writes(monkeypatch, tmp_path):
    from paper import costs

    path = tmp_path / "costs.json"
    data = {"machine": {"cores": 2, "cpu": "AMD EPYC", "python": "3.11.7"},
            "commands": [{"command": "appell verify", "seconds": 63.9, "what": "checks every claim"}]}
    costs.save(data, path)
    assert json.loads(path.read_text()) == data and path.read_text() == costs.save(data, path).read_text()
    monkeypatch.setattr(methods, "COSTS", path)
    assert r"\texttt{appell verify} 64\,s" in methods.methods_tex(_heading, "k")
    assert "2-core AMD EPYC machine from a source not recorded (wall time)" in methods.methods_tex(_heading, "k")
    # The times name the source they were measured on: this one, or an earlier one by its key.
    costs.save({**data, "machine": {**data["machine"], "source": "k"}}, path)
    assert "machine from this source (wall time)" in methods.methods_tex(_heading, "k")
    assert r"machine from an earlier source (key \texttt{k}) (wall time)" in methods.methods_tex(_heading, "k2")


def test_appell_costs_records_the_source_it_measured(monkeypatch):
    from paper import costs, record

    monkeypatch.setattr(costs, "COMMANDS", (("appell --help", ["--help"], "prints the usage"),))
    assert costs.measure()["machine"]["source"] == record.source_key()


def test_appell_costs_times_each_command_in_a_fresh_process(monkeypatch):
    from paper import costs

    monkeypatch.setattr(costs, "COMMANDS", (("appell --help", ["--help"], "prints the usage"),))
    data = costs.measure()
    assert [row["command"] for row in data["commands"]] == ["appell --help"]
    assert data["commands"][0]["seconds"] >= 0 and data["machine"]["cores"] >= 1


def test_a_measured_command_that_fails_is_one_line_and_nothing_is_saved(monkeypatch, capsys, tmp_path):
    """`appell costs` ended in a traceback (a RuntimeError holding the child's whole traceback) when a measured
    command failed (an audit, with APPELL_JOBS=abc): one line now, its last line, exit status 1."""
    from paper import costs, verification
    from paper.cli import main

    monkeypatch.setattr(costs, "COMMANDS", (("appell nonsense", ["nonsense"], "fails"),))
    monkeypatch.setattr(costs, "COSTS", tmp_path / "costs.json")
    monkeypatch.setattr("paper.cli._tex_available", lambda: None)
    monkeypatch.setattr(verification, "jobs", lambda: 1)
    assert main(["costs"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("appell: error: appell nonsense failed while being measured: ") and err.count("\n") == 1
    assert not (tmp_path / "costs.json").exists()


@pytest.mark.parametrize("value", ["abc", "1.5", "0", "-1", "٣"])
def test_a_bad_appell_jobs_is_one_line_before_any_work(monkeypatch, capsys, value):
    """APPELL_JOBS=abc ended in a traceback; 0 and -1 were taken as 1 (an audit)."""
    from paper import costs
    from paper.cli import main

    monkeypatch.setenv("APPELL_JOBS", value)
    monkeypatch.setattr(costs, "measure", lambda **kw: pytest.fail("measured"))
    for argv in (["verify", "eq1"], ["costs", "--no-save"]):
        assert main(argv) == 2
        assert capsys.readouterr().err == f"appell: error: APPELL_JOBS: a whole number of worker processes, at least 1; got {value!r}\n"


def test_an_appell_jobs_too_long_to_read_is_one_short_line(monkeypatch, capsys):
    """5,000 digits: Python refuses to read a number that long, and the command ended in its traceback (an audit)."""
    from paper.cli import main

    monkeypatch.setenv("APPELL_JOBS", "9" * 5000)
    assert main(["verify", "eq1"]) == 2
    assert capsys.readouterr().err == (
        "appell: error: APPELL_JOBS: a whole number of worker processes, at least 1; got '99999999999999999999'… "
        "(5000 characters)\n")


def test_appell_jobs_is_at_most_one_per_core(monkeypatch):
    """APPELL_JOBS=10000 forked 149 processes on two cores (an audit)."""
    import os

    from paper import verification

    monkeypatch.setenv("APPELL_JOBS", "10000")
    assert verification.jobs() == len(os.sched_getaffinity(0))
    monkeypatch.setenv("APPELL_JOBS", "1")
    assert verification.jobs() == 1


def test_the_committed_appendix_names_the_current_source():
    """A fast tripwire for make check: any change to derivation/, reduction/ or numerics/ changes the source key
    the methods paragraph quotes, so paper/ must be regenerated (make test's paper --check finds the rest)."""
    from paper import appendix, record

    committed = (appendix.PAPER / "generated" / "methods.tex").read_text()
    assert f"\\texttt{{{record.source_key()}}}" in committed, "paper/ is stale: run 'appell paper' and commit"


def test_the_claims_methods_names_are_claims_set_as_identifiers(text):
    from paper import verification
    from paper.latex_text import identifier

    assert all(rf"\texttt{{{identifier(name)}}}" in text for name in methods.KANE_ROUTE)
    assert set(methods.KANE_ROUTE) <= {claim.id for claim in verification.all_claims()}
