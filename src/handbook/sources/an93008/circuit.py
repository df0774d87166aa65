"""AN93008 figure 3: the op-amp limiter with a supply-referenced level shift (eq 1 to 8), SI units.

Names follow AN93008: R8/R9 the level shift (A = R9/(R8+R9)), R10/R11 the reference (B). The trip
point is AN94002's eq 13 with the supply in place of the zener and no R9 of AN94002's.
"""
from __future__ import annotations

from ...core import tolerance
from ..an94002 import circuit as an94002


def factor_a(r8, r9):
    """A = R9 / (R8 + R9) (eq 1 to 3).

    Parameters
    ----------
    r8, r9 : float
        The level shift's top and bottom resistors, ohm (floats, numpy arrays and casadi symbols alike).

    Returns
    -------
    float
        A, a pure number.
    """
    return r9 / (r8 + r9)


def factor_b(r10, r11):
    """B = R11 / (R10 + R11) (eq 4).

    Parameters
    ----------
    r10, r11 : float
        The reference's top and bottom resistors, ohm (floats, numpy arrays and casadi symbols alike).

    Returns
    -------
    float
        B, a pure number.
    """
    return r11 / (r10 + r11)


def v_cs_trip(v_supply, r8, r9, r10, r11, offset=0.0):
    """Eq 6 with the offset referred back: V_cs = V (1 - B/A) - V_os / A (works on numpy arrays).

    Parameters
    ----------
    v_supply : float
        Supply the limiter is referenced to, V.
    r8, r9 : float
        The level shift's top and bottom resistors, ohm.
    r10, r11 : float
        The reference's top and bottom resistors, ohm.
    offset : float
        The op-amp's input offset V_os, V.

    Returns
    -------
    float
        The trip voltage across the sense resistor, V.
    """
    return an94002.v_cs_trip(v_supply, 0.0, r10, r11, r8, r9, offset)


def b_for(v_cs, v_supply, a):
    """Eq 7: B = A (V - V_cs) / V.

    Parameters
    ----------
    v_cs : float
        The trip voltage wanted across the sense resistor, V.
    v_supply : float
        Supply the limiter is referenced to, V.
    a : float
        The level shift's factor A, a pure number.

    Returns
    -------
    float
        B, a pure number.
    """
    return a * (v_supply - v_cs) / v_supply


def r10_for(b, r11):
    """B = R11 / (R10 + R11) solved for R10.

    Parameters
    ----------
    b : float
        The reference's factor B, a pure number.
    r11 : float
        The reference's bottom resistor, ohm.

    Returns
    -------
    float
        R10, ohm.
    """
    return r11 * (1 - b) / b


def supply_worst_case(p: dict, include=("supply", "resistors", "offset")) -> tolerance.WorstCase:
    """Exact worst case of the figure 3 trip voltage: supply, every resistor and the offset at once
    (``include`` names the spreads to take; the others stay nominal).

    Parameters
    ----------
    p : Mapping
        The AN93008 parameters (names as in :mod:`.data`, SI units); reads ``v_supply``, ``offset`` (V),
        ``r8`` to ``r11`` (ohm), ``resistor_tolerance`` and ``supply_tolerance`` (fractions).
    include : tuple of str
        The spreads taken: ``"supply"``, ``"resistors"``, ``"offset"``.

    Returns
    -------
    WorstCase
        The trip voltage at nominal and at its extremes, V, with the corners giving them.
    """
    v = p["v_supply"]
    nominal = {"v_supply": v, "r8": p["r8"], "r9": p["r9"], "r10": p["r10"], "r11": p["r11"], "offset": 0.0}
    spread = {}
    if "resistors" in include:
        spread.update({k: tolerance.symmetric(p[k], p["resistor_tolerance"]) for k in ("r8", "r9", "r10", "r11")})
    if "supply" in include:
        spread["v_supply"] = tolerance.symmetric(v, p["supply_tolerance"])
    if "offset" in include:
        spread["offset"] = (-p["offset"], p["offset"])
    return tolerance.corners(v_cs_trip, nominal, spread)
