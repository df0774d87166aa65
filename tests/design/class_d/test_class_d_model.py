"""The class-D models (handbook.design.class_d.model) at their datasheet points and against sweeps."""
import math

import numpy as np
import pytest

from handbook.design import class_d
from handbook.design.class_d.model import band_deviation_box_db, band_deviation_db, sensitivity
from handbook.sources.lm4651 import circuit as lm4651

from oracles import p_clip


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



def test_residue_counts_only_inside_the_analysers_band():
    r = class_d.design()
    s, parts = r.spec, (r.r_osc, r.l_out, r.c_out, r.r_dly)
    narrow = class_d.model.one({**s, "thd_bandwidth": 22e3}, *parts)["thd_n"]  # both corners above 22 kHz
    fs, lo, co = r.f_sw_min, 0.9 * r.l_out, 0.95 * r.c_out
    assert narrow == pytest.approx(0.003 * (125e3 / fs) ** 2 * 250e-12 / (lo * co)) and narrow < r.thd_n
    # the old default parts (66.8 kHz, 100 uH, 10 uF): 3 % of residue inside the band, six times thd_max
    old = class_d.model.one(s, 13e3, 100e-6, 10e-6, 5100.0)
    assert old["thd_n"] > 0.028 and old["margins"]["THD+N"] < -4



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



def test_sensitivity_names_the_oscillator_for_clipping():
    r = class_d.design()
    rows = sensitivity(r.spec, r.r_osc, r.l_out, r.c_out, r.r_dly)
    typical = rows["typical (no tolerance)"]
    assert typical["clipping"] == pytest.approx(p_clip(r.f_sw, 4, 20) / 125 - 1)
    drops = {k: typical["clipping"] - v["clipping"] for k, v in rows.items() if k != "typical (no tolerance)"}
    assert max(drops, key=drops.get) in ("oscillator (eq 5 vs table)", "all at their limits")
    assert drops["inductor tolerance"] == pytest.approx(0.0)
