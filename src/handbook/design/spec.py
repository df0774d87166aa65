"""Design specifications: a TOML file with optional tables [commutation], [current_limiter], [class_d],
[converter].

Everything is checked before any computation, from the one schema (:mod:`handbook.design.schema`):
unknown tables and keys (with the near match; a key written outside any table is told which table it
belongs in), types, finiteness and ranges (a charge current of 22 instead of 22e-6 is out of range),
then each design's limits that contradict each other. A missing table or key takes the notes' values,
so an empty file designs the notes' own examples. All values are in SI units.
"""
from __future__ import annotations

import difflib
import tomllib
from collections.abc import Mapping
from pathlib import Path
from types import MappingProxyType

from ..core import InputError
from . import class_d, commutation, converter, limiter
from .common import tables_of
from .schema import TABLES
from .solvers import Infeasible

#: table -> the design module that checks and solves it
DESIGNS = {"commutation": commutation, "current_limiter": limiter, "class_d": class_d,
           "converter": converter}
#: table -> the results its design reports (unit and label declared on the result's fields)
OUTPUTS = {"commutation": commutation.CommutationResult.outputs(), "current_limiter": limiter.LimiterResult.outputs(),
           "class_d": class_d.ClassDResult.outputs(), "converter": converter.ConverterResult.outputs()}


class Spec(Mapping):
    """A read specification: a mapping {table: the keys given there}, as written (every table present, empty
    where nothing was given), with every table checked once, at reading: ``tables`` {table: its checked
    :class:`~handbook.design.common.Table`}, which the designs take without checking again."""

    def __init__(self, given: dict, tables: dict, written: tuple = ()):  # read-only views: what was read, checked
        self._given = MappingProxyType({t: MappingProxyType(dict(body)) for t, body in given.items()})
        self.tables = MappingProxyType(dict(tables))
        #: the tables the document wrote (possibly empty): a BOM lists only these, or all four when none was
        self.written = tuple(written)

    @property
    def asked(self) -> tuple:
        """The tables this spec asks to design: those it wrote, or all four when it wrote none."""
        return self.written or tuple(self._given)

    def __getitem__(self, table: str) -> dict:
        return self._given[table]

    def __iter__(self):
        return iter(self._given)

    def __len__(self) -> int:
        return len(self._given)


def parse(data: dict) -> Spec:
    """A specification read from its TOML tables: every key, value and contradiction checked here, once.

    Parameters
    ----------
    data : dict
        The parsed TOML document, {table: {key: value}} in SI units (speeds in rpm, temperatures in C);
        tables and keys left out take the notes' values.

    Returns
    -------
    Spec
        The keys as given, {table: {key: value}} with every table present, and ``tables``: each table checked
        and completed with its defaults (:class:`~handbook.design.common.Table`).

    Raises
    ------
    InputError
        For a document that is not a set of tables, an unknown table or key (with the near match, or the table
        a misplaced key belongs in), a value of the wrong type, not finite or out of range, or limits that
        contradict each other.
    """
    if not isinstance(data, dict):
        raise InputError("the specification must be a TOML document with tables")
    given = {t: {} for t in TABLES}
    for table, body in data.items():
        if table not in TABLES:
            homes = tables_of(table)
            if homes:
                raise InputError(f"{table} = {body!r} is written outside any table: put it under [{homes[0]}]")
            near = difflib.get_close_matches(table, TABLES, n=1)
            raise InputError(f"unknown table [{table}]" + (f": did you mean [{near[0]}]?" if near else
                                                            f": use {', '.join('[' + t + ']' for t in TABLES)}"))
        if not isinstance(body, dict):
            raise InputError(f"{table} must be a table ([{table}]), not a value")
        given[table] = dict(body)
    return Spec(given, {t: DESIGNS[t].checked(given[t]) for t in DESIGNS}, tuple(t for t in TABLES if t in data))


def load(path: str | Path) -> dict:
    """Read and check a TOML specification file (:func:`parse`).

    Parameters
    ----------
    path : str or pathlib.Path
        The TOML file, UTF-8.

    Returns
    -------
    Spec
        The checked specification, as :func:`parse` returns it.

    Raises
    ------
    InputError
        When the file cannot be read, is not valid UTF-8 TOML, or :func:`parse` rejects it.
    """
    try:
        text = Path(path).read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror}") from None
    try:
        data = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError(f"{path} is not valid TOML: {exc}") from None
    return parse(data)


def check(spec: Mapping) -> dict:
    """Every table completed with the defaults and checked (ranges and contradictions) before any solver: a
    :class:`Spec` was checked when it was read, a plain {table: keys} mapping is checked here.

    Parameters
    ----------
    spec : Mapping
        A :class:`Spec`, or {table: {key: value}} in SI units (tables left out take their defaults).

    Returns
    -------
    dict
        {table: its checked :class:`~handbook.design.common.Table`} for all four tables.

    Raises
    ------
    InputError
        When a table of a plain mapping is invalid.
    """
    return (spec if isinstance(spec, Spec) else parse(dict(spec))).tables


def run_each(spec: dict) -> dict:
    """Each design on its own: {table: its Result, or the Infeasible saying what can be met}.

    Parameters
    ----------
    spec : Mapping
        A :class:`Spec`, or {table: {key: value}} in SI units (tables left out take their defaults).

    Returns
    -------
    dict
        {table: the design's result (a :class:`~handbook.design.common.Result`), or the
        :class:`~handbook.design.solvers.Infeasible` it raised (not raised)} for all four tables.

    Raises
    ------
    InputError
        When a table is invalid (before any design runs).
    """
    checked = check(spec)
    out = {}
    for table, module in DESIGNS.items():
        try:
            out[table] = module.design(checked[table])
        except Infeasible as exc:
            out[table] = exc
    return out


def run(spec: dict) -> dict:
    """All four designs. Raises InputError for bad input, Infeasible for the first unmeetable table.

    Parameters
    ----------
    spec : Mapping
        A :class:`Spec`, or {table: {key: value}} in SI units (tables left out take their defaults).

    Returns
    -------
    dict
        {table: the design's :class:`~handbook.design.common.Result`} for all four tables.

    Raises
    ------
    InputError
        When a table is invalid.
    Infeasible
        The first (in the order of :data:`DESIGNS`) that a design raised, after all four have run.
    """
    out = run_each(spec)
    for result in out.values():
        if isinstance(result, Infeasible):
            raise result
    return out


def summary(result: dict) -> dict:
    """{table: {output key: SI value}} for the JSON output.

    Parameters
    ----------
    result : dict
        {table: its :class:`~handbook.design.common.Result`}, as :func:`run` returns it.

    Returns
    -------
    dict
        {table: {output key: value}}, each result's :meth:`~handbook.design.common.Result.summary` (SI units).
    """
    return {t: r.summary() for t, r in result.items()}


def traced(spec: Spec) -> dict:
    """What a JSON output carries to trace a design to its input: the handbook's version, the spec as read
    (every table after defaults, SI units), its hash, and the unit of every output.

    Parameters
    ----------
    spec : Spec
        The read specification (:func:`parse`, :func:`load`).

    Returns
    -------
    dict
        ``version`` (str), ``spec_sha256`` (hex of the canonical JSON of ``spec`` and the tables it asked for),
        ``spec`` ({table: {key:
        value}}, after defaults), ``asked`` (the tables the spec wrote; all four when it wrote none; the others
        are the notes' defaults) and ``units`` ({table: {output key: unit}}; "1" a plain number, "fraction" a
        fraction, "" text, "degC" degrees Celsius).
    """
    import hashlib
    import json

    from ..core.version import VERSION

    read = {t: dict(spec.tables[t]) for t in spec.tables}
    # the tables asked for are part of what was designed (a [class_d]-only spec designs one circuit of the same
    # defaults): hashed with the values
    canonical = json.dumps({"asked": sorted(spec.asked), "spec": read}, sort_keys=True, default=str,
                           separators=(",", ":"))
    unit = {"%": "fraction", "C": "degC"}  # a fraction stored, a percentage only when shown
    return {"version": VERSION, "spec_sha256": hashlib.sha256(canonical.encode()).hexdigest(), "spec": read,
            "asked": list(spec.asked), "units": {t: {o.key: unit.get(o.unit, o.unit) for o in outs}
                                                 for t, outs in OUTPUTS.items()}}


__all__ = ["DESIGNS", "OUTPUTS", "Spec", "InputError", "Infeasible", "check", "load", "parse", "run", "run_each",
           "summary", "traced"]
