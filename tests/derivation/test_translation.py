"""Every French sentence a claim quotes has our English translation, and the translation keeps its formulas."""

import re

import derivation
import reduction
from derivation import transcription, translation


def _quoted_sentences() -> set[str]:
    """The sentences the claims quote: as what the paper states, or as the context of a claim of ours."""
    claims = [*derivation.claims(), *reduction.claims()]
    stated = {c.printed_tex for c in claims if c.printed_tex and transcription.is_prose(c.printed_tex)}
    return stated | {c.context for c in claims if c.context}


def test_every_quoted_sentence_is_translated_and_every_translation_is_of_a_quote():
    quoted = _quoted_sentences()
    assert len(quoted) >= 30
    assert sorted(quoted - translation.TRANSLATIONS.keys()) == []  # a new quote needs its translation
    assert sorted(translation.TRANSLATIONS.keys() - quoted) == []  # a quote changed or gone: its translation too


def test_a_translation_keeps_the_formulas_of_its_quote():
    """The formulas are the quote's, glyphs included (ĉ, U as printed): a translation that put one right, or
    lost one, would say what the paper does not."""
    formulas = re.compile(r"\$\$[^$]*\$\$|\$[^$]*\$")  # a display $$…$$ whole, as the appendix sets it
    for quote, english in translation.TRANSLATIONS.items():
        assert formulas.findall(english) == formulas.findall(quote), quote
        assert not re.search(r"[éèàêôçù]", formulas.sub("", english)), english  # no French left
    nine = r"Nous admettrons que le coefficient $\delta$ est assez petit pour que $$(9) \quad \delta < fR.$$"
    assert formulas.findall(nine)[-1] == r"$$(9) \quad \delta < fR.$$"  # not two empty $$ (a review)


def test_a_formula_or_an_unknown_quote_has_no_translation():
    assert translation.english(r"y - x = A,") is None
    assert translation.english("puis reste nulle") == "and then remains zero"
