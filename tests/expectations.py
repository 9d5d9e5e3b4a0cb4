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

# The digits each numeric-only claim must reach, pinned: lowering one makes the check easier to pass and nothing
# else would show it (a mutation audit lowered n11.trajectory's 25 to 2 unseen).
REQUIRED_DIGITS = {
    "normal.tau_mpmath": 30, "inv.general_numeric": 30, "n3.closed_form_mpmath": 28, "n4.closed_form_mpmath": 28,
    "n7.closed_form_mpmath": 28, "n2.pivot_mpmath": 28, "n8.integral_11_mpmath": 28, "n9.y_minus_x_mpmath": 28,
    "n9.cartesian_is_reduced": 28, "n8.energy_mpmath": 28, "n8.end_exponent_mpmath": 10,
    "straight.closed_form_mpmath": 18, "cartesian_route.agrees_mpmath": 25, "n8.spin_near_zero_mpmath": 30,
    "n10.closed_form_mpmath": 30, "n10.recovery_mpmath": 30, "n11.trajectory": 25,
}
