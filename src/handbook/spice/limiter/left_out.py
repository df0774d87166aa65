"""What the limiters' equations leave out and the decks keep, computed: each check's expected difference.

A check's tolerance is then the numerical method's alone (the ramp's step, .meas interpolation), and a change in
the equation as small as the tolerance shows (the mutation test). Each term is physics of the circuit, written
here from the parts' figures, not fitted to the simulation:

* **lag**: the LM358 model has one pole (A0 and GBW of :data:`models.LM358`). While the motor current ramps,
  its differential input falls at ``k`` V/s through the offset; the output, clamped at its high swing until
  then, follows x' = w (A0 v_d - x), w = 2 pi GBW / A0, and crosses mid-swing ``tau`` later, found from the
  closed form x(tau) = V_H e^(-w tau) - A0 k (tau - (1 - e^(-w tau)) / w). The sense voltage has risen by
  dV_cs/dt x tau by then.
* **bias**: the LM358's 500 nA out of each input, through the dividers' source resistances (the node
  equation's terms, :func:`.decks.trip_voltage`).
* **zener**: D1 is specified at 5 mA; the model's breakdown (:func:`models.bzx79_c8v2`: IBV = 5 mA at BV, RS
  in series) puts V_Z(I) = V_Z(5 mA) + V_T ln(I / 5 mA) + RS (I - 5 mA), 15 ohm of slope at 5 mA; I_Z is R14's
  current less what the two dividers feed into D1's anode.
* **R12 in R7**: R7 carries the level-shift divider's current too, so the motor current at a given V_cs is
  lower by it.
"""
from __future__ import annotations

import math

from ...sources import an94002
from .. import models


def lag(v_start: float, v_mid: float, k: float) -> float:
    """Seconds from the differential input crossing the offset to the output reaching ``v_mid``, the input
    moving at ``k`` V/s (negative: falling) and the output starting from its clamp ``v_start`` (module text)."""
    m = models.LM358
    w, a0 = 2 * math.pi * m["gbw"] / m["a0"], m["a0"]
    down = v_mid < v_start

    def past(tau):  # the output has reached v_mid
        x = v_start * math.exp(-w * tau) + a0 * k * (tau - (1 - math.exp(-w * tau)) / w)
        return x <= v_mid if down else x >= v_mid

    lo, hi = 0.0, 1e-6
    while not past(hi):
        hi *= 2
        if hi > 1e3:
            raise ValueError(f"the output never reaches {v_mid:.3g} V from {v_start:.3g} V with the input moving "
                             f"{k:.3g} V/s")
    for _ in range(80):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if past(mid) else (mid, hi)
    return (lo + hi) / 2


def zener_shift(i_z: float) -> float:
    """How far the BZX79 model's V_Z at ``i_z`` lies from its figure at the 5 mA test current (V)."""
    v_t = models.K_Q * models.T25
    rs = models.BZX79_C8V2_RZ - v_t / models.BZX79_C8V2_IZT
    return v_t * math.log(i_z / models.BZX79_C8V2_IZT) + rs * (i_z - models.BZX79_C8V2_IZT)


def divider_currents(p: dict, v_cs: float) -> dict:
    """At the trip (V+ = V-): the reference divider's current (R9 + R10 + R11, across D1), the level shift's
    (R12 + R13, across D1 less V_cs), R14's, and D1's: R14's less the two (A)."""
    v_z = p["zener_voltage"]
    i_ref = v_z / (p["r9"] + p["r10"] + p["r11"])
    i_shift = (v_z - v_cs) / (p["r12"] + p["r13"])
    i_r14 = (p["v_supply"] - v_z) / p["r14"]
    return {"ref": i_ref, "shift": i_shift, "r14": i_r14, "zener": i_r14 - i_ref - i_shift}


def bias_shift(p: dict) -> float:
    """How far the LM358's bias currents move AN94002 figure 3's trip V_cs (V): the node equation's terms
    I_+ R12 - I_- ((R9 + R10) || R11) / A (handbook.design.limiter.model), what eq 13 leaves out."""
    a = an94002.factor_a(p["r12"], p["r13"])
    r_m = (p["r9"] + p["r10"]) * p["r11"] / (p["r9"] + p["r10"] + p["r11"])
    return p["ibp"] * p["r12"] - p["ibn"] * r_m / a


def _shift_moved(p: dict, dvz: float) -> float:
    """How far eq 11's level shift moves when D1's voltage moves by ``dvz`` (V)."""
    return (an94002.level_shift(p["zener_voltage"] + dvz, p["r12"], p["r13"])
            - an94002.level_shift(p["zener_voltage"], p["r12"], p["r13"]))


def opamp_terms(p: dict, v_cs: float, ramp: float, v_mid: float, with_bias: bool) -> dict:
    """Relative terms (fractions of ``v_cs``, the equation's trip) for AN94002 figure 3 ramped from 0 to
    ``p["i_max"]`` in ``ramp`` seconds: lag, bias (when the equation has none), zener, and r12 (the motor
    current's share only: add it to an "i_trip" row, not a "vcs" row)."""
    a = an94002.factor_a(p["r12"], p["r13"])
    slope = p["r7"] * p["i_max"] / ramp  # dV_cs/dt
    tau = lag(p["v_supply"] - models.LM358["v_oh_drop"], v_mid, -a * slope)
    cur = divider_currents(p, v_cs)
    dvz = zener_shift(cur["zener"])
    network = (p["r9"], p["r10"], p["r11"], p["r12"], p["r13"])
    dvcs_dvz = (an94002.v_cs_trip(p["zener_voltage"] + 1e-3, *network, p["vos"])
                - an94002.v_cs_trip(p["zener_voltage"], *network, p["vos"])) / 1e-3
    bias = bias_shift(p) if with_bias else 0.0
    return {"lag": slope * tau / v_cs, "bias": bias / v_cs, "zener": dvcs_dvz * dvz / v_cs,
            "r12": -cur["shift"] * p["r7"] / v_cs, "tau": tau, "dvz": dvz, "i_zener": cur["zener"]}


def supply_terms(p: dict, v_supply: float, v_cs: float, ramp: float, v_mid: float) -> dict:
    """The same for AN93008 figure 3 (no zener): lag and bias, fractions of ``v_cs``."""
    from ...sources import an93008

    a = an93008.factor_a(p["r8"], p["r9"])
    slope = p["r7"] * p["i_max"] / ramp
    tau = lag(v_supply - models.LM358["v_oh_drop"], v_mid, -a * slope)
    r_p, r_m = p["r8"] * p["r9"] / (p["r8"] + p["r9"]), p["r10"] * p["r11"] / (p["r10"] + p["r11"])
    # the bias currents flow out of the pins: V+ rises by I_bp (R8 || R9), V- by I_bn (R10 || R11), so the
    # trip's V_cs moves by (I_bp R_p - I_bn R_m) / A
    bias = (p["ibp"] * r_p - p["ibn"] * r_m) / a
    return {"lag": slope * tau / v_cs, "bias": bias / v_cs, "tau": tau}


def shift_terms(p: dict, shift: float, with_bias: bool) -> dict:
    """At no motor current, fractions of ``shift`` (V_s - V+, eq 11): the bias current out of V+ through
    R12 || R13 (when the equation has none) and the zener's 15 ohm at the current it carries there."""
    cur = divider_currents(p, 0.0)
    dvz = zener_shift(cur["zener"])
    r_p = p["r12"] * p["r13"] / (p["r12"] + p["r13"])
    return {"bias": (-p["ibp"] * r_p / shift) if with_bias else 0.0, "zener": _shift_moved(p, dvz) / shift,
            "dvz": dvz}


def back_terms(p: dict, v_back: float, ramp: float, v_mid: float) -> dict:
    """Where V+ comes back ``headroom`` below the supply as the current rises (AN94002 figure 3 at its
    least-headroom corner), fractions of ``v_back`` (the equation's V_cs there): the zener's 15 ohm at its
    current then (it moves the headroom at no current, ``head0``, and so the V_cs that restores it) and the
    model's change-over (:func:`models.lm358`: inputs in range over the last 1 mV below the limit, the
    output's apparent input -10 mV until then): the drive turns positive where ok v_d = 10 mV (1 - ok), that
    is (1 - ok) mV of headroom before the limit, and the output then takes :func:`lag` to rise to mid-swing,
    the drive growing at (v_d + 10 mV) per mV of headroom recovered."""
    a = an94002.factor_a(p["r12"], p["r13"])
    cur = divider_currents(p, v_back)
    dvz = zener_shift(cur["zener"])
    d_head = _shift_moved(p, dvz)
    network = (p["r9"], p["r10"], p["r11"], p["r12"], p["r13"])
    v_d = a * (an94002.v_cs_trip(p["zener_voltage"], *network, p["vos"]) - v_back)  # V+ - V- less the offset
    ok = 0.01 / (v_d + 0.01)
    early = (1 - ok) * 1e-3  # V of headroom before the limit at which the drive turns positive
    slope = p["r7"] * p["i_max"] / ramp
    tau = lag(models.LM358["v_ol"], v_mid, (v_d + 0.01) * a * slope / 1e-3)
    return {"zener": -d_head / a / v_back, "change_over": -early / a / v_back, "lag": slope * tau / v_back,
            "r12": -cur["shift"] * p["r7"] / v_back, "ok": ok, "dvz": dvz, "tau": tau}


def bc557_vbe(v_be25: float, i_c: float, temperature: float) -> float:
    """V_BE of the BC557 model (:func:`models.bc557`: IS from ``v_be25`` at 2 mA and 25 C, NF = 1, EG = 1.11 eV,
    XTI = 3) at ``i_c`` and ``temperature`` (C): SPICE's saturation current law IS(T) = IS (T/T0)^XTI
    exp(EG (T - T0) / (V_T(T) T0)) solved for V_BE = V_T(T) ln(I_C / IS(T))."""
    t0, t = models.T25, temperature + 273.15
    is25 = models.BC557_IC / math.exp(v_be25 / (models.K_Q * t0))
    v_t = models.K_Q * t
    is_t = is25 * (t / t0) ** 3 * math.exp(1.11 * (t - t0) / (v_t * t0))
    return v_t * math.log(i_c / is_t)


def one_transistor_terms(p: dict, r7: float, temperature: float, equation: float) -> dict:
    """The one-transistor limiter at ``temperature``: the motor current where T2's collector carries 2 mA is
    V_BE(T) / R7 plus T2's base current I_C / h_FE. "base" is that current as a fraction of the equation's (what
    the equation leaves out); "tc" the model's own drift of V_BE (V/K), which the check holds the equation's rule
    of thumb against, and "silicon" the difference it makes (for the text, never an expected difference: it is
    the claim under test)."""
    v_be = bc557_vbe(p["v_be_bc557"], models.BC557_IC, temperature)
    return {"silicon": v_be / r7 / equation - 1, "base": models.BC557_IC / models.BC557_BF / equation,
            "tc": (v_be - p["v_be_bc557"]) / (temperature - 25.0) if temperature != 25.0 else float("nan")}
