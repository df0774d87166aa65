"""The op-amp current limiter (AN94002 figure 3) designed as a whole network: R7, R9, R10, R11, R12, R13.

Problem. Every resistor takes a value of its series within its range (or the value it is pinned to). At
every tolerance corner (:mod:`.model`: resistors, zener tolerance and drift, op-amp offset and
bias current; exact) the trip current stays inside [i_no_trip (1 + m), i_must_trip (1 - m)] with m =
``min_margin``, and both op-amp inputs stay ``input_headroom`` below the supply. Objective: the smallest R7
(least loss and least drop at any motor current); among networks with that R7, the largest worst margin.

Solution. An exact search (:mod:`.search`): for each series R7 from the smallest up, every level shift
(R12, R13) gets a closed-form interval that the reference ratio (R9 + R10) / R11 must lie in for the margins
to be met (a bound valid for every network, not a solver's verdict), and the reference networks inside it
are evaluated exactly; the first R7 with a network is the smallest, and for it the network of the largest
worst margin is settled within GAP. With four free divider resistors on E96 there are about 10^11 networks
per R7, far too many to enumerate; on E6/E12 dividers the tests and ``tools/benchmark.py`` check that this
search finds exactly what enumeration finds. The chosen network is re-verified at every corner by
:func:`.model.verify`.
"""
from __future__ import annotations

from dataclasses import dataclass

from ...core import series
from ...core.units import eng
from ...sources.an94002 import circuit as an94002
from .. import ratings
from ..common import Result, reported
from ..solvers import Infeasible
from . import by_yield
from . import model as net
from .explain import drop_levers, explain
from .model import TABLE, checked
from .search import GAP, solve

#: the motor ICs' own output current limits, minimum (TDA5144 datasheet, June 1994; TDA5143T datasheet)
IC_LIMIT_MIN = {"TDA5144": 1.8, "TDA5143": 0.7}
#: the highest motor supply the zener can be fed from, V: the TDA5144's V_MOT maximum (TDA5144 datasheet, June 1994:
#: 1.7 to 16 V), the board's own limit ("up to a supply voltage of 16 V", AN94002 section 2)
SUPPLY_MAX = 16.0
#: the least voltage R14 needs across it at the lowest supply, D1 at its highest, to feed D1 (V)
R14_V_MIN = 0.5


@dataclass(frozen=True)
class LimiterResult(Result):
    r7: float = reported('ohm', 'R7')
    r9: float = reported('ohm', 'R9')
    r10: float = reported('ohm', 'R10')
    r11: float = reported('ohm', 'R11')
    r12: float = reported('ohm', 'R12')
    r13: float = reported('ohm', 'R13')
    i_trip_min: float = reported('A', 'lowest trip current')
    i_trip_max: float = reported('A', 'highest trip current')
    i_trip_nominal: float = reported('A', 'nominal trip current')
    p_r7: float = reported('W', 'loss in R7 at the highest trip current (stalled motor)')
    r7_rating: float = reported('W', "R7's power rating (the stall loss at 50 % of it at the highest ambient)")
    r7_package: str = reported('', "R7's package class")
    v_drop: float = reported('V', 'largest drop across R7: the highest trip current, which flows with R7 at its low end')
    r14: float = reported('ohm', "R14, D1's feed")
    p_r14: float = reported('W', 'loss in R14 at the highest supply')
    i_zener_min: float = reported('A', 'current into D1 at the lowest supply (the dividers at their most)')
    p_zener: float = reported('W', "D1's dissipation at the highest supply (the dividers at their least)")
    v_cs_nominal: float = reported('V', 'nominal sense voltage')
    margin_low: float = reported('%', 'margin above i_no_trip')
    margin_high: float = reported('%', 'margin below i_must_trip')
    headroom_min: float = reported('V', 'least op-amp input distance below the supply')
    divider_current: float = reported('A', 'current the dividers draw from the zener node')
    margin_bound: float = reported('%', 'no network with this R7 has a worst margin above')  # proven by the search
    r7_proven: bool = reported('', 'R7 proven the smallest (every smaller one ruled out)')
    best_proven: bool = reported('', 'worst margin proven within 0.25 point of the best with this R7')
    unproven: tuple = reported('ohm', 'smaller R7 values the search left unsettled (evaluation limit)')
    binding: str = reported('', 'binding')
    warnings: tuple = reported('', 'warnings')
    evaluated: int  # networks the search evaluated exactly
    r7_tried: int  # R7 values whose networks it searched (the others ruled out by the bound alone)
    mc_yield: float | None = None  # criterion = "yield": the accepted lot's yield (by_yield.lot_yield); else None
    box_scale: float | None = None  # criterion = "yield": the factor on every tolerance of the box searched

    table = TABLE

    @property
    def network(self) -> tuple:
        return self.r9, self.r10, self.r11, self.r12, self.r13


def design(spec: dict | None = None, board: bool = True) -> LimiterResult:
    """The smallest series R7 with the divider network of the largest worst margin; verified at every corner.

    Parameters
    ----------
    spec : dict or None
        The ``[current_limiter]`` table (keys of :data:`handbook.design.schema.TABLES`); defaults fill the rest.
    board : bool
        True (the design): the network on its board, the supply held to the IC's rating and the zener, the
        drop across R7 to ``v_drop_max``, R14 designed. False: the network alone (R14's figures None where the
        supply cannot feed the zener), as the search's own tests compare it with references that know no board.

    Returns
    -------
    LimiterResult
        The chosen R7 and R9..R13 with their trip currents, margins and headroom at every corner. With
        ``criterion = "yield"`` (:mod:`.by_yield`) the network is the one its Monte Carlo lot accepts, the corner
        figures are still the full corners' (they may lie inside min_margin, or outside the window), and
        ``mc_yield`` and ``box_scale`` say what the lot held and which box was searched.

    Raises
    ------
    InputError
        When ``spec`` is invalid (:func:`~handbook.design.limiter.model.checked`).
    Infeasible
        When no network of the series meets the spec; its message says what can be met.
    """
    s = checked(spec)
    if board:
        supply_rated(s)
    found = solve(s) if s["criterion"] == "corners" else by_yield.solve_yield(s)
    r7, network = found["r7"], found["network"]
    if r7 is None:
        why = explain(s)
        if found["unproven"]:  # the search stopped before settling these: "nothing meets it" is not proven
            raise Infeasible(TABLE, f"{why} (not proven: the search for R7 = "
                             f"{', '.join(eng(v, 'Ω', 3) for v in found['unproven'])} stopped at its evaluation limit)",
                             {**why.achievable, "unproven": found["unproven"]})
        raise why
    v = net.verify(r7, network, s)
    m_lo, m_hi = float(v["margin_low"]), float(v["margin_high"])
    r9, r10, r11, r12, r13 = network
    v_nominal = an94002.v_cs_trip(s["zener_voltage"], r9, r10, r11, r12, r13)
    result = dict(
        spec=s, r7=r7, r9=r9, r10=r10, r11=r11, r12=r12, r13=r13, i_trip_min=float(v["i_trip_min"]),
        i_trip_max=float(v["i_trip_max"]), i_trip_nominal=float(v_nominal / r7), v_cs_nominal=float(v_nominal),
        p_r7=float(v["i_trip_max"]) ** 2 * r7 * (1 - s["r7_tolerance"]), margin_low=m_lo, margin_high=m_hi,
        headroom_min=float(v["headroom_min"]), divider_current=float(v["divider_current"]),
        binding="the lowest trip current" if m_lo <= m_hi else "the highest trip current",
        evaluated=found["evaluated"], r7_tried=found["tried"],
        # by yield the search's bound and proof are the shrunk box's, not the spec's: not reported as the spec's
        margin_bound=found["bound"] if s["criterion"] == "corners" else None,
        r7_proven=not found["unproven"] and s["criterion"] == "corners",
        best_proven=found["proven"] and s["criterion"] == "corners",
        unproven=found["unproven"],
        mc_yield=found.get("yield"), box_scale=found.get("scale"))
    result["v_drop"] = float(v["i_trip_max"]) * r7 * (1 - s["r7_tolerance"])  # I = V_cs / R7: highest at R7's low end
    if board and result["v_drop"] > s["v_drop_max"]:  # R7 is the smallest that meets the window: no larger one drops less
        text, levers = drop_levers(s)
        kept = ("keeps every corner" if s["criterion"] == "corners" else
                f"keeps a Monte Carlo lot at yield_min = {s['yield_min']:g} (criterion = yield)")
        raise Infeasible(TABLE, f"the smallest R7 that {kept} inside {s['i_no_trip']:g} .. "
                         f"{s['i_must_trip']:g} A is {eng(r7, 'Ω', 3)}, which drops {result['v_drop']:.3g} V at the "
                         f"highest trip current, more than v_drop_max = {s['v_drop_max']:g} V: allow that drop, widen the "
                         "window or tighten the tolerances (the divider errors reach the trip multiplied by about "
                         f"V_D1 / V_cs){text}", {"v_drop_min": result["v_drop"], "r7": r7, **levers})
    result["r7_rating"], result["r7_package"] = ratings.resistor(result["p_r7"], ambient(s))
    if net.zener_range(s)[1] < s["v_supply_min"] - R14_V_MIN:  # always so on the board (supply_rated)
        result.update(zener_feed(s, float(v["divider_current"])))
    else:
        result.update(r14=None, p_r14=None, i_zener_min=None, p_zener=None)
    return LimiterResult(**result, warnings=tuple(warnings(result, s)))


def yield_note(r: dict, s: dict) -> list[str]:
    """With ``criterion = "yield"``: the design's lot and its corners, side by side (one sentence).

    Parameters
    ----------
    r : dict
        The design's figures, keyed as :class:`LimiterResult`'s fields; "mc_yield", "box_scale", "margin_low" and
        "margin_high" are read.
    s : Mapping
        The checked ``[current_limiter]`` table; ``criterion``, ``yield_min`` and ``min_margin`` are read.

    Returns
    -------
    list of str
        One sentence with ``criterion = "yield"``, none with "corners".
    """
    if s["criterion"] != "yield" or r.get("mc_yield") is None:
        return []
    worst = min(r["margin_low"], r["margin_high"])
    return [f"criterion = yield: {r['mc_yield']:.4%} of {by_yield.N:,} boards (seed {by_yield.SEED}, every part uniform "
            f"in its tolerance) stay inside the window narrowed by min_margin, against yield_min = {s['yield_min']:g}; "
            f"the network was searched on the corners of a box of {r['box_scale']:.3g} x every tolerance. At the full "
            f"corners its worst margin is {worst:.2%} (min_margin = {s['min_margin']:.0%}): "
            + ("the corners hold too" if worst >= s["min_margin"] - 1e-12 else "the corners alone would refuse it")]


def ambient(s: dict) -> float:
    """The limiter's highest ambient, C: 25 C plus ``temp_span`` (the span its zener drift is taken over).

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table; ``temp_span`` (K) is read.

    Returns
    -------
    float
        The highest ambient, C.
    """
    return 25.0 + s["temp_span"]


def supply_rated(s: dict) -> None:
    """The motor supply within the IC's rating and above the zener: else nothing can be met.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table; ``v_supply_min``, ``v_supply_max`` (V), ``ic`` and the zener's
        figures are read.

    Raises
    ------
    Infeasible
        When ``v_supply_max`` is above :data:`SUPPLY_MAX` (the TDA5143/5144's V_MOT maximum), or D1 at its highest
        leaves no room below ``v_supply_min`` for R14 to feed it.
    """
    if s["v_supply_max"] > SUPPLY_MAX:
        raise Infeasible(TABLE, f"v_supply_max = {s['v_supply_max']:g} V is above the {s['ic']}'s motor supply "
                         f"rating, V_MOT at most {SUPPLY_MAX:g} V (TDA5144 datasheet; AN94002 section 2: 'up to a "
                         f"supply voltage of 16 V'): a higher supply needs its own regulator ahead of the IC",
                         {"v_supply_max": SUPPLY_MAX})
    if s["v_supply_min"] > s["v_supply_max"]:
        raise Infeasible(TABLE, f"v_supply_min = {s['v_supply_min']:g} V is above v_supply_max = "
                         f"{s['v_supply_max']:g} V", {"v_supply_max": s["v_supply_min"]})
    vz_high = net.zener_range(s)[1]
    if vz_high >= s["v_supply_min"] - R14_V_MIN:
        raise Infeasible(TABLE, f"D1 reaches {vz_high:.3g} V at its tolerance and drift, too close to the lowest "
                         f"supply v_supply_min = {s['v_supply_min']:g} V for R14 to feed it (at least {R14_V_MIN:g} V "
                         "across R14): choose a lower zener_voltage",
                         {"zener_voltage_max": s["zener_voltage"] * (s["v_supply_min"] - R14_V_MIN) / vz_high})


def zener_feed(s: dict, i_divider: float) -> dict:
    """R14 designed: at the lowest supply, D1 at its highest and R14 at its high end, it still feeds D1 its test
    current plus the dividers' current; its loss, and D1's, at the highest supply with D1 at its lowest.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).
    i_divider : float
        The most current the chosen dividers draw from the zener node, A.

    Returns
    -------
    dict
        ``r14`` (ohm, the ``r14_series`` value at or below the largest that works at ``resistor_tolerance``),
        ``p_r14`` (W), ``i_zener_min`` (A) and ``p_zener`` (W, at the zener voltage of D1's range that
        dissipates most, all of R14's current in D1: the dividers at their least may draw almost nothing).
    """
    vz_low, vz_high = net.zener_range(s)
    t = s["resistor_tolerance"]
    largest = (s["v_supply_min"] - vz_high) / (s["zener_test_current"] + i_divider) / (1 + t)
    r14 = series.at_most(s["r14_series"], largest)
    i_max = (s["v_supply_max"] - vz_low) / (r14 * (1 - t))
    # D1 takes V_z (V_supply - V_z) / R14: largest at V_z = V_supply / 2, else at the end of D1's range nearer it
    # (one zener voltage for both factors: its highest with R14's current at its lowest is no corner)
    vz = min(max(s["v_supply_max"] / 2, vz_low), vz_high)
    return {"r14": r14, "p_r14": i_max ** 2 * r14 * (1 - t),
            "i_zener_min": (s["v_supply_min"] - vz_high) / (r14 * (1 + t)) - i_divider,
            "p_zener": vz * (s["v_supply_max"] - vz) / (r14 * (1 - t))}


def warnings(r: dict, s: dict) -> list[str]:
    """What an engineer should know about a design that meets the spec.

    Parameters
    ----------
    r : dict
        The design's figures, keyed as :class:`LimiterResult`'s fields; "i_trip_max" (A) and "p_r7" (W) are read.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); ``ic``, ``r7_power_rating`` (W), ``zener_voltage`` (V)
        and ``zener_tolerance`` (fraction) are read.

    Returns
    -------
    list of str
        One sentence per warning, none when there is nothing to say: the highest trip current above the IC's
        own minimum output limit (:data:`IC_LIMIT_MIN`, A), R7's loss above its rating, a zener at or above the
        motor supply's limit (:data:`SUPPLY_MAX`, V), an R7 or a tie-break the search did not settle (its
        evaluation limit).
    """
    out = []
    limit = IC_LIMIT_MIN[s["ic"]]
    if r["i_trip_max"] > limit:
        out.append(f"the highest trip current {r['i_trip_max']:.3g} A is above the {s['ic']}'s own output "
                   f"limit (minimum {limit:g} A): on some boards the IC limits first")
    if r["r7_rating"] > s["r7_power_rating"]:
        out.append(f"R7 dissipates up to {r['p_r7']:.3g} W while the limiter holds a stalled motor at the highest "
                   f"trip current: at 50 % of its rating at {ambient(s):g} C that needs a {r['r7_rating']:.3g} W part "
                   f"({r['r7_package']}), above r7_power_rating = {s['r7_power_rating']:g} W")
    zener_need = 0.0 if r["p_zener"] is None else ratings.power_needed(r["p_zener"], ambient(s), ratings.ZENER["knee"],
                                                                        ratings.ZENER["zero"])
    if zener_need > ratings.ZENER["rating"]:
        out.append(f"D1 dissipates up to {r['p_zener'] * 1e3:.3g} mW at the highest supply: more than 50 % of a "
                   f"500 mW BZX79 at {ambient(s):g} C; use a 1.3 W zener or feed it less (a narrower supply range)")
    vz_high = s["zener_voltage"] * (1 + s["zener_tolerance"])
    if vz_high >= SUPPLY_MAX:
        out.append(f"D1 reaches {vz_high:.3g} V at its tolerance ({s['zener_voltage']:g} V nominal): at or above the "
                   f"{SUPPLY_MAX:g} V the motor supply of a {s['ic']} board may reach (TDA5144 datasheet, V_MOT; AN94002 "
                   "section 2), so no supply the IC survives feeds it; choose a zener well below the supply")
    if r["unproven"]:
        out.append(f"not proven the smallest R7: the search for R7 = "
                   f"{', '.join(eng(v, 'Ω', 3) for v in r['unproven'])} stopped at its evaluation limit without a network, "
                   "so a network with a smaller R7 may exist")
    worst = min(r["margin_low"], r["margin_high"])
    if s["criterion"] == "corners" and (not r.get("best_proven", True) or r["margin_bound"] - worst > GAP + 1e-12):
        out.append(f"the worst margin {worst:.2%} is not proven the best for this R7: the search stopped at its "
                   f"evaluation limit with networks of up to {r['margin_bound']:.2%} not ruled out")
    return out + yield_note(r, s)


def judge(r7: float, network, s: dict) -> dict:
    """Any limiter (the note's, say) by the same exact checks as a design: trip currents, margins, headroom.

    Parameters
    ----------
    r7 : float
        The sense resistor R7, nominal, ohm.
    network : tuple of float
        (R9, R10, R11, R12, R13), nominal, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    dict
        "i_trip_min" and "i_trip_max", the lowest and highest trip current over every corner, A; "margin_low"
        and "margin_high", the margins above ``i_no_trip`` and below ``i_must_trip``, fractions; "headroom_min",
        the least headroom of either op-amp input, V; "divider_current", what both dividers draw from the zener
        node, A (all floats); "meets", bool: what a design must meet (:func:`.model.verify`'s "ok": both margins
        at least ``min_margin``, the headroom at least ``input_headroom``, a positive trip current, the divider
        current at most ``divider_current_max``).
    """
    v = net.verify(r7, network, s)
    out = {k: float(v[k]) for k in ("i_trip_min", "i_trip_max", "margin_low", "margin_high", "headroom_min",
                                     "divider_current")}
    out["meets"] = bool(v["ok"])  # the design's own acceptance: margins, headroom, a positive trip, divider current
    return out


