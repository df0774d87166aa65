"""`python -m handbook` from the shell, as a user runs it."""
import json
import subprocess
import sys

SI_UNITS = {"F", "ohm", "V", "A", "s", "Hz", "W", "K/W", "1", "1/K", "V/K", "rpm", "F*rpm"}


def run(*args):
    out = subprocess.run([sys.executable, "-m", "handbook", *args], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_examples_json():
    rows = json.loads(run("examples", "--json"))
    assert len(rows) > 20
    for r in rows:
        assert {"id", "source", "quantity", "unit", "printed", "computed", "status"} <= set(r)
        assert isinstance(r["printed"], float) and isinstance(r["computed"], float)
        assert r["unit"] in SI_UNITS
        assert r["status"] in {"exact", "rounding", "misprint", "inconsistent"}
    by_id = {r["id"]: r for r in rows}
    assert by_id["an94002-capcd-bound"]["printed"] == 1.48e-8  # 0.0148 uF in farads
    assert by_id["an94002-offset-tol"]["printed"] == 0.12  # a percentage as a fraction
    assert by_id["an94002-window-high"]["status"] == "misprint"


def test_equations_json_and_tables():
    rows = json.loads(run("equations", "--json"))
    assert {"id", "source", "printed_latex", "derived_latex", "agrees", "note"} <= set(rows[0])
    assert {r["id"] for r in rows if not r["agrees"]} == {"an94002-eq6", "an94002-eq9b", "an94002-eq11-num",
                                                          "an93008-eq2", "tda5341-capcdm", "tda5341-max-delay",
                                                          "lm4651-eq2", "lm4651-eq8"}
    text = run("examples")
    assert "an94002-c3" in text and "misprint" in text
    assert "an94002-eq13" in run("equations")


def test_unknown_command_is_a_usage_error():
    out = subprocess.run([sys.executable, "-m", "handbook", "frobnicate"], capture_output=True, text=True)
    assert out.returncode == 2 and "invalid choice" in out.stderr and "Traceback" not in out.stderr
