"""Bill of materials: every chosen part with the rating that carries its worst-case stress, as CSV and JSON.

One sheet per design, its designators prefixed with the sheet (:data:`SHEETS`: ``A2-R7`` is R7 of the current
limiter), so the four circuits' parts never collide; within a sheet the source's own designators where it
names the part (AN94002's C3, R7, R14, D1, IC1), else numbered on that sheet. Each row holds the value with
its unit, its tolerance (the design's, or for R9..R13 the stocked class that leaves room for their drift), the
rating it needs under :mod:`handbook.design.ratings`'
convention (stated in the row), the technology or dielectric where the design depends on it, a package class
that carries the rating (never a part number that was not read from a catalogue: magnetics name the core and
material of PyOpenMagnetics' database), the temperature coefficient where the design's corners depend on it,
and the reason in one line.
"""
from __future__ import annotations

import csv
import math
import os
import tempfile
from pathlib import Path

from ..core.units import eng, to_figures
from . import ratings

#: design table -> (sheet prefix, the circuit)
SHEETS = {"commutation": ("A1", "TDA5143/TDA5144 timers (AN94002 2.1)"),
          "current_limiter": ("A2", "op-amp current limiter (AN94002 figure 3)"),
          "class_d": ("A3", "LM4651/LM4652 class-D amplifier"),
          "converter": ("A4", "TCA5600 dc/dc converter")}

#: the CSV's columns (the JSON rows have the same keys)
COLUMNS = ("sheet", "designator", "quantity", "part", "value", "unit", "value_text", "tolerance", "power_rating",
           "voltage_rating", "current_rating", "rating_text", "stress", "technology", "package", "tempco", "reason")

#: units of the numeric columns (the JSON's ``units`` map)
UNITS = {"value": "the row's unit", "tolerance": "fraction", "power_rating": "W", "voltage_rating": "V",
         "current_rating": "A", "stress": "the rating's unit (W, V or A)"}

#: the highest voltage any TDA5144 pin may carry: its supply V_P, at most 18 V (TDA5144 datasheet)
TDA5144_VP_MAX = 18.0
#: the voltage across the LM4651's R_OSC and R_DLY, at most (an assumption: the pins set bias currents and the
#: datasheet gives no pin voltage; 5 V bounds a bias reference of this kind)
PIN_VOLTAGE = 5.0
#: Schottky rectifiers' repetitive reverse voltage classes, V (a catalogue ladder: 40 V to 200 V parts are common)
SCHOTTKY_VOLTAGES = (40.0, 60.0, 100.0, 150.0, 200.0)
#: the LM4651/LM4652 datasheet's flyback diode, D1 (Recommendations for Critical External Components): 3 A, 50 V
D1_SUGGESTED = (3.0, 50.0)
#: the TDA5144's supply V_P, V (TDA5144 datasheet: 4 V to 18 V)
TDA5144_VP = (4.0, TDA5144_VP_MAX)
#: the LM358's supply, single, V (TI LM358 datasheet, SLOS068, recommended operating conditions: 3 V to 32 V)
LM358_SUPPLY = (3.0, 32.0)
#: the TCA5600's storage capacitor C2 as the excerpt's figure 13 draws it, F (the design does not size it)
C2_FIGURE_13 = 100e-6


def _row(sheet: str, refs: str, part: str, value, unit: str, tolerance=None, *, power=None, voltage=None,
         current=None, rating_text="", stress=None, technology="", package="", tempco="", reason="") -> dict:
    refs_ = [f"{sheet}-{r}" for r in refs.split()]
    shown = value if isinstance(value, str) else eng(value, unit)
    return {"sheet": sheet, "designator": " ".join(refs_), "quantity": len(refs_), "part": part,
            "value": None if isinstance(value, str) else float(value), "unit": unit, "value_text": shown,
            "tolerance": tolerance, "power_rating": power, "voltage_rating": voltage, "current_rating": current,
            "rating_text": rating_text, "stress": stress, "technology": technology, "package": package,
            "tempco": tempco, "reason": reason}


def _cap_class(c: float) -> tuple[str, str, str]:
    """(technology, package class, tempco) of a timing capacitor: C0G up to 100 nF, polypropylene film above."""
    if c <= 100e-9:
        package = next(p for top, p in ((1e-9, "0603 chip"), (10e-9, "0805 chip"), (47e-9, "1206 chip"),
                                        (100e-9, "1210 chip")) if c <= top * (1 + 1e-9))
        return "C0G/NP0 ceramic", package, "0 ± 30 ppm/K"
    return "polypropylene film", _film_package(c), "−200 ppm/K"


def _film_package(c: float) -> str:
    return next((p for top, p in ((1e-6, "radial film, 5 mm pitch"), (2.2e-6, "radial film, 7.5 mm pitch"),
                                  (10e-6, "radial film, 15 mm pitch"), (47e-6, "radial film, 27.5 mm pitch"))
                 if c <= top * (1 + 1e-9)), "film, chassis-mount")


def _resistor(sheet, ref, part, value, tolerance, series, p_worst, t_ambient, why, technology="metal film",
              tempco="≤ 100 ppm/K") -> dict:
    rating, package = ratings.resistor(p_worst, t_ambient)
    return _row(sheet, ref, part, value, "Ω", tolerance, power=rating, stress=p_worst, technology=technology,
                package=package, tempco=tempco,
                rating_text=f"{eng(rating, 'W')}: {eng(p_worst, 'W')} at most at {t_ambient:g} °C, 50 % derating",
                reason=f"{series} value; {why}" if series else why)


def commutation_rows(c, ic: str = "TDA5144") -> list[dict]:
    """The timing capacitors of the TDA5144 (C3 CAP-CD, C4 CAP-DC, C5 CAP-ST, C6 CAP-TI, as AN94002's parts
    list numbers them) and the IC.

    Parameters
    ----------
    c : CommutationResult
        The commutation design (:func:`handbook.design.commutation.design`).
    ic : str
        The motor IC's type.

    Returns
    -------
    list of dict
        The rows (keys :data:`COLUMNS`); C5 and C6 only when designed (motor data, flyback time given).
    """
    sheet, s = SHEETS["commutation"][0], c.spec
    rows = [_row(sheet, "IC1", f"{ic} BLDC motor driver", ic, "", voltage=TDA5144_VP[1],
                 rating_text=f"supply V_P {TDA5144_VP[0]:g} V to {TDA5144_VP[1]:g} V (TDA5144 datasheet); the timers "
                             "charge their capacitors from it, so no capacitor sees more",
                 reason="the motor IC the timers belong to")]
    caps = [("C3", "CAP-CD", c.cap_cd, f"commutation delay: smallest value whose swing at {s['rpm_min']:g} rpm fits "
             f"the switching window at every corner ({c.rpm_min_reliable:.0f} to {c.rpm_max_reliable:.0f} rpm)"),
            ("C4", "CAP-DC", c.cap_dc, "the slave timer: the same value as CAP-CD")]
    if c.cap_st is not None:
        caps.append(("C5", "CAP-ST", c.cap_st, "start oscillator: outlasts the rotor's rocking at every corner"))
    if c.cap_ti is not None:
        caps.append(("C6", "CAP-TI", c.cap_ti, "watchdog: outlasts the longest flyback pulse"))
    for ref, name, value, why in caps:
        tech, package, tempco = _cap_class(value)
        v_rating = ratings.capacitor_voltage(TDA5144_VP_MAX, film="film" in tech)
        rows.append(_row(sheet, ref, f"{name} timing capacitor", value, "F", s["tolerance"], voltage=v_rating,
                         stress=TDA5144_VP_MAX, technology=tech, package=package, tempco=tempco,
                         rating_text=f"{v_rating:g} V: any pin may reach V_P, at most {TDA5144_VP_MAX:g} V, 50 % "
                                     "derating", reason=f"{s['series']} value; {why}"))
    return rows


def limiter_rows(lim) -> list[dict]:
    """The op-amp limiter's parts: R7, R9..R14, D1, the LM358 (IC2, as AN94002's parts list).

    Parameters
    ----------
    lim : LimiterResult
        The limiter design (:func:`handbook.design.limiter.design`).

    Returns
    -------
    list of dict
        The rows (keys :data:`COLUMNS`).
    """
    from .limiter.model import zener_range
    from .limiter.result import ambient

    sheet, s = SHEETS["current_limiter"][0], lim.spec
    t_a = ambient(s)
    vz_low, vz_high = zener_range(s)
    rows = [_row(sheet, "IC2", "LM358 dual op-amp", "LM358", "", voltage=LM358_SUPPLY[1], stress=s["v_supply_max"],
                 rating_text=f"supply {LM358_SUPPLY[0]:g} V to {LM358_SUPPLY[1]:g} V (TI LM358 datasheet, recommended "
                             f"operating conditions): {s['v_supply_max']:g} V at most here; input offset "
                             f"{s['offset'] * 1e3:g} mV in the design's corners (the LM358: 9 mV maximum over "
                             "temperature)",
                 reason="the comparator of AN94002 figure 3")]
    rows.append(_row(sheet, "R7", "current-sense resistor", lim.r7, "Ω", s["r7_tolerance"], power=lim.r7_rating,
                     stress=lim.p_r7, technology="metal film or metal strip, current sense", package=lim.r7_package,
                     tempco="≤ 100 ppm/K (min_margin covers about 1 %)",
                     rating_text=f"{eng(lim.r7_rating, 'W')}: {eng(lim.p_r7, 'W')} holding a stalled motor at "
                                 f"{t_a:g} °C, 50 % derating",
                     reason=(f"{s['r7_series']} value; the smallest that keeps every corner's trip in "
                             f"{s['i_no_trip']:g} to {s['i_must_trip']:g} A" if lim.box_scale is None else
                             f"{s['r7_series']} value; the smallest whose Monte Carlo lot keeps the trip in "
                             f"{s['i_no_trip']:g} to {s['i_must_trip']:g} A for {lim.mc_yield:.4%} of boards "
                             "(criterion = yield; not every corner)") + f"; drops {eng(lim.v_drop, 'V')}"))
    t = s["resistor_tolerance"]
    current = {9: vz_high / ((lim.r9 + lim.r10 + lim.r11) * (1 - t)), 12: vz_high / ((lim.r12 + lim.r13) * (1 - t))}
    current.update({10: current[9], 11: current[9], 13: current[12]})  # each divider's string carries one current
    bought, budget = _bought(t, s["temp_span"]) or t, _drift_budget(t, s["temp_span"])  # one class for R9..R13
    for n, role in ((9, "trip reference"), (10, "reference divider"), (11, "reference divider"),
                    (12, "level shift"), (13, "level shift")):
        value = getattr(lim, f"r{n}")
        rows.append(_resistor(sheet, f"R{n}", f"{role} resistor", value, bought, s[f"r{n}_series"],
                              current[n] ** 2 * value * (1 + t), t_a, "network of the largest worst margin with this R7"
                              + (" (pinned by the spec)" if s[f"r{n}"] is not None else ""),
                              technology="thin or metal film, one type for R9..R13",
                              tempco=budget))
    if lim.r14 is not None:
        rows.append(_resistor(sheet, "R14", "zener feed resistor", lim.r14, s["resistor_tolerance"], s["r14_series"],
                              lim.p_r14, t_a, f"feeds D1 its {eng(s['zener_test_current'], 'A')} test current plus "
                              f"the dividers' at {s['v_supply_min']:g} V"))
        need = ratings.power_needed(lim.p_zener, t_a, ratings.ZENER["knee"], ratings.ZENER["zero"])
        small = need <= ratings.ZENER["rating"]  # else the 1.3 W class (DO-41), derated the same way
        rating = ratings.ZENER["rating"] if small else ratings.ZENER_LARGE
        tech = f"{_zener_name(s['zener_voltage'])}, DO-35 glass" if small else "1.3 W zener class, DO-41"
        rows.append(_row(sheet, "D1", "reference zener", s["zener_voltage"], "V", s["zener_tolerance"],
                         power=rating, stress=lim.p_zener, technology=tech, package="DO-35" if small else "DO-41",
                         tempco=f"up to {eng(s['zener_tc'], 'V')}/K",
                         rating_text=f"{eng(rating, 'W')}: {eng(lim.p_zener, 'W')} at {s['v_supply_max']:g} V needs "
                                     f"{eng(need, 'W')} at {t_a:g} °C (50 % derating)",
                         reason=f"bridges both dividers; {eng(vz_low, 'V')} to {eng(vz_high, 'V')} with drift"))
    return rows


#: the divider resistors' temperature coefficient the BOM asks for, 1/K (:data:`.ratings.DIVIDER_TC`)
DIVIDER_TC = ratings.DIVIDER_TC


#: resistor tolerance classes a distributor stocks, fractions
TOLERANCE_CLASSES = (0.0005, 0.001, 0.0025, 0.005, 0.01, 0.02, 0.05)


def _bought(tolerance: float, span: float) -> float | None:
    """The tolerance class R9..R13 are bought in: the largest stocked class within what the design's ``tolerance``
    (initial tolerance and drift together) leaves after :data:`DIVIDER_TC`'s drift over ``span`` (K); None where no
    stocked class fits."""
    room = tolerance - DIVIDER_TC * span
    return max((c for c in TOLERANCE_CLASSES if c <= room * (1 + 1e-9)), default=None)


def _drift_budget(tolerance: float, span: float) -> str:
    """What R9..R13 must be bought as: the design's ``tolerance`` holds initial tolerance plus drift over the
    temperature span, so the class bought (:func:`_bought`) plus :data:`DIVIDER_TC`'s drift must stay inside it."""
    drift, bought = DIVIDER_TC * span, _bought(tolerance, span)
    if bought is None:
        return (f"≤ {DIVIDER_TC * 1e6:g} ppm/K drifts {drift:.2%} over ±{span:g} K, leaving no stocked tolerance class "
                f"inside the design's ±{tolerance:.2%}: a tracking network, or a larger resistor_tolerance")
    return (f"≤ {DIVIDER_TC * 1e6:g} ppm/K, bought ±{bought:.2%}: with {drift:.2%} of drift over ±{span:g} K that is "
            f"±{bought + drift:.2%}, inside the design's ±{tolerance:.2%}")


def _zener_name(v: float) -> str:
    """The BZX79-C name of a zener voltage of its E24 series (8.2 V -> BZX79-C8V2), else 'zener'."""
    from ..core import series

    if abs(series.nearest("E24", v) - v) > 1e-9 or not 2.4 <= v <= 75:
        return "zener"
    text = f"{v:.2g}" if v < 10 else f"{v:.0f}"
    return "BZX79-C" + (text.replace(".", "V") if "." in text else text + "V")


def _flyback_diodes(sheet: str, v_c: float, rail_text: str, i_peak: float, q_dead: float) -> dict:
    """The LM4652's flyback Schottkys: the bridge's 2 V_s reverse, 50 % derating; the coil current in the dead time
    (``q_dead``: the share of a period a clamp diode can conduct, at most)."""
    v_d = next(v for v in SCHOTTKY_VOLTAGES if v_c <= ratings.DERATING * v * (1 + 1e-12))
    return _row(sheet, "D1 D2 D3 D4", "flyback Schottky diode, from each bridge output to each rail", "Schottky", "",
                voltage=v_d, current=D1_SUGGESTED[0], stress=v_c, technology="fast Schottky rectifier",
                package="SMC or DO-201 class",
                rating_text=f"V_RRM ≥ {v_d:g} V: the output swings {rail_text}, {v_c:.4g} V across a diode, 50 % "
                            f"derating (the datasheet's own {D1_SUGGESTED[1]:g} V part runs at "
                            f"{v_c / D1_SUGGESTED[1] * 100:.0f} %); "
                            f"I_F(AV) {D1_SUGGESTED[0]:g} A as the datasheet suggests: a diode carries the coil current, up to "
                            f"{eng(i_peak, 'A')}, only in the dead time ({q_dead * 100:.2f} % of a period at most), so its "
                            f"repetitive peak must reach {eng(i_peak, 'A')}",
                reason="the datasheet's D1, protecting the output MOSFETs from flyback voltages; four, one per output "
                       "and rail, is the bridge's clamp (an assumption: the datasheet's figure names D1 only)")


def _filter_currents(cd) -> tuple[float, float, float]:
    """(the coils' rms at the thermal basis, C_BYP's audio rms, the ripple's rms), A. The coils: the larger corner's
    audio (the slow corner clips higher) with the triangular ripple at the slow corner, L low and the high rail
    (V_s / (2 L f) peak to peak, rms a 2 sqrt(3)th). C_BYP: the clipping sine at the top of the band (C high, the
    largest clipping power: the slow corner at the high rail), and the same ripple, which it takes."""
    from ..sources.lm4651 import circuit as lm4651
    from .class_d import model

    s, v_high = cd.spec, model.rails(cd.spec)[1]
    p_th_max = max(float(model.thermal_power(s, f)) for f in (cd.f_sw_min, cd.f_sw_max))
    c_hi, l_lo = cd.c_out * (1 + s["c_tolerance"]), cd.l_out * (1 - s["l_tolerance"])
    i_audio_c = (float(lm4651.p_clip(cd.f_sw_min, s["r_load"], v_high)) * s["r_load"]) ** 0.5 * 2 * math.pi * s["f_audio"] * c_hi
    i_ripple_c = v_high / (2 * l_lo * cd.f_sw_min) / (2 * 3 ** 0.5)
    return math.hypot((p_th_max / s["r_load"]) ** 0.5, i_ripple_c), i_audio_c, i_ripple_c


def class_d_rows(cd) -> list[dict]:
    """The class-D parts: the LM4651 (U1) and LM4652 (U2), R_OSC (R1), R_DLY (R2), the filter's two inductors
    (L1, L2) and C_BYP (C1), the flyback diodes (D1 to D4) and the heat sink (HS1), numbered on their sheet.

    Parameters
    ----------
    cd : ClassDResult
        The class-D design (:func:`handbook.design.class_d.design`).

    Returns
    -------
    list of dict
        The rows (keys :data:`COLUMNS`).
    """
    from ..sources.lm4651 import circuit as lm4651
    from .class_d import model

    sheet, s, fig = SHEETS["class_d"][0], cd.spec, cd.figures
    _, p_set = model.heat_corner(s, cd.f_sw_min, cd.f_sw_max)
    t_a = s["t_ambient"]
    i_peak = float(fig["i_peak"])
    i_sat = ratings.SATURATION_MARGIN * i_peak
    v_high = model.rails(s)[1]
    v_c = 2 * v_high
    rail_text = f"±{s['supply']:g} V" + (f" ± {s['supply_tolerance'] * 100:.3g} % (up to ±{v_high:.4g} V)"
                                         if s["supply_tolerance"] else "")
    v_rating = ratings.capacitor_voltage(v_c, film=True)
    pin = PIN_VOLTAGE ** 2  # R_OSC and R_DLY each carry at most PIN_VOLTAGE
    i_rms, i_audio_c, i_ripple_c = _filter_currents(cd)
    i_c1 = math.hypot(i_audio_c, i_ripple_c)
    theta_most = _down(cd.theta_sa_required)
    supply_text = (f"supply V+ + V− {lm4651.SUPPLY_TOTAL[0]:g} V to {lm4651.SUPPLY_TOTAL[1]:g} V, T_A −40 °C to +85 °C (LM4651/"
                   f"LM4652 operating ratings): {rail_text} is {v_c:.4g} V, at {t_a:g} °C ambient")
    return [
        _row(sheet, "U1", "LM4651 class-D PWM driver", "LM4651", "", voltage=lm4651.SUPPLY_TOTAL[1], stress=v_c,
             rating_text=supply_text, reason="drives the LM4652" + (
                 "; pin 17 (DELAY) to ground: its own 27 ns meets dead_time_min, no R_DLY" if cd.r_dly == 0 else "")),
        _row(sheet, "U2", f"LM4652 MOSFET H-bridge, {s['package']} package", "LM4652", "", voltage=lm4651.SUPPLY_TOTAL[1],
             stress=v_c, current=lm4651.I_LIMIT,
             rating_text=f"{supply_text}; output current: the LM4651's limit, which the datasheet's R_SCKT text asks to "
                         f"keep at 10 A, above the coils' worst peak {eng(i_peak, 'A')}; its maximum saturation drain "
                         f"current is 8 A minimum, 10 A typical (LM4652 table, at V_GS 6 V, V_DS 10 V)"
                         + (", below that peak: the datasheet's own 125 W, 50 µH example peaks near 8.7 A too"
                            if i_peak > 8.0 else "")
                         + f"; T_j {cd.t_junction:.4g} °C with HS1, below 150 °C",
             reason="the output stage; its heat sink is HS1"),
        _resistor(sheet, "R1", "R_OSC, oscillator", cd.r_osc, s["r_tolerance"], s["r_osc_series"], pin / cd.r_osc, t_a,
                  f"sets {eng(cd.f_sw, 'Hz')} by eq 5 ({eng(cd.f_sw_min, 'Hz')} to {eng(cd.f_sw_max, 'Hz')} at the "
                  "oscillator's and R_OSC's, R_DLY's tolerance)"),
        *([_resistor(sheet, "R2", "R_DLY, dead time", cd.r_dly, s["r_tolerance"], s["r_dly_series"], pin / cd.r_dly, t_a,
                     f"dead time at least {s['dead_time_min'] * 1e9:.1f} ns at its low tolerance end")] if cd.r_dly > 0 else []),
        _row(sheet, "L1 L2", "output filter inductor, one per bridge output", cd.l_out, "H", s["l_tolerance"],
             current=i_sat, stress=i_peak, technology="powder or gapped ferrite core, low-loss at the switching "
             "frequency", package="power inductor",
             rating_text=f"saturation ≥ {eng(i_sat, 'A')} (1.2 × the worst peak {eng(i_peak, 'A')}, audio plus "
                         f"ripple at clipping; the design held the peak to i_sat = {eng(s['i_sat'], 'A')} over 1.2); "
                         + _short_text(i_sat) + "; rms ≥ "
                         f"{eng(i_rms, 'A')} at the thermal basis (the slower corner's audio and the ripple); DCR ≤ "
                         f"{eng(s['l_dcr'] * cd.l_out, 'Ω')}",
             reason=f"{s['l_series']} value; the filter's corner {eng(cd.f_corner, 'Hz')}"),
        _row(sheet, "C1", "C_BYP, output filter capacitor", cd.c_out, "F", s["c_tolerance"], voltage=v_rating,
             current=i_c1 / ratings.DERATING, stress=v_c, technology="polyester or polypropylene film (the datasheet's "
             "Mylar)", package=_film_package(cd.c_out), tempco="",
             rating_text=f"{v_rating:g} V: the bridge swings {rail_text} per side, up to {v_c:.4g} V across "
                         f"it, 50 % derating; rms current ≥ {eng(i_c1 / ratings.DERATING, 'A')}: it carries "
                         f"{eng(i_c1, 'A')} (the clipping sine at the top of the band, {eng(i_audio_c, 'A')}, and the "
                         f"coils' ripple, {eng(i_ripple_c, 'A')}), 50 % derating",
             reason=f"{s['c_series']} value; across the load"),
        _flyback_diodes(sheet, v_c, rail_text, i_peak, float(fig["dead_time"]) * cd.f_sw_max),
        _row(sheet, "HS1", "LM4652 heat sink", f"≤ {theta_most} K/W", "K/W",
             rating_text=f"θ_SA at most {theta_most} K/W: the LM4652 dissipating {eng(p_set, 'W')} at "
                         f"the oscillator corner that sets it, T_j {model.DEV['tj_max'] - s['tj_margin']:g} °C, "
                         f"{t_a:g} °C ambient" + ("" if s["theta_sa_available"] is None else
                                                  f"; the {s['theta_sa_available']:g} K/W given holds T_j at "
                                                  f"{cd.t_junction:.4g} °C") + _full_power_text(cd),
             stress=cd.p_dissipation, technology="extruded aluminium, with thermal grease (θ_CS "
             f"{s['theta_cs']:g} K/W)", package="TO-220 mount",
             reason=f"sized at {cd.thermal_basis}: {eng(cd.p_thermal, 'W')} of output"),
    ]


def _down(value: float) -> str:
    """A largest allowed value to three significant figures, rounded down (22.75 K/W is written 22.7, not 22.8; a
    value already of three figures, 22.7, stays itself however its binary form falls)."""
    return f"{value:.3g}" if value <= 0 else f"{to_figures(value * (1 + 1e-12), math.floor, 3):.3g}"


def _short_text(i_sat: float) -> str:
    """What a shorted output does to coils rated ``i_sat`` (A): the LM4651 turns every MOSFET off at its current
    limit, 10 A at its minimum setting (the datasheet's SCKT pin; it gives no upper bound), which coils of a lower
    rating reach saturated; the book's saturation margin asks 1.2 x that limit to keep them clear of it."""
    from ..sources.lm4651 import circuit as lm4651

    limit, clear = eng(lm4651.I_LIMIT, "A"), ratings.SATURATION_MARGIN * lm4651.I_LIMIT
    if i_sat >= clear:
        return (f"a shorted output reaches the LM4651's current limit ({limit} at its minimum setting, every MOSFET "
                f"off) with the coils' saturation margin, {ratings.SATURATION_MARGIN:g} ×, kept")
    where = ("above this rating: the coils saturate on the way (softly in a powder core)" if i_sat < lm4651.I_LIMIT
             else "inside the coils' saturation margin")
    return (f"a shorted output is turned off at the LM4651's current limit ({limit} at its minimum setting), {where}; "
            f"coils rated {eng(clear, 'A')} or more ({ratings.SATURATION_MARGIN:g} × the limit) keep clear of it")


def _full_power_text(cd) -> str:
    """For a heat sink sized at 1/8 of the clipping power: what a continuous sine at the clipping power (a bench
    test at full power) asks of it, and the T_j the heat sink given (if any) then reaches; empty otherwise."""
    from .class_d import model
    from .common import checked_table

    s = cd.spec
    if s["thermal_basis"] != "iec_1_8":
        return ""
    full = checked_table("class_d", {**dict(s), "thermal_basis": "continuous_sine", "p_continuous": None})
    need, t_j, _, _ = (float(x) for x in model.thermal(full, cd.f_sw_min, cd.f_sw_max))
    target, shutdown = model.DEV["tj_max"] - s["tj_margin"], model.DEV["tj_max"]
    text = "; a continuous sine at the clipping power (a bench test at full power) " + (
        f"needs ≤ {_down(need)} K/W" if need > 0 else f"leaves no heat sink that holds T_j at {target:g} °C")
    if s["theta_sa_available"] is not None:
        given = s["theta_sa_available"]
        text += (f"; the {given:g} K/W given holds T_j at {t_j:.4g} °C there" if t_j <= shutdown else
                 f"; with the {given:g} K/W given T_j passes {shutdown:g} °C there: the LM4652's thermal shutdown trips")
    return text


def converter_rows(cv) -> list[dict]:
    """The TCA5600 converter's parts: the IC (U1), the storage capacitor (C2, figure 13's), the rectifier (D1), the
    coil (L1) and the sense resistor (R1), on their sheet.

    Parameters
    ----------
    cv : ConverterResult
        The converter's design (:func:`handbook.design.converter.design`).

    Returns
    -------
    list of dict
        The rows (keys :data:`COLUMNS`): the coil by its core shape, material and maker as PyOpenMagnetics'
        database names them, wound to order.
    """
    from .converter import cores, r1_ends

    sheet, s = SHEETS["converter"][0], cv.spec
    t_a = s["t_ambient"]
    maker = cores.load()["materials"][cv.core_material]["manufacturer"]
    i_sat = cv.i_peak_max / (1 - cv.saturation_margin)  # B is linear in I: the margin is 1 - B_peak / B_sat
    p_r1 = cv.i_rms ** 2 * cv.r1_part * r1_ends(s)[1]
    r1_drift_pct = s["r1_tempco"] * abs(t_a - 25.0) * 100
    v_c2 = s["v_out"] + s["v_regulator_drop"]
    v_off = v_c2 + s["v_f"]
    v_c2_rating = ratings.capacitor_voltage(v_c2)
    return [
        _row(sheet, "U1", "TCA5600 dc/dc converter", "TCA5600", "",
             rating_text=f"no public electrical characteristics (the excerpt prints none): check the full datasheet for "
                         f"V_CC2 up to {s['v_supply_max']:g} V, its switch off at {eng(v_off, 'V')} (C2 plus D1's drop) "
                         f"and carrying {eng(cv.i_peak_max, 'A')} peak",
             reason="the converter of the excerpt's figure 13"),
        _row(sheet, "C2", "storage capacitor at the regulator's input", C2_FIGURE_13, "F", 0.2, voltage=v_c2_rating,
             stress=v_c2, technology=f"aluminium electrolytic, low ESR, 105 °C class ({t_a:g} °C ambient)",
             package="radial",
             rating_text=f"{v_c2_rating:g} V: it holds V_out2 + V(9-8) = {eng(v_c2, 'V')}, 50 % derating; ripple "
                         f"current at least {eng(cv.i_rms, 'A')} rms (the coil's whole triangle, an upper bound)",
             reason="figure 13's value, not sized by the design; the excerpt asks C2 ≫ C7 (0.22 µF) to limit the "
                    "by-pass current through C7 while the coil dumps"),
        _row(sheet, "D1", "rectifier, coil to C2", "rectifier", "", voltage=2 * v_c2, current=cv.i_peak_max, stress=v_c2,
             technology=f"fast silicon rectifier with V_F {eng(s['v_f'], 'V')} ±{s['device_spread'] * 100:g} % at a few "
             "hundred mA, as the design assumes (a Schottky's lower V_F shortens the dump and raises the frequency: "
             "design with its own v_f)", package="SOD-123 or DO-41 class",
             rating_text=f"V_RRM ≥ {eng(2 * v_c2, 'V')}: it blocks C2's {eng(v_c2, 'V')} while S1 is on, 50 % derating; "
                         f"I_F(AV) ≥ {eng(cv.i_peak_max, 'A')}: its average is at most half the worst peak "
                         f"{eng(cv.i_peak_max, 'A')}, 50 % derating",
             reason="figure 13's V_F between the coil (pin 10) and C2 (pin 9); the excerpt does not say whether the "
                    "TCA5600 holds it: fit it unless the full datasheet does"),
        _row(sheet, "L1", "converter coil, wound to order", cv.l1_nominal, "H", s["a_l_tolerance"], current=i_sat,
             stress=cv.i_peak_max, technology=f"{cv.turns} turns of {cv.wire} on {maker} {cv.core_shape}, "
             f"{cv.core_material}, gapped to A_L {eng(cv.a_l, 'H')}", package=f"{cv.core_shape} set on its bobbin",
             rating_text=f"saturates at about {eng(i_sat, 'A')} at {t_a + cv.temperature_rise:.3g} °C; the worst "
                         f"peak {eng(cv.i_peak_max, 'A')} leaves {cv.saturation_margin:.0%}",
             reason=f"eq 6 in the slow corner: {eng(cv.l1_max, 'H')} at most at +{s['a_l_tolerance'] * 100:g} % A_L; rise "
                    f"{cv.temperature_rise:.2g} K"),
        _resistor(sheet, "R1", "current-sense resistor", cv.r1_part, s["r1_tolerance"], s["r1_series"], p_r1, t_a,
                  f"eq 6a in the device corner that delivers least: {eng(cv.r1_worst, 'Ω')} over its high end "
                  f"(+{s['r1_tolerance'] * 100:g} % and +{r1_drift_pct:.2g} % drift at {t_a:g} °C), rounded down",
                  tempco=f"≤ {s['r1_tempco'] * 1e6:g} ppm/K"),
    ]


#: design table -> its rows
ROWS = {"commutation": commutation_rows, "current_limiter": limiter_rows, "class_d": class_d_rows,
        "converter": converter_rows}


def rows(result: dict) -> list[dict]:
    """The BOM of the designs in ``result``, sheet by sheet (A1 timers, A2 limiter, A3 class-D, A4 converter).

    Parameters
    ----------
    result : dict
        {table: its design's result} for the tables to list (what :func:`handbook.design.spec.run_each`
        designed; a table left out has no rows).

    Returns
    -------
    list of dict
        One row per line item (keys :data:`COLUMNS`): designators unique across the sheets, ``quantity`` their
        count, numbers in SI units (:data:`UNITS`), None where a column does not apply.
    """
    out = []
    for table, make in ROWS.items():
        if table not in result:
            continue
        if table == "commutation":
            ic = result["current_limiter"].spec["ic"] if "current_limiter" in result else "TDA5144"
            out += make(result[table], ic)
        else:
            out += make(result[table])
    return out


def write(table: list[dict], path: str | Path) -> None:
    """Write the BOM as CSV atomically: a complete file or none at all.

    Parameters
    ----------
    table : list of dict
        The rows, as :func:`rows` returns them (keys :data:`COLUMNS`).
    path : str or pathlib.Path
        The CSV file to write (replaced if it exists); its directory must exist.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=".bom-", suffix=".csv", dir=path.parent if str(path.parent) else ".")
    try:
        with os.fdopen(fd, "w", newline="", encoding="utf-8-sig") as fh:  # the BOM mark: spreadsheets read Ω, ±
            w = csv.DictWriter(fh, fieldnames=list(COLUMNS))
            w.writeheader()
            w.writerows({k: ("" if r[k] is None else r[k]) for k in COLUMNS} for r in table)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
