"""The design report's page: one self-contained HTML document (styles inside, images inline as SVG or data: URIs,
math as MathML, no script, nothing fetched), with the handbook's version and the spec's SHA-256 in a header and a
footer on screen and in the running footer of every printed page."""
from __future__ import annotations

import base64
import html
import io
import re

from ...core.units import readable
from ..tables import shown_value

esc = html.escape

#: the styles of the report's content (tables, figures, math, notes): the page's and the book's form's alike
CONTENT_CSS = """
table { border-collapse: collapse; margin: 8px 0 14px; font-size: 13px; }
th, td { border: 1px solid #bbb; padding: 3px 6px; vertical-align: top; text-align: left; }
th { background: #eef1f5; }
td.num, th.num { text-align: right; white-space: nowrap; }
.scroll { overflow-x: auto; max-width: 100%; }
figure { margin: 10px 0 18px; }
figure svg, figure img { max-width: 100%; height: auto; }
figcaption { font-size: 12px; color: #444; }
.note { color: #555; font-style: italic; }
.warn { color: #8a1c00; }
.ok { color: #145214; }
details > summary { cursor: pointer; font-weight: bold; margin: 6px 0; }
math { font-size: 1.05em; }
.calc-math { margin: 0.9em 0; line-height: 2.2; overflow-x: auto; max-width: 100%; }
.calc-step { margin-bottom: 1.2em; }
"""

#: screen and print styles of the page; the running footer's text is filled in per report (:func:`document`)
CSS = """
:root { color-scheme: light; }
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; font-size: 14px; line-height: 1.45;
       max-width: 1100px; margin: 0 auto; padding: 0 16px; color: #1b1b1b; }
h1 { font-size: 26px; margin: 16px 0 4px; } h2 { font-size: 21px; margin-top: 30px; border-bottom: 2px solid #345; }
h3 { font-size: 17px; margin-top: 22px; }
.trace { font-size: 12px; color: #333; background: #f6f7f9; border: 1px solid #ccd; padding: 6px 10px;
         overflow-wrap: anywhere; }
""" + CONTENT_CSS + """
@page { size: A4; margin: 16mm 13mm 20mm 13mm;
        @bottom-left { content: "__FOOTER__"; font-size: 7.5pt; color: #333; }
        @bottom-right { content: "page " counter(page) " of " counter(pages); font-size: 8pt; } }
@media print {
  body { max-width: none; padding: 0; font-size: 10.5pt; }
  footer.trace { display: none; }
  details::details-content { content-visibility: visible !important; display: block !important; }
  h2, h3, h4 { break-after: avoid; } figure, tr { break-inside: avoid; }
  table { font-size: 8.5pt; } .scroll, .calc-math { overflow: visible; }
}
"""


def scoped(css: str, scope: str) -> str:
    """Rules of plain CSS (no @-rules) with every selector put under ``scope``.

    Parameters
    ----------
    css : str
        ``selector, selector { declarations }`` rules, one a line.
    scope : str
        The enclosing selector (".design-report").

    Returns
    -------
    str
        The scoped rules.
    """
    out = []
    for rule in filter(None, (r.strip() for r in css.split("}"))):
        sel, decl = rule.split("{", 1)
        out.append(", ".join(f"{scope} {x.strip()}" for x in sel.split(",")) + " {" + decl + "}")
    return "\n".join(out)


def fragment(body_html: str) -> str:
    """A section of the report as the book shows it: its HTML inside ``<div class="design-report">`` with the
    report's content styles scoped to that box (:data:`CONTENT_CSS`), so the book's own styles are untouched.

    Parameters
    ----------
    body_html : str
        The section's body.

    Returns
    -------
    str
        HTML.
    """
    return f'<div class="design-report"><style>{scoped(CONTENT_CSS, ".design-report")}</style>{body_html}</div>'


def table(header: list[str], rows: list[list[str]], numeric: tuple[int, ...] = ()) -> str:
    """An HTML table in a box that scrolls sideways on a narrow screen; ``rows`` hold HTML already escaped.

    Parameters
    ----------
    header : list of str
        Column titles (plain text, escaped here).
    rows : list of list of str
        The cells, as HTML.
    numeric : tuple of int
        Columns set right-aligned (numbers).

    Returns
    -------
    str
        The table's HTML.
    """
    cls = lambda k: ' class="num"' if k in numeric else ""  # noqa: E731
    head = "".join(f"<th{cls(k)}>{esc(h)}</th>" for k, h in enumerate(header))
    body = "".join("<tr>" + "".join(f"<td{cls(k)}>{c}</td>" for k, c in enumerate(r)) + "</tr>" for r in rows)
    return f'<div class="scroll"><table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>'


def value(key: str, v, unit: str) -> str:
    """A value as a person reads it (:func:`~handbook.report.tables.shown_value`), wrapped in ``<data>`` carrying
    the exact number (``repr``) and its key: what a reader sees and what a script checks against ``design
    --json`` are the same value.

    Parameters
    ----------
    key : str
        ``table.key`` of the value.
    v : object
        The value (SI units; a fraction where ``unit`` is "%").
    unit : str
        Its unit as the result or the schema declares it.

    Returns
    -------
    str
        HTML: ``<data>`` for a number, the escaped text otherwise.
    """
    shown = esc(readable(shown_value(v, unit)))
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return f'<data value="{float(v)!r}" data-key="{esc(key)}">{shown}</data>'
    return shown


def inline_svg(data: bytes | str, prefix: str) -> str:
    """An SVG file's text ready to sit inside the page: no XML prolog or doctype, every id (and every reference
    to one) prefixed, so that two drawings' clip paths never collide.

    Parameters
    ----------
    data : bytes or str
        The SVG document (matplotlib's output).
    prefix : str
        A prefix unique to this drawing in the page.

    Returns
    -------
    str
        The ``<svg>`` element.
    """
    text = data.decode("utf-8") if isinstance(data, bytes) else data
    text = text[text.index("<svg"):]
    text = re.sub(r'\bid="([^"]+)"', lambda m: f'id="{prefix}-{m.group(1)}"', text)
    text = re.sub(r'url\(#([^)]+)\)', lambda m: f"url(#{prefix}-{m.group(1)})", text)
    return re.sub(r'href="#([^"]+)"', lambda m: f'href="#{prefix}-{m.group(1)}"', text)


def figure_svg(fig, prefix: str, caption: str) -> str:
    """A matplotlib figure (:class:`matplotlib.figure.Figure`) inline as SVG (text kept as text, same bytes
    each time), with its caption.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure (closed by the garbage collector: no pyplot state is used).
    prefix : str
        Its ids' prefix in the page (:func:`inline_svg`).
    caption : str
        Plain text.

    Returns
    -------
    str
        ``<figure>`` HTML.
    """
    import matplotlib

    buf = io.StringIO()
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": prefix}):
        fig.savefig(buf, format="svg", bbox_inches="tight", metadata={"Date": None})
    return f"<figure>{inline_svg(buf.getvalue(), prefix)}<figcaption>{esc(caption)}</figcaption></figure>"


def data_uri_png(data: bytes) -> str:
    """A PNG as a data: URI (for an ``<img>``)."""
    return "data:image/png;base64," + base64.b64encode(data).decode("ascii")


def note(text: str) -> str:
    """A one-line note (a section left out, and why)."""
    return f'<p class="note">{esc(text)}</p>'


def document(title: str, trace: dict, sections: list[tuple[str, str, str]]) -> str:
    """The whole page: title, the trace block (version, SHA-256, spec file) on top and at the bottom, a contents
    list, the sections; print styles with the same trace in every page's running footer.

    Parameters
    ----------
    title : str
        The report's title (plain text).
    trace : dict
        ``version``, ``spec_sha256`` and ``spec_file`` (what the report was made from).
    sections : list of (str, str, str)
        (anchor id, heading, body HTML) in order.

    Returns
    -------
    str
        The HTML document.
    """
    line = (f"handbook {trace['version']} · spec {trace['spec_file']} · spec SHA-256 {trace['spec_sha256']}")
    css = CSS.replace("__FOOTER__", line.replace("\\", "\\\\").replace('"', '\\"'))
    block = f'<div class="trace" id="trace-top">{esc(line)}</div>'
    toc = "".join(f'<li><a href="#{sid}">{esc(head)}</a></li>' for sid, head, _ in sections)
    body = "".join(f'<section id="{sid}"><h2>{esc(head)}</h2>{html_}</section>' for sid, head, html_ in sections)
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">'
            f'<meta name="handbook-version" content="{esc(trace["version"])}">'
            f'<meta name="spec-sha256" content="{esc(trace["spec_sha256"])}">'
            f"<title>{esc(title)}</title><style>{css}</style></head><body><header>{block}<h1>{esc(title)}</h1>"
            f"<nav><ul>{toc}</ul></nav></header><main>{body}</main>"
            f'<footer class="trace" id="trace-bottom">{esc(line)}</footer></body></html>\n')
