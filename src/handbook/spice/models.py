"""Device models for ngspice, written in the project from the datasheet figures gathered in
the parts' public datasheets (no vendor macro-model is copied). One function per device,
returning its netlist lines; every number is cited where it is set. Where a datasheet gives no figure the
model needs, the value is an assumption and says so.
"""
from __future__ import annotations

import math

#: Boltzmann constant over the elementary charge, V/K (thermal voltage kT/q = K_Q * T)
K_Q = 1.380649e-23 / 1.602176634e-19
T25 = 298.15  # K: the datasheets' 25 C, the models' nominal temperature (TNOM)

# ----------------------------------------------------------------------------------------------
# BZX79-C8V2 zener

#: BZX79-C8V2: V_Z min / nominal / max at I_Z = 5 mA (BZX79-C8V2 datasheet)
BZX79_C8V2_VZ = (7.7, 8.2, 8.7)
BZX79_C8V2_IZT = 5e-3  # A: the test current of V_Z (BZX79 datasheet)
BZX79_C8V2_RZ = 15.0  # ohm: dynamic resistance, datasheet maximum "below 15 ohm" (BZX79 datasheet)


def bzx79_c8v2(name: str = "BZX79C8V2", v_z: float = BZX79_C8V2_VZ[1], r_z: float = BZX79_C8V2_RZ,
               tc: float = 0.0, digits: int = 6) -> list[str]:
    """`.model` of a BZX79-C8V2 whose breakdown is ``v_z`` at the 5 mA test current.

    ngspice's diode conducts IBV at V = BV in breakdown, plus I RS: with IBV = 5 mA the voltage at 5 mA is
    BV + 5 mA x RS. The dynamic resistance at 5 mA is RS plus the exponential's n V_T / I (5.1 ohm at
    25 C); RS is chosen so that the two add up to ``r_z`` (default the datasheet's 15 ohm maximum: the
    worst case for how far V_Z moves with the current the dividers draw). Pass ``v_z`` = 7.7 or 8.7
    (:data:`BZX79_C8V2_VZ`) or any tolerance corner. The temperature coefficient (+0.03 to +0.08 %/K,
    BZX79 datasheet) is modelled only when ``tc`` (V/K) is given: then BV moves by ``tc`` per kelvin from 25 C
    (ngspice's TCV, in V/K with the opposite sign: BV(T) = BV - TCV (T - TNOM)); by default the circuits fold the
    drift into ``v_z``. ``digits``: significant digits of BV and RS in the model line.
    """
    rs = r_z - K_Q * T25 / BZX79_C8V2_IZT
    if rs <= 0 or v_z <= 0:
        raise ValueError(f"zener model: r_z = {r_z:g} ohm must exceed {K_Q * T25 / BZX79_C8V2_IZT:.3g} ohm, v_z > 0")
    bv = v_z - BZX79_C8V2_IZT * rs
    return [f"* BZX79-C8V2: V_Z = {v_z:.6g} V at 5 mA, r_z = {r_z:g} ohm (BZX79 datasheet: 7.7..8.7 V, < 15 ohm)",
            f".model {name} D(BV={bv:.{digits}g} IBV={BZX79_C8V2_IZT:g} RS={rs:.{digits}g} IS=1e-14 TNOM=25"
            + (f" TCV={-tc:.6g})" if tc else ")")]


# ----------------------------------------------------------------------------------------------
# BC557 PNP

#: BC557: V_BE(on) min / typ / max at I_C = 2 mA (BC557 datasheet, one maker)
BC557_VBE = (0.55, 0.62, 0.70)
BC557_IC = 2e-3  # A: the current of that figure
BC557_BF = 200.0  # assumption: no current gain is taken from a datasheet; it moves the base current only


def bc557(name: str = "BC557", v_be: float = BC557_VBE[1]) -> list[str]:
    """`.model` of a BC557 whose V_BE is ``v_be`` at I_C = 2 mA and 25 C (IS = 2 mA / exp(V_BE / V_T)).

    Its temperature behaviour is SPICE's silicon default (EG = 1.11 eV, XTI = 3), not tuned: that gives
    dV_BE/dT of about -1.9 mV/K at 2 mA, an independent check of the -2 mV/K rule of thumb (no BC557
    datasheet consulted gives a coefficient). No Early voltage and no resistances (none is in the datasheets).
    """
    is_ = BC557_IC / math.exp(v_be / (K_Q * T25))
    return [f"* BC557: V_BE(on) = {v_be:.6g} V at 2 mA, 25 C (BC557 datasheet: 0.55 / 0.62 / 0.70 V); "
            f"BF = {BC557_BF:g} assumed",
            f".model {name} PNP(IS={is_:.6g} BF={BC557_BF:g} BR=5 NF=1 EG=1.11 XTI=3 TNOM=25)"]


# ----------------------------------------------------------------------------------------------
# LM358 (one amplifier), behavioural

#: LM358 figures. From the LM358 datasheet (TI SLOS068): the offset (9 mV max over temperature) and the input
#: common-mode limit (0 to V_CC - 2 V over temperature). The bias current is the LM358 datasheet's (TI
#: SLOS068) 500 nA over temperature, as the design's spec cites it. The rest are assumptions (typical LM358
#: figures, not from the datasheet): they set how fast and how far the output moves, not where it trips.
LM358 = {
    "offset_max": 9e-3,  # V, LM358 datasheet: 9 mV max over temperature
    "bias": 500e-9,  # A, LM358 datasheet (TI SLOS068), over temperature; out of the pins (PNP inputs)
    "cm_headroom": 2.0,  # V, LM358 datasheet: inputs 0 to V_CC - 2 V over temperature
    "a0": 1e5,  # V/V, assumption: 100 V/mV
    "gbw": 0.7e6,  # Hz, assumption: unity-gain bandwidth 0.7 MHz
    "v_oh_drop": 1.5,  # V, assumption: the output goes no higher than V_CC - 1.5 V
    "v_ol": 0.02,  # V, assumption: and no lower than 20 mV above its ground
}


def lm358(name: str = "LM358", stuck: str = "low", values: dict | None = None) -> list[str]:
    """A `.subckt` of one LM358 amplifier: pins ``inp inn vcc vee out``, instance parameters ``vos`` (input
    offset, V: the output switches where V+ - V- = vos), ``ibp`` and ``ibn`` (bias current out of each input
    into the circuit, A; negative for a current into the pin).

    One dominant pole (A0 and GBW of :data:`LM358`), the output clamped to [V_ol, V_CC - 1.5 V] without
    wind-up. **Input common-mode limit**: while either input is within 2 V of V_CC (LM358 datasheet, over
    temperature) the datasheet no longer says what the output does; the model then ignores the inputs and
    drives the output to one rail (``stuck`` = "low" or "high"), so a simulation shows the comparison lost
    instead of a plausible answer. Which way a real LM358 goes is not specified: the choice is an
    assumption, made so that the failure is visible. The change-over takes 1 mV below the limit.

    ``values`` ({"vos", "ibp", "ibn"}) writes those figures into the subcircuit instead of taking them as
    instance parameters: a plain ``.subckt`` line without ngspice's ``params:`` and no brace expressions, which
    other SPICEs read too (the exported netlists, :mod:`handbook.spice.netlist`).
    """
    if stuck not in ("low", "high"):
        raise ValueError(f"stuck = {stuck!r}: 'low' or 'high'")
    m = LM358
    rx = 1e5  # ohm: internal node; gm = A0 / rx
    cx = m["a0"] / (2 * math.pi * m["gbw"] * rx)  # pole at GBW / A0
    drive = -0.01 if stuck == "low" else 0.01  # V of apparent input while out of range
    hi, lo = f"(v(vcc,vee)-{m['v_oh_drop']:g})", f"{m['v_ol']:g}"
    ok = "v(ok,vee)"
    if values is None:
        head = f".subckt {name} inp inn vcc vee out params: vos=0 ibp={m['bias']:g} ibn={m['bias']:g}"
        vos, ibp, ibn = "vos", "{ibp}", "{ibn}"
    else:  # the figures written in: a plain subcircuit
        head = f".subckt {name} inp inn vcc vee out"
        vos, ibp, ibn = (f"{values[k]:.6g}" for k in ("vos", "ibp", "ibn"))
    return [
        f"* LM358, behavioural: offset vos, bias ib (500 nA max, TI SLOS068), common-mode limit V_CC - "
        f"{m['cm_headroom']:g} V (LM358 datasheet); A0, GBW and output swing assumed",
        head,
        f"Ibp vcc inp {ibp}",
        f"Ibn vcc inn {ibn}",
        f"Bok ok vee V=max(min((min(v(vcc,inp),v(vcc,inn))-{m['cm_headroom']:g})/1e-3+1,1),0)",
        f"Bgm vee x I={m['a0'] / rx:g}*({ok}*(v(inp,inn)-({vos}))+(1-{ok})*({drive:g}))",
        f"Rx x vee {rx:g}",
        f"Cx x vee {cx:.6g}",
        f"Bcl x vee I=10*(max(v(x,vee)-{hi},0)+min(v(x,vee)-{lo},0))",
        f"Bout out vee V=max(min(v(x,vee),{hi}),{lo})",
        f".ends {name}",
    ]


# ----------------------------------------------------------------------------------------------
# BD434 PNP (series regulator T1 of the AN94002 speed control)

#: BD434: AN94002 2.2 names the part and asks for at least 1 V across R7 and T1 for linear control;
#: no BD434 datasheet figure is used for it. Every value below is an assumption, of the order that public
#: BD433-BD438 datasheets print (h_FE at least 85 at 0.5 A and 50 at 2 A, V_CE(sat) up to 0.5 V at 2 A).
BD434 = {"bf": 85.0, "is": 1e-12, "vaf": 50.0, "ikf": 3.0, "rb": 2.0, "re": 0.05, "rc": 0.1, "cje": 200e-12,
         "cjc": 100e-12, "tf": 20e-9}


def bd434(name: str = "BD434", **figures) -> list[str]:
    """`.model` of a BD434 (PNP, 22 V, 4 A): assumed figures (see :data:`BD434`); V_BE about 0.7 V at 1 A.
    ``figures`` overrides any of them (``bf``, ``is``, ``ikf``, ...): the speed loop's tests vary them to show
    that no verdict rests on them."""
    unknown = set(figures) - set(BD434)
    if unknown:
        raise KeyError(f"BD434 figure(s) {', '.join(sorted(unknown))}; known: {', '.join(BD434)}")
    m = {**BD434, **figures}
    return [f"* BD434 PNP: assumed figures, not from a datasheet (BF {m['bf']:g}: h_FE of the order of the "
            "BD43x datasheets at 0.5 A)",
            f".model {name} PNP(IS={m['is']:g} BF={m['bf']:g} NF=1 VAF={m['vaf']:g} IKF={m['ikf']:g} BR=5 RB={m['rb']:g} "
            f"RE={m['re']:g} RC={m['rc']:g} CJE={m['cje']:g} CJC={m['cjc']:g} TF={m['tf']:g})"]


def bd434_dc(i_c: float, v_ec: float, **figures) -> tuple[float, float]:
    """(h_FE, V_EB) of :func:`bd434` at collector current ``i_c`` and emitter-collector voltage ``v_ec`` (its
    terminals), by the Gummel-Poon DC equations ngspice solves for that model at 27 C, in full: the base charge
    q_b = q_1 (1 + sqrt(1 + 4 q_2)) / 2 with q_1 = 1 / (1 - V_BC / VAF) (the Early effect) and q_2 = I_BE / IKF (high
    injection), I_C = (I_BE - I_BC) / q_b - I_BC / BR, I_B = I_BE / BF + I_BC / BR, the junction voltages inside RB,
    RE and RC. What a datasheet's h_FE curve and V_BE(sat) curve would give; solved by bisection on the internal
    emitter-base voltage, the internal emitter-collector voltage iterated (its drops are milliohms times amperes).

    Parameters
    ----------
    i_c : float
        Collector current (its magnitude), A, > 0.
    v_ec : float
        Emitter-collector voltage at the terminals, V (the transistor in its active region: above about 0.3 V).
    **figures
        Overrides of :data:`BD434`.

    Returns
    -------
    tuple of float
        (h_FE = I_C / I_B, V_EB at the terminals in V).
    """
    m = {**BD434, **figures}
    vt = K_Q * (273.15 + 27.0)
    br = 5.0  # the model line's BR

    def currents(v_eb_i: float, v_ec_i: float) -> tuple[float, float]:
        i_be = m["is"] * math.expm1(v_eb_i / vt)
        v_bc_i = v_eb_i - v_ec_i  # the collector junction, forward sense (negative: reverse biased)
        i_bc = m["is"] * math.expm1(v_bc_i / vt)
        q1 = 1 / (1 - v_bc_i / m["vaf"])
        qb = q1 / 2 * (1 + math.sqrt(1 + 4 * i_be / m["ikf"]))
        return (i_be - i_bc) / qb - i_bc / br, i_be / m["bf"] + i_bc / br

    v_ec_i, i_b = v_ec, 0.0
    for _ in range(20):
        lo, hi = 0.0, 1.5
        for _ in range(200):
            mid = (lo + hi) / 2
            if mid in (lo, hi):  # the interval is down to adjacent doubles: more rounds change nothing
                break
            lo, hi = (mid, hi) if currents(mid, v_ec_i)[0] < i_c else (lo, mid)
        v_eb_i = (lo + hi) / 2
        i_b = currents(v_eb_i, v_ec_i)[1]
        v_ec_i, last = v_ec - (i_c + i_b) * m["re"] - i_c * m["rc"], v_ec_i
        if v_ec_i == last:  # the fixed point, to the last bit
            break
    return i_c / i_b, v_eb_i + i_b * m["rb"] + (i_c + i_b) * m["re"]
