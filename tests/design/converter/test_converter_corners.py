"""The converter holds at every corner of what it assumes: an oracle written here (eq 1, 2, 4 and 5 by hand, no
handbook.design code) takes the designed R1 and L1 through all 2^5 corners of R1 (its tolerance and its drift
from 25 C to t_ambient, each at the same end), A_L, V12(H), V_CE(sat) and V_F,
and the Monte Carlo lot of the default, the template's and the pump example's converter meets every limit
(handbook.design.converter.operating, handbook.design.worstcase.models)."""
import itertools
import tomllib

import pytest
from converter_oracle import E96, ROOT

from handbook.design.converter import result as converter

#: the schema's defaults of the keys the oracle reads, written out again
DEFAULTS = {"v_supply_min": 8.0, "v_supply_max": 14.4, "v_out": 12.0, "i_out": 0.05, "f_min": 20e3,
            "v_regulator_drop": 2.5, "v_f": 0.8, "v_ce_sat": 0.5, "v12h": 0.4, "r1_tolerance": 0.01,
            "a_l_tolerance": 0.1, "device_spread": 0.1, "audible": "avoid", "r1_tempco": 100e-6, "t_ambient": 85.0}
PUMP = tomllib.loads((ROOT / "book" / "examples" / "pump_yield.toml").read_text())["converter"]
SPECS = {
    "default": {},
    "warn": {"audible": "warn"},
    "wide spread": {"device_spread": 0.3},
    "no spread": {"device_spread": 0.0, "audible": "warn"},
    "pump example": PUMP,
    # V_L- nearly gone at the lowest supply: there the least current is delivered with V12(H) at its HIGH end
    "low supply": {"v_supply_min": 1.6, "v_supply_max": 2.0, "v_out": 5.0, "v12h": 0.8, "i_out": 0.005},
}


def delivered(s, r1, v12h, vce, vf):
    """Eq 5 read backwards at v_supply_min: I_out = I_peak / (2 (1 + alpha)), alpha = V_L+ / V_L- (eq 1 to 3)."""
    vl_plus = s["v_out"] + s["v_regulator_drop"] + vf - s["v_supply_min"]
    vl_minus = s["v_supply_min"] - vce - v12h
    return v12h / r1 / (2 * (1 + vl_plus / vl_minus))


def frequency(s, vcc, inductance, r1, v12h, vce, vf):
    """1 / (t1 + t2), t1 = L I_peak / V_L- and t2 = L I_peak / V_L+ (eq 4), I_peak = V12(H) / R1; 0 without V_L+."""
    vl_plus, vl_minus = s["v_out"] + s["v_regulator_drop"] + vf - vcc, vcc - vce - v12h
    if vl_plus <= 0:
        return 0.0
    i_peak = v12h / r1
    return 1 / (inductance * i_peak / vl_minus + inductance * i_peak / vl_plus)


def corners(s, r1, l_nominal):
    """Every corner of R1, A_L, V12(H), V_CE(sat) and V_F (2^5 = 32): R1, L and the three figures."""
    t, a, d = s["r1_tolerance"], s["a_l_tolerance"], s["device_spread"]
    drift = s["r1_tempco"] * abs(s["t_ambient"] - 25.0)  # 100 ppm/K x 60 K = 0.6 % at the defaults
    for e in itertools.product((-1, 1), repeat=5):
        yield (r1 * (1 + e[0] * t) * (1 + e[0] * drift), l_nominal * (1 + e[1] * a), s["v12h"] * (1 + e[2] * d),
               s["v_ce_sat"] * (1 + e[3] * d), s["v_f"] * (1 + e[4] * d))


@pytest.mark.parametrize("name", list(SPECS))
def test_every_corner_delivers_i_out_and_runs_at_f_min(name):
    """At all 32 corners the designed R1 (series value) and L1 (nominal, wound) deliver i_out and run at f_min at
    the lowest supply, and with audible = "avoid" stay at or above 20 kHz over the supply range; the least current,
    the lowest frequencies and the peak currents the design reports are the corners' own extremes; neither part
    is oversized (the next E96 R1 up misses i_out at some corner, a larger L1 misses f_min)."""
    r = converter.design(SPECS[name])
    s = {**DEFAULTS, **SPECS[name]}
    assert {k: r.spec[k] for k in s} == s
    r1, l_nom = r.r1_part, r.l1_nominal
    rows = list(corners(s, r1, l_nom))
    assert len(rows) == 32
    current = [delivered(s, r1c, v12h, vce, vf) for r1c, _, v12h, vce, vf in rows]
    f_low = [frequency(s, s["v_supply_min"], lc, r1c, v12h, vce, vf) for r1c, lc, v12h, vce, vf in rows]
    assert min(current) >= s["i_out"] and min(current) == pytest.approx(r.i_out_least, rel=1e-12)
    assert min(f_low) >= r.f_min_design * (1 - 1e-9) and min(f_low) == pytest.approx(r.f_min_design, rel=1e-9)
    assert r.f_min_design >= s["f_min"]
    peaks = [v12h / r1c for r1c, _, v12h, _, _ in rows]
    assert r.i_peak_max == pytest.approx(max(peaks), rel=1e-12) and r.i_peak_min == pytest.approx(min(peaks), rel=1e-12)
    assert r.l1_max == pytest.approx(l_nom * (1 + s["a_l_tolerance"]), rel=1e-12)
    # the supply range, both ends and a grid: the lowest full-load frequency is the design's f_sw_min
    n = 400
    grid = [s["v_supply_min"] + (s["v_supply_max"] - s["v_supply_min"]) * k / n for k in range(n + 1)]
    f_all = min(frequency(s, v, lc, r1c, v12h, vce, vf) for r1c, lc, v12h, vce, vf in rows for v in grid)
    assert f_all == pytest.approx(r.f_sw_min, rel=1e-9)
    if s["audible"] == "avoid":
        assert f_all >= 20e3 * (1 - 1e-9)
    # nothing to spare: the next E96 value above R1 misses i_out somewhere, 0.1 % more inductance misses f_min
    above = min(v * 10.0 ** k for v in E96 for k in range(-3, 7) if v * 10.0 ** k > r1 * (1 + 1e-9))
    assert min(delivered(s, r1c, v12h, vce, vf) for r1c, _, v12h, vce, vf in corners(s, above, l_nom)) < s["i_out"]
    assert min(frequency(s, s["v_supply_min"], lc, r1c, v12h, vce, vf)
               for r1c, lc, v12h, vce, vf in corners(s, r1, l_nom * 1.001)) < r.f_min_design


def test_the_low_supply_corner_is_v12h_high():
    """Where V_L- nearly vanishes the least current is delivered with V12(H) at its high end (the current's
    logarithm is concave in V12(H), so the least lies at one end): the oracle's corners say which, and R1 is sized
    there. At V12(H)'s low end that R1 would deliver more."""
    spec = SPECS["low supply"]
    s = {**DEFAULTS, **spec}
    r = converter.design(spec)
    r1_high = r.r1_part * (1 + s["r1_tolerance"]) * (1 + s["r1_tempco"] * (s["t_ambient"] - 25.0))
    d = s["device_spread"]
    at = {end: delivered(s, r1_high, s["v12h"] * (1 + end * d), s["v_ce_sat"] * (1 + d), s["v_f"] * (1 + d))
          for end in (-1, 1)}
    assert at[1] < at[-1] and at[1] == pytest.approx(r.i_out_least, rel=1e-12)


def _lots():
    from handbook.cli_text import template

    return {"default": {}, "template": tomllib.loads(template())["converter"], "pump example": PUMP}


@pytest.mark.parametrize("name", ["default", "template", "pump example"])
def test_monte_carlo_lot_meets_every_limit(name):
    """The worst-case analysis draws R1, A_L and the three device figures uniformly within what the design assumed
    (device_spread, not a constant of its own): 100 000 boards of each design meet every limit."""
    from handbook.design import spec as spec_module
    from handbook.design.worstcase import analyse

    r = spec_module.run_each(spec_module.parse({"converter": _lots()[name]}))["converter"]
    w = analyse("converter", r, n=100_000, seed=1)
    assert w.yield_all >= 0.9999, w.yields
    assert set(w.yields) == {"i_out", "f_min", "audio band"}
    spread = {d.part: (d.low, d.high) for d in w.distributions}
    assert spread["TCA5600 V12(H)"] == pytest.approx((r.spec["v12h"] * 0.9, r.spec["v12h"] * 1.1), rel=1e-12)
