"""The designs against exhaustive enumeration written out here, on many generated specifications."""
import itertools
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook import an94002, design, lm4651, series
from handbook.solvers import Infeasible

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


# ---------------------------------------------------------------------------------------------
# CAP-CD

def test_note_motor_gives_18nF_and_15nF_fails_for_its_tolerance():
    r = design.design_commutation()
    assert r["cap_cd"] == pytest.approx(18e-9) and r["cap_dc"] == r["cap_cd"]
    assert r["next_smaller"] == pytest.approx(15e-9)
    # 15 nF at -5 %: 22 uA for 10/(1800*6) s over 14.25 nF is more than the 1.4 V window
    assert 22e-6 * (10 / 10800) / 14.25e-9 > 1.4
    assert 22e-6 * (10 / 10800) / 17.1e-9 < 1.4
    assert "window" in r["binding"]
    assert r["rpm_max_reliable"] == pytest.approx(10 * 10.6e-6 / (0.1 * 6 * 18.9e-9))


def _enumerate_cap(spec):
    s = {**design.COMMUTATION_DEFAULTS, **spec}
    t_slow, t_fast = 10 / (s["rpm_min"] * s["pole_pairs"]), 10 / (s["rpm_max"] * s["pole_pairs"])
    for c in series.values(s["series"], 1e-12, 1e-3):
        if s["i_charge_max"] * t_slow / (c * (1 - s["tolerance"])) <= s["window"] * (1 + 1e-12):
            ok = s["i_charge_min"] * t_fast / (c * (1 + s["tolerance"])) >= s["min_excursion"] * (1 - 1e-12)
            return c if ok else None
    return None


@SETTINGS
@given(n=st.integers(1, 12), rpm_min=st.floats(100, 20000), span=st.floats(1.05, 20),
       i_max=st.floats(2e-6, 50e-6), spread=st.floats(0.2, 1.0), window=st.floats(0.5, 2.5),
       floor=st.floats(0.02, 0.4), tol=st.sampled_from([0.01, 0.05, 0.1, 0.2]),
       ser=st.sampled_from(["E6", "E12", "E24"]))
def test_cap_cd_equals_enumeration(n, rpm_min, span, i_max, spread, window, floor, tol, ser):
    spec = dict(pole_pairs=n, rpm_min=rpm_min, rpm_max=rpm_min * span, i_charge_max=i_max,
                i_charge_min=i_max * spread, window=window, min_excursion=min(floor, window / 2), tolerance=tol,
                series=ser)
    expected = _enumerate_cap(spec)
    try:
        got = design.design_commutation(spec)
    except Infeasible as exc:
        assert expected is None
        assert exc.achievable["rpm_max_reliable"] < spec["rpm_max"]
        return
    assert got["cap_cd"] == pytest.approx(expected, rel=1e-12)
    chk = design.commutation_verify(got["cap_cd"], got["spec"])
    assert chk["window_ok"] and chk["noise_ok"]


# ---------------------------------------------------------------------------------------------
# R7 and R9

def _corners_vcs(r9, s):
    """All 128 corners, written out independently of design.vcs_extremes."""
    t = s["resistor_tolerance"]
    drift = s["zener_tc"] * s["temp_span"]
    vals = []
    for sg in itertools.product((-1, 1), repeat=7):
        r9_, r10, r11, r12, r13 = (x * (1 + t * g) for x, g in
                                   zip((r9, s["r10"], s["r11"], s["r12"], s["r13"]), sg[:5]))
        vz = s["zener_voltage"] * (1 + s["zener_tolerance"] * sg[5]) + drift * sg[5]
        a, b = r13 / (r12 + r13), r11 / (r9_ + r10 + r11)
        vals.append(vz * (1 - b / a) - s["offset"] * sg[6] / a)
    vals = np.array(vals)
    return vals.min(axis=0), vals.max(axis=0)


def test_closed_form_corners_equal_all_128_corners():
    s = {**design.LIMITER_DEFAULTS, "zener_tc": 6.2e-3, "temp_span": 25.0}
    r9 = np.geomspace(10, 1e6, 300)
    lo, hi = design.vcs_extremes(r9, s)
    lo2, hi2 = _corners_vcs(r9, s)
    np.testing.assert_allclose(lo, lo2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(hi, hi2, rtol=1e-12, atol=1e-15)


def _enumerate_limiter(spec):
    s = {**design.LIMITER_DEFAULTS, **spec}
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    lo, hi = _corners_vcs(r9s, s)
    for r7 in series.values(s["r7_series"], s["r7_min"], s["r7_max"]):
        i_lo, i_hi = lo / (r7 * (1 + s["r7_tolerance"])), hi / (r7 * (1 - s["r7_tolerance"]))
        margin = np.minimum(i_lo / s["i_no_trip"] - 1, 1 - i_hi / s["i_must_trip"])
        if (margin >= -1e-12).any():
            return r7, float(r9s[np.argmax(margin)])
    return None


def test_default_limiter_design():
    r = design.design_current_limiter()
    assert (r["r7"], r["r9"]) == _enumerate_limiter({}) == (0.33, 1210.0)
    assert r["i_trip_min"] >= 0.9 and r["i_trip_max"] <= 1.8
    assert r["p_r7"] == pytest.approx(0.9 ** 2 * 0.33)
    assert r["r7_relaxed"] <= r["r7"]


@SETTINGS
@given(i_no=st.floats(0.05, 10), ratio=st.floats(1.1, 4), rt=st.sampled_from([0.001, 0.005, 0.01, 0.02]),
       r7t=st.sampled_from([0.01, 0.05]), zt=st.sampled_from([0.01, 0.02, 0.05]), off=st.floats(0, 10e-3))
def test_limiter_equals_enumeration(i_no, ratio, rt, r7t, zt, off):
    spec = dict(i_no_trip=i_no, i_must_trip=i_no * ratio, resistor_tolerance=rt, r7_tolerance=r7t,
                zener_tolerance=zt, offset=off)
    expected = _enumerate_limiter(spec)
    try:
        got = design.design_current_limiter(spec)
    except Infeasible:
        assert expected is None
        return
    assert expected is not None and got["r7"] == pytest.approx(expected[0])
    # the R9 choice: same margin as the enumeration's best (ties between equal margins are allowed)
    s = got["spec"]
    m_got = min(design.limiter_margins(got["r7"], got["r9"], s))
    m_exp = min(design.limiter_margins(expected[0], expected[1], s))
    assert m_got == pytest.approx(m_exp, rel=1e-9, abs=1e-12)
    lo, hi = _corners_vcs(np.array([got["r9"]]), s)  # independent re-check of feasibility
    assert lo[0] / (got["r7"] * (1 + r7t)) >= i_no * (1 - 1e-9)
    assert hi[0] / (got["r7"] * (1 - r7t)) <= i_no * ratio * (1 + 1e-9)


def test_monte_carlo_yield_of_the_design_and_of_the_note():
    r = design.design_current_limiter()
    mc = design.monte_carlo_trip(r["r7"], r["r9"], r["spec"], n=100_000, seed=1)
    assert mc["yield"] == 1.0  # inside the exact corners by construction
    assert r["i_trip_min"] <= mc["i_min"] and mc["i_max"] <= r["i_trip_max"]
    # the note's design: R9 for 100 mV (eq 14) and R7 = 100 mV / 1.35 A (E24: 0.075 ohm)
    r9_note = series.nearest("E96", an94002.r9_for(0.1, 8.2, 5.6e3, 16e3))
    note = design.monte_carlo_trip(0.075, r9_note, r["spec"], n=100_000, seed=1)
    # an independent sampler: every part uniform in its tolerance, another seed, the divider formula written out
    rng = np.random.default_rng(7)
    n = 100_000
    u = lambda x, t: x * (1 + rng.uniform(-t, t, n))  # noqa: E731
    r9_, r10, r11, r12, r13 = u(r9_note, .01), u(5.6e3, .01), u(16e3, .01), u(5.6e3, .01), u(16e3, .01)
    vz, vos = u(8.2, .05), rng.uniform(-9e-3, 9e-3, n)
    v_plus_minus_v_minus_zero = vz * (1 - (r11 / (r9_ + r10 + r11)) / (r13 / (r12 + r13))) - vos * (r12 + r13) / r13
    i = v_plus_minus_v_minus_zero / u(0.075, .05)
    expected = np.mean((i >= 0.9) & (i <= 1.8))
    sigma = math.sqrt(expected * (1 - expected) / n)
    assert abs(note["yield"] - expected) < 6 * sigma
    assert note["yield"] < 0.85  # one board in five or more trips outside 0.9..1.8 A
    assert note["i_min"] < 0.5 and note["i_max"] > 2.0


def test_infeasible_limiter_reports_the_narrowest_window():
    with pytest.raises(Infeasible) as exc:
        design.design_current_limiter({"i_no_trip": 1.0, "i_must_trip": 1.1})
    ratio = exc.value.achievable["narrowest_ratio"]
    s = design.LIMITER_DEFAULTS
    lo, hi = _corners_vcs(np.array([s["r9_max"]]), s)
    assert ratio == pytest.approx(hi[0] / lo[0] * 1.05 / 0.95, rel=1e-9)
    assert design.design_current_limiter({"i_no_trip": 1.0, "i_must_trip": ratio * 1.02})["r7"] > 0


# ---------------------------------------------------------------------------------------------
# class D

def test_calibration_points_of_the_class_d_models():
    assert lm4651.p_clip(125e3, 4) == pytest.approx(125)
    assert lm4651.p_clip(75e3, 4) == pytest.approx(135)
    assert lm4651.p_clip(125e3, 8) == pytest.approx(75)
    assert lm4651.thd_n(125e3) == pytest.approx(0.003)
    # the datasheet's example: 125 W, 4 ohm, 125 kHz, 350 ns over-modulation as it prints it
    frac = lm4651.switching_loss_fraction(125e3, t_overmod=350e-9)
    assert frac == pytest.approx((25 + 26 + 350) * 1e-9 * 125e3)
    p_sw = lm4651.p_switch(125e3, 125, t_overmod=350e-9)
    assert p_sw == pytest.approx(0.050125 * 125 / (1 - 0.050125))
    assert lm4651.p_conduction(125, 4) == pytest.approx(125 / 4 * 0.46)
    assert lm4651.theta_sa_required(21.0, 50, "TF") == pytest.approx(100 / 21 - 2.2)


def test_default_class_d_design():
    r = design.design_class_d()
    assert r["r_osc"] == 8200.0
    assert r["f_sw"] == pytest.approx(1e9 / (4000 + 8200 - 2000))
    assert r["thd_n"] <= 0.005 and r["p_clip"] >= 125
    assert "THD" in r["binding"]
    assert r["efficiency"] > lm4651.losses(125e3, 125, 4)[2]  # better than the datasheet's 125 kHz


def _enumerate_class_d(spec):
    s = {**design.CLASS_D_DEFAULTS, **spec}
    best = None
    for r in series.values(s["r_osc_series"], 10, 1e6):
        f = 1e9 / (4000 + r - 0.4 * s["r_dly"])
        if not 50e3 <= f <= 225e3:
            continue
        x = (25e-9 + 26e-9 + 310e-9) * f
        p = x * s["p_out"] / (1 - x) + s["p_out"] / s["r_load"] * 0.46
        thd_ok = 0.003 * (125e3 / f) ** 2 <= s["thd_max"] * (1 + 1e-9)
        clip_ok = lm4651.p_clip(f, s["r_load"], s["supply"]) >= s["p_out"] * (1 - 1e-9)
        need = (150 - s["t_ambient"]) / p - {"TF": 2.0, "T": 1.0}[s["package"]] - s["theta_cs"]
        heat_ok = need > 0 and (s["theta_sa_available"] is None or s["theta_sa_available"] <= need * (1 + 1e-9))
        if thd_ok and clip_ok and heat_ok and (best is None or p < best[0]):
            best = (p, r)
    return None if best is None else best[1]


@SETTINGS
@given(p_out=st.floats(20, 150), r_load=st.sampled_from([4.0, 6.0, 8.0]), t_a=st.floats(0, 70),
       thd=st.floats(0.002, 0.02), sink=st.one_of(st.none(), st.floats(0.5, 8)),
       pkg=st.sampled_from(["TF", "T"]), ser=st.sampled_from(["E12", "E24", "E96"]))
def test_class_d_equals_enumeration(p_out, r_load, t_a, thd, sink, pkg, ser):
    spec = dict(p_out=p_out, r_load=r_load, t_ambient=t_a, thd_max=thd, theta_sa_available=sink, package=pkg,
                r_osc_series=ser)
    expected = _enumerate_class_d(spec)
    try:
        got = design.design_class_d(spec)
    except Infeasible:
        assert expected is None
        return
    assert got["r_osc"] == expected
    ev = design.class_d_evaluate(got["f_sw"], got["spec"])
    assert ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"]


# ---------------------------------------------------------------------------------------------
# the command line

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
    ("[commutation]\nrpm_min = 1800\nrpm_max = 900\n", "rpm_min = 1800 must be below"),
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
