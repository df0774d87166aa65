"""The TDA5341 excerpt (and the TDA5144 datasheet's version): equations, numbers against hand calculations, statuses."""
import math

import pytest

from handbook.sources import tda5341

HAND_5341 = {
    "tda5341-fosc": math.sqrt(4.5e-3 * 0.48 * 6 / 6.34e-7) / (2 * math.pi), "tda5341-tstart": 1 / 48.4,
    "tda5341-capst": 0.024 / 0.78 * 1e-6, "tda5341-capst-choice": 33e-9, "tda5341-window": 1.41,
    "tda5341-constant": 10e-6 / 1.41 * 1e9, "tda5341-capcdm": 10e-6 / (1.41 * 1600), "tda5341-capcdm-choice": 4.7e-9,
    "tda5341-max-delay": 1.41 / 20e-6 * 1e-9, "tda5144-constant": 8.1e-6 / 1.3 * 1e9,
    "tda5144-cap": 8.1e-6 / (1.3 * 400), "tda5144-max-delay": 1.3 / 16.2e-6 * 1e-9,
}
MISPRINTS = {"tda5341-tstart", "tda5144-max-delay"}


@pytest.mark.parametrize("ex_id,value", sorted(HAND_5341.items()))
def test_recomputed_against_hand(ex_id, value):
    rows = {r["id"]: r for r in tda5341.evaluate()}
    assert rows[ex_id]["computed"] == pytest.approx(value, rel=1e-9)


def test_statuses():
    rows = tda5341.evaluate()
    assert {r["id"] for r in rows} == set(HAND_5341)
    assert {r["id"] for r in rows if r["status"] == "misprint"} == MISPRINTS
    assert all(r["status"] in ("exact", "rounding", "truncated", "rounded intermediate")
               for r in rows if r["id"] not in MISPRINTS)
    assert all(r["consequence"] for r in rows if r["id"] in MISPRINTS)
    # 22.755 Hz printed 22.7: the last digit cut off, not rounded (22.8): truncated, not a misprint
    fosc = {r["id"]: r for r in rows}["tda5341-fosc"]
    assert fosc["status"] == "truncated" and "truncated" in fosc["reason"]
    assert math.floor(fosc["computed"] * 10) / 10 == 22.7 and round(fosc["computed"], 1) == 22.8


def test_equations_check():
    eqs = {e.id: e.check() for e in tda5341.SOURCE.equations()}
    assert all(c.dims_ok for c in eqs.values())
    assert {k for k, c in eqs.items() if not c.agrees} == {"tda5341-capcdm", "tda5341-max-delay"}
    assert float(eqs["tda5341-max-delay"].factor) == pytest.approx(0.070 / 0.0705)
