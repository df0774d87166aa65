"""The package's layers: core <- sources <- design <- spice <- report <- the command line and the book.

Every import in src/handbook (at the top of a module or inside a function) is read from the source with
``ast``; a module may import from its own layer or a lower one, never a higher one, and no two modules may
import each other, directly or round a longer loop. And ``design --json`` loads neither matplotlib nor IPython.
"""
import ast
import os
import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
#: first component under handbook -> layer (higher may import lower)
LAYERS = {"core": 0, "sources": 1, "design": 2, "spice": 3, "report": 4,
          "catalog": 5, "cli": 5, "cli_text": 5, "render": 5, "__main__": 5, "__init__": 5}


def _modules() -> dict[str, Path]:
    out = {}
    for path in (SRC / "handbook").rglob("*.py"):
        parts = path.relative_to(SRC).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def _resolve(module: str, is_package: bool, node: ast.ImportFrom | ast.Import, known: dict) -> set[str]:
    """The handbook modules an import statement loads (a name that is a submodule counts as that module)."""
    if isinstance(node, ast.Import):
        return {a.name for a in node.names if a.name.split(".")[0] == "handbook"}
    if node.level:
        base = module.split(".") if is_package else module.split(".")[:-1]
        base = base[:len(base) - node.level + 1]
        target = ".".join(base + ([node.module] if node.module else []))
    else:
        target = node.module or ""
    if target.split(".")[0] != "handbook":
        return set()
    out = set()
    for alias in node.names:
        sub = f"{target}.{alias.name}"
        out.add(sub if sub in known else target)
    return out


def graph() -> dict[str, set[str]]:
    known = _modules()
    edges = {}
    for module, path in known.items():
        tree = ast.parse(path.read_text())
        found = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                found |= _resolve(module, path.name == "__init__.py", node, known)
        found = {m for m in found if m in known and m != module}
        # importing a module first runs every package __init__ above it that is not already running (the
        # importer's own parents are): those run too, and a loop through them breaks the import just the same
        mine = _parents(module) | {module}
        edges[module] = found | {p for m in found for p in _parents(m) if p not in mine and p in known}
    return edges


def _parents(module: str) -> set[str]:
    parts = module.split(".")
    return {".".join(parts[:i]) for i in range(1, len(parts))}


def _layer(module: str) -> int:
    parts = module.split(".")
    return LAYERS["__init__" if len(parts) == 1 else parts[1]]


def test_every_module_has_a_layer():
    tops = {m.split(".")[1] for m in graph() if "." in m}
    assert tops <= set(LAYERS), tops - set(LAYERS)


def test_no_upward_import():
    up = [f"{a} (layer {_layer(a)}) imports {b} (layer {_layer(b)})" for a, bs in graph().items() for b in bs
          if _layer(b) > _layer(a)]
    assert not up, "\n".join(sorted(up))


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10_000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def test_no_import_cycle():
    # a package's __init__ imports its own modules to offer them; a module importing its package back closes
    # a loop, and so does any longer round
    assert not _cycles(graph())


def test_the_resolver_reads_relative_aliased_and_parent_imports():
    known = {"handbook.design.solvers": None, "handbook.design.converter": None, "handbook.design.converter.cores": None,
             "handbook.report.tables": None, "handbook.report": None, "handbook.design": None}
    one = ast.parse("from .converter.cores import candidates\nimport handbook.report.tables as t\nfrom .. import report\n")
    got = set().union(*(_resolve("handbook.design.solvers", False, n, known) for n in one.body))
    assert got == {"handbook.design.converter.cores", "handbook.report.tables", "handbook.report"}
    assert _parents("handbook.design.converter.cores") == {"handbook", "handbook.design", "handbook.design.converter"}


def test_a_loop_through_a_package_init_is_a_cycle():
    """solvers -> converter.cores runs converter/__init__, which imports converter.result, which imports solvers:
    the edge to the parent package closes the loop the plain module edges miss."""
    edges = {"handbook.design.solvers": {"handbook.design.converter.cores", "handbook.design.converter"},
             "handbook.design.converter": {"handbook.design.converter.result"},
             "handbook.design.converter.result": {"handbook.design.solvers"}, "handbook.design.converter.cores": set()}
    assert _cycles(edges) == [["handbook.design.converter", "handbook.design.converter.result", "handbook.design.solvers"]]


def test_the_checker_sees_a_cycle_and_an_upward_import():
    edges = {"handbook.design.a": {"handbook.design.b"}, "handbook.design.b": {"handbook.design.a"},
             "handbook.core.x": set()}
    assert _cycles(edges) == [["handbook.design.a", "handbook.design.b"]]
    assert _layer("handbook.report.tables") > _layer("handbook.spice.checks") > _layer("handbook.design.spec")


def test_design_json_loads_no_plotting_or_notebook_library(tmp_path):
    spec = tmp_path / "spec.toml"
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    spec.write_text(subprocess.run([sys.executable, "-m", "handbook", "design", "--template"], capture_output=True,
                                   text=True, check=True, env=env).stdout)
    probe = ("import atexit, runpy, sys\n"
             "atexit.register(lambda: print('LOADED', sorted(m for m in ('matplotlib', 'IPython', 'myst_nb') "
             "if m in sys.modules), file=sys.stderr))\n"
             f"sys.argv = ['handbook', 'design', {str(spec)!r}, '--json']\n"
             "runpy.run_module('handbook', run_name='__main__')\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert '"cap_cd"' in out.stdout and "LOADED []" in out.stderr, out.stderr[-2000:]
