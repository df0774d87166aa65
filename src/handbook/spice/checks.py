"""Every circuit's SPICE checks in one place, for `python -m handbook spice` and the tests, and the
designs confirmed by simulation (`python -m handbook design SPEC.toml --spice`)."""
from __future__ import annotations

from ..core.units import signed_percent
from . import class_d, converter, decoupling, limiter, speed, timers
from .runner import SpiceError, SpiceUnavailable, available, why_unavailable

#: the circuit builders, each () -> Circuit with the notes' values
BUILDERS = (
    limiter.one_transistor, limiter.opamp, limiter.opamp_corner, limiter.supply_referenced,
    timers.start_oscillator, timers.commutation_delay, timers.watchdog, speed.circuit, speed.loop_filter,
    decoupling.circuit,
    class_d.circuit, class_d.circuit_8ohm, class_d.ripple, class_d.ripple_8ohm, converter.circuit,
)

#: design table -> the function taking that design's result, returning its SPICE figures
DESIGN_CHECKS = {"commutation": timers.design_check, "current_limiter": limiter.design_check,
                 "class_d": class_d.design_check, "converter": converter.design_check}


def circuits() -> list:
    return [build() for build in BUILDERS]


def rows() -> list[dict]:
    """One row per check of every circuit: id, circuit, quantity, unit, equation, spice, rel_diff,
    expected_difference (what physics predicts, :class:`~.circuit.Check`), residual, agrees, rtol, why, kind
    ("independent" or "sanity": agrees by construction), verdict (what the book says: "agrees",
    "consistent (by construction)" or "differs") and faults_seen (the deliberate equation faults of
    :mod:`.referee` this row would catch).
    A circuit whose run fails gives one row saying so (agrees False, its message in "error"); the others
    are still reported. A missing ngspice raises SpiceUnavailable (nothing can be reported)."""
    from .referee import refereed

    out = []
    for c in circuits():
        try:
            out += refereed(c)
        except SpiceError as exc:
            out.append({"id": f"{c.id}-run", "circuit": c.id, "quantity": "the simulation itself", "unit": "",
                        "equation": float("nan"), "spice": float("nan"), "rel_diff": float("nan"), "agrees": False,
                        "expected_difference": 0.0, "residual": float("nan"), "rtol": 0.0, "why": "",
                        "kind": "independent", "verdict": "differs", "faults_seen": [], "error": str(exc)})
    return out


def confirm(results: dict) -> dict:
    """{table: SPICE figures of that design} for every design result given (Infeasible entries skipped): each
    figure beside the design's own ("*_equation"), "meets_spec" (SPICE's figures judged against the spec),
    "agrees" and "differs" (:func:`judged`)."""
    out = {}
    for table, result in results.items():
        if table in DESIGN_CHECKS and hasattr(result, "spec"):
            out[table] = judged(table, DESIGN_CHECKS[table](result))
    return out


#: what each design table's SPICE figures are held against: (quantity, unit, key of the SPICE figure (its
#: "_equation" twin is the design's own), tolerance, why, kind)
CONFIRM = {
    "commutation": (
        ("largest CAP-CD swing at rpm_min over every corner", "V", "swing_rpm_min", 0.002,
         "each of the 16 timers integrates the design's constant charge current between its own levels, the same "
         "arithmetic as the design's formula: by construction, so it checks the corner search (SPICE keeps its own "
         "largest) and the deck, not the formula; the step is t_com / 400 at rpm_max and the gate's edges t_com / "
         "1000 (0.04 % seen)", "sanity"),
        ("smallest CAP-CD swing at rpm_max over every corner", "V", "swing_rpm_max", 0.002,
         "the same: by construction, 4 timers at rpm_max; the step at rpm_max is t_com / 400 (0.04 % seen)",
         "sanity"),
        ("shortest start period (CAP-ST low, the largest I_ST)", "s", "start_period_min", 0.001,
         "the chapter's start oscillator with the chosen C5 at its low end: the same charge balance as eq 1, by "
         "construction; the comparator switches a step (period / 2000) late at each level: ±0.1 %", "sanity"),
        ("shortest watchdog time (CAP-TI low, the largest I_WD)", "s", "t_wd_min", 0.005,
         "the chapter's watchdog with the chosen C6 at its low end: eq 9's ramp from 0.3 V to 2.2 V, by construction; "
         "two switchings a time step each: ±0.5 %", "sanity"),
        ("longest watchdog time (CAP-TI high, the smallest I_WD)", "s", "t_wd_max", 0.005,
         "as the shortest, C6 at its high end: ±0.5 %", "sanity")),
    "current_limiter": (
        ("lowest trip current over every corner", "A", "i_trip_min", 0.005,
         "1024 copies of the network (every resistor, zener, offset and bias corner) solved by ngspice in DC, the "
         "lowest kept; the design's node equation takes V_Z at 5 mA and R7 carrying the motor current only, SPICE "
         "the zener's 15 ohm at the current it carries at each corner and R12's current in R7 (up to 0.35 % seen): "
         "±0.5 %", "independent"),
        ("highest trip current over every corner", "A", "i_trip_max", 0.005,
         "as the lowest: the zener's dynamic resistance at its real current and R12's current in R7 (0.35 % seen "
         "at the default spec): ±0.5 %", "independent"),
        ("least input headroom at no motor current over every corner", "V", "headroom_min", 0.002,
         "eq 11 with the bias against the same 1024 copies at no motor current; the zener's 15 ohm at its real "
         "current moves V_Z by a few mV (0.03 % seen): ±0.2 %", "independent")),
    "class_d": (
        ("output filter corner with the load", "Hz", "f_corner", 0.001,
         f"2 L in series with C_BYP across R_L is exactly the bridge's network; the AC grid ({class_d.AC_CHECK_PER_DECADE} "
         "points a decade, interpolated: below 0.001 %, the referee's corner rows) is all that is left: ±0.1 %",
         "independent"),
        ("switching residue at the load, rms, worst of the eight corners", "V", "ripple_at_load", 0.002,
         "the design keeps only the square wave's fundamental (8 V_s / pi) and ideal edges; SPICE every harmonic "
         "(+0.07 % rms) and the 25/26 ns edges; 400 steps a period and the rms about its mean leave a few 0.01 % at most "
         "(class_d.ripple_bound): ±0.2 %", "independent")),
    "converter": (
        ("least current into C2 at v_supply_min over every corner", "A", "i_out", None,
         "the deck's own exact figure at its worst corner (eq 2's ramp, D1's falling drop, the restart) predicts the "
         "difference from the design's eq 1 to 5; the step's bound, 2 h over t2 and the period, is the tolerance",
         "independent"),
        ("lowest full-load frequency over every corner", "Hz", "f", None,
         "as above: the expected difference is the deck's exact period against eq 4's; the tolerance 2 h over the "
         "period", "independent")),
}


def confirm_rows(table: str, result, figures: dict | None = None) -> list[dict]:
    """The design's own worst-case figures beside the simulation's, for the design chapters: rows of (quantity,
    unit, equation, spice, rel_diff, rtol, why, kind, agrees, verdict), the verdict as :func:`circuit.verdict`
    gives it ("agrees" only for an independent check). ``figures``: design_check's output, if already run."""
    from .circuit import verdict

    sim = figures if figures is not None else confirm({table: result})[table]
    rows = []
    for quantity, unit, key, rtol, why, kind in CONFIRM[table]:
        if key not in sim:  # a part the design did not choose (CAP-ST, CAP-TI without their data): no row
            continue
        eq, value = float(sim[f"{key}_equation"]), float(sim[key])
        expected, rtol = float(sim.get(f"{key}_expected", 0.0)), float(sim.get(f"{key}_rtol", rtol))
        rel = abs(value - eq) / abs(eq)
        if expected:
            why = f"expected {signed_percent(expected)}: {why}"
        row = {"key": key, "quantity": quantity, "unit": unit, "equation": eq, "spice": value, "rel_diff": rel, "rtol": rtol,
               "expected_difference": expected, "why": why, "kind": kind,
               "agrees": bool(abs(value / eq - 1 - expected) <= rtol)}
        rows.append({**row, "verdict": verdict(row)})
    return rows


def judged(table: str, figures: dict) -> dict:
    """A design table's SPICE figures with the judgement added: "agrees" (every row of :data:`CONFIRM` within
    its tolerance of the design's own figure) and "differs" (the keys outside it)."""
    off = [r["key"] for r in confirm_rows(table, None, figures) if not r["agrees"]]
    return {**figures, "agrees": not off, "differs": off}


def warnings(table: str, figures: dict) -> list[str]:
    """What --spice says on stderr for one table: the design not confirmed (ok False), a commutation window
    reached, the spec missed by SPICE's figures, a figure outside its tolerance of the design's."""
    out = []
    if figures.get("ok") is False:
        out.append("the simulation does not confirm the design (the op-amp's output is not high at no motor "
                   "current, or not low at the top of the sweep, at some corner)")
    if figures.get("window_reached"):
        out.append("a corner's CAP-CD swing reached its window at rpm_min: the design does not fit")
    if figures.get("meets_spec") is False:
        out.append("SPICE's figures miss the spec" + "".join(f"; {m}" for m in figures.get("misses", ())))
    from ..core.units import eng

    units = {key: unit for _q, unit, key, *_ in CONFIRM[table]}
    for key in figures.get("differs", ()):
        out.append(f"SPICE's {key} = {eng(figures[key], units.get(key, ''))} is outside its tolerance of the "
                   f"design's {eng(figures[key + '_equation'], units.get(key, ''))}")
    return out


__all__ = ["CONFIRM", "SpiceError", "SpiceUnavailable", "available", "circuits", "confirm", "confirm_rows", "judged", "rows",
           "warnings", "why_unavailable"]
