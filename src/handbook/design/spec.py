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
import math
import numbers
import tomllib
from pathlib import Path

from ..core import InputError
from ..core.source import unknown_key_message
from ..core.validate import out_of_range
from . import class_d, commutation, converter, limiter
from .schema import TABLES
from .solvers import Infeasible

#: table -> the design module that checks and solves it
DESIGNS = {"commutation": commutation, "current_limiter": limiter, "class_d": class_d,
           "converter": converter}
#: table -> the results its design reports (unit and label declared on the result's fields)
OUTPUTS = {"commutation": commutation.CommutationResult.outputs(), "current_limiter": limiter.LimiterResult.outputs(),
           "class_d": class_d.ClassDResult.outputs(), "converter": converter.ConverterResult.outputs()}


def _table_of(key: str) -> str | None:
    return next((t for t, params in TABLES.items() if any(p.name == key for p in params)), None)


def parse(data: dict) -> dict:
    """Checked spec: {table: {key: value}} with every table present (missing keys left to the defaults)."""
    if not isinstance(data, dict):
        raise InputError("the specification must be a TOML document with tables")
    out = {t: {} for t in TABLES}
    for table, body in data.items():
        if table not in TABLES:
            home = _table_of(table)
            if home is not None:
                raise InputError(f"{table} = {body!r} is written outside any table: put it under [{home}]")
            near = difflib.get_close_matches(table, TABLES, n=1)
            raise InputError(f"unknown table [{table}]" + (f": did you mean [{near[0]}]?" if near else
                                                            f": use {', '.join('[' + t + ']' for t in TABLES)}"))
        if not isinstance(body, dict):
            raise InputError(f"{table} must be a table ([{table}]), not a value")
        params = {p.name: p for p in TABLES[table]}
        for key, value in body.items():
            if key not in params:
                home = _table_of(key)
                if home is not None:  # a known key in the wrong table
                    raise InputError(f"{key} is not a key of [{table}]: it belongs in [{home}]")
                near = difflib.get_close_matches(key, params, n=1)
                raise InputError(f"unknown key {table}.{key}" + (f": did you mean {table}.{near[0]}?" if near else
                                                                 f": known keys are {', '.join(params)}"))
            out[table][key] = _checked(params[key], value, f"{table}.{key}")
    return out


def _checked(param, value, name: str):
    """The schema's check of one value; a number out of range is told with engineering prefixes ('50 MHz',
    'from 1 kHz to 1 MHz') and the key's meaning."""
    if (isinstance(value, numbers.Real) and not isinstance(value, bool) and math.isfinite(value)
            and not param.choices and not isinstance(param.default, str)):
        error = out_of_range(name, value, param.unit, param.low, param.high, param.low_open, param.meaning)
        if error is not None:
            raise error
    return param.check(value, name[: -len(param.name)])


def load(path: str | Path) -> dict:
    try:
        text = Path(path).read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror}") from None
    try:
        data = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError(f"{path} is not valid TOML: {exc}") from None
    return parse(data)


def check(spec: dict) -> dict:
    """Every table completed with the defaults and checked (ranges and contradictions) before any solver."""
    return {t: DESIGNS[t].checked(spec.get(t, {})) for t in DESIGNS}


def run_each(spec: dict) -> dict:
    """Each design on its own: {table: its Result, or the Infeasible saying what can be met}."""
    checked = check(spec)
    out = {}
    for table, module in DESIGNS.items():
        try:
            out[table] = module.design(checked[table])
        except Infeasible as exc:
            out[table] = exc
    return out


def run(spec: dict) -> dict:
    """All four designs. Raises InputError for bad input, Infeasible for the first unmeetable table."""
    out = run_each(spec)
    for result in out.values():
        if isinstance(result, Infeasible):
            raise result
    return out


def summary(result: dict) -> dict:
    """{table: {output key: SI value}} for the JSON output."""
    return {t: r.summary() for t, r in result.items()}


__all__ = ["DESIGNS", "OUTPUTS", "InputError", "Infeasible", "check", "load", "parse", "run", "run_each", "summary",
           "unknown_key_message"]
