"""The commutation timing set (CAP-CD, CAP-ST, CAP-TI) against hand calculations from the datasheet figures
and against all-corner enumerations written out in tests/oracles.py (no code shared with handbook.design)."""
import json
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError
from handbook.design import commutation
from handbook.design.solvers import Infeasible

from oracles import enumerate_cap, enumerate_cap_st, enumerate_cap_ti

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])
#: AN94002 2.1.1's example motor
NOTE_MOTOR = dict(inertia=72e-6, torque_constant=25e-3, start_current=0.5)


def test_default_is_8n2_with_the_source_current_and_18nF_reaches_half_the_speed():
    r = commutation.design()
    # 11 uA (source max) for 10/(1800 x 6) s over (2.3 - 0.9) V, at -5 %: 7.658 nF -> 8.2 nF
    assert 11e-6 * (10 / 10800) / (1.4 * 0.95) == pytest.approx(7.658e-9, rel=1e-3)
    assert r.continuous_optimum == pytest.approx(11e-6 * (10 / 10800) / (1.4 * 0.95), rel=1e-12)
    assert r.cap_cd == pytest.approx(8.2e-9) and r.cap_dc == r.cap_cd and r.next_smaller == pytest.approx(6.8e-9)
    assert r.window_corner == {"cap": pytest.approx(8.2e-9 * 0.95), "i": 11e-6, "v_low": 0.9, "v_high": 2.3}
    # top speed: 5.3 uA on 8.2 nF x 1.05 with a 0.1 V floor; 18 nF gives less than half of it
    assert r.rpm_max_reliable == pytest.approx(10 * 5.3e-6 / (6 * 8.61e-9 * 0.1), rel=1e-12)
    note = commutation.verify(18e-9, r.spec)
    assert note["window_ok"] and note["noise_ok"]
    assert note["rpm_max_reliable"] == pytest.approx(10 * 5.3e-6 / (6 * 18.9e-9 * 0.1), rel=1e-12)
    assert 10 * 10.6e-6 / (6 * 18.9e-9 * 0.1) / note["rpm_max_reliable"] == pytest.approx(2.0)
    assert r.cap_st is None and r.cap_ti is None and r.warnings == ()
    assert set(r.summary()) >= {"cap_cd", "rpm_min_reliable", "rpm_max_reliable", "cap_st", "cap_ti", "warnings"}


@SETTINGS
@given(n=st.integers(1, 12), rpm_min=st.floats(100, 20000), span=st.floats(1.05, 20),
       i_max=st.floats(2e-6, 50e-6), spread=st.floats(0.2, 1.0), v_low=st.floats(0.3, 1.2),
       low_spread=st.floats(0, 0.3), window=st.floats(0.5, 2.5), high_spread=st.floats(0, 0.4),
       floor=st.floats(0.02, 0.4), tol=st.sampled_from([0.0, 0.01, 0.05, 0.1, 0.2]),
       ser=st.sampled_from(["E6", "E12", "E24"]))
def test_cap_cd_equals_all_corner_enumeration(n, rpm_min, span, i_max, spread, v_low, low_spread, window,
                                             high_spread, floor, tol, ser):
    spec = dict(pole_pairs=n, rpm_min=rpm_min, rpm_max=rpm_min * span, i_charge_max=i_max,
                i_charge_min=i_max * spread, v_low_min=v_low, v_low_max=v_low + low_spread,
                v_high_min=v_low + low_spread + window, v_high_max=v_low + low_spread + window + high_spread,
                min_excursion=min(floor, window / 2), tolerance=tol, series=ser)
    expected = enumerate_cap(spec)
    try:
        got = commutation.design(spec)
    except Infeasible as exc:
        assert expected is None
        assert exc.achievable["rpm_max_reliable"] < spec["rpm_max"]
        return
    assert got.cap_cd == pytest.approx(expected, rel=1e-12)


def test_cap_st_for_the_note_motor_by_hand():
    r = commutation.design(NOTE_MOTOR)
    # slowest rocking: K_t and I at -10 %, J at +10 % (eq 2)
    f_min = math.sqrt(25e-3 * 0.9 * 0.5 * 0.9 * 6 / (72e-6 * 1.1)) / (2 * math.pi)
    settle = math.log(10) / (0.1 * 2 * math.pi * f_min)
    assert r.start.f_osc_min == pytest.approx(f_min, rel=1e-12) and settle == pytest.approx(0.8314, rel=1e-4)
    # shortest period 2 C (1 - 0.05) (2.2 - 0.2) / 2.5 uA >= settle: C >= 0.547 uF -> 0.56 uF (0.47 uF: 0.714 s)
    assert r.start.bound == pytest.approx(settle * 2.5e-6 / (2 * 2.0 * 0.95), rel=1e-12)
    assert r.cap_st == pytest.approx(0.56e-6) and r.start.next_smaller == pytest.approx(0.47e-6)
    assert r.start.period_max == pytest.approx(2 * 0.56e-6 * 1.05 * 2.0 / 1.5e-6, rel=1e-12)
    # the note's 0.22 uF: shortest period 0.334 s, too short unless the damping ratio is at least 0.25
    assert 2 * 0.22e-6 * 0.95 * 2.0 / 2.5e-6 < settle
    assert commutation.timers.check_start(0.22e-6, {**r.spec, "damping_ratio": 0.25})["settles"]
    assert not commutation.timers.check_start(0.22e-6, r.spec)["settles"]
    assert enumerate_cap_st(NOTE_MOTOR) == pytest.approx(r.cap_st)


@SETTINGS
@given(j=st.floats(1e-8, 1e-3), kt=st.floats(1e-3, 0.2), i=st.floats(0.05, 3), n=st.integers(1, 12),
       zeta=st.floats(0.02, 3), residual=st.floats(0.01, 0.5), mt=st.sampled_from([0.0, 0.1, 0.3]),
       tol=st.sampled_from([0.02, 0.1]), t_max=st.one_of(st.none(), st.floats(0.01, 5)),
       ser=st.sampled_from(["E6", "E12", "E24"]))
def test_cap_st_equals_all_corner_enumeration(j, kt, i, n, zeta, residual, mt, tol, t_max, ser):
    spec = dict(inertia=j, torque_constant=kt, start_current=i, pole_pairs=n, damping_ratio=zeta, residual=residual,
                motor_tolerance=mt, tolerance=tol, t_start_max=t_max, series=ser, rpm_min=10.0, rpm_max=20.0)
    expected = enumerate_cap_st(spec)
    try:
        got = commutation.design(spec)
    except Infeasible as exc:
        assert expected is None and exc.achievable["t_start_max_possible"] > t_max
        return
    assert got.cap_st == pytest.approx(expected, rel=1e-12)


def test_cap_ti_by_hand():
    r = commutation.design({**NOTE_MOTOR, "flyback_time": 1e-3})
    # shortest watchdog C 0.95 x 1.9 V / 6.25 uA >= 1 ms: C >= 3.463 nF -> 3.9 nF
    assert 1e-3 * 6.25e-6 / (1.9 * 0.95) == pytest.approx(3.463e-9, rel=1e-3)
    assert r.cap_ti == pytest.approx(3.9e-9)
    assert r.watchdog.t_wd_max == pytest.approx(3.9e-9 * 1.05 * 1.9 / 3.75e-6, rel=1e-12)
    # reverse at 500 rpm: 150 el. degrees take 25 / (500 x 6) = 8.33 ms; the middle of 3.463 nF and
    # 8.33 ms x 3.75 uA / (1.9 x 1.05) = 15.66 nF is 7.36 nF: 6.8 nF (smaller ratio 1.96) beats 8.2 nF (1.91)
    r = commutation.design({**NOTE_MOTOR, "flyback_time": 1e-3, "rpm_reverse": 500.0})
    assert math.sqrt(3.463e-9 * 15.66e-9) == pytest.approx(7.36e-9, rel=1e-3)
    assert r.cap_ti == pytest.approx(6.8e-9)
    assert r.watchdog.t_reverse == pytest.approx(25 / 3000, rel=1e-12)


@SETTINGS
@given(fly=st.floats(1e-5, 0.02), rev=st.one_of(st.none(), st.floats(10, 20000)), n=st.integers(1, 12),
       tol=st.sampled_from([0.02, 0.1, 0.2]), ser=st.sampled_from(["E6", "E12", "E24"]))
def test_cap_ti_equals_all_corner_enumeration(fly, rev, n, tol, ser):
    spec = dict(flyback_time=fly, rpm_reverse=rev, pole_pairs=n, tolerance=tol, series=ser)
    expected = enumerate_cap_ti(spec)
    try:
        got = commutation.design(spec)
    except Infeasible as exc:
        assert expected is None and exc.achievable["rpm_reverse_caught"] < rev
        return
    assert got.cap_ti == pytest.approx(expected, rel=1e-12)


def test_unmeetable_timers_say_what_can_be_met():
    with pytest.raises(Infeasible) as exc:
        commutation.design({**NOTE_MOTOR, "t_start_max": 1.0})
    assert exc.value.achievable["t_start_max_possible"] == pytest.approx(2 * 0.56e-6 * 1.05 * 2 / 1.5e-6)
    with pytest.raises(Infeasible) as exc:
        commutation.design({"flyback_time": 5e-3, "rpm_reverse": 3000.0})
    assert exc.value.achievable["rpm_reverse_caught"] < 3000


@pytest.mark.parametrize("spec,words", [
    (dict(pole_pairs=4, rpm_min=2e5, rpm_max=3e5), ["rpm_max = 300000", "cannot commutate", "AN94002 2.1.3"]),
    (dict(pole_pairs=1, rpm_min=2e5, rpm_max=4e5), ["CAP-CD = 470 pF", "stray capacitance"]),
    (dict(pole_pairs=2, rpm_min=20.0, rpm_max=60.0), ["CAP-CD = 2.2 uF", "electrolytic", "5.3 uA"]),
    (dict(pole_pairs=2, rpm_min=20.0, rpm_max=60.0, inertia=1e-8, torque_constant=1e-2, start_current=0.5),
     ["start oscillator", "would fire", "AN94002 2.1.1"]),
])
def test_implausible_but_valid_designs_carry_warnings(spec, words):
    text = " ".join(commutation.design(spec).warnings)
    assert all(w in text for w in words), text


@pytest.mark.parametrize("spec,words", [
    (dict(inertia=1e-5), ["torque_constant", "start_current"]),
    (dict(rpm_reverse=100.0), ["rpm_reverse", "flyback_time"]),
    (dict(v_low_max=2.4), ["v_low_max", "v_high_min"]),
    (dict(min_excursion=1.5), ["min_excursion", "1.4"]),
    (dict(i_charge_min=12e-6), ["i_charge_min", "i_charge_max"]),
    (dict(damping_ratio=0.0), ["damping_ratio", "> 0"]),
])
def test_bad_input_names_the_key(spec, words):
    with pytest.raises(InputError) as exc:
        commutation.design(spec)
    assert all(w in str(exc.value) for w in words), str(exc.value)


def test_json_summary_keeps_the_contract_and_designs_with_warnings():
    """The [commutation] object of `python -m handbook design --json` is this summary, dumped as JSON."""
    c = json.loads(json.dumps(commutation.design(dict(pole_pairs=2, rpm_min=20.0, rpm_max=60.0)).summary()))
    assert c["cap_cd"] == pytest.approx(2.2e-6) and c["cap_st"] is None and c["cap_ti"] is None
    assert any("electrolytic" in w for w in c["warnings"])
    c = json.loads(json.dumps(commutation.design({**NOTE_MOTOR, "flyback_time": 1e-3}).summary()))
    assert c["cap_st"] == pytest.approx(0.56e-6) and c["cap_ti"] == pytest.approx(3.9e-9) and c["warnings"] == []
