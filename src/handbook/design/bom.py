"""Bill of materials: the chosen parts with the reason for each value, written atomically as CSV."""
from __future__ import annotations

import csv
import os
import tempfile
from pathlib import Path


def rows(result: dict) -> list[dict]:
    """Reference, value (SI, for programs), value_text (with its unit, for people), tolerance, series, and why
    each value was chosen.

    Parameters
    ----------
    result : dict
        The four designs' results, {table: result}: ``result["commutation"]`` a
        :class:`~handbook.design.commutation.CommutationResult`, ``"current_limiter"`` a
        :class:`~handbook.design.limiter.LimiterResult`, ``"class_d"`` a :class:`~handbook.design.class_d.ClassDResult`
        and ``"converter"`` a :class:`~handbook.design.converter.ConverterResult` (what
        :func:`handbook.design.spec.run` returns).

    Returns
    -------
    list of dict
        One row per part, in the order C3, C4 (C5, C6 when designed), R7, R9..R13, D1, R_OSC, R_DLY, L1/L2,
        C_BYP, heat sink, then the converter's L1 and R1: ``reference`` (str), ``value`` (float, SI: F, ohm, H,
        the zener's V, the heat sink's K/W), ``value_text`` (str, with its unit), ``tolerance`` (fraction, or None
        for the heat sink), ``series`` (str, "" where none) and ``reason`` (str).
    """
    c, lim, cd, cv = result["commutation"], result["current_limiter"], result["class_d"], result["converter"]
    sc, sl, sd = c.spec, lim.spec, cd.spec
    table = [
        ("C3", c.cap_cd, sc["tolerance"], sc["series"],
         f"CAP-CD: smallest value whose swing at {sc['rpm_min']:g} rpm fits the {sc['v_high_min']:g} V - "
         f"{sc['v_low_max']:g} V window at every tolerance corner; reliable {c.rpm_min_reliable:.0f} to "
         f"{c.rpm_max_reliable:.0f} rpm"),
        ("C4", c.cap_dc, sc["tolerance"], sc["series"], "CAP-DC: the slave timer needs the same value as CAP-CD"),
        *([("C5", c.cap_st, sc["tolerance"], sc["series"],
            f"CAP-ST: smallest value whose shortest start period ({c.start.period_min:.3g} s) outlasts the decay of "
            f"the slowest rotor rocking ({c.start.f_osc_min:.3g} Hz) to {sc['residual']:g}")] if c.start else []),
        *([("C6", c.cap_ti, sc["tolerance"], sc["series"],
            f"CAP-TI: watchdog {c.watchdog.t_wd_min * 1e3:.3g} to {c.watchdog.t_wd_max * 1e3:.3g} ms outlasts the "
            f"{sc['flyback_time'] * 1e3:.3g} ms flyback; catches reverse rotation up to "
            f"{c.watchdog.rpm_reverse_caught:.0f} rpm")] if c.watchdog else []),
        ("R7", lim.r7, sl["r7_tolerance"], sl["r7_series"],
         f"current sense: smallest value with which every board's trip current stays in {sl['i_no_trip']:g}.."
         f"{sl['i_must_trip']:g} A with a {sl['min_margin']:.0%} margin ({lim.i_trip_min:.3f}..{lim.i_trip_max:.3f} A "
         f"at the worst corners); up to {lim.p_r7:.3g} W while it holds a stalled motor"),
        *((f"R{n}", getattr(lim, f"r{n}"), sl["resistor_tolerance"], sl[f"r{n}_series"],
           ("pinned by the spec; " if sl[f"r{n}"] is not None else "")
           + f"{role}: network of the largest worst margin with this R7 ({lim.binding} binds)")
          for n, role in ((9, "trip reference"), (10, "reference divider"), (11, "reference divider"),
                          (12, "level shift"), (13, "level shift"))),
        ("D1", sl["zener_voltage"], sl["zener_tolerance"], "", "zener bridging the level shift (BZX79-C8V2 on the board)"),
        ("R_OSC", cd.r_osc, 0.01, sd["r_osc_series"],
         f"sets f_sw = {cd.f_sw / 1e3:.1f} kHz by eq 5 ({cd.f_sw_min / 1e3:.1f} to {cd.f_sw_max / 1e3:.1f} kHz "
         f"at the oscillator's tolerance): joint optimum ({sd['objective']}) with L and C_BYP; binds: {cd.binding}"),
        ("R_DLY", cd.r_dly, 0.01, sd["r_dly_series"],
         f"dead time {sd['dead_time_min'] * 1e9:.1f} ns or more (27 ns + 1.7 pF x R_DLY), the least: more costs THD"),
        ("L1, L2", cd.l_out, sd["l_tolerance"], sd["l_series"],
         f"bridge output filter, one per output; saturation {sd['i_sat']:g} A or more"),
        ("C_BYP", cd.c_out, sd["c_tolerance"], sd["c_series"], "bridge output filter across the load, film"),
        ("heat sink", cd.theta_sa_required, None, "",
         f"LM4652 heat sink of {cd.theta_sa_required:.2f} K/W or better (thermal resistance, sink to air): T_j "
         f"{cd.t_junction:.0f} °C at worst"),
        *converter_rows(cv),
    ]
    return [{"reference": r, "value": v, "value_text": readable(r, v, ser), "tolerance": t, "series": ser, "reason": why}
            for r, v, t, ser, why in table]


def converter_rows(cv) -> list[tuple]:
    """The TCA5600 converter's coil and sense resistor (the class-D filter already uses L1, L2).

    Parameters
    ----------
    cv : ConverterResult
        The converter's design (:func:`handbook.design.converter.design`).

    Returns
    -------
    list of tuple
        Two rows, (reference, value, tolerance, series, reason): the coil "L1 (TCA5600)" (its nominal
        inductance, H; A_L's tolerance as a fraction; no series) and "R1 (TCA5600)" (the series part, ohm;
        R1's tolerance as a fraction; ``r1_series``).
    """
    from ..core.units import eng

    sv = cv.spec
    return [
        ("L1 (TCA5600)", cv.l1_nominal, sv["a_l_tolerance"], "",
         f"eq 6 gives L1 = {eng(cv.l1, 'H')} as the largest inductance (a larger L or peak current runs slower than "
         f"f_min = {eng(sv['f_min'], 'Hz')} at VCC2 = {eng(sv['v_supply_min'], 'V')}): wound for "
         f"{eng(cv.l1_nominal, 'H')}, which at +{sv['a_l_tolerance']:.0%} A_L with R1 at its low end still keeps "
         f"f_min; {cv.turns} turns of {cv.wire} on {cv.core_shape} in {cv.core_material}, A_L {eng(cv.a_l, 'H')} "
         f"(centre gap about {eng(cv.gap, 'm')} by PyOpenMagnetics' gap model; grind to A_L); "
         f"{cv.saturation_margin:.0%} of saturation left at {eng(cv.i_peak_max, 'A')}; loss "
         f"{eng(cv.core_loss + cv.winding_loss, 'W')}, rise {cv.temperature_rise:.2g} K; binds: {cv.binding}"),
        ("R1 (TCA5600)", cv.r1_part, sv["r1_tolerance"], sv["r1_series"],
         f"eq 6a: V12(H) / I_peak = {sv['v12h']:g} V / {eng(cv.i_peak, 'A')} = {eng(cv.r1, 'Ω')}; the "
         f"{sv['r1_series']} value at or below {eng(cv.r1 / (1 + sv['r1_tolerance']), 'Ω')} so that at "
         f"+{sv['r1_tolerance']:.0%} the peak current still reaches eq 5's (the load it carries is proportional "
         f"to it); at -{sv['r1_tolerance']:.0%} it is {eng(cv.i_peak_max, 'A')}, which the coil holds"),
    ]


#: the unit of each reference's value, by its first letter (the heat sink's is K/W)
_UNITS = {"C": "F", "R": "ohm", "L": "H", "D": "V"}


def readable(ref: str, value: float, series: str) -> str:
    """The value as a person reads it: 18 nF, 1.21 kΩ, 100 µH, 8.2 V (zener), 0.68 K/W.

    Parameters
    ----------
    ref : str
        The part's reference: its first letter gives the unit (C: F, R: ohm, L: H, D: V); "heat sink": K/W.
    value : float
        The part's value in that SI unit.
    series : str
        The part's E-series (not used: the value is shown as it is).

    Returns
    -------
    str
        The value with an engineering prefix and its unit (three significant figures for the heat sink; the
        bare number for a reference of no known unit).
    """
    from ..core.units import eng

    if ref == "heat sink":
        return f"{value:.3g} K/W"
    unit = _UNITS.get(ref[0], "")
    return eng(value, unit.replace("ohm", "Ω")) if unit else f"{value:g}"


def write(table: list[dict], path: str | Path) -> None:
    """Write the BOM as CSV atomically: a complete file or none at all.

    Parameters
    ----------
    table : list of dict
        The rows, as :func:`rows` returns them (keys ``reference``, ``value``, ``value_text``, ``tolerance``,
        ``series``, ``reason``).
    path : str or pathlib.Path
        The CSV file to write (replaced if it exists); its directory must exist.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=".bom-", suffix=".csv", dir=path.parent if str(path.parent) else ".")
    try:
        with os.fdopen(fd, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=["reference", "value", "value_text", "tolerance", "series", "reason"])
            w.writeheader()
            w.writerows(table)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
