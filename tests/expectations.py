"""What each claim's check must reach, pinned.  A proof that falls back to a sample, or an identity that no longer
reduces exactly, changes what the package can say about the paper while the verdict stays "confirmed" (a mutation
audit: with eq. (9) broken, nine inequalities went from proved to sampled and no test saw it), so the change
must be deliberate: an inequality SymPy cannot prove is named in SAMPLED."""

from derivation.checks import DENSE_SAMPLES
from derivation.claim import NumericCheck

SAMPLED: frozenset[str] = frozenset()  # inequalities checked on dense samples only, not proved: none today


def expected_symbolic(claim) -> str:
    """The symbolic column a claim's verdict must show (`Claim.check`)."""
    if isinstance(claim, NumericCheck):
        return "numeric only"
    if claim.glyph_only:
        return "glyph only"
    if claim.is_inequality:
        return f"sampled ({DENSE_SAMPLES} points)" if claim.id in SAMPLED else "proved"
    return "exact"
