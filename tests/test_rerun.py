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
                out[name] = float("".join(data["application/papermill.record/text/plain"]))
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
