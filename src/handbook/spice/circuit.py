"""One description per circuit: its parts (the notes' designators and values), its SPICE netlist, its
schematic, and the checks that hold the book's equations against the simulation.

A circuit module builds a :class:`Circuit` from its parameters; the netlist and the schematic are both
drawn from the same ``parts`` (a test checks that they name the same set with the same values). Each
:class:`Check` names a `.meas` result of the netlist, the value the book's equation gives, and the
tolerance the chapter states and justifies (what the equation leaves out that the simulation keeps).

A check is one of two kinds, and the book says which:

* ``"independent"``: the simulator computes the quantity from the circuit by a route the equation does not
  take (a measured frequency against a printed rule, a transistor's exponential against a datasheet figure
  moved along the diode law, a loop solved by ngspice against the hand analysis of that loop). It could
  disagree, and its verdict is "agrees" or "differs".
* ``"sanity"``: the netlist is built from the same formula or the same numbers as the equation (a part
  value computed from the target it is then measured against, a constant current integrated between the
  very levels the equation uses). It cannot disagree unless the deck is miswired or the solver's step is
  too coarse; its verdict is "consistent (by construction)", never "agrees".
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


#: the kinds of check, and the verdict the book prints for each when the values are within the tolerance
KINDS = {"independent": "agrees", "sanity": "consistent (by construction)"}


def verdict(row: dict) -> str:
    """What the book says of one row: "agrees" only for an independent check; a sanity check that holds is
    "consistent (by construction)"; either outside its tolerance "differs"."""
    if not row["agrees"]:
        return "differs"
    return KINDS[row.get("kind", "independent")]


@dataclass(frozen=True)
class Check:
    id: str  # "limiter-opamp-trip-high"
    quantity: str  # what a person reads
    unit: str
    equation: float  # the book's equation's value (SI)
    measure: str  # the .meas name in the netlist
    rtol: float  # agreement the chapter states
    why: str  # why that tolerance: what the equation leaves out
    kind: str = "independent"  # or "sanity": agrees by construction (see the module text)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"check {self.id}: kind {self.kind!r} is not one of {', '.join(KINDS)}")


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
    rel_diff, agrees, rtol, why, kind, verdict)."""
    from .runner import run as run_spice

    measured = (run or run_spice)(circuit.netlist)
    rows = []
    for c in circuit.checks:
        value, equation = float(measured[c.measure.lower()]), float(c.equation)
        rel = abs(value - equation) / abs(equation) if equation else abs(value)
        rows.append({"id": c.id, "circuit": circuit.id, "quantity": c.quantity, "unit": c.unit,
                     "equation": equation, "spice": value, "rel_diff": rel, "agrees": bool(rel <= c.rtol),
                     "rtol": c.rtol, "why": c.why, "kind": c.kind})
        rows[-1]["verdict"] = verdict(rows[-1])
    return rows
