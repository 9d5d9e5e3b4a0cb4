"""The machine-readable supplement: every claim's forms in full, as SymPy `srepr` and LaTeX.

The appendix shows each form in the paper's arrangement, broken to fit a
column; a form too long for that (or any form a reader wants to compute
with) is here whole: for each claim its id, where it stands, its status, and
the printed, derived, corrected and displayed forms, each as
``{"srepr": …, "latex": …}`` (``sympy.parse_expr`` or ``eval`` with
``from sympy import *`` reads an srepr back).  Sorted keys, no timestamps:
regeneration is byte-identical, as for the rest of paper/.
"""

from __future__ import annotations

import json

import sympy as sp

from derivation.claim import Claim, NumericCheck, Verdict
from derivation.notation import latex
from paper import claim_blocks, display


def _form(rows: list[sp.Basic] | None, printer) -> list[dict] | None:
    if rows is None:
        return None
    return [{"srepr": sp.srepr(row), "latex": printer(row)} for row in rows]


def entry(claim: Claim | NumericCheck, verdict: Verdict) -> dict:
    """One claim's record in the supplement."""
    out = {
        "id": claim.id,
        "where": claim.where,
        "status": verdict.status,
        "symbolic": verdict.symbolic,
        "numeric": verdict.numeric,
        "printed_tex": claim.printed_tex,
        "context": claim.context,
    }
    if isinstance(claim, NumericCheck):
        return out
    try:
        derived = claim.derived
    except Exception:  # the verdict says why
        return out
    out.update(
        printed=_form(claim.printed, latex),
        derived=_form(derived, latex),
        corrected=_form(claim.corrected, latex),
        display=_form(claim_blocks.derived_trees(claim), display.display_tex),
        display_where={display.display_tex(k): {"srepr": sp.srepr(v), "latex": display.display_tex(v)}
                       for k, v in claim.display_where.items()},
    )
    return out


def supplement_json(results: list[tuple[Claim, Verdict]]) -> str:
    """The supplement's text: byte-identical for the same claims and verdicts."""
    body = {
        "about": "Appell (1911), machine-checked: every claim's forms as SymPy srepr and LaTeX (appell paper).",
        "claims": [entry(claim, verdict) for claim, verdict in results],
    }
    return json.dumps(body, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
