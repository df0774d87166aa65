"""Generated specifications, valid and broken, thrown at the loader and the three solvers.

Every one must end in a design that re-verifies independently (tests/oracles.py, no code shared with
handbook.design), in an InputError naming the offending table.key (or table), or in an Infeasible that
says what can be met. Nothing else may escape.

Two tiers, for the run time: 1,000 specifications of every key (junk values, typos and unknown tables
among them) through the loader, the contradiction checks and the commutation design (closed forms, a few
ms); then 20 junk-free ones through all three designs (the limiter's exact search takes up to about
a second), each table on its own so that an unmeetable table does not hide the others.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError, series
from handbook.design import commutation, spec
from handbook.design.schema import TABLES
from handbook.design.solvers import Infeasible

from oracles import _band_ok, _class_d_heat, enumerate_cap, enumerate_cap_st, enumerate_cap_ti, limiter_corners, p_clip

SERIES = st.sampled_from(["E6", "E12", "E24", "E96"])
TOL = st.sampled_from([0.001, 0.005, 0.01, 0.02, 0.05, 0.1])
PIN = st.sampled_from([33.0, 100.0, 1e3, 2.2e3, 4.7e3, 10e3, 22e3])

SANE = {
    "commutation": {
        "pole_pairs": st.integers(1, 16), "rpm_min": st.floats(100, 5000), "rpm_max": st.floats(500, 30000),
        "i_charge_min": st.floats(2e-6, 10e-6), "i_charge_max": st.floats(8e-6, 40e-6),
        "v_low_min": st.floats(0.5, 0.85), "v_low_max": st.floats(0.8, 1.2),
        "v_high_min": st.floats(1.5, 2.4), "v_high_max": st.floats(2.3, 3.0), "min_excursion": st.floats(0.02, 0.4),
        "tolerance": st.sampled_from([0.01, 0.02, 0.05, 0.1, 0.2]), "series": SERIES,
        "inertia": st.floats(1e-7, 1e-3), "torque_constant": st.floats(1e-3, 0.2), "start_current": st.floats(0.05, 3),
        "motor_tolerance": st.sampled_from([0.0, 0.1, 0.2]), "damping_ratio": st.floats(0.02, 2),
        "residual": st.floats(0.01, 0.5), "t_start_max": st.floats(0.1, 10), "flyback_time": st.floats(1e-5, 5e-3),
        "rpm_reverse": st.floats(10, 5000), "i_st_min": st.floats(1e-6, 2e-6), "i_st_max": st.floats(1.8e-6, 4e-6),
        "v_st_low": st.floats(0.05, 0.5), "v_st_high": st.floats(1.5, 3.0),
        "i_wd_min": st.floats(2e-6, 5e-6), "i_wd_max": st.floats(4.5e-6, 8e-6)},
    "current_limiter": {
        "i_no_trip": st.floats(0.05, 2), "i_must_trip": st.floats(0.1, 10),
        "min_margin": st.sampled_from([0.0, 0.01, 0.02, 0.05]),
        "resistor_tolerance": st.sampled_from([0.001, 0.005, 0.01, 0.02, 0.05]),
        "r7_tolerance": st.sampled_from([0.01, 0.02, 0.05]), "zener_voltage": st.floats(4.7, 12),
        "zener_tolerance": st.sampled_from([0.01, 0.02, 0.05]), "zener_tc": st.floats(0, 8e-3),
        "temp_span": st.floats(0, 50), "offset": st.floats(0, 0.01), "input_bias": st.floats(0, 1e-6),
        "input_offset_current": st.floats(0, 3e-7), "divider_current_max": st.floats(2e-4, 1e-2),
        "r7_power_rating": st.floats(0.1, 5),
        "input_headroom": st.floats(0, 3), "ic": st.sampled_from(["TDA5144", "TDA5143"]),
        "r7_series": st.sampled_from(["E12", "E24", "E96"]), "r9_series": st.sampled_from(["E24", "E96"]),
        **{f"r{n}": PIN for n in (9, 10, 11, 12, 13)},
        **{f"r{n}_series": st.sampled_from(["E12", "E24", "E96"]) for n in (10, 11, 12, 13)}},
    "class_d": {
        "p_out": st.floats(5, 200), "r_load": st.sampled_from([2.0, 4.0, 6.0, 8.0, 16.0]), "supply": st.floats(12, 22),
        "t_ambient": st.floats(-20, 90), "package": st.sampled_from(["TF", "T"]), "theta_cs": st.floats(0, 1),
        "theta_sa_available": st.floats(0.3, 20), "p_continuous": st.floats(1, 200),
        "thermal_basis": st.sampled_from(["iec_1_8", "continuous_sine"]), "thd_max": st.floats(0.001, 0.05),
        "thd_test_power": st.floats(1, 50), "objective": st.sampled_from(["efficiency", "heat_sink"]),
        "f_audio": st.floats(100, 20e3), "droop_max": st.floats(0.1, 3), "q_max": st.floats(0.5, 2),
        "ripple_max": st.floats(0.1, 2), "i_sat": st.floats(2, 20), "l_tolerance": TOL, "c_tolerance": TOL,
        "l_dcr": st.floats(0, 1000), "osc_tol_slow": st.floats(0, 0.3), "osc_tol_fast": st.floats(0, 0.3),
        "r_tolerance": st.floats(0, 0.05),
        "rds_on_25": st.floats(0.1, 0.5), "t_overmod": st.floats(0, 500e-9), "tj_margin": st.floats(0, 30),
        "dead_time_min": st.floats(10e-9, 100e-9), "r_osc_series": st.sampled_from(["E12", "E24", "E96"]),
        "r_dly_series": st.sampled_from(["E12", "E24"]), "l_series": st.sampled_from(["E6", "E12"]),
        "c_series": st.sampled_from(["E6", "E12"])},
}
assert all(set(keys) <= {p.name for p in TABLES[t]} for t, keys in SANE.items())  # the schema moved on
JUNK = st.one_of(st.just(float("nan")), st.just(float("inf")), st.just(-1.0), st.just(0.0), st.just(1e12),
                 st.just(22), st.text(max_size=4), st.booleans(), st.lists(st.integers(), max_size=2),
                 st.just("E13"), st.just(2.5))
TABLE_NAMES = ("commutation", "current_limiter", "class_d", "clas_d")


MOTOR = ("inertia", "torque_constant", "start_current")


@st.composite
def specs(draw, junk: bool = True, keep: int = 3):
    """A spec: each table present or not, each key given with probability keep/4; the motor data (all
    three or none) and rpm_reverse (with flyback_time) mostly consistent, a part of them 1 time in 20;
    with ``junk``, 1 spec in 3 has one junk value and a few a misspelt key or table."""
    data = {}
    for table, keys in SANE.items():
        if draw(st.booleans()):
            continue
        given = {k for k in keys if k not in MOTOR and draw(st.integers(0, 3)) < keep}
        if table == "commutation":
            if draw(st.booleans()):
                given |= set(MOTOR) - ({draw(st.sampled_from(MOTOR))} if draw(st.integers(0, 19)) == 0 else set())
            if "flyback_time" not in given and draw(st.integers(0, 19)):
                given.discard("rpm_reverse")
        data[table] = {k: draw(strat) for k, strat in keys.items() if k in given}
        if "p_continuous" in data[table]:  # a continuous power belongs to the continuous-sine basis
            data[table]["thermal_basis"] = "continuous_sine"
    if junk and data and draw(st.integers(0, 2)) == 0:
        table = draw(st.sampled_from(sorted(data)))
        data[table][draw(st.sampled_from(sorted(SANE[table])))] = draw(JUNK)
    if junk and data and draw(st.integers(0, 30)) == 0:
        table = draw(st.sampled_from(sorted(data)))
        data[table][draw(st.sampled_from(["rpm_mni", "i_trip", "supply_v", "tolerence", "window", "r_dly"]))] = 1.0
    if junk and draw(st.integers(0, 40)) == 0:
        data["clas_d"] = {}
    return data


def _clear_input_error(exc):
    msg = str(exc)
    assert any(f"{t}." in msg or f"[{t}" in msg or t in msg for t in TABLE_NAMES), msg


def _clear_infeasible(exc, table):
    assert str(exc) and exc.achievable and exc.table == table, (table, exc)


def _finite(result):
    for v in result.summary().values():
        assert not (isinstance(v, float) and not math.isfinite(v)), result.summary()


def _reverify_commutation(c):
    s = c.spec
    assert c.cap_cd == c.cap_dc == pytest.approx(enumerate_cap(s), rel=1e-9)
    assert (c.cap_st is None) == (s["inertia"] is None)
    if c.cap_st is not None:
        assert c.cap_st == pytest.approx(enumerate_cap_st(s), rel=1e-9)
    assert (c.cap_ti is None) == (s["flyback_time"] is None)
    if c.cap_ti is not None:
        assert c.cap_ti == pytest.approx(enumerate_cap_ti(s), rel=1e-9)
    _finite(c)


def _reverify_limiter(lim):
    s, m = lim.spec, lim.spec["min_margin"]
    lo, hi, head, i_div = (float(x) for x in limiter_corners(lim.r7, lim.network, s))
    assert lo >= s["i_no_trip"] * (1 + m) * (1 - 1e-9) and hi <= s["i_must_trip"] * (1 - m) * (1 + 1e-9)
    assert head >= s["input_headroom"] - 1e-9 and i_div <= s["divider_current_max"] * (1 + 1e-9)
    assert (lim.i_trip_min, lim.i_trip_max) == pytest.approx((lo, hi), rel=1e-9)
    for name, value in zip(("r7", "r9", "r10", "r11", "r12", "r13"), (lim.r7, *lim.network)):
        if s[name] is not None:
            assert value == s[name]
        else:
            assert s[f"{name}_min"] * (1 - 1e-9) <= value <= s[f"{name}_max"] * (1 + 1e-9)
            assert min(abs(value / v - 1) for v in series.values(s[f"{name}_series"], value / 2, value * 2)) < 1e-9
    _finite(lim)


def _reverify_class_d(cd):
    s = cd.spec
    assert cd.figures["ok"]
    assert cd.f_sw == pytest.approx(1e9 / (4000 + cd.r_osc - 0.4 * cd.r_dly), rel=1e-9)  # eq 5
    t = s["r_tolerance"]  # eq 5 with R_OSC and R_DLY at their ends, times the table's spread
    slow = (1 - s["osc_tol_slow"]) * 1e9 / (4000 + cd.r_osc * (1 + t) - 0.4 * cd.r_dly * (1 - t))
    fast = (1 + s["osc_tol_fast"]) * 1e9 / (4000 + cd.r_osc * (1 - t) - 0.4 * cd.r_dly * (1 + t))
    assert (cd.f_sw_min, cd.f_sw_max) == pytest.approx((slow, fast), rel=1e-9)
    assert 50e3 * (1 - 1e-9) <= slow and fast <= 225e3 * (1 + 1e-9)
    assert 27e-9 + 1.7e-12 * cd.r_dly * (1 - t) >= s["dead_time_min"] * (1 - 1e-9)
    assert p_clip(fast, s["r_load"], s["supply"]) >= s["p_out"] * (1 - 1e-9)
    theta = min(_class_d_heat(s, slow), _class_d_heat(s, fast))
    assert theta == pytest.approx(cd.theta_sa_required, rel=1e-6, abs=1e-9)
    assert theta >= (s["theta_sa_available"] or 0.0) - 1e-9
    for k_l in (1 - s["l_tolerance"], 1 + s["l_tolerance"]):
        for k_c in (1 - s["c_tolerance"], 1 + s["c_tolerance"]):
            assert _band_ok(s, np.array([cd.l_out * k_l]), np.array([cd.c_out * k_c]))[0]
    _finite(cd)


@settings(max_examples=1000, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(specs())
def test_every_spec_loads_and_designs_commutation_or_names_what_is_wrong(data):
    try:
        checked = spec.check(spec.parse(data))
    except InputError as exc:
        _clear_input_error(exc)
        return
    try:
        c = commutation.design(checked["commutation"])
    except Infeasible as exc:
        _clear_infeasible(exc, "commutation")
        return
    _reverify_commutation(c)


@settings(max_examples=20, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(specs(junk=False, keep=1))
def test_every_valid_spec_ends_in_verified_designs_or_says_what_can_be_met(data):
    try:
        results = spec.run_each(spec.parse(data))
    except InputError as exc:
        _clear_input_error(exc)
        return
    for table, reverify in (("commutation", _reverify_commutation), ("current_limiter", _reverify_limiter),
                            ("class_d", _reverify_class_d)):
        r = results[table]
        if isinstance(r, Infeasible):
            _clear_infeasible(r, table)
        else:
            reverify(r)
