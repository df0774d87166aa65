"""The LM4651/LM4652 switching frequency and R_OSC: the most efficient frequency meeting THD+N, clipping
power and the heat sink.

Problem (f in kHz, 50..225): minimise the LM4652's dissipation at p_out (eq 9, 10 and conduction) subject
to THD+N(f) <= thd_max, P_clip(f) >= p_out, and with a given heat sink T_a + P_D (theta_JC + theta_CS +
theta_SA) <= T_jmax. solve (IPOPT) -> snap (R_OSC from the series, eq 6 with the R_DLY correction) ->
verify (every figure at the frequency that resistor really gives) -> Result.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca

from ..core import series
from ..sources.lm4651 import circuit as lm4651
from .common import Result, completed
from .solvers import Infeasible, minimise

TABLE = "class_d"


@dataclass(frozen=True)
class ClassDResult(Result):
    f_sw: float
    r_osc: float
    efficiency: float
    p_dissipation: float
    p_total: float
    theta_sa_required: float
    t_junction: float
    thd_n: float
    p_clip: float
    binding: str
    f_continuous: float
    band: tuple

    table = TABLE


def checked(spec: dict | None) -> dict:
    return completed(TABLE, spec)


def evaluate(f_sw: float, s: dict, rtol: float = 1e-9) -> dict:
    """Every figure of merit at one switching frequency (plain floats; the independent re-check)."""
    p4652, total, eff = lm4651.losses(f_sw, s["p_out"], s["r_load"])
    need = lm4651.theta_sa_required(p4652, s["t_ambient"], s["package"], s["theta_cs"])
    sink = s["theta_sa_available"]
    tj = lm4651.t_junction(p4652, s["t_ambient"], need if sink is None else sink, s["package"], s["theta_cs"])
    return {"f_sw": f_sw, "efficiency": eff, "p_dissipation": p4652, "p_total": total,
            "theta_sa_required": need, "t_junction": tj, "thd_n": lm4651.thd_n(f_sw),
            "p_clip": lm4651.p_clip(f_sw, s["r_load"], s["supply"]),
            "ok_thd": lm4651.thd_n(f_sw) <= s["thd_max"] * (1 + rtol),
            "ok_clip": lm4651.p_clip(f_sw, s["r_load"], s["supply"]) >= s["p_out"] * (1 - rtol),
            "ok_heat": need > 0 and (sink is None or sink <= need * (1 + rtol))}


def band(s: dict) -> dict:
    """The feasible switching-frequency band in closed form: every constraint is monotonic in f.

    THD+N falls with f (a lower bound f_thd), the clipping power falls with f (an upper bound
    f_clip), and the LM4652's dissipation rises with f (with a given heat sink, an upper bound f_heat).
    """
    f_lo, f_hi = lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"]
    f_thd = lm4651.F_REF * (lm4651.THD_REF / s["thd_max"]) ** (1 / lm4651.THD_EXPONENT)
    # p_clip(f) = p_out  <=>  1 - A f = sqrt(2 R_L p_out) (R_L + R_S) / (R_L V_EFF supply/20)
    g = math.sqrt(2 * s["r_load"] * s["p_out"]) * (s["r_load"] + lm4651.R_S) / (
        s["r_load"] * lm4651.V_EFF * s["supply"] / lm4651.SUPPLY_REF)
    f_clip = (1 - g) / lm4651.A_OM
    f_heat = math.inf
    if s["theta_sa_available"] is not None:
        theta = lm4651.DEVICE["theta_jc"][s["package"]] + s["theta_cs"] + s["theta_sa_available"]
        p_allow = (lm4651.DEVICE["tj_max"] - s["t_ambient"]) / theta
        y = (p_allow - lm4651.p_conduction(s["p_out"], s["r_load"])) / s["p_out"]
        tau = lm4651.DEVICE["t_rise"] + lm4651.DEVICE["t_fall"] + lm4651.DEVICE["t_overmod"]
        f_heat = (y / (1 + y)) / tau if y > 0 else -math.inf
    return {"f_thd": f_thd, "f_clip": f_clip, "f_heat": f_heat,
            "lower": max(f_lo, f_thd), "upper": min(f_hi, f_clip, f_heat)}


def _infeasible(s: dict, band: dict):
    """Raise the Infeasible that names what can be met, from the closed-form band."""
    lo, f_lo, f_hi = band["lower"], lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"]
    if band["f_clip"] < f_lo:
        p_max = lm4651.p_clip(f_lo, s["r_load"], s["supply"])
        raise Infeasible(TABLE, f"{s['p_out']:g} W clips into {s['r_load']:g} ohm at +-{s['supply']:g} V even at "
                         f"{f_lo / 1e3:g} kHz: at most {p_max:.0f} W", {"p_out_max": p_max})
    if band["f_thd"] > f_hi:
        raise Infeasible(TABLE, f"THD+N {s['thd_max']:.3%} needs f_sw >= {band['f_thd'] / 1e3:.0f} kHz, above the "
                         f"{f_hi / 1e3:g} kHz limit; at {f_hi / 1e3:g} kHz the model gives {lm4651.thd_n(f_hi):.3%}",
                         {"thd_min": lm4651.thd_n(f_hi)})
    if band["f_thd"] > band["f_clip"]:
        raise Infeasible(
            TABLE,
            f"THD+N {s['thd_max']:.3%} needs f_sw >= {band['f_thd'] / 1e3:.1f} kHz but {s['p_out']:g} W without "
            f"clipping needs f_sw <= {band['f_clip'] / 1e3:.1f} kHz: at {band['f_thd'] / 1e3:.1f} kHz at most "
            f"{lm4651.p_clip(lo, s['r_load'], s['supply']):.1f} W, or at {band['f_clip'] / 1e3:.1f} kHz THD+N "
            f"{lm4651.thd_n(band['f_clip']):.3%}",
            {"p_out_max": lm4651.p_clip(lo, s["r_load"], s["supply"]), "thd_min": lm4651.thd_n(band["f_clip"])})
    ev = evaluate(lo, {**s, "theta_sa_available": None})
    theta = lm4651.DEVICE["theta_jc"][s["package"]] + s["theta_cs"] + s["theta_sa_available"]
    t_a_max = lm4651.DEVICE["tj_max"] - ev["p_dissipation"] * theta
    raise Infeasible(
        TABLE,
        f"with a {s['theta_sa_available']:g} K/W heat sink the LM4652 overheats at every allowed frequency: at "
        f"{lo / 1e3:.1f} kHz it dissipates {ev['p_dissipation']:.1f} W and needs a heat sink of "
        f"{ev['theta_sa_required']:.2f} K/W or better, or an ambient of at most {t_a_max:.0f} C",
        {"theta_sa_required": ev["theta_sa_required"], "t_ambient_max": t_a_max, "f_sw": lo})


def solve(s: dict, fband: dict):
    """IPOPT on the continuous problem: f in kHz, the LM4652's dissipation minimised."""
    x = ca.SX.sym("f_kHz")
    f = x * 1e3
    p4652 = lm4651.p_switch(f, s["p_out"]) + lm4651.p_conduction(s["p_out"], s["r_load"])
    cons = [("thd", lm4651.thd_n(f) / s["thd_max"], -ca.inf, 1.0),
            ("clipping", lm4651.p_clip(f, s["r_load"], s["supply"]) / s["p_out"], 1.0, ca.inf)]
    if s["theta_sa_available"] is not None:
        cons.append(("heat_sink", lm4651.t_junction(p4652, s["t_ambient"], s["theta_sa_available"], s["package"],
                                                    s["theta_cs"]) / lm4651.DEVICE["tj_max"], -ca.inf, 1.0))
    f_lo, f_hi = lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"]
    return minimise(p4652, x, cons, x0=[0.5 * (fband["lower"] + fband["upper"]) / 1e3], lbx=[f_lo / 1e3],
                    ubx=[f_hi / 1e3])


def snap(s: dict, f_star: float, fband: dict):
    """R_OSC: the series value whose real frequency lies in the band with the best efficiency (the lowest
    frequency); the neighbours of the ideal resistor are tried first, then the whole series."""
    f_lo, f_hi = lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"]
    ideal = lm4651.r_osc_for(f_star, s["r_dly"])
    near = [series.at_most(s["r_osc_series"], ideal), series.at_least(s["r_osc_series"], ideal)]
    rows = []
    for pool in (near, series.values(s["r_osc_series"], 10.0, 1e6)):
        for r in pool:
            f_real = lm4651.f_sw_for(r, s["r_dly"])
            if f_lo <= f_real <= f_hi:
                ev = evaluate(f_real, s)
                if ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"]:
                    rows.append((ev["efficiency"], r, ev))
        if rows:
            break
    if not rows:
        raise Infeasible(
            TABLE, f"the feasible band {fband['lower'] / 1e3:.2f} to {fband['upper'] / 1e3:.2f} kHz holds no "
            f"{s['r_osc_series']} R_OSC (ideal {ideal:.0f} ohm gives {f_star / 1e3:.2f} kHz): use a finer series or "
            f"relax THD+N", {"f_sw": f_star, "r_osc_ideal": ideal, "band": (fband["lower"], fband["upper"])})
    _, r_osc, ev = max(rows, key=lambda t: t[0])
    return r_osc, ev


BINDING = {"thd": "THD+N limit at the test point", "clipping": "clipping power at 1 % THD",
           "heat_sink": "junction temperature with the given heat sink"}


def design(spec: dict | None = None) -> ClassDResult:
    """Highest efficiency at p_out subject to THD+N, clipping power and the heat sink."""
    s = checked(spec)
    fband = band(s)
    if fband["lower"] > fband["upper"] * (1 + 1e-9):
        _infeasible(s, fband)
    sol = solve(s, fband)
    f_star = float(sol.x[0]) * 1e3
    r_osc, ev = snap(s, f_star, fband)
    binding = [BINDING[b] for b in sol.binding(1e-8)]
    return ClassDResult(
        spec=s, f_sw=ev["f_sw"], r_osc=r_osc, efficiency=ev["efficiency"], p_dissipation=ev["p_dissipation"],
        p_total=ev["p_total"], theta_sa_required=ev["theta_sa_required"], t_junction=ev["t_junction"],
        thd_n=ev["thd_n"], p_clip=ev["p_clip"],
        binding=binding[0] if binding else "none (efficiency is best at the lowest frequency allowed)",
        f_continuous=f_star, band=(fband["lower"], fband["upper"]))


def enumerate_series(s: dict):
    """Exhaustive: the series R_OSC whose real frequency re-verifies with the best efficiency, or None."""
    s = checked(s)
    best = None
    for r in series.values(s["r_osc_series"], 10.0, 1e6):
        f = lm4651.f_sw_for(r, s["r_dly"])
        if lm4651.DEVICE["f_min"] <= f <= lm4651.DEVICE["f_max"]:
            ev = evaluate(f, s)
            if ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"] and (best is None or ev["efficiency"] > best[0]):
                best = (ev["efficiency"], r)
    return None if best is None else best[1]
