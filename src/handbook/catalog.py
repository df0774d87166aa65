"""Every source document's claims, equations and errata, in book order (the registry and errata chapters
and the command line read them from here)."""
from __future__ import annotations

from .sources import ORDER


def sources() -> tuple:
    from . import sources as pkg

    return pkg.SOURCES


def equation_summaries() -> list[dict]:
    """Every equation's summary, from the on-disk check cache where it is current."""
    return [{**s, "note_name": src.name} for src in sources() for s in src.equation_summaries()]


def claims() -> list[dict]:
    """Every printed number of every source, recomputed with the source's own values."""
    return [r for src in sources() for r in src.evaluate()]


def errata(note: str | None = None) -> list[dict]:
    """Every misprint and inconsistency of every source, generated from the registries, source by source.

    Numbers whose status is misprint or inconsistent, equations whose printed form does not agree with
    its derivation (other than by a rounded constant), equations reconstructed from a garbled OCR, and
    the textual errata. Each row names its source document in ``note``; with ``note`` given, only that
    document's rows.
    """
    known = [s.name for s in sources()]
    if note is not None and note not in known:
        raise ValueError(f"errata: no source document {note!r}; known: {', '.join(known)}")
    rows = []
    for src in sources():
        if note is None or src.name == note:
            rows += _errata_of(src)
    return rows


def _errata_of(src) -> list[dict]:
    rows = []
    for r in src.evaluate():
        if r["status"] in ("misprint", "inconsistent", "wrong method"):
            rows.append({"id": r["id"], "note": src.name, "source": r["source"], "kind": r["status"],
                         "what": r["quantity"], "printed": r["printed_text"], "recomputed": r["computed"],
                         "unit": r["unit"], "evidence": r["reason"], "consequence": r["consequence"]})
    for s in src.equation_summaries():
        base = {"id": s["id"], "note": src.name, "source": s["source"], "what": s["title"],
                "printed": s["printed_latex"], "recomputed": None, "unit": ""}
        if (not s["agrees"] and s["relation"] == "differs" and not s["rounded_constants"]) or not s["dimensions_ok"]:
            rows.append({**base, "kind": "equation", "evidence": s["note"], "consequence": "see the chapter"})
        elif s["reconstructed"]:
            rows.append({**base, "kind": "reconstructed", "evidence": s["reconstructed"],
                         "consequence": "none once reconstructed"})
    for t in src.errata:
        rows.append({"id": t.id, "note": src.name, "source": t.source, "kind": "text", "what": t.what,
                     "printed": "", "recomputed": None, "unit": "", "evidence": t.evidence,
                     "consequence": t.consequence})
    return rows


__all__ = ["ORDER", "claims", "equation_summaries", "errata", "sources"]
