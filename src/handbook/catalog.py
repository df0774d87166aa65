"""Every source module's equations, numeric examples and textual errata, in book order."""
from __future__ import annotations

from . import an93008, an94002, lm4651, tca5600, tda5341

#: source modules in book order; each offers equations(), examples() and TEXT_ERRATA
SOURCES = (an94002, an93008, tda5341, lm4651, tca5600)


def equations():
    return [e for m in SOURCES for e in m.equations()]


def examples():
    return [r for m in SOURCES for r in m.examples()]


def text_errata():
    return [t for m in SOURCES for t in m.TEXT_ERRATA]


def errata() -> list[dict]:
    """Every misprint and inconsistency of every source, generated from the registries.

    Numbers whose status is misprint or inconsistent, equations whose printed form does not agree with
    its derivation (other than by a rounded constant), and the textual errata.
    """
    rows = []
    for r in examples():
        if r["status"] in ("misprint", "inconsistent"):
            rows.append({"id": r["id"], "source": r["source"], "kind": r["status"], "what": r["quantity"],
                         "printed": r["printed_text"], "recomputed": r["computed"], "unit": r["unit"],
                         "evidence": r["reason"], "consequence": r["consequence"]})
    for e in equations():
        s = e.summary()
        if (not s["agrees"] and s["relation"] == "differs" and not e.rounded_constants) or not s["dimensions_ok"]:
            rows.append({"id": s["id"], "source": s["source"], "kind": "equation", "what": s["title"],
                         "printed": s["printed_latex"], "recomputed": None, "unit": "", "evidence": s["note"],
                         "consequence": "see the chapter"})
        elif e.reconstructed:
            rows.append({"id": s["id"], "source": s["source"], "kind": "reconstructed", "what": s["title"],
                         "printed": s["printed_latex"], "recomputed": None, "unit": "", "evidence": e.reconstructed,
                         "consequence": "none once reconstructed"})
    for t in text_errata():
        rows.append({"id": t.id, "source": t.source, "kind": "text", "what": t.what, "printed": "", "recomputed": None,
                     "unit": "", "evidence": t.evidence, "consequence": t.consequence})
    return rows
