"""The LaTeX appendix: sections in the paper's order, each claim as printed | derived | verdict, the rules
its LaTeX keeps (the paper's tags once, prefixed labels), staleness, compilation."""

import dataclasses
import re
import shutil

import pytest
import sympy as sp

from derivation.claim import Verdict
from paper import appendix, claim_blocks, display, verification


def test_sections_follow_the_paper():
    assert appendix.section_of("n°7, eq. (10)") == "n°7"
    assert appendix.section_of("beyond n°8: straight shots") == "beyond n°8: straight shots"
    # The paper's numbers go on the paper's numbered equations only (the claims eq1 … eq14).
    assert claim_blocks.tag_of("eq10") == "10" and claim_blocks.tag_of("route2.eq7") is None
    assert claim_blocks.tag_of("n2.pivot") is None


@pytest.fixture(scope="module")
def few_results():
    claims = verification.all_claims()
    chosen = ("eq1", "eq2", "eq7", "route2.eq7", "eq10", "n7.f1_below_f", "n8.hypothesis", "n8.theta_right_angle",
              "inv.s3", "n10.closed_form_mpmath")
    return verification.check_all([c for c in claims if c.id in chosen])


def _fragments(tmp_path, results):
    appendix.generate(tmp_path, results, figures=False)
    return {p.name: p.read_text() for p in (tmp_path / "generated").glob("*.tex")}


def test_every_claim_reads_printed_derived_verdict_with_the_papers_tag_once(few_results, tmp_path):
    text = "".join(_fragments(tmp_path, few_results).values())
    for claim, _ in few_results:
        assert claim_blocks.label_of(claim.id) in text
    for wide in (True, False):  # as a line of either width reads it (a display laid out twice has its tag twice)
        shown = claim_blocks.one_layout(text, wide)
        assert shown.count(r"\appelltag{7}") == 1  # eq7 carries (7); route2.eq7, the same equation by Kane, does not
        assert shown.count(r"\appelltag{10}") == 1 and shown.count(r"\appelltag{1}") == 1 and r"\tag{" not in shown
    eq7 = text[text.index("{appell:claim:eq7}"):text.index("{appell:claim:route2.eq7}")]
    assert "Printed (transcription):" in eq7 and "Derived:" in eq7 and "Verdict:" in eq7
    assert r"\sin(\beta - \alpha)" in eq7.split("Derived:")[1]  # the paper's arrangement, not SymPy's sin(α − β)


def test_an_inequality_shows_as_one_and_a_glyph_record_shows_what_is_meant(few_results, tmp_path):
    fragments = _fragments(tmp_path, few_results)
    n7 = fragments["n7.tex"]
    f1 = n7[n7.index("{appell:claim:n7.f1-below-f}"):]
    assert r"< f" in f1.split("Derived:")[1].split("Verdict")[0]  # f₁ = δR/(R² + k²) < f
    n8 = fragments["n8.tex"]
    hypothesis = n8[n8.index("{appell:claim:n8.hypothesis}"):n8.index("{appell:claim:n8.theta-right-angle}")]
    assert r"$\delta < fR$" in hypothesis and "Derived:" not in hypothesis  # δ < fR, not "δ − fR = −Rf + δ"
    assert "glyph only" in hypothesis


def test_a_verdict_names_its_numeric_check_only_where_it_is_not_the_usual_one():
    """A referee: "30 digits at 5 points" closed 83 verdicts and "sign at 5 points, 30 digits" 28 more.  The methods
    paragraph says it once; a verdict keeps it where it is another check (one point, fewer digits) or failed."""
    (parabola,) = [c for c in verification.all_claims() if c.id == "n3.parabola"]
    (bound,) = [c for c in verification.all_claims() if getattr(c, "is_inequality", False) and c.erratum is None][:1]

    def said(claim, status, symbolic, numeric):
        return claim_blocks.verdict_text(claim, Verdict(claim.id, claim.where, status, symbolic, numeric))

    assert said(parabola, "confirmed", "exact", "30 digits at 5 points").endswith("derived = reading, exact.")
    assert said(bound, "confirmed", "proved", "sign at 5 points, 30 digits").endswith(r"\emph{confirmed}: proved.")
    assert said(parabola, "confirmed", "exact", "30 digits at 1 point").endswith("exact; 30 digits at 1 point.")
    assert said(parabola, "confirmed", "exact", "27 digits at 5 points").endswith("exact; 27 digits at 5 points.")
    assert said(bound, "confirmed", "proved", "sign at 4 points, 30 digits").endswith("proved; sign at 4 points, 30 digits.")
    assert "30 digits at 5 points" in said(parabola, "failed", "exact", "30 digits at 5 points")
    methods = (appendix.PAPER / "generated" / "methods.tex").read_text()
    assert "A verdict names its numeric check only where it is not all 30 digits at all 5 points" in methods


def test_appells_number_tags_his_equation_not_the_meaning_of_a_sentence_and_a_glyph_is_the_transcriptions():
    """A referee: "(9)" stood on max Ω' = (fR − δ)g/k² > 0, which is not Appell's (9) (δ < fR, a sentence), and an
    OCR glyph's verdict said "printed differently", blaming the 1911 paper for our copy's slip."""
    claims = {c.id: c for c in verification.all_claims()}

    def block(claim_id, status):
        claim = claims[claim_id]
        return claim_blocks.claim_block(claim, Verdict(claim.id, claim.where, status, "exact", "30 digits at 5 points"))

    assert r"\appelltag{9}" not in block("eq9", "confirmed") and r"\appelltag{10}" in block("eq10", "erratum")
    assert r"\appelltag{12}" in block("eq12", "confirmed")
    assert r"\emph{transcription differs}" in block("eq2", "erratum")
    assert r"\emph{printed differently}" in block("eq10", "erratum")


def test_a_sentence_of_the_paper_shows_the_reading_it_is_compared_with(monkeypatch):
    """A referee's audit: "derived = printed, exact" under a French sentence did not say what was compared.  The
    claim's reading of the sentence in symbols (`Claim.printed`) is shown as Read as, and the verdict names it."""
    (parabola,) = [c for c in verification.all_claims() if c.id == "n3.parabola"]
    verdict = Verdict(parabola.id, parabola.where, "confirmed", "exact", "30 digits at 5 points")
    block = claim_blocks.claim_block(parabola, verdict)

    def shown_reading(text):  # under "Read as:", or "Read as, and derived:" where the two are one display
        return re.split(r"Derived:|Verdict:", text.split("Read as")[1])[0]

    reading = shown_reading(block)
    assert r"\xi'' = - f g" in reading and "derived = reading, exact" in block
    # The reading is the claim's own printed form: another one shows as another display.
    wrong = dataclasses.replace(parabola, printed=[sp.Eq(sp.Symbol("xi''"), 2 * sp.Symbol("f"))])
    assert r"2 f" in shown_reading(claim_blocks.claim_block(wrong, verdict))
    # A reading given in the order to read (`Claim.reading`) is shown instead of SymPy's order: −mgδΩ, not −Ωδgm.
    (rolling,) = [c for c in verification.all_claims() if c.id == "n8.energy_all_phases"]
    shown = claim_blocks.claim_block(rolling, Verdict(rolling.id, rolling.where, "confirmed", "exact", "30 digits"))
    assert r"= - m g \delta \Omega" in shown_reading(shown)
    plain = claim_blocks.claim_block(dataclasses.replace(rolling, reading=None), Verdict(rolling.id, rolling.where, "confirmed", "exact", "30 digits"))
    assert r"= - m g \delta \Omega" not in shown_reading(plain)
    # A formula of the paper is compared as printed: no reading shown.
    (eq10,) = [c for c in verification.all_claims() if c.id == "eq10"]
    assert "Read as" not in claim_blocks.claim_block(eq10, Verdict("eq10", eq10.where, "erratum", "exact", "30 digits"))


def test_every_numbered_equation_of_the_paper_shows_its_print():
    """A referee's audit: (9), the hypothesis δ < fR, said "Beyond the paper: no printed form", and the paper prints
    it.  Every claim tagged with one of Appell's numbers quotes the transcription; a display in a quoted sentence
    ($$…$$) is set in its line."""
    tagged = [c for c in verification.all_claims() if claim_blocks.tag_of(c.id)]
    assert len(tagged) >= 14 and [c.id for c in tagged if not c.printed_tex] == []
    (eq9,) = [c for c in tagged if c.id == "eq9"]
    assert "(9)" in eq9.printed_tex and r"\delta < fR" in eq9.printed_tex
    assert claim_blocks.quotation(r"pour que $$(9) \quad \delta < fR.$$") == (
        r"\begin{quote}``pour que $(9) \quad \delta < fR.$''\end{quote}")


def test_a_quoted_sentence_is_followed_by_its_translation():
    """A referee: no translation of the French quotes.  Each sentence is followed by ours, in italics, its formulas
    as quoted."""
    block = claim_blocks.quotation(r"le mouvement parabolique du centre")
    assert block == r"\begin{quote}``le mouvement parabolique du centre''\par\textit{the parabolic motion of the centre}\end{quote}"
    quote = r"où le second membre est négatif à cause de l'hypothèse $\hat{c} < fR$"
    assert claim_blocks.quotation(quote).endswith(
        r"\textit{where the right-hand side is negative because of the hypothesis $\hat{c} < fR$}\end{quote}")


def test_a_formula_quoted_from_a_sentence_is_set_as_a_quotation():
    """n°8's $\\hat{c} < fR$ is a formula (its letters are tied to its reading) quoted from a sentence: it is set in
    quotation marks, never as $…$ inside a display (a LaTeX error)."""
    block = claim_blocks.printed_block(r"$\hat{c} < fR$")
    assert block == r"\begin{quote}``$\hat{c} < fR$''\end{quote}"
    assert claim_blocks.printed_block(r"y - x = A,").startswith(r"\begin{equation*}")


def test_a_long_form_is_broken_not_shrunk(few_results, tmp_path):
    text = "".join(_fragments(tmp_path, few_results).values())
    assert r"\resizebox" not in text and r"\appellfit" not in text
    s3 = text[text.index("{appell:claim:inv.s3}"):]
    assert r"\Bigl(" in s3 and r"&\quad" in s3  # (a − c)(9b² − …)/(27b³cos³θ) opened round its long factor


def test_a_display_is_laid_out_for_a_narrow_column_and_for_a_page_where_the_two_differ():
    """A referee: displays broken for a two-column journal's column stayed broken on a one-column page (main.pdf
    was 43 pages); each is now written for both, and the line it stands on picks (appell-appendix.sty)."""
    terms = [r"- \frac{R\delta}{k^2} g \cos(\beta - \alpha)", r"+ \frac{R^2}{k^2} g \sin\beta"] * 2
    shown = claim_blocks.forms_display([[r"V^{\prime} &= - f g \cos\alpha", *terms]], tag="7")
    assert shown.startswith(claim_blocks.WIDE_OR_NARROW)
    wide, narrow = claim_blocks.one_layout(shown, True), claim_blocks.one_layout(shown, False)
    for layout, column in ((wide, display.ONE_COLUMN), (narrow, display.COLUMN)):
        assert layout.count(r"\appelltag{7}") == 1 and claim_blocks.WIDE_OR_NARROW not in layout
        lines = layout.split(r"\begin{aligned}")[1].split(r"\end{aligned}")[0].split(r"\\")
        assert max(display.tex_width(line.replace("&", "")) for line in lines) <= column - display.TAG_ROOM
    assert wide.count(r"\\") < narrow.count(r"\\") and display.tex_width(wide) > display.COLUMN
    # one layout where they agree; a printed formula too wide for a column stands whole on a page's line
    assert claim_blocks.forms_display([[r"V^{\prime} &= - f g \cos\alpha"]]) == r"\begin{equation*}V^{\prime} = - f g \cos\alpha\end{equation*}"
    printed = (r"\left\{\begin{aligned}V' &= -fg\cos\alpha - \frac{R\delta}{k^2}g\cos(\beta - \alpha) + \frac{R^2}{k^2}"
               r"g\sin\beta\cos\beta,\\ V\alpha' &= -\frac{R\delta}{k^2}g\cos(\beta - \alpha).\end{aligned}\right.")
    assert display.COLUMN < display.tex_width(printed) <= display.ONE_COLUMN
    page = claim_blocks.one_layout(claim_blocks.printed_display(printed), True)
    assert page == r"\begin{equation*}" + printed + r"\end{equation*}"  # the paper's brace kept
    assert r"\\" in claim_blocks.one_layout(claim_blocks.printed_display(printed), False)


def test_one_layout_reads_nested_and_escaped_braces():
    fit = claim_blocks.fitted(r"\left\{ a \right. {b}", r"c \} {d}")
    assert claim_blocks.one_layout(f"x {fit} y {fit}", True) == r"x \left\{ a \right. {b} y \left\{ a \right. {b}"
    assert claim_blocks.one_layout(f"x {fit} y", False) == r"x c \} {d} y"
    with pytest.raises(ValueError, match="unclosed"):
        claim_blocks.one_layout(fit[:-1], False)


def test_a_long_heading_gives_a_short_title_for_running_heads_and_n_o_that_capitals_leave_alone():
    """In a thesis (the appendix a chapter) the long titles overfilled the running heads by up to 105 pt, and
    their capitals turned n°5 into N^O5 (a referee's drop-in test): book-chapter.tex compiles it (--pdf)."""
    head = appendix.heading("n°5 — The hypothesis δ < fR (9): what needs it", "n5")
    assert head.startswith(r"\appellsubsection[\texorpdfstring{\appellno{}5 --- The hypothesis $\delta < f R$ (9)}{")
    assert r"{\texorpdfstring{\appellno{}5 --- The hypothesis $\delta < f R$ (9): what needs it}" in head
    assert appendix.heading("Errata", "errata").startswith(r"\appellsubsection{\texorpdfstring{Errata}")
    # The bookmark keeps the whole title: the three "Beyond n°8" subsections are told apart in the PDF's outline.
    beyond = appendix.heading("beyond n°8: straight shots", "straight")
    assert beyond.startswith(r"\appellsubsection[\texorpdfstring{") and "]{" in beyond
    assert "straight shots" in beyond[:beyond.index("]{")]


def test_a_figure_reference_is_tied_to_its_word():
    """"Figure ~\\ref" left a space beside the tie (a referee's nit): the tie replaces it."""
    text = appendix._prose_with_refs("Figure [fig:phases] follows V.")
    assert text == r"Figure~\ref{appell:fig:phases} follows $V$."


def test_the_latex_rules_are_checked_before_writing():
    base = {"generated/a.tex": r"\label{appell:sec:a} see \ref{appell:sec:a}"}
    appendix.check_latex(base)
    with pytest.raises(appendix.GenerationError, match=r"\(5\) shown more than once"):
        appendix.check_latex({**base, "generated/b.tex": r"\tag{5} x \tag{5}"})
    with pytest.raises(appendix.GenerationError, match=r"\(4\) shown more than once"):
        appendix.check_latex({**base, "generated/b.tex": r"\appelltag{4} x \appelltag{4}"})
    with pytest.raises(appendix.GenerationError, match="without the appell: prefix: sec:b"):
        appendix.check_latex({**base, "generated/b.tex": r"\label{sec:b}"})
    with pytest.raises(appendix.GenerationError, match="more than once: appell:sec:a"):
        appendix.check_latex({**base, "generated/b.tex": r"\label{appell:sec:a}"})
    with pytest.raises(appendix.GenerationError, match="undefined label.*appell:bib:nobody"):
        appendix.check_latex({**base, "generated/b.tex": r"\appellcite{nobody}"})
    # a display written for two widths holds its tag and label in each: one of them is typeset
    both = claim_blocks.fitted(r"\appelltag{4}\label{appell:eq:4}", r"\appelltag{4}\label{appell:eq:4} x")
    appendix.check_latex({**base, "generated/b.tex": both})
    for twice in (both + r"\appelltag{4}", both + r"\label{appell:eq:4}"):
        with pytest.raises(appendix.GenerationError, match="more than once"):
            appendix.check_latex({**base, "generated/b.tex": twice})
    with pytest.raises(appendix.GenerationError, match="undefined label.*appell:eq:5"):  # in the narrow one only
        appendix.check_latex({**base, "generated/b.tex": claim_blocks.fitted(r"\label{appell:eq:5}", "x") + r"\ref{appell:eq:5}"})


def test_a_duplicated_paper_equation_fails_generation(few_results, tmp_path):
    eq7, verdict = next((c, v) for c, v in few_results if c.id == "eq7")
    twice = few_results + [(dataclasses.replace(eq7, where="n°9"), verdict)]
    with pytest.raises(appendix.GenerationError, match=r"\(7\) shown more than once"):
        appendix.generate(tmp_path, twice, figures=False)


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


def test_regeneration_is_byte_identical_supplement_included(few_results, tmp_path):
    first, second = tmp_path / "a", tmp_path / "b"
    appendix.generate(first, few_results, figures=False)
    appendix.generate(second, few_results, figures=False)
    for path in first.rglob("*"):
        if path.is_file() and path.name != ".appell-paper":
            assert path.read_bytes() == (second / path.relative_to(first)).read_bytes(), path


@pytest.mark.slow  # regenerates the whole appendix twice (a minute)
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
    assert "none (the derivation raised)" in text and r"\emph{failed}: derivation raised" in text
    assert "1 failed" in (tmp_path / "generated" / "verification.tex").read_text()


@pytest.mark.slow  # pdflatex: main.tex and ten host documents, a few seconds each
@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex: make tex installs it (make test does)")
def test_the_appendix_compiles_alone_and_in_every_host_without_errors_or_overfull_boxes(few_results, tmp_path):
    appendix.generate(tmp_path, few_results, figures=False)
    # The figures are not part of this subset: stub them with any PDF of ours.
    (tmp_path / "figures").mkdir()
    for name in appendix.FIGURES:
        shutil.copy(appendix.PAPER / "figures" / "work_precision.pdf", tmp_path / "figures" / f"{name}.pdf")
    compiled = appendix.compile_pdf(tmp_path)
    assert set(compiled) == {"main", "article-onecolumn", "article-twocolumn", "amsart", "revtex-reprint", "article-default",
                             "ieeetran", "mnras", "book-chapter", "article-twocolumn-11pt", "amsart-12pt"}
    for document, result in compiled.items():
        assert result["problems"] == [], document
        assert result["pages"] >= 2, document


def test_every_figure_has_a_short_caption_for_a_list_of_figures():
    """A referee: each caption holds every parameter of its scenes, which a host's \\listoffigures would print whole."""
    from paper import appendix, figures
    from paper.latex_text import tex_text

    assert set(figures.SHORT_CAPTIONS) == set(appendix.FIGURES)  # every figure the appendix places, and no other
    for name in appendix.FIGURES:
        short = figures.SHORT_CAPTIONS[name]
        tex = appendix.figure(name)
        assert f"\\caption[{tex_text(short)}]{{" in tex
        long = tex[tex.index("]{") + 2: tex.index(r"\label")]
        assert len(short) < 80 and 3 * len(short) < len(long), name


def _as_recorded(status_of=lambda claim: None):
    """Every claim with the verdict its erratum implies (or ``status_of``'s), as the record would hold it."""
    out = []
    for claim in verification.all_claims():
        status = status_of(claim) or ("erratum" if claim.erratum is not None else "confirmed")
        out.append((claim, Verdict(claim.id, claim.where, status, "exact", "")))
    return out


def test_the_findings_paragraph_counts_and_names_the_paper_s_own_errors():
    """The findings open the appendix (a referee found the record and the errata only at its end): the counts
    are the record's, each error of the paper is named with its claim and what is wrong, the glyphs counted."""
    from derivation.claim import NumericCheck

    results = _as_recorded()
    text = appendix.findings_tex(results)
    # counted as the claims are labelled: a printed form or sentence, "Beyond the paper", a numeric cross-check
    # (counted by the words 'beyond n°…' of their place, 15 claims labelled beyond the paper were the paper's)
    quoted = [c for c, _ in results if c.printed_tex]  # "Printed (transcription)"
    beyond = [c for c, _ in results if not c.printed_tex and not isinstance(c, NumericCheck)]  # "Beyond the paper"
    own = len(results) - len(quoted) - len(beyond)
    assert own and all(isinstance(c, NumericCheck) for c, _ in results if c not in quoted + beyond)
    assert (f"{len(results)} claims are checked: {len(quoted)} check a formula or a sentence as the paper prints it, "
            f"{len(beyond)} go beyond it (labelled so), and {own} are numerical checks of our own") in text
    differs = [c for c, _ in results if c.erratum is not None]
    of_paper = [c for c in differs if c.erratum.kind != "ocr"]
    premises = [c for c, _ in results if getattr(c, "premise", None)]
    assert premises and all(c.erratum is None for c in premises)
    assert (f"{len(results) - len(differs)} are confirmed ({len(premises)} of them laws and definitions the "
            "derivation takes as printed) and no check fails") in text
    assert f"The other {len(differs) - len(of_paper)} differences are glyphs" in text
    assert "The paper has one mathematical erratum: in n\\textsuperscript{o}7, eq. (10)" in text
    assert "The paper has one remark, a minor slip: in n\\textsuperscript{o}8" in text
    for claim in of_paper:
        assert claim.erratum.summary, f"{claim.id}: an error of the paper needs its summary for the findings"
        assert claim_blocks.label_of(claim.id) in text
    for sentence, ids in appendix.BEYOND_FINDINGS:
        assert all(claim_blocks.label_of(i) in text for i in ids)


def test_a_finding_beyond_the_paper_is_stated_only_when_its_claims_hold():
    failing = appendix.BEYOND_FINDINGS[-1][1][0]
    results = _as_recorded(lambda claim: "failed" if claim.id == failing else None)
    text = appendix.findings_tex(results)
    assert claim_blocks.label_of(failing) not in text
    assert "1 fails (Section~\\ref{appell:sec:verification})" in text and "no check fails" not in text
    assert claim_blocks.label_of(appendix.BEYOND_FINDINGS[0][1][0]) in text


def test_the_findings_follow_the_introduction():
    text = appendix.appendix_tex(["n2"])
    assert text.index("generated/findings}") < text.index("generated/methods}")


def test_a_premise_s_verdict_says_it_is_the_derivation_s_input():
    """The friction laws and Ω's definition are what the derivation starts from: their 'confirmed' says so."""
    claims = {c.id: c for c in verification.all_claims()}
    for cid, words in (("n2.friction", "a law the model takes from the paper"), ("eq3", "a definition, so that")):
        text = claim_blocks.verdict_text(claims[cid], Verdict(cid, claims[cid].where, "confirmed", "exact", "30 digits at 5 points"))
        assert words in text
    plain = claim_blocks.verdict_text(claims["eq4"], Verdict("eq4", "", "confirmed", "exact", "30 digits at 5 points"))
    assert "the derivation" not in plain


def _with_errata(kinds: dict[str, str]):
    """The record with the claims of ``kinds`` (id -> erratum kind) as the only ones printed differently, the others
    confirmed: built with dataclasses.replace, so that the findings meet cases the paper does not have."""
    from derivation.claim import Erratum

    out = []
    for claim, verdict in _as_recorded():
        if claim.id in kinds:
            kind = kinds[claim.id]
            erratum = Erratum(kind, "a reason", glyphs={sp.Symbol("zeta"): sp.Symbol("xi")} if kind == "ocr" else {},
                              summary="" if kind == "ocr" else f"what is wrong in {claim.id}")
            claim = dataclasses.replace(claim, erratum=erratum)
            verdict = dataclasses.replace(verdict, status="erratum")
        elif claim.erratum is not None:
            claim, verdict = dataclasses.replace(claim, erratum=None), dataclasses.replace(verdict, status="confirmed")
        out.append((claim, verdict))
    return out


def test_the_findings_read_right_for_other_records():
    """Several errata of one kind, one glyph, none at all, failed claims (a review: '2 remarks, a minor slip',
    'All 1 differences are glyphs', '2 failed' beside 'no check fails')."""
    two = appendix.findings_tex(_with_errata({"n2.normal": "remark", "n2.pivot": "remark", "eq6": "mathematical"}))
    assert "The paper has 2 remarks, minor slips: in " in two and "The paper has one mathematical erratum: in " in two
    assert "glyph" not in two and "lists them with the corrections" in two
    one = appendix.findings_tex(_with_errata({"n2.normal": "ocr"}))
    assert "The one difference is a glyph our transcription shows wrong" in one and "its meaning" in one
    assert "The paper has" not in one and "lists it with the corrections" in one
    after = appendix.findings_tex(_with_errata({"eq6": "mathematical", "n2.normal": "ocr", "n2.pivot": "ocr"}))
    assert "The other 2 differences are glyphs" in after
    none = appendix.findings_tex(_with_errata({}))
    assert "differ" not in none and "Section~\\ref{appell:sec:errata}" not in none
    failing = [(c, dataclasses.replace(v, status="failed") if c.id in ("eq6", "n2.pivot") else v) for c, v in _with_errata({})]
    assert "and 2 fail (Section~\\ref{appell:sec:verification})" in appendix.findings_tex(failing)


def test_the_record_says_how_its_numeric_only_count_meets_the_findings_own_checks():
    """The findings counted 16 numerical checks of our own, the record 19 'numeric only' (a referee read them as
    disagreeing: three quoted claims are checked by numbers too); the record says how many are the findings'."""
    from derivation.claim import NumericCheck

    results = _as_recorded()
    own = [c for c, _ in results if isinstance(c, NumericCheck) and not c.printed_tex]
    quoted = [c for c, _ in results if c.printed_tex][:3]
    numeric = {c.id for c in own + quoted}
    record = [(c, dataclasses.replace(v, symbolic="numeric only") if c.id in numeric else v) for c, v in results]
    text = appendix.verification_tex(record)
    assert f"{len(own) + 3} numeric only ({len(own)} of them the numerical checks of our own)" in text
    assert f"{len(own)} are numerical checks of our own" in appendix.findings_tex(record)
    alone = [(c, dataclasses.replace(v, symbolic="numeric only") if c in own else v) for c, v in results]
    text = appendix.verification_tex(alone)  # all of them the findings': nothing to add
    assert f"{len(own)} numeric only" in text and "of them the numerical checks" not in text


def test_a_premise_whose_check_fails_does_not_say_what_it_shows():
    claims = {c.id: c for c in verification.all_claims()}
    text = claim_blocks.verdict_text(claims["n2.friction"], Verdict("n2.friction", "", "failed", "exact", "x"))
    assert "the derivation uses it as printed" not in text


def test_a_reading_that_is_the_derived_display_is_shown_once():
    """11 claims showed the same display under Read as and under Derived (a referee): once, labelled both; a
    printed formula keeps its own display beside the derived one, and a reading that differs keeps both."""
    claims = {c.id: c for c in verification.all_claims()}

    def block(cid):
        return claim_blocks.claim_block(claims[cid], Verdict(cid, claims[cid].where, "confirmed", "exact", "30 digits at 5 points"))

    once = block("n3.parabola")
    assert "Read as, and derived:" in once and "Read as:" not in once and "Derived:" not in once
    assert once.count(r"\xi'' = - f g") == 1
    printed = block("n3.alpha")  # a formula of the paper: printed, then derived
    assert "Printed (transcription):" in printed and "Derived:" in printed and "and derived" not in printed
    differs = block("n2.symmetry")  # read term by term, derived as SymPy gives it
    assert "Read as:" in differs and "Derived:" in differs


def test_a_claim_beyond_the_paper_shows_its_short_stated_side():
    """Δ = … without "= 0" (a referee): a claim with no printed form ends each derived row with its stated side when
    that is short and not already what the row shows (V + ΩR is not repeated after ΩR + V)."""
    claims = {c.id: c for c in verification.all_claims()}

    def ends(cid):  # each derived row, its pieces joined
        return [" ".join(pieces) for pieces in claim_blocks.derived_rows(claims[cid])]

    assert ends("normal.tau_series")[0].endswith(r"- \gamma = 0")
    mirror = ends("inv.mirror")
    assert mirror[0].endswith(r"= - \mathcal{F}(z)") and mirror[1].endswith(r"= J(a, b, c)")
    assert ends("normal.tau_integrand")[1] == r"\ln\mathcal{R}(0) &= 0"  # already the stated side
    assert ends("straight.centre")[0].endswith(r"&= \Omega R + V")  # its stated V + ΩR is what the row shows
