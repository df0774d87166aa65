"""Every number AN94002 prints as the result of a calculation, recomputed; one builder per chapter.

The op-amp limiter's claims (section 2.4) are in :mod:`.claims_limiter`.
"""
from __future__ import annotations

from ...core import Claim, Printed, series
from . import claims_limiter
from .circuit import (
    c_min_for_impedance,
    cap_cd_min,
    cap_st_for,
    cap_ti_for,
    choose_cap_cd,
    limit_tc,
    oscillation_frequency,
    r3_for,
    v_in_for,
    v_mot_max,
)
from .claims_limiter import vd1_min
from .data import FACTS, NAME

TDA5144 = "TDA5144 datasheet"


def fact(key: str, index: int):
    """A claim's computation that returns one of a fact's figures (it reads no parameter).

    Parameters
    ----------
    key : str
        The fact's name in :data:`~handbook.sources.an94002.data.FACTS`.
    index : int or None
        Which of its figures (tuples: min/typ/max, low/high); None for a fact that is one figure.

    Returns
    -------
    callable
        A function of the parameters (which it ignores) returning the figure, SI units.
    """
    return lambda p: FACTS[key].value if index is None else FACTS[key].value[index]


def cap_st(p):
    """CAP-ST for the chosen start frequency (eq 1).

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``f_start`` (Hz), ``i_cap_st`` (A),
        ``v_st_low`` and ``v_st_high`` (V).

    Returns
    -------
    float
        CAP-ST, F.
    """
    return cap_st_for(1 / p["f_start"], p["i_cap_st"], p["v_st_low"], p["v_st_high"])


def cap_st_choice(p):
    """CAP-ST chosen: the value of ``cap_st_series`` nearest the eq 1 value.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``cap_st_series`` and what :func:`cap_st`
        reads.

    Returns
    -------
    float
        CAP-ST, F.
    """
    return series.nearest(p["cap_st_series"], cap_st(p))


def window(p):
    """The smallest CAP-CD window dV_capmin.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_cd_high_min`` and ``v_cd_low_max``, V.

    Returns
    -------
    float
        The window, V.
    """
    return p["v_cd_high_min"] - p["v_cd_low_max"]


def capcd_bound(p):
    """The CAP-CD lower bound (eq 5/6) at ``rpm_min`` with the largest charge current and the window.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``rpm_min`` (rpm), ``pole_pairs``,
        ``i_charge_max`` (A) and what :func:`window` reads.

    Returns
    -------
    float
        The smallest CAP-CD, F.
    """
    return cap_cd_min(p["rpm_min"], p["pole_pairs"], p["i_charge_max"], window(p))


def cap_cd_choice(p):
    """CAP-CD chosen: the smallest series value meeting the bound at its low tolerance end.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads what :func:`capcd_bound` reads,
        ``cap_tolerance`` and ``cap_series``.

    Returns
    -------
    float
        CAP-CD, F.
    """
    return choose_cap_cd(p["rpm_min"], p["pole_pairs"], p["i_charge_max"], window(p), p["cap_tolerance"],
                         p["cap_series"])[0]


def vmot_max(p):
    """The highest controllable V_mot: the lowest supply less the drop R7 and T1 need.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``v_supply``, ``v_drop_min`` (V) and
        ``supply_tolerance``.

    Returns
    -------
    float
        V_mot, V.
    """
    return v_mot_max(p["v_supply"], p["supply_tolerance"], p["v_drop_min"])


def r13_max(p):
    """The largest E24 R13 keeping the level shift at the lowest zener voltage.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``level_shift_min`` (V), ``r12`` (ohm),
        ``zener_voltage`` (V) and ``zener_tolerance``.

    Returns
    -------
    float
        R13, ohm.
    """
    k = p["level_shift_min"] / vd1_min(p)
    return series.at_most("E24", p["r12"] * (1 - k) / k)


def start() -> list[Claim]:
    """The claims of section 2.1.1, the start oscillator.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "start"
    return [
        Claim(id="an94002-fosc", where=f"{NAME} 2.1.1", quantity="rotor oscillation frequency f_osc",
              printed=Printed("5", "Hz"), chapter=ch,
              compute=lambda p: oscillation_frequency(p["torque_constant"], p["start_current"], p["pole_pairs"],
                                                      p["inertia"]),
              reason="sqrt(25e-3 x 0.5 x 6 / 72e-6) / 2 pi = 5.14 Hz, printed to one digit"),
        Claim(id="an94002-tstart", where=f"{NAME} 2.1.1", quantity="start period for a 2 Hz start frequency",
              printed=Printed("500", "ms"), chapter=ch, compute=lambda p: 1 / p["f_start"], reason="1 / 2 Hz"),
        Claim(id="an94002-capst", where=f"{NAME} 2.1.1", quantity="CAP-ST from eq 1", printed=Printed("0.23", "uF"),
              chapter=ch, compute=cap_st, reason="0.5 s / 2.15 s/uF = 0.2326 uF"),
        Claim(id="an94002-capst-choice", where=f"{NAME} 2.1.1", quantity="CAP-ST chosen (nearest E12)",
              printed=Printed("0.22", "uF"), chapter=ch, compute=cap_st_choice,
              reason="0.22 uF is the E12 value nearest 0.2326 uF (start frequency 2.11 Hz)"),
        Claim(id="an94002-capst-datasheet", where=f"{NAME} 2.1.1 vs TDA5144 datasheet",
              quantity="CAP-ST for 500 ms, datasheet levels", printed=Printed("0.23", "uF"), chapter=ch,
              compute=lambda p: cap_st_for(1 / p["f_start"], p["i_cap_st"], *FACTS["cap_st_levels"].value),
              reason="the TDA5144 datasheet switches CAP-ST at 0.20 V and 2.20 V and gets 0.25 uF; the note's 0.05 V "
                     "level (and 2.15 factor) comes from the TDA5141/TDA5145 datasheets",
              basis=TDA5144, consequence="with a TDA5144, 0.22 uF gives a 440 ms period, not 473 ms: size CAP-ST "
                                         "with the datasheet of the IC on the board"),
    ]


def commutation() -> list[Claim]:
    """The claims of section 2.1.2, the adaptive commutation delay.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "commutation"
    return [
        Claim(id="an94002-window", where=f"{NAME} 2.1.2", quantity="smallest CAP-CD window dV_capmin = 2.3 - 0.9",
              printed=Printed("1.4", "V"), chapter=ch, compute=window,
              reason="2.3 V - 0.9 V; agrees with the datasheet's minimum upper and maximum lower level"),
        Claim(id="an94002-eq6-constant", where=f"{NAME} 2.1.2, eq (6)",
              quantity="constant of the CAP-CD bound (C in uF, RPM in rpm)", printed=Printed("160", "uF*rpm"),
              chapter=ch, compute=lambda p: 10 * p["i_charge_max"] / window(p),
              reason="10 x 22 uA / 1.4 V = 157.1 uF rpm, rounded up to two figures (conservative by 1.8 %)"),
        Claim(id="an94002-capcd-bound", where=f"{NAME} 2.1.2", quantity="CAP-CD lower bound for 1800 rpm, 6 pole pairs",
              printed=Printed("0.0148", "uF"), chapter=ch, compute=capcd_bound,
              via_rounded=lambda p: 160e-6 / (p["rpm_min"] * p["pole_pairs"]), safe_side="above",
              reason="a lower bound printed on the safe side: 160 / (1800 x 6) = 0.01481 uF follows from the note's "
                     "constant, 157.14 rounded up to 160; from 22 uA and 1.4 V directly the bound is 0.01455 uF, "
                     "which 0.0148 is 1.7 % above (a larger capacitor than needed, never a smaller one)"),
        Claim(id="an94002-c3", where=f"{NAME} 2.1.2", quantity="C3 = CAP-CD chosen", printed=Printed("18", "nF"),
              chapter=ch, compute=cap_cd_choice, basis="note, with this book's 5 % capacitor tolerance",
              reason="the note's choice, recomputed under an assumption of this book: with a 5 % capacitor "
                     "tolerance (the note states none) the smallest E12 value meeting the 14.55 nF bound at its low "
                     "end is 18 nF (15 nF x 0.95 = 14.25 nF falls short); without a tolerance 15 nF would do"),
        Claim(id="an94002-c4", where=f"{NAME} 2.1.2", quantity="C4 = CAP-DC (same timer, same value)",
              printed=Printed("0.018", "uF"), chapter=ch, compute=cap_cd_choice,
              basis="note, with this book's 5 % capacitor tolerance",
              reason="CAP-DC runs the slave timer with the same currents and window, so C4 = C3"),
        Claim(id="an94002-ich-max", where=f"{NAME} 2.1.2 vs TDA5144 datasheet",
              quantity="largest CAP-CD charge current I_chmax", printed=Printed("22", "uA"), chapter=ch,
              compute=fact("cap_cd_charge", 2),
              reason="22 uA is the datasheet's largest discharge (sink) current; the charge current is at most "
                     "11 uA (sink/source ratio about 2), so the note's capacitor is twice the size the bound needs",
              basis=TDA5144, consequence="CAP-CD comes out twice the size the bound needs, halving the top speed "
                                         "at which commutation stays reliable"),
    ]


def watchdog() -> list[Claim]:
    """The claims of section 2.1.3, the watchdog.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "watchdog"
    return [
        Claim(id="an94002-eq9-constant", where=f"{NAME} 2.1.3, eq (9)", quantity="CAP-TI per second of watchdog time",
              printed=Printed("2.63", "uF"), chapter=ch,
              compute=lambda p: cap_ti_for(1.0, p["i_wd"], p["v_ti_low"], p["v_ti_high"]),
              reason="5 uA / 1.9 V = 2.6316 uF per s"),
        Claim(id="an94002-eq9-window", where=f"{NAME} 2.1.3, eq (9)", quantity="CAP-TI watchdog window 2.2 V - 0.3 V",
              printed=Printed("1.9", "V"), chapter=ch, compute=lambda p: p["v_ti_high"] - p["v_ti_low"],
              reason="2.2 V - 0.3 V"),
    ]


def speed() -> list[Claim]:
    """The claims of section 2.2, the speed control.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "speed"
    return [
        Claim(id="an94002-vmot-max", where=f"{NAME} 2.2", quantity="highest controllable V_mot",
              printed=Printed("9.8", "V"), chapter=ch, compute=vmot_max, reason="0.9 x 12 V - 1 V"),
        Claim(id="an94002-vin", where=f"{NAME} 2.2, eq (10)", quantity="V_in for V_mot = 9.8 V",
              printed=Printed("2", "V"), chapter=ch, compute=lambda p: v_in_for(vmot_max(p), p["r3"], p["r4"]),
              reason="9.8 V x 10 k / 49 k = 2.000 V"),
        Claim(id="an94002-vmot-min", where=f"{NAME} 2.2 vs TDA5144 datasheet", quantity="lowest running V_mot",
              printed=Printed("1.7", "V"), chapter=ch, compute=fact("v_mot_range", 0),
              reason="the datasheet's V_MOT range starts at 1.7 V", basis=TDA5144),
    ]


def one_transistor() -> list[Claim]:
    """The claims of section 2.3, the one-transistor limiter.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "one_transistor"
    return [
        Claim(id="an94002-vbe-tc", where=f"{NAME} 2.3", quantity="temperature coefficient of the one-transistor limit",
              printed=Printed("-0.25", "%/K"), chapter=ch, compute=lambda p: limit_tc(p["v_be"], p["v_be_tc"]),
              reason="-2 mV/K / 800 mV"),
        Claim(id="an94002-vbe", where=f"{NAME} 2.3 vs BC557 datasheet", quantity="V_be at which T2 limits",
              printed=Printed("0.8", "V"), chapter=ch, compute=fact("bc557_vbe_10ma", None), relation="<=",
              reason="T2 takes over the OTA's drive to the output transistor's base, so it runs at milliamps to tens of "
                     "milliamps (the OTA sinks up to 40 mA), where the BC556-558 sheets give V_BE(on) up to 0.82 V "
                     "(at 10 mA); the 2 mA column (0.55 to 0.70 V) does not bound it. 'About 0.8 V' is inside",
              basis="BC557 datasheet"),
    ]


def decoupling() -> list[Claim]:
    """The claims of section 3, the supply decoupling.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    return [
        Claim(id="an94002-c2", where=f"{NAME} 3", quantity="C2 capacitance for |Z| < 2 ohm at 2 MHz (ideal capacitor)",
              printed=Printed("10", "uF"), chapter="decoupling",
              compute=lambda p: c_min_for_impedance(p["z_max"], p["f_decoupling"]),
              reason="10 uF is far above the 40 nF the reactance needs: the real limits are ESR < 2 ohm and "
                     "ESL < 159 nH", relation=">="),
    ]


def parts() -> list[Claim]:
    """The claims of section 4, the parts list.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    ch = "parts"
    return [
        Claim(id="an94002-r3", where=f"{NAME} 4, parts list R3",
              quantity="R3 for V_in = 2 V at V_mot = 9.8 V (R4 = 10 k)", printed=Printed("39", "kohm"), chapter=ch,
              compute=lambda p: r3_for(vmot_max(p), 2.0, p["r4"]),
              reason="10 k x (9.8/2 - 1) = 39.0 k, an E12 value"),
        Claim(id="an94002-r13", where=f"{NAME} 4, parts list R11/R13",
              quantity="largest E24 R13 keeping a 2 V shift at 7.79 V (R12 = 5.6 k)", printed=Printed("16", "kohm"),
              chapter=ch, compute=r13_max,
              reason="R13 <= 5.6 k x (7.79 - 2)/2 = 16.2 k; 16 k is the largest E24 value below"),
        Claim(id="an94002-c5", where=f"{NAME} 4, parts list C5", quantity="C5 = CAP-ST", printed=Printed("220", "nF"),
              chapter=ch, compute=cap_st_choice,
              reason="the 0.22 uF of 2.1.1 (C5 as CAP-ST is inferred from the value: the schematic did not "
                     "survive OCR)"),
        Claim(id="an94002-c6", where=f"{NAME} 4, parts list C6", quantity="C6 = CAP-TI (at least 2000 pF)",
              printed=Printed("10", "nF"), chapter=ch, compute=lambda p: p["cap_ti_min"],
              reason="10 nF meets the 2000 pF minimum; the watchdog time is 3.8 ms", relation=">="),
    ]


def build() -> list[Claim]:
    """Every AN94002 claim, in the note's order.

    Returns
    -------
    list of Claim
        Every claim, the op-amp limiter's (:mod:`.claims_limiter`) included.
    """
    return (start() + commutation() + watchdog() + speed() + one_transistor() + claims_limiter.build()
            + decoupling() + parts())
