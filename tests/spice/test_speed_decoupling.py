"""The speed-control loop and the decoupling capacitor C2 against the book's equations; drawings against
netlists, both ways."""
import math

import pytest
from drawn_parts import assert_same_parts

from handbook.spice import decoupling, runner, speed
from handbook.spice.circuit import evaluate

BUILDERS = (speed.circuit, speed.loop_filter, decoupling.circuit)
#: netlist elements that are not parts, and why
AUX = {"VIN": "the control input V_in (swept)", "BOTA": "the OTA, behavioural: its figures are the parts GM, "
       "I_SINK and V_SAT", r"I[123]": "the 1 A AC test sources that make |V| read |Z|",
       "BREACH": "a probe: V_mot, forced up over the sweep's last step so that vin_top always reads"}


@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__name__)
def test_drawing_netlist_and_parts_are_one_set_with_one_set_of_values(build):
    assert_same_parts(build(), AUX)


@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__name__)
def test_every_check_agrees(ngspice, build):
    c = build()
    assert len(c.checks) >= 2
    for row in evaluate(c):
        assert row["agrees"], f"{row['id']}: equation {row['equation']:.6g}, spice {row['spice']:.6g} ({row['rel_diff']:.2%})"


def test_speed_error_is_the_ota_input_difference(ngspice):
    # V_mot falls short of eq 10 (the divider alone) by the OTA's input difference times the divider's gain
    c = speed.circuit()
    out = runner.run(c.netlist)
    r3, r4 = c.part("R3").value, c.part("R4").value
    v_in_top = speed.note.v_in_range({**speed.note.params()})[1]
    assert v_in_top * (r3 + r4) / r4 - out["vmot_top"] == pytest.approx(out["vdiff_top"] * (r3 + r4) / r4, rel=1e-3)


def test_speed_shortfall_by_hand(ngspice):
    """The shortfall at the top by hand, with T1's h_FE taken as a flat 85 and V_EB as 0.8 V (no model
    function): I_C = 9.8 V x (1/10 + 1/49k) = 0.98 A, I_sink = 0.8/680 + 0.98/85 = 12.7 mA, V_in - V+ =
    12.7 mA / 0.3 S = 42 mV, times 4.9 = 0.21 V. The model's h_FE falls at 1 A (knee at IKF = 3 A), so the
    simulated shortfall is larger, about 0.26 V: between the flat-85 figure and twice it."""
    out = runner.run(speed.circuit().netlist)
    dv = 2.0 * 4.9 - out["vmot_top"]  # eq 10 at V_in = 2 V (the top of the range, 9.8 V / 4.9)
    assert 0.21 < dv < 0.42


@pytest.mark.parametrize("t1", [{"bf": 50, "ikf": 2}, {"bf": 200, "ikf": 10, "is": 1e-11}, {"bf": 50, "vaf": 20},
                                {"bf": 150, "is": 1e-13, "vaf": 100}], ids=str)
def test_no_verdict_rests_on_the_bd434s_assumed_figures(ngspice, t1):
    """The BD434's figures are assumptions: varied over a wide range (h_FE 50 to 200, IS x 0.1 to x 10, the
    knee and the Early voltage), every check still agrees, while V_mot itself moves by far more than the
    tolerance (so the checks are not insensitive by being loose)."""
    base = {r["id"]: r for r in evaluate(speed.circuit())}
    rows = {r["id"]: r for r in evaluate(speed.circuit({"t1": t1}))}
    assert all(r["agrees"] for r in rows.values()), [(r["id"], r["rel_diff"]) for r in rows.values()]
    moved = abs(rows["speed-vmot-top"]["spice"] / base["speed-vmot-top"]["spice"] - 1)
    assert moved > 3 * rows["speed-vmot-top"]["rtol"]


def test_a_motor_the_ota_cannot_drive_to_the_top_is_a_verdict_not_an_error(ngspice):
    """At 13 V (11.7 V at its lowest) a 5 ohm motor would draw 2.1 A at the top of the control range, and T1 (h_FE
    about 50 there) would need more base current than the OTA's 40 mA: the loop cannot get there. The circuit still
    evaluates: the rows at the top read what SPICE reaches, differ and say why; the low end still agrees."""
    rows = {r["id"]: r for r in evaluate(speed.circuit({"v_supply": 13.0, "r_motor": 5.0}))}
    top = rows["speed-vin-top"]
    assert top["verdict"] == "differs" and "more than its 40 mA" in top["why"]
    assert top["spice"] == pytest.approx(speed.DC_END, abs=speed.DC_STEP)  # the sweep's end: never reached
    assert not rows["speed-vmot-top"]["agrees"] and rows["speed-vmot-top"]["spice"] < rows["speed-vmot-top"]["equation"]
    assert rows["speed-vmot-low"]["agrees"] and "40 mA" not in rows["speed-vmot-low"]["why"]


def test_the_dc_rows_tolerances_are_the_methods():
    """The DC rows' tolerances are built from the sweep's step, the deck's solver tolerances and the printout, not
    seen: the deck sets RELTOL far below ngspice's 1e-3, and the interpolation's share is V_mot's curvature."""
    c = speed.circuit()
    assert f".options reltol={speed.RELTOL:g}" in c.netlist and speed.RELTOL < 1e-6
    b = speed.dc_bounds(speed.note.v_in_range(speed.note.params())[1], speed.with_defaults(speed.defaults(), {}))
    assert 0 < b["chord"] < 1e-6 and b["v_mot"] < 1e-5
    assert {ch.id: ch.kind for ch in c.checks}["speed-eq10-top"] == "sanity"


def test_loop_filter_corner_is_r1_c8(ngspice):
    c = speed.loop_filter()
    out = runner.run(c.netlist)
    assert out["f_rc"] == pytest.approx(1 / (2 * math.pi * 22 * 220e-9), rel=5e-3)  # 32.88 kHz, board R1 and C8
    doubled = runner.run(speed.loop_filter({"c8": 440e-9}).netlist)
    assert doubled["f_rc"] == pytest.approx(out["f_rc"] / 2, rel=5e-3)


def test_decoupling_self_resonance_and_sanity_kinds(ngspice):
    rows = {r["id"]: r for r in evaluate(decoupling.circuit())}
    # 10 uF with 15 nH: 1 / (2 pi sqrt(1.5e-13)) = 410.9 kHz
    assert rows["decoupling-f-res"]["spice"] == pytest.approx(410.9e3, rel=2e-3)
    assert rows["decoupling-f-res"]["kind"] == "independent"
    assert {rows["decoupling-z-cmin"]["verdict"], rows["decoupling-z-lmax"]["verdict"]} == {"consistent (by construction)"}


def test_sweeps(ngspice):
    s = speed.sweep(points=7)
    assert s["v_mot"] == sorted(s["v_mot"])
    z = decoupling.sweep(points=6)
    assert min(z["c2"]) >= decoupling.defaults()["esr"] * 0.99
