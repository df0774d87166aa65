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
    drawn: str = ""  # the designator the drawing shows, where it is not ``ref`` (a designed circuit: the BOM's)


#: the kinds of check, and the verdict the book prints for each when the values are within the tolerance
KINDS = {"independent": "agrees", "sanity": "consistent (by construction)"}


def verdict(row: dict) -> str:
    """What the book says of one row: "agrees" only for an independent check; a sanity check that holds is
    "consistent (by construction)"; either outside its tolerance "differs"; a row's caveat (:class:`Check`) follows,
    after a semicolon."""
    said = KINDS[row.get("kind", "independent")] if row["agrees"] else "differs"
    return f"{said}; {row['caveat']}" if row.get("caveat") else said


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
    #: the difference physics predicts, (SPICE - equation) / equation, from what ``why`` names the equation
    #: leaving out (computed, never fitted); ``rtol`` is then the numerical method's alone, about it
    expected: float = 0.0
    #: (the run's `.meas` results) -> "" or a sentence the verdict adds: a condition of the operating point the
    #: simulation shows and the equation assumes (an op-amp input outside its common-mode range), said in the row
    caveat: Callable[[dict], str] | None = field(default=None, compare=False, repr=False)

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
    #: () -> the same circuit built again (set by :func:`rebuildable`): the referee builds it with a faulty equation
    rebuild: Callable = field(repr=False, compare=False, default=None)

    def part(self, ref: str) -> Part:
        return next(p for p in self.parts if p.ref == ref)


def rebuildable(builder: Callable[..., Circuit]) -> Callable[..., Circuit]:
    """A circuit builder whose circuits know how to build themselves again with the same parameters
    (``Circuit.rebuild``): what :mod:`.referee` needs to put a fault in an equation and read the checks again."""
    import functools
    import inspect
    from dataclasses import replace

    takes_params = bool(inspect.signature(builder).parameters)

    @functools.wraps(builder)
    def build(p: dict | None = None) -> Circuit:
        c = builder(p) if takes_params else builder()
        return replace(c, rebuild=functools.partial(build, None if p is None else dict(p)))

    return build


def with_defaults(defaults: dict, p: dict | None) -> dict:
    """A circuit's parameters: its defaults with ``p`` applied; an unknown key is refused, naming the known."""
    unknown = set(p or {}) - set(defaults)
    if unknown:
        raise KeyError(f"unknown parameter(s): {', '.join(sorted(unknown))}; known: {', '.join(sorted(defaults))}")
    return {**defaults, **(p or {})}


def judge(check: Check, equation: float, value: float) -> dict:
    """One check's figures: rel_diff |SPICE - equation| / |equation| (|SPICE| where the equation is 0),
    expected_difference (the check's ``expected``), residual (the signed difference less the expected) and
    agrees (|residual| <= rtol)."""
    signed = (value - equation) / abs(equation) if equation else value
    residual = signed - check.expected
    return {"rel_diff": abs(signed), "expected_difference": check.expected, "residual": residual,
            "agrees": bool(abs(residual) <= check.rtol)}


def measured(circuit: Circuit, run=None) -> dict:
    """The netlist's `.meas` results (one ngspice run)."""
    from .runner import run as run_spice

    return (run or run_spice)(circuit.netlist)


def evaluate(circuit: Circuit, run=None, values: dict | None = None) -> list[dict]:
    """Run the netlist once (or take ``values``, its `.meas` results) and compare every check: rows (id,
    circuit, quantity, unit, equation, spice, rel_diff, expected_difference, residual, agrees, rtol, why, kind,
    verdict, and caveat where the check's caveat says one)."""
    got = values if values is not None else measured(circuit, run)
    rows = []
    for c in circuit.checks:
        value, equation = float(got[c.measure.lower()]), float(c.equation)
        rows.append({"id": c.id, "circuit": circuit.id, "quantity": c.quantity, "unit": c.unit,
                     "equation": equation, "spice": value, **judge(c, equation, value),
                     "rtol": c.rtol, "why": c.why, "kind": c.kind})
        if c.caveat is not None and (note := c.caveat(got)):
            rows[-1]["caveat"] = note
        rows[-1]["verdict"] = verdict(rows[-1])
    return rows
