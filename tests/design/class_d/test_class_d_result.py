"""The class-D design (handbook.design.class_d.result): the default by hand, the heat sink from the corner
that sets it, and the joint design against an independent all-corner enumeration (tests/oracles.py, sharing
no code with handbook.design); implausible and bad specs."""
import itertools
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError
from handbook.design import class_d
from handbook.design.solvers import Infeasible
from handbook.sources.lm4651 import circuit as lm4651

from oracles import enumerate_class_d, p_clip

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_default_design_by_hand():
    r = class_d.design()
    assert (r.r_osc, r.l_out, r.c_out, r.r_dly) == enumerate_class_d({})
    f = 1e9 / (4000 + r.r_osc - 0.4 * r.r_dly)
    # the corners: the table's -20 %/+23.5 % on eq 5 with R_OSC and R_DLY at their 1 % ends
    slow = 0.8e9 / (4000 + 1.01 * r.r_osc - 0.4 * 0.99 * r.r_dly)
    fast = 1.235e9 / (4000 + 0.99 * r.r_osc - 0.4 * 1.01 * r.r_dly)
    assert r.f_sw == pytest.approx(f) and r.f_sw_min == pytest.approx(slow) and r.f_sw_max == pytest.approx(fast)
    # THD+N's worst corner: slow oscillator, L and C at their low ends. Its fundamental lies inside the
    # analyser's 80 kHz band, so the residue (8 V_s / pi / sqrt 2 through the filter) over the 10 W test
    # signal's sqrt(10 x 4) V rms adds, root-sum-square
    fs, lo, co = slow, 0.9 * r.l_out, 0.95 * r.c_out
    w = 2 * math.pi * fs
    residue = 160 / math.pi / math.sqrt(2) / abs(1 + 1j * w * 2 * lo / 4 - w * w * 2 * lo * co) / math.sqrt(40)
    thd = math.hypot(0.003 * (125e3 / fs) ** 2 * 250e-12 / (lo * co), residue)
    assert fs < 80e3 and r.thd_n == pytest.approx(thd) and r.thd_n <= 0.005
    # clipping at the fast corner, from the oracle's own fit of the three datasheet points
    assert r.p_clip == pytest.approx(p_clip(fast, 4, 20)) and r.p_clip >= 125
    # efficiency at 125 W: conduction 230 mOhm, eq 9/10 310 ns, idle, two coils of 300 ohm/H x L
    x = 361e-9 * f
    loss = 125 / 4 * 0.46 + x * 125 / (1 - x) + lm4651.P_IDLE_REF + 125 / 4 * 2 * 300 * r.l_out
    assert r.efficiency == pytest.approx(125 / (125 + loss))
    assert r.t_junction == pytest.approx(140.0)
    # the coils' worst peak: the audio at the slow corner's clipping (top of the band, C high) plus half the ripple
    # at the slow corner, L low: above the LM4652's 8 A minimum saturation drain current (its table), said
    lo, ch = 0.9 * r.l_out, 1.05 * r.c_out
    peak = max((2 * 4 * p_clip(f, 4, 20)) ** 0.5 * math.hypot(1 / 4, 2 * math.pi * 500 * c) + 20 / (4 * l * f)
               for f in (slow, fast) for l in (lo, 1.1 * r.l_out) for c in (ch, 0.95 * r.c_out))
    assert r.figures["i_peak"] == pytest.approx(peak) and peak > 8
    assert len(r.warnings) == 1 and r.warnings[0].startswith(f"the coils' worst peak, {peak:.2f} A, is above the "
                                                              "LM4652's minimum saturation drain current, 8 A")
    assert "THD+N" in r.binding



def test_heat_sink_figures_come_from_the_corner_that_sets_it():
    r = class_d.design()
    # the corner that sets theta_SA sits at 140 C; its dissipation is then thermal Ohm's law
    assert r.t_junction == pytest.approx(140.0)
    assert r.p_dissipation == pytest.approx(90 / (r.theta_sa_required + 2.2))
    # no heat sink: the package's 43 K/W would take the junction past the 150 C shutdown even at an eighth of
    # the clipping power: "needs a heat sink", no junction temperature past the shutdown
    hot = []
    for f in (r.f_sw_min, r.f_sw_max):
        p, x = p_clip(f, 4, 20) / 8, 401e-9 * f
        watts = x * p / (1 - x) + lm4651.P_IDLE_REF - 0.036 * 20 + p / 4 * 2 * 0.3 * (1 + 0.002 * 125)
        hot.append(50 + 43 * watts)
    assert max(hot) > 150 and r.needs_heat_sink and r.t_junction_no_sink is None
    assert r.figures["t_junction_no_sink"] == pytest.approx(max(hot))
    cool = class_d.design({"p_out": 20.0, "supply": 12.0, "r_load": 8.0, "t_ambient": 25.0, "thd_test_power": 5.0})
    assert not cool.needs_heat_sink and cool.t_junction_no_sink < 150
    # a heat sink given: T_j below the target, and the warning for one better than any made
    given = class_d.design({"theta_sa_available": 0.01})
    assert given.t_junction < 140 and "0.01 K/W: no TO-220 heat sink made" in given.warnings[0]



def test_iec_thermal_basis_is_an_eighth_of_the_clipping_power_by_hand():
    """The default basis (IEC 62368-1 Annex E: 1/8 of the non-clipped power), at the defaults, by hand from the
    datasheet's figures: eq 9/10 with 25 + 26 + 350 ns, R_DS(on) 300 mOhm at 25 C rising 0.2 %/K to T_j =
    140 C, the idle loss of 55 % efficiency at 5 W less the LM4651's 36 mA (|I+| + |I-|: 20 V x 36 mA = 0.72 W),
    theta_JC 2.0 + theta_CS 0.2 K/W."""
    r = class_d.design()
    assert r.spec["thermal_basis"] == "iec_1_8" and "1/8 of the clipping power" in r.thermal_basis
    x5 = 361e-9 * 125e3  # the system table's 55 % at 5 W: what is left after conduction and switching is idle
    idle = 5 / 0.55 - 5 - 2 * 0.2 * 5 / 4 - x5 * 5 / (1 - x5) - 0.036 * 20
    need = {}
    for f in (r.f_sw_min, r.f_sw_max):
        p, x = p_clip(f, 4, 20) / 8, 401e-9 * f
        watts = x * p / (1 - x) + idle + 2 * 0.3 * (1 + 0.15 / 75 * 115) * p / 4
        need[(140 - 50) / watts - 2.2] = (p, watts)
    assert r.theta_sa_required == pytest.approx(min(need), rel=1e-9)
    assert (r.p_thermal, r.p_dissipation) == pytest.approx(need[min(need)], rel=1e-9)
    assert 15 < r.p_thermal < 17 and 12 < r.theta_sa_required < 13  # 16.3 W, 12.1 K/W: a small clip-on sink
    full = class_d.design({"thermal_basis": "continuous_sine"})
    assert full.theta_sa_required < 0.7 and full.p_thermal == pytest.approx(full.p_clip, rel=0.05)
    with pytest.raises(InputError, match=r'p_continuous = 50 W .*thermal_basis = "continuous_sine"'):
        class_d.design({"p_continuous": 50.0})


def test_heat_sink_is_sized_at_what_the_amplifier_can_deliver():
    small = class_d.design({"p_out": 50.0, "thermal_basis": "continuous_sine"})
    # it carries the clipping power at each oscillator corner, not p_out: the heat sink does not shrink
    need = []
    for f in (small.f_sw_min, small.f_sw_max):
        p, x = p_clip(f, 4, 20), 401e-9 * f
        need.append(90 / (x * p / (1 - x) + p / 4 * 2 * 0.3 * 1.23 + lm4651.P_IDLE_REF - 0.036 * 20) - 2.2)
    assert small.theta_sa_required == pytest.approx(min(need)) and small.theta_sa_required < 0.7
    fixed = class_d.design({"p_out": 50.0, "thermal_basis": "continuous_sine", "p_continuous": 50.0})
    assert fixed.theta_sa_required > 2 * small.theta_sa_required
    # by hand at the fast corner for 50 W: eq 9/10 with 350 ns, 300 mOhm x 1.23 at 140 C, idle less 36 mA
    f = fixed.f_sw_max
    x = 401e-9 * f
    watts = x * 50 / (1 - x) + 50 / 4 * 2 * 0.3 * (1 + 0.002 * 115) + lm4651.P_IDLE_REF - 0.036 * 20
    assert fixed.theta_sa_required == pytest.approx(90 / watts - 2.2)



@SETTINGS
@given(frac=st.floats(0.2, 0.95), r_load=st.sampled_from([4.0, 6.0, 8.0]), t_a=st.floats(0, 70),
       thd=st.floats(0.003, 0.02), sink=st.one_of(st.none(), st.floats(0.5, 8)), pkg=st.sampled_from(["TF", "T"]),
       ser=st.sampled_from(["E12", "E24", "E96"]), objective=st.sampled_from(["efficiency", "heat_sink"]),
       ripple=st.floats(0.05, 1.0), f_audio=st.sampled_from([200.0, 500.0, 2000.0]), dcr=st.floats(50, 2000),
       q_max=st.floats(0.7, 1.5), l_ser=st.sampled_from(["E6", "E12"]), band=st.sampled_from([22e3, 80e3, 150e3]),
       l_tol=st.sampled_from([0.1, 0.3]), v_tol=st.sampled_from([0.0, 0.03, 0.08]))
def test_class_d_equals_independent_enumeration(frac, r_load, t_a, thd, sink, pkg, ser, objective, ripple, f_audio,
                                                 dcr, q_max, l_ser, band, l_tol, v_tol):
    spec = dict(p_out=frac * 130 * 4 / r_load ** 0.8, r_load=r_load, t_ambient=t_a, thd_max=thd,
                theta_sa_available=sink, package=pkg, r_osc_series=ser, objective=objective, ripple_max=ripple,
                f_audio=f_audio, l_dcr=dcr, q_max=q_max, l_series=l_ser, c_series=l_ser, thd_bandwidth=band,
                l_tolerance=l_tol, supply_tolerance=v_tol)
    expected = enumerate_class_d(spec)
    try:
        got = class_d.design(spec)
    except Infeasible as exc:
        assert expected is None, exc
        return
    assert (got.r_osc, got.l_out, got.c_out, got.r_dly) == expected



def test_implausible_designs_still_design_with_warnings():
    tiny = class_d.design({"p_out": 8.0, "thermal_basis": "continuous_sine", "p_continuous": 8.0, "t_ambient": 0.0,
                           "supply": 15.0})
    assert 30 < tiny.theta_sa_required < 43 - 2.2 and "above about 30 K/W" in tiny.warnings[0]
    hot = class_d.design({"t_ambient": 65.0, "thermal_basis": "continuous_sine"})
    assert hot.theta_sa_required < 0.5 and "below about 0.5 K/W" in hot.warnings[0]
    with pytest.raises(Infeasible) as exc:  # hotter still: say the hottest ambient that works
        class_d.design({"t_ambient": 85.0, "thermal_basis": "continuous_sine"})
    assert 65 < exc.value.achievable["t_ambient_max"] < 85 and "ambient of at most" in str(exc.value)
    # the 8 ohm example's slowest corner (83.7 kHz) sits 5 % above the analyser's 80 kHz band: the residue there,
    # 8 x 20 V / pi / sqrt2 through the filter (L and C at their low ends) over sqrt(10 W x 8 ohm), is said, not
    # counted as a brick wall does
    import tomllib
    from pathlib import Path

    eight = class_d.design(tomllib.loads((Path(__file__).resolve().parents[3] / "book" / "examples" /
                                          "amplifier_8ohm.toml").read_text())["class_d"])
    said = [w for w in eight.warnings if "brick-wall" in w]
    assert 80e3 <= eight.f_sw_min < 120e3 and len(said) == 1 and "83.72 kHz" in said[0]
    share = lm4651.ripple_rms(eight.f_sw_min, 0.9 * eight.l_out, 0.95 * eight.c_out, 8.0, 20.0) / (10 * 8) ** 0.5
    assert f"{share * 100:.2f} % of the test signal" in said[0]
    assert not [w for w in class_d.design().warnings if "brick-wall" in w]  # 61 kHz: inside the band, counted
    # a hot board designs (its heat sink holds T_j), but the parts are rated to 85 C only (operating ratings): said
    warm = class_d.design({"t_ambient": 90.0})
    assert [w for w in warm.warnings if "operating range" in w] == [
        "t_ambient = 90 °C: outside the LM4651/LM4652's operating range, \N{MINUS SIGN}40 to 85 °C (datasheet "
        "operating ratings); the heat sink holds T_j, but the parts are not rated there"]
    assert not [w for w in class_d.design({"t_ambient": 85.0 - 1e-9}).warnings if "operating range" in w]
    # rails near the absolute maximum (+-22 V, the operating top too), and the LM4652 past its 32 W
    near = class_d.design({"supply": 21.0, "supply_tolerance": 0.047})
    assert [w for w in near.warnings if "absolute maximum ±22 V" in w] == [
        "the high rail, ±21.99 V, is 99.9 % of the LM4651/LM4652's absolute maximum ±22 V (also the top of the operating "
        "range): the supply's ripple, load dump and switching spikes add to it; measure the rails on the board"]
    assert not [w for w in class_d.design().warnings if "absolute maximum ±22 V" in w]  # +-20 V: 90.9 %
    full = class_d.design({"p_out": 110.0, "supply_tolerance": 0.05, "thermal_basis": "continuous_sine"})
    assert full.p_dissipation > 32 and [w for w in full.warnings if "above its absolute maximum 32 W" in w]
    assert class_d.design().p_dissipation < 32 and not [w for w in class_d.design().warnings if "32 W" in w]



def test_bad_input_names_key_value_and_range():
    with pytest.raises(InputError, match=r"class_d.supply = 10.*from 11 V to 22 V"):
        class_d.checked({"supply": 10.0})
    with pytest.raises(InputError, match="class_d.objective"):
        class_d.checked({"objective": "cost"})
    # the rails' tolerance: +-22 V is the LM4651/LM4652's top (V+ + V- 44 V); say the tolerance that fits
    with pytest.raises(InputError, match=r"supply_tolerance = 0.1 puts the rails at \+-18.9 V to \+-23.1 V.* at most "
                                         r"0.0476 fits"):
        class_d.checked({"supply": 21.0, "supply_tolerance": 0.1})


def test_rails_tolerance_by_hand():
    """+-20 V +-5 % for 110 W: clipping at +-19 V, THD+N, the residue, the coils' peak and the heat sink at +-21 V,
    each by hand from the oracle's own clipping fit."""
    r = class_d.design({"supply_tolerance": 0.05, "p_out": 110.0})
    assert (r.r_osc, r.l_out, r.c_out, r.r_dly) == enumerate_class_d({"supply_tolerance": 0.05, "p_out": 110.0})
    slow, fast = r.f_sw_min, r.f_sw_max
    assert r.p_clip == pytest.approx(p_clip(fast, 4, 19.0)) and r.p_clip >= 110
    assert p_clip(fast, 4, r.supply_least) == pytest.approx(110.0)  # the least rail delivers p_out exactly
    assert 18.5 < r.supply_least < 19.0  # below the low rail: 111.6 W there
    # a small p_out: the test power (10 W) sets it, and never below the LM4651/LM4652's +-11 V operating minimum
    assert class_d.design({"p_out": 5.0}).supply_least == 11.0
    worst = 0.0  # the residue's worst corner at +-21 V: 8 x 21 V / pi / sqrt2 through the loaded filter
    for f, lo, co in itertools.product((slow, fast), (0.9 * r.l_out, 1.1 * r.l_out), (0.95 * r.c_out, 1.05 * r.c_out)):
        w = 2 * math.pi * f
        worst = max(worst, 168 / math.pi / math.sqrt(2) / abs(1 + 1j * w * 2 * lo / 4 - w * w * 2 * lo * co))
    assert r.figures["ripple"] == pytest.approx(worst)
    x5 = 361e-9 * 125e3
    idle = (5 / 0.55 - 5 - 2 * 0.2 * 5 / 4 - x5 * 5 / (1 - x5)) * 21 / 20 - 0.036 * 21
    need = []
    for f in (slow, fast):
        p, x = p_clip(f, 4, 21.0) / 8, 401e-9 * f
        need.append(90 / (x * p / (1 - x) + idle + 2 * 0.3 * (1 + 0.002 * 115) * p / 4) - 2.2)
    assert r.theta_sa_required == pytest.approx(min(need), rel=1e-9)
    nominal = class_d.design({"p_out": 110.0})  # exact rails: more clipping power, a smaller heat sink needed
    assert nominal.p_clip > r.p_clip and nominal.theta_sa_required > r.theta_sa_required


def test_rails_the_default_can_take():
    """125 W at +-20 V -5 % does not clip-free: the design says the tolerance that fits, and it does."""
    with pytest.raises(Infeasible) as exc:
        class_d.design({"supply_tolerance": 0.05})
    most = exc.value.achievable["supply_tolerance_max"]
    assert 0.02 < most < 0.05 and f"supply_tolerance at most {most:.3g}" in str(exc.value)
    fits = class_d.design({"supply_tolerance": most - 1e-4})  # the oracle's clipping fit at the rail said
    assert p_clip(fits.f_sw_max, 4, 20 * (1 - most)) == pytest.approx(125.0, rel=1e-3)
    with pytest.raises(Infeasible):
        class_d.design({"supply_tolerance": most + 1e-3})
