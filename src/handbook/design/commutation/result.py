"""The TDA5143/TDA5144 timing set: CAP-CD (= CAP-DC), and from motor data CAP-ST and CAP-TI.

CAP-CD is charged at I_ch for one commutation interval t_com (eq 4) and must swing by I_ch t_com / C:
within the window between the low and high switching levels at ``rpm_min``, above the noise floor at
``rpm_max``. The swing rises with I_ch and falls with C; the window rises with the high level and falls
with the low level (signs proven symbolically in the design chapter). So the worst case is a corner of
the tolerance box, and the smallest capacitor meeting the window has the exact closed form

    C >= I_ch,max t_com(rpm_min) / ((1 - tol) (V_high,min - V_low,max))

snapped to the series and re-checked at all 16 corners (:func:`verify`). The choice is one-dimensional
and monotonic: no optimiser is needed and none is used. The smallest C also gives the largest swing at
``rpm_max``, so it maximises the noise margin. CAP-ST and CAP-TI: :mod:`.timers`; the
device sanity warnings: :mod:`.checks`.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from ...core import InputError, series, tolerance
from ...sources.an94002 import circuit as an94002
from ..common import Result, Table, checked_table, completed, is_checked, ordered, reported
from ..solvers import Infeasible
from . import checks, timers

TABLE = "commutation"

BINDING = {
    "window": "swing at rpm_min fits the window (largest current, smallest capacitor, narrowest window)",
    "noise": "swing at rpm_max stays above the noise floor (smallest current, largest capacitor)",
}


@dataclass(frozen=True)
class CommutationResult(Result):
    cap_cd: float = reported('F', 'CAP-CD')
    cap_dc: float = reported('F', 'CAP-DC')
    rpm_min_reliable: float = reported('rpm', 'lowest reliable speed')
    rpm_max_reliable: float = reported('rpm', 'highest reliable speed')
    noise_margin: float = reported('%', 'margin above the noise floor at rpm_max')
    binding: str = reported('', 'binding')
    cap_st: float | None = reported('F', 'CAP-ST (motor data given)')
    cap_ti: float | None = reported('F', 'CAP-TI (flyback_time given)')
    warnings: tuple = reported('', 'warnings')
    continuous_optimum: float  # the closed-form bound (F)
    swing_at_rpm_min: float
    swing_at_rpm_max: float
    window_corner: dict  # the corner at which the window binds
    next_smaller: float
    next_smaller_fails: str
    start: timers.StartResult | None
    watchdog: timers.WatchdogResult | None

    table = TABLE


def checked(spec: Mapping | None) -> Table:
    """The ``[commutation]`` table completed with its defaults and checked: ranges, then the limits that
    contradict each other (ordered ranges, the noise floor inside the window, ``rpm_reverse`` without
    ``flyback_time``, part of the motor data).

    Parameters
    ----------
    spec : Mapping or None
        The ``[commutation]`` table, {key: value} in SI units (speeds in rpm): missing keys take their defaults,
        None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    Table
        Every key of the table, checked (SI units, speeds in rpm).

    Raises
    ------
    InputError
        When a key is unknown, a value is out of range, or two limits contradict each other.
    """
    if is_checked(TABLE, spec):  # checked once, where it was read
        return spec
    s = completed(TABLE, spec)
    ordered(TABLE, "rpm_min", "rpm_max", s, "rpm")
    for low, high, unit in (("i_charge_min", "i_charge_max", "A"), ("v_low_min", "v_low_max", "V"),
                            ("v_high_min", "v_high_max", "V"), ("i_st_min", "i_st_max", "A"),
                            ("i_wd_min", "i_wd_max", "A")):
        ordered(TABLE, low, high, s, unit, strict=False)
    ordered(TABLE, "v_low_max", "v_high_min", s, "V")
    ordered(TABLE, "v_st_low", "v_st_high", s, "V")
    window = s["v_high_min"] - s["v_low_max"]
    if s["min_excursion"] >= window:
        raise InputError(f"commutation.min_excursion = {s['min_excursion']:g} V must be below the narrowest window "
                         f"v_high_min - v_low_max = {window:g} V")
    if s["rpm_reverse"] is not None and s["flyback_time"] is None:
        raise InputError(f"commutation.rpm_reverse = {s['rpm_reverse']:g} rpm bounds CAP-TI from above; give "
                         "commutation.flyback_time too (its lower bound), or leave rpm_reverse out")
    timers.motor_given(s)
    return checked_table(TABLE, s)


def box(c: float, s: dict, levels: bool = True) -> dict:
    """The tolerance box of one capacitor value: capacitance, charge current (and the two levels).

    Parameters
    ----------
    c : float
        CAP-CD, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
    levels : bool
        Include the low and high switching levels.

    Returns
    -------
    dict
        {"cap": (low, high) in F, at +- ``tolerance``; "i": (``i_charge_min``, ``i_charge_max``) in A}, and with
        ``levels`` "v_low" and "v_high": (smallest, largest) in V.
    """
    out = {"cap": tolerance.symmetric(c, s["tolerance"]), "i": (s["i_charge_min"], s["i_charge_max"])}
    if levels:
        out.update(v_low=(s["v_low_min"], s["v_low_max"]), v_high=(s["v_high_min"], s["v_high_max"]))
    return out


def bounds(s: dict) -> tuple[float, float]:
    """(smallest C meeting the window at rpm_min, largest C meeting the noise floor at rpm_max), in F:
    the closed forms at the corners the monotonicity picks.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    tuple of float
        (the smallest continuous CAP-CD whose swing at ``rpm_min`` fits the narrowest window, F; the largest
        whose swing at ``rpm_max`` stays above ``min_excursion``, F). The spec can be met only if the first is
        not above the second.
    """
    n, tol = s["pole_pairs"], s["tolerance"]
    window = s["v_high_min"] - s["v_low_max"]
    c_low = s["i_charge_max"] * an94002.t_com(s["rpm_min"], n) / (window * (1 - tol))
    c_high = s["i_charge_min"] * an94002.t_com(s["rpm_max"], n) / (s["min_excursion"] * (1 + tol))
    return c_low, c_high


def verify(c: float, s: dict) -> dict:
    """One capacitor value at every corner (16 for the window, 4 for the noise floor): worst swings and
    the speeds it covers.

    Parameters
    ----------
    c : float
        CAP-CD, nominal, F.
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    dict
        ``swing_at_rpm_min`` (the swing at ``rpm_min`` at the corner where it most exceeds the window, V),
        ``window_at_corner`` (that corner's window, V), ``window_corner`` (that corner: {"cap" F, "i" A,
        "v_low" V, "v_high" V}), ``swing_at_rpm_max`` (the smallest swing at ``rpm_max``, V), ``window_ok`` and
        ``noise_ok`` (bool: the window and the noise floor hold at every corner), ``rpm_min_reliable`` and
        ``rpm_max_reliable`` (the speed range every corner covers, rpm).
    """
    n, floor = s["pole_pairs"], s["min_excursion"]
    t_slow, t_fast = an94002.t_com(s["rpm_min"], n), an94002.t_com(s["rpm_max"], n)
    excess, corner = timers.worst(lambda cap, i, v_low, v_high: i * t_slow / cap - (v_high - v_low), box(c, s),
                                  largest=True)
    swing_fast, _ = timers.worst(lambda cap, i: i * t_fast / cap, box(c, s, False), largest=False)
    lo, _ = timers.worst(lambda cap, i, v_low, v_high: 10 * i / (n * cap * (v_high - v_low)), box(c, s), largest=True)
    hi, _ = timers.worst(lambda cap, i: 10 * i / (n * cap * floor), box(c, s, False), largest=False)
    swing_slow = excess + corner["v_high"] - corner["v_low"]
    return {
        "swing_at_rpm_min": swing_slow, "window_at_corner": corner["v_high"] - corner["v_low"],
        "window_corner": corner, "swing_at_rpm_max": swing_fast,
        "window_ok": excess <= 1e-12 * swing_slow, "noise_ok": swing_fast >= floor * (1 - 1e-12),
        "rpm_min_reliable": lo, "rpm_max_reliable": hi,
    }


def infeasible(s: dict, chosen: float, check: dict) -> Infeasible:
    """The Infeasible for a speed range no CAP-CD covers: what the smallest fitting value reaches, and the
    speed ratio any capacitor can cover (it does not depend on the capacitor).

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
    chosen : float
        The smallest series CAP-CD that fits the window at ``rpm_min``, F.
    check : dict
        Its :func:`verify`; ``rpm_max_reliable`` (rpm) is read.

    Returns
    -------
    Infeasible
        The exception to raise (not raised here): ``achievable`` holds ``cap_cd`` (F), ``rpm_min`` and
        ``rpm_max_reliable`` (rpm) and ``rpm_ratio_possible`` (the widest rpm_max / rpm_min, a pure number).
    """
    c_probe = 1e-9  # the achievable speed ratio does not depend on the capacitor
    probe = verify(c_probe, s)
    return Infeasible(
        TABLE,
        f"no {s['series']} capacitor covers {s['rpm_min']:g} to {s['rpm_max']:g} rpm: the smallest that fits "
        f"the window at {s['rpm_min']:g} rpm ({chosen * 1e9:.3g} nF) keeps a swing above "
        f"{s['min_excursion']:g} V only up to {check['rpm_max_reliable']:.0f} rpm",
        {"cap_cd": chosen, "rpm_min": s["rpm_min"], "rpm_max_reliable": check["rpm_max_reliable"],
         "rpm_ratio_possible": probe["rpm_max_reliable"] / probe["rpm_min_reliable"]})


def design_cap_cd(s: dict) -> dict:
    """CAP-CD: closed-form bound -> smallest series value at or above it -> every corner re-checked.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    dict
        ``cap_cd`` (the chosen series value, F), ``bound`` (the continuous bound, F), ``check`` (its
        :func:`verify`), ``below`` (the next smaller series value, F) and ``why`` (str: why that one fails).

    Raises
    ------
    Infeasible
        When no series value both fits the window at ``rpm_min`` and keeps the swing above the noise floor at
        ``rpm_max`` (:func:`infeasible`).
    """
    c_low, c_high = bounds(s)
    chosen = series.at_least(s["series"], c_low * (1 - 1e-12))
    check = verify(chosen, s)
    if not (c_low <= c_high * (1 + 1e-9) and check["window_ok"] and check["noise_ok"]):
        raise infeasible(s, chosen, check)
    below = series.at_most(s["series"], chosen * (1 - 1e-9))
    fail = verify(below, s)
    corner = fail["window_corner"]
    why = (f"{below * 1e9:.3g} nF at {corner['cap'] * 1e9:.4g} nF with {corner['i'] * 1e6:.3g} µA swings "
           f"{fail['swing_at_rpm_min']:.3g} V at {s['rpm_min']:g} rpm, more than the "
           f"{corner['v_high']:g} V - {corner['v_low']:g} V window")
    return {"cap_cd": chosen, "bound": c_low, "check": check, "below": below, "why": why}


def design(spec: dict | None = None) -> CommutationResult:
    """The timing set: CAP-CD = CAP-DC always; CAP-ST with J, K_t and start_current; CAP-TI with
    flyback_time. Each closed form, snapped, re-checked at every corner; device warnings attached.

    Parameters
    ----------
    spec : Mapping or None
        The ``[commutation]`` table, {key: value} in SI units (speeds in rpm): missing keys take their defaults,
        None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    CommutationResult
        The checked spec; CAP-CD = CAP-DC, CAP-ST and CAP-TI (F; None where not designed); the reliable speed
        range (rpm); the noise margin (fraction); what binds; the warnings; and the details (continuous bound
        and next smaller value in F, swings in V, the binding corner, the start and watchdog designs).

    Raises
    ------
    InputError
        When the spec is invalid.
    Infeasible
        When no series CAP-CD covers the speed range, no CAP-ST settles within ``t_start_max``, or no CAP-TI
        both outlasts the flyback and catches ``rpm_reverse``.
    """
    s = checked(spec)
    cd = design_cap_cd(s)
    check = cd["check"]
    start, watchdog = timers.design_start(s), timers.design_watchdog(s)
    noise_margin = check["swing_at_rpm_max"] / s["min_excursion"] - 1
    return CommutationResult(
        spec=s, cap_cd=cd["cap_cd"], cap_dc=cd["cap_cd"],
        rpm_min_reliable=check["rpm_min_reliable"], rpm_max_reliable=check["rpm_max_reliable"],
        binding=BINDING["window"], continuous_optimum=cd["bound"], noise_margin=noise_margin,
        swing_at_rpm_min=check["swing_at_rpm_min"], swing_at_rpm_max=check["swing_at_rpm_max"],
        window_corner=check["window_corner"], next_smaller=cd["below"], next_smaller_fails=cd["why"],
        cap_st=None if start is None else start.cap_st, cap_ti=None if watchdog is None else watchdog.cap_ti,
        start=start, watchdog=watchdog,
        warnings=tuple(checks.warnings(s, cd["cap_cd"], start, watchdog)),
    )


def enumerate_series(spec: dict) -> float | None:
    """Exhaustive check: the smallest value of the series (1 pF..1 mF) that passes :func:`verify`.

    Parameters
    ----------
    spec : Mapping or None
        The ``[commutation]`` table, {key: value} in SI units (speeds in rpm): missing keys take their defaults,
        None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    float or None
        The smallest series CAP-CD meeting both the window and the noise floor at every corner, F; None when
        none does.

    Raises
    ------
    InputError
        When the spec is invalid.
    """
    s = checked(spec)
    for v in series.values(s["series"], 1e-12, 1e-3):
        chk = verify(v, s)
        if chk["window_ok"]:
            return v if chk["noise_ok"] else None
    return None


def sensitivity(s: dict) -> list[dict]:
    """Which tolerance eats most of the speed range: each group pinned to the middle of its range in turn.

    For a capacitor at its bound the worst-case speed range rpm_max_reliable / rpm_min_reliable is
    (window_min / floor) (I_min / I_max) (1 - tol) / (1 + tol); a group's share is the part of the log of
    that loss (against every group pinned) that pinning it recovers.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).

    Returns
    -------
    list of dict
        One row per group ("capacitor tolerance", "charge current", "low level", "high level"): ``group``
        (str), ``range_gain`` (the factor by which pinning it widens rpm_max_reliable / rpm_min_reliable),
        ``share`` (the fraction of the log of the whole loss it recovers) and ``cap_cd_bound`` (the continuous
        CAP-CD bound with it pinned, F).
    """
    mid = lambda lo, hi: (lo + hi) / 2  # noqa: E731
    groups = {"capacitor tolerance": {"tolerance": 0.0},
              "charge current": dict.fromkeys(("i_charge_min", "i_charge_max"), mid(s["i_charge_min"],
                                                                                     s["i_charge_max"])),
              "low level": dict.fromkeys(("v_low_min", "v_low_max"), mid(s["v_low_min"], s["v_low_max"])),
              "high level": dict.fromkeys(("v_high_min", "v_high_max"), mid(s["v_high_min"], s["v_high_max"]))}

    def ratio(pinned: dict) -> float:
        chk = verify(1e-9, {**s, **pinned})
        return chk["rpm_max_reliable"] / chk["rpm_min_reliable"]

    base = ratio({})
    ideal = ratio({k: v for g in groups.values() for k, v in g.items()})
    total = math.log(ideal / base)  # 0 when nothing spreads: no group has a share of a loss that is not there
    rows = []
    for name, pinned in groups.items():
        gain = ratio(pinned) / base
        rows.append({"group": name, "range_gain": gain, "share": math.log(gain) / total if total > 0 else 0.0,
                     "cap_cd_bound": bounds({**s, **pinned})[0]})
    return rows
