"""The limiter design (handbook.design.limiter) against an exact reference over the full series.

tests/exact_limiter.py is a branch and bound written from the node equations again, sharing no code with the
design; its bounds hold for every network of a box and are exact on one network (its docstring has the proofs),
so it returns the true smallest R7 and the true best worst margin with it. Here it is first held against
tests/oracles.py:enumerate_limiter (every network at every corner) on reduced series, then the design against it
on 64 wide specifications drawn with a fixed seed from tests/limiter_specs.py:wide_spec (the benchmark's
generator) with R9..R13 on E96 or E192 (R7 on E24 or E96; 16 of them with one resistor pinned): 33 have a
solution, 31 have no network at all; none is skipped. On each, the design finds the same smallest R7 (or, like
the reference, nothing), a worst margin within limiter.GAP of the reference's best and not above it, and a bound
on the best margin that the reference's best does not exceed; the networks of both hold at every corner of the
oracle. The whole file takes about 20 s on one core (the design about two thirds of it).
"""
import numpy as np
import pytest
from exact_limiter import exact_limiter
from limiter_specs import reduced_spec, wide_spec

from handbook.design import limiter
from handbook.design.schema import defaults
from handbook.design.solvers import Infeasible

from oracles import enumerate_limiter, limiter_corners

SEED, WIDE_SPECS = 18, 64


def _biased_spec(rng):
    """Bias currents up to 10 uA and R11, R13 (E6) over three decades up to where I R = 2 V_D1: the bias drop
    exceeds the zener voltage inside the ranges, so the figures' monotone directions change there."""
    i_no = float(10 ** rng.uniform(-1, 0.5))
    spec = dict(i_no_trip=i_no, i_must_trip=i_no * float(rng.uniform(1.5, 4)), min_margin=float(rng.choice([0.0, 0.02])),
                resistor_tolerance=float(rng.choice([0.001, 0.01])), r7_tolerance=0.01, zener_voltage=float(rng.uniform(4, 8)),
                zener_tolerance=0.02, zener_tc=0.0, temp_span=25.0, offset=float(rng.uniform(0, 0.005)),
                input_bias=float(10 ** rng.uniform(-5.5, -5)), input_offset_current=float(10 ** rng.uniform(-7, -5)),
                divider_current_max=0.1, input_headroom=float(rng.uniform(0.2, 1.0)), r7_series="E12", r7_min=0.01,
                r7_max=100.0)
    top = 2 * spec["zener_voltage"] / (spec["input_bias"] + spec["input_offset_current"] / 2)
    for n in ("r9", "r10", "r12"):
        low = float(10 ** rng.uniform(1, 3))
        spec.update({f"{n}_series": "E6", f"{n}_min": low, f"{n}_max": low * 10})
    for n in ("r11", "r13"):
        spec.update({f"{n}_series": "E6", f"{n}_min": top / 1000, f"{n}_max": top})
    return spec


def _reduced_cases():
    rng = np.random.default_rng(2026)
    cases = {f"reduced-{k}": reduced_spec(rng) for k in range(8)}
    rng = np.random.default_rng(6)
    cases.update({f"biased-{k}": _biased_spec(rng) for k in range(4)})
    base = reduced_spec(np.random.default_rng(7))
    cases["no-bias-no-offset-current"] = {**base, "input_bias": 0.0, "input_offset_current": 0.0, "min_margin": 0.0}
    cases["margin-5-percent"] = {**base, "min_margin": 0.05, "input_bias": 500e-9, "input_offset_current": 150e-9}
    cases["no-solution"] = {**base, "i_must_trip": base["i_no_trip"] * 1.1, "min_margin": 0.02}
    cases["reference-pinned"] = {"r9": 105.0, "r10": 5620.0, "r11": 11300.0}  # E96 level shift over two decades
    cases["r7-pinned"] = {**base, "r7": 1.2, "r12": 12000.0}
    return cases


REDUCED = _reduced_cases()
_rng = np.random.default_rng(SEED)
WIDE = [wide_spec(_rng, divider_series=("E96", "E192")) for _ in range(WIDE_SPECS)]
ISSUE_18 = dict(i_no_trip=1.5375553447469856, i_must_trip=3.759833528645647, min_margin=0.05, resistor_tolerance=0.005,
                r7_tolerance=0.02, zener_voltage=20.454639911244172, zener_tolerance=0.02, zener_tc=0.01899320811016074,
                temp_span=59.00419989365312, offset=0.032682535995104574, input_bias=5e-06, input_offset_current=5e-06,
                divider_current_max=0.0009831299364458264, input_headroom=0.8931756024241944, r7_series="E96",
                r7_min=0.6950642965952302, r7_max=3.4921242780091024, r12=8660.0,
                **{f"r{n}_series": "E48" for n in (9, 10, 11, 12, 13)})
_FEASIBLE = {}  # wide spec index -> whether the reference found a network (for the count below)


def _holds_at_every_corner(r7, network, spec, worst=None):
    """The oracle's every corner: the network meets the spec with R7 (and its worst margin is ``worst``)."""
    s = {**defaults("current_limiter"), **spec}
    lo, hi, head, i_div = limiter_corners(r7, network, s)
    assert lo >= s["i_no_trip"] * (1 + s["min_margin"]) * (1 - 1e-9)
    assert hi <= s["i_must_trip"] * (1 - s["min_margin"]) * (1 + 1e-9)
    assert head >= s["input_headroom"] - 1e-9 and i_div <= s["divider_current_max"] * (1 + 1e-9)
    if worst is not None:
        assert min(lo / s["i_no_trip"] - 1, 1 - hi / s["i_must_trip"]) == pytest.approx(worst, abs=1e-9)


def _against_the_reference(spec):
    """The design's smallest R7, its worst margin and its bound against the exact reference's; the
    reference's network held at every corner. Returns whether the spec is feasible."""
    expected = exact_limiter(spec)
    if expected is not None:
        _holds_at_every_corner(expected[0], expected[1], spec, expected[2])
    try:
        got = limiter.design(spec, board=False)
    except Infeasible:
        assert expected is None
        return False
    assert expected is not None, f"the design finds R7 = {got.r7} where the reference finds nothing"
    assert got.r7 == expected[0]
    worst = min(got.margin_low, got.margin_high)
    assert expected[2] - limiter.GAP - 1e-9 <= worst <= expected[2] + 1e-9
    assert got.margin_bound >= expected[2] - 1e-9
    _holds_at_every_corner(got.r7, got.network, spec)
    return True


@pytest.mark.parametrize("name", list(REDUCED))
def test_the_reference_equals_enumeration_on_reduced_series(name):
    """The reference's own check: the same smallest R7 (or nothing) and the same best worst margin as
    exhaustive enumeration, on reduced-series specs with pinned resistors, zero and nonzero bias and offset
    currents, bias drops above the zener voltage, min_margin 0 and > 0, a spec with no solution and a pinned
    R7; and its network holds at every corner of the oracle."""
    spec = REDUCED[name]
    expected, got = enumerate_limiter(spec), exact_limiter(spec)
    if expected is None:
        assert got is None
        return
    assert got is not None and got[0] == expected[0] and got[2] == pytest.approx(expected[2], abs=1e-9)
    _holds_at_every_corner(got[0], got[1], spec, got[2])


def test_the_reduced_cases_cover_both_answers():
    """The cases above include specs with and without a solution (enumeration's answers for two of them)."""
    answers = [enumerate_limiter(REDUCED[n]) is None for n in ("no-solution", "reference-pinned")]
    assert answers == [True, False]


def test_issue_18s_spec_against_the_reference():
    """Issue 18's spec (E48, R12 pinned at 8.66 kOhm): the reference finds R7 = 0.698 ohm and a best network
    at 26.89 %; the design finds the same R7 and a network within GAP of it."""
    expected = exact_limiter(ISSUE_18)
    assert expected[0] == 0.698 and expected[2] == pytest.approx(0.26891, abs=1e-5)
    assert _against_the_reference(ISSUE_18)


@pytest.mark.parametrize("index", range(WIDE_SPECS))
def test_the_design_equals_the_reference_on_wide_specs(index):
    """Wide E96/E192 specs (docstring of the module): the same smallest R7, the margin within GAP and below
    the best, the bound above it."""
    _FEASIBLE[index] = _against_the_reference(WIDE[index])


def test_the_wide_specs_hold_at_least_20_feasible_ones():
    """Enough of the wide specs have a solution for the comparison to mean something (counted by the test
    above; skipped when that did not run in full in this process)."""
    if len(_FEASIBLE) < WIDE_SPECS:
        pytest.skip("the wide specs were not all compared in this process")
    assert sum(_FEASIBLE.values()) >= 20
