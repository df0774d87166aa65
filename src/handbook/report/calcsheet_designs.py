"""The calculation sheet's steps for each of the four designs, in the order each design takes them.

Every value substituted is the design's own: read from its result and its checked spec (``result.spec``).
A step from a registry record says which form it shows; a number no registry equation gives (a search, an
E-series pick, a tolerance, a rating rule) is a step in words.
"""
from __future__ import annotations

from .calcsheet_steps import equation_step, shown, words

_AN = "AN94002"
_CLASS_D = "handbook.design.class_d"


def _pct(fraction: float) -> str:
    return f"{fraction * 100:.3g} %"


def _at(value: float, unit: str) -> str:
    return shown(value, unit)[1]


# ----------------------------------------------------------------------------------------------
# commutation (AN94002 2.1)

def commutation(r) -> list:
    """The TDA5143/5144 timing set: CAP-CD by eq 6, its speed range by eq 7 and eq 5, CAP-ST by eq 2 and 1,
    CAP-TI by eq 9.

    Parameters
    ----------
    r : CommutationResult
        The designed timing set.

    Returns
    -------
    list of Step
        The steps, CAP-CD first, then CAP-ST and CAP-TI where they were designed.
    """
    s, tol, n = r.spec, r.spec["tolerance"], r.spec["pole_pairs"]
    window = s["v_high_min"] - s["v_low_max"]
    here = "handbook.design.commutation"
    out = [equation_step("Smallest CAP-CD whose swing at rpm_min fits the narrowest window, at the capacitor's low "
                         "end", "an94002-eq6",
                         {"I_{ch,max}": (s["i_charge_max"], "A"), "N_{min}": (s["rpm_min"] / 60, "rpm"),
                          r"\Delta{}V_{win}": (window, "V"), "n": (n, "1")},
                         (r.continuous_optimum * (1 - tol), "F")),
           words(f"With the capacitor {tol * 100:g} % low the nominal must be "
                 f"{_at(r.continuous_optimum * (1 - tol), 'F')} / (1 − {tol:g}) = {_at(r.continuous_optimum, 'F')}",
                 (r.continuous_optimum, "F"), f"{here}: capacitor tolerance {tol * 100:g} %"),
           words(f"{s['series']} value at or above {_at(r.continuous_optimum, 'F')}: {_at(r.cap_cd, 'F')} "
                 f"(CAP-DC = CAP-CD; the next smaller, {_at(r.next_smaller, 'F')}, fails at a corner)",
                 (r.cap_cd, "F"), f"{here}: {s['series']} series pick, re-checked at all 16 corners"),
           equation_step("Highest reliable speed: the smallest swing (smallest current, capacitor high) stays above "
                         "the noise floor", "an94002-eq7",
                         {"I_{ch,min}": (s["i_charge_min"], "A"), "C_{CD}": (r.cap_cd * (1 + tol), "F"),
                          r"\Delta{}V_{noise}": (s["min_excursion"], "V"), "n": (n, "1")},
                         (r.rpm_max_reliable / 60, "rpm")),
           equation_step("Lowest reliable speed: the largest swing (largest current, capacitor low) fits the "
                         "narrowest window", "an94002-eq5",
                         {"I": (s["i_charge_max"], "A"), "C_{CD}": (r.cap_cd * (1 - tol), "F"),
                          r"\Delta{}V": (window, "V"), "n": (n, "1")},
                         (r.rpm_min_reliable / 60, "rpm"), solve_for="N"),
           words(f"Smallest swing at {s['rpm_max']:g} rpm, {_at(r.swing_at_rpm_max, 'V')}, over the "
                 f"{_at(s['min_excursion'], 'V')} noise floor: noise margin {_pct(r.noise_margin)}",
                 (r.noise_margin, "%"), f"{here}: the swing at rpm_max at its worst corner")]
    if r.start is not None:
        out += _start(r, s)
    if r.watchdog is not None:
        out += _watchdog(r, s)
    return out


def _start(r, s) -> list:
    st, tol, mt = r.start, s["tolerance"], s["motor_tolerance"]
    here = "handbook.design.commutation (timers)"
    return [
        equation_step(f"Slowest rotor rocking about a detent (K_t and I {mt * 100:g} % low, J {mt * 100:g} % high)",
                      "an94002-eq2",
                      {"K_t": (s["torque_constant"] * (1 - mt), "N·m/A"), "I": (s["start_current"] * (1 - mt), "A"),
                       "p": (s["pole_pairs"], "1"), "J": (s["inertia"] * (1 + mt), "kg·m²")},
                      (st.f_osc_min, "Hz")),
        words(f"The rocking at {_at(st.f_osc_min, 'Hz')} (damping ratio {s['damping_ratio']:g}) decays to "
              f"{s['residual']:g} of its first swing in ln(1/{s['residual']:g}) / (ζ 2π f) = {_at(st.settle, 's')}",
              (st.settle, "s"), f"{here}: a damped oscillator's envelope (not a registry equation)"),
        equation_step("Smallest CAP-ST whose shortest start period (largest current) outlasts the decay, at the "
                      "capacitor's low end", "an94002-eq1",
                      {"t_{start}": (st.settle, "s"), "I_{ST}": (s["i_st_max"], "A"),
                       "V_{high}": (s["v_st_high"], "V"), "V_{low}": (s["v_st_low"], "V")},
                      (st.bound * (1 - tol), "F"), solve_for="C_{ST}"),
        words(f"With the capacitor {tol * 100:g} % low the nominal must be {_at(st.bound, 'F')}; {s['series']} value at or "
              f"above it: {_at(st.cap_st, 'F')}", (st.cap_st, "F"), f"{here}: {s['series']} series pick"),
        equation_step("Shortest start period of the chosen CAP-ST (capacitor low, largest current)", "an94002-eq1",
                      {"C_{ST}": (st.cap_st * (1 - tol), "F"), "I_{ST}": (s["i_st_max"], "A"),
                       "V_{high}": (s["v_st_high"], "V"), "V_{low}": (s["v_st_low"], "V")},
                      (st.period_min, "s")),
    ]


def _watchdog(r, s) -> list:
    from ..design.commutation.timers import V_TI

    wd, tol = r.watchdog, s["tolerance"]
    here = "handbook.design.commutation (timers)"
    levels = {"V_{high}": (V_TI[1], "V"), "V_{low}": (V_TI[0], "V")}
    reverse = "" if wd.t_reverse is None else (f" and whose longest catches reverse rotation at "
                                              f"{s['rpm_reverse']:g} rpm ({_at(wd.t_reverse, 's')} for 150° el.)")
    return [
        words(f"{s['series']} CAP-TI whose shortest watchdog time outlasts the {_at(s['flyback_time'], 's')} flyback"
              f"{reverse}, at least 2000 pF: {_at(wd.cap_ti, 'F')} ({wd.binding})", (wd.cap_ti, "F"),
              f"{here}: {s['series']} series pick; AN94002 2.1.3 (CAP-TI at least 2000 pF)"),
        equation_step("Shortest watchdog time (capacitor low, largest current)", "an94002-eq9",
                      {"C_{TI}": (wd.cap_ti * (1 - tol), "F"), "I_{wd}": (s["i_wd_max"], "A"), **levels},
                      (wd.t_wd_min, "s"), solve_for="t_{wd}"),
        equation_step("Longest watchdog time (capacitor high, smallest current)", "an94002-eq9",
                      {"C_{TI}": (wd.cap_ti * (1 + tol), "F"), "I_{wd}": (s["i_wd_min"], "A"), **levels},
                      (wd.t_wd_max, "s"), solve_for="t_{wd}"),
    ]


# ----------------------------------------------------------------------------------------------
# current limiter (AN94002 2.4)

def limiter(r) -> list:
    """The op-amp current limiter: the search's network, its trip voltage by eq 13, the trip current, its
    corners, R7's loss and rating and R14.

    Parameters
    ----------
    r : LimiterResult
        The designed limiter.

    Returns
    -------
    list of Step
        The steps, the search first.
    """
    s = r.spec
    here = "handbook.design.limiter"
    net = ", ".join(f"R{k} = {_at(getattr(r, f'r{k}'), 'Ω')}" for k in (9, 10, 11, 12, 13))
    out = [
        words(f"Exact search over {s['r7_series']} R7 and the divider networks: the smallest R7 with every corner "
              f"inside {_at(s['i_no_trip'], 'A')} .. {_at(s['i_must_trip'], 'A')} is {_at(r.r7, 'Ω')}; {net}",
              (r.r7, "Ω"), f"{here}: exact search by closed-form bounds (search.solve)")
        if r.box_scale is None else
        words(f"criterion = yield: the exact search run on the corners of every tolerance times {r.box_scale:.3g}, "
              f"shrunk until a Monte Carlo lot meets yield_min = {s['yield_min']:.6g}: R7 = {_at(r.r7, 'Ω')}; {net} "
              "(at the full corners this network does not stay inside the window: the next step's margins)",
              (r.r7, "Ω"), f"{here}: yield search (by_yield), corners of a shrunk box"),
        equation_step("Nominal sense voltage at the trip point (zener at its nominal voltage)", "an94002-eq13",
                      {"V_{D1}": (s["zener_voltage"], "V"), "R_9": (r.r9, "Ω"), "R_{10}": (r.r10, "Ω"),
                       "R_{11}": (r.r11, "Ω"), "R_{12}": (r.r12, "Ω"), "R_{13}": (r.r13, "Ω")},
                      (r.v_cs_nominal, "V")),
        words(f"Nominal trip current by Ohm's law at R7: {_at(r.v_cs_nominal, 'V')} / {_at(r.r7, 'Ω')} = "
              f"{_at(r.i_trip_nominal, 'A')}", (r.i_trip_nominal, "A"), f"{here}: I = V_cs / R7"),
        words(f"Trip current at every corner (resistors ±{_pct(s['resistor_tolerance'])}, R7 ±{_pct(s['r7_tolerance'])}, "
              f"zener tolerance and drift, op-amp offset and bias currents): {_at(r.i_trip_min, 'A')} .. "
              f"{_at(r.i_trip_max, 'A')}, margins {_pct(r.margin_low)} and {_pct(r.margin_high)}",
              (f"{_at(r.i_trip_min, 'A')} .. {_at(r.i_trip_max, 'A')}", ""),
              f"{here}: every tolerance corner, exactly (model.verify)"),
        words(f"Loss in R7 at the highest trip current, R7 at its low end: ({_at(r.i_trip_max, 'A')})² · "
              f"{_at(r.r7 * (1 - s['r7_tolerance']), 'Ω')} = {_at(r.p_r7, 'W')}", (r.p_r7, "W"),
              f"{here}: P = I² R"),
        words(f"R7's rating: the stall loss at 50 % of the rating at the highest ambient: {_at(r.r7_rating, 'W')} "
              f"({r.r7_package})", (r.r7_rating, "W"), "handbook.design.ratings: derating rule"),
    ]
    if r.r14 is not None:
        out.append(words(f"{s['r14_series']} R14 at or below the largest that feeds D1 its test current and the "
                         f"dividers at the lowest supply: {_at(r.r14, 'Ω')}", (r.r14, "Ω"),
                         f"{here}: {s['r14_series']} series pick (zener_feed)"))
    return out


# ----------------------------------------------------------------------------------------------
# class D (LM4651/LM4652)

def class_d(r) -> list:
    """The LM4651/LM4652 amplifier: R_DLY, the search's R_OSC, L and C_BYP, eq 5's frequency, the output
    filter (corner, Q, residue), THD+N, clipping and the coils' peak at their worst corners, the LM4652's
    dissipation by eq 9, 10 and conduction, and eq 11's heat sink.

    Parameters
    ----------
    r : ClassDResult
        The designed amplifier.

    Returns
    -------
    list of Step
        The steps, R_DLY first.
    """
    from ..sources.lm4651.circuit import C_DEAD, T_DEAD_0

    s = r.spec
    here = _CLASS_D
    r_eff = r.r_osc - 0.4 * r.r_dly
    return [
        words(f"{s['r_dly_series']} R_DLY at or above ({_at(s['dead_time_min'], 's')} − {_at(T_DEAD_0, 's')}) / "
              f"({_at(C_DEAD * 1e3, 's')}/kΩ × (1 − {_pct(s['r_tolerance'])})), the LM4651 table's dead time at "
              f"R_DLY = 0 plus eq 4's slope, met at R_DLY's low tolerance end: {_at(r.r_dly, 'Ω')}",
              (r.r_dly, "Ω"), f"{here}: {s['r_dly_series']} series pick; LM4651/LM4652 "
              "table and eq (4)", errata=("lm4651-dead-time",)),
        words(f"IPOPT, then a proven series search over {s['r_osc_series']} R_OSC, {s['l_series']} L and "
              f"{s['c_series']} C_BYP at the worst of the tolerance corners: R_OSC = {_at(r.r_osc, 'Ω')}, "
              f"L = {_at(r.l_out, 'H')}, C_BYP = {_at(r.c_out, 'F')}", (r.r_osc, "Ω"),
              f"{here}: continuous optimum snapped to the series (search)"),
        equation_step(f"Switching frequency, R_OSC less 0.4 R_DLY ({_at(r.r_osc, 'Ω')} − 0.4 · "
                      f"{_at(r.r_dly, 'Ω')})", "lm4651-eq5",
                      {r"\{R_{OSC}\}_{\Omega}": (r_eff, "1")}, (r.f_sw, "Hz"), errata=("lm4651-f-15k", "lm4651-rosc")),
        words(f"Oscillator corners (−{_pct(s['osc_tol_slow'])}, +{_pct(s['osc_tol_fast'])}, eq 5 against the "
              f"datasheet's table, with R_OSC and R_DLY each ±{_pct(s['r_tolerance'])}): "
              f"{_at(r.f_sw_min, 'Hz')} .. {_at(r.f_sw_max, 'Hz')}",
              (f"{_at(r.f_sw_min, 'Hz')} .. {_at(r.f_sw_max, 'Hz')}", ""), f"{here}: oscillator tolerance"),
        equation_step("Output filter's corner", "lm4651-filter",
                      {"L_1": (r.l_out, "H"), "C_{BYP}": (r.c_out, "F")}, (r.f_corner, "Hz")),
        *_class_d_filter(r, s),
        *_class_d_heat(r, s),
    ]


def _corner_text(s: dict, corner: tuple) -> str:
    f, l_c, c_c = corner
    return f"f_SW {_at(f, 'Hz')}, L {_at(l_c, 'H')}, C_BYP {_at(c_c, 'F')}"


def _class_d_filter(r, s) -> list:
    """Q, the residue, THD+N, clipping and the coils' peak, each at the corner where it is worst (the rails at their
    high end, clipping at their low end)."""
    from ..design.class_d import model
    from ..sources.lm4651 import circuit as lm

    fig, rl, (v_low, vs) = r.figures, s["r_load"], model.rails(s)
    worst = model.worst_corners(s, r.r_osc, r.l_out, r.c_out, r.r_dly)
    (fq, lq, cq), (fr, lr, cr), (ft, lt, ct), (fi, li, ci) = (worst[k] for k in ("filter Q", "ripple", "THD+N",
                                                                                  "inductor peak"))
    p_t = s["thd_test_power"]
    dist = lm.thd_n_joint(ft, lt, ct, p_t, rl, vs)
    resid = lm.residue_fraction(ft, lt, ct, p_t, rl, vs)
    counted = ft < s["thd_bandwidth"]
    v_pk = lm.v_clip_peak(fi, rl, vs)
    rss = (f"√(({_pct(dist)})² + ({_pct(resid)})²)" if counted else
           f"the distortion alone (the residue, {_pct(resid)}, at {_at(ft, 'Hz')} lies above the "
           f"{_at(s['thd_bandwidth'], 'Hz')} band)")
    load = {"R_L": (rl, "Ω"), "V_s": (vs, "V")}
    rail = _rail(s, "high")
    return [
        equation_step(f"Filter Q at its worst corner ({_corner_text(s, worst['filter Q'])})", "lm4651-filter-q",
                      {"R_L": (rl, "Ω"), "L_1": (lq, "H"), "C_{BYP}": (cq, "F")}, (fig["q"], "1")),
        equation_step(f"Switching residue at its worst corner ({_corner_text(s, worst['ripple'])}){rail}", "lm4651-ripple",
                      {**load, "f_{SW}": (fr, "Hz"), "L_1": (lr, "H"), "C_{BYP}": (cr, "F")}, (fig["ripple"], "V")),
        equation_step(f"THD+N's distortion at {_at(p_t, 'W')}, at the worst corner ({_corner_text(s, worst['THD+N'])}){rail}",
                      "lm4651-thd", {r"\{f_{SW}\}_{\mathrm{Hz}}": (ft, "1"), r"\{L_1\}_{\mathrm{H}}": (lt, "1"),
                                     r"\{C_{BYP}\}_{\mathrm{F}}": (ct, "1"), r"\{V_s\}_{\mathrm{V}}": (vs, "1"),
                                     r"\{P_{out}\}_{\mathrm{W}}": (p_t, "1"), r"\{R_L\}_{\Omega}": (rl, "1")},
                      (dist, "%")),
        words(f"THD+N as the analyser reads it: the residue there over the test signal's rms, "
              f"{_at(lm.ripple_rms(ft, lt, ct, rl, vs), 'V')} / √({_at(p_t, 'W')} · {_at(rl, 'Ω')}) = {_pct(resid)}; "
              f"THD+N = {rss} = {_pct(fig['thd_n'])}", (f"{_pct(fig['thd_n'])}", ""),
              f"{_CLASS_D}: thd_n_measured (residue root-sum-square inside the analyser's band)"),
        equation_step(f"Clipping power at the fast corner ({_at(r.f_sw_max, 'Hz')}){_rail(s, 'low')}", "lm4651-p-clip",
                      {r"\{V_s\}_{\mathrm{V}}": (v_low, "1"), r"\{f_{SW}\}_{\mathrm{Hz}}": (r.f_sw_max, "1"),
                       r"\{R_L\}_{\Omega}": (rl, "1")}, (r.p_clip, "W")),
        words(f"Lowest rail that still delivers {_at(model.p_unclipped(s), 'W')} unclipped at the fast corner (the "
              f"clipping power goes as V_s²): {_at(s['supply'], 'V')} × √({_at(model.p_unclipped(s), 'W')} / "
              f"{_at(lm.p_clip(r.f_sw_max, rl, s['supply']), 'W')}) = ±{_at(r.supply_least, 'V')}",
              (r.supply_least, "V"), f"{_CLASS_D}: model.supply_least"),
        equation_step(f"Coils' peak current at the worst corner ({_corner_text(s, worst['inductor peak'])}; V_pk at "
                      f"clipping there, √(2 R_L P_clip) = {_at(v_pk, 'V')}){rail}", "lm4651-inductor-peak",
                      {"V_{pk}": (v_pk, "V"), **load, "f_a": (s["f_audio"], "Hz"), "C_{BYP}": (ci, "F"),
                       "L_1": (li, "H"), "f_{SW}": (fi, "Hz")}, (fig["i_peak"], "A"), errata=("lm4651-isckt",)),
    ]



def _rail(s: dict, end: str) -> str:
    """Where the rails are taken, when they have a tolerance: ", at the high rail (+-21 V)"."""
    from ..design.class_d import model

    if not s["supply_tolerance"]:
        return ""
    return f", at the {end} rail (±{_at(model.rails(s)[end == 'high'], 'V')})"


def _class_d_heat(r, s) -> list:
    """The LM4652's dissipation at the corner that sets the heat sink (eq 9, 10, conduction, idle), eq 11."""
    from ..design.class_d import model
    from ..sources.lm4651 import circuit as lm
    from ..sources.lm4651.circuit import DEVICE

    here = _CLASS_D
    t_target = DEVICE["tj_max"] - s["tj_margin"]
    theta_jc = DEVICE["theta_jc"][s["package"]]
    f_set, p_set = model.heat_corner(s, r.f_sw_min, r.f_sw_max)  # the corner and dissipation eq 11 is taken at
    terms = {k: float(v) for k, v in model.loss_terms(s, f_set, t_target).items()}
    p_th, x, rds = terms["p_out"], terms["fraction"], terms["rds_on"]
    p_sw, p_cond, p_idle = terms["switching"], terms["conduction"], terms["idle"]
    v_high = model.rails(s)[1]
    fitted = ("the one needed: at the corner that sets it T_j is the target by construction, the other corner runs "
              "cooler" if s["theta_sa_available"] is None else f"θ_SA = {s['theta_sa_available']:g} K/W available")
    return [
        equation_step(f"Switching loss fraction at the corner that sets the heat sink ({_at(f_set, 'Hz')})",
                      "lm4651-eq9", {"t_r": (DEVICE["t_rise"], "s"), "t_f": (DEVICE["t_fall"], "s"),
                                     "T_{OVERMOD}": (s["t_overmod"], "s"), "f": (f_set, "Hz")}, (x, "%"),
                      errata=("lm4651-overmod",)),
        equation_step(f"Switching dissipation at {r.thermal_basis} ({_at(p_th, 'W')}){_rail(s, 'high')}",
                      "lm4651-eq10",
                      {"x": (x, "1"), "P_{out}": (p_th, "W")}, (p_sw, "W")),
        equation_step(f"Conduction dissipation, R_DS(on) at its maximum at T_j = {t_target:g} °C: "
                      f"{_at(s['rds_on_25'], 'Ω')} × (1 + {lm.RDS_TC * 100:.2g} %/K × ({t_target:g} − 25) K) = "
                      f"{_at(rds, 'Ω')} (the rise: the Example Design's 230 mΩ at 100 °C against the table's 200 mΩ "
                      "at 25 °C)", "lm4651-conduction",
                      {"P_{out}": (p_th, "W"), "R_L": (s["r_load"], "Ω"), "R_{DS(on)}": (rds, "Ω")}, (p_cond, "W"),
                      errata=("lm4651-t-rds",)),
        words(f"LM4652 dissipation: switching {_at(p_sw, 'W')} + conduction {_at(p_cond, 'W')} + idle "
              f"{_at(p_idle, 'W')} = {_at(p_set, 'W')}; the idle loss is what the system table's 55 % at 5 W leaves "
              f"after conduction and switching, {_at(lm.P_IDLE_REF, 'W')} at ±20 V (× {v_high:.4g} V / 20 V: "
              f"{_at(lm.p_idle(v_high), 'W')}), less the LM4651's own 36 mA (|I_VCC+| + |I_VEE−|) × "
              f"{v_high:.4g} V = {_at(lm.I_Q_4651 * v_high, 'W')}",
              (p_set, "W"), f"{here}: thermal model (model.heat)"),
        equation_step(f"Heat sink needed to hold T_j at {t_target:g} °C", "lm4651-eq11",
                      {"T_{jmax}": (t_target, "°C"), "T_{a}": (s["t_ambient"], "°C"), "P_D": (p_set, "W"),
                       r"\theta_{JC}": (theta_jc, "K/W"), r"\theta_{CS}": (s["theta_cs"], "K/W")},
                      (r.theta_sa_required, "K/W")),
        words(f"With the heat sink fitted ({fitted}) the hotter corner runs at T_j = {r.t_junction:.4g} °C and "
              f"dissipates {_at(r.p_dissipation, 'W')}", (r.p_dissipation, "W"), f"{here}: thermal model (model.thermal)"),
    ]


# ----------------------------------------------------------------------------------------------
# converter (TCA5600)

def _figures(c: dict) -> str:
    """V12(H), V_CE(sat) and V_F of one of the converter's corners, as the sheet writes them."""
    return f"V12(H) {_at(c['v12h'], 'V')}, V_CE(sat) {_at(c['v_ce_sat'], 'V')}, V_F {_at(c['v_f'], 'V')}"


def converter(r) -> list:
    """The TCA5600 dc/dc converter: eq 1 to 6a at the lowest supply, R1 from its series, the coil.

    Parameters
    ----------
    r : ConverterResult
        The designed converter.

    Returns
    -------
    list of Step
        The steps, eq 1 first.
    """
    from ..design.converter import corner, r1_drift, r1_ends
    from ..design.converter.coil import coil_voltages

    s = r.spec
    here = "handbook.design.converter"
    weak, slow = corner(s, "weak"), corner(s, "slow")
    w_plus, w_minus = coil_voltages(weak, s["v_supply_min"])
    w_peak = weak["v12h"] / r.r1_worst
    s_plus, s_minus = coil_voltages(slow, s["v_supply_min"])
    drift, r_hi = r1_drift(s), r1_ends(s)[1]
    v = {"V_{out2}": (s["v_out"], "V"), "V_{(9-8)}": (s["v_regulator_drop"], "V"), "V_F": (s["v_f"], "V"),
         "V_{CC2}": (s["v_supply_min"], "V"), "V_{CE(sat)}": (s["v_ce_sat"], "V"), "V_{12(H)}": (s["v12h"], "V")}
    pick = lambda *names: {k: v[k] for k in names}  # noqa: E731
    out = [
        equation_step("Coil voltage while dumping, at the lowest supply", "tca5600-eq1",
                      pick("V_F", "V_{(9-8)}", "V_{CC2}", "V_{out2}"), (r.vl_plus, "V")),
        equation_step("Coil voltage while charging, at the lowest supply", "tca5600-eq2",
                      pick("V_{12(H)}", "V_{CC2}", "V_{CE(sat)}"), (r.vl_minus, "V")),
        equation_step("Charge to dump time ratio", "tca5600-eq3",
                      {"V_{L+}": (r.vl_plus, "V"), "V_{L-}": (r.vl_minus, "V")}, (r.alpha, "1")),
        equation_step("Charging time at the lowest frequency", "tca5600-eq4",
                      {r"\alpha": (r.alpha, "1"), "f": (r.f_min_design, "Hz")}, (r.t1, "s")),
        equation_step("Peak coil current", "tca5600-eq5",
                      {"I_{out2}": (s["i_out"], "A"), r"\alpha": (r.alpha, "1")}, (r.i_peak, "A")),
        equation_step("Coil inductance", "tca5600-eq6",
                      {"V_{L-}": (r.vl_minus, "V"), "t_1": (r.t1, "s"), "I_{L(peak)}": (r.i_peak, "A")}, (r.l1, "H")),
        equation_step("Current-sense resistor", "tca5600-eq6a",
                      {"V_{12(H)}": (s["v12h"], "V"), "I_{L(peak)}": (r.i_peak, "A")}, (r.r1, "Ω")),
        words(f"Eq 1 to 6a again in the device corner that delivers least ({_figures(weak)}, "
              f"±{_pct(s['device_spread'])}): V_L+ = {_at(w_plus, 'V')}, V_L− = {_at(w_minus, 'V')}, "
              f"I_L(peak) = 2 · {_at(s['i_out'], 'A')} · (1 + {w_plus:.4g} / {w_minus:.4g}) = {_at(w_peak, 'A')}, "
              f"R1 = {_at(weak['v12h'], 'V')} / {_at(w_peak, 'A')} = {_at(r.r1_worst, 'Ω')}", (r.r1_worst, "Ω"),
              f"{here}: device_spread (assumed; no public TCA5600 characteristics)"),
        words(f"{s['r1_series']} R1 at or below {_at(r.r1_worst, 'Ω')} over R1's high end, (1 + {s['r1_tolerance']:g}) "
              f"for its tolerance × (1 + {drift:.3g}) for its drift to {s['t_ambient']:g} °C at "
              f"{s['r1_tempco'] * 1e6:g} ppm/K: {_at(r.r1_worst / r_hi, 'Ω')}, so {_at(r.r1_part, 'Ω')}; at that high end "
              f"in that corner it delivers {_at(r.i_out_least, 'A')}; the peak current reaches {_at(r.i_peak_max, 'A')} "
              "with V12(H) high and R1 at its low end", (r.r1_part, "Ω"), f"{here}: {s['r1_series']} series pick"),
        words(f"Inductance to wind: in the slow corner ({_figures(slow)}) at the lowest supply, L1 at +"
              f"{_pct(s['a_l_tolerance'])} A_L runs at f_min with the highest peak current when L1,max = 1 / (f_min · "
              f"I_pk,max · (1/V_L− + 1/V_L+)) = 1 / ({_at(r.f_min_design, 'Hz')} · {_at(r.i_peak_max, 'A')} · (1/"
              f"{_at(s_minus, 'V')} + 1/{_at(s_plus, 'V')})) = {_at(r.l1_max, 'H')}; wound for it / (1 + "
              f"{s['a_l_tolerance']:g}) = {_at(r.l1_nominal, 'H')}", (r.l1_nominal, "H"),
              f"{here}: A_L tolerance, device_spread"),
        words(f"Smallest core of the candidate set meeting every limit: {r.core_shape} in {r.core_material}, "
              f"{r.turns} turns, {r.wire}", (f"{r.core_shape}, {r.turns} turns", ""),
              f"{here}: exact enumeration of PyOpenMagnetics' cores, smallest first"),
    ]
    return out + _coil(r, s)


def _core_loss_step(r, s, shape: dict, material: dict, here: str):
    """The iGSE core loss with its numbers, at the point of the largest loss (supply and hot corner)."""
    from ..design.converter import coil as cl

    pt = r.coil.core_loss_at
    if pt is None:  # no supply point where the converter switches at full load
        return words("Core loss: the converter does not switch at full load anywhere in the supply range",
                     (r.core_loss, "W"), f"{here}: iGSE (coil.core_loss)")
    rng, inside = cl.steinmetz_range(material, pt["f"])
    k_i, a, b, c_t = cl.igse_coefficients(material, pt["f"])
    density = pt["loss"] / shape["ve"]
    return words(f"Core loss by the improved generalised Steinmetz equation (Venkatachalam et al., 2002): P = V_e k_i "
                 f"ΔB^β f^α (D^(1−α) + (1−D)^(1−α)) c_t, {r.core_material}'s range {_at(rng['f_low'], 'Hz')} .. "
                 f"{_at(rng['f_high'], 'Hz')}{'' if inside else ' (extrapolated)'}: k = {rng['k']:.4g}, α = {a:.4g}, "
                 f"β = {b:.4g}, so k_i = k / ((2π)^(α−1) 2^(β−α) ∫₀^2π |cos θ|^α dθ) = {k_i:.4g}, c_t = {c_t:.4g} at "
                 f"{cl.T_LOSS:g} °C; the largest at V_CC2 = {_at(pt['vcc'], 'V')} with V12(H) high: "
                 f"ΔB = L1,max I_pk,max / (N A_e) = {_at(pt['delta_b'], 'T')} over the effective area "
                 f"{_at(shape['ae'], 'm²')}, f = {_at(pt['f'], 'Hz')}, D = {pt['duty']:.3f}: {density / 1e3:.4g} kW/m³ "
                 f"× V_e {shape['ve'] * 1e9:.4g} mm³ = {_at(pt['loss'], 'W')}", (r.core_loss, "W"),
                 f"{here}: iGSE (coil.core_loss), PyOpenMagnetics' Steinmetz ranges")


def _coil(r, s) -> list:
    """The chosen core wound: turns, gap, flux density, winding loss, core loss and temperature rise."""
    from ..design.converter import coil as cl
    from ..design.converter import cores

    table = cores.load()
    shape, material = table["shapes"][r.core_shape], table["materials"][r.core_material]
    here = "handbook.design.converter (coil)"
    c = r.coil
    r_core = cl.core_reluctance(shape, material)
    t_coil = s["t_ambient"] + r.temperature_rise
    b_sat = cl.b_sat(material, t_coil)
    n_gap, n_sat = cl.turn_bounds(shape, material, s, {"l1_nominal": r.l1_nominal, "l1_max": r.l1_max,
                                                        "i_peak_max": r.i_peak_max}, t_coil)
    r_gap = r.turns ** 2 / r.l1_nominal - r_core
    per_m = c.r_dc / (r.turns * shape["mlt"])
    flux = {"L_1": (r.l1_max, "H"), "I_{L(peak)}": (r.i_peak_max, "A"), "N": (r.turns, "1")}
    return [
        words(f"Turns: at least √(L1 (ℛ_core + ℛ_gap at {_at(cl.GAP_MIN, 'm')})) = {n_gap:.2f} for a gap the model "
              f"holds, and L1,max I_pk,max / ((1 − {_pct(s['saturation_margin_min'])}) B_sat A_min) = {n_sat:.2f} to keep "
              f"the saturation margin at the coil's own {t_coil:.3g} °C (B_sat {_at(b_sat, 'T')}): N = {r.turns}",
              (f"{r.turns} turns", ""), f"{here}: the fewest turns meeting both (coil.coil)"),
        equation_step(f"Reluctance the gaps must add for L1 = {_at(r.l1_nominal, 'H')} with {r.turns} turns",
                      "tca5600-gap", {"N": (r.turns, "1"), "L_1": (r.l1_nominal, "H"),
                                      r"\mathcal{R}_{core}": (r_core, "1/H")}, (r_gap, "1/H")),
        words(f"PyOpenMagnetics' gap model (all of the core's gaps against the centre gap's length) inverted: centre "
              f"gap {_at(r.gap, 'm')}; A_L = L1 / N² = {_at(r.a_l, 'H')}", (r.gap, "m"),
              f"{here}: PyOpenMagnetics gap reluctance table, log-log interpolation"),
        equation_step("Peak flux density over the centre column (A its area), at the highest peak current and L1 at "
                      "its high end", "tca5600-b-peak", {**flux, "A": (shape["a_centre"], "m²")}, (r.b_peak, "T")),
        equation_step("The same over the core's narrowest section (A its area), where saturation is judged",
                      "tca5600-b-peak", {**flux, "A": (shape["a_min"], "m²")}, (r.b_peak_min_area, "T")),
        words(f"Saturation margin at {t_coil:.3g} °C: 1 − {_at(r.b_peak_min_area, 'T')} / {_at(b_sat, 'T')} = "
              f"{_pct(r.saturation_margin)} (at least {_pct(s['saturation_margin_min'])})", (r.saturation_margin, "%"),
              f"{here}: {r.core_material}'s saturation against temperature, PyOpenMagnetics"),
        equation_step(f"Winding loss: {r.wire} ({_at(c.wire_diameter, 'm')} copper, the thickest that fits the "
                      f"bobbin; {c.current_density / 1e6:.3g} A/mm²), copper at its hottest", "tca5600-winding",
                      {"I_{rms}": (r.i_rms, "A"), "N": (r.turns, "1"), r"\ell_{MLT}": (shape["mlt"], "m"),
                       "r'": (per_m, "Ω/m")}, (r.winding_loss, "W")),
        _core_loss_step(r, s, shape, material, here),
        equation_step("Temperature rise of the coil", "tca5600-rise",
                      {"R_{th}": (shape["r_th"], "K/W"), "P_{Cu}": (r.winding_loss, "W"),
                       "P_{core}": (r.core_loss, "W")}, (r.temperature_rise, "K")),
    ]


#: spec table -> its sheet
BUILDERS = {"commutation": commutation, "current_limiter": limiter, "class_d": class_d, "converter": converter}
