"""Every circuit's SPICE checks in one place, for `python -m handbook spice` and the tests, and the
designs confirmed by simulation (`python -m handbook design SPEC.toml --spice`)."""
from __future__ import annotations

from importlib import import_module

from .circuit import evaluate
from .runner import SpiceError, SpiceUnavailable, available, why_unavailable

#: the circuit builders, "module:function" under handbook.spice, each () -> Circuit with the notes' values
BUILDERS: tuple[str, ...] = (
    "limiters:one_transistor", "limiters:opamp", "limiters:opamp_corner", "limiters:supply_referenced",
    "timers:start_oscillator", "timers:commutation_delay", "timers:watchdog", "speed:circuit", "speed:loop_filter",
    "decoupling:circuit",
    "class_d:circuit", "class_d:circuit_8ohm", "class_d:ripple", "class_d:ripple_8ohm", "converter:circuit",
)

#: design table -> "module:function" taking that design's result, returning its SPICE figures
DESIGN_CHECKS = {"commutation": "timers:design_check", "current_limiter": "limiters:design_check",
                 "class_d": "class_d:design_check"}


def _load(path: str):
    module, name = path.split(":")
    return getattr(import_module(f"{__package__}.{module}"), name)


def circuits() -> list:
    return [_load(b)() for b in BUILDERS]


def rows() -> list[dict]:
    """One row per check of every circuit: id, circuit, quantity, unit, equation, spice, rel_diff, agrees, kind
    ("independent" or "sanity": agrees by construction) and verdict (what the book says: "agrees",
    "consistent (by construction)" or "differs").
    A circuit whose run fails gives one row saying so (agrees False, its message in "error"); the others
    are still reported. A missing ngspice raises SpiceUnavailable (nothing can be reported)."""
    out = []
    for c in circuits():
        try:
            out += evaluate(c)
        except SpiceError as exc:
            out.append({"id": f"{c.id}-run", "circuit": c.id, "quantity": "the simulation itself", "unit": "",
                        "equation": float("nan"), "spice": float("nan"), "rel_diff": float("nan"), "agrees": False,
                        "rtol": 0.0, "why": "", "kind": "independent", "verdict": "differs",
                        "error": str(exc)})
    return out


def confirm(results: dict) -> dict:
    """{table: SPICE figures of that design} for every design result given (Infeasible entries skipped)."""
    out = {}
    for table, result in results.items():
        if table in DESIGN_CHECKS and hasattr(result, "spec"):
            out[table] = _load(DESIGN_CHECKS[table])(result)
    return out


def confirm_rows(table: str, result) -> list[dict]:
    """The design's own worst-case figures beside the simulation's, for the design chapters: rows of
    (quantity, unit, equation, spice, rel_diff)."""
    sim = confirm({table: result})[table]
    if table == "commutation":
        # SPICE runs every corner and keeps its own worst: it does not reuse the corner the design picked
        pairs = [("largest swing at rpm_min over every corner", "V", result.swing_at_rpm_min, "swing_rpm_min"),
                 ("smallest swing at rpm_max over every corner", "V", result.swing_at_rpm_max, "swing_rpm_max")]
    elif table == "current_limiter":
        pairs = [("lowest trip current (its worst corner)", "A", result.i_trip_min, "i_trip_min"),
                 ("highest trip current (its worst corner)", "A", result.i_trip_max, "i_trip_max")]
    else:
        from ..sources.lm4651.circuit import filter_f0

        pairs = [("output filter corner with the load", "Hz", filter_f0(result.l_out, result.c_out), "f_corner"),
                 ("switching residue at the load, rms (worst corner)", "V", result.figures["ripple"], "ripple_at_load")]
    return [{"quantity": q, "unit": u, "equation": float(eq), "spice": float(sim[key]),
             "rel_diff": abs(float(sim[key]) - float(eq)) / abs(float(eq))} for q, u, eq, key in pairs]


__all__ = ["SpiceError", "SpiceUnavailable", "available", "circuits", "confirm", "confirm_rows", "rows", "why_unavailable"]
