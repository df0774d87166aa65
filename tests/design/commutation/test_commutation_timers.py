"""CAP-ST and CAP-TI from the motor (handbook.design.commutation.timers) by hand and against all-corner
enumerations written out in tests/oracles.py (no code shared with handbook.design)."""
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.design import commutation
from handbook.design.solvers import Infeasible

from oracles import enumerate_cap_st, enumerate_cap_ti

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])
#: AN94002 2.1.1's example motor
NOTE_MOTOR = dict(inertia=72e-6, torque_constant=25e-3, start_current=0.5)


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
