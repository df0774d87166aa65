"""Render a re-run chapter (or "Design your own" on a spec) to a web page with the book's look, offline.

A papermill re-run is a notebook whose prose still holds ``{glue:text}`` roles: only the book's build
(Jupyter Book, myst-nb) puts the glued values in, typesets the math (MathJax from the pinned
``django-static-mathjax`` wheel, no CDN) and lays out the tables. This builds a one-page book around the
notebook with the project's own ``_config.yml``, extension and style sheet, without executing anything:

    python -m handbook render out.ipynb [-o DIR]            # a chapter re-run with papermill
    python -m handbook render --spec my_spec.toml [-o DIR]  # "Design your own" on a spec, then rendered
    python -m handbook rerun design/cap_cd -p pole_pairs 4 [-o DIR]   # a chapter with other values, checked first

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
    failed, title = _stopped_and_title(nb)
    if failed:
        raise InputError(f"render: {nb.name} did not run to the end ({failed}); fix the input and re-run it "
                         "(python -m handbook rerun)")
    target = Path(out).resolve() if out else nb.with_name(nb.stem + "_html")
    with tempfile.TemporaryDirectory(prefix="handbook-render-") as tmp:
        src = Path(tmp)
        (src / "page.ipynb").write_text(_for_one_page(nb, root), encoding="utf-8")
        (src / "_config.yml").write_text(yaml.safe_dump(_config(root, title or nb.stem), sort_keys=False))
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


def _stopped_and_title(nb: Path) -> tuple[str, str]:
    """(where and why an executed notebook stopped, or ''; the chapter's title from its first heading, or '')."""
    import json

    try:
        cells = json.loads(nb.read_text(encoding="utf-8"))["cells"]
    except (ValueError, KeyError) as exc:
        raise InputError(f"render: {nb.name} is not a readable notebook ({exc})") from None
    title = next((line[2:].strip() for c in cells if c["cell_type"] == "markdown"
                  for line in "".join(c["source"]).splitlines() if line.startswith("# ")), "")
    for c in cells:
        for o in c.get("outputs", []):
            if o.get("output_type") == "error":
                return f"cell {c.get('execution_count')}: {o.get('ename')}: {str(o.get('evalue')).splitlines()[0]}", title
    return "", title


_DOC = re.compile(r"\{doc\}`([^`<]*?)(?:\s*<([^>]+)>)?`")


def _for_one_page(nb: Path, root: Path) -> str:
    """The notebook as one page shows it: a re-run's values written into the chapter's own parameters cell (its
    unit comments kept) instead of a second, injected cell; links to the book's other chapters named in words
    (a one-page build cannot resolve them)."""
    import json

    doc = json.loads(nb.read_text(encoding="utf-8"))
    cells = doc["cells"]
    tags = [c.get("metadata", {}).get("tags", []) for c in cells]
    own = next((i for i, t in enumerate(tags) if "parameters" in t), None)
    injected = next((i for i, t in enumerate(tags) if "injected-parameters" in t), None)
    if own is not None and injected is not None:
        from .core import parameters

        values = parameters.assignments("".join(cells[injected]["source"]))
        lines = "".join(cells[own]["source"]).splitlines(keepends=True)
        for k, line in enumerate(lines):
            m = re.match(r"(\s*)([A-Za-z_]\w*)(\s*=\s*)([^#\n]*?)\s*(#.*)?(\n?)$", line)
            if m and m.group(2) in values:
                comment = f"  {m.group(5)}" if m.group(5) else ""
                lines[k] = f"{m.group(1)}{m.group(2)}{m.group(3)}{values.pop(m.group(2))!r}{comment}{m.group(6)}"
        lines += [f"{name} = {value!r}\n" for name, value in values.items()]
        cells[own]["source"] = lines
        del cells[injected]
    titles = {}
    for c in cells:
        if c["cell_type"] != "markdown":
            continue
        text = "".join(c["source"])

        def named(m):
            label, target = m.group(1).strip(), (m.group(2) or m.group(1)).strip()
            if m.group(2) and label:
                return f"*{label}*"
            if target not in titles:
                path = _chapter_path(root, nb, target)
                titles[target] = _stopped_and_title(path)[1] if path else ""
            return f"the chapter *{titles[target] or target}*"
        c["source"] = _DOC.sub(named, text).splitlines(keepends=True)
    return json.dumps(doc)


def _chapter_path(root: Path, nb: Path, target: str) -> Path | None:
    """The notebook a ``{doc}`` target names: relative to one of the book's folders (the re-run's own folder is
    not known once papermill has written it elsewhere)."""
    book = root / "book"
    for base in (book, *sorted(p for p in book.iterdir() if p.is_dir())):
        path = (base / target).with_suffix(".ipynb").resolve()
        if path.is_file():
            return path
    return None


def _chapters(root: Path) -> dict:
    """Every chapter with a parameters cell: "design/cap_cd" -> its notebook."""
    import json

    out = {}
    for path in sorted((root / "book").rglob("*.ipynb")):
        if "_build" in path.parts or ".ipynb_checkpoints" in path.parts:
            continue
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        if any("parameters" in c.get("metadata", {}).get("tags", []) for c in cells):
            out[path.relative_to(root / "book").with_suffix("").as_posix()] = path
    return out


def _value(text: str):
    """A command-line value as papermill's -p reads it: a Python literal (4, 0.5, None, "E12"), else text."""
    import ast

    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


class CannotBeMet(InputError):
    """A re-run design chapter whose parameters are valid but no parts meet (the command exits 3)."""


def execute(source: str | Path, out: str | Path, parameters: dict, cwd: str | Path | None = None, **kwargs) -> None:
    """``source`` executed by papermill with ``parameters`` into ``out``; papermill's error when a cell raises.

    The notebook is written once, at the end (papermill then writes it with the failed cell too): papermill's
    default writes and validates the whole notebook at every cell's start and end, up to a second of a chapter.
    ``cwd``: where the kernel starts; ``kwargs`` go to ``papermill.execute_notebook`` (``km``: a kernel already
    running)."""
    import papermill as pm

    pm.execute_notebook(str(source), str(out), parameters=parameters, kernel_name="python3",
                        cwd=None if cwd is None else str(cwd), progress_bar=False, request_save_on_cell_execute=False,
                        **kwargs)


def rerun(chapter: str, pairs: list[tuple[str, str]], out: str | Path | None = None) -> Path:
    """Re-run a chapter with other values, checked first, then render it; returns the page's path.

    Parameters
    ----------
    chapter : str
        The chapter, as "design/cap_cd" or "cap_cd" (a name no other chapter has).
    pairs : list of tuple
        (name, value as text) per parameter to change.
    out : str or Path or None
        The folder to write the page into (default: ``<chapter>_html`` in the working directory).

    Returns
    -------
    Path
        The rendered page.
    """
    import json

    import papermill as pm

    from .core import parameters

    root = _project()
    chapters = _chapters(root)
    names = {k: v for k, v in chapters.items() if k == chapter or k.rsplit("/", 1)[-1] == chapter}
    if len(names) != 1:
        import difflib

        near = difflib.get_close_matches(chapter, list(chapters), n=1)
        hint = f" (did you mean {near[0]!r}?)" if near else ""
        raise InputError(f"rerun: no chapter {chapter!r} with a parameters cell{hint}; they are {', '.join(chapters)}")
    (key, path), = names.items()
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    cell = next(c for c in cells if "parameters" in c.get("metadata", {}).get("tags", []))
    given = {name: _value(text) for name, text in pairs}
    parameters.check(parameters.assignments("".join(cell["source"])), given, chapter=key)
    target = Path(out).resolve() if out else Path.cwd() / (key.replace("/", "_") + "_html")
    with tempfile.TemporaryDirectory(prefix="handbook-rerun-") as tmp:
        nb = Path(tmp) / f"{path.stem}.ipynb"
        try:
            execute(path, nb, given, cwd=path.parent)
        except pm.PapermillExecutionError as exc:
            why = str(exc.evalue).splitlines()[0] if exc.evalue else exc.ename
            if exc.ename == "Infeasible":  # a valid spec nothing can meet: the design says what can be met
                raise CannotBeMet(f"rerun: {key}: cannot be met: {why}") from None
            raise InputError(f"rerun: {key} stopped in its cell {exc.exec_count}: {exc.ename}: {why}") from None
        return render(nb, target)


def render_spec(spec: str | Path, out: str | Path | None = None) -> Path:
    """Run "Design your own" on ``spec`` with papermill, then render it."""
    from .design import spec as spec_mod

    path = Path(spec).resolve()
    spec_mod.load(path)  # a bad spec is refused here, with the key and the value, before anything runs
    root = _project()
    target = Path(out).resolve() if out else path.with_name(path.stem + "_html")
    target.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="handbook-design-") as tmp:
        nb = Path(tmp) / f"{path.stem}.ipynb"
        execute(root / "book" / "design" / "your_own.ipynb", nb, {"spec_file": str(path)}, cwd=root / "book" / "design")
        return render(nb, target)
