"""The worst case of CAP-ST (start oscillator) and CAP-TI (watchdog) in the commutation analysis, for the fan
example (book/examples/fan_motor.toml: motor data, flyback_time and rpm_reverse): its EVA bounds against the
corners written out here by hand (t = C dV / I, eq 2's sqrt(K_t I p / J) / 2 pi with the rocking's decay, 150
electrical degrees at rpm_reverse), and against the design's own corner figures; the Monte Carlo inside EVA; a
yield against a closed form; and a spec without motor data giving CAP-CD's quantities alone, as before."""
import math
import tomllib
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from handbook.design import commutation
from handbook.design import worstcase as wc

FAN = Path(__file__).resolve().parents[2] / "book" / "examples" / "fan_motor.toml"
#: the TDA5144's figures the schema defaults to (datasheet, June 1994; CAP-TI's 5 uA typical +-25 %), the
#: capacitor and motor tolerances, the rocking's damping ratio and residual, written here again
I_ST, V_ST, I_WD, V_TI = (1.5e-6, 2.5e-6), (0.2, 2.2), (3.75e-6, 6.25e-6), (0.3, 2.2)
TOL, MOTOR_TOL, ZETA, RESIDUAL = 0.05, 0.1, 0.1, 0.1
CAP_CD_KEYS = ("swing_rpm_min", "window_fill", "swing_rpm_max")


@pytest.fixture(scope="module")
def fan():
    table = tomllib.loads(FAN.read_text())["commutation"]
    r = commutation.design(table)
    return table, r, wc.analyse("commutation", r, n=100_000, seed=1)


def test_the_fan_spec_chooses_both_timers(fan):
    table, r, _ = fan
    assert {"inertia", "torque_constant", "start_current", "flyback_time", "rpm_reverse"} <= set(table)
    assert r.cap_st == pytest.approx(390e-9) and r.cap_ti == pytest.approx(8.2e-9)


def test_start_period_and_rocking_by_hand(fan):
    """Shortest start period 2 C (1 - tol) dV / I_max, longest 2 C (1 + tol) dV / I_min; the slowest rocking
    (K_t and I low, J high) decays to the residual in ln(1/residual) / (zeta 2 pi f) (zeta < 1)."""
    m, r, w = fan
    c, dv = r.cap_st, V_ST[1] - V_ST[0]
    p_min, p_max = 2 * c * (1 - TOL) * dv / I_ST[1], 2 * c * (1 + TOL) * dv / I_ST[0]
    f_slow = math.sqrt(m["torque_constant"] * (1 - MOTOR_TOL) * m["start_current"] * (1 - MOTOR_TOL)
                       * m["pole_pairs"] / (m["inertia"] * (1 + MOTOR_TOL))) / (2 * math.pi)
    f_fast = math.sqrt(m["torque_constant"] * (1 + MOTOR_TOL) * m["start_current"] * (1 + MOTOR_TOL)
                       * m["pole_pairs"] / (m["inertia"] * (1 - MOTOR_TOL))) / (2 * math.pi)
    settle_max, settle_min = (math.log(1 / RESIDUAL) / (ZETA * 2 * math.pi * f) for f in (f_slow, f_fast))
    period, settle, ratio = (w.quantity(k) for k in ("start_period", "rocking_settle", "start_settles"))
    assert (period.eva_low, period.eva_high) == pytest.approx((p_min, p_max), rel=1e-12)
    assert (settle.eva_low, settle.eva_high) == pytest.approx((settle_min, settle_max), rel=1e-12)
    assert (ratio.eva_low, ratio.eva_high) == pytest.approx((p_min / settle_max, p_max / settle_min), rel=1e-12)
    assert p_min == pytest.approx(0.5928, rel=1e-12) and (ratio.limit_low, ratio.limit_high) == (1.0, None)
    assert period.limit_high is None  # no t_start_max in the fan's spec


def test_watchdog_by_hand(fan):
    """Watchdog C dV / I: shortest C (1 - tol) 1.9 V / I_max against the flyback, longest C (1 + tol) 1.9 V / I_min
    against a rotor turning back 150 electrical degrees at rpm_reverse (p pole pairs: 150 / 360 of 60 / (rpm p))."""
    m, r, w = fan
    dv = V_TI[1] - V_TI[0]
    t_min, t_max = r.cap_ti * (1 - TOL) * dv / I_WD[1], r.cap_ti * (1 + TOL) * dv / I_WD[0]
    t_reverse = 150 / 360 * 60 / (m["rpm_reverse"] * m["pole_pairs"])
    wd, rev = w.quantity("watchdog_time"), w.quantity("reverse_over_watchdog")
    assert (wd.eva_low, wd.eva_high) == pytest.approx((t_min, t_max), rel=1e-12)
    assert (rev.eva_low, rev.eva_high) == pytest.approx((t_reverse / t_max, t_reverse / t_min), rel=1e-12)
    assert (wd.limit_low, wd.limit_high) == (m["flyback_time"], None) and (rev.limit_low, rev.limit_high) == (1.0, None)
    assert t_min == pytest.approx(2.36816e-3, rel=1e-12) and t_reverse == pytest.approx(1 / 24, rel=1e-12)


def test_eva_is_the_designs_own_corners(fan):
    """The consistency check: EVA gives the extremes check_start and check_watchdog report, and the margins the
    design states are the ratios' EVA margins."""
    _, r, w = fan
    st, wd = r.start, r.watchdog
    assert (w.quantity("start_period").eva_low, w.quantity("start_period").eva_high) == \
        pytest.approx((st.period_min, st.period_max), rel=1e-12)
    assert w.quantity("rocking_settle").eva_high == pytest.approx(st.settle, rel=1e-12)
    assert w.quantity("start_settles").eva_low - 1 == pytest.approx(st.margin, rel=1e-12)
    assert (w.quantity("watchdog_time").eva_low, w.quantity("watchdog_time").eva_high) == \
        pytest.approx((wd.t_wd_min, wd.t_wd_max), rel=1e-12)
    assert w.quantity("watchdog_time").eva_low / r.spec["flyback_time"] - 1 == pytest.approx(wd.margin_flyback, rel=1e-12)
    assert w.quantity("reverse_over_watchdog").eva_low - 1 == pytest.approx(wd.margin_reverse, rel=1e-12)


def test_monte_carlo_inside_eva_and_every_limit_met(fan):
    _, _, w = fan
    for q in w.quantities:
        x = w.samples[q.key]
        slack = 1e-12 * max(abs(q.eva_low), abs(q.eva_high))
        assert q.eva_low - slack <= x.min() <= q.mc_low <= q.mc_high <= x.max() <= q.eva_high + slack, q.key
        assert q.eva_low <= q.rss_low <= q.nominal <= q.rss_high <= q.eva_high, q.key
    assert set(w.yields) == {"window", "min_excursion", "rocking settles", "flyback_time", "rpm_reverse"}
    assert w.yield_all == 1.0  # the design's corners hold every limit, so every board does


def test_sensitivity_ranks_for_the_least_margin(fan):
    """With eight quantities the shares are of the one of least worst-case margin, computed here from the bounds."""
    _, _, w = fan
    margins = {}
    for q in w.quantities:
        sides = ([q.eva_low / q.limit_low - 1] if q.limit_low is not None else []) + \
                ([1 - q.eva_high / q.limit_high] if q.limit_high is not None else [])
        if sides:
            margins[q.key] = min(sides)
    assert w.binding == min(margins, key=margins.get) == "start_settles"
    assert w.sensitivity[0].source == "CAP-ST current" and sum(x.share for x in w.sensitivity) == pytest.approx(1.0)
    shares = {x.source: x.share for x in w.sensitivity}
    assert shares["charge current"] == shares["CAP-TI current"] == 0.0  # no part of the start oscillator's ratio


def test_a_start_period_limit_that_bites_matches_a_closed_form(fan):
    """P(2 C dV / I <= t_start_max) = P(I >= 2 C dV / t_start_max), C and I independent uniforms: I's tail
    integrated over C by the midpoint rule."""
    _, r, _ = fan
    s = {**r.spec, "t_start_max": 0.9}
    result = SimpleNamespace(cap_cd=r.cap_cd, cap_st=r.cap_st, cap_ti=r.cap_ti, spec=s)
    w = wc.analyse("commutation", result, n=200_000, seed=3)
    c_lo, c_hi = r.cap_st * (1 - TOL), r.cap_st * (1 + TOL)
    cs = c_lo + (np.arange(100_000) + 0.5) / 100_000 * (c_hi - c_lo)
    a, b = I_ST
    p = float(np.clip((b - 2 * cs * (V_ST[1] - V_ST[0]) / s["t_start_max"]) / (b - a), 0, 1).mean())
    assert 0.2 < p < 0.98
    assert w.quantity("start_period").limit_high == 0.9
    assert w.yields["t_start_max"] == pytest.approx(p, abs=4 * math.sqrt(p * (1 - p) / w.n))


def test_no_motor_data_gives_cap_cd_alone():
    """Without motor data or flyback_time the model is CAP-CD's alone: its three quantities, four inputs, two
    limits; and CAP-CD's numbers in the fan's analysis are those of the same CAP-CD analysed alone (its inputs are
    drawn first, so even the Monte Carlo's are the same)."""
    r = commutation.design(None)
    assert r.cap_st is None and r.cap_ti is None
    w = wc.analyse("commutation", r, n=20_000, seed=1)
    assert tuple(q.key for q in w.quantities) == CAP_CD_KEYS and set(w.yields) == {"window", "min_excursion"}
    assert [d.part for d in w.distributions] == ["CAP-CD", "TDA5144 CAP-CD charge current", "TDA5144 CAP-CD low level",
                                                 "TDA5144 CAP-CD high level"]
    assert len(w.drift) == 2
    table = tomllib.loads(FAN.read_text())["commutation"]
    fan = commutation.design(table)
    alone = wc.analyse("commutation", SimpleNamespace(cap_cd=fan.cap_cd, spec=fan.spec), n=20_000, seed=1)
    both = wc.analyse("commutation", fan, n=20_000, seed=1)
    assert both.quantities[:3] == alone.quantities
    for k in CAP_CD_KEYS:
        assert np.array_equal(both.samples[k], alone.samples[k])


def test_flyback_without_reverse_speed_has_the_watchdog_time_only():
    r = commutation.design({"flyback_time": 1e-3})
    w = wc.analyse("commutation", r, n=5_000, seed=1)
    assert tuple(q.key for q in w.quantities) == (*CAP_CD_KEYS, "watchdog_time")
    assert w.quantity("watchdog_time").eva_low == pytest.approx(r.watchdog.t_wd_min, rel=1e-12)


def test_eq_2_broadcasts_as_it_computes_one_value():
    """The rocking frequency on arrays (the Monte Carlo's) is the scalar equation's, element by element."""
    from handbook.sources.an94002 import circuit as an94002

    kt, i, j = np.array([0.01, 0.02, 0.025]), np.array([0.3, 0.5, 0.45]), np.array([5e-6, 72e-6, 1e-5])
    arr = an94002.oscillation_frequency(kt, i, 6, j)
    assert isinstance(arr, np.ndarray) and arr.shape == (3,)
    assert arr.tolist() == [an94002.oscillation_frequency(*x, 6, y) for *x, y in zip(kt.tolist(), i.tolist(), j.tolist())]
    assert type(an94002.oscillation_frequency(0.025, 0.5, 6, 72e-6)) is float


def test_the_report_shows_the_timers_quantities_with_their_units(fan):
    """Section 4 of the design report for the fan: every new quantity a row whose values are <data> with a unit, the
    motor figures as a person reads them, no ASCII units (the book's browser test's pattern)."""
    import re

    from handbook.report.design_report import worst

    _, _, w = fan
    html = worst.one("commutation", w)
    for key in ("start_period", "rocking_settle", "start_settles", "watchdog_time", "reverse_over_watchdog"):
        for part in ("nominal", "eva.low", "eva.high", "rss.low", "mc.high"):
            assert f'data-key="wc.commutation.{key}.{part}"' in html, (key, part)
    assert re.search(r'data-key="wc.commutation.start_period.eva.low">592.8 ms<', html)
    assert re.search(r'data-key="wc.commutation.watchdog_time.limit.low">300 µs<', html)
    assert "13.5 mN m/A" in html and "4.5 × 10⁻⁶ kg m²" in html and "kg m^2" not in html
    text = re.sub(r"<[^>]+>", " ", re.sub(r"<svg.*?</svg>", " ", html, flags=re.S))
    assert not re.search(r"(?<![\w.])\d+(?:\.\d+)?\s?(?:u[FAHVWs]|[kM]?ohms?|[mk]?Ohm|deg)\b|\+-\s?\d|\+/-\s?\d", text)
    cells = re.findall(r"<td[^>]*>(.*?)</td>", re.sub(r"<svg.*?</svg>", " ", html, flags=re.S))
    bare = [c for c in cells if re.fullmatch(r"\s*-?\d+(\.\d+)?(e-?\d+)?\s*", c)]
    assert not bare, bare[:5]  # every number went through value() (a plain ratio, unit "1", is a <data> too)
