"""Independent oracles the tests share: every tolerance corner and every series value, written out here
from the circuit laws, sharing no code with handbook.design (a check built on the design's own formula
would check nothing)."""
import itertools

import numpy as np
from scipy.optimize import fsolve

from handbook.core import series
from handbook.design.schema import defaults


def enumerate_cap(spec):
    s = {**defaults("commutation"), **spec}
    t_slow, t_fast = 10 / (s["rpm_min"] * s["pole_pairs"]), 10 / (s["rpm_max"] * s["pole_pairs"])
    for c in series.values(s["series"], 1e-12, 1e-3):
        if s["i_charge_max"] * t_slow / (c * (1 - s["tolerance"])) <= s["window"] * (1 + 1e-12):
            ok = s["i_charge_min"] * t_fast / (c * (1 + s["tolerance"])) >= s["min_excursion"] * (1 - 1e-12)
            return c if ok else None
    return None


def corners_vcs(r9, s):
    """All 128 corners, written out independently of design.vcs_extremes."""
    t = s["resistor_tolerance"]
    drift = s["zener_tc"] * s["temp_span"]
    vals = []
    for sg in itertools.product((-1, 1), repeat=7):
        r9_, r10, r11, r12, r13 = (x * (1 + t * g) for x, g in
                                   zip((r9, s["r10"], s["r11"], s["r12"], s["r13"]), sg[:5]))
        vz = s["zener_voltage"] * (1 + s["zener_tolerance"] * sg[5]) + drift * sg[5]
        a, b = r13 / (r12 + r13), r11 / (r9_ + r10 + r11)
        vals.append(vz * (1 - b / a) - s["offset"] * sg[6] / a)
    vals = np.array(vals)
    return vals.min(axis=0), vals.max(axis=0)


def enumerate_limiter(spec):
    s = {**defaults("current_limiter"), **spec}
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    lo, hi = corners_vcs(r9s, s)
    for r7 in series.values(s["r7_series"], s["r7_min"], s["r7_max"]):
        i_lo, i_hi = lo / (r7 * (1 + s["r7_tolerance"])), hi / (r7 * (1 - s["r7_tolerance"]))
        margin = np.minimum(i_lo / s["i_no_trip"] - 1, 1 - i_hi / s["i_must_trip"])
        if (margin >= -1e-12).any():
            return r7, float(r9s[np.argmax(margin)])
    return None


def _clip_model():
    """The clipping-power model solved here from the datasheet's three 1 % THD points (125 W at 125 kHz and
    135 W at 75 kHz into 4 ohm, 75 W at 125 kHz into 8 ohm, +-20 V) by a numerical root finder."""
    points = ((125e3, 4.0, 125.0), (75e3, 4.0, 135.0), (125e3, 8.0, 75.0))

    def residual(x):
        v, a_us, r_s = x
        return [(v * (1 - a_us * 1e-6 * f) * rl / (rl + r_s)) ** 2 / (2 * rl) / p - 1 for f, rl, p in points]

    v, a_us, r_s = fsolve(residual, [40.0, 0.5, 0.3], xtol=1e-14)
    return lambda f, r_load, supply: (v * supply / 20 * (1 - a_us * 1e-6 * f) * r_load / (r_load + r_s)) ** 2 / (2 * r_load)


p_clip = _clip_model()


def enumerate_class_d(spec):
    s = {**defaults("class_d"), **spec}
    best = None
    for r in series.values(s["r_osc_series"], 10, 1e6):
        f = 1e9 / (4000 + r - 0.4 * s["r_dly"])
        if not 50e3 <= f <= 225e3:
            continue
        x = (25e-9 + 26e-9 + 310e-9) * f
        p = x * s["p_out"] / (1 - x) + s["p_out"] / s["r_load"] * 0.46
        thd_ok = 0.003 * (125e3 / f) ** 2 <= s["thd_max"] * (1 + 1e-9)
        clip_ok = p_clip(f, s["r_load"], s["supply"]) >= s["p_out"] * (1 - 1e-9)
        need = (150 - s["t_ambient"]) / p - {"TF": 2.0, "T": 1.0}[s["package"]] - s["theta_cs"]
        heat_ok = need > 0 and (s["theta_sa_available"] is None or s["theta_sa_available"] <= need * (1 + 1e-9))
        if thd_ok and clip_ok and heat_ok and (best is None or p < best[0]):
            best = (p, r)
    return None if best is None else best[1]
