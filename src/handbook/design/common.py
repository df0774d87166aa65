"""What every design shares: completing and checking its table, and the result's JSON summary."""
from __future__ import annotations

import difflib
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, fields

from ..core import InputError
from .schema import TABLES


def tables_of(key: str) -> list[str]:
    """The spec tables that have ``key``, in the schema's order (``t_ambient`` is in two).

    Parameters
    ----------
    key : str
        A key of the schema, or any name.

    Returns
    -------
    list of str
        The tables whose schema holds ``key``; empty when none does.
    """
    return [t for t, params in TABLES.items() if any(p.name == key for p in params)]


def key_error(table: str, key: str) -> InputError:
    """The error for ``key`` in ``[table]`` where the schema has no such key: the table it belongs in, if
    another has it, else the nearest key of this table, else the list of them.

    Parameters
    ----------
    table : str
        The table the key was written in ("commutation", "current_limiter", "class_d", "converter").
    key : str
        The key that table's schema does not have.

    Returns
    -------
    InputError
        The error to raise (not raised here), its message naming the key's table or the near match.
    """
    homes = [t for t in tables_of(key) if t != table]
    if homes:
        return InputError(f"{key} is not a key of [{table}]: it belongs in {' or '.join(f'[{t}]' for t in homes)}")
    names = [p.name for p in TABLES[table]]
    near = difflib.get_close_matches(key, names, n=1)
    return InputError(f"unknown key {table}.{key}" + (f": did you mean {table}.{near[0]}?" if near else
                                                     f": known keys are {', '.join(names)}"))


class Table(Mapping):
    """One table of a specification, checked: every key of the schema present (defaults filled in), every
    value in range, the table's own contradictions ruled out. Frozen; read as a mapping (``s["rpm_min"]``) or
    by attribute (``s.rpm_min``). Only a design's ``checked`` makes one, so a design handed a Table does not
    check it again; ``{**s, key: value}`` is a plain dict, checked afresh where it is used as a spec.
    """

    __slots__ = ("name", "_values", "_checked")

    def __init__(self, name: str, values: Mapping):
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "_values", dict(values))
        object.__setattr__(self, "_checked", False)  # only checked_table marks one: a hand-made Table is checked again

    def __getitem__(self, key: str):
        return self._values[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __getattr__(self, key: str):
        if key.startswith("_"):  # not a key: copy and pickle look for such names before __init__ has run
            raise AttributeError(key)
        try:
            return self._values[key]
        except KeyError:
            raise AttributeError(f"[{self.name}] has no key {key!r}") from None

    def __reduce__(self):
        return _restored, (self.name, self._values, self._checked)

    def __setattr__(self, key, value):
        raise AttributeError(f"a checked [{self.name}] table is frozen: make a new spec with {{**s, {key!r}: ...}}")

    def __repr__(self) -> str:
        return f"Table({self.name!r}, {self._values!r})"


def checked_table(name: str, values: Mapping) -> Table:
    """The :class:`Table` a design's ``checked`` returns once every value and contradiction has been checked.

    Parameters
    ----------
    name : str
        The spec table ("commutation", "current_limiter", "class_d", "converter").
    values : Mapping
        Every key of the table, checked, SI units.

    Returns
    -------
    Table
        The frozen table, marked as checked (:func:`is_checked`).
    """
    table = Table(name, values)
    object.__setattr__(table, "_checked", True)
    return table


def _restored(name: str, values: Mapping, checked: bool) -> Table:
    """A Table from its pickled parts, checked only if it was (copy and pickle keep the mark)."""
    return checked_table(name, values) if checked else Table(name, values)


def is_checked(table: str, spec) -> bool:
    """``spec`` is already a checked ``[table]`` (made by that design's ``checked``): a design takes it as it is.

    Parameters
    ----------
    table : str
        The table's name.
    spec : object
        What a design was handed: a :class:`Table`, a mapping of keys, or None.

    Returns
    -------
    bool
        True when ``spec`` is a :class:`Table` of that name made by :func:`checked_table`.
    """
    return isinstance(spec, Table) and spec.name == table and spec._checked


def completed(table: str, spec: Mapping | None) -> dict:
    """The table's defaults with ``spec`` applied, each value checked against the schema (one message style:
    :meth:`handbook.core.source.Param.check`).

    Parameters
    ----------
    table : str
        The table's name in the schema (:data:`~handbook.design.schema.TABLES`).
    spec : Mapping or None
        The keys given, {key: value} in SI units; None: none.

    Returns
    -------
    dict
        Every key of the table, {key: value}: the default where none is given, else the checked value (a whole
        number for a key whose default is one).

    Raises
    ------
    InputError
        For a key the table does not have, a value of the wrong type, not finite or out of range.
    """
    params = {p.name: p for p in TABLES[table]}
    out = {name: p.default for name, p in params.items()}
    for key, value in (spec or {}).items():
        if key not in params:
            raise key_error(table, key)
        out[key] = value if value is None and params[key].default is None else params[key].check(value, f"{table}.")
    return out


def ordered(table: str, low_key: str, high_key: str, s: dict, unit: str, strict: bool = True) -> None:
    """``s[low_key]`` must be below ``s[high_key]`` (or not above, with ``strict`` False).

    Parameters
    ----------
    table : str
        The table's name, for the message.
    low_key, high_key : str
        The two keys of ``s``.
    s : dict
        The completed table, {key: value}.
    unit : str
        The two values' unit, for the message ("A", "V", "rpm").
    strict : bool
        True: ``s[low_key]`` must be below ``s[high_key]``; False: it may equal it.

    Raises
    ------
    InputError
        When the two are not in that order.
    """
    low, high = s[low_key], s[high_key]
    if (low >= high) if strict else (low > high):
        verb = "must be below" if strict else "must not exceed"
        raise InputError(f"{table}.{low_key} = {low:g} {unit} {verb} {table}.{high_key} = {high:g} {unit}")


@dataclass(frozen=True)
class Output:
    """One result a design reports: its key in the JSON (SI), the unit, and a label for people."""

    key: str
    unit: str  # "F", "ohm", "A", ...; "%" for a fraction shown as a percentage; "" for text or plain numbers
    label: str


def reported(unit: str, label: str):
    """A result field the design reports (in the JSON, the text output and the chapters' tables), with its
    unit and its label: the one place either is written.

    Parameters
    ----------
    unit : str
        The field's SI unit ("F", "ohm", "Hz", ...), "%" for a fraction shown as a percentage, "" for text or a
        plain number.
    label : str
        What the field is, for people.

    Returns
    -------
    dataclasses.Field
        A dataclass field with no default whose metadata carries ``unit`` and ``label``.
    """
    return field(metadata={"unit": unit, "label": label})


@dataclass(frozen=True)
class Result:
    """A design's result: its checked spec and the values it reports (the fields declared with
    :func:`reported`, in their order)."""

    spec: dict

    table = ""

    @classmethod
    def outputs(cls) -> tuple[Output, ...]:
        """The reported fields, in order, with unit and label.

        Returns
        -------
        tuple of Output
            One (key, unit, label) per field declared with :func:`reported`, in the class's field order.
        """
        return tuple(Output(f.name, f.metadata["unit"], f.metadata["label"]) for f in fields(cls) if "unit" in f.metadata)

    def summary(self) -> dict:
        """The reported values in SI units, keyed as in the JSON output.

        Returns
        -------
        dict
            {key: value} for every reported field (:meth:`outputs`), in SI units (fractions where the unit is
            "%"), in their order.
        """
        return {o.key: getattr(self, o.key) for o in self.outputs()}


def explained(design, spec: dict | None):
    """Why ``spec`` cannot be met, and what can (the :class:`~handbook.design.solvers.Infeasible` that
    ``design`` raises), or None when ``design`` meets it: every design's ``explain``.

    Parameters
    ----------
    design : callable
        A design's ``design(spec)``, which raises :class:`~handbook.design.solvers.Infeasible` when nothing meets
        the spec.
    spec : dict or None
        The design's table, {key: value} in SI units (None: the defaults).

    Returns
    -------
    Infeasible or None
        The exception ``design`` raised (not raised again), or None when it met the spec.

    Raises
    ------
    InputError
        When ``spec`` is invalid (``design`` raises it, and it is not caught).
    """
    from .solvers import Infeasible
    try:
        design(spec)
    except Infeasible as exc:
        return exc
    return None
