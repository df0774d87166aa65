"""The speed-control loop and the decoupling capacitor C2 against the book's equations; drawings against
netlists."""
import pytest
from drawn_parts import assert_drawn_as_netlisted

from handbook.spice import decoupling, runner, speed
from handbook.spice.circuit import evaluate

BUILDERS = (speed.circuit, decoupling.circuit)



@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__module__)
def test_parts_drawn_are_the_parts_simulated(build):
    assert_drawn_as_netlisted(build())


@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__module__)
def test_every_check_agrees(ngspice, build):
    c = build()
    assert len(c.checks) >= 2
    for row in evaluate(c):
        assert row["agrees"], f"{row['id']}: equation {row['equation']:.6g}, spice {row['spice']:.6g} ({row['rel_diff']:.2%})"


def test_speed_error_is_the_ota_input_difference(ngspice):
    # V_mot falls short of eq 10 by exactly the OTA's input difference times the divider's gain
    c = speed.circuit()
    out = runner.run(c.netlist)
    r3, r4 = c.part("R3").value, c.part("R4").value
    top = next(ch.equation for ch in c.checks if ch.id == "speed-vmot-top")
    assert top - out["vmot_top"] == pytest.approx(out["vdiff_top"] * (r3 + r4) / r4, rel=1e-3)


def test_sweeps(ngspice):
    s = speed.sweep(points=7)
    assert s["v_mot"] == sorted(s["v_mot"])
    z = decoupling.sweep(points=6)
    assert min(z["c2"]) >= decoupling.defaults()["esr"] * 0.99
