"""The TCA5600 converter designed down to a real coil: eq 1 to 6a, then the smallest core that holds L1.

The converter is a boost stage: the switch (pin 9 to R1) charges L1 from VCC2 for t1 until the drop
across R1 reaches V12(H); then the coil dumps into C2, the regulator's input, for t2 until its current
is zero, and the next charge starts (TCA5600 excerpt, figures 13 and 14). Eq 4's t1 + t2 = 1/f puts the
worst operating point (VCC2 lowest, Iout2 largest) at the boundary between continuous and discontinuous
conduction; every lighter load lets the regulator's feedback stop the converter between cycles.

Operating point: eq 1 to 6a by the source's own functions (:mod:`handbook.sources.tca5600.circuit`) at the
nominal device figures: alpha, t1, t2, I_peak, L1 and R1.

Parts, their tolerances and the device's spread (:mod:`.operating`). V12(H), V_CE(sat) and V_F are taken at
their corners, +-``device_spread`` (no public characteristics: spread and drift together). The peak current is
V12(H)/R1 and the load the converter carries is I_peak/2 x V_L-/(V_L- + V_L+) whatever the inductance, so R1 is
eq 6a at the device corner that delivers least (V12(H) low, V_CE(sat) and V_F high unless V_L- is nearly gone),
fitted from its series (``r1_series``, E96 by default) at or below that R1 over its high end, (1 + ``r1_tolerance``)
(1 + its drift ``r1_tempco`` x |t_ambient - 25 C|): at that end it still delivers ``i_out``. With V12(H) high and R1
at its low end the peak current is I_peak,max. The frequency
1/(L I_peak (1/V_L- + 1/V_L+)) falls as L, I_peak and V_CE(sat) grow and V_F falls, so the inductance that runs at
f_min at the lowest VCC2 in that slow corner is a largest one: the coil is wound for it / (1 + ``a_l_tolerance``).
The switching frequency is reported over VCC2 = ``v_supply_min`` .. ``v_supply_max`` at every corner (it peaks
where V_L- = V_L+ and falls towards both ends: at the highest VCC2 it can fall into the audio band).

Coil. For every candidate core (shape and material from PyOpenMagnetics' database, shipped as
:mod:`.cores`): the reluctance is the core's l_e / (mu0 mu_i A_e) in series with PyOpenMagnetics'
own gap model (Zhang's reluctance of the ground centre gap, with fringing, and the outer legs' residual gaps),
tabulated over the gap's length; the gap for the nominal inductance is read from that table. Fringing makes
the centre gap's reluctance smaller than lg / (mu0 A_centre), so a gap worked out without it over the centre
column would give too much inductance; worked out over A_e (larger than the centre column of EP and EFD
cores) it gives too little. The turns are the fewest whole ones that keep the peak flux L_max I_peak,max / N
at the narrowest section (the least of the centre column, the outer legs together and the database's
minimum area) ``saturation_margin_min`` below the material's saturation at ``t_ambient`` + the coil's own
rise (linear between the material's 25 C and 100 C figures, extended beyond) and leave a centre gap of at
least :data:`GAP_MIN`; the thickest wire that fits the bobbin with ``fill_factor`` (least copper loss); the
core loss by the improved generalised Steinmetz equation (iGSE) for the triangular flux of figure 14 at
the largest flux swing, the largest over the supply range at full load; the copper loss I_rms^2 R_dc at
``t_ambient`` + ``temperature_rise_max``; and the temperature rise from the core's thermal resistance. The
choice is the candidate of least effective volume that meets the saturation margin, the fit, the gap,
``temperature_rise_max`` and ``current_density_max`` in its thickest fitting wire (ties: the least loss);
``binding`` names the limit that rules out the next smaller core. With ``audible`` = "avoid" f_min is first
raised until the full-load frequency stays above the audio band at every corner
(:func:`~.operating.inaudible_f_min`).
The candidate set is finite and every candidate is evaluated exactly,
so enumeration is the exact optimum: no solver is needed and none is used. The frequency trade-off (higher
f_min: a smaller L1 and core, more core loss per volume) is shown as a sweep over f_min in the design chapter.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from ...core import InputError
from ...core.units import eng, to_figures
from ...sources.tca5600 import data as tca5600_data
from ..common import Result, Table, checked_table, completed, is_checked, ordered, reported
from ..solvers import Infeasible
from . import cores
from .coil import (  # noqa: F401 (the coil's names are this module's too)
    ALPHA_CU,
    GAP_MIN,
    MU0,
    RHO_CU,
    SUPPLY_POINTS,
    T_LOSS,
    T_WIRE_TABLE,
    Coil,
    b_sat,
    candidates,
    coil,
    coil_voltages,
    core_loss,
    core_reluctance,
    frequency,
    gap_for,
    gap_reluctance,
    igse_density,
    steinmetz_range,
    supplies,
    v_top,
    wind,
)
from .operating import (  # noqa: F401 (the operating point's names are this module's too)
    AUDIO_BAND,
    DEVICE,
    FAST,
    HOT,
    SLOW,
    corner,
    delivered,
    designed_at,
    inaudible_f_min,
    operating_point,
    r1_ends,
    source_params,
    weakest,
)

TABLE = "converter"
#: assumption: the TCA5600's internal switch carries the peak current the excerpt's own R1 = 0.68 ohm sets at
#: the assumed V12(H) = 0.4 V, about 0.59 A (no public maximum ratings were found): a warning above it
SWITCH_I_MAX = 0.4 / tca5600_data.APPLICATION["r1"]
#: assumption: the self-capacitance of a small multi-layer bobbin winding (measure the ring once the coil
#: current reaches zero); a warning when the self-resonance is below ten times the highest switching frequency
C_SELF = 10e-12
#: turns above which the winding is impractical by hand and its self-capacitance grows: a warning
TURNS_WARN = 300
#: the lowest Iout2 the exit-3 search tries (A): below it no TCA5600 board is sensible
I_OUT_FLOOR = 1e-6


@dataclass(frozen=True)
class ConverterResult(Result):
    f_min_design: float = reported('Hz', 'f_min designed at (raised above the spec\'s by audible = avoid)')
    alpha: float = reported('1', 'time ratio alpha = t1/t2 (eq 3)')
    t1: float = reported('s', 'charging time t1 (eq 4)')
    t2: float = reported('s', 'dumping time t2')
    i_peak: float = reported('A', 'peak coil current (eq 5)')
    l1: float = reported('H', 'coil inductance L1 (eq 6)')
    r1: float = reported('ohm', 'current-sense resistor R1 (eq 6a)')
    r1_worst: float = reported('ohm', 'R1 by eq 5 and 6a at the device corner that delivers least (+-device_spread)')
    r1_part: float = reported('ohm', 'R1 fitted (series value at or below that R1 over its high end: tolerance and drift)')
    i_out_least: float = reported('A', 'current delivered at v_supply_min, least over every corner')
    i_peak_max: float = reported('A', 'highest peak coil current (V12(H) at its high end, R1 at its low end)')
    l1_nominal: float = reported('H', 'inductance wound, nominal (f_min at +a_l_tolerance and the slow corner)')
    f_sw_min: float = reported('Hz', 'lowest full-load frequency, supply range and corners')
    f_sw_max: float = reported('Hz', 'highest full-load frequency, supply range and corners')
    core_shape: str = reported('', 'core shape')
    core_material: str = reported('', 'core material')
    turns: int = reported('', 'turns')
    gap: float = reported('m', "centre-column gap (PyOpenMagnetics' gap model)")
    a_l: float = reported('H', 'A_L (inductance per turn squared, nominal)')
    wire: str = reported('', 'wire')
    b_peak: float = reported('T', 'peak flux density, centre column (highest peak current)')
    b_peak_min_area: float = reported('T', 'peak flux density, narrowest section (the one saturation is judged at)')
    core_loss: float = reported('W', 'core loss (iGSE)')
    winding_loss: float = reported('W', 'winding loss (I_rms² R_dc, copper at its hottest)')
    temperature_rise: float = reported('K', 'temperature rise')
    saturation_margin: float = reported('%', 'saturation margin (narrowest section, hot, highest I_peak)')
    binding: str = reported('', 'binding')
    warnings: tuple = reported('', 'warnings')
    i_peak_min: float
    l1_max: float
    vl_plus: float
    vl_minus: float
    i_rms: float
    coil: Coil
    candidates: tuple  # every candidate Coil, in the order of the choice (smallest first)
    next_smaller: Coil | None  # the largest candidate smaller than the choice, and why it fails

    table = TABLE


def checked(spec: Mapping | None) -> Table:
    """The ``[converter]`` table completed with its defaults and checked: ranges, then the limits that
    contradict each other (V_L+ and V_L- must be positive at ``v_supply_min`` at every corner of
    ``device_spread``, the supply range ordered).

    Parameters
    ----------
    spec : Mapping or None
        The ``[converter]`` table, {key: value} in SI units (temperatures in C): missing keys take their
        defaults, None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    Table
        Every key of the table, checked (SI units; temperatures in C).

    Raises
    ------
    InputError
        When a key is unknown, a value is out of range, or two limits contradict each other.
    """
    if is_checked(TABLE, spec):  # checked once, where it was read
        return spec
    s = completed(TABLE, spec)
    spread = s["device_spread"]  # V_F at its low end, V_CE(sat) and V12(H) at their high ends
    above = s["v_supply_min"] - s["v_regulator_drop"] - s["v_f"] * (1 - spread)
    if s["v_out"] <= above:
        raise InputError(f"converter.v_out = {s['v_out']:g} V must be above v_supply_min - v_regulator_drop - v_f x "
                         f"(1 - device_spread) = {above:g} V: the coil must dump upwards into the regulator's input "
                         "(eq 1, V_L+ > 0 at every corner)")
    drops = (s["v_ce_sat"] + s["v12h"]) * (1 + spread)
    if s["v_supply_min"] <= drops:
        raise InputError(f"converter.v_supply_min = {s['v_supply_min']:g} V must be above (v_ce_sat + v12h) x "
                         f"(1 + device_spread) = {drops:g} V: the coil needs a voltage to charge (eq 2, V_L- > 0 at "
                         "every corner)")
    ordered(TABLE, "v_supply_min", "v_supply_max", s, "V", strict=False)
    return checked_table(TABLE, s)


def choose(s: dict) -> tuple[dict, list[Coil], Coil | None]:
    """The operating point, every candidate coil, and the choice: the first candidate that meets every limit.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).

    Returns
    -------
    tuple
        (the operating point, :func:`operating_point`; every candidate :class:`~.coil.Coil`, smallest effective
        volume first; the chosen one, or None when none meets every limit).
    """
    op = operating_point(s)
    every = candidates(s, op)
    return op, every, next((c for c in every if c.ok), None)


def _feasible(s: dict) -> bool:
    op = operating_point(s)
    table = cores.load()
    return any(coil(sh, m, s, op, table).ok for sh in table["shapes"] for m in table["materials"])


def _bisect(pred, good: float, bad: float, steps: int = 14) -> float:
    """Between a ``good`` x (pred true) and a ``bad`` one, the good end of the last bracket (geometric)."""
    for _ in range(steps):
        mid = math.sqrt(good * bad)
        good, bad = (mid, bad) if pred(mid) else (good, mid)
    return good


def _current_that_works(s: dict) -> float | None:
    """The largest Iout2 at or below the spec's that some candidate meets: a downward scan (halving) from
    i_out to :data:`I_OUT_FLOOR` for a feasible point, then bisection up to the last infeasible one."""
    pred = lambda i: _feasible({**s, "i_out": i})  # noqa: E731
    bad = s["i_out"]
    good = bad / 2
    while good >= I_OUT_FLOOR and not pred(good):
        bad, good = good, good / 2
    return _bisect(pred, good, bad) if good >= I_OUT_FLOOR else None


def _frequency_that_works(s: dict) -> float | None:
    """The lowest f_min above the spec's, up to the schema's highest, that some candidate meets: an upward
    scan (doubling) for a feasible point, then bisection down to the last infeasible one."""
    from ..schema import TABLES

    f_high = next(p.high for p in TABLES[TABLE] if p.name == "f_min")
    pred = lambda f: _feasible({**s, "f_min": f})  # noqa: E731
    bad, good = s["f_min"], min(2 * s["f_min"], f_high)
    while not pred(good):
        if good >= f_high:
            return None
        bad, good = good, min(2 * good, f_high)
    return _bisect(pred, good, bad)


def infeasible(s: dict, every: list[Coil]) -> Infeasible:
    """Nothing in the candidate set meets the spec: what would (a lower current, a higher frequency),
    and which candidate comes nearest (the way to a larger core family).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    every : list of Coil
        Every candidate (none meets the spec).

    Returns
    -------
    Infeasible
        The exception to raise (not raised here): ``achievable`` holds ``i_out`` (the largest load current some
        candidate meets at this f_min, A, rounded down to four figures; None below 1 uA), ``f_min`` (the lowest
        frequency some candidate meets at this load, Hz, rounded up; None when none up to the schema's highest
        f_min does),
        ``largest_core`` (str) and ``largest_core_fails`` (str).
    """
    from ...core.units import eng

    i_ok = _current_that_works(s)
    f_ok = _frequency_that_works(s)
    largest = max(every, key=lambda c: (c.ve, -c.loss))
    why = largest.fails
    parts = [f"no core of the candidate set (P 7.4 .. P 26/16, RM 4 .. RM 10, EP 7 .. EP 20, E 8.3 .. E 25, "
             f"EFD 10 .. EFD 25 in 3C90 and N87) holds L1 at the peak current with a "
             f"{s['saturation_margin_min']:.0%} saturation margin within {s['temperature_rise_max']:g} K: "
             f"the largest, {largest.shape} in {largest.material}, fails: {why}"]
    # shown to four figures, rounded the safe way (a current down, a frequency up), so a value copied back works
    i_ok = to_figures(i_ok, math.floor) if i_ok is not None else None
    f_ok = to_figures(f_ok, math.ceil) if f_ok is not None else None
    if i_ok is not None:
        parts.append(f"i_out up to {eng(i_ok, 'A')} can be met at f_min = {eng(s['f_min'], 'Hz')}")
    if f_ok is not None:
        parts.append(f"f_min = {eng(f_ok, 'Hz')} meets i_out = {eng(s['i_out'], 'A')}")
    parts.append("a larger core family (RM 12/14, P 30/19 and up, ETD, PQ) is outside the candidate set")
    return Infeasible(TABLE, "; ".join(parts), {"i_out": i_ok, "f_min": f_ok, "largest_core": largest.shape,
                                                 "largest_core_fails": why})


def binding(every: list[Coil], chosen: Coil) -> str:
    """The limit that rules out the next smaller core (the one just below the choice).

    Parameters
    ----------
    every : list of Coil
        Every candidate, smallest effective volume first.
    chosen : Coil
        The chosen candidate.

    Returns
    -------
    str
        The limits the candidates of the next smaller volume fail, with each one's reason; or "none: the smallest
        candidate core passes".
    """
    smaller = [c for c in every if c.ve < chosen.ve * (1 - 1e-9)]
    if not smaller:
        return "none: the smallest candidate core passes"
    ve = smaller[-1].ve
    nearest = [c for c in smaller if c.ve == ve]
    limits = sorted({lim for c in nearest for lim in c.limits})
    return (f"{' and '.join(limits)} (the next smaller core, {nearest[0].shape}: "
            + "; ".join(f"in {c.material} {c.fails}" for c in nearest) + ")")


def audio_band(s: dict, op: dict) -> tuple[float, float] | None:
    """The VCC2 span over which the full-load frequency at the slow corner lies below :data:`AUDIO_BAND`.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`operating_point`): ``l1_max`` (H), ``i_peak_max`` (A) and the ``slow`` corner
        (V_F low, V12(H) and V_CE(sat) high) are read.

    Returns
    -------
    tuple of float or None
        (lowest, highest) VCC2 of the 401 supply points in the band (and ``v_supply_max`` when it reaches
        :func:`~.coil.v_top` at the slow corner, where the frequency is zero), V; None when no point is.
    """
    slow = op["slow"]
    points = [v for v in supplies(slow, 401) if frequency(slow, v, op["l1_max"], op["i_peak_max"]) < AUDIO_BAND]
    if s["v_supply_max"] >= v_top(slow):
        points.append(s["v_supply_max"])
    return (min(points), max(points)) if points else None


def warnings(s: dict, op: dict, c: Coil) -> list[str]:
    """What a valid design does that is implausible or outside the models: each warning says its threshold.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`operating_point`).
    c : Coil
        The chosen coil.

    Returns
    -------
    list of str
        The warnings, possibly none: V_L+ vanishing below ``v_supply_max``; a full-load frequency in the audio
        band; core loss extrapolated outside the Steinmetz fit; wire thicker than twice the skin depth; a peak
        current above the assumed switch limit
        (:data:`SWITCH_I_MAX`); more than :data:`TURNS_WARN` turns or a self-resonance below ten times the
        highest switching frequency.
    """
    from ...core.units import eng

    table = cores.load()
    out = []
    top = v_top(op["slow"])
    if s["v_supply_max"] >= top:
        out.append(f"at VCC2 = {eng(top, 'V')} and above (v_supply_max = {eng(s['v_supply_max'], 'V')}; V_F at its low "
                   "end) V_L+ vanishes: the coil no longer dumps against a voltage, the frequency falls to zero and VCC2 "
                   "feeds the regulator through the coil and the rectifier")
    span = audio_band(s, op)
    if span is not None:
        out.append(f"at full load the switching frequency lies in the audio band (below {eng(AUDIO_BAND, 'Hz')}, the "
                   f"excerpt's example) for VCC2 from {eng(span[0], 'V')} to {eng(span[1], 'V')}, down to "
                   f"{eng(op['f_sw_min'], 'Hz')}: the coil may be heard (at lighter loads the regulator's feedback "
                   "pauses it, in bursts slower still); a higher f_min or a lower v_supply_max moves it out")
    material = table["materials"][c.material]
    _, points = core_loss(material, table["shapes"][c.shape], s, op, c.turns)
    freqs = [pt["f"] for pt in points]
    outside = [f for f in freqs if not steinmetz_range(material, f)[1]]
    if outside:
        rng = material["steinmetz"]
        out.append(f"core loss extrapolated: {c.material}'s Steinmetz fit spans {eng(rng[0]['f_low'], 'Hz')} to "
                   f"{eng(rng[-1]['f_high'], 'Hz')}; the loss is taken at the largest flux swing (L1 at its high "
                   f"end, the highest peak current), where the full-load frequency over the supply range runs "
                   f"{eng(min(freqs), 'Hz')} to {eng(max(freqs), 'Hz')} (over every corner "
                   f"{eng(op['f_sw_min'], 'Hz')} to {eng(op['f_sw_max'], 'Hz')})")
    f_top = max(op["f_sw_max"], 1.0)
    skin = math.sqrt(RHO_CU * (1 + ALPHA_CU * 80) / (math.pi * f_top * MU0))
    if c.wire_diameter is not None and c.wire_diameter > 2 * skin:
        out.append(f"wire {eng(c.wire_diameter, 'm')} is thicker than twice the skin depth at "
                   f"{eng(op['f_sw_max'], 'Hz')} ({eng(skin, 'm')}): the copper loss (I_rms² R_dc) is underestimated")
    if op["i_peak_max"] > SWITCH_I_MAX:
        out.append(f"the peak current reaches {eng(op['i_peak_max'], 'A')} (V12(H) high, R1 low), above the "
                   f"{eng(SWITCH_I_MAX, 'A')} assumed for the TCA5600's internal switch (the excerpt's R1 = "
                   f"{eng(tca5600_data.APPLICATION['r1'], 'Ω')} at V12(H) = 400 mV; no public maximum ratings): "
                   "check the switch or use an external one")
    srf = 1 / (2 * math.pi * math.sqrt(op["l1_max"] * C_SELF))
    if c.turns > TURNS_WARN or srf < 10 * op["f_sw_max"]:
        out.append(f"{c.turns} turns, L1 up to {eng(op['l1_max'], 'H')}: with an assumed {eng(C_SELF, 'F')} of "
                   f"winding capacitance the coil self-resonates near {eng(srf, 'Hz')}"
                   + (f", below ten times the highest switching frequency ({eng(op['f_sw_max'], 'Hz')})"
                      if srf < 10 * op["f_sw_max"] else "")
                   + (f"; more than {TURNS_WARN} turns are impractical to wind" if c.turns > TURNS_WARN else "")
                   + ": a larger i_out or f_min, or a design outside eq 1 to 6a, suits this spec better")
    return out


def design(spec: dict | None = None) -> ConverterResult:
    """Eq 1 to 6a, then the smallest candidate core meeting the saturation margin, the bobbin and the
    temperature rise (exact enumeration). Raises Infeasible when no candidate does.

    Parameters
    ----------
    spec : Mapping or None
        The ``[converter]`` table, {key: value} in SI units (temperatures in C): missing keys take their
        defaults, None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    ConverterResult
        The checked spec; eq 1 to 6a's alpha (pure number), t1, t2 (s), I_peak (A), L1 (H), R1 (ohm) at the
        nominal device figures; R1 at the device corner that delivers least and the fitted R1 (ohm), the least
        current delivered (A), the peak currents (A), the inductances (H), the frequency range (Hz); the coil (shape,
        material, turns, gap in m, A_L in H, wire, flux densities in T, losses in W, rise in K, saturation margin
        as a fraction); V_L+, V_L- (V) and I_rms (A); what binds, the warnings, every candidate and the next
        smaller one.

    Raises
    ------
    InputError
        When the spec is invalid.
    Infeasible
        When no candidate core meets it (:func:`infeasible`).
    """
    given = checked(spec)
    s = designed_at(given)
    op, every, chosen = choose(s)
    if chosen is None:
        raise infeasible(s, every)
    notes = () if s["f_min"] == given["f_min"] else (
        f"audible = avoid: f_min raised from {eng(given['f_min'], 'Hz')} to {eng(s['f_min'], 'Hz')} so that the full-load "
        f"frequency stays at or above {eng(AUDIO_BAND, 'Hz')} (by {given['audible_margin'] * 100:g} %, audible_margin) "
        f"at every corner up to v_supply_max = {eng(s['v_supply_max'], 'V')} (audible = warn keeps the f_min given)",)
    smaller = [c for c in every if c.ve < chosen.ve * (1 - 1e-9)]
    return ConverterResult(
        spec=given, f_min_design=s["f_min"], alpha=op["alpha"], t1=op["t1"], t2=op["t2"], i_peak=op["i_peak"],
        l1=op["l1"], r1=op["r1"], r1_worst=op["r1_worst"], i_out_least=op["i_out_least"],
        r1_part=op["r1_part"], i_peak_min=op["i_peak_min"], i_peak_max=op["i_peak_max"], l1_nominal=op["l1_nominal"],
        l1_max=op["l1_max"], f_sw_min=op["f_sw_min"], f_sw_max=op["f_sw_max"],
        vl_plus=op["vl_plus"], vl_minus=op["vl_minus"], i_rms=op["i_rms"],
        core_shape=chosen.shape, core_material=chosen.material, turns=chosen.turns, gap=chosen.gap, a_l=chosen.a_l,
        wire=chosen.wire, b_peak=chosen.b_peak, b_peak_min_area=chosen.b_peak_min_area, core_loss=chosen.core_loss,
        winding_loss=chosen.winding_loss,
        temperature_rise=chosen.temperature_rise, saturation_margin=chosen.saturation_margin,
        binding=binding(every, chosen), coil=chosen, candidates=tuple(every),
        next_smaller=smaller[-1] if smaller else None, warnings=notes + tuple(warnings(s, op, chosen)))


def sweep(s: dict, frequencies) -> list[dict]:
    """The chosen coil at each f_min (the rest of the spec unchanged): the trade-off of the chapter's plot.

    Parameters
    ----------
    s : Mapping
        The ``[converter]`` table, {key: value} in SI units (checked again with each ``f_min``).
    frequencies : iterable of float
        The values of ``f_min`` to design at, Hz.

    Returns
    -------
    list of dict
        One row per frequency: ``f_min`` (Hz) and ``core`` (shape and material, str, None where nothing meets
        the spec), and where something does ``ve`` (m^3), ``l1`` and ``l1_nominal`` (H), ``turns``, ``core_loss``
        and ``winding_loss`` (W) and ``temperature_rise`` (K).

    Raises
    ------
    InputError
        When the spec with that ``f_min`` is invalid (an ``f_min`` out of range, for one).
    """
    rows = []
    for f in frequencies:
        try:
            r = design({**s, "f_min": float(f)})
        except Infeasible:
            rows.append({"f_min": float(f), "core": None})
            continue
        rows.append({"f_min": float(f), "core": f"{r.core_shape} {r.core_material}", "ve": r.coil.ve, "l1": r.l1,
                     "l1_nominal": r.l1_nominal, "turns": r.turns, "core_loss": r.core_loss,
                     "winding_loss": r.winding_loss, "temperature_rise": r.temperature_rise})
    return rows
