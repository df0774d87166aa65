"""`python -m handbook design`: exit codes, messages naming the key, JSON and the BOM."""
import json
import subprocess
import sys

import pytest


def _run(tmp_path, text, *extra):
    path = tmp_path / "spec.toml"
    path.write_text(text)
    return subprocess.run([sys.executable, "-m", "handbook", "design", str(path), *extra],
                          capture_output=True, text=True, timeout=60)


def test_design_cli_empty_spec_designs_the_notes_examples(tmp_path):
    out = _run(tmp_path, "", "--json")
    assert out.returncode == 0, out.stderr
    r = json.loads(out.stdout)
    # 11 uA (the source column's maximum) x t_com(1800 rpm, 6 pole pairs) = 10 / 10800 s, into the narrowest
    # window 2.3 V - 0.9 V at -5 %: 7.66 nF -> E12 8.2 nF (the note's 18 nF used the 22 uA sink current)
    assert 11e-6 * 10 / 10800 / (1.4 * 0.95) == pytest.approx(7.658e-9, rel=1e-3)
    assert r["commutation"]["cap_cd"] == 8.2e-9 and r["commutation"]["cap_st"] is None
    assert {"cap_cd", "rpm_min_reliable", "rpm_max_reliable", "cap_st", "cap_ti", "warnings"} <= set(r["commutation"])
    assert {"r7", "r9", "r10", "r11", "r12", "r13", "i_trip_min", "i_trip_max", "margin_low", "margin_high",
            "headroom_min", "warnings", "i_trip_nominal", "p_r7", "binding"} <= set(r["current_limiter"])
    assert {"f_sw", "f_sw_min", "f_sw_max", "r_osc", "r_dly", "l_out", "c_out", "theta_sa_required", "t_junction",
            "p_dissipation", "efficiency", "thd_n", "warnings", "binding"} <= set(r["class_d"])
    assert all(isinstance(r[t]["warnings"], list) for t in ("commutation", "current_limiter", "class_d", "converter"))


def test_text_output_names_the_tables_the_spec_did_not_ask_for(tmp_path):
    out = _run(tmp_path, "[class_d]\np_out = 50.0\n")
    assert out.returncode == 0, out.stderr
    heads = [line for line in out.stdout.splitlines() if line.startswith("[")]
    assert heads == ["[commutation]  (not in your spec: the notes' defaults)",
                     "[current_limiter]  (not in your spec: the notes' defaults)", "[class_d]",
                     "[converter]  (not in your spec: the notes' defaults)"]
    assert all(h in _run(tmp_path, "").stdout.splitlines() for h in ("[commutation]", "[class_d]"))


def test_design_cli_text_output_has_units(tmp_path):
    out = _run(tmp_path, "")
    assert out.returncode == 0, out.stderr
    assert "8.2 nF" in out.stdout and "430 mΩ" in out.stdout and " kHz" in out.stdout and "e-0" not in out.stdout


@pytest.mark.parametrize("text,needle", [
    ("[commutation]\nrpm_mni = 900\n", "did you mean commutation.rpm_min"),
    ("[commutation]\ni_charge_max = 22\n", "commutation.i_charge_max = 22"),
    ("[commutation]\npole_pairs = -2\n", "commutation.pole_pairs"),
    ("[commutation]\nrpm_min = 1800\nrpm_max = 900\n", "rpm_min = 1800 rpm must be below"),
    ("[current_limiter]\ni_no_trip = 2.0\ni_must_trip = 1.0\n", "i_no_trip = 2 A must be below"),
    ("[class_d]\npackage = 'TO3'\n", "class_d.package"),
    ("[class_d]\np_out = nan\n", "finite"),
    ("[clas_d]\n", "did you mean [class_d]"),
    ("[commutation\n", "not valid TOML"),
])
def test_design_cli_bad_input_exits_2_naming_the_key(tmp_path, text, needle):
    out = _run(tmp_path, text)
    assert out.returncode == 2 and needle in out.stderr and "Traceback" not in out.stderr


def test_design_cli_unmeetable_spec_exits_3_with_what_can_be_met(tmp_path):
    out = _run(tmp_path, "[commutation]\nrpm_max = 50000\n", "--json")
    assert out.returncode == 3 and "Traceback" not in out.stderr
    info = json.loads(out.stdout)["infeasible"]
    # 8.2 nF at +5 % with the smallest current 5.3 uA swings 0.1 V (the noise floor) up to 10 259 rpm
    expected = 5.3e-6 * 10 / (6 * 8.2e-9 * 1.05 * 0.1)
    assert info["table"] == "commutation" and info["achievable"]["rpm_max_reliable"] == pytest.approx(expected, rel=1e-6)


def test_bom_written_on_success_and_never_on_failure(tmp_path):
    import csv

    bom = tmp_path / "bom.csv"
    out = _run(tmp_path, "[commutation]\npole_pairs = 2\nrpm_min = 1500.0\nrpm_max = 6000.0\n", "--bom", str(bom))
    assert out.returncode == 0, out.stderr
    rows = {r["designator"]: r for r in csv.DictReader(bom.open(encoding="utf-8-sig"))}
    c3 = rows["A1-C3"]  # 11 uA x 10/3000 s / 1.4 V / 0.95 = 27.6 nF -> E12 33 nF
    assert float(c3["value"]) == pytest.approx(33e-9) and c3["value_text"] == "33 nF"
    assert c3["reason"].startswith("E12 value") and "window" in c3["reason"] and c3["technology"].startswith("C0G")
    assert set(rows) == {"A1-IC1", "A1-C3", "A1-C4"}  # only the table the spec wrote
    bom.unlink()
    for text, code in (("[commutation]\nrpm_max = 50000\n", 3), ("[commutation]\nrpm_min = -1\n", 2)):
        out = _run(tmp_path, text, "--bom", str(bom))
        assert out.returncode == code and not bom.exists() and not list(tmp_path.glob(".bom-*"))


def test_template_is_a_complete_spec_that_designs_as_it_stands(tmp_path):
    from handbook.design.schema import TABLES

    tpl = subprocess.run([sys.executable, "-m", "handbook", "design", "--template"], capture_output=True, text=True,
                         timeout=60)
    assert tpl.returncode == 0
    for table, params in TABLES.items():
        assert f"[{table}]" in tpl.stdout
        assert all(f"{p.name} =" in tpl.stdout for p in params)
    fed_back = _run(tmp_path, tpl.stdout, "--json")
    empty = _run(tmp_path, "", "--json")
    assert fed_back.returncode == 0 and json.loads(fed_back.stdout) == json.loads(empty.stdout)


def test_json_error_object_and_the_table_a_key_belongs_to(tmp_path):
    out = _run(tmp_path, "pole_pairs = 4\n", "--json")
    assert out.returncode == 2 and "put it under [commutation]" in out.stderr
    err = json.loads(out.stdout)["error"]
    assert err["exit"] == 2 and "pole_pairs = 4" in err["message"]
    # a known key under the wrong table names the table it belongs in
    wrong = _run(tmp_path, "[commutation]\ni_no_trip = 0.5\n")
    assert wrong.returncode == 2 and "it belongs in [current_limiter]" in wrong.stderr


def test_one_table_that_cannot_be_met_still_reports_the_others(tmp_path):
    out = _run(tmp_path, "[commutation]\nrpm_max = 50000\n", "--json")
    assert out.returncode == 3
    r = json.loads(out.stdout)
    assert r["commutation"]["infeasible"]["table"] == "commutation"
    assert r["current_limiter"]["r7"] > 0 and r["class_d"]["f_sw"] > 0
    text = _run(tmp_path, "[commutation]\nrpm_max = 50000\n")
    assert text.returncode == 3 and "cannot be met" in text.stdout and "R7" in text.stdout


def test_help_is_plain_text():
    out = subprocess.run([sys.executable, "-m", "handbook", "design", "--help"], capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0 and "``" not in out.stdout and ":mod:" not in out.stdout and "--template" in out.stdout


@pytest.mark.parametrize("columns", [80, 120])
def test_text_output_fits_the_terminal(columns):
    import os
    from pathlib import Path

    spec = Path(__file__).resolve().parents[2] / "book" / "examples" / "fan_motor.toml"
    out = subprocess.run([sys.executable, "-m", "handbook", "design", str(spec)], capture_output=True, text=True,
                         timeout=60, env={**os.environ, "COLUMNS": str(columns)})
    assert out.returncode == 0 and "[converter]" in out.stdout
    assert max(len(line) for line in out.stdout.splitlines()) <= columns
    assert "e+0" not in out.stdout and "e-0" not in out.stdout  # no scientific notation for a person to read
