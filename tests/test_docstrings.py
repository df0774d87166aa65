"""Every public function documents its arguments and what it returns (numpydoc ``Parameters`` / ``Returns``).

Public: a function defined in the module (not imported into it) whose name does not start with ``_``, and
the public methods of the module's public classes (properties are attributes, not checked). Lambdas and
nested functions stored in tables are not module-level functions and are not checked (a lambda bound to a
public module-level name is).
"""
from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
import re
import textwrap

#: the packages checked, with every module under them
PACKAGES = ("handbook.sources", "handbook.core", "handbook.design")

_HEADER = re.compile(r"^\s*-{3,}\s*$")
_ENTRY = re.compile(r"^(?P<names>\*{0,2}\w+(?:\s*,\s*\*{0,2}\w+)*)\s*(?::\s*\S.*)?$")



def _modules(package: str):
    pkg = importlib.import_module(package)
    yield pkg
    for info in pkgutil.walk_packages(pkg.__path__, prefix=f"{package}."):
        yield importlib.import_module(info.name)


def _functions(module):
    """(qualified name, function) for every public function defined in ``module`` and every public method of
    its public classes."""
    for name, obj in sorted(vars(module).items()):
        if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
            continue
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():  # methods, not a dataclass field's default (a lambda)
                fn = member.__func__ if isinstance(member, (staticmethod, classmethod)) else member
                if not attr.startswith("_") and inspect.isfunction(fn) and fn.__name__ == attr:
                    yield f"{module.__name__}.{name}.{attr}", fn
            continue
        fn = inspect.unwrap(obj) if callable(obj) else obj
        if inspect.isfunction(fn) and fn.__name__ in (name, "<lambda>"):  # a lambda bound to a public name counts;
            yield f"{module.__name__}.{name}", fn  # another name for a function does not (it is checked as itself)


def _sections(doc: str) -> dict[str, list[str]]:
    """A numpydoc docstring's sections: title -> its lines (the header and its underline excluded)."""
    lines = inspect.cleandoc(doc or "").splitlines()
    sections, current = {}, None
    for i, line in enumerate(lines):
        if _HEADER.match(line) and i and lines[i - 1].strip():
            current = lines[i - 1].strip()
            sections[current] = []
            continue
        if current is not None and not (i + 1 < len(lines) and _HEADER.match(lines[i + 1]) and line.strip()):
            sections[current].append(line)
    return sections


def documented_parameters(doc: str) -> set[str]:
    """The names the ``Parameters`` section documents: ``name : type`` lines at the section's indentation
    (``a, b : float`` for several names; ``*args`` and ``**kwargs`` with or without their stars)."""
    body = [line for line in _sections(doc).get("Parameters", []) if line.strip()]
    if not body:
        return set()
    indent = len(body[0]) - len(body[0].lstrip())
    names = set()
    for line in body:
        if len(line) - len(line.lstrip()) != indent:
            continue
        m = _ENTRY.match(line.strip())
        if m and (":" in line or line.strip().startswith("*")):
            names.update(n.strip().lstrip("*") for n in m["names"].split(","))
    return names


def returns_value(fn) -> bool:
    """The function returns something: a return annotation other than None, or ``return <value>`` in its own
    body (not in a nested function)."""
    annotation = inspect.signature(fn).return_annotation
    if fn.__name__ == "<lambda>" or annotation not in (inspect.Signature.empty, None, "None"):
        return True
    tree = ast.parse(textwrap.dedent(inspect.getsource(fn)))
    stack = list(ast.iter_child_nodes(tree.body[0]))
    while stack:
        node = stack.pop()
        if isinstance(node, ast.Return) and node.value is not None and not (
                isinstance(node.value, ast.Constant) and node.value.value is None):
            return True
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            stack.extend(ast.iter_child_nodes(node))
    return False


def missing(fn, qualname: str) -> list[str]:
    """``qualname: argument`` for every undocumented argument, ``qualname: Returns`` for a missing Returns
    section, and ``qualname: name (documented, not an argument)`` for a stale entry."""
    args = [p.name for p in inspect.signature(fn).parameters.values() if p.name not in ("self", "cls")]
    documented = documented_parameters(fn.__doc__)
    out = [f"{qualname}: {a}" for a in args if a not in documented]
    out += [f"{qualname}: {n} (documented, not an argument)" for n in sorted(documented - set(args))]
    if returns_value(fn) and not any(line.strip() for line in _sections(fn.__doc__).get("Returns", [])):
        out.append(f"{qualname}: Returns")
    return out


def test_the_parser():
    doc = """Summary.

    Parameters
    ----------
    a, b : float
        Two values, V.
        not_a_name : a description line, deeper.
    *args
        More.
    **kw : dict
        Options.

    Returns
    -------
    float
        The sum, V.
    """
    assert documented_parameters(doc) == {"a", "b", "args", "kw"}
    assert _sections(doc)["Returns"][0].strip() == "float"
    assert documented_parameters("Summary only.") == set()

    def f(x, *, y=1):
        """Summary.

        Parameters
        ----------
        x : float
            A value.
        z : float
            Not an argument.
        """
        def inner():
            return 1
        return None

    assert missing(f, "m.f") == ["m.f: y", "m.f: z (documented, not an argument)"]


def test_every_public_function_documents_its_parameters_and_return():
    seen, problems = set(), []
    for package in PACKAGES:
        for module in _modules(package):
            for qualname, fn in _functions(module):
                if fn not in seen:
                    seen.add(fn)
                    problems += missing(fn, qualname)
    assert seen, f"no public function found under {PACKAGES}"
    assert not problems, f"{len(problems)} undocumented:\n" + "\n".join(problems)
