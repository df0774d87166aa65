"""Tolerance corners and the percentage stack-up (handbook.core.tolerance) against hand-worked numbers."""
import itertools

import numpy as np
import pytest

from handbook.core.tolerance import WorstCase, corners, stack_product, symmetric


def divider(vin, r1, r2):
    return vin * r2 / (r1 + r2)


def test_divider_at_one_percent_by_hand():
    """12 V over 30k / 10k: nominal 3 V. The output is lowest with R1 high and R2 low:
    12 x 9.9k / (30.3k + 9.9k) = 118.8 / 40.2 = 2.955224 V, and highest with R1 low and R2 high:
    12 x 10.1k / (29.7k + 10.1k) = 121.2 / 39.8 = 3.045226 V; relative -3/201 and +3/199."""
    wc = corners(divider, {"vin": 12.0, "r1": 30e3, "r2": 10e3}, {"r1": (29.7e3, 30.3e3), "r2": (9.9e3, 10.1e3)})
    assert isinstance(wc, WorstCase)
    assert wc.nominal == pytest.approx(3.0, rel=1e-15)
    assert wc.low == pytest.approx(2.9552239, rel=1e-7) and wc.high == pytest.approx(3.0452261, rel=1e-7)
    assert wc.low_corner == {"r1": 30.3e3, "r2": 9.9e3} and wc.high_corner == {"r1": 29.7e3, "r2": 10.1e3}
    assert wc.rel_low == pytest.approx(-3 / 201, rel=1e-12) and wc.rel_high == pytest.approx(3 / 199, rel=1e-12)


def test_divider_with_the_supply_at_five_percent_by_hand():
    """Adding Vin 11.4..12.6 V: low 11.4 x 9.9 / 40.2 = 2.807463 V, high 12.6 x 10.1 / 39.8 = 3.197487 V."""
    spread = {"vin": (11.4, 12.6), "r1": (29.7e3, 30.3e3), "r2": (9.9e3, 10.1e3)}
    wc = corners(divider, {"vin": 12.0, "r1": 30e3, "r2": 10e3}, spread)
    assert wc.low == pytest.approx(2.8074627, rel=1e-7) and wc.high == pytest.approx(3.1974874, rel=1e-7)
    assert wc.low_corner == {"vin": 11.4, "r1": 30.3e3, "r2": 9.9e3}
    assert wc.high_corner == {"vin": 12.6, "r1": 29.7e3, "r2": 10.1e3}


def test_equal_resistors_give_half_plus_minus_half_a_percent():
    """10k / 10k at 1 %: 9.9 / (10.1 + 9.9) = 0.495 and 10.1 / (9.9 + 10.1) = 0.505."""
    wc = corners(divider, {"vin": 1.0, "r1": 10e3, "r2": 10e3}, {"r1": symmetric(10e3, 0.01), "r2": symmetric(10e3, 0.01)})
    assert (wc.low, wc.nominal, wc.high) == pytest.approx((0.495, 0.5, 0.505), rel=1e-12)


@pytest.mark.parametrize("k", [0, 1, 2, 3, 5])
def test_every_one_of_the_2_to_the_k_corners_is_evaluated_once(k):
    names = [f"x{i}" for i in range(k)]
    nominal = {n: 1.0 for n in names} | {"fixed": 7.0}
    spread = {n: (0.5 + i, 2.0 + i) for i, n in enumerate(names)}
    seen = []

    def f(fixed, **xs):
        seen.append((np.array(fixed, dtype=float, ndmin=1), {n: np.array(v, dtype=float, ndmin=1) for n, v in xs.items()}))
        return fixed + sum(xs.values())

    wc = corners(f, nominal, spread)
    assert len(seen) == 2  # once at the nominal point, once vectorised over the corners
    fixed, xs = seen[1]
    assert len(fixed) == 2**k and np.all(fixed == 7.0)  # an input not in the spread stays nominal
    points = set(zip(*(xs[n] for n in names))) if k else {()}
    assert len(points) == 2**k and points == set(itertools.product(*(spread[n] for n in names)))
    # the sum is lowest with every input low and highest with every input high
    assert wc.low == pytest.approx(7.0 + sum(0.5 + i for i in range(k)))
    assert wc.high == pytest.approx(7.0 + sum(2.0 + i for i in range(k)))
    assert wc.nominal == pytest.approx(7.0 + k)


def test_no_spread_leaves_the_nominal():
    wc = corners(divider, {"vin": 12.0, "r1": 30e3, "r2": 10e3}, {})
    assert (wc.low, wc.nominal, wc.high) == pytest.approx((3.0, 3.0, 3.0))
    assert wc.low_corner == {} and wc.high_corner == {}


def test_monotone_function_extremes_match_a_dense_grid():
    """a - b + c d with positive c, d: monotone in each input, so the extremes over the box (found here on an
    11-point grid per input, ends included) are at vertices: high = a_hi - b_lo + c_hi d_hi."""
    f = lambda a, b, c, d: a - b + c * d
    spread = {"a": (1.0, 2.0), "b": (0.5, 3.0), "c": (0.2, 0.4), "d": (4.0, 9.0)}
    wc = corners(f, {"a": 1.5, "b": 1.0, "c": 0.3, "d": 5.0}, spread)
    grid = np.meshgrid(*(np.linspace(*spread[n], 11) for n in "abcd"), indexing="ij")
    vals = f(*grid)
    assert wc.high == pytest.approx(vals.max(), rel=1e-12) and wc.low == pytest.approx(vals.min(), rel=1e-12)
    assert wc.high == pytest.approx(2.0 - 0.5 + 0.4 * 9.0) and wc.low == pytest.approx(1.0 - 3.0 + 0.2 * 4.0)
    assert wc.high_corner == {"a": 2.0, "b": 0.5, "c": 0.4, "d": 9.0}
    assert wc.low_corner == {"a": 1.0, "b": 3.0, "c": 0.2, "d": 4.0}
    assert wc.nominal == pytest.approx(1.5 - 1.0 + 1.5)


def test_a_non_monotone_function_is_only_searched_at_the_corners():
    """-(x - 1)^2 over 0..2 peaks at 0 inside the range; both corners give -1, as the docstring warns."""
    wc = corners(lambda x: -(x - 1.0) ** 2, {"x": 1.0}, {"x": (0.0, 2.0)})
    assert (wc.low, wc.high, wc.nominal) == (-1.0, -1.0, 0.0)


def test_a_spread_given_high_first_still_finds_both_ends():
    wc = corners(lambda x, y: x * y, {"x": 2.0, "y": 3.0}, {"x": (2.2, 1.8), "y": (3.3, 2.7)})
    assert wc.low == pytest.approx(1.8 * 2.7) and wc.high == pytest.approx(2.2 * 3.3)


def test_symmetric():
    assert symmetric(10e3, 0.01) == pytest.approx((9900.0, 10100.0), rel=1e-15)
    assert symmetric(8.2, 0.05) == pytest.approx((7.79, 8.61), rel=1e-14)
    assert symmetric(5.0, 0.0) == (5.0, 5.0)


def test_stack_product_by_hand():
    # 1 % and 2 %: 0.99 x 0.98 = 0.9702 and 1.01 x 1.02 = 1.0302
    assert stack_product([0.01, 0.02]) == pytest.approx((-0.0298, 0.0302), rel=1e-12)
    # three 5 % parts: 0.95^3 = 0.857375 and 1.05^3 = 1.157625
    assert stack_product(t for t in (0.05, 0.05, 0.05)) == pytest.approx((-0.142625, 0.157625), rel=1e-12)
    assert stack_product([]) == (0.0, 0.0)
    low, high = stack_product([0.1])
    assert (low, high) == pytest.approx((-0.1, 0.1)) and isinstance(low, float) and isinstance(high, float)


def test_stack_product_is_the_corner_extreme_of_a_product_of_factors():
    """A product of independent factors (1 +- t_i) is monotone in each: its corners give the stack-up."""
    tols = (0.01, 0.02, 0.05)
    spread = {f"k{i}": (1 - t, 1 + t) for i, t in enumerate(tols)}
    wc = corners(lambda k0, k1, k2: k0 * k1 * k2, {n: 1.0 for n in spread}, spread)
    assert (wc.rel_low, wc.rel_high) == pytest.approx((0.99 * 0.98 * 0.95 - 1, 1.01 * 1.02 * 1.05 - 1), rel=1e-12)
    assert stack_product(tols) == pytest.approx((wc.rel_low, wc.rel_high), rel=1e-12)
