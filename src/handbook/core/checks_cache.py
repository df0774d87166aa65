"""The equations and their checks stored on disk, keyed on the code that defines them.

Building a source's equations (each derivation solved by sympy) and simplifying every printed-minus-derived
difference takes seconds, in every process that shows one: a chapter's kernel, a design report. Both are
stored under ``$HANDBOOK_CACHE`` (default ``~/.cache/handbook``), in files named by a hash of the source files
that define the equations, of the checking code itself and of the sympy version: any edit to them makes a
new key, so a stale derivation or check is never read. The summaries (what the command line prints) are JSON;
the records themselves, with their checks done, a pickle, written only when reading it back gives every
summary unchanged. Where the cache cannot be written or read, everything is simply computed.
"""
from __future__ import annotations

import hashlib
import importlib
import importlib.util
import io
import json
import os
import pickle
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


def _path(source, kind: str, suffix: str) -> Path:
    """The cache file of one kind ("equations": the summaries, "records": the records) for ``source``'s code now."""
    return cache_dir() / f"{kind}-{source.name.replace('/', '_')}-{key(source)}{suffix}"


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
    path = _path(source, "equations", ".json")
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        pass
    rows = [e.summary() for e in source.equations()]
    _store(path, json.dumps(rows).encode())
    return rows


class _Pickler(pickle.Pickler):
    """Unit quantities by reference (``sympy.physics.units.ohm`` itself): pickled by value, sympy drops the LaTeX
    form a quantity was made with (Ω would read back as "ohm")."""

    def reducer_override(self, obj):
        from sympy.physics import units
        from sympy.physics.units.quantities import Quantity

        if isinstance(obj, Quantity) and getattr(units, str(obj.name), None) is obj:
            return _unit, (str(obj.name),)
        return NotImplemented


def _unit(name: str):
    """The quantity ``sympy.physics.units.<name>`` (what :class:`_Pickler` stores a unit as)."""
    from sympy.physics import units

    return getattr(units, name)


def _store(path: Path, data: bytes) -> None:
    """``data`` written to ``path`` whole or not at all (another process may be writing the same file)."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_bytes(data)
        os.replace(tmp, path)
    except OSError:
        pass


def cached_equations(source) -> tuple:
    """A source's equation records, their checks done: read from the cache, or built (its equations module's
    ``build()``), checked and stored there.

    Parameters
    ----------
    source : Source
        The source document (its ``name`` and ``equations_module`` are read).

    Returns
    -------
    tuple of Equation
        The records in the module's order.
    """
    path = _path(source, "records", ".pickle")
    try:
        return pickle.loads(path.read_bytes())
    except Exception:  # noqa: BLE001 (no file, or one another version wrote: built again)
        pass
    records = tuple(importlib.import_module(source.equations_module).build())
    summaries = [e.summary() for e in records]  # the checks, done once here and stored with the records
    buffer = io.BytesIO()
    try:
        _Pickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(records)
        same = [e.summary() for e in pickle.loads(buffer.getvalue())] == summaries  # read back, nothing lost
    except Exception:  # noqa: BLE001 (a record holds what cannot be stored: not stored, still returned)
        same = False
    if same:
        _store(path, buffer.getvalue())
    return records
