"""The project's ngspice runner: results read from .meas, clear messages for a bad netlist, a failed
measurement and a missing ngspice (never a traceback)."""
import math
import subprocess
import sys

import pytest

from handbook.spice import runner

needs_ngspice = pytest.mark.skipif(runner.available() is None, reason=runner.why_unavailable())


@needs_ngspice
def test_rc_charge_matches_the_exponential():
    # 1 kOhm into 1 uF from a 5 V step: v(t) = 5 (1 - exp(-t / 1 ms)); half way at ln 2 ms
    out = runner.run("* rc step\nV1 in 0 PULSE(0 5 0 1n 1n 10m 20m)\nR1 in out 1k\nC1 out 0 1u\n"
                     ".tran 1u 3m\n.meas tran v3 FIND v(out) AT=3m\n.meas tran t50 WHEN v(out)=2.5 RISE=1\n.end\n")
    assert out["v3"] == pytest.approx(5 * (1 - math.exp(-3)), rel=2e-3)
    assert out["t50"] == pytest.approx(1e-3 * math.log(2), rel=2e-3)


@needs_ngspice
def test_bad_netlist_and_failed_measurement_are_messages():
    with pytest.raises(runner.SpiceError, match="broken deck: ngspice refused the netlist"):
        runner.run("* broken deck\nR1 a\n.tran 1u 1m\n.end\n")
    with pytest.raises(runner.SpiceError, match="measurement tx failed"):
        runner.run("* never\nV1 a 0 1\nR1 a 0 1k\n.tran 1u 1m\n.meas tran tx WHEN v(a)=5\n.end\n")


def test_missing_ngspice_says_how_to_get_it(monkeypatch):
    monkeypatch.setattr(runner.shutil, "which", lambda name: None)
    with pytest.raises(runner.SpiceUnavailable, match="apt-get install ngspice"):
        runner.run("* x\nR1 a 0 1\n.op\n.end\n")


def test_spice_command_without_ngspice_exits_with_a_message(tmp_path):
    env = {"PATH": str(tmp_path), "PYTHONPATH": ":".join(sys.path)}
    out = subprocess.run([sys.executable, "-m", "handbook", "design", str(tmp_path / "none.toml"), "--spice"],
                         capture_output=True, text=True, env=env, timeout=60)
    assert out.returncode == 2 and "Traceback" not in out.stderr  # the missing spec is reported first
    (tmp_path / "empty.toml").write_text("")
    out = subprocess.run([sys.executable, "-m", "handbook", "design", str(tmp_path / "empty.toml"), "--spice"],
                         capture_output=True, text=True, env=env, timeout=60)
    assert out.returncode == 4 and "ngspice is not installed" in out.stderr and "Traceback" not in out.stderr
