"""LM4651/LM4652 datasheet: the device figures (with where they are printed), the Example Design's
values and the textual errata."""
from __future__ import annotations

from ...core import Fact, Param, ReadingNote, TextErratum

NAME = "LM4651/LM4652"
DATASHEET = "LM4651/LM4652 datasheet (National Semiconductor, 2000)"

#: the device figures the models and the Example Design rely on
FACTS = {
    "t_rise": Fact(25e-9, f"{DATASHEET}, LM4652 electrical characteristics: t_r, typical"),
    "t_fall": Fact(26e-9, f"{DATASHEET}, LM4652 electrical characteristics: t_f, typical"),
    "t_overmod": Fact(310e-9, f"{DATASHEET}, LM4651 electrical characteristics: over-modulation protection time "
                              "T_OVERMOD, typical (the Example Design uses 350 ns)"),
    "rds_on_hot": Fact(0.230, f"{DATASHEET}, Example Design: R_DS(on) 'at 100 C' (the LM4652 table gives 0.200 ohm "
                              "typical and 0.300 ohm maximum at 25 C only)"),
    "theta_jc": Fact({"TF": 2.0, "T": 1.0}, f"{DATASHEET}, LM4652 thermal resistance junction to case, K/W: "
                                            "isolated (TF) and non-isolated (T) TO-220"),
    "tj_max": Fact(150.0, f"{DATASHEET}, LM4652 absolute maximum junction temperature, C"),
    "f_min": Fact(50e3, f"{DATASHEET}, LM4651: switching frequency '50 kHz to 225 kHz'"),
    "f_max": Fact(225e3, f"{DATASHEET}, LM4651: switching frequency '50 kHz to 225 kHz'"),
    "p_driver": Fact(1.0, f"{DATASHEET}, system table: the LM4651's own dissipation, the example's 22 W system less "
                          "21 W in the LM4652"),
}


def _fact(name: str, key: str, unit: str, meaning: str, low: float, high: float) -> Param:
    """A parameter whose default is a device figure (one number, typed once, with its citation)."""
    return Param(name=name, default=FACTS[key].value, unit=unit, meaning=meaning, low=low, high=high,
                 cite=FACTS[key].cite)


#: the Example Design's values (125 W into 4 ohm, 3 V rms in, 50 C ambient)
PARAMETERS = (
    Param(name="p_out", default=125.0, unit="W", meaning="output power", low=1e-3, high=1000.0),
    Param(name="r_load", default=4.0, unit="ohm", meaning="load resistance", low=0.5, high=100.0),
    _fact("t_rise", "t_rise", "s", "LM4652 rise time t_r", 1e-10, 1e-6),
    _fact("t_fall", "t_fall", "s", "LM4652 fall time t_f", 1e-10, 1e-6),
    Param(name="t_overmod_example", default=350e-9, unit="s", meaning="over-modulation time the Example Design "
          "puts in eq 9", low=0.0, high=5e-6),
    _fact("t_overmod_table", "t_overmod", "s", "over-modulation time T_OVERMOD, LM4651 table (typical)", 0.0, 5e-6),
    _fact("rds_on_hot", "rds_on_hot", "ohm", "LM4652 on-resistance R_DS(on) when hot", 1e-3, 10.0),
    Param(name="t_ambient", default=50.0, unit="degC", meaning="ambient temperature (Celsius)", low=-55.0, high=150.0),
    Param(name="theta_cs", default=0.2, unit="K/W", meaning="case-to-sink thermal resistance (thermal grease)",
          low=0.0, high=10.0),
    _fact("tj_max", "tj_max", "degC", "largest junction temperature (Celsius)", 25.0, 200.0),
    _fact("p_driver", "p_driver", "W", "LM4651 driver's own dissipation", 0.0, 20.0),
    Param(name="f_sw", default=125e3, unit="Hz", meaning="switching frequency", low=1e3, high=1e6),
    Param(name="r_dly", default=5e3, unit="ohm", meaning="dead-time resistor R_DLY", low=0.0, high=1e6),
    Param(name="r_sckt", default=100e3, unit="ohm", meaning="current-limit resistor R_SCKT", low=1e3, high=1e8),
    Param(name="t_start", default=1.0, unit="s", meaning="start-up (mute) time", low=1e-3, high=100.0),
    Param(name="v_in_rms", default=3.0, unit="V", meaning="input voltage for full power (rms)", low=1e-3,
          high=100.0),
    Param(name="rf11", default=620e3, unit="ohm", meaning="feedback resistor R_f11", low=1.0, high=1e8),
    Param(name="rf12", default=62e3, unit="ohm", meaning="feedback resistor R_f12", low=1.0, high=1e8),
    Param(name="r1", default=20e3, unit="ohm", meaning="input resistor R1", low=1.0, high=1e8),
    Param(name="c_start", default=10e-6, unit="F", meaning="start-up capacitor C_START fitted", low=1e-9,
          high=1e-2),
)

ERRATA = (
    TextErratum("lm4651-t-50uf", f"{NAME}, Output Stage Filtering", "'a 50 uF inductor'",
                "the Example Design and figure 1 use 50 uH inductors", "none once read as uH"),
    TextErratum("lm4651-t-rds", f"{NAME}, Example Design", "R_DS(on) 'at 100 C' = 0.230 ohm is not in the table",
                "the LM4652 table gives 200 mOhm typical and 300 mOhm maximum at 25 C only",
                "0.230 ohm is optimistic against the 300 mOhm maximum: conduction loss may be 30 % higher"),
    TextErratum("lm4651-t-r1", f"{NAME}, DC offset vs Example Design vs figure 1",
                "R1 is 25 k in the DC-offset section, 20 k in the Example Design and 4.7 k in figure 1",
                "20 k and 4.7 k are an explicit alternative of the Example Design ('If a 20k input impedance is not "
                "required ... R1's value set to 4.7k'); only the DC-offset section's 25 k, beside a 1 uF capacitor, "
                "matches neither",
                "choose C_IN for the R1 you fit (the Example warns that a lower R1 needs a larger C_IN): 1 uF is "
                "paired only with the 25 k (6.4 Hz); figure 1's C_IN did not survive the OCR"),
    TextErratum("lm4651-t-frange", f"{NAME}, Features, Oscillator Control, pin 16 and the LM4651 table",
                "the switching-frequency range is printed four ways: 50 to 200 kHz (Features), 50 to 225 kHz "
                "(Oscillator Control), 75 to 225 kHz for R_OSC = 15.5 k to 0 (pin 16) and 65 to 200 kHz for "
                "R_OSC = 15 k to 0 (LM4651 table)",
                "eq 5 gives 51.3 to 250 kHz over 15.5 k to 0; a larger R_OSC runs slower, so the table's 65 kHz at "
                "15 k and pin 16's 75 kHz at 15.5 k cannot both hold (see lm4651-f-pin-15k5 and lm4651-f-pin-0)",
                "the book takes 50 to 225 kHz (Oscillator Control) as the usable range and the table's typical "
                "points for eq 5's spread; above 200 kHz, measure", same_fact="lm4651-f-15k"),
    TextErratum("lm4651-t-170w", f"{NAME}, title and Key Specifications",
                "'170 W' output power into 4 ohm at < 10 % THD, with no switching frequency stated",
                "the system table, specified at f_SW = 125 kHz unless stated, gives 155 W at 10 % THD (125 W at "
                "1 %); 170 W is its f_SW = 75 kHz row",
                "at the recommended 125 to 145 kHz expect 155 W at 10 % THD and 125 W at 1 %; 170 W needs 75 kHz, "
                "with the worse THD+N below 10 W that the datasheet warns of"),
    TextErratum("lm4651-t-eq-labels", f"{NAME}, Example Design",
                "the gain equation, called 'Equation (12)' in the text, is labelled '(3)', and the next line '(4)'",
                "eq 3 is the current limit and eq 4 the dead time; the Example's own labels (3) and (4) name two "
                "other equations",
                "none once the gain formula is read as eq 12"),
    TextErratum("lm4651-t-c1-value", f"{NAME}, Recommendations for Critical External Components vs items 11 and "
                "Output Stage Filtering", "the components table gives 'C1 & C_BYP 5uF - 10uF'; the text gives C1 as 0.1 "
                "to 1 uF three times",
                "External Components item 11, Output Stage Filtering and the Example Design all give C1 0.1 to 1 uF "
                "(2 to 20 % of C_BYP = 5 uF); the table's '&' elsewhere means both parts take the value ('C_B1 & "
                "C_BT 0.1uF')",
                "fit C1 = 0.1 to 1 uF: the table most likely groups C1 with C_BYP under one film-capacitor supplier "
                "(5 uF is the text's C_BYP, 10 uF its output-to-ground alternative of twice C_BYP); 5 to 10 uF per "
                "output would lower the output filter's corner from 7.1 kHz (C_BYP alone) to 5.8 or 5.0 kHz"),
    TextErratum("lm4651-t-torque", f"{NAME}, Heat Sinking", "a recommended maximum screw torque of '40 inch-lbs. or "
                "3.3 foot-lbs.' for the 15-lead TO-220 package",
                "40 in-lb is 4.5 N m (and 3.3 ft-lb, so not a slip of one figure); makers' mounting notes for TO-220 "
                "and the comparable 15-lead Multiwatt tab give at most 0.7 to 0.8 N m (STMicroelectronics AN260 and "
                "TN1225), and the datasheet's next sentences warn that over-tightening warps the package",
                "tighten to the package maker's 0.55 to 0.7 N m (about 5 to 6 in-lb); 40 in-lb strips an M3 or 6-32 "
                "thread or warps the tab, and a warped tab raises theta_CS, which the Example budgets at 0.2 K/W"),
    TextErratum("lm4651-t-esd-pins", f"{NAME}, Absolute Maximum Ratings vs the LM4652 pin table",
                "the ESD rating names the LM4652's 'pins 2,6,10,11'; the pin table makes pin 11 'NC' and pin 14 HG1, "
                "the fourth gate input beside LG1 (2), LG2 (6) and HG2 (10)",
                "either the label's 11 is an OCR or printing slip for 14, or one of the two tables is wrong (the pin "
                "table has another slip, lm4651-t-pin15); the sources cannot decide which",
                "treat all four gate inputs, pins 2, 6, 10 and 14, as the ESD-rated pins, and handle the LM4652 as an "
                "ESD-sensitive part throughout"),
    TextErratum("lm4651-t-roffset", f"{NAME}, system table V_OS vs Output Offset Voltage Minimization",
                "the output offset of 0.7 V is specified at 'R_OFFSET = 0 Ω'",
                "R_OFFSET is the 1.8 M divider from the +6 V output to the input; read literally, 0 ohm puts 6 V on "
                "the input and rails the output (6 V x 7.95 = 48 V), and the datasheet uses '0 Ω' literally elsewhere "
                "(R_DLY, R_OSC). The 1.8 M (3.29 uA into 25 k, 82 mV, 0.65 V at the output) cancels about the 0.7 V: "
                "the condition means the resistor not fitted",
                "read the condition as R_OFFSET not fitted; expect about 0.7 V of output offset (175 mA into 4 ohm) "
                "until the 1.8 M is in place"),
    TextErratum("lm4651-t-theta-ja", f"{NAME}, thermal resistances vs note 3",
                "the LM4651's junction-to-ambient resistance is 52 K/W (thermal table) and 62 K/W (note 3)",
                "the thermal table lists 'LM4651 N Package theta_JA 52 C/W'; note 3 derates the LM4651 'based on "
                "... theta_JA = 62 C/W'",
                "derate with 62 K/W, the safe side: at the LM4651's 1 W the die runs 62 K above ambient, not 52 K "
                "(112 C at the example's 50 C)"),
    TextErratum("lm4651-t-ilimit", f"{NAME}, eq (3), pin 18 and Example Design vs LM4652 ratings",
                "the short-circuit limit can only be set at or above 10 A, the LM4652's absolute maximum output "
                "current",
                "eq 3 gives 10 A only with R_SCKT open and more with any R_SCKT (11 A with the example's 100 k; pin "
                "18: 'Minimum setting is 10A'); the absolute maximum ratings give the LM4652's output current as "
                "10 A (the OCR separated names from values: 10 A is the only current among them), and the LM4652 "
                "table's saturation drain current is 8 A minimum, 10 A typical",
                "the limit guards against a short, not the rating: the example's 11 A is 10 % above the absolute "
                "maximum, and the advice to raise it for loads below 4 ohm goes further; keep the output current "
                "plus the inductor ripple below 10 A by design, as the Example Design asks"),
    TextErratum("lm4651-t-pin15", f"{NAME}, LM4652 and LM4651 pin descriptions",
                "the LM4652 pin table names both pin 7 and pin 15 'VO2'",
                "the LM4651's pin 14 (FBK1) is to be 'connected to the feedback filter from V_O1 (pin 15 on the "
                "LM4652)' and pin 19 (FBK2) to 'V_O2 (pin 7)': pin 15 is VO1 (the OCR may have misread a subscript)",
                "read pin 15 as VO1 feeding FBK1; swapping FBK1 and FBK2 would invert the feedback"),
    TextErratum("lm4651-t-gain-r", f"{NAME}, Error Amplifier, components table and Example Design",
                "which resistors set the gain: 'R_f and R1' (Error Amplifier), R_f 'sets the gain and bandwidth' "
                "(components table), R1, R2, R_f11 and R_f12 (eq 12); and the Example inserts R_f and V_CC into "
                "eq 12, which contains neither",
                "eq 12 as printed in the components table and the Example Design has only R1, R2, R_f11 and R_f12, "
                "and with them reproduces the Example's 7.5 (R2 = 0.7 R1)",
                "the error amplifier's own gain is set by R_f and R1, so the Error Amplifier text may be right about "
                "that stage; the slips are the components table calling it the system's gain and the Example "
                "inserting R_f and V_CC into eq 12. Use eq 12 for the gain and eq 7 (R_f C_f) for the error "
                "amplifier's pole, and confirm the gain on the built amplifier"),
)

#: what is not an error of the datasheet: how the book reads it
READING_NOTES = (
    ReadingNote("lm4651-t-standby", f"{NAME}, Key Specifications, system table and Standby Function",
                "standby attenuation printed as '>100dB (Min)', '>115 dB' and '(>120dB)'",
                "three lower bounds (a guaranteed minimum, a typical in the system table, a figure in prose) that "
                "agree; the book designs with the guaranteed 100 dB"),
    ReadingNote("lm4651-t-supply", f"{NAME}, Example Design", "the +-20 V supply comes from a graph the OCR lost",
                "the electrical tables are specified at +-20 V, 4 ohm and 125 kHz, consistent with the Example's "
                "choice; the book takes +-20 V"),
    ReadingNote("lm4651-pd-75k", f"{NAME}, system table, P_d at f_SW = 75 kHz, P_O = 135 W",
                "eq 9 and eq 10 against the table's 75 kHz row",
                "the Example Design's method (eq 9 with its 350 ns, eq 10, 2 x 0.230 ohm, 1 W in the LM4651) gives "
                "20.7 W where the table prints 22 W (20.3 W with the table's 310 ns): a 6 % miss of an empirical "
                "estimate against a measured typical, which the datasheet never says eq 9 reproduces. Where the "
                "operating point is a table row, the book sizes the heat sink from the table"),
)
