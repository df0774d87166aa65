"""The branch and bound over series values (handbook.design.branch_bound) on toy problems with a known optimum.

The toy: maximise -sum w_i (x_i - c_i)^2 subject to sum x_i <= S (-inf where infeasible), each x_i taken from
a sorted list of positive values. Exhaustive enumeration (numpy over itertools.product) is the oracle. Two
relaxations, both valid upper bounds over a box lb <= x <= ub:

* ``clip``: the coupling constraint dropped; the separable concave maximum is at x = clip(c, lb, ub);
* ``dual``: the constraint kept, solved through its Lagrange multiplier (bisection); the bound returned is the
  dual function at the multiplier found, an upper bound by weak duality whatever the bisection's accuracy.

Both return None when even the box's lowest corner breaks the constraint (the box holds no feasible point).
"""
import itertools

import numpy as np
import pytest

from handbook.design.branch_bound import search

UNLIMITED = dict(max_nodes=10**6, max_nodes_unsolved=10**6)


class Toy:
    """One instance, with its relaxations and a log of every call the search makes."""

    def __init__(self, values, c, w, s_max):
        self.values = [np.asarray(v, dtype=float) for v in values]
        self.c, self.w, self.s_max = np.asarray(c, dtype=float), np.asarray(w, dtype=float), float(s_max)
        self.calls = []  # (lb, ub, state) of every relax call
        self.evaluated = []  # every array of choices handed to evaluate

    def f(self, x):
        return -(((np.asarray(x) - self.c) ** 2) * self.w).sum(axis=-1)

    def evaluate(self, choices):
        self.evaluated.append(np.array(choices))
        return np.where(choices.sum(axis=1) <= self.s_max, self.f(choices), -np.inf)

    def clip(self, lb, ub, state):
        self.calls.append((lb.copy(), ub.copy(), state))
        if lb.sum() > self.s_max:
            return None
        x = np.clip(self.c, lb, ub)
        return float(self.f(x)), x, len(self.calls)

    def dual(self, lb, ub, state):
        self.calls.append((lb.copy(), ub.copy(), state))
        if lb.sum() > self.s_max:
            return None
        x_of = lambda lam: np.clip(self.c - lam / (2 * self.w), lb, ub)  # the box maximiser of the Lagrangian
        if x_of(0.0).sum() <= self.s_max:
            x = x_of(0.0)
            return float(self.f(x)), x, len(self.calls)
        lo, hi = 0.0, 1.0
        while x_of(hi).sum() > self.s_max:
            hi *= 2
        for _ in range(100):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if x_of(mid).sum() > self.s_max else (lo, mid)
        x = x_of(hi)
        dual = float(self.f(x) - hi * (x.sum() - self.s_max))  # >= the constrained maximum for any multiplier >= 0
        return dual, x, len(self.calls)

    def cheap(self, lb, ub):
        return float(self.f(np.clip(self.c, lb, ub)))

    def enumerate(self):
        """The oracle: every choice scored, the best returned with its score."""
        grid = np.array(list(itertools.product(*self.values)))
        scores = np.where(grid.sum(axis=1) <= self.s_max, self.f(grid), -np.inf)
        j = int(np.argmax(scores))
        return float(scores[j]), tuple(float(v) for v in grid[j]), int(np.sum(scores == scores[j]))


def random_toy(seed: int, n: int = 40) -> Toy:
    """Three E24-like lists of n values (about 1.6 decades each), centres well inside, the constraint binding."""
    rng = np.random.default_rng(seed)
    values = [np.round(rng.uniform(1, 3) * 10 ** (np.arange(n) / 24), 6) for _ in range(3)]
    c = [rng.uniform(v[3], v[-4]) for v in values]
    return Toy(values, c, rng.uniform(0.5, 2, 3), 0.8 * sum(c))


def hand_toy() -> Toy:
    """Two variables from (1, 2, 3, 4), c = (2.5, 2.3), x1 + x2 <= 3.8. The feasible pairs, by hand:
    (1, 1): -(1.5^2 + 1.3^2) = -3.94; (1, 2): -(1.5^2 + 0.3^2) = -2.34; (2, 1): -(0.5^2 + 1.3^2) = -1.94."""
    return Toy([[1, 2, 3, 4]] * 2, [2.5, 2.3], [1, 1], 3.8)


def test_hand_worked_instance():
    toy = hand_toy()
    assert toy.enumerate()[:2] == (pytest.approx(-1.94), (2.0, 1.0))
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert out.choice == (2.0, 1.0) and out.score == pytest.approx(-1.94, abs=1e-12)
    assert out.proven and out.nodes == len(toy.calls) > 0


@pytest.mark.parametrize("relaxation", ["clip", "dual"])
@pytest.mark.parametrize("seed", range(4))
def test_equals_enumeration_with_relaxations(seed, relaxation):
    toy = random_toy(seed)
    best, choice, ties = toy.enumerate()
    assert ties == 1 and np.isfinite(best)  # a unique optimum, so the choice itself can be compared
    out = search(toy.values, getattr(toy, relaxation), toy.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert out.choice == choice and out.score == best
    assert out.proven and out.bound >= out.score and out.bound - out.score <= 1e-9
    assert out.nodes == len(toy.calls) > 0 and len(out.relaxations) <= out.nodes
    assert out.relaxations[0] >= best - 1e-9  # the root's bound holds for every choice
    assert out.nodes < 40**3  # the relaxations pruned: far fewer nodes than choices


@pytest.mark.parametrize("seed", range(3))
def test_tighter_relaxation_needs_fewer_nodes(seed):
    loose, tight = random_toy(seed), random_toy(seed)
    a = search(loose.values, loose.clip, loose.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    b = search(tight.values, tight.dual, tight.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert a.choice == b.choice == loose.enumerate()[1]
    assert 0 < b.nodes < a.nodes


@pytest.mark.parametrize("seed", range(3))
def test_a_huge_leaf_size_enumerates_the_whole_problem(seed):
    toy = random_toy(seed)
    best, choice, _ = toy.enumerate()
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=10**9, **UNLIMITED)
    assert (out.choice, out.score) == (choice, best)
    assert toy.calls == [] and out.nodes == 0 and out.leaves == 1 and out.proven
    assert len(toy.evaluated) == 1 and len(toy.evaluated[0]) == 40**3


def test_a_leaf_size_just_below_the_whole_relaxes_the_root_only():
    toy = random_toy(0, n=10)
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=999, **UNLIMITED)
    assert out.choice == toy.enumerate()[1]
    # 1000 choices > 999: the root is relaxed; its two children hold fewer than 999 and are enumerated whole
    assert out.nodes == 1 and len(toy.calls) == 1 and 1 <= out.leaves <= 2


def test_the_root_gets_no_state_and_children_their_parents():
    toy = random_toy(1)
    search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert len(toy.calls) > 2 and toy.calls[0][2] is None
    for lb, ub, state in toy.calls[1:]:
        assert state is not None
        p_lb, p_ub, _ = toy.calls[state - 1]  # the state is the 1-based number of the call that returned it
        assert np.all(p_lb <= lb) and np.all(ub <= p_ub) and (np.any(p_lb < lb) or np.any(ub < p_ub))


def test_scan_tries_the_whole_range_of_its_variable():
    toy, plain = random_toy(2), random_toy(2)
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, scan=0, leaf_size=1, **UNLIMITED)
    search(plain.values, plain.dual, plain.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert out.choice == toy.enumerate()[1]
    first = toy.evaluated[0]  # the root's heuristic: every value of variable 0, at most two of the others
    assert set(first[:, 0]) == set(toy.values[0])
    assert len(set(first[:, 1])) <= 2 and len(set(first[:, 2])) <= 2
    assert len(plain.evaluated[0]) <= 8 and len(set(plain.evaluated[0][:, 0])) <= 2


def test_threshold_at_the_optimum_finds_it_and_above_finds_nothing():
    toy = random_toy(3)
    best, choice, _ = toy.enumerate()
    at = search(toy.values, toy.dual, toy.evaluate, best, leaf_size=1, **UNLIMITED)
    assert (at.choice, at.score, at.proven) == (choice, best, True)
    toy = random_toy(3)
    above = search(toy.values, toy.dual, toy.evaluate, best + 1e-6, leaf_size=1, **UNLIMITED)
    assert above.choice is None and above.score == -np.inf and above.proven
    assert above.nodes == len(toy.calls) > 0


def test_an_infeasible_problem_finds_nothing():
    toy = hand_toy()
    toy.s_max = 1.9  # below the smallest sum, 1 + 1
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert out.choice is None and out.score == -np.inf and out.proven
    assert out.nodes == 1 and out.relaxations == []  # the root's relaxation reports the box empty


@pytest.mark.parametrize("seed", range(4))
def test_max_nodes_stops_with_a_valid_bound(seed):
    toy = random_toy(seed)
    best, choice, _ = toy.enumerate()
    full = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert full.nodes > 2
    toy.calls.clear()
    # the dual relaxation's maximiser is feasible, so the root's heuristic finds a choice and max_nodes applies
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, max_nodes=2, max_nodes_unsolved=10**6)
    assert not out.proven and out.nodes == 2 == len(toy.calls)
    assert out.choice is not None and toy.evaluate(np.array([out.choice]))[0] == out.score
    assert out.score <= best <= out.bound  # the open bound still covers the optimum
    assert out.bound < np.inf


def test_max_nodes_unsolved_stops_with_nothing_found_and_a_valid_bound():
    for seed in range(50):  # an instance whose root heuristic misses the optimum, with the threshold at the optimum
        toy = random_toy(seed)
        best, choice, _ = toy.enumerate()
        out = search(toy.values, toy.clip, toy.evaluate, best, leaf_size=1, max_nodes=10**6, max_nodes_unsolved=1)
        if out.choice is None:
            break
    else:
        pytest.fail("no instance whose root heuristic misses the optimum")
    assert not out.proven and out.nodes == 1 and out.score == -np.inf
    assert best <= out.bound < np.inf
    toy.calls.clear()
    unlimited = search(toy.values, toy.clip, toy.evaluate, best, leaf_size=1, **UNLIMITED)
    assert unlimited.choice == choice and unlimited.proven


def test_max_nodes_unsolved_zero_stops_before_any_relaxation():
    toy = random_toy(0)
    out = search(toy.values, toy.dual, toy.evaluate, -np.inf, leaf_size=1, max_nodes=10**6, max_nodes_unsolved=0)
    assert toy.calls == [] and out.choice is None and not out.proven and out.bound == np.inf


@pytest.mark.parametrize("seed", range(4))
def test_a_valid_cheap_bound_prunes_without_changing_the_answer(seed):
    plain, cheap = random_toy(seed), random_toy(seed)
    a = search(plain.values, plain.dual, plain.evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    b = search(cheap.values, cheap.dual, cheap.evaluate, -np.inf, leaf_size=1, cheap_bound=cheap.cheap, **UNLIMITED)
    assert a.choice == b.choice == plain.enumerate()[1] and a.score == b.score
    assert b.cheap > 0 and len(cheap.calls) < len(plain.calls)
    assert b.proven and b.bound >= b.score


@pytest.mark.parametrize("gap", [0.5, 5.0])
@pytest.mark.parametrize("seed", range(4))
def test_a_gap_stops_within_it_of_the_optimum(seed, gap):
    toy = random_toy(seed)
    best, _, _ = toy.enumerate()
    out = search(toy.values, toy.clip, toy.evaluate, -np.inf, gap=gap, leaf_size=1, **UNLIMITED)
    assert out.proven and best - gap <= out.score <= best
    assert out.score <= out.bound <= out.score + gap
    assert out.bound >= best  # a proven bound is a true upper bound


@pytest.mark.parametrize("cheap", [False, True])
def test_a_proven_bound_with_a_gap_is_a_true_upper_bound(cheap):
    """The hand instance, the clip relaxation, gap 2.05. By hand: the root (bound 0 at x = c) finds no feasible
    choice around (2.5, 2.3); x1 in {3, 4} is empty (3 + 1 > 3.8); x1 in {1, 2} (bound -0.25 at x = (2, 2.3))
    finds (1, 2) at -2.34 and is split on x2; the child {1, 2} x {1, 2} (bound -0.34 at x = (2, 2), below
    -2.34 + 2.05 = -0.29) is dropped, though it holds the optimum (2, 1) at -1.94. Stopping at -2.34 is within the
    gap; but the bound reported as proven must not fall below -1.94, whether that child was settled by the
    relaxation or by the cheap bound."""
    toy = hand_toy()
    out = search(toy.values, toy.clip, toy.evaluate, -np.inf, gap=2.05, leaf_size=1, cheap_bound=toy.cheap if cheap else None,
                 **UNLIMITED)
    assert out.proven and out.choice == (1.0, 2.0) and out.score == pytest.approx(-2.34, abs=1e-12)
    assert out.cheap == (2 if cheap else 0)
    assert out.bound >= -1.94 - 1e-12


def test_a_relaxation_that_drops_a_constraint_still_gives_the_optimum():
    """One variable from (1, 2, 3, 4), maximise -(x - 1)^2 subject to x >= 3: the optimum is x = 3, score -4.
    Dropping the constraint is a valid relaxation (bound 0 >= every score, at x = 1), so the search is exact."""
    values = [np.array([1.0, 2.0, 3.0, 4.0])]
    evaluate = lambda ch: np.where(ch[:, 0] >= 3, -(ch[:, 0] - 1) ** 2, -np.inf)
    relax = lambda lb, ub, state: (-float(np.clip(1.0, lb[0], ub[0]) - 1) ** 2, np.clip([1.0], lb, ub), None)
    out = search(values, relax, evaluate, -np.inf, leaf_size=1, **UNLIMITED)
    assert (out.choice, out.score) == ((3.0,), -4.0)
