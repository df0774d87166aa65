"""SPICE as a referee that can fail: the faults each circuit's checks must see, and the operating points they
must hold at.

**Faults** (:data:`FAULTS`). For each circuit, deliberate errors in the equations its checks use: a sign
flipped, a term dropped, a factor 2, one equation for another (eq 14 for eq 13). A fault replaces the
equation's function in its source module while the circuit is built again, so every check computes its
equation column through the faulty function as the book would; the simulation is not run again (the circuit is
what it is), and a check *sees* the fault when the faulty equation falls outside its tolerance of SPICE's
figure. A fault in a formula the circuit module writes inline is a ``scale`` on the checks that use it.

**Operating points** (:data:`SPACES`). For each circuit builder, the ranges its parameters may take under the
chapter's stated assumptions (supply, device figures, speeds, loads); :func:`draw` draws seeded points from
them. Every independent check must agree at every point: a tolerance fitted to one operating point fails.
"""
from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from types import ModuleType

import numpy as np

from ..sources import an93008, an94002, lm4651, tca5600
from . import class_d, converter, decoupling, limiter, speed, timers
from .circuit import Circuit, evaluate, judge, measured


@dataclass(frozen=True)
class Fault:
    """One deliberate error in one equation."""

    equation: str  # the equation as the book names it: "AN94002 eq 13"
    name: str  # what is wrong: "the offset's sign flipped"
    module: ModuleType | None = None  # where the equation's function lives
    attr: str = ""  # its name there
    wrap: Callable | None = field(default=None, compare=False)  # the true function -> the faulty one
    scale: tuple = ()  # ((check id, factor), ...) for a formula written inline in the circuit module

    @property
    def label(self) -> str:
        return f"{self.equation}: {self.name}"


@contextlib.contextmanager
def applied(fault: Fault):
    """The fault's function in place of the true one, for the duration: in every module of the package that
    holds it (a source package re-exports its circuit module's functions, and those call each other)."""
    if fault.module is None:
        yield
        return
    true = getattr(fault.module, fault.attr)
    holders = [m for name, m in list(sys.modules.items())
               if name.startswith("handbook.") and getattr(m, fault.attr, None) is true]
    faulty = fault.wrap(true)
    for m in holders:
        setattr(m, fault.attr, faulty)
    try:
        yield
    finally:
        for m in holders:
            setattr(m, fault.attr, true)


def _args(fn, **changes):
    """A wrapper calling ``fn`` with some keyword arguments changed: name -> function of the true value."""
    import inspect

    sig = inspect.signature(fn)

    def faulty(*a, **k):
        bound = sig.bind(*a, **k)
        bound.apply_defaults()
        for name, change in changes.items():
            bound.arguments[name] = change(bound.arguments[name])
        return fn(*bound.args, **bound.kwargs)

    return faulty


def _times(factor):
    return lambda fn: (lambda *a, **k: factor * fn(*a, **k))


def _f(module, attr, equation, name, **changes):
    return Fault(equation, name, module, attr, lambda fn: _args(fn, **changes))


def _alpha(p: dict) -> float:
    """TCA5600's alpha = V_L+ / V_L- (eq 3), for the faults of eq 4 and 5."""
    vl_plus, vl_minus = tca5600.coil_voltages(p)
    return vl_plus / vl_minus


_EQ13 = "AN94002 eq 13"
_EQ11 = "AN94002 eq 11"
_OPAMP_FAULTS = (
    _f(an94002, "v_cs_trip", _EQ13, "the offset's sign flipped", offset=lambda v: -v),
    _f(an94002, "v_cs_trip", _EQ13, "the offset term dropped", offset=lambda v: 0.0),
    Fault(_EQ13, "eq 14 (the matched dividers) in its place", an94002, "v_cs_trip",
          lambda fn: (lambda vz, r9, r10, r11, r12, r13, offset=0.0: an94002.v_cs_matched(vz, r9, r10, r11))),
    Fault(_EQ13, "a factor 2", an94002, "v_cs_trip", _times(2.0)),
    Fault(_EQ13, "the offset referred through B instead of A", an94002, "v_cs_trip",
          lambda fn: (lambda vz, r9, r10, r11, r12, r13, offset=0.0: fn(vz, r9, r10, r11, r12, r13, offset)
                      + offset / an94002.factor_a(r12, r13) - offset / an94002.factor_b(r9, r10, r11))),
    Fault(_EQ11, "R12 and R13 swapped", an94002, "level_shift",
          lambda fn: (lambda vz, r12, r13, v_cs=0.0: fn(vz, r13, r12, v_cs))),
    Fault(_EQ11, "a factor 2", an94002, "level_shift", _times(2.0)),
)

#: circuit id -> the faults its checks must see (a circuit with no independent check sees them by construction)
FAULTS: dict[str, tuple[Fault, ...]] = {
    "limiter-one-transistor": (
        _f(an94002, "limit_current", "AN94002 2.3 (V_BE drift)", "the drift's sign flipped", v_be_tc=lambda v: -v),
        _f(an94002, "limit_current", "AN94002 2.3 (V_BE drift)", "the drift dropped", v_be_tc=lambda v: 0.0),
        _f(an94002, "limit_current", "AN94002 2.3 (V_BE drift)", "the drift doubled", v_be_tc=lambda v: 2 * v),
    ),
    "limiter-opamp": _OPAMP_FAULTS,
    "limiter-opamp-corner": (_OPAMP_FAULTS[2], _OPAMP_FAULTS[3], *_OPAMP_FAULTS[5:]),  # no offset at the corner
    "limiter-supply": (
        Fault("AN93008 eq 6", "the supply's share taken as B / A, not 1 - B / A", an93008, "v_cs_trip",
              lambda fn: (lambda v, r8, r9, r10, r11, offset=0.0: v - fn(v, r8, r9, r10, r11, offset))),
        Fault("AN93008 eq 6", "R10 and R11 swapped (B upside down)", an93008, "v_cs_trip",
              lambda fn: (lambda v, r8, r9, r10, r11, offset=0.0: fn(v, r8, r9, r11, r10, offset))),
        Fault("AN93008 eq 6", "a factor 2", an93008, "v_cs_trip", _times(2.0)),
        Fault("AN93008 eq 1", "R8 and R9 swapped", an93008, "factor_a", lambda fn: (lambda r8, r9: fn(r9, r8))),
    ),
    "speed": (
        Fault("AN94002 eq 10", "R3 / R4 for (R3 + R4) / R4", an94002, "v_in_for",
              lambda fn: (lambda v_mot, r3, r4: v_mot * r4 / r3)),
        Fault("AN94002 eq 10", "a factor 2", an94002, "v_in_for", _times(2.0)),
    ),
    "speed-loop-filter": (
        Fault("1 / (2 pi R1 C8)", "2 pi dropped", scale=(("speed-rc-corner", 2 * np.pi),)),
        Fault("1 / (2 pi R1 C8)", "a factor 2", scale=(("speed-rc-corner", 2.0), ("speed-rc-rolloff", 2.0))),
    ),
    "decoupling": (
        Fault("AN94002 2.4 |Z| of C2", "the ESL term's sign flipped", an94002, "impedance",
              lambda fn: (lambda f, c, esr=0.0, esl=0.0: fn(f, c, esr, -esl))),
        Fault("AN94002 2.4 |Z| of C2", "the ESR dropped", an94002, "impedance",
              lambda fn: (lambda f, c, esr=0.0, esl=0.0: fn(f, c, 0.0, esl))),
        Fault("1 / (2 pi sqrt(ESL C2))", "a factor 2", scale=(("decoupling-f-res", 2.0),)),
    ),
    "tca5600-converter": (
        Fault("TCA5600 eq 1, 2", "V12(H) left out of V_L-", tca5600, "coil_voltages",
              lambda fn: (lambda p: (fn(p)[0], fn(p)[1] + p["v12h"]))),
        Fault("TCA5600 eq 1, 2", "V_F's sign flipped in V_L+", tca5600, "coil_voltages",
              lambda fn: (lambda p: (fn(p)[0] - 2 * p["v_f"], fn(p)[1]))),
        Fault("TCA5600 eq 1, 2", "V_CE(sat) left out of V_L-", tca5600, "coil_voltages",
              lambda fn: (lambda p: (fn(p)[0], fn(p)[1] + p["vce_sat"]))),
        Fault("TCA5600 eq 2 to 6a", "a factor 2 in t1", tca5600, "operating_point",
              lambda fn: (lambda l1, r1, p: {**fn(l1, r1, p), "t1": 2 * fn(l1, r1, p)["t1"]})),
        Fault("TCA5600 eq 4", "t1 (1 + alpha) for t1 (1 + 1/alpha)", tca5600, "operating_point",
              lambda fn: (lambda l1, r1, p: {**fn(l1, r1, p), "f": fn(l1, r1, p)["f"] * (1 + 1 / _alpha(p))
                                             / (1 + _alpha(p))})),
        Fault("TCA5600 eq 5", "1 + 1/alpha for 1 + alpha", tca5600, "operating_point",
              lambda fn: (lambda l1, r1, p: {**fn(l1, r1, p), "i_out_max": fn(l1, r1, p)["i_out_max"]
                                             * (1 + _alpha(p)) / (1 + 1 / _alpha(p))})),
    ),
}
for _rl in ("4ohm", "8ohm"):
    FAULTS[f"lm4651-filter-{_rl}"] = (
        Fault("LM4651 filter corner", "one coil instead of two in series", lm4651.circuit, "filter_f0",
              lambda fn: (lambda l_out, c_out: fn(l_out / 2, c_out))),
        Fault("LM4651 filter Q", "R_L doubled", lm4651.circuit, "filter_q",
              lambda fn: (lambda l_out, c_out, r_load: fn(l_out, c_out, 2 * r_load))),
        Fault("LM4651 filter |H|", "a factor 2", lm4651.circuit, "filter_gain2", _times(2.0)),
    )
    FAULTS[f"lm4651-ripple-{_rl}"] = (
        Fault("LM4651 residue", "4 V_s / pi for 8 V_s / pi (one half-bridge)", lm4651.circuit, "ripple_rms",
              _times(0.5)),
        Fault("LM4651 residue", "the filter taken at f_sw / 2", lm4651.circuit, "ripple_rms",
              lambda fn: (lambda f_sw, l_out, c_out, r_load, supply: fn(f_sw / 2, l_out, c_out, r_load, supply))),
    )
FAULTS.update({
    "cap-st": (Fault("AN94002 2.1.1 start period", "a factor 2", an94002, "start_period", _times(2.0)),),
    "cap-cd": (Fault("AN94002 2.1.2 excursion", "a factor 2", an94002, "excursion", _times(2.0)),
               Fault("AN94002 2.1.2 t_com", "a factor 2", an94002, "t_com", _times(2.0))),
    "cap-ti": (Fault("AN94002 2.1.3 watchdog time", "a factor 2", an94002, "watchdog_time", _times(2.0)),),
})


def faulty_checks(circuit: Circuit, fault: Fault) -> dict:
    """{check id: the check as the book would print it with the fault in place}: ``circuit`` built again
    (``circuit.rebuild``) through the faulty function, so each check's equation column *and* its expected
    difference are what the faulty code gives (an expected difference that absorbed the equation would hide the
    fault, and this shows it). A check the faulty build leaves out, or a build the fault breaks, gives none."""
    from dataclasses import replace

    with applied(fault):
        try:
            c = circuit.rebuild()
        except (ValueError, ArithmeticError):
            return {}
    out = {ch.id: ch for ch in c.checks}
    for cid, factor in fault.scale:
        out[cid] = replace(out[cid], equation=out[cid].equation * factor)
    return out


def seen(circuit: Circuit, values: dict) -> dict:
    """{check id: [labels of the faults that check sees]} for ``circuit`` with its `.meas` results ``values``: a
    check sees a fault when, built with the fault, it misses SPICE by more than its tolerance about its expected
    difference. A check the fault removes (its equation gives no figure) or a build it breaks sees nothing: a
    comparison that was not made proves nothing."""
    out = {ch.id: [] for ch in circuit.checks}
    for fault in FAULTS.get(circuit.id, ()):
        for cid, ch in faulty_checks(circuit, fault).items():
            eq = float(ch.equation)
            if cid in out and (eq != eq or not judge(ch, eq, float(values[ch.measure.lower()]))["agrees"]):
                out[cid].append(fault.label)
    return out


def refereed(circuit: Circuit) -> list[dict]:
    """:func:`evaluate`'s rows of ``circuit`` with "faults_seen" added to each (one ngspice run)."""
    values = measured(circuit)
    rows = evaluate(circuit, values=values)
    by_check = seen(circuit, values)
    for r in rows:
        r["faults_seen"] = by_check[r["id"]]
    return rows


# ----------------------------------------------------------------------------------------------
# operating points

#: builder -> {parameter: (low, high)}: the chapter's stated assumptions (each range's reason beside it)
SPACES: dict[Callable, dict] = {
    limiter.one_transistor: {
        "i_limit": (0.5, 2.0),  # the limit currents the chapters design for
        "v_be_bc557": (0.55, 0.70),  # BC557 V_BE(on) min..max at 2 mA (BC557 datasheet)
        "v_supply": (10.8, 13.2),  # 12 V +- 10 %
    },
    limiter.opamp: {
        "v_supply": (10.8, 13.2),  # 12 V +- 10 %
        "zener_voltage": (7.7, 8.7),  # BZX79-C8V2 minimum to maximum at 5 mA (datasheet)
        "r7": (0.05, 0.2),  # 50 .. 200 mV across R7 at the note's 1 A
        "r9": (200.0, 400.0),  # eq 14's R9 for 70 .. 140 mV
        "r14": (620.0, 820.0),  # D1's feed about the parts list's 750 ohm
        "vos": (-9e-3, 9e-3),  # LM358 offset, over temperature (datasheet)
        "ibp": (0.0, 5e-7), "ibn": (0.0, 5e-7),  # LM358 bias, 0 .. 500 nA (datasheet)
    },
    limiter.opamp_corner: {  # the least-headroom corner: it starts inside the LM358's 2 V and comes back out
        "v_supply": (10.8, 13.2),  # 12 V +- 10 %
        # the design's lowest D1 (tolerance and drift, 7.53 V) about, up to the datasheet minimum: below 7.5 V V+
        # comes back inside the LM358's range only past the trip, and the corner's story (stuck, then back) ends
        "zener_voltage": (7.5, 7.7),
        "r7": (0.08, 0.15),
        "r12": (5488.0, 5600.0), "r13": (16000.0, 16320.0),  # R12 low, R13 high, up to 2 %
        "ibp": (1e-7, 5e-7), "ibn": (1e-7, 5e-7),
    },
    limiter.supply_referenced: {
        "v_supply": (12.0, 15.0),  # AN93008's 12 V and above (V_low is taken 10 % below)
        "r7": (0.05, 0.2),
        "vos": (-9e-3, 9e-3), "ibp": (0.0, 5e-7), "ibn": (0.0, 5e-7),
    },
    # the start oscillator's rule (2 s per uF) is the datasheet's for its typical current and levels: CAP-ST only
    timers.start_oscillator: {"cap_st": (100e-9, 470e-9)},
    # CAP-CD no smaller than the chapter's eq 6 asks for the slowest speed (1000 rpm) and the largest charge current
    # (11 uA) drawn here, in the datasheet's narrowest window (2.3 V - 0.9 V): 13 nF. A smaller one clips at V_high
    # at the lowest speed, a design the chapter never draws, and the sanity rows would read the clip, not the timer
    timers.commutation_delay: {
        "cap_cd": (an94002.cap_cd_min(1000.0, an94002.params()["pole_pairs"], 11e-6, timers.CD_HIGH[0] - timers.CD_LOW[2]),
                   33e-9),
        "rpm_min": (1000.0, 2500.0), "rpm_max": (3600.0, 9000.0), "i_ch": (6e-6, 11e-6), "i_dis": (12e-6, 22e-6)},
    timers.watchdog: {"cap_ti": (2.2e-9, 22e-9), "i_wd": (4e-6, 6e-6), "i_ti_fast": (45e-6, 70e-6),
                      "i_ti_discharge": (20e-6, 35e-6)},
    # the chapter's loop is linear up to the top of the control range: the OTA sinks T1's base current below its
    # 40 mA. With the assumed BD434 (h_FE about 50 at 2 A) that holds up to about 1.95 A of motor current at the top
    # (10.7 V at 13 V - 10 %): motors from 6 ohm (1.8 A there) to 20 ohm, the chapter's 10 ohm (about 1 A) inside.
    # Below about 5.5 ohm at 13 V the loop cannot reach the top, and speed.circuit's rows say so and differ.
    speed.circuit: {"v_supply": (11.0, 13.0), "r_motor": (6.0, 20.0), "gm": (0.2, 0.4), "r2": (470.0, 1000.0),
                    "r3": (33e3, 47e3)},
    speed.loop_filter: {"r1": (10.0, 47.0), "c8": (100e-9, 470e-9), "r_motor": (6.0, 20.0), "gm": (0.2, 0.4)},
    # the ranges live beside the circuits, whose AC tolerances are bounded at their largest Q (decoupling.Q_MAX,
    # class_d.Q_MAX)
    decoupling.circuit: dict(decoupling.SPACE),
    class_d.circuit: dict(class_d.FILTER_SPACE),
    class_d.ripple: {**class_d.FILTER_SPACE, "f_sw": (100e3, 200e3), "supply": (15.0, 25.0)},
    converter.circuit: {"v12h": (0.2, 0.8), "vce_sat": (0.2, 0.8), "v_f": (0.5, 1.0), "v_cc2_min": (6.0, 10.0),
                        "v_out2": (10.0, 15.0)},
}


def draw(build: Callable, n: int, seed: int = 22) -> list[dict]:
    """``n`` seeded operating points of ``build`` inside :data:`SPACES`, a Latin hypercube: each parameter's range
    cut into ``n`` equal strata, one point in each, the strata shuffled independently per parameter, so every
    range is covered end to end however many parameters there are."""
    rng = np.random.default_rng(seed)
    space = SPACES[build]
    cols = {k: lo + (hi - lo) * (rng.permutation(n) + rng.uniform(size=n)) / n for k, (lo, hi) in space.items()}
    return [{k: float(cols[k][i]) for k in space} for i in range(n)]
