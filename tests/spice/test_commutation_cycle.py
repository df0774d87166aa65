"""CAP-CD / CAP-DC driven by a running motor's back-EMF (spice.commutation_cycle) against the note's equations and
sentences: eq 4's time between commutations, six commutations a cycle, and the zero crossing half-way between
two commutations when the discharge is twice the charge (AN94002 2.1.2)."""
import pytest

from handbook.sources import an94002 as note
from handbook.spice import commutation_cycle as cc
from handbook.spice import timers

P = note.params()


@pytest.mark.parametrize("rpm", [P["rpm_min"], 2 * P["rpm_min"]])
def test_commutations_come_every_t_com_six_a_cycle(ngspice, rpm):
    f = cc.figures(cc.cycle({"rpm": rpm}))
    assert f["interval"] == pytest.approx(10 / (rpm * P["pole_pairs"]), rel=5e-4)  # eq 4, by hand
    assert f["per_cycle"] == pytest.approx(6, abs=1e-3)


@pytest.mark.parametrize("ratio", [None, 1.85, 2.25], ids=["typ", "ratio-min", "ratio-max"])
def test_the_zero_crossing_sits_where_the_current_ratio_puts_it(ngspice, ratio):
    """Charge for t_com, sink at I_dis back down: the commutation comes t_com I_ch / I_dis after the zero crossing,
    60 degrees x I_ch / I_dis (less the 2 mV clamp's C x 2 mV / I_dis), so the zero crossing lies 1 - I_ch / I_dis of
    the way from one commutation to the next: half-way (the note) for the typical 8.1 / 16.2 uA, 4 % and 6 % of
    the interval off it at the datasheet's sink/source ratios 1.85 and 2.25."""
    q = cc.defaults()
    i_dis = q["i_dis"] if ratio is None else q["i_ch"] * ratio
    c = cc.cycle({"i_dis": i_dis})
    f = cc.figures(c)
    r = q["i_ch"] / i_dis
    clamp = q["cap_cd"] * timers.CLAMP / i_dis / c["t_cycle"] * 360
    assert f["delay_deg"] == pytest.approx(60 * r - clamp, abs=0.1)
    assert f["zc_place"] == pytest.approx(1 - r, abs=0.004)
    assert (abs(f["zc_place"] - 0.5) < 0.005) == (ratio is None)  # the note's "half-way" holds only at ratio 2
