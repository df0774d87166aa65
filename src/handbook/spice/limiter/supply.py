"""AN93008's supply-referenced limiter (its figure 3) simulated: R7 in the motor supply, R8/R9 dividing the sensed rail
onto the LM358's + input, R10/R11 the reference on its - input, at the nominal supply and at 12 V - 10 % (two copies
in one run), driven and measured as the other limiters (:mod:`.decks`: the motor current ramped through R7, the trip
read where the output falls through mid-swing; expected differences from :mod:`.left_out`, tolerances from
:mod:`.numerics`)."""
from __future__ import annotations

from ...sources import an93008, an94002
from .. import models
from ..circuit import Check, Circuit, Part, rebuildable
from . import left_out, numerics
from .decks import (
    DIGITS,
    OPAMP_NODES,
    RAMP,
    STEPS,
    T0,
    _deck,
    _mid,
    _opamp_meas,
    _probe,
    _ramp_nodes,
    dc_bound,
    element_lines,
    input_range,
    trip_bound,
)


def supply_defaults() -> dict:
    """AN93008's values; R7 = 100 mV over the limit AN94002's chapters use (AN93008 leaves it TBD)."""
    p = an93008.params()
    return {"v_supply": p["v_supply"], "v_low": p["v_supply"] * (1 - p["supply_tolerance"]),
            "r7": p["v_cs"] / an94002.params()["i_limit"], "r8": p["r8"], "r9": p["r9"], "r10": p["r10"],
            "r11": p["r11"], "vos": 0.0, "ibp": models.LM358["bias"], "ibn": models.LM358["bias"],
            "i_max": 2 * an94002.params()["i_limit"]}


def supply_parts(p: dict) -> tuple[Part, ...]:
    return (Part("VS", p["v_supply"], "V", f"supply (a second copy runs at {p['v_low']:g} V)"),
            Part("R7", p["r7"], "ohm", "sense resistor"), Part("R8", p["r8"], "ohm", "level shift, top"),
            Part("R9", p["r9"], "ohm", "level shift, bottom"), Part("R10", p["r10"], "ohm", "reference, top"),
            Part("R11", p["r11"], "ohm", "reference, bottom"),
            Part("U1", "LM358", "", f"offset {p['vos'] * 1e3:g} mV, bias {p['ibp'] * 1e9:g} nA"),
            Part("IM", p["i_max"], "A", "motor current, ramped from 0 to this value"))


SUPPLY_NODES = {"VS": "vs{s} 0", "R7": "vs{s} cs{s}", "R8": "cs{s} inp{s}", "R9": "inp{s} 0", "R10": "vs{s} inn{s}",
                "R11": "inn{s} 0", "U1": OPAMP_NODES["U1"], "IM": _ramp_nodes("csm")}


@rebuildable
def supply_referenced(p: dict | None = None) -> Circuit:
    """AN93008 figure 3 at the nominal supply and at 12 V - 10 % (two copies in one run)."""
    p = {**supply_defaults(), **(p or {})}
    top = an93008.v_cs_trip(max(p["v_supply"], p["v_low"]), p["r8"], p["r9"], p["r10"], p["r11"], p["vos"])
    if top > 0:  # the ramp runs to twice the highest trip eq 6 expects, whatever the supply and network
        p["i_max"] = max(p["i_max"], 2 * top / p["r7"])
    parts, body, meas = supply_parts(p), [], []
    u1 = {k: f"{p[k]:.{DIGITS}g}" for k in ("vos", "ibp", "ibn")}
    for sfx, v in (("", p["v_supply"]), ("_1", p["v_low"])):
        lines = element_lines(parts, SUPPLY_NODES, sfx, DIGITS, **u1)
        lines[0] = f"VS{sfx} vs{sfx} 0 {v:.{DIGITS}g}"
        body += [*lines, f"VAM{sfx} cs{sfx} csm{sfx} 0", _probe(f"cs{sfx}", f"v(vs{sfx})-v(cs{sfx})"),
                 _probe(f"hp{sfx}", f"v(vs{sfx})-v(inp{sfx})"), _probe(f"hm{sfx}", f"v(vs{sfx})-v(inn{sfx})"),
                 _probe(f"vp{sfx}", f"v(inp{sfx})")]
        meas += _opamp_meas(sfx, _mid({"v_supply": v}))
    meas.append(f".meas tran vplus_1 FIND v(pvp_1) AT={T0 / 2:g}")

    def trip(v):
        return an93008.v_cs_trip(v, p["r8"], p["r9"], p["r10"], p["r11"], p["vos"])

    a = an93008.factor_a(p["r8"], p["r9"])
    checks = ()
    for cid, v, name, sfx in (("limiter-supply-vcs", p["v_supply"], "vcs_trip", ""),
                              ("limiter-supply-vcs-low", p["v_low"], "vcs_trip_1", "_1")):
        x = left_out.supply_terms(p, v, trip(v), RAMP, _mid({"v_supply": v}))
        bx = trip_bound(x, p, trip(v), current=False, v_supply=v)
        checks += (Check(
            cid, f"V_cs where the output switches, {v:g} V (eq 6)", "V", trip(v), name, bx["total"],
            f"expected {x['lag'] + x['bias']:+.3%}: the LM358's one pole ({x['tau'] * 1e3:.3g} ms from the input's "
            f"crossing to mid-swing while the current ramps, the output let go by its clamp 117 µV of input before the "
            f"crossing) {x['lag']:+.3%}, the bias currents through the dividers {x['bias']:+.3%}; "
            + numerics.words(bx, RAMP / STEPS), expected=x["lag"] + x["bias"],
            caveat=input_range(sfx, "its output idles low, acting on a motor that draws nothing")),)
    r_p = p["r8"] * p["r9"] / (p["r8"] + p["r9"])
    bias_p = p["ibp"] * r_p / (a * p["v_low"])
    v_cs0 = p["r7"] * (p["v_low"] * (1 - a) - p["ibp"] * r_p) / p["r8"]  # R8's current through R7, no motor current
    r7_p = -a * v_cs0 / (a * p["v_low"])
    bp = dc_bound({"v_supply": p["v_low"]}, a * p["v_low"])
    checks += (
        Check("limiter-supply-vplus", f"V_+ at V_cs = 0, {p['v_low']:g} V (eq 1: the note's 8.8 V)", "V",
              a * p["v_low"], "vplus_1", bp["total"],
              f"expected {bias_p + r7_p:+.4%}: the bias current out of V+ through R8 || R9 {bias_p:+.4%}, R8's current "
              f"through R7 (V_cs is not 0 with no motor current) {r7_p:+.5%}; " + numerics.words(bp, 0.0),
              expected=bias_p + r7_p, caveat=input_range("_1", "the op-amp's output idles low")),)
    deck = _deck("AN93008 figure 3: supply-referenced limiter", models.lm358(), body, meas)
    return Circuit("limiter-supply", "Supply-referenced op-amp limiter", "AN93008 figure 3", parts, deck, checks,
                   draw=lambda: draw_supply(parts))


def draw_supply(parts):
    from .drawings import supply
    return supply(parts)
