"""1,000 generated specifications, valid and broken, thrown at the loader and the three solvers.

Every one must end in a design that re-verifies independently, in an InputError naming the offending
table.key (or table), or in an Infeasible that says what can be met. Nothing else may escape.
"""
import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import InputError
from handbook.design import class_d, commutation, spec
from handbook.design.schema import TABLES
from handbook.design.solvers import Infeasible

from oracles import corners_vcs

SANE = {
    "commutation": {"pole_pairs": st.integers(1, 16), "rpm_min": st.floats(100, 5000), "rpm_max": st.floats(500, 30000),
                    "i_charge_min": st.floats(2e-6, 20e-6), "i_charge_max": st.floats(5e-6, 40e-6),
                    "window": st.floats(0.5, 2.5), "min_excursion": st.floats(0.02, 0.4),
                    "tolerance": st.sampled_from([0.01, 0.02, 0.05, 0.1, 0.2]),
                    "series": st.sampled_from(["E6", "E12", "E24", "E96"])},
    "current_limiter": {"i_no_trip": st.floats(0.05, 5), "i_must_trip": st.floats(0.1, 10),
                        "resistor_tolerance": st.sampled_from([0.001, 0.005, 0.01, 0.02, 0.05]),
                        "r7_tolerance": st.sampled_from([0.01, 0.02, 0.05]), "zener_voltage": st.floats(4.7, 12),
                        "zener_tolerance": st.sampled_from([0.01, 0.02, 0.05]), "offset": st.floats(0, 0.01),
                        "zener_tc": st.floats(0, 8e-3), "temp_span": st.floats(0, 50),
                        "r7_series": st.sampled_from(["E12", "E24", "E96"]), "r9_series": st.sampled_from(["E24", "E96"])},
    "class_d": {"p_out": st.floats(5, 200), "r_load": st.sampled_from([2.0, 4.0, 6.0, 8.0, 16.0]),
                "supply": st.floats(12, 22), "t_ambient": st.floats(-20, 90), "package": st.sampled_from(["TF", "T"]),
                "theta_cs": st.floats(0, 1), "theta_sa_available": st.floats(0.3, 20), "thd_max": st.floats(0.001, 0.05),
                "r_osc_series": st.sampled_from(["E12", "E24", "E96"])},
}
JUNK = st.one_of(st.just(float("nan")), st.just(float("inf")), st.just(-1.0), st.just(0.0), st.just(1e12),
                 st.just(22), st.text(max_size=4), st.booleans(), st.lists(st.integers(), max_size=2),
                 st.just("E13"), st.just(2.5))


@st.composite
def specs(draw):
    data = {}
    for table, keys in SANE.items():
        if draw(st.booleans()):
            continue
        body = {}
        for key, strat in keys.items():
            if draw(st.integers(0, 3)) == 0:
                continue
            body[key] = draw(JUNK) if draw(st.integers(0, 15)) == 0 else draw(strat)
        if draw(st.integers(0, 30)) == 0:
            body[draw(st.sampled_from(["rpm_mni", "i_trip", "supply_v", "tolerence"]))] = 1.0
        data[table] = body
    if draw(st.integers(0, 40)) == 0:
        data["clas_d"] = {}
    return data


def _reverify(result):
    c = result["commutation"]
    chk = commutation.verify(c.cap_cd, c.spec)
    assert chk["window_ok"] and chk["noise_ok"]
    lim = result["current_limiter"]
    s = lim.spec
    lo, hi = corners_vcs(np.array([lim.r9]), s)
    assert lo[0] / (lim.r7 * (1 + s["r7_tolerance"])) >= s["i_no_trip"] * (1 - 1e-9)
    assert hi[0] / (lim.r7 * (1 - s["r7_tolerance"])) <= s["i_must_trip"] * (1 + 1e-9)
    cd = result["class_d"]
    ev = class_d.evaluate(cd.f_sw, cd.spec)
    assert ev["ok_thd"] and ev["ok_clip"] and ev["ok_heat"]
    for table in result.values():
        for v in table.summary().values():
            assert not (isinstance(v, float) and not math.isfinite(v))


@settings(max_examples=1000, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(specs())
def test_every_spec_ends_in_a_verified_design_or_a_clear_error(data):
    try:
        result = spec.run(spec.parse(data))
    except InputError as exc:
        msg = str(exc)
        tables = ("commutation", "current_limiter", "class_d", "clas_d")
        assert any(f"{t}." in msg or f"[{t}" in msg or t in msg for t in tables), msg
        return
    except Infeasible as exc:
        assert str(exc) and exc.achievable and exc.table in TABLES
        return
    _reverify(result)
