"""LM4651/LM4652 joint design: what binds, what a spec nothing meets can still reach, the warnings a
valid but implausible design carries, and the datasheet's own typical application judged by the same
checks."""
from __future__ import annotations

import numpy as np

from ...sources.lm4651 import circuit as lm4651
from .. import ratings
from ..solvers import Infeasible
from . import model

TABLE = "class_d"
DEV = lm4651.DEVICE
#: heat sinks for a TO-220 run from about 30 K/W (small clip-on) down to about 0.5 K/W (a large extrusion
#: in free air; lower needs a fan): outside that range the design warns (a market survey, not the datasheet)
THETA_SA_MADE = (0.5, 30.0)
#: a rail above this share of the absolute maximum is warned of (a judgement: 5 % for ripple and spikes)
RAIL_WARN = 0.95
#: the datasheet's typical application (figure 1 and its text): R_OSC 3.9 k (Example Design, from eq 6),
#: R_DLY 5 k (recommended), L 50 uH and C_BYP 5 uF (Output Stage Filtering)
DATASHEET_PARTS = {"r_osc": 3.9e3, "l_out": 50e-6, "c_out": 5e-6, "r_dly": 5e3}


def datasheet_application(s: dict) -> dict:
    """The datasheet's own R_OSC, L, C_BYP and R_DLY through every check of the design, at every corner.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).

    Returns
    -------
    dict
        The figures of :data:`DATASHEET_PARTS` as :func:`~handbook.design.class_d.model.one` gives them (SI
        units; ``margins`` {check: fraction}, ``ok`` bool).
    """
    p = DATASHEET_PARTS
    return model.one(s, p["r_osc"], p["l_out"], p["c_out"], p["r_dly"])


def binding_text(sol, fig: dict) -> str:
    """The constraints IPOPT's multipliers name at the continuous optimum, then the tightest margins of the
    series design.

    Parameters
    ----------
    sol : Solution
        IPOPT's continuous optimum (:func:`~handbook.design.class_d.result.solve`).
    fig : dict
        The series design's figures (:func:`~handbook.design.class_d.model.at`); its ``margins`` {check:
        fraction} are read.

    Returns
    -------
    str
        The binding constraints' names, each once ("none" when no multiplier is above 1e-7), then the two
        smallest margins of the series design as percentages.
    """
    names = [n for n in sol.binding(1e-7) if n != "heat sink objective"]
    names = list(dict.fromkeys(names))
    tight = sorted(fig["margins"].items(), key=lambda kv: kv[1])[:2]
    text = ", ".join(names) if names else "none"
    return f"{text} (series design's tightest margins: " + ", ".join(f"{k} {v:.1%}" for k, v in tight) + ")"


#: the LM4651/LM4652's operating ambient, C ("Temperature Range -40 C <= T_A <= +85 C", operating ratings)
T_A_RATED = (-40.0, 85.0)

#: a residue this close above the analyser's band edge (f_sw below 1.5 x the bandwidth) is partly measured by a
#: real band-limiting filter, which the THD+N model takes as a brick wall: said as a warning
BRICK_WALL_GUARD = 1.5

def warnings(s: dict, fig: dict, l_out: float, c_out: float) -> list[str]:
    """What a valid design does that is implausible: each warning says its threshold and why.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    fig : dict
        The design's figures as plain floats (:func:`~handbook.design.class_d.model.at`): ``theta_sa_required``
        (K/W), ``f_sw_min`` (Hz), ``i_peak`` (A) and ``p_dissipation`` (W) are read.
    l_out : float
        The filter inductors' L, H.
    c_out : float
        C_BYP, F.

    Returns
    -------
    list of str
        The warnings, possibly none: a heat sink given or needed outside what is made (:data:`THETA_SA_MADE`) or
        none needed at all, a ``p_continuous`` above what the amplifier delivers or below ``p_out``, a load
        outside the models' 4 to 8 ohm, C_BYP above 50 uF, L above ten times the datasheet's 50 uH, an ambient
        outside the parts' operating range (:data:`T_A_RATED`), a slowest oscillator corner just above the THD+N
        analyser's band (:data:`BRICK_WALL_GUARD`); the high rail above :data:`RAIL_WARN` of the absolute
        maximum, the coils' peak above the LM4652's 8 A minimum saturation current, its dissipation above 32 W.
    """
    out = []
    need, path = fig["theta_sa_required"], DEV["theta_jc"][s["package"]] + s["theta_cs"]
    free_air = lm4651.THETA_JA[s["package"]]
    given = s["theta_sa_available"]
    if given is not None and given < THETA_SA_MADE[0]:
        out.append(f"theta_sa_available = {given:g} K/W: no TO-220 heat sink made is that good (below about "
                   f"{THETA_SA_MADE[0]:g} K/W needs a very large extrusion or forced air); check the value")
    elif given is not None and given > THETA_SA_MADE[1]:
        out.append(f"theta_sa_available = {given:g} K/W: above about {THETA_SA_MADE[1]:g} K/W, worse than the "
                   "smallest clip-on TO-220 heat sinks made; check the value")
    if need + path >= free_air:
        out.append(f"no heat sink needed: {need:.1f} K/W of sink would do, and the bare {s['package']} package "
                   f"already reaches {free_air:g} K/W junction to ambient (datasheet thermal table)")
    elif need > THETA_SA_MADE[1]:
        out.append(f"heat sink of {need:.1f} K/W needed: above about {THETA_SA_MADE[1]:g} K/W, the smallest "
                   "clip-on TO-220 heat sinks made; any heat sink will do")
    elif need < THETA_SA_MADE[0]:
        out.append(f"heat sink of {need:.2f} K/W needed: below about {THETA_SA_MADE[0]:g} K/W a TO-220 needs a "
                   "very large extrusion or forced air")
    p_max = lm4651.p_clip(fig["f_sw_min"], s["r_load"], model.rails(s)[1])
    if s["p_continuous"] is not None and s["p_continuous"] > p_max:
        out.append(f"p_continuous = {s['p_continuous']:g} W is more than the amplifier can deliver "
                   f"({p_max:.0f} W at the slowest oscillator corner and the high rail): the heat sink is larger than needed")
    if s["p_continuous"] is not None and s["p_continuous"] < s["p_out"]:
        out.append(f"p_continuous = {s['p_continuous']:g} W is below p_out = {s['p_out']:g} W: the heat sink "
                   "cannot carry the rated output continuously")
    bw, f_slow = s["thd_bandwidth"], fig["f_sw_min"]
    if bw <= f_slow < BRICK_WALL_GUARD * bw:
        # the residue at that corner with L and C at their low ends (the filter well above its corner: the largest)
        share = lm4651.residue_fraction(f_slow, l_out * (1 - s["l_tolerance"]), c_out * (1 - s["c_tolerance"]),
                                        s["thd_test_power"], s["r_load"], model.rails(s)[1])
        out.append(f"the slowest oscillator corner, {f_slow / 1e3:.4g} kHz, lies just above the THD+N analyser's "
                   f"{bw / 1e3:g} kHz band ({(f_slow / bw - 1) * 100:.1f} % above it): the THD+N model counts the switching "
                   f"residue only inside the band (a brick-wall filter); a real analyser's band-limiting filter passes "
                   f"part of the residue, {share * 100:.2f} % of the test signal unattenuated at that corner (L and "
                   f"C_BYP at their low ends), against thd_max = {s['thd_max'] * 100:.2f} %")
    if not T_A_RATED[0] <= s["t_ambient"] <= T_A_RATED[1]:
        low, high = (f"{v:g}".replace("-", "\N{MINUS SIGN}") for v in T_A_RATED)
        out.append(f"t_ambient = {s['t_ambient']:g} °C: outside the LM4651/LM4652's operating range, {low} to "
                   f"{high} °C (datasheet operating ratings); the heat sink holds T_j, but the parts are not rated there")
    if not 4.0 <= s["r_load"] <= 8.0:
        out.append(f"r_load = {s['r_load']:g} ohm: the clipping and THD+N models are calibrated at 4 and 8 ohm only")
    if c_out > 50e-6:
        out.append(f"C_BYP = {c_out * 1e6:.3g} uF: the datasheet suggests 5 to 10 uF film; above 50 uF film "
                   "capacitors are bulky")
    if l_out > 10 * lm4651.L_REF:
        out.append(f"L = {l_out * 1e6:.3g} uH: ten times the datasheet's 50 uH; a choke carrying "
                   f"{fig['i_peak']:.1f} A at that inductance is large")
    return out + _ratings(s, fig)


def _ratings(s: dict, fig: dict) -> list[str]:
    """The LM4651/LM4652's absolute maximum ratings against this design's stresses, where they come close: the
    rails against +-22 V, the coils' worst peak against the LM4652's 8 A minimum saturation drain current, the
    dissipation against its 32 W."""
    out, high = [], model.rails(s)[1]
    if high > RAIL_WARN * lm4651.SUPPLY_ABS_MAX:
        out.append(f"the high rail, ±{high:.4g} V, is {high / lm4651.SUPPLY_ABS_MAX * 100:.1f} % of the LM4651/LM4652's "
                   f"absolute maximum ±{lm4651.SUPPLY_ABS_MAX:g} V (also the top of the operating range): the supply's "
                   "ripple, load dump and switching spikes add to it; measure the rails on the board")
    if fig["i_peak"] > lm4651.I_D_SAT_MIN:
        out.append(f"the coils' worst peak, {fig['i_peak']:.2f} A, is above the LM4652's minimum saturation drain "
                   f"current, {lm4651.I_D_SAT_MIN:g} A (10 A typical, at V_GS 6 V; LM4652 table): a part at that minimum "
                   "limits the peak and clips early (the datasheet's own 125 W, 50 µH example peaks near 8.7 A); the "
                   "peak is mostly the audio current at clipping, so only a lower supply or a higher-impedance load "
                   "lowers it much")
    if fig["p_dissipation"] > lm4651.P_D_MAX_4652:
        out.append(f"the LM4652 dissipates {fig['p_dissipation']:.1f} W, above its absolute maximum "
                   f"{lm4651.P_D_MAX_4652:g} W (absolute maximum ratings) even with the heat sink holding T_j: a "
                   "lower thermal basis or p_continuous, or a lower supply")
    return out


def _achievable(s: dict, fig: dict) -> dict:
    """For each failed check: its best margin among the candidates that meet every other check."""
    margins = fig["margins"]
    ok = {k: m >= -1e-12 for k, m in margins.items()}
    out = {}
    for k, m in margins.items():
        others = np.ones(m.shape, dtype=bool)
        for j, o in ok.items():
            if j != k:
                others &= o
        if not ok[k].any() and others.any():
            i = np.flatnonzero(others)[np.argmax(m[others])]
            out[k] = model.at(fig, i)
    return out


#: check -> (label, value in the figures, how it is shown, the spec key it is held to)
SHOW = {"THD+N": ("THD+N", "thd_n", "{:.3%}", "thd_max"), "clipping": ("clipping power", "p_clip", "{:.1f} W", "p_out"),
        "ripple": ("ripple", "ripple", "{:.3f} V", "ripple_max"),
        "audio band": ("band deviation", "band_deviation", "{:.2f} dB", "droop_max"),
        "filter Q": ("Q", "q", "{:.2f}", "q_max"), "inductor peak": ("peak current", "i_peak", "{:.2f} A", "i_sat"),
        "heat sink": ("theta_SA", "theta_sa_required", "{:.2f} K/W", "theta_sa_available")}


def _rail_reach(s: dict, ev: dict, achievable: dict) -> str:
    """What the rails must be for the best candidate's clipping power to reach p_out (the clipping power goes as
    V_s squared): its lowest rail, and the supply_tolerance this supply allows."""
    least = float(ev["supply_least"])
    achievable["supply_least"] = least
    low = model.rails(s)[0]
    text = f" at the low rail ±{low:.4g} V" if s["supply_tolerance"] else ""
    if least > lm4651.RAILS[1]:
        return text + f"; it needs rails of ±{least:.4g} V, above the LM4651/LM4652's ±{lm4651.RAILS[1]:g} V"
    text += f"; it needs rails of at least ±{least:.4g} V"
    if least <= s["supply"]:
        achievable["supply_tolerance_max"] = 1 - least / s["supply"]
        text += f" (supply_tolerance at most {1 - least / s['supply']:.3g} with supply = {s['supply']:g} V)"
    return text


def _heat_sink_reach(s: dict, ev: dict, achievable: dict) -> str:
    """What the heat sink asked for (an ideal one, 0 K/W, if none) can carry with the best candidate: the
    largest p_continuous at this ambient, the hottest ambient (when above the schema's -40 C), and whether
    p_continuous is more than the amplifier can deliver at all (its clipping power at 50 kHz, the slowest
    the datasheet allows the oscillator)."""
    path = DEV["theta_jc"][s["package"]] + s["theta_cs"]
    sink = s["theta_sa_available"] or 0.0
    t_target = DEV["tj_max"] - s["tj_margin"]
    watts = (t_target - s["t_ambient"]) / (ev["theta_sa_required"] + path)  # the best candidate's dissipation
    text = ""
    p_max = float(lm4651.p_clip(DEV["f_min"], s["r_load"], model.rails(s)[1]))
    if s["p_continuous"] is not None and s["p_continuous"] > p_max:
        achievable["p_deliverable"] = p_max
        text += (f"; p_continuous = {s['p_continuous']:g} W is more than the amplifier can deliver: about "
                 f"{p_max:.0f} W at most (clipping at {DEV['f_min'] / 1e3:.0f} kHz, the slowest oscillator)")
    # at T_j = t_target the LM4652's dissipation is linear in the power it carries, P = w0 + w1 p, at each
    # oscillator corner: the largest p the heat sink carries is the smaller of the two corners'
    allowed = (t_target - s["t_ambient"]) / (path + sink)
    p_cont = np.inf
    for f in (ev["f_sw_min"], ev["f_sw_max"]):
        sine = ({**s, "thermal_basis": "continuous_sine", "p_continuous": q} for q in (0, 1))
        w0, w1 = ((t_target - s["t_ambient"]) / (model.heat(at, f)[0] + path) for at in sine)
        p_cont = min(p_cont, (allowed - w0) / (w1 - w0))
    achievable["p_continuous_max"] = max(p_cont, 0.0)
    which = "an ideal heat sink" if s["theta_sa_available"] is None else "the heat sink"
    text += (f"; the LM4652 would dissipate {watts:.1f} W at T_j = {t_target:.0f} C, {which} carries "
             f"{allowed:.1f} W there: ")
    if s["thermal_basis"] == "iec_1_8":  # the power carried is an eighth of the clipping power
        text += (f"{max(p_cont, 0.0):.0f} W of output at most, an eighth of {8 * max(p_cont, 0.0):.0f} W "
                 "(thermal_basis = iec_1_8)")
    else:
        text += f"p_continuous at most {max(p_cont, 0.0):.0f} W"
    if "p_deliverable" in achievable and p_cont >= achievable["p_deliverable"]:
        text += f", more than the amplifier delivers: leave p_continuous out (or at most {p_max:.0f} W)"
    t_amb = t_target - watts * (path + sink)
    if t_amb >= -40.0:
        achievable["t_ambient_max"] = t_amb
        text += f", or an ambient of at most {t_amb:.0f} C"
    return text


def infeasible(s: dict, r_dly: float, searched=None):
    """Raise the Infeasible that says, for each check no series design meets, the best it reaches while every
    other check holds (the whole grid, exhaustively; ``searched`` = (R_OSC, L, C, figures) if evaluated).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_dly : float
        The design's R_DLY, ohm.
    searched : tuple or None
        (R_OSC in ohm, L in H, C_BYP in F, figures): flat candidate arrays and their
        :func:`~handbook.design.class_d.model.figures` (None where not yet evaluated), the set already searched;
        None: the whole series grid.

    Raises
    ------
    Infeasible
        Always: when no series R_OSC keeps the oscillator inside 50..225 kHz at both corners, else naming each
        check no candidate meets with the best it reaches while the others hold (``achievable``: those values
        in SI units, and for the heat sink the largest ``p_continuous`` (W) and hottest ``t_ambient`` (C) it
        carries), or, when each check can be met alone but not all together, the candidate closest to meeting
        all and by how much it misses each.
    """
    r, l_out, c_out, fig = searched if searched is not None else (*model.grid(s, r_dly), None)
    if not r.size:
        raise Infeasible(TABLE, "no series R_OSC keeps the oscillator inside 50..225 kHz at both tolerance "
                         f"corners (-{s['osc_tol_slow']:.0%} / +{s['osc_tol_fast']:.0%})",
                         {"f_sw_span": DEV["f_max"] / DEV["f_min"]})
    fig = fig if fig is not None else model.figures(s, r, l_out, c_out, r_dly)
    reach = _achievable(s, fig)
    parts, achievable = [], {}
    for k, ev in reach.items():
        label, key, fmt, spec_key = SHOW.get(k, (k, None, None, None))
        if key is None:
            parts.append(f"{k} fails")
            achievable[k] = ev["margins"][k]
            continue
        if k == "clipping" and s["thd_test_power"] > s["p_out"]:  # the test point must not clip either
            spec_key = "thd_test_power"
        asked = s[spec_key]
        shown = "an ideal heat sink, 0 K/W" if asked is None else f"{spec_key} = {fmt.format(asked)}"
        if k == "inductor peak":  # the coils' saturation over the book's margin, or the LM4651's own limit
            asked = model.i_peak_limit(s)
            shown = (f"the LM4651's current limit, {fmt.format(asked)} (i_sat = {fmt.format(s[spec_key])} over the "
                     f"saturation margin {ratings.SATURATION_MARGIN:g} is above it)" if asked == lm4651.I_LIMIT else
                     f"i_sat = {fmt.format(s[spec_key])} over the saturation margin {ratings.SATURATION_MARGIN:g}, "
                     f"{fmt.format(asked)}")
        parts.append(f"{label}: best {fmt.format(ev[key])} (asked {shown})")
        achievable[key] = ev[key]
        if k == "clipping":
            parts[-1] += _rail_reach(s, ev, achievable)
        if k == "heat sink":
            parts[-1] += _heat_sink_reach(s, ev, achievable)
    if not reach:  # each check can be met alone, but not together: the candidate closest to meeting all
        i = int(np.argmax(np.min(np.stack(list(fig["margins"].values())), axis=0)))
        ev = model.at(fig, i)
        fails = {k: v for k, v in ev["margins"].items() if v < 0}
        parts = [f"at best (R_OSC {r[i]:.4g} ohm, L {l_out[i] * 1e6:.3g} uH, C_BYP {c_out[i] * 1e6:.3g} uF) "
                 + ", ".join(f"{k} misses by {-v:.1%}" for k, v in fails.items())]
        achievable = {"margin_" + k.replace(" ", "_"): v for k, v in fails.items()}
    raise Infeasible(TABLE, "no series R_OSC, L and C_BYP meets every check at every tolerance corner; "
                     + "; ".join(parts) + " with the other checks met", achievable)
