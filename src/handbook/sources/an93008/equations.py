"""AN93008 equations 1 to 7 (the supply-referenced limiter of figure 3): each function returns one record."""
from __future__ import annotations

import sympy as sp
from sympy.physics import units as u

from ...core.equation import Equation
from .data import NAME

V, OHM = u.volt, u.ohm
Vs, Vcs, Vp, Vm, R8, R9, R10, R11 = sp.symbols(r"V_{supply} V_{cs} V_{+} V_{-} R_8 R_9 R_{10} R_{11}", positive=True)
A, B = sp.symbols("A B", positive=True)
UNITS = {Vs: V, Vcs: V, R8: OHM, R9: OHM, R10: OHM, R11: OHM}
SUB = {A: R9 / (R8 + R9), B: R11 / (R10 + R11)}


def _v_plus():
    """KCL at V+: R8 from V_s - V_cs, R9 to ground."""
    return sp.solve(sp.Eq((Vs - Vcs - Vp) / R8, Vp / R9), Vp)[0]


def _v_minus():
    return sp.solve(sp.Eq((Vs - Vm) / R10, Vm / R11), Vm)[0]


def eq1() -> Equation:
    """Eq 1: the level-shifted sense voltage at V+ (KCL at V+).

    Returns
    -------
    Equation
        The record ``an93008-eq1``: V_+ (V) against V_supply, V_cs (V), R8 and R9 (ohm).
    """
    return Equation(
        id="an93008-eq1", source=f"{NAME} 2.2, eq (1)", title="Level-shifted sense voltage at V+", lhs=Vp, lhs_unit=V,
        printed=Vs * R9 / (R8 + R9) - Vcs * R9 / (R8 + R9), derived=_v_plus(), units=UNITS,
        printed_tex=r"V_{supply} \frac{R_9}{R_8 + R_9} - V_{cs} \frac{R_9}{R_8 + R_9}",
        law="KCL at V+: R8 from V_supply - V_cs, R9 to ground")


def eq2() -> Equation:
    """Eq 2: eq 1 with R8 = 7.5 k and R9 = 33 k, V+ = 0.815 (V_supply - V_cs).

    Returns
    -------
    Equation
        The record ``an93008-eq2``: V_+ (V) against V_supply and V_cs (V), constant rounded.
    """
    return Equation(
        id="an93008-eq2", source=f"{NAME} 2.2, eq (2)", title="Eq 1 with R8 = 7.5 k, R9 = 33 k", lhs=Vp, lhs_unit=V,
        printed=sp.Rational("0.815") * (Vs - Vcs), derived=_v_plus(), units=UNITS,
        values={R8: 7500 * OHM, R9: 33000 * OHM}, printed_tex=r"0.815 \, V_{supply} - 0.815 \, V_{cs}",
        law="eq 1 evaluated", note="0.815 is 33/40.5 = 0.81481 rounded.", rounded=(("0.815", sp.Rational(66, 81)),))


def eq4() -> Equation:
    """Eq 4: the reference at V-, V_supply R11 / (R10 + R11).

    Returns
    -------
    Equation
        The record ``an93008-eq4``: V_- (V) against V_supply (V), R10 and R11 (ohm).
    """
    return Equation(
        id="an93008-eq4", source=f"{NAME} 2.2, eq (4)", title="Reference at V-", lhs=Vm, lhs_unit=V,
        printed=Vs * R11 / (R10 + R11), derived=_v_minus(), units=UNITS,
        law="KCL at V-: R10 from V_supply, R11 to ground")


def eq6() -> Equation:
    """Eq 3 to 6: the sense voltage at the trip point, V_supply (1 - B/A).

    Returns
    -------
    Equation
        The record ``an93008-eq6``: V_cs (V) against V_supply (V) and R8 to R11 (ohm).
    """
    return Equation(
        id="an93008-eq6", source=f"{NAME} 2.2, eq (3) to (6)", title="Sense voltage at the trip point", lhs=Vcs,
        lhs_unit=V, printed=(Vs - B / A * Vs).subs(SUB), derived=sp.solve(sp.Eq(_v_plus(), _v_minus()), Vcs)[0],
        units=UNITS, printed_tex=r"V_{supply} - \frac{B}{A} V_{supply}",
        law="virtual short V+ = V- (eq 5) solved for V_cs")


def eq7() -> Equation:
    """Eq 7: B for a wanted V_cs, A (V_supply - V_cs) / V_supply.

    Returns
    -------
    Equation
        The record ``an93008-eq7``: B, a pure number, against V_supply, V_cs (V), R8 and R9 (ohm).
    """
    return Equation(
        id="an93008-eq7", source=f"{NAME} 2.2, eq (7)", title="B for a wanted V_cs", lhs=B, lhs_unit=sp.Integer(1),
        printed=(A * (Vs - Vcs) / Vs).subs(SUB), derived=sp.solve(sp.Eq(Vs - B / A * Vs, Vcs), B)[0].subs(SUB),
        units=UNITS, printed_tex=r"A \frac{V_{supply} - V_{cs}}{V_{supply}}", law="eq 6 solved for B")


def build() -> list[Equation]:
    """Every AN93008 equation record (figure 3, eq 1 to 7).

    Returns
    -------
    list of Equation
        Equations 1, 2, 4, 6 and 7, in the note's order.
    """
    return [eq1(), eq2(), eq4(), eq6(), eq7()]
