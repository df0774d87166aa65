"""What every design shares: completing and checking its table, and the result's JSON summary."""
from __future__ import annotations

from dataclasses import dataclass, field, fields

from ..core import InputError
from ..core.source import unknown_key_message
from .schema import TABLES


def completed(table: str, spec: dict | None) -> dict:
    """The table's defaults with ``spec`` applied, each value checked against the schema."""
    params = {p.name: p for p in TABLES[table]}
    out = {name: p.default for name, p in params.items()}
    for key, value in (spec or {}).items():
        if key not in params:
            raise InputError(unknown_key_message(f"key in [{table}]:", key, params))
        out[key] = value if value is None and params[key].default is None else params[key].check(value, f"{table}.")
    return out


def ordered(table: str, low_key: str, high_key: str, s: dict, unit: str, strict: bool = True) -> None:
    """``s[low_key]`` must be below ``s[high_key]`` (or not above, with ``strict`` False)."""
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
    unit and its label: the one place either is written."""
    return field(metadata={"unit": unit, "label": label})


@dataclass(frozen=True)
class Result:
    """A design's result: its checked spec and the values it reports (the fields declared with
    :func:`reported`, in their order)."""

    spec: dict

    table = ""

    @classmethod
    def outputs(cls) -> tuple[Output, ...]:
        """The reported fields, in order, with unit and label."""
        return tuple(Output(f.name, f.metadata["unit"], f.metadata["label"]) for f in fields(cls) if "unit" in f.metadata)

    def summary(self) -> dict:
        """The reported values in SI units, keyed as in the JSON output."""
        return {o.key: getattr(self, o.key) for o in self.outputs()}


def explained(design, spec: dict | None):
    """Why ``spec`` cannot be met, and what can (the :class:`~handbook.design.solvers.Infeasible` that
    ``design`` raises), or None when ``design`` meets it: every design's ``explain``."""
    from .solvers import Infeasible
    try:
        design(spec)
    except Infeasible as exc:
        return exc
    return None
