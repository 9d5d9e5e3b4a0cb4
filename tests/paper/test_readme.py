"""The README's examples are checked against real runs (paper.readme): the checker itself must catch drift."""

import pytest

from paper import readme

README = """Intro.

    $ appell simulate numerics/scenes/bad.json
    appell: error: params.delta: must be < f R (eq. (9), the paper's whole analysis assumes it), got delta = 0.01 >= f R = 0.0057150000000000005

Text between.

    $ appell simulate states.npz --params params.json      # a comment
    $ appell verify --json

    {"not": "an example"}
"""


def test_examples_are_found_with_their_shown_output():
    found = readme.examples(README)
    assert [(e.line, e.command) for e in found] == [
        (3, "appell simulate numerics/scenes/bad.json"), (8, "appell simulate states.npz --params params.json"),
        (9, "appell verify --json")]
    assert found[0].shown[0].startswith("appell: error: params.delta") and found[1].shown == ()
    assert found[2].shown == ("", '{"not": "an example"}')  # a blank line inside a block continues it


def test_mismatch_in_order_with_skips_and_masked_timings():
    real = "a\nb\n12 scenes in 0.0006 s (20,373 scenes/s, 2 threads; + 0.52 s loading the compiled engine), tol 1e-10\nc\n"
    assert readme.mismatch(("a", "...", "c"), real) is None
    assert readme.mismatch(("a", "b"), real) is None
    assert readme.mismatch(("12 scenes in 9 s (1 scenes/s, 8 threads; + 3 s loading the compiled engine), tol 1e-10",), "a\n" + real) is not None  # no "...": must be the first line
    assert readme.mismatch(("...", "12 scenes in 9 s (1 scenes/s, 8 threads; + 3 s loading the compiled engine), tol 1e-10"), real) is None
    assert readme.mismatch(("...", "12 scenes in 9 s (1 scenes/s, 8 threads; + 3 s loading the compiled engine), tol 1e-9"), real)
    one = "6 scenes in 0.0002 s (28,122 scenes/s, 1 thread; + 0.71 s loading the compiled engine), tol 1e-10"
    assert readme.mismatch(("6 scenes in 9 s (1 scenes/s, 1 thread; + 3 s loading the compiled engine), tol 1e-10",), one) is None
    assert readme.mismatch(("b", "a"), real) is not None  # order matters
    assert "printed 'b'" in readme.mismatch(("a", "x"), real)


def test_check_runs_the_commands_and_reports_drift(tmp_path):
    good = tmp_path / "README.md"
    good.write_text(README.split("Text between.")[0])
    assert readme.check(good) == []
    drifted = tmp_path / "drifted.md"
    drifted.write_text(README.split("Text between.")[0].replace("got delta = 0.01", "got delta = 0.02"))
    (problem,) = readme.check(drifted)
    assert problem.startswith("drifted.md:3: appell simulate numerics/scenes/bad.json: shown")
    unknown = tmp_path / "unknown.md"
    unknown.write_text("    $ appell simulate x.json --no-such-flag\n")
    assert "does not parse" in readme.check(unknown)[0]


def test_a_marked_markdown_table_is_an_excerpt_of_its_command():
    text = "Prose.\n\n<!-- $ appell accuracy -->\n| case | error |\n|---|---|\n| sample | 2.3e-12 |\n\nMore prose.\n"
    (example,) = readme.examples(text)
    assert example.command == "appell accuracy" and example.line == 3
    assert example.shown == ("...", "| case | error |", "|---|---|", "| sample | 2.3e-12 |")
    assert readme.mismatch(example.shown, "title\n\n| case | error |\n|---|---|\n| sample | 2.3e-12 |\n") is None
    assert readme.mismatch(example.shown, "| case | error |\n|---|---|\n| sample | 2.4e-12 |\n") is not None


def test_only_rounding_level_figures_are_masked():
    assert readme.mismatch(("| centre hit | 3.6e-16 | 0.0e+00 |",), "| centre hit | 4.9e-16 | 3.8e-18 |") is None
    assert readme.mismatch(("| sample | 2.3e-12 | 6.5e-14 |",), "| sample | 2.3e-12 | 6.6e-14 |") is not None
    assert readme.mismatch(("rest point xi = 6.882583357 m",), "rest point xi = 6.882583358 m") is not None


def test_python_examples_run_in_a_temporary_folder_and_must_print_what_is_shown(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    good = tmp_path / "good.md"
    good.write_text('Text.\n\n    >>> print(round(2 ** 0.5, 4))\n    1.4142\n    >>> open("made.txt", "w").write("x")\n    1\n')
    assert readme.python_examples(good) == []
    assert not (tmp_path / "made.txt").exists()  # written in the temporary folder, not here
    bad = tmp_path / "bad.md"
    bad.write_text("Text.\n\n    >>> print(1 + 1)\n    3\n")
    (problem,) = readme.python_examples(bad)
    assert problem.startswith("bad.md:3: >>> print(1 + 1)") and "Expected: 3 Got: 2" in problem


def test_the_numbers_of_tests_are_what_pytest_collects():
    counts = readme.collected("tests/x.py::test_y\n\n627/793 tests collected (166 deselected) in 5.86s\n")
    assert counts == {"check": 627, "test": 793}
    assert readme.collected("793 tests collected in 5.1s") == {"check": 793, "test": 793}  # no test marked slow
    text = "x\n`make check` runs 627 tests in 69 s; `make test` from a fresh clone runs 793 tests in 4 min\n"
    assert readme.count_problems(text, counts) == []
    wrong = readme.count_problems(text.replace("793", "753"), counts)
    assert wrong == ["README.md:2: `make test` runs 753 tests, says the README; pytest collects 793"]
    assert len(readme.count_problems("no counts here", counts)) == 2  # a README that drops them is caught too
    with pytest.raises(ValueError, match="no count"):
        readme.collected("ERROR collecting tests/x.py")


def test_the_page_counts_are_what_pdflatex_wrote(tmp_path):
    """The README's pages of main.pdf and the host documents against pdflatex's logs (they were 38 and 41 for 39
    and 42 before this check); nothing compiled: not checked, and said so."""
    text = ("`main.pdf` is 39 pages (A4); in the host documents the appendix takes 51 pages\n(article, one column), "
            "28 (article, two columns), 42 (amsart), 23 (revtex4-2 reprint), 50 (article, the class's\ndefaults), "
            "21 (IEEEtran), 20 (mnras), 51 (book, the appendix\na chapter), 30 (article, two columns at 11 pt) and\n"
            "55 (amsart at 12 pt)")
    assert readme.page_problems(text, tmp_path) is None
    (tmp_path / "hosts").mkdir()
    for log, pages in zip(readme.PAGE_LOGS, (39, 51, 28, 42, 23, 50, 21, 20, 51, 30, 55), strict=True):
        (tmp_path / log).write_text(f"...\nOutput written on {log[:-4]}.pdf ({pages} pages, 450266 bytes).\n")
    assert readme.page_problems(text, tmp_path) == []
    problems = readme.page_problems(text.replace("42 (amsart)", "41 (amsart)"), tmp_path)
    assert len(problems) == 1 and "amsart is 41 pages, says the README; pdflatex wrote 42" in problems[0]
    assert readme.page_problems("no counts here", tmp_path)[0].startswith("README.md: does not give the page counts")
    (tmp_path / readme.PAGE_LOGS[3]).unlink()
    assert readme.page_problems(text, tmp_path) == [f"README.md: amsart was not compiled in {tmp_path} (no hosts/amsart.log): "
                                                     "its pages unchecked"]


def test_the_costs_are_paper_data_costs_json(tmp_path):
    """The README's costs against the file `appell costs` writes (an audit: the prose restating it was checked by
    nothing, and a stale figure elsewhere in the README, 1.53 s for 3.1 s, had drifted unseen)."""
    costs = tmp_path / "costs.json"
    costs.write_text('{"commands": [{"command": "appell verify", "seconds": 74.8}, {"command": "appell paper", '
                     '"seconds": 53.7}, {"command": "appell paper --pdf", "seconds": 79.1}], '
                     '"machine": {"cores": 2, "cpu": "Intel(R) Xeon(R) Processor"}}')
    text = ("`appell verify` checks the 152 claims in\n75 s wall ... Measured (`appell costs`, 2 cores, Intel Xeon): "
            "`appell verify` 74.8 s,\n`appell paper` 53.7 s, `appell paper --pdf` 79.1 s.")
    assert readme.cost_problems(text, costs) == []
    for old, new in (("53.7", "53.8"), ("2 cores", "4 cores"), ("Intel Xeon", "AMD EPYC"), ("in\n75 s", "in\n74 s")):
        assert len(readme.cost_problems(text.replace(old, new), costs)) == 1, old
    assert len(readme.cost_problems("nothing said", costs)) == 2


def test_after_a_skip_the_shown_lines_are_consecutive():
    """``...`` skips lines before the next shown one only: the lines after it must follow one another (a mutation
    audit: a skip that stayed open for every later line passed)."""
    assert readme.mismatch(("...", "a", "c"), "x\na\nc\n") is None
    assert readme.mismatch(("...", "a", "c"), "x\na\nb\nc\n") == "shown 'c', printed 'b'"


def test_the_check_fails_on_each_kind_of_problem(monkeypatch, capsys):
    """`python -m paper.readme --check` exits 1 when any of its five checks finds a problem (dropping the Python
    examples from it passed every test)."""
    parts = ("check", "python_examples", "suite_counts", "cost_problems", "page_problems")
    for failing in parts:
        for part in parts:
            monkeypatch.setattr(readme, part, lambda *a, _bad=part == failing, **k: ["R.md:1: wrong"] if _bad else [])
        assert readme.main(["--check"]) == 1, failing
        assert "R.md:1: wrong" in capsys.readouterr().err


def test_a_doctest_failure_the_report_cannot_name_still_fails(monkeypatch, tmp_path):
    """The fallback of `python_examples`: failures counted but no failure block read is a problem, never a pass."""
    import doctest

    def unreadable(self, test, out=None, **kw):
        self.failures = 1
        out("no block this parser reads\n")

    monkeypatch.setattr(doctest.DocTestRunner, "run", unreadable)
    page = tmp_path / "R.md"
    page.write_text("    >>> 1\n    1\n")
    assert readme.python_examples(page) == ["R.md: 1 Python examples failed"]
