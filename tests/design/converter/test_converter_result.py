"""The converter's operating point and its result: eq 1 to 6a and the parts' tolerances by hand, the
frequency range, the exit-3 searches and the warnings (handbook.design.converter.result)."""

import pytest
from converter_oracle import E96, hand_frequency, hand_operating_point

from handbook.design.converter import result as converter
from handbook.design.solvers import Infeasible


def test_eq_1_to_6a_at_the_defaults(result):
    # V_L+ = 12 + 2.5 + 0.8 - 8 = 7.3 V, V_L- = 8 - 0.5 - 0.4 = 7.1 V
    assert result.alpha == pytest.approx(7.3 / 7.1, rel=1e-12)
    assert result.t1 == pytest.approx(25.347e-6, rel=1e-4)  # 50 us x 7.3 / 14.4
    assert result.t2 == pytest.approx(24.653e-6, rel=1e-4)
    assert result.i_peak == pytest.approx(0.20282, rel=1e-4)  # 2 x 50 mA x 14.4 / 7.1
    assert result.l1 == pytest.approx(887.33e-6, rel=1e-4)
    assert result.r1 == pytest.approx(1.9722, rel=1e-4)
    hand = hand_operating_point()
    for key, value in hand.items():
        assert getattr(result, key) == pytest.approx(value, rel=1e-12), key


def test_eq_1_to_6a_with_other_inputs():
    spec = {"v_supply_min": 10.0, "v_out": 15.0, "i_out": 0.08, "f_min": 30e3, "v_regulator_drop": 2.0,
            "v_f": 0.7, "v_ce_sat": 0.3, "v12h": 0.3}
    op = converter.operating_point(converter.checked(spec))
    hand = hand_operating_point(10.0, 15.0, 2.0, 0.7, 0.3, 0.3, 0.08, 30e3)
    for key, value in hand.items():
        assert op[key] == pytest.approx(value, rel=1e-12), key


def test_r1_and_l1_at_their_tolerances_and_the_device_spread_by_hand(result):
    # the device corner that delivers least (+-10 %): V12(H) = 0.36 V, V_CE(sat) = 0.55 V, V_F = 0.88 V, so
    # V_L- = 8 - 0.55 - 0.36 = 7.09 V and V_L+ = 12 + 2.5 + 0.88 - 8 = 7.38 V; eq 5 and 6a there:
    # I_peak = 2 x 50 mA x (1 + 7.38 / 7.09) = 204.1 mA, R1 = 0.36 V / I_peak = 1.7639 ohm
    r1_worst = 0.36 / (2 * 0.05 * (1 + 7.38 / 7.09))
    assert result.r1_worst == pytest.approx(r1_worst, rel=1e-12) == pytest.approx(1.7639, rel=1e-4)
    # R1 at its high end: +1 % tolerance and +100 ppm/K x (85 - 25) K = +0.6 % drift, (1.01)(1.006) = 1.01606; the
    # largest E96 value at or below 1.7639 / 1.01606 = 1.7360 ohm is 1.69 ohm (1.74 is above)
    high, low = 1.01 * 1.006, 0.99 * 0.994
    target = r1_worst / high
    e96 = [v * 10 ** k for k in (-1, 0, 1) for v in E96]
    assert result.r1_part == pytest.approx(max(v for v in e96 if v <= target), rel=1e-9) == pytest.approx(1.69)
    # at R1's high end in that corner it still delivers i_out: 0.36 / (1.69 x 1.01606) / 2 x 7.09 / 14.47 = 51.36 mA
    i_least = 0.36 / (1.69 * high) / 2 * 7.09 / (7.09 + 7.38)
    assert result.i_out_least == pytest.approx(i_least, rel=1e-12) and 0.0513 <= i_least < 0.0514
    # the peak currents: V12(H) low and R1 high; V12(H) high and R1 low (the coil's worst)
    i_min, i_max = 0.36 / (1.69 * high), 0.44 / (1.69 * low)
    assert result.i_peak_min == pytest.approx(i_min, rel=1e-12) and result.i_peak_max == pytest.approx(i_max, rel=1e-12)
    # L1 is a largest inductance: in the slow corner (V12(H) = 0.44 V, V_CE(sat) = 0.55 V, V_F = 0.72 V: V_L- =
    # 7.01 V, V_L+ = 7.22 V), A_L at +10 % and I_peak,max, it runs at f_min at the lowest VCC2; wound for it / 1.1
    slow = {"v12h": 0.44, "vce": 0.55, "vf": 0.72}
    l_max = 1 / (20e3 * i_max * (1 / 7.01 + 1 / 7.22))
    assert result.l1_max == pytest.approx(l_max, rel=1e-12) and result.l1_nominal == pytest.approx(l_max / 1.1, rel=1e-12)
    assert hand_frequency(8.0, l_max, i_max, **slow) == pytest.approx(20e3, rel=1e-9)
    # the frequency over VCC2 = 8 .. 14.4 V: slowest at 14.4 V in the slow corner; fastest in the fast corner
    # (V12(H) = 0.36 V, V_CE(sat) = 0.45 V, V_F = 0.88 V) where V_L- = V_L+ (VCC2 = (15.38 + 0.81) / 2 = 8.095 V),
    # with L at -10 % and I_peak,min
    assert result.f_sw_min == pytest.approx(hand_frequency(14.4, l_max, i_max, **slow), rel=1e-9)
    assert result.f_sw_min == pytest.approx(4345, rel=1e-3)
    fast = {"v12h": 0.36, "vce": 0.45, "vf": 0.88}
    assert result.f_sw_max == pytest.approx(hand_frequency(8.095, l_max / 1.1 * 0.9, i_min, **fast), rel=1e-9)
    assert result.f_sw_max == pytest.approx(31592, rel=1e-3)
    # the coil: I_rms = 264.6 mA / sqrt(3) = 152.7 mA; the smaller cores' thickest fitting wire would carry more than
    # 5 A/mm² (EFD 10/5/3 fits 0.16 mm: 152.7 mA in 0.02011 mm^2 is 7.60 A/mm²), so it grows: EP 10 in N87,
    # 64 turns of 0.265 mm, pi x 0.1325^2 = 0.05515 mm^2, 2.77 A/mm²
    assert (result.core_shape, result.core_material, result.turns, result.wire) == ("EP 10", "N87", 64,
                                                                                   "Round 0.265 - Grade 1")
    i_rms = i_max / 3 ** 0.5
    assert result.coil.current_density == pytest.approx(i_rms / (3.141592653589793 * 0.1325e-3 ** 2), rel=1e-9)
    assert 2.7e6 < result.coil.current_density <= 5e6 and result.binding.startswith("current density (the next "
                                                                                   "smaller core, EFD 10/5/3")


def test_more_current_needs_a_larger_core_and_too_much_is_infeasible():
    small = converter.design({"i_out": 0.02, "audible": "warn"})
    large = converter.design({"i_out": 0.3, "audible": "warn"})
    assert small.coil.ve < large.coil.ve
    # 0.287 ohm (E96 below 0.3 A's 0.2940 ohm / 1.01606), I_peak,max = 0.44 / (0.287 x 0.99 x 0.994) = 1.558 A,
    # 0.8995 A rms: RM 6's thickest fitting wire, 0.45 mm, carries 0.8995 / 0.1590 = 5.66 A/mm²
    assert large.binding.startswith("current density (the next smaller core, RM 6: in 3C90 its thickest fitting wire "
                                    "(Round 0.45 - Grade 1) carries 5.66 A/mm²")
    with pytest.raises(Infeasible) as exc:
        converter.design({"i_out": 5.0, "audible": "warn"})
    text = str(exc.value)
    assert "i_out up to" in text and "larger core family" in text
    i_ok = exc.value.achievable["i_out"]
    assert 1.0 < i_ok < 5.0
    converter.design({"i_out": i_ok, "audible": "warn"})  # what it says can be met, is
    with pytest.raises(Infeasible):
        converter.design({"i_out": i_ok * 1.02, "audible": "warn"})


def test_exit_3_finds_a_lower_current_and_a_higher_frequency():
    """At f_min = 1 kHz, 0.5 A needs too many turns for any core: the downward scan finds the current that
    works (the old upward bisection from 1 uA found none), and the frequency route a higher f_min."""
    spec = {"f_min": 1e3, "i_out": 0.5, "audible": "warn"}
    with pytest.raises(Infeasible) as exc:
        converter.design(spec)
    got = exc.value.achievable
    assert got["i_out"] is not None and got["f_min"] is not None
    assert 0.05 < got["i_out"] < 0.5 and 1e3 < got["f_min"] <= 1e6
    assert "i_out up to" in str(exc.value) and "f_min = " in str(exc.value)
    converter.design({**spec, "i_out": got["i_out"]})
    converter.design({**spec, "f_min": got["f_min"]})
    with pytest.raises(Infeasible):
        converter.design({**spec, "f_min": got["f_min"] / 1.02})
    converter.design({**spec, "i_out": 0.05})  # the review's example: designs


def test_warnings():
    warn = {"audible": "warn"}
    default = converter.design(warn).warnings
    assert any("audio band" in w and "14.4 V" in w and "4.345 kHz" in w for w in default)
    assert any("extrapolated" in w for w in default)  # 20 kHz and below, under the 25 kHz fits
    assert not any("A/mm²" in w for w in default)  # the current density is a limit now, not a warning
    quiet = converter.design({"f_min": 40e3, "v_supply_max": 8.0}).warnings
    assert not any("audio band" in w or "extrapolated" in w for w in quiet)
    # VCC2 up to the output side: the frequency falls to zero
    top = converter.design({**warn, "v_supply_max": 15.3})
    assert top.f_sw_min == 0.0 and any("V_L+ vanishes" in w for w in top.warnings)
    # a peak current above the switch's assumed rating; an absurdly small current: thousands of turns
    assert any("assumed for the TCA5600's internal switch" in w
               for w in converter.design({**warn, "i_out": 0.5}).warnings)
    tiny = converter.design({**warn, "i_out": 1e-6})
    assert tiny.turns > 300 and any("self-resonates" in w and "impractical" in w for w in tiny.warnings)


def test_audible_avoid_keeps_every_corner_above_the_audio_band():
    """The default (audible = avoid) raises f_min until the full-load frequency, L1 at +10 % and I_peak,max with
    V12(H) and V_CE(sat) at +10 % and V_F at -10 % (the slow corner), stays at or above 20 kHz x (1 + 2 %,
    audible_margin) = 20.4 kHz over the whole supply range, here checked on a fine grid by the oracle's own
    1 / (t1 + t2); 1 % less f_min would fall below it, and with no margin the floor is 20 kHz exactly. A supply
    reaching V_L+ = 0 in that corner (12 + 2.5 + 0.72 = 15.22 V) or so close that 1 MHz would be needed exits 3
    saying so."""
    r = converter.design()
    assert r.spec["f_min"] == 20e3 and r.f_min_design > 20e3
    assert r.warnings[0].startswith("audible = avoid: f_min raised from 20 kHz")
    grid = [8.0 + (14.4 - 8.0) * k / 2000 for k in range(2001)]
    slowest = min(hand_frequency(v, r.l1_nominal * 1.1, r.i_peak_max, vf=0.72, vce=0.55, v12h=0.44) for v in grid)
    assert slowest >= 20.4e3 * (1 - 1e-9) and slowest == pytest.approx(20.4e3, rel=1e-4)
    lower = converter.design({"audible": "warn", "f_min": r.f_min_design / 1.01})
    assert lower.f_sw_min < 20.4e3
    bare = converter.design({"audible_margin": 0.0})
    assert bare.f_sw_min == pytest.approx(20e3, rel=1e-4) and bare.f_min_design < r.f_min_design
    assert r.coil.current_density <= 5e6  # the defaults meet the current-density limit too
    with pytest.raises(Infeasible, match="V_L\\+ vanishes") as exc:
        converter.design({"v_supply_max": 15.25})
    assert exc.value.achievable["v_supply_max"] == pytest.approx(15.22, rel=1e-12)
    with pytest.raises(Infeasible, match="more than the 1 MHz allowed") as exc:
        converter.design({"v_supply_max": 15.219})
    assert exc.value.achievable["f_min"] > 1e6


def test_schema_defaults_are_the_chapters():
    from handbook.design import schema
    from handbook.sources.tca5600 import data

    chapter = {p.name: p.default for p in data.PARAMETERS}
    names = {"v_supply_min": "v_cc2_min", "v_out": "v_out2", "i_out": "i_out2", "f_min": "f_min",
             "v_regulator_drop": "regulator_drop", "v_f": "v_f", "vce_sat": "vce_sat", "v12h": "v12h"}
    names["v_ce_sat"] = names.pop("vce_sat")
    defaults = schema.defaults("converter")
    assert {k: defaults[k] for k in names} == {k: chapter[v] for k, v in names.items()}
