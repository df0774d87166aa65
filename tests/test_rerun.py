"""Re-running a chapter with another motor's data, the way a reader does (papermill)."""
import json
from pathlib import Path

import papermill as pm
import pytest

BOOK = Path(__file__).resolve().parents[1] / "book"


def _glued(nb_path):
    nb = json.loads(Path(nb_path).read_text())
    out, tables = {}, []
    for cell in nb["cells"]:
        for o in cell.get("outputs", []):
            data = o.get("data", {})
            name = o.get("metadata", {}).get("scrapbook", {}).get("name")
            if name:
                text = "".join(data["application/papermill.record/text/plain"])
                try:
                    out[name] = float(text)
                except ValueError:  # a glued text (a value with its unit): kept as written
                    out[name] = text.strip("'\"")
            if "text/markdown" in data:
                tables.append("".join(data["text/markdown"]))
    return out, "\n".join(tables)


def test_commutation_chapter_with_a_four_pole_pair_motor(tmp_path):
    out = tmp_path / "out.ipynb"
    pm.execute_notebook(str(BOOK / "an94002" / "commutation_delay.ipynb"), str(out),
                        parameters={"pole_pairs": 4, "rpm_min": 900.0}, kernel_name="python3",
                        cwd=str(BOOK / "an94002"), progress_bar=False)
    g, tables = _glued(out)
    bound = 22e-6 * 10 / (900 * 4 * 1.4)  # farads, worked by hand
    assert g["bound_nF"] == pytest.approx(bound * 1e9, rel=1e-9)
    assert g["c3_nF"] == pytest.approx(47.0)  # E12: 39 nF x 0.95 = 37.05 nF < 43.65 nF; 47 nF x 0.95 = 44.65 nF
    assert g["rpm_lo"] == pytest.approx(10 * 22e-6 / (1.4 * 4 * 47e-9 * 0.95), rel=1e-9)
    # the note's printed bound no longer applies; numbers that do not depend on the motor still compare
    assert "| CAP-CD lower bound for 1800 rpm, 6 pole pairs | 0.0148 uF | 0.04365 uF | n/a |" in tables
    assert "| 1.4 V | 1.4 V | exact |" in tables


def test_opamp_limiter_chapter_with_a_matched_network_and_200mV(tmp_path):
    out = tmp_path / "out.ipynb"
    pm.execute_notebook(str(BOOK / "an94002" / "opamp_limiter.ipynb"), str(out),
                        parameters={"resistor_tolerance": 0.001, "v_cs": 0.2}, kernel_name="python3",
                        cwd=str(BOOK / "an94002"), progress_bar=False)
    g, tables = _glued(out)
    r9 = 0.2 * 21.6e3 / (8.2 - 0.2)  # eq 14 solved for R9, by hand
    assert g["r9_target"] == pytest.approx(r9, rel=1e-12)
    # worst case by hand at the high corner: every part at its least favourable end
    hi = dict(vz=8.2 * 1.05, r9=r9 * 1.001, r10=5600 * 1.001, r11=16000 * 0.999, r12=5600 * 0.999, r13=16000 * 1.001)
    a, b = hi["r13"] / (hi["r12"] + hi["r13"]), hi["r11"] / (hi["r9"] + hi["r10"] + hi["r11"])
    v_hi = hi["vz"] * (1 - b / a) + 9e-3 / a
    assert g["wc_hi_mV"] == pytest.approx(v_hi * 1e3, rel=1e-9)
    assert "| level-shift factor A = R13/(R12+R13) | 0.741 | 0.7407 | rounding |" in tables  # R12, R13 unchanged
    assert "| sense signal at the op-amp input for V_cs = 100 mV | 74.1 mV | 148.1 mV | n/a |" in tables


def test_design_your_own_with_the_fan_spec(tmp_path):
    out = tmp_path / "out.ipynb"
    spec = tmp_path / "fan.toml"
    spec.write_text("[commutation]\npole_pairs = 2\nrpm_min = 1500.0\nrpm_max = 6000.0\n"
                    "[current_limiter]\ni_no_trip = 0.3\ni_must_trip = 0.7\n")
    pm.execute_notebook(str(BOOK / "design" / "your_own.ipynb"), str(out), parameters={"spec_file": str(spec)},
                        kernel_name="python3", cwd=str(BOOK / "design"), progress_bar=False)
    _, tables = _glued(out)
    # CAP-CD by hand: 11 uA (the source column's maximum) for 10/(1500*2) s over the narrowest window
    # 2.3 V - 0.9 V at -5 % -> 27.6 nF -> E12 33 nF
    assert 11e-6 * (10 / 3000) / 1.4 / 0.95 == pytest.approx(27.57e-9, rel=1e-3)
    assert "| CAP-CD | 33 nF |" in tables
    assert "| C3 | 33 nF | 5 % | E12 |" in tables
    # the limiter keeps 0.3..0.7 A at every corner
    row = [line for line in tables.splitlines() if line.startswith("| lowest trip current |")][0]
    assert row.split("|")[2].split()[1] == "mA" and float(row.split("|")[2].split()[0]) >= 300
