"""Component choice by optimisation: CAP-CD, R7/R9 of the op-amp limiter, class-D switching frequency.

Each design states its problem (variables, objective, constraints), solves the continuous relaxation
with IPOPT (casadi), snaps to series values, re-verifies the snapped design with plain numpy, and
names the constraint that binds (from IPOPT's multipliers and from the re-verified margins).
Specifications no component can meet raise :class:`~handbook.solvers.Infeasible` saying what can be met.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from . import an94002, lm4651, series, validate
from .solvers import Infeasible, minimise

# ============================================================================================
# 1. CAP-CD for the TDA5143/TDA5144

COMMUTATION_DEFAULTS = {
    "pole_pairs": 6,
    "rpm_min": 1800.0,
    "rpm_max": 3600.0,  # not in the note: twice rpm_min, a documented default
    "i_charge_min": 10.6e-6,  # A: TDA5144 datasheet, the column AN94002 reads its 22 uA from
    "i_charge_max": 22e-6,  # A: AN94002's value (the datasheet's largest sink current)
    "window": 1.4,  # V: 2.3 V - 0.9 V (TDA5144 datasheet levels)
    "min_excursion": 0.1,  # V: assumed noise floor
    "tolerance": 0.05,
    "series": "E12",
}

C_BINDING = {
    "window": "swing at rpm_min fits the window (largest current, smallest capacitor)",
    "noise": "swing at rpm_max stays above the noise floor (smallest current, largest capacitor)",
}


def _commutation_checked(spec: dict) -> dict:
    s = {**COMMUTATION_DEFAULTS, **spec}
    validate.pole_pairs("commutation.pole_pairs", s["pole_pairs"])
    for k in ("rpm_min", "rpm_max"):
        validate.positive(f"commutation.{k}", s[k], "rpm", high=1e6)
    validate.ordered("commutation.rpm_min", s["rpm_min"], "commutation.rpm_max", s["rpm_max"])
    for k in ("i_charge_min", "i_charge_max"):
        validate.positive(f"commutation.{k}", s[k], "A", high=1e-3)
    if s["i_charge_min"] > s["i_charge_max"]:
        raise validate.InputError(f"commutation.i_charge_min = {s['i_charge_min']:g} A must not exceed "
                                  f"commutation.i_charge_max = {s['i_charge_max']:g} A")
    validate.positive("commutation.window", s["window"], "V", high=5.0)
    validate.positive("commutation.min_excursion", s["min_excursion"], "V", high=5.0)
    if s["min_excursion"] >= s["window"]:
        raise validate.InputError(f"commutation.min_excursion = {s['min_excursion']:g} V must be below "
                                  f"commutation.window = {s['window']:g} V")
    validate.fraction("commutation.tolerance", s["tolerance"])
    if s["series"] not in series.SERIES_NAMES:
        raise validate.InputError(f"commutation.series = {s['series']!r}: use one of {', '.join(series.SERIES_NAMES)}")
    return s


def commutation_bounds(s: dict) -> tuple[float, float]:
    """(smallest C meeting the window at rpm_min, largest C meeting the noise floor at rpm_max), in F."""
    n, tol = s["pole_pairs"], s["tolerance"]
    c_low = s["i_charge_max"] * an94002.t_com(s["rpm_min"], n) / (s["window"] * (1 - tol))
    c_high = s["i_charge_min"] * an94002.t_com(s["rpm_max"], n) / (s["min_excursion"] * (1 + tol))
    return c_low, c_high


def commutation_verify(c: float, s: dict) -> dict:
    """Independent check of one capacitor value: both worst-case swings and the speeds it supports."""
    n, tol = s["pole_pairs"], s["tolerance"]
    swing_slow = an94002.excursion(c * (1 - tol), s["rpm_min"], n, s["i_charge_max"])
    swing_fast = an94002.excursion(c * (1 + tol), s["rpm_max"], n, s["i_charge_min"])
    lo, hi = an94002.reliable_speed_range(c, tol, n, s["i_charge_min"], s["i_charge_max"], s["window"],
                                          s["min_excursion"])
    return {
        "swing_at_rpm_min": swing_slow, "swing_at_rpm_max": swing_fast,
        "window_ok": swing_slow <= s["window"] * (1 + 1e-12),
        "noise_ok": swing_fast >= s["min_excursion"] * (1 - 1e-12),
        "rpm_min_reliable": lo, "rpm_max_reliable": hi,
    }


def design_commutation(spec: dict | None = None) -> dict:
    """Smallest series CAP-CD whose swing fits the window at rpm_min; verified against the noise floor.

    Problem (C in nF): minimise C subject to
      g_window = I_max t_com(rpm_min) / (C (1 - tol)) <= window
      g_noise  = I_min t_com(rpm_max) / (C (1 + tol)) >= min_excursion.
    The smallest C maximises the margin of the second constraint. CAP-DC takes the same value.
    """
    s = _commutation_checked(spec or {})
    n, tol = s["pole_pairs"], s["tolerance"]
    t_slow, t_fast = an94002.t_com(s["rpm_min"], n), an94002.t_com(s["rpm_max"], n)
    c_low, c_high = commutation_bounds(s)
    x = ca.SX.sym("c_nF")
    c = x * 1e-9
    sol = minimise(x, x, [
        ("window", s["i_charge_max"] * t_slow / (c * (1 - tol)) / s["window"], -ca.inf, 1.0),
        ("noise", s["i_charge_min"] * t_fast / (c * (1 + tol)) / s["min_excursion"], 1.0, ca.inf),
    ], x0=[max(c_low, 1e-12) * 1e9 * 1.5], lbx=[1e-3], ubx=[1e9])
    continuous_ok = c_low <= c_high * (1 + 1e-9)
    chosen = series.at_least(s["series"], c_low * (1 - 1e-12))
    check = commutation_verify(chosen, s)
    if not (continuous_ok and check["window_ok"] and check["noise_ok"]):
        raise Infeasible(
            f"no {s['series']} capacitor covers {s['rpm_min']:g} to {s['rpm_max']:g} rpm: the smallest that fits "
            f"the window at {s['rpm_min']:g} rpm ({chosen * 1e9:.3g} nF) keeps a swing above "
            f"{s['min_excursion']:g} V only up to {check['rpm_max_reliable']:.0f} rpm",
            {"cap_cd": chosen, "rpm_min": s["rpm_min"], "rpm_max_reliable": check["rpm_max_reliable"],
             "rpm_ratio_possible": an94002.rpm_ratio(s["window"], s["min_excursion"], s["i_charge_min"],
                                                     s["i_charge_max"]) * (1 - tol) / (1 + tol)})
    below = series.at_most(s["series"], chosen * (1 - 1e-9))
    return {
        "cap_cd": chosen, "cap_dc": chosen,
        "rpm_min_reliable": check["rpm_min_reliable"], "rpm_max_reliable": check["rpm_max_reliable"],
        "binding": C_BINDING["window"] if sol.binding()[:1] == ["window"] or not sol.success else C_BINDING[sol.binding()[0]],
        "continuous_optimum": float(sol.x[0]) * 1e-9,
        "noise_margin": check["swing_at_rpm_max"] / s["min_excursion"] - 1,
        "swing_at_rpm_min": check["swing_at_rpm_min"], "swing_at_rpm_max": check["swing_at_rpm_max"],
        "next_smaller": below,
        "next_smaller_fails": (f"{below * 1e9:.3g} nF x (1 - {tol:g}) = {below * (1 - tol) * 1e9:.3g} nF swings "
                               f"{an94002.excursion(below * (1 - tol), s['rpm_min'], n, s['i_charge_max']):.3g} V at "
                               f"{s['rpm_min']:g} rpm, more than the {s['window']:g} V window"),
        "spec": s,
    }


def commutation_enumerate(s: dict) -> float | None:
    """Exhaustive check: the smallest value of the series (1 pF..1 mF) that passes commutation_verify."""
    s = _commutation_checked(s)
    for v in series.values(s["series"], 1e-12, 1e-3):
        chk = commutation_verify(v, s)
        if chk["window_ok"]:
            return v if chk["noise_ok"] else None
    return None


# ============================================================================================
# 2. R7 and R9 of the op-amp current limiter

LIMITER_DEFAULTS = {
    # TDA5144 output current limit 1.8 / 2.0 / 2.4 A (datasheet): the external limiter must have acted
    # by the internal limit's minimum, 1.8 A, and must let half of it, 0.9 A, through.
    "i_no_trip": 0.9,
    "i_must_trip": 1.8,
    "resistor_tolerance": 0.01,
    "r7_tolerance": 0.05,
    "zener_voltage": 8.2,
    "zener_tolerance": 0.05,
    "zener_tc": 0.0,  # V/K; set with temp_span to add the zener's drift (AN94002: 6.2 mV/K, 25 K)
    "temp_span": 0.0,  # K either side of 25 C
    "offset": 9e-3,
    "r10": 5.6e3, "r11": 16e3, "r12": 5.6e3, "r13": 16e3,
    "r7_series": "E24", "r7_min": 0.01, "r7_max": 10.0,
    "r9_series": "E96", "r9_min": 10.0, "r9_max": 1e6,
}


def _limiter_checked(spec: dict) -> dict:
    s = {**LIMITER_DEFAULTS, **spec}
    for k in ("i_no_trip", "i_must_trip"):
        validate.positive(f"current_limiter.{k}", s[k], "A", high=100.0)
    if s["i_no_trip"] >= s["i_must_trip"]:
        raise validate.InputError(f"current_limiter.i_no_trip = {s['i_no_trip']:g} A must be below "
                                  f"current_limiter.i_must_trip = {s['i_must_trip']:g} A")
    for k in ("resistor_tolerance", "r7_tolerance", "zener_tolerance"):
        validate.fraction(f"current_limiter.{k}", s[k])
    validate.positive("current_limiter.zener_voltage", s["zener_voltage"], "V", high=100.0)
    validate.number("current_limiter.offset", s["offset"], low=0.0, high=0.1, unit="V")
    validate.number("current_limiter.zener_tc", s["zener_tc"], low=0.0, high=0.1, unit="V/K")
    validate.number("current_limiter.temp_span", s["temp_span"], low=0.0, high=200.0, unit="K")
    for k in ("r10", "r11", "r12", "r13", "r7_min", "r7_max", "r9_min", "r9_max"):
        validate.positive(f"current_limiter.{k}", s[k], "ohm", high=1e9)
    validate.ordered("current_limiter.r7_min", s["r7_min"], "current_limiter.r7_max", s["r7_max"])
    validate.ordered("current_limiter.r9_min", s["r9_min"], "current_limiter.r9_max", s["r9_max"])
    for k in ("r7_series", "r9_series"):
        if s[k] not in series.SERIES_NAMES:
            raise validate.InputError(f"current_limiter.{k} = {s[k]!r}: use one of {', '.join(series.SERIES_NAMES)}")
    return s


def zener_range(s: dict) -> tuple[float, float]:
    drift = s["zener_tc"] * s["temp_span"]
    return s["zener_voltage"] * (1 - s["zener_tolerance"]) - drift, s["zener_voltage"] * (1 + s["zener_tolerance"]) + drift


def vcs_extremes(r9, s: dict):
    """Lowest and highest trip voltage over every tolerance corner, in closed form.

    V_cs = V_D1 - (1 + R12/R13) (V_D1 B + V_os), B = R11 / (R9 + R10 + R11). Whatever V_D1 is, V_cs
    rises with R9, R10 and R13 and falls with R11, R12 and V_os (because V_D1 B + V_os > 0), so the
    high corner of the resistors and offset is (R9+, R10+, R11-, R12-, R13+, V_os-) and the low corner
    its mirror image. V_cs is linear in V_D1 with slope 1 - B/A, whose sign depends on the design, so
    both zener ends are evaluated. The unit tests check this against all 128 corners. Works on numpy
    arrays and casadi symbols.
    """
    t = s["resistor_tolerance"]
    vz_lo, vz_hi = zener_range(s)
    lo_, hi_ = 1 - t, 1 + t

    def vcs(vz, r9_, r10, r11, r12, r13, vos):
        return vz - (1 + r12 / r13) * (vz * r11 / (r9_ + r10 + r11) + vos)

    high_r = (r9 * hi_, s["r10"] * hi_, s["r11"] * lo_, s["r12"] * lo_, s["r13"] * hi_, -s["offset"])
    low_r = (r9 * lo_, s["r10"] * lo_, s["r11"] * hi_, s["r12"] * hi_, s["r13"] * lo_, s["offset"])
    symbolic = isinstance(r9, (ca.SX, ca.MX))
    fmax, fmin = (ca.fmax, ca.fmin) if symbolic else (np.maximum, np.minimum)
    high = fmax(vcs(vz_hi, *high_r), vcs(vz_lo, *high_r))
    low = fmin(vcs(vz_lo, *low_r), vcs(vz_hi, *low_r))
    return low, high


def trip_currents(r7, r9, s: dict):
    """(lowest, highest) trip current with R7's tolerance too."""
    low, high = vcs_extremes(r9, s)
    return low / (r7 * (1 + s["r7_tolerance"])), high / (r7 * (1 - s["r7_tolerance"]))


def limiter_margins(r7, r9, s: dict):
    """Relative margins to the two limits (both >= 0 when the design meets the spec)."""
    i_lo, i_hi = trip_currents(r7, r9, s)
    return i_lo / s["i_no_trip"] - 1, 1 - i_hi / s["i_must_trip"]


def _best_r9(r7: float, r9s: np.ndarray, s: dict):
    m_lo, m_hi = limiter_margins(r7, r9s, s)
    worst = np.minimum(m_lo, m_hi)
    ok = worst >= -1e-12
    if not ok.any():
        return None
    i = int(np.argmax(np.where(ok, worst, -np.inf)))
    return float(r9s[i]), float(worst[i])


def limiter_enumerate(s: dict):
    """Exhaustive search over both series: (r7, r9) or None. Used by the tests and the benchmark."""
    s = _limiter_checked(s)
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    for r7 in series.values(s["r7_series"], s["r7_min"], s["r7_max"]):
        best = _best_r9(r7, r9s, s)
        if best:
            return r7, best[0]
    return None


def narrowest_window(s: dict) -> float:
    """The smallest i_must_trip / i_no_trip any R9 of the range allows (at the largest R9)."""
    low, high = vcs_extremes(np.array([s["r9_max"]]), s)
    return float(high[0] / low[0] * (1 + s["r7_tolerance"]) / (1 - s["r7_tolerance"]))


def design_current_limiter(spec: dict | None = None) -> dict:
    """Smallest R7 (least loss), then the R9 with the largest smaller margin to the two limits.

    Problem (x = ln R7, ln R9): minimise ln R7 subject to
      I_trip,min = V_cs,min(R9) / (R7 (1 + t7)) >= i_no_trip
      I_trip,max = V_cs,max(R9) / (R7 (1 - t7)) <= i_must_trip
    with V_cs,min/max the exact tolerance corners (vcs_extremes). The relaxation's R7 is a lower
    bound on every series design; the series search starts there and walks up, taking for each R7
    the best series R9 (all of them are checked: the line search is exact).
    """
    s = _limiter_checked(spec or {})
    ratio_needed = narrowest_window(s)
    if s["i_must_trip"] / s["i_no_trip"] < ratio_needed:
        raise Infeasible(
            f"no R7/R9 keeps the trip current between {s['i_no_trip']:g} A and {s['i_must_trip']:g} A at every "
            f"tolerance corner: the narrowest window these tolerances allow is i_must_trip / i_no_trip >= "
            f"{ratio_needed:.3g} (for i_no_trip = {s['i_no_trip']:g} A, i_must_trip >= {ratio_needed * s['i_no_trip']:.3g} A)",
            {"narrowest_ratio": ratio_needed, "i_must_trip_min": ratio_needed * s["i_no_trip"]})
    x = ca.SX.sym("x", 2)
    r7, r9 = ca.exp(x[0]), ca.exp(x[1])
    i_lo, i_hi = trip_currents(r7, r9, s)
    x0 = [math.log(math.sqrt(s["r7_min"] * s["r7_max"])), math.log(s["r9_max"] / 10)]
    sol = minimise(x[0], x, [
        ("i_no_trip", i_lo / s["i_no_trip"], 1.0, ca.inf),
        ("i_must_trip", i_hi / s["i_must_trip"], -ca.inf, 1.0),
    ], x0=x0, lbx=[math.log(s["r7_min"]), math.log(s["r9_min"])], ubx=[math.log(s["r7_max"]), math.log(s["r9_max"])])
    r7_relaxed = math.exp(sol.x[0]) if sol.success else s["r7_min"]
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    for r7_c in series.values(s["r7_series"], series.at_most(s["r7_series"], max(r7_relaxed * (1 - 1e-6), s["r7_min"])), s["r7_max"]):
        if r7_c < s["r7_min"]:
            continue
        best = _best_r9(r7_c, r9s, s)
        if best:
            break
    else:
        raise Infeasible(f"no {s['r7_series']} R7 in {s['r7_min']:g}..{s['r7_max']:g} ohm with an {s['r9_series']} R9 "
                         f"meets {s['i_no_trip']:g}..{s['i_must_trip']:g} A",
                         {"narrowest_ratio": ratio_needed, "r7_relaxed": r7_relaxed})
    r9_c, worst = best
    i_lo_c, i_hi_c = trip_currents(r7_c, r9_c, s)
    m_lo, m_hi = limiter_margins(r7_c, r9_c, s)
    nominal = an94002.v_cs_trip(s["zener_voltage"], r9_c, s["r10"], s["r11"], s["r12"], s["r13"]) / r7_c
    binding = "i_no_trip (lowest trip current)" if m_lo <= m_hi else "i_must_trip (highest trip current)"
    return {
        "r7": r7_c, "r9": r9_c,
        "i_trip_min": float(i_lo_c), "i_trip_max": float(i_hi_c), "i_trip_nominal": float(nominal),
        "p_r7": s["i_no_trip"] ** 2 * r7_c,
        "binding": binding,
        "relaxed_binding": sol.binding(),
        "margin_low": float(m_lo), "margin_high": float(m_hi),
        "r7_relaxed": r7_relaxed, "r9_relaxed": math.exp(sol.x[1]),
        "v_cs_nominal": float(nominal * r7_c),
        "spec": s,
    }


def monte_carlo_trip(r7: float, r9: float, s: dict, n: int = 100_000, seed: int = 1) -> dict:
    """Trip currents of ``n`` boards, every part uniform within its tolerance (fixed seed, vectorised)."""
    s = _limiter_checked(s)
    rng = np.random.default_rng(seed)
    t = s["resistor_tolerance"]

    def u(x, tol):
        return x * (1 + rng.uniform(-tol, tol, n))

    vz_lo, vz_hi = zener_range(s)
    vz = rng.uniform(vz_lo, vz_hi, n)
    v = an94002.v_cs_trip(vz, u(r9, t), u(s["r10"], t), u(s["r11"], t), u(s["r12"], t), u(s["r13"], t),
                          rng.uniform(-s["offset"], s["offset"], n))
    i = v / u(r7, s["r7_tolerance"])
    ok = (i >= s["i_no_trip"]) & (i <= s["i_must_trip"])
    return {"yield": float(ok.mean()), "i_p001": float(np.quantile(i, 0.001)),
            "i_p999": float(np.quantile(i, 0.999)), "i_min": float(i.min()), "i_max": float(i.max()), "samples": i}


# ============================================================================================
# 3. switching frequency of the LM4651/LM4652

CLASS_D_DEFAULTS = {
    "p_out": 125.0,  # W, the datasheet example
    "r_load": 4.0,
    "supply": 20.0,  # V, +- rails
    "t_ambient": 50.0,  # C
    "package": "TF",
    "theta_cs": 0.2,  # K/W, with thermal grease (datasheet)
    "theta_sa_available": None,  # K/W of the heat sink you have; None: report the one needed
    "thd_max": 0.005,  # THD+N limit at the test point: 0.5 % (a design limit; the datasheet types 0.3 %)
    "thd_test_power": 10.0,  # W, where the THD+N limit applies
    "r_dly": 5e3,  # ohm, the datasheet's recommended dead-time resistor
    "r_osc_series": "E24",
}


def _class_d_checked(spec: dict) -> dict:
    s = {**CLASS_D_DEFAULTS, **spec}
    validate.positive("class_d.p_out", s["p_out"], "W", high=1e4)
    validate.positive("class_d.r_load", s["r_load"], "ohm", high=1e3)
    validate.positive("class_d.supply", s["supply"], "V", high=22.0)
    validate.number("class_d.t_ambient", s["t_ambient"], low=-40.0, high=149.0, unit="C")
    if s["package"] not in lm4651.DATASHEET["theta_jc"]:
        raise validate.InputError(f"class_d.package = {s['package']!r}: use 'TF' (isolated) or 'T' (non-isolated)")
    validate.number("class_d.theta_cs", s["theta_cs"], low=0.0, high=10.0, unit="K/W")
    if s["theta_sa_available"] is not None:
        validate.positive("class_d.theta_sa_available", s["theta_sa_available"], "K/W", high=100.0)
    validate.number("class_d.thd_max", s["thd_max"], low=0.0, low_open=True, high=0.1,
                    unit="(fraction: 0.3 % = 0.003)")
    validate.positive("class_d.thd_test_power", s["thd_test_power"], "W", high=1e4)
    validate.number("class_d.r_dly", s["r_dly"], low=0.0, high=1e5, unit="ohm")
    if s["r_osc_series"] not in series.SERIES_NAMES:
        raise validate.InputError(f"class_d.r_osc_series = {s['r_osc_series']!r}: use one of {', '.join(series.SERIES_NAMES)}")
    return s


def class_d_evaluate(f_sw: float, s: dict, rtol: float = 1e-9) -> dict:
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


def class_d_band(s: dict) -> dict:
    """The feasible switching-frequency band in closed form: every constraint is monotonic in f.

    THD+N falls with f (a lower bound f_thd), the clipping power falls with f (an upper bound
    f_clip), and the LM4652's dissipation rises with f (with a given heat sink, an upper bound f_heat).
    """
    f_lo, f_hi = lm4651.DATASHEET["f_min"], lm4651.DATASHEET["f_max"]
    f_thd = lm4651.F_REF * (lm4651.THD_REF / s["thd_max"]) ** (1 / lm4651.THD_EXPONENT)
    # p_clip(f) = p_out  <=>  1 - A f = sqrt(2 R_L p_out) (R_L + R_S) / (R_L V_EFF supply/20)
    g = math.sqrt(2 * s["r_load"] * s["p_out"]) * (s["r_load"] + lm4651.R_S) / (
        s["r_load"] * lm4651.V_EFF * s["supply"] / lm4651.SUPPLY_REF)
    f_clip = (1 - g) / lm4651.A_OM
    f_heat = math.inf
    if s["theta_sa_available"] is not None:
        theta = lm4651.DATASHEET["theta_jc"][s["package"]] + s["theta_cs"] + s["theta_sa_available"]
        p_allow = (lm4651.DATASHEET["tj_max"] - s["t_ambient"]) / theta
        y = (p_allow - lm4651.p_conduction(s["p_out"], s["r_load"])) / s["p_out"]
        tau = lm4651.DATASHEET["t_rise"] + lm4651.DATASHEET["t_fall"] + lm4651.DATASHEET["t_overmod"]
        f_heat = (y / (1 + y)) / tau if y > 0 else -math.inf
    return {"f_thd": f_thd, "f_clip": f_clip, "f_heat": f_heat,
            "lower": max(f_lo, f_thd), "upper": min(f_hi, f_clip, f_heat)}


def _class_d_infeasible(s: dict, band: dict):
    lo, f_lo, f_hi = band["lower"], lm4651.DATASHEET["f_min"], lm4651.DATASHEET["f_max"]
    if band["f_clip"] < f_lo:
        p_max = lm4651.p_clip(f_lo, s["r_load"], s["supply"])
        raise Infeasible(f"{s['p_out']:g} W clips into {s['r_load']:g} ohm at +-{s['supply']:g} V even at "
                         f"{f_lo / 1e3:g} kHz: at most {p_max:.0f} W", {"p_out_max": p_max})
    if band["f_thd"] > f_hi:
        raise Infeasible(f"THD+N {s['thd_max']:.3%} needs f_sw >= {band['f_thd'] / 1e3:.0f} kHz, above the "
                         f"{f_hi / 1e3:g} kHz limit; at {f_hi / 1e3:g} kHz the model gives {lm4651.thd_n(f_hi):.3%}",
                         {"thd_min": lm4651.thd_n(f_hi)})
    if band["f_thd"] > band["f_clip"]:
        raise Infeasible(
            f"THD+N {s['thd_max']:.3%} needs f_sw >= {band['f_thd'] / 1e3:.1f} kHz but {s['p_out']:g} W without "
            f"clipping needs f_sw <= {band['f_clip'] / 1e3:.1f} kHz: at {band['f_thd'] / 1e3:.1f} kHz at most "
            f"{lm4651.p_clip(lo, s['r_load'], s['supply']):.1f} W, or at {band['f_clip'] / 1e3:.1f} kHz THD+N "
            f"{lm4651.thd_n(band['f_clip']):.3%}",
            {"p_out_max": lm4651.p_clip(lo, s["r_load"], s["supply"]), "thd_min": lm4651.thd_n(band["f_clip"])})
    ev = class_d_evaluate(lo, {**s, "theta_sa_available": None})
    theta = lm4651.DATASHEET["theta_jc"][s["package"]] + s["theta_cs"] + s["theta_sa_available"]
    t_a_max = lm4651.DATASHEET["tj_max"] - ev["p_dissipation"] * theta
    raise Infeasible(
        f"with a {s['theta_sa_available']:g} K/W heat sink the LM4652 overheats at every allowed frequency: at "
        f"{lo / 1e3:.1f} kHz it dissipates {ev['p_dissipation']:.1f} W and needs a heat sink of "
        f"{ev['theta_sa_required']:.2f} K/W or better, or an ambient of at most {t_a_max:.0f} C",
        {"theta_sa_required": ev["theta_sa_required"], "t_ambient_max": t_a_max, "f_sw": lo})


def design_class_d(spec: dict | None = None) -> dict:
    """Highest efficiency at p_out subject to THD+N, clipping power and the heat sink.

    Problem (f in kHz, 50..225): minimise the LM4652's dissipation at p_out (eq 9, 10 and conduction)
    subject to THD+N(f) <= thd_max, P_clip(f) >= p_out, and with a given heat sink
    T_a + P_D (theta_JC + theta_CS + theta_SA) <= T_jmax. Then R_OSC from the series (eq 6 with the
    R_DLY correction), re-verified at the frequency that resistor really gives.
    """
    s = _class_d_checked(spec or {})
    f_lo, f_hi = lm4651.DATASHEET["f_min"], lm4651.DATASHEET["f_max"]
    band = class_d_band(s)
    if band["lower"] > band["upper"] * (1 + 1e-9):
        _class_d_infeasible(s, band)
    x = ca.SX.sym("f_kHz")
    f = x * 1e3
    p4652 = lm4651.p_switch(f, s["p_out"]) + lm4651.p_conduction(s["p_out"], s["r_load"])
    cons = [("thd", lm4651.thd_n(f) / s["thd_max"], -ca.inf, 1.0),
            ("clipping", lm4651.p_clip(f, s["r_load"], s["supply"]) / s["p_out"], 1.0, ca.inf)]
    if s["theta_sa_available"] is not None:
        cons.append(("heat_sink", lm4651.t_junction(p4652, s["t_ambient"], s["theta_sa_available"], s["package"],
                                                    s["theta_cs"]) / lm4651.DATASHEET["tj_max"], -ca.inf, 1.0))
    sol = minimise(p4652, x, cons, x0=[0.5 * (band["lower"] + band["upper"]) / 1e3], lbx=[f_lo / 1e3], ubx=[f_hi / 1e3])
    f_star = float(sol.x[0]) * 1e3
    # snap R_OSC: the series value whose real frequency lies in the band with the best efficiency (the
    # lowest frequency); the neighbours of the ideal resistor are tried first, then the whole series
    ideal = lm4651.r_osc_for(f_star, s["r_dly"])
    near = [series.at_most(s["r_osc_series"], ideal), series.at_least(s["r_osc_series"], ideal)]
    rows = []
    for pool in (near, series.values(s["r_osc_series"], 10.0, 1e6)):
        for r in pool:
            f_real = lm4651.f_sw_for(r, s["r_dly"])
            if f_lo <= f_real <= f_hi:
                ev = class_d_evaluate(f_real, s)
                if ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"]:
                    rows.append((ev["efficiency"], r, ev))
        if rows:
            break
    if not rows:
        raise Infeasible(
            f"the feasible band {band['lower'] / 1e3:.2f} to {band['upper'] / 1e3:.2f} kHz holds no {s['r_osc_series']} "
            f"R_OSC (ideal {ideal:.0f} ohm gives {f_star / 1e3:.2f} kHz): use a finer series or relax THD+N",
            {"f_sw": f_star, "r_osc_ideal": ideal, "band": (band["lower"], band["upper"])})
    eff, r_osc, ev = max(rows, key=lambda t: t[0])
    names = {"thd": "THD+N limit at the test point", "clipping": "clipping power at 1 % THD",
             "heat_sink": "junction temperature with the given heat sink"}
    binding = [names[b] for b in sol.binding(1e-8)]
    return {
        "f_sw": ev["f_sw"], "r_osc": r_osc, "efficiency": ev["efficiency"], "p_dissipation": ev["p_dissipation"],
        "p_total": ev["p_total"], "theta_sa_required": ev["theta_sa_required"], "t_junction": ev["t_junction"],
        "thd_n": ev["thd_n"], "p_clip": ev["p_clip"],
        "binding": binding[0] if binding else "none (efficiency is best at the lowest frequency allowed)",
        "f_continuous": f_star, "band": (band["lower"], band["upper"]), "spec": s,
    }


def class_d_enumerate(s: dict):
    """Exhaustive: the series R_OSC whose real frequency re-verifies with the best efficiency, or None."""
    s = _class_d_checked(s)
    best = None
    for r in series.values(s["r_osc_series"], 10.0, 1e6):
        f = lm4651.f_sw_for(r, s["r_dly"])
        if lm4651.DATASHEET["f_min"] <= f <= lm4651.DATASHEET["f_max"]:
            ev = class_d_evaluate(f, s)
            if ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"] and (best is None or ev["efficiency"] > best[0]):
                best = (ev["efficiency"], r)
    return None if best is None else best[1]
