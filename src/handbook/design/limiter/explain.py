"""What can be met when no limiter network meets the spec: the message of the Infeasible the design raises.

In order: the input headroom alone (its best over the resistor ranges, exact at the range's vertices by
the corner proof of :mod:`.model`); the margin (the best worst margin any continuous network
reaches, from the relaxation: IPOPT's figure, a local optimum); a pinned resistor (the exact search repeated
without each pin); the ranges.
"""
from __future__ import annotations

import numpy as np

from ...core import InputError
from ..solvers import Infeasible
from . import model as net
from .model import TABLE, best_headroom, choices
from .relaxation import Relaxation, smallest_r7
from .search import solve


def best_margin(s: dict) -> float | None:
    """The largest worst margin of any continuous network within the ranges (IPOPT on the relaxation).

    Parameters
    ----------
    s : Mapping
        The ``[current_limiter]`` table (SI units); every resistor's pin or series range bounds the relaxation.

    Returns
    -------
    float or None
        The largest worst margin, a fraction of the limits (negative: no continuous network keeps every corner
        inside the window); None when IPOPT finds the relaxation infeasible.

    Raises
    ------
    InputError
        When a free resistor's range holds no value of its series.
    """
    lists = [choices(s, n) for n in net.RESISTORS]
    lb, ub = np.array([v[0] for v in lists]), np.array([v[-1] for v in lists])
    res = Relaxation(s).solve(lb, ub, [*np.log(np.sqrt(lb * ub)), 0.0], 0.0)
    return None if res is None else float(res[0][6])


#: the tolerances a reader can tighten, each halved in turn to see which buys the most margin
TOLERANCES = ("resistor_tolerance", "r7_tolerance", "zener_tolerance", "zener_tc", "offset", "input_bias",
              "input_offset_current")


def window_reach(s: dict, margin: float | None = None) -> tuple[str, dict]:
    """The narrowest window the tolerances allow and the tolerance whose halving buys the most margin (the
    relaxation's figures: IPOPT over continuous networks, a local optimum, so about what a series network
    reaches).

    R7 scales every corner's trip current alike, so at the best network both margins are equal: with the best
    worst margin m0 at the window ratio k0 = i_must_trip / i_no_trip, the network's corner spread I_max / I_min
    is k0 (1 - m0) / (1 + m0), which does not depend on the window; the narrowest ratio that keeps
    ``min_margin`` = m is then that spread times (1 + m) / (1 - m), in closed form.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table whose window cannot be met.
    margin : float or None
        The best worst margin at ``s``'s window (:func:`best_margin`), if already known.

    Returns
    -------
    tuple
        (a clause for the message, "" when IPOPT finds nothing; {"i_must_trip_min": the smallest i_must_trip,
        A, with ``i_no_trip`` as it is, or None; "tighten": the tolerance key whose halving gains most, or None;
        "tighten_gain": that gain, a fraction, or None})
    """
    base = best_margin(s) if margin is None else margin
    out, text = {"i_must_trip_min": None, "tighten": None, "tighten_gain": None}, ""
    if base is None:
        return text, out
    k0, m = s["i_must_trip"] / s["i_no_trip"], s["min_margin"]
    k = k0 * (1 - base) / (1 + base) * (1 + m) / (1 - m)
    out["i_must_trip_min"] = s["i_no_trip"] * k
    text += (f"; with these tolerances the narrowest window IPOPT's continuous network meets is {s['i_no_trip']:g} .. "
             f"{s['i_no_trip'] * k:.4g} A (i_must_trip / i_no_trip = {k:.4g}; series values need about that or a "
             "little more, and v_drop_max then bounds the R7 it takes)")
    gains = {}
    for key in TOLERANCES:
        if s[key] > 0:
            tight = best_margin({**s, key: s[key] / 2})
            if tight is not None:
                gains[key] = tight - base
    if gains:
        key = max(gains, key=gains.get)
        out.update(tighten=key, tighten_gain=gains[key])
        text += f"; halving {key} buys the most ({gains[key]:+.2%} of worst margin)"
    return text, out


def drop_levers(s: dict) -> tuple[str, dict]:
    """For a window met only with too large a drop in R7: the tolerance whose halving lowers the smallest R7
    most, and about what drop that leaves (IPOPT's smallest continuous R7, :func:`~.relaxation.smallest_r7`,
    scaled by the exact design's drop).

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table.

    Returns
    -------
    tuple
        (a clause for the message, "" when IPOPT finds nothing; {"tighten": the tolerance key, or None,
        "r7_relaxed_tight": IPOPT's smallest R7 with it halved, ohm, or None})
    """
    base = smallest_r7(s)
    tight = {key: smallest_r7({**s, key: s[key] / 2}) for key in TOLERANCES if s[key] > 0}
    tight = {k: v for k, v in tight.items() if v is not None}
    if base is None or not tight:
        return "", {"tighten": None, "r7_relaxed_tight": None}
    key = min(tight, key=tight.get)
    return (f"; halving {key} lowers the smallest R7 most, to about {tight[key] / base:.0%} of it (IPOPT's "
            "continuous network)", {"tighten": key, "r7_relaxed_tight": tight[key]})


def least_divider_current(s: dict) -> float:
    """The least current any network of the ranges (or pins) draws from the zener node (largest values).

    Parameters
    ----------
    s : Mapping
        The ``[current_limiter]`` table (SI units); each divider resistor's pin or series range is used.

    Returns
    -------
    float
        The least divider current, A: :func:`~handbook.design.limiter.model.divider_current` of every divider
        resistor at its largest value.

    Raises
    ------
    InputError
        When a free divider resistor's range holds no value of its series.
    """
    return float(net.divider_current(tuple(choices(s, n)[-1] for n in net.DIVIDER), s))


def _reason(s: dict) -> tuple[str, dict]:
    least = least_divider_current(s)
    if least > s["divider_current_max"]:
        return (f"every network draws at least {least * 1e3:.3g} mA from the zener node, more than divider_current_max "
                f"= {s['divider_current_max'] * 1e3:.3g} mA: allow larger divider resistors (r9_max .. r13_max) or a "
                f"stronger zener feed", {"divider_current_min": least})
    head = best_headroom(s)
    if head < s["input_headroom"]:
        return (f"no network keeps both op-amp inputs {s['input_headroom']:g} V below the supply: with D1 at its "
                f"lowest ({net.zener_range(s)[0]:.3g} V) the best these resistor ranges allow is {head:.3g} V; use a "
                f"higher zener_voltage, wider ranges or an op-amp that works nearer its supply (a lower "
                f"input_headroom)", {"headroom_max": head})
    margin = best_margin(s)
    if margin is None or margin < s["min_margin"]:
        start = (f"no network keeps every corner's trip current inside {s['i_no_trip']:g} .. {s['i_must_trip']:g} A "
                 f"with a {s['min_margin']:.1%} margin: ")
        reach = window_reach(s, margin)
        if margin is None or margin < 0:
            return (start + "none keeps it inside the window at all at every corner; widen the window (now "
                    f"i_must_trip / i_no_trip = {s['i_must_trip'] / s['i_no_trip']:.3g}), use tighter tolerances or "
                    f"free a pinned resistor{reach[0]}", {"min_margin_max": margin, **reach[1]})
        return (start + f"the best worst margin any network reaches is {margin:.2%}; lower min_margin to that, widen "
                f"the window (now i_must_trip / i_no_trip = {s['i_must_trip'] / s['i_no_trip']:.3g}) or use tighter "
                f"tolerances{reach[0]}", {"min_margin_max": margin, **reach[1]})
    r7_relaxed = smallest_r7(s)
    hint = f" (IPOPT's continuous network needs R7 >= {r7_relaxed:.3g} ohm)" if r7_relaxed else ""
    return (f"no {s['r7_series']} R7 within {s['r7_min']:g} .. {s['r7_max']:g} ohm has a series network meeting "
            f"the spec{hint}: widen the R7 range or use finer series", {"r7_relaxed": r7_relaxed})


def explain(s: dict) -> Infeasible:
    """The Infeasible that says why, and what would be met. A pinned resistor is blamed when the exact search,
    that pin freed, finds a series network that meets the whole spec (the divider current's and the headroom's
    exact bests are checked first); a pin whose own range holds no value of its series is not freed.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units) that no network meets.

    Returns
    -------
    Infeasible
        Not raised: its message says why and what can be met; its ``achievable`` holds one of
        "divider_current_min" (the least divider current, A), "headroom_max" (the best least headroom, V),
        "min_margin_max" (the best worst margin, a fraction, or None) or "r7_relaxed" (ohm, or None), and
        "pinned" (the blamed resistor's name, "r7" .. "r13") when a pinned resistor is blamed.

    Raises
    ------
    InputError
        When a free resistor's range holds no value of its series.
    """
    message, achievable = _reason(s)
    for name in (n for n in ("r7",) + net.DIVIDER if s[n] is not None):
        free = {**s, name: None}
        try:
            lifted = _lifts(free, s, achievable)
        except InputError:  # its range holds no value of its series: freeing it is no way out
            continue
        found = solve(free)["r7"] if lifted else None
        if found is not None:
            return Infeasible(TABLE, f"{name} = {s[name]:g} ohm (pinned) makes the spec infeasible: {message}. Left "
                             f"free, a network of the {s[name + '_series']} range {s[name + '_min']:g} .. "
                             f"{s[name + '_max']:g} ohm meets it (with R7 = {found:.3g} ohm)",
                              {**achievable, "pinned": name})
    return Infeasible(TABLE, message, achievable)


def _lifts(free: dict, s: dict, achievable: dict) -> bool:
    """Freeing a pin lifts the cause ``achievable`` names (a necessary condition, checked before the search)."""
    if "divider_current_min" in achievable:
        return least_divider_current(free) <= s["divider_current_max"]
    if "headroom_max" in achievable:
        return best_headroom(free) >= s["input_headroom"]
    return True  # the margin: the exact search decides
