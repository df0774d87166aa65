"""The rendered book in a real browser: build it, open every page in headless Chromium.

Checks, for every page of _toc.yml: it loads; its math is typeset by MathJax (no raw TeX left);
every figure its notebook made is on the page and its file exists; every internal link and anchor
resolves; the browser console shows no errors. A screenshot of one chapter is kept in
_build/artifacts/. Needs Debian's `chromium` (`make test` installs it where apt-get runs as root);
without it the checks report themselves skipped and why.
"""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path
from urllib.parse import unquote

import pytest
import yaml
from bs4 import BeautifulSoup
from build_pdf import offline_config
from cdp import Browser

from handbook.report.chromium import OFFLINE
from handbook.report.chromium import chromium as chromium_path

ROOT = Path(__file__).resolve().parents[1]
HTML = ROOT / "_build" / "html"
CHROMIUM = chromium_path()
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine: install Debian's "
                                "'chromium' package (make test does so where apt-get runs as root)")
FLAGS = [*OFFLINE, "--disable-quic"]  # the design report's offline flags, QUIC off too


def toc_files():
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]]
    for part in toc.get("parts", []):
        files += [c["file"] for c in part["chapters"]]
    return files


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The book built from the committed outputs (nbval proves they equal a fresh execution; `make book`
    re-executes every chapter). Same configuration as _config.yml except for execution."""
    path = offline_config(tmp_path_factory.mktemp("config"))
    jb = Path(sys.executable).with_name("jupyter-book")
    # from a fresh environment: Sphinx reports a page's warnings only when it reads the page, so a page read
    # before (by `make pdf`, or a build whose -W failed) would pass unread
    shutil.rmtree(ROOT / "_build" / ".doctrees", ignore_errors=True)
    out = subprocess.run([str(jb), "build", str(ROOT), "-W", "-n", "--keep-going", "--config", str(path)],
                         capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    # Sphinx's incremental build does not copy a changed static file again: the book's own style, as it stands
    shutil.copy(ROOT / "book" / "_static" / "handbook.css", HTML / "_static" / "handbook.css")
    return HTML


def _console_errors(console):
    """The console's messages that report a failure: an uncaught exception, a resource that failed to load, an
    error a script wrote (by its text: the theme writes a harmless "invalid theme mode" at level error)."""
    return [f"{level}: {text}"[:200] for level, text in console if re.search(r"Uncaught|Error|Failed|error", text)]


#: the layout rule, run in the page (tests/layout_probe.js): what sticks out of the text column, as JSON
PROBE = Path(__file__).with_name("layout_probe.js").read_text()
#: a phone's screen: the page's window is set this wide (the page's media queries see it)
NARROW = 390
#: a page is complete when the probe has written its report: MathJax has typeset it and the layout is measured
READY = "document.getElementById('layout-probe')"


def _layout(soup):
    """The layout probe's report (and the probe's element taken out of the page, so no other check sees it)."""
    found = [el.extract().get_text() for el in soup.find_all("pre", id="layout-probe")]
    return json.loads(found[-1]) if found else None


@pytest.fixture(scope="module")
def browser():
    """One Chromium for every page load of this file (tests/cdp.py): starting one costs as much as a chapter's
    load, and the check loads every page twice."""
    with Browser(CHROMIUM, FLAGS) as b:
        yield b


def _load(browser, page: Path, width: int):
    """The console's lines of the page loaded in a window ``width`` px wide, once typeset and measured (``browser``
    then holds it): it is loaded as a copy beside itself (its links and styles resolve the same) with the layout
    probe at the end of its body."""
    copy = page.with_name(f"{page.stem}.probe-{width}.html")
    copy.write_text(page.read_text().replace("</body>", f"<script>{PROBE}</script></body>", 1))
    try:
        return browser.load(copy.as_uri(), width, ready=READY)
    finally:
        copy.unlink(missing_ok=True)


@pytest.fixture(scope="module")
def rendered(site, browser):
    """Every page of the table of contents as Chromium left it in a 1400 px window: the page's file, its DOM parsed
    once (html.parser takes about a second on a long chapter, so the tests share one parse), the console's lines
    and the layout probe's report."""
    out = {}
    for doc in toc_files():
        page = site / f"{doc}.html"
        console = _load(browser, page, 1400)
        soup = BeautifulSoup(browser.dom(), "html.parser")
        out[doc] = (page, soup, console, _layout(soup))
    return out


@pytest.fixture(scope="module")
def narrow(site, browser):
    """doc -> the layout probe's report of the page in a window as wide as a phone's screen."""
    out = {}
    for doc in toc_files():
        _load(browser, site / f"{doc}.html", NARROW)
        out[doc] = json.loads(browser.evaluate(f"{READY}.textContent"))
    return out


@pytest.fixture(scope="module")
def parsed(rendered):
    """Each page's file, its soup and the text a reader sees (code, scripts and styles left out)."""
    return {doc: (page, soup, _reader_text(soup)) for doc, (page, soup, _, _) in rendered.items()}


def _reader_text(soup, hidden=("pre", "code", "script", "style"), hidden_class=None, sep=""):
    """The page's text outside the ``hidden`` elements (and those of class ``hidden_class``), without changing the
    soup."""
    def shown(string):
        return not any(p.name in hidden or hidden_class in (p.get("class") or []) for p in string.parents)
    return sep.join(s for s in soup.strings if shown(s))


def test_every_page_loads(parsed):
    for doc, (_page, soup, _) in parsed.items():
        assert soup.find("h1"), f"{doc}: no title rendered"
        assert soup.find("main") or soup.find("article"), f"{doc}: no content"


def test_math_is_typeset(parsed):
    typeset = 0
    for doc, (_, soup, text) in parsed.items():
        for el in soup.select(".math"):
            assert el.find("mjx-container"), f"{doc}: math left as raw TeX: {el.get_text()[:80]!r}"
            typeset += 1
        assert not re.search(r"\\\(|\\\[|\$\$", text), f"{doc}: raw TeX delimiters in the text"
    assert typeset > 100


#: characters that never belong in a page's text (a tab where "\\t" of "\\theta" was meant, NUL, escapes)
CONTROL = re.compile(r"[\x00-\x08\x09\x0b\x0c\x0e-\x1f\x7f]")


def test_math_has_no_mathjax_errors_and_text_no_control_characters(parsed):
    """MathJax puts an error inside its own container (so "typeset" alone passes it): look for the error
    markers themselves, and for control characters in what a reader sees."""
    for doc, (_, soup, text) in parsed.items():
        errors = soup.select("[data-mjx-error], mjx-merror, merror")
        assert not errors, f"{doc}: MathJax error: {errors[0].get('data-mjx-error') or errors[0].get_text()[:80]!r}"
        bad = CONTROL.search(text)
        assert not bad, f"{doc}: control character {bad.group()!r} near {text[max(0, bad.start() - 40):bad.start() + 20]!r}"


#: units as ASCII stand-ins where a person reads them: 10 uF, 2 ohm, 4.7 kohm, +-5 %, -90 deg
ASCII_UNITS = re.compile(r"(?<![\w.])\d+(?:\.\d+)?\s?(?:u[FAHVWs]|[kM]?ohms?|[mk]?Ohm|deg)\b|\+-\s?\d|\+/-\s?\d")


def test_units_are_written_as_a_person_reads_them(parsed):
    """µ, Ω, ± and ° in everything a reader sees, outputs included (a table, a printed line): only what the reader
    types (a code cell's source, a code span) keeps ASCII."""
    for doc, (_, soup, _) in parsed.items():
        text = _reader_text(soup, ("script", "style", "code"), "cell_input", sep=" ")  # outputs (pre) included
        bad = [text[max(0, m.start() - 50):m.end() + 10] for m in ASCII_UNITS.finditer(text)]
        assert not bad, f"{doc}: ASCII units in what a reader sees: {bad[:5]}"


def test_tables_are_rendered(parsed):
    """A Markdown table that failed to parse shows up as raw '|---|' text (a '|' inside a cell does that)."""
    tables = 0
    for doc, (_, soup, text) in parsed.items():
        tables += len(soup.select("main table, article table"))
        assert "|---|" not in text.replace(" ", ""), f"{doc}: a Markdown table was left as text"
    assert tables > 40


def test_every_figure_is_on_its_page(parsed):
    for doc, (page, soup, _) in parsed.items():
        source = ROOT / f"{doc}.ipynb"
        made = 0
        if source.exists():
            nb = json.loads(source.read_text())
            made = sum("image/png" in o.get("data", {}) for c in nb["cells"] for o in c.get("outputs", []))
        imgs = [i for i in soup.select("main img, article img")
                if "_images/" in i.get("src", "")]
        assert len(imgs) == made, f"{doc}: {made} figures made, {len(imgs)} on the page"
        for img in imgs:
            f = (page.parent / unquote(img["src"])).resolve()
            assert f.exists() and f.stat().st_size > 1000, f"{doc}: missing figure {img['src']}"


def test_internal_links_resolve(site, parsed):
    ids = {page: {t.get("id") for t in soup.find_all(id=True)} for page, soup, _ in parsed.values()}

    def anchors(path):  # a page outside the table of contents (the index, the search page): its file
        if path not in ids:
            ids[path] = {t.get("id") for t in BeautifulSoup(path.read_text(), "html.parser").find_all(id=True)}
        return ids[path]

    checked = 0
    for doc, (page, soup, _) in parsed.items():
        for a in soup.select("a[href]"):
            href = a["href"]
            if re.match(r"^[a-z]+:", href) and not href.startswith("file:"):
                continue  # external
            target, _, frag = href.partition("#")
            path = page if not target else (page.parent / unquote(target)).resolve()
            if path.is_dir():
                path = path / "index.html"
            assert path.exists(), f"{doc}: broken link {href}"
            if frag and path.suffix == ".html":
                assert frag in anchors(path), f"{doc}: missing anchor {href}"
            checked += 1
    assert checked > 200


def test_browser_console_has_no_errors(rendered):
    bad = {doc: _console_errors(console) for doc, (_, _, console, _) in rendered.items()}
    assert not {d: v for d, v in bad.items() if v}


#: the page has been typeset (a page without MathJax at once)
TYPESET = "!(window.MathJax && MathJax.startup && MathJax.startup.promise) || MathJax.startup.promise.then(() => true)"


def test_screenshot_of_a_chapter_is_kept(site, browser):
    art = ROOT / "_build" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    shot = art / "opamp_limiter.png"
    shot.unlink(missing_ok=True)
    browser.load((site / "book/an94002/opamp_limiter.html").as_uri(), 1280, 2400, ready=TYPESET)
    shot.write_bytes(browser.screenshot())
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 50_000


def _sticking_out(report) -> list[str]:
    return [f"{w['tag']}.{w['cls'].split()[0] if w['cls'] else ''} in section '{w['section']}', {w['over']} px over: "
            f"{w['text'][:60]!r}" for w in report["wide"]]


def test_every_block_fits_the_column_at_1400_px_and_on_a_phone(rendered, narrow):
    """No visible block wider than the text column except inside its own scroll box (tables, code, display
    equations), at 1400 px and 390 px: a table that loses a column, an equation cut at the edge or a line that
    pushes the page sideways fails here with the page and the block."""
    for width, reports in ((1400, {d: v[3] for d, v in rendered.items()}), (NARROW, narrow)):
        for doc, report in reports.items():
            assert report is not None, f"{doc} at {width} px: the layout probe did not run"
            assert report["width"] <= width and report["column"] <= width + 1, f"{doc} at {width} px: {report}"
            assert not report["wide"], f"{doc} at {width} px: " + "; ".join(_sticking_out(report))


def test_the_console_check_sees_an_exception_and_a_missing_file(browser, tmp_path):
    """The console check can fail: a page whose script throws at once, again 400 ms and 5 s after the load, and
    whose image is missing, is reported four times (a page runs 20 s of virtual time after it is ready)."""
    page = tmp_path / "broken.html"
    page.write_text('<!DOCTYPE html><html><body><h1>x</h1><img src="missing.png"><script>'
                    'setTimeout(() => { throw new Error("late"); }, 400); '
                    'setTimeout(() => { throw new Error("later"); }, 5000); null.f();</script></body></html>')
    console = browser.load(page.as_uri(), 800, ready="document.readyState === 'complete'")
    errors = _console_errors(console)
    assert len(errors) == 4, errors
    for said in ("Uncaught TypeError", "Error: late", "Error: later", "missing.png"):
        assert any(said in e for e in errors), (said, errors)
