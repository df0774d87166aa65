"""AN93008 and the TDA5341 excerpt: equations, numbers against hand calculations, statuses, errata."""
import math
import re

import pytest

from handbook import an93008, book, catalog, tda5341

A = 33 / 40.5  # R9 / (R8 + R9), by hand

HAND_93 = {
    "an93008-vbe-tc": -0.0025, "an93008-offset-generic": 0.1, "an93008-vsupply-min": 10.8,
    "an93008-level-shift": 10.8 * 7.5 / 40.5, "an93008-vplus": 10.8 * A, "an93008-factor-a": A,
    "an93008-vcs-at-opamp": 0.1 * A, "an93008-window-high": 0.1 * A + 0.009, "an93008-window-low": 0.1 * A - 0.009,
    "an93008-offset-tol": 0.009 / (0.1 * A), "an93008-supply-tol": 0.1, "an93008-b": A * 10.7 / 10.8,
    "an93008-r10": 33e3 * (1 - A * 10.7 / 10.8) / (A * 10.7 / 10.8), "an93008-total-supply": 1.11 * 1.1 * 1.05 - 1,
    "an93008-vz-min": 7.79, "an93008-factor-a-zener": 1 - 2 / 7.79, "an93008-offset-tol-zener": 9 / 74,
    "an93008-zener-drift": 0.155, "an93008-zener-drift-pct": 0.155 / 7.7, "an93008-zener-total": 0.07,
    "an93008-total-zener": 1.12 * 1.07 * 1.05 - 1, "an93008-zener-total-a": 0.03,
    "an93008-total-zener-a": 1.12 * 1.03 * 1.05 - 1,
}
HAND_5341 = {
    "tda5341-fosc": math.sqrt(4.5e-3 * 0.48 * 6 / 6.34e-7) / (2 * math.pi), "tda5341-tstart": 1 / 48.4,
    "tda5341-capst": 0.024 / 0.78 * 1e-6, "tda5341-capst-choice": 33e-9, "tda5341-window": 1.41,
    "tda5341-constant": 10e-6 / 1.41 * 1e9, "tda5341-capcdm": 10e-6 / (1.41 * 1600), "tda5341-capcdm-choice": 4.7e-9,
    "tda5341-max-delay": 1.41 / 20e-6 * 1e-9, "tda5144-constant": 8.1e-6 / 1.3 * 1e9,
    "tda5144-cap": 8.1e-6 / (1.3 * 400), "tda5144-max-delay": 1.3 / 16.2e-6 * 1e-9,
}
MISPRINTS = {"an93008-resistor-tol", "an93008-vz-min", "tda5341-fosc", "tda5341-tstart", "tda5144-max-delay"}


@pytest.mark.parametrize("ex_id,value", sorted({**HAND_93, **HAND_5341}.items()))
def test_recomputed_against_hand(ex_id, value):
    rows = {r["id"]: r for r in an93008.examples() + tda5341.examples()}
    assert rows[ex_id]["computed"] == pytest.approx(value, rel=1e-9)


def test_statuses():
    rows = an93008.examples() + tda5341.examples()
    assert {r["id"] for r in rows} == set(HAND_93) | set(HAND_5341) | {"an93008-resistor-tol"}
    assert {r["id"] for r in rows if r["status"] == "misprint"} == MISPRINTS
    assert all(r["status"] in ("exact", "rounding") for r in rows if r["id"] not in MISPRINTS)
    # R10 = 7.87 k follows from the rounded A = 0.815, not from the exact 0.81481
    assert {r["id"]: r["status"] for r in rows}["an93008-r10"] == "rounding"


def test_supply_referenced_worst_case_by_hand():
    wc = an93008.supply_worst_case(an93008.DEFAULTS)
    # high corner: supply +10 %, R8 -, R9 +, R10 +, R11 -, offset -9 mV
    v, r8, r9, r10, r11 = 13.2, 7.5e3 * .95, 33e3 * 1.05, 7.87e3 * 1.05, 33e3 * .95
    a, b = r9 / (r8 + r9), r11 / (r10 + r11)
    assert wc.high == pytest.approx(v * (1 - b / a) + 9e-3 / a, rel=1e-12)
    assert wc.low < 0  # some boards never limit


def test_equations_check():
    eqs = {e.id: e.check() for e in an93008.equations() + tda5341.equations()}
    assert all(c.dims_ok for c in eqs.values())
    assert {k for k, c in eqs.items() if not c.agrees} == {"an93008-eq2", "tda5341-capcdm", "tda5341-max-delay"}
    assert float(eqs["tda5341-max-delay"].factor) == pytest.approx(0.070 / 0.0705)


def test_errata_cover_every_misprint_and_inconsistency_with_a_consequence():
    rows = catalog.errata()
    ids = {r["id"] for r in rows}
    bad = {r["id"] for r in catalog.examples() if r["status"] in ("misprint", "inconsistent")}
    assert bad <= ids and MISPRINTS <= ids
    assert all(r["consequence"] for r in rows)
    assert {"an94002-eq2", "tda5341-capcdm"} <= ids  # reconstructed equations are listed
    assert "an94002-eq11-num" not in ids  # differs by rounded constants only


def test_errata_by_source_document_and_as_book_entries():
    rows = catalog.errata()
    by_note = {n: catalog.errata(n) for n in ("AN94002", "AN93008", "TDA5341", "LM4651/LM4652", "TCA5600")}
    assert sum(len(v) for v in by_note.values()) == len(rows)
    assert all(r["note"] == n for n, v in by_note.items() for r in v)
    with pytest.raises(ValueError, match="AN94002"):
        catalog.errata("AN9400")
    counts = book.errata_counts(rows).data.splitlines()
    assert counts[-1].split("|")[-2].strip() == str(len(rows))
    text = book.errata_md(by_note["AN94002"]).data
    # the note's 22 uA against the TDA5144's 11 uA charge current, in the note's own unit
    assert "printed 22 uA, recomputed 11 uA" in text
    assert text.count("\n- ") + 1 == len(by_note["AN94002"])
    assert "Evidence: " in text and "For a designer: " in text
    assert not re.search(r"\.\.(\\|$)", text, re.M)  # one full stop at each sentence's end
