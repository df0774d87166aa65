"""What an unmeetable class-D spec can meet (handbook.design.class_d.explain), and the datasheet's typical
application judged by the design's own checks."""

import pytest

from handbook.design import class_d
from handbook.design.class_d.explain import datasheet_application
from handbook.design.solvers import Infeasible

from oracles import p_clip


def test_contradictory_specs_say_what_can_be_met():
    with pytest.raises(Infeasible) as exc:  # a THD+N test point above clipping is no test
        class_d.design({"thd_test_power": 500.0})
    assert "thd_test_power = 500.0 W" in str(exc.value) and exc.value.achievable["p_clip"] < 140
    with pytest.raises(Infeasible) as exc:
        class_d.design({"thermal_basis": "continuous_sine", "p_continuous": 1000.0})
    text = str(exc.value)
    assert exc.value.achievable["p_deliverable"] == pytest.approx(p_clip(50e3, 4, 20))
    assert "about 140 W at most" in text and "ambient" not in text and "0.00 K/W" not in text
    assert "an ideal heat sink, 0 K/W" in text



def test_infeasible_says_what_can_be_met():
    with pytest.raises(Infeasible) as exc:
        class_d.design({"p_out": 200.0})
    best = exc.value.achievable["p_clip"]
    # the lowest E24 frequency whose slow corner stays at 50 kHz or above, at its fast corner
    # (R_OSC and R_DLY at their 1 % ends: slowest with R_OSC high and R_DLY low)
    f = min(1.235e9 / (4000 + 0.99 * r - 0.4 * 5100 * 1.01) for r in (11e3, 12e3, 13e3, 15e3)
            if 0.8e9 / (4000 + 1.01 * r - 0.4 * 5100 * 0.99) >= 50e3)
    assert best == pytest.approx(p_clip(f, 4, 20)) and "p_out" in str(exc.value)



def test_datasheet_typical_application_judged_by_the_same_checks():
    ev = datasheet_application(class_d.checked({}))
    f = 1e9 / (4000 + 3900 - 2000)
    assert ev["f_sw"] == pytest.approx(f)
    fast = 1.235e9 / (4000 + 0.99 * 3900 - 0.4 * 1.01 * 5000)  # R_OSC low, R_DLY high: their 1 % ends
    assert ev["p_clip"] == pytest.approx(p_clip(fast, 4, 20)) and not ev["ok"]
    assert ev["margins"]["clipping"] < 0 < ev["margins"]["THD+N"]
