"""CAP-ST (start oscillator) and CAP-TI (watchdog) of the TDA5143/TDA5144 from the motor's data.

Both choices are one-dimensional and every quantity is monotonic in each input (charge balance,
t = C dV / I, and eq 2's sqrt(K_t I p / J)), so the worst case sits at a corner of the tolerance box and
the continuous bound has an exact closed form; the series value is snapped from it and re-checked at
every corner (:func:`worst`, 2^k points). No numerical optimiser is needed and none is used.

* CAP-ST: the smallest capacitor whose shortest start period (smallest C, largest current) still lets
  the slowest rotor rocking (smallest K_t and start current, largest J; eq 2) decay to ``residual``;
  the longest period (largest C, smallest current) must stay within ``t_start_max`` if given.
* CAP-TI: the shortest watchdog time (smallest C, largest current) must outlast the flyback pulse; the
  longest must be shorter than a reverse-turning rotor needs for 150 electrical degrees at
  ``rpm_reverse`` (if given). With both, the value maximising the smaller of the two ratios.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...core import InputError, series, tolerance
from ...sources.an94002 import circuit as an94002
from ..solvers import Infeasible

TABLE = "commutation"
#: CAP-TI watchdog ramp 0.3 V -> 2.2 V (AN94002 2.1.3; TDA5144 datasheet)
V_TI = (0.3, 2.2)
#: the smallest CAP-TI (AN94002 2.1.3: "The minimum value for CAP-TI is 2000 pF")
CAP_TI_MIN = 2e-9
START_KEYS = ("inertia", "torque_constant", "start_current")


def worst(f, ranges: dict, largest: bool) -> tuple[float, dict]:
    """The largest (or smallest) value of ``f`` over every corner of the box ``ranges`` (core.tolerance.corners).

    Parameters
    ----------
    f : callable
        A function of keyword arguments, one per name of ``ranges``, returning a float.
    ranges : dict
        {argument name: (low, high)}, each end in the argument's own unit.
    largest : bool
        True for the largest value, False for the smallest.

    Returns
    -------
    tuple
        (value, corner): the extreme value of ``f`` (its own unit) and the corner, {name: value}, where it
        lies (the first such corner on a tie).
    """
    middle = {n: (lo + hi) / 2 for n, (lo, hi) in ranges.items()}
    wc = tolerance.corners(np.vectorize(f, otypes=[float]), middle, ranges)
    return (wc.high, wc.high_corner) if largest else (wc.low, wc.low_corner)


def motor_given(s: dict) -> bool:
    """True when J, K_t and the start current are all given; a part of them is an input error.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    bool
        True when ``inertia``, ``torque_constant`` and ``start_current`` are all given, False when none is.

    Raises
    ------
    InputError
        When some but not all of the three are given.
    """
    given = [k for k in START_KEYS if s[k] is not None]
    if given and len(given) < len(START_KEYS):
        missing = [f"commutation.{k}" for k in START_KEYS if s[k] is None]
        raise InputError(f"CAP-ST needs all of {', '.join('commutation.' + k for k in START_KEYS)}: "
                         f"{', '.join(missing)} not given")
    return bool(given)


# ----------------------------------------------------------------------------------------------
# CAP-ST

@dataclass(frozen=True)
class StartResult:
    cap_st: float
    bound: float  # closed-form smallest continuous capacitor
    f_osc_min: float  # slowest rotor rocking over the motor's corners (eq 2)
    f_osc_max: float
    settle: float  # rocking decay time at the slowest corner
    period_min: float  # shortest start period of the chosen capacitor (worst corner)
    period_max: float
    margin: float  # period_min / settle - 1
    next_smaller: float
    binding: str


def rocking_box(s: dict) -> dict:
    """The motor's tolerance box for the rocking frequency (eq 2): each motor figure at +- ``motor_tolerance``.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    dict
        {"torque_constant": (low, high) in N m/A, "current": (low, high) start current in A, "inertia": (low,
        high) in kg m^2}.
    """
    t = s["motor_tolerance"]
    return {"torque_constant": tolerance.symmetric(s["torque_constant"], t),
            "current": tolerance.symmetric(s["start_current"], t), "inertia": tolerance.symmetric(s["inertia"], t)}


def f_osc(s: dict):
    """Eq 2 as a function of the motor's figures, the pole pairs taken from ``s``.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    callable
        ``f(torque_constant, current, inertia)`` (N m/A, A, kg m^2) -> the rotor's rocking frequency about a
        detent, Hz.
    """
    return lambda torque_constant, current, inertia: an94002.oscillation_frequency(
        torque_constant, current, s["pole_pairs"], inertia)


def start_box(c: float, s: dict) -> dict:
    """The tolerance box of one CAP-ST value: capacitance and charge current.

    Parameters
    ----------
    c : float
        CAP-ST, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    dict
        {"cap": (low, high) in F, at +- ``tolerance``; "i_cap": (``i_st_min``, ``i_st_max``) in A}.
    """
    return {"cap": tolerance.symmetric(c, s["tolerance"]), "i_cap": (s["i_st_min"], s["i_st_max"])}


def start_period(s: dict):
    """Eq 1 as a function of the capacitor and its current, the switching levels taken from ``s``.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    callable
        ``f(cap, i_cap)`` (F, A) -> the start oscillator's period, s.
    """
    return lambda cap, i_cap: an94002.start_period(cap, i_cap, s["v_st_low"], s["v_st_high"])


def check_start(c: float, s: dict) -> dict:
    """Every corner of one CAP-ST value: shortest and longest period against the rocking's decay.

    Parameters
    ----------
    c : float
        CAP-ST, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    dict
        ``settle`` (the slowest rocking's decay to ``residual``, s), ``period_min`` and ``period_max`` (the start
        period at its shortest and longest corner, s), ``settles`` (bool: the shortest period outlasts the
        decay) and ``fast_enough`` (bool: the longest is within ``t_start_max``, or none is set).
    """
    f_lo = worst(f_osc(s), rocking_box(s), largest=False)[0]
    settle = an94002.settle_time(f_lo, s["damping_ratio"], s["residual"])
    p_lo = worst(start_period(s), start_box(c, s), largest=False)[0]
    p_hi = worst(start_period(s), start_box(c, s), largest=True)[0]
    return {"settle": settle, "period_min": p_lo, "period_max": p_hi, "settles": p_lo >= settle * (1 - 1e-12),
            "fast_enough": s["t_start_max"] is None or p_hi <= s["t_start_max"] * (1 + 1e-12)}


def design_start(s: dict) -> StartResult | None:
    """Smallest series CAP-ST whose shortest period outlasts the slowest rocking's decay (closed form).

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    StartResult or None
        The chosen CAP-ST (F), its continuous bound (F), the rocking frequency range (Hz), the decay time and
        the period range (s), the margin (fraction), the next smaller series value (F) and what binds; None when
        no motor data is given.

    Raises
    ------
    InputError
        When only part of the motor data is given (:func:`motor_given`).
    Infeasible
        When the smallest series value that lets the rocking decay has a longest period above ``t_start_max``.
    """
    if not motor_given(s):
        return None
    f_lo = worst(f_osc(s), rocking_box(s), largest=False)[0]
    settle = an94002.settle_time(f_lo, s["damping_ratio"], s["residual"])
    # period_min = 2 C (1 - tol) dV / I_max >= settle, exactly:
    bound = settle * s["i_st_max"] / (2 * (s["v_st_high"] - s["v_st_low"]) * (1 - s["tolerance"]))
    chosen = series.at_least(s["series"], bound * (1 - 1e-12))
    chk = check_start(chosen, s)
    if not (chk["settles"] and chk["fast_enough"]):
        shortest_max = chk["period_max"]
        raise Infeasible(TABLE, f"no {s['series']} CAP-ST lets the rocking decay to {s['residual']:g} "
                         f"(damping ratio {s['damping_ratio']:g}) and keeps the start period within "
                         f"{s['t_start_max']:g} s: the smallest that settles ({chosen * 1e9:.4g} nF) may take "
                         f"{shortest_max:.3g} s", {"cap_st": chosen, "t_start_max_possible": shortest_max,
                                                    "settle_time": settle})
    return StartResult(
        cap_st=chosen, bound=bound, f_osc_min=f_lo, f_osc_max=worst(f_osc(s), rocking_box(s), largest=True)[0],
        settle=settle, period_min=chk["period_min"], period_max=chk["period_max"],
        margin=chk["period_min"] / settle - 1, next_smaller=series.at_most(s["series"], chosen * (1 - 1e-9)),
        binding="the rocking must decay before the next start pulse (slowest rotor, shortest period)")


# ----------------------------------------------------------------------------------------------
# CAP-TI

@dataclass(frozen=True)
class WatchdogResult:
    cap_ti: float
    t_wd_min: float  # shortest watchdog time (smallest C, largest current)
    t_wd_max: float
    t_reverse: float | None  # the limit from rpm_reverse
    rpm_reverse_caught: float  # fastest reverse rotation the longest watchdog still catches
    margin_flyback: float  # t_wd_min / flyback_time - 1
    margin_reverse: float | None  # t_reverse / t_wd_max - 1
    binding: str


def watchdog_time(s: dict):
    """Eq 9 solved for the time, as a function of the capacitor and its current (ramp :data:`V_TI`).

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
        Not read: the ramp's levels are the device's (:data:`V_TI`).

    Returns
    -------
    callable
        ``f(cap, i_wd)`` (F, A) -> the watchdog time, s.
    """
    return lambda cap, i_wd: an94002.watchdog_time(cap, i_wd, *V_TI)


def check_watchdog(c: float, s: dict) -> dict:
    """Every corner of one CAP-TI value: shortest and longest watchdog time against the flyback and the
    reverse-rotation limit.

    Parameters
    ----------
    c : float
        CAP-TI, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
        ``flyback_time`` must be given.

    Returns
    -------
    dict
        ``t_wd_min`` and ``t_wd_max`` (the watchdog time at its shortest and longest corner, s), ``t_reverse``
        (the time a rotor reversing at ``rpm_reverse`` takes for 150 electrical degrees, s; None when no
        ``rpm_reverse``), ``long_enough`` (bool: the shortest outlasts the flyback and ``c`` is at least
        :data:`CAP_TI_MIN`) and ``short_enough`` (bool: the longest is within ``t_reverse``, or there is none).
    """
    box = {"cap": tolerance.symmetric(c, s["tolerance"]), "i_wd": (s["i_wd_min"], s["i_wd_max"])}
    lo = worst(watchdog_time(s), box, largest=False)[0]
    hi = worst(watchdog_time(s), box, largest=True)[0]
    t_rev = None if s["rpm_reverse"] is None else an94002.reverse_catch_time(s["rpm_reverse"], s["pole_pairs"])
    return {"t_wd_min": lo, "t_wd_max": hi, "t_reverse": t_rev,
            "long_enough": lo >= s["flyback_time"] * (1 - 1e-12) and c >= CAP_TI_MIN * (1 - 1e-12),
            "short_enough": t_rev is None or hi <= t_rev * (1 + 1e-12)}


def watchdog_score(c: float, s: dict) -> float:
    """The smaller of the two ratios (flyback side, reverse side); the choice maximises it.

    Parameters
    ----------
    c : float
        CAP-TI, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
        ``flyback_time`` must be given.

    Returns
    -------
    float
        min(t_wd_min / flyback_time, t_reverse / t_wd_max), a pure number (the second only with
        ``rpm_reverse``); at least 1 where both limits hold.
    """
    chk = check_watchdog(c, s)
    ratios = [chk["t_wd_min"] / s["flyback_time"]]
    if chk["t_reverse"] is not None:
        ratios.append(chk["t_reverse"] / chk["t_wd_max"])
    return min(ratios)


def cap_ti_choice(s: dict) -> float:
    """Closed form: the smallest C meeting the flyback; with a reverse limit the geometric middle of the
    two bounds, snapped to whichever neighbouring series value has the larger smaller ratio.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
        ``flyback_time`` must be given.

    Returns
    -------
    float
        The chosen series CAP-TI, F (at least :data:`CAP_TI_MIN`); not yet checked against the limits.
    """
    dv = V_TI[1] - V_TI[0]
    low = s["flyback_time"] * s["i_wd_max"] / (dv * (1 - s["tolerance"]))
    if s["rpm_reverse"] is None:
        return series.at_least(s["series"], max(low, CAP_TI_MIN) * (1 - 1e-12))
    high = an94002.reverse_catch_time(s["rpm_reverse"], s["pole_pairs"]) * s["i_wd_min"] / (dv * (1 + s["tolerance"]))
    middle = math.sqrt(low * high)
    below = series.at_most(s["series"], middle)
    candidates = [c for c in (below, series.at_least(s["series"], middle)) if c >= CAP_TI_MIN * (1 - 1e-12)]
    candidates = candidates or [series.at_least(s["series"], CAP_TI_MIN * (1 - 1e-12))]
    return max(candidates, key=lambda c: watchdog_score(c, s))


def design_watchdog(s: dict) -> WatchdogResult | None:
    """CAP-TI from the flyback time (and the reverse speed, if given), checked at every corner.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    WatchdogResult or None
        The chosen CAP-TI (F), its watchdog time range and the reverse limit (s), the fastest reverse rotation
        caught (rpm), the margins on either side (fractions; the reverse one None without ``rpm_reverse``) and
        what binds; None when no ``flyback_time`` is given.

    Raises
    ------
    Infeasible
        When no series value both outlasts the flyback (and is at least 2000 pF) and catches reverse rotation
        at ``rpm_reverse``.
    """
    if s["flyback_time"] is None:
        return None
    chosen = cap_ti_choice(s)
    chk = check_watchdog(chosen, s)
    caught = 150.0 / 60.0 * 10.0 / (s["pole_pairs"] * chk["t_wd_max"])
    if not (chk["long_enough"] and chk["short_enough"]):
        raise Infeasible(TABLE, f"no {s['series']} CAP-TI both outlasts the {s['flyback_time'] * 1e3:.3g} ms flyback "
                         f"(and is at least 2000 pF) and catches reverse rotation at {s['rpm_reverse']:g} rpm: the "
                         f"best ({chosen * 1e9:.4g} nF) catches it only up to {caught:.0f} rpm",
                         {"cap_ti": chosen, "rpm_reverse_caught": caught, "t_wd_min": chk["t_wd_min"]})
    t_rev = chk["t_reverse"]
    m_fly = chk["t_wd_min"] / s["flyback_time"] - 1
    m_rev = None if t_rev is None else t_rev / chk["t_wd_max"] - 1
    if m_rev is None:
        binding = "watchdog outlasts the flyback (smallest C, largest current)"
    else:
        binding = ("balanced: flyback and reverse rotation" if abs(m_fly - m_rev) < 1e-9 else
                   "flyback (shortest watchdog)" if m_fly < m_rev else "reverse rotation (longest watchdog)")
    return WatchdogResult(cap_ti=chosen, t_wd_min=chk["t_wd_min"], t_wd_max=chk["t_wd_max"], t_reverse=t_rev,
                          rpm_reverse_caught=caught, margin_flyback=m_fly, margin_reverse=m_rev, binding=binding)
