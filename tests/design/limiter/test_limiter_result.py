"""The limiter's result, its explanations and its analysis (handbook.design.limiter.result, .explain,
.analysis): a pinned resistor named, what can be met, the warnings, bad input, the Monte Carlo lot."""
import math

import pytest
from hypothesis import HealthCheck, settings

from handbook.core import InputError
from handbook.design import limiter
from handbook.design.solvers import Infeasible

from oracles import limiter_corners

SETTINGS = settings(max_examples=25, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_pinned_resistor_that_breaks_the_spec_is_named():
    with pytest.raises(Infeasible) as exc:
        limiter.design({"r12": 1e3, "r13": 100e3})
    assert "r12 = 1000 Ω (pinned)" in str(exc.value) and exc.value.achievable["pinned"] == "r12"
    assert limiter.design({"r13": 100e3}).r12 > 1e3  # freed, R12 takes another value


def test_infeasible_margin_says_what_can_be_met():
    with pytest.raises(Infeasible) as exc:
        limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.35})
    best = exc.value.achievable["min_margin_max"]
    assert 0 < best < 0.02 and f"best worst margin any network reaches is {best:.2%}" in str(exc.value)
    # the same spec with half the margin the message offers designs, and holds at every corner
    r = limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.35, "min_margin": best * 0.5, "v_drop_max": 10.0})
    lo, hi, _, _ = limiter_corners(r.r7, r.network, r.spec)
    assert lo >= 1.0 * (1 + best * 0.5) - 1e-9 and hi <= 1.35 * (1 - best * 0.5) + 1e-9
    with pytest.raises(Infeasible, match="none keeps it inside the window at all"):
        limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.25})


def test_an_unmeetable_window_says_the_narrowest_that_can_be_met_and_what_to_tighten():
    """The narrowest window is bisected on the relaxation; a series network meets it 3 % wider (the exact search,
    checked again at every corner by the oracle) and nothing 3 % narrower; halving the named tolerance buys
    margin, and it is the one that buys most."""
    with pytest.raises(Infeasible) as exc:
        limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.25})
    got = exc.value.achievable
    k, key = got["i_must_trip_min"], got["tighten"]
    assert 1.25 < k < 1.5 and f"1 .. {k:.4g} A" in str(exc.value) and f"halving {key} buys the most" in str(exc.value)
    wide = limiter.design({"i_no_trip": 1.0, "i_must_trip": k * 1.03, "v_drop_max": 10.0})
    lo, hi, _, _ = limiter_corners(wide.r7, wide.network, wide.spec)
    assert lo >= 1.02 * (1 - 1e-9) and hi <= k * 1.03 * 0.98 * (1 + 1e-9)
    with pytest.raises(Infeasible):
        limiter.design({"i_no_trip": 1.0, "i_must_trip": k * 0.97, "v_drop_max": 10.0})
    s = limiter.checked({"i_no_trip": 1.0, "i_must_trip": 1.25})
    from handbook.design.limiter.explain import TOLERANCES, best_margin
    base = best_margin(s)
    gains = {t: best_margin({**s, t: s[t] / 2}) - base for t in TOLERANCES if s[t] > 0}
    assert gains[key] == max(gains.values()) > 0


def test_warnings_name_the_ic_limit_and_the_sense_resistor_power():
    r = limiter.design({"ic": "TDA5143"})
    assert any("TDA5143" in w and "0.7 A" in w for w in r.warnings)
    assert not any("R7 dissipates" in w for w in limiter.design().warnings)
    small = limiter.design({"r7_power_rating": 2.0})  # the stall needs a 3 W part: the board takes 2 W at most
    assert any("R7 dissipates" in w and "needs a 3 W part" in w for w in small.warnings)


def test_r7_is_rated_for_the_stall_at_half_its_rating():
    """By hand at the defaults: the stall loss I_trip,max^2 R7 (1 - 5 %) is 1.25 W; at 50 % of the rating (the
    ambient 25 + 25 = 50 C is below the 70 C knee) it needs 2.5 W: the 3 W leaded class."""
    r = limiter.design()
    p = r.i_trip_max ** 2 * r.r7 * 0.95
    assert r.p_r7 == pytest.approx(p, rel=1e-12) and 1.2 < p < 1.3
    assert (r.r7_rating, r.r7_package) == (3.0, "3 W leaded film") and 0.5 * r.r7_rating >= p
    hot = limiter.design({"temp_span": 75.0, "v_drop_max": 2.0})  # 100 C: (155 - 100) / 85 of the rating is left
    assert hot.r7_rating * 0.5 * (155 - 100) / 85 >= hot.p_r7 and hot.r7_rating == 10.0  # 1.64 W needs 5.07 W


def test_the_drop_in_the_motor_path_is_held_to_v_drop_max():
    """R7 is the smallest that meets the window, so no other network drops less: a window whose R7 drops more
    than v_drop_max cannot be met, and says the drop it needs."""
    r = limiter.design()
    # the trip current is V_cs / R7, so the highest flows with R7 at its low end: the largest drop is that V_cs
    assert r.v_drop == pytest.approx(r.i_trip_max * r.r7 * 0.95, rel=1e-12) and r.v_drop <= 1.0
    with pytest.raises(Infeasible) as exc:
        limiter.design({"i_no_trip": 0.8, "i_must_trip": 1.2, "min_margin": 0.0})
    need = exc.value.achievable["v_drop_min"]
    assert need > 1.0 and f"drops {need:.3g} V" in str(exc.value) and "v_drop_max = 1 V" in str(exc.value)
    # the lever it names is the one that helps most: the exact design with it halved needs a smaller R7 than
    # with any other tolerance halved (the divider errors reach the trip multiplied by V_D1 / V_cs)
    key = exc.value.achievable["tighten"]
    assert key == "resistor_tolerance" and f"halving {key}" in str(exc.value)
    base = {"i_no_trip": 0.8, "i_must_trip": 1.2, "min_margin": 0.0, "v_drop_max": 10.0}
    halved = {k: limiter.design({**base, k: limiter.checked({})[k] / 2}).r7
              for k in ("resistor_tolerance", "r7_tolerance", "zener_tolerance", "offset")}
    assert halved[key] == min(halved.values()) < exc.value.achievable["r7"]
    allowed = limiter.design({"i_no_trip": 0.8, "i_must_trip": 1.2, "min_margin": 0.0, "v_drop_max": need * 1.001})
    assert allowed.r7 == exc.value.achievable["r7"] and allowed.v_drop == pytest.approx(need)


def test_the_supply_is_held_to_the_ic_and_feeds_the_zener():
    """16 V is the TDA5144's V_MOT maximum (AN94002's board limit): a 24 V supply cannot be met. R14 by hand at
    the defaults (10.8 to 13.2 V): D1 at its highest, 8.2 V x 1.061 + 25 K x 6.6 mV/K = 8.865 V, must still get
    its 5 mA test current plus the dividers' current through R14 at +1 %; the loss at 13.2 V with D1 at its
    lowest, 8.2 V x 0.939 - 0.165 V, and R14 at -1 %."""
    with pytest.raises(Infeasible, match="V_MOT at most 16 V") as exc:
        limiter.design({"v_supply_min": 21.6, "v_supply_max": 26.4})
    assert exc.value.achievable["v_supply_max"] == 16.0
    with pytest.raises(Infeasible, match="too close to the lowest supply"):
        limiter.design({"zener_voltage": 10.0})
    r = limiter.design()
    vz_high, vz_low = 8.2 * 1.061 + 0.165, 8.2 * 0.939 - 0.165
    largest = (10.8 - vz_high) / (5e-3 + r.divider_current) / 1.01
    assert r.r14 == 300.0 and 300.0 <= largest < 330.0  # E24: 300 is the largest at or below it
    assert r.i_zener_min == pytest.approx((10.8 - vz_high) / (300 * 1.01) - r.divider_current) and r.i_zener_min >= 5e-3
    i_max = (13.2 - vz_low) / (300 * 0.99)
    assert r.p_r14 == pytest.approx(i_max ** 2 * 297)
    # D1 at 13.2 V through R14 at 297 ohm, over its whole range (a grid, no formula of the design's): above
    # V_s / 2 = 6.6 V its V_z (13.2 - V_z) / 297 falls as V_z rises, so the most is at its lowest, 7.535 V: 143.7 mW
    grid = [vz_low + (vz_high - vz_low) * k / 1000 for k in range(1001)]
    assert r.p_zener == pytest.approx(max(v * (13.2 - v) / 297 for v in grid), rel=1e-12)
    assert r.p_zener == pytest.approx(0.1437, abs=1e-4)
    assert not r.warnings


def test_bad_limiter_input_names_the_key():
    with pytest.raises(InputError, match="current_limiter.r9_min"):
        limiter.design({"r9_min": 1e4, "r9_max": 1e3})
    with pytest.raises(InputError, match=r"r7_min = 1.05 ohm .. current_limiter.r7_max = 1.08 ohm holds no E24 value"):
        limiter.design({"r7_min": 1.05, "r7_max": 1.08})
    with pytest.raises(InputError, match="r13_min"):
        limiter.checked({"r13_min": 1055.0, "r13_max": 1065.0})
    with pytest.raises(InputError, match="min_margin"):
        limiter.design({"i_no_trip": 1.0, "i_must_trip": 1.1, "min_margin": 0.05})


def test_monte_carlo_inside_the_corners_and_the_notes_design_outside():
    r = limiter.design()
    mc = limiter.monte_carlo_trip(r.r7, r.network, r.spec, n=50_000, seed=1)
    assert mc["yield"] == 1.0 and r.i_trip_min <= mc["i_min"] and mc["i_max"] <= r.i_trip_max
    # the note's method: V_cs = 100 mV by eq 14 (R9 = 267 ohm) and R7 = 0.075 ohm
    note = limiter.monte_carlo_trip(0.075, (267.0, 5.6e3, 16e3, 5.6e3, 16e3), r.spec, n=50_000, seed=1)
    assert note["yield"] < 0.85 and note["i_min"] < 0.5 and note["i_max"] > 2.0
    assert math.isfinite(note["i_p999"])


def test_judge_holds_a_network_to_everything_a_design_must_meet():
    """The default design judged against its own spec meets it; with divider_current_max just below what its
    dividers draw (V_D1 / (R9 + R10 + R11) + V_D1 / (R12 + R13) at the highest zener voltage, by the oracle) it no
    longer does, though margins and headroom are unchanged."""
    r = limiter.design({})
    assert limiter.judge(r.r7, r.network, r.spec)["meets"]
    *_, i_div = limiter_corners(r.r7, r.network, r.spec)
    tight = limiter.checked({**r.spec, "divider_current_max": 0.99 * i_div})
    judged = limiter.judge(r.r7, r.network, tight)
    assert not judged["meets"] and judged["divider_current"] == pytest.approx(i_div, rel=1e-9)
    assert min(judged["margin_low"], judged["margin_high"]) >= tight["min_margin"]


@pytest.mark.parametrize("spec", [{}, {"i_no_trip": 0.3, "i_must_trip": 0.7, "r7_tolerance": 0.1}])
def test_r7_loss_is_the_worst_corner_of_v_squared_over_r(spec):
    """A stalled motor holds V_cs at its trip level across R7: the loss V_cs^2 / R7 is largest with the highest
    trip voltage (the oracle's corners with R7 exact) across the smallest R7, not the highest current times the
    largest R7 (the two cannot meet: the highest current is the smallest R7's)."""
    r = limiter.design(spec)
    t = r.spec["r7_tolerance"]
    _, v_hi, _, _ = limiter_corners(1.0, r.network, {**r.spec, "r7_tolerance": 0.0})  # R7 = 1 ohm exact: V_cs
    worst = max(float(v_hi) ** 2 / (r.r7 * (1 + g * t)) for g in (-1, 1))
    assert r.p_r7 == pytest.approx(worst, rel=1e-9)
    assert r.p_r7 < float(v_hi) ** 2 / r.r7 * (1 + t) / (1 - t) ** 2 * 0.99  # what the old product gave


def test_a_blamed_pin_is_one_whose_freedom_meets_the_spec():
    """The message's claim is checked by designing with the pin freed: the R7 it names is the design's."""
    with pytest.raises(Infeasible) as exc:
        limiter.design({"r12": 1e3, "r13": 100e3})
    freed = limiter.design({"r13": 100e3})
    assert f"meets it (with R7 = {freed.r7:.3g} Ω)" in str(exc.value)


def test_a_pin_whose_own_range_holds_no_series_value_is_not_freed():
    """R12 pinned to 1 kohm breaks the spec; its range (8.7 kohm, between the E48 values 8.66 k and 9.09 k) holds
    no value to free it to: the answer is still an Infeasible saying what can be met, not an input error."""
    spec = {"r12": 1e3, "r13": 100e3, "r12_min": 8700.0, "r12_max": 8700.0, "r12_series": "E48"}
    with pytest.raises(Infeasible) as exc:
        limiter.design(spec)
    assert "pinned" not in exc.value.achievable and exc.value.achievable


def test_a_search_stopped_by_its_limit_says_so(monkeypatch):
    """The evaluation limit is what stands between the search and a proof: with none left, no R7 is settled,
    and the answer says the spec is not proven unmeetable instead of claiming it; a tie-break stopped early is
    reported (best_proven False) and warned about."""
    from handbook.design.limiter import search

    monkeypatch.setattr(search, "MAX_EVALUATIONS", -1)
    with pytest.raises(Infeasible) as exc:
        limiter.design({})
    assert "not proven" in str(exc.value) and exc.value.achievable["unproven"]
    s = limiter.checked({})
    split = search.Split(s)
    monkeypatch.setattr(search, "MAX_EVALUATIONS", 10**9)
    r = limiter.design({})
    assert r.r7_proven and r.best_proven and not r.warnings[1:]  # the default: proven, one warning (R7's loss)
    monkeypatch.setattr(search, "MAX_EVALUATIONS", -1)
    stopped = search.best_network(split, r.r7, s["min_margin"], r.network)
    assert not stopped["proven"] and stopped["bound"] >= stopped["score"]
    warned = limiter.warnings({**r.summary(), "best_proven": False, "margin_bound": stopped["bound"]}, s)
    assert any("not proven the best" in w for w in warned)


def test_yield_reports_no_proof_of_the_full_box():
    """By yield the search ran on a shrunk box: its bound and its proof are that box's, so neither is reported as
    the spec's (the corners' proof lines would say what was never shown)."""
    r = limiter.design({"criterion": "yield", "r7_tolerance": 0.1})
    assert r.box_scale < 1 and r.margin_bound is None and r.r7_proven is False and r.best_proven is False
    full = limiter.design({"r7_tolerance": 0.1})
    assert full.r7_proven and full.margin_bound is not None and r.r7 < full.r7


def test_yield_with_the_sense_resistor_pinned():
    """R7 pinned at the value the yield search itself picks: a box exists where the full corners' input headroom
    holds (the box's search is asked again for the headroom the full corners lack), so it designs; its lot is
    re-judged here at the full tolerances, and its full-corner headroom is at least input_headroom."""
    from handbook.design.limiter import by_yield
    from handbook.design.limiter import model as net

    free = limiter.design({"criterion": "yield", "r7_tolerance": 0.1})
    pinned = limiter.design({"criterion": "yield", "r7_tolerance": 0.1, "r7": free.r7})
    s = limiter.checked({"criterion": "yield", "r7_tolerance": 0.1, "r7": free.r7})
    network = (pinned.r9, pinned.r10, pinned.r11, pinned.r12, pinned.r13)
    assert pinned.r7 == free.r7 and float(net.verify(pinned.r7, network, s)["headroom_min"]) >= s["input_headroom"] - 1e-9
    y = by_yield.lot_yield(pinned.r7, network, s, n=200_000, seed=5)
    assert by_yield.meets(y, 200_000, s["yield_min"])
