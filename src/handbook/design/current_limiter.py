"""The op-amp current limiter (AN94002 figure 3) designed as a whole network: R7, R9, R10, R11, R12, R13.

Problem. Every resistor takes a value of its series within its range (or the value it is pinned to). At
every tolerance corner (:mod:`.limiter_network`: resistors, zener tolerance and drift, op-amp offset and
bias current; exact) the trip current stays inside [i_no_trip (1 + m), i_must_trip (1 - m)] with m =
``min_margin``, and both op-amp inputs stay ``input_headroom`` below the supply. Objective: the smallest R7
(least loss and least drop at any motor current); among networks with that R7, the largest worst margin.

Solution. R7 comes first: IPOPT minimises ln R7 over the continuous relaxation of all six resistors, a
lower bound for every series design. Then, for each series R7 from that bound up, a branch and bound
(:mod:`.branch_bound`, IPOPT on every node's relaxation) maximises the worst margin over the five divider
resistors; the first R7 whose best network reaches ``min_margin`` is the answer. With four free divider
resistors on E96 there are about 10^11 networks per R7, far too many to enumerate; on E6/E12 dividers the
tests and ``tools/benchmark.py`` check that this search finds exactly what enumeration finds. The chosen
network is re-verified at every corner by :func:`limiter_network.verify`.
"""
from __future__ import annotations

import functools
import itertools
import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core import InputError, series
from ..sources.an94002 import circuit as an94002
from . import branch_bound
from . import limiter_network as net
from .common import Result, completed, ordered
from .solvers import IPOPT_OPTIONS

TABLE = "current_limiter"
RESISTORS = ("r7",) + net.DIVIDER
#: the motor ICs' own output current limits, minimum (datasheet_facts: TDA5144 / TDA5143T datasheets)
IC_LIMIT_MIN = {"TDA5144": 1.8, "TDA5143": 0.7}
zener_range = net.zener_range
#: the tie-break is settled to within this worst margin (0.25 percentage point): the bound proves no
#: network with the same R7 is better by more
GAP = 2.5e-3
#: a node holding at most this many networks is evaluated whole (about the cost of one IPOPT solve)
LEAF_SIZE = 2000


@dataclass(frozen=True)
class LimiterResult(Result):
    r7: float
    r9: float
    r10: float
    r11: float
    r12: float
    r13: float
    i_trip_min: float
    i_trip_max: float
    i_trip_nominal: float
    p_r7: float
    v_cs_nominal: float
    margin_low: float
    margin_high: float
    headroom_min: float
    divider_current: float
    binding: str
    warnings: tuple
    r7_relaxed: float
    nodes: int
    r7_tried: int
    margin_bound: float  # no network with this R7 has a larger worst margin (proven by the search)
    unproven: tuple  # smaller R7 values whose search stopped at its node limit without finding a network

    table = TABLE

    @property
    def network(self) -> tuple:
        return self.r9, self.r10, self.r11, self.r12, self.r13


def checked(spec: dict | None) -> dict:
    s = completed(TABLE, spec)
    ordered(TABLE, "i_no_trip", "i_must_trip", s, "A")
    for name in RESISTORS:
        ordered(TABLE, f"{name}_min", f"{name}_max", s, "ohm", strict=False)
    for name in RESISTORS:  # a range holding no series value is bad input, found before any solver
        choices(s, name)
    if s["i_no_trip"] * (1 + s["min_margin"]) >= s["i_must_trip"] * (1 - s["min_margin"]):
        raise InputError(f"{TABLE}.min_margin = {s['min_margin']:g} leaves no room between i_no_trip = "
                         f"{s['i_no_trip']:g} A and i_must_trip = {s['i_must_trip']:g} A: use a smaller margin")
    return s


def choices(s: dict, name: str) -> np.ndarray:
    """The values a resistor may take: its pinned value, or its series within its range."""
    if s[name] is not None:
        return np.array([float(s[name])])
    values = series.values(s[f"{name}_series"], s[f"{name}_min"], s[f"{name}_max"])
    if not values:
        name_series = s[f"{name}_series"]
        below, above = series.at_most(name_series, s[f"{name}_min"]), series.at_least(name_series, s[f"{name}_max"])
        raise InputError(f"{TABLE}.{name}_min = {s[name + '_min']:g} ohm .. {TABLE}.{name}_max = {s[name + '_max']:g} ohm "
                         f"holds no {s[name + '_series']} value: widen it to include {below:g} or {above:g} ohm")
    return np.array(values)


def scores(r7: float, r: np.ndarray, s: dict) -> np.ndarray:
    """Exact worst margin of each network (rows of R9..R13) with this R7; -inf where a headroom fails."""
    v = net.verify(r7, tuple(r.T), s)
    worst = np.minimum(v["margin_low"], v["margin_high"])
    ok = ((v["headroom_min"] >= s["input_headroom"] - 1e-12) & (v["i_trip_min"] > 0)
          & (v["divider_current"] <= s["divider_current_max"] * (1 + 1e-12)))
    return np.where(ok, worst, -np.inf)


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
    g = ([lo / (r7 * (1 + s["r7_tolerance"]) * s["i_no_trip"]) - 1 - t for lo in lows]
         + [1 - hi / (r7 * (1 - s["r7_tolerance"]) * s["i_must_trip"]) - t for hi in highs]
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
        """(x, status, state) of the box lb..ub (resistor values), or None when IPOPT proves it infeasible.
        ``warm``: a parent's state (its x and multipliers)."""
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
    way, R9 ten steps, every combination evaluated exactly; repeated while it improves the worst margin."""
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


def _best_network(r7: float, s: dict, relax: Relaxation, lists: list, threshold: float, max_nodes: int = 40):
    """Branch and bound over R9..R13 with R7 fixed: the network with the largest worst margin."""
    def relaxed(lb, ub, state):
        res = relax.solve(np.r_[r7, lb], np.r_[r7, ub], [math.log(r7), *np.log(np.sqrt(lb * ub)), 0.0], 0.0,
                          warm=state)
        if res is None and state is not None:  # a warm start that fails is repeated cold before it prunes
            res = relax.solve(np.r_[r7, lb], np.r_[r7, ub], [math.log(r7), *np.log(np.sqrt(lb * ub)), 0.0], 0.0)
        if res is None:
            return None
        x, status, new_state = res
        if status not in ("Solve_Succeeded", "Solved_To_Acceptable_Level"):
            return np.inf, np.sqrt(lb * ub), None  # cannot bound this box: keep it and split it
        return float(x[6]) + 1e-9, np.exp(x[1:6]), new_state

    return branch_bound.search(lists[1:], relaxed, lambda c: scores(r7, c, s), threshold, gap=GAP, scan=0,
                               max_nodes=max_nodes, leaf_size=LEAF_SIZE, cheap_bound=lambda lb, ub: vertex_bound(r7, lb, ub, s))


def vertex_bound(r7: float, lb, ub, s: dict) -> float:
    """An upper bound on the worst margin of every network in the box lb..ub, from its 32 vertices alone.

    For one tolerance corner (signs, zener end, offset and bias fixed) the margin is monotone in each
    resistor (the corner proof), so its largest value over the box is at a vertex; the worst margin, a
    minimum over corners, is at most the smallest of those maxima. -inf when some corner's headroom is
    below the limit at every vertex (no network in the box can meet it).
    """
    vert = np.array(list(itertools.product(*zip(lb, ub)))).T
    lows, highs = net.trip_voltage_corners(tuple(vert), s)
    m = np.concatenate([np.stack(lows) / (r7 * (1 + s["r7_tolerance"]) * s["i_no_trip"]) - 1,
                        1 - np.stack(highs) / (r7 * (1 - s["r7_tolerance"]) * s["i_must_trip"])])
    head = np.stack(net.headroom_corners(tuple(vert), s))
    if (head.max(axis=1) < s["input_headroom"] - 1e-12).any() or net.divider_current(ub, s) > s["divider_current_max"]:
        return -np.inf
    return float(m.max(axis=1).min())


def solve(s: dict) -> dict:
    """The smallest feasible series R7 and, with it, the network of the largest worst margin: {r7, network,
    outcome, r7_relaxed, tried, unproven} (r7 None when there is none). Each R7 from the relaxation's bound
    up gets its own branch and bound; the first that finds a network is the smallest (a search that stops at
    its node limit without one is recorded in ``unproven``)."""
    from .limiter_infeasible import best_headroom
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
        out = _best_network(float(r7), s, relax, lists, s["min_margin"] - 1e-12)
        if out.choice is not None and not out.proven:  # the node budget ran out: polish what was found
            out.choice, out.score = polish(float(r7), out.choice, s, lists)
        if out.choice is not None:
            return {**found, "r7": float(r7), "network": out.choice, "outcome": out}
        if not out.proven:
            found["unproven"] += (float(r7),)
    return found


def design(spec: dict | None = None) -> LimiterResult:
    """The smallest series R7 with the divider network of the largest worst margin; verified at every corner."""
    s = checked(spec)
    found = solve(s)
    r7, network, out = found["r7"], found["network"], found["outcome"]
    if r7 is None:
        from .limiter_infeasible import explain
        explain(s, found["r7_relaxed"])
    v = net.verify(r7, network, s)
    m_lo, m_hi = float(v["margin_low"]), float(v["margin_high"])
    r9, r10, r11, r12, r13 = network
    v_nominal = an94002.v_cs_trip(s["zener_voltage"], r9, r10, r11, r12, r13)
    result = dict(
        spec=s, r7=r7, r9=r9, r10=r10, r11=r11, r12=r12, r13=r13, i_trip_min=float(v["i_trip_min"]),
        i_trip_max=float(v["i_trip_max"]), i_trip_nominal=float(v_nominal / r7), v_cs_nominal=float(v_nominal),
        p_r7=float(v["i_trip_max"]) ** 2 * r7 * (1 + s["r7_tolerance"]), margin_low=m_lo, margin_high=m_hi,
        headroom_min=float(v["headroom_min"]), divider_current=float(v["divider_current"]),
        binding="the lowest trip current" if m_lo <= m_hi else "the highest trip current",
        r7_relaxed=found["r7_relaxed"], nodes=out.nodes, r7_tried=found["tried"], margin_bound=out.bound,
        unproven=found["unproven"])
    return LimiterResult(**result, warnings=tuple(warnings(result, s)))


def warnings(r: dict, s: dict) -> list[str]:
    """What an engineer should know about a design that meets the spec."""
    out = []
    limit = IC_LIMIT_MIN[s["ic"]]
    if r["i_trip_max"] > limit:
        out.append(f"the highest trip current {r['i_trip_max']:.3g} A is above the {s['ic']}'s own output "
                   f"limit (minimum {limit:g} A): on some boards the IC limits first")
    if r["p_r7"] > s["r7_power_rating"]:
        out.append(f"R7 dissipates up to {r['p_r7']:.3g} W while the limiter holds a stalled motor at the highest "
                   f"trip current: more than its {s['r7_power_rating']:g} W rating (r7_power_rating)")
    return out


#: what spreads the trip current, and the spec keys that set each (zeroed one at a time by sensitivity)
SPREAD_SOURCES = {"R9..R13 tolerance": ("resistor_tolerance",), "R7 tolerance": ("r7_tolerance",),
                  "zener tolerance": ("zener_tolerance",), "zener drift": ("zener_tc",), "op-amp offset": ("offset",),
                  "op-amp bias current": ("input_bias", "input_offset_current")}


def sensitivity(r7: float, network, s: dict) -> list[tuple[str, float, float]]:
    """Which tolerance eats the window: for each source, (name, share of ln(i_trip_max / i_trip_min), the
    worst margin with that source removed). The shares are of the log spread at every corner, each
    source removed alone; they need not add to one (the sources interact), so they are normalised."""
    base = net.verify(r7, network, s)
    spread = math.log(float(base["i_trip_max"] / base["i_trip_min"]))
    rows = []
    for name, keys in SPREAD_SOURCES.items():
        v = net.verify(r7, network, {**s, **{k: 0.0 for k in keys}})
        rows.append((name, spread - math.log(float(v["i_trip_max"] / v["i_trip_min"])),
                     float(min(v["margin_low"], v["margin_high"]))))
    total = sum(r[1] for r in rows) or 1.0
    return [(name, gain / total, margin) for name, gain, margin in rows]


def judge(r7: float, network, s: dict) -> dict:
    """Any limiter (the note's, say) by the same exact checks as a design: trip currents, margins, headroom."""
    v = net.verify(r7, network, s)
    out = {k: float(v[k]) for k in ("i_trip_min", "i_trip_max", "margin_low", "margin_high", "headroom_min")}
    out["meets"] = bool(min(out["margin_low"], out["margin_high"]) >= s["min_margin"] - 1e-12
                        and out["headroom_min"] >= s["input_headroom"] - 1e-12)
    return out


def enumerate_series(spec: dict):
    """Exhaustive search (every network and every R7; for reduced series only): (r7, network, worst margin)
    or None. Used by the benchmark beside :func:`design`."""
    s = checked(spec)
    lists = [choices(s, name) for name in RESISTORS]
    grid = np.array(np.meshgrid(*lists[1:], indexing="ij")).reshape(5, -1).T
    for r7 in lists[0]:
        sc = scores(float(r7), grid, s)
        ok = sc >= s["min_margin"] - 1e-12
        if ok.any():
            j = int(np.argmax(np.where(ok, sc, -np.inf)))
            return float(r7), tuple(float(x) for x in grid[j]), float(sc[j])
    return None


def monte_carlo_trip(r7: float, network, s: dict, n: int = 100_000, seed: int = 1) -> dict:
    """Trip currents of ``n`` boards, every part uniform within its tolerance (fixed seed, vectorised)."""
    s = checked(s)
    rng = np.random.default_rng(seed)
    t = s["resistor_tolerance"]

    def u(x, tol):
        return x * (1 + rng.uniform(-tol, tol, n))

    vz_lo, vz_hi = zener_range(s)
    r9, r10, r11, r12, r13 = (u(x, t) for x in network)
    ios = min(s["input_offset_current"], 2 * s["input_bias"])
    common = rng.uniform(-1, 1, n) * (s["input_bias"] - ios / 2)  # both inputs the same way, differing by <= I_os
    half = rng.uniform(-ios / 2, ios / 2, n)
    v = (an94002.v_cs_trip(rng.uniform(vz_lo, vz_hi, n), r9, r10, r11, r12, r13, rng.uniform(-s["offset"], s["offset"], n))
         + (common + half) * r12 - (common - half) * (r9 + r10) * r11 / (r9 + r10 + r11) * (1 + r12 / r13))
    i = v / u(r7, s["r7_tolerance"])
    ok = (i >= s["i_no_trip"]) & (i <= s["i_must_trip"])
    return {"yield": float(ok.mean()), "i_p001": float(np.quantile(i, 0.001)),
            "i_p999": float(np.quantile(i, 0.999)), "i_min": float(i.min()), "i_max": float(i.max()), "samples": i}
