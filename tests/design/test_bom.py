"""The bill of materials (handbook.design.bom): every part a person reads with its unit, the values those of
the designs, and a CSV written whole or not at all."""
import csv
import os

import pytest

from handbook.design import bom, spec


@pytest.fixture(scope="module")
def designs():
    return spec.run({})


@pytest.mark.parametrize("ref, value, text", [("C3", 18e-9, "18 nF"), ("R9", 1210.0, "1.21 kΩ"), ("L1, L2", 100e-6, "100 µH"),
                                              ("D1", 8.2, "8.2 V"), ("heat sink", 0.6812, "0.681 K/W"),
                                              ("R7", 0.43, "430 mΩ")])
def test_readable_values_carry_their_unit(ref, value, text):
    assert bom.readable(ref, value, "E24") == text


def test_rows_are_the_designs_values_in_order(designs):
    rows = bom.rows(designs)
    refs = [r["reference"] for r in rows]
    assert refs[:2] == ["C3", "C4"] and refs[refs.index("R7"):refs.index("R7") + 7] == [
        "R7", "R9", "R10", "R11", "R12", "R13", "D1"]
    assert refs[-2:] == ["L1 (TCA5600)", "R1 (TCA5600)"]
    by = {r["reference"]: r for r in rows}
    lim, cd = designs["current_limiter"], designs["class_d"]
    assert by["R7"]["value"] == lim.r7 and by["R13"]["value"] == lim.network[4]
    assert by["C_BYP"]["value"] == cd.c_out and by["heat sink"]["tolerance"] is None
    assert all(r["reason"] and r["value_text"][-1] not in "0123456789" for r in rows)  # every value with a unit


def test_write_is_whole_or_nothing(tmp_path, designs):
    rows = bom.rows(designs)
    path = tmp_path / "bom.csv"
    bom.write(rows, path)
    back = list(csv.DictReader(path.open()))
    assert [r["reference"] for r in back] == [r["reference"] for r in rows]
    assert float(back[0]["value"]) == rows[0]["value"]
    path.write_text("old")
    with pytest.raises(ValueError):  # a row with a field the CSV does not have: nothing replaces the old file
        bom.write(rows + [{"reference": "X", "colour": "red"}], path)
    assert path.read_text() == "old" and os.listdir(tmp_path) == ["bom.csv"]
