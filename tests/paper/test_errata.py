"""The errata list (`paper.errata`, and its LaTeX items in `paper.claim_blocks`): each entry by its class, and
what its check found only when the check does not bear it out."""

from derivation.claim import Verdict
from paper import claim_blocks, errata, verification

ENTRY = {"id": "eq2", "where": "n°2, eq. (2)", "kind": "ocr", "class": "transcription artefact", "printed": "a",
         "corrected": "b", "reason": "the transcription puts a dot", "status": "erratum"}


def test_an_entry_says_its_class_and_its_check_only_when_it_fails():
    """"check: erratum" on every line said nothing a reader could use; a failed check must still show."""
    assert errata.as_text([ENTRY]).splitlines()[0] == "eq2  (n°2, eq. (2); transcription artefact)"
    failed = errata.as_text([{**ENTRY, "status": "failed"}]).splitlines()[0]
    assert failed == "eq2  (n°2, eq. (2); transcription artefact; but its check failed: this erratum does not stand)"


def test_a_latex_item_gives_its_reason_after_a_colon_and_says_a_failed_check():
    claims = {c.id: c for c in verification.all_claims()}  # listed: nothing derived
    claim = claims["eq2"]
    head = claim_blocks.erratum_item(claim, Verdict("eq2", claim.where, "erratum", "exact", "")).splitlines()[0]
    # a colon, not a full stop: a reason may begin with a formula (sin(β − α) ≤ 1 ...), which takes no capital
    assert "transcription artefact): the transcription puts a dot" in head and "check" not in head
    head = claim_blocks.erratum_item(claim, Verdict("eq2", claim.where, "failed", "exact", "")).splitlines()[0]
    assert "but its check failed: this erratum does not stand): the transcription" in head


def test_an_erratum_keeps_the_status_its_check_found():
    """`appell errata` exits 1 on an entry whose check failed: `errata.errata` must list every claim with an erratum
    and carry its verdict's status (a mutation audit: dropping such entries, or writing "erratum" for every one,
    passed; so did showing nothing for a check that came out "confirmed")."""
    claims = {c.id: c for c in verification.all_claims()}  # listed: nothing derived
    results = [(claims["eq2"], Verdict("eq2", claims["eq2"].where, "failed", "exact", "")),
               (claims["eq10"], Verdict("eq10", claims["eq10"].where, "confirmed", "exact", "")),
               (claims["eq1"], Verdict("eq1", claims["eq1"].where, "confirmed", "exact", ""))]
    entries = errata.errata(results)
    assert [(e["id"], e["status"]) for e in entries] == [("eq2", "failed"), ("eq10", "confirmed")]
    confirmed = errata.as_text([{**ENTRY, "status": "confirmed"}]).splitlines()[0]
    assert confirmed.endswith("; but its check confirmed: this erratum does not stand)")


def test_the_paper_s_errata_come_first_with_their_displays_and_the_glyphs_one_line_each():
    """The two errata a reader looks for came among thirteen OCR glyphs, and each glyph's printed and corrected
    displays were shown a second time (its claim shows them): the paper's first, in full; then one line a glyph."""
    from paper import appendix

    results = [(c, Verdict(c.id, c.where, "erratum", "exact", "")) for c in verification.all_claims()
               if getattr(c, "erratum", None) is not None]
    text = appendix.errata_tex(results)
    of_paper, of_copy = text.split(r"\emph{Of the transcription.}")
    paper_ids = [c.id for c, _ in results if c.erratum.kind != "ocr"]
    copy_ids = [c.id for c, _ in results if c.erratum.kind == "ocr"]
    assert paper_ids and copy_ids
    for claim_id in paper_ids:  # each with its printed and corrected forms
        assert f"{{appell:claim:{claim_id.replace('_', '-')}}}" in of_paper
    assert of_paper.count(r"\item ") == len(paper_ids) == of_paper.count("Corrected:") == of_paper.count("Printed:")
    # one line a misreading, naming every place it occurs (ζ read for ξ took four lines, a referee)
    misreadings = {tuple(sorted(map(str, {**c.erratum.glyphs, **c.erratum.tex}.items())))
                   for c, _ in results if c.erratum.kind == "ocr"}
    assert of_copy.count(r"\item ") == len(misreadings) < len(copy_ids)
    assert "equation" not in of_copy and "Printed:" not in of_copy
    for claim_id in copy_ids:
        assert of_copy.count(f"{{appell:claim:{claim_id.replace('_', '-')}}}") == 1
    assert r"\item $\zeta$ read for $\xi$: " in of_copy
    assert all(line.startswith(r"\item ") for line in of_copy.split(r"\begin{appellerrata}")[1].splitlines()[1:-1])
    assert f"{len(results)} places" in of_paper
