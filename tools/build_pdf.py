"""The book as one PDF, offline: Jupyter Book's single-page HTML build of the committed outputs (nbval proves
them current), printed by Debian's Chromium with MathJax's typesetting finished, a document outline (the PDF's
table of contents, from the headings) and page numbers in the footer.

Usage: ``python tools/build_pdf.py [OUT.pdf]`` (``make pdf``; default ``_build/pdf/handbook.pdf``). Exit 1 with a
line saying why when Chromium is missing or a step fails.
"""
from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

from handbook.report.chromium import chromium
from handbook.report.chromium import print_pdf as print_pdf_with

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "_build" / "pdf" / "handbook.pdf"
#: Chromium's virtual time for the page to load and MathJax to typeset every equation of the book (ms)
BUDGET_MS = 120_000
#: print styles: no sidebars or buttons on paper, the text column the page's width, code that wraps
PRINT_CSS = """
@page { size: A4; margin: 18mm 15mm 20mm 15mm;
        @bottom-center { content: "Design handbook for driver ICs \\2014  page " counter(page) " of " counter(pages);
                         font-size: 9pt; } }
@media print {
  .bd-sidebar-primary, .bd-sidebar-secondary, .bd-header, .bd-header-article, .header-article-items,
  .prev-next-area, .bd-footer, .bd-footer-content, .bd-footer-article, .skip-link, .search-button-field,
  .headerlink, #pst-back-to-top, .toggle-details__summary, .cell_input, details.above-input { display: none !important; }
  html, body, .bd-container, .bd-container__inner, .bd-main, .bd-content, .bd-article-container, .bd-article,
  .bd-page-width { display: block !important; margin: 0 !important; padding: 0 !important; max-width: none !important;
  width: auto !important; overflow: visible !important; }
  pre { white-space: pre-wrap !important; word-break: break-word; font-size: 75%; }
  table { font-size: 75%; width: 100% !important; }
  td, th { word-break: break-word; }
  img { max-width: 100% !important; break-inside: avoid; }
  mjx-container[display="true"] { overflow: visible !important; }
  section > h1 { break-before: page; }
}
"""


def offline_config(folder: Path) -> Path:
    """The book's _config.yml with execution off (the committed outputs, which nbval proves current), written into
    ``folder`` with its paths made absolute (they are relative to the config file, which now lives elsewhere)."""
    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    config["execute"]["execute_notebooks"] = "off"
    config["sphinx"]["local_extensions"] = {k: str(ROOT / v) for k, v in config["sphinx"]["local_extensions"].items()}
    path = folder / "_config.yml"
    path.write_text(yaml.safe_dump(config))
    return path


def build_html(work: Path) -> Path:
    """The single-page HTML of the whole book (execution off) in _build/singlehtml, its configuration written in
    ``work``; the page to print. Sphinx's environment (_build/.doctrees) is the one the browser check's HTML build
    of the same configuration leaves (nitpicky too), so after it nothing is read again; a warning fails it, as it
    fails the book's build."""
    path = offline_config(work)
    jb = Path(sys.executable).with_name("jupyter-book")
    out = subprocess.run([str(jb), "build", str(ROOT), "--builder", "singlehtml", "-W", "-n", "--keep-going", "--config",
                          str(path)], capture_output=True, text=True, timeout=900)  # the book's own warning rules
    site = ROOT / "_build" / "singlehtml"
    redirect = re.search(r'url=([^"]+)"', (site / "index.html").read_text()) if (site / "index.html").exists() else None
    if out.returncode != 0 or redirect is None or not (site / redirect.group(1)).exists():
        raise SystemExit(f"the single-page HTML build failed:\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    # the builder writes the root document's folder (book/intro.html) but links it as if at the top (_static/,
    # _images/): the page is moved up beside them
    page = site / "handbook.html"
    # folded tables (dropdowns) print open: paper has no toggle
    opener = "<script>document.querySelectorAll('details.sd-dropdown').forEach(d => { d.open = true; });</script>"
    page.write_text((site / redirect.group(1)).read_text().replace("</head>", f"<style>{PRINT_CSS}</style></head>", 1)
                    .replace("</body>", f"{opener}</body>", 1))
    return page


def print_pdf(page: Path, pdf: Path, browser: str) -> None:
    """The page printed by Chromium the way the design report is (:func:`handbook.report.chromium.print_pdf`)."""
    stderr = print_pdf_with(page, pdf, browser, budget_ms=BUDGET_MS)
    if not pdf.exists() or pdf.stat().st_size < 10_000:
        raise SystemExit(f"Chromium printed no PDF:\n{stderr[-2000:]}")


def main(argv: list[str]) -> int:
    pdf = Path(argv[0]).resolve() if argv else OUT
    browser = chromium()
    if browser is None:
        print("no Chromium on this machine: install Debian's 'chromium' package (make system does so as root)")
        return 1
    with tempfile.TemporaryDirectory() as work:
        print_pdf(build_html(Path(work)), pdf, browser)
    print(pdf)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
