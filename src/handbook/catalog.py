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

    Numbers whose status is misprint, inconsistent or wrong method, equations whose printed form does not
    agree with its derivation (other than by a rounded constant) and the textual errata. Each row names its
    source document in ``note`` and carries the case against the source: ``quote`` (the passages, each as
    [document, text], the disputed one first), ``confidence``, ``charitable`` (the most charitable reading,
    answered) and ``places`` (every other place the same fact shows). With ``note`` given, only that
    document's rows. Reconstructions of lost OCR are not errata: see :func:`reading_notes`.
    """
    rows = []
    for src in _chosen(note, "errata"):
        rows += _errata_of(src)
    return rows


def reading_notes(note: str | None = None) -> list[dict]:
    """What is not an error of the source: equations reconstructed from a garbled OCR, figures the OCR lost,
    what the public record lacks and the book's own readings; rows of ``id``, ``note``, ``source``, ``what``
    and ``note_text``."""
    rows = []
    for src in _chosen(note, "reading_notes"):
        for s in src.equation_summaries():
            if s["reconstructed"] and not _equation_erratum(s):
                rows.append({"id": s["id"], "note": src.name, "source": s["source"], "what": s["title"],
                             "note_text": s["reconstructed"]})
        rows += [{"id": r.id, "note": src.name, "source": r.source, "what": r.what, "note_text": r.note}
                 for r in src.reading_notes]
    return rows


def _chosen(note: str | None, what: str) -> list:
    known = [s.name for s in sources()]
    if note is not None and note not in known:
        raise ValueError(f"{what}: no source document {note!r}; known: {', '.join(known)}")
    return [s for s in sources() if note is None or s.name == note]


def _equation_erratum(s: dict) -> bool:
    return (not s["agrees"] and s["relation"] == "differs" and not s["rounded_constants"]) or not s["dimensions_ok"]


def _case(src, ident: str, places: dict) -> dict:
    """The case against the source for erratum ``ident``: its passages, confidence, charitable reading, and the
    places of the same fact (its own list, then every record marked ``same_fact=ident``)."""
    case = src.cases.get(ident)
    also = places.get(ident, [])
    if case is None:
        return {"quote": [], "confidence": "", "charitable": "", "places": also}
    return {"quote": [list(q) for q in case.passages(src.name)], "confidence": case.confidence,
            "charitable": case.charitable, "places": list(case.places) + also}


def _same_fact_places(src) -> dict:
    """Erratum id -> 'where: what' of every record of ``src`` that names it as ``same_fact``."""
    places: dict = {}
    for c in src.claims():
        if c.same_fact:
            places.setdefault(c.same_fact, []).append(f"{c.where}: {c.quantity}, printed {c.printed}")
    for t in src.errata:
        if t.same_fact:
            places.setdefault(t.same_fact, []).append(f"{t.source}: {t.what}")
    return places


def _errata_of(src) -> list[dict]:
    rows = []
    by_id = {c.id: c for c in src.claims()}
    places = _same_fact_places(src)
    for r in src.evaluate():
        if r["status"] in ("misprint", "inconsistent", "wrong method") and not by_id[r["id"]].same_fact:
            rows.append({"id": r["id"], "note": src.name, "source": r["source"], "kind": r["status"],
                         "what": r["quantity"], "printed": r["printed_text"], "recomputed": r["computed"],
                         "unit": r["unit"], "evidence": r["reason"], "consequence": r["consequence"],
                         **_case(src, r["id"], places)})
    for s in src.equation_summaries():
        if _equation_erratum(s):
            rows.append({"id": s["id"], "note": src.name, "source": s["source"], "what": s["title"],
                         "printed": s["printed_latex"], "recomputed": None, "unit": "", "kind": "equation",
                         "evidence": s["note"], "consequence": "see the chapter",
                         **_case(src, s["id"], places)})
    for t in src.errata:
        if t.same_fact:
            continue
        rows.append({"id": t.id, "note": src.name, "source": t.source, "kind": "text", "what": t.what,
                     "printed": "", "recomputed": None, "unit": "", "evidence": t.evidence,
                     "consequence": t.consequence, **_case(src, t.id, places)})
    return rows


__all__ = ["ORDER", "claims", "equation_summaries", "errata", "reading_notes", "sources"]
