"""AN94002: evaluation board for the TDA5143/TDA5144 (Philips, R. Galema, 1995).

Engineering functions for every calculation of the note, its equations (printed form, derivation
from circuit laws) and every number it prints as the result of a calculation.

All functions take and return SI values (farads, volts, amperes, seconds, ohms; rotational speed in
rpm, as the note states it). Device figures the note relies on without printing come from
``shared/appnotes/datasheet_facts.md`` and are cited where used (see ``DATASHEET``).
"""
from __future__ import annotations

import functools
import math

import numpy as np

from . import series, tolerance, validate
from .examples import Example, Printed, TextErratum, evaluate_all

NOTE = "AN94002"

# ----------------------------------------------------------------------------------------------
# inputs: the note's values (defaults of every chapter's `parameters` cell)

DEFAULTS: dict = {
    # 2.1.1 start oscillator
    "inertia": 72e-6,  # J, kg m^2
    "torque_constant": 25e-3,  # K_t, N m / A
    "pole_pairs": 6,
    "start_current": 0.5,  # A
    "i_cap_st": 2e-6,  # CAP-ST charge = discharge current, A (AN94002 2.1.1)
    "v_st_low": 0.05,  # V (AN94002; the TDA5144 datasheet says 0.20 V)
    "v_st_high": 2.2,  # V
    "f_start": 2.0,  # chosen start frequency, Hz
    "cap_st_series": "E12",
    # 2.1.2 adaptive commutation delay
    "rpm_min": 1800.0,
    "i_charge_max": 22e-6,  # A, as AN94002 uses it (the datasheet's maximum *discharge* current)
    "i_charge_min": 10.6e-6,  # A, same column pairing as the note's 22 uA (datasheet sink minimum)
    "v_cd_high_min": 2.3,  # V, CAP-CD upper switching level, minimum (TDA5144 datasheet)
    "v_cd_low_max": 0.9,  # V, CAP-CD lower switching level, maximum
    "min_excursion": 0.1,  # V, smallest excursion still safe from noise: an assumption, not the note's
    "cap_tolerance": 0.05,
    "cap_series": "E12",
    # 2.1.3 watchdog
    "i_wd": 5e-6,  # A
    "v_ti_low": 0.3,  # V
    "v_ti_high": 2.2,  # V
    "cap_ti": 10e-9,  # F, the board's C6
    "cap_ti_min": 2e-9,  # F
    "i_ti_fast": 57e-6,  # A, 0.2 V to 0.3 V (internal timing)
    "v_ti_start": 0.2,  # V
    "i_ti_discharge": 28e-6,  # A
    # 2.2 speed control
    "v_supply": 12.0,
    "supply_tolerance": 0.10,
    "v_drop_min": 1.0,  # V across R7 and T1
    "r3": 39e3,
    "r4": 10e3,
    "v_mot_min": 1.7,  # V, back-EMF comparators
    "ota_headroom": 1.7,  # V, OTA inputs <= V_P - 1.7 V
    "v_p_min": 10.8,  # V, lowest V_P: an assumption (V_P from the same 12 V +- 10 % supply)
    # 2.3 one-transistor limiter
    "v_be": 0.8,  # V
    "v_be_tc": -2e-3,  # V/K
    "i_limit": 1.0,  # A, the user's limit current (the note leaves R7 "TBD")
    "t_low": 0.0,  # C, temperature range for the drift plots
    "t_high": 70.0,
    # 2.4 op-amp limiter
    "v_zener": 8.2,
    "zener_tolerance": 0.05,
    "zener_tc": 6.2e-3,  # V/K, "max. 6.2 mV/C"
    "temp_span": 25.0,  # K, 25 C +- 25 C
    "r10": 5.6e3, "r11": 16e3, "r12": 5.6e3, "r13": 16e3,
    "v_cs": 0.1,  # V, current-sense voltage at the limit
    "offset": 9e-3,  # V, LM358 maximum input offset
    "offset_generic": 10e-3,  # V, "normal for general purpose low-cost op-amps"
    "resistor_tolerance": 0.01,  # R9..R13 (the parts list gives 1 % for R10..R13)
    "level_shift_min": 2.0,  # V below the supply (LM358 common-mode range)
    # 3 decoupling
    "z_max": 2.0,  # ohm
    "f_decoupling": 2e6,  # Hz
    "c2": 10e-6,  # F
    "esr": 1.0,  # ohm, an illustrative electrolytic ESR at 2 MHz (assumption, not from a datasheet)
    "esl": 15e-9,  # H, an illustrative lead + body inductance (assumption)
}

#: Figures AN94002 relies on without printing, with where they were read (datasheet_facts.md).
DATASHEET = {
    "cap_cd_charge": ((5.3e-6, 8.1e-6, 11e-6), "TDA5144 datasheet (June 1994), CAP-CD electrical table: "
                      "charge (source) current min/typ/max; column pairing is an interpretation of a scrambled table"),
    "cap_cd_discharge": ((10.6e-6, 16.2e-6, 22e-6), "TDA5144 datasheet, CAP-CD discharge (sink) current min/typ/max"),
    "cap_cd_low": ((0.80, 0.875, 0.90), "TDA5144 datasheet, CAP-CD lower switching level min/typ/max"),
    "cap_cd_high": ((2.3, 2.4, 2.55), "TDA5144 datasheet, CAP-CD upper switching level min/typ/max"),
    "cap_st_levels": ((0.20, 2.20), "TDA5144 datasheet: CAP-ST switching levels 0.20 V and 2.20 V; "
                      "its own example gives C = 0.5/2 = 0.25 uF for 500 ms"),
    "cap_st_current": ((1.5e-6, 2.0e-6, 2.5e-6), "TDA5144 datasheet, CAP-ST charge/discharge current"),
    "v_mot_range": ((1.7, 16.0), "TDA5144 datasheet, V_MOT 1.7 to 16 V"),
    "bc557_vbe": ((0.55, 0.62, 0.70), "BC557 datasheet (one maker): V_BE(on) at 2 mA min/typ/max"),
    "bzx79_tc": ((0.03e-2, 0.08e-2), "BZX79 datasheet: temperature coefficient +0.03 to +0.08 %/K"),
    "lm358_offset": ((7e-3, 9e-3), "LM358 datasheet: input offset 7 mV max at 25 C, 9 mV over temperature"),
    "lm358_cm": ((1.5, 2.0), "LM358 datasheet: common-mode range to V_CC - 1.5 V at 25 C, V_CC - 2 V over temperature"),
}


def params(**overrides) -> dict:
    """The note's inputs with ``overrides`` applied; unknown names are refused with the near match."""
    unknown = [k for k in overrides if k not in DEFAULTS]
    if unknown:
        import difflib
        hints = []
        for k in unknown:
            m = difflib.get_close_matches(k, DEFAULTS, n=1)
            hints.append(f"{k!r}" + (f" (did you mean {m[0]!r}?)" if m else ""))
        raise validate.InputError("unknown AN94002 parameter " + ", ".join(hints))
    p = dict(DEFAULTS)
    p.update(overrides)
    return p


# ----------------------------------------------------------------------------------------------
# 2.1.1 start oscillator

def oscillation_frequency(torque_constant, current, pole_pairs, inertia):
    """Eq 2: rotor oscillation about a detent, f = sqrt(K_t I p / J) / (2 pi)."""
    validate.positive("torque_constant", torque_constant, "N m/A")
    validate.positive("start_current", current, "A")
    validate.pole_pairs("pole_pairs", pole_pairs)
    validate.positive("inertia", inertia, "kg m^2")
    return math.sqrt(torque_constant * current * pole_pairs / inertia) / (2 * math.pi)


def start_period(cap, i_cap=2e-6, v_low=0.05, v_high=2.2):
    """Eq 1 from charge balance: charge and discharge at I over the window, t = 2 C dV / I."""
    validate.ordered("v_st_low", v_low, "v_st_high", v_high)
    return 2 * cap * (v_high - v_low) / validate.positive("i_cap_st", i_cap, "A")


def cap_st_for(t_start, i_cap=2e-6, v_low=0.05, v_high=2.2):
    validate.ordered("v_st_low", v_low, "v_st_high", v_high)
    return validate.positive("t_start", t_start, "s") * i_cap / (2 * (v_high - v_low))


# ----------------------------------------------------------------------------------------------
# 2.1.2 adaptive commutation delay

def t_cycle(rpm, pole_pairs):
    """Eq 3: one electrical cycle, 60 / (RPM n) seconds."""
    return 60.0 / (validate.positive("rpm", rpm, "rpm") * validate.pole_pairs("pole_pairs", pole_pairs))


def t_com(rpm, pole_pairs):
    """Eq 4: six commutations per electrical cycle, 10 / (RPM n) seconds."""
    return t_cycle(rpm, pole_pairs) / 6


def excursion(cap, rpm, pole_pairs, i_charge):
    """Voltage swing on CAP-CD: charged for one commutation interval, dV = I t_com / C."""
    return i_charge * t_com(rpm, pole_pairs) / validate.positive("cap_cd", cap, "F")


def cap_cd_min(rpm_min, pole_pairs, i_charge_max, window):
    """Eq 5/6: the smallest CAP-CD whose swing at rpm_min fits the window with the largest current."""
    validate.positive("i_charge_max", i_charge_max, "A")
    return i_charge_max * t_com(rpm_min, pole_pairs) / validate.positive("window", window, "V")


def rpm_min_for(cap, pole_pairs, i_charge_max, window):
    """The lowest speed at which a capacitor's swing still fits the window (eq 5 solved for RPM)."""
    return 10.0 * i_charge_max / (validate.positive("window", window, "V") * pole_pairs * cap)


def rpm_max_for(cap, pole_pairs, i_charge_min, min_excursion):
    """Eq 7: the highest speed at which the swing with the smallest current stays above the noise floor."""
    validate.positive("min_excursion", min_excursion, "V")
    return 10.0 * i_charge_min / (min_excursion * validate.pole_pairs("pole_pairs", pole_pairs) * cap)


def reliable_speed_range(cap, tolerance, pole_pairs, i_charge_min, i_charge_max, window, min_excursion):
    """The speeds a capacitor covers in the worst case: the lowest at its small tolerance end with the
    largest current (eq 5), the highest at its large end with the smallest current (eq 7)."""
    return (rpm_min_for(cap * (1 - tolerance), pole_pairs, i_charge_max, window),
            rpm_max_for(cap * (1 + tolerance), pole_pairs, i_charge_min, min_excursion))


def rpm_ratio(window, min_excursion, i_charge_min, i_charge_max):
    """Eq 8: RPM_max / RPM_min for a capacitor sized exactly at the bound."""
    return window * i_charge_min / (min_excursion * i_charge_max)


def choose_cap_cd(rpm_min, pole_pairs, i_charge_max, window, tolerance=0.05, series_name="E12"):
    """The smallest series value that meets the bound at its low tolerance end.

    Returns (chosen, bound, {value: reason}) where the dict explains each smaller series value that fails.
    """
    bound = cap_cd_min(rpm_min, pole_pairs, i_charge_max, window)
    chosen = series.smallest_meeting(series_name, bound, validate.fraction("cap_tolerance", tolerance))
    rejected = {}
    for v in series.values(series_name, chosen / 3, chosen * 0.999):
        if v * (1 - tolerance) < bound <= v:
            rejected[v] = (f"meets the nominal bound {bound * 1e9:.2f} nF but not at -{tolerance:.0%}: "
                           f"{v * (1 - tolerance) * 1e9:.2f} nF")
        elif v < bound:
            rejected[v] = f"below the bound {bound * 1e9:.2f} nF"
    return chosen, bound, rejected


# ----------------------------------------------------------------------------------------------
# 2.1.3 watchdog

def cap_ti_for(t_wd, i_wd=5e-6, v_low=0.3, v_high=2.2):
    """Eq 9: C = I t_wd / dV (charge from 0.3 V to 2.2 V at 5 uA)."""
    validate.ordered("v_ti_low", v_low, "v_ti_high", v_high)
    return i_wd * validate.positive("t_wd", t_wd, "s") / (v_high - v_low)


def watchdog_time(cap, i_wd=5e-6, v_low=0.3, v_high=2.2):
    validate.ordered("v_ti_low", v_low, "v_ti_high", v_high)
    return validate.positive("cap_ti", cap, "F") * (v_high - v_low) / validate.positive("i_wd", i_wd, "A")


def cap_ti_waveform(cap, p: dict, stalled: bool = True):
    """Piecewise-linear CAP-TI voltage for one watchdog cycle (times in s, volts).

    Fast charge 0.2 -> 0.3 V at 57 uA, watchdog charge 0.3 -> 2.2 V at 5 uA, then discharge at
    28 uA back to 0.2 V. With ``stalled`` False the EMF recovers halfway up the watchdog ramp.
    """
    v0, v1, v2 = p["v_ti_start"], p["v_ti_low"], p["v_ti_high"]
    t1 = cap * (v1 - v0) / p["i_ti_fast"]
    top = v2 if stalled else v1 + 0.5 * (v2 - v1)
    t2 = t1 + cap * (top - v1) / p["i_wd"]
    t3 = t2 + cap * (top - v0) / p["i_ti_discharge"]
    return np.array([0.0, t1, t2, t3]), np.array([v0, v1, top, v0])


# ----------------------------------------------------------------------------------------------
# 2.2 speed control

def v_mot_max(v_supply, supply_tolerance, v_drop_min):
    """Highest controllable V_mot: the lowest supply less the drop R7 and T1 need."""
    return validate.positive("v_supply", v_supply, "V") * (1 - validate.fraction("supply_tolerance", supply_tolerance)) - v_drop_min


def v_in_for(v_mot, r3, r4):
    """Eq 10: the OTA holds AMPIN+ = AMPIN-, so V_in equals the divided V_mot."""
    return v_mot * validate.positive("r4", r4, "ohm") / (validate.positive("r3", r3, "ohm") + r4)


def r3_for(v_mot, v_in, r4):
    """Eq 10 solved for R3."""
    validate.positive("v_in", v_in, "V")
    if v_mot <= v_in:
        raise validate.InputError(f"v_mot = {v_mot:g} V must exceed v_in = {v_in:g} V for a divider")
    return r4 * (v_mot / v_in - 1)


def v_in_range(p: dict) -> tuple[float, float]:
    """V_in for the lowest running V_mot and for the highest controllable V_mot."""
    top = v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"])
    return v_in_for(p["v_mot_min"], p["r3"], p["r4"]), v_in_for(top, p["r3"], p["r4"])


def ota_input_max(p: dict) -> float:
    """The OTA inputs may not exceed V_P - 1.7 V (TDA5144 datasheet, quoted by the note)."""
    return p["v_p_min"] - p["ota_headroom"]


# ----------------------------------------------------------------------------------------------
# 2.3 one-transistor limiter

def r7_for_limit(i_limit, v_be=0.8):
    return validate.positive("v_be", v_be, "V") / validate.positive("i_limit", i_limit, "A")


def limit_current(r7, temperature, v_be=0.8, v_be_tc=-2e-3, t_ref=25.0):
    """I_lim(T) = V_be(T) / R7 with V_be(T) = V_be + TC (T - T_ref)."""
    return (v_be + v_be_tc * (np.asarray(temperature, dtype=float) - t_ref)) / validate.positive("r7", r7, "ohm")


def limit_tc(v_be=0.8, v_be_tc=-2e-3):
    """Relative temperature coefficient of the limit current: (dV_be/dT) / V_be, per kelvin."""
    return v_be_tc / validate.positive("v_be", v_be, "V")


# ----------------------------------------------------------------------------------------------
# 2.4 op-amp limiter (zener-bridged level shift)

def factor_a(r12, r13):
    """A = R13 / (R12 + R13): the level-shift divider's gain (eq 11)."""
    return r13 / (r12 + r13)


def factor_b(r9, r10, r11):
    """B = R11 / (R9 + R10 + R11): the reference divider (eq 12)."""
    return r11 / (r9 + r10 + r11)


def level_shift(v_d1, r12, r13, v_cs=0.0):
    """V_s - V_+ from eq 11: how far below the supply the op-amp inputs sit."""
    return v_d1 - factor_a(r12, r13) * (v_d1 - v_cs)


def v_cs_trip(v_d1, r9, r10, r11, r12, r13, offset=0.0):
    """The sense voltage at which the op-amp trips: eq 13 with the input offset referred back.

    V_+ - V_- = V_os at the trip point; with eq 11 and 12 that gives
    V_cs = V_D1 (1 - B/A) - V_os / A. Works elementwise on numpy arrays.
    """
    a = factor_a(r12, r13)
    return v_d1 * (1 - factor_b(r9, r10, r11) / a) - offset / a


def v_cs_matched(v_d1, r9, r10, r11):
    """Eq 14: V_cs = V_D1 R9 / (R9 + R10 + R11), valid only for R10 = R12 and R11 = R13 exactly."""
    return v_d1 * r9 / (r9 + r10 + r11)


def r9_for(v_cs, v_d1, r10, r11):
    """Eq 14 solved for R9."""
    validate.positive("v_cs", v_cs, "V")
    if v_cs >= v_d1:
        raise validate.InputError(f"v_cs = {v_cs:g} V must be below the zener voltage {v_d1:g} V")
    return v_cs * (r10 + r11) / (v_d1 - v_cs)


def trip_worst_case(p: dict, r9: float | None = None, include=("resistors", "zener", "offset")):
    """Exact worst case of the trip voltage over every tolerance corner (see tolerance.corners)."""
    r9 = r9_for(p["v_cs"], p["v_zener"], p["r10"], p["r11"]) if r9 is None else r9
    tr = validate.fraction("resistor_tolerance", p["resistor_tolerance"])
    nominal = dict(v_d1=p["v_zener"], r9=r9, r10=p["r10"], r11=p["r11"], r12=p["r12"], r13=p["r13"], offset=0.0)
    spread = {}
    if "resistors" in include:
        spread.update({k: tolerance.symmetric(nominal[k], tr) for k in ("r9", "r10", "r11", "r12", "r13")})
    if "zener" in include:
        spread["v_d1"] = tolerance.symmetric(p["v_zener"], validate.fraction("zener_tolerance", p["zener_tolerance"]))
    if "offset" in include:
        spread["offset"] = (-p["offset"], p["offset"])
    return tolerance.corners(v_cs_trip, nominal, spread)


def note_stack_up(p: dict) -> dict:
    """The note's tolerance arithmetic: offset, zener and resistor percentages multiplied."""
    a = factor_a(p["r12"], p["r13"])
    t_off = p["offset"] / (a * p["v_cs"])
    tols = [t_off, p["zener_tolerance"], 0.05]
    low, high = tolerance.stack_product(tols)
    return {"offset": t_off, "zener": p["zener_tolerance"], "resistors": 0.05, "high": high, "low": low,
            "sum": tolerance.stack_sum(tols)}


# ----------------------------------------------------------------------------------------------
# 3 decoupling

def c_min_for_impedance(z_max, f):
    """An ideal capacitor's |Z| = 1/(2 pi f C) stays below z_max for C >= 1/(2 pi f z_max)."""
    return 1.0 / (2 * math.pi * validate.positive("f_decoupling", f, "Hz") * validate.positive("z_max", z_max, "ohm"))


def impedance(f, c, esr=0.0, esl=0.0):
    """|Z| of a real capacitor, series R-L-C: sqrt(ESR^2 + (wL - 1/(wC))^2)."""
    w = 2 * np.pi * np.asarray(f, dtype=float)
    return np.sqrt(esr ** 2 + (w * esl - 1 / (w * c)) ** 2)


def esl_max(z_max, f):
    """The largest series inductance for which wL alone stays below z_max."""
    return z_max / (2 * math.pi * f)


# ----------------------------------------------------------------------------------------------
# 4 parts list (OCR of the note's table; the option column O1/O2/O12 is from the note)

#: (reference, value as printed, value in SI or None for TBD/type, tolerance, option, type, 12NC)
PARTS = [
    ("R1", "22 ohm", 22.0, 0.05, "", "SFR25", "2322 181 53229"),
    ("R2", "680 ohm", 680.0, 0.05, "", "SFR25", "2322 181 53681"),
    ("R3", "39 kohm", 39e3, 0.05, "", "SFR25", "2322 181 53393"),
    ("R4", "10 kohm", 10e3, 0.05, "", "SFR25", "2322 181 53103"),
    ("R5", "1 kohm", 1e3, 0.05, "O2", "SFR25", "2322 181 53102"),
    ("R6", "1 kohm", 1e3, 0.05, "O1", "SFR25", "2322 181 53102"),
    ("R7", "TBD", None, None, "O12", "PR01", "2322 193"),
    ("R8", "TBD", None, None, "O2", "PR01", "2322 193"),
    ("R9", "TBD", None, None, "O2", "SFR25", "2322 181 53"),
    ("R10", "5.6 kohm", 5.6e3, 0.01, "O2", "SFR25", "2322 181 53562"),
    ("R11", "16 kohm", 16e3, 0.01, "O2", "SFR25", "2322 181 53163"),
    ("R12", "5.6 kohm", 5.6e3, 0.01, "O2", "SFR25", "2322 181 53562"),
    ("R13", "16 kohm", 16e3, 0.01, "O2", "SFR25", "2322 181 53163"),
    ("R14", "750 ohm", 750.0, 0.05, "O2", "SFR25", "2322 181 53701"),
    ("R15", "3.9 kohm", 3.9e3, 0.05, "O2", "SFR25", "2322 181 53392"),
    ("R16", "10 kohm", 10e3, 0.05, "", "SFR25", "2322 181 53103"),
    ("R17", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("R18", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("R19", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("C1", "10 uF", 10e-6, None, "", "RSM 037", "2222 037 68109"),
    ("C2", "10 uF", 10e-6, None, "", "RSM 037", "2222 037 68109"),
    ("C3", "18 nF", 18e-9, None, "", "MKT 370", "2222 370 21183"),
    ("C4", "18 nF", 18e-9, None, "", "MKT 370", "2222 370 21183"),
    ("C5", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C6", "10 nF", 10e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C7", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C8", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C9", "10 uF", 10e-6, None, "O1", "RSM 037", "2222 037 68109"),
    ("C10", "10 uF", 10e-6, None, "O2", "RSM 037", "2222 037 68109"),
]

#: what the text says each part does, and which example checks its value
PART_ROLES = {
    "R1": ("series with C8: stability of the V_mot loop", None),
    "R3": ("V_mot divider, top (eq 10)", "an94002-r3"),
    "R4": ("V_mot divider, bottom (eq 10)", None),
    "R7": ("current sense (user's limit current)", None),
    "R9": ("sets the trip voltage (eq 14, figure 7)", None),
    "R10": ("reference divider, = R12 (eq 14)", None),
    "R11": ("reference divider, = R13 (eq 14)", "an94002-r13"),
    "R12": ("level shift, top (eq 11)", None),
    "R13": ("level shift, bottom (eq 11)", "an94002-r13"),
    "R17": ("artificial centre tap (1 k)", None), "R18": ("artificial centre tap (1 k)", None),
    "R19": ("artificial centre tap (1 k)", None),
    "C2": ("supply decoupling: |Z| < 2 ohm at 2 MHz", "an94002-c2"),
    "C3": ("CAP-CD (eq 6)", "an94002-c3"),
    "C4": ("CAP-DC = CAP-CD", "an94002-c4"),
    "C5": ("CAP-ST (eq 1; inferred from the value)", "an94002-c5"),
    "C6": ("CAP-TI (eq 9)", "an94002-c6"),
    "C8": ("with R1: stability of the V_mot loop", None),
}


def decode_12nc(code: str) -> float | None:
    """Value encoded in the last three digits of a Philips 12NC: two digits and a decade.

    For the SFR25 resistors the decade digit 9 means x 0.1 and 8 x 0.01 (ohms); for the MKT 370
    capacitors the code is in picofarads. Electrolytics (RSM 037) use another scheme: None.
    """
    digits = code.replace(" ", "")
    if len(digits) != 12 or digits.startswith("2222037"):
        return None
    mant, dec = int(digits[-3:-1]), int(digits[-1])
    mult = {9: 0.1, 8: 0.01}.get(dec, 10.0 ** dec)
    value = mant * mult
    return value * 1e-12 if digits.startswith("2222370") else value


# ----------------------------------------------------------------------------------------------
# equations

def equations() -> list:
    """Every AN94002 equation (built once; sympy solving takes about a second)."""
    return list(_equations())


@functools.lru_cache(maxsize=1)
def _equations() -> tuple:
    import sympy as sp  # imported here: the design code and the CLI do not need sympy
    from sympy.physics import units as u

    from .registry import Equation

    uF_ = u.farad / 10 ** 6
    uA_ = u.ampere / 10 ** 6


    def _collected(expr, symbols):
        """``expr`` as one fraction with its numerator collected in ``symbols`` (for display; same value)."""
        num, den = sp.fraction(sp.together(expr))
        return sp.collect(sp.expand(num), symbols, sp.factor) / den


    def _timer_law(charge, current, time, window):
        """Charge balance on a capacitor charged at a constant current: I t = C dV, solved for ``charge``."""
        return sp.solve(sp.Eq(current * time, charge * window), charge)[0]

    # physical symbols
    C, t, I, dV = sp.symbols(r"C t I \Delta{}V", positive=True)
    C_ST, t_start, I_st, V_lo, V_hi = sp.symbols(r"C_{ST} t_{start} I_{ST} V_{low} V_{high}", positive=True)
    f_osc, s_ = sp.symbols(r"f_{osc} s")
    K_t, I_m, p_, J = sp.symbols(r"K_t I p J", positive=True)
    N, n = sp.symbols(r"N n", positive=True)  # rotational speed (1/s), pole pairs
    t_cyc, t_com_, C_CD, I_max, I_min, V_win, V_noise = sp.symbols(
        r"t_{cyc} t_{com} C_{CD} I_{ch\,max} I_{ch\,min} \Delta{}V_{win} \Delta{}V_{noise}", positive=True)
    N_max, N_min = sp.symbols(r"N_{max} N_{min}", positive=True)
    C_TI, t_wd, I_wd = sp.symbols(r"C_{TI} t_{wd} I_{wd}", positive=True)
    V_in, V_mot, R3, R4 = sp.symbols(r"V_{in} V_{mot} R_3 R_4", positive=True)
    V_s, V_D1, V_cs, V_p, V_m = sp.symbols(r"V_s V_{D1} V_{cs} V_{+} V_{-}", positive=True)
    R9, R10, R11, R12, R13 = sp.symbols(r"R_9 R_{10} R_{11} R_{12} R_{13}", positive=True)
    A_, B_ = sp.symbols("A B", positive=True)
    V_be, R7, I_lim, T, TC = sp.symbols(r"V_{be} R_7 I_{lim} T TC_{V_{be}}", real=True)
    Z, f, C2 = sp.symbols(r"|Z| f C_2", positive=True)
    # printed symbols: plain numbers in the note's units
    C_uF, RPM, RPM_min = sp.symbols(r"CAP_{\mu{}F} RPM RPM_{min}", positive=True)
    RPM_ratio = sp.Symbol(r"\frac{RPM_{max}}{RPM_{min}}", positive=True)

    eqs: list = []
    V, A, F, S, OHM = u.volt, u.ampere, u.farad, u.second, u.ohm

    # eq 1: start oscillator
    t_half = sp.solve(sp.Eq(I_st * t, C_ST * (V_hi - V_lo)), t)[0]
    eqs.append(Equation(
        id="an94002-eq1", source=f"{NOTE} 2.1.1, eq (1)", title="Start oscillator period (CAP-ST)",
        lhs=t_start, lhs_unit=S, lhs_scale=S,
        printed=sp.Rational("2.15") * C_uF, scales={C_uF: C_ST / uF_},
        derived=2 * t_half, units={C_ST: F, I_st: A, V_lo: V, V_hi: V},
        values={I_st: 2 * uA_, V_lo: sp.Rational("0.05") * V, V_hi: sp.Rational("2.2") * V},
        law="charge balance I t = C dV, once up and once down the window",
        note="The constant 2.15 hides s/uF: it is 2 (2.2 V - 0.05 V) / 2 uA.",
    ))
    # eq 2: mechanical oscillator
    sol = sp.solve(sp.Eq(J * s_ ** 2 + K_t * I_m * p_, 0), s_)
    omega = sp.im(sol[1]) if sp.im(sol[1]).is_positive else sp.im(sol[0])
    eqs.append(Equation(
        id="an94002-eq2", source=f"{NOTE} 2.1.1, eq (2)", title="Rotor oscillation about a detent",
        lhs=f_osc, lhs_unit=u.hertz,
        printed=sp.sqrt(K_t * I_m * p_ / J) / (2 * sp.pi),
        derived=omega / (2 * sp.pi),
        units={K_t: u.newton * u.meter / A, I_m: A, J: u.kilogram * u.meter ** 2},
        law="J theta'' = -K_t I sin(p theta) ~ -K_t I p theta: a harmonic oscillator",
        reconstructed=("the OCR reads f = 1/(2 pi sqrt(K_t I p / J)), which has the unit of time, not "
                       "frequency, and gives 4.9 ms for the example; the note's own 5 Hz and the TDA5341 "
                       "datasheet's form (K_t I p / J)^0.5 / (2 pi) fix it as f = sqrt(K_t I p / J) / (2 pi)."),
        ocr_form=1 / (2 * sp.pi * sp.sqrt(K_t * I_m * p_ / J)),
    ))
    # eq 3 and 4
    eqs.append(Equation(
        id="an94002-eq3", source=f"{NOTE} 2.1.2, eq (3)", title="Electrical cycle time",
        lhs=t_cyc, lhs_unit=S, lhs_scale=S, printed=60 / (RPM * n), scales={RPM: N * u.minute},
        derived=1 / (n * N), units={N: 1 / S},
        law="n electrical cycles per mechanical revolution: f_el = n N",
        note="RPM is the speed in revolutions per minute; 60 is s/min.",
    ))
    eqs.append(Equation(
        id="an94002-eq4", source=f"{NOTE} 2.1.2, eq (4)", title="Time between commutations",
        lhs=t_com_, lhs_unit=S, lhs_scale=S, printed=10 / (RPM * n), scales={RPM: N * u.minute},
        derived=1 / (6 * n * N), units={N: 1 / S},
        law="six commutations per electrical cycle (three phases, two edges each)",
    ))
    # eq 5: CAP-CD from charge balance (general form)
    eqs.append(Equation(
        id="an94002-eq5", source=f"{NOTE} 2.1.2, eq (5)", title="CAP-CD from its charge per commutation",
        lhs=C_CD, lhs_unit=F, lhs_scale=F, printed=I * 10 / (RPM * n * dV),
        scales={RPM: N * u.minute, I: I / A, dV: dV / V},
        derived=_timer_law(C_CD, I, 1 / (6 * n * N), dV), units={I: A, dV: V, N: 1 / S},
        law="charge balance I t_com = C dV over one commutation interval",
        note="Evaluated with I_ch,max and the window at RPM_min it becomes the bound C >= ...",
        relation="=",
    ))
    # eq 6: the numeric bound with the constant 160
    eqs.append(Equation(
        id="an94002-eq6", source=f"{NOTE} 2.1.2, eq (6)", title="CAP-CD lower bound, 160/(RPM_min n)",
        lhs=C_CD, lhs_unit=F, lhs_scale=uF_, relation=">=",
        printed=160 / (RPM_min * n), scales={RPM_min: N_min * u.minute},
        derived=_timer_law(C_CD, I_max, 1 / (6 * n * N_min), V_win),
        units={I_max: A, V_win: V, N_min: 1 / S},
        values={I_max: 22 * uA_, V_win: sp.Rational("1.4") * V},
        law="charge balance with the largest charge current and the smallest window at RPM_min",
        note=("The exact constant is 10 x 22 uA / 1.4 V = 157.14 uF rpm; 160 rounds it up by 1.8 % "
              "(conservative). The note's 22 uA is the TDA5144's largest discharge current; the charge "
              "current is at most 11 uA (datasheet), which halves the bound."),
    ))
    # eq 7
    eqs.append(Equation(
        id="an94002-eq7", source=f"{NOTE} 2.1.2, eq (7)", title="Highest reliable speed for a given CAP-CD",
        lhs=N_max, lhs_unit=1 / S, lhs_scale=1 / u.minute,
        printed=I_min * 10 / (V_noise * n * C_CD),
        scales={I_min: I_min / A, V_noise: V_noise / V, C_CD: C_CD / F},
        derived=sp.solve(sp.Eq(I_min / (6 * n * N_max), C_CD * V_noise), N_max)[0],
        units={I_min: A, V_noise: V, C_CD: F},
        law="charge balance with the smallest current; the swing must stay above the noise floor",
        note=("Here the note's dV_capmin is the smallest swing still safe from noise, not the 1.4 V window "
              "that eq 6 also calls dV_capmin; this book names them dV_noise and dV_win. I, dV and C are "
              "plain numbers in A, V and F and the result is in rpm: the 10 hides 60 s/min / 6."),
    ))
    # eq 8
    N_min_sol = sp.solve(sp.Eq(I_max / (6 * n * N_min), C_CD * V_win), N_min)[0]
    N_max_sol = sp.solve(sp.Eq(I_min / (6 * n * N_max), C_CD * V_noise), N_max)[0]
    eqs.append(Equation(
        id="an94002-eq8", source=f"{NOTE} 2.1.2, eq (8)", title="Speed range of one capacitor",
        lhs=RPM_ratio, lhs_unit=sp.Integer(1), printed=V_win * I_min / (V_noise * I_max),
        derived=sp.simplify(N_max_sol / N_min_sol), units={I_min: A, I_max: A, V_win: V, V_noise: V},
        law="eq 7 divided by eq 5 at the bound: C, n and the 10 cancel",
        note="The note's dV_capmax (the window at RPM_min) is dV_win here, its dV_capmin is dV_noise.",
    ))
    # eq 9 (two printed forms)
    eqs.append(Equation(
        id="an94002-eq9", source=f"{NOTE} 2.1.3, eq (9), first form", title="CAP-TI for a watchdog time",
        lhs=C_TI, lhs_unit=F, printed=5 * sp.Rational(1, 10 ** 6) * t_wd / sp.Rational("1.9"),
        printed_tex=r"\frac{5 \times 10^{-6} \, t_{wd}}{1.9}",
        scales={t_wd: t_wd / S}, lhs_scale=F,
        derived=_timer_law(C_TI, I_wd, t_wd, V_hi - V_lo), units={I_wd: A, t_wd: S, V_hi: V, V_lo: V},
        values={I_wd: 5 * uA_, V_hi: sp.Rational("2.2") * V, V_lo: sp.Rational("0.3") * V},
        law="charge balance at 5 uA from 0.3 V to 2.2 V",
    ))
    eqs.append(Equation(
        id="an94002-eq9b", source=f"{NOTE} 2.1.3, eq (9), second form", title="CAP-TI = 2.63 t_wd",
        lhs=C_TI, lhs_unit=F, printed=sp.Rational("2.63") * t_wd, lhs_scale=uF_,
        scales={t_wd: t_wd / S},
        derived=_timer_law(C_TI, I_wd, t_wd, V_hi - V_lo), units={I_wd: A, t_wd: S, V_hi: V, V_lo: V},
        values={I_wd: 5 * uA_, V_hi: sp.Rational("2.2") * V, V_lo: sp.Rational("0.3") * V},
        law="charge balance at 5 uA from 0.3 V to 2.2 V",
        note="2.63 is 5/1.9 = 2.6316 rounded; units hidden: C in uF for t_wd in s (or nF for ms).",
    ))
    # eq 10
    V_node = sp.Symbol("V_node")
    node = sp.solve(sp.Eq((V_mot - V_node) / R3, V_node / R4), V_node)[0]
    eqs.append(Equation(
        id="an94002-eq10", source=f"{NOTE} 2.2, eq (10)", title="Speed-control divider",
        lhs=V_in, lhs_unit=V, printed=V_mot * R4 / (R3 + R4), derived=node,
        units={V_mot: V, R3: OHM, R4: OHM},
        law="KCL at AMPIN+ (no input current), and the OTA loop holds AMPIN+ = AMPIN- = V_in",
    ))
    # eq 11 and 12: KCL at the op-amp inputs
    vp = sp.solve(sp.Eq((V_s - V_cs - V_p) / R12, (V_p - (V_s - V_D1)) / R13), V_p)[0]
    vm = sp.solve(sp.Eq((V_s - V_m) / (R9 + R10), (V_m - (V_s - V_D1)) / R11), V_m)[0]
    eqs.append(Equation(
        id="an94002-eq11", source=f"{NOTE} 2.4, eq (11)", title="Level-shifted sense voltage at V+",
        lhs=V_p, lhs_unit=V, printed=V_s - V_D1 + (V_D1 - V_cs) * R13 / (R12 + R13), derived=vp,
        printed_tex=r"V_s - V_{D1} + (V_{D1} - V_{cs}) \frac{R_{13}}{R_{12} + R_{13}}",
        units={V_s: V, V_D1: V, V_cs: V, R12: OHM, R13: OHM},
        law="KCL at V+: the current through R12 (from V_s - V_cs) equals that through R13 (to V_s - V_D1)",
    ))
    eqs.append(Equation(
        id="an94002-eq11-num", source=f"{NOTE} 2.4, eq (11) with R12 = 5.6 k, R13 = 16 k, V_D1 = 7.79 V",
        title="Eq 11 with the board's values", lhs=V_p, lhs_unit=V, lhs_scale=V, scales={V_s: V_s / V, V_cs: V_cs / V},
        printed=V_s - sp.Rational("2.02") - sp.Rational("0.741") * V_cs, derived=vp,
        printed_tex=r"V_s - 2.02 - 0.741 \, V_{cs}",
        units={V_s: V, V_cs: V, V_D1: V, R12: OHM, R13: OHM},
        values={V_D1: sp.Rational("7.79") * V, R12: sp.Rational(5600) * OHM, R13: sp.Rational(16000) * OHM},
        law="eq 11 evaluated", rounded_constants=True,
        note="2.02 and 0.741 are 2.0196 V and 0.74074 rounded.",
    ))
    eqs.append(Equation(
        id="an94002-eq12", source=f"{NOTE} 2.4, eq (12)", title="Reference at V-",
        lhs=V_m, lhs_unit=V, printed=(V_s - V_D1) + V_D1 * R11 / (R9 + R10 + R11), derived=vm,
        printed_tex=r"(V_s - V_{D1}) + V_{D1} \frac{R_{11}}{R_9 + R_{10} + R_{11}}",
        units={V_s: V, V_D1: V, R9: OHM, R10: OHM, R11: OHM},
        law="KCL at V-: R9 + R10 from V_s, R11 to V_s - V_D1",
    ))
    vcs = sp.solve(sp.Eq(vp, vm), V_cs)[0]
    eqs.append(Equation(
        id="an94002-eq13", source=f"{NOTE} 2.4, eq (13)", title="Sense voltage at the trip point",
        lhs=V_cs, lhs_unit=V, printed=(V_D1 - V_D1 * B_ / A_).subs({A_: R13 / (R12 + R13), B_: R11 / (R9 + R10 + R11)}),
        derived=vcs, units={V_D1: V, R9: OHM, R10: OHM, R11: OHM, R12: OHM, R13: OHM},
        printed_tex=(r"V_{D1} - V_{D1} \frac{B}{A}, \quad A = \frac{R_{13}}{R_{12} + R_{13}}, \;"
                     r" B = \frac{R_{11}}{R_9 + R_{10} + R_{11}}"),
        law="op-amp virtual short V+ = V- with eq 11 and eq 12, solved for V_cs (offset zero)",
        note="The printed form is V_D1 - V_D1 B / A with A = R13/(R12+R13), B = R11/(R9+R10+R11).",
    ))
    eqs.append(Equation(
        id="an94002-eq14", source=f"{NOTE} 2.4, eq (14)", title="Sense voltage with matched dividers",
        lhs=V_cs, lhs_unit=V, printed=V_D1 * R9 / (R9 + R10 + R11),
        derived=vcs.subs({R12: R10, R13: R11}), units={V_D1: V, R9: OHM, R10: OHM, R11: OHM},
        law="eq 13 with R12 = R10 and R13 = R11 exactly",
        note="Holds only for exact matching; real 1 % parts break it badly (chapter 2.4).",
    ))
    # level shift
    eqs.append(Equation(
        id="an94002-level-shift", source=f"{NOTE} 2.4, text after eq (11)", title="Level shift below the supply",
        lhs=sp.Symbol(r"V_s - V_{+}"), lhs_unit=V, printed=V_D1 * R12 / (R12 + R13),
        derived=sp.simplify((V_s - vp).subs(V_cs, 0)), units={V_D1: V, R12: OHM, R13: OHM, V_s: V},
        law="eq 11 at V_cs = 0",
        note="The note sizes R12/R13 for 2 V at the lowest zener voltage 7.79 V (LM358 common-mode range).",
    ))
    # trip point with offset (this book's form, used for the tolerance analysis)
    V_os = sp.Symbol("V_{os}", real=True)
    vcs_os = sp.solve(sp.Eq(vp - vm, V_os), V_cs)[0]
    eqs.append(Equation(
        id="an94002-trip-offset", source=f"{NOTE} 2.4, text (offset referred to V_cs)",
        title="Trip point with the op-amp offset", lhs=V_cs, lhs_unit=V,
        printed=(V_D1 * (1 - B_ / A_) - V_os / A_).subs({A_: R13 / (R12 + R13), B_: R11 / (R9 + R10 + R11)}),
        derived=_collected(vcs_os, (V_D1, V_os)), units={V_D1: V, V_os: V, R9: OHM, R10: OHM, R11: OHM, R12: OHM, R13: OHM},
        printed_tex=r"V_{D1} \left(1 - \frac{B}{A}\right) - \frac{V_{os}}{A}",
        law="the op-amp switches where V+ - V- = V_os",
        note="The note states the effect in words (offset divided by A); the printed form here is that statement.",
    ))
    # tolerance stack-up
    t1, t2, t3 = sp.symbols("t_1 t_2 t_3", positive=True)
    x1, x2, x3 = sp.symbols("x_1 x_2 x_3", positive=True)
    prod = x1 * x2 * x3
    high = prod.subs({x1: 1 + t1, x2: 1 + t2, x3: 1 + t3}) - 1  # each factor at its high end
    eqs.append(Equation(
        id="an94002-stack-up", source=f"{NOTE} 2.4, tolerance table", title="Total tolerance (upper end)",
        lhs=sp.Symbol(r"t_{total}"), lhs_unit=sp.Integer(1),
        printed=(1 + t1) * (1 + t2) * (1 + t3) - 1, derived=high, units={},
        law="worst case of a product of independent factors x_i in [1 - t_i, 1 + t_i]",
        note=("Right for the upper end only: the lower end is (1-t1)(1-t2)(1-t3) - 1 = -20.6 % for the note's "
              "numbers, not -23 %. The premise (independent factors entering as a product) fails for the "
              "resistors, which enter through a difference of two ratios (chapter 2.4)."),
    ))
    # one-transistor limiter
    eqs.append(Equation(
        id="an94002-vbe-tc", source=f"{NOTE} 2.3, text", title="Relative drift of the one-transistor limit",
        lhs=sp.Symbol(r"\frac{1}{I_{lim}}\frac{dI_{lim}}{dT}"), lhs_unit=1 / u.kelvin,
        printed=TC / V_be, derived=sp.simplify(sp.diff((V_be + TC * T) / R7, T) / ((V_be + TC * T) / R7)).subs(T, 0),
        units={TC: V / u.kelvin, V_be: V, R7: OHM},
        law="I_lim = V_be(T) / R7 (the transistor turns on at V_be), differentiated at the reference temperature",
    ))
    # decoupling
    w = sp.Symbol("omega", positive=True)
    eqs.append(Equation(
        id="an94002-decoupling", source=f"{NOTE} 3, text", title="Capacitance for |Z| below 2 ohm at 2 MHz",
        lhs=C2, lhs_unit=F, relation=">=", printed=1 / (2 * sp.pi * f * Z),
        derived=sp.solve(sp.Eq(sp.Abs(1 / (sp.I * w * C2)), Z), C2)[0].subs(w, 2 * sp.pi * f),
        units={f: u.hertz, Z: OHM},
        law="|Z| = |1/(j omega C)| of an ideal capacitor, set equal to the limit",
        note="The note states only the requirement; this is the ideal-capacitor bound (40 nF). ESR and ESL are what a real 10 uF part must keep below 2 ohm.",
    ))
    for e in eqs:
        e.chapter = _EQ_CHAPTER[e.id]
    return tuple(eqs)


_EQ_CHAPTER = {
    "an94002-eq1": "start", "an94002-eq2": "start",
    "an94002-eq3": "commutation", "an94002-eq4": "commutation", "an94002-eq5": "commutation",
    "an94002-eq6": "commutation", "an94002-eq7": "commutation", "an94002-eq8": "commutation",
    "an94002-eq9": "watchdog", "an94002-eq9b": "watchdog", "an94002-eq10": "speed",
    "an94002-vbe-tc": "one_transistor",
    "an94002-eq11": "opamp", "an94002-eq11-num": "opamp", "an94002-eq12": "opamp", "an94002-eq13": "opamp",
    "an94002-eq14": "opamp", "an94002-level-shift": "opamp", "an94002-trip-offset": "opamp",
    "an94002-stack-up": "opamp", "an94002-decoupling": "decoupling",
}


# ----------------------------------------------------------------------------------------------
# numeric examples

def _r9(p):
    return r9_for(p["v_cs"], p["v_zener"], p["r10"], p["r11"])


def _a(p):
    return factor_a(p["r12"], p["r13"])


def _vd1_min(p):
    return p["v_zener"] * (1 - p["zener_tolerance"])


def _capcd_bound(p):
    return cap_cd_min(p["rpm_min"], p["pole_pairs"], p["i_charge_max"], p["v_cd_high_min"] - p["v_cd_low_max"])


def _resistor_only(p):
    wc = trip_worst_case(p, include=("resistors",))
    return max(abs(wc.rel_low), abs(wc.rel_high))


def _total_exact(p):
    wc = trip_worst_case(p)
    return max(abs(wc.rel_low), abs(wc.rel_high))


def examples_list() -> list[Example]:
    S = "start"
    CD = "commutation"
    WD = "watchdog"
    SC = "speed"
    T1 = "one_transistor"
    OP = "opamp"
    DC = "decoupling"
    PL = "parts"
    ex = [
        # ---- 2.1.1
        Example("an94002-fosc", f"{NOTE} 2.1.1", "rotor oscillation frequency f_osc", Printed("5", "Hz"),
                lambda p: oscillation_frequency(p["torque_constant"], p["start_current"], p["pole_pairs"], p["inertia"]),
                "sqrt(25e-3 x 0.5 x 6 / 72e-6) / 2 pi = 5.14 Hz, printed to one digit",
                ("torque_constant", "start_current", "pole_pairs", "inertia"), chapter=S),
        Example("an94002-tstart", f"{NOTE} 2.1.1", "start period for a 2 Hz start frequency", Printed("500", "ms"),
                lambda p: 1 / p["f_start"], "1 / 2 Hz", ("f_start",), chapter=S),
        Example("an94002-capst", f"{NOTE} 2.1.1", "CAP-ST from eq 1", Printed("0.23", "uF"),
                lambda p: cap_st_for(1 / p["f_start"], p["i_cap_st"], p["v_st_low"], p["v_st_high"]),
                "0.5 s / 2.15 s/uF = 0.2326 uF", ("f_start", "i_cap_st", "v_st_low", "v_st_high"), chapter=S),
        Example("an94002-capst-choice", f"{NOTE} 2.1.1", "CAP-ST chosen (nearest E12)", Printed("0.22", "uF"),
                lambda p: series.nearest(p["cap_st_series"], cap_st_for(1 / p["f_start"], p["i_cap_st"], p["v_st_low"], p["v_st_high"])),
                "0.22 uF is the E12 value nearest 0.2326 uF (start frequency 2.11 Hz)",
                ("f_start", "i_cap_st", "v_st_low", "v_st_high", "cap_st_series"), chapter=S),
        Example("an94002-capst-datasheet", f"{NOTE} 2.1.1 vs TDA5144 datasheet", "CAP-ST for 500 ms, datasheet levels",
                Printed("0.23", "uF"), lambda p: cap_st_for(1 / p["f_start"], p["i_cap_st"], *DATASHEET["cap_st_levels"][0]),
                "the TDA5144 datasheet switches CAP-ST at 0.20 V and 2.20 V and gets 0.25 uF; the note's 0.05 V "
                "level (and 2.15 factor) comes from the TDA5141/TDA5145 datasheets",
                ("f_start", "i_cap_st"), basis="TDA5144 datasheet", consequence="with a TDA5144, 0.22 uF gives a 440 ms period, not 473 ms: size CAP-ST with the datasheet of the IC on the board",
                chapter=S),
        # ---- 2.1.2
        Example("an94002-window", f"{NOTE} 2.1.2", "smallest CAP-CD window dV_capmin = 2.3 - 0.9", Printed("1.4", "V"),
                lambda p: p["v_cd_high_min"] - p["v_cd_low_max"], "2.3 V - 0.9 V; agrees with the datasheet's "
                "minimum upper and maximum lower level", ("v_cd_high_min", "v_cd_low_max"), chapter=CD),
        Example("an94002-eq6-constant", f"{NOTE} 2.1.2, eq (6)", "constant of the CAP-CD bound (C in uF, RPM in rpm)",
                Printed("160", "uF*rpm"), lambda p: 10 * p["i_charge_max"] / (p["v_cd_high_min"] - p["v_cd_low_max"]),
                "10 x 22 uA / 1.4 V = 157.1 uF rpm, rounded up to two figures (conservative by 1.8 %)",
                ("i_charge_max", "v_cd_high_min", "v_cd_low_max"), chapter=CD),
        Example("an94002-capcd-bound", f"{NOTE} 2.1.2", "CAP-CD lower bound for 1800 rpm, 6 pole pairs",
                Printed("0.0148", "uF"), _capcd_bound,
                "160 / (1800 x 6) = 0.01481 uF follows from the rounded constant; from 22 uA and 1.4 V directly the bound is 0.01455 uF",
                ("rpm_min", "pole_pairs", "i_charge_max", "v_cd_high_min", "v_cd_low_max"),
                via_rounded=lambda p: 160e-6 / (p["rpm_min"] * p["pole_pairs"]), chapter=CD),
        Example("an94002-c3", f"{NOTE} 2.1.2", "C3 = CAP-CD chosen", Printed("18", "nF"),
                lambda p: choose_cap_cd(p["rpm_min"], p["pole_pairs"], p["i_charge_max"],
                                        p["v_cd_high_min"] - p["v_cd_low_max"], p["cap_tolerance"], p["cap_series"])[0],
                "smallest E12 value that meets 14.55 nF at -5 %: 15 nF x 0.95 = 14.25 nF falls short, 18 nF does not",
                ("rpm_min", "pole_pairs", "i_charge_max", "v_cd_high_min", "v_cd_low_max", "cap_tolerance", "cap_series"),
                chapter=CD),
        Example("an94002-c4", f"{NOTE} 2.1.2", "C4 = CAP-DC (same timer, same value)", Printed("0.018", "uF"),
                lambda p: choose_cap_cd(p["rpm_min"], p["pole_pairs"], p["i_charge_max"],
                                        p["v_cd_high_min"] - p["v_cd_low_max"], p["cap_tolerance"], p["cap_series"])[0],
                "CAP-DC runs the slave timer with the same currents and window, so C4 = C3",
                ("rpm_min", "pole_pairs", "i_charge_max", "v_cd_high_min", "v_cd_low_max", "cap_tolerance", "cap_series"),
                chapter=CD),
        Example("an94002-ich-max", f"{NOTE} 2.1.2 vs TDA5144 datasheet", "largest CAP-CD charge current I_chmax",
                Printed("22", "uA"), lambda p: DATASHEET["cap_cd_charge"][0][2],
                "22 uA is the datasheet's largest discharge (sink) current; the charge current is at most 11 uA "
                "(sink/source ratio about 2), so the note's capacitor is twice the size the bound needs",
                (), basis="TDA5144 datasheet", consequence="CAP-CD comes out twice the size the bound needs, halving the top speed at which commutation stays reliable",
                chapter=CD),
        # ---- 2.1.3
        Example("an94002-eq9-constant", f"{NOTE} 2.1.3, eq (9)", "CAP-TI per second of watchdog time",
                Printed("2.63", "uF"), lambda p: cap_ti_for(1.0, p["i_wd"], p["v_ti_low"], p["v_ti_high"]),
                "5 uA / 1.9 V = 2.6316 uF per s", ("i_wd", "v_ti_low", "v_ti_high"), chapter=WD),
        Example("an94002-eq9-window", f"{NOTE} 2.1.3, eq (9)", "CAP-TI watchdog window 2.2 V - 0.3 V", Printed("1.9", "V"),
                lambda p: p["v_ti_high"] - p["v_ti_low"], "2.2 V - 0.3 V", ("v_ti_low", "v_ti_high"), chapter=WD),
        # ---- 2.2
        Example("an94002-vmot-max", f"{NOTE} 2.2", "highest controllable V_mot", Printed("9.8", "V"),
                lambda p: v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"]),
                "0.9 x 12 V - 1 V", ("v_supply", "supply_tolerance", "v_drop_min"), chapter=SC),
        Example("an94002-vin", f"{NOTE} 2.2, eq (10)", "V_in for V_mot = 9.8 V", Printed("2", "V"),
                lambda p: v_in_for(v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"]), p["r3"], p["r4"]),
                "9.8 V x 10 k / 49 k = 2.000 V", ("v_supply", "supply_tolerance", "v_drop_min", "r3", "r4"), chapter=SC),
        Example("an94002-vmot-min", f"{NOTE} 2.2 vs TDA5144 datasheet", "lowest running V_mot", Printed("1.7", "V"),
                lambda p: DATASHEET["v_mot_range"][0][0], "the datasheet's V_MOT range starts at 1.7 V",
                (), basis="TDA5144 datasheet", chapter=SC),
        # ---- 2.3
        Example("an94002-vbe-tc", f"{NOTE} 2.3", "temperature coefficient of the one-transistor limit",
                Printed("-0.25", "%/K"), lambda p: limit_tc(p["v_be"], p["v_be_tc"]),
                "-2 mV/K / 800 mV", ("v_be", "v_be_tc"), chapter=T1),
        Example("an94002-vbe", f"{NOTE} 2.3 vs BC557 datasheet", "V_be at which T2 limits", Printed("0.8", "V"),
                lambda p: DATASHEET["bc557_vbe"][0][2],
                "BC557 V_BE(on) is 0.55 to 0.70 V at 2 mA; 0.8 V is above the maximum, so the real limit is "
                "lower than R7 = 0.8 V / I_lim predicts (by about 22 % at the typical 0.62 V)",
                (), basis="BC557 datasheet", consequence="R7 sized with 0.8 V limits about 20 % below the target with a typical BC557; check the limit on the board",
                chapter=T1),
        # ---- 2.4
        Example("an94002-offset-generic", f"{NOTE} 2.4", "tolerance from a 10 mV offset at V_cs = 100 mV",
                Printed("10", "%"), lambda p: p["offset_generic"] / p["v_cs"], "10 mV / 100 mV, before any level shift",
                ("offset_generic", "v_cs"), chapter=OP),
        Example("an94002-vd1-min", f"{NOTE} 2.4", "lowest zener voltage 8.2 V - 5 %", Printed("7.79", "V"),
                _vd1_min, "0.95 x 8.2 V", ("v_zener", "zener_tolerance"), chapter=OP),
        Example("an94002-factor-a", f"{NOTE} 2.4", "level-shift factor A = R13/(R12+R13)", Printed("0.741", "1"),
                _a, "16 k / 21.6 k = 0.74074", ("r12", "r13"), chapter=OP),
        Example("an94002-a-vd1", f"{NOTE} 2.4", "A x V_D1 in eq 11", Printed("5.77", "V"),
                lambda p: _a(p) * _vd1_min(p), "0.74074 x 7.79 V = 5.770 V", ("r12", "r13", "v_zener", "zener_tolerance"),
                chapter=OP),
        Example("an94002-level-shift", f"{NOTE} 2.4", "level shift at V_D1 = 7.79 V, V_cs = 0", Printed("2.02", "V"),
                lambda p: level_shift(_vd1_min(p), p["r12"], p["r13"]), "7.79 V x 5.6 k / 21.6 k = 2.0196 V",
                ("r12", "r13", "v_zener", "zener_tolerance"), chapter=OP),
        Example("an94002-vcs-at-opamp", f"{NOTE} 2.4", "sense signal at the op-amp input for V_cs = 100 mV",
                Printed("74.1", "mV"), lambda p: _a(p) * p["v_cs"], "0.74074 x 100 mV = 74.07 mV",
                ("r12", "r13", "v_cs"), chapter=OP),
        Example("an94002-window-high", f"{NOTE} 2.4", "op-amp input at trip, offset -9 mV side (upper)",
                Printed("90.5", "mV"), lambda p: _a(p) * p["v_cs"] + p["offset"],
                "74.07 + 9 = 83.07 mV; 90.5 mV is AN93008's 81.5 + 9 (A = 0.815) copied unchanged",
                ("r12", "r13", "v_cs", "offset"), consequence="none for the tolerance (the +-12 % is right), but a reader checking the window against 74.1 mV is misled",
                chapter=OP),
        Example("an94002-window-low", f"{NOTE} 2.4", "op-amp input at trip, offset +9 mV side (lower)",
                Printed("72.5", "mV"), lambda p: _a(p) * p["v_cs"] - p["offset"],
                "74.07 - 9 = 65.07 mV; 72.5 mV is AN93008's 81.5 - 9 (A = 0.815) copied unchanged",
                ("r12", "r13", "v_cs", "offset"), consequence="as for the upper end: the printed window belongs to AN93008's supply-referenced circuit",
                chapter=OP),
        Example("an94002-offset-tol", f"{NOTE} 2.4", "offset-related tolerance of the limit", Printed("12", "%"),
                lambda p: p["offset"] / (_a(p) * p["v_cs"]), "9 mV / 74.07 mV = 12.15 % (consistent with A = 0.741, "
                "not with the printed 90.5/72.5 mV window)", ("r12", "r13", "v_cs", "offset"), chapter=OP),
        Example("an94002-zener-tol", f"{NOTE} 2.4, eq (13)", "zener-related tolerance of the limit", Printed("5", "%"),
                lambda p: p["zener_tolerance"], "V_cs is proportional to V_D1 (eq 13)", ("zener_tolerance",), chapter=OP),
        Example("an94002-zener-drift", f"{NOTE} 2.4", "zener drift over 25 C +- 25 C", Printed("150", "mV"),
                lambda p: p["zener_tc"] * p["temp_span"], "6.2 mV/K x 25 K = 155 mV, printed to two figures",
                ("zener_tc", "temp_span"), chapter=OP),
        Example("an94002-zener-drift-pct", f"{NOTE} 2.4", "zener drift as a tolerance", Printed("2", "%"),
                lambda p: p["zener_tc"] * p["temp_span"] / _vd1_min(p), "155 mV / 7.79 V = 1.99 %",
                ("zener_tc", "temp_span", "v_zener", "zener_tolerance"), chapter=OP),
        Example("an94002-zener-tc", f"{NOTE} 2.4 vs BZX79 datasheet", "largest zener temperature coefficient",
                Printed("6.2", "mV/K"), lambda p: DATASHEET["bzx79_tc"][0][1] * p["v_zener"],
                "BZX79 datasheet: up to +0.08 %/K, 6.56 mV/K at 8.2 V; the drift becomes +-164 mV, +-2.1 %",
                ("v_zener",), basis="BZX79 datasheet", consequence="the drift term grows from +-2.0 % to +-2.1 %: negligible",
                chapter=OP),
        Example("an94002-resistor-tol", f"{NOTE} 2.4", "resistor-related tolerance of the limit (1 % R9..R13)",
                Printed("5", "%"), _resistor_only,
                "eq 14's matching (R10 = R12, R11 = R13) carried into the tolerance; with each 1 % resistor "
                "varying on its own V_cs = V_D1 (1 - B/A) moves -86 %/+85 % (a 100 mV difference of two 8 V dividers)",
                ("r10", "r11", "r12", "r13", "v_cs", "v_zener", "resistor_tolerance"), consequence="the limiter can trip anywhere from almost no current to twice the design value on a real board; design it with the exact worst case (chapter 'Choosing R7 and R9')",
                chapter=OP),
        Example("an94002-total-tol", f"{NOTE} 2.4", "total initial tolerance, note's method 1.12 x 1.05 x 1.05",
                Printed("23", "%"), lambda p: 1.12 * 1.05 * 1.05 - 1,
                "1.12 x 1.05 x 1.05 = 1.2348; the method's lower end is 0.88 x 0.95 x 0.95 = 0.794 (-20.6 %)",
                (), chapter=OP),
        Example("an94002-total-exact", f"{NOTE} 2.4", "total initial tolerance, exact worst case of eq 13",
                Printed("23", "%"), _total_exact,
                "every corner of 1 % R9..R13, 5 % zener and +-9 mV offset: the trip voltage spans 1.2 to 206 mV "
                "(-99 %/+106 %), not +-23 %",
                ("r10", "r11", "r12", "r13", "v_cs", "v_zener", "zener_tolerance", "offset", "resistor_tolerance"),
                consequence="a board built as the note says is not guaranteed to limit at all, or may limit far too early; see the design chapter for a limiter that is",
                chapter=OP),
        # ---- 3
        Example("an94002-c2", f"{NOTE} 3", "C2 capacitance for |Z| < 2 ohm at 2 MHz (ideal capacitor)",
                Printed("10", "uF"), lambda p: c_min_for_impedance(p["z_max"], p["f_decoupling"]),
                "10 uF is far above the 40 nF the reactance needs: the real limits are ESR < 2 ohm and ESL < 159 nH",
                ("z_max", "f_decoupling"), relation=">=", chapter=DC),
        # ---- parts list
        Example("an94002-r3", f"{NOTE} 4, parts list R3", "R3 for V_in = 2 V at V_mot = 9.8 V (R4 = 10 k)",
                Printed("39", "kohm"),
                lambda p: r3_for(v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"]), 2.0, p["r4"]),
                "10 k x (9.8/2 - 1) = 39.0 k, an E12 value", ("v_supply", "supply_tolerance", "v_drop_min", "r4"),
                chapter=PL),
        Example("an94002-r13", f"{NOTE} 4, parts list R11/R13", "largest E24 R13 keeping a 2 V shift at 7.79 V (R12 = 5.6 k)",
                Printed("16", "kohm"),
                lambda p: series.at_most("E24", p["r12"] * (1 - p["level_shift_min"] / _vd1_min(p)) / (p["level_shift_min"] / _vd1_min(p))),
                "R13 <= 5.6 k x (7.79 - 2)/2 = 16.2 k; 16 k is the largest E24 value below", 
                ("r12", "v_zener", "zener_tolerance", "level_shift_min"), chapter=PL),
        Example("an94002-c5", f"{NOTE} 4, parts list C5", "C5 = CAP-ST", Printed("220", "nF"),
                lambda p: series.nearest(p["cap_st_series"], cap_st_for(1 / p["f_start"], p["i_cap_st"], p["v_st_low"], p["v_st_high"])),
                "the 0.22 uF of 2.1.1 (C5 as CAP-ST is inferred from the value: the schematic did not survive OCR)",
                ("f_start", "i_cap_st", "v_st_low", "v_st_high", "cap_st_series"), chapter=PL),
        Example("an94002-c6", f"{NOTE} 4, parts list C6", "C6 = CAP-TI (at least 2000 pF)", Printed("10", "nF"),
                lambda p: p["cap_ti_min"], "10 nF meets the 2000 pF minimum; the watchdog time is 3.8 ms",
                ("cap_ti_min",), relation=">=", chapter=PL),
    ]
    return ex


def examples(p: dict | None = None, chapter: str | None = None) -> list[dict]:
    """Every AN94002 example evaluated with ``p`` (default: the note's values)."""
    return evaluate_all(examples_list(), p, DEFAULTS, chapter)


#: misprints and inconsistencies of AN94002 that are not numbers
TEXT_ERRATA = [
    TextErratum("an94002-t-dvcapmin", f"{NOTE} 2.1.2, eq (6) and (7)",
                "one name, dV_capmin, for two quantities: the 1.4 V window in eq 6 and the noise floor in eq 7",
                "eq 6 sets dV_capmin = 2.3 - 0.9 = 1.4 V; eq 7 calls the smallest swing safe from noise dV_capmin too, "
                "and eq 8 then renames the window dV_capmax",
                "read eq 7 and 8 with dV_win (window) and dV_noise (floor); using 1.4 V in eq 7 would give a top speed "
                "14 times too low"),
    TextErratum("an94002-t-160", f"{NOTE} 2.1.2", "'CAP-CD >= 160 / 1800 x 6' read left to right is 0.533 uF",
                "the printed result 0.0148 uF shows the intended 160 / (1800 x 6)", "none once read as intended"),
    TextErratum("an94002-t-1v", f"{NOTE} 2 and 2.3", "the one-transistor limiter needs 'about 1 V' (section 2) or 'about 0.8 V' (2.3)",
                "both are rough figures for the same V_be; the BC557 datasheet gives 0.55 to 0.70 V at 2 mA",
                "size R7 from the measured limit, not from either figure"),
    TextErratum("an94002-t-12nc", f"{NOTE} 4, parts list", "three 12NC codes decode to other values than printed",
                "R1 ...53229 is 2.2 ohm (printed 22 ohm); R14 ...53701 is 700 ohm, not an E-series value (printed 750 ohm, "
                "code ...751); C6 ...17224 is 220 nF, the code of C5/C7/C8 (printed 10 nF)",
                "order by value and check the code: the wrong C6 would make the watchdog 22 times longer"),
    TextErratum("an94002-t-cadcd", f"{NOTE} 2.1.2", "'CAD-CD' and 'CAD-DC' for CAP-CD and CAP-DC", "typographical", "none"),
]
