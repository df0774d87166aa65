"""Render a re-run chapter (or "Design your own" on a spec) to a web page with the book's look, offline.

A papermill re-run is a notebook whose prose still holds ``{glue:text}`` roles: only the book's build
(Jupyter Book, myst-nb) puts the glued values in, typesets the math (MathJax from the pinned
``django-static-mathjax`` wheel, no CDN) and lays out the tables. This builds a one-page book around the
notebook with the project's own ``_config.yml``, extension and style sheet, without executing anything:

    python -m handbook render out.ipynb [-o DIR]            # a chapter re-run with papermill
    python -m handbook render --spec my_spec.toml [-o DIR]  # "Design your own" on a spec, then rendered

and prints the path of the page to open.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

from .core import InputError

ROOT = Path(__file__).resolve().parents[2]  # the project (src/handbook/render.py)


def _project() -> Path:
    missing = [p for p in ("_config.yml", "book/_ext/book_fixes.py", "book/_static/handbook.css") if not (ROOT / p).exists()]
    if missing:
        raise InputError(f"render needs the handbook's project files beside the package ({', '.join(missing)} not "
                         f"found under {ROOT}); run it from a clone installed with `pip install -e .`")
    return ROOT


def _config(root: Path, title: str) -> dict:
    cfg = yaml.safe_load((root / "_config.yml").read_text())
    cfg["title"] = title
    cfg["only_build_toc_files"] = True
    cfg["exclude_patterns"] = ["_build/*"]
    cfg["execute"] = {"execute_notebooks": "off"}  # the notebook was executed by papermill: its outputs are shown
    sphinx = cfg.setdefault("sphinx", {})
    sphinx["local_extensions"] = {"book_fixes": str(root / "book" / "_ext")}
    sphinx.setdefault("config", {})["html_static_path"] = [str(root / "book" / "_static")]
    # links to the book's other chapters cannot resolve in a one-page build: say so, do not fail on it
    sphinx["config"]["suppress_warnings"] = [*sphinx["config"].get("suppress_warnings", []), "myst.xref_missing"]
    return cfg


_ANSI = re.compile(r"\x1b\[[0-9;]*m")


def render(notebook: str | Path, out: str | Path | None = None, warnings: list | None = None) -> Path:
    """Build ``notebook`` (executed, e.g. by papermill) into ``out`` (default: beside it, ``<name>_html``);
    returns the page's path. The build's warnings are appended to ``warnings``; a value the prose glues but
    the notebook does not hold (a notebook not executed, or stopped early) is an error."""
    root = _project()
    nb = Path(notebook).resolve()
    if not nb.is_file() or nb.suffix != ".ipynb":
        raise InputError(f"render: {notebook!r} is not a notebook file (.ipynb); give the notebook papermill wrote")
    target = Path(out).resolve() if out else nb.with_name(nb.stem + "_html")
    with tempfile.TemporaryDirectory(prefix="handbook-render-") as tmp:
        src = Path(tmp)
        shutil.copy(nb, src / "page.ipynb")
        (src / "_config.yml").write_text(yaml.safe_dump(_config(root, nb.stem), sort_keys=False))
        (src / "_toc.yml").write_text("format: jb-book\nroot: page\n")
        proc = subprocess.run([sys.executable, "-c", "from jupyter_book.cli.main import main; main()", "build",
                               str(src), "--path-output", str(src), "--all", "-q"],
                              capture_output=True, text=True)
        html = src / "_build" / "html"
        said = [_ANSI.sub("", line).replace(str(src / "page.ipynb"), nb.name)
                for line in proc.stderr.splitlines() if "WARNING" in line]
        unglued = sorted(set(re.findall(r"No key '([^']+)' found in glue data", "\n".join(said))))
        if unglued:
            raise InputError(f"render: {nb.name}'s prose uses glued values its outputs do not hold "
                             f"({', '.join(unglued)}): execute it first (papermill, or the book's tools/run_notebooks.py)")
        if warnings is not None:  # links to the book's other chapters cannot resolve in a one-page build
            warnings.extend(w for w in said if "unknown document" not in w)
        if proc.returncode != 0 or not (html / "page.html").exists():
            said = [line for line in (proc.stderr + proc.stdout).splitlines() if line.strip()][-8:]
            raise InputError(f"render: the book build of {nb.name} failed:\n" + "\n".join(said))
        if target.exists():
            shutil.rmtree(target)
        shutil.copytree(html, target)
    return target / "page.html"


def render_spec(spec: str | Path, out: str | Path | None = None) -> Path:
    """Run "Design your own" on ``spec`` with papermill, then render it."""
    import papermill as pm

    from .design import spec as spec_mod

    path = Path(spec).resolve()
    spec_mod.load(path)  # a bad spec is refused here, with the key and the value, before anything runs
    root = _project()
    target = Path(out).resolve() if out else path.with_name(path.stem + "_html")
    target.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="handbook-design-") as tmp:
        nb = Path(tmp) / f"{path.stem}.ipynb"
        pm.execute_notebook(str(root / "book" / "design" / "your_own.ipynb"), str(nb),
                            parameters={"spec_file": str(path)}, kernel_name="python3",
                            cwd=str(root / "book" / "design"), progress_bar=False)
        return render(nb, target)
