"""Appell (1911), n°9–n°11: the reduction of the sliding phase to an Abel equation, and beyond.

`n9_reduced_system` writes (7)–(8) as (12)–(14) in x = fV, y = δΩ, θ = β − α;
`n10_special_case` integrates a = c; `n11_abel` follows Appell to
z' = z³ − z² + λz(1 − z)²; `abel` holds the general theory of Abel equations
(normal form, invariants s₃, s₅, J); `normal_form` and `invariants` apply it
to Appell's equation, where the paper stopped.
"""

from __future__ import annotations


def sections() -> tuple:
    """The modules with claims of n°9–n°11 and beyond, in order."""
    from reduction import invariants, n9_reduced_system, n10_special_case, n11_abel, normal_form

    return (n9_reduced_system, n10_special_case, n11_abel, normal_form, invariants)


def claims() -> list:
    """Every claim of n°9–n°11 and beyond, in order."""
    return [claim for section in sections() for claim in section.claims()]
