"""AN94002: the note's values (every chapter's parameters), the outside facts it relies on, its textual errata.

Device figures the note relies on without printing come from the devices' public datasheets
(each :class:`~handbook.core.source.Fact` names which) and are cited where used.
"""
from __future__ import annotations

from ...core import Fact, Param, TextErratum

NAME = "AN94002"
TDA5144 = "TDA5144 datasheet (June 1994)"
LM358 = "LM358 datasheet"
BZX79 = "BZX79 datasheet"
ASSUMED = "assumption"

SERIES = ("E3", "E6", "E12", "E24", "E48", "E96", "E192")

PARAMETERS = (
    # 2.1.1 start oscillator
    Param(name="inertia", default=72e-6, unit="kg m^2", meaning="rotor + load inertia J", low=1e-12, high=1.0),
    Param(name="torque_constant", default=25e-3, unit="N m/A", meaning="torque constant K_t", low=1e-6, high=10.0),
    Param(name="pole_pairs", default=6, unit="", meaning="magnetic pole pairs n", low=1, high=100),
    Param(name="start_current", default=0.5, unit="A", meaning="motor current while starting", low=1e-4, high=100.0),
    Param(name="i_cap_st", default=2e-6, unit="A", meaning="CAP-ST charge = discharge current (2.1.1)",
          low=1e-9, high=1e-3),
    Param(name="v_st_low", default=0.05, unit="V", meaning="CAP-ST lower switching level (the TDA5144 datasheet "
          "says 0.20 V)", low=0.0, high=10.0),
    Param(name="v_st_high", default=2.2, unit="V", meaning="CAP-ST upper switching level", low=0.0, high=10.0),
    Param(name="f_start", default=2.0, unit="Hz", meaning="chosen start frequency", low=1e-3, high=1e4),
    Param(name="cap_st_series", default="E12", unit="", meaning="series CAP-ST is picked from", choices=SERIES),
    # 2.1.2 adaptive commutation delay
    Param(name="rpm_min", default=1800.0, unit="rpm", meaning="lowest speed that must commutate correctly",
          low=1.0, high=1e6),
    Param(name="i_charge_max", default=22e-6, unit="A", meaning="largest CAP-CD charge current, as the note uses it "
          "(the datasheet's maximum discharge current)", low=1e-9, high=1e-3),
    Param(name="i_charge_min", default=10.6e-6, unit="A", meaning="smallest CAP-CD charge current (same column "
          "pairing as the note's 22 uA: the datasheet's sink minimum)", low=1e-9, high=1e-3, cite=TDA5144),
    Param(name="v_cd_high_min", default=2.3, unit="V", meaning="CAP-CD upper switching level, minimum",
          low=0.0, high=10.0, cite=TDA5144),
    Param(name="v_cd_low_max", default=0.9, unit="V", meaning="CAP-CD lower switching level, maximum",
          low=0.0, high=10.0, cite=TDA5144),
    Param(name="min_excursion", default=0.1, unit="V", meaning="smallest CAP-CD swing still safe from noise "
          "(the note gives none)", low=1e-4, high=10.0, cite=ASSUMED),
    Param(name="cap_tolerance", default=0.05, unit="1", meaning="capacitor tolerance (the note states none)", low=0.0,
          high=0.5, cite=ASSUMED),
    Param(name="cap_series", default="E12", unit="", meaning="series CAP-CD is picked from", choices=SERIES),
    # 2.1.3 watchdog
    Param(name="i_wd", default=5e-6, unit="A", meaning="watchdog charge current (0.3 V to 2.2 V)",
          low=1e-9, high=1e-3),
    Param(name="v_ti_low", default=0.3, unit="V", meaning="watchdog ramp start", low=0.0, high=10.0),
    Param(name="v_ti_high", default=2.2, unit="V", meaning="watchdog threshold", low=0.0, high=10.0),
    Param(name="cap_ti", default=10e-9, unit="F", meaning="CAP-TI fitted (the board's C6)", low=1e-12, high=1e-3),
    Param(name="cap_ti_min", default=2e-9, unit="F", meaning="smallest CAP-TI the note allows", low=1e-12, high=1e-3),
    Param(name="i_ti_fast", default=57e-6, unit="A", meaning="internal-timing charge current (0.2 V to 0.3 V)",
          low=1e-9, high=1e-2),
    Param(name="v_ti_start", default=0.2, unit="V", meaning="CAP-TI level after discharge", low=0.0, high=10.0),
    Param(name="i_ti_discharge", default=28e-6, unit="A", meaning="CAP-TI discharge current", low=1e-9, high=1e-2),
    # 2.2 speed control
    Param(name="v_supply", default=12.0, unit="V", meaning="nominal supply V_s", low=0.1, high=100.0),
    Param(name="supply_tolerance", default=0.10, unit="1", meaning="supply tolerance", low=0.0, high=0.5),
    Param(name="v_drop_min", default=1.0, unit="V", meaning="smallest drop across R7 and T1 for linear control",
          low=0.0, high=50.0),
    Param(name="r3", default=39e3, unit="ohm", meaning="V_mot divider, top", low=1.0, high=1e8),
    Param(name="r4", default=10e3, unit="ohm", meaning="V_mot divider, bottom", low=1.0, high=1e8),
    Param(name="v_mot_min", default=1.7, unit="V", meaning="lowest V_mot at which the back-EMF comparators work",
          low=0.0, high=50.0, cite=TDA5144),
    Param(name="ota_headroom", default=1.7, unit="V", meaning="the OTA inputs must stay below V_P less this",
          low=0.0, high=20.0, cite=TDA5144),
    Param(name="v_p_min", default=10.8, unit="V", meaning="lowest V_P (from the same 12 V +- 10 % supply)",
          low=0.1, high=100.0, cite=ASSUMED),
    Param(name="winding_resistance", default=4.0, unit="ohm", meaning="motor winding resistance, the two windings "
          "in series the outputs drive (the note gives no motor data; a stall current above the limiters' 1 A)",
          low=0.01, high=1e4, cite=ASSUMED),
    Param(name="winding_inductance", default=2e-3, unit="H", meaning="motor winding inductance, the same two windings "
          "(the note gives no motor data)", low=1e-7, high=10.0, cite=ASSUMED),
    # 2.3 one-transistor limiter
    Param(name="v_be", default=0.8, unit="V", meaning="V_be at which T2 turns on (the note's figure)",
          low=0.1, high=2.0),
    Param(name="v_be_tc", default=-2e-3, unit="V/K", meaning="temperature coefficient of V_be (rule of thumb; no "
          "datasheet gives one)", low=-0.02, high=0.02, cite=ASSUMED),
    Param(name="i_limit", default=1.0, unit="A", meaning="the limit current wanted (the note leaves R7 'TBD')",
          low=1e-4, high=100.0, cite=ASSUMED),
    Param(name="t_low", default=0.0, unit="degC", meaning="temperature range of the drift plots, low end",
          low=-273.0, high=500.0, cite=ASSUMED),
    Param(name="t_high", default=70.0, unit="degC", meaning="temperature range of the drift plots, high end",
          low=-273.0, high=500.0, cite=ASSUMED),
    # 2.4 op-amp limiter
    Param(name="zener_voltage", default=8.2, unit="V", meaning="nominal zener voltage V_D1", low=0.1, high=100.0),
    Param(name="zener_tolerance", default=0.05, unit="1", meaning="zener tolerance (BZX79-C: 5 %)",
          low=0.0, high=0.5, cite=BZX79),
    Param(name="zener_tc", default=6.2e-3, unit="V/K", meaning="zener temperature coefficient (the note's "
          "'max. 6.2 mV/C')", low=-0.1, high=0.1),
    Param(name="temp_span", default=25.0, unit="K", meaning="temperature excursion from 25 C", low=0.0, high=300.0),
    Param(name="r10", default=5.6e3, unit="ohm", meaning="reference divider, = R12", low=1.0, high=1e8),
    Param(name="r11", default=16e3, unit="ohm", meaning="reference divider, = R13", low=1.0, high=1e8),
    Param(name="r12", default=5.6e3, unit="ohm", meaning="level-shift divider, top", low=1.0, high=1e8),
    Param(name="r13", default=16e3, unit="ohm", meaning="level-shift divider, bottom", low=1.0, high=1e8),
    Param(name="v_cs", default=0.1, unit="V", meaning="current-sense voltage at the limit", low=1e-4, high=50.0),
    Param(name="offset", default=9e-3, unit="V", meaning="op-amp input offset, maximum over temperature",
          low=0.0, high=1.0, cite=LM358),
    Param(name="offset_generic", default=10e-3, unit="V", meaning="offset 'normal for general purpose low-cost "
          "op-amps'", low=0.0, high=1.0),
    Param(name="resistor_tolerance", default=0.01, unit="1", meaning="tolerance of R9..R13 (the parts list gives "
          "1 % for R10..R13)", low=0.0, high=0.5),
    Param(name="level_shift_min", default=2.0, unit="V", meaning="op-amp inputs at least this far below the supply "
          "(common-mode range)", low=0.0, high=50.0, cite=LM358),
    # 3 decoupling
    Param(name="z_max", default=2.0, unit="ohm", meaning="largest allowed |Z| of C2", low=1e-6, high=1e6),
    Param(name="f_decoupling", default=2e6, unit="Hz", meaning="frequency at which |Z| is limited",
          low=1.0, high=1e10),
    Param(name="c2", default=10e-6, unit="F", meaning="the decoupling capacitor fitted", low=1e-15, high=1.0),
    Param(name="esr", default=1.0, unit="ohm", meaning="its equivalent series resistance at 2 MHz (illustrative "
          "electrolytic, not from a datasheet)", low=0.0, high=1e3, cite=ASSUMED),
    Param(name="esl", default=15e-9, unit="H", meaning="its lead + body inductance (illustrative)",
          low=0.0, high=1e-3, cite=ASSUMED),
)

#: Figures AN94002 relies on without printing, with the datasheet each was read from.
FACTS = {
    "cap_cd_charge": Fact((5.3e-6, 8.1e-6, 11e-6), f"{TDA5144}, CAP-CD electrical table: charge (source) current "
                          "min/typ/max; column pairing is an interpretation of a scrambled table"),
    "cap_st_levels": Fact((0.20, 2.20), f"{TDA5144}: CAP-ST switching levels 0.20 V and 2.20 V; its own example "
                          "gives C = 0.5/2 = 0.25 uF for 500 ms"),
    "cap_st_current": Fact((1.5e-6, 2.0e-6, 2.5e-6), f"{TDA5144}, CAP-ST charge/discharge current"),
    "v_mot_range": Fact((1.7, 16.0), f"{TDA5144}, V_MOT 1.7 to 16 V"),
    "bc557_vbe": Fact((0.55, 0.62, 0.70), "BC557 datasheet (one maker): V_BE(on) at 2 mA min/typ/max"),
    "bc557_vbe_10ma": Fact(0.82, "BC556-BC558 datasheets (MCC, Rectron): V_BE(on) up to 0.82 V at I_C = 10 mA, V_CE = 5 V"),
    "bzx79_vz": Fact((7.7, 8.7), f"{BZX79}: BZX79-C8V2 V_Z 7.7 to 8.7 V at 5 mA (the C series is 'about +-5 %')"),
    "bzx79_tc": Fact((0.03e-2, 0.08e-2), f"{BZX79}: temperature coefficient +0.03 to +0.08 %/K, a column printed to "
                     "one significant figure (0.08 holds up to 0.085 %/K)"),
}

#: misprints and inconsistencies of AN94002 that are not numbers
ERRATA = (
    TextErratum("an94002-t-dvcapmin", f"{NAME} 2.1.2, eq (6) and (7)",
                "one name, dV_capmin, for two quantities: the 1.4 V window in eq 6 and the noise floor in eq 7",
                "eq 6 sets dV_capmin = 2.3 - 0.9 = 1.4 V; eq 7 calls the smallest swing safe from noise dV_capmin "
                "too, and eq 8 then renames the window dV_capmax",
                "read eq 7 and 8 with dV_win (window) and dV_noise (floor); using 1.4 V in eq 7 would give a top "
                "speed 14 times too low against the 0.1 V floor the book assumes (the note gives none)"),
    TextErratum("an94002-t-160", f"{NAME} 2.1.2", "'CAP-CD >= 160 / 1800 x 6' read left to right is 0.533 uF",
                "the printed result 0.0148 uF shows the intended 160 / (1800 x 6)", "none once read as intended"),
    TextErratum("an94002-t-1v", f"{NAME} 2 and 2.3",
                "the one-transistor limiter needs 'about 1 V' (section 2) or 'about 0.8 V' (2.3)",
                "both are rough figures for the same V_be of the same transistor, which the note's two sections "
                "print 25 % apart; which holds depends on T2's collector current (the BC556-558 sheets span 0.55 V "
                "at 2 mA to 0.82 V at 10 mA)",
                "size R7 from the measured limit, not from either figure"),
    TextErratum("an94002-t-12nc", f"{NAME} 4, parts list", "two 12NC codes decode to other values than printed",
                "R14 ...53701 is 700 ohm by the decade rule, not an E-series value (printed 750 ohm, whose code is "
                "...751: a one-digit slip, possibly the OCR's); C6 ...17224 is 220 nF, the code of C5/C7/C8 (printed "
                "10 nF), but the OCR's code column holds 11 codes for the 10 capacitors, so which code belongs to C6 "
                "is uncertain. R1 ...53229 is 22 ohm as printed (9 is the decade of 10 to 99 ohm)",
                "order by the printed value, which the text confirms (C6 = 10 nF), and check the code on the "
                "reel: a 220 nF part fitted from the code would make the watchdog 22 times longer"),
    TextErratum("an94002-t-mosfet", f"{NAME} 2.3 vs 2.2 and the parts list",
                "T2 'decreases the drive for the MOSFET that determines the voltage V_mot', on a board whose series "
                "regulator is a bipolar transistor",
                "section 2.2 and the parts list make T1 a BD434 (a bipolar PNP power transistor), and the note has no "
                "MOSFET anywhere; the sentence is AN93008's (section 2.1), whose own text allows 'the transistor or "
                "power MOSFET'",
                "T2 diverts the BD434's base current (which the OTA sinks), not a gate charge: it conducts milliamps to "
                "tens of milliamps at the limit, so its V_BE is the datasheets' figure at those currents (up to "
                "0.82 V at 10 mA), not at 2 mA"),
    TextErratum("an94002-t-cadcd", f"{NAME} 2.1.2", "'CAD-CD' and 'CAD-DC' for CAP-CD and CAP-DC",
                "typographical: the same paragraphs also print CAP-CD and CAP-DC",
                "none once read as CAP-CD and CAP-DC"),
)
