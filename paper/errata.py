"""The errata: each place where the printed paper (as transcribed) does not follow.

Printed forms are the OCR quoted verbatim; corrected forms are generated
from the claim's SymPy objects through the paper's notation, never retyped.
"""

from __future__ import annotations

from derivation.claim import Claim, Verdict

KIND_NAMES = {"ocr": "likely OCR artefact", "mathematical": "mathematical discrepancy"}


def errata(results: list[tuple[Claim, Verdict]]) -> list[dict]:
    """One entry per claim whose printed form was shown to differ, with the check's verdict."""
    return [
        {
            "id": claim.id,
            "where": claim.where,
            "kind": claim.erratum.kind,
            "class": KIND_NAMES[claim.erratum.kind],
            "printed": claim.printed_tex,
            "corrected": claim.corrected_tex,
            "reason": claim.erratum.reason,
            "status": verdict.status,
        }
        for claim, verdict in results
        if claim.erratum is not None
    ]


def as_text(entries: list[dict]) -> str:
    out = []
    for e in entries:
        out += [
            f"{e['id']}  ({e['where']}; {e['class']}; check: {e['status']})",
            f"  printed:   {e['printed']}",
            f"  corrected: {e['corrected']}",
            f"  reason:    {e['reason']}",
            "",
        ]
    kinds = {k: sum(e["kind"] == k for e in entries) for k in KIND_NAMES}
    out.append(f"{len(entries)} errata: {kinds['ocr']} likely OCR artefacts, {kinds['mathematical']} mathematical")
    return "\n".join(out)
