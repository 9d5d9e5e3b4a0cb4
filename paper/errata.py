"""The errata: each place where the printed paper (as transcribed) does not follow.

Printed forms are the OCR quoted verbatim; corrected forms are generated
from the claim's SymPy objects through the paper's notation, never retyped.
"""

from __future__ import annotations

from derivation.claim import ERRATUM_CLASSES, Claim, Verdict, errata_summary


def errata(results: list[tuple[Claim, Verdict]]) -> list[dict]:
    """One entry per claim whose printed form was shown to differ, with the check's verdict."""
    return [
        {
            "id": claim.id,
            "where": claim.where,
            "kind": claim.erratum.kind,
            "class": ERRATUM_CLASSES[claim.erratum.kind],
            "printed": claim.printed_tex,
            "corrected": claim.corrected_tex,
            "reason": claim.erratum.reason,
            "status": verdict.status,
        }
        for claim, verdict in results
        if claim.erratum is not None
    ]


def checked(status: str) -> str:
    """Nothing when the check shows the paper printed differently, as the entry says; else what it found."""
    return "" if status == "erratum" else f"; but its check {status}: this erratum does not stand"


def as_text(entries: list[dict]) -> str:
    out = []
    for e in entries:
        out += [
            f"{e['id']}  ({e['where']}; {e['class']}{checked(e['status'])})",
            f"  printed:   {e['printed']}",
            f"  corrected: {e['corrected']}",
            f"  reason:    {e['reason']}",
            "",
        ]
    out.append(f"{len(entries)} differences from the printed form: {errata_summary([e['kind'] for e in entries])}")
    return "\n".join(out)
