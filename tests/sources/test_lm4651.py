"""LM4651/LM4652: the datasheet's numbers against hand calculations, and their statuses."""
import math

import pytest

from handbook.sources import lm4651

X = (25 + 26 + 350) * 1e-9 * 125e3  # eq 9 with the example's 350 ns
P_4652 = X * 125 / (1 - X) + 125 / 4 * 0.46  # the LM4652 dissipation, recomputed (the example rounds it to 21 W)
HAND = {
    "lm4651-f-4k": 125e3, "lm4651-f-15k": 1e9 / 19e3, "lm4651-f-0": 250e3, "lm4651-dead-time": 0.85e-9,
    "lm4651-rosc": 1e9 / 125e3 - 4000 + 2000, "lm4651-isckt": 1e5 / (1e4 * 1e5 / 1.1e5), "lm4651-cstart": 1 / 8.5e4,
    "lm4651-vout-rms": math.sqrt(500), "lm4651-gain": math.sqrt(500) / 3,
    "lm4651-gain-db": 20 * math.log10(math.sqrt(500) / 3),
    "lm4651-r2-ratio": 0.7, "lm4651-r2": 14e3, "lm4651-overmod": 310e-9, "lm4651-loss-pct": X,
    "lm4651-p-switch": X * 125 / (1 - X), "lm4651-i-rms": math.sqrt(125 / 4), "lm4651-p-rds": 125 / 4 * 0.46,
    "lm4651-p-total": P_4652, "lm4651-theta-tf": 100 / P_4652 - 2.2, "lm4651-theta-t": 100 / P_4652 - 1.2,
    "lm4651-efficiency": 125 / 147, "lm4651-system-pd": P_4652 + 1.0,
    "lm4651-eps0": 8.8541878128e-12 * 0.0254 * 1e12, "lm4651-rf-ratio": 10.0,
    "lm4651-gain-4k7": 3.5 / 4.7 * 11 - 3.5 / 4.7 + 0.5,
    "lm4651-hp-corner": 1 / (2 * math.pi * 25e3 * 1e-6),  # 6.366 Hz, printed 6.35
}
STATUS = {
    "inconsistent": {"lm4651-f-15k", "lm4651-f-0", "lm4651-dead-time", "lm4651-overmod", "lm4651-eps0"},
    "misprint": {"lm4651-rosc", "lm4651-isckt", "lm4651-cstart", "lm4651-gain-4k7", "lm4651-hp-corner"},
    "conservative": {"lm4651-theta-tf", "lm4651-theta-t"},  # 2.5 and 3.5 K/W: rounded down to the better heat sink
}


@pytest.mark.parametrize("ex_id,value", sorted(HAND.items()))
def test_recomputed_against_hand(ex_id, value):
    assert {r["id"]: r for r in lm4651.evaluate()}[ex_id]["computed"] == pytest.approx(value, rel=1e-9)


def test_statuses_and_consequences():
    rows = lm4651.evaluate()
    assert {r["id"] for r in rows} == set(HAND)
    for status, ids in STATUS.items():
        assert {r["id"] for r in rows if r["status"] == status} == ids
    assert all(r["status"] in ("exact", "rounding") for r in rows if r["id"] not in set().union(*STATUS.values()))
    assert all(r["consequence"] for r in rows if r["status"] in ("misprint", "inconsistent"))


def test_equations():
    checks = {e.id: e.check() for e in lm4651.SOURCE.equations()}
    assert all(c.dims_ok for c in checks.values())
    assert {k for k, c in checks.items() if not c.agrees} == {"lm4651-eq2", "lm4651-eq8"}
    assert float(checks["lm4651-eq2"].factor) == pytest.approx(84 / 85)
    assert float(checks["lm4651-eq8"].factor) == pytest.approx(0.22479 / (8.8541878128e-12 * 0.0254 * 1e12), rel=1e-6)


def test_heat_sink_from_the_recomputed_dissipation_and_the_printed_21_w():
    rows = {r["id"]: r for r in lm4651.evaluate()}
    assert rows["lm4651-theta-tf"]["computed"] == pytest.approx(
        lm4651.theta_sa_required(rows["lm4651-p-total"]["computed"], 50.0, "TF", 0.2), rel=1e-12)
    # a change of the edge times reaches the heat sink through the dissipation
    changed = {r["id"]: r for r in lm4651.evaluate(lm4651.params(t_rise=50e-9))}
    assert changed["lm4651-theta-tf"]["status"] == "n/a"
    assert changed["lm4651-overmod"]["status"] == "inconsistent"


def test_parameters_are_checked_and_defaults_come_from_the_facts():
    from handbook.core import InputError

    defaults = lm4651.SOURCE.defaults
    assert defaults["t_overmod_table"] == lm4651.DEVICE["t_overmod"] == lm4651.FACTS["t_overmod"].value
    assert all(defaults[k] == lm4651.DEVICE[k] for k in ("t_rise", "t_fall", "rds_on_hot", "tj_max", "p_driver"))
    with pytest.raises(InputError, match="t_overmod_table"):
        lm4651.params(t_overmod_tabel=300e-9)
    with pytest.raises(InputError, match="out of range"):
        lm4651.params(r_load=-4.0)


def test_the_three_r1_values_are_an_erratum_with_their_corners():
    text = {e.id: e for e in lm4651.SOURCE.errata}["lm4651-t-r1"]
    for r1, corner in ((25e3, 6.4), (20e3, 8.0), (4.7e3, 33.9)):
        assert 1 / (2 * math.pi * r1 * 1e-6) == pytest.approx(corner, abs=0.05)
        assert f"{corner:.1f} Hz" in text.evidence

