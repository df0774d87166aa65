"""Class D: calibration points of the models and the design against an independent enumeration."""
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.design import class_d
from handbook.design.solvers import Infeasible
from handbook.sources.lm4651 import circuit as lm4651

from oracles import enumerate_class_d

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_calibration_points_of_the_class_d_models():
    assert lm4651.p_clip(125e3, 4) == pytest.approx(125)
    assert lm4651.p_clip(75e3, 4) == pytest.approx(135)
    assert lm4651.p_clip(125e3, 8) == pytest.approx(75)
    assert lm4651.thd_n(125e3) == pytest.approx(0.003)
    # the datasheet's example: 125 W, 4 ohm, 125 kHz, 350 ns over-modulation as it prints it
    frac = lm4651.switching_loss_fraction(125e3, t_overmod=350e-9)
    assert frac == pytest.approx((25 + 26 + 350) * 1e-9 * 125e3)
    p_sw = lm4651.p_switch(125e3, 125, t_overmod=350e-9)
    assert p_sw == pytest.approx(0.050125 * 125 / (1 - 0.050125))
    assert lm4651.p_conduction(125, 4) == pytest.approx(125 / 4 * 0.46)
    assert lm4651.theta_sa_required(21.0, 50, "TF") == pytest.approx(100 / 21 - 2.2)


def test_default_class_d_design():
    r = class_d.design()
    assert r.r_osc == 8200.0
    assert r.f_sw == pytest.approx(1e9 / (4000 + 8200 - 2000))
    assert r.thd_n <= 0.005 and r.p_clip >= 125
    assert "THD" in r.binding
    assert r.efficiency > lm4651.losses(125e3, 125, 4)[2]  # better than the datasheet's 125 kHz


@SETTINGS
@given(p_out=st.floats(20, 150), r_load=st.sampled_from([4.0, 6.0, 8.0]), t_a=st.floats(0, 70),
       thd=st.floats(0.002, 0.02), sink=st.one_of(st.none(), st.floats(0.5, 8)),
       pkg=st.sampled_from(["TF", "T"]), ser=st.sampled_from(["E12", "E24", "E96"]))
def test_class_d_equals_enumeration(p_out, r_load, t_a, thd, sink, pkg, ser):
    spec = dict(p_out=p_out, r_load=r_load, t_ambient=t_a, thd_max=thd, theta_sa_available=sink, package=pkg,
                r_osc_series=ser)
    expected = enumerate_class_d(spec)
    try:
        got = class_d.design(spec)
    except Infeasible:
        assert expected is None
        return
    assert got.r_osc == expected
    ev = class_d.evaluate(got.f_sw, got.spec)
    assert ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"]
