"""The converter through the command line and the bill of materials: exit 2 and 3 with their messages, JSON in
SI, text with units."""
import json
import subprocess
import sys

import pytest

from handbook.cli import main as cli_main
from handbook.design import bom


def test_bom_rows(result):
    rows = {r["designator"]: r for r in bom.converter_rows(result)}
    coil, r1 = rows["A4-L1"], rows["A4-R1"]
    assert coil["value"] == result.l1_nominal and coil["tolerance"] == 0.1 and "eq 6" in coil["reason"]
    assert "Ferroxcube" in coil["technology"] or "TDK" in coil["technology"]
    assert (r1["value"], r1["tolerance"]) == (pytest.approx(1.69), 0.01) and r1["reason"].startswith("E96 value")
    assert "1.764 Ω over its high end (+1 % and +0.6 % drift at 85 °C), rounded down" in r1["reason"]
    assert "672.2 µH at most at +10 % A_L" in coil["reason"] and r1["tempco"] == "≤ 100 ppm/K"


def _cli(tmp_path, capsys, text, *extra):
    path = tmp_path / "spec.toml"
    path.write_text(text)
    code = cli_main(["design", str(path), *extra])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize("text,needle", [
    # V_F at its low end, 0.72 V: 8 - 2.5 - 0.72 = 4.78 V
    ("[converter]\nv_out = 3.0\n", "converter.v_out = 3 V must be above v_supply_min - v_regulator_drop - v_f x "
                                   "(1 - device_spread) = 4.78 V"),
    ("[converter]\nf_min = 5e7\n", "converter.f_min = 50 MHz is out of range: use a value from 1 kHz to 1 MHz"),
    ("[converter]\nf_min = 500.0\n", "converter.f_min = 500 Hz is out of range: use a value from 1 kHz to 1 MHz"),
    ("[converter]\ni_out = -1\n", "converter.i_out = -1 A is out of range: use a value > 0 A and <= 10 A"),
    ("[commutation]\ni_charge_min = 22\n", "commutation.i_charge_min = 22 A is out of range: use a value > 0 A and "
                                           "<= 1 mA"),
    ("[converter]\nv_supply_min = 0.8\n", "converter.v_supply_min = 0.8 V must be above (v_ce_sat + v12h) x "
                                           "(1 + device_spread) = 0.99 V"),
    ("[converter]\ndevice_spread = 0.6\n", "converter.device_spread = 0.6 is out of range: use a value from 0 to 0.5"),
    ("[converter]\nv_supply_max = 7.5\n", "converter.v_supply_min = 8 V must not exceed converter.v_supply_max = "
                                           "7.5 V"),
    ("[converter]\nr1_series = 'E7'\n", "converter.r1_series = 'E7': use one of"),
    ("[converter]\nf_mni = 3e4\n", "did you mean converter.f_min"),
])
def test_cli_bad_input_exits_2(tmp_path, capsys, text, needle):
    code, _, err = _cli(tmp_path, capsys, text)
    assert code == 2 and needle in err, err


def test_cli_infeasible_exits_3_saying_what_would(tmp_path):
    path = tmp_path / "spec.toml"
    path.write_text("[converter]\ni_out = 5.0\n")
    out = subprocess.run([sys.executable, "-m", "handbook", "design", str(path), "--json"], capture_output=True,
                         text=True, timeout=60)
    assert out.returncode == 3 and "Traceback" not in out.stderr
    body = json.loads(out.stdout)
    info = body["infeasible"]
    assert info["table"] == "converter" and "larger core family" in info["message"]
    assert 1.0 < info["achievable"]["i_out"] < 5.0
    assert body["class_d"]["f_sw"] > 0  # the other tables are still designed


def test_cli_json_si_bom_and_text_with_units(tmp_path, capsys):
    code, out, err = _cli(tmp_path, capsys, "[converter]\naudible = 'warn'\n", "--json", "--bom", str(tmp_path / "bom.csv"))
    assert code == 0, err
    r = json.loads(out)["converter"]
    assert r["l1"] == pytest.approx(887.33e-6, rel=1e-4) and isinstance(r["gap"], float) and r["turns"] == 64
    assert r["r1_part"] == pytest.approx(1.69) and r["binding"].startswith("current density")
    assert r["f_sw_min"] == pytest.approx(4345, rel=1e-3) and r["i_out_least"] == pytest.approx(0.05136, rel=1e-3)
    bom_text = (tmp_path / "bom.csv").read_text()
    assert "A4,A4-L1,1,\"converter coil, wound to order\"" in bom_text
    assert "611.1 µH,0.1," in bom_text and "1.69 Ω,0.01," in bom_text
    code, text, _ = _cli(tmp_path, capsys, "[converter]\naudible = 'warn'\n")
    # eq 1 to 6a at the nominal figures; R1, L1 and the frequencies at the corners (test_converter_result's hand
    # figures): 1.764 ohm in the corner that delivers least, 51.36 mA delivered there, 264.6 mA at the highest peak
    for needle in ("887.3 µH", "611.1 µH", "1.764 Ω", "1.69 Ω", "51.36 mA", "202.8 mA", "264.6 mA", "25.35 µs", "EP 10",
                   "4.345 kHz", "31.59 kHz", "current density (the next smaller core"):
        assert needle in text, needle


def test_text_of_tiny_and_huge_values(tmp_path, capsys):
    """A microampere spec designs (with warnings): henries, kilohms and thousands of turns shown with prefixes
    (R1 = 86.6 kohm: E96 below 88.20 kohm / 1.01606; the coil 34.44 H at most, 6119 turns)."""
    code, text, err = _cli(tmp_path, capsys, "[converter]\ni_out = 1e-6\naudible = 'warn'\n")
    assert code == 0, err
    for needle in ("44.37 H", "98.61 kΩ", "86.6 kΩ", "34.44 H", "6119", "self-resonates"):
        assert needle in text, needle


def test_template_designs(tmp_path, capsys):
    from handbook.cli_text import template

    text = template()
    assert "[converter]" in text and "v12h = 0.4" in text and "v_supply_max = 14.4" in text
    code, _, err = _cli(tmp_path, capsys, text, "--json")
    assert code == 0, err
