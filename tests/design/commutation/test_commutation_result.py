"""CAP-CD and the commutation set's public face (handbook.design.commutation.result) against hand calculations
from the datasheet figures and an all-corner enumeration written out in tests/oracles.py (no code shared with
handbook.design); infeasible, implausible and bad specs."""
import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError
from handbook.design import commutation
from handbook.design.solvers import Infeasible

from oracles import enumerate_cap

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
    (dict(pole_pairs=2, rpm_min=20.0, rpm_max=60.0), ["CAP-CD = 2.2 µF", "electrolytic", "5.3 µA"]),
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
