"""`python -m handbook design SPEC.toml --schematic DIR`: one SVG per designed table the spec asked for (as --bom
decides), valid XML, labelled with the chosen values; an unwritable folder exits 2 with a message and leaves
nothing behind. And each designed drawing passes the drawing tests of tests/spice/test_drawings.py."""
import functools
import json
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from drawn_layout import faults
from drawn_parts import drawn_parts

from handbook.core.units import eng

SVG = "{http://www.w3.org/2000/svg}"


def _run(tmp_path, text, *extra):
    path = tmp_path / "spec.toml"
    path.write_text(text)
    return subprocess.run([sys.executable, "-m", "handbook", "design", str(path), *extra],
                          capture_output=True, text=True, timeout=120)


def _texts(path) -> list[str]:
    root = ET.parse(path).getroot()  # raises on anything that is not well-formed XML
    assert root.tag == SVG + "svg"
    return ["".join(t.itertext()) for t in root.iter(SVG + "text")]


def test_one_svg_per_asked_table_with_the_chosen_values(tmp_path):
    folder = tmp_path / "new" / "schematics"  # made, parents too
    out = _run(tmp_path, "[current_limiter]\n[converter]\n", "--schematic", str(folder), "--json")
    assert out.returncode == 0, out.stderr
    r = json.loads(out.stdout)
    assert sorted(p.name for p in folder.iterdir()) == ["converter.svg", "current_limiter.svg"]
    assert r["schematic"]["files"] == [str(folder / "current_limiter.svg"), str(folder / "converter.svg")]
    lim, conv = _texts(folder / "current_limiter.svg"), _texts(folder / "converter.svg")
    # the notes' default limiter designs R7 = 430 mΩ (the design CLI's own test); the drawing prints it under "R7"
    assert r["current_limiter"]["r7"] == pytest.approx(0.43)
    assert "430 mΩ" in lim and lim.index("430 mΩ") == lim.index("R7") + 1
    for key, ref in (("r9", "R9"), ("r10", "R10"), ("r11", "R11"), ("r12", "R12"), ("r13", "R13"), ("r14", "R14")):
        assert lim[lim.index(ref) + 1] == eng(r["current_limiter"][key], "Ω"), ref
    assert "R1 " + eng(r["converter"]["r1_part"], "Ω") in conv  # R1 as bought, L1 as wound: the BOM's values
    assert "L1 " + eng(r["converter"]["l1_nominal"], "H") in conv
    assert not [t for t in lim + conv if "ohm" in t.lower() or " uF" in t]


def _main(tmp_path, monkeypatch, text, *extra, results=None):
    """The command in this process, every table designed once (:func:`_designs`), or ``results`` as given."""
    from handbook import cli
    from handbook.design import spec as specmod

    designs = dict(results or _designs())
    monkeypatch.setattr(specmod, "run_each", lambda spec: dict(designs))
    path = tmp_path / "spec.toml"
    path.write_text(text)
    return cli.main(["design", str(path), *extra])


def test_the_tables_drawn_are_the_ones_the_spec_asked_for(tmp_path, monkeypatch, capsys):
    folder = tmp_path / "one"
    assert _main(tmp_path, monkeypatch, "[commutation]\n", "--schematic", str(folder)) == 0
    assert [p.name for p in folder.iterdir()] == ["commutation.svg"]
    texts = _texts(folder / "commutation.svg")
    c3 = eng(_designs()["commutation"].cap_cd, "F")
    assert c3 == "8.2 nF" and f"C3 {c3}" in texts and f"C4 {c3}" in texts  # the notes' defaults: E12 8.2 nF
    folder = tmp_path / "all"
    assert _main(tmp_path, monkeypatch, "", "--schematic", str(folder)) == 0
    assert sorted(p.name for p in folder.iterdir()) == ["class_d.svg", "commutation.svg", "converter.svg",
                                                         "current_limiter.svg"]


def test_a_table_that_cannot_be_met_is_left_out_and_named(tmp_path, monkeypatch, capsys):
    from handbook.design.solvers import Infeasible

    folder = tmp_path / "s"
    results = {**_designs(), "commutation": Infeasible("commutation", "rpm_max cannot be met", {})}
    assert _main(tmp_path, monkeypatch, "[commutation]\n[class_d]\n", "--schematic", str(folder), results=results) == 3
    assert "schematic: [commutation] left out: it cannot be met" in capsys.readouterr().err
    assert [p.name for p in folder.iterdir()] == ["class_d.svg"]


def test_an_unwritable_folder_exits_2_with_a_message_and_writes_nothing(tmp_path, monkeypatch, capsys):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    assert _main(tmp_path, monkeypatch, "[current_limiter]\n", "--schematic", str(blocker / "sub"), "--json") == 2
    out = capsys.readouterr()
    assert f"error: cannot write the schematics to {blocker / 'sub'}: Not a directory" in out.err
    assert json.loads(out.out)["error"]["exit"] == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file", "spec.toml"]


def test_a_write_failing_half_way_leaves_none_of_the_files(tmp_path):
    from handbook.spice import designed

    results = _designs()
    (tmp_path / "converter.svg").mkdir()  # the second file cannot be put in place
    with pytest.raises(OSError):
        designed.write_svgs({t: results[t] for t in ("current_limiter", "converter")}, tmp_path)
    assert [p.name for p in tmp_path.iterdir()] == ["converter.svg"]  # the blocker alone: no SVG, no temporary file


@functools.cache
def _designs() -> dict:
    """Every table designed from the notes' defaults (an empty spec: all four)."""
    from handbook.design import spec as specmod

    return specmod.run_each(specmod.parse({}))


#: what each designed drawing must carry: {table: {designator as read back: the result's attribute, or a key of
#: its spec}}
CARRIED = {"commutation": {"C3": "cap_cd", "C4": "cap_dc"},
           "current_limiter": {"R7": "r7", "R9": "r9", "R10": "r10", "R11": "r11", "R12": "r12", "R13": "r13",
                               "R14": "r14"},
           "class_d": {"L1": "l_out", "L2": "l_out", "C1": "c_out", "RL": "spec:r_load", "VO1": "spec:supply"},
           "converter": {"L1": "l1_nominal", "R1": "r1_part", "VCC2": "spec:v_supply_min", "U1": "spec:v12h"}}


@pytest.mark.parametrize("table", sorted(CARRIED))
def test_each_designed_drawing_is_clean_and_carries_the_design(table):
    from handbook.spice import designed

    result = _designs()[table]
    d = designed.drawing(table, result)
    assert faults(d) == []
    on = drawn_parts(d)
    for ref, attr in CARRIED[table].items():
        want = result.spec[attr[5:]] if attr.startswith("spec:") else getattr(result, attr)
        assert on[ref] == pytest.approx(want, rel=1e-3), ref


#: what a designed drawing shows that is no part to order: the simulation's stimulus, the load, a device's inside
NOT_ORDERED = {"commutation": {"I_CH", "I_DIS", "V_LOW", "V_HIGH", "ICH", "IDIS", "VLOW", "VHIGH"},
               "current_limiter": {"VS", "IM"}, "class_d": {"VO1", "VO2", "RL"}, "converter": {"VCC2", "S1", "VC2"}}


@pytest.mark.parametrize("table", sorted(CARRIED))
def test_each_drawn_part_to_order_carries_its_bom_designator(table):
    """The drawing and the BOM name a part alike (the limiter's LM358 is IC2, C_BYP is C1), and its value is the
    BOM's."""
    from handbook.design import bom
    from handbook.spice import designed

    result = _designs()[table]
    rows = bom.ROWS[table](result)
    ordered = {ref.split("-", 1)[1]: row for row in rows for ref in row["designator"].split()}
    on = drawn_parts(designed.drawing(table, result))
    to_order = set(on) - NOT_ORDERED[table]
    assert to_order and to_order <= set(ordered), (table, sorted(to_order - set(ordered)))
    for ref in to_order:
        if ordered[ref]["value"] is not None and isinstance(on[ref], float):
            assert on[ref] == pytest.approx(ordered[ref]["value"], rel=1e-3), ref


def test_the_converter_is_drawn_at_the_specs_operating_point_not_the_chapters():
    from handbook.design import spec as specmod
    from handbook.spice import designed

    result = specmod.run_each(specmod.parse({"converter": {"v_supply_min": 9.0, "v12h": 0.45}}))["converter"]
    on = drawn_parts(designed.drawing("converter", result))
    assert (on["VCC2"], on["U1"]) == (pytest.approx(9.0), pytest.approx(0.45))  # the chapter's are 8 V, 400 mV
