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
    assert r["commutation"]["cap_cd"] == 1.8e-8
    assert {"r7", "r9", "i_trip_min", "i_trip_max", "i_trip_nominal", "p_r7", "binding"} <= set(r["current_limiter"])
    assert {"f_sw", "r_osc", "efficiency", "p_dissipation", "theta_sa_required", "t_junction", "binding"} <= set(r["class_d"])


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
    assert info["table"] == "commutation" and info["achievable"]["rpm_max_reliable"] == pytest.approx(9347.44, rel=1e-4)


def test_bom_written_on_success_and_never_on_failure(tmp_path):
    import csv

    bom = tmp_path / "bom.csv"
    out = _run(tmp_path, "[commutation]\npole_pairs = 2\nrpm_min = 1500.0\nrpm_max = 6000.0\n", "--bom", str(bom))
    assert out.returncode == 0, out.stderr
    rows = {r["reference"]: r for r in csv.DictReader(bom.open())}
    assert float(rows["C3"]["value"]) == pytest.approx(56e-9)  # 22 uA x 10/3000 s / 1.4 V / 0.95 = 55.1 nF -> E12 56 nF
    assert rows["C3"]["series"] == "E12" and "window" in rows["C3"]["reason"]
    assert {"C3", "C4", "R7", "R9", "R_OSC"} <= set(rows)
    bom.unlink()
    for text, code in (("[commutation]\nrpm_max = 50000\n", 3), ("[commutation]\nrpm_min = -1\n", 2)):
        out = _run(tmp_path, text, "--bom", str(bom))
        assert out.returncode == code and not bom.exists() and not list(tmp_path.glob(".bom-*"))
