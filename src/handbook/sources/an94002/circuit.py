"""AN94002 circuit functions: start oscillator, commutation delay, watchdog, speed control, limiters,
decoupling. Every function takes and returns SI values (rotational speed in rpm, as the note states it)."""
from __future__ import annotations

import math

import numpy as np

from ...core import series, tolerance, validate

# ----------------------------------------------------------------------------------------------
# 2.1.1 start oscillator

def oscillation_frequency(torque_constant, current, pole_pairs, inertia):
    """Eq 2: rotor oscillation about a detent, f = sqrt(K_t I p / J) / (2 pi).

    Parameters
    ----------
    torque_constant : float or numpy.ndarray
        Motor torque constant K_t, N m/A.
    current : float or numpy.ndarray
        Start current I through the windings, A.
    pole_pairs : int
        Magnetic pole pairs p.
    inertia : float or numpy.ndarray
        Rotor and load inertia J, kg m^2.

    Returns
    -------
    float or numpy.ndarray
        The rotor's oscillation frequency about a detent, Hz (elementwise for arrays, which broadcast).
    """
    validate.positive("torque_constant", torque_constant, "N m/A")
    validate.positive("start_current", current, "A")
    validate.pole_pairs("pole_pairs", pole_pairs)
    validate.positive("inertia", inertia, "kg m^2")
    x = torque_constant * current * pole_pairs / inertia
    return (np.sqrt(x) if isinstance(x, np.ndarray) else math.sqrt(x)) / (2 * math.pi)


def start_period(cap, i_cap=2e-6, v_low=0.05, v_high=2.2):
    """Eq 1 from charge balance: charge and discharge at I over the window, t = 2 C dV / I.

    Parameters
    ----------
    cap : float or numpy.ndarray
        CAP-ST, F.
    i_cap : float or numpy.ndarray
        Charge (= discharge) current of CAP-ST, A.
    v_low, v_high : float
        The lower and upper switching levels of CAP-ST, V.

    Returns
    -------
    float or numpy.ndarray
        The start oscillator's period, s (elementwise for arrays).
    """
    validate.ordered("v_st_low", v_low, "v_st_high", v_high)
    return 2 * cap * (v_high - v_low) / validate.positive("i_cap_st", i_cap, "A")


def cap_st_for(t_start, i_cap=2e-6, v_low=0.05, v_high=2.2):
    """Eq 1 solved for the capacitor: CAP-ST = t I / (2 dV) for a start period ``t_start``.

    Parameters
    ----------
    t_start : float
        The start oscillator's period wanted, s.
    i_cap : float
        Charge (= discharge) current of CAP-ST, A.
    v_low, v_high : float
        The lower and upper switching levels of CAP-ST, V.

    Returns
    -------
    float
        CAP-ST, F.
    """
    validate.ordered("v_st_low", v_low, "v_st_high", v_high)
    return validate.positive("t_start", t_start, "s") * i_cap / (2 * (v_high - v_low))


# ----------------------------------------------------------------------------------------------
# 2.1.2 adaptive commutation delay

def t_cycle(rpm, pole_pairs):
    """Eq 3: one electrical cycle, 60 / (RPM n) seconds.

    Parameters
    ----------
    rpm : float
        Rotational speed, rpm.
    pole_pairs : int
        Magnetic pole pairs n.

    Returns
    -------
    float
        The electrical cycle time, s.
    """
    return 60.0 / (validate.positive("rpm", rpm, "rpm") * validate.pole_pairs("pole_pairs", pole_pairs))


def t_com(rpm, pole_pairs):
    """Eq 4: six commutations per electrical cycle, 10 / (RPM n) seconds.

    Parameters
    ----------
    rpm : float
        Rotational speed, rpm.
    pole_pairs : int
        Magnetic pole pairs n.

    Returns
    -------
    float
        The time between commutations, s.
    """
    return t_cycle(rpm, pole_pairs) / 6


def excursion(cap, rpm, pole_pairs, i_charge):
    """Voltage swing on CAP-CD: charged for one commutation interval, dV = I t_com / C.

    Parameters
    ----------
    cap : float
        CAP-CD, F.
    rpm : float
        Rotational speed, rpm.
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge : float
        CAP-CD charge current, A.

    Returns
    -------
    float
        The voltage swing on CAP-CD over one commutation interval, V.
    """
    return i_charge * t_com(rpm, pole_pairs) / validate.positive("cap_cd", cap, "F")


def cap_cd_min(rpm_min, pole_pairs, i_charge_max, window):
    """Eq 5/6: the smallest CAP-CD whose swing at rpm_min fits the window with the largest current.

    Parameters
    ----------
    rpm_min : float
        Lowest speed that must commutate correctly, rpm.
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge_max : float
        Largest CAP-CD charge current, A.
    window : float
        Smallest CAP-CD voltage window (upper level minimum less lower level maximum), V.

    Returns
    -------
    float
        The smallest CAP-CD, F.
    """
    validate.positive("i_charge_max", i_charge_max, "A")
    return i_charge_max * t_com(rpm_min, pole_pairs) / validate.positive("window", window, "V")


def rpm_min_for(cap, pole_pairs, i_charge_max, window):
    """The lowest speed at which a capacitor's swing still fits the window (eq 5 solved for RPM).

    Parameters
    ----------
    cap : float
        CAP-CD, F.
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge_max : float
        Largest CAP-CD charge current, A.
    window : float
        Smallest CAP-CD voltage window, V.

    Returns
    -------
    float
        The lowest reliable speed, rpm.
    """
    return 10.0 * i_charge_max / (validate.positive("window", window, "V") * pole_pairs * cap)


def rpm_max_for(cap, pole_pairs, i_charge_min, min_excursion):
    """Eq 7: the highest speed at which the swing with the smallest current stays above the noise floor.

    Parameters
    ----------
    cap : float
        CAP-CD, F.
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge_min : float
        Smallest CAP-CD charge current, A.
    min_excursion : float
        Smallest CAP-CD swing still safe from noise, V.

    Returns
    -------
    float
        The highest reliable speed, rpm.
    """
    validate.positive("min_excursion", min_excursion, "V")
    return 10.0 * i_charge_min / (min_excursion * validate.pole_pairs("pole_pairs", pole_pairs) * cap)


def reliable_speed_range(cap, tolerance, pole_pairs, i_charge_min, i_charge_max, window, min_excursion):
    """The speeds a capacitor covers in the worst case: the lowest at its small tolerance end with the
    largest current (eq 5), the highest at its large end with the smallest current (eq 7).

    Parameters
    ----------
    cap : float
        CAP-CD, nominal, F.
    tolerance : float
        Its tolerance as a fraction (5 % is 0.05).
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge_min, i_charge_max : float
        Smallest and largest CAP-CD charge current, A.
    window : float
        Smallest CAP-CD voltage window, V.
    min_excursion : float
        Smallest CAP-CD swing still safe from noise, V.

    Returns
    -------
    tuple of float
        (lowest, highest) reliable speed, rpm.
    """
    return (rpm_min_for(cap * (1 - tolerance), pole_pairs, i_charge_max, window),
            rpm_max_for(cap * (1 + tolerance), pole_pairs, i_charge_min, min_excursion))


def rpm_ratio(window, min_excursion, i_charge_min, i_charge_max):
    """Eq 8: RPM_max / RPM_min for a capacitor sized exactly at the bound.

    Parameters
    ----------
    window : float
        Smallest CAP-CD voltage window (the note's dV_capmax), V.
    min_excursion : float
        Smallest swing still safe from noise (the note's dV_capmin of eq 7), V.
    i_charge_min, i_charge_max : float
        Smallest and largest CAP-CD charge current, A.

    Returns
    -------
    float
        RPM_max / RPM_min, a pure number.
    """
    return window * i_charge_min / (min_excursion * i_charge_max)


def eng(value: float, unit: str) -> str:
    """An engineering value with its unit, as the chapters show it (654.8 pF, 14.55 nF).

    Parameters
    ----------
    value : float
        The value, SI units.
    unit : str
        Its unit symbol ("F", "Ω").

    Returns
    -------
    str
        The value to 4 significant figures with an SI prefix and the unit.
    """
    from ...core.units import eng as _eng

    return _eng(value, unit)


def choose_cap_cd(rpm_min, pole_pairs, i_charge_max, window, tolerance=0.05, series_name="E12"):
    """The smallest series value that meets the bound at its low tolerance end.

    Returns (chosen, bound, {value: reason}) where the dict explains each smaller series value that fails.

    Parameters
    ----------
    rpm_min : float
        Lowest speed that must commutate correctly, rpm.
    pole_pairs : int
        Magnetic pole pairs n.
    i_charge_max : float
        Largest CAP-CD charge current, A.
    window : float
        Smallest CAP-CD voltage window, V.
    tolerance : float
        Capacitor tolerance as a fraction (5 % is 0.05).
    series_name : str
        The E-series the capacitor is picked from ("E12").

    Returns
    -------
    tuple
        (chosen, bound, rejected): the chosen capacitor, F; the bound of :func:`cap_cd_min`, F; and a dict,
        smaller series value (F) -> why it fails (str).
    """
    bound = cap_cd_min(rpm_min, pole_pairs, i_charge_max, window)
    chosen = series.smallest_meeting(series_name, bound, validate.fraction("cap_tolerance", tolerance))
    rejected = {}
    for v in series.values(series_name, chosen / 3, chosen * 0.999):
        if v * (1 - tolerance) < bound <= v:
            rejected[v] = (f"meets the nominal bound {eng(bound, 'F')} but not at -{tolerance:.0%}: "
                           f"{eng(v * (1 - tolerance), 'F')}")
        elif v < bound:
            rejected[v] = f"below the bound {eng(bound, 'F')}"
    return chosen, bound, rejected


# ----------------------------------------------------------------------------------------------
# 2.1.3 watchdog

def cap_ti_for(t_wd, i_wd=5e-6, v_low=0.3, v_high=2.2):
    """Eq 9: C = I t_wd / dV (charge from 0.3 V to 2.2 V at 5 uA).

    Parameters
    ----------
    t_wd : float
        Watchdog time wanted, s.
    i_wd : float
        Watchdog charge current, A.
    v_low, v_high : float
        Start and end of the watchdog ramp, V.

    Returns
    -------
    float
        CAP-TI, F.
    """
    validate.ordered("v_ti_low", v_low, "v_ti_high", v_high)
    return i_wd * validate.positive("t_wd", t_wd, "s") / (v_high - v_low)


def watchdog_time(cap, i_wd=5e-6, v_low=0.3, v_high=2.2):
    """Eq 9 solved for the time: t_wd = C dV / I, the watchdog time a CAP-TI gives.

    Parameters
    ----------
    cap : float or numpy.ndarray
        CAP-TI, F.
    i_wd : float or numpy.ndarray
        Watchdog charge current, A.
    v_low, v_high : float
        Start and end of the watchdog ramp, V.

    Returns
    -------
    float or numpy.ndarray
        The watchdog time, s (elementwise for arrays).
    """
    validate.ordered("v_ti_low", v_low, "v_ti_high", v_high)
    return validate.positive("cap_ti", cap, "F") * (v_high - v_low) / validate.positive("i_wd", i_wd, "A")


def cap_ti_waveform(cap, p: dict, stalled: bool = True):
    """Piecewise-linear CAP-TI voltage for one watchdog cycle (times in s, volts).

    Fast charge 0.2 -> 0.3 V at 57 uA, watchdog charge 0.3 -> 2.2 V at 5 uA, then discharge at
    28 uA back to 0.2 V. With ``stalled`` False the EMF recovers halfway up the watchdog ramp.

    Parameters
    ----------
    cap : float
        CAP-TI, F.
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_ti_start``, ``v_ti_low``, ``v_ti_high``
        (V) and ``i_ti_fast``, ``i_wd``, ``i_ti_discharge`` (A).
    stalled : bool
        True: the motor stays stalled and the ramp reaches ``v_ti_high``; False: it stops halfway.

    Returns
    -------
    tuple of numpy.ndarray
        (times, volts): the four corners of the waveform, s and V.
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
    """Highest controllable V_mot: the lowest supply less the drop R7 and T1 need.

    Parameters
    ----------
    v_supply : float
        Nominal supply V_s, V.
    supply_tolerance : float
        Supply tolerance as a fraction (10 % is 0.1).
    v_drop_min : float
        Smallest drop across R7 and T1 for linear control, V.

    Returns
    -------
    float
        The highest controllable V_mot, V.
    """
    low = 1 - validate.fraction("supply_tolerance", supply_tolerance)
    return validate.positive("v_supply", v_supply, "V") * low - v_drop_min


def v_in_for(v_mot, r3, r4):
    """Eq 10: the OTA holds AMPIN+ = AMPIN-, so V_in equals the divided V_mot.

    Parameters
    ----------
    v_mot : float
        Motor supply V_mot, V.
    r3, r4 : float
        The divider's top and bottom resistors, ohm.

    Returns
    -------
    float
        The control input V_in, V.
    """
    return v_mot * validate.positive("r4", r4, "ohm") / (validate.positive("r3", r3, "ohm") + r4)


def r3_for(v_mot, v_in, r4):
    """Eq 10 solved for R3.

    Parameters
    ----------
    v_mot : float
        Motor supply V_mot, V.
    v_in : float
        Control input V_in, V.
    r4 : float
        The divider's bottom resistor, ohm.

    Returns
    -------
    float
        The divider's top resistor R3, ohm.
    """
    validate.positive("v_in", v_in, "V")
    if v_mot <= v_in:
        raise validate.InputError(f"v_mot = {v_mot:g} V must exceed v_in = {v_in:g} V for a divider")
    return r4 * (v_mot / v_in - 1)


def v_in_range(p: dict) -> tuple[float, float]:
    """V_in for the lowest running V_mot and for the highest controllable V_mot.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_supply``, ``v_drop_min``,
        ``v_mot_min`` (V), ``supply_tolerance`` (fraction) and ``r3``, ``r4`` (ohm).

    Returns
    -------
    tuple of float
        (V_in at the lowest V_mot, V_in at the highest controllable V_mot), V.
    """
    top = v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"])
    return v_in_for(p["v_mot_min"], p["r3"], p["r4"]), v_in_for(top, p["r3"], p["r4"])


def ota_input_max(p: dict) -> float:
    """The OTA inputs may not exceed V_P - 1.7 V (TDA5144 datasheet, quoted by the note).

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_p_min`` and ``ota_headroom``, V.

    Returns
    -------
    float
        The highest allowed OTA input voltage, V.
    """
    return p["v_p_min"] - p["ota_headroom"]


# ----------------------------------------------------------------------------------------------
# 2.3 one-transistor limiter

def r7_for_limit(i_limit, v_be=0.8):
    """R7 for a limit current: R7 = V_be / I_lim (the transistor turns on at V_be).

    Parameters
    ----------
    i_limit : float
        Limit current wanted, A.
    v_be : float
        V_be at which the transistor turns on, V.

    Returns
    -------
    float
        R7, ohm.
    """
    return validate.positive("v_be", v_be, "V") / validate.positive("i_limit", i_limit, "A")


def limit_current(r7, temperature, v_be=0.8, v_be_tc=-2e-3, t_ref=25.0):
    """I_lim(T) = V_be(T) / R7 with V_be(T) = V_be + TC (T - T_ref).

    Parameters
    ----------
    r7 : float
        Sense resistor R7, ohm.
    temperature : float or array_like
        Temperature(s), degrees C (only the difference from ``t_ref`` counts, so K differences alike).
    v_be : float
        V_be at ``t_ref``, V.
    v_be_tc : float
        Temperature coefficient of V_be, V/K.
    t_ref : float
        Reference temperature of ``v_be``, degrees C.

    Returns
    -------
    float or numpy.ndarray
        The limit current at each temperature, A.
    """
    return (v_be + v_be_tc * (np.asarray(temperature, dtype=float) - t_ref)) / validate.positive("r7", r7, "ohm")


def limit_tc(v_be=0.8, v_be_tc=-2e-3):
    """Relative temperature coefficient of the limit current: (dV_be/dT) / V_be, per kelvin.

    Parameters
    ----------
    v_be : float
        V_be at which the transistor turns on, V.
    v_be_tc : float
        Temperature coefficient of V_be, V/K.

    Returns
    -------
    float
        The relative temperature coefficient of the limit current, 1/K.
    """
    return v_be_tc / validate.positive("v_be", v_be, "V")


# ----------------------------------------------------------------------------------------------
# 2.4 op-amp limiter (zener-bridged level shift)

def factor_a(r12, r13):
    """A = R13 / (R12 + R13): the level-shift divider's gain (eq 11).

    Parameters
    ----------
    r12, r13 : float
        The level-shift divider's top and bottom resistors, ohm (floats or numpy arrays).

    Returns
    -------
    float
        A, a pure number.
    """
    return r13 / (r12 + r13)


def factor_b(r9, r10, r11):
    """B = R11 / (R9 + R10 + R11): the reference divider (eq 12).

    Parameters
    ----------
    r9, r10, r11 : float
        The reference divider's resistors, ohm (floats or numpy arrays).

    Returns
    -------
    float
        B, a pure number.
    """
    return r11 / (r9 + r10 + r11)


def level_shift(zener_voltage, r12, r13, v_cs=0.0):
    """V_s - V_+ from eq 11: how far below the supply the op-amp inputs sit.

    Parameters
    ----------
    zener_voltage : float
        Zener voltage V_D1, V.
    r12, r13 : float
        The level-shift divider's top and bottom resistors, ohm.
    v_cs : float
        Current-sense voltage, V.

    Returns
    -------
    float
        V_s - V_+, V.
    """
    return zener_voltage - factor_a(r12, r13) * (zener_voltage - v_cs)


def v_cs_trip(zener_voltage, r9, r10, r11, r12, r13, offset=0.0):
    """The sense voltage at which the op-amp trips: eq 13 with the input offset referred back.

    V_+ - V_- = V_os at the trip point; with eq 11 and 12 that gives
    V_cs = V_D1 (1 - B/A) - V_os / A. Works elementwise on numpy arrays.

    Parameters
    ----------
    zener_voltage : float
        Zener voltage V_D1, V.
    r9, r10, r11 : float
        The reference divider's resistors, ohm.
    r12, r13 : float
        The level-shift divider's top and bottom resistors, ohm.
    offset : float
        The op-amp's input offset V_os, V.

    Returns
    -------
    float
        The trip voltage across the sense resistor R7, V.
    """
    a = factor_a(r12, r13)
    return zener_voltage * (1 - factor_b(r9, r10, r11) / a) - offset / a


def v_cs_matched(zener_voltage, r9, r10, r11):
    """Eq 14: V_cs = V_D1 R9 / (R9 + R10 + R11), valid only for R10 = R12 and R11 = R13 exactly.

    Parameters
    ----------
    zener_voltage : float
        Zener voltage V_D1, V.
    r9, r10, r11 : float
        The reference divider's resistors, ohm.

    Returns
    -------
    float
        The trip voltage across the sense resistor R7, V.
    """
    return zener_voltage * r9 / (r9 + r10 + r11)


def r9_for(v_cs, zener_voltage, r10, r11):
    """Eq 14 solved for R9.

    Parameters
    ----------
    v_cs : float
        The trip voltage wanted across R7, V.
    zener_voltage : float
        Zener voltage V_D1, V.
    r10, r11 : float
        The reference divider's other resistors, ohm.

    Returns
    -------
    float
        Reference resistor R9, ohm.
    """
    validate.positive("v_cs", v_cs, "V")
    if v_cs >= zener_voltage:
        raise validate.InputError(f"v_cs = {v_cs:g} V must be below the zener voltage {zener_voltage:g} V")
    return v_cs * (r10 + r11) / (zener_voltage - v_cs)


def trip_worst_case(p: dict, r9: float | None = None, include=("resistors", "zener", "offset")):
    """Exact worst case of the trip voltage over every tolerance corner (see tolerance.corners).

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_cs``, ``zener_voltage``, ``offset`` (V),
        ``r10`` to ``r13`` (ohm) and ``resistor_tolerance``, ``zener_tolerance`` (fractions).
    r9 : float or None
        Reference resistor R9, ohm; None: designed from ``p`` by eq 14 (:func:`r9_for`).
    include : tuple of str
        The spreads taken: ``"resistors"``, ``"zener"``, ``"offset"``; the others stay nominal.

    Returns
    -------
    WorstCase
        The trip voltage across R7 at nominal and at its extremes, V, with the corners giving them.
    """
    r9 = r9_for(p["v_cs"], p["zener_voltage"], p["r10"], p["r11"]) if r9 is None else r9
    tr = validate.fraction("resistor_tolerance", p["resistor_tolerance"])
    nominal = dict(zener_voltage=p["zener_voltage"], r9=r9, r10=p["r10"], r11=p["r11"], r12=p["r12"], r13=p["r13"], offset=0.0)
    spread = {}
    if "resistors" in include:
        spread.update({k: tolerance.symmetric(nominal[k], tr) for k in ("r9", "r10", "r11", "r12", "r13")})
    if "zener" in include:
        spread["zener_voltage"] = tolerance.symmetric(p["zener_voltage"],
                                                      validate.fraction("zener_tolerance", p["zener_tolerance"]))
    if "offset" in include:
        spread["offset"] = (-p["offset"], p["offset"])
    return tolerance.corners(v_cs_trip, nominal, spread)


def note_stack_up(p: dict) -> dict:
    """The note's tolerance arithmetic: offset, zener and resistor percentages multiplied.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``offset``, ``v_cs`` (V), ``r12``, ``r13``
        (ohm) and ``zener_tolerance``.

    Returns
    -------
    dict
        Fractions: ``offset`` (the offset's share, V_os / (A V_cs)), ``zener``, ``resistors`` (the note's 5 %),
        ``high`` and ``low`` (the stacked relative deviations, ``low`` negative).
    """
    a = factor_a(p["r12"], p["r13"])
    t_off = p["offset"] / (a * p["v_cs"])
    tols = [t_off, p["zener_tolerance"], 0.05]
    low, high = tolerance.stack_product(tols)
    return {"offset": t_off, "zener": p["zener_tolerance"], "resistors": 0.05, "high": high, "low": low}


# ----------------------------------------------------------------------------------------------
# 3 decoupling

def c_min_for_impedance(z_max, f):
    """An ideal capacitor's |Z| = 1/(2 pi f C) stays below z_max for C >= 1/(2 pi f z_max).

    Parameters
    ----------
    z_max : float
        Largest allowed |Z|, ohm.
    f : float
        Frequency at which |Z| is limited, Hz.

    Returns
    -------
    float
        The smallest capacitance, F.
    """
    return 1.0 / (2 * math.pi * validate.positive("f_decoupling", f, "Hz") * validate.positive("z_max", z_max, "ohm"))


def impedance(f, c, esr=0.0, esl=0.0):
    """|Z| of a real capacitor, series R-L-C: sqrt(ESR^2 + (wL - 1/(wC))^2).

    Parameters
    ----------
    f : float or array_like
        Frequency, Hz.
    c : float
        Capacitance, F.
    esr : float
        Equivalent series resistance, ohm.
    esl : float
        Equivalent series inductance, H.

    Returns
    -------
    float or numpy.ndarray
        |Z| at each frequency, ohm.
    """
    w = 2 * np.pi * np.asarray(f, dtype=float)
    return np.sqrt(esr ** 2 + (w * esl - 1 / (w * c)) ** 2)


def esl_max(z_max, f):
    """The largest series inductance for which wL alone stays below z_max.

    Parameters
    ----------
    z_max : float
        Largest allowed |Z|, ohm.
    f : float
        Frequency at which |Z| is limited, Hz.

    Returns
    -------
    float
        The largest series inductance, H.
    """
    return z_max / (2 * math.pi * f)


# ----------------------------------------------------------------------------------------------
# motor-side timing (the design of handbook.design.commutation builds on these)

def decay_rate(f_osc, damping_ratio):
    """Envelope decay rate (1/s) of the rotor rocking about a detent, J x'' + c x' + K_t I p x = 0.

    Underdamped (zeta < 1): zeta w_n. Overdamped: the slow root, w_n (zeta - sqrt(zeta^2 - 1)).

    Parameters
    ----------
    f_osc : float or numpy.ndarray
        Undamped oscillation frequency about the detent (eq 2), Hz.
    damping_ratio : float
        Damping ratio zeta, a pure number > 0.

    Returns
    -------
    float or numpy.ndarray
        The envelope decay rate sigma, 1/s (elementwise for an array of frequencies).
    """
    w = 2 * math.pi * validate.positive("f_osc", f_osc, "Hz")
    z = validate.positive("damping_ratio", damping_ratio, "")
    return w * (z - math.sqrt(max(z * z - 1.0, 0.0)))


def settle_time(f_osc, damping_ratio, residual):
    """Time for the rocking's envelope exp(-sigma t) to fall to ``residual`` of its first swing.

    Parameters
    ----------
    f_osc : float or numpy.ndarray
        Undamped oscillation frequency about the detent (eq 2), Hz.
    damping_ratio : float
        Damping ratio zeta, a pure number > 0.
    residual : float
        The envelope left, as a fraction of the first swing (0 < residual < 1).

    Returns
    -------
    float or numpy.ndarray
        The settling time, s (elementwise for an array of frequencies).
    """
    validate.positive("residual", residual, "")
    return math.log(1.0 / validate.fraction("residual", residual)) / decay_rate(f_osc, damping_ratio)


def reverse_catch_time(rpm, pole_pairs, angle_el=150.0):
    """Time a rotor turning backwards at ``rpm`` needs for ``angle_el`` electrical degrees.

    After a commutation the floating winding of a reversed motor shows the wrong EMF polarity until the
    rotor has turned back 150 to 180 electrical degrees (120 degrees of flat trapezoid top plus the 30
    to 60 degrees left of the step): the watchdog must act within the shortest of these, 150 degrees,
    which is 2.5 commutation intervals at that speed.

    Parameters
    ----------
    rpm : float
        Reverse rotational speed, rpm.
    pole_pairs : int
        Magnetic pole pairs n.
    angle_el : float
        Electrical angle the rotor must turn back, degrees.

    Returns
    -------
    float
        The time, s.
    """
    return angle_el / 60.0 * t_com(rpm, pole_pairs)
