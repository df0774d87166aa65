"""The project's ngspice runner: results read from .meas, clear messages for a bad netlist, a failed
measurement and a missing ngspice (never a traceback)."""
import json
import math
import re
import subprocess
import sys

import pytest

from handbook.spice import decoupling, runner

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
    with pytest.raises(runner.SpiceError, match="broken deck: malformed element line"):
        runner.run("* broken deck\nR1 a\n.tran 1u 1m\n.end\n")
    with pytest.raises(runner.SpiceError, match="broken deck: ngspice refused the netlist"):
        runner.run("* broken deck\nV1 a 0 1\nQ1 a a 0 NOSUCH\n.tran 1u 1m\n.end\n")
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


@needs_ngspice
def test_spice_command_and_designs_confirmed_by_simulation():
    out = subprocess.run([sys.executable, "-m", "handbook", "spice", "--json"], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    rows = json.loads(out.stdout)
    assert {"id", "circuit", "quantity", "equation", "spice", "rel_diff", "expected_difference", "residual", "agrees",
            "rtol", "why", "kind", "verdict", "faults_seen"} <= set(rows[0])
    for r in rows:  # agreement is the residual (SPICE's difference less the expected one) inside the tolerance
        signed = (r["spice"] - r["equation"]) / r["equation"]
        assert abs(signed - r["expected_difference"]) <= r["rtol"] and r["why"], r["id"]
    assert any(r["expected_difference"] and r["rel_diff"] > r["rtol"] for r in rows)  # physics, not tolerance
    assert all(isinstance(r["faults_seen"], list) for r in rows) and any(r["faults_seen"] for r in rows)
    # the verdict, and after a semicolon what a row's caveat says (an op-amp input outside its range, circuit.Check)
    assert all(r["verdict"].split("; ")[0] == ("agrees" if r["kind"] == "independent" else "consistent (by construction)")
               for r in rows)
    assert any("outside the op-amp's input range" in r["verdict"] for r in rows)
    assert len({r["circuit"] for r in rows}) >= 9 and all(r["agrees"] for r in rows)
    # a circuit's variants (the filter's AC and transient decks, each load) count as one circuit
    family = {r["circuit"]: re.sub(r"-(4|8)ohm$", "", r["circuit"]).replace("ripple", "filter") for r in rows}
    for f in set(family.values()):
        assert sum(family[r["circuit"]] == f for r in rows) >= 2, f


@needs_ngspice
def test_design_spice_adds_the_simulated_corners(tmp_path):
    (tmp_path / "empty.toml").write_text("")
    out = subprocess.run([sys.executable, "-m", "handbook", "design", str(tmp_path / "empty.toml"), "--spice", "--json"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    r = json.loads(out.stdout)
    lim, com, cd = r["current_limiter"], r["commutation"], r["class_d"]
    # the simulated worst corners land on the equations' worst corners within the op-amp model's finite gain
    assert lim["spice"]["i_trip_min"] == pytest.approx(lim["i_trip_min"], rel=0.01)
    assert lim["spice"]["i_trip_max"] == pytest.approx(lim["i_trip_max"], rel=0.01)
    assert {"swing_rpm_min", "swing_rpm_max"} <= set(com["spice"]) and {"f_corner", "ripple_at_load"} <= set(cd["spice"])
    # every table: each SPICE figure beside the design's own, judged against the tolerance and the spec
    for table, keys in (("current_limiter", ("i_trip_min", "i_trip_max", "headroom_min")),
                        ("commutation", ("swing_rpm_min", "swing_rpm_max")), ("class_d", ("f_corner", "ripple_at_load"))):
        sp = r[table]["spice"]
        assert all(f"{k}_equation" in sp for k in keys), table
        assert sp["meets_spec"] and sp["agrees"] and sp["differs"] == [], table
    # the converter: at the top of the supply range D1's falling drop against a dump voltage under a volt slows its
    # slowest corner by 0.8 % in SPICE; audible_margin (2 %) keeps it above 20 kHz: no warning at the defaults
    said = [w for w in out.stderr.splitlines() if "warning" in w]
    assert said == [], said
    conv = r["converter"]["spice"]
    assert conv["agrees"] and conv["meets_spec"] and 20e3 <= conv["f"] < r["converter"]["f_sw_min"]
    # the corner of the filter by hand: 1 / (2 pi sqrt(2 L C)) with the chosen L and C
    assert cd["spice"]["f_corner"] == pytest.approx(1 / (2 * math.pi * math.sqrt(2 * cd["l_out"] * cd["c_out"])), rel=0.01)


@needs_ngspice
def test_a_failing_circuit_is_reported_and_the_others_still_are(monkeypatch):
    from handbook.spice import checks
    from handbook.spice.circuit import Check, Circuit

    broken = Circuit("broken", "a broken deck", "test", (), "* a broken deck\nR1 a\n.tran 1u 1m\n.end\n",
                     (Check("broken-x", "x", "V", 1.0, "x", 0.01, "none"),))
    monkeypatch.setattr(checks, "circuits", lambda: [broken, decoupling.circuit()])
    rows = checks.rows()
    bad = [r for r in rows if r["circuit"] == "broken"]
    assert len(bad) == 1 and not bad[0]["agrees"] and "line 2: `R1 a`" in bad[0]["error"]
    assert any(r["circuit"] == "decoupling" and r["agrees"] for r in rows)


def test_spice_json_without_ngspice_prints_an_error_object(tmp_path):
    env = {"PATH": str(tmp_path), "PYTHONPATH": ":".join(sys.path)}
    out = subprocess.run([sys.executable, "-m", "handbook", "spice", "--json"], capture_output=True, text=True,
                         env=env, timeout=60)
    assert out.returncode == 4 and "Traceback" not in out.stderr
    err = json.loads(out.stdout)["error"]
    assert err["exit"] == 4 and err["skipped"] and "ngspice is not installed" in err["message"]


@needs_ngspice
def test_a_garbage_line_and_an_unknown_node_are_named():
    # "this is garbage" reads as a transmission line named "this": ngspice names the device, the runner the line
    with pytest.raises(runner.SpiceError, match=r"at line 4: `this is garbage`"):
        runner.run("* garbage\nR1 a 0 1k\nV1 a 0 1\nthis is garbage\n.op\n.meas op x FIND v(a)\n.end\n")
    # ngspice says only "no data saved ... not found": the runner names the measurement and the node
    with pytest.raises(runner.SpiceError, match=r"line 5: `\.meas dc x FIND v\(nonode\) AT=0\.5` reads v\(nonode\)"):
        runner.run("* unknown node\nR1 a 0 1k\nV1 a 0 1\n.dc V1 0 1 0.1\n.meas dc x FIND v(nonode) AT=0.5\n.end\n")


def test_unknown_vectors_reads_meas_lines_against_the_elements():
    deck = "* t\nR1 a b 1k\nV1 a 0 1\n.meas dc x FIND v(a,b) AT=1\n.meas dc y FIND i(V2) AT=1\n.meas dc z FIND v(q) AT=1\n"
    assert runner.unknown_vectors(deck) == [(5, ".meas dc y FIND i(V2) AT=1", "i(V2)"),
                                            (6, ".meas dc z FIND v(q) AT=1", "v(q)")]


def test_a_malformed_element_line_is_named_with_its_line_number():
    # ngspice itself takes "R1 a" without a word (a 1 mOhm resistor): the runner reads the deck first
    with pytest.raises(runner.SpiceError, match=r"line 3: `R1 a` \(a R element needs two nodes and a value\)"):
        runner.run("* half a resistor\nV1 a 0 1\nR1 a\nR2 a 0 1k\n.op\n.end\n")


@needs_ngspice
def test_ngspice_refusing_a_line_is_mapped_to_the_decks_line():
    # a transistor whose model does not exist: ngspice names its line 4; the message shows it
    with pytest.raises(runner.SpiceError, match=r"at line 4: `Q1 c b 0 NOSUCH`.*could not find a valid modelname"):
        runner.run("* missing model\nV1 c 0 1\nR1 c b 1k\nQ1 c b 0 NOSUCH\n.op\n.end\n")
    with pytest.raises(runner.SpiceError, match=r"at line 5: `\.meas ac ph FIND par"):
        runner.run("* bad meas\nV1 a 0 DC 0 AC 1\nR1 a n1 1k\nC1 n1 0 1n\n.meas ac ph FIND par('vp(n1)') AT=1k\n"
                   ".ac dec 10 1 1e6\n.end\n")


def test_waveform_or_reason_returns_a_sentence_not_a_traceback(monkeypatch):
    out, why = runner.waveform_or_reason(lambda x: x * 2, 21)
    assert (out, why) == (42, None)

    def refused():
        return runner.run("* half a resistor\nR1 a\n.op\n.end\n")

    out, why = runner.waveform_or_reason(refused)
    assert out is None and why.startswith("SPICE plot not drawn: half a resistor") and "line 2" in why
    monkeypatch.setattr(runner.shutil, "which", lambda name: None)
    out, why = runner.waveform_or_reason(runner.run, "* x\nR1 a 0 1\n.op\n.end\n")
    assert out is None and why.startswith("SPICE plot skipped: ngspice is not installed")
    with pytest.raises(ZeroDivisionError):  # anything else is a bug, and is raised
        runner.waveform_or_reason(lambda: 1 / 0)


def test_confirm_rows_carry_tolerance_reason_kind_and_verdict():
    """The design chapters' "Confirmed by simulation" tables: every row has its tolerance, its reason and its
    kind, and the commutation's rows (constant current between the design's own levels) never say "agrees"."""
    from handbook.spice import checks

    figures = {"swing_rpm_min": 1.3070, "swing_rpm_min_equation": 1.3075, "swing_rpm_max": 0.2849,
               "swing_rpm_max_equation": 0.2850, "window_reached": True, "meets_spec": False}
    rows = checks.confirm_rows("commutation", None, figures)
    assert [r["kind"] for r in rows] == ["sanity", "sanity"]
    assert all(r["verdict"] == "consistent (by construction)" and r["rtol"] and r["why"] for r in rows)
    judged = checks.judged("commutation", figures)
    said = checks.warnings("commutation", judged)
    assert judged["agrees"] and any("reached its window" in w for w in said) and any("miss the spec" in w for w in said)
    off = checks.judged("commutation", {**figures, "swing_rpm_min": 1.4, "window_reached": False, "meets_spec": True})
    assert off["differs"] == ["swing_rpm_min"] and checks.warnings("commutation", off) == [
        "SPICE's swing_rpm_min = 1.4 V is outside its tolerance of the design's 1.308 V"]
    for table in checks.CONFIRM:  # a tolerance of None: the design check gives one per run ("*_rtol")
        assert all(kind in ("independent", "sanity") and (rtol is None or 0 < rtol <= 0.005)
                   for *_, rtol, _, kind in checks.CONFIRM[table])
    assert all(rtol is None for *_, rtol, _, _ in checks.CONFIRM["converter"])


@needs_ngspice
def test_chapter_table_names_the_circuit_when_decks_share_quantities():
    from handbook.report.spice_tables import chapter_table
    from handbook.spice import class_d, converter

    text = chapter_table(class_d.circuit(), class_d.circuit_8ohm(), class_d.ripple()).data
    assert text.splitlines()[0].lstrip("| ").startswith("circuit")
    corner = f"±{class_d.circuit().checks[0].rtol * 100:.2g} %"  # the AC grid's bound (0.00052 %)
    assert "R_L = 8 Ω, AC" in text and corner in text and "Why each tolerance" in text
    assert "Faults put into the equations (8; each seen by an independent check)" in text
    one = chapter_table(converter.circuit()).data
    assert not one.splitlines()[0].lstrip("| ").startswith("circuit") and "±0.1 %" in one
