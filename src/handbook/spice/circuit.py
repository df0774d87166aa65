"""One description per circuit: its parts (the notes' designators and values), its SPICE netlist, its
schematic, and the checks that hold the book's equations against the simulation.

A circuit module builds a :class:`Circuit` from its parameters; the netlist and the schematic are both
drawn from the same ``parts`` (a test checks that they name the same set with the same values). Each
:class:`Check` names a `.meas` result of the netlist, the value the book's equation gives, and the
tolerance the chapter states and justifies (what the equation leaves out that the simulation keeps).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Part:
    ref: str  # the notes' designator: R7, D1, C3, U1 ...
    value: float | str  # SI value, or a model / device name
    unit: str = ""  # "ohm", "F", "H", "V", "A", or "" for a named device
    note: str = ""


@dataclass(frozen=True)
class Check:
    id: str  # "limiter-opamp-trip-high"
    quantity: str  # what a person reads
    unit: str
    equation: float  # the book's equation's value (SI)
    measure: str  # the .meas name in the netlist
    rtol: float  # agreement the chapter states
    why: str  # why that tolerance: what the equation leaves out


@dataclass(frozen=True)
class Circuit:
    id: str
    title: str
    source: str  # "AN94002 figure 3", ...
    parts: tuple[Part, ...]
    netlist: str  # complete deck: title line, models, elements, analysis, .meas lines
    checks: tuple[Check, ...]
    draw: Callable = field(repr=False, compare=False, default=None)  # () -> schemdraw.Drawing of the same parts

    def part(self, ref: str) -> Part:
        return next(p for p in self.parts if p.ref == ref)


def with_defaults(defaults: dict, p: dict | None) -> dict:
    """A circuit's parameters: its defaults with ``p`` applied; an unknown key is refused, naming the known."""
    unknown = set(p or {}) - set(defaults)
    if unknown:
        raise KeyError(f"unknown parameter(s): {', '.join(sorted(unknown))}; known: {', '.join(sorted(defaults))}")
    return {**defaults, **(p or {})}


def evaluate(circuit: Circuit, run=None) -> list[dict]:
    """Run the netlist once and compare every check: rows (id, circuit, quantity, unit, equation, spice,
    rel_diff, agrees, rtol, why)."""
    from .runner import run as run_spice

    measured = (run or run_spice)(circuit.netlist)
    rows = []
    for c in circuit.checks:
        value, equation = float(measured[c.measure.lower()]), float(c.equation)
        rel = abs(value - equation) / abs(equation) if equation else abs(value)
        rows.append({"id": c.id, "circuit": circuit.id, "quantity": c.quantity, "unit": c.unit,
                     "equation": equation, "spice": value, "rel_diff": rel, "agrees": bool(rel <= c.rtol),
                     "rtol": c.rtol, "why": c.why})
    return rows
