"""The SPICE checks as the book shows them: "equation vs SPICE" tables with each tolerance's reason.

The rows come from :mod:`handbook.spice` (:func:`handbook.spice.circuit.evaluate` for a circuit of the notes,
:func:`handbook.spice.checks.confirm_rows` for a design); this module only lays them out.
"""
from __future__ import annotations

from IPython.display import Markdown

from ..core.units import eng, signed_percent
from ..spice import checks
from ..spice.referee import refereed
from ..spice.runner import SpiceError, SpiceUnavailable
from .tables import folded, readable, table


def chapter_table(*circuits, by_circuit: bool | None = None):
    """The chapters' "equation vs SPICE" table of one or more circuits (quantity, equation, SPICE, difference,
    tolerance, verdict) with each tolerance's reason below it, as Markdown; or a line saying the SPICE
    check was skipped and why when ngspice is missing. ``by_circuit`` (default: when more than one circuit is
    given) adds a first column naming each row's circuit by its title, for decks that share quantities (the
    LM4651 filter with 4 and 8 ohm, AC and transient)."""
    try:
        rows = [r for c in circuits for r in refereed(c)]
    except SpiceUnavailable as exc:
        return Markdown(f"**SPICE check skipped:** {exc}.")
    except SpiceError as exc:  # a netlist ngspice refused: said on the page, not a traceback
        return Markdown(f"**SPICE run failed:** {exc}.")
    titles = {c.id: c.title for c in circuits}
    first = (len(circuits) > 1) if by_circuit is None else by_circuit
    return rows_table(rows, lead={r["circuit"]: titles[r["circuit"]] for r in rows} if first else None)


def rows_table(rows: list[dict], equation_head: str = "equation", lead: dict | None = None):
    """Check rows (as :func:`~handbook.spice.referee.refereed` or ``checks.confirm_rows`` give them) as the book
    shows them: quantity, equation, SPICE, difference, expected difference (physics the equation leaves out,
    computed), tolerance about it, verdict; then each tolerance's reason and, where the rows carry them, the
    deliberate equation faults each check sees. ``lead``: circuit id -> title, for a first column naming each
    row's circuit."""
    name = (lambda r: [lead[r["circuit"]]]) if lead else (lambda r: [])
    body = table([*(["circuit"] if lead else []), "quantity", equation_head, "SPICE", "difference", "expected",
                  "tolerance", "verdict"],
                 [[*name(r), r["quantity"], eng(r["equation"], r["unit"]), eng(r["spice"], r["unit"]),
                   signed_percent((r["spice"] - r["equation"]) / r["equation"]),
                   signed_percent(r.get("expected_difference", 0)),
                   _tolerance(r["rtol"]), r["verdict"] if r["agrees"] else
                   "**differs**" + (f"; {r['caveat']}" if r.get("caveat") else "")] for r in rows])
    # one line per reason: rows that share a tolerance and its reason (a filter's corner, Q and gain; the same check
    # at three temperatures) are named together instead of repeating the paragraph for each
    groups: dict[tuple, list[str]] = {}
    for r in rows:
        key = (_tolerance(r["rtol"]), r["kind"] == "sanity", r["why"])
        groups.setdefault(key, []).append(f"{''.join(t + ', ' for t in name(r))}*{r['quantity']}*")
    why = "\n".join(f"- {'; '.join(dict.fromkeys(names))}, {tol}"
                    + (" (a sanity check: it agrees by construction)" if sanity else "") + f": {reason}."
                    for (tol, sanity, reason), names in groups.items())
    n = len(groups)
    out = body.data + "\n\n" + folded(f"Why each tolerance ({n} reason{'s' * (n != 1)})", readable(why)).data
    if any("faults_seen" in r for r in rows):
        out += "\n\n" + faults_list(rows).data
    return Markdown(out)


def faults_list(rows: list[dict]):
    """The mutation check as the chapter shows it: each deliberate fault of :data:`handbook.spice.referee.FAULTS`
    put into the equations of these rows' circuits, and the checks that see it (folded)."""
    from ..spice.referee import FAULTS

    lines, unseen = [], 0
    for cid in dict.fromkeys(r["circuit"] for r in rows):
        for fault in FAULTS.get(cid, ()):
            by = [r for r in rows if r["circuit"] == cid and fault.label in r.get("faults_seen", ())]
            independent = [r for r in by if r["kind"] == "independent"]
            unseen += not independent
            who = ", ".join(f"*{r['quantity']}*" for r in (independent or by))
            lines.append(f"- {fault.label}: seen by {who}" + ("" if independent else
                         " (by construction only: no independent check of this circuit)" if by else
                         "**seen by no check**"))
    title = (f"Faults put into the equations ({len(lines)}; each seen by an independent check)" if not unseen else
             f"Faults put into the equations ({len(lines)}; {unseen} seen by no independent check)")
    return folded(title, readable("Each fault is put into the equation's function and the circuit's equation "
                                  "column computed again against the same simulation: a check sees the fault when "
                                  "it then differs.\n\n" + "\n".join(lines)))


def _tolerance(rtol: float) -> str:
    """±0.5 %, ±0.05 %, ±0.00052 %: enough figures to show a tight tolerance as it is, never an exponent."""
    from ..spice.bounds import percent

    return percent(rtol) if rtol > 0 else f"±{rtol * 100:g} %"


def confirm_table(table: str, result):
    """The design chapters' "Confirmed by simulation" table: quantity, the design's figure, SPICE's, the
    difference, the tolerance and the verdict, with each tolerance's reason below; or why it was skipped."""
    try:
        rows = checks.confirm_rows(table, result)
    except SpiceUnavailable as exc:
        return Markdown(f"*SPICE check skipped: {exc}.*")
    except SpiceError as exc:
        return Markdown(f"**SPICE run failed:** {exc}.")
    return rows_table(rows, equation_head="design (equations)")
