"""Every circuit's SPICE checks in one place, for `python -m handbook spice` and the tests, and the
designs confirmed by simulation (`python -m handbook design SPEC.toml --spice`)."""
from __future__ import annotations

from importlib import import_module

from .circuit import evaluate
from .runner import SpiceError, SpiceUnavailable, available, why_unavailable

#: the circuit builders, "module:function" under handbook.spice, each () -> Circuit with the notes' values
BUILDERS: tuple[str, ...] = (
    "limiters:one_transistor", "limiters:opamp", "limiters:opamp_corner", "limiters:supply_referenced",
    "timers:start_oscillator", "timers:commutation_delay", "timers:watchdog", "speed:circuit", "decoupling:circuit",
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
    """One row per check of every circuit: id, circuit, quantity, unit, equation, spice, rel_diff, agrees."""
    return [row for c in circuits() for row in evaluate(c)]


def confirm(results: dict) -> dict:
    """{table: SPICE figures of that design} for every design result given (Infeasible entries skipped)."""
    out = {}
    for table, result in results.items():
        if table in DESIGN_CHECKS and hasattr(result, "spec"):
            out[table] = _load(DESIGN_CHECKS[table])(result)
    return out


__all__ = ["SpiceError", "SpiceUnavailable", "available", "circuits", "confirm", "rows", "why_unavailable"]
