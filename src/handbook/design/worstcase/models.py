"""The worst-case models of the TDA5144 timing set, the LM4651/LM4652 class-D stage and the TCA5600 converter:
each design's own equations (the sources' ``circuit`` functions, elementwise on numpy arrays) over the inputs
its corners vary.

* commutation: CAP-CD's swing at ``rpm_min`` as a fraction of that board's window (limit 1: the swing fits
  between the low and high switching levels) and its swing at ``rpm_max`` (limit ``min_excursion``), over the
  capacitor tolerance and the TDA5144's charge current and two levels; with CAP-ST and CAP-TI chosen (motor
  data, ``flyback_time``) their quantities too (:mod:`.timers`);
* class_d: the oscillator (limits: the LM4651's 50 .. 225 kHz), the dead time (``dead_time_min``), the clipping
  power (``p_out``), the inductor's peak (``i_sat`` / 1.2 and 10 A), the output filter's corner (no limit of its
  own: reported), its Q (``q_max``), the switching residue at the load (``ripple_max``) and THD+N as the analyser
  reads it (``thd_max``), over R_OSC, R_DLY, L, C_BYP and the oscillator's spread against eq 5;
* converter: the current the converter delivers at ``v_supply_min`` (limit ``i_out``) and the full-load
  frequency there (limit the spec's ``f_min``) and at its lowest over the supply range (limit 20 kHz with
  ``audible = "avoid"``), over R1, L1 (A_L) and the TCA5600's V12(H), V_CE(sat) and V_F (each +-the spec's
  ``device_spread``, the spread the design itself assumed).
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ...sources.an94002 import circuit as an94002
from ...sources.lm4651 import circuit as lm4651
from ..class_d import model as class_d_model
from . import timers
from .engine import Measure, Model, Source, combine
from .limiter import UNIFORM


def commutation(result) -> Model:
    """The model of a designed timing set: CAP-CD's, and CAP-ST's and CAP-TI's where the design chose them.

    Parameters
    ----------
    result : CommutationResult
        A designed timing set; ``cap_cd``, ``cap_st`` and ``cap_ti`` (None, or absent: not chosen) and the
        checked spec are read.

    Returns
    -------
    Model
        Inputs ``cap``, ``i_ch``, ``v_low``, ``v_high``; quantities ``swing_rpm_min`` (V, no limit),
        ``window_fill`` (the swing at rpm_min over the window, limit 1) and ``swing_rpm_max`` (V, limit
        ``min_excursion``); then :func:`.timers.start`'s and :func:`.timers.watchdog`'s inputs and quantities
        for a chosen CAP-ST and CAP-TI.
    """
    s, c_st, c_ti = result.spec, getattr(result, "cap_st", None), getattr(result, "cap_ti", None)
    parts = [cap_cd(result.cap_cd, s)]
    parts += [] if c_st is None else [timers.start(c_st, s)]
    parts += [] if c_ti is None else [timers.watchdog(c_ti, s)]
    m = combine(*parts)
    pins = timers.pin_drift(s, c_st is not None, c_ti is not None)
    return dataclasses.replace(m, drift=m.drift + (pins,)) if pins else m


def cap_cd(c: float, s: dict) -> Model:
    """The CAP-CD model of a designed timing set.

    Parameters
    ----------
    c : float
        The chosen CAP-CD, F.
    s : dict
        The checked ``[commutation]`` table.

    Returns
    -------
    Model
        Inputs ``cap``, ``i_ch``, ``v_low``, ``v_high``; quantities ``swing_rpm_min`` (V, no limit),
        ``window_fill`` (the swing at rpm_min over the window, limit 1) and ``swing_rpm_max`` (V, limit
        ``min_excursion``).
    """
    t_slow, t_fast = an94002.t_com(s["rpm_min"], s["pole_pairs"]), an94002.t_com(s["rpm_max"], s["pole_pairs"])
    table = "TDA5144 datasheet (June 1994), CAP-CD table: min and max only; " + UNIFORM
    srcs = (timers.capacitor("cap", "CAP-CD", c, s),
            Source("i_ch", "TDA5144 CAP-CD charge current", s["i_charge_min"], s["i_charge_max"],
                   (s["i_charge_min"] + s["i_charge_max"]) / 2, "charge current", table, unit="A"),
            Source("v_low", "TDA5144 CAP-CD low level", s["v_low_min"], s["v_low_max"],
                   (s["v_low_min"] + s["v_low_max"]) / 2, "low level", table, unit="V"),
            Source("v_high", "TDA5144 CAP-CD high level", s["v_high_min"], s["v_high_max"],
                   (s["v_high_min"] + s["v_high_max"]) / 2, "high level", table, unit="V"))

    def f(cap, i_ch, v_low, v_high):
        swing = i_ch * t_slow / cap
        return {"swing_rpm_min": swing, "window_fill": swing / (v_high - v_low), "swing_rpm_max": i_ch * t_fast / cap}

    measures = (Measure("swing_rpm_min", "CAP-CD swing at rpm_min", "V"),
                Measure("window_fill", "CAP-CD swing at rpm_min, fraction of the board's window", "1", None, 1.0,
                        "window"),
                Measure("swing_rpm_max", "CAP-CD swing at rpm_max", "V", s["min_excursion"], None, "min_excursion"))
    drift = (timers.capacitor_drift("CAP-CD", c, s),
             "The TDA5144's charge current and levels are the datasheet's min and max (June 1994); the project "
             "holds no figure for their temperature drift beyond them.")
    return Model(srcs, measures, f, drift)


def class_d(result) -> Model:
    """The output-filter and oscillator model of a designed class-D stage.

    Parameters
    ----------
    result : ClassDResult
        A designed stage; ``r_osc``, ``r_dly``, ``l_out``, ``c_out`` and the checked spec are read.

    Returns
    -------
    Model
        Inputs ``r_osc``, ``r_dly`` (ohm, +-``r_tolerance``; R_DLY only where one is fitted), ``osc`` (the
        oscillator's factor on eq 5), ``l``, ``c``, ``v_s`` (V, +-``supply_tolerance``, only where it is not 0);
        quantities ``f_sw`` (Hz, limits the LM4651's range),
        ``dead_time`` (s, limit ``dead_time_min``), ``p_clip`` (W, at least ``p_out`` and the test power),
        ``i_peak`` (A, at most ``i_sat`` / 1.2 and 10 A), ``f_corner`` (Hz, no limit), ``q`` (limit ``q_max``),
        ``ripple`` (V rms, limit ``ripple_max``) and ``thd_n`` (fraction, limit ``thd_max``). The band's flatness
        is left to the design's own search over the whole L, C box (its peaking is not monotonic in L and C, so
        corners would not bound it).
    """
    s, lo, co = result.spec, result.l_out, result.c_out
    rl, vs, rt = s["r_load"], s["supply"], s["r_tolerance"]
    res = f"class_d.r_tolerance = {rt:g} (metal film); " + UNIFORM
    resistors = tuple(Source(k, part, v * (1 - rt), v * (1 + rt), v, "R_OSC, R_DLY tolerance", res, unit="ohm")
                      for k, part, v in (("r_osc", "R_OSC", result.r_osc), ("r_dly", "R_DLY", result.r_dly)) if v > 0)
    srcs = resistors + (Source("osc", "LM4651 oscillator (factor on eq 5)", 1 - s["osc_tol_slow"], 1 + s["osc_tol_fast"], 1.0,
                   "oscillator", "LM4651 table against eq 5 (typicals; no limit is printed): osc_tol_slow, "
                   "osc_tol_fast; " + UNIFORM),
            Source("l", "L1, L2", lo * (1 - s["l_tolerance"]), lo * (1 + s["l_tolerance"]), lo, "inductor tolerance",
                   f"class_d.l_tolerance = {s['l_tolerance']:g}; both coils taken equal (the filter's model); "
                   + UNIFORM, unit="H"),
            Source("c", "C_BYP", co * (1 - s["c_tolerance"]), co * (1 + s["c_tolerance"]), co, "capacitor tolerance",
                   f"class_d.c_tolerance = {s['c_tolerance']:g} (film, J); " + UNIFORM, unit="F"))
    st = s["supply_tolerance"]
    if st:  # the rails' tolerance, where the spec gives one
        srcs += (Source("v_s", "±V_S rails", vs * (1 - st), vs * (1 + st), vs, "supply tolerance",
                        f"class_d.supply_tolerance = {st:g}; both rails taken equal; " + UNIFORM, unit="V"),)

    def f(osc, l, c, r_osc, r_dly=0.0, v_s=vs):
        fs = lm4651.f_sw_for(r_osc, r_dly) * osc
        return {"f_sw": fs, "dead_time": lm4651.dead_time_total(r_dly) + 0 * osc, "f_corner": lm4651.filter_f0(l, c),
                "q": lm4651.filter_q(l, c, rl),
                "ripple": lm4651.ripple_rms(fs, l, c, rl, v_s), "p_clip": lm4651.p_clip(fs, rl, v_s),
                "i_peak": lm4651.inductor_peak(fs, l, c, lm4651.v_clip_peak(fs, rl, v_s), rl, v_s, s["f_audio"]),
                "thd_n": lm4651.thd_n_measured(fs, l, c, s["thd_test_power"], rl, v_s, s["thd_bandwidth"])}

    measures = (Measure("f_sw", "switching frequency", "Hz", lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"],
                        "oscillator range"),
                Measure("dead_time", "dead time (27 ns + 1.7 ns/kΩ × R_DLY)", "s", s["dead_time_min"], None,
                        "dead_time_min"),
                Measure("f_corner", "output filter corner", "Hz"),
                Measure("q", "output filter Q with the load", "1", None, s["q_max"], "q_max"),
                Measure("ripple", "switching residue at the load, rms", "V", None, s["ripple_max"], "ripple_max"),
                Measure("p_clip", "clipping power (no clipping at p_out nor at the THD+N test point)", "W",
                        class_d_model.p_unclipped(s), None, "p_out"),
                Measure("i_peak", "inductor peak current (audio at clipping plus ripple)", "A", None,
                        class_d_model.i_peak_limit(s), "i_sat / 1.2, 10 A"),
                Measure("thd_n", "THD+N at the test point (analyser's band)", "%", None, s["thd_max"], "thd_max"))
    drift = ("The oscillator's spread is eq 5 against the LM4651 table's typicals at 25 C (osc_tol_slow, "
             "osc_tol_fast); the datasheet prints no temperature drift for it.",
             "The dead time's 27 ns at R_DLY = 0 and its 1.7 ns/kΩ slope are the LM4651 table's typicals (no limits "
             "printed; eq 4 as printed cannot be used, erratum lm4651-dead-time): only R_DLY's tolerance varies here, "
             "so a dead-time margin of a few per cent is a margin on the typicals, not on the device.",
             f"C_BYP is film (the BOM's class); L's tolerance l_tolerance = {s['l_tolerance']:.0%} is taken to hold "
             "over temperature; R_DS(on) is taken to rise 0.2 %/K, the Example Design's 230 mΩ 'at 100 °C' against "
             "the LM4652 table's 200 mΩ typical at 25 °C (the 230 mΩ is not in the table: erratum lm4651-t-rds), applied "
             "to the 300 mΩ maximum; the heat sink's corner carries it, not these quantities. The datasheet gives no "
             "other figure: power MOSFETs commonly rise faster, so a steeper part needs a larger heat sink. No ageing "
             "figure is printed for any of these parts.",
             "Not sampled here: the audio band's flatness (the design checks it over the whole L, C tolerance box, "
             "where corners would not bound it) and the heat sink (sized at its own worst corner).")
    return Model(srcs, measures, f, drift)


def r1_drift_sentence(result) -> str:
    """R1's temperature drift as the report's section 4 states it: how far it moves by t_ambient, that the design's
    corners and this analysis take it, and the current delivered at the weak corner with it.

    Parameters
    ----------
    result : ConverterResult
        A designed converter (a stand-in without ``i_out_least`` gets the drift alone).

    Returns
    -------
    str
        The sentence.
    """
    from ..converter.operating import r1_drift

    s = result.spec
    text = (f"R1's temperature coefficient, at most {s['r1_tempco'] * 1e6:g} ppm/K either way (converter.r1_tempco, "
            f"the BOM's class), moves it up to {r1_drift(s) * 100:.2f} % from 25 °C to t_ambient = {s['t_ambient']:g} °C; "
            "the design's corners take it beside the "
            f"{s['r1_tolerance'] * 100:g} % tolerance, and so does this analysis (the input 'R1 drift', uniform "
            "either way: the tempco's sign and size are unknown within the bound)")
    least = getattr(result, "i_out_least", None)  # None: a stand-in result that carries no weak-corner figure
    if least is None:
        return text + "."
    return text + (f": at the weak corner, R1 at both high ends still delivers {least * 1e3:.2f} mA "
                   f"(i_out = {s['i_out'] * 1e3:.4g} mA).")


def converter(result) -> Model:
    """The operating-point model of a designed TCA5600 converter.

    Parameters
    ----------
    result : ConverterResult
        A designed converter; ``r1_part``, ``l1_nominal`` and the checked spec (``device_spread``: the TCA5600's
        V12(H), V_CE(sat) and V_F either way, a fraction) are read.

    Returns
    -------
    Model
        Inputs ``r1``, ``r1_drift`` (a factor), ``l``, ``v12h``, ``vce``, ``vf``; quantities ``i_out_max`` (A, limit ``i_out``),
        ``f_sw_vmin`` (Hz, limit the spec's ``f_min``) and ``f_sw_low`` (Hz, the lowest over the supply range;
        limit 20 kHz with ``audible = "avoid"``, else none).
    """
    from ..converter.operating import r1_drift as drift_of
    from ..converter.result import AUDIO_BAND

    s, r1, l1 = result.spec, result.r1_part, result.l1_nominal
    spread = s["device_spread"]
    dev = (f"converter.device_spread = {spread:g}, an assumption: +-{spread:.0%} (no public TCA5600 characteristics; "
           "TCA5600 chapter's reading note); ")
    drift_r1 = drift_of(s)  # zero at 25 C or with r1_tempco = 0: a fixed factor of 1 then, not an input
    srcs = (Source("r1", "R1", r1 * (1 - s["r1_tolerance"]), r1 * (1 + s["r1_tolerance"]), r1, "R1 tolerance",
                   f"converter.r1_tolerance = {s['r1_tolerance']:g}; " + UNIFORM, unit="ohm"),
            *((Source("r1_drift", "R1 drift to t_ambient", 1 - drift_r1, 1 + drift_r1, 1.0, "R1 drift",
                      f"converter.r1_tempco = {s['r1_tempco'] * 1e6:g} ppm/K × |t_ambient − 25 °C|, either way; "
                      + UNIFORM),) if drift_r1 > 0 else ()),
            Source("l", "L1 (A_L)", l1 * (1 - s["a_l_tolerance"]), l1 * (1 + s["a_l_tolerance"]), l1, "A_L tolerance",
                   f"converter.a_l_tolerance = {s['a_l_tolerance']:g} (gapped core, turns fixed); " + UNIFORM, unit="H"),
            *(Source(k, part, s[key] * (1 - spread), s[key] * (1 + spread), s[key], part, dev + UNIFORM, unit="V")
              for k, key, part in (("v12h", "v12h", "TCA5600 V12(H)"), ("vce", "v_ce_sat", "TCA5600 V_CE(sat)"),
                                   ("vf", "v_f", "rectifier V_F"))))
    top = s["v_out"] + s["v_regulator_drop"]

    def freq(vcc, l, i_pk, vce, vf, v12h):
        plus, minus = top + vf - vcc, vcc - vce - v12h
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(plus > 0, 1 / (l * i_pk * (1 / minus + 1 / np.where(plus > 0, plus, 1.0))), 0.0)

    def f(r1, l, v12h, vce, vf, r1_drift=1.0):
        i_pk = v12h / (r1 * r1_drift)  # eq 5 read backwards: R1 (as drifted) sets the peak current
        plus, minus = top + vf - s["v_supply_min"], s["v_supply_min"] - vce - v12h
        f_lo = freq(s["v_supply_min"], l, i_pk, vce, vf, v12h)
        return {"i_out_max": i_pk / 2 * minus / (minus + plus), "f_sw_vmin": f_lo,
                "f_sw_low": np.minimum(f_lo, freq(s["v_supply_max"], l, i_pk, vce, vf, v12h))}

    avoid = s["audible"] == "avoid"
    measures = (Measure("i_out_max", "current delivered at v_supply_min", "A", s["i_out"], None, "i_out"),
                Measure("f_sw_vmin", "full-load frequency at v_supply_min", "Hz", s["f_min"], None, "f_min"),
                Measure("f_sw_low", "lowest full-load frequency over the supply range", "Hz",
                        AUDIO_BAND if avoid else None, None, "audio band" if avoid else ""))
    drift = (f"A_L's temperature drift is taken inside a_l_tolerance = {s['a_l_tolerance']:.0%} (the schema's "
             "assumption for a gap ground to order); the core's saturation, which does drift, is judged by the design "
             "at t_ambient + the coil's rise (the material's 25 C and 100 C figures, PyOpenMagnetics' database).",
             r1_drift_sentence(result),
             "V12(H), V_CE(sat) and V_F have no public figures, nor temperature coefficients (the TCA5600 chapter's "
             f"reading note): the assumed +-{spread:.0%} (device_spread) stands for spread and drift together.",
             "Ageing: no source here prints it for these parts (an electrolytic C2 loses capacitance as it ages, which "
             "the design does not use: C2 only holds the regulator's input).")
    return Model(srcs, measures, f, drift)
