"""`python -m handbook render`: a re-run chapter as a page with the book's look, built offline."""
import json
import shutil
from pathlib import Path

from bs4 import BeautifulSoup

from handbook import cli

BOOK = Path(__file__).resolve().parents[1] / "book"


def test_a_chapter_renders_with_its_glued_values_typeset_math_and_the_books_style(tmp_path, capsys):
    nb = tmp_path / "watchdog_rerun.ipynb"
    shutil.copy(BOOK / "an94002" / "watchdog.ipynb", nb)
    assert cli.main(["render", str(nb), "-o", str(tmp_path / "html")]) == 0
    page = Path(capsys.readouterr().out.strip())
    assert page == tmp_path / "html" / "page.html"
    soup = BeautifulSoup(page.read_text(), "html.parser")
    text = " ".join(soup.get_text(" ").split())
    assert "{glue" not in text
    # the glued watchdog time of the fitted 10 nF, by hand: 10 nF x (2.2 V - 0.3 V) / 5 uA = 3.80 ms
    assert "watchdog time of 3.80 ms" in text
    assert soup.find("script", src=lambda s: s and s.endswith("mathjax/tex-mml-chtml.js"))  # served locally
    assert (tmp_path / "html" / "_static" / "mathjax" / "tex-mml-chtml.js").exists()
    assert soup.find("link", href=lambda s: s and "handbook.css" in s)
    assert soup.select("table")  # the status table, laid out


def test_a_notebook_that_was_not_executed_is_refused_naming_what_is_missing(tmp_path, capsys):
    nb = json.loads((BOOK / "an94002" / "watchdog.ipynb").read_text())
    for cell in nb["cells"]:
        cell.pop("outputs", None) if cell["cell_type"] == "code" else None
    (tmp_path / "raw.ipynb").write_text(json.dumps(nb))
    assert cli.main(["render", str(tmp_path / "raw.ipynb")]) == 2
    err = capsys.readouterr().err
    assert "glued values its outputs do not hold" in err and "t_board_ms" in err and "execute it first" in err
    assert not (tmp_path / "raw_html").exists()


def test_render_needs_exactly_one_input(capsys):
    assert cli.main(["render"]) == 2
    assert "either a notebook or --spec" in capsys.readouterr().err
    assert cli.main(["render", "no_such.ipynb"]) == 2
    assert "is not a notebook file" in capsys.readouterr().err
