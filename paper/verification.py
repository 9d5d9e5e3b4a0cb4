"""The verification record: every claim of the package, checked.

`appell verify`, `appell errata` and the LaTeX appendix all read this list.
"""

from __future__ import annotations

import multiprocessing
import os
import re
import sys
from dataclasses import asdict

from derivation.claim import ERRATUM_CLASSES, Claim, NumericCheck, Verdict, errata_summary
from numerics.workers import fork_pool
from paper.output import SettingError

_PENDING: list[Claim] = []  # the claims a forked worker checks, by index


def all_claims() -> list[Claim]:
    """Every claim, in the order of the data flow and of the paper."""
    import derivation
    import numerics
    import reduction

    sections = [section for package in (derivation, reduction, numerics) for section in package.sections()]
    return [claim for section in sections for claim in _claims_of(section)]


def _claims_of(section) -> list[Claim]:
    """The claims of one module.  Listing them runs no derivation, so it should not raise; if it
    does, one failed check named after the module stands for them, and every other module's still run."""
    try:
        return section.claims()
    except Exception as error:
        failure = error  # `error` is unbound once the except clause ends; the check raises it again

        def listing():
            raise failure

        name = section.__name__
        return [NumericCheck(name, name, f"The claims of {name}, which could not be listed.", None, listing, 0)]


def _check(index: int) -> Verdict:
    return _PENDING[index].check()


def jobs() -> int:
    """Worker processes: $APPELL_JOBS, at most one per available core (the checks are CPU-bound: 10000 forked 149
    processes on two cores), or one per core."""
    cores = len(os.sched_getaffinity(0))
    value = os.environ.get("APPELL_JOBS", "").strip()
    if not value:
        return cores
    # (At most 9 digits: Python refuses to read a number of 4,300, with a traceback.)
    if not re.fullmatch(r"[0-9]{1,9}", value) or int(value) < 1:
        shown = repr(value) if len(value) <= 40 else f"{value[:20]!r}… ({len(value)} characters)"
        raise SettingError(f"APPELL_JOBS: a whole number of worker processes, at least 1; got {shown}")
    return min(int(value), cores)


def check_all(claims: list[Claim] | None = None, progress=None) -> list[tuple[Claim, Verdict]]:
    """Check every claim, in worker processes when there is more than one core.

    The checks are independent and CPU-bound (SymPy, mpmath), so forked
    workers divide the wall time; the record is in the claims' order.
    ``progress(done)`` is called as verdicts come in.
    """
    claims = all_claims() if claims is None else claims
    n = min(jobs(), len(claims))
    verdicts = []
    if n <= 1 or "fork" not in multiprocessing.get_all_start_methods():
        for claim in claims:
            verdicts.append(claim.check())
            if progress:
                progress(len(verdicts))
        return list(zip(claims, verdicts))
    _PENDING[:] = claims
    try:
        with fork_pool(n) as pool:
            for verdict in pool.imap(_check, range(len(claims)), chunksize=1):
                verdicts.append(verdict)
                if progress:
                    progress(len(verdicts))
    finally:
        _PENDING.clear()
    return list(zip(claims, verdicts))


def verify(claims: list[Claim] | None = None, quiet: bool = False) -> list[tuple[Claim, Verdict]]:
    """Check every claim (progress on stderr when it is a terminal); a whole record is kept (`paper.record`)."""
    from paper import record
    from paper.progress import Progress

    whole = claims is None
    claims = all_claims() if whole else claims
    bar = Progress(len(claims), "claims checked", quiet)
    results = check_all(claims, bar.update)
    bar.close()
    if whole and record.save(record_of(results)) is None:  # else every later command checks them all again, silently
        print(f"appell: cannot keep the verification record in {record.path().parent} ($APPELL_CACHE sets the "
              "folder): the next command checks every claim again", file=sys.stderr)
    return results


def named(ids: list[str]) -> tuple[list[Claim], list[str]]:
    """The claims with these ids (as the table shows them), in the order given, and the ids no claim has."""
    by_id = {claim.id: claim for claim in all_claims()}  # listing derives nothing
    return [by_id[i] for i in ids if i in by_id], [i for i in ids if i not in by_id]


def explained(claim: Claim, verdict: Verdict) -> str:
    """One claim in words, for a reader without the code: what it says, as printed, as corrected, as derived
    (SymPy's plain text; the appendix shows it typeset), and what the check found."""
    import sympy as sp

    lines = [f"{claim.id} — {claim.where}: {claim.statement}"]
    if claim.printed_tex is not None:
        lines.append(f"  printed:   {claim.printed_tex}")
    if claim.context:
        lines.append(f"  context:   {claim.context} (the paper's; the claim is ours)")
    if claim.erratum is not None:
        lines.append(f"  corrected: {claim.corrected_tex}")
    if isinstance(claim, Claim) and verdict.symbolic != "derivation raised":
        lines += [f"  derived:   {sp.sstr(form)}" for form in claim.derived]
    lines.append(f"  verdict:   {shown_status(claim, verdict)} — symbolic: {verdict.symbolic}; numeric: {verdict.numeric}")
    if claim.erratum is not None:
        lines.append(f"  reason:    {claim.erratum.reason}")
    if verdict.note:
        lines.append(f"  why:       {verdict.note}")
    return "\n".join(lines)


def record_of(results: list[tuple[Claim, Verdict]]) -> dict:
    """What the record keeps: the verdicts as `appell verify --json` prints them, and the errata."""
    from paper import errata

    return {"verify": as_json(results), "errata": errata.errata(results)}


def recorded(quiet: bool = False) -> dict:
    """The record of every claim: the kept one when it matches the source and versions (saying so on
    stderr), else every claim verified now."""
    import sys

    from paper import record

    kept = record.load()
    if kept is None or [row["id"] for row in kept["verify"]["claims"]] != [c.id for c in all_claims()]:
        if not quiet:  # said even when piped: the minutes before the first answer are not a hang
            why = record.unwritable()
            kept_or_not = ("kept for the next run" if why is None else
                           f"not kept: {why}, and $APPELL_CACHE sets the folder")
            print("appell: no verification record of this source and these versions yet: checking every claim first "
                  f"(a minute or two; {kept_or_not})", file=sys.stderr, flush=True)
        return record_of(verify(quiet=quiet))
    if not quiet:
        print(f"appell: answering from the verification record {record.path()} (same source and versions; "
              "'appell verify' checks again)", file=sys.stderr)
    return kept


def results_from(kept: dict, claims: list[Claim] | None = None) -> list[tuple[Claim, Verdict]]:
    """(claim, verdict) pairs from a record's verdicts, for the claims that are in it."""
    fields = Verdict.__dataclass_fields__
    verdicts = {row["id"]: Verdict(**{k: v for k, v in row.items() if k in fields}) for row in kept["verify"]["claims"]}
    claims = all_claims() if claims is None else claims
    return [(claim, verdicts[claim.id]) for claim in claims]


def as_json(results: list[tuple[Claim, Verdict]]) -> dict:
    rows = []
    for claim, verdict in results:
        row = asdict(verdict)
        row["statement"] = claim.statement
        row["printed_tex"] = claim.printed_tex
        row["context"] = claim.context
        row["erratum"] = None if claim.erratum is None else claim.erratum.kind
        row["class"] = None if claim.erratum is None else ERRATUM_CLASSES[claim.erratum.kind]
        rows.append(row)
    counts = {status: sum(r["status"] == status for r in rows) for status in ("confirmed", "erratum", "failed")}
    classes = {kind: sum(r["erratum"] == kind and r["status"] == "erratum" for r in rows) for kind in ERRATUM_CLASSES}
    glyph_records = sum(r["symbolic"] == "glyph only" for r in rows)
    return {"claims": rows, "summary": {"total": len(rows), **counts, "errata by class": classes, "glyph records": glyph_records}}


# What the table's columns say, printed under it (a reader of `appell verify` need not read the code).
LEGEND = """\
symbolic: exact — SymPy reduced the difference of the two sides to 0 (the derived form against the printed one,
          or against its correction where the paper is printed differently); proved — an inequality's sign proved
          over the physical parameters under eq. (9); sampled (N points) — its sign checked at N points only, not
          proved (a strict inequality, < or >, must be proved: sampled it fails); glyph only — the meant form
          typed and tied to the print by its glyphs, not derived; numeric only — a statement about motions,
          checked on high-precision integrations alone
numeric:  the same again in high-precision arithmetic at points of the physical parameters, or on the cases of
          a numeric-only claim (a check of its own: SymPy failing to reach 0 proves nothing either way)
status:   confirmed — the printed form follows; else how it is printed differently: mathematical erratum (it
          does not follow), remark (a slip nothing after it uses), transcription artefact (a glyph of the OCR
          copy); `appell errata` shows each beside its correction; failed — the derivation does not give it"""


def shown_status(claim: Claim, verdict: Verdict) -> str:
    """A verdict's status as the table shows it: an erratum by its class (mathematical, remark, transcription)."""
    return ERRATUM_CLASSES[claim.erratum.kind] if verdict.status == "erratum" and claim.erratum else verdict.status


def as_table(results: list[tuple[Claim, Verdict]]) -> str:
    header = ("id", "where", "symbolic", "numeric", "status")
    rows = [(v.id, v.where, v.symbolic, v.numeric, shown_status(c, v)) for c, v in results]
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
    line = "  ".join("{:<%d}" % w for w in widths)
    out = [line.format(*header).rstrip(), line.format(*("-" * w for w in widths))]
    out += [line.format(*r).rstrip() for r in rows]
    # Only a failed verdict carries a note: the reason (a derivation that raised, an erratum that does not stand).
    notes = [f"{v.id}: {v.note}" for _, v in results if v.note]
    if notes:
        out += ["", "Why they failed:", *notes]
    summary = as_json(results)["summary"]
    kinds = [v.erratum.kind for v, verdict in results if v.erratum is not None and verdict.status == "erratum"]
    out.append(
        f"\n{summary['total']} claims: {summary['confirmed']} confirmed, "
        f"{summary['erratum']} printed differently ({errata_summary(kinds)}), {summary['failed']} failed; "
        f"{summary['glyph records']} of them glyph records (the meant form typed, not derived)"
    )
    out += ["", LEGEND]
    return "\n".join(out)
