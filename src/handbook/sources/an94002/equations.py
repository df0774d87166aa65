"""AN94002 equations: each printed form with its derivation from a circuit law, one function per record."""
from __future__ import annotations

import sympy as sp
from sympy.physics import units as u

from ...core.equation import Equation
from .data import NAME

V, A, F, S, OHM = u.volt, u.ampere, u.farad, u.second, u.ohm
uF = u.farad / 10 ** 6
uA = u.ampere / 10 ** 6

# physical symbols
C, t, I, dV = sp.symbols(r"C t I \Delta{}V", positive=True)
C_ST, t_start, I_st, V_lo, V_hi = sp.symbols(r"C_{ST} t_{start} I_{ST} V_{low} V_{high}", positive=True)
f_osc, s_ = sp.symbols(r"f_{osc} s")
K_t, I_m, p_, J = sp.symbols(r"K_t I p J", positive=True)
N, n = sp.symbols(r"N n", positive=True)  # rotational speed (1/s), pole pairs
t_cyc, t_com, C_CD, I_max, I_min, V_win, V_noise = sp.symbols(
    r"t_{cyc} t_{com} C_{CD} I_{ch\,max} I_{ch\,min} \Delta{}V_{win} \Delta{}V_{noise}", positive=True)
N_max, N_min = sp.symbols(r"N_{max} N_{min}", positive=True)
C_TI, t_wd, I_wd = sp.symbols(r"C_{TI} t_{wd} I_{wd}", positive=True)
V_in, V_mot, R3, R4 = sp.symbols(r"V_{in} V_{mot} R_3 R_4", positive=True)
V_s, V_D1, V_cs, V_p, V_m = sp.symbols(r"V_s V_{D1} V_{cs} V_{+} V_{-}", positive=True)
R9, R10, R11, R12, R13 = sp.symbols(r"R_9 R_{10} R_{11} R_{12} R_{13}", positive=True)
A_, B_ = sp.symbols("A B", positive=True)
V_be, R7, I_lim, T, TC = sp.symbols(r"V_{be} R_7 I_{lim} T TC_{V_{be}}", real=True)
Z, f, C2 = sp.symbols(r"|Z| f C_2", positive=True)
V_os = sp.Symbol("V_{os}", real=True)
# printed symbols: plain numbers in the note's units
# upright names: "RPM n" reads as two symbols, not "RPMn"
C_uF, RPM, RPM_min = sp.symbols(r"\mathrm{CAP}_{\mu{}F} \mathrm{RPM} \mathrm{RPM}_{min}", positive=True)
RPM_ratio = sp.Symbol(r"\frac{RPM_{max}}{RPM_{min}}", positive=True)

#: the note's A and B (eq 13) in the resistors
AB = {A_: R13 / (R12 + R13), B_: R11 / (R9 + R10 + R11)}
R_UNITS = {R9: OHM, R10: OHM, R11: OHM, R12: OHM, R13: OHM}
TI_VALUES = {I_wd: 5 * uA, V_hi: sp.Rational("2.2") * V, V_lo: sp.Rational("0.3") * V}


def collected(expr, symbols):
    """``expr`` as one fraction with its numerator collected in ``symbols`` (for display; same value).

    Parameters
    ----------
    expr : sympy.Expr
        The expression.
    symbols : tuple of sympy.Symbol
        The symbols the numerator is collected in.

    Returns
    -------
    sympy.Expr
        The same value, as numerator / denominator.
    """
    num, den = sp.fraction(sp.together(expr))
    return sp.collect(sp.expand(num), symbols, sp.factor) / den


def timer_law(charge, current, time, window):
    """Charge balance on a capacitor charged at a constant current: I t = C dV, solved for ``charge``.

    Parameters
    ----------
    charge : sympy.Symbol
        The unknown solved for (usually the capacitance C).
    current : sympy.Expr
        The constant charge current I (A).
    time : sympy.Expr
        The charging time t (s).
    window : sympy.Expr
        The voltage swing dV (V).

    Returns
    -------
    sympy.Expr
        ``charge`` expressed in the others (C = I t / dV).
    """
    return sp.solve(sp.Eq(current * time, charge * window), charge)[0]


def v_plus():
    """V+ from KCL: R12 from V_s - V_cs, R13 to V_s - V_D1.

    Returns
    -------
    sympy.Expr
        V_+ in V_s, V_cs, V_D1, R12 and R13.
    """
    return sp.solve(sp.Eq((V_s - V_cs - V_p) / R12, (V_p - (V_s - V_D1)) / R13), V_p)[0]


def v_minus():
    """V- from KCL: R9 + R10 from V_s, R11 to V_s - V_D1.

    Returns
    -------
    sympy.Expr
        V_- in V_s, V_D1, R9, R10 and R11.
    """
    return sp.solve(sp.Eq((V_s - V_m) / (R9 + R10), (V_m - (V_s - V_D1)) / R11), V_m)[0]


def v_cs_at_trip():
    """Eq 13 derived: V+ = V- solved for V_cs.

    Returns
    -------
    sympy.Expr
        V_cs in V_D1 and R9 to R13.
    """
    return sp.solve(sp.Eq(v_plus(), v_minus()), V_cs)[0]


# ----------------------------------------------------------------------------------------------
# 2.1.1 start oscillator

def eq1() -> Equation:
    """Eq 1: the start oscillator's period from CAP-ST (the constant 2.15 hides s/uF).

    Returns
    -------
    Equation
        The record ``an94002-eq1``: t_start (s) against C_ST (printed in uF).
    """
    t_half = sp.solve(sp.Eq(I_st * t, C_ST * (V_hi - V_lo)), t)[0]
    return Equation(
        id="an94002-eq1", source=f"{NAME} 2.1.1, eq (1)", title="Start oscillator period (CAP-ST)",
        lhs=t_start, lhs_unit=S, lhs_scale=S,
        printed=sp.Rational("2.15") * C_uF, scales={C_uF: C_ST / uF},
        derived=2 * t_half, units={C_ST: F, I_st: A, V_lo: V, V_hi: V},
        values={I_st: 2 * uA, V_lo: sp.Rational("0.05") * V, V_hi: sp.Rational("2.2") * V},
        law="charge balance I t = C dV, once up and once down the window",
        note="The constant 2.15 hides s/uF: it is 2 (2.2 V - 0.05 V) / 2 uA.",
    )


def eq2() -> Equation:
    """Eq 2: the rotor's oscillation frequency about a detent (rebuilt from a garbled OCR).

    Returns
    -------
    Equation
        The record ``an94002-eq2``: f_osc (Hz) against K_t, I, p and J.
    """
    sol = sp.solve(sp.Eq(J * s_ ** 2 + K_t * I_m * p_, 0), s_)
    omega = sp.im(sol[1]) if sp.im(sol[1]).is_positive else sp.im(sol[0])
    return Equation(
        id="an94002-eq2", source=f"{NAME} 2.1.1, eq (2)", title="Rotor oscillation about a detent",
        lhs=f_osc, lhs_unit=u.hertz,
        printed=sp.sqrt(K_t * I_m * p_ / J) / (2 * sp.pi),
        derived=omega / (2 * sp.pi),
        units={K_t: u.newton * u.meter / A, I_m: A, J: u.kilogram * u.meter ** 2},
        law="J theta'' = -K_t I sin(p theta) ~ -K_t I p theta: a harmonic oscillator",
        reconstructed=("the OCR reads f = 1/(2 pi sqrt(K_t I p / J)), which has the unit of time, not "
                       "frequency, and gives 4.9 ms for the example; the note's own 5 Hz and the TDA5341 "
                       "datasheet's form (K_t I p / J)^0.5 / (2 pi) fix it as f = sqrt(K_t I p / J) / (2 pi)."),
        ocr_form=1 / (2 * sp.pi * sp.sqrt(K_t * I_m * p_ / J)),
    )


# ----------------------------------------------------------------------------------------------
# 2.1.2 adaptive commutation delay

def eq3() -> Equation:
    """Eq 3: the electrical cycle time, 60 / (RPM n).

    Returns
    -------
    Equation
        The record ``an94002-eq3``: t_cyc (s).
    """
    return Equation(
        id="an94002-eq3", source=f"{NAME} 2.1.2, eq (3)", title="Electrical cycle time",
        lhs=t_cyc, lhs_unit=S, lhs_scale=S, printed=60 / (RPM * n), scales={RPM: N * u.minute},
        derived=1 / (n * N), units={N: 1 / S},
        law="n electrical cycles per mechanical revolution: f_el = n N",
        note="RPM is the speed in revolutions per minute; 60 is s/min.",
    )


def eq4() -> Equation:
    """Eq 4: the time between commutations, 10 / (RPM n).

    Returns
    -------
    Equation
        The record ``an94002-eq4``: t_com (s).
    """
    return Equation(
        id="an94002-eq4", source=f"{NAME} 2.1.2, eq (4)", title="Time between commutations",
        lhs=t_com, lhs_unit=S, lhs_scale=S, printed=10 / (RPM * n), scales={RPM: N * u.minute},
        derived=1 / (6 * n * N), units={N: 1 / S},
        law="six commutations per electrical cycle (three phases, two edges each)",
    )


def eq5() -> Equation:
    """CAP-CD from charge balance (general form).

    Returns
    -------
    Equation
        The record ``an94002-eq5``: C_CD (F) against I (A), RPM and dV (V).
    """
    return Equation(
        id="an94002-eq5", source=f"{NAME} 2.1.2, eq (5)", title="CAP-CD from its charge per commutation",
        lhs=C_CD, lhs_unit=F, lhs_scale=F, printed=I * 10 / (RPM * n * dV),
        scales={RPM: N * u.minute, I: I / A, dV: dV / V},
        derived=timer_law(C_CD, I, 1 / (6 * n * N), dV), units={I: A, dV: V, N: 1 / S},
        law="charge balance I t_com = C dV over one commutation interval",
        note="Evaluated with I_ch,max and the window at RPM_min it becomes eq 6's lower bound on CAP-CD.",
        relation="=",
    )


def eq6() -> Equation:
    """The numeric bound with the constant 160.

    Returns
    -------
    Equation
        The record ``an94002-eq6``: the bound C_CD >= 160 / (RPM_min n) (C in uF).
    """
    return Equation(
        id="an94002-eq6", source=f"{NAME} 2.1.2, eq (6)", title="CAP-CD lower bound, 160/(RPM_min n)",
        lhs=C_CD, lhs_unit=F, lhs_scale=uF, relation=">=",
        printed=160 / (RPM_min * n), scales={RPM_min: N_min * u.minute},
        derived=timer_law(C_CD, I_max, 1 / (6 * n * N_min), V_win),
        units={I_max: A, V_win: V, N_min: 1 / S},
        values={I_max: 22 * uA, V_win: sp.Rational("1.4") * V},
        law="charge balance with the largest charge current and the smallest window at RPM_min",
        rounded=(("160", sp.Rational(10 * 22, 14) * 10),),
        note=("The exact constant is 10 x 22 uA / 1.4 V = 157.14 uF rpm; 160 rounds it up by 1.8 % "
              "(conservative). The note's 22 uA is the TDA5144's largest discharge current; the charge "
              "current is at most 11 uA (datasheet), which halves the bound."),
    )


def eq7() -> Equation:
    """Eq 7: the highest reliable speed for a given CAP-CD (the noise floor's swing).

    Returns
    -------
    Equation
        The record ``an94002-eq7``: RPM_max (rpm) against I_ch,min (A), dV_noise (V), n and C_CD (F).
    """
    return Equation(
        id="an94002-eq7", source=f"{NAME} 2.1.2, eq (7)", title="Highest reliable speed for a given CAP-CD",
        lhs=N_max, lhs_unit=1 / S, lhs_scale=1 / u.minute,
        printed=I_min * 10 / (V_noise * n * C_CD),
        scales={I_min: I_min / A, V_noise: V_noise / V, C_CD: C_CD / F},
        derived=sp.solve(sp.Eq(I_min / (6 * n * N_max), C_CD * V_noise), N_max)[0],
        units={I_min: A, V_noise: V, C_CD: F},
        law="charge balance with the smallest current; the swing must stay above the noise floor",
        note=("Here the note's dV_capmin is the smallest swing still safe from noise, not the 1.4 V window "
              "that eq 6 also calls dV_capmin; this book names them dV_noise and dV_win. I, dV and C are "
              "plain numbers in A, V and F and the result is in rpm: the 10 hides 60 s/min / 6."),
    )


def eq8() -> Equation:
    """Eq 8: the speed range RPM_max / RPM_min of one capacitor.

    Returns
    -------
    Equation
        The record ``an94002-eq8``: a pure number in the windows (V) and currents (A).
    """
    n_min = sp.solve(sp.Eq(I_max / (6 * n * N_min), C_CD * V_win), N_min)[0]
    n_max = sp.solve(sp.Eq(I_min / (6 * n * N_max), C_CD * V_noise), N_max)[0]
    return Equation(
        id="an94002-eq8", source=f"{NAME} 2.1.2, eq (8)", title="Speed range of one capacitor",
        lhs=RPM_ratio, lhs_unit=sp.Integer(1), printed=V_win * I_min / (V_noise * I_max),
        derived=sp.simplify(n_max / n_min), units={I_min: A, I_max: A, V_win: V, V_noise: V},
        law="eq 7 divided by eq 5 at the bound: C, n and the 10 cancel",
        note="The note's dV_capmax (the window at RPM_min) is dV_win here, its dV_capmin is dV_noise.",
    )


# ----------------------------------------------------------------------------------------------
# 2.1.3 watchdog (two printed forms)

def eq9() -> Equation:
    """Eq 9, first form: CAP-TI = 5e-6 t_wd / 1.9 for a watchdog time.

    Returns
    -------
    Equation
        The record ``an94002-eq9``: C_TI (F) against t_wd (s).
    """
    return Equation(
        id="an94002-eq9", source=f"{NAME} 2.1.3, eq (9), first form", title="CAP-TI for a watchdog time",
        lhs=C_TI, lhs_unit=F, printed=5 * sp.Rational(1, 10 ** 6) * t_wd / sp.Rational("1.9"),
        printed_tex=r"\frac{5 \times 10^{-6} \, t_{wd}}{1.9}",
        scales={t_wd: t_wd / S}, lhs_scale=F,
        derived=timer_law(C_TI, I_wd, t_wd, V_hi - V_lo), units={I_wd: A, t_wd: S, V_hi: V, V_lo: V},
        values=dict(TI_VALUES),
        law="charge balance at 5 uA from 0.3 V to 2.2 V", rounded=(("2.63", sp.Rational(50, 19)),),
    )


def eq9b() -> Equation:
    """Eq 9, second form: CAP-TI = 2.63 t_wd (C in uF, t_wd in s).

    Returns
    -------
    Equation
        The record ``an94002-eq9b``: C_TI (printed in uF) against t_wd (s).
    """
    return Equation(
        id="an94002-eq9b", source=f"{NAME} 2.1.3, eq (9), second form", title="CAP-TI = 2.63 t_wd",
        lhs=C_TI, lhs_unit=F, printed=sp.Rational("2.63") * t_wd, lhs_scale=uF,
        scales={t_wd: t_wd / S},
        derived=timer_law(C_TI, I_wd, t_wd, V_hi - V_lo), units={I_wd: A, t_wd: S, V_hi: V, V_lo: V},
        values=dict(TI_VALUES),
        law="charge balance at 5 uA from 0.3 V to 2.2 V", rounded=(("2.63", sp.Rational(50, 19)),),
        note="2.63 is 5/1.9 = 2.6316 rounded; units hidden: C in uF for t_wd in s (or nF for ms).",
    )


# ----------------------------------------------------------------------------------------------
# 2.2 speed control

def eq10() -> Equation:
    """Eq 10: the speed-control divider, V_in = V_mot R4 / (R3 + R4).

    Returns
    -------
    Equation
        The record ``an94002-eq10``: V_in (V) against V_mot (V), R3 and R4 (ohm).
    """
    v_node = sp.Symbol("V_node")
    node = sp.solve(sp.Eq((V_mot - v_node) / R3, v_node / R4), v_node)[0]
    return Equation(
        id="an94002-eq10", source=f"{NAME} 2.2, eq (10)", title="Speed-control divider",
        lhs=V_in, lhs_unit=V, printed=V_mot * R4 / (R3 + R4), derived=node,
        units={V_mot: V, R3: OHM, R4: OHM},
        law="KCL at AMPIN+ (no input current), and the OTA loop holds AMPIN+ = AMPIN- = V_in",
    )


# ----------------------------------------------------------------------------------------------
# 2.4 op-amp limiter: KCL at the op-amp inputs

def eq11() -> Equation:
    """Eq 11: the level-shifted sense voltage at the op-amp's V+.

    Returns
    -------
    Equation
        The record ``an94002-eq11``: V_+ (V) against V_s, V_D1, V_cs (V), R12 and R13 (ohm).
    """
    return Equation(
        id="an94002-eq11", source=f"{NAME} 2.4, eq (11)", title="Level-shifted sense voltage at V+",
        lhs=V_p, lhs_unit=V, printed=V_s - V_D1 + (V_D1 - V_cs) * R13 / (R12 + R13), derived=v_plus(),
        printed_tex=r"V_s - V_{D1} + (V_{D1} - V_{cs}) \frac{R_{13}}{R_{12} + R_{13}}",
        units={V_s: V, V_D1: V, V_cs: V, R12: OHM, R13: OHM},
        law="KCL at V+: the current through R12 (from V_s - V_cs) equals that through R13 (to V_s - V_D1)",
    )


def eq11_num() -> Equation:
    """Eq 11 with the board's values: V+ = V_s - 2.02 - 0.741 V_cs (volts).

    Returns
    -------
    Equation
        The record ``an94002-eq11-num``: V_+ (V) against V_s and V_cs (V), constants rounded.
    """
    return Equation(
        id="an94002-eq11-num", source=f"{NAME} 2.4, eq (11) with R12 = 5.6 k, R13 = 16 k, V_D1 = 7.79 V",
        title="Eq 11 with the board's values", lhs=V_p, lhs_unit=V, lhs_scale=V,
        scales={V_s: V_s / V, V_cs: V_cs / V},
        printed=V_s - sp.Rational("2.02") - sp.Rational("0.741") * V_cs, derived=v_plus(),
        printed_tex=r"V_s - 2.02 - 0.741 \, V_{cs}",
        units={V_s: V, V_cs: V, V_D1: V, R12: OHM, R13: OHM},
        values={V_D1: sp.Rational("7.79") * V, R12: sp.Rational(5600) * OHM, R13: sp.Rational(16000) * OHM},
        law="eq 11 evaluated",
        rounded=(("2.02", sp.Rational(779, 100) * sp.Rational(5600, 21600)), ("0.741", sp.Rational(16000, 21600))),
        note="2.02 and 0.741 are 2.0196 V and 0.74074 rounded.",
    )


def eq12() -> Equation:
    """Eq 12: the reference at the op-amp's V-.

    Returns
    -------
    Equation
        The record ``an94002-eq12``: V_- (V) against V_s, V_D1 (V) and R9 to R11 (ohm).
    """
    return Equation(
        id="an94002-eq12", source=f"{NAME} 2.4, eq (12)", title="Reference at V-",
        lhs=V_m, lhs_unit=V, printed=(V_s - V_D1) + V_D1 * R11 / (R9 + R10 + R11), derived=v_minus(),
        printed_tex=r"(V_s - V_{D1}) + V_{D1} \frac{R_{11}}{R_9 + R_{10} + R_{11}}",
        units={V_s: V, V_D1: V, R9: OHM, R10: OHM, R11: OHM},
        law="KCL at V-: R9 + R10 from V_s, R11 to V_s - V_D1",
    )


def eq13() -> Equation:
    """Eq 13: the sense voltage at the trip point, V_D1 - V_D1 B / A.

    Returns
    -------
    Equation
        The record ``an94002-eq13``: V_cs (V) against V_D1 (V) and R9 to R13 (ohm).
    """
    return Equation(
        id="an94002-eq13", source=f"{NAME} 2.4, eq (13)", title="Sense voltage at the trip point",
        lhs=V_cs, lhs_unit=V, printed=(V_D1 - V_D1 * B_ / A_).subs(AB),
        derived=v_cs_at_trip(), units={V_D1: V, **R_UNITS},
        printed_tex=(r"V_{D1} - V_{D1} \frac{B}{A}, \quad A = \frac{R_{13}}{R_{12} + R_{13}}, \;"
                     r" B = \frac{R_{11}}{R_9 + R_{10} + R_{11}}"),
        law="op-amp virtual short V+ = V- with eq 11 and eq 12, solved for V_cs (offset zero)",
        note="The printed form is V_D1 - V_D1 B / A with A = R13/(R12+R13), B = R11/(R9+R10+R11).",
    )


def eq14() -> Equation:
    """Eq 14: the trip point with matched dividers, V_cs = V_D1 R9 / (R9 + R10 + R11).

    Returns
    -------
    Equation
        The record ``an94002-eq14``: V_cs (V) against V_D1 (V), R9, R10 and R11 (ohm).
    """
    return Equation(
        id="an94002-eq14", source=f"{NAME} 2.4, eq (14)", title="Sense voltage with matched dividers",
        lhs=V_cs, lhs_unit=V, printed=V_D1 * R9 / (R9 + R10 + R11),
        derived=v_cs_at_trip().subs({R12: R10, R13: R11}), units={V_D1: V, R9: OHM, R10: OHM, R11: OHM},
        law="eq 13 with R12 = R10 and R13 = R11 exactly",
        note="Holds only for exact matching; real 1 % parts break it badly (chapter 2.4).",
    )


def level_shift() -> Equation:
    """The level shift below the supply, V_D1 R12 / (R12 + R13) (text after eq 11).

    Returns
    -------
    Equation
        The record ``an94002-level-shift``: V_s - V_+ (V) at V_cs = 0.
    """
    return Equation(
        id="an94002-level-shift", source=f"{NAME} 2.4, text after eq (11)", title="Level shift below the supply",
        lhs=sp.Symbol(r"V_s - V_{+}"), lhs_unit=V, printed=V_D1 * R12 / (R12 + R13),
        derived=sp.simplify((V_s - v_plus()).subs(V_cs, 0)), units={V_D1: V, R12: OHM, R13: OHM, V_s: V},
        law="eq 11 at V_cs = 0",
        note="The note sizes R12/R13 for 2 V at the lowest zener voltage 7.79 V (LM358 common-mode range).",
    )


def trip_offset() -> Equation:
    """The trip point with the offset (this book's form, used for the tolerance analysis).

    Returns
    -------
    Equation
        The record ``an94002-trip-offset``: V_cs (V) against V_D1, V_os (V) and R9 to R13 (ohm).
    """
    vcs_os = sp.solve(sp.Eq(v_plus() - v_minus(), V_os), V_cs)[0]
    return Equation(
        id="an94002-trip-offset", source=f"{NAME} 2.4, text (offset referred to V_cs)",
        title="Trip point with the op-amp offset", lhs=V_cs, lhs_unit=V,
        printed=(V_D1 * (1 - B_ / A_) - V_os / A_).subs(AB),
        derived=collected(vcs_os, (V_D1, V_os)), units={V_D1: V, V_os: V, **R_UNITS},
        printed_tex=r"V_{D1} \left(1 - \frac{B}{A}\right) - \frac{V_{os}}{A}",
        law="the op-amp switches where V+ - V- = V_os",
        note="The note states the effect in words (offset divided by A); the printed form here is that statement.",
    )


def stack_up() -> Equation:
    """The note's tolerance stack-up, (1 + t1)(1 + t2)(1 + t3) - 1 (upper end).

    Returns
    -------
    Equation
        The record ``an94002-stack-up``: the total tolerance, a fraction.
    """
    t1, t2, t3 = sp.symbols("t_1 t_2 t_3", positive=True)
    x1, x2, x3 = sp.symbols("x_1 x_2 x_3", positive=True)
    high = (x1 * x2 * x3).subs({x1: 1 + t1, x2: 1 + t2, x3: 1 + t3}) - 1  # each factor at its high end
    return Equation(
        id="an94002-stack-up", source=f"{NAME} 2.4, tolerance table", title="Total tolerance (upper end)",
        lhs=sp.Symbol(r"t_{total}"), lhs_unit=sp.Integer(1),
        printed=(1 + t1) * (1 + t2) * (1 + t3) - 1, derived=high, units={},
        law="worst case of a product of independent factors x_i in [1 - t_i, 1 + t_i]",
        note=("Right for the upper end only: the lower end is (1-t1)(1-t2)(1-t3) - 1 = -20.6 % for the note's "
              "numbers, not -23 %. The premise (independent factors entering as a product) fails for the "
              "resistors, which enter through a difference of two ratios (chapter 2.4)."),
    )


# ----------------------------------------------------------------------------------------------
# 2.3 one-transistor limiter, 3 decoupling

def vbe_tc() -> Equation:
    """The relative drift of the one-transistor limit, TC / V_be (section 2.3).

    Returns
    -------
    Equation
        The record ``an94002-vbe-tc``: (1/I_lim) dI_lim/dT (1/K) against TC (V/K) and V_be (V).
    """
    i_lim = (V_be + TC * T) / R7
    return Equation(
        id="an94002-vbe-tc", source=f"{NAME} 2.3, text", title="Relative drift of the one-transistor limit",
        lhs=sp.Symbol(r"\frac{1}{I_{lim}}\frac{dI_{lim}}{dT}"), lhs_unit=1 / u.kelvin,
        printed=TC / V_be, derived=sp.simplify(sp.diff(i_lim, T) / i_lim).subs(T, 0),
        units={TC: V / u.kelvin, V_be: V, R7: OHM},
        law="I_lim = V_be(T) / R7 (the transistor turns on at V_be), differentiated at the reference temperature",
    )


def decoupling() -> Equation:
    """The capacitance for |Z| below 2 ohm at 2 MHz, C >= 1 / (2 pi f |Z|) (section 3).

    Returns
    -------
    Equation
        The record ``an94002-decoupling``: the bound on C2 (F) against f (Hz) and |Z| (ohm).
    """
    w = sp.Symbol("omega", positive=True)
    return Equation(
        id="an94002-decoupling", source=f"{NAME} 3, text", title="Capacitance for |Z| below 2 ohm at 2 MHz",
        lhs=C2, lhs_unit=F, relation=">=", printed=1 / (2 * sp.pi * f * Z),
        derived=sp.solve(sp.Eq(sp.Abs(1 / (sp.I * w * C2)), Z), C2)[0].subs(w, 2 * sp.pi * f),
        units={f: u.hertz, Z: OHM},
        law="|Z| = |1/(j omega C)| of an ideal capacitor, set equal to the limit",
        note="The note states only the requirement; this is the ideal-capacitor bound (40 nF). ESR and ESL are "
             "what a real 10 uF part must keep below 2 ohm.",
    )


def build() -> list[Equation]:
    """Every AN94002 equation, in the note's order.

    Returns
    -------
    list of Equation
        The records, eq 1 to eq 14 and those the text implies.
    """
    return [eq1(), eq2(), eq3(), eq4(), eq5(), eq6(), eq7(), eq8(), eq9(), eq9b(), eq10(), eq11(), eq11_num(),
            eq12(), eq13(), eq14(), level_shift(), trip_offset(), stack_up(), vbe_tc(), decoupling()]
