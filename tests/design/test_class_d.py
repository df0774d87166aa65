"""Class D: the models at their datasheet points, the default design by hand, and the joint design against an
independent all-corner enumeration (tests/oracles.py, sharing no code with handbook.design)."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError
from handbook.design import class_d
from handbook.design.class_d.explain import datasheet_application
from handbook.design.class_d.model import band_deviation_box_db, band_deviation_db, sensitivity
from handbook.design.solvers import Infeasible
from handbook.sources.lm4651 import circuit as lm4651

from oracles import enumerate_class_d, p_clip

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_calibration_points_of_the_class_d_models():
    assert lm4651.p_clip(125e3, 4) == pytest.approx(125)
    assert lm4651.p_clip(75e3, 4) == pytest.approx(135)
    assert lm4651.p_clip(125e3, 8) == pytest.approx(75)
    # eq 5 against the LM4651 table: 200 kHz where eq 5 says 250 kHz, 65 kHz where it says 1e9/19000
    assert lm4651.F_TOL_LOW == pytest.approx(1 - 200e3 / 250e3)
    assert lm4651.F_TOL_HIGH == pytest.approx(65e3 / (1e9 / 19e3) - 1)
    assert lm4651.dead_time_total(0) == pytest.approx(27e-9) and lm4651.dead_time_total(5e3) == pytest.approx(35.5e-9)
    assert lm4651.rds_on_max(100) == pytest.approx(0.300 * 1.15)
    # the filter of Output Stage Filtering: 50 uH, 5 uF -> 7.12 kHz, Q 0.894 into 4 ohm
    assert lm4651.filter_f0(50e-6, 5e-6) == pytest.approx(1 / (2 * math.pi * math.sqrt(500e-12)))
    assert lm4651.filter_q(50e-6, 5e-6, 4) == pytest.approx(4 * math.sqrt(0.05))
    assert lm4651.thd_n_joint(125e3, 50e-6, 5e-6, 10, 4, 20) == pytest.approx(0.003)
    # ... and as the analyser reads it: 125 kHz lies outside the table's 10 Hz..80 kHz band, no residue added
    assert lm4651.thd_n_measured(125e3, 50e-6, 5e-6, 10, 4, 20, 80e3) == pytest.approx(0.003)
    # the idle loss reproduces 55 % at 5 W by construction; 85 % at 125 W is an independent check (coils off)
    s = class_d.checked({"p_out": 5.0, "l_dcr": 0.0})
    x = 361e-9 * 125e3
    assert 5 / (5 + 5 / 4 * 0.4 + x * 5 / (1 - x) + lm4651.p_idle(20)) == pytest.approx(0.55)
    eff125 = class_d.model.efficiency({**s, "p_out": 125.0}, 125e3, 50e-6)
    assert eff125 == pytest.approx(0.85, abs=0.01)


def test_default_design_by_hand():
    r = class_d.design()
    assert (r.r_osc, r.l_out, r.c_out, r.r_dly) == enumerate_class_d({})
    f = 1e9 / (4000 + r.r_osc - 0.4 * r.r_dly)
    assert r.f_sw == pytest.approx(f) and r.f_sw_min == pytest.approx(0.8 * f) and r.f_sw_max == pytest.approx(1.235 * f)
    # THD+N's worst corner: slow oscillator, L and C at their low ends. Its fundamental lies inside the
    # analyser's 80 kHz band, so the residue (8 V_s / pi / sqrt 2 through the filter) over the 10 W test
    # signal's sqrt(10 x 4) V rms adds, root-sum-square
    fs, lo, co = 0.8 * f, 0.9 * r.l_out, 0.95 * r.c_out
    w = 2 * math.pi * fs
    residue = 160 / math.pi / math.sqrt(2) / abs(1 + 1j * w * 2 * lo / 4 - w * w * 2 * lo * co) / math.sqrt(40)
    thd = math.hypot(0.003 * (125e3 / fs) ** 2 * 250e-12 / (lo * co), residue)
    assert fs < 80e3 and r.thd_n == pytest.approx(thd) and r.thd_n <= 0.005
    # clipping at the fast corner, from the oracle's own fit of the three datasheet points
    assert r.p_clip == pytest.approx(p_clip(1.235 * f, 4, 20)) and r.p_clip >= 125
    # efficiency at 125 W: conduction 230 mOhm, eq 9/10 310 ns, idle, two coils of 300 ohm/H x L
    x = 361e-9 * f
    loss = 125 / 4 * 0.46 + x * 125 / (1 - x) + lm4651.P_IDLE_REF + 125 / 4 * 2 * 300 * r.l_out
    assert r.efficiency == pytest.approx(125 / (125 + loss))
    assert r.t_junction == pytest.approx(140.0) and r.warnings == []
    assert "THD+N" in r.binding


def test_residue_counts_only_inside_the_analysers_band():
    r = class_d.design()
    s, parts = r.spec, (r.r_osc, r.l_out, r.c_out, r.r_dly)
    narrow = class_d.model.one({**s, "thd_bandwidth": 22e3}, *parts)["thd_n"]  # both corners above 22 kHz
    fs, lo, co = r.f_sw_min, 0.9 * r.l_out, 0.95 * r.c_out
    assert narrow == pytest.approx(0.003 * (125e3 / fs) ** 2 * 250e-12 / (lo * co)) and narrow < r.thd_n
    # the old default parts (66.8 kHz, 100 uH, 10 uF): 3 % of residue inside the band, six times thd_max
    old = class_d.model.one(s, 13e3, 100e-6, 10e-6, 5100.0)
    assert old["thd_n"] > 0.028 and old["margins"]["THD+N"] < -4


def test_heat_sink_figures_come_from_the_corner_that_sets_it():
    r = class_d.design()
    # the corner that sets theta_SA sits at 140 C; its dissipation is then thermal Ohm's law
    assert r.t_junction == pytest.approx(140.0)
    assert r.p_dissipation == pytest.approx(90 / (r.theta_sa_required + 2.2))
    # no heat sink: the package's 43 K/W; above 150 C it shuts down, shown at R_DS(on)'s 150 C value
    hot = []
    for f in (r.f_sw_min, r.f_sw_max):
        p, x = p_clip(f, 4, 20), 401e-9 * f
        watts = x * p / (1 - x) + lm4651.P_IDLE_REF - 0.036 * 40 + p / 4 * 2 * 0.3 * (1 + 0.002 * 125)
        hot.append(50 + 43 * watts)
    assert r.t_junction_no_sink == pytest.approx(max(hot)) and r.t_junction_no_sink > 150
    # a heat sink given: T_j below the target, and the warning for one better than any made
    given = class_d.design({"theta_sa_available": 0.01})
    assert given.t_junction < 140 and "0.01 K/W: no TO-220 heat sink made" in given.warnings[0]


def test_contradictory_specs_say_what_can_be_met():
    with pytest.raises(Infeasible) as exc:  # a THD+N test point above clipping is no test
        class_d.design({"thd_test_power": 500.0})
    assert "thd_test_power = 500.0 W" in str(exc.value) and exc.value.achievable["p_clip"] < 140
    with pytest.raises(Infeasible) as exc:
        class_d.design({"p_continuous": 1000.0})
    text = str(exc.value)
    assert exc.value.achievable["p_deliverable"] == pytest.approx(p_clip(50e3, 4, 20))
    assert "about 140 W at most" in text and "ambient" not in text and "0.00 K/W" not in text
    assert "an ideal heat sink, 0 K/W" in text


@pytest.mark.parametrize("f_audio, l_out, c_out, tol, inside", [(1000.0, 150e-6, 47e-6, 0.3, 0.7),
                                                                 (500.0, 220e-6, 22e-6, 0.1, 0.0),
                                                                 (3000.0, 30e-6, 40e-6, 0.2, 0.0)])
def test_band_deviation_over_the_box_against_a_sweep(f_audio, l_out, c_out, tol, inside):
    """The box's worst against a dense sweep of f, L and C; ``inside``: by how much it beats every corner (dB)."""
    s = {"f_audio": f_audio, "r_load": 4.0, "l_tolerance": tol, "c_tolerance": tol}
    box = band_deviation_box_db(s, l_out, c_out)
    L, C = np.meshgrid(np.linspace(1 - tol, 1 + tol, 81) * l_out, np.linspace(1 - tol, 1 + tol, 81) * c_out)
    w = 2 * np.pi * np.linspace(0, f_audio, 801)
    h = np.abs(1 / (1 + 1j * w * 2 * L[..., None] / 4 - w ** 2 * 2 * L[..., None] * C[..., None]))
    swept = 20 * np.abs(np.log10(h)).max()
    corners = max(band_deviation_db(f_audio, l_out * a, c_out * b, 4.0) for a in (1 - tol, 1 + tol)
                  for b in (1 - tol, 1 + tol))
    assert swept <= box + 1e-9 and box == pytest.approx(swept, abs=2e-3) and box >= corners + inside


def test_heat_sink_is_sized_at_what_the_amplifier_can_deliver():
    small = class_d.design({"p_out": 50.0})
    # it carries the clipping power at each oscillator corner, not p_out: the heat sink does not shrink
    need = []
    for f in (small.f_sw_min, small.f_sw_max):
        p, x = p_clip(f, 4, 20), 401e-9 * f
        need.append(90 / (x * p / (1 - x) + p / 4 * 2 * 0.3 * 1.23 + lm4651.P_IDLE_REF - 0.036 * 40) - 2.2)
    assert small.theta_sa_required == pytest.approx(min(need)) and small.theta_sa_required < 0.7
    fixed = class_d.design({"p_out": 50.0, "p_continuous": 50.0})
    assert fixed.theta_sa_required > 2 * small.theta_sa_required
    # by hand at the fast corner for 50 W: eq 9/10 with 350 ns, 300 mOhm x 1.23 at 140 C, idle less 36 mA
    f = fixed.f_sw_max
    x = 401e-9 * f
    watts = x * 50 / (1 - x) + 50 / 4 * 2 * 0.3 * (1 + 0.002 * 115) + lm4651.P_IDLE_REF - 0.036 * 40
    assert fixed.theta_sa_required == pytest.approx(90 / watts - 2.2)


@SETTINGS
@given(frac=st.floats(0.2, 0.95), r_load=st.sampled_from([4.0, 6.0, 8.0]), t_a=st.floats(0, 70),
       thd=st.floats(0.003, 0.02), sink=st.one_of(st.none(), st.floats(0.5, 8)), pkg=st.sampled_from(["TF", "T"]),
       ser=st.sampled_from(["E12", "E24", "E96"]), objective=st.sampled_from(["efficiency", "heat_sink"]),
       ripple=st.floats(0.05, 1.0), f_audio=st.sampled_from([200.0, 500.0, 2000.0]), dcr=st.floats(50, 2000),
       q_max=st.floats(0.7, 1.5), l_ser=st.sampled_from(["E6", "E12"]), band=st.sampled_from([22e3, 80e3, 150e3]),
       l_tol=st.sampled_from([0.1, 0.3]))
def test_class_d_equals_independent_enumeration(frac, r_load, t_a, thd, sink, pkg, ser, objective, ripple, f_audio,
                                                 dcr, q_max, l_ser, band, l_tol):
    spec = dict(p_out=frac * 130 * 4 / r_load ** 0.8, r_load=r_load, t_ambient=t_a, thd_max=thd,
                theta_sa_available=sink, package=pkg, r_osc_series=ser, objective=objective, ripple_max=ripple,
                f_audio=f_audio, l_dcr=dcr, q_max=q_max, l_series=l_ser, c_series=l_ser, thd_bandwidth=band,
                l_tolerance=l_tol)
    expected = enumerate_class_d(spec)
    try:
        got = class_d.design(spec)
    except Infeasible as exc:
        assert expected is None, exc
        return
    assert (got.r_osc, got.l_out, got.c_out, got.r_dly) == expected


def test_infeasible_says_what_can_be_met():
    with pytest.raises(Infeasible) as exc:
        class_d.design({"p_out": 200.0})
    best = exc.value.achievable["p_clip"]
    # the lowest E24 frequency whose slow corner stays at 50 kHz or above, at its fast corner
    f = min(1e9 / (4000 + r - 0.4 * 5100) for r in (11e3, 12e3, 13e3, 15e3) if 0.8e9 / (4000 + r - 2040) >= 50e3)
    assert best == pytest.approx(p_clip(1.235 * f, 4, 20)) and "p_out" in str(exc.value)


def test_implausible_designs_still_design_with_warnings():
    tiny = class_d.design({"p_out": 10.0, "p_continuous": 10.0, "t_ambient": 0.0, "supply": 15.0})
    assert 30 < tiny.theta_sa_required < 43 - 2.2 and "above about 30 K/W" in tiny.warnings[0]
    hot = class_d.design({"t_ambient": 70.0})
    assert hot.theta_sa_required < 0.5 and "below about 0.5 K/W" in hot.warnings[0]
    with pytest.raises(Infeasible) as exc:  # hotter still: say the hottest ambient that works
        class_d.design({"t_ambient": 85.0})
    assert 70 < exc.value.achievable["t_ambient_max"] < 85 and "ambient of at most" in str(exc.value)


def test_bad_input_names_key_value_and_range():
    with pytest.raises(InputError, match=r"class_d.supply = 10.*from 11 V to 22 V"):
        class_d.checked({"supply": 10.0})
    with pytest.raises(InputError, match="class_d.objective"):
        class_d.checked({"objective": "cost"})


def test_datasheet_typical_application_judged_by_the_same_checks():
    ev = datasheet_application(class_d.checked({}))
    f = 1e9 / (4000 + 3900 - 2000)
    assert ev["f_sw"] == pytest.approx(f)
    assert ev["p_clip"] == pytest.approx(p_clip(1.235 * f, 4, 20)) and not ev["ok"]
    assert ev["margins"]["clipping"] < 0 < ev["margins"]["THD+N"]


def test_sensitivity_names_the_oscillator_for_clipping():
    r = class_d.design()
    rows = sensitivity(r.spec, r.r_osc, r.l_out, r.c_out, r.r_dly)
    typical = rows["typical (no tolerance)"]
    assert typical["clipping"] == pytest.approx(p_clip(r.f_sw, 4, 20) / 125 - 1)
    drops = {k: typical["clipping"] - v["clipping"] for k, v in rows.items() if k != "typical (no tolerance)"}
    assert max(drops, key=drops.get) in ("oscillator (eq 5 vs table)", "all at their limits")
    assert drops["inductor tolerance"] == pytest.approx(0.0)
