"""The LaTeX appendix: text in pdflatex's terms, sections in the paper's order, staleness, compilation."""

import dataclasses
import shutil

import pytest

from paper import appendix, verification


def test_text_becomes_latex_and_unknown_characters_are_refused():
    assert appendix.tex_text("θ ≤ π/2, n°7, ξ̇', κδ") == r"$\theta$ $\leq$ $\pi$/2, n\textsuperscript{o}7, $\dot{\xi}$', $\kappa\delta$"
    assert appendix.tex_text("50% & a_b") == r"50\% \& a\_b"
    with pytest.raises(ValueError, match="U\\+2603"):
        appendix.tex_text("snow ☃")


def test_sections_follow_the_paper():
    assert appendix.section_of("n°7, eq. (10)") == "n°7"
    assert appendix.section_of("beyond n°8: straight shots") == "beyond n°8: straight shots"
    assert appendix._tag("n°8, eq. (11)") == "11" and appendix._tag("n°8") is None


@pytest.fixture(scope="module")
def few_results():
    claims = verification.all_claims()
    chosen = [c for c in claims if c.id in ("eq1", "eq2", "eq10", "n8.theta_right_angle", "n10.closed_form_mpmath")]
    return verification.check_all(chosen)


def test_every_claim_is_in_a_fragment_with_its_tag(few_results, tmp_path):
    appendix.generate(tmp_path, few_results, figures=False)
    text = "".join(p.read_text() for p in sorted((tmp_path / "generated").glob("n*.tex")))
    for claim, _ in few_results:
        assert appendix._breakable(claim.id) in text
    assert r"\tag{10}" in text and r"\tag{1}" in text
    assert "eq10" in (tmp_path / "generated" / "errata.tex").read_text()
    assert "5 claims" in (tmp_path / "generated" / "verification.tex").read_text()


def test_staleness_is_detected_file_by_file(few_results, tmp_path):
    committed = tmp_path / "committed"
    appendix.generate(committed, few_results, figures=False)
    assert appendix.stale(committed, results=few_results, figures=False) == []
    (committed / "generated" / "n2.tex").write_text("edited by hand\n")
    (committed / "main.tex").unlink()
    (committed / "generated" / "old.tex").write_text("a fragment nothing generates any more\n")
    assert sorted(appendix.stale(committed, results=few_results, figures=False)) == [
        "generated/n2.tex", "generated/old.tex (no longer generated)", "main.tex",
    ]


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex: make tex installs it (make test does)")
def test_generated_latex_compiles_without_errors_or_overfull_lines(few_results, tmp_path):
    appendix.generate(tmp_path, few_results, figures=False)
    # The figures are not part of this subset: stub them with any PDF of ours.
    (tmp_path / "figures").mkdir()
    for name in ("shots", "phases", "end_of_sliding", "work_precision"):
        shutil.copy(appendix.PAPER / "figures" / "work_precision.pdf", tmp_path / "figures" / f"{name}.pdf")
    assert appendix.compile_pdf(tmp_path) == []


def test_paper_check_names_the_stale_files(monkeypatch, capsys):
    from paper.cli import main

    monkeypatch.setattr(appendix, "stale", lambda *a, **k: ["generated/n7.tex"])
    assert main(["paper", "--check"]) == 1
    assert "generated/n7.tex" in capsys.readouterr().err
    monkeypatch.setattr(appendix, "stale", lambda *a, **k: [])
    assert main(["paper", "--check"]) == 0


def test_a_claim_whose_derivation_raised_is_shown_without_its_form(tmp_path):
    def underivable():
        raise ArithmeticError("(7)-(8) do not have the structure of (12)")

    eq1 = next(c for c in verification.all_claims() if c.id == "eq1")
    broken = dataclasses.replace(eq1, derived=underivable)
    appendix.generate(tmp_path, [(broken, broken.check())], figures=False)
    text = (tmp_path / "generated" / "n2.tex").read_text()
    assert appendix._breakable("eq1") in text and "Not derived: the derivation raised ArithmeticError; failed." in text
    assert "1 failed" in (tmp_path / "generated" / "verification.tex").read_text()
