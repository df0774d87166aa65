"""The current limiters simulated: AN94002's one-transistor limiter (figure 2) and op-amp limiter (figure 3,
the zener-bridged level shift; AN93008's figure 4 is the same circuit); AN93008's supply-referenced limiter (its
figure 3) is :mod:`.supply`, built from this module's pieces.

Every limiter is driven the same way: the motor current, a current source in series with the sense resistor
R7, ramps slowly from zero (0 to ``i_max`` in ``RAMP`` seconds after a 1 ms pause), and ngspice measures the
motor current at which the limiter acts: for the op-amp limiters where the LM358's output falls through the
middle of its swing, for the one-transistor limiter where T2's collector current reaches 2 mA (the current
of the BC557's V_BE(on) figure). The regulator the limiter throttles (T1, the OTA) is not simulated: the
ramp is open loop, so the measured point is the limiter's threshold, which is what the equations give.
Device models: :mod:`.models` (BZX79-C8V2, BC557, LM358, from their datasheets).

Each check's expected difference is the physics its equation leaves out (:mod:`.left_out`), and its tolerance the
numerical method's bound at that operating point (:mod:`.numerics`): the ramp's step, the solver's tolerance
(:data:`SOLVER`), the printed digits. The decks write every value with all its digits (:data:`DIGITS`).
"""
from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from ...core import series
from ...sources import an94002
from ...sources.an94002.parts import PARTS
from .. import models
from ..circuit import Check, Circuit, Part, rebuildable
from ..runner import run
from . import left_out, numerics

RAMP = 1.0  # s: the motor current's ramp (slow against the LM358's 7 Hz pole, see the checks' tolerances)
T0 = 1e-3  # s: the pause before the ramp, where the V_cs = 0 figures are read
BOARD = {ref: value for ref, _, value, *_ in PARTS}
#: netlist names of the designators whose letter is not SPICE's (T2 is a Q element, U1 a subcircuit)
NAMES = {"T2": "QT2", "U1": "XU1"}


#: significant digits of the values in the referee's decks: all of a float's, so the deck is the circuit the
#: equation column computes (eq 13's trip is a 1 % difference of two terms: a value rounded to 6 digits would move
#: it by some 0.01 %); the exported netlists (:mod:`..netlist`) keep 6
DIGITS = 15


def element_lines(parts, nodes: dict[str, str], sfx: str = "", digits: int = 6, **extra) -> list[str]:
    """One line per part: ``nodes[ref]`` holds its nodes, ``{s}`` for the suffix ``sfx`` and ``{v}`` where the
    value goes (else the value ends the line), written to ``digits`` significant digits; ``extra`` fills any other
    field."""
    out = []
    for p in parts:
        value = p.value if isinstance(p.value, str) else f"{p.value:.{digits}g}"
        body = nodes[p.ref].format(s=sfx, v=value, **extra)
        out.append(f"{NAMES.get(p.ref, p.ref)}{sfx} {body}" + ("" if "{v}" in nodes[p.ref] else f" {value}"))
    return out


def _ramp_nodes(top: str) -> str:
    """The motor: a 0 V ammeter (VAM) then the ramping current source, from the sense point to ground."""
    return f"{top}{{s}} 0 PWL(0 0 {T0:g} 0 {T0 + RAMP:g} {{v}})"


#: the solver's tolerances, tighter than ngspice's defaults (RELTOL 1e-3, VNTOL 1 uV, ABSTOL 1 pA): Newton stops when
#: no node moves more than RELTOL |v| + VNTOL (no branch current more than RELTOL |i| + ABSTOL) between iterations,
#: so every reading is that close to the solution (a few nV here), far below the ramp's own bound
SOLVER = {"reltol": 1e-9, "vntol": 1e-12, "abstol": 1e-15}
#: the ramp's time steps: ngspice takes none longer than RAMP / STEPS
STEPS = 2000


def _deck(title: str, models_: list[str], body: list[str], meas: list[str], steps: int = STEPS) -> str:
    return "\n".join([f"* {title}", ".options temp=25 tnom=25",
                      ".options " + " ".join(f"{k}={v:g}" for k, v in SOLVER.items()), *models_, *body,
                      f".tran {RAMP / steps:g} {T0 + RAMP:g} 0 {RAMP / steps:g}", *meas, ".end"]) + "\n"


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
        lines = element_lines(parts, ONE_T_NODES, sfx, DIGITS)
        lines[2] += f" temp={t:g}"
        body += [*lines, f"VAM{sfx} cs{sfx} csm{sfx} 0", f"VC{sfx} col{sfx} cl{sfx} 0"]
        name = f"i_on_{k}"
        meas.append(f".meas tran {name} FIND i(VAM{sfx}) WHEN i(VC{sfx})={models.BC557_IC:g} RISE=1")
        eq = float(an94002.limit_current(parts[1].value, t, p["v_be_bc557"], p["v_be_tc"]))
        x = left_out.one_transistor_terms(p, parts[1].value, t, eq)
        r7, v_t = parts[1].value, models.K_Q * (273.15 + t)
        h, rate = RAMP / STEPS, parts[-1].value / RAMP  # the motor current's A/s

        def bound(i_c, value, v_t=v_t, r7=r7, rate=rate, h=h, t=t):
            v_be = left_out.bc557_vbe(p["v_be_bc557"], i_c, t)
            # all of V_BE but the band gap's EG (T - T0) / T0 scales with the simulator's V_T (left_out.bc557_vbe)
            v_t_part = v_be + 1.11 * (t - 25.0) / models.T25
            return numerics.exponential_row(h, SOLVER, v_rate=r7 * rate, v_t=v_t, v_be=v_be, v_t_part=v_t_part,
                                            rate=rate, value=value, v_node=p["v_supply"])
        b = bound(models.BC557_IC, eq)
        if t == 25.0:
            checks.append(Check(
                f"limiter-1t-on-{t:g}C", f"motor current where T2 takes over (I_C = 2 mA), {t:g} °C", "A", eq, name,
                b["total"], f"by construction: the model's IS is set so that V_BE is the datasheet's "
                f"{p['v_be_bc557']:g} V at 2 mA and 25 °C, the figure the equation divides by R7; expected "
                f"{x['base']:+.4%}: T2's base current (I_C / h_FE, h_FE = 200 assumed), which R7 carries too. This "
                f"checks the deck (R7, T2's connection), not the equation; {numerics.words(b, h)}", kind="sanity",
                expected=x["base"]))
        else:
            checks.append(Check(
                f"limiter-1t-on-{t:g}C", f"motor current where T2 takes over (I_C = 2 mA), {t:g} °C", "A", eq, name,
                b["total"],
                f"the equation's drift is the rule of thumb, {p['v_be_tc'] * 1e3:g} mV/K; SPICE's BC557 drifts by "
                f"silicon's law (EG = 1.11 eV, XTI = 3, not tuned), {x['tc'] * 1e3:.3f} mV/K at 2 mA from 25 to "
                f"{t:g} °C. Expected {x['silicon'] + x['base']:+.3%}: the silicon law's V_BE against the rule's "
                f"({(x['tc'] - p['v_be_tc']) * (t - 25.0) * 1e3:+.2f} mV) {x['silicon']:+.3%}, T2's base current "
                f"I_C / h_FE, which R7 carries too, {x['base']:+.4%}; so the row holds the rule to its known bias. "
                f"{numerics.words(b, h)}", expected=x["silicon"] + x["base"]))
        if t == 25.0:  # the trip at other collector currents: V_BE moved along the diode law from 2 mA
            for tag, i_c in (("low", models.BC557_IC / 10), ("high", models.BC557_IC * 5)):
                meas.append(f".meas tran i_on_{tag} FIND i(VAM{sfx}) WHEN i(VC{sfx})={i_c:g} RISE=1")
                v_be = p["v_be_bc557"] + v_t * np.log(i_c / models.BC557_IC)
                eq_tag = float(v_be / r7 + i_c / models.BC557_BF)
                b = bound(i_c, eq_tag)
                checks.append(Check(
                    f"limiter-1t-on-{tag}-25C", f"motor current where T2's collector carries {i_c * 1e3:g} mA, 25 °C",
                    "A", eq_tag, f"i_on_{tag}", b["total"],
                    f"by construction: the BC557 model's IS is set from 0.62 V at 2 mA with NF = 1 and no base, "
                    f"emitter or collector resistance and no Early voltage, so its V_BE(I_C) is exactly 0.62 V + V_T "
                    f"ln(I_C / 2 mA) ({(v_be - p['v_be_bc557']) * 1e3:+.1f} mV here), the formula of the equation "
                    f"column (plus T2's base current I_C / h_FE, h_FE = 200 assumed: "
                    f"{i_c / models.BC557_BF / (v_be / r7) * 100:.3f} % of the current). It checks the deck (R7, T2's "
                    f"connection, the ramp), not the diode law; {numerics.words(b, h)}", kind="sanity"))
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


def opamp_block(p: dict, sfx: str = "", nodes: dict = OPAMP_NODES, digits: int = 6) -> tuple[list[str], list[str]]:
    """(models, elements) of one op-amp limiter, node names ending in ``sfx`` (the LM358 subcircuit is shared);
    ``nodes``: where each part sits (:data:`OPAMP_NODES`, or a variant of it); values to ``digits`` digits."""
    u1 = {k: f"{p[k]:.{digits}g}" for k in ("vos", "ibp", "ibn")}
    lines = element_lines(opamp_parts(p), nodes, sfx, digits, **u1)
    lines += [f"VAM{sfx} cs{sfx} csm{sfx} 0", _probe(f"cs{sfx}", f"v(vs{sfx})-v(cs{sfx})"),
              _probe(f"hp{sfx}", f"v(vs{sfx})-v(inp{sfx})"), _probe(f"hm{sfx}", f"v(vs{sfx})-v(inn{sfx})")]
    return models.bzx79_c8v2(f"DZ{sfx}", p["zener_voltage"], tc=p.get("zener_tc", 0.0), digits=digits), lines


def _mid(p: dict) -> float:
    """The middle of the LM358's output swing: where the output is taken to switch."""
    return (p["v_supply"] - models.LM358["v_oh_drop"] + models.LM358["v_ol"]) / 2


def _opamp_meas(sfx: str, mid: float, first_edge: str = "FALL=1") -> list[str]:
    """The trip (output falls through ``mid``): V_cs and the motor current there; both headrooms at V_cs = 0."""
    at = f"WHEN v(out{sfx})={mid:.{DIGITS}g} {first_edge}"
    return [f".meas tran vcs_trip{sfx} FIND v(pcs{sfx}) {at}", f".meas tran i_trip{sfx} FIND i(VAM{sfx}) {at}",
            f".meas tran head_p{sfx} FIND v(php{sfx}) AT={T0 / 2:g}",
            f".meas tran head_m{sfx} FIND v(phm{sfx}) AT={T0 / 2:g}",
            f".meas tran out0{sfx} FIND v(out{sfx}) AT={T0 / 2:g}"]


def _opamp_deck(title: str, blocks: list[dict], stuck: str = "low", extra_meas=(), extra_body=(),
                steps: int = None) -> str:
    models_, body, meas = models.lm358(stuck=stuck), [], []
    for k, p in enumerate(blocks):
        sfx = "" if k == 0 else f"_{k}"
        m, lines = opamp_block(p, sfx, digits=DIGITS)
        models_ += m
        body += lines
        meas += _opamp_meas(sfx, _mid(p))
    return _deck(title, models_, [*body, *extra_body], [*meas, *extra_meas], steps or STEPS)


def left_out_why(t: dict, keys: tuple) -> str:
    """The expected difference of an op-amp limiter row, term by term (:mod:`.left_out`)."""
    words = {"lag": f"the LM358's one pole ({t['tau'] * 1e3:.3g} ms from the input's crossing to mid-swing while the "
                    "current ramps, the output let go by its clamp 117 µV of input before the crossing)",
             "bias": "the bias currents through the dividers",
             "zener": f"D1's 15 Ω at the {t.get('i_zener', 0) * 1e3:.2f} mA it carries ({t['dvz'] * 1e3:+.1f} mV, its "
                      "current taken at its own voltage)",
             "r12": "R12's current, which R7 carries too"}
    total = sum(t[k] for k in keys)
    return f"expected {total:+.3%}: " + ", ".join(f"{words[k]} {t[k]:+.3%}" for k in keys)


def trip_bound(t: dict, p: dict, value: float, current: bool, steps: int = STEPS, v_supply: float = None) -> dict:
    """The numerical bound of a trip row (:func:`.numerics.ramp_row`) from its terms ``t`` (:func:`.left_out.opamp_terms`
    or ``supply_terms``): ``current`` for the motor current's reading (else V_cs's); ``steps`` the deck's."""
    rate = p["i_max"] / RAMP if current else t["slope"]
    return numerics.ramp_row(t["response"], t["tau"], RAMP / steps, SOLVER, rate=rate, v_rate=t["slope"], value=value,
                             v_node=v_supply or p["v_supply"], a=t["a"], reads_nodes=not current)


def dc_bound(p: dict, value: float) -> dict:
    """The numerical bound of a reading at no motor current (:func:`.numerics.dc_row`)."""
    return numerics.dc_row(SOLVER, p["v_supply"], value)


def input_range(sfx: str = "", what: str = "its output idles low"):
    """A check's caveat (:class:`..circuit.Check`): when the run shows V+ or V- within the LM358's common-mode limit
    (2 V below the supply, its datasheet) at no motor current, a sentence saying so, and ``what`` that means for
    the row when the model's output is then low (it ignores its inputs there and drives its output low, blending
    them back in over the last 1 mV); else ""."""
    limit = models.LM358["cm_headroom"]

    def caveat(got: dict) -> str:
        heads = {"V+": got[f"head_p{sfx}"], "V−": got[f"head_m{sfx}"]}
        low = {k: v for k, v in heads.items() if v < limit}
        if not low:
            return ""
        pin, head = min(low.items(), key=lambda kv: kv[1])
        idle = got[f"out0{sfx}"] < models.LM358["v_oh_drop"]  # the output's swing is v_ol .. V_s - 1.5 V: low here
        return (f"outside the op-amp's input range at no motor current ({pin} {head:.4g} V below the supply, the "
                f"LM358 needs {limit:g} V)" + (f": {what}" if idle else ""))
    return caveat


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
    b0 = dc_bound(p, shift)
    checks = (
        Check("limiter-opamp-shift", "V_s − V_+ at V_cs = 0 (eq 11: the level shift)", "V", shift, "head_p",
              b0["total"], f"expected {s0['bias'] + s0['zener'] + s0['r7']:+.4%}: the bias current out of V+ through "
              f"R12 || R13 {s0['bias']:+.4%}, D1's 15 Ω at the current it carries ({s0['dvz'] * 1e3:+.1f} mV, taken at "
              f"its own voltage) {s0['zener']:+.4%}, R12's current through R7 (V_cs is not 0 with no motor current) "
              f"{s0['r7']:+.5%}; " + numerics.words(b0, 0.0), expected=s0["bias"] + s0["zener"] + s0["r7"],
              caveat=input_range()),)
    if t:
        bv, bi = trip_bound(t, p, eq_vcs, current=False), trip_bound(t, p, eq_vcs / p["r7"], current=True)
        checks += (
            Check("limiter-opamp-vcs", "V_cs where the output switches (eq 13)", "V", eq_vcs, "vcs_trip", bv["total"],
                  left_out_why(t, ("lag", "bias", "zener")) + "; " + numerics.words(bv, RAMP / STEPS),
                  expected=t["lag"] + t["bias"] + t["zener"], caveat=input_range()),
            Check("limiter-opamp-itrip", "motor current where the output switches (eq 13 / R7)", "A",
                  eq_vcs / p["r7"], "i_trip", bi["total"],
                  left_out_why(t, ("lag", "bias", "zener", "r12")) + "; " + numerics.words(bi, RAMP / STEPS),
                  expected=t["lag"] + t["bias"] + t["zener"] + t["r12"], caveat=input_range()))
    # a second copy that eq 14 and a wrong-signed offset term cannot pass: the note's offset (9 mV, LM358 over
    # temperature) and a level shift 2 % off the reference (R13 low), where eq 13 and eq 14 part
    q = {**p, "vos": an94002.params()["offset"], "r13": p["r13"] * (1 - MISMATCH)}
    eq_q = trip_voltage(q)
    if eq_q > 0:
        q["i_max"] = 2 * eq_q / q["r7"]
        eq14 = an94002.v_cs_matched(q["zener_voltage"], q["r9"], q["r10"], q["r11"]) / eq_q - 1
        wrong_sign = 2 * q["vos"] / an94002.factor_a(q["r12"], q["r13"]) / eq_q
        tq = left_out.opamp_terms(q, eq_q, RAMP, _mid(q), with_bias=False)
        bq = trip_bound(tq, q, eq_q, current=False)
        checks += (Check("limiter-opamp-vcs-offset", f"V_cs where the output switches, with {q['vos'] * 1e3:g} mV of "
                         f"offset and R13 {MISMATCH:.0%} low (eq 13 with the offset and bias)", "V", eq_q, "vcs_trip_1",
                         bq["total"], f"eq 13 with the offset referred through A and the bias currents' node terms "
                         f"(here eq 14 would be {eq14:+.0%} off and a wrong-signed offset {wrong_sign:.0%}); "
                         + left_out_why(tq, ("lag", "zener")) + "; " + numerics.words(bq, RAMP / STEPS),
                         expected=tq["lag"] + tq["zener"], caveat=input_range("_1")),)
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


#: the corner deck's time steps: the output comes back up some 0.4 ms after its drive turns positive, and
#: :func:`.numerics.crossing_time` bounds a crossing a step or more after the release: 0.2 ms
CORNER_STEPS = 5000


@rebuildable
def opamp_corner(p: dict | None = None) -> Circuit:
    """The note's network at its least-headroom corner: V+ starts 1.92 V below the supply, inside the LM358's
    2 V; the model's output then sticks low (the limiter acts with no current) until V+ is back in range."""
    p = {**corner_defaults(), **(p or {})}
    eq = corner_equations(p)
    p["i_max"] = max(p["i_max"], 2 * eq["trip"] / p["r7"])  # the ramp runs past the trip, whatever the network
    parts = opamp_parts(p)
    mid, h = _mid(p), RAMP / CORNER_STEPS
    # the output's first rise through mid-swing after a quarter of the pause: where V+ is in range already at no
    # motor current the output is high then, and the reading is the motor current then, 0 A (never held low)
    probe = [_probe("back", f"v(out)*u(time-{T0 / 4:g})")]
    back = [f".meas tran i_back FIND i(VAM) WHEN v(pback)={mid:.{DIGITS}g} RISE=1"]
    s0 = left_out.shift_terms(p, eq["head0"], with_bias=False)
    b0 = dc_bound(p, eq["head0"])
    b = left_out.back_terms(p, eq["v_back"], RAMP, mid)
    eq_i = eq["v_back"] / p["r7"]
    back_exp = (b["reading"] - eq_i) / abs(eq_i) if eq_i else 0.0
    a = an94002.factor_a(p["r12"], p["r13"])
    if b.get("never"):  # only where the equation's figure is far off (a fault put in it): nothing to read
        bb = {"total": numerics.PRINTED}
        why_back = ("eq 11 with the bias solved for 2 V of headroom; the output, held low, would not come back before "
                    "the trip if V+ were back in range where this figure says: no expected reading; "
                    f"±{numerics.pct(bb['total'])} %")
    elif b["held"]:
        bb = numerics.ramp_row(b["response"], b["t_cross"], h, SOLVER, rate=p["i_max"] / RAMP, v_rate=b["slope"],
                               value=eq_i, v_node=p["v_supply"], a=a, reads_nodes=False)
        why_back = (f"eq 11 with the bias solved for 2 V of headroom; expected {back_exp:+.3%}: D1's 15 Ω at its current "
                    f"there ({b['dvz'] * 1e3:+.1f} mV) moves V+'s headroom, and the current that brings it to 2 V, by "
                    f"{b['zener']:+.3%}; the "
                    f"model's change-over (it blends its inputs in over the last 1 mV below the limit: its drive turns "
                    f"positive {b['early'] * 1e3:.3f} mV of headroom before 2 V) {b['change_over']:+.3%}; the output's "
                    f"rise from its low clamp to mid-swing ({b['tau'] * 1e3:.3g} ms, its drive quadratic in time while "
                    f"the inputs are blended in, linear after, solved exactly) {b['lag']:+.3%}; R12's current in R7 "
                    f"{b['r12']:+.3%}. Where V+ is in range already at no motor current the output is never held low "
                    "and the row reads 0 A; " + numerics.words(bb, h))
    else:
        bb = {"total": numerics.PRINTED + SOLVER["abstol"] / abs(eq_i or 1.0)}
        why_back = (f"eq 11 with the bias solved for 2 V of headroom gives {eq['v_back'] * 1e3:.3g} mV of V_cs, but "
                    f"D1's 15 Ω at its current ({b['dvz'] * 1e3:+.1f} mV) lifts V+'s headroom to 2 V or more already at "
                    f"no motor current: the output is never held low, and the deck's probe reads the motor current "
                    f"then, 0 A: expected {back_exp:+.0%}; left: the printed digits and the solver's ABSTOL: "
                    f"±{numerics.pct(bb['total'])} %")

    def never_held(got: dict) -> str:
        if got["i_back"] != 0.0:
            return ""
        return (f"never held low: V+ {got['head_p']:.4g} V below the supply at no motor current, in the LM358's range, "
                "so the row reads 0 A")
    t = left_out.opamp_terms(p, eq["trip"], RAMP, mid, with_bias=False)
    bt = trip_bound(t, p, eq["trip"] / p["r7"], current=True, steps=CORNER_STEPS)
    checks = (
        Check("limiter-corner-headroom", "V_s − V_+ at V_cs = 0, least-headroom corner (eq 11 with the bias)", "V",
              eq["head0"], "head_p", b0["total"], f"eq 11 less the bias current out of V+ through R12 || R13 (at the "
              f"note's network this corner is the design's worst case, a test holds the two together); expected "
              f"{s0['zener'] + s0['r7']:+.4%}: D1's 15 Ω at the current it carries ({s0['dvz'] * 1e3:+.1f} mV, taken at "
              f"its own voltage) {s0['zener']:+.4%}, R12's current through R7 {s0['r7']:+.5%}; "
              + numerics.words(b0, 0.0), expected=s0["zener"] + s0["r7"], caveat=input_range()),
        Check("limiter-corner-back", "motor current where V+ is back 2 V below the supply (output rises)", "A",
              eq_i, "i_back", bb["total"], why_back, expected=back_exp, caveat=never_held),
        Check("limiter-corner-trip", "motor current where the output falls (node equation with bias)", "A",
              eq["trip"] / p["r7"], "i_trip", bt["total"], "the node equation holds the offset and the bias currents; "
              + left_out_why(t, ("lag", "zener", "r12")) + "; " + numerics.words(bt, h), expected=t["lag"] + t["zener"]
              + t["r12"], caveat=input_range(what="its output idles low until V+ is back in range")))
    deck = _opamp_deck("AN94002 figure 3 at its least-headroom corner", [p], extra_meas=back, extra_body=probe,
                       steps=CORNER_STEPS)
    return Circuit("limiter-opamp-corner", "Op-amp limiter, least-headroom corner", "AN94002 figure 3", parts,
                   deck, checks, draw=lambda: draw_opamp(parts))


def draw_one_transistor(parts):
    from .drawings import one_transistor
    return one_transistor(parts)


def draw_opamp(parts):
    from .drawings import opamp
    return opamp(parts)


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
