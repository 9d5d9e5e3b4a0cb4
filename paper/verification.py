"""The verification record: every claim of the package, checked.

`appell verify`, `appell errata` and the LaTeX appendix all read this list.
"""

from __future__ import annotations

from dataclasses import asdict

from derivation.claim import Claim, Verdict


def all_claims() -> list[Claim]:
    """Every claim, in the order of the data flow and of the paper."""
    import derivation
    import numerics
    import reduction

    return derivation.claims() + reduction.claims() + numerics.claims()


def check_all(claims: list[Claim] | None = None) -> list[tuple[Claim, Verdict]]:
    claims = all_claims() if claims is None else claims
    return [(claim, claim.check()) for claim in claims]


def as_json(results: list[tuple[Claim, Verdict]]) -> dict:
    rows = []
    for claim, verdict in results:
        row = asdict(verdict)
        row["statement"] = claim.statement
        row["printed_tex"] = claim.printed_tex
        row["erratum"] = None if claim.erratum is None else claim.erratum.kind
        rows.append(row)
    counts = {status: sum(r["status"] == status for r in rows) for status in ("confirmed", "erratum", "failed")}
    return {"claims": rows, "summary": {"total": len(rows), **counts}}


def as_table(results: list[tuple[Claim, Verdict]]) -> str:
    header = ("id", "where", "symbolic", "numeric", "status")
    rows = [(v.id, v.where, v.symbolic, v.numeric, v.status) for _, v in results]
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
    line = "  ".join("{:<%d}" % w for w in widths)
    out = [line.format(*header), line.format(*("-" * w for w in widths))]
    out += [line.format(*r) for r in rows]
    summary = as_json(results)["summary"]
    out.append(
        f"\n{summary['total']} claims: {summary['confirmed']} confirmed, "
        f"{summary['erratum']} errata in the printed paper, {summary['failed']} failed"
    )
    return "\n".join(out)
