"""LM4651/LM4652 joint design: what binds, what a spec nothing meets can still reach, the warnings a
valid but implausible design carries, and the datasheet's own typical application judged by the same
checks."""
from __future__ import annotations

import numpy as np

from ..sources.lm4651 import circuit as lm4651
from . import class_d_model as model
from .solvers import Infeasible

TABLE = "class_d"
DEV = lm4651.DEVICE
#: heat sinks for a TO-220 run from about 30 K/W (small clip-on) down to about 0.5 K/W (a large extrusion
#: in free air; lower needs a fan): outside that range the design warns (a market survey, not the datasheet)
THETA_SA_MADE = (0.5, 30.0)
#: the datasheet's typical application (figure 1 and its text): R_OSC 3.9 k (Example Design, from eq 6),
#: R_DLY 5 k (recommended), L 50 uH and C_BYP 5 uF (Output Stage Filtering)
DATASHEET_PARTS = {"r_osc": 3.9e3, "l_out": 50e-6, "c_out": 5e-6, "r_dly": 5e3}


def datasheet_application(s: dict) -> dict:
    """The datasheet's own R_OSC, L, C_BYP and R_DLY through every check of the design, at every corner."""
    p = DATASHEET_PARTS
    return model.one(s, p["r_osc"], p["l_out"], p["c_out"], p["r_dly"])


def binding_text(sol, fig: dict) -> str:
    """The constraints IPOPT's multipliers name at the continuous optimum, then the tightest margins of the
    series design."""
    names = [n for n in sol.binding(1e-7) if n != "heat sink objective"]
    names = list(dict.fromkeys(names))
    tight = sorted(fig["margins"].items(), key=lambda kv: kv[1])[:2]
    text = ", ".join(names) if names else "none"
    return f"{text} (series design's tightest margins: " + ", ".join(f"{k} {v:.1%}" for k, v in tight) + ")"


def warnings(s: dict, fig: dict, l_out: float, c_out: float) -> list[str]:
    """What a valid design does that is implausible: each warning says its threshold and why."""
    out = []
    need, path = fig["theta_sa_required"], DEV["theta_jc"][s["package"]] + s["theta_cs"]
    free_air = {"TF": 43.0, "T": 37.0}[s["package"]]
    if need + path >= free_air:
        out.append(f"no heat sink needed: {need:.1f} K/W of sink would do, and the bare {s['package']} package "
                   f"already reaches {free_air:g} K/W junction to ambient (datasheet thermal table)")
    elif need > THETA_SA_MADE[1]:
        out.append(f"heat sink of {need:.1f} K/W needed: above about {THETA_SA_MADE[1]:g} K/W, the smallest "
                   "clip-on TO-220 heat sinks made; any heat sink will do")
    elif need < THETA_SA_MADE[0]:
        out.append(f"heat sink of {need:.2f} K/W needed: below about {THETA_SA_MADE[0]:g} K/W a TO-220 needs a "
                   "very large extrusion or forced air")
    p_max = lm4651.p_clip(fig["f_sw_min"], s["r_load"], s["supply"])
    if s["p_continuous"] is not None and s["p_continuous"] > p_max:
        out.append(f"p_continuous = {s['p_continuous']:g} W is more than the amplifier can deliver "
                   f"({p_max:.0f} W at the slowest oscillator corner): the heat sink is larger than needed")
    if s["p_continuous"] is not None and s["p_continuous"] < s["p_out"]:
        out.append(f"p_continuous = {s['p_continuous']:g} W is below p_out = {s['p_out']:g} W: the heat sink "
                   "cannot carry the rated output continuously")
    if not 4.0 <= s["r_load"] <= 8.0:
        out.append(f"r_load = {s['r_load']:g} ohm: the clipping and THD+N models are calibrated at 4 and 8 ohm only")
    if c_out > 50e-6:
        out.append(f"C_BYP = {c_out * 1e6:.3g} uF: the datasheet suggests 5 to 10 uF film; above 50 uF film "
                   "capacitors are bulky")
    if l_out > 10 * lm4651.L_REF:
        out.append(f"L = {l_out * 1e6:.3g} uH: ten times the datasheet's 50 uH; a choke carrying "
                   f"{fig['i_peak']:.1f} A at that inductance is large")
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
SHOW = {"THD+N": ("THD+N", "thd_n", "{:.3%}", "thd_max"), "clipping": ("p_out", "p_clip", "{:.1f} W", "p_out"),
        "ripple": ("ripple", "ripple", "{:.3f} V", "ripple_max"),
        "audio band": ("band deviation", "band_deviation", "{:.2f} dB", "droop_max"),
        "filter Q": ("Q", "q", "{:.2f}", "q_max"), "inductor peak": ("peak current", "i_peak", "{:.2f} A", "i_sat"),
        "heat sink": ("theta_SA", "theta_sa_required", "{:.2f} K/W", "theta_sa_available")}


def infeasible(s: dict, r_dly: float, searched=None):
    """Raise the Infeasible that says, for each check no series design meets, the best it reaches while every
    other check holds (the whole grid, exhaustively; ``searched`` = (R_OSC, L, C, figures) if evaluated)."""
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
        asked = s[spec_key] if s.get(spec_key) is not None else 0.0
        parts.append(f"{label}: best {fmt.format(ev[key])} (asked {fmt.format(asked)})")
        achievable[key] = ev[key]
        if k == "heat sink":  # the hottest ambient the best candidate survives with the asked heat sink
            path = DEV["theta_jc"][s["package"]] + s["theta_cs"]
            t_target = DEV["tj_max"] - s["tj_margin"]
            watts = (t_target - s["t_ambient"]) / (ev["theta_sa_required"] + path)
            achievable["t_ambient_max"] = t_target - watts * (path + asked)
            parts[-1] += (f": the LM4652 dissipates {watts:.1f} W at T_j = {t_target:.0f} C, so an ambient of at "
                          f"most {achievable['t_ambient_max']:.0f} C")
    if not reach:  # each check can be met alone, but not together: the candidate closest to meeting all
        i = int(np.argmax(np.min(np.stack(list(fig["margins"].values())), axis=0)))
        ev = model.at(fig, i)
        fails = {k: v for k, v in ev["margins"].items() if v < 0}
        parts = [f"at best (R_OSC {r[i]:.4g} ohm, L {l_out[i] * 1e6:.3g} uH, C_BYP {c_out[i] * 1e6:.3g} uF) "
                 + ", ".join(f"{k} misses by {-v:.1%}" for k, v in fails.items())]
        achievable = {"margin_" + k.replace(" ", "_"): v for k, v in fails.items()}
    raise Infeasible(TABLE, "no series R_OSC, L and C_BYP meets every check at every tolerance corner; "
                     + "; ".join(parts) + " with the other checks met", achievable)
