"""TCA5600 converter coil: eq 1 to 6a at the worst operating point, and what given L1 and R1 do (SI units).

The converter has no time base: the switch turns on, the coil current rises until the drop across R1
reaches V12(H), the switch turns off and the coil dumps its energy into C2 (the programmable
regulator's input) until the current is zero.
"""
from __future__ import annotations

from ...core import InputError


def coil_voltages(p: dict) -> tuple[float, float]:
    """Eq 1 and 2 (KVL): (V_L+ while dumping, V_L- while charging).

    Parameters
    ----------
    p : Mapping
        The TCA5600 parameters (names as in :mod:`.data`, SI units); reads ``v_out2``, ``regulator_drop``,
        ``v_f``, ``v_cc2_min``, ``vce_sat`` and ``v12h``, V.

    Returns
    -------
    tuple of float
        (V_L+, V_L-), V. Raises :class:`~handbook.core.InputError` where either is not positive.
    """
    vl_plus = p["v_out2"] + p["regulator_drop"] + p["v_f"] - p["v_cc2_min"]
    vl_minus = p["v_cc2_min"] - p["vce_sat"] - p["v12h"]
    if vl_plus <= 0 or vl_minus <= 0:
        raise InputError(f"no boost operation: V_L+ = {vl_plus:.3g} V and V_L- = {vl_minus:.3g} V must both be "
                         f"positive (the output side must sit above the supply, the supply above the switch drops)")
    return vl_plus, vl_minus


def design(p: dict) -> dict:
    """Eq 3 to 6a at the worst operating point: alpha, t1, I_peak, L1 and R1.

    Parameters
    ----------
    p : Mapping
        The TCA5600 parameters (names as in :mod:`.data`, SI units): what :func:`coil_voltages` reads,
        ``f_min`` (Hz) and ``i_out2`` (A).

    Returns
    -------
    dict
        ``vl_plus``, ``vl_minus`` (V), ``alpha`` (t1 / t2, a pure number), ``t1``, ``t2`` (s), ``i_peak`` (A),
        ``l1`` (H) and ``r1`` (ohm).
    """
    vl_plus, vl_minus = coil_voltages(p)
    alpha = vl_plus / vl_minus
    t1 = 1 / ((1 + 1 / alpha) * p["f_min"])
    i_peak = 2 * p["i_out2"] * (1 + alpha)
    return {"vl_plus": vl_plus, "vl_minus": vl_minus, "alpha": alpha, "t1": t1, "t2": t1 / alpha,
            "i_peak": i_peak, "l1": vl_minus * t1 / i_peak, "r1": p["v12h"] / i_peak}


def operating_point(l1: float, r1: float, p: dict) -> dict:
    """What given L1 and R1 do at the operating point: the peak current is set by R1, the free-running
    frequency by L1, and the load they can carry by the triangle's average.

    Parameters
    ----------
    l1 : float
        Coil inductance L1, H.
    r1 : float
        Current-sense resistor R1, ohm.
    p : Mapping
        The TCA5600 parameters (names as in :mod:`.data`, SI units): what :func:`coil_voltages` reads.

    Returns
    -------
    dict
        ``i_peak`` (A), ``t1`` (s), ``f`` (the free-running frequency, Hz) and ``i_out_max`` (the
        largest load current, A).
    """
    vl_plus, vl_minus = coil_voltages(p)
    alpha = vl_plus / vl_minus
    i_peak = p["v12h"] / r1
    t1 = l1 * i_peak / vl_minus
    return {"i_peak": i_peak, "t1": t1, "f": 1 / (t1 * (1 + 1 / alpha)), "i_out_max": i_peak / (2 * (1 + alpha))}
