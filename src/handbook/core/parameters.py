"""A chapter's parameters cell, and the values a reader injects into it (papermill's ``-p``), checked before the
chapter computes anything: an unknown name is refused with the near match, a value of the wrong kind with the
chapter's default beside it. The chapters call it through ``report.setup()``; ``python -m handbook rerun`` calls
it before it starts a kernel."""
from __future__ import annotations

import ast
import difflib

from .validate import InputError

#: the first line papermill writes into the cell it injects after a chapter's parameters cell
INJECTED_MARK = "# Parameters"


def assignments(source: str) -> dict:
    """The names a parameters cell assigns, each with its literal value (``...`` where it is not a literal).

    Parameters
    ----------
    source : str
        The cell's Python source.

    Returns
    -------
    dict
        Name -> value, in the cell's order.
    """
    out = {}
    for node in ast.parse(source).body:
        if isinstance(node, ast.Assign):
            targets, value = node.targets, node.value
        elif isinstance(node, ast.AnnAssign) and node.value is not None:
            targets, value = [node.target], node.value
        else:
            continue
        try:
            literal = ast.literal_eval(value)
        except ValueError:
            literal = ...
        for t in targets:
            if isinstance(t, ast.Name):
                out[t.id] = literal
    return out


def _kind(value) -> str:
    if value is None or value is ...:
        return "any"
    if isinstance(value, bool):
        return "true or false"
    if isinstance(value, int):
        return "a whole number"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, str):
        return "text"
    return "any"


def _fits(default, value) -> bool:
    kind = _kind(default)
    if kind == "any":
        return True
    if kind == "true or false":
        return isinstance(value, bool)
    if kind == "a whole number":
        return isinstance(value, int) and not isinstance(value, bool) or (isinstance(value, float) and value.is_integer())
    if kind == "a number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    return isinstance(value, str)


def check(declared: dict, given: dict, chapter: str = "this chapter") -> None:
    """Refuse a given parameter the chapter does not declare, or one of another kind than its default.

    Parameters
    ----------
    declared : dict
        The parameters cell's names and defaults (:func:`assignments`).
    given : dict
        The names and values a reader injects.
    chapter : str
        How to name the chapter in a message.

    Returns
    -------
    None
        Nothing; raises :class:`~handbook.core.validate.InputError` (one line: the key, the value, the near
        match or the kind the default has) on the first bad entry.
    """
    for key, value in given.items():
        if key not in declared:
            near = difflib.get_close_matches(key, list(declared), n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise InputError(f"{chapter}: unknown parameter {key!r}{hint}; its parameters are "
                             f"{', '.join(declared)}")
        if not _fits(declared[key], value):
            raise InputError(f"{chapter}: parameter {key!r} = {value!r} is not {_kind(declared[key])} (its default is "
                             f"{declared[key]!r})")


def check_history(history: list[str]) -> None:
    """In a kernel: when the cell before the current one is papermill's injected parameters, check it against the
    parameters cell before it (:func:`check`). Nothing happens in a chapter run as written.

    Parameters
    ----------
    history : list of str
        The kernel's input history, the current cell last (IPython's ``In``).

    Returns
    -------
    None
        Nothing; raises :class:`~handbook.core.validate.InputError` on a bad injected parameter.
    """
    if len(history) < 3 or not history[-2].lstrip().startswith(INJECTED_MARK):
        return
    check(assignments(history[-3]), assignments(history[-2]))


__all__ = ["INJECTED_MARK", "assignments", "check", "check_history"]
