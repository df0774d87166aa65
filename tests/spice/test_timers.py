"""The TDA5144 timers (CAP-ST, CAP-CD/CAP-DC, CAP-TI) against the book's equations, their drawings against
their netlists, and the commutation design confirmed at its worst corners."""
import pytest
from drawn_parts import assert_drawn_as_netlisted

from handbook.design import commutation
from handbook.sources import an94002 as note
from handbook.spice import timers
from handbook.spice.circuit import evaluate

BUILDERS = (timers.start_oscillator, timers.commutation_delay, timers.watchdog)



@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__name__)
def test_parts_drawn_are_the_parts_simulated(build):
    assert_drawn_as_netlisted(build())


@pytest.mark.parametrize("build", BUILDERS, ids=lambda b: b.__name__)
def test_every_check_agrees(ngspice, build):
    c = build()
    assert len(c.checks) >= 2
    for row in evaluate(c):
        assert row["agrees"], f"{row['id']}: equation {row['equation']:.6g}, spice {row['spice']:.6g} ({row['rel_diff']:.2%})"


def test_board_values_come_from_the_parts_list():
    assert timers.start_oscillator().part("C5").value == 220e-9
    assert timers.commutation_delay().part("C3").value == 18e-9
    assert timers.watchdog().part("C6").value == note.params()["cap_ti"]


def test_commutation_design_confirmed_at_its_corners(ngspice):
    result = commutation.design({})
    spice = timers.design_check(result)
    assert spice["swing_rpm_min"] == pytest.approx(result.swing_at_rpm_min, rel=0.01)
    assert spice["swing_rpm_max"] == pytest.approx(result.swing_at_rpm_max, rel=0.01)


def test_a_swing_beyond_the_window_is_clipped_at_the_high_level(ngspice):
    # 4.7 nF at the note's 1800 rpm with 11 uA would swing 2.2 V: the source stops at the 2.3 V level
    result = commutation.design({})
    small = type(result)(**{**result.__dict__, "cap_cd": 4.7e-9})
    spice = timers.design_check(small)
    window = result.spec["v_high_min"] - result.spec["v_low_max"]
    assert spice["swing_rpm_min"] == pytest.approx(window, abs=0.01)


def test_figure_4_waveforms(ngspice):
    w = timers.commutation_waveforms(points=60)
    assert len(w["t"]) == len(w["cd"]) == len(w["dc"]) == 60
    assert min(w["cd"]) >= timers.CD_LOW[1] - 1e-3 and max(w["dc"]) <= timers.CD_HIGH[1]


def test_unknown_parameter_is_an_error():
    with pytest.raises(KeyError, match="unknown parameter"):
        timers.watchdog({"cap": 1e-9})
