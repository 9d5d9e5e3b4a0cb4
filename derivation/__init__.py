"""Appell (1911), n°1–n°8, re-derived from first principles with SymPy.

The data flow starts here: `newton_euler` and `kane` give the equations of
motion by two routes, `polar` writes them as (7)–(8), and one module per
section of the paper (`n2_motion` … `n8_general`) derives its results and
states them as claims (`claim.Claim`) against the printed forms.
"""

from __future__ import annotations

from derivation.claim import Claim


def sections() -> tuple:
    """The modules with claims of n°1–n°8, in the order of the paper, then the straight shots beyond it."""
    from derivation import n2_motion, n3_classical, n4_ideal, n5_hypothesis, n6_rolling_returns, n7_pure_rolling, n8_general, straight_shot

    return (n2_motion, n3_classical, n4_ideal, n5_hypothesis, n6_rolling_returns, n7_pure_rolling, n8_general, straight_shot)


def claims() -> list[Claim]:
    """Every claim of n°1–n°8, in order."""
    return [claim for section in sections() for claim in section.claims()]
