"""`python -m handbook render`: a re-run chapter as a page with the book's look, built offline."""
import json
import shutil
from pathlib import Path

import pytest
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


def _cli(*args):
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-m", "handbook", *args], capture_output=True, text=True, timeout=300)


def test_rerun_refuses_a_misspelt_or_mistyped_parameter_in_one_line_before_anything_runs():
    out = _cli("rerun", "cap_cd", "-p", "pole_pair", "4")
    assert out.returncode == 2 and out.stdout == "" and "Traceback" not in out.stderr
    assert out.stderr.strip().splitlines() == [out.stderr.strip()] and "did you mean 'pole_pairs'?" in out.stderr
    out = _cli("rerun", "design/cap_cd", "-p", "pole_pairs", "four")
    assert out.returncode == 2 and "'pole_pairs' = 'four' is not a whole number" in out.stderr
    out = _cli("rerun", "no_such_chapter")
    assert out.returncode == 2 and "design/cap_cd" in out.stderr and "Traceback" not in out.stderr


def test_papermill_itself_stops_a_chapter_given_an_unknown_parameter(tmp_path):
    """`papermill ... -p pole_pair 4` used to run with the note's 6 pole pairs and exit 0; report.setup() now
    stops the chapter in its first cell, naming the parameter it probably meant."""
    import papermill as pm

    with pytest.raises(pm.PapermillExecutionError, match="did you mean 'pole_pairs'"):
        pm.execute_notebook(str(BOOK / "design" / "cap_cd.ipynb"), str(tmp_path / "out.ipynb"),
                            parameters={"pole_pair": 4}, kernel_name="python3", cwd=str(BOOK / "design"),
                            progress_bar=False)


def test_render_says_a_notebook_stopped_and_why(tmp_path, capsys):
    nb = {"cells": [{"cell_type": "markdown", "metadata": {}, "source": ["# A chapter\n"]},
                    {"cell_type": "code", "execution_count": 3, "metadata": {}, "source": ["1/0"],
                     "outputs": [{"output_type": "error", "ename": "InputError", "evalue": "bad key 'x'\nmore",
                                  "traceback": []}]}],
          "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path = tmp_path / "stopped.ipynb"
    path.write_text(json.dumps(nb))
    assert cli.main(["render", str(path)]) == 2
    err = capsys.readouterr().err
    assert "did not run to the end (cell 3: InputError: bad key 'x')" in err and "rerun" in err


def test_a_rerun_page_shows_one_parameters_cell_with_the_readers_values_and_names_linked_chapters(tmp_path):
    from handbook import render

    prose = ["# Title\n", "See {doc}`../an94002/watchdog` and {doc}`the delay <../an94002/commutation_delay>`.\n"]
    nb = {"cells": [{"cell_type": "markdown", "metadata": {}, "source": prose},
                    {"cell_type": "code", "metadata": {"tags": ["parameters"]}, "outputs": [], "execution_count": 1,
                     "source": ["pole_pairs = 6          # n\n", "rpm_min = 1800.0        # rpm\n"]},
                    {"cell_type": "code", "metadata": {"tags": ["injected-parameters"]}, "outputs": [],
                     "execution_count": 2, "source": ["# Parameters\n", "pole_pairs = 4\n"]}],
          "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path = tmp_path / "x.ipynb"
    path.write_text(json.dumps(nb))
    page = json.loads(render._for_one_page(path, render.ROOT))
    params = "".join(page["cells"][1]["source"])
    assert len(page["cells"]) == 2 and params == "pole_pairs = 4  # n\nrpm_min = 1800.0        # rpm\n"
    text = "".join(page["cells"][0]["source"])
    assert "{doc}" not in text and "the chapter *Watchdog timer: CAP-TI*" in text and "*the delay*" in text
