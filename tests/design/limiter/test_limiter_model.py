"""The limiter network at every tolerance corner (handbook.design.limiter.model): the corner proof, the
corners against the oracle's 2^10, the issue's counter-example, the default design at every corner."""

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

from handbook.design import limiter
from handbook.design.limiter import model as net
from handbook.design.schema import defaults
from handbook.design.solvers import Infeasible

from oracles import limiter_corners

SETTINGS = settings(max_examples=25, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_corner_proof_every_quantity_is_linear_fractional():
    proof = net.corner_proof()
    assert len(proof) == 28  # V_cs and I_trip in 9 and 10 quantities, the headrooms in 4 and 5
    assert all(num <= 1 and den <= 1 and positive for num, den, positive in proof.values())


def test_corners_equal_the_oracles_2_to_the_10_corners():
    rng = np.random.default_rng(3)
    network = tuple(10 ** rng.uniform(2, 5, 500) for _ in range(5))  # any divider, V_cs of either sign
    for extra in ({"offset": 0.1, "input_bias": 2e-6, "input_offset_current": 0.5e-6},
                  {"input_bias": 1e-6, "input_offset_current": 5e-6, "zener_tc": 0.0}):  # I_os above 2 I_b: currents of
        # either sign at once
        s = {**defaults("current_limiter"), **extra}
        v = net.verify(0.47, network, s)
        lo, hi, head, i_div = limiter_corners(0.47, network, s)
        np.testing.assert_allclose(v["i_trip_min"], lo, rtol=1e-10, atol=1e-13)
        np.testing.assert_allclose(v["i_trip_max"], hi, rtol=1e-10, atol=1e-13)
        np.testing.assert_allclose(v["headroom_min"], head, rtol=1e-10, atol=1e-13)
        np.testing.assert_allclose(v["divider_current"], i_div, rtol=1e-10)


def test_the_issues_counter_example_is_fixed():
    # the old closed form claimed 1.7993 A for R7 = 5.1 ohm; every corner (no bias, no drift, no margin) gives
    # 1.8002 A; R7 = 5.6 ohm is the smallest E24 value that holds
    spec = dict(r10=160e3, r11=130.0, r12=110e3, r13=2200.0, input_bias=0.0, input_offset_current=0.0, zener_tc=0.0,
                min_margin=0.0,
                zener_tolerance=0.05)
    s = {**defaults("current_limiter"), **spec}
    _, hi, _, _ = limiter_corners(5.1, (10.0, 160e3, 130.0, 110e3, 2200.0), s)
    assert hi == pytest.approx(1.8002, abs=1e-4)
    r = limiter.design(spec, board=False)
    assert r.r7 == 5.6 and (r.r10, r.r11, r.r12, r.r13) == (160e3, 130.0, 110e3, 2200.0)
    lo, hi, _, _ = limiter_corners(r.r7, r.network, s)
    assert 0.9 <= lo and hi <= 1.8


def test_default_design_against_every_corner():
    r = limiter.design()
    s = r.spec
    lo, hi, head, i_div = limiter_corners(r.r7, r.network, s)
    assert (r.i_trip_min, r.i_trip_max, r.headroom_min, r.divider_current) == pytest.approx((lo, hi, head, i_div), rel=1e-12)
    assert lo >= 0.9 * 1.02 - 1e-12 and hi <= 1.8 * 0.98 + 1e-12 and head >= 2.0 and i_div <= 1e-3
    assert r.margin_low == pytest.approx(lo / 0.9 - 1) and r.margin_high == pytest.approx(1 - hi / 1.8)
    # stalled, the limiter holds the motor at up to i_trip_max, which flows in the smallest R7 (0.43 ohm x 0.95):
    # 1.75 A^2 x 0.41 ohm = 1.26 W, above the PR01's 1 W: the design picks a part that carries it at 50 %
    assert r.p_r7 == pytest.approx(hi ** 2 * r.r7 * 0.95) and r.p_r7 > 1.0
    assert r.r7_rating == 3.0 and not r.warnings
    # the note's network fails the LM358's input range at its worst corner: (8.2 V x 0.939 - 0.165 V drift)
    # x 5.6/21.6 less the resistors' tolerance and the bias current is about 1.92 V, below 2 V
    _, _, head_note, _ = limiter_corners(0.43, (r.r9, 5.6e3, 16e3, 5.6e3, 16e3), s)
    assert 1.9 < head_note < 2.0
    with pytest.raises(Infeasible, match="2 V below the supply"):
        limiter.design({"r10": 5.6e3, "r11": 16e3, "r12": 5.6e3, "r13": 16e3})
