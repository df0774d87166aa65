"""Every source module's equations, numeric examples and textual errata, in book order."""
from __future__ import annotations

from . import an93008, an94002, lm4651, tca5600, tda5341

#: source modules in book order; each offers equations(), examples() and TEXT_ERRATA
SOURCES = (an94002, an93008, tda5341, lm4651, tca5600)


def equations():
    return [e for m in SOURCES for e in m.equations()]


def examples():
    return [r for m in SOURCES for r in m.examples()]


def errata(note: str | None = None) -> list[dict]:
    """Every misprint and inconsistency of every source, generated from the registries, source by source.

    Numbers whose status is misprint or inconsistent, equations whose printed form does not agree with
    its derivation (other than by a rounded constant), equations reconstructed from a garbled OCR, and
    the textual errata. Each row names its source document in ``note`` (``an94002.NOTE`` ...); with
    ``note`` given, only that document's rows.
    """
    known = [m.NOTE for m in SOURCES]
    if note is not None and note not in known:
        raise ValueError(f"errata: no source document {note!r}; known: {', '.join(known)}")
    rows = []
    for m in SOURCES:
        if note is not None and m.NOTE != note:
            continue
        for r in m.examples():
            if r["status"] in ("misprint", "inconsistent"):
                rows.append({"id": r["id"], "note": m.NOTE, "source": r["source"], "kind": r["status"],
                             "what": r["quantity"], "printed": r["printed_text"], "recomputed": r["computed"],
                             "unit": r["unit"], "evidence": r["reason"], "consequence": r["consequence"]})
        for e in m.equations():
            s = e.summary()
            if (not s["agrees"] and s["relation"] == "differs" and not e.rounded_constants) or not s["dimensions_ok"]:
                rows.append({"id": s["id"], "note": m.NOTE, "source": s["source"], "kind": "equation",
                             "what": s["title"], "printed": s["printed_latex"], "recomputed": None, "unit": "",
                             "evidence": s["note"], "consequence": "see the chapter"})
            elif e.reconstructed:
                rows.append({"id": s["id"], "note": m.NOTE, "source": s["source"], "kind": "reconstructed",
                             "what": s["title"], "printed": s["printed_latex"], "recomputed": None, "unit": "",
                             "evidence": e.reconstructed, "consequence": "none once reconstructed"})
        for t in m.TEXT_ERRATA:
            rows.append({"id": t.id, "note": m.NOTE, "source": t.source, "kind": "text", "what": t.what,
                         "printed": "", "recomputed": None, "unit": "", "evidence": t.evidence,
                         "consequence": t.consequence})
    return rows
