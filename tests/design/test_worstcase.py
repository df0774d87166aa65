"""The worst-case analysis (handbook.design.worstcase): its EVA is the designs' own corners, it bounds every
Monte Carlo board, its yields agree with estimates written here independently, and it is deterministic."""
import functools
import math
from types import SimpleNamespace

import numpy as np
import pytest

from handbook.design import class_d, commutation, converter, limiter
from handbook.design import worstcase as wc

DESIGNS = {"commutation": commutation, "current_limiter": limiter, "class_d": class_d, "converter": converter}


@functools.cache
def designed(table):
    return DESIGNS[table].design(None)


@functools.cache
def analysed(table):
    return wc.analyse(table, designed(table), n=100_000, seed=1)


@pytest.mark.parametrize("table", list(DESIGNS))
def test_eva_bounds_every_monte_carlo_board(table):
    """Every quantity is monotonic in each input over its range, so its extremes lie at corners: no board of the
    lot lies outside EVA (nor the MC quantiles, nor nominal)."""
    w = analysed(table)
    for q in w.quantities:
        x = w.samples[q.key]
        assert x.shape == (w.n,)
        slack = 1e-12 * max(abs(q.eva_low), abs(q.eva_high))
        assert q.eva_low - slack <= x.min() and x.max() <= q.eva_high + slack, q.key
        assert q.eva_low <= q.mc_low <= q.mc_high <= q.eva_high, q.key
        assert q.eva_low <= q.nominal <= q.eva_high, q.key


def test_eva_is_the_designs_own_corners():
    """The corners here give the extremes each design reports from its own enumeration."""
    lim = designed("current_limiter")
    w = analysed("current_limiter")
    assert w.quantity("i_trip_low").eva_low == pytest.approx(lim.i_trip_min, rel=1e-12)
    assert w.quantity("i_trip_high").eva_high == pytest.approx(lim.i_trip_max, rel=1e-12)
    assert w.quantity("headroom").eva_low == pytest.approx(lim.headroom_min, rel=1e-12)
    com = designed("commutation")
    w = analysed("commutation")
    assert w.quantity("swing_rpm_min").eva_high == pytest.approx(com.swing_at_rpm_min, rel=1e-12)
    assert w.quantity("swing_rpm_max").eva_low == pytest.approx(com.swing_at_rpm_max, rel=1e-12)
    cd = designed("class_d")
    w = analysed("class_d")
    assert (w.quantity("f_sw").eva_low, w.quantity("f_sw").eva_high) == pytest.approx((cd.f_sw_min, cd.f_sw_max))
    assert w.quantity("thd_n").eva_high == pytest.approx(cd.thd_n, rel=1e-12)
    assert w.quantity("f_corner").nominal == pytest.approx(cd.f_corner, rel=1e-12)
    # rails with a tolerance: an input of their own; EVA's corners equal the design's rail ends
    rails = class_d.design({"supply_tolerance": 0.05, "p_out": 110.0})
    w = wc.analyse("class_d", rails, n=20_000, seed=1)
    (v_s,) = [d for d in w.distributions if d.part == "±V_S rails"]
    assert (v_s.low, v_s.high) == pytest.approx((19.0, 21.0)) and v_s.unit == "V"
    assert w.quantity("p_clip").eva_low == pytest.approx(rails.p_clip, rel=1e-12)
    assert w.quantity("thd_n").eva_high == pytest.approx(rails.thd_n, rel=1e-12)
    assert w.quantity("i_peak").eva_high == pytest.approx(rails.figures["i_peak"], rel=1e-12)
    assert w.quantity("ripple").eva_high == pytest.approx(rails.figures["ripple"], rel=1e-12)
    # the converter's corners are R1, A_L and the TCA5600's V12(H), V_CE(sat) and V_F at +-device_spread, the
    # spread the design assumed: EVA is the design's own least current, f_min and lowest frequency, with the
    # spread as given, none or wide
    for spread in (None, 0.0, 0.3):
        cv = designed("converter") if spread is None else converter.design({"device_spread": spread})
        w = analysed("converter") if spread is None else wc.analyse("converter", cv, n=20_000, seed=1)
        assert w.quantity("f_sw_low").eva_low == pytest.approx(cv.f_sw_min, rel=1e-9)
        assert w.quantity("f_sw_vmin").eva_low == pytest.approx(cv.f_min_design, rel=1e-9)
        assert w.quantity("i_out_max").eva_low == pytest.approx(cv.i_out_least, rel=1e-12)
        assert cv.i_out_least >= cv.spec["i_out"]
        assert w.yield_all == 1.0  # the design's corners hold every limit, so every board does


@pytest.mark.parametrize("table", list(DESIGNS))
def test_same_seed_same_numbers(table):
    r = designed(table)
    a, b = wc.analyse(table, r, n=5_000, seed=7), wc.analyse(table, r, n=5_000, seed=7)
    c = wc.analyse(table, r, n=5_000, seed=8)
    assert a.quantities == b.quantities and a.yields == b.yields and a.sensitivity == b.sensitivity
    for key in a.samples:
        assert np.array_equal(a.samples[key], b.samples[key])
    assert any(not np.array_equal(a.samples[k], c.samples[k]) for k in a.samples)
    assert (a.n, a.seed) == (5_000, 7)


def _limiter_trip(r7, r9, r10, r11, r12, r13, vz, vos, i_plus, i_minus):
    """The trip current from the two node equations solved here by hand (AN94002 eq 11 and 12 plus the op-amp's
    errors): V+ - V- = V_os with V+ = Z + (V_D1 - V_cs) R13/(R12 + R13) + I+ R12 R13/(R12 + R13) and
    V- = Z + V_D1 R11/(R9 + R10 + R11) + I- (R9 + R10) R11/(R9 + R10 + R11), linear in V_cs."""
    v_minus = vz * r11 / (r9 + r10 + r11) + i_minus * (r9 + r10) * r11 / (r9 + r10 + r11)
    k = r13 / (r12 + r13)
    v_cs = vz - (v_minus + vos - i_plus * r12 * k) / k
    return v_cs / r7


def test_limiter_yield_matches_a_plain_python_loop():
    """A tightened window on the designed network (the default's yield is 1.0, which tells nothing): the same
    documented draws, each board by a plain loop over the node equations at both ends of its temperature span."""
    lim = designed("current_limiter")
    s = {**lim.spec, "i_no_trip": 1.15, "i_must_trip": 1.45}
    result = SimpleNamespace(r7=lim.r7, network=lim.network, spec=s)
    n, seed = 3_000, 5
    w = wc.analyse("current_limiter", result, n=n, seed=seed)
    rng = np.random.default_rng(seed)  # the documented order: R7, R9..R13, V_Z, |tc|, V_os, I_avg, I_diff
    t, t7 = s["resistor_tolerance"], s["r7_tolerance"]
    draws = [rng.uniform(lim.r7 * (1 - t7), lim.r7 * (1 + t7), n)]
    draws += [rng.uniform(r * (1 - t), r * (1 + t), n) for r in lim.network]
    draws += [rng.uniform(s["zener_voltage"] * (1 - s["zener_tolerance"]), s["zener_voltage"] * (1 + s["zener_tolerance"]), n),
              rng.uniform(0.03 / 0.08 * s["zener_tc"], s["zener_tc"], n),  # BZX79: +0.03 .. +0.08 %/K
              rng.uniform(-s["offset"], s["offset"], n),
              rng.uniform(-s["input_bias"], s["input_bias"], n),
              rng.uniform(-s["input_offset_current"], s["input_offset_current"], n)]
    low_ok = high_ok = 0
    for r7, r9, r10, r11, r12, r13, vz, tc, vos, i_avg, i_diff in zip(*draws):
        ip, im = i_avg + i_diff / 2, i_avg - i_diff / 2
        trips = [_limiter_trip(r7, r9, r10, r11, r12, r13, vz + sign * tc * s["temp_span"], vos, ip, im)
                 for sign in (-1, 1)]
        low_ok += min(trips) >= s["i_no_trip"]
        high_ok += max(trips) <= s["i_must_trip"]
    assert 0.5 < w.yields["i_no_trip"] < 0.999 and 0.5 < w.yields["i_must_trip"] < 0.999  # the limits bite
    assert w.yields["i_no_trip"] == pytest.approx(low_ok / n, abs=1.5 / n)  # a tie at the limit, at most
    assert w.yields["i_must_trip"] == pytest.approx(high_ok / n, abs=1.5 / n)


def test_limiter_yield_matches_a_lot_of_its_own():
    """The same question on a lot the engine did not draw: the test's own sampler (another generator, another
    seed, every input scaled from one matrix of uniforms in its own order, the ranges written from the spec here)
    through the node equations at both ends of each board's temperature span. Two independent lots of one
    design agree within four standard deviations of their difference; a wrong range or distribution in the
    engine would move its yield by more."""
    lim = designed("current_limiter")
    s = {**lim.spec, "i_no_trip": 1.15, "i_must_trip": 1.45}
    n = 200_000
    w = wc.analyse("current_limiter", SimpleNamespace(r7=lim.r7, network=lim.network, spec=s), n=n, seed=11)
    t, t7, vz, tc = s["resistor_tolerance"], s["r7_tolerance"], s["zener_voltage"], s["zener_tc"]
    ranges = [(lim.r7 * (1 - t7), lim.r7 * (1 + t7))] + [(r * (1 - t), r * (1 + t)) for r in lim.network]
    ranges += [(vz * (1 - s["zener_tolerance"]), vz * (1 + s["zener_tolerance"])),
               (0.03 / 0.08 * tc, tc),  # the BZX79's +0.03 .. +0.08 %/K
               (-s["offset"], s["offset"]), (-s["input_bias"], s["input_bias"]),
               (-s["input_offset_current"], s["input_offset_current"])]
    u = np.random.Generator(np.random.PCG64DXSM(20261127)).random((len(ranges), n))[::-1]  # reversed order
    r7, r9, r10, r11, r12, r13, v_z, k, vos, i_avg, i_diff = (lo + (hi - lo) * x for (lo, hi), x in zip(ranges, u))
    ip, im = i_avg + i_diff / 2, i_avg - i_diff / 2
    cold, hot = (_limiter_trip(r7, r9, r10, r11, r12, r13, v_z + sign * k * s["temp_span"], vos, ip, im)
                 for sign in (-1, 1))
    mine = {"i_no_trip": float((np.minimum(cold, hot) >= s["i_no_trip"]).mean()),
            "i_must_trip": float((np.maximum(cold, hot) <= s["i_must_trip"]).mean())}
    for limit, p in mine.items():
        assert 0.5 < p < 0.999  # the limit bites
        assert w.yields[limit] == pytest.approx(p, abs=4 * math.sqrt(2 * p * (1 - p) / n)), limit


def test_commutation_yield_matches_a_closed_form():
    """P(swing at rpm_max >= floor) = P(I >= floor C / t_fast), I and C independent uniforms: the integral over
    C of I's tail, by the midpoint rule on a fine grid; a floor that bites."""
    com = designed("commutation")
    s = {**com.spec, "min_excursion": 0.4}
    result = SimpleNamespace(cap_cd=com.cap_cd, spec=s)
    w = wc.analyse("commutation", result, n=200_000, seed=3)
    t_fast = 10 / (s["rpm_max"] * s["pole_pairs"])  # eq 4: six commutations per electrical cycle
    c_lo, c_hi = com.cap_cd * (1 - s["tolerance"]), com.cap_cd * (1 + s["tolerance"])
    cs = c_lo + (np.arange(100_000) + 0.5) / 100_000 * (c_hi - c_lo)
    a, b = s["i_charge_min"], s["i_charge_max"]
    p = float(np.clip((b - s["min_excursion"] * cs / t_fast) / (b - a), 0, 1).mean())
    assert 0.2 < p < 0.98
    assert w.yields["min_excursion"] == pytest.approx(p, abs=4 * math.sqrt(p * (1 - p) / w.n))


def test_class_d_yield_matches_a_closed_form():
    """P(Q <= q_max), Q = R_L sqrt(C / 2L): P(C <= 2 L q_max^2 / R_L^2) integrated over L (midpoint rule)."""
    cd = designed("class_d")
    s = {**cd.spec, "q_max": 0.9}
    result = SimpleNamespace(r_osc=cd.r_osc, r_dly=cd.r_dly, l_out=cd.l_out, c_out=cd.c_out, spec=s)
    w = wc.analyse("class_d", result, n=200_000, seed=4)
    ls = cd.l_out * (1 + s["l_tolerance"] * (2 * (np.arange(100_000) + 0.5) / 100_000 - 1))
    c_lo, c_hi = cd.c_out * (1 - s["c_tolerance"]), cd.c_out * (1 + s["c_tolerance"])
    p = float(np.clip((2 * ls * s["q_max"] ** 2 / s["r_load"] ** 2 - c_lo) / (c_hi - c_lo), 0, 1).mean())
    assert 0.2 < p < 0.98
    assert w.yields["q_max"] == pytest.approx(p, abs=4 * math.sqrt(p * (1 - p) / w.n))


def test_converter_yield_matches_the_linearised_sum_of_uniforms():
    """A converter designed assuming no device spread (device_spread = 0: R1 = 1.91 ohm), built from TCA5600s
    whose V12(H), V_CE(sat) and V_F spread +-10 %: the lot misses i_out on some boards. The delivered current
    I = V12(H)/R1 / 2 x V_L- / (V_L- + V_L+) (written here from eq 1, 2 and 5), nearly linear over its inputs'
    ranges: I ~ nominal + sum of e_k u_k, u_k uniform in -1..1, e_k each input's half-swing. P(I >= i_out) from
    the exact density of that sum (the uniforms' densities convolved on a grid); within 0.01 (what the
    linearisation leaves out, and the lot's noise)."""
    cv = converter.design({"device_spread": 0.0})
    s = {**cv.spec, "device_spread": 0.1}
    w = wc.analyse("converter", SimpleNamespace(spec=s, r1_part=cv.r1_part, l1_nominal=cv.l1_nominal), n=100_000, seed=1)
    assert cv.r1_part == pytest.approx(1.91)
    x = {"r1": cv.r1_part, "v12h": s["v12h"], "vce": s["v_ce_sat"], "vf": s["v_f"]}
    tol = {"r1": s["r1_tolerance"], "v12h": 0.1, "vce": 0.1, "vf": 0.1}

    def current(r1, v12h, vce, vf):
        minus = s["v_supply_min"] - vce - v12h
        plus = s["v_out"] + s["v_regulator_drop"] + vf - s["v_supply_min"]
        return v12h / r1 / 2 * minus / (minus + plus)

    nominal = current(**x)
    halves = [abs(current(**{**x, k: x[k] * (1 + tol[k])}) - current(**{**x, k: x[k] * (1 - tol[k])})) / 2 for k in x]
    step = sum(halves) / 4000
    density = np.array([1.0])
    for e in halves:
        m = max(1, round(e / step))
        density = np.convolve(density, np.full(2 * m + 1, 1.0 / (2 * m + 1)))
    grid = (np.arange(density.size) - density.size // 2) * step
    p = float(density[grid >= s["i_out"] - nominal].sum())
    assert 0.2 < w.yields["i_out"] < 0.98
    assert w.yields["i_out"] == pytest.approx(p, abs=0.01)


@pytest.mark.parametrize("table", list(DESIGNS))
def test_sensitivity_shares_and_halving(table):
    """The shares add to one, ranked; halving a tolerance never costs worst-case margin, nor yield beyond noise."""
    w = analysed(table)
    assert sum(x.share for x in w.sensitivity) == pytest.approx(1.0)
    assert [x.share for x in w.sensitivity] == sorted((x.share for x in w.sensitivity), reverse=True)
    base = min(q_margin for q_margin in _margins(w))
    for x in w.sensitivity:
        assert x.margin_if_halved >= base - 1e-12
        # halving a range about nominal moves some boards away from a limit (an input that pushes one quantity up
        # and another down, or a limit on either side), so the yield may fall, but only by noise here
        assert x.yield_if_halved >= w.yield_all - 5 * math.sqrt(w.yield_all * (1 - w.yield_all) / w.n)


def _margins(w):
    for q in w.quantities:
        if q.limit_low is not None:
            yield q.eva_low / q.limit_low - 1
        if q.limit_high is not None:
            yield 1 - q.eva_high / q.limit_high


@pytest.mark.parametrize("table", list(DESIGNS))
def test_distributions_and_drift_cite_their_sources(table):
    w = analysed(table)
    assert w.distributions and all(d.kind == "uniform" and d.low <= d.high and d.cite for d in w.distributions)
    assert w.drift and all(isinstance(x, str) and x for x in w.drift)
    assert w.binding in {q.key for q in w.quantities}


@functools.cache
def by_yield_design():
    return limiter.design({"criterion": "yield", "yield_min": 0.9999})


def test_a_design_by_yield_meets_yield_min_on_a_fresh_lot_ten_times_larger():
    """criterion = "yield": the lot the search accepted (seed 1, 100 000 boards) and a fresh one (seed 2, 10x the
    boards) both meet yield_min; the corners, reported beside it, are what the corners design would refuse."""
    from handbook.design.limiter import by_yield

    r, corners = by_yield_design(), designed("current_limiter")
    assert r.mc_yield is not None and 0 < r.box_scale < 1
    fresh = by_yield.lot_yield(r.r7, r.network, r.spec, n=10 * by_yield.N, seed=2)
    assert fresh >= r.spec["yield_min"], fresh
    assert r.r7 < corners.r7  # what the pessimism of the corners cost
    assert min(r.margin_low, r.margin_high) < r.spec["min_margin"]  # its corners, reported as they are
    assert any(w.startswith("criterion = yield") for w in r.warnings)
    assert corners.mc_yield is None and not any(w.startswith("criterion = yield") for w in corners.warnings)


def test_the_yield_acceptance_is_an_upper_bound_on_failures():
    from handbook.design.limiter import by_yield

    n = 100_000
    assert by_yield.meets(1.0, n, 0.9999) and not by_yield.meets(1 - 10 / n, n, 0.9999)
    assert not by_yield.meets(1 - 5 / n, n, 0.9999)  # 5 failures in 100 000: the rate may well be above 1e-4


@pytest.mark.parametrize("table", ["commutation", "current_limiter", "class_d", "converter"])
def test_rss_lies_inside_the_extreme_values(table):
    """One-sided RSS is never wider than the exact corners (the class-D oscillator's 0.8 .. 1.235 spread put the
    old symmetric RSS outside them), and it is as wide as the largest single input's move on each side."""
    for q in analysed(table).quantities:
        assert q.eva_low - 1e-12 * abs(q.eva_low) <= q.rss_low <= q.nominal <= q.rss_high
        assert q.rss_high <= q.eva_high + 1e-12 * abs(q.eva_high), q.key


def test_r1_drift_is_in_the_design_and_in_the_analysis_by_hand():
    """The default converter at 85 C: R1 may drift 100 ppm/K x 60 K = 0.6 % either way beyond its 1 % tolerance.
    The design sizes R1 with both (1.69 ohm, not the 1.74 ohm the tolerance alone allows); at the weak corner
    (V12(H) 0.36 V, V_L- 7.09 V, V_L+ 7.38 V, from eq 1 and 2 at 8 V) it delivers 0.36 / (1.69 x 1.01 x 1.006) / 2
    x 7.09 / 14.47 = 51.36 mA, and the analysis's extreme-value corner equals it (the drift an input of its own)."""
    from handbook.design.converter.operating import r1_drift
    from handbook.design.worstcase.models import r1_drift_sentence

    cv = converter.design()
    assert r1_drift(cv.spec) == pytest.approx(0.006) and cv.r1_part == pytest.approx(1.69)
    hand = 0.36 / (1.69 * 1.01 * 1.006) / 2 * 7.09 / (7.09 + 7.38)
    assert cv.i_out_least == pytest.approx(hand, rel=1e-3) and hand >= 0.05
    w = wc.analyse("converter", cv, n=10_000, seed=1)
    q = {x.key: x for x in w.quantities}["i_out_max"]
    assert q.eva_low == pytest.approx(cv.i_out_least, rel=1e-9)
    assert "R1 drift to t_ambient" in {d.part for d in w.distributions}
    assert "0.60 % from 25 °C to t_ambient = 85 °C" in r1_drift_sentence(cv) and "51.36 mA" in r1_drift_sentence(cv)
    cold = converter.design({"t_ambient": 25.0})  # no drift: a factor of 1, not an input
    assert r1_drift(cold.spec) == 0.0 and "R1 drift to t_ambient" not in {
        d.part for d in wc.analyse("converter", cold, n=1000, seed=1).distributions}


def test_each_limit_names_the_tolerance_that_moves_it_most():
    """The class-D filter's Q = R_L sqrt(C / (2 L)): to first order L's 10 % moves it by 5 %, C's 5 % by 2.5 %, so L
    carries 0.05^2 / (0.05^2 + 0.025^2) = 80 % of its spread; its worst case is L low, C high; the list runs from
    the least margin up."""
    cd = designed("class_d")
    w = analysed("class_d")
    rows = {x.key: x for x in w.by_limit}
    assert rows["q"].source == "inductor tolerance" and rows["q"].share == pytest.approx(0.8, abs=0.01)
    q_worst = 4 * math.sqrt(1.05 * cd.c_out / (2 * 0.9 * cd.l_out))
    assert rows["q"].margin == pytest.approx(1 - q_worst / cd.spec["q_max"], rel=1e-9)
    assert rows["p_clip"].source == "oscillator" and rows["dead_time"].source == "R_OSC, R_DLY tolerance"
    margins = [x.margin for x in w.by_limit]
    assert margins == sorted(margins) and w.by_limit[0].key == w.binding
    assert "f_corner" not in rows  # no limit, no row
