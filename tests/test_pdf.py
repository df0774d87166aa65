"""The book as one PDF (``make pdf``, tools/build_pdf.py): it builds offline, its outline (the PDF's table of
contents) names every part of _toc.yml, and its text holds every chapter's title, typeset math (no TeX source
left) and page numbers on every page. Needs Debian's Chromium, as the browser check does."""
import re
import subprocess
import sys
import unicodedata

import pytest
from test_browser import CHROMIUM, ROOT, toc_files

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine: install Debian's 'chromium' "
                                "package (make test does so where apt-get runs as root)")


def _title(doc: str) -> str:
    """A page's title: the first heading of its Markdown, notebook or first Markdown cell."""
    path = next(p for p in (ROOT / f"{doc}.md", ROOT / f"{doc}.ipynb") if p.exists())
    text = path.read_text()
    if path.suffix == ".ipynb":
        import json
        text = "\n".join("".join(c["source"]) for c in json.loads(text)["cells"] if c["cell_type"] == "markdown")
    return re.search(r"^# (.+)$", text, re.MULTILINE).group(1).strip()


@pytest.fixture(scope="module")
def pdf(tmp_path_factory):
    """(the outline's titles, each page's text with its white space collapsed), read back with PDFium (pypdfium2:
    the book's 580 pages in about two seconds, where pypdf takes half a minute; PDFium gives a hyphen at a line's
    end as U+FFFE)."""
    import pypdfium2 as pdfium

    out = tmp_path_factory.mktemp("pdf") / "handbook.pdf"
    run = subprocess.run([sys.executable, str(ROOT / "tools" / "build_pdf.py"), str(out)], capture_output=True, text=True,
                         timeout=900)
    assert run.returncode == 0 and out.exists(), run.stdout[-2000:] + run.stderr[-2000:]
    doc = pdfium.PdfDocument(out)
    try:
        return ([item.get_title() for item in doc.get_toc()],
                [" ".join(page.get_textpage().get_text_range().replace("\ufffe", "-").split()) for page in doc])
    finally:
        doc.close()


def _bare(text: str) -> str:
    """Text without Markdown marks or white space (the PDF's text extraction splits and joins words its own way),
    ligatures undone (the PDF's "ﬁ")."""
    text = unicodedata.normalize("NFKC", text).translate(str.maketrans("’‘“”", "''\"\""))  # Sphinx's curly quotes
    return re.sub(r"[*`\s]", "", text)


def test_every_chapter_title_is_in_the_pdf(pdf):
    _, pages = pdf
    text = _bare(" ".join(pages))
    for doc in toc_files():
        assert _bare(_title(doc)) in text, f"{doc}: its title {_title(doc)!r} is not in the PDF"
    assert len(pages) > 100


def test_the_outline_leads_to_every_chapter(pdf):
    """The PDF's outline (its table of contents in a reader's side panel) has an entry for every chapter."""
    outline = [_bare(t) for t in pdf[0]]
    for doc in toc_files():
        # (Chromium repeats a heading's text in its entry when the heading wraps: an entry that holds the title)
        title = _bare(_title(doc))
        assert any(title in entry for entry in outline), f"{doc}: no entry for {_title(doc)!r} in the outline"


def test_every_page_is_numbered_and_the_math_typeset(pdf):
    _, pages = pdf
    for k, text in enumerate(pages, 1):
        assert f"page {k} of {len(pages)}" in text, f"page {k}: no page number in its footer"
    # the errata quote each passage as the OCR gives it (TeX included), between "The source:" and "Evidence:"
    text = re.sub(r"The source:.*?Evidence:", " ", " ".join(pages))
    left = re.search(r"\\(frac|mathrm|left|right|displaystyle|sqrt)\b|\$\$", text)
    assert not left, f"TeX source left in the PDF: {text[max(0, left.start() - 80):left.end() + 40]!r}"
