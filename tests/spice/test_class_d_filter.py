"""The LM4651/LM4652 bridge output filter with its load: the drawing and the netlist carry the same parts,
and ngspice agrees with the book's filter model (corner, Q, band, switching residue) within the stated
tolerances, for 4 and 8 ohm loads and for a class-D design."""
import math
import re

import pytest
from drawn_layout import plain
from drawn_parts import assert_same_parts, drawn_labels

from handbook.sources.lm4651 import circuit as eqs
from handbook.spice import class_d
from handbook.spice.circuit import evaluate

BUILT = (class_d.circuit, class_d.circuit_8ohm, class_d.ripple, class_d.ripple_8ohm)




@pytest.mark.parametrize("build", BUILT)
def test_drawing_netlist_and_parts_are_one_set_both_ways(build):
    assert_same_parts(build(), {"EPROBE": "the load voltage as one node, for .meas (a probe)"})


def _line(netlist: str, ref: str) -> list[str]:
    lines = [ln.split() for ln in netlist.splitlines() if ln.split()[:1] == [ref]]
    assert len(lines) == 1, f"{ref}: {len(lines)} netlist lines"
    return lines[0]


@pytest.mark.parametrize("build", BUILT)
def test_drawing_and_netlist_have_the_same_parts(build):
    c = build()
    labels = drawn_labels(c.draw())
    drawn = {lab.split()[0] for lab in labels if re.match(r"^[A-Z]+[_0-9A-Z]* ", lab)}
    assert drawn == {p.ref for p in c.parts}
    for p in c.parts:
        assert plain(class_d.label(p)) in labels
        words = _line(c.netlist, p.ref)
        if p.ref.startswith("VO"):  # a +-V_s square: PULSE(v1 v2 ...)
            v1, v2 = (float(w) for w in " ".join(words[3:]).removeprefix("PULSE(").split()[:2])
            assert abs(v1) == pytest.approx(p.value) and v2 == pytest.approx(-v1)
        else:
            assert float(words[3]) == pytest.approx(p.value, rel=1e-6)


def test_defaults_are_the_datasheets():
    p = {q.ref: q.value for q in class_d.circuit().parts}
    assert (p["L1"], p["L2"], p["C_BYP"], p["R_L"], p["VO1"]) == (50e-6, 50e-6, 5e-6, 4.0, 20.0)
    assert class_d.circuit_8ohm().part("R_L").value == 8.0
    with pytest.raises(KeyError, match="unknown parameter"):
        class_d.circuit({"l_typo": 1e-6})


@pytest.mark.parametrize("build", BUILT)
def test_every_check_agrees_within_its_tolerance(ngspice, build):
    c = build()
    assert len(c.checks) >= 1
    for row in evaluate(c):
        assert row["agrees"], f"{row['id']}: equation {row['equation']:.6g}, SPICE {row['spice']:.6g}, {row['why']}"


def test_the_largest_q_the_referee_draws_agrees_within_the_grids_bound(ngspice):
    """The sharpest peak of the operating points (8 ohm across 10 uF, 2 x 22 uH: Q 3.81), where |H|'s curvature
    bounds the AC grid's interpolation: the Q row's tolerance is that bound (k^2 Q^2 / 2 and the printed digits)."""
    rows = {r["id"]: r for r in evaluate(class_d.circuit({"l_out": 22e-6, "c_out": 10e-6, "r_load": 8.0}))}
    q = rows["lm4651-filter-8ohm-q"]
    assert q["agrees"] and q["equation"] == pytest.approx(class_d.Q_MAX)
    k = 10 ** (1 / class_d.AC_CHECK_PER_DECADE) - 1
    assert q["rtol"] == pytest.approx(k * k * class_d.Q_MAX ** 2 / 2 + 5e-7, rel=0.1)


def test_the_residue_is_read_about_its_mean(ngspice):
    """ngspice's first-order step after each corner of the edges builds a DC at the load (it read +0.09 % in the
    raw rms with a hundredth of the period as the step); the deck reads the rms about the mean, as the Fourier sum."""
    from handbook.spice.runner import run

    c = class_d.ripple({"l_out": 100e-6, "c_out": 10e-6, "r_load": 8.0, "f_sw": 200e3, "supply": 25.0})
    out = run(c.netlist)
    assert out["ripple"] == pytest.approx((out["ripple_rms"] ** 2 - out["ripple_avg"] ** 2) ** 0.5, rel=1e-5)
    assert evaluate(c)[0]["agrees"]


def test_the_filter_model_has_two_checks_or_more_per_load(ngspice):
    assert len(class_d.circuit().checks) + len(class_d.ripple().checks) >= 2


def test_response_follows_the_model_for_both_loads(ngspice):
    got = class_d.response(points=9)
    for r in (4.0, 8.0):
        model = [10 * math.log10(eqs.filter_gain2(f, eqs.L_REF, eqs.C_REF, r)) for f in got["f"]]
        assert list(got[r]) == pytest.approx(model, abs=1e-3)


def test_a_class_d_design_is_confirmed(ngspice):
    from types import SimpleNamespace

    from handbook.design.class_d import model

    spec = {"r_load": 4.0, "supply": 20.0, "supply_tolerance": 0.05, "f_audio": 500.0, "osc_tol_slow": 0.2, "osc_tol_fast": 0.235,
            "l_tolerance": 0.1, "c_tolerance": 0.05, "ripple_max": 0.5}
    fo, lo, co = model.corner_factors(spec)
    # at the high rail, +-21 V: the residue grows with the rails
    worst = max(eqs.ripple_rms(77.16e3 * a, 220e-6 * b, 22e-6 * c, 4.0, 21.0) for a, b, c in zip(fo, lo, co))
    result = SimpleNamespace(spec=spec, l_out=220e-6, c_out=22e-6, f_sw=77.16e3, f_sw_min=77.16e3 * 0.8,
                             f_sw_max=77.16e3 * 1.235, figures={"ripple": worst})
    out = class_d.design_check(result)
    assert set(out) == {"f_corner", "f_corner_equation", "ripple_at_load", "ripple_at_load_equation", "corners",
                        "meets_spec"}
    assert out["f_corner_equation"] == pytest.approx(eqs.filter_f0(220e-6, 22e-6), rel=1e-12)
    assert out["f_corner"] == pytest.approx(out["f_corner_equation"], rel=1e-3)
    assert out["ripple_at_load"] == pytest.approx(worst, rel=2e-3) and out["meets_spec"]
    tight = SimpleNamespace(**{**vars(result), "spec": {**spec, "ripple_max": 0.9 * out["ripple_at_load"]}})
    assert class_d.design_check(tight)["meets_spec"] is False  # judged against the spec by SPICE's own figure
