"""The search for the smallest series R7 and, with it, the divider network of the largest worst margin.

R7 comes first: IPOPT minimises ln R7 over the continuous relaxation of all six resistors, a lower bound for
every series design. Then, for each series R7 from that bound up, a branch and bound
(:mod:`handbook.design.branch_bound`, IPOPT on every node's relaxation) maximises the worst margin over the
five divider resistors; the first R7 whose best network reaches ``min_margin`` is the answer. With four
free divider resistors on E96 there are about 10^11 networks per R7, far too many to enumerate; on E6/E12
dividers the tests and ``tools/benchmark.py`` check that this search finds exactly what enumeration finds
(:func:`enumerate_series`).
"""
from __future__ import annotations

import functools
import itertools
import math

import casadi as ca
import numpy as np

from ...core import InputError
from .. import branch_bound
from ..solvers import IPOPT_OPTIONS
from . import model as net
from .model import RESISTORS, best_headroom, checked, choices, scores

#: the tie-break is settled to within this worst margin (0.25 percentage point): the bound proves no
#: network with the same R7 is better by more
GAP = 2.5e-3
#: a node holding at most this many networks is evaluated whole (about the cost of one IPOPT solve)
LEAF_SIZE = 2000
#: relaxations spent on one R7 with no network found yet before it is given up as unsettled (reported in
#: ``unproven``, and warned about)
MAX_NODES_UNSOLVED = 3000
#: the most divider networks :func:`enumerate_series` evaluates (a few hundred MB of numpy arrays)
ENUMERATE_MAX = 2_000_000


#: the spec values the relaxation takes as parameters (one NLP, built once per process, serves every spec)
RELAX_KEYS = ("zener_voltage", "zener_tolerance", "zener_tc", "temp_span", "input_bias", "input_offset_current",
              "offset", "resistor_tolerance", "r7_tolerance", "i_no_trip", "i_must_trip", "input_headroom",
              "divider_current_max")


@functools.cache
def _solvers():
    """(cold, warm) IPOPT instances of the relaxation, the spec's values as parameters."""
    x, w, q = ca.SX.sym("x", 7), ca.SX.sym("w"), ca.SX.sym("q", len(RELAX_KEYS) + 1)
    s = dict(zip(RELAX_KEYS, ca.vertsplit(q[:-1])))
    r7, r, t = ca.exp(x[0]), tuple(ca.exp(x[i]) for i in range(1, 6)), x[6]
    lows, highs = net.trip_voltage_corners(r, s, relaxed=True)
    g = ([net.margins(lo, 0.0, r7, s)[0] - t for lo in lows]
         + [net.margins(0.0, hi, r7, s)[1] - t for hi in highs]
         + [(v - s["input_headroom"]) / q[-1] for v in net.headroom_corners(r, s)]
         + [1 - net.divider_current(r, s) / s["divider_current_max"]])
    nlp = {"x": x, "p": ca.vertcat(w, q), "f": w * x[0] - (1 - w) * x[6], "g": ca.vertcat(*g)}
    base = {**IPOPT_OPTIONS, "ipopt.tol": 1e-9, "ipopt.mu_strategy": "adaptive"}
    # a child node starts from its parent's solution and multipliers: a handful of iterations, not 30
    warm = {**base, "ipopt.warm_start_init_point": "yes", "ipopt.mu_init": 1e-5, "ipopt.warm_start_bound_push": 1e-9,
            "ipopt.warm_start_mult_bound_push": 1e-9}
    return ca.nlpsol("limiter", "ipopt", nlp, base), ca.nlpsol("limiter_warm", "ipopt", nlp, warm)


class Relaxation:
    """The continuous problem in x = (ln R7, ln R9 .. ln R13, t), t the worst margin, for one spec; called
    with a node's bounds. Weight w = 1: minimise ln R7 (t >= min_margin); w = 0: maximise t."""

    def __init__(self, s: dict):
        # the offset current counts up to twice the bias current (beyond that the two currents are free)
        values = {**s, "input_offset_current": min(s["input_offset_current"], 2 * s["input_bias"])}
        self.q = [float(values[k]) for k in RELAX_KEYS] + [max(s["input_headroom"], 1.0)]
        self.solver, self.warm = _solvers()

    def solve(self, lb, ub, x0, weight: float, t_min: float = -10.0, warm: dict | None = None):
        """(x, status, state) of the box lb..ub (resistor values), or None when IPOPT reports it infeasible
        (a local verdict: the callers bound such a box by :func:`vertex_bound` before dropping it).

        Parameters
        ----------
        lb, ub : array of float
            The box: lowest and highest R7, R9..R13, ohm.
        x0 : array of float
            The starting point (ln R7, ln R9 .. ln R13, t).
        weight : float
            1: minimise ln R7 (t >= ``t_min``); 0: maximise the worst margin t.
        t_min : float
            The least worst margin, fraction.
        warm : dict or None
            A parent's state (its x and multipliers) for a warm start.

        Returns
        -------
        tuple or None
            (x: ln R7, ln R9 .. ln R13 and t; IPOPT's return status; the state for a child's warm start).
        """
        solver = self.solver if warm is None else self.warm
        args = dict(x0=x0, p=[weight, *self.q], lbx=[*np.log(lb), t_min], ubx=[*np.log(ub), 10.0], lbg=0, ubg=np.inf)
        if warm is not None:
            args.update(x0=np.clip(warm["x"], args["lbx"], args["ubx"]), lam_x0=warm["lam_x"], lam_g0=warm["lam_g"])
        r = solver(**args)
        status = solver.stats()["return_status"]
        if status in ("Infeasible_Problem_Detected", "Restoration_Failed"):
            return None
        return np.array(r["x"]).ravel(), status, {"x": np.array(r["x"]).ravel(), "lam_x": r["lam_x"], "lam_g": r["lam_g"]}


def _root(s: dict, relax: Relaxation, lists: list) -> float | None:
    """The relaxation's smallest R7 with every margin >= min_margin (None: no continuous network does)."""
    lb, ub = np.array([v[0] for v in lists]), np.array([v[-1] for v in lists])
    res = relax.solve(lb, ub, [*np.log(np.sqrt(lb * ub)), 0.0], 1.0, s["min_margin"])
    if res is not None and res[1] in ("Solve_Succeeded", "Solved_To_Acceptable_Level") and math.isfinite(res[0][0]):
        return math.exp(res[0][0])
    # IPOPT found no point: a local verdict, not a proof. The bound is then the smallest R7 whose exact vertex
    # bound over the whole divider box still allows the margin (None only when none does)
    ok = [r7 for r7 in lists[0] if vertex_bound(float(r7), lb[1:], ub[1:], s) >= s["min_margin"] - 1e-12]
    return float(ok[0]) if ok else None


def polish(r7: float, network: tuple, s: dict, lists: list, rounds: int = 8) -> tuple[tuple, float]:
    """Local search after the branch and bound's node budget: each divider resistor one series step either
    way, R9 ten steps, every combination evaluated exactly; repeated while it improves the worst margin.

    Parameters
    ----------
    r7 : float
        The sense resistor, ohm.
    network : tuple of float
        R9..R13 to start from, ohm (series values of ``lists``).
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).
    lists : list of array of float
        Each resistor's series values, R7 first, ohm.
    rounds : int
        At most this many improving steps.

    Returns
    -------
    tuple
        (the best network found, R9..R13 in ohm; its worst margin, fraction).
    """
    idx = [int(np.searchsorted(v, x)) for v, x in zip(lists[1:], network)]
    best = float(scores(r7, np.array([network]), s)[0])
    for _ in range(rounds):
        pools = [range(max(0, j - (10 if i == 0 else 1)), min(len(v) - 1, j + (10 if i == 0 else 1)) + 1)
                 for i, (j, v) in enumerate(zip(idx, lists[1:]))]
        grid = np.array(list(itertools.product(*pools)))
        cand = np.stack([lists[1 + i][grid[:, i]] for i in range(5)], axis=1)
        sc = scores(r7, cand, s)
        k = int(np.argmax(sc))
        if sc[k] <= best + 1e-12:
            break
        best, idx = float(sc[k]), list(grid[k])
    return tuple(float(lists[1 + i][j]) for i, j in enumerate(idx)), best


def _best_network(r7: float, s: dict, relax: Relaxation, lists: list, threshold: float, max_nodes: int = 40,
                  leaf_size: int = LEAF_SIZE, max_nodes_unsolved: int = MAX_NODES_UNSOLVED):
    """Branch and bound over R9..R13 with R7 fixed: the network with the largest worst margin."""
    def relaxed(lb, ub, state):
        # IPOPT's "infeasible" is a local verdict: a warm start that fails is repeated cold, then from the box's
        # two extreme corners, before the box is dropped
        middle = np.sqrt(lb * ub)
        starts = [(middle, state)] + [(middle, None)] * (state is not None) + [(lb, None), (ub, None)]
        for x0, warm in starts:
            res = relax.solve(np.r_[r7, lb], np.r_[r7, ub], [math.log(r7), *np.log(x0), 0.0], 0.0, warm=warm)
            if res is not None:
                break
        else:
            return None
        x, status, new_state = res
        if status not in ("Solve_Succeeded", "Solved_To_Acceptable_Level"):
            return np.inf, np.sqrt(lb * ub), None  # cannot bound this box: keep it and split it
        return float(x[6]) + 1e-9, np.exp(x[1:6]), new_state

    return branch_bound.search(lists[1:], relaxed, lambda c: scores(r7, c, s), threshold, gap=GAP, scan=0,
                               max_nodes=max_nodes, max_nodes_unsolved=max_nodes_unsolved, leaf_size=leaf_size,
                               cheap_bound=lambda lb, ub: vertex_bound(r7, lb, ub, s))


def vertex_bound(r7: float, lb, ub, s: dict) -> float:
    """An upper bound on the worst margin of every network in the box lb..ub, from its 32 vertices alone.

    For one tolerance corner (signs, zener end, offset and bias fixed) the margin is monotone in each
    resistor (the corner proof), so its largest value over the box is at a vertex; the worst margin, a
    minimum over corners, is at most the smallest of those maxima. -inf when some corner's headroom is
    below the limit at every vertex (no network in the box can meet it).

    Parameters
    ----------
    r7 : float
        The sense resistor, ohm.
    lb, ub : array of float
        The box: lowest and highest R9..R13, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    float
        The bound on the worst margin, fraction; -inf when no network of the box meets the headroom or the
        divider current.
    """
    vert = np.array(list(itertools.product(*zip(lb, ub)))).T
    lows, highs = net.trip_voltage_corners(tuple(vert), s)
    m = np.concatenate(net.margins(np.stack(lows), np.stack(highs), r7, s))
    head = np.stack(net.headroom_corners(tuple(vert), s))
    if (head.max(axis=1) < s["input_headroom"] - 1e-12).any() or net.divider_current(ub, s) > s["divider_current_max"]:
        return -np.inf
    return float(m.max(axis=1).min())


def solve(s: dict, leaf_size: int = LEAF_SIZE) -> dict:
    """The smallest feasible series R7 and, with it, the network of the largest worst margin: {r7, network,
    outcome, r7_relaxed, tried, unproven} (r7 None when there is none). Each R7 from the relaxation's bound
    up gets its own branch and bound; the first that finds a network is the smallest (a search that stops at
    its node limit without one is recorded in ``unproven``).

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).
    leaf_size : int
        A node holding at most this many networks is evaluated whole.

    Returns
    -------
    dict
        "r7" (ohm, or None), "network" (R9..R13, ohm), "outcome" (the branch and bound's
        :class:`~handbook.design.branch_bound.Outcome`), "r7_relaxed" (the relaxation's R7, ohm), "tried" (R7 values
        searched), "unproven" (smaller R7 values, ohm, whose search stopped at its node limit).
    """
    found = {"r7": None, "network": None, "outcome": None, "r7_relaxed": None, "tried": 0, "unproven": ()}
    if best_headroom(s) < s["input_headroom"]:  # exact, and cheap: no network can meet the headroom
        return found
    lists = [choices(s, name) for name in RESISTORS]
    relax = Relaxation(s)
    found["r7_relaxed"] = _root(s, relax, lists)
    if found["r7_relaxed"] is None:
        return found
    for r7 in lists[0][lists[0] >= found["r7_relaxed"] * (1 - 1e-9)]:
        found["tried"] += 1
        out = _best_network(float(r7), s, relax, lists, s["min_margin"] - 1e-12, leaf_size=leaf_size)
        if out.choice is not None and not out.proven:  # the node budget ran out: polish what was found
            out.choice, out.score = polish(float(r7), out.choice, s, lists)
        if out.choice is not None:
            return {**found, "r7": float(r7), "network": out.choice, "outcome": out}
        if not out.proven:
            found["unproven"] += (float(r7),)
    return found


def enumerate_series(spec: dict):
    """Exhaustive search (every network and every R7; for reduced series only): (r7, network, worst margin)
    or None. Used by the benchmark beside :func:`design`.

    Parameters
    ----------
    spec : Mapping
        The ``[current_limiter]`` table.

    Returns
    -------
    tuple or None
        (the smallest R7 with a network, ohm; the network of the largest worst margin, R9..R13 in ohm; that margin,
        fraction), or None when no network of the series meets the spec.

    Raises
    ------
    InputError
        When the series hold more than :data:`ENUMERATE_MAX` divider networks.
    """
    s = checked(spec)
    lists = [choices(s, name) for name in RESISTORS]
    networks = math.prod(len(v) for v in lists[1:])
    if networks > ENUMERATE_MAX:
        raise InputError(f"{networks:,} divider networks are too many to enumerate (at most {ENUMERATE_MAX:,}): pin "
                         "resistors or narrow their ranges or series (limiter.design searches any size)")
    grid = np.array(np.meshgrid(*lists[1:], indexing="ij")).reshape(5, -1).T
    for r7 in lists[0]:
        sc = scores(float(r7), grid, s)
        ok = sc >= s["min_margin"] - 1e-12
        if ok.any():
            j = int(np.argmax(np.where(ok, sc, -np.inf)))
            return float(r7), tuple(float(x) for x in grid[j]), float(sc[j])
    return None
