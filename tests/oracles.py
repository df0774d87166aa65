"""Independent oracles the tests share: every tolerance corner and every series value, written out here
from the circuit laws, sharing no code with handbook.design (a check built on the design's own formula
would check nothing)."""
import itertools

import numpy as np
from scipy.optimize import fsolve

from handbook.core import series
from handbook.design.schema import defaults


def _corner_values(f, **ranges):
    """f at every corner of the box (each argument at either end of its (low, high) range)."""
    names = list(ranges)
    return [f(**dict(zip(names, ends))) for ends in itertools.product(*(ranges[n] for n in names))]


def enumerate_cap(spec):
    """CAP-CD: the first series value (1 pF up) whose swing I t_com / C fits V_high - V_low at all 16 corners
    at rpm_min; None unless its swing at rpm_max stays above the floor at all 4 corners."""
    s = {**defaults("commutation"), **spec}
    tol, n = s["tolerance"], s["pole_pairs"]
    t_slow, t_fast = 10 / (s["rpm_min"] * n), 10 / (s["rpm_max"] * n)
    currents = (s["i_charge_min"], s["i_charge_max"])
    for c in series.values(s["series"], 1e-12, 1e-3):
        caps = (c * (1 - tol), c * (1 + tol))
        excess = _corner_values(lambda i, k, vl, vh: i * t_slow / k - (vh - vl), i=currents, k=caps,
                                vl=(s["v_low_min"], s["v_low_max"]), vh=(s["v_high_min"], s["v_high_max"]))
        if max(excess) <= 1e-12:
            swings = _corner_values(lambda i, k: i * t_fast / k, i=currents, k=caps)
            return c if min(swings) >= s["min_excursion"] * (1 - 1e-12) else None
    return None


def enumerate_cap_st(spec):
    """CAP-ST: the first series value whose shortest start period 2 C dV / I (32 corners with the motor's)
    outlasts the rocking's decay ln(1/r) / sigma, sigma = w_n (zeta - sqrt(zeta^2 - 1) if overdamped),
    w_n = sqrt(K_t I p / J); None if its longest period then exceeds t_start_max."""
    s = {**defaults("commutation"), **spec}
    tol, mt, z = s["tolerance"], s["motor_tolerance"], s["damping_ratio"]
    spread = lambda x, t: (x * (1 - t), x * (1 + t))  # noqa: E731
    w_n = _corner_values(lambda k, i, j: (k * i * s["pole_pairs"] / j) ** 0.5, k=spread(s["torque_constant"], mt),
                         i=spread(s["start_current"], mt), j=spread(s["inertia"], mt))
    settle = max(np.log(1 / s["residual"]) / (w * (z - max(z * z - 1, 0) ** 0.5)) for w in w_n)
    dv = s["v_st_high"] - s["v_st_low"]
    for c in series.values(s["series"], 1e-12, 1e-3):
        periods = _corner_values(lambda k, i: 2 * k * dv / i, k=spread(c, tol), i=(s["i_st_min"], s["i_st_max"]))
        if min(periods) >= settle * (1 - 1e-12):
            ok = s["t_start_max"] is None or max(periods) <= s["t_start_max"] * (1 + 1e-12)
            return c if ok else None
    return None


def enumerate_cap_ti(spec):
    """CAP-TI (>= 2000 pF): watchdog C 1.9 V / I at 4 corners; shortest >= flyback_time; with rpm_reverse the
    longest <= 150 electrical degrees of reverse travel, 25 / (rpm n), and the value with the largest smaller
    ratio. None if no value passes."""
    s = {**defaults("commutation"), **spec}
    tol, n = s["tolerance"], s["pole_pairs"]
    t_rev = None if s["rpm_reverse"] is None else 25 / (s["rpm_reverse"] * n)
    best = None
    for c in series.values(s["series"], 2e-9, 1e-3):
        t_wd = _corner_values(lambda k, i: k * 1.9 / i, k=(c * (1 - tol), c * (1 + tol)),
                              i=(s["i_wd_min"], s["i_wd_max"]))
        if min(t_wd) < s["flyback_time"] * (1 - 1e-12) or (t_rev is not None and max(t_wd) > t_rev * (1 + 1e-12)):
            continue
        if t_rev is None:
            return c
        score = min(min(t_wd) / s["flyback_time"], t_rev / max(t_wd))
        if best is None or score > best[0]:
            best = (score, c)
    return None if best is None else best[1]


def limiter_corners(r7, network, s):
    """Every corner of the op-amp limiter (R7, R9..R13 at either end, the zener at either end, the offset at
    either sign, and the two bias currents at every vertex of their parallelogram: their average within
    +-I_b, their difference within +-I_os, as op-amp datasheets define the two), written from the node
    equations: V_+ = Z + (V_D1 - V_cs) R13/(R12 + R13) + I_p R12||R13 and V_- = Z + V_D1 R11/(R9 + R10 + R11)
    + I_m (R9 + R10)||R11 meet at V_+ - V_- = V_os.
    ``network`` = (R9, R10, R11, R12, R13), each a float or an array (networks side by side).
    Returns (lowest trip current, highest trip current, least headroom of the two inputs, most current
    both dividers draw from the zener node), all exact."""
    t, ib = s["resistor_tolerance"], s["input_bias"]
    ios = s["input_offset_current"]
    vz0, dz = s["zener_voltage"], s["zener_voltage"] * s["zener_tolerance"] + s["zener_tc"] * s["temp_span"]
    # the datasheet's definitions: the inputs' average within +-I_b, their difference within +-I_os (the
    # parallelogram's four vertices)
    biases = [(avg + d / 2, avg - d / 2) for avg in (-ib, ib) for d in (-ios, ios)]
    net = [np.asarray(x, dtype=float) for x in network]
    v_lo = np.full(np.broadcast(*net).shape, np.inf)
    v_hi, head, i_div = -v_lo, v_lo.copy(), -v_lo
    for sg in itertools.product((-1.0, 1.0), repeat=5):
        r9, r10, r11, r12, r13 = (x * (1 + t * g) for x, g in zip(net, sg))
        a, k = r13 / (r12 + r13), r11 / (r9 + r10 + r11)
        r_plus, r_minus = r12 * r13 / (r12 + r13), (r9 + r10) * r11 / (r9 + r10 + r11)
        for vz in (vz0 - dz, vz0 + dz):
            i_div = np.maximum(i_div, vz / (r9 + r10 + r11) + vz / (r12 + r13))
            for i_p, i_m in biases:
                head = np.minimum(head, np.minimum(vz - vz * a - i_p * r_plus, vz - vz * k - i_m * r_minus))
                for vos in (-s["offset"], s["offset"]):
                    v_cs = vz - (vz * k + i_m * r_minus - i_p * r_plus + vos) / a
                    v_lo, v_hi = np.minimum(v_lo, v_cs), np.maximum(v_hi, v_cs)
    # I = V_cs / R7 rises with V_cs for either end of R7 (> 0): its extremes are V_cs's over both ends
    ends = (r7 * (1 - s["r7_tolerance"]), r7 * (1 + s["r7_tolerance"]))
    i_lo = np.minimum(v_lo / ends[0], v_lo / ends[1])
    i_hi = np.maximum(v_hi / ends[0], v_hi / ends[1])
    return i_lo, i_hi, head, i_div


def enumerate_limiter(spec):
    """Exhaustive: every network of the (reduced) series and every R7; (r7, network, worst margin) of the
    smallest feasible R7 and, with it, the largest worst margin; None when nothing is feasible."""
    s = {**defaults("current_limiter"), **spec}
    lists = [[s[n]] if s.get(n) is not None else series.values(s[n + "_series"], s[n + "_min"], s[n + "_max"])
             for n in ("r7", "r9", "r10", "r11", "r12", "r13")]
    grid = np.array(np.meshgrid(*lists[1:], indexing="ij")).reshape(5, -1)
    lo, hi, head, i_div = limiter_corners(1.0, grid, s)  # trip currents scale as 1/R7
    best = None
    for r7 in lists[0]:
        worst = np.minimum(lo / r7 / s["i_no_trip"] - 1, 1 - hi / r7 / s["i_must_trip"])
        ok = ((worst >= s["min_margin"] - 1e-12) & (head >= s["input_headroom"] - 1e-12) & (lo > 0)
              & (i_div <= s["divider_current_max"] * (1 + 1e-12)))
        if ok.any():
            j = int(np.argmax(np.where(ok, worst, -np.inf)))
            best = (r7, tuple(float(x) for x in grid[:, j]), float(worst[j]))
            break
    return best


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


def _class_d_heat(s, f):
    """theta_SA needed at oscillator frequency f: T_j at 150 C less the margin, R_DS(on) 300 mOhm max at 25 C
    rising as the datasheet's 200 -> 230 mOhm (25 -> 100 C), eq 9/10 with 25 + 26 + 350 ns, and the idle
    loss of 55 % at 5 W less the LM4651's own 36 mA."""
    p = p_clip(f, s["r_load"], s["supply"])  # the clipping power, whole or its eighth (IEC 62368-1 Annex E)
    p = p / 8 if s["thermal_basis"] == "iec_1_8" else p if s["p_continuous"] is None else s["p_continuous"]
    t_j = 150.0 - s["tj_margin"]
    x = (25e-9 + 26e-9 + s["t_overmod"]) * f
    x5 = (25e-9 + 26e-9 + 310e-9) * 125e3
    # the LM4651's own idle: its 36 mA is |I+| + |I-| (the table's definition), drawn from +-V_s: V_s x 36 mA
    idle = (5 / 0.55 - 5 - 5 / 4 * 2 * 0.2 - x5 * 5 / (1 - x5)) * s["supply"] / 20 - 0.036 * s["supply"]
    watts = x * p / (1 - x) + idle + p / s["r_load"] * 2 * s["rds_on_25"] * (1 + 0.15 / 75 * (t_j - 25))
    return (t_j - s["t_ambient"]) / watts - {"TF": 2.0, "T": 1.0}[s["package"]] - s["theta_cs"]


def _band_ok(s, L, C):
    """Loaded filter |H| across 0..f_audio by a dense sweep (not the closed form), and its Q, per (L, C)."""
    f = np.linspace(0, s["f_audio"], 801)
    h = np.abs(1 / (1 + 2j * np.pi * f * 2 * L[..., None] / s["r_load"]
                    - (2 * np.pi * f) ** 2 * 2 * L[..., None] * C[..., None]))
    dev = 20 * np.abs(np.log10(h)).max(-1)
    q = s["r_load"] * np.sqrt(C / (2 * L))
    return (dev <= s["droop_max"] * (1 + 1e-9)) & (q <= s["q_max"] * (1 + 1e-9))


def _peak_inside_box_ok(s, L, C):
    """The largest |H| over 0..f_audio and the whole tolerance box, per nominal (L, C): with y = w^2,
    |H|^-2 = 1 + y (4 L^2/R^2 - 4 L C) + 4 L^2 C^2 y^2, a parabola in y minimised in closed form on
    [0, w_audio^2]; C y appears only as a product beside y alone, so the largest C is the worst (any
    (C, y) does no better than (C_max, C y / C_max)); L is swept over its tolerance on 401 points."""
    y_top, r = (2 * np.pi * s["f_audio"]) ** 2, s["r_load"]
    c = C * (1 + s["c_tolerance"])
    least = np.full(np.shape(L), np.inf)
    for k in np.linspace(1 - s["l_tolerance"], 1 + s["l_tolerance"], 401):
        lk = L * k
        lin, quad = 4 * lk ** 2 / r ** 2 - 4 * lk * c, 4 * lk ** 2 * c ** 2
        y = np.clip(-lin / (2 * quad), 0, y_top)
        least = np.minimum(least, 1 + lin * y + quad * y * y)
    return -10 * np.log10(least) <= s["droop_max"] * (1 + 1e-9)


def enumerate_class_d(spec):
    """Every series R_OSC x L x C_BYP at all eight corners (oscillator -20 %/+23.5 % on eq 5 with R_OSC and R_DLY
    at their +-1 % ends, L and C +-tolerance), the rails at five points across +-supply_tolerance (not only its
    ends: nothing here assumes a figure monotonic in V_s), the filter's peaking over the whole L, C box: the best
    feasible (R_OSC, L, C, R_DLY), or None. Written from the datasheet's numbers alone (THD+N: 0.3 % at 10 W in a
    10 Hz..80 kHz band)."""
    s = {**defaults("class_d"), **spec}
    t = s["r_tolerance"]
    r_dly = next(r for r in [0.0] + series.values(s["r_dly_series"], 1, 1e6)
                 if 27e-9 + 1.7e-12 * r * (1 - t) >= s["dead_time_min"] * (1 - 1e-12))
    r = np.array(series.values(s["r_osc_series"], 100, 1e5))
    # eq 5 at the resistors' ends: slowest with R_OSC high and R_DLY low, times the table's spread
    f_lo = (1 - s["osc_tol_slow"]) * 1e9 / (4000 + r * (1 + t) - 0.4 * r_dly * (1 - t))
    f_hi = (1 + s["osc_tol_fast"]) * 1e9 / (4000 + r * (1 - t) - 0.4 * r_dly * (1 + t))
    keep = (f_lo > 0) & (f_hi > 0) & (f_lo >= 50e3 * (1 - 1e-12)) & (f_hi <= 225e3 * (1 + 1e-12))
    r, f_lo, f_hi = r[keep], f_lo[keep], f_hi[keep]
    ls, cs = np.array(series.values(s["l_series"], 1e-6, 1e-3)), np.array(series.values(s["c_series"], 1e-7, 1e-4))
    R, L, C = np.meshgrid(r, ls, cs, indexing="ij")
    F = 1e9 / (4000 + R - 0.4 * r_dly)
    slow, fast = np.meshgrid(f_lo, ls, cs, indexing="ij")[0], np.meshgrid(f_hi, ls, cs, indexing="ij")[0]
    ok = np.ones(F.shape, dtype=bool)
    rl, st = s["r_load"], s.get("supply_tolerance", 0.0)
    rails = s["supply"] * np.linspace(1 - st, 1 + st, 5 if st else 1)
    for v, so, sl, sc in itertools.product(rails, (slow, fast), (-1, 1), (-1, 1)):
        fc, lc, cc = so, L * (1 + sl * s["l_tolerance"]), C * (1 + sc * s["c_tolerance"])
        w = 2 * np.pi * fc
        thd = 0.003 * (125e3 / fc) ** 2 * (250e-12 / (lc * cc)) * v / 20 * np.sqrt(40 / (s["thd_test_power"] * rl))
        h = np.abs(1 / (1 + 1j * w * 2 * lc / rl - w ** 2 * 2 * lc * cc))
        ripple = 4 * 2 * v / np.pi * h / np.sqrt(2)
        # an analyser whose band (brick wall) reaches the switching fundamental reads the ripple too
        in_band = np.where(fc < s["thd_bandwidth"], ripple / np.sqrt(s["thd_test_power"] * rl), 0.0)
        thd = np.sqrt(thd ** 2 + in_band ** 2)
        v_pk = np.sqrt(2 * rl * p_clip(fc, rl, v))
        i_pk = v_pk * np.hypot(1 / rl, 2 * np.pi * s["f_audio"] * cc) + v / (4 * lc * fc)
        ok &= (thd <= s["thd_max"] * (1 + 1e-9)) & (ripple <= s["ripple_max"] * (1 + 1e-9))
        ok &= i_pk * 1.2 <= min(s["i_sat"], 12.0) * (1 + 1e-9)  # 1.2: the saturation margin
    for sl, sc in itertools.product((-1, 1), (-1, 1)):  # the filter alone: on the (L, C) plane
        l2, c2 = np.meshgrid(ls * (1 + sl * s["l_tolerance"]), cs * (1 + sc * s["c_tolerance"]), indexing="ij")
        ok &= _band_ok(s, l2, c2)[None]
    ok &= _peak_inside_box_ok(s, *np.meshgrid(ls, cs, indexing="ij"))[None]
    theta = np.min([_class_d_heat({**s, "supply": v}, f) for v in rails for f in (slow, fast)], axis=0)
    sink = 0.0 if s["theta_sa_available"] is None else s["theta_sa_available"]
    unclipped = max(s["p_out"], s["thd_test_power"])  # the THD+N test point must not clip either
    clip = np.min([p_clip(fast, rl, v) for v in rails], axis=0)
    ok &= (clip >= unclipped * (1 - 1e-9)) & (theta >= sink * (1 + 1e-9) - 1e-12)
    v = s["supply"]  # the efficiency at the nominal rails
    p = s["p_out"]
    x = (25e-9 + 26e-9 + 310e-9) * F
    x5 = (25e-9 + 26e-9 + 310e-9) * 125e3
    idle = (5 / 0.55 - 5 - 0.5 - x5 * 5 / (1 - x5)) * v / 20
    eff = p / (p + p / rl * 2 * 0.230 + x * p / (1 - x) + idle + p / rl * 2 * s["l_dcr"] * L)
    if not ok.any():
        return None
    keys = (eff, theta) if s["objective"] == "efficiency" else (theta, eff)
    i = np.lexsort((C[ok], L[ok], -keys[1][ok], -keys[0][ok]))[0]
    return float(R[ok][i]), float(L[ok][i]), float(C[ok][i]), float(r_dly)
