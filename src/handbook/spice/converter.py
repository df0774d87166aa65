"""TCA5600/TCF5600 DC/DC converter's power stage (excerpt, figures 13 and 14; eq 1 to 6a).

The stage as eq 1 and 2 describe it (KVL in the two phases): VCC2 drives the coil L1 through the internal
switch S1 (a constant V_CE(sat)) and the sense resistor R1 to ground while charging; when S1 opens, the
coil dumps through the rectifier D1 (V_F) into C2, which sits at the programmable regulator's input,
V_out2 + V(9-8). The converter has no time base (excerpt): the comparator U1 opens S1 when R1's drop
reaches V12(H), and S1 closes again when the coil has dumped its energy, so the coil current is figure
14's triangle, t1 + t2 = 1/f (eq 4). Assumptions, each a simplification the chapter names:

* S1 is an ideal switch (1 mOhm) with V_CE(sat) as a constant source in series;
* U1 is one ngspice switch with hysteresis on R1 x the coil current (R1's own drop while charging, the
  dump current scaled by R1 while dumping): off at V12(H), on again at 0.1 % of it, with no delay;
* D1 is a silicon junction (N = 1, no series resistance) whose drop is V_F at the dump's mean current,
  I_peak / 2: its drop falls as the current does, where eq 1 holds V_F constant;
* C2 (100 uF, figure 13) is taken as holding its voltage over a cycle (7 uC a cycle moves it 74 mV): a
  source VC2 at V_out2 + V(9-8), which the current delivered into it is measured against.

Every device value is the chapter's assumption (:mod:`handbook.sources.tca5600.data`: the excerpt prints
no electrical characteristics); L1 and R1 are figure 13's.
"""
from __future__ import annotations

import math
from functools import partial

import numpy as np

from ..core.units import eng, signed_percent
from ..sources import tca5600
from . import schematic
from .bounds import percent
from .circuit import Check, Circuit, Part, rebuildable, with_defaults
from .runner import run

EXCERPT = "TCA5600/TCF5600 excerpt"
K_Q = 1.380649e-23 / 1.602176634e-19  # V/K: kT/q per kelvin
T_SIM = 300.15  # K: ngspice's default temperature (27 C), where the diode's IS is set
RESTART = 1e-3  # S1 closes again when the coil current is down to this fraction of V12(H) / R1

STEPS_PER_PERIOD = 2000  # transient step: a 2000th of the expected period (0.05 % of the peak per step)


def defaults() -> dict:
    """The chapter's operating point (tca5600.params()) with figure 13's L1 and R1."""
    return {**tca5600.params(), **tca5600.APPLICATION}


def parts(p: dict) -> tuple[Part, ...]:
    return (Part("VCC2", p["v_cc2_min"], "V", "the converter's supply, at its lowest"),
            Part("L1", p["l1"], "H"), Part("S1", p["vce_sat"], "V", "internal switch, V_CE(sat)"),
            Part("R1", p["r1"], "ohm", "current sense"), Part("U1", p["v12h"], "V", "comparator, V12(H)"),
            Part("D1", p["v_f"], "V", "rectifier, V_F"),
            Part("VC2", p["v_out2"] + p["regulator_drop"], "V", "C2 at the regulator's input, V_out2 + V(9-8)"))


def by_ref(ps: tuple[Part, ...], ref: str) -> Part:
    return next(q for q in ps if q.ref == ref)


def label(part: Part, sep: str = " ") -> str:
    """A part as the drawing shows it: designator, and value with its unit (what the value is, where it is
    a device's figure), subscripts typeset."""
    return schematic.label(part, sep, what={"S1": "V_CE(sat)", "U1": "V12(H)", "D1": "V_F"}.get(part.ref, ""))


def diode_is(v_f: float, i_at: float) -> float:
    """Saturation current of a junction (N = 1) that drops v_f at i_at, at ngspice's 27 C."""
    return i_at / math.expm1(v_f / (K_Q * T_SIM))


def element_lines(ps: tuple[Part, ...]) -> list[str]:
    """The parts as netlist lines (a part may need a model or a helper line): vcc, sw (the coil's switched end),
    e (R1's top), out (C2)."""
    v = {q.ref: q.value for q in ps}
    i_peak = v["U1"] / v["R1"]
    delta = RESTART * v["U1"]
    return [
        f"VCC2 vcc 0 {v['VCC2']:.6g}",
        f"L1 vcc sw {v['L1']:.6g}",
        f"S1 sw c ctl 0 SW_S1 $ V_CE(sat) {v['S1']:.6g} V: VS1",  # the switch, its saturation drop in VS1
        f"VS1 c e {v['S1']:.6g}",  # S1's V_CE(sat), in series with the ideal switch
        f"R1 e 0 {v['R1']:.6g}",
        # U1: the control is V12(H) less R1 x the coil current (R1's drop, or the dump current through VAMD)
        f"BU1 ctl 0 V={v['U1']:.6g} - (v(e)+{v['R1']:.6g}*i(VAMD))",
        f".model SW_S1 SW(VT={(v['U1'] - delta) / 2:.6g} VH={(v['U1'] - delta) / 2:.6g} RON=1m ROFF=1G)",
        f"D1 sw d1 D_D1 $ V_F {v['D1']:.6g} V at I_peak / 2: the model's IS",
        "VAMD d1 out 0",  # an ammeter: senses the dump current
        f"* D1: V_F = {v['D1']:.6g} V at I_peak / 2 = {i_peak / 2:.6g} A (an assumption, tca5600 data)",
        f".model D_D1 D(IS={diode_is(v['D1'], i_peak / 2):.6g} N=1)",
        f"VC2 out 0 {v['VC2']:.6g}",
    ]


def expected(p: dict) -> dict:
    """The equations' figures for these L1 and R1 at this operating point (eq 1 to 6a)."""
    op = tca5600.operating_point(p["l1"], p["r1"], p)
    vl_plus, vl_minus = tca5600.coil_voltages(p)
    return {**op, "t2": op["t1"] * vl_minus / vl_plus}


def exact(p: dict) -> dict:
    """The stage's figures from the deck's own circuit (KVL on its nodes, written here, not taken from
    :mod:`handbook.sources.tca5600`): while S1 is closed the coil sees V = VCC2 - V_CE(sat) less R1's drop, which
    grows with the current, so the current rises as (V/R1)(1 - exp(-t R1/L)) and reaches V12(H)/R1 at
    t1 = (L/R1) ln(V / (V - V12(H))); while it dumps it sees V_dump = V_C2 + V_F - VCC2 (R1 is not in its path).

    The ``*_deck`` figures keep what the deck does that the equations leave out: S1 closes again at ``RESTART``
    of the peak (not at zero current), so t1 starts from i0 = RESTART I_peak; D1 drops V_F + V_T ln(2 i / I_peak)
    as its current falls (a junction, N = 1), so the dump takes the integral of L di / V_dump(i) from I_peak down
    to i0 and delivers the integral of L i di / V_dump(i). ``t1_flat`` and ``t2_flat`` are the printed equations'
    forms on the same KVL (R1's drop held at V12(H), V_F constant): each check's expected difference is a ratio
    of these figures, never a figure over the equation it checks."""
    from scipy.integrate import quad

    v = p["v_cc2_min"] - p["vce_sat"]
    v_dump = p["v_out2"] + p["regulator_drop"] + p["v_f"] - p["v_cc2_min"]
    i_peak = p["v12h"] / p["r1"]
    i0, v_t = RESTART * i_peak, K_Q * T_SIM

    def dump(i):
        return v_dump + v_t * math.log(2 * i / i_peak)

    t1 = p["l1"] / p["r1"] * math.log(v / (v - p["v12h"]))
    t1_deck = p["l1"] / p["r1"] * math.log((v - p["r1"] * i0) / (v - p["v12h"]))
    t2_deck = quad(lambda i: p["l1"] / dump(i), i0, i_peak, limit=200)[0]
    q_deck = quad(lambda i: p["l1"] * i / dump(i), i0, i_peak, limit=200)[0]
    t1_flat, t2_flat = p["l1"] * i_peak / (v - p["v12h"]), p["l1"] * i_peak / v_dump
    return {"t1": t1, "t1_first": p["l1"] * i_peak / (v - p["v12h"] / 2), "t1_flat": t1_flat, "t2_flat": t2_flat,
            "t1_deck": t1_deck, "t2_deck": t2_deck, "f_deck": 1 / (t1_deck + t2_deck),
            "i_out_deck": q_deck / (t1_deck + t2_deck), "f_flat": 1 / (t1_flat + t2_flat),
            "i_out_flat": i_peak / 2 * t2_flat / (t1_flat + t2_flat)}


def _tran(p: dict, extra: list[str]) -> list[str]:
    """Seven expected periods; the checks read the third cycle (S1 closes at the sw node's 3rd and 4th fall)."""
    period = 1 / expected(p)["f"]
    step = period / STEPS_PER_PERIOD
    return [f".tran {step:.6g} {7 * period:.6g} 0 {step:.6g} uic",
            "Bq 0 q I=i(VAMD)", "Cq q 0 1", "Rq q 0 1e15", *extra]  # q: charge delivered to C2


def _meas(p: dict) -> list[str]:
    mid = (p["v_out2"] + p["regulator_drop"]) / 2  # the sw node: ~V_CE(sat) closed, ~V_C2 + V_F open
    return [f".meas tran t_on3 WHEN v(sw)={mid:.6g} FALL=3", f".meas tran t_off4 WHEN v(sw)={mid:.6g} RISE=4",
            f".meas tran t_on4 WHEN v(sw)={mid:.6g} FALL=4",
            f".meas tran i_peak MAX i(L1) FROM={1.5 / expected(p)['f']:.6g}",  # every cycle alike after the first
            f".meas tran q3 FIND v(q) WHEN v(sw)={mid:.6g} FALL=3", f".meas tran q4 FIND v(q) WHEN v(sw)={mid:.6g} FALL=4",
            ".meas tran t1 PARAM='t_off4-t_on3'", ".meas tran t2 PARAM='t_on4-t_off4'",
            ".meas tran f PARAM='1/(t_on4-t_on3)'", ".meas tran i_out PARAM='(q4-q3)/(t_on4-t_on3)'"]


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """Figure 13's power stage at the chapter's operating point, run for seven cycles: figure 14 in SPICE."""
    p = with_defaults(defaults(), p)
    ps, e, x = parts(p), expected(p), exact(p)
    ramp = "eq 2 holds R1's drop at V12(H) all through t1; it ramps from 0, so the coil sees about V12(H)/2 more"
    diode = "D1's drop falling with its current (V_F + V_T ln(2 i / I_peak), a junction)"
    restart = f"the deck's S1 closes again at {RESTART:.1%} of the peak, not at zero current"
    h = 1 / e["f"] / STEPS_PER_PERIOD  # the transient's step (_tran)
    # each quantity is read between two crossings (t1: S1's close and open; t2: open and the restart; the period:
    # two closes), each located by .meas's interpolation within one step h wherever S1's switching falls inside it
    # (the waveform's kink is not a breakpoint): a time within 2 h, its relative error 2 h / time; the current into
    # C2 is the dump's charge over the period, each within 2 h at its ends
    tol = {"t1": 2 * h / e["t1"], "t2": 2 * h / e["t2"], "f": 2 * h * e["f"]}
    tol["i_out"] = tol["t2"] + tol["f"]

    def step(key: str) -> str:
        return (f"the step h = {eng(h, 's')} (a {STEPS_PER_PERIOD}th of the period): each of the quantity's two "
                f"crossings located within h by .meas's interpolation: {percent(tol[key])}")

    checks = (
        Check("tca5600-peak", "peak coil current", "A", e["i_peak"], "i_peak", 1e-3,
              "by construction: the deck's comparator U1 is written to open S1 at V12(H) / R1, which is eq 6a; this "
              "checks the deck's switching, not the equation. SPICE's step (0.05 % of the peak) and RON are all: ±0.1 %",
              kind="sanity"),
        Check("tca5600-t1", "charging time t1 (the circuit: L/R1 ln(V / (V - V12(H))))", "s", x["t1"], "t1", tol["t1"],
              "by construction: the exact charge of the deck's own R-L loop (KVL on its nodes, converter.exact), not "
              "a book equation, so it checks the deck and the simulator's integration, not the notes (eq 2 is the "
              f"next row); expected {_pct(x['t1_deck'] / x['t1'] - 1)}: {restart}; {step('t1')}",
              kind="sanity", expected=x["t1_deck"] / x["t1"] - 1),
        Check("tca5600-t1-eq2", "charging time t1 by eq 2 as printed", "s", e["t1"], "t1", tol["t1"],
              f"expected {_pct(x['t1_deck'] / x['t1_flat'] - 1)}: {ramp}: eq 2's known bias, the exact charge against "
              f"R1's drop held at V12(H), {_pct(x['t1'] / x['t1_flat'] - 1)} (to first order -V12(H) / (2 V_L-), "
              f"{_pct(x['t1_first'] / x['t1_flat'] - 1)}), and {restart} ({_pct(x['t1_deck'] / x['t1'] - 1)}); {step('t1')}",
              expected=x["t1_deck"] / x["t1_flat"] - 1),
        Check("tca5600-t2", "dumping time t2 (eq 3)", "s", e["t2"], "t2", tol["t2"],
              f"expected {_pct(x['t2_deck'] / x['t2_flat'] - 1)}: {diode}, down to the restart; {step('t2')}",
              expected=x["t2_deck"] / x["t2_flat"] - 1),
        Check("tca5600-f", "free-running frequency (eq 4, with eq 2's t1)", "Hz", e["f"], "f", tol["f"],
              f"expected {_pct(x['f_deck'] / x['f_flat'] - 1)}: eq 2's bias in t1, {diode} and {restart}; {step('f')}",
              expected=x["f_deck"] / x["f_flat"] - 1),
        Check("tca5600-iout", "current into C2 (eq 5, the half-triangle over the period)", "A", e["i_out_max"],
              "i_out", tol["i_out"], f"expected {_pct(x['i_out_deck'] / x['i_out_flat'] - 1)}: the dump's charge with "
              f"{diode}, over the deck's period (eq 2's bias in t1, the restart); {step('i_out')} (t2's and the "
              "period's)",
              expected=x["i_out_deck"] / x["i_out_flat"] - 1))
    title = f"TCA5600 converter power stage, L1 = {eng(p['l1'], 'H')}, R1 = {p['r1']:g} ohm"
    netlist = "\n".join([f"* {title}", *element_lines(ps), *_tran(p, _meas(p)), ".end"]) + "\n"
    return Circuit(id="tca5600-converter", title=title, source=f"{EXCERPT}, figures 13 and 14, eq 1 to 6a",
                   parts=ps, netlist=netlist, checks=checks, draw=partial(draw, ps))


def waveform(p: dict | None = None, points: int = 241) -> dict:
    """The coil's current and voltage over two cycles from the third switch-on (figure 14), from SPICE:
    {"t": s from that switch-on, "i": A, "v": V (vcc - sw: V_L- while charging, -V_L+ while dumping)}."""
    p = with_defaults(defaults(), p)
    period = 1 / expected(p)["f"]
    t0 = 2.9 * period  # just before the third switch-on; measured exactly below
    t = t0 + np.linspace(0.0, 2.4 * period, points)
    meas = [f".meas tran t_on3 WHEN v(sw)={(p['v_out2'] + p['regulator_drop']) / 2:.6g} FALL=3"]
    meas += [f".meas tran i{k:03d} FIND i(L1) AT={x:.9g}" for k, x in enumerate(t)]
    meas += ["Ecoil vl 0 vcc sw 1"]  # the coil's voltage as one node (a probe)
    meas += [f".meas tran v{k:03d} FIND v(vl) AT={x:.9g}" for k, x in enumerate(t)]
    deck = "\n".join(["* TCA5600 converter, coil waveform", *element_lines(parts(p)), *_tran(p, meas), ".end"]) + "\n"
    got = run(deck)
    return {"t": t - got["t_on3"], "i": np.array([got[f"i{k:03d}"] for k in range(points)]),
            "v": np.array([got[f"v{k:03d}"] for k in range(points)])}


def draw(ps: tuple[Part, ...]):
    """VCC2, L1, the switch S1 with R1 under it, D1 into C2 (held at V_out2 + V(9-8): the source VC2, as in the
    deck); the comparator U1 with R1's drop on its − input and its V12(H) reference on +, fed from VCC2 and
    ground, opening S1 (dashed: its control). Labelled from the parts."""
    import schemdraw.elements as elm

    lab = {q.ref: label(q) for q in ps}
    d = schematic.start(unit=3.0, fontsize=10)
    top, e, x_sw, x_ref, x_out = 8.5, 1.6, 5.0, 11.6, 15.0
    d.add(elm.SourceV().endpoints((0, -1), (0, top)).label(lab["VCC2"], loc="top"))
    d.add(elm.Inductor2().endpoints((0, top), (x_sw, top)).label(lab["L1"]))
    d.add(elm.Diode().endpoints((x_sw, top), (x_out, top)).label(lab["D1"]))
    d.add(elm.SourceV().endpoints((x_out, -1), (x_out, top)).label(lab["VC2"] + "\n(C2, held)", loc="bottom"))
    s1 = d.add(elm.Switch().endpoints((x_sw, top), (x_sw, e)).label(lab["S1"], loc="top"))
    d.add(elm.Resistor().endpoints((x_sw, e), (x_sw, -1)).label(lab["R1"], loc="top"))
    for x in (0, x_sw, x_out, x_ref):
        d.add(elm.Ground().at((x, -1)))
    d.add(elm.Dot().at((x_sw, top)))
    d.add(elm.Dot().at((x_sw, e)))
    # U1 points left, its output at S1's control: − (below) from R1's top, + (above) from the V12(H) reference
    u1 = schematic.amplifier(d, (x_sw + 1.6, s1.center[1]), theta=180, anchor="out", positive=schematic.typeset("VCC2"),
                             text=label(by_ref(ps, "U1"), sep="\n"), text_at=(x_sw + 0.4, e + 0.95))
    edge = s1.get_bbox(transform=True).xmax
    d.add(elm.Line().endpoints(u1.out, (edge + CONTROL_GAP, u1.out[1])).linestyle("--"))
    bend = u1.in1[0] + 0.6
    d.add(elm.Line().endpoints((x_sw, e), (bend, e)))
    d.add(elm.Line().endpoints((bend, e), (bend, u1.in1[1])))
    d.add(elm.Line().endpoints((bend, u1.in1[1]), u1.in1))
    d.add(elm.Line().endpoints(u1.in2, (x_ref, u1.in2[1])))
    d.add(elm.Battery().endpoints((x_ref, -1), (x_ref, 1.0)).label(schematic.typeset("V12(H)"), loc="bottom"))
    d.add(elm.Line().endpoints((x_ref, 1.0), (x_ref, u1.in2[1])))
    return d


CONTROL_GAP = 0.35  # the dashed control line stops this short of the switch's symbol


def _pct(x: float, places: int = 2) -> str:
    """A signed share as the book writes it (:func:`~handbook.core.units.signed_percent`)."""
    return signed_percent(x, places)


def _corner_params(result, supply: float, ends: tuple[int, ...]) -> dict:
    """The deck's parameters with the designed L1 and R1 and the TCA5600 at one corner of the design's box: R1
    at its ends (tolerance and drift, :func:`~handbook.design.converter.r1_ends`), L1 +-a_l_tolerance, V12(H),
    V_CE(sat) and V_F each +-device_spread (``ends``: -1 or 1 each, in that order), VCC2 at ``supply``."""
    from ..design.converter import r1_ends, source_params

    s = result.spec
    k = dict(zip(("r1", "l1", "v12h", "vce_sat", "v_f"), ends))
    spread = s["device_spread"]
    p = {**defaults(), **source_params(s), "v_cc2_min": supply}
    r_lo, r_hi = r1_ends(s)
    p.update(r1=result.r1_part * (r_hi if k["r1"] > 0 else r_lo), l1=result.l1_nominal * (1 + k["l1"] * s["a_l_tolerance"]),
             **{key: p[key] * (1 + k[key] * spread) for key in ("v12h", "vce_sat", "v_f")})
    return p


def _worst(result, supplies, key: str) -> tuple[dict, dict]:
    """The corner (of 32, at each supply) where the deck's own exact figures (:func:`exact`: its KVL with the
    restart and D1's falling drop, not the design's equations) give the least ``key``: (its parameters, its exact
    figures)."""
    import itertools

    best = None
    for v in supplies:
        for ends in itertools.product((-1, 1), repeat=5):
            p = _corner_params(result, v, ends)
            if p["v_out2"] + p["regulator_drop"] + p["v_f"] <= v:  # no dump: the coil cannot discharge into C2
                continue
            x = exact(p)
            if best is None or x[f"{key}_deck"] < best[1][f"{key}_deck"]:
                best = (p, x)
    return best


def design_check(result) -> dict:
    """A designed TCA5600 converter simulated at its worst corners: the current delivered into C2 at
    v_supply_min at the corner that delivers least, and the full-load frequency at the corner where it is lowest
    (over the whole supply range with ``audible = "avoid"``, the design's ``f_sw_min``; else at v_supply_min,
    against ``f_min``), the corners found by the deck's own exact figures over the design's box. Each beside the
    design's figure ("*_equation"), the difference the deck's physics predicts against it ("*_expected": eq 2's
    ramp, D1's falling drop and the restart, :func:`exact`, at the corner simulated) and the step's bound
    ("*_rtol", 2 h over the time per crossing, as :func:`circuit`); "meets_spec": SPICE delivers at least
    ``i_out`` and switches no lower than 20 kHz (avoid) or ``f_min``."""
    from ..design.converter.result import AUDIO_BAND
    from ..design.worstcase import engine, models

    s = result.spec
    avoid = s["audible"] == "avoid"
    lowest = result.f_sw_min if avoid else float(engine.corners(models.converter(result))["f_sw_vmin"].min())
    out = {"corners": 2, "corners_searched": 32 * (3 if avoid else 2)}
    supplies_f = (s["v_supply_min"], s["v_supply_max"]) if avoid else (s["v_supply_min"],)
    at = {}  # key -> (the corner's parameters, its exact figures)
    for key, eq, supplies in (("i_out", result.i_out_least, (s["v_supply_min"],)), ("f", lowest, supplies_f)):
        p, x = at[key] = _worst(result, supplies, key)
        got, e = run(circuit(p).netlist), expected(p)
        h = 1 / e["f"] / STEPS_PER_PERIOD
        rtol = 2 * h / e["t2"] + 2 * h * e["f"] if key == "i_out" else 2 * h * e["f"]
        out |= {key: got[key], f"{key}_equation": eq, f"{key}_expected": x[f"{key}_deck"] / eq - 1,
                f"{key}_rtol": rtol, f"{key}_supply": p["v_cc2_min"]}
    floor, name = (AUDIO_BAND, "the audio band's edge, kept by audible = avoid") if avoid else (s["f_min"], "f_min")
    out["misses"] = ([f"the current into C2 at v_supply_min, {eng(out['i_out'], 'A')}, is below i_out = "
                      f"{eng(s['i_out'], 'A')}"] if out["i_out"] < s["i_out"] else [])
    if out["f"] < floor:
        p, x = at["f"]
        v_dump = p["v_out2"] + p["regulator_drop"] + p["v_f"] - p["v_cc2_min"]
        digits = 6 if out["f"] / floor > 0.999 else 4  # 19.998 kHz, not "20 kHz below 20 kHz"
        need = math.ceil(result.f_min_design * floor / out["f"] / 100) * 100  # f scales with f_min (L1 as 1/f_min)
        out["misses"].append(
            f"the full-load frequency at {eng(out['f_supply'], 'V')} and its slow corner, {eng(out['f'], 'Hz', digits)}, is "
            f"below {name} ({eng(floor, 'Hz')}), {_pct(out['f'] / out['f_equation'] - 1)} against the design's "
            f"{eng(out['f_equation'], 'Hz')} (the circuit's own figures predict {_pct(out['f_expected'])}): t2 is "
            f"{_pct(x['t2_deck'] / x['t2_flat'] - 1, 1)} longer than eq 3's, D1's drop falling with its current against a "
            f"dump voltage V_L+ of only {eng(v_dump, 'V')} at this supply, and t1 {_pct(x['t1_deck'] / x['t1_flat'] - 1, 1)} "
            "(R1's drop ramps from zero where eq 2 holds it at V12(H); the restart). The design holds this floor "
            f"by eq 1 to 5 with audible_margin = {s['audible_margin'] * 100:g} %; a larger audible_margin, or f_min = "
            f"{eng(need, 'Hz')} or more (the {eng(result.f_min_design, 'Hz')} it designed at, times {eng(floor, 'Hz')} "
            "over SPICE's figure: L1 scales as 1/f_min), lifts it")
    out["meets_spec"] = not out["misses"]
    return out
