"""Printing a page to PDF with Debian's Chromium, offline: the book's PDF (``tools/build_pdf.py``) and the design
report (``python -m handbook report SPEC.toml -o F.pdf``) are printed the same way."""
from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

#: flags that keep a headless Chromium off the network and out of the user's profile
OFFLINE = ("--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync")


def chromium() -> str | None:
    """Debian's Chromium (or another Chromium on the path), or None.

    Returns
    -------
    str or None
        The browser's path, None when none is installed.
    """
    return next((p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p), None)


def print_pdf(page: Path, pdf: Path, browser: str, budget_ms: int = 20_000, outline: bool = True,
              timeout: float = 900) -> str:
    """Print ``page`` (a local HTML file) to ``pdf`` with Chromium's own print engine: no header or footer of
    Chromium's (the page's print CSS writes its own), a document outline from the headings.

    Parameters
    ----------
    page : pathlib.Path
        The HTML file (opened as a file:// URL; everything it needs must be inside it or beside it).
    pdf : pathlib.Path
        Where the PDF goes (replaced).
    browser : str
        The Chromium to run (:func:`chromium`).
    budget_ms : int
        Chromium's virtual time for the page to load (and any script to finish) before it is printed.
    outline : bool
        Write the PDF's outline (its table of contents) from the headings.
    timeout : float
        Seconds before the browser is given up on.

    Returns
    -------
    str
        What Chromium wrote on stderr (a harmless D-Bus line, usually).
    """
    pdf.parent.mkdir(parents=True, exist_ok=True)
    pdf.unlink(missing_ok=True)
    with tempfile.TemporaryDirectory() as profile:
        out = subprocess.run([browser, *OFFLINE, f"--user-data-dir={profile}", f"--virtual-time-budget={budget_ms}",
                              "--run-all-compositor-stages-before-draw",
                              *(["--generate-pdf-document-outline"] if outline else []), "--no-pdf-header-footer",
                              f"--print-to-pdf={pdf}", page.resolve().as_uri()], capture_output=True, text=True,
                             timeout=timeout)
    return out.stderr
