"""`python -m handbook report SPEC.toml -o F.html|F.pdf`: one self-contained file per spec (the template, the book's
examples, a partial spec), its numbers the same as `design --json`'s, bad specs refused as `design` refuses them
with nothing written; the worst-case section against a stand-in of handbook.design.worstcase's interface; the page
in headless Chromium (one launch) and the PDF read back with PDFium (pypdfium2)."""
import json
import re
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from cdp import Browser
from test_browser import CHROMIUM, FLAGS, _console_errors

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "book" / "examples").glob("*.toml"))
SECTIONS = ("spec", "circuits", "calculations", "worst-case", "spice", "losses", "notes")
DATA = re.compile(r'<data value="([^"]+)" data-key="([^"]+)">')


def _handbook(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "handbook", *map(str, args)], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    folder = tmp_path_factory.mktemp("template")
    spec = folder / "template.toml"
    spec.write_text(_handbook("design", "--template").stdout)
    return spec


def _report(spec: Path, out: Path, *extra):
    run = _handbook("report", spec, "-o", out, *extra)
    assert run.returncode == 0, run.stderr[-3000:]
    assert sorted(p.name for p in out.parent.iterdir() if p != spec) == [out.name], "one file, no temporary left"
    return out.read_text(encoding="utf-8")


def _values(page: str) -> dict[str, list[float]]:
    out: dict[str, list[float]] = {}
    for v, key in DATA.findall(page):
        out.setdefault(key, []).append(float(v))
    return out


def test_template_report_numbers_are_design_json_s(template, tmp_path):
    page = _report(template, tmp_path / "board.html", "--no-spice")
    design = json.loads(_handbook("design", template, "--json").stdout)
    shown = _values(page)
    checked = 0
    for table in ("commutation", "current_limiter", "class_d", "converter"):
        for key, v in design[table].items():
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                assert shown.get(f"{table}.{key}"), f"{table}.{key} is not in the report"
                assert set(shown[f"{table}.{key}"]) == {float(v)}, f"{table}.{key}: report {shown[f'{table}.{key}']} != {v}"
                checked += 1
    assert checked > 60
    # section 4's numbers are design --worstcase's: the same lot (N boards, seed), every bound of every quantity
    worst = json.loads(_handbook("design", template, "--json", "--worstcase").stdout)
    bounds = 0
    for table in ("commutation", "current_limiter", "class_d", "converter"):
        wc = worst[table]["worstcase"]
        assert wc["n"] == 100_000 and 0 <= wc["yield_all"] <= min(wc["yields"].values(), default=1.0)
        for q in wc["quantities"]:
            assert q["unit"] != "%"  # JSON carries fractions ("1"); per cent is the page's way of showing them
            for field in ("nominal", "eva_low", "eva_high", "rss_low", "rss_high", "mc_low", "mc_high"):
                key = f"wc.{table}.{q['key']}.{field.replace('_', '.')}"
                assert set(shown[key]) == {float(q[field])}, (key, shown.get(key), q[field])
                bounds += 1
        for name, y in wc["yields"].items():  # the yields as the page words them, to 2 decimals of a per cent
            assert f'<td>{name}</td><td class="num">{y:.2%}<'.replace("%<", " %<") in page, (table, name, y)
    assert bounds > 60
    # what a reader sees is the engineering value of the same number
    assert re.search(r'data-key="current_limiter.r7">430 mΩ<', page) and design["current_limiter"]["r7"] == 0.43
    for sid in SECTIONS:
        assert f'<section id="{sid}">' in page
    assert design["spec_sha256"] in page and f"handbook {design['version']}" in page
    assert "Nothing changed" in page and "--no-spice was given" in page
    # self-contained: no script, no stylesheet or image fetched from anywhere
    assert "<script" not in page and "<link" not in page and not re.search(r'(src|href)="(https?:)?//', page)
    assert "<math" in page and "MathJax" not in page and page.count("<svg") >= 4


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_each_example_gives_one_report_of_its_tables(example, tmp_path):
    spec = tmp_path / example.name
    spec.write_text(example.read_text())
    page = _report(spec, tmp_path / "board.html", "--no-spice")
    design = json.loads(_handbook("design", spec, "--json").stdout)
    for table in ("commutation", "current_limiter", "class_d", "converter"):
        assert (f'id="circuit-{table}"' in page) == (table in design["asked"])
    changed = page.split("What you changed", 1)
    assert len(changed) == 2, "an example changes keys: they come first"
    # the 8 ohm amplifier's load is what it changed, before the folded rest
    if example.stem == "amplifier_8ohm":
        assert 'data-key="spec.class_d.r_load">8 Ω<' in changed[1].split("<details>", 1)[0]
    shown = _values(page)
    for table in design["asked"]:  # the spec as read (defaults filled in) is what the report says was used
        for key, v in design["spec"][table].items():
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                assert set(shown[f"spec.{table}.{key}"]) == {float(v)}, f"spec.{table}.{key}"


def test_a_spec_of_only_class_d_gives_one_file_of_that_table(tmp_path):
    spec = tmp_path / "amp.toml"
    spec.write_text("[class_d]\n")
    page = _report(spec, tmp_path / "amp.html", "--no-spice")
    assert 'id="circuit-class_d"' in page and page.count('id="circuit-') == 1
    assert "<h3>[class_d]</h3>" in page and "[converter]" not in page and "A3-L1" in page and "A2-R7" not in page


def test_bad_specs_exit_as_design_does_and_write_nothing(tmp_path):
    for text, code, needle in (("[commutation]\nrpm_mni = 900\n", 2, "did you mean commutation.rpm_min"),
                               ("[clas_d]\n", 2, "did you mean [class_d]"),
                               ("[commutation]\nrpm_max = 50000\n", 3, "cannot be met [commutation]")):
        spec = tmp_path / "spec.toml"
        spec.write_text(text)
        design = _handbook("design", spec)
        for out in ("r.html", "r.pdf"):
            run = _handbook("report", spec, "-o", tmp_path / out)
            assert run.returncode == code == design.returncode and needle in run.stderr, run.stderr
            assert "Traceback" not in run.stderr
            assert [ln for ln in design.stderr.splitlines() if ln.startswith(("error", "cannot"))] == \
                [ln for ln in run.stderr.splitlines() if ln.startswith(("error", "cannot"))]
        assert sorted(p.name for p in tmp_path.iterdir()) == ["spec.toml"]
    bad = _handbook("report", spec, "-o", tmp_path / "r.docx")
    assert bad.returncode == 2 and "FILE.html or FILE.pdf" in bad.stderr
    gone = _handbook("report", spec, "-o", tmp_path / "no" / "r.html")
    assert gone.returncode == 2 and "does not exist" in gone.stderr


def _quantity(key, label, unit, nominal, spread, lo, hi):
    return SimpleNamespace(key=key, label=label, unit=unit, nominal=nominal, eva_low=nominal - spread,
                           eva_high=nominal + spread, rss_low=nominal - spread / 2, rss_high=nominal + spread / 2,
                           mc_low=nominal - spread / 3, mc_high=nominal + spread / 3, limit_low=lo, limit_high=hi)


def fake_analyse(table, result, n=100_000, seed=1, yield_all=0.9991):
    """A stand-in with handbook.design.worstcase.analyse's interface: two quantities, their samples, the yields
    keyed by limit as the engine keys them."""
    rng = np.random.default_rng(seed)
    qs = [_quantity("f_corner", "output filter corner", "Hz", 1618.0, 120.0, 1200.0, None),
          _quantity("ripple", "switching residue at the load", "V", 0.05, 0.01, None, 0.1)]
    return SimpleNamespace(
        quantities=qs, yields={"corner above 1.2 kHz": yield_all, "ripple_max": 1.0}, yield_all=yield_all, n=n,
        seed=seed, binding="switching residue at the load",
        samples={q.key: q.nominal + rng.normal(0, (q.eva_high - q.nominal) / 4, 2000) for q in qs},
        distributions=[SimpleNamespace(part="L1", kind="uniform", low=0.9, high=1.1, cite="±10 % inductor", unit="")],
        sensitivity=[SimpleNamespace(source="L1 tolerance", share=0.62, margin_if_halved=0.31, yield_if_halved=0.99995)],
        drift=["L1 loses 3 % of its inductance at 100 °C"],
        by_limit=[SimpleNamespace(key="ripple", margin=0.4, source="L1 tolerance", share=0.62)])


@pytest.fixture(scope="module")
def class_d_page(tmp_path_factory):
    """The [class_d]-only report built in-process with SPICE (when ngspice is here) and the worst-case stand-in."""
    from handbook.design import spec as specmod
    from handbook.report import design_report

    spec = specmod.parse({"class_d": {}})
    ctx = design_report.context(spec, specmod.run_each(spec), "class_d.toml")
    path = tmp_path_factory.mktemp("class_d") / "class_d.html"
    path.write_text(design_report.build(ctx, analyse=fake_analyse), encoding="utf-8")
    return path


def test_partial_spec_reports_only_its_table_with_worst_case_and_spice(class_d_page):
    page = class_d_page.read_text(encoding="utf-8")
    assert 'id="circuit-class_d"' in page and "circuit-current_limiter" not in page and "[commutation]" not in page
    # the worst-case section, against the interface: every column, a histogram per quantity, the tables
    assert 'data-key="wc.class_d.f_corner.nominal">1.618 kHz<' in page and "99.91 %" in page
    assert "corner above 1.2 kHz" in page and "least worst-case margin: <b>switching residue" in page
    assert "Below 99.90 %" not in page  # 99.91 % of the lot: no warning
    assert page.count('id="wc-class_d-') >= 2 and "±10 % inductor" in page and "L1 tolerance" in page
    # every limit with the tolerance moving it most, by its label
    assert ('<td>switching residue at the load</td><td class="num">40.00 %</td><td>L1 tolerance</td>'
            '<td class="num">62.00 %</td>') in page
    assert "L1 loses 3 %" in page and "100,000 samples" in page
    from handbook.spice import runner

    if runner.available():
        assert "output filter corner with the load" in page and 'id="sim-class_d' in page
    else:
        assert "SPICE confirmation skipped: ngspice is not installed" in page


def test_a_low_yield_and_a_failed_analysis_are_warnings():
    """A lot below 99.9 % is said in section 4 and among section 7's warnings; a worst-case analysis that fails
    is said in its place and among the warnings, never only as a note."""
    from handbook.design import spec as specmod
    from handbook.report import design_report

    spec = specmod.parse({"class_d": {}})
    ctx = design_report.context(spec, specmod.run_each(spec), "class_d.toml", no_spice=True)
    page = design_report.build(ctx, analyse=lambda *a, **k: fake_analyse(*a, **k, yield_all=0.95))
    notes = page[page.index('id="notes"'):]
    assert "Below 99.90 %" in page and "every limit met by 95.00 %" in notes

    def broken(*a, **k):
        raise ValueError("no model")

    ctx = design_report.context(spec, specmod.run_each(spec), "class_d.toml", no_spice=True)
    page = design_report.build(ctx, analyse=broken)
    assert "worst-case analysis failed: ValueError: no model" in page[page.index('id="notes"'):]


def test_a_figure_or_schematic_that_fails_is_a_warning(monkeypatch):
    """Section 2 draws what it can: a schematic or a plot that raises is named in its place and among section
    7's warnings."""
    from handbook.design import spec as specmod
    from handbook.report import design_report
    from handbook.report.design_report import sections
    from handbook.spice import designed

    def broken(*a, **k):
        raise RuntimeError("no axes")

    monkeypatch.setattr(sections, "_figures", broken)
    monkeypatch.setattr(designed, "drawing", broken)
    spec = specmod.parse({"class_d": {}})
    ctx = design_report.context(spec, specmod.run_each(spec), "class_d.toml", no_spice=True)
    circuits, notes = design_report.body(ctx, "circuits"), design_report.body(ctx, "notes")
    assert "figures not drawn: RuntimeError: no axes" in circuits and "schematic not drawn" in circuits
    assert "figures of how the choice was made not drawn: RuntimeError" in notes
    assert "schematic not drawn: RuntimeError: no axes" in notes


#: run in the page once loaded: what Chromium made of it, as JSON in a <pre> at the end of the body
PROBE = """<script>window.addEventListener("load", () => {
  const box = e => { const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0; };
  const out = {sections: [...document.querySelectorAll("body > section, main > section")].map(s => s.id),
    images: [...document.images].map(i => i.complete && i.naturalWidth > 0),
    svgs: [...document.querySelectorAll("figure svg")].map(box),
    math: [...document.querySelectorAll("math")].map(m => m.getBoundingClientRect().height)};
  const p = document.createElement("pre"); p.id = "probe"; p.textContent = JSON.stringify(out);
  document.body.appendChild(p); });</script>"""


@pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine: install Debian's 'chromium' package")
def test_the_page_in_chromium(class_d_page, tmp_path):
    probe = tmp_path / "probe.html"
    probe.write_text(class_d_page.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>", 1), encoding="utf-8")
    with Browser(CHROMIUM, FLAGS) as browser:
        console = browser.load(probe.as_uri(), 1400, ready="document.getElementById('probe')")
        dom = browser.dom()
    found = re.search(r'<pre id="probe">(.*?)</pre>', dom, re.S)
    assert found, dom[-2000:]
    got = json.loads(found.group(1).replace("&quot;", '"'))
    assert got["sections"] == list(SECTIONS)
    assert got["svgs"] and all(got["svgs"]) and all(got["images"])
    assert got["math"] and all(h > 10 for h in got["math"]), "MathML laid out by the browser"
    assert not _console_errors(console)


@pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine: install Debian's 'chromium' package")
def test_the_pdf_has_version_and_hash_on_every_page(tmp_path):
    import pypdfium2 as pdfium

    spec = tmp_path / "amp.toml"
    spec.write_text((ROOT / "book" / "examples" / "amplifier_8ohm.toml").read_text())
    pdf = tmp_path / "amp.pdf"
    run = _handbook("report", spec, "-o", pdf, "--no-spice")
    assert run.returncode == 0, run.stderr[-2000:]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["amp.pdf", "amp.toml"]
    sha = json.loads(_handbook("design", spec, "--json").stdout)["spec_sha256"]
    doc = pdfium.PdfDocument(pdf)
    pages = [" ".join(p.get_textpage().get_text_range().split()) for p in doc]
    doc.close()
    assert 2 <= len(pages) <= 40
    for k, text in enumerate(pages, 1):
        assert sha in text.replace(" ", "") and "handbook 0.1.0" in text, f"page {k}: no trace in its footer"
        assert f"page {k} of {len(pages)}" in text
    whole = " ".join(pages)
    assert "1. The spec" in whole and "7. Warnings, assumptions and trace" in whole and "8 Ω" in whole


@pytest.mark.parametrize("name", ["design/your_own", *(f"examples/{p.stem}" for p in EXAMPLES)])
def test_the_book_s_design_chapter_is_the_report_s_html_form(name):
    """"Design your own" and the worked examples are the report, section by section: the report's headings in its
    order, each followed by the one cell that shows that section of the report's own HTML, nothing else computed."""
    from handbook.report import design_report

    nb = json.loads((ROOT / "book" / f"{name}.ipynb").read_text())
    heads = [line[3:] for c in nb["cells"] if c["cell_type"] == "markdown"
             for line in "".join(c["source"]).splitlines() if line.startswith("## ")]
    assert heads == [head for _, head, _ in design_report.SECTIONS]
    shows = [re.fullmatch(r'design_report\.show\(ctx, "([\w-]+)"\)', "".join(c["source"]).strip())
             for c in nb["cells"] if c["cell_type"] == "code" and "show(" in "".join(c["source"])]
    assert [m.group(1) for m in shows if m] == [sid for sid, _, _ in design_report.SECTIONS] and all(shows)
    outputs = ["".join(o["data"]["text/html"]) for c in nb["cells"] if "show(" in "".join(c["source"])
               for o in c.get("outputs", []) if "text/html" in o.get("data", {})]
    assert len(outputs) == len(design_report.SECTIONS)
    assert all(o.startswith('<div class="design-report"><style>.design-report table') for o in outputs)


def test_a_table_nothing_meets_is_shown_with_what_can_be_met(tmp_path):
    """The book's form designs what can be met and says why the rest is not (the command writes no file)."""
    from handbook.report import design_report

    spec = tmp_path / "tight.toml"
    spec.write_text("[current_limiter]\nresistor_tolerance = 0.05\n[class_d]\n")
    ctx = design_report.for_book(str(spec), no_spice=True)
    assert list(ctx.designed) == ["class_d"] and list(ctx.unmet) == ["current_limiter"]
    notes = design_report.body(ctx, "notes")
    assert "cannot be met, so not designed: the smallest R7" in notes and "v_drop_max" in notes
    assert "<code>[current_limiter]</code> cannot be met" in design_report.body(ctx, "spec")
    assert _handbook("report", spec, "-o", tmp_path / "tight.html").returncode == 3
    assert not (tmp_path / "tight.html").exists()


def test_section_5_shows_the_timers_cycle_and_the_limiters_stall_of_this_design(tmp_path):
    """Section 5 of a spec with the timers and the limiter: the designed CAP-CD/CAP-DC through a commutation cycle
    (six commutations an electrical cycle, each half-way, 30 electrical degrees, after its zero crossing: AN94002
    2.1.2) and the designed limiter holding a stalled motor (settled at the trip current of its nominal parts, i.e.
    V_cs / R7 by eq 13, between the spec's two limits)."""
    from handbook.design import spec as specmod
    from handbook.report import design_report
    from handbook.spice import runner

    if runner.available() is None:
        pytest.skip(runner.why_unavailable())
    spec = specmod.parse({"commutation": {}, "current_limiter": {}})
    ctx = design_report.context(spec, specmod.run_each(spec), "two.toml")
    html = design_report.body(ctx, "spice")
    cycle = re.search(r"levels: ([\d.]+) commutations a cycle, each ([\d.]+)° after", html)
    assert cycle and float(cycle.group(1)) == pytest.approx(6, abs=0.05)
    assert float(cycle.group(2)) == pytest.approx(30, abs=1.0)
    lim = ctx.designed["current_limiter"]
    stall = re.search(r"peaks at ([\d.]+) (m?)A .* settles within 5 % in ([\d.]+) (m?)s", html)
    assert stall, "the stall's caption"
    peak = float(stall.group(1)) * (1e-3 if stall.group(2) else 1)
    assert lim.i_trip_nominal < peak < lim.spec["i_must_trip"]
    assert 'id="sim-limiter-step' in html or "sim-limiter-step" in html
