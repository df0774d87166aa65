"""AN93008: equations, numbers against hand calculations, statuses, the supply-referenced worst case, errata."""
import re

import pytest

from handbook import catalog, report
from handbook.core import InputError
from handbook.sources import SOURCES, an93008

A = 33 / 40.5  # R9 / (R8 + R9), by hand

HAND_93 = {
    "an93008-vbe-tc": -0.0025, "an93008-offset-generic": 0.1, "an93008-vsupply-min": 10.8,
    "an93008-level-shift": 10.8 * 7.5 / 40.5, "an93008-vplus": 10.8 * A, "an93008-factor-a": A,
    "an93008-vcs-at-opamp": 0.1 * A, "an93008-window-high": 0.1 * A + 0.009, "an93008-window-low": 0.1 * A - 0.009,
    "an93008-offset-tol": 0.009 / (0.1 * A), "an93008-supply-tol": 0.1, "an93008-b": A * 10.7 / 10.8,
    "an93008-r10": 33e3 * (1 - A * 10.7 / 10.8) / (A * 10.7 / 10.8), "an93008-total-supply": 1.11 * 1.1 * 1.05 - 1,
    "an93008-vz-min": 0.95 * 8.2, "an93008-factor-a-zener": 1 - 2 / 7.7, "an93008-offset-tol-zener": 9 / 74,
    "an93008-zener-drift": 0.155, "an93008-zener-drift-pct": 0.155 / 7.7, "an93008-zener-total": 0.07,
    "an93008-total-zener": 1.12 * 1.07 * 1.05 - 1, "an93008-zener-total-a": 0.03,
    "an93008-total-zener-a": 1.12 * 1.03 * 1.05 - 1,
    # against the BZX79-C8V2 datasheet (7.7 to 8.7 V at 5 mA, up to +0.08 %/K)
    "an93008-zener-spread": 0.5 / 8.2,  # both limits 0.5 V from 8.2 V: +-6.1 %
    "an93008-zener-tc": 0.00085 * 8.2,  # the column's 0.08 %/K printed to one figure: up to 0.085 %/K, 6.97 mV/K
    "an93008-zener-share": 0.5 / 8.2 + 6.2e-3 * 25 / 7.7,  # 6.10 % + the note's 2.01 % drift = 8.11 %
}
MISPRINTS = set()
INCONSISTENT = {"an93008-zener-spread", "an93008-zener-share"}
BOUNDS_MET = {"an93008-zener-tc"}  # 'max. 6.2 mV/°C' (0.076 %/K) inside the datasheet's column: not an erratum
WRONG = {"an93008-resistor-tol"}  # a wrong method, which errata lists with the misprints


@pytest.mark.parametrize("ex_id,value", sorted(HAND_93.items()))
def test_recomputed_against_hand(ex_id, value):
    rows = {r["id"]: r for r in an93008.evaluate()}
    assert rows[ex_id]["computed"] == pytest.approx(value, rel=1e-9)


def test_statuses():
    rows = an93008.evaluate()
    assert {r["id"] for r in rows} == set(HAND_93) | {"an93008-resistor-tol"}
    assert {r["id"] for r in rows if r["status"] == "misprint"} == MISPRINTS
    assert {r["id"] for r in rows if r["status"] == "wrong method"} == WRONG
    assert {r["id"] for r in rows if r["status"] == "inconsistent"} == INCONSISTENT
    assert {r["id"] for r in rows if r["status"] == "bound met"} == BOUNDS_MET
    assert all(r["status"] in ("exact", "rounding", "truncated", "rounded intermediate") for r in rows
               if r["id"] not in MISPRINTS | WRONG | INCONSISTENT | BOUNDS_MET)
    assert all(r["consequence"] for r in rows if r["id"] in INCONSISTENT)
    # R10 = 7.87 k follows from the rounded A = 0.815, not from the exact 0.81481
    assert {r["id"]: r["status"] for r in rows}["an93008-r10"] == "rounded intermediate"
    # 155 mV printed 150 and 7.79 V printed 7.7: cut off, not rounded by either rule
    assert {r["id"] for r in rows if r["status"] == "truncated"} == {"an93008-vz-min", "an93008-zener-drift"}


def test_supply_referenced_worst_case_by_hand():
    wc = an93008.supply_worst_case(an93008.SOURCE.defaults)
    # high corner: supply +10 %, R8 -, R9 +, R10 +, R11 -, offset -9 mV
    v, r8, r9, r10, r11 = 13.2, 7.5e3 * .95, 33e3 * 1.05, 7.87e3 * 1.05, 33e3 * .95
    a, b = r9 / (r8 + r9), r11 / (r10 + r11)
    assert wc.high == pytest.approx(v * (1 - b / a) + 9e-3 / a, rel=1e-12)
    assert wc.low < 0  # some boards never limit


def test_params_refuse_unknown_names_and_out_of_range_values():
    assert an93008.params(r8=8.2e3)["r8"] == 8.2e3
    with pytest.raises(InputError, match="did you mean 'r8'"):
        an93008.params(r88=8.2e3)
    with pytest.raises(InputError, match="out of range"):
        an93008.params(supply_tolerance=2.0)


def test_equations_check():
    eqs = {e.id: e.check() for e in an93008.SOURCE.equations()}
    assert all(c.dims_ok for c in eqs.values())
    assert {k for k, c in eqs.items() if not c.agrees} == {"an93008-eq2"}


def test_errata_cover_every_misprint_and_inconsistency_with_a_consequence():
    rows = catalog.errata()
    ids = {r["id"] for r in rows}
    same_fact = {c.id for src in SOURCES for c in src.claims() if c.same_fact}
    bad = {r["id"] for src in SOURCES for r in src.evaluate() if r["status"] in ("misprint", "inconsistent")}
    assert bad - same_fact <= ids and MISPRINTS | WRONG <= ids and not same_fact & ids
    assert all(r["consequence"] for r in rows)
    notes = {r["id"] for r in catalog.reading_notes()}
    assert {"an94002-eq2", "tda5341-capcdm"} <= notes - ids  # reconstructed equations are reading notes
    assert "an94002-eq11-num" not in ids  # differs by rounded constants only


def test_errata_by_source_document_and_as_book_entries():
    rows = catalog.errata()
    by_note = {n: catalog.errata(n) for n in ("AN94002", "AN93008", "TDA5341", "LM4651/LM4652", "TCA5600")}
    assert sum(len(v) for v in by_note.values()) == len(rows)
    assert all(r["note"] == n for n, v in by_note.items() for r in v)
    with pytest.raises(ValueError, match="AN94002"):
        catalog.errata("AN9400")
    counts = report.errata_counts(rows).data.splitlines()
    assert counts[-1].split("|")[-2].strip() == str(len(rows))
    text = report.errata_md(by_note["AN94002"]).data
    # the note's 22 uA against the TDA5144's 11 uA charge current, in the note's own unit
    assert "printed 22 µA, recomputed 11 µA" in text  # units as a person reads them
    assert text.count("\n- ") + 1 == len(by_note["AN94002"])
    assert "Evidence: " in text and "For a designer: " in text
    assert not re.search(r"\.\.(\\|$)", text, re.MULTILINE)  # one full stop at each sentence's end


def test_the_7v7_zener_minimum_is_a_truncation_not_a_misprint_and_the_ground_erratum():
    rows = {r["id"]: r for r in an93008.evaluate()}
    # "0.95 x 8.2 = 7.7 V": the product is 7.79 V, cut (not rounded) to one decimal; the book's status says so
    assert rows["an93008-vz-min"]["status"] == "truncated" and rows["an93008-vz-min"]["computed"] == pytest.approx(7.79)
    assert "truncated" in rows["an93008-vz-min"]["reason"]
    assert "an93008-vz-min" not in {r["id"] for r in catalog.errata("AN93008")}
    text = {e.id: e for e in an93008.SOURCE.errata}["an93008-t-gnd"]
    assert "GND3" in text.evidence and "AN94002" in text.source


def test_the_zener_errata_match_an94002s_by_hand():
    rows = {r["id"]: r for r in an93008.evaluate()}
    errata = {r["id"] for r in catalog.errata("AN93008")}
    assert INCONSISTENT - {"an93008-zener-share"} <= errata  # the share is the spread's fact, listed there
    # "8.2 V +-5 % (BZX79 C 8V2)": the datasheet's 7.7 .. 8.7 V is -6.10 % / +6.10 %
    spread = max(8.2 - 7.7, 8.7 - 8.2) / 8.2
    assert spread == pytest.approx(0.0610, abs=5e-5)
    assert rows["an93008-zener-spread"]["computed"] == pytest.approx(spread, rel=1e-12)
    assert rows["an93008-zener-spread"]["printed"] == 0.05
    # "+-5 % ... +-7 %": 6.10 % + 155 mV / 7.7 V (2.01 %) = 8.11 %; the total 1.12 x 1.081 x 1.05 is +27 %
    with_drift = spread + 6.2e-3 * 25 / 7.7
    assert with_drift == pytest.approx(0.0811, abs=5e-5)
    assert rows["an93008-zener-share"]["computed"] == pytest.approx(with_drift, rel=1e-12)
    assert round((1.12 * (1 + with_drift) * 1.05 - 1) * 100) == 27
    # "max. 6.2 mV/°C" is 0.0756 %/K at 8.2 V, which the datasheet's one-figure "+0.08 %/K" column holds
    assert round(6.2e-3 / 8.2 * 100, 2) == 0.08 and rows["an93008-zener-tc"]["status"] == "bound met"
    assert "an93008-zener-tc" not in errata
    for ex_id in INCONSISTENT | BOUNDS_MET:
        assert rows[ex_id]["basis"] == "BZX79 datasheet"


def test_factor_a_uses_the_notes_own_7v7():
    rows = {r["id"]: r for r in an93008.evaluate()}
    # "The minimum zener voltage is 0.95 x 8.2 = 7.7 V ... The factor A ... will now be 0.74": 1 - 2 / 7.7
    assert rows["an93008-factor-a-zener"]["computed"] == pytest.approx(0.74026, abs=5e-6)
    assert rows["an93008-factor-a-zener"]["status"] == "rounding"
