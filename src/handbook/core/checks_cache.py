"""The equations' checks stored on disk, keyed on the code that defines them.

Building a source's equations and simplifying every printed-minus-derived difference takes seconds;
the command line should answer in well under one. The summaries are stored as JSON under
``$HANDBOOK_CACHE`` (default ``~/.cache/handbook``), in a file named by a hash of the source files
that define the equations, of the checking code itself and of the sympy version: any edit to them
makes a new key, so a stale check is never read. Where the cache cannot be written, the checks are
simply computed.
"""
from __future__ import annotations

import hashlib
import importlib.util
import json
import os
from pathlib import Path


def _package_files(module: str) -> list[Path]:
    """Every .py file of the package ``module`` lives in (the module's own file if it is not in one)."""
    spec = importlib.util.find_spec(module)
    if spec is None or spec.origin is None:
        raise ModuleNotFoundError(module)
    folder = Path(spec.origin).parent
    return sorted(folder.rglob("*.py")) if (folder / "__init__.py").exists() else [Path(spec.origin)]


def key(source) -> str:
    """A hash of everything a source's equation summaries depend on.

    Parameters
    ----------
    source : Source
        The source document whose equations are checked (its ``name`` and ``equations_module`` are read).

    Returns
    -------
    str
        The first 20 hex digits of a SHA-256 over the sympy version, the source's name, and the code of every
        module the summaries can read: the whole package of its equations module (its data, circuit and facts
        as well as the equations) and the whole of ``handbook.core`` (the checking, units and validation).
    """
    from importlib.metadata import version

    h = hashlib.sha256(f"sympy {version('sympy')}\n{source.name}\n".encode())
    root = Path(__file__).resolve().parents[1]
    for path in [*_package_files(source.equations_module), *sorted((root / "core").rglob("*.py"))]:
        h.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()[:20]


def cache_dir() -> Path:
    """The directory the summaries are stored in: ``$HANDBOOK_CACHE``, else ``~/.cache/handbook``.

    Returns
    -------
    pathlib.Path
        The cache directory (not created here).
    """
    return Path(os.environ.get("HANDBOOK_CACHE") or Path.home() / ".cache" / "handbook")


def cached_summaries(source) -> list[dict]:
    """A source's equation summaries, read from the cache or computed and stored there.

    Parameters
    ----------
    source : Source
        The source document whose equations are summarised.

    Returns
    -------
    list of dict
        One :meth:`~handbook.core.equation.Equation.summary` per equation, in the order of
        ``source.equations()``.
    """
    path = cache_dir() / f"equations-{source.name.replace('/', '_')}-{key(source)}.json"
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        pass
    rows = [e.summary() for e in source.equations()]
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(rows))
        os.replace(tmp, path)
    except OSError:
        pass
    return rows
