"""AN93008: current limiter for the motor-control ICs of the TDA514x family (Philips, R. Galema, 1995).

The one-transistor limiter (as in AN94002 2.3), the op-amp limiter with a supply-referenced level
shift (figure 3, eq 1 to 8) and the improved one bridged by a zener (figure 4, as AN94002 figure 3).
Names follow AN93008: R8/R9 the level shift (A = R9/(R8+R9)), R10/R11 the reference (B).
"""
from __future__ import annotations

import functools

from . import an94002, tolerance
from .examples import Example, Printed, TextErratum, evaluate_all

NOTE = "AN93008"

DEFAULTS: dict = {
    "v_supply": 12.0, "supply_tolerance": 0.10,
    "r8": 7.5e3, "r9": 33e3, "r10": 7.87e3, "r11": 33e3,
    "v_cs": 0.1, "offset": 9e-3, "offset_generic": 10e-3,
    "resistor_tolerance": 0.05,
    "v_zener": 8.2, "zener_tolerance": 0.05, "zener_tolerance_a": 0.01, "zener_tc": 6.2e-3, "temp_span": 25.0,
    "level_shift": 2.0,
    "v_be": 0.8, "v_be_tc": -2e-3,
}


def params(**overrides) -> dict:
    p = dict(DEFAULTS)
    p.update(overrides)
    return p


def factor_a(r8, r9):
    """A = R9 / (R8 + R9) (eq 1 to 3)."""
    return r9 / (r8 + r9)


def factor_b(r10, r11):
    """B = R11 / (R10 + R11) (eq 4)."""
    return r11 / (r10 + r11)


def v_cs_trip(v_supply, r8, r9, r10, r11, offset=0.0):
    """Eq 6 with the offset referred back: V_cs = V (1 - B/A) - V_os / A (works on numpy arrays)."""
    return an94002.v_cs_trip(v_supply, 0.0, r10, r11, r8, r9, offset)


def b_for(v_cs, v_supply, a):
    """Eq 7: B = A (V - V_cs) / V."""
    return a * (v_supply - v_cs) / v_supply


def r10_for(b, r11):
    """B = R11 / (R10 + R11) solved for R10."""
    return r11 * (1 - b) / b


def supply_worst_case(p: dict):
    """Exact worst case of the figure 3 trip voltage: supply, every resistor and the offset at once."""
    v = p["v_supply"]
    nominal = dict(v_supply=v, r8=p["r8"], r9=p["r9"], r10=p["r10"], r11=p["r11"], offset=0.0)
    spread = {k: tolerance.symmetric(p[k], p["resistor_tolerance"]) for k in ("r8", "r9", "r10", "r11")}
    spread["v_supply"] = tolerance.symmetric(v, p["supply_tolerance"])
    spread["offset"] = (-p["offset"], p["offset"])
    return tolerance.corners(v_cs_trip, nominal, spread)


def _a(p):
    return factor_a(p["r8"], p["r9"])


def _v_low(p):
    return p["v_supply"] * (1 - p["supply_tolerance"])


def _resistor_only(p):
    wc = tolerance.corners(v_cs_trip, dict(v_supply=p["v_supply"], r8=p["r8"], r9=p["r9"], r10=p["r10"], r11=p["r11"],
                                           offset=0.0),
                           {k: tolerance.symmetric(p[k], p["resistor_tolerance"]) for k in ("r8", "r9", "r10", "r11")})
    return max(-wc.rel_low, wc.rel_high)


def examples_list() -> list[Example]:
    T1, OP, Z = "one_transistor", "supply", "zener"
    deps_a = ("r8", "r9")
    return [
        Example("an93008-vbe-tc", f"{NOTE} 2.1", "temperature coefficient of the one-transistor limit",
                Printed("-0.25", "%/K"), lambda p: p["v_be_tc"] / p["v_be"],
                "-2 mV/K / 800 mV (the value is right; the unit is printed as '°C' instead of '%/°C')",
                ("v_be", "v_be_tc"), chapter=T1),
        Example("an93008-offset-generic", f"{NOTE} 2.2", "tolerance from a 10 mV offset at V_cs = 100 mV",
                Printed("10", "%"), lambda p: p["offset_generic"] / p["v_cs"], "10 mV / 100 mV",
                ("offset_generic", "v_cs"), chapter=OP),
        Example("an93008-vsupply-min", f"{NOTE} 2.2", "lowest supply 12 V - 10 %", Printed("10.8", "V"), _v_low,
                "0.9 x 12 V", ("v_supply", "supply_tolerance"), chapter=OP),
        Example("an93008-level-shift", f"{NOTE} 2.2", "level shift at 10.8 V, V_cs = 0 (V_+ is then 8.8 V)",
                Printed("2", "V"), lambda p: _v_low(p) * (1 - _a(p)), "10.8 V x 7.5 k / 40.5 k = 2.000 V",
                deps_a + ("v_supply", "supply_tolerance"), chapter=OP),
        Example("an93008-vplus", f"{NOTE} 2.2", "V_+ at 10.8 V, V_cs = 0", Printed("8.8", "V"),
                lambda p: _v_low(p) * _a(p), "10.8 V x 33 k / 40.5 k = 8.800 V", deps_a + ("v_supply", "supply_tolerance"),
                chapter=OP),
        Example("an93008-factor-a", f"{NOTE} 2.2, eq (2)", "A = R9/(R8+R9)", Printed("0.815", "1"), _a,
                "33 k / 40.5 k = 0.81481", deps_a, chapter=OP),
        Example("an93008-vcs-at-opamp", f"{NOTE} 2.2", "sense signal at the op-amp input for V_cs = 100 mV",
                Printed("81.5", "mV"), lambda p: _a(p) * p["v_cs"], "0.81481 x 100 mV = 81.48 mV", deps_a + ("v_cs",),
                chapter=OP),
        Example("an93008-window-high", f"{NOTE} 2.2", "op-amp input at trip, upper", Printed("90.5", "mV"),
                lambda p: _a(p) * p["v_cs"] + p["offset"], "81.48 + 9 = 90.48 mV", deps_a + ("v_cs", "offset"),
                via_rounded=lambda p: 0.0815 + p["offset"], chapter=OP),
        Example("an93008-window-low", f"{NOTE} 2.2", "op-amp input at trip, lower", Printed("72.5", "mV"),
                lambda p: _a(p) * p["v_cs"] - p["offset"], "81.48 - 9 = 72.48 mV", deps_a + ("v_cs", "offset"),
                via_rounded=lambda p: 0.0815 - p["offset"], chapter=OP),
        Example("an93008-offset-tol", f"{NOTE} 2.2", "offset-related tolerance", Printed("11", "%"),
                lambda p: p["offset"] / (_a(p) * p["v_cs"]), "9 mV / 81.48 mV = 11.05 %", deps_a + ("v_cs", "offset"),
                chapter=OP),
        Example("an93008-supply-tol", f"{NOTE} 2.2, eq (6)", "supply-related tolerance", Printed("10", "%"),
                lambda p: p["supply_tolerance"], "V_cs is proportional to the supply (eq 6)", ("supply_tolerance",),
                chapter=OP),
        Example("an93008-b", f"{NOTE} 2.2, eq (8)", "B for V_cs = 100 mV at 10.8 V", Printed("0.807", "1"),
                lambda p: b_for(p["v_cs"], _v_low(p), _a(p)), "0.81481 x 10.7 / 10.8 = 0.80727",
                deps_a + ("v_cs", "v_supply", "supply_tolerance"), via_rounded=lambda p: 0.815 * 10.7 / 10.8, chapter=OP),
        Example("an93008-r10", f"{NOTE} 2.2", "R10 for B with R11 = 33 k", Printed("7.87", "kohm"),
                lambda p: r10_for(b_for(p["v_cs"], _v_low(p), _a(p)), p["r11"]),
                "with A = 0.815 as printed, R10 = 7.869 k (7.878 k with A = 0.81481); 7.87 k is also the nearest E96 value",
                deps_a + ("v_cs", "v_supply", "supply_tolerance", "r11"),
                via_rounded=lambda p: r10_for(b_for(p["v_cs"], _v_low(p), 0.815), p["r11"]), chapter=OP),
        Example("an93008-resistor-tol", f"{NOTE} 2.2", "resistor-related tolerance (5 % R8..R11)", Printed("5", "%"),
                _resistor_only,
                "V_cs = V (1 - B/A) is a 1 % difference of two ratios of 5 % resistors: the resistors alone move it "
                "by several hundred per cent",
                ("r8", "r9", "r10", "r11", "resistor_tolerance", "v_supply"), chapter=OP,
                consequence="the figure 3 limiter has no dependable trip point at all with 5 % resistors; see "
                            "'Choosing R7 and R9' for what the tolerances must be"),
        Example("an93008-total-supply", f"{NOTE} 2.2", "total tolerance, 1.11 x 1.1 x 1.05", Printed("28", "%"),
                lambda p: 1.11 * 1.1 * 1.05 - 1, "1.11 x 1.1 x 1.05 = 1.2821", (), chapter=OP),
        Example("an93008-vz-min", f"{NOTE} 2.2", "lowest zener voltage 0.95 x 8.2 V", Printed("7.7", "V"),
                lambda p: p["v_zener"] * (1 - p["zener_tolerance"]), "0.95 x 8.2 V = 7.79 V, which rounds to 7.8 V",
                ("v_zener", "zener_tolerance"), chapter=Z,
                consequence="small: the level shift designed at 7.7 V is 1 % larger than needed"),
        Example("an93008-factor-a-zener", f"{NOTE} 2.2", "A for a 2 V shift at the lowest zener voltage",
                Printed("0.74", "1"), lambda p: 1 - p["level_shift"] / (p["v_zener"] * (1 - p["zener_tolerance"])),
                "1 - 2 / 7.79 = 0.7433 (1 - 2/7.7 = 0.7403)", ("level_shift", "v_zener", "zener_tolerance"), chapter=Z),
        Example("an93008-offset-tol-zener", f"{NOTE} 2.2", "offset-related tolerance with A = 0.74", Printed("12", "%"),
                lambda p: p["offset"] / (0.74 * p["v_cs"]), "9 mV / 74 mV = 12.16 %", ("offset", "v_cs"), chapter=Z),
        Example("an93008-zener-drift", f"{NOTE} 2.2", "zener drift over 25 C +- 25 C", Printed("150", "mV"),
                lambda p: p["zener_tc"] * p["temp_span"], "6.2 mV/K x 25 K = 155 mV", ("zener_tc", "temp_span"), chapter=Z),
        Example("an93008-zener-drift-pct", f"{NOTE} 2.2", "zener drift relative to 7.7 V", Printed("2", "%"),
                lambda p: p["zener_tc"] * p["temp_span"] / 7.7, "155 mV / 7.7 V = 2.01 %", ("zener_tc", "temp_span"),
                chapter=Z),
        Example("an93008-zener-total", f"{NOTE} 2.2", "zener tolerance with drift, 5 % part", Printed("7", "%"),
                lambda p: p["zener_tolerance"] + round(p["zener_tc"] * p["temp_span"] / 7.7, 2),
                "5 % + 2 %, added linearly", ("zener_tolerance", "zener_tc", "temp_span"), chapter=Z),
        Example("an93008-total-zener", f"{NOTE} 2.2", "total tolerance, 1.12 x 1.07 x 1.05", Printed("26", "%"),
                lambda p: 1.12 * 1.07 * 1.05 - 1, "1.12 x 1.07 x 1.05 = 1.2583", (), chapter=Z),
        Example("an93008-zener-total-a", f"{NOTE} 2.2", "zener tolerance with drift, 1 % part (BZX79-A)", Printed("3", "%"),
                lambda p: p["zener_tolerance_a"] + round(p["zener_tc"] * p["temp_span"] / 7.7, 2), "1 % + 2 %",
                ("zener_tolerance_a", "zener_tc", "temp_span"), chapter=Z),
        Example("an93008-total-zener-a", f"{NOTE} 2.2", "total tolerance with a 1 % zener, 1.12 x 1.03 x 1.05",
                Printed("21", "%"), lambda p: 1.12 * 1.03 * 1.05 - 1, "1.12 x 1.03 x 1.05 = 1.2113", (), chapter=Z),
    ]


def examples(p: dict | None = None, chapter: str | None = None) -> list[dict]:
    return evaluate_all(examples_list(), p, DEFAULTS, chapter)


def equations() -> list:
    return list(_equations())


@functools.lru_cache(maxsize=1)
def _equations() -> tuple:
    import sympy as sp
    from sympy.physics import units as u

    from .registry import Equation

    V, OHM = u.volt, u.ohm
    Vs, Vcs, Vp, Vm, R8, R9, R10, R11 = sp.symbols(r"V_{supply} V_{cs} V_{+} V_{-} R_8 R_9 R_{10} R_{11}", positive=True)
    A, B = sp.symbols("A B", positive=True)
    vp = sp.solve(sp.Eq((Vs - Vcs - Vp) / R8, Vp / R9), Vp)[0]  # KCL at V+: R8 from V_s - V_cs, R9 to ground
    vm = sp.solve(sp.Eq((Vs - Vm) / R10, Vm / R11), Vm)[0]
    vcs = sp.solve(sp.Eq(vp, vm), Vcs)[0]
    units = {Vs: V, Vcs: V, R8: OHM, R9: OHM, R10: OHM, R11: OHM}
    sub = {A: R9 / (R8 + R9), B: R11 / (R10 + R11)}
    eqs = [
        Equation(id="an93008-eq1", source=f"{NOTE} 2.2, eq (1)", title="Level-shifted sense voltage at V+",
                 lhs=Vp, lhs_unit=V, printed=Vs * R9 / (R8 + R9) - Vcs * R9 / (R8 + R9), derived=vp, units=units,
                 printed_tex=r"V_{supply} \frac{R_9}{R_8 + R_9} - V_{cs} \frac{R_9}{R_8 + R_9}",
                 law="KCL at V+: R8 from V_supply - V_cs, R9 to ground"),
        Equation(id="an93008-eq2", source=f"{NOTE} 2.2, eq (2)", title="Eq 1 with R8 = 7.5 k, R9 = 33 k",
                 lhs=Vp, lhs_unit=V, printed=sp.Rational("0.815") * (Vs - Vcs), derived=vp, units=units,
                 values={R8: 7500 * OHM, R9: 33000 * OHM},
                 printed_tex=r"0.815 \, V_{supply} - 0.815 \, V_{cs}", law="eq 1 evaluated",
                 note="0.815 is 33/40.5 = 0.81481 rounded."),
        Equation(id="an93008-eq4", source=f"{NOTE} 2.2, eq (4)", title="Reference at V-", lhs=Vm, lhs_unit=V,
                 printed=Vs * R11 / (R10 + R11), derived=vm, units=units, law="KCL at V-: R10 from V_supply, R11 to ground"),
        Equation(id="an93008-eq6", source=f"{NOTE} 2.2, eq (3) to (6)", title="Sense voltage at the trip point",
                 lhs=Vcs, lhs_unit=V, printed=(Vs - B / A * Vs).subs(sub), derived=vcs, units=units,
                 printed_tex=r"V_{supply} - \frac{B}{A} V_{supply}", law="virtual short V+ = V- (eq 5) solved for V_cs"),
        Equation(id="an93008-eq7", source=f"{NOTE} 2.2, eq (7)", title="B for a wanted V_cs", lhs=B,
                 lhs_unit=sp.Integer(1), printed=(A * (Vs - Vcs) / Vs).subs(sub),
                 derived=sp.solve(sp.Eq(Vs - B / A * Vs, Vcs), B)[0].subs(sub), units=units,
                 printed_tex=r"A \frac{V_{supply} - V_{cs}}{V_{supply}}", law="eq 6 solved for B"),
    ]
    for e in eqs:
        e.chapter = "supply"
    return tuple(eqs)


TEXT_ERRATA = [
    TextErratum("an93008-t-unit", f"{NOTE} 2.1", "the one-transistor limit's drift is printed '-0.25 °C'",
                "-2 mV/K over 800 mV is -0.25 %/K; AN94002 2.3 prints the same sentence with '%/°C'",
                "none once read as %/K"),
    TextErratum("an93008-t-fig4", f"{NOTE} 2.2, figure 4", "figure 4's resistor values did not survive the OCR",
                "the text gives A = 0.74 and a 2 V shift; AN94002 figure 3 is the same circuit with 5.6 k / 16 k",
                "the book evaluates figure 4 with AN94002's values, which give the note's A"),
]
