"""The shape of the code: small modules, small functions, one package per source document."""
import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "handbook"


def _is_data(fn: ast.FunctionDef) -> bool:
    """A function whose body only returns a literal table (a docstring aside) is data, not logic."""
    body = [s for s in fn.body if not (isinstance(s, ast.Expr) and isinstance(s.value, ast.Constant))]
    return len(body) == 1 and isinstance(body[0], ast.Return) and isinstance(body[0].value, (ast.List, ast.Dict,
                                                                                                ast.Tuple))


def _docstring_lines(tree: ast.Module) -> set[int]:
    """The line numbers of every docstring (module, class, function): documentation, not code."""
    lines = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
                lines.update(range(first.lineno, first.end_lineno + 1))
    return lines


def test_no_module_over_450_lines_and_no_function_over_70():
    """Lines of code: docstrings (numpydoc Parameters and Returns on every public function) are not counted."""
    long = []
    for path in sorted(SRC.rglob("*.py")):
        text = path.read_text()
        tree = ast.parse(text)
        docs = _docstring_lines(tree)
        if text.count("\n") - len(docs) > 450:
            long.append(f"{path.relative_to(SRC)}: {text.count(chr(10)) - len(docs)} lines of code")
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and not _is_data(node):
                n = node.end_lineno - node.lineno + 1 - len(docs & set(range(node.lineno, node.end_lineno + 1)))
                if n > 70:
                    long.append(f"{path.relative_to(SRC)}:{node.lineno} {node.name}: {n} lines")
    assert not long, "\n".join(long)


def test_every_source_package_has_the_same_shape():
    from handbook.sources import ORDER

    for name in ORDER:
        files = {p.name for p in (SRC / "sources" / name).glob("*.py")}
        assert {"__init__.py", "circuit.py", "data.py", "equations.py"} <= files, name


def test_ruff_is_clean():
    import subprocess
    import sys

    root = SRC.parents[1]
    out = subprocess.run([sys.executable, "-m", "ruff", "check", "src", "tests", "tools"], cwd=root,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stdout[-3000:]
