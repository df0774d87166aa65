"""The errata chapter's tables: counts, entries with the case against the source, reading notes, and the
decisions a review of the errata led to."""
from __future__ import annotations

from IPython.display import Markdown

from ..core.claim import CONFIDENCE
from .tables import ERRATA_KINDS, _printed_and_recomputed, readable, table


def errata_counts(rows: list[dict], notes: list[dict] | None = None) -> Markdown:
    """How many errata each source document has, by kind and by confidence, and (given ``notes``) how many
    reading notes beside them, as a table."""
    docs = list(dict.fromkeys([r["note"] for r in rows] + [n["note"] for n in notes or []]))
    kinds = [k for k in ERRATA_KINDS if any(r["kind"] == k for r in rows)]
    sure = [c for c in CONFIDENCE if any(r["confidence"] == c for r in rows)]

    def line(name, rs, ns):
        return ([name] + [sum(r["kind"] == k for r in rs) for k in kinds] + [sum(r["confidence"] == c for r in rs) for c in sure]
                + [len(rs)] + ([len(ns)] if notes is not None else []))

    body = [line(d, [r for r in rows if r["note"] == d], [n for n in notes or [] if n["note"] == d]) for d in docs]
    body.append(line("all", rows, notes or []))
    head = (["source"] + [ERRATA_KINDS[k] for k in kinds] + [c for c in sure] + ["errata"]
            + (["reading notes"] if notes is not None else []))
    return table(head, body)


def _sentence(text: str) -> str:
    text = str(text).strip()
    return text if text.endswith((".", "!", "?")) else text + "."


#: how a quoted document is named to the reader
_DOCUMENTS = {"datasheet facts": "the device datasheets, as read for this book"}


def _quoted(note: str, quote: list) -> str:
    """The passages verbatim (as the OCR reads them), each named by its document when it is another one."""
    parts = []
    for doc, text in quote:
        code = "`` " + text.replace("`", "'") + " ``"
        parts.append(code if doc == note else f"{_DOCUMENTS.get(doc, doc)}: {code}")
    return "; ".join(parts)


def errata_md(rows: list[dict]) -> Markdown:
    """Errata as a list of entries (a seven-column table does not fit a book page): what, where, the passage
    disputed, the numbers, the evidence, the most charitable reading answered, the confidence, the other
    places the fact shows and what a designer should do about it."""
    if not rows:
        return Markdown("No errata.")
    items = []
    for r in rows:
        nums = readable(_printed_and_recomputed(r))
        head = (f"**{readable(r['what'])}** (`{r['id']}`; {readable(r['source'])}; *{ERRATA_KINDS[r['kind']]}*, "
                f"{r['confidence']})" + (f": {nums}." if nums else ""))
        lines = [f"- {head}", f"  The source: {_quoted(r['note'], r['quote'])}",
                 f"  Evidence: {readable(_sentence(r['evidence']))}",
                 f"  Read charitably: {readable(_sentence(r['charitable']))}"]
        if r["places"]:
            lines.append(f"  Also printed at: {readable('; '.join(r['places']))}.")
        lines.append(f"  For a designer: {readable(_sentence(r['consequence']))}")
        items.append("\\\n".join(lines))
    return Markdown("\n".join(items))


def reading_notes_md(rows: list[dict]) -> Markdown:
    """Reading notes (not errors of the source) as a list: what, where, and how the book reads it."""
    if not rows:
        return Markdown("No reading notes.")
    return Markdown("\n".join(f"- **{readable(r['what'])}** ({readable(r['source'])}): {readable(_sentence(r['note_text']))}"
                               for r in rows))


def review_table(review, said: str = "review said") -> Markdown:
    """A review of the errata and what was decided about each id it questioned: the review's verdict (headed
    ``said``), the decision and why."""
    return table(["id", said, "decision", "why"],
                 [[d.id, readable(d.verdict), d.outcome, readable(d.why)] for d in review.decisions])
