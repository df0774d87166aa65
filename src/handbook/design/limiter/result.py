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

from ...core.units import eng
from ...sources.an94002 import circuit as an94002
from ..common import Result, reported
from ..solvers import Infeasible
from . import model as net
from .explain import explain
from .model import TABLE, checked
from .search import GAP, solve

#: the motor ICs' own output current limits, minimum (TDA5144 datasheet, June 1994; TDA5143T datasheet)
IC_LIMIT_MIN = {"TDA5144": 1.8, "TDA5143": 0.7}
#: the highest motor supply the zener can be fed from, V: the TDA5144's V_MOT maximum (TDA5144 datasheet, June 1994:
#: 1.7 to 16 V), the board's own limit ("up to a supply voltage of 16 V", AN94002 section 2)
SUPPLY_MAX = 16.0


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

    table = TABLE

    @property
    def network(self) -> tuple:
        return self.r9, self.r10, self.r11, self.r12, self.r13


def design(spec: dict | None = None) -> LimiterResult:
    """The smallest series R7 with the divider network of the largest worst margin; verified at every corner.

    Parameters
    ----------
    spec : dict or None
        The ``[current_limiter]`` table (keys of :data:`handbook.design.schema.TABLES`); defaults fill the rest.

    Returns
    -------
    LimiterResult
        The chosen R7 and R9..R13 with their trip currents, margins and headroom at every corner.

    Raises
    ------
    InputError
        When ``spec`` is invalid (:func:`~handbook.design.limiter.model.checked`).
    Infeasible
        When no network of the series meets the spec; its message says what can be met.
    """
    s = checked(spec)
    found = solve(s)
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
        evaluated=found["evaluated"], r7_tried=found["tried"], margin_bound=found["bound"],
        r7_proven=not found["unproven"], best_proven=found["proven"], unproven=found["unproven"])
    return LimiterResult(**result, warnings=tuple(warnings(result, s)))


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
    if r["p_r7"] > s["r7_power_rating"]:
        out.append(f"R7 dissipates up to {r['p_r7']:.3g} W while the limiter holds a stalled motor at the highest "
                   f"trip current: more than its {s['r7_power_rating']:g} W rating (r7_power_rating)")
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
    if not r.get("best_proven", True) or r["margin_bound"] - worst > GAP + 1e-12:
        out.append(f"the worst margin {worst:.2%} is not proven the best for this R7: the search stopped at its "
                   f"evaluation limit with networks of up to {r['margin_bound']:.2%} not ruled out")
    return out


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


