"""Every number AN93008 prints in section 2 (the one-transistor, supply-referenced and zener limiters), recomputed."""
from __future__ import annotations

from ...core import Claim, Printed
from ..an94002.claims_limiter import tc_column_top  # the same BZX79-C8V2 and datasheet facts
from ..an94002.claims_limiter import zener_spread as _zener_spread
from .circuit import b_for, factor_a, r10_for, supply_worst_case
from .data import NAME

#: BZX79-C8V2 V_Z minimum at 5 mA (datasheet facts: 7.7 to 8.7 V)

T1, OP, Z = "one_transistor", "supply", "zener"

# printed numbers the note goes on to use
A_PRINTED = Printed("0.815", "1")  # A = R9/(R8+R9) of figure 3
VZ_MIN = Printed("7.7", "V")  # lowest zener voltage
A_ZENER = Printed("0.74", "1")  # A of figure 4


def _a(p):
    return factor_a(p["r8"], p["r9"])


def _v_low(p):
    return p["v_supply"] * (1 - p["supply_tolerance"])


def _resistor_only(p):
    wc = supply_worst_case(p, include=("resistors",))
    return max(-wc.rel_low, wc.rel_high)


def _drift_pct(p):
    """The zener drift over the temperature span, as a fraction of the note's 7.7 V."""
    return p["zener_tc"] * p["temp_span"] / VZ_MIN.si


def build() -> list[Claim]:
    """Every AN93008 claim: the one-transistor, the supply-referenced and the zener limiter.

    Returns
    -------
    list of Claim
        The claims, in the note's order.
    """
    return [
        Claim(id="an93008-vbe-tc", where=f"{NAME} 2.1", quantity="temperature coefficient of the one-transistor limit",
              printed=Printed("-0.25", "%/K"), compute=lambda p: p["v_be_tc"] / p["v_be"],
              reason="-2 mV/K / 800 mV (the value is right; the unit is printed as '°C' instead of '%/°C')",
              chapter=T1),
        Claim(id="an93008-offset-generic", where=f"{NAME} 2.2",
              quantity="tolerance from a 10 mV offset at V_cs = 100 mV",
              printed=Printed("10", "%"), compute=lambda p: p["offset_generic"] / p["v_cs"], reason="10 mV / 100 mV",
              chapter=OP),
        Claim(id="an93008-vsupply-min", where=f"{NAME} 2.2", quantity="lowest supply 12 V - 10 %",
              printed=Printed("10.8", "V"), compute=_v_low, reason="0.9 x 12 V", chapter=OP),
        Claim(id="an93008-level-shift", where=f"{NAME} 2.2",
              quantity="level shift at 10.8 V, V_cs = 0 (V_+ is then 8.8 V)", printed=Printed("2", "V"),
              compute=lambda p: _v_low(p) * (1 - _a(p)), reason="10.8 V x 7.5 k / 40.5 k = 2.000 V", chapter=OP),
        Claim(id="an93008-vplus", where=f"{NAME} 2.2", quantity="V_+ at 10.8 V, V_cs = 0", printed=Printed("8.8", "V"),
              compute=lambda p: _v_low(p) * _a(p), reason="10.8 V x 33 k / 40.5 k = 8.800 V", chapter=OP),
        Claim(id="an93008-factor-a", where=f"{NAME} 2.2, eq (2)", quantity="A = R9/(R8+R9)", printed=A_PRINTED,
              compute=_a, reason="33 k / 40.5 k = 0.81481", chapter=OP),
        Claim(id="an93008-vcs-at-opamp", where=f"{NAME} 2.2",
              quantity="sense signal at the op-amp input for V_cs = 100 mV", printed=Printed("81.5", "mV"),
              compute=lambda p: _a(p) * p["v_cs"], reason="0.81481 x 100 mV = 81.48 mV", chapter=OP),
        Claim(id="an93008-window-high", where=f"{NAME} 2.2", quantity="op-amp input at trip, upper",
              printed=Printed("90.5", "mV"), compute=lambda p: _a(p) * p["v_cs"] + p["offset"],
              reason="81.48 + 9 = 90.48 mV", via_rounded=lambda p: A_PRINTED.si * p["v_cs"] + p["offset"],
              chapter=OP),
        Claim(id="an93008-window-low", where=f"{NAME} 2.2", quantity="op-amp input at trip, lower",
              printed=Printed("72.5", "mV"), compute=lambda p: _a(p) * p["v_cs"] - p["offset"],
              reason="81.48 - 9 = 72.48 mV", via_rounded=lambda p: A_PRINTED.si * p["v_cs"] - p["offset"],
              chapter=OP),
        Claim(id="an93008-offset-tol", where=f"{NAME} 2.2", quantity="offset-related tolerance",
              printed=Printed("11", "%"), compute=lambda p: p["offset"] / (_a(p) * p["v_cs"]),
              reason="9 mV / 81.48 mV = 11.05 %", chapter=OP),
        Claim(id="an93008-supply-tol", where=f"{NAME} 2.2, eq (6)", quantity="supply-related tolerance",
              printed=Printed("10", "%"), compute=lambda p: p["supply_tolerance"],
              reason="V_cs is proportional to the supply (eq 6)", chapter=OP),
        Claim(id="an93008-b", where=f"{NAME} 2.2, eq (8)", quantity="B for V_cs = 100 mV at 10.8 V",
              printed=Printed("0.807", "1"), compute=lambda p: b_for(p["v_cs"], _v_low(p), _a(p)),
              reason="0.81481 x 10.7 / 10.8 = 0.80727",
              via_rounded=lambda p: b_for(p["v_cs"], _v_low(p), A_PRINTED.si), chapter=OP),
        Claim(id="an93008-r10", where=f"{NAME} 2.2", quantity="R10 for B with R11 = 33 k",
              printed=Printed("7.87", "kohm"),
              compute=lambda p: r10_for(b_for(p["v_cs"], _v_low(p), _a(p)), p["r11"]),
              reason="with A = 0.815 as printed, R10 = 7.869 k (7.878 k with A = 0.81481); 7.87 k is also the "
                     "nearest E96 value",
              via_rounded=lambda p: r10_for(b_for(p["v_cs"], _v_low(p), A_PRINTED.si), p["r11"]), chapter=OP),
        Claim(id="an93008-resistor-tol", where=f"{NAME} 2.2", quantity="resistor-related tolerance (5 % R8..R11)",
              printed=Printed("5", "%"), compute=_resistor_only,
              reason="V_cs = V (1 - B/A) is a 1 % difference of two ratios of 5 % resistors: the resistors alone move "
                     "it by several hundred per cent", chapter=OP,
              consequence="the figure 3 limiter has no dependable trip point at all with 5 % resistors; see "
                          "'Choosing R7 and R9' for what the tolerances must be", method_wrong=True),
        Claim(id="an93008-total-supply", where=f"{NAME} 2.2", quantity="total tolerance, 1.11 x 1.1 x 1.05",
              printed=Printed("28", "%"), compute=lambda p: 1.11 * 1.1 * 1.05 - 1, reason="1.11 x 1.1 x 1.05 = 1.2821",
              chapter=OP),
        Claim(id="an93008-vz-min", where=f"{NAME} 2.2", quantity="lowest zener voltage 0.95 x 8.2 V", printed=VZ_MIN,
              compute=lambda p: 0.95 * 8.2, truncated=True,
              reason="0.95 x 8.2 V = 7.79 V, printed 7.7 V: truncated to one decimal (AN94002 prints 7.79 V for the "
                     "same product). 7.7 V is also the BZX79-C8V2's datasheet minimum (V_Z 7.7 to 8.7 V at 5 mA, "
                     "datasheet facts), the value the level shift needs: the part spreads +-6.1 %, not +-5 %",
              chapter=Z, consequence="none for the level shift, which the note sized at the right 7.7 V; the +-5 % "
                                     "written beside it understates the zener's share of the trip tolerance (see "
                                     "an93008-zener-spread)"),
        Claim(id="an93008-zener-spread", where=f"{NAME} 2.2 vs BZX79 datasheet",
              quantity="zener tolerance of the BZX79-C8V2 ('8.2 V +-5 % (BZX79 C 8V2)')", printed=Printed("5", "%"),
              chapter=Z, compute=_zener_spread, basis="BZX79 datasheet",
              reason="the datasheet's V_Z limits, 7.7 and 8.7 V at 5 mA, are 8.2 V -6.1 % and +6.1 %; +-5 % is the "
                     "C series' nominal band, not the part's limits (as AN94002 2.4, an94002-zener-spread)",
              consequence="the zener's share of the trip tolerance is +-6.1 %, not +-5 % (V_cs is proportional to "
                           "the zener voltage); with the note's +-2 % drift it is +-8.1 %, not +-7 % (see "
                           "an93008-zener-share)"),
        Claim(id="an93008-factor-a-zener", where=f"{NAME} 2.2",
              quantity="A for a 2 V shift at the lowest zener voltage",
              printed=A_ZENER, compute=lambda p: 1 - p["level_shift"] / VZ_MIN.si,
              reason="1 - 2 V / 7.7 V = 0.7403, with the note's own lowest zener voltage (an93008-vz-min; "
                     "0.95 x 8.2 = 7.79 V would give 0.7433, also 0.74)", chapter=Z),
        Claim(id="an93008-offset-tol-zener", where=f"{NAME} 2.2", quantity="offset-related tolerance with A = 0.74",
              printed=Printed("12", "%"), compute=lambda p: p["offset"] / (A_ZENER.si * p["v_cs"]),
              reason="9 mV / 74 mV = 12.16 %", chapter=Z),
        Claim(id="an93008-zener-drift", where=f"{NAME} 2.2", quantity="zener drift over 25 C +- 25 C",
              printed=Printed("150", "mV"), compute=lambda p: p["zener_tc"] * p["temp_span"],
              reason="6.2 mV/K x 25 K = 155 mV, truncated to two figures (rounding would give 160 mV)",
              truncated=True, chapter=Z),
        Claim(id="an93008-zener-drift-pct", where=f"{NAME} 2.2", quantity="zener drift relative to 7.7 V",
              printed=Printed("2", "%"), compute=_drift_pct, reason="155 mV / 7.7 V = 2.01 %", chapter=Z),
        Claim(id="an93008-zener-tc", where=f"{NAME} 2.2 vs BZX79 datasheet",
              quantity="largest zener temperature coefficient ('max. 6.2 mV/°C')", printed=Printed("6.2", "mV/K"),
              chapter=Z, relation="<=", compute=lambda p: tc_column_top(p["zener_voltage"]), basis="BZX79 datasheet",
              reason="6.2 mV/K at 8.2 V is 0.076 %/K, inside the datasheet's +0.03 to +0.08 %/K column, which is "
                     "printed to one figure (as AN94002 2.4)"),
        Claim(id="an93008-zener-total", where=f"{NAME} 2.2", quantity="zener tolerance with drift, 5 % part",
              printed=Printed("7", "%"), compute=lambda p: p["zener_tolerance"] + round(_drift_pct(p), 2),
              reason="5 % + 2 %, added linearly", chapter=Z),
        Claim(id="an93008-zener-share", where=f"{NAME} 2.2 vs BZX79 datasheet",
              quantity="zener tolerance with drift ('together with a zener diode tolerance of +-5 % ... then "
                       "+-7 %'), with the part's datasheet spread",
              printed=Printed("7", "%"), chapter=Z, basis="BZX79 datasheet", same_fact="an93008-zener-spread",
              compute=lambda p: _zener_spread(p) + _drift_pct(p),
              reason="the BZX79-C8V2 spreads +-6.10 % (7.7 to 8.7 V), not +-5 %; with the note's drift, 155 mV / "
                     "7.7 V = 2.01 %, added linearly as the note does: +-8.11 %",
              consequence="the zener's share of the trip tolerance is about +-8.1 %, not +-7 %, and the note's total "
                          "becomes 1.12 x 1.081 x 1.05 = +-27 %, not "
                          "+-26 %; the budget's bigger faults are its resistor term (an93008-resistor-tol)"),
        Claim(id="an93008-total-zener", where=f"{NAME} 2.2", quantity="total tolerance, 1.12 x 1.07 x 1.05",
              printed=Printed("26", "%"), compute=lambda p: 1.12 * 1.07 * 1.05 - 1,
              reason="1.12 x 1.07 x 1.05 = 1.2583",
              chapter=Z),
        Claim(id="an93008-zener-total-a", where=f"{NAME} 2.2",
              quantity="zener tolerance with drift, 1 % part (BZX79-A)", printed=Printed("3", "%"),
              compute=lambda p: p["zener_tolerance_a"] + round(_drift_pct(p), 2), reason="1 % + 2 %", chapter=Z),
        Claim(id="an93008-total-zener-a", where=f"{NAME} 2.2",
              quantity="total tolerance with a 1 % zener, 1.12 x 1.03 x 1.05", printed=Printed("21", "%"),
              compute=lambda p: 1.12 * 1.03 * 1.05 - 1, reason="1.12 x 1.03 x 1.05 = 1.2113", chapter=Z),
    ]
