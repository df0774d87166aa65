"""TDA5341 equations, rebuilt from the OCR's pieces: each function returns one record."""
from __future__ import annotations

import sympy as sp
from sympy.physics import units as u

from ...core.equation import Equation
from .data import NAME

C, f, I, dV, Idis, t = sp.symbols(r"C f_{C1} I_{ch} \Delta{}V I_{dis} t_{max}", positive=True)
nF = u.farad / 10 ** 9


def capcdm() -> Equation:
    """The CAPCDM capacitor, 7092 / f_C1 nF (rebuilt from the OCR's pieces).

    Returns
    -------
    Equation
        The record ``tda5341-capcdm``: CAPCDM (printed in nF) against f_C1 (Hz).
    """
    f_num = sp.Symbol("f", positive=True)
    return Equation(
        id="tda5341-capcdm", source=f"{NAME}, CAPCDM (reconstructed)", title="CAPCDM = 7092 / f_C1 (C in nF)",
        lhs=C, lhs_unit=u.farad, lhs_scale=nF, printed=7092 / f_num, scales={f_num: f / u.hertz},
        derived=sp.solve(sp.Eq(I / f, C * dV), C)[0], units={I: u.ampere, dV: u.volt, f: u.hertz},
        values={I: 10 * u.ampere / 10 ** 6, dV: sp.Rational("1.41") * u.volt},
        law="charge balance: charged at 10 uA for one commutation period 1/f_C1 across 0.87..2.28 V",
        reconstructed="the OCR shows 'C = 10 ... 1.41 x f ... 7092' in pieces; the form C = 10 uA / (1.41 V "
                      "f_C1) = 7092 / f_C1 nF fits the pieces and the example 7092/1600 = 4.43",
        note="7092 is 7092.2 rounded.", rounded=(("7092", sp.Rational(10**6, 141)),))


def max_delay() -> Equation:
    """The longest commutation delay, 0.070 ms per nF of CAPCDM.

    Returns
    -------
    Equation
        The record ``tda5341-max-delay``: t_max (printed in ms) against C (printed in nF).
    """
    c_nf = sp.Symbol("C_nF")
    return Equation(
        id="tda5341-max-delay", source=f"{NAME}, CAPCDM", title="Maximum delay = 0.070 C ms (C in nF)",
        lhs=t, lhs_unit=u.second, lhs_scale=u.second / 1000, printed=sp.Rational("0.070") * c_nf,
        scales={c_nf: C / nF}, derived=sp.solve(sp.Eq(Idis * t, C * dV), t)[0],
        units={C: u.farad, Idis: u.ampere, dV: u.volt},
        values={Idis: 20 * u.ampere / 10 ** 6, dV: sp.Rational("1.41") * u.volt},
        law="charge balance: discharged at 20 uA across the window", note="0.070 is 0.0705 rounded.",
        rounded=(("0.070", sp.Rational(141, 2000)),))


def build() -> list[Equation]:
    """Every TDA5341 equation record.

    Returns
    -------
    list of Equation
        The CAPCDM and maximum-delay records.
    """
    return [capcdm(), max_delay()]
