"""The appendix's own references: cited by key, initials tied to their surname, mpmath's the pinned version."""

import re
from pathlib import Path
from importlib.metadata import version

import pytest

from paper import bibliography


def test_a_citation_names_a_reference_of_the_list():
    assert bibliography.cite("appell1911", "mpmath") == r"\appellcite{appell1911}, \appellcite{mpmath}"
    with pytest.raises(KeyError, match="no reference 'appell1912'"):
        bibliography.cite("appell1912")


def test_an_authors_initials_never_end_a_line():
    """"E.~S. Cheb-Terrab" let a line break between S. and Cheb-Terrab (a bibliography check)."""
    for key, text in bibliography.REFERENCES.items():
        authors = text.split(r"\emph")[0]
        assert not re.search(r"(?<![A-Za-z])[A-Z]\. ", authors), key


def test_mpmath_is_cited_at_the_version_the_appendix_is_generated_with():
    assert f"(version {version('mpmath')})" in bibliography.REFERENCES["mpmath"]


def test_every_reference_is_cited_in_the_appendix_and_every_citation_listed():
    """A reference no sentence cites is padding; a package the appendix measures against (scipy, heyoka) uncited
    was a referee's point: both directions, over the committed fragments."""
    paper = Path(bibliography.__file__).resolve().parent
    text = "".join(path.read_text(encoding="utf-8") for path in [paper / "appendix.tex", *sorted(paper.glob("generated/*.tex"))])
    cited = set(re.findall(r"\\appellcite\{([^}]+)\}", text))
    assert cited == set(bibliography.REFERENCES)
