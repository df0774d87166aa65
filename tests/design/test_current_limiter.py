"""R7 and R9: closed-form corners and the design against every corner and every series value."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.core import series
from handbook.design import current_limiter
from handbook.design.schema import defaults
from handbook.design.solvers import Infeasible
from handbook.sources.an94002 import circuit as an94002

from oracles import corners_vcs, enumerate_limiter

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_closed_form_corners_equal_all_128_corners():
    s = {**defaults("current_limiter"), "zener_tc": 6.2e-3, "temp_span": 25.0}
    r9 = np.geomspace(10, 1e6, 300)
    lo, hi = current_limiter.vcs_extremes(r9, s)
    lo2, hi2 = corners_vcs(r9, s)
    np.testing.assert_allclose(lo, lo2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(hi, hi2, rtol=1e-12, atol=1e-15)


def test_default_limiter_design():
    r = current_limiter.design()
    assert (r.r7, r.r9) == enumerate_limiter({}) == (0.33, 1210.0)
    assert r.i_trip_min >= 0.9 and r.i_trip_max <= 1.8
    assert r.p_r7 == pytest.approx(0.9 ** 2 * 0.33)
    assert r.r7_relaxed <= r.r7


@SETTINGS
@given(i_no=st.floats(0.05, 10), ratio=st.floats(1.1, 4), rt=st.sampled_from([0.001, 0.005, 0.01, 0.02]),
       r7t=st.sampled_from([0.01, 0.05]), zt=st.sampled_from([0.01, 0.02, 0.05]), off=st.floats(0, 10e-3))
def test_limiter_equals_enumeration(i_no, ratio, rt, r7t, zt, off):
    spec = dict(i_no_trip=i_no, i_must_trip=i_no * ratio, resistor_tolerance=rt, r7_tolerance=r7t,
                zener_tolerance=zt, offset=off)
    expected = enumerate_limiter(spec)
    try:
        got = current_limiter.design(spec)
    except Infeasible:
        assert expected is None
        return
    assert expected is not None and got.r7 == pytest.approx(expected[0])
    # the R9 choice: same margin as the enumeration's best (ties between equal margins are allowed)
    s = got.spec
    m_got = min(current_limiter.limiter_margins(got.r7, got.r9, s))
    m_exp = min(current_limiter.limiter_margins(expected[0], expected[1], s))
    assert m_got == pytest.approx(m_exp, rel=1e-9, abs=1e-12)
    lo, hi = corners_vcs(np.array([got.r9]), s)  # independent re-check of feasibility
    assert lo[0] / (got.r7 * (1 + r7t)) >= i_no * (1 - 1e-9)
    assert hi[0] / (got.r7 * (1 - r7t)) <= i_no * ratio * (1 + 1e-9)


def test_monte_carlo_yield_of_the_design_and_of_the_note():
    r = current_limiter.design()
    mc = current_limiter.monte_carlo_trip(r.r7, r.r9, r.spec, n=100_000, seed=1)
    assert mc["yield"] == 1.0  # inside the exact corners by construction
    assert r.i_trip_min <= mc["i_min"] and mc["i_max"] <= r.i_trip_max
    # the note's design: R9 for 100 mV (eq 14) and R7 = 100 mV / 1.35 A (E24: 0.075 ohm)
    r9_note = series.nearest("E96", an94002.r9_for(0.1, 8.2, 5.6e3, 16e3))
    note = current_limiter.monte_carlo_trip(0.075, r9_note, r.spec, n=100_000, seed=1)
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
        current_limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.1})
    ratio = exc.value.achievable["narrowest_ratio"]
    s = defaults("current_limiter")
    lo, hi = corners_vcs(np.array([s["r9_max"]]), s)
    assert ratio == pytest.approx(hi[0] / lo[0] * 1.05 / 0.95, rel=1e-9)
    assert current_limiter.design({"i_no_trip": 1.0, "i_must_trip": ratio * 1.02}).r7 > 0
