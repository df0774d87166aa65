"""Parameters cells that papermill can read, and worked examples in step with their source chapter."""
import ast
import json
from pathlib import Path

import papermill as pm
import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(p for p in (ROOT / "book").rglob("*.ipynb") if "_build" not in p.parts)


def _parameters_cell(path):
    nb = json.loads(path.read_text())
    cells = [c for c in nb["cells"] if "parameters" in c.get("metadata", {}).get("tags", [])]
    return "".join(cells[0]["source"]) if cells else None


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: str(p.relative_to(ROOT)))
def test_papermill_reads_every_parameter(path):
    src = _parameters_cell(path)
    if src is None:
        pytest.skip("no parameters cell")
    assigned = {t.id for node in ast.parse(src).body if isinstance(node, ast.Assign) for t in node.targets}
    assert set(pm.inspect_notebook(str(path))) == assigned


@pytest.mark.parametrize("name", sorted(p.stem for p in (ROOT / "book" / "examples").glob("*.toml")))
def test_worked_examples_are_the_design_chapter_run_on_their_spec(name):
    source = json.loads((ROOT / "book" / "design" / "your_own.ipynb").read_text())
    example = json.loads((ROOT / "book" / "examples" / f"{name}.ipynb").read_text())
    code = lambda nb: ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]  # noqa: E731
    injected = [c for c in example["cells"] if "injected-parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(injected) == 1 and f'spec_file = "{name}.toml"' in "".join(injected[0]["source"])
    assert [c for c in code(example) if "injected" not in c and 'spec_file = "' not in c] == \
        [c for c in code(source) if "spec_file = " not in c]
    assert (ROOT / "book" / "examples" / f"{name}.toml").exists()
