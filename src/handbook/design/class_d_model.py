"""LM4651/LM4652 joint design: every figure of a candidate (R_OSC, L, C, R_DLY) at every tolerance corner.

The corners are enumerated, never assumed: the oscillator at eq 5 x (1 - osc_tol_slow) and x (1 +
osc_tol_fast), L and C each at +- their tolerance (2 x 2 x 2 = 8 corners), and the LM4652 at its maximum
R_DS(on) at the junction temperature and the Example Design's 350 ns over-modulation time. Every
constraint takes its worst corner. The functions broadcast over numpy arrays of candidates (a corner
axis is added last), so the solver's snap, the exhaustive enumeration and the plots share one
evaluator. The models themselves are in :mod:`handbook.sources.lm4651.circuit`.
"""
from __future__ import annotations

import itertools

import numpy as np

from ..core import series
from ..sources.lm4651 import circuit as lm4651

DEV = lm4651.DEVICE
#: the search ranges of the series parts (H, F, ohm)
L_RANGE, C_RANGE, R_OSC_RANGE, R_DLY_RANGE = (1e-6, 1e-3), (0.1e-6, 100e-6), (100.0, 1e5), (0.0, 1e6)
#: the eight corners: (oscillator sign, L sign, C sign); -1 is the slow / low end
CORNERS = np.array(list(itertools.product((-1, 1), repeat=3)), dtype=float)
#: the constraints, in the order the chapter and the binding list name them
CHECKS = ("oscillator range", "THD+N", "clipping", "ripple", "audio band", "filter Q", "inductor peak",
          "dead time", "heat sink")


def corner_factors(s: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Multipliers of f, L and C at the eight corners."""
    fo = np.where(CORNERS[:, 0] < 0, 1 - s["osc_tol_slow"], 1 + s["osc_tol_fast"])
    return fo, 1 + s["l_tolerance"] * CORNERS[:, 1], 1 + s["c_tolerance"] * CORNERS[:, 2]


def band_deviation_db(f_audio, l_out, c_out, r_load):
    """Largest deviation of |H| from 0 dB over 0..f_audio (closed form): |H| rises to its peak at
    x_p = sqrt(1 - 1/(2 Q^2)) (when Q > 1/sqrt 2) and falls after it, so the band's extremes are |H(0)| = 1,
    |H(f_audio)| and the peak 1 / (u (2 - u)), u = 1/(2 Q^2), when it lies inside the band."""
    x2 = (f_audio / lm4651.filter_f0(l_out, c_out)) ** 2
    g_top = lm4651.filter_gain2(f_audio, l_out, c_out, r_load)
    u = 1 / (2 * lm4651.filter_q(l_out, c_out, r_load) ** 2)
    peak_inside = (u < 1) & (x2 >= 1 - u)
    g_peak = 1 / np.maximum(u * (2 - u), 1e-300)  # only used where u < 1
    g_max = np.where(peak_inside, g_peak, np.maximum(1.0, g_top))
    g_min = np.minimum(1.0, g_top)
    return 10 * np.log10(np.maximum(g_max, 1 / g_min))


def heat(s: dict, f, theta_sa=None):
    """(theta_SA needed, T_j with theta_SA, LM4652 dissipation at that T_j) at oscillator frequency f.

    The LM4652 carries p_continuous (default: the clipping power at f, all the amplifier can deliver), eq 9
    and 10 with the 350 ns over-modulation time, conduction with R_DS(on) maximum at T_j, and its idle
    share. P(T_j) is linear in T_j, so T_j = (T_a + theta P0) / (1 - theta k) exactly.
    """
    p = lm4651.p_clip(f, s["r_load"], s["supply"]) if s["p_continuous"] is None else s["p_continuous"]
    a = (lm4651.p_switch(f, p, t_overmod=s["t_overmod"]) + lm4651.p_idle_4652(s["supply"]))
    b = 2 * p / s["r_load"] * s["rds_on_25"] / lm4651.RDS_ON_MAX_25  # W per ohm of the maximum R_DS(on)
    path = DEV["theta_jc"][s["package"]] + s["theta_cs"]
    t_target = DEV["tj_max"] - s["tj_margin"]
    need = (t_target - s["t_ambient"]) / (a + b * lm4651.rds_on_max(t_target)) - path
    sink = need if theta_sa is None else theta_sa
    theta = path + sink
    k = b * lm4651.RDS_ON_MAX_25 * lm4651.RDS_TC
    p0 = a + b * lm4651.RDS_ON_MAX_25 * (1 - 25.0 * lm4651.RDS_TC)
    runaway = theta * k >= 1
    tj = np.where(runaway, np.inf, (s["t_ambient"] + theta * p0) / np.where(runaway, 1.0, 1 - theta * k))
    return need, tj, a + b * lm4651.rds_on_max(tj)


def efficiency(s: dict, f_nom, l_out):
    """Efficiency at p_out, typical parts at the nominal frequency: conduction with the Example Design's
    230 mOhm hot, eq 9/10 with the typical 310 ns, the idle loss and the coils (system table: 85 % at
    125 W)."""
    p = s["p_out"]
    loss = (lm4651.p_conduction(p, s["r_load"]) + lm4651.p_switch(f_nom, p) + lm4651.p_idle(s["supply"])
            + lm4651.coil_loss(p, s["r_load"], l_out, s["l_dcr"]))
    return p / (p + loss)


def figures(s: dict, r_osc, l_out, c_out, r_dly) -> dict:
    """Every figure and margin of candidates (arrays broadcast), each at its worst corner."""
    r_osc, l_out, c_out, r_dly = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in
                                                        (r_osc, l_out, c_out, r_dly)))
    f_nom = lm4651.f_sw_for(r_osc, r_dly)
    fo, lo, co = corner_factors(s)
    f, l, c = f_nom[..., None] * fo, l_out[..., None] * lo, c_out[..., None] * co
    rl, vs = s["r_load"], s["supply"]
    thd = lm4651.thd_n_joint(f, l, c, s["thd_test_power"], rl, vs).max(-1)
    ripple = lm4651.ripple_rms(f, l, c, rl, vs).max(-1)
    dev = band_deviation_db(s["f_audio"], l, c, rl).max(-1)
    q = lm4651.filter_q(l, c, rl).max(-1)
    i_pk = lm4651.inductor_peak(f, l, c, lm4651.v_clip_peak(f, rl, vs), rl, vs, s["f_audio"]).max(-1)
    f_slow, f_fast = f_nom * (1 - s["osc_tol_slow"]), f_nom * (1 + s["osc_tol_fast"])
    p_clip = lm4651.p_clip(f_fast, rl, vs)
    heats = [heat(s, x, s["theta_sa_available"]) for x in (f_slow, f_fast)]
    need = np.minimum(heats[0][0], heats[1][0])
    worst = np.where(heats[0][1] >= heats[1][1], 0, 1)
    tj = np.where(worst == 0, heats[0][1], heats[1][1])
    p_d = np.where(worst == 0, heats[0][2], heats[1][2])
    t_dead = lm4651.dead_time_total(r_dly)
    sink = 0.0 if s["theta_sa_available"] is None else s["theta_sa_available"]
    margins = {
        "oscillator range": np.minimum(f_slow / DEV["f_min"] - 1, 1 - f_fast / DEV["f_max"]),
        "THD+N": 1 - thd / s["thd_max"], "clipping": p_clip / s["p_out"] - 1,
        "ripple": 1 - ripple / s["ripple_max"], "audio band": 1 - dev / s["droop_max"],
        "filter Q": 1 - q / s["q_max"], "inductor peak": 1 - i_pk / min(s["i_sat"], lm4651.I_LIMIT),
        "dead time": t_dead / s["dead_time_min"] - 1,
        "heat sink": (need - sink) / (DEV["theta_jc"][s["package"]] + s["theta_cs"] + sink)}
    ok = np.ones(f_nom.shape, dtype=bool)
    for m in margins.values():
        ok &= m >= -1e-12
    return {"f_sw": f_nom, "f_sw_min": f_slow, "f_sw_max": f_fast, "thd_n": thd, "ripple": ripple,
            "band_deviation": dev, "q": q, "i_peak": i_pk, "p_clip": p_clip, "theta_sa_required": need,
            "t_junction": tj, "p_dissipation": p_d, "dead_time": t_dead,
            "efficiency": efficiency(s, f_nom, l_out), "margins": margins, "ok": ok}


def at(fig: dict, index) -> dict:
    """One candidate's figures as plain floats (margins included)."""
    out = {k: float(v[index]) for k, v in fig.items() if k not in ("margins", "ok")}
    out["margins"] = {k: float(v[index]) for k, v in fig["margins"].items()}
    out["ok"] = bool(fig["ok"][index])
    return out


def one(s: dict, r_osc: float, l_out: float, c_out: float, r_dly: float) -> dict:
    """The figures of one design as plain floats."""
    return at(figures(s, np.array([r_osc]), np.array([l_out]), np.array([c_out]), np.array([r_dly])), 0)


#: what sensitivity() switches on one at a time, from a design with every tolerance off
TOLERANCES = {
    "oscillator (eq 5 vs table)": ("osc_tol_slow", "osc_tol_fast"),
    "inductor tolerance": ("l_tolerance",),
    "capacitor tolerance": ("c_tolerance",),
    "R_DS(on) max vs typ": ("rds_on_25",),
    "T_overmod 350 vs 310 ns": ("t_overmod",),
}
TYPICAL = {"osc_tol_slow": 0.0, "osc_tol_fast": 0.0, "l_tolerance": 0.0, "c_tolerance": 0.0,
           "rds_on_25": 0.200, "t_overmod": DEV["t_overmod"]}


def sensitivity(s: dict, r_osc: float, l_out: float, c_out: float, r_dly: float) -> dict:
    """Margins with every tolerance at its typical value, then with each one alone at its limit, then all:
    {case: {check: margin}}; the drop from the first row is what that tolerance eats."""
    cases = {"typical (no tolerance)": {**s, **TYPICAL}}
    for name, keys in TOLERANCES.items():
        cases[name] = {**s, **TYPICAL, **{k: s[k] for k in keys}}
    cases["all at their limits"] = s
    return {name: one(spec, r_osc, l_out, c_out, r_dly)["margins"] for name, spec in cases.items()}


def axes(s: dict, r_dly: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The series values searched: R_OSC whose two oscillator corners stay inside 50..225 kHz, L and C."""
    r = np.array(series.values(s["r_osc_series"], *R_OSC_RANGE))
    f = lm4651.f_sw_for(r, r_dly)
    keep = (f > 0) & (f * (1 - s["osc_tol_slow"]) >= DEV["f_min"] * (1 - 1e-12)) & (
        f * (1 + s["osc_tol_fast"]) <= DEV["f_max"] * (1 + 1e-12))
    return r[keep], np.array(series.values(s["l_series"], *L_RANGE)), np.array(series.values(s["c_series"], *C_RANGE))


def grid(s: dict, r_dly: float, f_win=None, l_win=None, c_win=None):
    """Every combination of the series values (each optionally within a window) as flat candidate arrays."""
    r, l_out, c_out = axes(s, r_dly)
    f = lm4651.f_sw_for(r, r_dly)
    pick = [np.ones(len(v), dtype=bool) if w is None else (x >= w[0]) & (x <= w[1])
            for v, x, w in ((r, f, f_win), (l_out, l_out, l_win), (c_out, c_out, c_win))]
    R, L, C = np.meshgrid(r[pick[0]], l_out[pick[1]], c_out[pick[2]], indexing="ij")
    return R.ravel(), L.ravel(), C.ravel()


def pair_keys(s: dict, r_osc, l_out, r_dly):
    """(objective, the other) of (R_OSC, L) pairs, larger better: neither depends on C_BYP. The efficiency
    at p_out, and theta_SA needed at the worse oscillator corner (a larger one is a smaller heat sink)."""
    f = lm4651.f_sw_for(r_osc, r_dly)
    eff = efficiency(s, f, l_out)
    theta = np.minimum(heat(s, f * (1 - s["osc_tol_slow"]))[0], heat(s, f * (1 + s["osc_tol_fast"]))[0])
    theta = np.broadcast_to(theta, np.broadcast(eff, theta).shape)
    return (eff, theta) if s["objective"] == "efficiency" else (theta, eff)


def best(s: dict, r, l_out, c_out, r_dly):
    """Index of the best feasible candidate (objective, then the other, then the smaller L and C), or None."""
    fig = figures(s, r, l_out, c_out, r_dly)
    ok = np.flatnonzero(fig["ok"])
    if not ok.size:
        return None, fig
    first, second = pair_keys(s, r[ok], l_out[ok], r_dly)
    return ok[np.lexsort((c_out[ok], l_out[ok], -second, -first))[0]], fig
