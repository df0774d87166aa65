"""The converter's operating point and its corners: eq 1 to 6a at the nominal device figures, then R1, L1 and the
full-load frequency range at the worst corners of R1 (``r1_tolerance`` and its drift to t_ambient, :func:`r1_ends`),
A_L (``a_l_tolerance``) and the TCA5600's V12(H), V_CE(sat) and V_F (each +-``device_spread``: part-to-part spread
and drift together, an assumption).

Which corner is worst for what, from eq 1, 2 and 5 (VCC2 = v_supply_min for the current):

* the current delivered, I_peak/2 x V_L-/(V_L- + V_L+) with I_peak = V12(H)/R1, falls as V_CE(sat) and V_F rise
  and as R1 rises; its logarithm is concave in V12(H), so its least is at one end of V12(H) (the low one, unless
  V_L- is nearly gone): :func:`weakest` takes the least of the eight device corners, R1 at its high end. R1 is
  eq 6a at that corner, fitted at or below R1 over its high end (:func:`r1_ends`);
* the frequency 1/(L I_peak (1/V_L- + 1/V_L+)) falls as L, V12(H) and V_CE(sat) rise, as V_F falls and as R1
  falls, at every VCC2: :data:`SLOW` (A_L high, R1 low) sets L1 (f_min at v_supply_min) and the audio-band
  check over the supply range; :data:`FAST` (A_L low, R1 high) the highest frequency;
* the peak current V12(H)/R1 is highest with V12(H) high and R1 low: the coil's flux, saturation margin, rms
  current (its losses and current density) are taken there, the core loss the largest over V_CE(sat) and V_F's
  ends (:data:`HOT`).
"""
from __future__ import annotations

import itertools
import math

from ...core import series as eseries
from ...core.units import eng
from ...sources.tca5600 import circuit as tca5600
from ..common import Table, checked_table
from ..solvers import Infeasible
from .coil import coil_voltages, frequency, supplies, v_top

TABLE = "converter"
#: the upper end of the audio band (Hz): the excerpt's own example of a frequency above it
AUDIO_BAND = 20e3
#: the TCA5600's figures the corners move, each by +-device_spread, in the order of a corner's ends
DEVICE = ("v12h", "v_ce_sat", "v_f")
#: the ends (-1 low, +1 high) of V12(H), V_CE(sat), V_F at the lowest full-load frequency, at every VCC2
SLOW = (1, 1, -1)
#: ... and at the highest
FAST = (-1, -1, 1)
#: the device corners of the highest peak current (V12(H) high), over which the core loss is the largest
HOT = tuple((1, vce, vf) for vce in (-1, 1) for vf in (-1, 1))


def source_params(s: dict) -> dict:
    """The spec in the source functions' names (handbook.sources.tca5600.circuit).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C), or one of its corners (:func:`corner`).

    Returns
    -------
    dict
        ``v_cc2_min``, ``v_out2``, ``regulator_drop``, ``v_f``, ``vce_sat``, ``v12h`` (V), ``i_out2`` (A) and
        ``f_min`` (Hz), from ``v_supply_min``, ``v_out``, ``v_regulator_drop``, ``v_f``, ``v_ce_sat``, ``v12h``,
        ``i_out`` and ``f_min``.
    """
    return {"v_cc2_min": s["v_supply_min"], "v_out2": s["v_out"], "i_out2": s["i_out"], "f_min": s["f_min"],
            "regulator_drop": s["v_regulator_drop"], "v_f": s["v_f"], "vce_sat": s["v_ce_sat"], "v12h": s["v12h"]}


def corner(s: dict, ends) -> dict:
    """The table with V12(H), V_CE(sat) and V_F at the given ends of +-``device_spread``.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    ends : sequence of int, or str
        -1 (low end), 0 (nominal) or +1 (high end) for each of :data:`DEVICE`, in its order; or a corner's name:
        "slow" (:data:`SLOW`), "fast" (:data:`FAST`), "weak" (:func:`weakest`).

    Returns
    -------
    dict
        A plain copy of ``s`` with the three figures moved (V), for the functions that read them
        (:func:`~.coil.frequency`, :func:`~.coil.coil_voltages`, :func:`~.coil.v_top`, :func:`source_params`).
    """
    if isinstance(ends, str):
        ends = weakest(s) if ends == "weak" else {"slow": SLOW, "fast": FAST}[ends]
    d = s["device_spread"]
    return {**s, **{key: s[key] * (1 + end * d) for key, end in zip(DEVICE, ends)}}


def delivered(s: dict, r1: float) -> float:
    """The current the converter delivers at ``v_supply_min`` and full load: I_peak/2 x V_L-/(V_L- + V_L+) with
    I_peak = V12(H)/R1 (eq 1, 2 and 5 read backwards).

    Parameters
    ----------
    s : dict
        The ``[converter]`` table or one of its corners (:func:`corner`), SI units.
    r1 : float
        The sense resistor, ohm.

    Returns
    -------
    float
        The load current carried, A.
    """
    vl_plus, vl_minus = coil_voltages(s, s["v_supply_min"])
    return s["v12h"] / r1 / 2 * vl_minus / (vl_minus + vl_plus)


def weakest(s: dict) -> tuple[int, int, int]:
    """The device corner that delivers least at ``v_supply_min`` (whatever R1: the current scales with 1/R1).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).

    Returns
    -------
    tuple of int
        The ends (-1 or +1) of V12(H), V_CE(sat), V_F: of the eight corners, the one of least :func:`delivered`.
    """
    return min(itertools.product((-1, 1), repeat=3), key=lambda ends: delivered(corner(s, ends), 1.0))


def r1_drift(s: dict) -> float:
    """R1's drift from 25 C to t_ambient at its largest, either way: ``r1_tempco`` x |t_ambient - 25 C|.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (``r1_tempco`` in 1/K, ``t_ambient`` in C).

    Returns
    -------
    float
        The drift, a fraction.
    """
    return s["r1_tempco"] * abs(s["t_ambient"] - 25.0)


def r1_ends(s: dict) -> tuple[float, float]:
    """R1's low and high ends as multipliers of its nominal: its tolerance and its drift at t_ambient, each either
    way, (1 - tolerance)(1 - drift) and (1 + tolerance)(1 + drift).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (``r1_tolerance`` a fraction, ``r1_tempco`` in 1/K, ``t_ambient`` in C).

    Returns
    -------
    tuple of float
        (low, high) multipliers of R1's nominal.
    """
    tol, drift = s["r1_tolerance"], r1_drift(s)
    return (1 - tol) * (1 - drift), (1 + tol) * (1 + drift)


def operating_point(s: dict) -> dict:
    """Eq 1 to 6a (the source's functions) at the nominal figures; R1 by eq 6a at the corner that delivers least,
    fitted from its series; the peak currents at their corners, the inductance to wind (A_L's tolerance, the slow
    corner), the frequency range over the supply, and the triangle's rms current at the highest peak current,
    I_peak,max / sqrt(3).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).

    Returns
    -------
    dict
        The source's eq 1 to 6a at the nominal figures (``vl_plus``, ``vl_minus`` in V, ``alpha`` a pure number,
        ``t1``, ``t2`` in s, ``i_peak`` in A, ``l1`` in H, ``r1`` in ohm) and ``r1_worst`` (eq 6a at the weak
        corner, ohm), ``r1_part`` (the series R1, ohm), ``i_out_least`` (the current delivered at the weak corner,
        R1 at its high end, A), ``i_peak_min`` and ``i_peak_max`` (A: V12(H) low and R1 high, V12(H) high and R1
        low), ``l1_max``, ``l1_nominal``, ``l1_min`` (H, A_L at +, 0 and - its tolerance), ``f_sw_min`` and
        ``f_sw_max`` (the full-load frequency's extremes over the supply range and the corners, Hz), ``i_rms`` (A),
        ``duty`` (t1 f_min, a fraction) and the corners (:func:`corner`) ``weak``, ``slow``, ``fast`` and ``hot``
        (a tuple, :data:`HOT`).
    """
    op = tca5600.design(source_params(s))
    (r_lo, r_hi), tol_l = r1_ends(s), s["a_l_tolerance"]
    weak, slow, fast = corner(s, weakest(s)), corner(s, SLOW), corner(s, FAST)
    r1_worst = tca5600.design(source_params(weak))["r1"]  # eq 5 and 6a where the least current is delivered
    r1_part = eseries.at_most(s["r1_series"], r1_worst / r_hi)
    i_min, i_max = fast["v12h"] / (r1_part * r_hi), slow["v12h"] / (r1_part * r_lo)
    l_max = frequency(slow, s["v_supply_min"], 1.0, i_max) / s["f_min"]  # f_min at the slow corner, lowest VCC2
    l_nom = l_max / (1 + tol_l)
    l_min = l_nom * (1 - tol_l)
    f_slow = [frequency(slow, v, l_max, i_max) for v in supplies(slow)]
    if s["v_supply_max"] >= v_top(slow):
        f_slow.append(0.0)
    v_peak = min(max((v_top(fast) + fast["v_ce_sat"] + fast["v12h"]) / 2, s["v_supply_min"]), max(supplies(fast)))
    f_fast = max(frequency(fast, v, l_min, i_min) for v in (*supplies(fast), v_peak))
    return {**op, "r1_worst": r1_worst, "r1_part": r1_part, "i_out_least": delivered(weak, r1_part * r_hi),
            "i_peak_min": i_min, "i_peak_max": i_max, "l1_max": l_max, "l1_nominal": l_nom, "l1_min": l_min,
            "f_sw_min": min(f_slow), "f_sw_max": f_fast, "i_rms": i_max / math.sqrt(3), "duty": op["t1"] * s["f_min"],
            "weak": weak, "slow": slow, "fast": fast, "hot": tuple(corner(s, ends) for ends in HOT)}


def designed_at(s: Table) -> Table:
    """The checked table the design runs at: ``s`` itself, or with ``audible`` = "avoid" and a full-load
    frequency that would fall into the audio band, ``s`` with f_min raised to :func:`inaudible_f_min`.

    Parameters
    ----------
    s : Table
        The checked ``[converter]`` table.

    Returns
    -------
    Table
        The checked table to design at.

    Raises
    ------
    Infeasible
        From :func:`inaudible_f_min`, when no f_min keeps every corner out of the audio band.
    """
    if s["audible"] != "avoid":
        return s
    f_needed = inaudible_f_min(s)
    return s if f_needed <= s["f_min"] else checked_table(TABLE, {**dict(s), "f_min": f_needed})


def inaudible_f_min(s: dict) -> float:
    """The lowest f_min at which the full-load frequency stays at or above :data:`AUDIO_BAND` (1 + ``audible_margin``)
    at every corner over the supply range: every frequency scales with f_min (L1 is inversely proportional to it,
    the peak currents do not depend on it), so f_min x that floor / f_sw_min, re-checked through the operating point
    (R1's series rounding) and nudged up until it holds.

    Parameters
    ----------
    s : Mapping
        The checked ``[converter]`` table (SI units).

    Returns
    -------
    float
        The f_min to design at, Hz: the spec's own when it already stays out of the audio band.

    Raises
    ------
    Infeasible
        When ``v_supply_max`` reaches :func:`~.coil.v_top` at the slow corner (V_F low: the frequency falls to zero
        there, whatever f_min), or the f_min needed is above the schema's highest.
    """
    from ..schema import TABLES

    top = v_top(corner(s, SLOW))
    if s["v_supply_max"] >= top:
        raise Infeasible(TABLE, f"audible = avoid: at VCC2 = {eng(top, 'V')} (V_F at its low end) V_L+ vanishes and the "
                         f"full-load frequency falls to zero whatever f_min; keep v_supply_max below it (or audible = "
                         f"warn)", {"v_supply_max": top})
    f_high = next(p.high for p in TABLES[TABLE] if p.name == "f_min")
    f, floor = s["f_min"], AUDIO_BAND * (1 + s["audible_margin"])
    for _ in range(20):
        low = operating_point({**dict(s), "f_min": f})["f_sw_min"]
        if low >= floor * (1 - 1e-9):
            return f
        f = f * floor / low * (1 + 1e-6)
        if f > f_high:
            break
    raise Infeasible(TABLE, f"audible = avoid: the full-load frequency stays above {eng(AUDIO_BAND, 'Hz')} up to "
                     f"v_supply_max = {eng(s['v_supply_max'], 'V')} only with f_min above {eng(f, 'Hz')}, more than the "
                     f"{eng(f_high, 'Hz')} allowed: lower v_supply_max or use audible = warn", {"f_min": f})
