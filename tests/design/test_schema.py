"""The one schema: the README's key table and the design chapters' parameters cells must not drift from it."""
import ast
import json
from pathlib import Path

import pytest

from handbook.design import schema

ROOT = Path(__file__).resolve().parents[2]

#: design chapter -> the table its parameters cell sets
CHAPTERS = {"cap_cd": "commutation", "current_limiter": "current_limiter", "class_d": "class_d",
            "converter": "converter"}


def test_readme_key_table_is_the_schema():
    assert schema.markdown_table() in (ROOT / "README.md").read_text()


@pytest.mark.parametrize("chapter,table", CHAPTERS.items())
def test_parameters_cell_keys_and_defaults_are_the_schema(chapter, table):
    nb = json.loads((ROOT / "book" / "design" / f"{chapter}.ipynb").read_text())
    cell = next(c for c in nb["cells"] if "parameters" in c["metadata"].get("tags", []))
    assigned = {}
    for node in ast.parse("".join(cell["source"])).body:
        assert isinstance(node, ast.Assign) and len(node.targets) == 1, ast.dump(node)
        assigned[node.targets[0].id] = ast.literal_eval(node.value)
    defaults = schema.defaults(table)
    assert set(assigned) <= set(defaults), set(assigned) - set(defaults)
    for name, value in assigned.items():
        assert value == defaults[name] and type(value) is type(defaults[name]), name
    assert len(assigned) >= len(defaults) // 2  # the chapter offers the keys a reader changes


def test_help_lists_every_key():
    from handbook.cli import _spec_help

    text = _spec_help()
    for t, key, *_ in schema.key_rows():
        assert f"[{t}]" in text and f"    {key} = " in text
