"""The current limiters simulated: AN94002's one-transistor limiter (figure 2) and op-amp limiter (figure 3,
the zener-bridged level shift; AN93008's figure 4 is the same circuit), AN93008's supply-referenced limiter
(its figure 3), and a designed limiter confirmed at every candidate corner (:func:`design_check`).

Every limiter is driven the same way: the motor current, a current source in series with the sense resistor
R7, ramps slowly from zero (0 to ``i_max`` in ``RAMP`` seconds after a 1 ms pause), and ngspice measures the
motor current at which the limiter acts: for the op-amp limiters where the LM358's output falls through the
middle of its swing, for the one-transistor limiter where T2's collector current reaches 2 mA (the current
of the BC557's V_BE(on) figure). The regulator the limiter throttles (T1, the OTA) is not simulated: the
ramp is open loop, so the measured point is the limiter's threshold, which is what the equations give.
Device models: :mod:`.models` (BZX79-C8V2, BC557, LM358, from their datasheets).
"""
from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from ...core import series
from ...sources import an93008, an94002
from ...sources.an94002.parts import PARTS
from .. import models
from ..circuit import Check, Circuit, Part, rebuildable
from ..runner import run
from . import left_out

RAMP = 1.0  # s: the motor current's ramp (slow against the LM358's 7 Hz pole, see the checks' tolerances)
T0 = 1e-3  # s: the pause before the ramp, where the V_cs = 0 figures are read
BOARD = {ref: value for ref, _, value, *_ in PARTS}
#: netlist names of the designators whose letter is not SPICE's (T2 is a Q element, U1 a subcircuit)
NAMES = {"T2": "QT2", "U1": "XU1"}


def element_lines(parts, nodes: dict[str, str], sfx: str = "", **extra) -> list[str]:
    """One line per part: ``nodes[ref]`` holds its nodes, ``{s}`` for the suffix ``sfx`` and ``{v}`` where the
    value goes (else the value ends the line); ``extra`` fills any other field."""
    out = []
    for p in parts:
        value = p.value if isinstance(p.value, str) else f"{p.value:.6g}"
        body = nodes[p.ref].format(s=sfx, v=value, **extra)
        out.append(f"{NAMES.get(p.ref, p.ref)}{sfx} {body}" + ("" if "{v}" in nodes[p.ref] else f" {value}"))
    return out


def _ramp_nodes(top: str) -> str:
    """The motor: a 0 V ammeter (VAM) then the ramping current source, from the sense point to ground."""
    return f"{top}{{s}} 0 PWL(0 0 {T0:g} 0 {T0 + RAMP:g} {{v}})"


def _deck(title: str, models_: list[str], body: list[str], meas: list[str]) -> str:
    return "\n".join([f"* {title}", ".options temp=25 tnom=25", *models_, *body,
                      f".tran {RAMP / 2000:g} {T0 + RAMP:g} 0 {RAMP / 2000:g}", *meas, ".end"]) + "\n"


def _probe(name: str, expr: str) -> str:
    """A behavioural source whose node holds ``expr`` (`.meas` reads single nodes only)."""
    return f"Bp{name} p{name} 0 V={expr}"


# ----------------------------------------------------------------------------------------------
# (a) AN94002 figure 2: the one-transistor limiter

def one_transistor_defaults() -> dict:
    p = an94002.params()
    return {"i_limit": p["i_limit"], "v_be": p["v_be"], "v_be_tc": p["v_be_tc"], "v_supply": p["v_supply"],
            "v_be_bc557": an94002.FACTS["bc557_vbe"].value[1], "temps": (p["t_low"], 25.0, p["t_high"]),
            "r_load": 1e3}


def one_transistor_parts(p: dict) -> tuple[Part, ...]:
    r7 = an94002.r7_for_limit(p["i_limit"], p["v_be"])
    return (Part("VS", p["v_supply"], "V", "motor supply V_s"),
            Part("R7", r7, "ohm", "sense resistor, R7 = V_be / I_lim with the note's 0.8 V (r7_for_limit)"),
            Part("T2", "BC557", "", f"V_BE(on) {p['v_be_bc557']:g} V at 2 mA (typ, BC557 datasheet)"),
            Part("RL", p["r_load"], "ohm", "stand-in for the regulator drive T2 pulls on (not in the note)"),
            Part("IM", 2 * p["i_limit"], "A", "motor current, ramped from 0 to this value"))


ONE_T_NODES = {"VS": "vs{s} 0", "R7": "vs{s} cs{s}", "T2": "col{s} cs{s} vs{s}", "RL": "cl{s} 0",
               "IM": _ramp_nodes("csm")}


@rebuildable
def one_transistor(p: dict | None = None) -> Circuit:
    """AN94002 figure 2 at three temperatures side by side (T2's instance temperature; R7 has none)."""
    p = {**one_transistor_defaults(), **(p or {})}
    parts = one_transistor_parts(p)
    body, meas, checks = [], [], []
    for k, t in enumerate(p["temps"]):
        sfx = "" if t == 25.0 else f"_{k}"
        lines = element_lines(parts, ONE_T_NODES, sfx)
        lines[2] += f" temp={t:g}"
        body += [*lines, f"VAM{sfx} cs{sfx} csm{sfx} 0", f"VC{sfx} col{sfx} cl{sfx} 0"]
        name = f"i_on_{k}"
        meas.append(f".meas tran {name} FIND i(VAM{sfx}) WHEN i(VC{sfx})={models.BC557_IC:g} RISE=1")
        eq = float(an94002.limit_current(parts[1].value, t, p["v_be_bc557"], p["v_be_tc"]))
        if t == 25.0:
            checks.append(Check(
                f"limiter-1t-on-{t:g}C", f"motor current where T2 takes over (I_C = 2 mA), {t:g} °C", "A", eq, name,
                0.001, "by construction: the model's IS is set so that V_BE is the datasheet's 0.62 V at 2 mA and "
                "25 °C, the figure the equation divides by R7; only T2's base current (I_C / 200, 0.0014 %) differs. "
                "This checks the deck (R7, T2's connection), not the equation; the ramp's step (0.05 %, "
                "interpolated): ±0.1 %", kind="sanity"))
        else:
            x = left_out.one_transistor_terms(p, parts[1].value, t, eq)
            rule = 0.5e-3 * abs(t - 25.0) / (eq * parts[1].value)  # half a unit of the rule's one digit, in I
            checks.append(Check(
                f"limiter-1t-on-{t:g}C", f"motor current where T2 takes over (I_C = 2 mA), {t:g} °C", "A", eq, name,
                rule + RAMP_RTOL,
                f"the equation's drift is the rule of thumb, -2 mV/K, against SPICE's silicon physics (EG = 1.11 eV, "
                f"XTI = 3, not tuned: {x['tc'] * 1e3:.2f} mV/K at 2 mA); expected {x['base']:+.3%}: T2's base "
                f"current I_C / h_FE, which R7 carries too. A rule printed to one digit claims ±0.5 mV/K, "
                f"{abs(t - 25):.0f} K from 25 °C {rule:.2%} of the current, and the ramp's step 0.1 %: "
                f"±{(rule + RAMP_RTOL) * 100:.2g} %", expected=x["base"]))
        if t == 25.0:  # the trip at other collector currents: V_BE moved along the diode law from 2 mA
            r7, v_t = parts[1].value, models.K_Q * (273.15 + t)
            for tag, i_c in (("low", models.BC557_IC / 10), ("high", models.BC557_IC * 5)):
                meas.append(f".meas tran i_on_{tag} FIND i(VAM{sfx}) WHEN i(VC{sfx})={i_c:g} RISE=1")
                v_be = p["v_be_bc557"] + v_t * np.log(i_c / models.BC557_IC)
                checks.append(Check(
                    f"limiter-1t-on-{tag}-25C", f"motor current where T2's collector carries {i_c * 1e3:g} mA, 25 °C",
                    "A", float(v_be / r7 + i_c / models.BC557_BF), f"i_on_{tag}", 0.001,
                    f"by construction: the BC557 model's IS is set from 0.62 V at 2 mA with NF = 1 and no base, "
                    f"emitter or collector resistance and no Early voltage, so its V_BE(I_C) is exactly 0.62 V + V_T "
                    f"ln(I_C / 2 mA) ({(v_be - p['v_be_bc557']) * 1e3:+.1f} mV here), the formula of the equation "
                    f"column (plus T2's base current I_C / h_FE, h_FE = 200 assumed: "
                    f"{i_c / models.BC557_BF / (v_be / r7) * 100:.3f} % of the current). It checks the deck (R7, T2's "
                    "connection, the ramp), not the diode law. The ramp moves 0.05 % of the current per time step "
                    "and .meas interpolates within it: ±0.1 %", kind="sanity"))
    deck = _deck("AN94002 figure 2: one-transistor limiter", models.bc557(v_be=p["v_be_bc557"]), body, meas)
    return Circuit("limiter-one-transistor", "One-transistor current limiter", "AN94002 figure 2", parts, deck,
                   tuple(checks), draw=lambda: draw_one_transistor(parts))


# ----------------------------------------------------------------------------------------------
# (b) AN94002 figure 3: the op-amp limiter with the zener-bridged level shift

def opamp_defaults() -> dict:
    """The note's values: R9 from eq 14 for 100 mV, its E96 value (as the parts chapter picks it); R7 = V_cs
    over the chosen limit; D1 fed by R14 (parts list)."""
    p = an94002.params()
    r9 = series.nearest("E96", an94002.r9_for(p["v_cs"], p["zener_voltage"], p["r10"], p["r11"]))
    return {"v_supply": p["v_supply"], "zener_voltage": p["zener_voltage"], "r7": p["v_cs"] / p["i_limit"], "r9": r9,
            "r10": p["r10"], "r11": p["r11"], "r12": p["r12"], "r13": p["r13"], "r14": BOARD["R14"],
            "vos": 0.0, "ibp": models.LM358["bias"], "ibn": models.LM358["bias"], "i_max": 2 * p["i_limit"]}


def opamp_parts(p: dict) -> tuple[Part, ...]:
    return (Part("VS", p["v_supply"], "V", "supply V_s"), Part("R7", p["r7"], "ohm", "sense resistor"),
            Part("R9", p["r9"], "ohm", "sets the trip point"), Part("R10", p["r10"], "ohm", "reference divider"),
            Part("R11", p["r11"], "ohm", "reference divider"), Part("R12", p["r12"], "ohm", "level shift"),
            Part("R13", p["r13"], "ohm", "level shift"), Part("R14", p["r14"], "ohm", "D1's feed"),
            Part("D1", "BZX79-C8V2", "", f"V_Z = {p['zener_voltage']:.4g} V at 5 mA"),
            Part("U1", "LM358", "", f"offset {p['vos'] * 1e3:g} mV, bias {p['ibp'] * 1e9:g} / {p['ibn'] * 1e9:g} nA"),
            Part("IM", p["i_max"], "A", "motor current, ramped from 0 to this value"))


OPAMP_NODES = {"VS": "vs{s} 0", "R7": "vs{s} cs{s}", "R9": "vs{s} a{s}", "R10": "a{s} inn{s}",
               "R11": "inn{s} z{s}", "R12": "cs{s} inp{s}", "R13": "inp{s} z{s}", "R14": "z{s} 0",
               "D1": "z{s} vs{s} DZ{s} $ {v}", "U1": "inp{s} inn{s} vs{s} 0 out{s} {v} vos={vos} ibp={ibp} ibn={ibn}",
               "IM": _ramp_nodes("csm")}


def opamp_block(p: dict, sfx: str = "", nodes: dict = OPAMP_NODES) -> tuple[list[str], list[str]]:
    """(models, elements) of one op-amp limiter, node names ending in ``sfx`` (the LM358 subcircuit is shared);
    ``nodes``: where each part sits (:data:`OPAMP_NODES`, or a variant of it)."""
    u1 = {k: f"{p[k]:.6g}" for k in ("vos", "ibp", "ibn")}
    lines = element_lines(opamp_parts(p), nodes, sfx, **u1)
    lines += [f"VAM{sfx} cs{sfx} csm{sfx} 0", _probe(f"cs{sfx}", f"v(vs{sfx})-v(cs{sfx})"),
              _probe(f"hp{sfx}", f"v(vs{sfx})-v(inp{sfx})"), _probe(f"hm{sfx}", f"v(vs{sfx})-v(inn{sfx})")]
    return models.bzx79_c8v2(f"DZ{sfx}", p["zener_voltage"], tc=p.get("zener_tc", 0.0)), lines


def _mid(p: dict) -> float:
    """The middle of the LM358's output swing: where the output is taken to switch."""
    return (p["v_supply"] - models.LM358["v_oh_drop"] + models.LM358["v_ol"]) / 2


def _opamp_meas(sfx: str, mid: float, first_edge: str = "FALL=1") -> list[str]:
    """The trip (output falls through ``mid``): V_cs and the motor current there; both headrooms at V_cs = 0."""
    at = f"WHEN v(out{sfx})={mid:.6g} {first_edge}"
    return [f".meas tran vcs_trip{sfx} FIND v(pcs{sfx}) {at}", f".meas tran i_trip{sfx} FIND i(VAM{sfx}) {at}",
            f".meas tran head_p{sfx} FIND v(php{sfx}) AT={T0 / 2:g}",
            f".meas tran head_m{sfx} FIND v(phm{sfx}) AT={T0 / 2:g}",
            f".meas tran out0{sfx} FIND v(out{sfx}) AT={T0 / 2:g}"]


def _opamp_deck(title: str, blocks: list[dict], stuck: str = "low", extra_meas=()) -> str:
    models_, body, meas = models.lm358(stuck=stuck), [], []
    for k, p in enumerate(blocks):
        sfx = "" if k == 0 else f"_{k}"
        m, lines = opamp_block(p, sfx)
        models_ += m
        body += lines
        meas += _opamp_meas(sfx, _mid(p))
    return _deck(title, models_, body, [*meas, *extra_meas])


#: the limiters' tolerance about their expected difference: the numerical method's alone
RAMP_RTOL = 0.0015
RAMP_STEP = ("left: the ramp's step (it runs to twice the trip in 2000 steps: 0.1 % of the trip per step, .meas "
             "interpolating within it) and the terms' second order: ±0.15 %")


def left_out_why(t: dict, keys: tuple) -> str:
    """The expected difference of an op-amp limiter row, term by term (:mod:`.left_out`)."""
    words = {"lag": f"the LM358's one pole ({t['tau'] * 1e3:.2g} ms to mid-swing while the current ramps)",
             "bias": "the 500 nA bias currents through the dividers",
             "zener": f"D1's 15 Ω at the {t.get('i_zener', 0) * 1e3:.2f} mA it carries ({t['dvz'] * 1e3:+.1f} mV)",
             "r12": "R12's current, which R7 carries too"}
    total = sum(t[k] for k in keys)
    return (f"expected {total:+.2%}: " + ", ".join(f"{words[k]} {t[k]:+.2%}" for k in keys)
            + f"; {RAMP_STEP}")


#: the second copy's level-shift mismatch: R13 this fraction low (eq 13 and eq 14 part there)
MISMATCH = 0.02


@rebuildable
def opamp(p: dict | None = None) -> Circuit:
    """AN94002 figure 3 with the note's values: the trip as the motor current ramps, and the level shift."""
    p = {**opamp_defaults(), **(p or {})}
    eq_vcs = an94002.v_cs_trip(p["zener_voltage"], p["r9"], p["r10"], p["r11"], p["r12"], p["r13"], p["vos"])
    if eq_vcs > 0:  # the ramp runs to twice the trip eq 13 expects, whatever the network (a reader's values)
        p["i_max"] = max(p["i_max"], 2 * eq_vcs / p["r7"])
    parts = opamp_parts(p)
    shift = an94002.level_shift(p["zener_voltage"], p["r12"], p["r13"])
    s0 = left_out.shift_terms(p, shift, with_bias=True)
    t = left_out.opamp_terms(p, eq_vcs, RAMP, _mid(p), with_bias=True) if eq_vcs > 0 else None
    checks = (
        Check("limiter-opamp-shift", "V_s − V_+ at V_cs = 0 (eq 11: the level shift)", "V", shift, "head_p",
              RAMP_RTOL, f"expected {s0['bias'] + s0['zener']:+.2%}: the bias current out of V+ through R12 || R13 "
              f"{s0['bias']:+.2%}, D1's 15 Ω at the current it carries ({s0['dvz'] * 1e3:+.1f} mV) "
              f"{s0['zener']:+.2%}; left: the terms' second order (D1's exponential away from 5 mA): ±0.15 %",
              expected=s0["bias"] + s0["zener"]),)
    if t:
        checks += (
            Check("limiter-opamp-vcs", "V_cs where the output switches (eq 13)", "V", eq_vcs, "vcs_trip", RAMP_RTOL,
                  left_out_why(t, ("lag", "bias", "zener")), expected=t["lag"] + t["bias"] + t["zener"]),
            Check("limiter-opamp-itrip", "motor current where the output switches (eq 13 / R7)", "A",
                  eq_vcs / p["r7"], "i_trip", RAMP_RTOL, left_out_why(t, ("lag", "bias", "zener", "r12")),
                  expected=t["lag"] + t["bias"] + t["zener"] + t["r12"]))
    # a second copy that eq 14 and a wrong-signed offset term cannot pass: the note's offset (9 mV, LM358 over
    # temperature) and a level shift 2 % off the reference (R13 low), where eq 13 and eq 14 part
    q = {**p, "vos": an94002.params()["offset"], "r13": p["r13"] * (1 - MISMATCH)}
    eq_q = trip_voltage(q)
    if eq_q > 0:
        q["i_max"] = 2 * eq_q / q["r7"]
        eq14 = an94002.v_cs_matched(q["zener_voltage"], q["r9"], q["r10"], q["r11"]) / eq_q - 1
        wrong_sign = 2 * q["vos"] / an94002.factor_a(q["r12"], q["r13"]) / eq_q
        tq = left_out.opamp_terms(q, eq_q, RAMP, _mid(q), with_bias=False)
        checks += (Check("limiter-opamp-vcs-offset", f"V_cs where the output switches, with {q['vos'] * 1e3:g} mV of "
                         f"offset and R13 {MISMATCH:.0%} low (eq 13 with the offset and bias)", "V", eq_q, "vcs_trip_1",
                         RAMP_RTOL, f"eq 13 with the offset referred through A and the bias currents' node terms (here "
                         f"eq 14 would be {eq14:+.0%} off and a wrong-signed offset {wrong_sign:.0%}); "
                         + left_out_why(tq, ("lag", "zener")), expected=tq["lag"] + tq["zener"]),)
    deck = _opamp_deck("AN94002 figure 3: op-amp limiter", [p] + ([q] if eq_q > 0 else []))
    return Circuit("limiter-opamp", "Op-amp current limiter", "AN94002 figure 3", parts, deck, checks,
                   draw=lambda: draw_opamp(parts))


def corner_defaults() -> dict:
    """The note's network at the corner of least headroom of the design chapter's judgement: D1 at its lowest
    (tolerance 6.1 % and drift, the design spec), R12 low and R13 high by their 1 %, bias 500 nA."""
    from ...design import limiter as design
    from ...design.limiter import model as net

    s = design.checked({})
    p = opamp_defaults()
    t = s["resistor_tolerance"]
    return {**p, "zener_voltage": net.zener_range(s)[0], "r12": p["r12"] * (1 - t), "r13": p["r13"] * (1 + t),
            "ibp": s["input_bias"], "ibn": s["input_bias"], "spec": s}


def trip_voltage(p: dict) -> float:
    """V_cs at the trip with the offset and both bias currents: eq 13 (an94002.v_cs_trip) plus the bias terms
    of the design's node equation, I_+ R12 - I_- ((R9 + R10) || R11) / A (handbook.design.limiter.model)."""
    network = (p["r9"], p["r10"], p["r11"], p["r12"], p["r13"])
    return an94002.v_cs_trip(p["zener_voltage"], *network, p["vos"]) + left_out.bias_shift(p)


def corner_equations(p: dict) -> dict:
    """The corner's figures from the project's equations: least headroom of V+ (eq 11 with the bias, as the
    design's limiter model computes it), the sense voltage at which V+ comes back to 2 V below the supply,
    and the trip eq 13 with the offset and bias (the limiter model's node equation)."""
    from ...design.limiter import model as net

    s = p["spec"]
    r_p = p["r12"] * p["r13"] / (p["r12"] + p["r13"])
    head0 = an94002.level_shift(p["zener_voltage"], p["r12"], p["r13"]) - p["ibp"] * r_p
    a = an94002.factor_a(p["r12"], p["r13"])
    v_back = (s["input_headroom"] - head0) / a
    trip = trip_voltage(p)
    nominal_net = tuple(opamp_defaults()[k] for k in ("r9", "r10", "r11", "r12", "r13"))
    return {"head0": head0, "v_back": v_back, "trip": trip,
            "design_head": float(min(net.headroom_corners(nominal_net, s)))}


@rebuildable
def opamp_corner(p: dict | None = None) -> Circuit:
    """The note's network at its least-headroom corner: V+ starts 1.92 V below the supply, inside the LM358's
    2 V; the model's output then sticks low (the limiter acts with no current) until V+ is back in range."""
    p = {**corner_defaults(), **(p or {})}
    eq = corner_equations(p)
    p["i_max"] = max(p["i_max"], 2 * eq["trip"] / p["r7"])  # the ramp runs past the trip, whatever the network
    parts = opamp_parts(p)
    mid = _mid(p)
    back = [f".meas tran i_back FIND i(VAM) WHEN v(out)={mid:.6g} RISE=1"]
    s0 = left_out.shift_terms(p, eq["head0"], with_bias=False)
    b = left_out.back_terms(p, eq["v_back"], RAMP, mid)
    back_exp = b["zener"] + b["change_over"] + b["lag"] + b["r12"]
    back_rtol = 2 * RAMP_RTOL + 0.03 * abs(back_exp)
    t = left_out.opamp_terms(p, eq["trip"], RAMP, mid, with_bias=False)
    checks = (
        Check("limiter-corner-headroom", "V_s − V_+ at V_cs = 0, least-headroom corner (eq 11 with the bias)", "V",
              eq["head0"], "head_p", RAMP_RTOL, f"eq 11 less the bias current out of V+ through R12 || R13 (at the "
              f"note's network this corner is the design's worst case, a test holds the two together); expected "
              f"{s0['zener']:+.2%}: D1's 15 Ω at the current it carries ({s0['dvz'] * 1e3:+.1f} mV); "
              "left: the term's second order (D1's exponential away from 5 mA): ±0.15 %", expected=s0["zener"]),
        Check("limiter-corner-back", "motor current where V+ is back 2 V below the supply (output rises)", "A",
              eq["v_back"] / p["r7"], "i_back", back_rtol,
              f"eq 11 with the bias solved for 2 V of headroom; expected {back_exp:+.2%}: "
              f"D1's 15 Ω at its current there ({b['dvz'] * 1e3:+.1f} mV of shift) {b['zener']:+.2%}, the model's "
              f"change-over (the output's drive turns positive {1 - b['ok']:.2f} mV of headroom before the limit) "
              f"{b['change_over']:+.2%}, its rise to mid-swing ({b['tau'] * 1e3:.2g} ms) {b['lag']:+.2%}, R12's "
              f"current in R7 {b['r12']:+.2%}. Sensitive (1 mV of headroom is "
              f"{1e-3 / an94002.factor_a(p['r12'], p['r13']) / eq['v_back']:.1%} of this current): the ramp's step "
              "and the terms' second order count twice (0.3 %), and the terms, first order in D1's current and the "
              f"change-over, leave a few per cent of themselves (3 %): ±{back_rtol * 100:.2g} %",
              expected=back_exp),
        Check("limiter-corner-trip", "motor current where the output falls (node equation with bias)", "A",
              eq["trip"] / p["r7"], "i_trip", RAMP_RTOL, "the node equation holds the offset and the bias currents; "
              + left_out_why(t, ("lag", "zener", "r12")), expected=t["lag"] + t["zener"] + t["r12"]))
    deck = _opamp_deck("AN94002 figure 3 at its least-headroom corner", [p], extra_meas=back)
    return Circuit("limiter-opamp-corner", "Op-amp limiter, least-headroom corner", "AN94002 figure 3", parts,
                   deck, checks, draw=lambda: draw_opamp(parts))


# ----------------------------------------------------------------------------------------------
# (c) AN93008 figure 3: the supply-referenced limiter

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
    u1 = {k: f"{p[k]:.6g}" for k in ("vos", "ibp", "ibn")}
    for sfx, v in (("", p["v_supply"]), ("_1", p["v_low"])):
        lines = element_lines(parts, SUPPLY_NODES, sfx, **u1)
        lines[0] = f"VS{sfx} vs{sfx} 0 {v:.6g}"
        body += [*lines, f"VAM{sfx} cs{sfx} csm{sfx} 0", _probe(f"cs{sfx}", f"v(vs{sfx})-v(cs{sfx})"),
                 _probe(f"hp{sfx}", f"v(vs{sfx})-v(inp{sfx})"), _probe(f"hm{sfx}", f"v(vs{sfx})-v(inn{sfx})"),
                 _probe(f"vp{sfx}", f"v(inp{sfx})")]
        meas += _opamp_meas(sfx, _mid({"v_supply": v}))
    meas.append(f".meas tran vplus_1 FIND v(pvp_1) AT={T0 / 2:g}")

    def trip(v):
        return an93008.v_cs_trip(v, p["r8"], p["r9"], p["r10"], p["r11"], p["vos"])

    a = an93008.factor_a(p["r8"], p["r9"])
    checks = tuple(
        Check(cid, f"V_cs where the output switches, {v:g} V (eq 6)", "V", trip(v), name, RAMP_RTOL,
              f"expected {x['lag'] + x['bias']:+.2%}: the LM358's one pole ({x['tau'] * 1e3:.2g} ms to mid-swing while "
              f"the current ramps) {x['lag']:+.2%}, the 500 nA bias currents through the dividers {x['bias']:+.2%}; "
              f"{RAMP_STEP}", expected=x["lag"] + x["bias"])
        for cid, v, name in (("limiter-supply-vcs", p["v_supply"], "vcs_trip"),
                             ("limiter-supply-vcs-low", p["v_low"], "vcs_trip_1"))
        for x in [left_out.supply_terms(p, v, trip(v), RAMP, _mid({"v_supply": v}))])
    bias_p = p["ibp"] * p["r8"] * p["r9"] / (p["r8"] + p["r9"]) / (a * p["v_low"])
    checks += (
        Check("limiter-supply-vplus", f"V_+ at V_cs = 0, {p['v_low']:g} V (eq 1: the note's 8.8 V)", "V",
              a * p["v_low"], "vplus_1", 1e-4,
              f"expected {bias_p:+.3%}: the bias current out of V+ through R8 || R9; left: the solver's round-off: "
              "±0.01 %", expected=bias_p),)
    deck = _deck("AN93008 figure 3: supply-referenced limiter", models.lm358(), body, meas)
    return Circuit("limiter-supply", "Supply-referenced op-amp limiter", "AN93008 figure 3", parts, deck, checks,
                   draw=lambda: draw_supply(parts))


def draw_one_transistor(parts):
    from .drawings import one_transistor
    return one_transistor(parts)


def draw_opamp(parts):
    from .drawings import opamp
    return opamp(parts)


def draw_supply(parts):
    from .drawings import supply
    return supply(parts)


# ----------------------------------------------------------------------------------------------
# waveforms for the chapters' plots

def waveforms(circuit: Circuit, vectors: dict[str, str], points: int = 400) -> dict[str, np.ndarray]:
    """The circuit's deck run once more with `wrdata` instead of `.meas`: {name: samples} of each vector
    (ngspice expression) at ``points`` + 1 evenly spaced times of the simulation's own grid (``time`` added)."""

    keep = [ln for ln in circuit.netlist.splitlines() if not ln.lower().startswith(".meas") and ln.strip().lower() != ".end"]
    with tempfile.TemporaryDirectory(prefix="handbook-wave-") as tmp:
        out = Path(tmp) / "wave.txt"
        deck = "\n".join([*keep, ".control", "run", "linearize", f"wrdata {out} " + " ".join(vectors.values()), "quit 0",
                          ".endc", ".end"]) + "\n"
        run(deck)
        data = np.loadtxt(out)
    pick = np.linspace(0, len(data) - 1, points + 1).round().astype(int)
    cols = {"time": data[pick, 0]}
    cols.update({name: data[pick, 2 * k + 1] for k, name in enumerate(vectors)})
    return cols
