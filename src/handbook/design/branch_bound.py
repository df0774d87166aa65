"""Branch and bound over series values, with a continuous relaxation solved by IPOPT at every node.

Each variable takes one value of a sorted list (an E-series within its range, or one pinned value). A node
is a sub-range of every list; its relaxation lets each variable take any value between the node's first
and last entry. The relaxation's optimum bounds every series choice inside the node from above; a node
whose bound cannot beat the best choice found (or cannot reach ``threshold``) is dropped, any other is
split between the two series values around the relaxed optimum of its least settled variable. At every
node the series choices around the relaxed optimum are evaluated exactly (vectorised), which finds good
choices early. Best-first; the search is exact up to ``gap`` as long as each relaxation is solved to its
global optimum (the tests compare the result with exhaustive enumeration).
"""
from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Outcome:
    score: float  # the best exact score found (-inf: nothing reached the threshold)
    choice: tuple | None  # its values, one per variable
    nodes: int
    bound: float  # the best bound among the nodes left open when the search stopped (score when proven)
    proven: bool  # True unless the node limit stopped the search
    leaves: int = 0  # nodes small enough to evaluate whole
    cheap: int = 0  # nodes settled by the cheap bound
    relaxations: list = field(default_factory=list)


def _around(vals: np.ndarray, lo: int, hi: int, x: float) -> list[int]:
    """Indices (within lo..hi) of the series values just below and above x."""
    j = int(np.searchsorted(vals, x * (1 - 1e-12), side="right")) - 1
    return sorted({min(max(j, lo), hi), min(max(j + 1, lo), hi)})


def _take(best: Outcome, values, pools, evaluate, threshold: float) -> None:
    """Evaluate every choice of the pools (index lists) exactly; keep the best if it beats ``best``."""
    idx = np.array(list(itertools.product(*pools)))
    choices = np.stack([values[i][idx[:, i]] for i in range(len(values))], axis=1)
    scores = evaluate(choices)
    j = int(np.argmax(scores))
    if scores[j] > best.score and scores[j] >= threshold:
        best.score, best.choice = float(scores[j]), tuple(float(v) for v in choices[j])


def search(values: list[np.ndarray], relax, evaluate, threshold: float, gap: float = 1e-9,
           scan: int | None = None, max_nodes: int = 150, max_nodes_unsolved: int = 3000,
           leaf_size: int = 2000, cheap_bound=None) -> Outcome:
    """Maximise ``evaluate`` over series choices.

    ``relax(lb, ub, state)`` -> (bound, x, state) for the box lb <= x <= ub (values, not indices), or None
    when the box holds no feasible point; ``state`` is the parent's (None at the root), for a warm start.
    ``evaluate(choices)`` -> exact scores of an (n, k) array of choices
    (-inf where infeasible). ``scan``: a variable whose whole node range is tried in each heuristic
    (a cheap exact line search, e.g. the one resistor that centres the window). ``max_nodes`` stops the
    search once a choice reaching ``threshold`` is known (the outcome then carries the best open bound, so
    the gap left is known); ``max_nodes_unsolved`` stops it when none is known yet (``proven`` False).
    A node holding at most ``leaf_size`` choices is evaluated whole instead (exact, and cheaper than one
    relaxation: about 10 ms of IPOPT against a few thousand exact evaluations). ``cheap_bound(lb, ub)``,
    if given, is a valid upper bound tried before the relaxation (a node it settles costs no IPOPT call).

    Parameters
    ----------
    values : list of numpy.ndarray
        One sorted array per variable: the values it may take (an E-series within its range, or one pinned
        value), in the variable's own unit (ohm for the limiter's resistors).
    relax : callable
        ``relax(lb, ub, state)`` -> (bound, x, state), or None when the box holds no feasible point: ``lb`` and
        ``ub`` are arrays of k values (not indices), ``bound`` an upper bound of the score over the box, ``x`` the
        relaxed optimum (k values), ``state`` whatever warm-starts the children (None at the root).
    evaluate : callable
        ``evaluate(choices)`` -> array of n exact scores for an (n, k) array of choices (-inf where infeasible).
    threshold : float
        The least score a choice must reach to count (in the score's unit); nodes whose bound is below it are
        dropped.
    gap : float
        A node is explored only if its bound beats the best score found by more than this (score's unit).
    scan : int or None
        The index of a variable whose whole node range is tried in each heuristic, or None.
    max_nodes : int
        Relaxations after which the search stops once a choice reaching ``threshold`` is known.
    max_nodes_unsolved : int
        Relaxations after which the search stops while none is known (``proven`` is then False).
    leaf_size : int
        A node holding at most this many choices is evaluated whole instead of relaxed.
    cheap_bound : callable or None
        ``cheap_bound(lb, ub)`` -> a valid upper bound (float) of the score over the box, tried before
        ``relax``; None: none.

    Returns
    -------
    Outcome
        ``score`` (the best exact score, -inf when nothing reached ``threshold``), ``choice`` (its k values, or
        None), ``nodes`` (relaxations solved), ``bound`` (the best bound left open when the search stopped; the
        score, or the largest bound dropped within ``gap``, when proven), ``proven`` (False when a node limit
        stopped it), ``leaves`` and ``cheap`` (nodes settled whole and by ``cheap_bound``) and ``relaxations``
        (every relaxation's bound, in the order solved).
    """
    k = len(values)
    best = Outcome(-np.inf, None, 0, np.inf, True)
    counter = itertools.count()
    root = (tuple(0 for _ in range(k)), tuple(len(v) - 1 for v in values))
    heap = [(-np.inf, next(counter), root, None)]
    pruned = -np.inf  # the largest bound of a node dropped only because it could not beat the best by gap
    while heap:
        neg_parent, _, (lo, hi), x0 = heapq.heappop(heap)
        if -neg_parent < max(threshold, best.score + gap):
            pruned = max(pruned, -neg_parent) if -neg_parent >= threshold else pruned
            continue
        if best.nodes >= (max_nodes if best.choice is not None else max_nodes_unsolved):
            best.proven, best.bound = False, -neg_parent
            break
        if np.prod([hi[i] - lo[i] + 1 for i in range(k)], dtype=float) <= leaf_size:
            _take(best, values, [range(lo[i], hi[i] + 1) for i in range(k)], evaluate, threshold)
            best.leaves += 1
            continue
        lb = np.array([values[i][lo[i]] for i in range(k)])
        ub = np.array([values[i][hi[i]] for i in range(k)])
        if cheap_bound is not None:
            cheap = cheap_bound(lb, ub)
            if cheap < max(threshold, best.score + gap):  # dropped for its bound: the bound still counts
                pruned = max(pruned, min(cheap, -neg_parent)) if cheap >= threshold else pruned
                best.cheap += 1
                continue
        best.nodes += 1
        res = relax(lb, ub, x0)
        if res is None:
            continue
        bound, x, state = res
        best.relaxations.append(bound)
        if bound < max(threshold, best.score + gap):
            pruned = max(pruned, bound) if bound >= threshold else pruned
            continue
        _take(best, values, [range(lo[i], hi[i] + 1) if i == scan else _around(values[i], lo[i], hi[i], x[i])
                             for i in range(k)], evaluate, threshold)
        # branch on the variable whose relaxed value lies deepest between two series values (log scale)
        depth = []
        for i in range(k):
            a = _around(values[i], lo[i], hi[i], x[i])
            if len(a) < 2 or hi[i] == lo[i]:
                depth.append(-1.0)
                continue
            va, vb = values[i][a[0]], values[i][a[1]]
            depth.append(min(np.log(x[i] / va), np.log(vb / x[i])) / np.log(vb / va) if va <= x[i] <= vb else 0.5)
        i = int(np.argmax(depth))
        if depth[i] <= 1e-9 and bound <= best.score + gap:  # the relaxed optimum is a series choice: settled
            continue
        if depth[i] < 0:  # every relaxed value sits on a node's end, yet the bound is not reached there: halve
            i = int(np.argmax([hi[j] - lo[j] for j in range(k)]))  # the widest range (no other split helps)
            if hi[i] == lo[i]:
                continue
            split = (lo[i] + hi[i]) // 2
        else:
            split = _around(values[i], lo[i], hi[i], x[i])[0]
        if split == hi[i]:
            split -= 1
        for child in ((lo, hi[:i] + (split,) + hi[i + 1:]), (lo[:i] + (split + 1,) + lo[i + 1:], hi)):
            heapq.heappush(heap, (-bound, next(counter), child, state))
    if best.proven:  # every node left was dropped for its bound: none beats the best by more than gap
        best.bound = max(best.score, pruned)
    return best
