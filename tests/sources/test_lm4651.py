"""LM4651/LM4652: the datasheet's numbers against hand calculations, and their statuses."""
import math

import pytest

from handbook import lm4651

X = (25 + 26 + 350) * 1e-9 * 125e3  # eq 9 with the example's 350 ns
HAND = {
    "lm4651-f-4k": 125e3, "lm4651-f-15k": 1e9 / 19e3, "lm4651-f-0": 250e3, "lm4651-dead-time": 0.85e-9,
    "lm4651-rosc": 1e9 / 125e3 - 4000 + 2000, "lm4651-isckt": 1e5 / (1e4 * 1e5 / 1.1e5), "lm4651-cstart": 1 / 8.5e4,
    "lm4651-vout-rms": math.sqrt(500), "lm4651-gain": math.sqrt(500) / 3, "lm4651-gain-db": 20 * math.log10(math.sqrt(500) / 3),
    "lm4651-r2-ratio": 0.7, "lm4651-r2": 14e3, "lm4651-overmod": 310e-9, "lm4651-loss-pct": X,
    "lm4651-p-switch": X * 125 / (1 - X), "lm4651-i-rms": math.sqrt(125 / 4), "lm4651-p-rds": 125 / 4 * 0.46,
    "lm4651-p-total": X * 125 / (1 - X) + 125 / 4 * 0.46, "lm4651-theta-tf": 100 / 21 - 2.2, "lm4651-theta-t": 100 / 21 - 1.2,
    "lm4651-efficiency": 125 / 147, "lm4651-system-pd": X * 125 / (1 - X) + 125 / 4 * 0.46 + 1.0,
    "lm4651-eps0": 8.8541878128e-12 * 0.0254 * 1e12, "lm4651-rf-ratio": 10.0,
    "lm4651-gain-4k7": 3.5 / 4.7 * 11 - 3.5 / 4.7 + 0.5,
}
STATUS = {
    "inconsistent": {"lm4651-f-15k", "lm4651-f-0", "lm4651-dead-time", "lm4651-overmod", "lm4651-eps0"},
    "misprint": {"lm4651-rosc", "lm4651-isckt", "lm4651-cstart", "lm4651-theta-tf", "lm4651-theta-t",
                 "lm4651-gain-4k7"},
}


@pytest.mark.parametrize("ex_id,value", sorted(HAND.items()))
def test_recomputed_against_hand(ex_id, value):
    assert {r["id"]: r for r in lm4651.examples()}[ex_id]["computed"] == pytest.approx(value, rel=1e-9)


def test_statuses_and_consequences():
    rows = lm4651.examples()
    assert {r["id"] for r in rows} == set(HAND)
    for status, ids in STATUS.items():
        assert {r["id"] for r in rows if r["status"] == status} == ids
    assert all(r["status"] in ("exact", "rounding") for r in rows if r["id"] not in set().union(*STATUS.values()))
    assert all(r["consequence"] for r in rows if r["status"] in ("misprint", "inconsistent"))


def test_equations():
    checks = {e.id: e.check() for e in lm4651.equations()}
    assert all(c.dims_ok for c in checks.values())
    assert {k for k, c in checks.items() if not c.agrees} == {"lm4651-eq2", "lm4651-eq8"}
    assert float(checks["lm4651-eq2"].factor) == pytest.approx(84 / 85)
    assert float(checks["lm4651-eq8"].factor) == pytest.approx(0.22479 / (8.8541878128e-12 * 0.0254 * 1e12), rel=1e-6)
